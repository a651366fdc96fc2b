// Wheel joint: body B (a wheel) stays on the line through frame A's origin along its x-axis, moves
// along it on a suspension spring, turns freely and may be driven by a motor.
//
// With the axis geometry of the prismatic joint (tbAxisFrame: axis a, normal p, lever arms a1, a2,
// s1, s2, translation x = a·d; prismatic_joint.c derives them):
// - point on line: C = p·d = 0, Ċ = p·(vB − vA) + s2·ωB − s1·ωA,
//   K = mA⁻¹ + mB⁻¹ + IA⁻¹·s1² + IB⁻¹·s2² (the joint's positional softness in the biased pass);
// - suspension: C = x, the same Ċ along a, K along a; a soft constraint with the user's hertz
//   and damping ratio (Catto, "Soft Constraints", GDC 2011) in every pass;
// - motor: Ċ = ωB − ωA − motorSpeed, K = IA⁻¹ + IB⁻¹, accumulated |λ| ≤ h·maxMotorTorque;
// - limits on x, one-sided rows with speculation (tbSolveAxisLimit).
// Order: motor, spring, limits, then the point-on-line row, which matters most, last.
// Reference: Catto, "Modeling and Solving Constraints", GDC 2009; Box2D v3's wheel joint.
#include "joint.h"
#include "world/recording.h"

static tbJoint* tbGetWheel(tbJointId id, const char* f, tbWorld** world, bool mutating)
{
	return tbGetJointChecked(id, f, world, tb_wheelJoint, mutating);
}

static bool tbCheckWheelDef(const char* f, const tbWheelJointDef* def)
{
	return tbCheckNonNegative(f, "def->hertz", def->hertz) &&
		   tbCheckNonNegative(f, "def->dampingRatio", def->dampingRatio) &&
		   tbCheckRange(f, "def->lowerTranslation", def->lowerTranslation, "def->upperTranslation",
						def->upperTranslation) &&
		   tbCheckNonNegative(f, "def->maxMotorTorque", def->maxMotorTorque) &&
		   tbCheckFloat(f, "def->motorSpeed", def->motorSpeed);
}

tbJointId tbCreateWheelJoint(tbWorldId worldId, const tbWheelJointDef* def)
{
	TB_RECORD(CreateWheelJoint, &worldId, def);
	const char* f = "tbCreateWheelJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultWheelJointDef") == false ||
		tbCheckWheelDef(f, def) == false)
	{
		return id;
	}
	tbJoint* joint = tbCreateJointInternal(worldId, &def->base, tb_wheelJoint, f, &id);
	if (joint == NULL)
	{
		return id;
	}
	tbWheelJoint* w = &joint->wheel;
	w->enableSpring = def->enableSpring;
	w->hertz = def->hertz;
	w->dampingRatio = def->dampingRatio;
	w->enableLimit = def->enableLimit;
	w->lowerTranslation = def->lowerTranslation;
	w->upperTranslation = def->upperTranslation;
	w->enableMotor = def->enableMotor;
	w->maxMotorTorque = def->maxMotorTorque;
	w->motorSpeed = def->motorSpeed;
	return id;
}

// --- the step ----------------------------------------------------------------------------------

void tbPrepareWheelJoint(tbJoint* joint, const tbStepContext* context)
{
	tbWheelJoint* w = &joint->wheel;
	float k = joint->invIA + joint->invIB;
	w->motorMass = k > 0.0f ? 1.0f / k : 0.0f;
	w->springSoftness = tbMakeSoftness(w->hertz, w->dampingRatio, context->h);
	if (context->enableWarmStarting == false)
	{
		w->perpImpulse = 0.0f;
		w->springImpulse = 0.0f;
		w->motorImpulse = 0.0f;
		w->lowerImpulse = 0.0f;
		w->upperImpulse = 0.0f;
	}
}

void tbWarmStartWheelJoint(tbJoint* joint, tbStepContext* context)
{
	const tbWheelJoint* w = &joint->wheel;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbAxisFrame g = tbMakeAxisFrame(joint, &b);
	float axial = w->springImpulse + w->lowerImpulse - w->upperImpulse;
	tbApplyAxisImpulse(joint, &b, &g, axial, w->perpImpulse, w->motorImpulse);
	tbStoreJointBodies(joint, &b);
}

