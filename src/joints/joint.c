// Joints: the common part. Definitions and defaults, the pool (creation, destruction, stale-id
// detection), the functions every kind shares, the filter joint (no constraint: it only stops the
// two bodies colliding), the joints' place in the step, and the hooks that make joined bodies one
// island. Each constrained kind has its own file with its maths (revolute_joint.c,
// distance_joint.c, weld_joint.c, prismatic_joint.c, wheel_joint.c, motor_joint.c, mover_joint.c,
// pogo_joint.c).
//
// A joint is a set of equality and inequality constraints C(x) between two bodies, solved with
// the contacts by sequential impulses (Catto, "Modeling and Solving Constraints", GDC 2009):
// Ċ = J·v, an impulse λ along Jᵀ changes Ċ by K·λ with K = J·M⁻¹·Jᵀ, and the impulse that brings
// Ċ to the target −bias is λ = −K⁻¹(Ċ + bias). Accumulated impulses are kept from sub-step to
// sub-step and step to step (warm starting). Anchors are measured from the centres of mass; the
// position error during the step is read from the same position deltas (tbSolverBody) the
// contacts use, so every sub-step sees the drift the previous one left.
//
// Where joints sit in the step (solver.c and the method files): prepared once per step after the
// contacts (anchors in world axes, masses, softness); warm started before the contacts in every
// sub-step; solved before the contacts in each velocity pass. Joints go first so that the
// contacts, solved last, have the final word on non-penetration. Row by row, the joints are
// solved one at a time (scalar) in the order tbColorJoints gives (constraint_graph.c): small
// mechanisms in joint-id order, whole mechanisms side by side on the workers, the joints of large
// ones colour by colour. In the biased passes the equality rows of each tree of joined bodies are
// solved exactly instead (joint_tree.c, tbSolveJoints below).
//
// Position error by method (the `useBias` pass):
// - soft step: rows solved one at a time are soft constraints (Catto, "Soft Constraints", GDC
//   2011; Solver2D 2024), λ = −m_eff·massScale·(Ċ + biasRate·C) − impulseScale·λ_acc, with the
//   joint's constraintHertz (default 60 Hz) and constraintDampingRatio (default 2, Box2D v3's
//   values) and the hertz capped at a quarter of the sub-step rate, the cap contacts use (a
//   faster spring is not resolved by the sub-step and only adds jitter). The equality rows of a
//   joint tree are rigid, corrected by the same bias rate β = ω/(2ζ + hω) and no compliance. The
//   relaxing pass solves every row rigidly with no bias, removing the correction velocity.
// - Baumgarte and NGS: the same velocity code with a Baumgarte bias, biasRate = TB_BAUMGARTE/h,
//   massScale 1, impulseScale 0 (a fifth of the error per sub-step, as contacts under
//   Baumgarte). NGS corrects contact overlap on positions (solver_ngs.c); joints have no
//   position pass there: their drift is corrected by that velocity bias.
// Limits use speculation as contacts do: a limit not yet reached (C > 0) gets bias C/h, so it may
// be approached within a sub-step but not passed. Springs, motors and limits act in every pass.
//
// Islands: a joint with a dynamic body on each side links the two bodies: they sleep together
// (island.c follows joint edges from dynamic bodies) and wake together (tbWakeBody wakes the
// bodies joined to a dynamic body, transitively). A joint to a static body links nothing; a
// filter joint links nothing (it couples no motion).
#include "joint.h"

#include "core/array.h"
#include "world/recording.h"

#include <float.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>

// ---------------------------------------------------------------------------------------------
// Definitions

static tbJointDef tbDefaultJointDef(void)
{
	tbJointDef def;
	memset(&def, 0, sizeof(def));
	def.localFrameA = tbTransform_identity;
	def.localFrameB = tbTransform_identity;
	def.forceThreshold = FLT_MAX;
	def.torqueThreshold = FLT_MAX;
	def.constraintHertz = 60.0f;
	def.constraintDampingRatio = 2.0f;
	def.drawScale = 1.0f * tbGetLengthUnitsPerMeter(); // one metre, in length units
	return def;
}

