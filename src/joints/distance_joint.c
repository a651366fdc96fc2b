// Distance joint: keeps the anchors of two bodies at a rest length (rigid), or joins them by a
// spring whose force is bounded, with optional length limits (a rope: only maxLength) and a motor
// along the line.
//
// With anchors rA, rB from the centres of mass and d = (cB + rB) − (cA + rA), u = d/|d|:
//     C = |d| − L,  Ċ = u·(vB + ωB × rB − vA − ωA × rA),
//     J = [−u, −(rA × u), u, rB × u],  K = mA⁻¹ + mB⁻¹ + IA⁻¹(rA × u)² + IB⁻¹(rB × u)².
// An impulse λ > 0 pushes the bodies apart (B receives λ·u).
// - rigid (no spring): C = 0 with the joint's positional softness in the biased pass;
// - spring: a soft constraint with the user's hertz and damping ratio (Catto, "Soft Constraints",
//   GDC 2011), acting in every pass, its accumulated impulse clamped to
//   [h·lowerSpringForce, h·upperSpringForce] (lower < 0 bounds the pull, upper the push);
// - motor: Ċ = motorSpeed, accumulated |λ| ≤ h·maxMotorForce;
// - limits, one-sided: |d| − minLength ≥ 0 (λ ≥ 0) and maxLength − |d| ≥ 0 (pulls, λ ≥ 0 on the
//   flipped row), speculative when not reached (bias C/h), soft when violated.
// The line u is recomputed from the current position deltas at every solve; K is taken once per
// step along the line at the start of the step.
// Reference: Catto, "Modeling and Solving Constraints", GDC 2009; Box2D v3's distance joint.
#include "joint.h"

#include "tumble/constants.h"
#include "world/recording.h"

static tbJoint* tbGetDistance(tbJointId id, const char* f, tbWorld** world, bool mutating)
{
	return tbGetJointChecked(id, f, world, tb_distanceJoint, mutating);
}

static bool tbCheckDistanceDef(const char* f, const tbDistanceJointDef* def)
{
	return tbCheckNonNegative(f, "def->length", def->length) &&
		   tbCheckRange(f, "def->lowerSpringForce", def->lowerSpringForce, "def->upperSpringForce",
						def->upperSpringForce) &&
		   tbCheckNonNegative(f, "def->hertz", def->hertz) &&
		   tbCheckNonNegative(f, "def->dampingRatio", def->dampingRatio) &&
		   tbCheckNonNegative(f, "def->minLength", def->minLength) &&
		   tbCheckRange(f, "def->minLength", def->minLength, "def->maxLength", def->maxLength) &&
		   tbCheckNonNegative(f, "def->maxMotorForce", def->maxMotorForce) &&
		   tbCheckFloat(f, "def->motorSpeed", def->motorSpeed);
}

// Lengths below the linear slop would make the line direction meaningless.
static void tbSetLengthRange(tbDistanceJoint* d, float minLength, float maxLength)
{
	d->minLength = tbClampFloat(minLength, TB_LINEAR_SLOP, TB_HUGE);
	d->maxLength = tbClampFloat(maxLength, d->minLength, TB_HUGE);
}

tbJointId tbCreateDistanceJoint(tbWorldId worldId, const tbDistanceJointDef* def)
{
	TB_RECORD(CreateDistanceJoint, &worldId, def);
	const char* f = "tbCreateDistanceJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultDistanceJointDef") == false ||
		tbCheckDistanceDef(f, def) == false)
	{
		return id;
	}
	tbJoint* joint = tbCreateJointInternal(worldId, &def->base, tb_distanceJoint, f, &id);
	if (joint == NULL)
	{
		return id;
	}
	tbDistanceJoint* d = &joint->distance;
	d->length = tbClampFloat(def->length, TB_LINEAR_SLOP, TB_HUGE);
	d->enableSpring = def->enableSpring;
	d->lowerSpringForce = def->lowerSpringForce;
	d->upperSpringForce = def->upperSpringForce;
	d->hertz = def->hertz;
	d->dampingRatio = def->dampingRatio;
	d->enableLimit = def->enableLimit;
	tbSetLengthRange(d, def->minLength, def->maxLength);
	d->enableMotor = def->enableMotor;
	d->maxMotorForce = def->maxMotorForce;
	d->motorSpeed = def->motorSpeed;
	return id;
}

