// Pogo joint: the spring leg of a dynamic character (Box2D v3.2's pogo joint). Body A is usually
// the ground under the character, body B the character; the game typically creates the pogo again
// every step where the character stands, passing the last pogo's impulse and spring velocity on.
//
// Length and error. The pogo axis a is the y-axis of frame B (usually the world's up), the length
// ℓ = a·(pB − pA) from anchor A to anchor B, and the error C = ℓ − restLength.
//
// The spring is not a force law but a velocity target. A damped oscillator with state (C, u),
//   Ċ = u,   u̇ = −ω²·C − 2ζω·u,   ω = 2π·hertz, ζ = dampingRatio,
// is advanced by one implicit Euler sub-step of length h (u⁺ = u + h·u̇(C + h·u⁺, u⁺)):
//   u⁺ = (u − hω²·C) / (1 + 2ζhω + h²ω²),
// and the joint's one row pushes along the unit `normal` n so that the anchors' relative speed
// along n is u⁺ in the biased pass (and 0 in the relaxing pass, which removes that velocity once
// the positions have moved with it):
//   Ċn = n·(vB + ωB × rB − vA − ωA × rA),   J = [−nᵀ, −(rA × n), nᵀ, rB × n],
//   K = mA⁻¹ + mB⁻¹ + IA⁻¹(rA × n)² + IB⁻¹(rB × n)²,   λ = −K⁻¹·(Ċn − target),
// the accumulated λ kept within [−h·maxTensionForce, h·maxCompressionForce] (positive pushes B
// along n and A back). A pogo with hertz 0 applies nothing.
//
// What follows for a body on a static ground with n = a, while the caps hold: the length follows
// the discrete oscillator exactly, whatever the body's mass and the load on it. Per sub-step
// (C, u) is multiplied by (1/d)·[[1 + 2ζhω, h], [−hω², 1]], d = 1 + 2ζhω + h²ω²; undamped (ζ = 0) its
// eigenvalues are (1 ± ihω)/(1 + h²ω²): the length turns by atan(hω) per sub-step, a frequency
// atan(hω)/(2πh) (since atan(x)/x ≈ 1 − x²/3, below `hertz` by (hω)²/3 of it: 9e-4 for 2 Hz at
// h = 1/240 s), and keeps 1/√(1 + h²ω²) of its amplitude per sub-step (the integrator's own
// damping, about exp(−π·hω) per period). At rest the
// length is restLength, without the sag m·g/k of a force spring: gravity is cancelled inside each
// sub-step by an impulse m·g·h, up to maxCompressionForce; beyond it the body sinks at
// g − maxCompressionForce/m. After the relaxing pass the body's speed along n is zero, so a body
// held by a pogo looks at rest to the sleep test while its spring still moves: a character on a
// pogo should not sleep (Box2D v3.2's dynamic mover sample turns sleep off). The same maths as
// Box2D v3.2's pogo.
//
// Where the spring advances: in the warm start, once per sub-step, from the positions of that
// sub-step (they do not change between the warm start and the biased pass). Box2D v3.2 advances
// it in its single biased pass; Baumgarte and NGS here run several biased passes per sub-step,
// which would advance the spring several times.
// Reference: Catto, "Soft Constraints", GDC 2011 (implicit springs in a sub-stepped solver);
// Box2D v3.2's pogo joint.
#include "joint.h"
#include "world/recording.h"

static tbJoint* tbGetPogo(tbJointId id, const char* f, tbWorld** world, bool mutating)
{
	return tbGetJointChecked(id, f, world, tb_pogoJoint, mutating);
}

static bool tbCheckPogoDef(const char* f, const tbPogoJointDef* def)
{
	if (tbCheckVec2(f, "def->normal", def->normal) == false)
	{
		return false;
	}
	if (tbIsNormalized(def->normal) == false)
	{
		tbReportError(f, "def->normal is (%g, %g), not a unit vector; pass a direction of length 1 (tbNormalize)",
					  (double)def->normal.x, (double)def->normal.y);
		return false;
	}
	return tbCheckNonNegative(f, "def->hertz", def->hertz) &&
		   tbCheckNonNegative(f, "def->dampingRatio", def->dampingRatio) &&
		   tbCheckLength(f, "def->restLength", def->restLength, false) &&
		   tbCheckNonNegative(f, "def->maxTensionForce", def->maxTensionForce) &&
		   tbCheckNonNegative(f, "def->maxCompressionForce", def->maxCompressionForce) &&
		   tbCheckFloat(f, "def->impulse", def->impulse) && tbCheckFloat(f, "def->velocity", def->velocity);
}