tbDistanceJointDef tbDefaultDistanceJointDef(void)
{
	tbDistanceJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.length = 1.0f;
	def.lowerSpringForce = -FLT_MAX;
	def.upperSpringForce = FLT_MAX;
	def.maxLength = TB_HUGE;
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

tbFilterJointDef tbDefaultFilterJointDef(void)
{
	tbFilterJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

tbMotorJointDef tbDefaultMotorJointDef(void)
{
	tbMotorJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

tbMoverJointDef tbDefaultMoverJointDef(void)
{
	tbMoverJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

// Box2D v3.2 leaves every field zero, the normal too; a zero normal is no direction, so the
// default here is the world's up, the pogo axis's own default.
tbPogoJointDef tbDefaultPogoJointDef(void)
{
	tbPogoJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.normal = tbMakeVec2(0.0f, 1.0f);
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

tbPrismaticJointDef tbDefaultPrismaticJointDef(void)
{
	tbPrismaticJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

tbRevoluteJointDef tbDefaultRevoluteJointDef(void)
{
	tbRevoluteJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

tbWeldJointDef tbDefaultWeldJointDef(void)
{
	tbWeldJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

tbWheelJointDef tbDefaultWheelJointDef(void)
{
	tbWheelJointDef def;
	memset(&def, 0, sizeof(def));
	def.base = tbDefaultJointDef();
	def.enableSpring = true;
	def.hertz = 1.0f;
	def.dampingRatio = 0.7f;
	def.internalValue = TB_JOINT_DEF_MAGIC;
	return def;
}

// ---------------------------------------------------------------------------------------------
// Ids and checks

static const char* const s_jointTypeNames[tb_jointTypeCount] = {
	"distance", "filter", "motor", "mover", "pogo", "prismatic", "revolute", "weld", "wheel"};

tbJointId tbMakeJointId(const tbWorld* world, const tbJoint* joint)
{
	tbJointId id = {(int32_t)(joint - world->joints) + 1, world->worldId, joint->generation};
	return id;
}

static tbJoint* tbLookUpJoint(tbJointId id, tbWorld** worldOut)
{
	if (id.index1 <= 0 || id.world0 >= TB_MAX_WORLDS)
	{
		return NULL;
	}
	tbWorld* world = tbGetWorldFromIndex(id.world0);
	int index = id.index1 - 1;
	if (world == NULL || index >= world->jointPool.highWater || world->joints[index].inUse == false ||
		world->joints[index].generation != id.generation)
	{
		return NULL;
	}
	*worldOut = world;
	return world->joints + index;
}

bool tbJoint_IsValid(tbJointId id)
{
	tbWorld* world;
	return tbLookUpJoint(id, &world) != NULL;
}

tbJoint* tbGetJointChecked(tbJointId id, const char* function, tbWorld** worldOut, int type, bool mutating)
{
	tbWorld* world = NULL;
	tbJoint* joint = tbLookUpJoint(id, &world);
	if (joint == NULL)
	{
		tbReportError(function, "jointId is null or refers to a destroyed joint, body or world; do not use a joint id "
								"after tbDestroyJoint, after destroying one of its bodies or its world (check with "
								"tbJoint_IsValid)");
		return NULL;
	}
	if (type >= 0 && joint->type != type)
	{
		tbReportError(function, "jointId is a %s joint, not a %s joint; call the function of its kind (see "
								"tbJoint_GetType)", s_jointTypeNames[joint->type], s_jointTypeNames[type]);
		return NULL;
	}
	if (mutating && world->locked)
	{
		tbReportError(function, "the world is locked (stepping); change joints between steps");
		return NULL;
	}
	if (worldOut != NULL)
	{
		*worldOut = world;
	}
	return joint;
}

bool tbCheckRange(const char* function, const char* lowerName, float lower, const char* upperName, float upper)
{
	if (tbIsValidFloat(lower) == false || tbIsValidFloat(upper) == false || lower > upper)
	{
		tbReportError(function, "%s is %g and %s is %g; both must be finite with %s <= %s", lowerName, (double)lower,
					  upperName, (double)upper, lowerName, upperName);
		return false;
	}
	return true;
}

bool tbCheckJointDefPointer(const char* f, const void* def, int internalValue, const char* defaultName)
{
	if (tbCheckPointer(f, "def", def) == false)
	{
		return false;
	}
	if (internalValue != TB_JOINT_DEF_MAGIC)
	{
		tbReportError(f, "def was not initialised by %s(); start from it and change fields", defaultName);
		return false;
	}
	return true;
}

static bool tbCheckBodyForJoint(const char* f, const char* name, tbBodyId bodyId, const tbWorld* world)
{
	if (tbBody_IsValid(bodyId) == false)
	{
		tbReportError(f, "%s is null or refers to a destroyed body; pass a body id from tbCreateBody (check with "
						 "tbBody_IsValid)", name);
		return false;
	}
	if (bodyId.world0 != world->worldId)
	{
		tbReportError(f, "%s belongs to another world; a joint joins two bodies of the world passed as worldId", name);
		return false;
	}
	return true;
}

static bool tbCheckFrame(const char* f, const char* name, tbTransform frame)
{
	if (tbIsValidVec2(frame.p) == false)
	{
		tbReportError(f, "%s.p is (%g, %g) (NaN or infinity); pass finite coordinates", name, (double)frame.p.x,
					  (double)frame.p.y);
		return false;
	}
	if (tbIsCoordinate(frame.p) == false)
	{
		// An anchor is a point of the body, as a shape's vertex is: the same bound, beyond which the
		// solver's products of lengths overflow (an anchor at 9e17 m gave NaN velocities).
		tbReportError(f, "%s.p is (%g, %g), beyond TB_MAX_COORDINATE (%g m) from the body origin; put the anchor on "
						 "the body", name, (double)frame.p.x, (double)frame.p.y, (double)TB_MAX_COORDINATE);
		return false;
	}
	if (tbIsValidRotation(frame.q) == false)
	{
		tbReportError(f, "%s.q is (%g, %g), not a unit rotation; make it with tbMakeRot(angle)", name,
					  (double)frame.q.c, (double)frame.q.s);
		return false;
	}
	return true;
}

static bool tbCheckJointBase(const char* f, const tbWorld* world, const tbJointDef* def)
{
	if (tbCheckBodyForJoint(f, "def->base.bodyIdA", def->bodyIdA, world) == false ||
		tbCheckBodyForJoint(f, "def->base.bodyIdB", def->bodyIdB, world) == false)
	{
		return false;
	}
	if (def->bodyIdA.index1 == def->bodyIdB.index1)
	{
		tbReportError(f, "def->base.bodyIdA and def->base.bodyIdB are the same body; a joint joins two different "
						 "bodies");
		return false;
	}
	return tbCheckFrame(f, "def->base.localFrameA", def->localFrameA) &&
		   tbCheckFrame(f, "def->base.localFrameB", def->localFrameB) &&
		   tbCheckNonNegative(f, "def->base.forceThreshold", def->forceThreshold) &&
		   tbCheckNonNegative(f, "def->base.torqueThreshold", def->torqueThreshold) &&
		   tbCheckNonNegative(f, "def->base.constraintHertz", def->constraintHertz) &&
		   tbCheckNonNegative(f, "def->base.constraintDampingRatio", def->constraintDampingRatio) &&
		   tbCheckNonNegative(f, "def->base.drawScale", def->drawScale);
}

// ---------------------------------------------------------------------------------------------
// The pool: creation and destruction

static void tbLinkJointEdge(tbWorld* world, int jointId, int edgeIndex)
{
	tbJoint* joint = world->joints + jointId;
	tbBody* body = world->bodies + joint->edges[edgeIndex].bodyId;
	int key = (jointId << 1) | edgeIndex;
	joint->edges[edgeIndex].prevKey = TB_NULL_INDEX;
	joint->edges[edgeIndex].nextKey = body->headJointKey;
	if (body->headJointKey != TB_NULL_INDEX)
	{
		int head = body->headJointKey;
		world->joints[head >> 1].edges[head & 1].prevKey = key;
	}
	body->headJointKey = key;
	body->jointCount += 1;
}

static void tbUnlinkJointEdge(tbWorld* world, int jointId, int edgeIndex)
{
	tbJointEdge* edge = world->joints[jointId].edges + edgeIndex;
	tbBody* body = world->bodies + edge->bodyId;
	if (edge->prevKey != TB_NULL_INDEX)
	{
		world->joints[edge->prevKey >> 1].edges[edge->prevKey & 1].nextKey = edge->nextKey;
	}
	else
	{
		body->headJointKey = edge->nextKey;
	}
	if (edge->nextKey != TB_NULL_INDEX)
	{
		world->joints[edge->nextKey >> 1].edges[edge->nextKey & 1].prevKey = edge->prevKey;
	}
	body->jointCount -= 1;
}

/// Destroy the contacts between two bodies (a joint that forbids their collision), walking the
/// shorter contact list.
static void tbDestroyContactsBetween(tbWorld* world, int bodyIdA, int bodyIdB)
{
	const tbBody* a = world->bodies + bodyIdA;
	const tbBody* b = world->bodies + bodyIdB;
	int key = a->contactCount <= b->contactCount ? a->headContactKey : b->headContactKey;
	int other = a->contactCount <= b->contactCount ? bodyIdB : bodyIdA;
	while (key != TB_NULL_INDEX)
	{
		const tbContact* contact = world->contacts + (key >> 1);
		int next = contact->edges[key & 1].nextKey;
		if (contact->edges[(key & 1) ^ 1].bodyId == other)
		{
			tbDestroyContact(world, key >> 1, false);
		}
		key = next;
	}
}

/// Let the broad phase report the pairs of a body's shapes again (their contacts were forbidden
/// by a joint that is gone now): marking a proxy moved makes the next pair update query it.
static void tbRefindBodyPairs(tbWorld* world, const tbBody* body)
{
	if (body->type == tb_staticBody)
	{
		return;
	}
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		const tbShape* shape = world->shapes + id;
		if (shape->proxyKey != TB_NULL_INDEX)
		{
			tbBroadPhase_MoveProxy(&world->broadPhase, shape->proxyKey, shape->fatAABB);
		}
	}
}

void tbWakeJoint(tbWorld* world, const tbJoint* joint)
{
	tbWakeBody(world, world->bodies + joint->edges[0].bodyId);
	tbWakeBody(world, world->bodies + joint->edges[1].bodyId);
}

static int tbAllocJointSlot(tbWorld* world)
{
	bool isNew;
	int id = tbIdPool_Alloc(&world->jointPool, &isNew);
	if (isNew)
	{
		TB_ARRAY_RESERVE(world->joints, world->jointCapacity, id + 1);
		memset(world->joints + id, 0, sizeof(tbJoint));
		world->joints[id].generation = world->jointGenerationBase;
	}
	return id;
}

tbJoint* tbCreateJointInternal(tbWorldId worldId, const tbJointDef* def, tbJointType type, const char* f, tbJointId* id)
{
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL || tbCheckJointBase(f, world, def) == false)
	{
		return NULL;
	}
	if (tbStructureLocked(world, f, "create joints"))
	{
		return NULL;
	}
	int bodyIdA = def->bodyIdA.index1 - 1;
	int bodyIdB = def->bodyIdB.index1 - 1;
	if (def->collideConnected == false)
	{
		tbDestroyContactsBetween(world, bodyIdA, bodyIdB);
	}

	int jointId = tbAllocJointSlot(world);
	tbJoint* joint = world->joints + jointId;
	uint16_t generation = joint->generation; // advanced when the last joint here was destroyed
	memset(joint, 0, sizeof(tbJoint));
	joint->generation = generation;
	joint->inUse = true;
	joint->type = (uint8_t)type;
	joint->userData = def->userData;
	joint->collideConnected = def->collideConnected;
	joint->localFrameA.p = def->localFrameA.p;
	joint->localFrameA.q = tbNormalizeRot(def->localFrameA.q);
	joint->localFrameB.p = def->localFrameB.p;
	joint->localFrameB.q = tbNormalizeRot(def->localFrameB.q);
	joint->forceThreshold = def->forceThreshold;
	joint->torqueThreshold = def->torqueThreshold;
	joint->constraintHertz = def->constraintHertz;
	joint->constraintDampingRatio = def->constraintDampingRatio;
	joint->drawScale = def->drawScale;
	joint->edges[0].bodyId = bodyIdA;
	joint->edges[1].bodyId = bodyIdB;
	tbLinkJointEdge(world, jointId, 0);
	tbLinkJointEdge(world, jointId, 1);

	// As Box2D v3: a joint between an awake and a sleeping body wakes the sleeping one (they are one
	// island now); a joint between sleeping bodies leaves them asleep.
	const tbBody* a = world->bodies + bodyIdA;
	const tbBody* b = world->bodies + bodyIdB;
	if (type != tb_filterJoint && (a->awakeIndex != TB_NULL_INDEX || b->awakeIndex != TB_NULL_INDEX))
	{
		tbWakeJoint(world, joint);
	}
	*id = tbMakeJointId(world, joint);
	return joint;
}

static void tbDestroyJointInternal(tbWorld* world, int jointId, bool refindPairs)
{
	tbJoint* joint = world->joints + jointId;
	tbBody* a = world->bodies + joint->edges[0].bodyId;
	tbBody* b = world->bodies + joint->edges[1].bodyId;
	tbUnlinkJointEdge(world, jointId, 0);
	tbUnlinkJointEdge(world, jointId, 1);
	if (refindPairs && joint->collideConnected == false && tbJointBlocksCollision(world, joint->edges[0].bodyId,
																				  joint->edges[1].bodyId) == false)
	{
		tbRefindBodyPairs(world, a);
		tbRefindBodyPairs(world, b);
	}
	tbWakeBody(world, a);
	tbWakeBody(world, b);
	joint->inUse = false;
	tbIdPool_Release(&world->jointPool, jointId, &joint->generation, world->jointGenerationBase);
}

void tbDestroyJoint(tbJointId jointId)
{
	TB_RECORD(DestroyJoint, &jointId);
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbDestroyJoint", &world, -1, true);
	if (joint != NULL && tbStructureLocked(world, "tbDestroyJoint", "destroy joints") == false)
	{
		tbDestroyJointInternal(world, jointId.index1 - 1, true);
	}
}

void tbDestroyBodyJoints(tbWorld* world, tbBody* body)
{
	int key = body->headJointKey;
	while (key != TB_NULL_INDEX)
	{
		int next = world->joints[key >> 1].edges[key & 1].nextKey;
		tbDestroyJointInternal(world, key >> 1, false); // the body goes: no pairs to find again
		key = next;
	}
}

void tbFreeJoints(tbWorld* world)
{
	TB_ARRAY_FREE(world->joints, world->jointCapacity);
	tbIdPool_Destroy(&world->jointPool);
	TB_ARRAY_FREE(world->cache.solverJoints, world->cache.solverJointCapacity);
	TB_ARRAY_FREE(world->events.jointEvents, world->events.jointEventCapacity);
	TB_ARRAY_FREE(world->cache.jointWakeStack, world->cache.jointWakeCapacity);
}

// ---------------------------------------------------------------------------------------------
// The filter joint

tbJointId tbCreateFilterJoint(tbWorldId worldId, const tbFilterJointDef* def)
{
	TB_RECORD(CreateFilterJoint, &worldId, def);
	const char* f = "tbCreateFilterJoint";
	tbJointId id = TB_NULL_JOINT_ID;
	if (tbCheckJointDefPointer(f, def, def != NULL ? def->internalValue : 0, "tbDefaultFilterJointDef") == false)
	{
		return id;
	}
	tbCreateJointInternal(worldId, &def->base, tb_filterJoint, f, &id);
	return id;
}

// ---------------------------------------------------------------------------------------------
// Functions every kind shares

tbJointType tbJoint_GetType(tbJointId jointId)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetType", NULL, -1, false);
	return joint != NULL ? (tbJointType)joint->type : tb_distanceJoint;
}

tbBodyId tbJoint_GetBodyA(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetBodyA", &world, -1, false);
	return joint != NULL ? tbMakeBodyId(world, joint->edges[0].bodyId) : TB_NULL_BODY_ID;
}

tbBodyId tbJoint_GetBodyB(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetBodyB", &world, -1, false);
	return joint != NULL ? tbMakeBodyId(world, joint->edges[1].bodyId) : TB_NULL_BODY_ID;
}

tbWorldId tbJoint_GetWorld(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetWorld", &world, -1, false);
	if (joint == NULL)
	{
		return TB_NULL_WORLD_ID;
	}
	tbWorldId id = {(uint16_t)(world->worldId + 1), world->generation};
	return id;
}

static bool tbSetLocalFrame(tbJointId jointId, tbTransform frame, int edge, const char* f)
{
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, f, &world, -1, true);
	if (joint == NULL || tbCheckFrame(f, "localFrame", frame) == false)
	{
		return false;
	}
	frame.q = tbNormalizeRot(frame.q);
	if (edge == 0)
	{
		joint->localFrameA = frame;
	}
	else
	{
		joint->localFrameB = frame;
	}
	tbWakeJoint(world, joint);
	return true;
}

bool tbJoint_SetLocalFrameA(tbJointId jointId, tbTransform localFrame)
{
	TB_RECORD(JointSetLocalFrameA, &jointId, &localFrame);
	return tbSetLocalFrame(jointId, localFrame, 0, "tbJoint_SetLocalFrameA");
}

bool tbJoint_SetLocalFrameB(tbJointId jointId, tbTransform localFrame)
{
	TB_RECORD(JointSetLocalFrameB, &jointId, &localFrame);
	return tbSetLocalFrame(jointId, localFrame, 1, "tbJoint_SetLocalFrameB");
}

tbTransform tbJoint_GetLocalFrameA(tbJointId jointId)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetLocalFrameA", NULL, -1, false);
	return joint != NULL ? joint->localFrameA : tbTransform_identity;
}

tbTransform tbJoint_GetLocalFrameB(tbJointId jointId)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetLocalFrameB", NULL, -1, false);
	return joint != NULL ? joint->localFrameB : tbTransform_identity;
}

void tbJoint_SetCollideConnected(tbJointId jointId, bool shouldCollide)
{
	TB_RECORD(JointSetCollideConnected, &jointId, &shouldCollide);
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_SetCollideConnected", &world, -1, true);
	if (joint == NULL || joint->collideConnected == shouldCollide ||
		tbStructureLocked(world, "tbJoint_SetCollideConnected", "change collideConnected"))
	{
		return;
	}
	joint->collideConnected = shouldCollide;
	int bodyIdA = joint->edges[0].bodyId;
	int bodyIdB = joint->edges[1].bodyId;
	if (shouldCollide == false)
	{
		tbDestroyContactsBetween(world, bodyIdA, bodyIdB);
	}
	else if (tbJointBlocksCollision(world, bodyIdA, bodyIdB) == false)
	{
		tbRefindBodyPairs(world, world->bodies + bodyIdA);
		tbRefindBodyPairs(world, world->bodies + bodyIdB);
	}
	tbWakeJoint(world, joint);
}

bool tbJoint_GetCollideConnected(tbJointId jointId)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetCollideConnected", NULL, -1, false);
	return joint != NULL && joint->collideConnected;
}

void tbJoint_SetUserData(tbJointId jointId, void* userData)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_SetUserData", NULL, -1, false);
	if (joint != NULL)
	{
		joint->userData = userData;
	}
}

