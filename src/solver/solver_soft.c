// Soft step (default method): sub-stepped soft contacts with a relaxing pass (Catto, Solver2D
// blog 2024 "soft step"; Box2D v3).
//
// Overlap s < 0 is treated as a stiff spring-damper rather than a rigid constraint:
//     C = s, Ċ = J·v, J = [−n, −rA × n, n, rB × n],
//     m_eff = 1/(mA⁻¹ + mB⁻¹ + IA⁻¹(rA × n)² + IB⁻¹(rB × n)²),
//     λ = −m_eff·massScale·(Ċ + max(biasRate·C, −contactSpeed)) − impulseScale·λ_acc.
// Solving the spring implicitly over the sub-step h (ω = 2π·hertz, ζ = damping ratio) gives
// biasRate = ω/(2ζ + hω), massScale = hω(2ζ + hω)/(1 + hω(2ζ + hω)), impulseScale = 1/(1 + hω(2ζ + hω))
// (tbMakeSoftness). A spring whose period is ≥ 4 sub-steps stays stable however heavy the
// bodies are, which is why soft contacts survive mass ratios that crush rigid ones. A contact
// carrying the force F settles at the depth F/(m_eff·ω²) (the λ_acc term balances the bias at
// that depth), whatever the order or the number of passes: only the stiffness sets the sag.
//
// Per sub-step: one biased pass (push-out of overlap at a bounded speed), integrate positions,
// then relaxIterations passes with the bias off, which remove the push-out velocity so that
// resolved overlap does not turn into bounce (the "relax" of soft step); the last sub-step adds
// finalRelaxIterations passes. Speculative gaps (s > 0) always use the rigid bias s/h. It is the
// number of relaxing sweeps per step, wherever they fall, that lets a pile at its resting
// stiffness settle, and its stiffness that sets how many it needs: a stiffer spring rings longer
// through a pile and needs more sweeps; a softer one settles with fewer but sags more (the sag
// grows as 1/ω²) and lets a tall stack sway. The default, settled contacts at 1.75 × contactHertz
// with one relaxing pass per sub-step and one more in the last, keeps every bound of
// tests/test_stability.c with three fewer passes a step than two relaxing passes per sub-step at
// the resting stiffness (at 4 sub-steps 4 + 4 + 1 = 9 passes against 4 + 8 = 12); the passes
// after the first in a sub-step are the cheap repeats, so the step saves less than a quarter.
// docs/methods.md ("Cost") has the table of passes against stiffness it was chosen from.
// Positions do not move between the relax passes of a sub-step, so the wide solver computes each
// point's speculative bias in the first and reuses it in the others (tb_biasRelaxRepeat: no
// position deltas gathered, bit-identical impulses).
//
// Stiffness (tests/test_stability.c, docs/methods.md):
// - the resting stiffness, restHertz = min(2·contactHertz, ¼ sub-step rate): a spring faster than
//   a quarter of the sub-step rate is not resolved by the integrator and only adds jitter. Static
//   and kinematic contacts always use it (the ground has infinite mass, so there is no mass ratio
//   to protect; Box2D v3 makes the same choice);
// - the settled stiffness, settledHertz = min(settledHertzRatio·contactHertz, ¼ sub-step rate),
//   of dynamic contacts once settled. A load F settles at F/(m_eff·ω²), so it is what keeps piles
//   from sagging: a softer one lets a touching stack sink deeper and sway, and at Box2D v3's
//   settled 30 Hz a tall stack buckles and falls without extra relax passes;
// - a new dynamic contact keeps contactHertz for TB_SOFT_SETTLE_TIME of touching and then
//   stiffens to settledHertz: impacts and bodies falling into place meet the soft spring (a stiff
//   one rings through a pile and saturates friction, and perturbed card houses fall that stand
//   with the settling);
// - a dynamic contact overlapping by more than TB_SOFT_DEEP_OVERLAP at the start of the step is
//   a recovery (overlap recovery, the confined circles) and keeps contactHertz: a stiffer spring
//   squeezes bodies through each other (the confined circles overlap further when only deeper
//   overlaps stay soft);
// - contactHertzFollowsSubStep: contactHertz·subSteps/4 instead of contactHertz, so the soft
//   error floor (sag ≈ g/ω²) shrinks as sub-steps are added instead of staying put.
// None of these depends on the impulses. An earlier version stiffened each contact from the
// previous step's impulse (so that its load settled at a fixed depth); that fed every change of
// load back into the stiffness and kept heavy piles jittering (docs/methods.md).
//
// Rejected: friction in fewer passes (Box2D v3 solves friction only in its relaxing pass). Leaving
// friction out of the biased pass, or out of all relaxing passes but one, makes a pass cheaper but
// lets slopes creep and leaves the boxes of a large pyramid moving long after they should rest: the
// repeated passes settle the pile only when they also hold it by friction (docs/performance.md, on
// the gap to Box2D v3's solve). What does make friction cheaper is one row per contact instead of
// one per point (central friction, contact_solver.c): the same friction on a face, in every pass.
// Rejected: rigid contacts with position projection after each sub-step (fast, but it flings
// deeply overlapping bodies apart: see the overlap recovery scene in docs/stability.md).
#include "solver_methods.h"