// --- the step ----------------------------------------------------------------------------------

void tbPrepareDistanceJoint(tbJoint* joint, const tbStepContext* context)
{
	tbDistanceJoint* d = &joint->distance;
	tbVec2 rA = joint->frameA.p;
	tbVec2 rB = joint->frameB.p;
	tbVec2 axis = tbNormalize(tbAdd(joint->deltaCenter, tbSub(rB, rA)));
	float crA = tbCross(rA, axis);
	float crB = tbCross(rB, axis);
	float k = joint->invMassA + joint->invMassB + joint->invIA * crA * crA + joint->invIB * crB * crB;
	d->axialMass = k > 0.0f ? 1.0f / k : 0.0f;
	d->distanceSoftness = tbMakeSoftness(d->hertz, d->dampingRatio, context->h);
	if (context->enableWarmStarting == false)
	{
		d->impulse = 0.0f;
		d->lowerImpulse = 0.0f;
		d->upperImpulse = 0.0f;
		d->motorImpulse = 0.0f;
	}
}

void tbWarmStartDistanceJoint(tbJoint* joint, tbStepContext* context)
{
	const tbDistanceJoint* d = &joint->distance;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 rA, rB, separation;
	tbJointAnchors(joint, &b, &rA, &rB, &separation);
	tbVec2 axis = tbNormalize(separation);
	float axialImpulse = d->impulse + d->lowerImpulse - d->upperImpulse + d->motorImpulse;
	tbApplyJointImpulse(joint, &b, rA, rB, tbMulSV(axialImpulse, axis), 0.0f);
	tbStoreJointBodies(joint, &b);
}

// Velocity of anchor B relative to anchor A along the line.
static float tbAxialSpeed(const tbJointBodies* b, tbVec2 rA, tbVec2 rB, tbVec2 axis)
{
	tbVec2 dv = tbSub(tbAdd(b->vB, tbCrossSV(b->wB, rB)), tbAdd(b->vA, tbCrossSV(b->wA, rA)));
	return tbDot(dv, axis);
}

// A one-sided row along sign·axis: C ≥ 0 (tbOneSidedImpulse). Forced inline, as the revolute joint's
// rows are: the bodies handed to a call would stay on the stack through the whole solve.
static TB_FORCE_INLINE void tbSolveLengthLimit(tbJoint* joint, tbJointBodies* b, tbVec2 rA, tbVec2 rB, tbVec2 axis, float C,
											   float sign, float* accumulated, const tbStepContext* context, bool useBias)
{
	float Cdot = sign * tbAxialSpeed(b, rA, rB, axis);
	float impulse = tbOneSidedImpulse(joint, C, Cdot, joint->distance.axialMass, accumulated, context, useBias);
	tbApplyJointImpulse(joint, b, rA, rB, tbMulSV(sign * impulse, axis), 0.0f);
}