void* tbJoint_GetUserData(tbJointId jointId)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetUserData", NULL, -1, false);
	return joint != NULL ? joint->userData : NULL;
}

void tbJoint_WakeBodies(tbJointId jointId)
{
	TB_RECORD(JointWakeBodies, &jointId);
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_WakeBodies", &world, -1, true);
	if (joint != NULL)
	{
		tbWakeJoint(world, joint);
	}
}

static void tbGetJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque)
{
	*force = tbVec2_zero;
	*torque = 0.0f;
	switch (joint->type)
	{
		case tb_distanceJoint:
			tbGetDistanceJointReaction(world, joint, inv_h, force, torque);
			break;
		case tb_motorJoint:
			tbGetMotorJointReaction(world, joint, inv_h, force, torque);
			break;
		case tb_moverJoint:
			tbGetMoverJointReaction(world, joint, inv_h, force, torque);
			break;
		case tb_pogoJoint:
			tbGetPogoJointReaction(world, joint, inv_h, force, torque);
			break;
		case tb_prismaticJoint:
			tbGetPrismaticJointReaction(world, joint, inv_h, force, torque);
			break;
		case tb_revoluteJoint:
			tbGetRevoluteJointReaction(world, joint, inv_h, force, torque);
			break;
		case tb_weldJoint:
			tbGetWeldJointReaction(world, joint, inv_h, force, torque);
			break;
		case tb_wheelJoint:
			tbGetWheelJointReaction(world, joint, inv_h, force, torque);
			break;
		default:
			break;
	}
}

