// Mover joint: velocity control of a character. It drives the linear velocity of body B relative to
// body A towards a commanded velocity, the x and y axes each with its own force cap, and leaves
// rotation alone (Box2D v3.2's mover joint, with which a game moves a dynamic character).
//
// The rows act at the centres of mass, so they have no lever arm and cannot turn either body:
//   Ċ = vB − vA − linearVelocity                 (a 2-vector, world axes)
//   J = [−I, I] on (vA, vB),   K = J·M⁻¹·Jᵀ = (mA⁻¹ + mB⁻¹)·I
// K is a multiple of the identity, so the two axes are independent and share one effective mass
// m_eff = 1/(mA⁻¹ + mB⁻¹) (the body's mass against a static body A). Each pass applies
//   λ = −m_eff·Ċ,   accumulated per axis within ±h·maxVelocityForce (x and y separately).
// The clamp per axis is a box, not the motor joint's disc: a character may push hard sideways and
// softly upwards. With maxVelocityForce = (F, F), a body of mass m on a static body reaches the
// target at an acceleration of at most F/m on each axis (the force cap of one sub-step, h·F, is
// the whole impulse the row may apply in that sub-step).
// A zero cap on both axes turns the joint off. The rows act in every pass: it is a user force,
// with no position error to correct or relax.
// Reference: Catto, "Modeling and Solving Constraints", GDC 2009 (sequential impulses with
// clamped accumulated impulses); Box2D v3.2's mover joint.
#include "joint.h"
#include "world/recording.h"

static tbJoint* tbGetMover(tbJointId id, const char* f, tbWorld** world, bool mutating)
{
	return tbGetJointChecked(id, f, world, tb_moverJoint, mutating);
}

/// Both caps finite and ≥ 0, reported as name.x or name.y.
static bool tbCheckForcePair(const char* f, const char* name, tbVec2 force)
{
	if (tbIsValidFloat(force.x) == false || force.x < 0.0f || tbIsValidFloat(force.y) == false || force.y < 0.0f)
	{
		tbReportError(f, "%s is (%g, %g); both caps must be finite and >= 0 (N; 0 turns an axis off)", name,
					  (double)force.x, (double)force.y);
		return false;
	}
	return true;
}

tbJointId tbCreateMoverJoint(tbWorldId worldId, const tbMoverJointDef* def)
{
	TB_RECORD(CreateMoverJoint, &worldId, def);
	const char* f = "tbCreateMoverJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultMoverJointDef") == false ||
		tbCheckVec2(f, "def->linearVelocity", def->linearVelocity) == false ||
		tbCheckForcePair(f, "def->maxVelocityForce", def->maxVelocityForce) == false)
	{
		return id;
	}
	tbJoint* joint = tbCreateJointInternal(worldId, &def->base, tb_moverJoint, f, &id);
	if (joint == NULL)
	{
		return id;
	}
	tbMoverJoint* m = &joint->mover;
	m->linearVelocity = def->linearVelocity;
	m->maxVelocityForce = def->maxVelocityForce;
	return id;
}

// --- the step ----------------------------------------------------------------------------------

void tbPrepareMoverJoint(tbJoint* joint, const tbStepContext* context)
{
	tbMoverJoint* m = &joint->mover;
	float k = joint->invMassA + joint->invMassB;
	m->linearMass = k > 0.0f ? 1.0f / k : 0.0f;
	if (context->enableWarmStarting == false)
	{
		m->linearVelocityImpulse = tbVec2_zero;
	}
}

// Linear impulse P at the centres of mass: B receives +P, A −P; no angular part.
static void tbApplyMoverImpulse(const tbJoint* joint, tbJointBodies* b, tbVec2 P)
{
	b->vA = tbMulSub(b->vA, joint->invMassA, P);
	b->vB = tbMulAdd(b->vB, joint->invMassB, P);
}

// Zero caps on both axes: the joint is off, and an impulse kept from before is dropped rather than
// warm started (the solve would not take it back).
static bool tbMoverIsOff(tbMoverJoint* m)
{
	if (m->maxVelocityForce.x > 0.0f || m->maxVelocityForce.y > 0.0f)
	{
		return false;
	}
	m->linearVelocityImpulse = tbVec2_zero;
	return true;
}

