// Sequential impulses plus non-linear Gauss–Seidel position correction (Box2D 2.4 style;
// Catto GDC 2009 "Modeling and Solving Constraints", position projection section).
//
// Velocity pass: rigid contacts with no position bias (speculative gaps s > 0 still get s/h),
//     Ċ = J·v, J = [−n, −rA × n, n, rB × n], λ = −m_eff·Ċ,
//     m_eff = 1/(mA⁻¹ + mB⁻¹ + IA⁻¹(rA × n)² + IB⁻¹(rB × n)²),
// so the velocities carry no push-out energy. After the positions are integrated, overlap is
// removed directly on positions, positionIterations times per sub-step:
//     s from the current deltas (anchors rotated with the bodies, normal held fixed),
//     C = clamp(β·(s + linear slop), −TB_MAX_LINEAR_CORRECTION, 0),
//     K with the current anchors, P = (−C/K)·n,
//     ΔpA −= mA⁻¹P, ΔθA −= IA⁻¹ rA × P, ΔpB += mB⁻¹P, ΔθB += IB⁻¹ rB × P.
// Non-linear because s and K are recomputed from the moved bodies at every point; Gauss–Seidel
// because each point sees the corrections of the points before it. The passes stop early when
// the deepest overlap is within 3 slops (Box2D 2.4's test).
//
// Weakness (measured in STRESS.md scenes): the position pass ignores mass ratios' effect on
// velocity, so heavy bodies on light ones sink, and velocity iterations without bias need many
// iterations for tall stacks.
#include "solver.h"

#include "tumble/constants.h"

void tbNGSPrepare(tbStepContext* context)
{
	tbSoftness rigid = {0.0f, 1.0f, 0.0f};
	context->contactSoftness = rigid;
	context->staticSoftness = rigid;
}

// One position pass over all contacts; returns the smallest separation seen (m).
static float tbSolvePositionConstraints(tbStepContext* context)
{
	float minSeparation = 0.0f;
	tbSolverBody* bodies = context->bodies;
	for (int i = 0; i < context->constraintCount; ++i)
	{
		const tbContactConstraint* c = context->constraints + i;
		tbSolverBody* sA = bodies + c->indexA;
		tbSolverBody* sB = bodies + c->indexB;
		tbVec2 normal = c->normal;
		for (int j = 0; j < c->pointCount; ++j)
		{
			const tbContactConstraintPoint* cp = c->points + j;
			tbVec2 rA = tbRotateVector(sA->deltaRotation, cp->anchorA);
			tbVec2 rB = tbRotateVector(sB->deltaRotation, cp->anchorB);
			tbVec2 d = tbAdd(tbSub(sB->deltaPosition, sA->deltaPosition), tbSub(rB, rA));
			float s = cp->baseSeparation + tbDot(d, normal);
			minSeparation = tbMinFloat(minSeparation, s);

			float C = tbClampFloat(TB_BAUMGARTE * (s + TB_LINEAR_SLOP), -TB_MAX_LINEAR_CORRECTION, 0.0f);
			float rnA = tbCross(rA, normal);
			float rnB = tbCross(rB, normal);
			float K = c->invMassA + c->invMassB + c->invIA * rnA * rnA + c->invIB * rnB * rnB;
			float impulse = K > 0.0f ? -C / K : 0.0f;
			tbVec2 P = tbMulSV(impulse, normal);

			sA->deltaPosition = tbMulSub(sA->deltaPosition, c->invMassA, P);
			sA->deltaRotation = tbIntegrateRotation(sA->deltaRotation, -c->invIA * tbCross(rA, P));
			sB->deltaPosition = tbMulAdd(sB->deltaPosition, c->invMassB, P);
			sB->deltaRotation = tbIntegrateRotation(sB->deltaRotation, c->invIB * tbCross(rB, P));
		}
	}
	return minSeparation;
}

void tbNGSSubStep(tbStepContext* context)
{
	const tbWorldDef* def = &context->world->def;
	int velocityIterations = tbMaxInt(def->velocityIterations, 1);
	for (int i = 0; i < velocityIterations; ++i)
	{
		tbSolveContacts(context, tb_biasSpeculative);
	}
	tbIntegratePositions(context);
	for (int i = 0; i < def->positionIterations; ++i)
	{
		if (tbSolvePositionConstraints(context) >= -3.0f * TB_LINEAR_SLOP)
		{
			break;
		}
	}
}