tbVec2 tbJoint_GetConstraintForce(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetConstraintForce", &world, -1, false);
	tbVec2 force = tbVec2_zero;
	float torque = 0.0f;
	if (joint != NULL)
	{
		tbGetJointReaction(world, joint, world->jointInvH, &force, &torque);
	}
	return force;
}

float tbJoint_GetConstraintTorque(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetConstraintTorque", &world, -1, false);
	tbVec2 force = tbVec2_zero;
	float torque = 0.0f;
	if (joint != NULL)
	{
		tbGetJointReaction(world, joint, world->jointInvH, &force, &torque);
	}
	return torque;
}

// Motor, mover and pogo joints are user forces (velocity targets and a spring) with nothing rigid
// to violate, the filter joint has no rows, and the wheel joint turns freely: all read 0 where
// their kind has no entry below.
float tbJoint_GetLinearSeparation(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetLinearSeparation", &world, -1, false);
	if (joint == NULL)
	{
		return 0.0f;
	}
	switch (joint->type)
	{
		case tb_distanceJoint:
			return tbDistanceJointLinearSeparation(world, joint);
		case tb_prismaticJoint:
			return tbAxisJointLinearSeparation(world, joint, joint->prismatic.enableLimit,
											   joint->prismatic.lowerTranslation, joint->prismatic.upperTranslation);
		case tb_revoluteJoint:
			return tbRevoluteJointLinearSeparation(world, joint);
		case tb_weldJoint:
			return tbWeldJointLinearSeparation(world, joint);
		case tb_wheelJoint:
			return tbAxisJointLinearSeparation(world, joint, joint->wheel.enableLimit, joint->wheel.lowerTranslation,
											   joint->wheel.upperTranslation);
		default:
			return 0.0f;
	}
}

float tbJoint_GetAngularSeparation(tbJointId jointId)
{
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetAngularSeparation", &world, -1, false);
	if (joint == NULL)
	{
		return 0.0f;
	}
	switch (joint->type)
	{
		case tb_prismaticJoint:
			return tbPrismaticJointAngularSeparation(world, joint);
		case tb_revoluteJoint:
			return tbRevoluteJointAngularSeparation(world, joint);
		case tb_weldJoint:
			return tbWeldJointAngularSeparation(world, joint);
		default:
			return 0.0f;
	}
}