static void tbSolveDistanceSpring(tbJoint* joint, tbJointBodies* b, tbVec2 rA, tbVec2 rB, tbVec2 axis, float length,
								  const tbStepContext* context)
{
	tbDistanceJoint* d = &joint->distance;
	if (d->hertz > 0.0f)
	{
		tbSoftness s = d->distanceSoftness;
		float C = length - d->length;
		float Cdot = tbAxialSpeed(b, rA, rB, axis);
		float impulse = -s.massScale * d->axialMass * (Cdot + s.biasRate * C) - s.impulseScale * d->impulse;
		float newImpulse =
			tbClampFloat(d->impulse + impulse, context->h * d->lowerSpringForce, context->h * d->upperSpringForce);
		impulse = newImpulse - d->impulse;
		d->impulse = newImpulse;
		tbApplyJointImpulse(joint, b, rA, rB, tbMulSV(impulse, axis), 0.0f);
	}
	if (d->enableMotor)
	{
		float impulse = d->axialMass * (d->motorSpeed - tbAxialSpeed(b, rA, rB, axis));
		float maxImpulse = context->h * d->maxMotorForce;
		float newImpulse = tbClampFloat(d->motorImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - d->motorImpulse;
		d->motorImpulse = newImpulse;
		tbApplyJointImpulse(joint, b, rA, rB, tbMulSV(impulse, axis), 0.0f);
	}
}

// Soft when the spring is on, unless the limits pin the length anyway.
bool tbDistanceJointIsRigid(const tbJoint* joint)
{
	const tbDistanceJoint* d = &joint->distance;
	return !(d->enableSpring && (d->minLength < d->maxLength || d->enableLimit == false));
}

void tbSolveDistanceJoint(tbJoint* joint, tbStepContext* context, bool useBias)
{
	tbDistanceJoint* d = &joint->distance;
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 rA, rB, separation;
	tbJointAnchors(joint, &b, &rA, &rB, &separation);
	float length;
	tbVec2 axis = tbGetLengthAndNormalize(&length, separation);

	if (tbDistanceJointIsRigid(joint) == false)
	{
		tbSolveDistanceSpring(joint, &b, rA, rB, axis, length, context);
		if (d->enableLimit)
		{
			tbSolveLengthLimit(joint, &b, rA, rB, axis, length - d->minLength, 1.0f, &d->lowerImpulse, context, useBias);
			tbSolveLengthLimit(joint, &b, rA, rB, axis, d->maxLength - length, -1.0f, &d->upperImpulse, context,
							   useBias);
		}
	}
	else if (joint->solvedInTree == false) // a rigid row in a tree is solved there (joint_tree.c)
	{
		tbSoftness soft = {0.0f, 1.0f, 0.0f};
		if (useBias)
		{
			soft = joint->constraintSoftness;
		}
		float C = length - d->length;
		float Cdot = tbAxialSpeed(&b, rA, rB, axis);
		float impulse = -soft.massScale * d->axialMass * (Cdot + soft.biasRate * C) - soft.impulseScale * d->impulse;
		d->impulse += impulse;
		tbApplyJointImpulse(joint, &b, rA, rB, tbMulSV(impulse, axis), 0.0f);
	}
	tbStoreJointBodies(joint, &b);
}

// The rigid row along the line: Ċ = u·(vB + ωB × rB − vA − ωA × rA).
int tbDistanceJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows)
{
	tbVec2 rA, rB, separation;
	tbJointAnchors(joint, b, &rA, &rB, &separation);
	float length;
	tbVec2 u = tbGetLengthAndNormalize(&length, separation);
	tbSetJointRow(rows, 0, (tbVec3Row){-u.x, -u.y, -tbCross(rA, u)}, (tbVec3Row){u.x, u.y, tbCross(rB, u)},
				  length - joint->distance.length, &joint->distance.impulse);
	return 1;
}

static tbVec2 tbDistanceAxis(const tbWorld* world, const tbJoint* joint, float* length)
{
	tbPos pA = tbJointWorldFrameA(world, joint).p;
	tbPos pB = tbJointWorldFrameB(world, joint).p;
	return tbGetLengthAndNormalize(length, tbSubPos(pB, pA));
}

void tbGetDistanceJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	const tbDistanceJoint* d = &joint->distance;
	float length;
	tbVec2 axis = tbDistanceAxis(world, joint, &length);
	*force = tbMulSV(inv_h * (d->impulse + d->lowerImpulse - d->upperImpulse + d->motorImpulse), axis);
	*torque = 0.0f;
}

void tbDrawDistanceJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint)
{
	tbVec2 pA = tbToVec2(tbJointWorldFrameA(world, joint).p);
	tbVec2 pB = tbToVec2(tbJointWorldFrameB(world, joint).p);
	tbDrawLine(draw, pA, pB, tb_colorJoint);
	if (draw->DrawPointFcn != NULL)
	{
		tbDrawPointAt(draw, pA, 4.0f, tb_colorJoint);
		tbDrawPointAt(draw, pB, 4.0f, tb_colorJoint);
	}
}

