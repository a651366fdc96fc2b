// Revolute joint: a point of body B pinned to a point of body A; the bodies turn about it, with an
// optional angular spring, motor and limits.
//
// Point constraint (two rows). With anchors rA, rB from the centres of mass:
//     C = (cB + rB) − (cA + rA) = 0,  Ċ = vB + ωB × rB − vA − ωA × rA,
//     J = [−I, −skew(rA), I, skew(rB)],  skew(r)·ω = ω × r = ω·(−r.y, r.x),
//     K = J·M⁻¹·Jᵀ = (mA⁻¹ + mB⁻¹)·I + IA⁻¹·[rA.y², −rA.x·rA.y; −rA.x·rA.y, rA.x²] + (same for B),
// solved as a 2×2 block, λ = −K⁻¹(Ċ + bias). The position error C is read from the position deltas
// of the step: C = Δc_B − Δc_A + (cB0 − cA0) + rB − rA, the anchors rotated by each body's
// rotation since the start of the step.
//
// Angular rows. θ = angle of frame B relative to frame A (frames rotate with their bodies), and
//     Ċ = ωB − ωA,  J = [0, −1, 0, 1],  K = IA⁻¹ + IB⁻¹.
// - spring towards targetAngle: C = θ − θ_target (unwound), a soft constraint with the user's
//   hertz and damping ratio (Catto, "Soft Constraints", GDC 2011), in every pass;
// - motor: Ċ = ωB − ωA − motorSpeed, accumulated |λ| ≤ h·maxMotorTorque (friction-like);
// - limits, one-sided: C = θ − lower ≥ 0 and C = upper − θ ≥ 0, accumulated λ ≥ 0; a limit not
//   yet reached gets the speculative bias C/h (it may be closed in one sub-step, not passed).
// Order: spring, motor, limits, then the point constraint, which matters most, last.
// Reference: Catto, "Modeling and Solving Constraints", GDC 2009; Box2D v3's revolute joint.
#include "joint.h"

#include "core/arctangent.h"

#include <math.h>
#include "world/recording.h"

static tbJoint* tbGetRevolute(tbJointId id, const char* f, tbWorld** world, bool mutating)
{
	return tbGetJointChecked(id, f, world, tb_revoluteJoint, mutating);
}

static bool tbCheckRevoluteAngles(const char* f, const char* lowerName, float lower, const char* upperName, float upper)
{
	if (tbCheckRange(f, lowerName, lower, upperName, upper) == false)
	{
		return false;
	}
	if (lower < -TB_PI || upper > TB_PI)
	{
		tbReportError(f, "%s is %g and %s is %g; revolute limits lie in [-pi, pi] radians", lowerName, (double)lower,
					  upperName, (double)upper);
		return false;
	}
	return true;
}

static bool tbCheckRevoluteDef(const char* f, const tbRevoluteJointDef* def)
{
	return tbCheckFloat(f, "def->targetAngle", def->targetAngle) &&
		   tbCheckNonNegative(f, "def->hertz", def->hertz) &&
		   tbCheckNonNegative(f, "def->dampingRatio", def->dampingRatio) &&
		   tbCheckRevoluteAngles(f, "def->lowerAngle", def->lowerAngle, "def->upperAngle", def->upperAngle) &&
		   tbCheckNonNegative(f, "def->maxMotorTorque", def->maxMotorTorque) &&
		   tbCheckFloat(f, "def->motorSpeed", def->motorSpeed);
}

// Box2D v3 keeps limits within ±0.99π: at ±π the two limits meet through the wrap of the angle.
static float tbClampLimitAngle(float angle)
{
	return tbClampFloat(angle, -0.99f * TB_PI, 0.99f * TB_PI);
}