bool tbJoint_SetConstraintTuning(tbJointId jointId, float hertz, float dampingRatio)
{
	TB_RECORD(JointSetConstraintTuning, &jointId, &hertz, &dampingRatio);
	const char* f = "tbJoint_SetConstraintTuning";
	tbWorld* world;
	tbJoint* joint = tbGetJointChecked(jointId, f, &world, -1, true);
	if (joint == NULL || tbCheckNonNegative(f, "hertz", hertz) == false ||
		tbCheckNonNegative(f, "dampingRatio", dampingRatio) == false)
	{
		return false;
	}
	joint->constraintHertz = hertz;
	joint->constraintDampingRatio = dampingRatio;
	tbWakeJoint(world, joint);
	return true;
}

void tbJoint_GetConstraintTuning(tbJointId jointId, float* hertz, float* dampingRatio)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetConstraintTuning", NULL, -1, false);
	if (hertz != NULL)
	{
		*hertz = joint != NULL ? joint->constraintHertz : 0.0f;
	}
	if (dampingRatio != NULL)
	{
		*dampingRatio = joint != NULL ? joint->constraintDampingRatio : 0.0f;
	}
}

bool tbJoint_SetForceThreshold(tbJointId jointId, float threshold)
{
	TB_RECORD(JointSetForceThreshold, &jointId, &threshold);
	const char* f = "tbJoint_SetForceThreshold";
	tbJoint* joint = tbGetJointChecked(jointId, f, NULL, -1, true);
	if (joint == NULL || tbCheckNonNegative(f, "threshold", threshold) == false)
	{
		return false;
	}
	joint->forceThreshold = threshold;
	return true;
}

float tbJoint_GetForceThreshold(tbJointId jointId)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetForceThreshold", NULL, -1, false);
	return joint != NULL ? joint->forceThreshold : 0.0f;
}

bool tbJoint_SetTorqueThreshold(tbJointId jointId, float threshold)
{
	TB_RECORD(JointSetTorqueThreshold, &jointId, &threshold);
	const char* f = "tbJoint_SetTorqueThreshold";
	tbJoint* joint = tbGetJointChecked(jointId, f, NULL, -1, true);
	if (joint == NULL || tbCheckNonNegative(f, "threshold", threshold) == false)
	{
		return false;
	}
	joint->torqueThreshold = threshold;
	return true;
}

float tbJoint_GetTorqueThreshold(tbJointId jointId)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetTorqueThreshold", NULL, -1, false);
	return joint != NULL ? joint->torqueThreshold : 0.0f;
}

bool tbJoint_SetDrawScale(tbJointId jointId, float drawScale)
{
	const char* f = "tbJoint_SetDrawScale";
	tbJoint* joint = tbGetJointChecked(jointId, f, NULL, -1, false);
	if (joint == NULL || tbCheckNonNegative(f, "drawScale", drawScale) == false)
	{
		return false;
	}
	joint->drawScale = drawScale;
	return true;
}

float tbJoint_GetDrawScale(tbJointId jointId)
{
	tbJoint* joint = tbGetJointChecked(jointId, "tbJoint_GetDrawScale", NULL, -1, false);
	return joint != NULL ? joint->drawScale : 0.0f;
}

int tbBody_GetJointCount(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetJointCount", NULL, false);
	return body != NULL ? body->jointCount : 0;
}

int tbBody_GetJoints(tbBodyId bodyId, tbJointId* jointArray, int capacity)
{
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetJoints", &world, false);
	if (body == NULL || tbCheckPointer("tbBody_GetJoints", "jointArray", jointArray) == false)
	{
		return 0;
	}
	int count = 0;
	for (int key = body->headJointKey; key != TB_NULL_INDEX && count < capacity;)
	{
		const tbJoint* joint = world->joints + (key >> 1);
		jointArray[count++] = tbMakeJointId(world, joint);
		key = joint->edges[key & 1].nextKey;
	}
	return count;
}

tbJointEvents tbWorld_GetJointEvents(tbWorldId worldId)
{
	tbJointEvents events = {0};
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetJointEvents");
	if (world != NULL)
	{
		events.jointEvents = world->events.jointEvents;
		events.count = world->events.jointEventCount;
	}
	return events;
}

tbWorldTransform tbJointWorldFrameA(const tbWorld* world, const tbJoint* joint)
{
	return tbMulWorldTransforms(world->bodies[joint->edges[0].bodyId].transform, joint->localFrameA);
}

tbWorldTransform tbJointWorldFrameB(const tbWorld* world, const tbJoint* joint)
{
	return tbMulWorldTransforms(world->bodies[joint->edges[1].bodyId].transform, joint->localFrameB);
}

// ---------------------------------------------------------------------------------------------
// The step

static bool tbIsAwakeDynamic(const tbBody* body)
{
	return body->type == tb_dynamicBody && body->awakeIndex != TB_NULL_INDEX;
}

// The part of the preparation every kind shares: the solver's view of the two bodies and the
// positional softness of the chosen method.
static void tbPrepareJointBase(tbJoint* joint, const tbStepContext* context)
{
	const tbWorld* world = context->world;
	const tbBody* a = world->bodies + joint->edges[0].bodyId;
	const tbBody* b = world->bodies + joint->edges[1].bodyId;
	// Static and sleeping bodies stand in as the motionless body at index bodyCount.
	joint->indexA = a->awakeIndex != TB_NULL_INDEX ? a->awakeIndex : context->bodyCount;
	joint->indexB = b->awakeIndex != TB_NULL_INDEX ? b->awakeIndex : context->bodyCount;
	bool dynamicA = tbIsAwakeDynamic(a);
	bool dynamicB = tbIsAwakeDynamic(b);
	joint->invMassA = dynamicA ? a->invMass : 0.0f;
	joint->invIA = dynamicA && a->fixedRotation == false ? a->invInertia : 0.0f;
	joint->invMassB = dynamicB ? b->invMass : 0.0f;
	joint->invIB = dynamicB && b->fixedRotation == false ? b->invInertia : 0.0f;

	// Anchor minus centre of mass, in world axes: rotate(q, localFrame.p − localCenter).
	joint->frameA.q = tbMulRot(a->transform.q, joint->localFrameA.q);
	joint->frameA.p = tbRotateVector(a->transform.q, tbSub(joint->localFrameA.p, a->localCenter));
	joint->frameB.q = tbMulRot(b->transform.q, joint->localFrameB.q);
	joint->frameB.p = tbRotateVector(b->transform.q, tbSub(joint->localFrameB.p, b->localCenter));
	joint->deltaCenter = tbSubPos(b->center, a->center);

	if (world->def.solver == tb_solverSoft)
	{
		float hertz = tbMinFloat(joint->constraintHertz, 0.25f * context->inv_h);
		joint->constraintSoftness = tbMakeSoftness(hertz, joint->constraintDampingRatio, context->h);
	}
	else
	{
		tbSoftness baumgarte = {TB_BAUMGARTE * context->inv_h, 1.0f, 0.0f};
		joint->constraintSoftness = baumgarte;
	}
}