// --- getters and setters -----------------------------------------------------------------------

bool tbDistanceJoint_SetLength(tbJointId jointId, float length)
{
	TB_RECORD(DistanceJointSetLength, &jointId, &length);
	const char* f = "tbDistanceJoint_SetLength";
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "length", length) == false)
	{
		return false;
	}
	joint->distance.length = tbClampFloat(length, TB_LINEAR_SLOP, TB_HUGE);
	joint->distance.impulse = 0.0f;
	joint->distance.lowerImpulse = 0.0f;
	joint->distance.upperImpulse = 0.0f;
	tbWakeJoint(world, joint);
	return true;
}

float tbDistanceJoint_GetLength(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetLength", NULL, false);
	return joint != NULL ? joint->distance.length : 0.0f;
}

void tbDistanceJoint_EnableSpring(tbJointId jointId, bool enableSpring)
{
	TB_RECORD(DistanceJointEnableSpring, &jointId, &enableSpring);
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_EnableSpring", &world, true);
	if (joint != NULL && joint->distance.enableSpring != enableSpring)
	{
		joint->distance.enableSpring = enableSpring;
		joint->distance.impulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbDistanceJoint_IsSpringEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_IsSpringEnabled", NULL, false);
	return joint != NULL && joint->distance.enableSpring;
}

bool tbDistanceJoint_SetSpringForceRange(tbJointId jointId, float lowerForce, float upperForce)
{
	TB_RECORD(DistanceJointSetSpringForceRange, &jointId, &lowerForce, &upperForce);
	const char* f = "tbDistanceJoint_SetSpringForceRange";
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, f, &world, true);
	if (joint == NULL || tbCheckRange(f, "lowerForce", lowerForce, "upperForce", upperForce) == false)
	{
		return false;
	}
	joint->distance.lowerSpringForce = lowerForce;
	joint->distance.upperSpringForce = upperForce;
	tbWakeJoint(world, joint);
	return true;
}

void tbDistanceJoint_GetSpringForceRange(tbJointId jointId, float* lowerForce, float* upperForce)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetSpringForceRange", NULL, false);
	if (lowerForce != NULL)
	{
		*lowerForce = joint != NULL ? joint->distance.lowerSpringForce : 0.0f;
	}
	if (upperForce != NULL)
	{
		*upperForce = joint != NULL ? joint->distance.upperSpringForce : 0.0f;
	}
}

bool tbDistanceJoint_SetSpringHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(DistanceJointSetSpringHertz, &jointId, &hertz);
	const char* f = "tbDistanceJoint_SetSpringHertz";
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "hertz", hertz) == false)
	{
		return false;
	}
	joint->distance.hertz = hertz;
	tbWakeJoint(world, joint);
	return true;
}

float tbDistanceJoint_GetSpringHertz(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetSpringHertz", NULL, false);
	return joint != NULL ? joint->distance.hertz : 0.0f;
}

bool tbDistanceJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio)
{
	TB_RECORD(DistanceJointSetSpringDampingRatio, &jointId, &dampingRatio);
	const char* f = "tbDistanceJoint_SetSpringDampingRatio";
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "dampingRatio", dampingRatio) == false)
	{
		return false;
	}
	joint->distance.dampingRatio = dampingRatio;
	tbWakeJoint(world, joint);
	return true;
}

float tbDistanceJoint_GetSpringDampingRatio(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetSpringDampingRatio", NULL, false);
	return joint != NULL ? joint->distance.dampingRatio : 0.0f;
}

void tbDistanceJoint_EnableLimit(tbJointId jointId, bool enableLimit)
{
	TB_RECORD(DistanceJointEnableLimit, &jointId, &enableLimit);
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_EnableLimit", &world, true);
	if (joint != NULL && joint->distance.enableLimit != enableLimit)
	{
		joint->distance.enableLimit = enableLimit;
		joint->distance.lowerImpulse = 0.0f;
		joint->distance.upperImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbDistanceJoint_IsLimitEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_IsLimitEnabled", NULL, false);
	return joint != NULL && joint->distance.enableLimit;
}

bool tbDistanceJoint_SetLengthRange(tbJointId jointId, float minLength, float maxLength)
{
	TB_RECORD(DistanceJointSetLengthRange, &jointId, &minLength, &maxLength);
	const char* f = "tbDistanceJoint_SetLengthRange";
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "minLength", minLength) == false ||
		tbCheckRange(f, "minLength", minLength, "maxLength", maxLength) == false)
	{
		return false;
	}
	tbSetLengthRange(&joint->distance, minLength, maxLength);
	joint->distance.lowerImpulse = 0.0f;
	joint->distance.upperImpulse = 0.0f;
	tbWakeJoint(world, joint);
	return true;
}