tbJointId tbCreateRevoluteJoint(tbWorldId worldId, const tbRevoluteJointDef* def)
{
	TB_RECORD(CreateRevoluteJoint, &worldId, def);
	const char* f = "tbCreateRevoluteJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultRevoluteJointDef") == false ||
		tbCheckRevoluteDef(f, def) == false)
	{
		return id;
	}
	tbJoint* joint = tbCreateJointInternal(worldId, &def->base, tb_revoluteJoint, f, &id);
	if (joint == NULL)
	{
		return id;
	}
	tbRevoluteJoint* r = &joint->revolute;
	r->targetAngle = tbClampFloat(def->targetAngle, -TB_PI, TB_PI);
	r->enableSpring = def->enableSpring;
	r->hertz = def->hertz;
	r->dampingRatio = def->dampingRatio;
	r->enableLimit = def->enableLimit;
	r->lowerAngle = tbClampLimitAngle(def->lowerAngle);
	r->upperAngle = tbClampLimitAngle(def->upperAngle);
	r->enableMotor = def->enableMotor;
	r->maxMotorTorque = def->maxMotorTorque;
	r->motorSpeed = def->motorSpeed;
	return id;
}

// --- the step ----------------------------------------------------------------------------------

void tbPrepareRevoluteJoint(tbJoint* joint, const tbStepContext* context)
{
	tbRevoluteJoint* r = &joint->revolute;
	float k = joint->invIA + joint->invIB;
	r->axialMass = k > 0.0f ? 1.0f / k : 0.0f;
	r->springSoftness = tbMakeSoftness(r->hertz, r->dampingRatio, context->h);
	if (context->enableWarmStarting == false)
	{
		r->linearImpulse = tbVec2_zero;
		r->springImpulse = 0.0f;
		r->motorImpulse = 0.0f;
		r->lowerImpulse = 0.0f;
		r->upperImpulse = 0.0f;
	}
}

void tbWarmStartRevoluteJoint(tbJoint* joint, tbStepContext* context)
{
	const tbRevoluteJoint* r = &joint->revolute;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 rA, rB, d;
	tbJointAnchors(joint, &b, &rA, &rB, &d);
	float axialImpulse = r->springImpulse + r->motorImpulse + r->lowerImpulse - r->upperImpulse;
	tbApplyJointImpulse(joint, &b, rA, rB, r->linearImpulse, axialImpulse);
	tbStoreJointBodies(joint, &b);
}

// Angle of frame B relative to frame A now: the frames at the start of the step turned by each
// body's rotation since.
static TB_FORCE_INLINE float tbRevoluteAngle(const tbJoint* joint, const tbJointBodies* b)
{
	tbRot qA = tbMulRot(b->sA->deltaRotation, joint->frameA.q);
	tbRot qB = tbMulRot(b->sB->deltaRotation, joint->frameB.q);
	tbRot relative = tbInvMulRot(qA, qB); // tbRelativeAngle's sine and cosine
	return tbArctangent(relative.s, relative.c);
}

// One side of the limit. sign = +1: C = θ − lower, sign = −1: C = upper − θ; the impulse pushes
// the angle back inside and is accumulated ≥ 0.
static void tbSolveAngleLimit(tbJoint* joint, tbJointBodies* b, float C, float sign, float* accumulated,
							  const tbStepContext* context, bool useBias)
{
	float Cdot = sign * (b->wB - b->wA);
	float impulse = tbOneSidedImpulse(joint, C, Cdot, joint->revolute.axialMass, accumulated, context, useBias);
	b->wA -= joint->invIA * sign * impulse;
	b->wB += joint->invIB * sign * impulse;
}