static void tbSolveWheelAxis(tbJoint* joint, tbJointBodies* b, const tbAxisFrame* g, const tbStepContext* context,
							 bool useBias)
{
	tbWheelJoint* w = &joint->wheel;
	if (w->enableMotor && joint->invIA + joint->invIB > 0.0f)
	{
		float impulse = -w->motorMass * (b->wB - b->wA - w->motorSpeed);
		float maxImpulse = context->h * w->maxMotorTorque;
		float newImpulse = tbClampFloat(w->motorImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - w->motorImpulse;
		w->motorImpulse = newImpulse;
		b->wA -= joint->invIA * impulse;
		b->wB += joint->invIB * impulse;
	}
	float axialMass = tbAxialMassOf(joint, g);
	if (w->enableSpring && w->hertz > 0.0f)
	{
		tbSoftness s = w->springSoftness;
		float C = g->translation;
		float impulse = -s.massScale * axialMass * (tbAxialSpeedOf(b, g) + s.biasRate * C) - s.impulseScale * w->springImpulse;
		w->springImpulse += impulse;
		tbApplyAxisImpulse(joint, b, g, impulse, 0.0f, 0.0f);
	}
	if (w->enableLimit)
	{
		tbSolveAxisLimit(joint, b, g, axialMass, g->translation - w->lowerTranslation, 1.0f, &w->lowerImpulse, context,
						 useBias);
		tbSolveAxisLimit(joint, b, g, axialMass, w->upperTranslation - g->translation, -1.0f, &w->upperImpulse, context,
						 useBias);
	}
}

void tbSolveWheelJoint(tbJoint* joint, tbStepContext* context, bool useBias)
{
	tbWheelJoint* w = &joint->wheel;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbAxisFrame g = tbMakeAxisFrame(joint, &b);
	tbSolveWheelAxis(joint, &b, &g, context, useBias);
	if (joint->solvedInTree)
	{
		tbStoreJointBodies(joint, &b); // the line is solved with its tree (joint_tree.c)
		return;
	}

	// Point on line.
	tbSoftness soft = {0.0f, 1.0f, 0.0f};
	if (useBias)
	{
		soft = joint->constraintSoftness;
	}
	float C = tbDot(g.perp, g.d);
	float Cdot = tbDot(g.perp, tbSub(b.vB, b.vA)) + g.s2 * b.wB - g.s1 * b.wA;
	float k = joint->invMassA + joint->invMassB + joint->invIA * g.s1 * g.s1 + joint->invIB * g.s2 * g.s2;
	float perpMass = k > 0.0f ? 1.0f / k : 0.0f;
	float impulse = -soft.massScale * perpMass * (Cdot + soft.biasRate * C) - soft.impulseScale * w->perpImpulse;
	w->perpImpulse += impulse;
	tbApplyAxisImpulse(joint, &b, &g, 0.0f, impulse, 0.0f);
	tbStoreJointBodies(joint, &b);
}

// The point-on-line row (see the header comment).
int tbWheelJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows)
{
	tbAxisFrame g = tbMakeAxisFrame(joint, b);
	tbSetJointRow(rows, 0, (tbVec3Row){-g.perp.x, -g.perp.y, -g.s1}, (tbVec3Row){g.perp.x, g.perp.y, g.s2},
				  tbDot(g.perp, g.d), &joint->wheel.perpImpulse);
	return 1;
}

void tbGetWheelJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	const tbWheelJoint* w = &joint->wheel;
	tbVec2 axis = tbRot_GetXAxis(tbJointWorldFrameA(world, joint).q);
	tbVec2 perp = tbLeftPerp(axis);
	float axial = w->springImpulse + w->lowerImpulse - w->upperImpulse;
	*force = tbMulSV(inv_h, tbAdd(tbMulSV(axial, axis), tbMulSV(w->perpImpulse, perp)));
	*torque = inv_h * w->motorImpulse;
}

void tbDrawWheelJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint)
{
	const tbWheelJoint* w = &joint->wheel;
	tbTransform fA = tbRoundTransform(tbJointWorldFrameA(world, joint));
	tbVec2 pB = tbToVec2(tbJointWorldFrameB(world, joint).p);
	tbVec2 axis = tbRot_GetXAxis(fA.q);
	float lower = w->enableLimit ? w->lowerTranslation : -0.5f * joint->drawScale;
	float upper = w->enableLimit ? w->upperTranslation : 0.5f * joint->drawScale;
	tbDrawLine(draw, tbMulAdd(fA.p, lower, axis), tbMulAdd(fA.p, upper, axis), tb_colorJoint);
	tbDrawLine(draw, fA.p, pB, tb_colorNormal);
	if (draw->DrawPointFcn != NULL)
	{
		tbDrawPointAt(draw, pB, 4.0f, tb_colorJoint);
	}
}

// --- getters and setters -----------------------------------------------------------------------

void tbWheelJoint_EnableSpring(tbJointId jointId, bool enableSpring)
{
	TB_RECORD(WheelJointEnableSpring, &jointId, &enableSpring);
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_EnableSpring", &world, true);
	if (joint != NULL && joint->wheel.enableSpring != enableSpring)
	{
		joint->wheel.enableSpring = enableSpring;
		joint->wheel.springImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbWheelJoint_IsSpringEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_IsSpringEnabled", NULL, false);
	return joint != NULL && joint->wheel.enableSpring;
}

bool tbWheelJoint_SetSpringHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(WheelJointSetSpringHertz, &jointId, &hertz);
	const char* f = "tbWheelJoint_SetSpringHertz";
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "hertz", hertz) == false)
	{
		return false;
	}
	joint->wheel.hertz = hertz;
	tbWakeJoint(world, joint);
	return true;
}

