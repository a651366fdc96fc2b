// Sequential impulses with a Baumgarte velocity bias (Catto GDC 2005/2006; Baumgarte 1972).
//
// Rigid contact: C = s ≥ 0, Ċ = J·v, J = [−n, −rA × n, n, rB × n],
//     m_eff = 1/(mA⁻¹ + mB⁻¹ + IA⁻¹(rA × n)² + IB⁻¹(rB × n)²),
//     λ = −m_eff·(Ċ + bias), accumulated λ clamped ≥ 0, friction |λt| ≤ μ·λn.
// Position error is fed back into the velocity target:
//     bias = (β/h)·min(0, s + linear slop)   (β = TB_BAUMGARTE = 0.2),
// i.e. a fifth of the overlap beyond the slop is removed per sub-step. Speculative gaps s > 0
// use bias = s/h. velocityIterations passes per sub-step, then integrate positions; no relaxing
// pass, so the push-out velocity stays in the bodies.
//
// Kept as the textbook reference and for measurement: the bias adds energy (stacks jitter,
// pyramids never rest, deep overlap is resolved explosively), which is what the soft step and
// NGS methods fix in two different ways.
#include "solver_methods.h"

#include "contact_solver.h"
#include "integrator.h"
#include "joints/joint.h"

void tbBaumgartePrepare(tbStepContext* context)
{
	tbSoftness rigid = {0.0f, 1.0f, 0.0f};
	context->contactSoftness = rigid;
	context->staticSoftness = rigid;
}

void tbBaumgarteSubStep(tbStepContext* context)
{
	int velocityIterations = tbMaxInt(context->world->def.velocityIterations, 1);
	for (int i = 0; i < velocityIterations; ++i)
	{
		tbSolveJoints(context, true); // joint.c: the same Baumgarte bias
		tbSolveContacts(context, tb_biasBaumgarte);
	}
	tbIntegratePositions(context);
}