static TB_FORCE_INLINE void tbSolveRevoluteAngularRows(tbJoint* joint, tbJointBodies* b, const tbStepContext* context, bool useBias)
{
	tbRevoluteJoint* r = &joint->revolute;
	float iA = joint->invIA, iB = joint->invIB;
	if (r->enableSpring && r->hertz > 0.0f)
	{
		float C = tbUnwindAngle(tbRevoluteAngle(joint, b) - r->targetAngle);
		tbSoftness s = r->springSoftness;
		float impulse = -s.massScale * r->axialMass * (b->wB - b->wA + s.biasRate * C) - s.impulseScale * r->springImpulse;
		r->springImpulse += impulse;
		b->wA -= iA * impulse;
		b->wB += iB * impulse;
	}
	if (r->enableMotor)
	{
		float impulse = -r->axialMass * (b->wB - b->wA - r->motorSpeed);
		float maxImpulse = context->h * r->maxMotorTorque;
		// tbClampFloat's result (its bounds are ordered: the torque is checked non-negative), as a min
		// then a max, each one instruction: the clamp's branch was taken or not as a friction motor
		// slipped or held, which a ragdoll's limbs change from pass to pass.
		float unclamped = r->motorImpulse + impulse;
		float belowUpper = maxImpulse < unclamped ? maxImpulse : unclamped;
		float newImpulse = -maxImpulse > belowUpper ? -maxImpulse : belowUpper;
		impulse = newImpulse - r->motorImpulse;
		r->motorImpulse = newImpulse;
		b->wA -= iA * impulse;
		b->wB += iB * impulse;
	}
	if (r->enableLimit)
	{
		float angle = tbRevoluteAngle(joint, b);
		tbSolveAngleLimit(joint, b, angle - r->lowerAngle, 1.0f, &r->lowerImpulse, context, useBias);
		tbSolveAngleLimit(joint, b, r->upperAngle - angle, -1.0f, &r->upperImpulse, context, useBias);
	}
}

// The spring, motor and limit rows, when the joint has one and a body can turn. Inline: most joints
// (a grid of pins, a chain) have none, and the call alone was a measurable part of their solve.
// The rows are forced inline too: handed to a call, the caller's bodies (their address taken) lived
// on the stack through the whole solve, each velocity stored a float at a time and read back eight
// bytes at a time, a load the processor cannot forward from the two stores.
static TB_FORCE_INLINE void tbSolveRevoluteAngular(tbJoint* joint, tbJointBodies* b, const tbStepContext* context, bool useBias)
{
	const tbRevoluteJoint* r = &joint->revolute;
	bool anyRow = r->enableSpring || r->enableMotor || r->enableLimit;
	if (anyRow && joint->invIA + joint->invIB != 0.0f)
	{
		tbSolveRevoluteAngularRows(joint, b, context, useBias);
	}
}

/// Largest ratio of a rigid pin's turning to its moving inverse mass, (|rA|²·iA + |rB|²·iB)/(mA + mB):
/// K's condition number grows with it, and beyond it the impulse that closes the pin in one pass
/// is more than float velocities carry (a pin kilometres off its body, tests/test_joint.c).
#define TB_RIGID_PIN_MAX_CONDITION 1.0e6

/// The pin of a revolute joint alone between ground and one body (joint_tree.c: the exact solve of
/// its one-joint tree): rigid, Δλ = −K⁻¹·(Ċ + β·C), in double precision as the trees are solved.
/// False, nothing applied, when K is too badly conditioned for it: the soft row then solves the
/// pin, as a tree that cannot be factored leaves its rows to Gauss–Seidel.
static bool tbSolveRigidPin(tbJoint* joint, tbJointBodies* b, tbVec2 rA, tbVec2 rB, tbVec2 rhs)
{
	double mA = joint->invMassA, mB = joint->invMassB, iA = joint->invIA, iB = joint->invIB;
	double turning = ((double)rA.x * rA.x + (double)rA.y * rA.y) * iA + ((double)rB.x * rB.x + (double)rB.y * rB.y) * iB;
	if (!(turning <= TB_RIGID_PIN_MAX_CONDITION * (mA + mB)))
	{
		return false;
	}
	double k11 = mA + mB + (double)rA.y * rA.y * iA + (double)rB.y * rB.y * iB;
	double k12 = -(double)rA.y * rA.x * iA - (double)rB.y * rB.x * iB;
	double k22 = mA + mB + (double)rA.x * rA.x * iA + (double)rB.x * rB.x * iB;
	double det = k11 * k22 - k12 * k12;
	if (!(fabs(det) > 1e-6 * fabs(k11 * k22)))
	{
		return false;
	}
	double x = (k22 * rhs.x - k12 * rhs.y) / det;
	double y = (k11 * rhs.y - k12 * rhs.x) / det;
	tbVec2 impulse = {(float)-x, (float)-y};
	if (tbIsValidVec2(impulse) == false)
	{
		return false;
	}
	tbRevoluteJoint* r = &joint->revolute;
	r->linearImpulse = tbAdd(r->linearImpulse, impulse);
	tbApplyJointImpulse(joint, b, rA, rB, impulse, 0.0f);
	return true;
}

