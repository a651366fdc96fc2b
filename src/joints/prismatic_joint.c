// Prismatic joint: body B slides along the x-axis of frame A and keeps its angle relative to A,
// with an optional spring along the axis, a motor and translation limits.
//
// Let a be the axis (frame A's x-axis, turning with body A), p = leftPerp(a) the normal to it,
// rA, rB the anchors from the centres of mass and d = (cB + rB) − (cA + rA). The impulses act at
// anchor B, so on body A their lever arm is d + rA:
//     a1 = (d + rA) × a, a2 = rB × a,   s1 = (d + rA) × p, s2 = rB × p.
// Along the axis (translation x = a·d; spring, motor and limits):
//     Ċ = a·(vB − vA) + a2·ωB − a1·ωA,  K = mA⁻¹ + mB⁻¹ + IA⁻¹·a1² + IB⁻¹·a2².
// Across the axis and in angle, solved as one 2×2 block (stiffer than two separate rows):
//     C = (p·d, θ),  Ċ = (p·(vB − vA) + s2·ωB − s1·ωA, ωB − ωA),
//     K = [mA⁻¹ + mB⁻¹ + IA⁻¹·s1² + IB⁻¹·s2², IA⁻¹·s1 + IB⁻¹·s2; IA⁻¹·s1 + IB⁻¹·s2, IA⁻¹ + IB⁻¹].
// An axial impulse λ gives P = λ·a to B (−P to A) and angular impulses λ·a2 to B, −λ·a1 to A; the
// block's (λp, λθ) give P = λp·p and λp·s2 + λθ to B, −(λp·s1 + λθ) to A.
// The spring (towards targetTranslation) is a soft constraint with the user's hertz, in every
// pass; the motor's accumulated impulse is bounded by h·maxMotorForce; limits are one-sided rows
// with speculation, as the revolute joint's angle limits.
// Reference: Catto, "Modeling and Solving Constraints", GDC 2009; Box2D v3's prismatic joint.
#include "joint.h"
#include "world/recording.h"

static tbJoint* tbGetPrismatic(tbJointId id, const char* f, tbWorld** world, bool mutating)
{
	return tbGetJointChecked(id, f, world, tb_prismaticJoint, mutating);
}

static bool tbCheckPrismaticDef(const char* f, const tbPrismaticJointDef* def)
{
	return tbCheckNonNegative(f, "def->hertz", def->hertz) &&
		   tbCheckNonNegative(f, "def->dampingRatio", def->dampingRatio) &&
		   tbCheckFloat(f, "def->targetTranslation", def->targetTranslation) &&
		   tbCheckRange(f, "def->lowerTranslation", def->lowerTranslation, "def->upperTranslation",
						def->upperTranslation) &&
		   tbCheckNonNegative(f, "def->maxMotorForce", def->maxMotorForce) &&
		   tbCheckFloat(f, "def->motorSpeed", def->motorSpeed);
}

tbJointId tbCreatePrismaticJoint(tbWorldId worldId, const tbPrismaticJointDef* def)
{
	TB_RECORD(CreatePrismaticJoint, &worldId, def);
	const char* f = "tbCreatePrismaticJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultPrismaticJointDef") == false ||
		tbCheckPrismaticDef(f, def) == false)
	{
		return id;
	}
	tbJoint* joint = tbCreateJointInternal(worldId, &def->base, tb_prismaticJoint, f, &id);
	if (joint == NULL)
	{
		return id;
	}
	tbPrismaticJoint* p = &joint->prismatic;
	p->enableSpring = def->enableSpring;
	p->hertz = def->hertz;
	p->dampingRatio = def->dampingRatio;
	p->targetTranslation = def->targetTranslation;
	p->enableLimit = def->enableLimit;
	p->lowerTranslation = def->lowerTranslation;
	p->upperTranslation = def->upperTranslation;
	p->enableMotor = def->enableMotor;
	p->maxMotorForce = def->maxMotorForce;
	p->motorSpeed = def->motorSpeed;
	return id;
}

// --- the step ----------------------------------------------------------------------------------

