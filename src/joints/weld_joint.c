// Weld joint: holds frame B on frame A, rigidly or through a linear and an angular spring.
//
// Angular row: C = θ (angle of frame B relative to frame A), Ċ = ωB − ωA, K = IA⁻¹ + IB⁻¹.
// Linear rows: the revolute joint's point constraint, C = (cB + rB) − (cA + rA), solved as a
// 2×2 block with K = (mA⁻¹ + mB⁻¹)·I + IA⁻¹·[rA.y², −rA.x·rA.y; −rA.x·rA.y, rA.x²] + (same for B).
// The rows are solved one after the other (angular first), not as one 3×3 block: a block solve
// cannot mix the two stiffnesses, and sequential rows converge to the same answer under warm
// starting.
// Stiffness: hertz 0 means "as rigid as the solver allows": the joint's positional softness in
// the biased pass and rigid, no bias, in the relaxing pass (like every positional row). A hertz
// > 0 makes that row a spring (Catto, "Soft Constraints", GDC 2011) in every pass.
// Reference: Catto, "Modeling and Solving Constraints", GDC 2009; Box2D v3's weld joint.
#include "joint.h"
#include "world/recording.h"

static tbJoint* tbGetWeld(tbJointId id, const char* f, tbWorld** world, bool mutating)
{
	return tbGetJointChecked(id, f, world, tb_weldJoint, mutating);
}

static bool tbCheckWeldDef(const char* f, const tbWeldJointDef* def)
{
	return tbCheckNonNegative(f, "def->linearHertz", def->linearHertz) &&
		   tbCheckNonNegative(f, "def->angularHertz", def->angularHertz) &&
		   tbCheckNonNegative(f, "def->linearDampingRatio", def->linearDampingRatio) &&
		   tbCheckNonNegative(f, "def->angularDampingRatio", def->angularDampingRatio);
}

tbJointId tbCreateWeldJoint(tbWorldId worldId, const tbWeldJointDef* def)
{
	TB_RECORD(CreateWeldJoint, &worldId, def);
	const char* f = "tbCreateWeldJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultWeldJointDef") == false ||
		tbCheckWeldDef(f, def) == false)
	{
		return id;
	}
	tbJoint* joint = tbCreateJointInternal(worldId, &def->base, tb_weldJoint, f, &id);
	if (joint == NULL)
	{
		return id;
	}
	tbWeldJoint* w = &joint->weld;
	w->linearHertz = def->linearHertz;
	w->linearDampingRatio = def->linearDampingRatio;
	w->angularHertz = def->angularHertz;
	w->angularDampingRatio = def->angularDampingRatio;
	return id;
}

// --- the step ----------------------------------------------------------------------------------

void tbPrepareWeldJoint(tbJoint* joint, const tbStepContext* context)
{
	tbWeldJoint* w = &joint->weld;
	float k = joint->invIA + joint->invIB;
	w->axialMass = k > 0.0f ? 1.0f / k : 0.0f;
	w->linearSpring = w->linearHertz > 0.0f ? tbMakeSoftness(w->linearHertz, w->linearDampingRatio, context->h)
											: joint->constraintSoftness;
	w->angularSpring = w->angularHertz > 0.0f ? tbMakeSoftness(w->angularHertz, w->angularDampingRatio, context->h)
											  : joint->constraintSoftness;
	if (context->enableWarmStarting == false)
	{
		w->linearImpulse = tbVec2_zero;
		w->angularImpulse = 0.0f;
	}
}

void tbWarmStartWeldJoint(tbJoint* joint, tbStepContext* context)
{
	const tbWeldJoint* w = &joint->weld;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 rA, rB, d;
	tbJointAnchors(joint, &b, &rA, &rB, &d);
	tbApplyJointImpulse(joint, &b, rA, rB, w->linearImpulse, w->angularImpulse);
	tbStoreJointBodies(joint, &b);
}