tbJointId tbCreatePogoJoint(tbWorldId worldId, const tbPogoJointDef* def)
{
	TB_RECORD(CreatePogoJoint, &worldId, def);
	const char* f = "tbCreatePogoJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultPogoJointDef") == false ||
		tbCheckPogoDef(f, def) == false)
	{
		return id;
	}
	tbJoint* joint = tbCreateJointInternal(worldId, &def->base, tb_pogoJoint, f, &id);
	if (joint == NULL)
	{
		return id;
	}
	tbPogoJoint* p = &joint->pogo;
	p->normal = def->normal;
	p->hertz = def->hertz;
	p->dampingRatio = def->dampingRatio;
	p->restLength = def->restLength;
	p->maxTensionForce = def->maxTensionForce;
	p->maxCompressionForce = def->maxCompressionForce;
	p->impulse = def->impulse;
	p->velocity = def->velocity;
	return id;
}

// --- the step ----------------------------------------------------------------------------------

void tbPreparePogoJoint(tbJoint* joint, const tbStepContext* context)
{
	tbPogoJoint* p = &joint->pogo;
	float crA = tbCross(joint->frameA.p, p->normal);
	float crB = tbCross(joint->frameB.p, p->normal);
	float k = joint->invMassA + joint->invMassB + joint->invIA * crA * crA + joint->invIB * crB * crB;
	p->normalMass = k > 0.0f ? 1.0f / k : 0.0f;
	if (context->enableWarmStarting == false)
	{
		p->impulse = 0.0f;
	}
}

void tbWarmStartPogoJoint(tbJoint* joint, tbStepContext* context)
{
	tbPogoJoint* p = &joint->pogo;
	if (p->hertz == 0.0f)
	{
		p->impulse = 0.0f;
		return;
	}
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 rA, rB, d;
	tbJointAnchors(joint, &b, &rA, &rB, &d);

	// The spring's sub-step: u⁺ = (u − hω²C)/(1 + 2ζhω + h²ω²), C along frame B's current y-axis.
	tbVec2 axis = tbRot_GetYAxis(tbMulRot(b.sB->deltaRotation, joint->frameB.q));
	float C = tbDot(axis, d) - p->restLength;
	float omega = 2.0f * TB_PI * p->hertz;
	float hw = context->h * omega;
	p->velocity = (p->velocity - hw * omega * C) / (1.0f + 2.0f * p->dampingRatio * hw + hw * hw);

	tbApplyJointImpulse(joint, &b, rA, rB, tbMulSV(p->impulse, p->normal), 0.0f);
	tbStoreJointBodies(joint, &b);
}

void tbSolvePogoJoint(tbJoint* joint, tbStepContext* context, bool useBias)
{
	tbPogoJoint* p = &joint->pogo;
	if (p->hertz == 0.0f)
	{
		p->impulse = 0.0f;
		return;
	}
	tbJointBodies b = tbLoadJointBodies(context, joint);
	tbVec2 rA, rB, d;
	tbJointAnchors(joint, &b, &rA, &rB, &d);
	tbVec2 vr = tbSub(tbAdd(b.vB, tbCrossSV(b.wB, rB)), tbAdd(b.vA, tbCrossSV(b.wA, rA)));
	float Cdot = tbDot(p->normal, vr);
	float target = useBias ? p->velocity : 0.0f;

	float old = p->impulse;
	float total = old - p->normalMass * (Cdot - target);
	p->impulse = tbClampFloat(total, -context->h * p->maxTensionForce, context->h * p->maxCompressionForce);
	tbApplyJointImpulse(joint, &b, rA, rB, tbMulSV(p->impulse - old, p->normal), 0.0f);
	tbStoreJointBodies(joint, &b);
}

void tbGetPogoJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	(void)world;
	*force = tbMulSV(inv_h * joint->pogo.impulse, joint->pogo.normal);
	*torque = 0.0f;
}