/// Joints prepared per range of the workers' loop: each joint writes only itself.
#define TB_JOINTS_PER_TASK 256

static void tbPrepareJoint(tbJoint* joint, const tbStepContext* context)
{
	tbPrepareJointBase(joint, context);
	joint->treeNode = TB_NULL_INDEX;
	joint->solvedInTree = false;
	joint->loopyMechanism = false;
	joint->rigidPin = false;
	switch (joint->type)
	{
		case tb_distanceJoint:
			tbPrepareDistanceJoint(joint, context);
			break;
		case tb_motorJoint:
			tbPrepareMotorJoint(joint, context);
			break;
		case tb_moverJoint:
			tbPrepareMoverJoint(joint, context);
			break;
		case tb_pogoJoint:
			tbPreparePogoJoint(joint, context);
			break;
		case tb_prismaticJoint:
			tbPreparePrismaticJoint(joint, context);
			break;
		case tb_revoluteJoint:
			tbPrepareRevoluteJoint(joint, context);
			break;
		case tb_weldJoint:
			tbPrepareWeldJoint(joint, context);
			break;
		case tb_wheelJoint:
			tbPrepareWheelJoint(joint, context);
			break;
		default:
			break;
	}
}

/// Whether the solver takes the joint this step: in use, not a filter joint, and joining an awake
/// dynamic body (joined bodies wake together, so the other side is awake too, or static, or a
/// resting kinematic body).
static bool tbIsSolverJoint(const tbWorld* world, const tbJoint* joint)
{
	return joint->inUse && joint->type != tb_filterJoint &&
		   (tbIsAwakeDynamic(world->bodies + joint->edges[0].bodyId) ||
			tbIsAwakeDynamic(world->bodies + joint->edges[1].bodyId));
}

typedef struct tbPrepareJointsContext
{
	const tbStepContext* context;
	uint8_t* taken;		   ///< a byte per joint slot: 1 when the solver takes it
	atomic_int thresholds; ///< some joint taken has a force or torque threshold (tbFinishJoints)
} tbPrepareJointsContext;

/// Whether the joint reports joint events (tbFinishJoints): it has a finite threshold.
static bool tbHasJointThreshold(const tbJoint* joint)
{
	return !(joint->forceThreshold >= FLT_MAX && joint->torqueThreshold >= FLT_MAX);
}

/// Joint slots [startIndex, endIndex) in id order: each one the solver takes is prepared (writing
/// only itself) and marked.
static void tbPrepareJointsTask(int startIndex, int endIndex, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	tbPrepareJointsContext* task = taskContext;
	tbWorld* world = task->context->world;
	bool thresholds = false;
	for (int id = startIndex; id < endIndex; ++id)
	{
		tbJoint* joint = world->joints + id;
		bool taken = tbIsSolverJoint(world, joint);
		if (taken)
		{
			tbPrepareJoint(joint, task->context);
			thresholds = thresholds || tbHasJointThreshold(joint);
		}
		task->taken[id] = taken ? 1u : 0u;
	}
	if (thresholds)
	{
		atomic_store_explicit(&task->thresholds, 1, memory_order_relaxed);
	}
}

void tbPrepareJoints(tbStepContext* context)
{
	tbWorld* world = context->world;
	world->cache.solverJointCount = 0;
	world->events.jointEventCount = 0;
	world->cache.jointTreeCount = 0; // the trees live in the step arena: none survive a step
	world->cache.jointTreeNodeCount = 0;
	if (world->jointPool.count == 0)
	{
		return;
	}
	// One pass over the pool in id order, on the workers: each joint the solver takes is prepared
	// and marked; then the marked ids are listed in id order on the caller. On one thread the pass
	// was a large part of a two-worker step for a large grid of joints.
	int slots = world->jointPool.highWater;
	TB_ARRAY_RESERVE(world->cache.solverJoints, world->cache.solverJointCapacity, slots);
	tbPrepareJointsContext task;
	task.context = context;
	task.taken = tbArenaAlloc(&world->stepArena, slots);
	atomic_init(&task.thresholds, 0);
	tbParallelFor(&world->def, tbPrepareJointsTask, slots, TB_JOINTS_PER_TASK, &task);
	context->jointThresholds = atomic_load_explicit(&task.thresholds, memory_order_relaxed) != 0;
	int* ids = world->cache.solverJoints;
	int count = 0;
	for (int id = 0; id < slots; ++id)
	{
		ids[count] = id;
		count += task.taken[id];
	}
	world->cache.solverJointCount = count;
}

// Joints are visited in solve order, colour by colour, so their 272-byte records are scattered
// over the joint pool (a large grid of joints spans megabytes): ask for the one `ahead` places on.
// The warm start asks twice as far ahead as the solve: its work per joint is so short that at the
// solve's distance the line arrived only just before it was needed; the solve, longer per joint,
// gained nothing from asking farther.
#define TB_JOINT_WARM_START_AHEAD (2 * TB_PREFETCH_AHEAD)

static inline void tbPrefetchJointAhead(const tbWorld* world, int i, int end, int ahead)
{
	if (i + ahead < end)
	{
		// The solve's part only: the edges, ids and API fields after the kind's data stay behind.
		tbPrefetch(world->joints + world->cache.solverJoints[i + ahead], (int)offsetof(tbJoint, edges));
	}
}

void tbWarmStartJointRange(tbStepContext* context, int begin, int end)
{
	tbWorld* world = context->world;
	for (int i = begin; i < end; ++i)
	{
		tbJoint* joint = world->joints + world->cache.solverJoints[i];
		tbPrefetchJointAhead(world, i, end, TB_JOINT_WARM_START_AHEAD);
		switch (joint->type)
		{
			case tb_distanceJoint:
				tbWarmStartDistanceJoint(joint, context);
				break;
			case tb_motorJoint:
				tbWarmStartMotorJoint(joint, context);
				break;
			case tb_moverJoint:
				tbWarmStartMoverJoint(joint, context);
				break;
			case tb_pogoJoint:
				tbWarmStartPogoJoint(joint, context);
				break;
			case tb_prismaticJoint:
				tbWarmStartPrismaticJoint(joint, context);
				break;
			case tb_revoluteJoint:
				tbWarmStartRevoluteJoint(joint, context);
				break;
			case tb_weldJoint:
				tbWarmStartWeldJoint(joint, context);
				break;
			case tb_wheelJoint:
				tbWarmStartWheelJoint(joint, context);
				break;
			default:
				break;
		}
	}
}

void tbWarmStartJoints(tbStepContext* context)
{
	tbStepCache_BodiesMoved(&context->world->cache); // a new sub-step
	tbWarmStartJointRange(context, 0, context->world->cache.solverJointCount);
}