void tbSolveWeldJoint(tbJoint* joint, tbStepContext* context, bool useBias)
{
	tbWeldJoint* w = &joint->weld;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	float mA = joint->invMassA, mB = joint->invMassB, iA = joint->invIA, iB = joint->invIB;

	// Angular row (a rigid one is solved with its tree when the joint is in one, joint_tree.c).
	if (joint->solvedInTree == false || w->angularHertz > 0.0f)
	{
		// The relaxing pass of a rigid row has no bias, and so no use for the angle.
		tbSoftness soft = {0.0f, 1.0f, 0.0f};
		float bias = 0.0f;
		if (useBias || w->angularHertz > 0.0f)
		{
			soft = w->angularSpring;
			tbRot qA = tbMulRot(b.sA->deltaRotation, joint->frameA.q);
			tbRot qB = tbMulRot(b.sB->deltaRotation, joint->frameB.q);
			bias = soft.biasRate * tbRelativeAngle(qA, qB);
		}
		float Cdot = b.wB - b.wA;
		float impulse = -soft.massScale * w->axialMass * (Cdot + bias) - soft.impulseScale * w->angularImpulse;
		w->angularImpulse += impulse;
		b.wA -= iA * impulse;
		b.wB += iB * impulse;
	}

	// Linear rows.
	if (joint->solvedInTree == false || w->linearHertz > 0.0f)
	{
		// As the angular row: without bias only the anchors are needed, not the gap between them.
		tbSoftness soft = {0.0f, 1.0f, 0.0f};
		tbVec2 rA, rB, bias = tbVec2_zero;
		if (useBias || w->linearHertz > 0.0f)
		{
			soft = w->linearSpring;
			tbVec2 C;
			tbJointAnchors(joint, &b, &rA, &rB, &C);
			bias = tbMulSV(soft.biasRate, C);
		}
		else
		{
			rA = tbRotateVector(b.sA->deltaRotation, joint->frameA.p);
			rB = tbRotateVector(b.sB->deltaRotation, joint->frameB.p);
		}
		tbVec2 Cdot = tbSub(tbAdd(b.vB, tbCrossSV(b.wB, rB)), tbAdd(b.vA, tbCrossSV(b.wA, rA)));
		tbMat22 K;
		K.cx.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
		K.cy.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
		K.cx.y = K.cy.x;
		K.cy.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
		tbVec2 x = tbSolve22(K, tbAdd(Cdot, bias));
		tbVec2 impulse = {-soft.massScale * x.x - soft.impulseScale * w->linearImpulse.x,
						  -soft.massScale * x.y - soft.impulseScale * w->linearImpulse.y};
		w->linearImpulse = tbAdd(w->linearImpulse, impulse);
		tbApplyJointImpulse(joint, &b, rA, rB, impulse, 0.0f);
	}
	tbStoreJointBodies(joint, &b);
}

// The rigid rows: the angle, Ċ = ωB − ωA, and the pin, as the revolute joint's.
int tbWeldJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows)
{
	tbWeldJoint* w = &joint->weld;
	int count = 0;
	if (w->angularHertz == 0.0f)
	{
		tbRot qA = tbMulRot(b->sA->deltaRotation, joint->frameA.q);
		tbRot qB = tbMulRot(b->sB->deltaRotation, joint->frameB.q);
		tbSetJointRow(rows, count++, (tbVec3Row){0.0f, 0.0f, -1.0f}, (tbVec3Row){0.0f, 0.0f, 1.0f},
					  tbRelativeAngle(qA, qB), &w->angularImpulse);
	}
	if (w->linearHertz == 0.0f)
	{
		tbVec2 rA, rB, C;
		tbJointAnchors(joint, b, &rA, &rB, &C);
		tbSetJointRow(rows, count++, (tbVec3Row){-1.0f, 0.0f, rA.y}, (tbVec3Row){1.0f, 0.0f, -rB.y}, C.x,
					  &w->linearImpulse.x);
		tbSetJointRow(rows, count++, (tbVec3Row){0.0f, -1.0f, -rA.x}, (tbVec3Row){0.0f, 1.0f, rB.x}, C.y,
					  &w->linearImpulse.y);
	}
	return count;
}

void tbGetWeldJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	(void)world;
	*force = tbMulSV(inv_h, joint->weld.linearImpulse);
	*torque = inv_h * joint->weld.angularImpulse;
}

void tbDrawWeldJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint)
{
	tbTransform fA = tbRoundTransform(tbJointWorldFrameA(world, joint));
	tbTransform fB = tbRoundTransform(tbJointWorldFrameB(world, joint));
	float s = 0.25f * joint->drawScale;
	tbDrawLine(draw, tbMulSub(fA.p, s, tbRot_GetXAxis(fA.q)), tbMulAdd(fA.p, s, tbRot_GetXAxis(fA.q)), tb_colorJoint);
	tbDrawLine(draw, tbMulSub(fB.p, s, tbRot_GetYAxis(fB.q)), tbMulAdd(fB.p, s, tbRot_GetYAxis(fB.q)), tb_colorNormal);
}

// --- getters and setters -----------------------------------------------------------------------

static bool tbSetWeldValue(tbJointId jointId, const char* f, const char* name, float value, size_t offset)
{
	tbWorld* world;
	tbJoint* joint = tbGetWeld(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, name, value) == false)
	{
		return false;
	}
	*(float*)((char*)&joint->weld + offset) = value;
	tbWakeJoint(world, joint);
	return true;
}

static float tbGetWeldValue(tbJointId jointId, const char* f, size_t offset)
{
	tbJoint* joint = tbGetWeld(jointId, f, NULL, false);
	return joint != NULL ? *(const float*)((const char*)&joint->weld + offset) : 0.0f;
}

bool tbWeldJoint_SetLinearHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(WeldJointSetLinearHertz, &jointId, &hertz);
	return tbSetWeldValue(jointId, "tbWeldJoint_SetLinearHertz", "hertz", hertz, offsetof(tbWeldJoint, linearHertz));
}

float tbWeldJoint_GetLinearHertz(tbJointId jointId)
{
	return tbGetWeldValue(jointId, "tbWeldJoint_GetLinearHertz", offsetof(tbWeldJoint, linearHertz));
}

bool tbWeldJoint_SetLinearDampingRatio(tbJointId jointId, float dampingRatio)
{
	TB_RECORD(WeldJointSetLinearDampingRatio, &jointId, &dampingRatio);
	return tbSetWeldValue(jointId, "tbWeldJoint_SetLinearDampingRatio", "dampingRatio", dampingRatio,
						  offsetof(tbWeldJoint, linearDampingRatio));
}

float tbWeldJoint_GetLinearDampingRatio(tbJointId jointId)
{
	return tbGetWeldValue(jointId, "tbWeldJoint_GetLinearDampingRatio", offsetof(tbWeldJoint, linearDampingRatio));
}

bool tbWeldJoint_SetAngularHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(WeldJointSetAngularHertz, &jointId, &hertz);
	return tbSetWeldValue(jointId, "tbWeldJoint_SetAngularHertz", "hertz", hertz, offsetof(tbWeldJoint, angularHertz));
}

float tbWeldJoint_GetAngularHertz(tbJointId jointId)
{
	return tbGetWeldValue(jointId, "tbWeldJoint_GetAngularHertz", offsetof(tbWeldJoint, angularHertz));
}

bool tbWeldJoint_SetAngularDampingRatio(tbJointId jointId, float dampingRatio)
{
	TB_RECORD(WeldJointSetAngularDampingRatio, &jointId, &dampingRatio);
	return tbSetWeldValue(jointId, "tbWeldJoint_SetAngularDampingRatio", "dampingRatio", dampingRatio,
						  offsetof(tbWeldJoint, angularDampingRatio));
}

float tbWeldJoint_GetAngularDampingRatio(tbJointId jointId)
{
	return tbGetWeldValue(jointId, "tbWeldJoint_GetAngularDampingRatio", offsetof(tbWeldJoint, angularDampingRatio));
}

/// Rigid in translation (linearHertz 0): the anchors' distance; a soft weld allows any.
float tbWeldJointLinearSeparation(const tbWorld* world, const tbJoint* joint)
{
	if (joint->weld.linearHertz > 0.0f)
	{
		return 0.0f;
	}
	return tbLength(tbSubPos(tbJointWorldFrameB(world, joint).p, tbJointWorldFrameA(world, joint).p));
}

/// Rigid in rotation (angularHertz 0): the frames' relative angle (signed, as Box2D v3.2).
float tbWeldJointAngularSeparation(const tbWorld* world, const tbJoint* joint)
{
	if (joint->weld.angularHertz > 0.0f)
	{
		return 0.0f;
	}
	return tbRelativeAngle(tbJointWorldFrameA(world, joint).q, tbJointWorldFrameB(world, joint).q);
}