float tbWheelJoint_GetSpringHertz(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_GetSpringHertz", NULL, false);
	return joint != NULL ? joint->wheel.hertz : 0.0f;
}

bool tbWheelJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio)
{
	TB_RECORD(WheelJointSetSpringDampingRatio, &jointId, &dampingRatio);
	const char* f = "tbWheelJoint_SetSpringDampingRatio";
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "dampingRatio", dampingRatio) == false)
	{
		return false;
	}
	joint->wheel.dampingRatio = dampingRatio;
	tbWakeJoint(world, joint);
	return true;
}

float tbWheelJoint_GetSpringDampingRatio(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_GetSpringDampingRatio", NULL, false);
	return joint != NULL ? joint->wheel.dampingRatio : 0.0f;
}

void tbWheelJoint_EnableLimit(tbJointId jointId, bool enableLimit)
{
	TB_RECORD(WheelJointEnableLimit, &jointId, &enableLimit);
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_EnableLimit", &world, true);
	if (joint != NULL && joint->wheel.enableLimit != enableLimit)
	{
		joint->wheel.enableLimit = enableLimit;
		joint->wheel.lowerImpulse = 0.0f;
		joint->wheel.upperImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbWheelJoint_IsLimitEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_IsLimitEnabled", NULL, false);
	return joint != NULL && joint->wheel.enableLimit;
}

float tbWheelJoint_GetLowerLimit(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_GetLowerLimit", NULL, false);
	return joint != NULL ? joint->wheel.lowerTranslation : 0.0f;
}

float tbWheelJoint_GetUpperLimit(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_GetUpperLimit", NULL, false);
	return joint != NULL ? joint->wheel.upperTranslation : 0.0f;
}

bool tbWheelJoint_SetLimits(tbJointId jointId, float lower, float upper)
{
	TB_RECORD(WheelJointSetLimits, &jointId, &lower, &upper);
	const char* f = "tbWheelJoint_SetLimits";
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, f, &world, true);
	if (joint == NULL || tbCheckRange(f, "lower", lower, "upper", upper) == false)
	{
		return false;
	}
	joint->wheel.lowerTranslation = lower;
	joint->wheel.upperTranslation = upper;
	tbWakeJoint(world, joint);
	return true;
}

void tbWheelJoint_EnableMotor(tbJointId jointId, bool enableMotor)
{
	TB_RECORD(WheelJointEnableMotor, &jointId, &enableMotor);
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_EnableMotor", &world, true);
	if (joint != NULL && joint->wheel.enableMotor != enableMotor)
	{
		joint->wheel.enableMotor = enableMotor;
		joint->wheel.motorImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbWheelJoint_IsMotorEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_IsMotorEnabled", NULL, false);
	return joint != NULL && joint->wheel.enableMotor;
}

bool tbWheelJoint_SetMotorSpeed(tbJointId jointId, float motorSpeed)
{
	TB_RECORD(WheelJointSetMotorSpeed, &jointId, &motorSpeed);
	const char* f = "tbWheelJoint_SetMotorSpeed";
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, f, &world, true);
	if (joint == NULL || tbCheckFloat(f, "motorSpeed", motorSpeed) == false)
	{
		return false;
	}
	joint->wheel.motorSpeed = motorSpeed;
	tbWakeJoint(world, joint);
	return true;
}

float tbWheelJoint_GetMotorSpeed(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_GetMotorSpeed", NULL, false);
	return joint != NULL ? joint->wheel.motorSpeed : 0.0f;
}

bool tbWheelJoint_SetMaxMotorTorque(tbJointId jointId, float torque)
{
	TB_RECORD(WheelJointSetMaxMotorTorque, &jointId, &torque);
	const char* f = "tbWheelJoint_SetMaxMotorTorque";
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "torque", torque) == false)
	{
		return false;
	}
	joint->wheel.maxMotorTorque = torque;
	tbWakeJoint(world, joint);
	return true;
}

float tbWheelJoint_GetMaxMotorTorque(tbJointId jointId)
{
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_GetMaxMotorTorque", NULL, false);
	return joint != NULL ? joint->wheel.maxMotorTorque : 0.0f;
}

float tbWheelJoint_GetMotorTorque(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetWheel(jointId, "tbWheelJoint_GetMotorTorque", &world, false);
	return joint != NULL ? world->jointInvH * joint->wheel.motorImpulse : 0.0f;
}