void tbSolveJointRowRange(tbStepContext* context, int begin, int end, bool useBias)
{
	tbWorld* world = context->world;
	for (int i = begin; i < end; ++i)
	{
		tbJoint* joint = world->joints + world->cache.solverJoints[i];
		tbPrefetchJointAhead(world, i, end, TB_PREFETCH_AHEAD);
		switch (joint->type)
		{
			case tb_distanceJoint:
				tbSolveDistanceJoint(joint, context, useBias);
				break;
			case tb_motorJoint:
				tbSolveMotorJoint(joint, context, useBias);
				break;
			case tb_moverJoint:
				tbSolveMoverJoint(joint, context, useBias);
				break;
			case tb_pogoJoint:
				tbSolvePogoJoint(joint, context, useBias);
				break;
			case tb_prismaticJoint:
				tbSolvePrismaticJoint(joint, context, useBias);
				break;
			case tb_revoluteJoint:
				tbSolveRevoluteJoint(joint, context, useBias);
				break;
			case tb_weldJoint:
				tbSolveWeldJoint(joint, context, useBias);
				break;
			case tb_wheelJoint:
				tbSolveWheelJoint(joint, context, useBias);
				break;
			default:
				break;
		}
	}
}

// A pass over the joints. The relaxing pass, and a biased pass without trees, solve every row one
// at a time. A biased pass with joint trees (joint_tree.c) sweeps symmetrically: the joints' own
// rows (springs, motors, limits, and the equality rows of joints outside the trees), the trees'
// equality rows exactly, then the joints' own rows again, since the exact solve moved their bodies:
// left last, it would undo part of what the motors and limits did, and a pile of ragdolls with
// friction motors keeps many more bodies above the sleep speed with rows then trees than with the
// symmetric sweep (docs/methods.md, "Joint trees"). Exact solves in the relaxing pass too cost
// twice the work for the same peak chain stretch. Positions change only between sub-steps, so the
// trees are factored once per sub-step (the first biased pass: Baumgarte and NGS run several).
void tbBeginJointPass(tbStepContext* context, bool useBias)
{
	tbWorld* world = context->world;
	if (useBias && world->cache.jointTreesStale)
	{
		tbFactorJointTrees(context);
		world->cache.jointTreesStale = false;
	}
	tbMarkTreeRows(context, useBias);
}

void tbSolveJoints(tbStepContext* context, bool useBias)
{
	tbWorld* world = context->world;
	tbBeginJointPass(context, useBias);
	tbSolveJointRowRange(context, 0, world->cache.solverJointCount, useBias);
	if (useBias && world->cache.jointTreeCount > 0)
	{
		tbSolveJointTrees(context);
		tbSolveJointRowRange(context, 0, world->cache.solverJointCount, useBias);
	}
}

// Rigid tree rows have no compliance to damp them, and one relaxing iteration does not remove the
// correction velocity they leave where contacts close loops between trees: in a pile of ragdolls
// it leaves a jitter that keeps bodies above the sleep speed (row by row leaves none), and a
// second iteration removes it. More joint-only sweeps or exact relaxing of the trees do not do
// it: joints and contacts must relax together. So a step with joint trees relaxes twice more
// than the world asks: once more still left a ragdoll of the pile moving and the pile awake,
// twice more lets it sleep, for a somewhat dearer step (docs/methods.md, "Joint trees").
int tbJointTreeRelaxIterations(const tbStepContext* context)
{
	const tbWorld* world = context->world;
	return world->cache.jointTreeCount > 0 && world->def.relaxIterations > 0 ? 2 : 0;
}

// The relaxing iterations after the first are there for contact stacks (card houses, docs/
// stability.md); joints solved row by row are relaxed by the first alone, as Box2D v3.2 relaxes
// them once: relaxing them in every iteration closes the pins of a large grid of joints only a
// little further for a much dearer solve (docs/methods.md, "Relaxing"). Joint trees need their
// rows relaxed in every iteration, with the contacts (tbJointTreeRelaxIterations above).
bool tbRelaxJointsInIteration(const tbStepContext* context, int iteration)
{
	return iteration == 0 || context->world->cache.jointTreeCount > 0;
}

void tbSetJointRow(tbJointRows* rows, int row, tbVec3Row a, tbVec3Row b, float C, float* impulse)
{
	float* ja = rows->JA + 3 * row;
	float* jb = rows->JB + 3 * row;
	ja[0] = a.x;
	ja[1] = a.y;
	ja[2] = a.w;
	jb[0] = b.x;
	jb[1] = b.y;
	jb[2] = b.w;
	rows->bias[row] = C;
	rows->impulse[row] = impulse;
}

int tbJointEqualityRowCount(const tbJoint* joint)
{
	switch (joint->type)
	{
		case tb_distanceJoint:
			return tbDistanceJointIsRigid(joint) ? 1 : 0;
		case tb_prismaticJoint:
		case tb_revoluteJoint:
			return 2;
		case tb_weldJoint:
			return (joint->weld.linearHertz == 0.0f ? 2 : 0) + (joint->weld.angularHertz == 0.0f ? 1 : 0);
		case tb_wheelJoint:
			return 1;
		default:
			return 0;
	}
}

void tbGetJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows)
{
	int count = 0;
	switch (joint->type)
	{
		case tb_distanceJoint:
			count = tbDistanceJointEqualityRows(joint, b, rows);
			break;
		case tb_prismaticJoint:
			count = tbPrismaticJointEqualityRows(joint, b, rows);
			break;
		case tb_revoluteJoint:
			count = tbRevoluteJointEqualityRows(joint, b, rows);
			break;
		case tb_weldJoint:
			count = tbWeldJointEqualityRows(joint, b, rows);
			break;
		case tb_wheelJoint:
			count = tbWheelJointEqualityRows(joint, b, rows);
			break;
		default:
			break;
	}
	// The rows hold their position error C; the bias of the biased pass is β·C.
	float beta = joint->constraintSoftness.biasRate;
	for (int r = 0; r < count; ++r)
	{
		rows->bias[r] *= beta;
	}
}

// Joint events: the force and torque come from the impulses the joint holds at the end of the
// step (one sub-step's worth, so force = impulse/h). Box2D v3 tests during the biased passes
// instead; the end of the step is the force the game sees through tbJoint_GetConstraintForce.
void tbFinishJoints(tbStepContext* context)
{
	tbWorld* world = context->world;
	world->jointInvH = context->inv_h;
	if (context->jointThresholds == false)
	{
		return; // no joint taken this step can report (most worlds): no walk over every joint
	}
	for (int i = 0; i < world->cache.solverJointCount; ++i)
	{
		tbJoint* joint = world->joints + world->cache.solverJoints[i];
		if (tbHasJointThreshold(joint) == false)
		{
			continue;
		}
		tbVec2 force;
		float torque;
		tbGetJointReaction(world, joint, context->inv_h, &force, &torque);
		if (tbLength(force) >= joint->forceThreshold || tbAbsFloat(torque) >= joint->torqueThreshold)
		{
			tbJointEvent event = {tbMakeJointId(world, joint), joint->userData};
			TB_ARRAY_PUSH(world->events.jointEvents, world->events.jointEventCount, world->events.jointEventCapacity, event);
		}
	}
}