void tbPreparePrismaticJoint(tbJoint* joint, const tbStepContext* context)
{
	tbPrismaticJoint* p = &joint->prismatic;
	p->springSoftness = tbMakeSoftness(p->hertz, p->dampingRatio, context->h);
	if (context->enableWarmStarting == false)
	{
		p->impulse = tbVec2_zero;
		p->springImpulse = 0.0f;
		p->motorImpulse = 0.0f;
		p->lowerImpulse = 0.0f;
		p->upperImpulse = 0.0f;
	}
}

void tbWarmStartPrismaticJoint(tbJoint* joint, tbStepContext* context)
{
	const tbPrismaticJoint* p = &joint->prismatic;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbAxisFrame g = tbMakeAxisFrame(joint, &b);
	float axial = p->springImpulse + p->motorImpulse + p->lowerImpulse - p->upperImpulse;
	tbApplyAxisImpulse(joint, &b, &g, axial, p->impulse.x, p->impulse.y);
	tbStoreJointBodies(joint, &b);
}

static void tbSolvePrismaticAxis(tbJoint* joint, tbJointBodies* b, const tbAxisFrame* g, const tbStepContext* context,
								 bool useBias)
{
	tbPrismaticJoint* p = &joint->prismatic;
	float axialMass = tbAxialMassOf(joint, g);
	if (p->enableSpring && p->hertz > 0.0f)
	{
		tbSoftness s = p->springSoftness;
		float C = g->translation - p->targetTranslation;
		float impulse = -s.massScale * axialMass * (tbAxialSpeedOf(b, g) + s.biasRate * C) - s.impulseScale * p->springImpulse;
		p->springImpulse += impulse;
		tbApplyAxisImpulse(joint, b, g, impulse, 0.0f, 0.0f);
	}
	if (p->enableMotor)
	{
		float impulse = axialMass * (p->motorSpeed - tbAxialSpeedOf(b, g));
		float maxImpulse = context->h * p->maxMotorForce;
		float newImpulse = tbClampFloat(p->motorImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - p->motorImpulse;
		p->motorImpulse = newImpulse;
		tbApplyAxisImpulse(joint, b, g, impulse, 0.0f, 0.0f);
	}
	if (p->enableLimit)
	{
		tbSolveAxisLimit(joint, b, g, axialMass, g->translation - p->lowerTranslation, 1.0f, &p->lowerImpulse, context,
						 useBias);
		tbSolveAxisLimit(joint, b, g, axialMass, p->upperTranslation - g->translation, -1.0f, &p->upperImpulse, context,
						 useBias);
	}
}

void tbSolvePrismaticJoint(tbJoint* joint, tbStepContext* context, bool useBias)
{
	tbPrismaticJoint* p = &joint->prismatic;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbAxisFrame g = tbMakeAxisFrame(joint, &b);
	tbSolvePrismaticAxis(joint, &b, &g, context, useBias);
	if (joint->solvedInTree)
	{
		tbStoreJointBodies(joint, &b); // the line and the angle are solved with its tree (joint_tree.c)
		return;
	}

	// The block across the axis and in angle.
	float mA = joint->invMassA, mB = joint->invMassB, iA = joint->invIA, iB = joint->invIB;
	tbVec2 Cdot = {tbDot(g.perp, tbSub(b.vB, b.vA)) + g.s2 * b.wB - g.s1 * b.wA, b.wB - b.wA};
	tbSoftness soft = {0.0f, 1.0f, 0.0f};
	tbVec2 bias = tbVec2_zero;
	if (useBias)
	{
		soft = joint->constraintSoftness;
		tbRot qA = tbMulRot(b.sA->deltaRotation, joint->frameA.q);
		tbRot qB = tbMulRot(b.sB->deltaRotation, joint->frameB.q);
		tbVec2 C = {tbDot(g.perp, g.d), tbRelativeAngle(qA, qB)};
		bias = tbMulSV(soft.biasRate, C);
	}
	float k11 = mA + mB + iA * g.s1 * g.s1 + iB * g.s2 * g.s2;
	float k12 = iA * g.s1 + iB * g.s2;
	float k22 = iA + iB;
	if (k22 == 0.0f)
	{
		k22 = 1.0f; // neither body turns: the angular row is void, keep K invertible
	}
	tbMat22 K = {{k11, k12}, {k12, k22}};
	tbVec2 x = tbSolve22(K, tbAdd(Cdot, bias));
	tbVec2 impulse = {-soft.massScale * x.x - soft.impulseScale * p->impulse.x,
					  -soft.massScale * x.y - soft.impulseScale * p->impulse.y};
	p->impulse = tbAdd(p->impulse, impulse);
	tbApplyAxisImpulse(joint, &b, &g, 0.0f, impulse.x, impulse.y);
	tbStoreJointBodies(joint, &b);
}

// The rows across the axis and in angle (see the header comment).
int tbPrismaticJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows)
{
	tbAxisFrame g = tbMakeAxisFrame(joint, b);
	tbRot qA = tbMulRot(b->sA->deltaRotation, joint->frameA.q);
	tbRot qB = tbMulRot(b->sB->deltaRotation, joint->frameB.q);
	tbSetJointRow(rows, 0, (tbVec3Row){-g.perp.x, -g.perp.y, -g.s1}, (tbVec3Row){g.perp.x, g.perp.y, g.s2},
				  tbDot(g.perp, g.d), &joint->prismatic.impulse.x);
	tbSetJointRow(rows, 1, (tbVec3Row){0.0f, 0.0f, -1.0f}, (tbVec3Row){0.0f, 0.0f, 1.0f}, tbRelativeAngle(qA, qB),
				  &joint->prismatic.impulse.y);
	return 2;
}

void tbGetPrismaticJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	const tbPrismaticJoint* p = &joint->prismatic;
	tbVec2 axis = tbRot_GetXAxis(tbJointWorldFrameA(world, joint).q);
	tbVec2 perp = tbLeftPerp(axis);
	float axial = p->springImpulse + p->motorImpulse + p->lowerImpulse - p->upperImpulse;
	*force = tbMulSV(inv_h, tbAdd(tbMulSV(axial, axis), tbMulSV(p->impulse.x, perp)));
	*torque = inv_h * p->impulse.y;
}

void tbDrawPrismaticJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint)
{
	const tbPrismaticJoint* p = &joint->prismatic;
	tbTransform fA = tbRoundTransform(tbJointWorldFrameA(world, joint));
	tbVec2 pB = tbToVec2(tbJointWorldFrameB(world, joint).p);
	tbVec2 axis = tbRot_GetXAxis(fA.q);
	tbVec2 perp = tbMulSV(0.1f * joint->drawScale, tbLeftPerp(axis));
	if (p->enableLimit)
	{
		tbVec2 lower = tbMulAdd(fA.p, p->lowerTranslation, axis);
		tbVec2 upper = tbMulAdd(fA.p, p->upperTranslation, axis);
		tbDrawLine(draw, lower, upper, tb_colorJoint);
		tbDrawLine(draw, tbSub(lower, perp), tbAdd(lower, perp), tb_colorJoint);
		tbDrawLine(draw, tbSub(upper, perp), tbAdd(upper, perp), tb_colorJoint);
	}
	else
	{
		tbDrawLine(draw, tbMulSub(fA.p, 0.5f * joint->drawScale, axis), tbMulAdd(fA.p, 0.5f * joint->drawScale, axis),
						  tb_colorJoint);
	}
	tbDrawLine(draw, fA.p, pB, tb_colorNormal);
}

// --- getters and setters -----------------------------------------------------------------------

void tbPrismaticJoint_EnableSpring(tbJointId jointId, bool enableSpring)
{
	TB_RECORD(PrismaticJointEnableSpring, &jointId, &enableSpring);
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_EnableSpring", &world, true);
	if (joint != NULL && joint->prismatic.enableSpring != enableSpring)
	{
		joint->prismatic.enableSpring = enableSpring;
		joint->prismatic.springImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbPrismaticJoint_IsSpringEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_IsSpringEnabled", NULL, false);
	return joint != NULL && joint->prismatic.enableSpring;
}

bool tbPrismaticJoint_SetSpringHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(PrismaticJointSetSpringHertz, &jointId, &hertz);
	const char* f = "tbPrismaticJoint_SetSpringHertz";
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "hertz", hertz) == false)
	{
		return false;
	}
	joint->prismatic.hertz = hertz;
	tbWakeJoint(world, joint);
	return true;
}