void tbSolveRevoluteJoint(tbJoint* joint, tbStepContext* context, bool useBias)
{
	tbRevoluteJoint* r = &joint->revolute;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 rA, rB, separation;
	if (useBias && joint->rigidPin)
	{
		// The exact pin first, then the spring, motor and limits, which a tree's sweep also solves
		// after its exact solve (joint.c, tbSolveJoints): the pin moves the body they drive.
		tbJointAnchors(joint, &b, &rA, &rB, &separation);
		tbVec2 Cdot = tbSub(tbAdd(b.vB, tbCrossSV(b.wB, rB)), tbAdd(b.vA, tbCrossSV(b.wA, rA)));
		if (tbSolveRigidPin(joint, &b, rA, rB, tbMulAdd(Cdot, joint->constraintSoftness.biasRate, separation)))
		{
			tbSolveRevoluteAngular(joint, &b, context, useBias);
			tbStoreJointBodies(joint, &b);
			return;
		}
	}
	tbSolveRevoluteAngular(joint, &b, context, useBias);
	if (joint->solvedInTree)
	{
		tbStoreJointBodies(joint, &b); // the pin is solved with its tree (joint_tree.c)
		return;
	}

	// The relaxing pass (no bias) needs only the anchors, not how far apart they are.
	tbSoftness soft = {0.0f, 1.0f, 0.0f};
	tbVec2 bias = tbVec2_zero;
	if (useBias)
	{
		tbJointAnchors(joint, &b, &rA, &rB, &separation);
		soft = joint->constraintSoftness;
		bias = tbMulSV(soft.biasRate, separation);
	}
	else
	{
		rA = tbRotateVector(b.sA->deltaRotation, joint->frameA.p);
		rB = tbRotateVector(b.sB->deltaRotation, joint->frameB.p);
	}
	tbVec2 Cdot = tbSub(tbAdd(b.vB, tbCrossSV(b.wB, rB)), tbAdd(b.vA, tbCrossSV(b.wA, rA)));

	float mA = joint->invMassA, mB = joint->invMassB, iA = joint->invIA, iB = joint->invIB;
	tbMat22 K;
	K.cx.x = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
	K.cy.x = -rA.y * rA.x * iA - rB.y * rB.x * iB;
	K.cx.y = K.cy.x;
	K.cy.y = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
	tbVec2 x = tbSolve22(K, tbAdd(Cdot, bias));
	tbVec2 impulse = {-soft.massScale * x.x - soft.impulseScale * r->linearImpulse.x,
					  -soft.massScale * x.y - soft.impulseScale * r->linearImpulse.y};
	r->linearImpulse = tbAdd(r->linearImpulse, impulse);
	tbApplyJointImpulse(joint, &b, rA, rB, impulse, 0.0f);
	tbStoreJointBodies(joint, &b);
}

// The pin's two rows: Ċ = vB + ωB × rB − vA − ωA × rA, with ω × r = ω·(−r.y, r.x).
int tbRevoluteJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows)
{
	tbVec2 rA, rB, separation;
	tbJointAnchors(joint, b, &rA, &rB, &separation);
	tbSetJointRow(rows, 0, (tbVec3Row){-1.0f, 0.0f, rA.y}, (tbVec3Row){1.0f, 0.0f, -rB.y}, separation.x,
				  &joint->revolute.linearImpulse.x);
	tbSetJointRow(rows, 1, (tbVec3Row){0.0f, -1.0f, -rA.x}, (tbVec3Row){0.0f, 1.0f, rB.x}, separation.y,
				  &joint->revolute.linearImpulse.y);
	return 2;
}

void tbGetRevoluteJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	(void)world;
	const tbRevoluteJoint* r = &joint->revolute;
	*force = tbMulSV(inv_h, r->linearImpulse);
	*torque = inv_h * (r->springImpulse + r->motorImpulse + r->lowerImpulse - r->upperImpulse);
}

