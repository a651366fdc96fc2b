// Motor joint: velocity control and capped springs between two frames. With body A static and
// frame A moved by the game each step, it drags body B (how Box2D v3.2 replaces the mouse joint).
//
// Angular rows, Ċ = ωB − ωA, K = IA⁻¹ + IB⁻¹:
// - spring: C = θ (frame B relative to frame A), a soft constraint with angularHertz and
//   angularDampingRatio (Catto, "Soft Constraints", GDC 2011), accumulated |λ| ≤ h·maxSpringTorque;
// - velocity: Ċ − angularVelocity = 0, accumulated |λ| ≤ h·maxVelocityTorque.
// Linear rows at the frame origins, Ċ = vB + ωB × rB − vA − ωA × rA (2-vector), K the revolute
// joint's 2×2 point matrix:
// - spring: C = (cB + rB) − (cA + rA), soft with linearHertz, the accumulated impulse vector
//   clamped to length h·maxSpringForce (a disc: the cap holds in every direction);
// - velocity: Ċ − linearVelocity = 0, accumulated impulse clamped to length h·maxVelocityForce.
// A spring or velocity row with zero cap (or a spring with zero hertz) is off. Every row acts in
// every pass: these are user forces, not constraints with a position error to relax.
// Reference: Catto, "Soft Constraints", GDC 2011; Box2D v3.2's motor joint.
#include "joint.h"
#include "world/recording.h"

static tbJoint* tbGetMotor(tbJointId id, const char* f, tbWorld** world, bool mutating)
{
	return tbGetJointChecked(id, f, world, tb_motorJoint, mutating);
}

static bool tbCheckMotorDef(const char* f, const tbMotorJointDef* def)
{
	return tbCheckVec2(f, "def->linearVelocity", def->linearVelocity) &&
		   tbCheckNonNegative(f, "def->maxVelocityForce", def->maxVelocityForce) &&
		   tbCheckFloat(f, "def->angularVelocity", def->angularVelocity) &&
		   tbCheckNonNegative(f, "def->maxVelocityTorque", def->maxVelocityTorque) &&
		   tbCheckNonNegative(f, "def->linearHertz", def->linearHertz) &&
		   tbCheckNonNegative(f, "def->linearDampingRatio", def->linearDampingRatio) &&
		   tbCheckNonNegative(f, "def->maxSpringForce", def->maxSpringForce) &&
		   tbCheckNonNegative(f, "def->angularHertz", def->angularHertz) &&
		   tbCheckNonNegative(f, "def->angularDampingRatio", def->angularDampingRatio) &&
		   tbCheckNonNegative(f, "def->maxSpringTorque", def->maxSpringTorque);
}

tbJointId tbCreateMotorJoint(tbWorldId worldId, const tbMotorJointDef* def)
{
	TB_RECORD(CreateMotorJoint, &worldId, def);
	const char* f = "tbCreateMotorJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultMotorJointDef") == false ||
		tbCheckMotorDef(f, def) == false)
	{
		return id;
	}
	tbJoint* joint = tbCreateJointInternal(worldId, &def->base, tb_motorJoint, f, &id);
	if (joint == NULL)
	{
		return id;
	}
	tbMotorJoint* m = &joint->motor;
	m->linearVelocity = def->linearVelocity;
	m->maxVelocityForce = def->maxVelocityForce;
	m->angularVelocity = def->angularVelocity;
	m->maxVelocityTorque = def->maxVelocityTorque;
	m->linearHertz = def->linearHertz;
	m->linearDampingRatio = def->linearDampingRatio;
	m->maxSpringForce = def->maxSpringForce;
	m->angularHertz = def->angularHertz;
	m->angularDampingRatio = def->angularDampingRatio;
	m->maxSpringTorque = def->maxSpringTorque;
	return id;
}

// --- the step ----------------------------------------------------------------------------------

void tbPrepareMotorJoint(tbJoint* joint, const tbStepContext* context)
{
	tbMotorJoint* m = &joint->motor;
	m->linearSpring = tbMakeSoftness(m->linearHertz, m->linearDampingRatio, context->h);
	m->angularSpring = tbMakeSoftness(m->angularHertz, m->angularDampingRatio, context->h);
	float k = joint->invIA + joint->invIB;
	m->angularMass = k > 0.0f ? 1.0f / k : 0.0f;
	if (context->enableWarmStarting == false)
	{
		m->linearVelocityImpulse = tbVec2_zero;
		m->linearSpringImpulse = tbVec2_zero;
		m->angularVelocityImpulse = 0.0f;
		m->angularSpringImpulse = 0.0f;
	}
}