float tbPrismaticJoint_GetSpringHertz(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetSpringHertz", NULL, false);
	return joint != NULL ? joint->prismatic.hertz : 0.0f;
}

bool tbPrismaticJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio)
{
	TB_RECORD(PrismaticJointSetSpringDampingRatio, &jointId, &dampingRatio);
	const char* f = "tbPrismaticJoint_SetSpringDampingRatio";
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "dampingRatio", dampingRatio) == false)
	{
		return false;
	}
	joint->prismatic.dampingRatio = dampingRatio;
	tbWakeJoint(world, joint);
	return true;
}

float tbPrismaticJoint_GetSpringDampingRatio(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetSpringDampingRatio", NULL, false);
	return joint != NULL ? joint->prismatic.dampingRatio : 0.0f;
}

bool tbPrismaticJoint_SetTargetTranslation(tbJointId jointId, float translation)
{
	TB_RECORD(PrismaticJointSetTargetTranslation, &jointId, &translation);
	const char* f = "tbPrismaticJoint_SetTargetTranslation";
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, f, &world, true);
	if (joint == NULL || tbCheckFloat(f, "translation", translation) == false)
	{
		return false;
	}
	joint->prismatic.targetTranslation = translation;
	tbWakeJoint(world, joint);
	return true;
}

float tbPrismaticJoint_GetTargetTranslation(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetTargetTranslation", NULL, false);
	return joint != NULL ? joint->prismatic.targetTranslation : 0.0f;
}

void tbPrismaticJoint_EnableLimit(tbJointId jointId, bool enableLimit)
{
	TB_RECORD(PrismaticJointEnableLimit, &jointId, &enableLimit);
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_EnableLimit", &world, true);
	if (joint != NULL && joint->prismatic.enableLimit != enableLimit)
	{
		joint->prismatic.enableLimit = enableLimit;
		joint->prismatic.lowerImpulse = 0.0f;
		joint->prismatic.upperImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbPrismaticJoint_IsLimitEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_IsLimitEnabled", NULL, false);
	return joint != NULL && joint->prismatic.enableLimit;
}

float tbPrismaticJoint_GetLowerLimit(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetLowerLimit", NULL, false);
	return joint != NULL ? joint->prismatic.lowerTranslation : 0.0f;
}

float tbPrismaticJoint_GetUpperLimit(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetUpperLimit", NULL, false);
	return joint != NULL ? joint->prismatic.upperTranslation : 0.0f;
}

bool tbPrismaticJoint_SetLimits(tbJointId jointId, float lower, float upper)
{
	TB_RECORD(PrismaticJointSetLimits, &jointId, &lower, &upper);
	const char* f = "tbPrismaticJoint_SetLimits";
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, f, &world, true);
	if (joint == NULL || tbCheckRange(f, "lower", lower, "upper", upper) == false)
	{
		return false;
	}
	joint->prismatic.lowerTranslation = lower;
	joint->prismatic.upperTranslation = upper;
	tbWakeJoint(world, joint);
	return true;
}

void tbPrismaticJoint_EnableMotor(tbJointId jointId, bool enableMotor)
{
	TB_RECORD(PrismaticJointEnableMotor, &jointId, &enableMotor);
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_EnableMotor", &world, true);
	if (joint != NULL && joint->prismatic.enableMotor != enableMotor)
	{
		joint->prismatic.enableMotor = enableMotor;
		joint->prismatic.motorImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbPrismaticJoint_IsMotorEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_IsMotorEnabled", NULL, false);
	return joint != NULL && joint->prismatic.enableMotor;
}

bool tbPrismaticJoint_SetMotorSpeed(tbJointId jointId, float motorSpeed)
{
	TB_RECORD(PrismaticJointSetMotorSpeed, &jointId, &motorSpeed);
	const char* f = "tbPrismaticJoint_SetMotorSpeed";
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, f, &world, true);
	if (joint == NULL || tbCheckFloat(f, "motorSpeed", motorSpeed) == false)
	{
		return false;
	}
	joint->prismatic.motorSpeed = motorSpeed;
	tbWakeJoint(world, joint);
	return true;
}