// A small circle at the pin and frame B's x-axis through it (shows the joint angle).
void tbDrawRevoluteJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint)
{
	tbTransform fB = tbRoundTransform(tbJointWorldFrameB(world, joint));
	float radius = 0.1f * joint->drawScale;
	if (draw->DrawCircleFcn != NULL)
	{
		tbDrawCircleAt(draw, fB.p, radius, tb_colorJoint);
	}
	tbDrawLine(draw, fB.p, tbMulAdd(fB.p, radius, tbRot_GetXAxis(fB.q)), tb_colorJoint);
}

// --- getters and setters -----------------------------------------------------------------------

void tbRevoluteJoint_EnableSpring(tbJointId jointId, bool enableSpring)
{
	TB_RECORD(RevoluteJointEnableSpring, &jointId, &enableSpring);
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_EnableSpring", &world, true);
	if (joint != NULL && joint->revolute.enableSpring != enableSpring)
	{
		joint->revolute.enableSpring = enableSpring;
		joint->revolute.springImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbRevoluteJoint_IsSpringEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_IsSpringEnabled", NULL, false);
	return joint != NULL && joint->revolute.enableSpring;
}

bool tbRevoluteJoint_SetSpringHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(RevoluteJointSetSpringHertz, &jointId, &hertz);
	const char* f = "tbRevoluteJoint_SetSpringHertz";
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "hertz", hertz) == false)
	{
		return false;
	}
	joint->revolute.hertz = hertz;
	tbWakeJoint(world, joint);
	return true;
}

float tbRevoluteJoint_GetSpringHertz(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetSpringHertz", NULL, false);
	return joint != NULL ? joint->revolute.hertz : 0.0f;
}

bool tbRevoluteJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio)
{
	TB_RECORD(RevoluteJointSetSpringDampingRatio, &jointId, &dampingRatio);
	const char* f = "tbRevoluteJoint_SetSpringDampingRatio";
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "dampingRatio", dampingRatio) == false)
	{
		return false;
	}
	joint->revolute.dampingRatio = dampingRatio;
	tbWakeJoint(world, joint);
	return true;
}

float tbRevoluteJoint_GetSpringDampingRatio(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetSpringDampingRatio", NULL, false);
	return joint != NULL ? joint->revolute.dampingRatio : 0.0f;
}

bool tbRevoluteJoint_SetTargetAngle(tbJointId jointId, float angle)
{
	TB_RECORD(RevoluteJointSetTargetAngle, &jointId, &angle);
	const char* f = "tbRevoluteJoint_SetTargetAngle";
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, f, &world, true);
	if (joint == NULL || tbCheckFloat(f, "angle", angle) == false)
	{
		return false;
	}
	joint->revolute.targetAngle = tbClampFloat(angle, -TB_PI, TB_PI);
	tbWakeJoint(world, joint);
	return true;
}

float tbRevoluteJoint_GetTargetAngle(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetTargetAngle", NULL, false);
	return joint != NULL ? joint->revolute.targetAngle : 0.0f;
}

float tbRevoluteJoint_GetAngle(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetAngle", &world, false);
	if (joint == NULL)
	{
		return 0.0f;
	}
	return tbRelativeAngle(tbJointWorldFrameA(world, joint).q, tbJointWorldFrameB(world, joint).q);
}