void tbWarmStartMotorJoint(tbJoint* joint, tbStepContext* context)
{
	const tbMotorJoint* m = &joint->motor;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 rA, rB, d;
	tbJointAnchors(joint, &b, &rA, &rB, &d);
	tbVec2 linear = tbAdd(m->linearVelocityImpulse, m->linearSpringImpulse);
	float angular = m->angularVelocityImpulse + m->angularSpringImpulse;
	tbApplyJointImpulse(joint, &b, rA, rB, linear, angular);
	tbStoreJointBodies(joint, &b);
}

// Add `impulse` to an accumulated impulse vector whose length is capped: returns what was applied.
static tbVec2 tbAccumulateCapped(tbVec2* accumulated, tbVec2 impulse, float maxLength)
{
	tbVec2 old = *accumulated;
	tbVec2 total = tbAdd(old, impulse);
	if (tbLengthSquared(total) > maxLength * maxLength)
	{
		total = tbMulSV(maxLength, tbNormalize(total));
	}
	*accumulated = total;
	return tbSub(total, old);
}

static float tbAccumulateClamped(float* accumulated, float impulse, float maxImpulse)
{
	float old = *accumulated;
	*accumulated = tbClampFloat(old + impulse, -maxImpulse, maxImpulse);
	return *accumulated - old;
}

static void tbSolveMotorAngular(tbJoint* joint, tbJointBodies* b, const tbStepContext* context)
{
	tbMotorJoint* m = &joint->motor;
	float iA = joint->invIA, iB = joint->invIB;
	if (m->maxSpringTorque > 0.0f && m->angularHertz > 0.0f)
	{
		tbRot qA = tbMulRot(b->sA->deltaRotation, joint->frameA.q);
		tbRot qB = tbMulRot(b->sB->deltaRotation, joint->frameB.q);
		float C = tbRelativeAngle(qA, qB);
		tbSoftness s = m->angularSpring;
		float impulse =
			-s.massScale * m->angularMass * (b->wB - b->wA + s.biasRate * C) - s.impulseScale * m->angularSpringImpulse;
		impulse = tbAccumulateClamped(&m->angularSpringImpulse, impulse, context->h * m->maxSpringTorque);
		b->wA -= iA * impulse;
		b->wB += iB * impulse;
	}
	if (m->maxVelocityTorque > 0.0f)
	{
		float impulse = -m->angularMass * (b->wB - b->wA - m->angularVelocity);
		impulse = tbAccumulateClamped(&m->angularVelocityImpulse, impulse, context->h * m->maxVelocityTorque);
		b->wA -= iA * impulse;
		b->wB += iB * impulse;
	}
}

void tbSolveMotorJoint(tbJoint* joint, tbStepContext* context, bool useBias)
{
	(void)useBias; // every row is a user force, the same in every pass
	tbMotorJoint* m = &joint->motor;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbSolveMotorAngular(joint, &b, context);

	tbVec2 rA, rB, C;
	tbJointAnchors(joint, &b, &rA, &rB, &C);
	float mA = joint->invMassA, mB = joint->invMassB, iA = joint->invIA, iB = joint->invIB;
	tbMat22 K;
	K.cx.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
	K.cy.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
	K.cx.y = K.cy.x;
	K.cy.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
	if (m->maxSpringForce > 0.0f && m->linearHertz > 0.0f)
	{
		tbSoftness s = m->linearSpring;
		tbVec2 Cdot = tbSub(tbAdd(b.vB, tbCrossSV(b.wB, rB)), tbAdd(b.vA, tbCrossSV(b.wA, rA)));
		tbVec2 x = tbSolve22(K, tbMulAdd(Cdot, s.biasRate, C));
		tbVec2 impulse = {-s.massScale * x.x - s.impulseScale * m->linearSpringImpulse.x,
						  -s.massScale * x.y - s.impulseScale * m->linearSpringImpulse.y};
		impulse = tbAccumulateCapped(&m->linearSpringImpulse, impulse, context->h * m->maxSpringForce);
		tbApplyJointImpulse(joint, &b, rA, rB, impulse, 0.0f);
	}
	if (m->maxVelocityForce > 0.0f)
	{
		tbVec2 Cdot = tbSub(tbAdd(b.vB, tbCrossSV(b.wB, rB)), tbAdd(b.vA, tbCrossSV(b.wA, rA)));
		tbVec2 x = tbSolve22(K, tbSub(Cdot, m->linearVelocity));
		tbVec2 impulse = tbAccumulateCapped(&m->linearVelocityImpulse, tbNeg(x), context->h * m->maxVelocityForce);
		tbApplyJointImpulse(joint, &b, rA, rB, impulse, 0.0f);
	}
	tbStoreJointBodies(joint, &b);
}

void tbGetMotorJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	(void)world;
	const tbMotorJoint* m = &joint->motor;
	*force = tbMulSV(inv_h, tbAdd(m->linearVelocityImpulse, m->linearSpringImpulse));
	*torque = inv_h * (m->angularVelocityImpulse + m->angularSpringImpulse);
}

void tbDrawMotorJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint)
{
	tbTransform fA = tbRoundTransform(tbJointWorldFrameA(world, joint));
	tbTransform fB = tbRoundTransform(tbJointWorldFrameB(world, joint));
	float s = 0.25f * joint->drawScale;
	tbDrawLine(draw, fA.p, tbMulAdd(fA.p, s, tbRot_GetXAxis(fA.q)), tb_colorJoint);
	tbDrawLine(draw, fB.p, tbMulAdd(fB.p, s, tbRot_GetXAxis(fB.q)), tb_colorNormal);
	tbDrawLine(draw, fA.p, fB.p, tb_colorTree);
}

// --- getters and setters -----------------------------------------------------------------------

bool tbMotorJoint_SetLinearVelocity(tbJointId jointId, tbVec2 velocity)
{
	TB_RECORD(MotorJointSetLinearVelocity, &jointId, &velocity);
	const char* f = "tbMotorJoint_SetLinearVelocity";
	tbWorld* world;
	tbJoint* joint = tbGetMotor(jointId, f, &world, true);
	if (joint == NULL || tbCheckVec2(f, "velocity", velocity) == false)
	{
		return false;
	}
	joint->motor.linearVelocity = velocity;
	tbWakeJoint(world, joint);
	return true;
}

tbVec2 tbMotorJoint_GetLinearVelocity(tbJointId jointId)
{
	tbJoint* joint = tbGetMotor(jointId, "tbMotorJoint_GetLinearVelocity", NULL, false);
	return joint != NULL ? joint->motor.linearVelocity : tbVec2_zero;
}

bool tbMotorJoint_SetAngularVelocity(tbJointId jointId, float velocity)
{
	TB_RECORD(MotorJointSetAngularVelocity, &jointId, &velocity);
	const char* f = "tbMotorJoint_SetAngularVelocity";
	tbWorld* world;
	tbJoint* joint = tbGetMotor(jointId, f, &world, true);
	if (joint == NULL || tbCheckFloat(f, "velocity", velocity) == false)
	{
		return false;
	}
	joint->motor.angularVelocity = velocity;
	tbWakeJoint(world, joint);
	return true;
}

float tbMotorJoint_GetAngularVelocity(tbJointId jointId)
{
	tbJoint* joint = tbGetMotor(jointId, "tbMotorJoint_GetAngularVelocity", NULL, false);
	return joint != NULL ? joint->motor.angularVelocity : 0.0f;
}

// The non-negative parameters share one setter and one getter (offset into tbMotorJoint).
static bool tbSetMotorValue(tbJointId jointId, const char* f, const char* name, float value, size_t offset)
{
	tbWorld* world;
	tbJoint* joint = tbGetMotor(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, name, value) == false)
	{
		return false;
	}
	*(float*)((char*)&joint->motor + offset) = value;
	tbWakeJoint(world, joint);
	return true;
}

static float tbGetMotorValue(tbJointId jointId, const char* f, size_t offset)
{
	tbJoint* joint = tbGetMotor(jointId, f, NULL, false);
	return joint != NULL ? *(const float*)((const char*)&joint->motor + offset) : 0.0f;
}

bool tbMotorJoint_SetMaxVelocityForce(tbJointId jointId, float maxForce)
{
	TB_RECORD(MotorJointSetMaxVelocityForce, &jointId, &maxForce);
	return tbSetMotorValue(jointId, "tbMotorJoint_SetMaxVelocityForce", "maxForce", maxForce,
						   offsetof(tbMotorJoint, maxVelocityForce));
}