float tbPrismaticJoint_GetMotorSpeed(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetMotorSpeed", NULL, false);
	return joint != NULL ? joint->prismatic.motorSpeed : 0.0f;
}

bool tbPrismaticJoint_SetMaxMotorForce(tbJointId jointId, float force)
{
	TB_RECORD(PrismaticJointSetMaxMotorForce, &jointId, &force);
	const char* f = "tbPrismaticJoint_SetMaxMotorForce";
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "force", force) == false)
	{
		return false;
	}
	joint->prismatic.maxMotorForce = force;
	tbWakeJoint(world, joint);
	return true;
}

float tbPrismaticJoint_GetMaxMotorForce(tbJointId jointId)
{
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetMaxMotorForce", NULL, false);
	return joint != NULL ? joint->prismatic.maxMotorForce : 0.0f;
}

float tbPrismaticJoint_GetMotorForce(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetMotorForce", &world, false);
	return joint != NULL ? world->jointInvH * joint->prismatic.motorImpulse : 0.0f;
}

float tbPrismaticJoint_GetTranslation(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetTranslation", &world, false);
	if (joint == NULL)
	{
		return 0.0f;
	}
	tbWorldTransform fA = tbJointWorldFrameA(world, joint);
	tbPos pB = tbJointWorldFrameB(world, joint).p;
	return tbDot(tbSubPos(pB, fA.p), tbRot_GetXAxis(fA.q));
}

float tbPrismaticJoint_GetSpeed(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetPrismatic(jointId, "tbPrismaticJoint_GetSpeed", &world, false);
	if (joint == NULL)
	{
		return 0.0f;
	}
	// x = a·d with the axis a turning with body A: ẋ = (ωA × a)·d + a·(vB + ωB × rB − vA − ωA × rA).
	const tbBody* a = world->bodies + joint->edges[0].bodyId;
	const tbBody* b = world->bodies + joint->edges[1].bodyId;
	tbWorldTransform fA = tbJointWorldFrameA(world, joint);
	tbPos pB = tbJointWorldFrameB(world, joint).p;
	tbVec2 axis = tbRot_GetXAxis(fA.q);
	tbVec2 rA = tbSubPos(fA.p, a->center);
	tbVec2 rB = tbSubPos(pB, b->center);
	tbVec2 d = tbSubPos(pB, fA.p);
	tbVec2 vA = tbAdd(a->linearVelocity, tbCrossSV(a->angularVelocity, rA));
	tbVec2 vB = tbAdd(b->linearVelocity, tbCrossSV(b->angularVelocity, rB));
	return tbDot(d, tbCrossSV(a->angularVelocity, axis)) + tbDot(axis, tbSub(vB, vA));
}

/// With a the axis (frame A's x-axis) and p = anchor B − anchor A: the offset across the axis
/// |perp(a)·p| must be zero, and the translation a·p must lie in [lower, upper] when the limit is
/// on; the two errors are orthogonal, so they combine as √(across² + beyond²).
float tbAxisJointLinearSeparation(const tbWorld* world, const tbJoint* joint, bool enableLimit, float lower, float upper)
{
	tbWorldTransform fA = tbJointWorldFrameA(world, joint);
	tbVec2 p = tbSubPos(tbJointWorldFrameB(world, joint).p, fA.p);
	tbVec2 axis = tbRot_GetXAxis(fA.q);
	float across = tbDot(tbLeftPerp(axis), p);
	float beyond = 0.0f;
	if (enableLimit)
	{
		float translation = tbDot(axis, p);
		beyond = translation < lower ? lower - translation : (translation > upper ? translation - upper : 0.0f);
	}
	return sqrtf(across * across + beyond * beyond);
}

/// The frames may not turn relative to each other: their relative angle (signed, as Box2D v3.2).
float tbPrismaticJointAngularSeparation(const tbWorld* world, const tbJoint* joint)
{
	return tbRelativeAngle(tbJointWorldFrameA(world, joint).q, tbJointWorldFrameB(world, joint).q);
}