#include "contact_solver.h"
#include "integrator.h"
#include "joints/joint.h"

#include "tumble/constants.h"

// Settling of a new dynamic contact: it keeps contactHertz for TB_SOFT_SETTLE_TIME of touching
// (0.25 s, 15 steps at 60 Hz), then stiffens linearly to the settled stiffness (settledHertz)
// over as long again. The time is about how long the cards of a card house take to fall into
// place: stiff from the first step, the spring rings through the house and some perturbed houses
// fall; a ramp that starts at once stiffens while the cards still move, and holding the soft
// spring first stands the most (tests/test_stability.c). The ramp moves the resting depth of a
// loaded contact smoothly (from F/(m_eff·ω0²) to F/(m_eff·ω²)) instead of at once.
#define TB_SOFT_SETTLE_TIME 0.25f

// Overlap (m) beyond which a dynamic contact is a recovery and stays soft: 10 × linear slop =
// 0.05 m. It trades the two ways of being wrong: recoveries start far deeper than that (the
// overlap recovery and confined-circles scenes are built with overlaps of a few tenths of a
// metre), and loads rest well above it once stiff; but a heavy box on a light one rests a few
// centimetres deep while its contact is still soft (F/(m_eff·ω²) at contactHertz), which a
// lower threshold would take for a recovery and leave soft for good.
#define TB_SOFT_DEEP_OVERLAP (10.0f * TB_LINEAR_SLOP)

void tbSoftPrepare(tbStepContext* context)
{
	const tbWorldDef* def = &context->world->def;
	float maxHertz = 0.25f * context->inv_h;
	float hertz = def->contactHertz;
	if (def->contactHertzFollowsSubStep)
	{
		hertz = def->contactHertz * (float)context->subStepCount / 4.0f;
	}
	hertz = tbMinFloat(hertz, maxHertz);
	float restHertz = tbMinFloat(2.0f * hertz, maxHertz);
	float settledHertz = tbMinFloat(def->settledHertzRatio * hertz, maxHertz);
	context->contactHertz = hertz;
	context->restHertz = restHertz;
	context->settledHertz = settledHertz;
	context->contactSoftness = tbMakeSoftness(hertz, def->contactDampingRatio, context->h);
	context->staticSoftness = tbMakeSoftness(restHertz, def->contactDampingRatio, context->h);
	context->settledSoftness = tbMakeSoftness(settledHertz, def->contactDampingRatio, context->h);
	// The settling ramp below is applied by the contact preparation (tbSettleSoftness, contact_solver.c)
	// while each contact is in cache; a pass of its own here waited on a load per contact.
	context->settleSteps = TB_SOFT_SETTLE_TIME / context->timeStep;
	context->deepOverlap = TB_SOFT_DEEP_OVERLAP;
	context->dampingRatio = def->contactDampingRatio;
	// Box2D v3.2's contact softening caps the stiffness lower, at an eighth of the sub-step rate,
	// before scaling it down by the mass ratio (contact_solver.c, tbSoftenedSoftness).
	context->contactSoftening = def->enableContactSoftening;
	context->softeningHertz = tbMinFloat(hertz, 0.125f * context->inv_h);
}

int tbSoftRelaxIterations(const tbStepContext* context, int subStepIndex)
{
	const tbWorldDef* def = &context->world->def;
	int final = subStepIndex == context->subStepCount - 1 ? def->finalRelaxIterations : 0;
	return def->relaxIterations + final + tbJointTreeRelaxIterations(context); // joint.c
}

void tbSoftSubStep(tbStepContext* context)
{
	tbProfile* profile = &context->world->profile;
	tbSolveJoints(context, true); // joint.c: soft positional correction
	tbSolveContacts(context, tb_biasSoft);
	tbProfileLap(&profile->solveImpulses, &context->lapTicks);
	tbIntegratePositions(context);
	tbProfileLap(&profile->integratePositions, &context->lapTicks);
	int relaxIterations = tbSoftRelaxIterations(context, context->subStepIndex);
	for (int i = 0; i < relaxIterations; ++i)
	{
		if (tbRelaxJointsInIteration(context, i))
		{
			tbSolveJoints(context, false); // rigid, no correction
		}
		tbSolveContacts(context, i == 0 ? tb_biasRelax : tb_biasRelaxRepeat);
	}
	tbProfileLap(&profile->relaxImpulses, &context->lapTicks);
}