float tbDistanceJoint_GetMinLength(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetMinLength", NULL, false);
	return joint != NULL ? joint->distance.minLength : 0.0f;
}

float tbDistanceJoint_GetMaxLength(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetMaxLength", NULL, false);
	return joint != NULL ? joint->distance.maxLength : 0.0f;
}

float tbDistanceJoint_GetCurrentLength(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetCurrentLength", &world, false);
	float length = 0.0f;
	if (joint != NULL)
	{
		tbDistanceAxis(world, joint, &length);
	}
	return length;
}

void tbDistanceJoint_EnableMotor(tbJointId jointId, bool enableMotor)
{
	TB_RECORD(DistanceJointEnableMotor, &jointId, &enableMotor);
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_EnableMotor", &world, true);
	if (joint != NULL && joint->distance.enableMotor != enableMotor)
	{
		joint->distance.enableMotor = enableMotor;
		joint->distance.motorImpulse = 0.0f;
		tbWakeJoint(world, joint);
	}
}

bool tbDistanceJoint_IsMotorEnabled(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_IsMotorEnabled", NULL, false);
	return joint != NULL && joint->distance.enableMotor;
}

bool tbDistanceJoint_SetMotorSpeed(tbJointId jointId, float motorSpeed)
{
	TB_RECORD(DistanceJointSetMotorSpeed, &jointId, &motorSpeed);
	const char* f = "tbDistanceJoint_SetMotorSpeed";
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, f, &world, true);
	if (joint == NULL || tbCheckFloat(f, "motorSpeed", motorSpeed) == false)
	{
		return false;
	}
	joint->distance.motorSpeed = motorSpeed;
	tbWakeJoint(world, joint);
	return true;
}

float tbDistanceJoint_GetMotorSpeed(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetMotorSpeed", NULL, false);
	return joint != NULL ? joint->distance.motorSpeed : 0.0f;
}

bool tbDistanceJoint_SetMaxMotorForce(tbJointId jointId, float force)
{
	TB_RECORD(DistanceJointSetMaxMotorForce, &jointId, &force);
	const char* f = "tbDistanceJoint_SetMaxMotorForce";
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "force", force) == false)
	{
		return false;
	}
	joint->distance.maxMotorForce = force;
	tbWakeJoint(world, joint);
	return true;
}

float tbDistanceJoint_GetMaxMotorForce(tbJointId jointId)
{
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetMaxMotorForce", NULL, false);
	return joint != NULL ? joint->distance.maxMotorForce : 0.0f;
}

float tbDistanceJoint_GetMotorForce(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetDistance(jointId, "tbDistanceJoint_GetMotorForce", &world, false);
	return joint != NULL ? world->jointInvH * joint->distance.motorImpulse : 0.0f;
}

/// Rigid (no spring): |ℓ − length|. With a spring the length may vary, so only a limit violated
/// counts: min − ℓ below the range, ℓ − max above it.
float tbDistanceJointLinearSeparation(const tbWorld* world, const tbJoint* joint)
{
	const tbDistanceJoint* d = &joint->distance;
	float length = tbLength(tbSubPos(tbJointWorldFrameB(world, joint).p, tbJointWorldFrameA(world, joint).p));
	if (d->enableSpring == false)
	{
		return tbAbsFloat(length - d->length);
	}
	if (d->enableLimit == false)
	{
		return 0.0f;
	}
	return length < d->minLength ? d->minLength - length : (length > d->maxLength ? length - d->maxLength : 0.0f);
}