// The leg: anchor A to anchor B, the rest length marked from anchor B down its axis, and the
// normal at anchor A.
void tbDrawPogoJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint)
{
	tbTransform fA = tbRoundTransform(tbJointWorldFrameA(world, joint));
	tbTransform fB = tbRoundTransform(tbJointWorldFrameB(world, joint));
	tbVec2 axis = tbRot_GetYAxis(fB.q);
	tbVec2 rest = tbMulSub(fB.p, joint->pogo.restLength, axis);
	tbDrawLine(draw, fA.p, fB.p, tb_colorTree);
	tbDrawLine(draw, fB.p, rest, tb_colorJoint);
	tbDrawLine(draw, fA.p, tbMulAdd(fA.p, 0.25f * joint->drawScale, joint->pogo.normal), tb_colorNormal);
}

// --- getters and setters -----------------------------------------------------------------------

bool tbPogoJoint_SetRestLength(tbJointId jointId, float length)
{
	TB_RECORD(PogoJointSetRestLength, &jointId, &length);
	const char* f = "tbPogoJoint_SetRestLength";
	tbWorld* world;
	tbJoint* joint = tbGetPogo(jointId, f, &world, true);
	if (joint == NULL || tbCheckLength(f, "length", length, false) == false)
	{
		return false;
	}
	joint->pogo.restLength = length;
	tbWakeJoint(world, joint);
	return true;
}

float tbPogoJoint_GetRestLength(tbJointId jointId)
{
	tbJoint* joint = tbGetPogo(jointId, "tbPogoJoint_GetRestLength", NULL, false);
	return joint != NULL ? joint->pogo.restLength : 0.0f;
}

bool tbPogoJoint_SetSpringHertz(tbJointId jointId, float hertz)
{
	TB_RECORD(PogoJointSetSpringHertz, &jointId, &hertz);
	const char* f = "tbPogoJoint_SetSpringHertz";
	tbWorld* world;
	tbJoint* joint = tbGetPogo(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "hertz", hertz) == false)
	{
		return false;
	}
	joint->pogo.hertz = hertz;
	tbWakeJoint(world, joint);
	return true;
}

float tbPogoJoint_GetSpringHertz(tbJointId jointId)
{
	tbJoint* joint = tbGetPogo(jointId, "tbPogoJoint_GetSpringHertz", NULL, false);
	return joint != NULL ? joint->pogo.hertz : 0.0f;
}

bool tbPogoJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio)
{
	TB_RECORD(PogoJointSetSpringDampingRatio, &jointId, &dampingRatio);
	const char* f = "tbPogoJoint_SetSpringDampingRatio";
	tbWorld* world;
	tbJoint* joint = tbGetPogo(jointId, f, &world, true);
	if (joint == NULL || tbCheckNonNegative(f, "dampingRatio", dampingRatio) == false)
	{
		return false;
	}
	joint->pogo.dampingRatio = dampingRatio;
	tbWakeJoint(world, joint);
	return true;
}

float tbPogoJoint_GetSpringDampingRatio(tbJointId jointId)
{
	tbJoint* joint = tbGetPogo(jointId, "tbPogoJoint_GetSpringDampingRatio", NULL, false);
	return joint != NULL ? joint->pogo.dampingRatio : 0.0f;
}

float tbPogoJoint_GetLength(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetPogo(jointId, "tbPogoJoint_GetLength", &world, false);
	if (joint == NULL)
	{
		return 0.0f;
	}
	tbWorldTransform fA = tbJointWorldFrameA(world, joint);
	tbWorldTransform fB = tbJointWorldFrameB(world, joint);
	return tbDot(tbRot_GetYAxis(fB.q), tbSubPos(fB.p, fA.p));
}

float tbPogoJoint_GetVelocity(tbJointId jointId)
{
	tbJoint* joint = tbGetPogo(jointId, "tbPogoJoint_GetVelocity", NULL, false);
	return joint != NULL ? joint->pogo.velocity : 0.0f;
}

float tbPogoJoint_GetImpulse(tbJointId jointId)
{
	tbJoint* joint = tbGetPogo(jointId, "tbPogoJoint_GetImpulse", NULL, false);
	return joint != NULL ? joint->pogo.impulse : 0.0f;
}
