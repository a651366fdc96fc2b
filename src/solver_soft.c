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
// bodies are, which is why soft contacts survive mass ratios that crush rigid ones.
//
// Per sub-step: one biased pass (push-out of overlap at a bounded speed), integrate positions,
// then relaxIterations passes with the bias off, which remove the push-out velocity so that
// resolved overlap does not turn into bounce (the "relax" of soft step). Speculative gaps
// (s > 0) always use the rigid bias s/h.
//
// Stiffness choices (measured with tests/test_solver.c):
// - hertz = min(contactHertz, ¼ sub-step rate): a spring faster than a quarter of the sub-step
//   rate is not resolved by the integrator and only adds jitter.
// - contactHertzFollowsSubStep: hertz = min(contactHertz·subSteps/4, ¼ sub-step rate), so the
//   soft error floor (sag ≈ g/ω²) shrinks as sub-steps are added instead of staying put.
// - dynamic vs static or kinematic contacts use twice the stiffness (capped the same way): the
//   ground has infinite mass, so there is no mass ratio to protect and stiffer ground contact
//   halves the settling depth. Box2D v3 makes the same choice.
//
// Rejected: rigid contacts with position projection after each sub-step (fast, but it flings
// deeply overlapping bodies apart: see the overlap recovery scene in STRESS.md).
#include "solver.h"

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
	float staticHertz = tbMinFloat(2.0f * hertz, maxHertz);
	context->contactSoftness = tbMakeSoftness(hertz, def->contactDampingRatio, context->h);
	context->staticSoftness = tbMakeSoftness(staticHertz, def->contactDampingRatio, context->h);
}

void tbSoftSubStep(tbStepContext* context)
{
	tbSolveContacts(context, tb_biasSoft);
	tbIntegratePositions(context);
	int relaxIterations = context->world->def.relaxIterations;
	for (int i = 0; i < relaxIterations; ++i)
	{
		tbSolveContacts(context, tb_biasRelax);
	}
}