void tbRevoluteJoint_EnableLimit(tbJointId jointId, bool enableLimit)
{
	TB_RECORD(RevoluteJointEnableLimit, &jointId, &enableLimit);
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_EnableLimit", &world, true);
	if (joint != NULL && joint->revolute.enableLimit != enableLimit)
	{
		joint->revolute.enableLimit = enableLimit;
		joint->revolute.lowerImpulse = 0.0f;
		joint->revolute.upperImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbRevoluteJoint_IsLimitEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_IsLimitEnabled", NULL, false);
	return joint != NULL && joint->revolute.enableLimit;
}

float tbRevoluteJoint_GetLowerLimit(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetLowerLimit", NULL, false);
	return joint != NULL ? joint->revolute.lowerAngle : 0.0f;
}

float tbRevoluteJoint_GetUpperLimit(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetUpperLimit", NULL, false);
	return joint != NULL ? joint->revolute.upperAngle : 0.0f;
}

bool tbRevoluteJoint_SetLimits(tbJointId jointId, float lower, float upper)
{
	TB_RECORD(RevoluteJointSetLimits, &jointId, &lower, &upper);
	const char* f = "tbRevoluteJoint_SetLimits";
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, f, &world, true);
	if (joint == NULL || tbCheckRevoluteAngles(f, "lower", lower, "upper", upper) == false)
	{
		return false;
	}
	joint->revolute.lowerAngle = tbClampLimitAngle(lower);
	joint->revolute.upperAngle = tbClampLimitAngle(upper);
	tbWakeJoint(world, joint);
	return true;
}

void tbRevoluteJoint_EnableMotor(tbJointId jointId, bool enableMotor)
{
	TB_RECORD(RevoluteJointEnableMotor, &jointId, &enableMotor);
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_EnableMotor", &world, true);
	if (joint != NULL && joint->revolute.enableMotor != enableMotor)
	{
		joint->revolute.enableMotor = enableMotor;
		joint->revolute.motorImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbRevoluteJoint_IsMotorEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_IsMotorEnabled", NULL, false);
	return joint != NULL && joint->revolute.enableMotor;
}

bool tbRevoluteJoint_SetMotorSpeed(tbJointId jointId, float motorSpeed)
{
	TB_RECORD(RevoluteJointSetMotorSpeed, &jointId, &motorSpeed);
	const char* f = "tbRevoluteJoint_SetMotorSpeed";
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, f, &world, true);
	if (joint == NULL || tbCheckFloat(f, "motorSpeed", motorSpeed) == false)
	{
		return false;
	}
	joint->revolute.motorSpeed = motorSpeed;
	tbWakeJoint(world, joint);
	return true;
}

float tbRevoluteJoint_GetMotorSpeed(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetMotorSpeed", NULL, false);
	return joint != NULL ? joint->revolute.motorSpeed : 0.0f;
}

float tbRevoluteJoint_GetMotorTorque(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetMotorTorque", &world, false);
	return joint != NULL ? world->jointInvH * joint->revolute.motorImpulse : 0.0f;
}

bool tbRevoluteJoint_SetMaxMotorTorque(tbJointId jointId, float torque)
{
	TB_RECORD(RevoluteJointSetMaxMotorTorque, &jointId, &torque);
	const char* f = "tbRevoluteJoint_SetMaxMotorTorque";
	tbWorld* world;
	tbJoint* joint = tbGetRevolute(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "torque", torque) == false)
	{
		return false;
	}
	joint->revolute.maxMotorTorque = torque;
	tbWakeJoint(world, joint);
	return true;
}

float tbRevoluteJoint_GetMaxMotorTorque(tbJointId jointId)
{
	tbJoint* joint = tbGetRevolute(jointId, "tbRevoluteJoint_GetMaxMotorTorque", NULL, false);
	return joint != NULL ? joint->revolute.maxMotorTorque : 0.0f;
}

/// The anchors must coincide: their distance.
float tbRevoluteJointLinearSeparation(const tbWorld* world, const tbJoint* joint)
{
	return tbLength(tbSubPos(tbJointWorldFrameB(world, joint).p, tbJointWorldFrameA(world, joint).p));
}

/// Free to turn except past an enabled limit: how far the joint angle is outside [lower, upper].
float tbRevoluteJointAngularSeparation(const tbWorld* world, const tbJoint* joint)
{
	const tbRevoluteJoint* r = &joint->revolute;
	if (r->enableLimit == false)
	{
		return 0.0f;
	}
	float angle = tbRelativeAngle(tbJointWorldFrameA(world, joint).q, tbJointWorldFrameB(world, joint).q);
	return angle < r->lowerAngle ? r->lowerAngle - angle : (angle > r->upperAngle ? angle - r->upperAngle : 0.0f);
}
