// Soft step (default method): sub-stepped soft contacts with a relaxing pass (Catto, Solver2D
// blog 2024 "soft step"; Box2D v3).
//
// Overlap s < 0 is treated as a stiff spring-damper rather than a rigid constraint:
//     C = s, Ċ = J·v, J = [−n, −rA × n, n, rB × n],
//     m_eff = 1/(mA⁻¹ + mB⁻¹ + IA⁻¹(rA × n)² + IB⁻¹(rB × n)²),
//     λ = −m_eff·massScale·(Ċ + max(biasRate·C, −maxContactPushSpeed)) − impulseScale·λ_acc.
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
// stiffness settle, and its stiffness that sets how many it needs. Measured at 60 Hz, 4 sub-steps,
// 10 s, sleep off where it says drift (tests/test_stability.c's scenes):
//
//   relaxing passes    settled  large_pyramid top      heavy_on_    touching  card houses  step, ms
//   per sub-step+last  stiffness drift/speed/sag       pyramids     stack sag standing     pyramid
//   2 + 0 (earlier)    60 Hz    0.013/0.002/0.199 m    asleep 332   0.035 m   20/20        6.07
//   1 + 0              60 Hz    0.227/0.579/0.223 m    never        0.035 m   20/20
//   1 + 2              60 Hz    0.064/0.031/0.195 m    asleep 478   0.035 m   20/20
//   1 + 0              52.5 Hz  0.042/0.036/0.263 m    asleep 506   0.045 m   20/20
//   1 + 1 (default)    52.5 Hz  0.008/0.006/0.257 m    asleep 392   0.045 m   20/20        5.55
//   1 + 1              48 Hz    0.017/0.003/0.304 m    asleep 266   0.054 m (sways 0.12 m)
//   1 + 0              45 Hz    0.017/0.003/0.342 m    asleep 249   0.064 m (sways 0.31 m)
//   1 + 0              30 Hz    0.009/0.000/0.734 m    asleep 154   1.28 m (falls)
//
// (speed: the fastest box over the last second; step: large_pyramid, one worker, medians of 3
// alternated runs of 120 steps.) Settled contacts at 1.75 × contactHertz with one relaxing pass
// per sub-step and one more in the last keep every test's bound with three fewer passes a step
// (12 → 9; the passes after the first in a sub-step are the cheap repeats, so the step is 9 %
// faster, not 25 %); the sag grows as 1/ω² (a touching stack 0.035 → 0.045 m, Box2D v3: 0.135 m).
// A softer settled spring needs fewer sweeps but the tall stack sways; a stiffer one needs two
// per sub-step. Positions do not move between the relax passes of a sub-step, so the wide solver
// computes each point's speculative bias in the first and reuses it in the others
// (tb_biasRelaxRepeat: no position deltas gathered, bit-identical impulses). Perturbed card
// houses stand in 20 of 20 in every row.
//
// Stiffness (tests/test_stability.c, docs/methods.md):
// - the resting stiffness, restHertz = min(2·contactHertz, ¼ sub-step rate): a spring faster than
//   a quarter of the sub-step rate is not resolved by the integrator and only adds jitter. Static
//   and kinematic contacts always use it (the ground has infinite mass, so there is no mass ratio
//   to protect; Box2D v3 makes the same choice);
// - the settled stiffness, settledHertz = min(settledHertzRatio·contactHertz, ¼ sub-step rate),
//   of dynamic contacts once settled (table above). A load F settles at F/(m_eff·ω²), so it is
//   what keeps piles from sagging: the touching stack of 20 sinks 0.045 m at 52.5 Hz, 0.035 m at
//   60 Hz, 0.136 m at 30 Hz, where it also sways (0.15 m) and, without extra relax passes,
//   buckles and falls;
// - a new dynamic contact keeps contactHertz for TB_SOFT_SETTLE_TIME of touching and then
//   stiffens to settledHertz: impacts and bodies falling into place meet the soft spring (a stiff
//   one rings through a pile and saturates friction: 47 of 60 perturbed card houses stand with
//   the resting stiffness from the first step, 59 of 60 with the settling);
// - a dynamic contact overlapping by more than TB_SOFT_DEEP_OVERLAP at the start of the step is
//   a recovery (overlap recovery, the confined circles) and keeps contactHertz: a stiffer spring
//   squeezes bodies through each other (confined: overlap 0.42 → 0.70 m when only overlaps
//   beyond 0.2 m stay soft);
// - contactHertzFollowsSubStep: contactHertz·subSteps/4 instead of contactHertz, so the soft
//   error floor (sag ≈ g/ω²) shrinks as sub-steps are added instead of staying put.
// None of these depends on the impulses. An earlier version stiffened each contact from the
// previous step's impulse (so that its load settled at a fixed depth); that fed every change of
// load back into the stiffness and kept heavy piles jittering (docs/methods.md).
//
// Rejected: friction in fewer passes (Box2D v3 solves friction only in its relaxing pass). Measured
// at 4 sub-steps against friction in every pass (with the earlier 2 relaxing passes per sub-step): friction in the first relaxing pass only was
// 10–15 % faster on the pyramids but made slopes creep 0.44 mm instead of 0.04 mm and left
// large_pyramid's fastest box at 0.039 m/s after 9 s (0.002 m/s now); friction in the biased and
// first relaxing passes only (5 % faster) left it at 0.69 m/s, in the biased and last only at
// 0.34 m/s. The repeated passes settle the pile only when they also hold it by friction. (Measured
// again with one relaxing pass per sub-step, 2026-11-27: without friction in the biased passes the
// fastest box was at 0.094 m/s after 9 s, against 0.006; friction only in the last sub-step's
// relaxing passes, 0.17 m/s.) What does make friction cheaper is one row per contact instead of one
// per point (central friction, contact_solver.c): the same friction on a face, in every pass.
// Rejected: rigid contacts with position projection after each sub-step (fast, but it flings
// deeply overlapping bodies apart: see the overlap recovery scene in docs/stability.md).
#include "solver_methods.h"

#include "contact_solver.h"
#include "integrator.h"
#include "joints/joint.h"

#include "tumble/constants.h"

// Settling of a new dynamic contact: it keeps contactHertz for TB_SOFT_SETTLE_TIME of touching
// (0.25 s, 15 steps at 60 Hz), then stiffens linearly to the resting stiffness over as long
// again. The cards of a card house fall into place within about 15 steps: measured over 60
// perturbed houses (x ±1 mm, ±3 mrad), 47 stand with the resting stiffness from the first step,
// 57 with a linear ramp over the first 0.25 s, 59 with this one. The ramp moves the resting
// depth of a loaded contact smoothly (from F/(m_eff·ω0²) to F/(m_eff·ω²)) instead of at once.
#define TB_SOFT_SETTLE_TIME 0.25f

// Overlap (m) beyond which a dynamic contact is a recovery and stays soft: 10 × linear slop =
// 0.05 m. Recoveries start far deeper (overlap recovery 0.25 m, confined circles 0.3 to 0.5 m);
// loads rest well above it once stiff, and a 100 kg box on a 1 kg one rests at 3.6 cm while its
// contact is still soft, which a lower threshold (0.02 m) would take for a recovery and leave soft.
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