float tbMotorJoint_GetMaxVelocityForce(tbJointId jointId)
{
	return tbGetMotorValue(jointId, "tbMotorJoint_GetMaxVelocityForce", offsetof(tbMotorJoint, maxVelocityForce));
}

bool tbMotorJoint_SetMaxVelocityTorque(tbJointId jointId, float maxTorque)
{
	TB_RECORD(MotorJointSetMaxVelocityTorque, &jointId, &maxTorque);
	return tbSetMotorValue(jointId, "tbMotorJoint_SetMaxVelocityTorque", "maxTorque", maxTorque,
						   offsetof(tbMotorJoint, maxVelocityTorque));
}

float tbMotorJoint_GetMaxVelocityTorque(tbJointId jointId)
{
	return tbGetMotorValue(jointId, "tbMotorJoint_GetMaxVelocityTorque", offsetof(tbMotorJoint, maxVelocityTorque));
}

bool tbMotorJoint_SetLinearHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(MotorJointSetLinearHertz, &jointId, &hertz);
	return tbSetMotorValue(jointId, "tbMotorJoint_SetLinearHertz", "hertz", hertz, offsetof(tbMotorJoint, linearHertz));
}

float tbMotorJoint_GetLinearHertz(tbJointId jointId)
{
	return tbGetMotorValue(jointId, "tbMotorJoint_GetLinearHertz", offsetof(tbMotorJoint, linearHertz));
}

bool tbMotorJoint_SetLinearDampingRatio(tbJointId jointId, float damping)
{
	TB_RECORD(MotorJointSetLinearDampingRatio, &jointId, &damping);
	return tbSetMotorValue(jointId, "tbMotorJoint_SetLinearDampingRatio", "damping", damping,
						   offsetof(tbMotorJoint, linearDampingRatio));
}

float tbMotorJoint_GetLinearDampingRatio(tbJointId jointId)
{
	return tbGetMotorValue(jointId, "tbMotorJoint_GetLinearDampingRatio", offsetof(tbMotorJoint, linearDampingRatio));
}

bool tbMotorJoint_SetAngularHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(MotorJointSetAngularHertz, &jointId, &hertz);
	return tbSetMotorValue(jointId, "tbMotorJoint_SetAngularHertz", "hertz", hertz,
						   offsetof(tbMotorJoint, angularHertz));
}

float tbMotorJoint_GetAngularHertz(tbJointId jointId)
{
	return tbGetMotorValue(jointId, "tbMotorJoint_GetAngularHertz", offsetof(tbMotorJoint, angularHertz));
}

bool tbMotorJoint_SetAngularDampingRatio(tbJointId jointId, float damping)
{
	TB_RECORD(MotorJointSetAngularDampingRatio, &jointId, &damping);
	return tbSetMotorValue(jointId, "tbMotorJoint_SetAngularDampingRatio", "damping", damping,
						   offsetof(tbMotorJoint, angularDampingRatio));
}

float tbMotorJoint_GetAngularDampingRatio(tbJointId jointId)
{
	return tbGetMotorValue(jointId, "tbMotorJoint_GetAngularDampingRatio", offsetof(tbMotorJoint, angularDampingRatio));
}

bool tbMotorJoint_SetMaxSpringForce(tbJointId jointId, float maxForce)
{
	TB_RECORD(MotorJointSetMaxSpringForce, &jointId, &maxForce);
	return tbSetMotorValue(jointId, "tbMotorJoint_SetMaxSpringForce", "maxForce", maxForce,
						   offsetof(tbMotorJoint, maxSpringForce));
}

float tbMotorJoint_GetMaxSpringForce(tbJointId jointId)
{
	return tbGetMotorValue(jointId, "tbMotorJoint_GetMaxSpringForce", offsetof(tbMotorJoint, maxSpringForce));
}

bool tbMotorJoint_SetMaxSpringTorque(tbJointId jointId, float maxTorque)
{
	TB_RECORD(MotorJointSetMaxSpringTorque, &jointId, &maxTorque);
	return tbSetMotorValue(jointId, "tbMotorJoint_SetMaxSpringTorque", "maxTorque", maxTorque,
						   offsetof(tbMotorJoint, maxSpringTorque));
}

float tbMotorJoint_GetMaxSpringTorque(tbJointId jointId)
{
	return tbGetMotorValue(jointId, "tbMotorJoint_GetMaxSpringTorque", offsetof(tbMotorJoint, maxSpringTorque));
}
