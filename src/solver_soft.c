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
#include "solver_methods.h"

#include "contact_solver.h"
#include "integrator.h"
#include "joint.h"

#include "tumble/constants.h"

// Load-aware stiffness: a resting contact that carries the force F (N, per point, from the
// accumulated impulse of the previous step: F = λ/h) settles at the depth F/(m_eff·ω²). It is
// stiffened so that this depth stays ≤ TB_SOFT_TARGET_SAG, but never beyond the ¼ sub-step rate
// cap. Deep overlaps (s < −TB_SOFT_DEEP_OVERLAP at the start of the step) keep the base softness:
// they are recoveries (overlap recovery, the confined circles), where a stiffer spring squeezes
// bodies through each other (confined: overlap 0.37 → 0.71 m with every contact at the cap).
#define TB_SOFT_TARGET_SAG (0.4f * TB_LINEAR_SLOP)
#define TB_SOFT_DEEP_OVERLAP (4.0f * TB_LINEAR_SLOP)

static tbSoftness tbSoftnessFromOmega(float omega, float dampingRatio, float h)
{
	float a1 = 2.0f * dampingRatio + h * omega;
	float a2 = h * omega * a1;
	float a3 = 1.0f / (1.0f + a2);
	tbSoftness soft = {omega / a1, a2 * a3, a3};
	return soft;
}

void tbSoftPrepareContacts(tbStepContext* context)
{
	if (context->enableWarmStarting == false)
	{
		return; // no load is known
	}
	float dampingRatio = context->world->def.contactDampingRatio;
	float h = context->h;
	float omegaMax = 2.0f * TB_PI * 0.25f * context->inv_h;
	float omegaMaxSquared = omegaMax * omegaMax;
	// ω² = F/(m_eff·sag) = (λ/h)·K/sag with K = 1/normalMass.
	float scale = context->inv_h / TB_SOFT_TARGET_SAG;
	for (int i = 0; i < context->constraintCount; ++i)
	{
		tbContactConstraint* c = context->constraints + i;
		if (c->softness.massScale <= 0.0f)
		{
			continue;
		}
		float need = 0.0f;
		for (int j = 0; j < c->pointCount; ++j)
		{
			const tbContactConstraintPoint* cp = c->points + j;
			float s0 = cp->baseSeparation + tbDot(tbSub(cp->anchorB, cp->anchorA), c->normal);
			if (s0 < -TB_SOFT_DEEP_OVERLAP)
			{
				need = 0.0f;
				break;
			}
			if (cp->normalMass > 0.0f)
			{
				need = tbMaxFloat(need, cp->normalImpulse / cp->normalMass);
			}
		}
		float omegaSquared = scale * need;
		if (omegaSquared <= 0.0f)
		{
			continue;
		}
		float omega = omegaSquared < omegaMaxSquared ? sqrtf(omegaSquared) : omegaMax;
		// The base stiffness ω0 has biasRate·(2ζ + hω0) = ω0; only ever stiffen.
		float omega0 = c->softness.biasRate * (2.0f * dampingRatio) / (1.0f - h * c->softness.biasRate);
		if (omega > omega0)
		{
			c->softness = tbSoftnessFromOmega(omega, dampingRatio, h);
		}
	}
}

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
	tbSolveJoints(context, true); // joint.c: soft positional correction
	tbSolveContacts(context, tb_biasSoft);
	tbIntegratePositions(context);
	int relaxIterations = context->world->def.relaxIterations + tbJointTreeRelaxIterations(context); // joint.c
	for (int i = 0; i < relaxIterations; ++i)
	{
		tbSolveJoints(context, false); // rigid, no correction
		tbSolveContacts(context, tb_biasRelax);
	}
}