// ---------------------------------------------------------------------------------------------
// Islands, waking and the pair filter

void tbWakeJointedBodies(tbWorld* world, tbBody* body)
{
	if (body->type != tb_dynamicBody || body->headJointKey == TB_NULL_INDEX)
	{
		return;
	}
	// An explicit stack instead of recursion (a long chain would be a deep recursion): a nested
	// call, made by the tbWakeBody below, only pushes its body; the outer loop walks it.
	TB_ARRAY_PUSH(world->cache.jointWakeStack, world->cache.jointWakeCount, world->cache.jointWakeCapacity, (int)(body - world->bodies));
	if (world->cache.jointWakeActive)
	{
		return;
	}
	world->cache.jointWakeActive = true;
	while (world->cache.jointWakeCount > 0)
	{
		const tbBody* b = world->bodies + world->cache.jointWakeStack[--world->cache.jointWakeCount];
		for (int key = b->headJointKey; key != TB_NULL_INDEX;)
		{
			const tbJoint* joint = world->joints + (key >> 1);
			tbBody* other = world->bodies + joint->edges[(key & 1) ^ 1].bodyId;
			if (joint->type != tb_filterJoint && other->type != tb_staticBody && other->awakeIndex == TB_NULL_INDEX)
			{
				tbWakeBody(world, other);
			}
			key = joint->edges[key & 1].nextKey;
		}
	}
	world->cache.jointWakeActive = false;
}

/// The rule contacts follow (island.c): an awake dynamic body wakes what it is joined to; a
/// kinematic one only while it moves.
static bool tbWakesJoinedBody(const tbBody* body)
{
	if (body->awakeIndex == TB_NULL_INDEX)
	{
		return false;
	}
	bool moving = tbLengthSquared(body->linearVelocity) > 0.0f || body->angularVelocity != 0.0f;
	return body->type == tb_dynamicBody || (body->type == tb_kinematicBody && moving);
}

void tbWakeJointPartners(tbWorld* world)
{
	// Joined bodies wake together, so a joint has one side awake and the other asleep only after a
	// sleeping island took a kinematic body with it, or after tbBody_SetAwake(false) on one body.
	// Joined bodies join and leave the awake set together, so with no kinematic body (whose
	// velocity can change while both sides keep their state) a half-asleep joint can only appear
	// when the awake set changed: a grid of 19,800 joints that all stay awake skips the walk.
	if (world->jointPool.count == 0 || (world->cache.jointWakeDirty == false && world->kinematicBodyCount == 0))
	{
		return;
	}
	world->cache.jointWakeDirty = false;
	for (int id = 0; id < world->jointPool.highWater; ++id)
	{
		const tbJoint* joint = world->joints + id;
		if (joint->inUse == false || joint->type == tb_filterJoint)
		{
			continue;
		}
		tbBody* a = world->bodies + joint->edges[0].bodyId;
		tbBody* b = world->bodies + joint->edges[1].bodyId;
		if (b->type != tb_staticBody && b->awakeIndex == TB_NULL_INDEX && tbWakesJoinedBody(a))
		{
			tbWakeBody(world, b);
		}
		else if (a->type != tb_staticBody && a->awakeIndex == TB_NULL_INDEX && tbWakesJoinedBody(b))
		{
			tbWakeBody(world, a);
		}
	}
}

bool tbJointBlocksCollision(const tbWorld* world, int bodyIdA, int bodyIdB)
{
	const tbBody* a = world->bodies + bodyIdA;
	const tbBody* b = world->bodies + bodyIdB;
	int key = a->jointCount <= b->jointCount ? a->headJointKey : b->headJointKey;
	int other = a->jointCount <= b->jointCount ? bodyIdB : bodyIdA;
	while (key != TB_NULL_INDEX)
	{
		const tbJoint* joint = world->joints + (key >> 1);
		if (joint->edges[(key & 1) ^ 1].bodyId == other && joint->collideConnected == false)
		{
			return true;
		}
		key = joint->edges[key & 1].nextKey;
	}
	return false;
}

// ---------------------------------------------------------------------------------------------
// Drawing

/// The extras (tbDebugDraw::drawJointExtras): the constraint force of the last step at anchor B,
/// forceScale metres per newton, with its magnitude, what tbJoint_GetConstraintForce returns.
static void tbDrawJointForce(tbWorld* world, const tbDebugDraw* draw, const tbJoint* joint)
{
	tbVec2 force = tbVec2_zero;
	float torque = 0.0f;
	tbGetJointReaction(world, joint, world->jointInvH, &force, &torque);
	tbVec2 p = tbToVec2(tbJointWorldFrameB(world, joint).p);
	tbDrawLine(draw, p, tbMulAdd(p, draw->forceScale, force), tb_colorMagenta);
	char text[48];
	snprintf(text, sizeof(text), "%.1f N, %.1f N·m", (double)tbLength(force), (double)torque);
	tbDrawStringAt(draw, p, text, tb_colorWhite);
}

void tbDrawJoints(tbWorld* world, const tbDebugDraw* draw)
{
	if (draw->drawJoints == false)
	{
		return;
	}
	for (int id = 0; id < world->jointPool.highWater; ++id)
	{
		if (world->joints[id].inUse == false)
		{
			continue;
		}
		// Drawn at the joint's own size times the view's (tbDebugDraw::jointScale); the joint's
		// drawScale itself is left as the game set it.
		tbJoint scaled = world->joints[id];
		scaled.drawScale *= draw->jointScale;
		const tbJoint* joint = &scaled;
		if (draw->drawJointExtras)
		{
			tbDrawJointForce(world, draw, joint);
		}
		switch (joint->type)
		{
			case tb_distanceJoint:
				tbDrawDistanceJoint(draw, world, joint);
				break;
			case tb_motorJoint:
				tbDrawMotorJoint(draw, world, joint);
				break;
			case tb_moverJoint:
				tbDrawMoverJoint(draw, world, joint);
				break;
			case tb_pogoJoint:
				tbDrawPogoJoint(draw, world, joint);
				break;
			case tb_prismaticJoint:
				tbDrawPrismaticJoint(draw, world, joint);
				break;
			case tb_revoluteJoint:
				tbDrawRevoluteJoint(draw, world, joint);
				break;
			case tb_weldJoint:
				tbDrawWeldJoint(draw, world, joint);
				break;
			case tb_wheelJoint:
				tbDrawWheelJoint(draw, world, joint);
				break;
			default:
			{
				// Filter joint: a thin link between the body origins.
				tbVec2 pA = tbToVec2(world->bodies[joint->edges[0].bodyId].transform.p);
				tbVec2 pB = tbToVec2(world->bodies[joint->edges[1].bodyId].transform.p);
				tbDrawLine(draw, pA, pB, tb_colorAABB);
				break;
			}
		}
	}
}