void tbWarmStartMoverJoint(tbJoint* joint, tbStepContext* context)
{
	if (tbMoverIsOff(&joint->mover))
	{
		return;
	}
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbApplyMoverImpulse(joint, &b, joint->mover.linearVelocityImpulse);
	tbStoreJointBodies(joint, &b);
}

void tbSolveMoverJoint(tbJoint* joint, tbStepContext* context, bool useBias)
{
	(void)useBias; // a user force, the same in every pass
	tbMoverJoint* m = &joint->mover;
	if (tbMoverIsOff(m))
	{
		return;
	}
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 Cdot = tbSub(tbSub(b.vB, b.vA), m->linearVelocity);
	tbVec2 maxImpulse = tbMulSV(context->h, m->maxVelocityForce);
	tbVec2 old = m->linearVelocityImpulse;
	tbVec2 total = tbMulSub(old, m->linearMass, Cdot);
	m->linearVelocityImpulse = tbClamp(total, tbNeg(maxImpulse), maxImpulse);
	tbApplyMoverImpulse(joint, &b, tbSub(m->linearVelocityImpulse, old));
	tbStoreJointBodies(joint, &b);
}

void tbGetMoverJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	(void)world;
	*force = tbMulSV(inv_h, joint->mover.linearVelocityImpulse);
	*torque = 0.0f;
}

// Body B's centre joined to body A's, and the commanded velocity drawn from B's centre (the
// distance covered in a tenth of a second, times drawScale).
void tbDrawMoverJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint)
{
	const tbBody* a = world->bodies + joint->edges[0].bodyId;
	const tbBody* b = world->bodies + joint->edges[1].bodyId;
	tbVec2 cA = tbToVec2(tbTransformWorldPoint(a->transform, a->localCenter));
	tbVec2 cB = tbToVec2(tbTransformWorldPoint(b->transform, b->localCenter));
	tbDrawLine(draw, cA, cB, tb_colorTree);
	tbVec2 tip = tbMulAdd(cB, 0.1f * joint->drawScale, joint->mover.linearVelocity);
	// Both factors are only checked finite (and non-negative): their product may overflow, and an
	// arrow to infinity is not drawn.
	if (tbIsValidVec2(tip))
	{
		tbDrawLine(draw, cB, tip, tb_colorJoint);
	}
}

// --- getters and setters -----------------------------------------------------------------------

bool tbMoverJoint_SetLinearVelocity(tbJointId jointId, tbVec2 velocity)
{
	TB_RECORD(MoverJointSetLinearVelocity, &jointId, &velocity);
	const char* f = "tbMoverJoint_SetLinearVelocity";
	tbWorld* world;
	tbJoint* joint = tbGetMover(jointId, f, &world, true);
	if (joint == NULL || tbCheckVec2(f, "velocity", velocity) == false)
	{
		return false;
	}
	joint->mover.linearVelocity = velocity;
	tbWakeJoint(world, joint);
	return true;
}

tbVec2 tbMoverJoint_GetLinearVelocity(tbJointId jointId)
{
	tbJoint* joint = tbGetMover(jointId, "tbMoverJoint_GetLinearVelocity", NULL, false);
	return joint != NULL ? joint->mover.linearVelocity : tbVec2_zero;
}

bool tbMoverJoint_SetMaxVelocityForce(tbJointId jointId, tbVec2 maxForce)
{
	TB_RECORD(MoverJointSetMaxVelocityForce, &jointId, &maxForce);
	const char* f = "tbMoverJoint_SetMaxVelocityForce";
	tbWorld* world;
	tbJoint* joint = tbGetMover(jointId, f, &world, true);
	if (joint == NULL || tbCheckForcePair(f, "maxForce", maxForce) == false)
	{
		return false;
	}
	joint->mover.maxVelocityForce = maxForce;
	tbWakeJoint(world, joint);
	return true;
}

tbVec2 tbMoverJoint_GetMaxVelocityForce(tbJointId jointId)
{
	tbJoint* joint = tbGetMover(jointId, "tbMoverJoint_GetMaxVelocityForce", NULL, false);
	return joint != NULL ? joint->mover.maxVelocityForce : tbVec2_zero;
}
