// Bodies: creation and destruction, the awake set, mass from shapes, getters and setters, and
// the finalize stage (shape boxes, broad-phase moves, sleep timers, move events).
#include "body.h"

#include "chain.h"
#include "world.h"

#include "core/task.h"
#include "joints/joint.h"

#include "core/array.h"
#include "recording.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define TB_BODY_DEF_MAGIC 0x7B3A1C02

tbBodyDef tbDefaultBodyDef(void)
{
	tbBodyDef def;
	memset(&def, 0, sizeof(def));
	def.type = tb_staticBody;
	def.rotation = tbRot_identity;
	def.gravityScale = 1.0f;
	def.sleepThreshold = TB_LINEAR_SLEEP_TOLERANCE;
	def.safetyFactor = TB_CONTINUOUS_FRACTION;
	def.enableSleep = true;
	def.enableContactRecycling = true;
	def.isAwake = true;
	def.isEnabled = true;
	def.allowFastRotation = false;
	def.internalValue = TB_BODY_DEF_MAGIC;
	return def;
}

tbBodyId tbMakeBodyId(const tbWorld* world, int bodyId)
{
	tbBodyId id = {bodyId + 1, world->worldId, world->bodies[bodyId].generation};
	return id;
}

tbBody* tbGetBodyChecked(tbBodyId id, const char* function, tbWorld** worldOut, bool mutating)
{
	if (id.index1 <= 0)
	{
		tbReportError(function, "bodyId is null; pass an id returned by tbCreateBody");
		return NULL;
	}
	tbWorld* world = id.world0 < TB_MAX_WORLDS ? tbGetWorldFromIndex(id.world0) : NULL;
	int index = id.index1 - 1;
	if (world == NULL || index >= world->bodyPool.highWater || world->bodies[index].inUse == false ||
		world->bodies[index].generation != id.generation)
	{
		tbReportError(function, "bodyId refers to a destroyed body or world; do not use a body id after "
								"tbDestroyBody/tbDestroyWorld (check with tbBody_IsValid)");
		return NULL;
	}
	if (mutating && world->locked)
	{
		tbReportError(function, "the world is locked (stepping); change bodies between steps");
		return NULL;
	}
	if (worldOut != NULL)
	{
		*worldOut = world;
	}
	return world->bodies + index;
}

bool tbBody_IsValid(tbBodyId id)
{
	if (id.index1 <= 0 || id.world0 >= TB_MAX_WORLDS)
	{
		return false;
	}
	tbWorld* world = tbGetWorldFromIndex(id.world0);
	int index = id.index1 - 1;
	return world != NULL && index < world->bodyPool.highWater && world->bodies[index].inUse &&
		   world->bodies[index].generation == id.generation;
}

static bool tbCheckBodyDef(const tbBodyDef* def)
{
	const char* f = "tbCreateBody";
	if (tbCheckPointer(f, "def", def) == false)
	{
		return false;
	}
	if (def->internalValue != TB_BODY_DEF_MAGIC)
	{
		tbReportError(f, "def was not initialised by tbDefaultBodyDef(); start from tbDefaultBodyDef() and change fields");
		return false;
	}
	if ((unsigned)def->type >= tb_bodyTypeCount)
	{
		tbReportError(f, "def->type is %d; use tb_staticBody, tb_kinematicBody or tb_dynamicBody", (int)def->type);
		return false;
	}
	if (tbIsValidRotation(def->rotation) == false)
	{
		tbReportError(f, "def->rotation is (%g, %g), not a unit rotation; make it with tbMakeRot(angle)",
					  (double)def->rotation.c, (double)def->rotation.s);
		return false;
	}
	return tbCheckPosition(f, "def->position", def->position) &&
		   tbCheckVec2(f, "def->linearVelocity", def->linearVelocity) &&
		   tbCheckFloat(f, "def->angularVelocity", def->angularVelocity) &&
		   tbCheckNonNegative(f, "def->linearDamping", def->linearDamping) &&
		   tbCheckNonNegative(f, "def->angularDamping", def->angularDamping) &&
		   tbCheckFloat(f, "def->gravityScale", def->gravityScale) &&
		   tbCheckNonNegative(f, "def->sleepThreshold", def->sleepThreshold) &&
		   tbCheckNonNegative(f, "def->safetyFactor", def->safetyFactor);
}

// The awake list keeps its order (the solver order must not depend on which body slept first), so
// a removal leaves a hole (TB_NULL_INDEX) that the next step, or the next body to join, closes in
// one pass over the list. Shifting the list at every removal cost O(awake bodies) per body: a game
// destroying 100 of 20,000 awake bodies moved and re-indexed two million entries.
void tbCompactAwakeSet(tbWorld* world)
{
	if (world->awakeHoles == 0)
	{
		return;
	}
	int kept = 0;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		int id = world->awakeBodies[i];
		if (id == TB_NULL_INDEX)
		{
			continue;
		}
		world->awakeBodies[kept] = id;
		world->bodies[id].awakeIndex = kept;
		kept += 1;
	}
	world->awakeBodyCount = kept;
	world->awakeHoles = 0;
}

static void tbAddToAwakeSet(tbWorld* world, tbBody* body, int bodyId)
{
	tbCompactAwakeSet(world); // appended after the bodies still awake, as if removed eagerly
	body->awakeIndex = world->awakeBodyCount;
	TB_ARRAY_PUSH(world->awakeBodies, world->awakeBodyCount, world->awakeBodyCapacity, bodyId);
	tbStepCache_AwakeSetChanged(&world->cache, false);
}

static void tbRemoveFromAwakeSet(tbWorld* world, tbBody* body)
{
	world->awakeBodies[body->awakeIndex] = TB_NULL_INDEX;
	world->awakeHoles += 1;
	body->awakeIndex = TB_NULL_INDEX;
	tbStepCache_AwakeSetChanged(&world->cache, true);
}

void tbWakeBody(tbWorld* world, tbBody* body)
{
	if (body->type == tb_staticBody || body->awakeIndex != TB_NULL_INDEX || body->isDisabled)
	{
		body->sleepTime = 0.0f;
		return;
	}
	body->sleepTime = 0.0f;
	tbAddToAwakeSet(world, body, (int)(body - world->bodies));
	tbWakeJointedBodies(world, body); // joined bodies wake together (joint.c)
}

void tbSleepBody(tbWorld* world, tbBody* body)
{
	if (body->awakeIndex == TB_NULL_INDEX)
	{
		return;
	}
	tbRemoveFromAwakeSet(world, body);
	body->linearVelocity = tbVec2_zero;
	body->angularVelocity = 0.0f;
	body->force = tbVec2_zero;
	body->torque = 0.0f;
}

static int tbAllocBodySlot(tbWorld* world)
{
	bool isNew;
	int id = tbIdPool_Alloc(&world->bodyPool, &isNew);
	if (isNew)
	{
		TB_ARRAY_RESERVE(world->bodies, world->bodyCapacity, id + 1);
		memset(world->bodies + id, 0, sizeof(tbBody));
		world->bodies[id].generation = world->bodyGenerationBase;
	}
	return id;
}

tbBodyId tbCreateBody(tbWorldId worldId, const tbBodyDef* def)
{
	TB_RECORD(CreateBody, &worldId, def);
	tbWorld* world = tbGetWorldChecked(worldId, "tbCreateBody");
	if (world == NULL || tbCheckBodyDef(def) == false)
	{
		return TB_NULL_BODY_ID;
	}
	if (tbStructureLocked(world, "tbCreateBody", "create bodies"))
	{
		return TB_NULL_BODY_ID;
	}
	int id = tbAllocBodySlot(world);
	tbBody* body = world->bodies + id;
	uint16_t generation = body->generation; // advanced when the last body here was destroyed
	memset(body, 0, sizeof(tbBody));
	body->generation = generation;
	body->inUse = true;
	body->name = def->name;
	body->userData = def->userData;
	body->type = (uint8_t)def->type;
	world->kinematicBodyCount += def->type == tb_kinematicBody ? 1 : 0;
	world->staticBodyCount += def->type == tb_staticBody ? 1 : 0;
	body->transform.p = def->position;
	body->transform.q = def->rotation; // checked a unit rotation (tbCheckBodyDef); kept as given, read back exactly
	body->center = def->position;
	body->center0 = def->position;
	body->rotation0 = body->transform.q;
	body->linearVelocity = def->type == tb_staticBody ? tbVec2_zero : def->linearVelocity;
	body->angularVelocity = def->type == tb_staticBody ? 0.0f : def->angularVelocity;
	body->linearDamping = def->linearDamping;
	body->angularDamping = def->angularDamping;
	body->gravityScale = def->gravityScale;
	body->sleepThreshold = def->sleepThreshold;
	body->safetyFactor = def->safetyFactor;
	body->speculativeReach = tbMaxFloat(TB_SPECULATIVE_REACH, 0.0f); // no shape yet: minExtent 0
	body->enableSleep = def->enableSleep;
	body->fixedRotation = def->fixedRotation || def->motionLocks.angularZ;
	body->lockLinearX = def->motionLocks.linearX;
	body->lockLinearY = def->motionLocks.linearY;
	body->enableContactRecycling = def->enableContactRecycling;
	world->linearLockCount += body->lockLinearX || body->lockLinearY ? 1 : 0;
	body->isBullet = def->isBullet;
	body->allowFastRotation = def->allowFastRotation;
	world->fastRotationCount += body->allowFastRotation ? 1 : 0;
	// A body created disabled is as tbBody_Disable leaves one: its shapes get no proxies
	// (tbCreateShapeProxy is skipped for it) and it never enters the awake set until enabled.
	body->isDisabled = def->isEnabled == false;
	body->headShapeId = TB_NULL_INDEX;
	body->headContactKey = TB_NULL_INDEX;
	body->headJointKey = TB_NULL_INDEX;
	body->awakeIndex = TB_NULL_INDEX;
	body->mass = 0.0f;
	body->invMass = def->type == tb_dynamicBody ? 1.0f : 0.0f;
	tbUpdateBodyDerived(body);
	if (def->type != tb_staticBody && (def->isAwake || def->enableSleep == false) && def->isEnabled)
	{
		tbAddToAwakeSet(world, body, id);
	}
	return tbMakeBodyId(world, id);
}

void tbDestroyBodyContacts(tbWorld* world, tbBody* body, bool wakeBodies)
{
	int key = body->headContactKey;
	while (key != TB_NULL_INDEX)
	{
		tbContact* contact = world->contacts + (key >> 1);
		int next = contact->edges[key & 1].nextKey;
		tbDestroyContact(world, key >> 1, wakeBodies);
		key = next;
	}
}

void tbDestroyBody(tbBodyId bodyId)
{
	TB_RECORD(DestroyBody, &bodyId);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbDestroyBody", &world, true);
	if (body == NULL)
	{
		return;
	}
	if (tbStructureLocked(world, "tbDestroyBody", "destroy bodies"))
	{
		return;
	}
	tbDestroyBodyJoints(world, body);
	tbDestroyBodyChains(world, bodyId.index1 - 1);
	tbDestroyBodyContacts(world, body, true);
	int shapeId = body->headShapeId;
	while (shapeId != TB_NULL_INDEX)
	{
		tbShape* shape = world->shapes + shapeId;
		int next = shape->nextShapeId;
		tbDestroyShapeProxy(world, shape);
		shape->inUse = false;
		tbIdPool_Release(&world->shapePool, shapeId, &shape->generation, world->shapeGenerationBase);
		shapeId = next;
	}
	if (body->awakeIndex != TB_NULL_INDEX)
	{
		tbRemoveFromAwakeSet(world, body);
	}
	body->inUse = false;
	world->kinematicBodyCount -= body->type == tb_kinematicBody ? 1 : 0;
	world->staticBodyCount -= body->type == tb_staticBody ? 1 : 0;
	world->linearLockCount -= body->lockLinearX || body->lockLinearY ? 1 : 0;
	world->fastRotationCount -= body->allowFastRotation ? 1 : 0;
	tbIdPool_Release(&world->bodyPool, bodyId.index1 - 1, &body->generation, world->bodyGenerationBase);
}

/// The reach of a body's speculative contacts, max(TB_SPECULATIVE_REACH, safetyFactor × minExtent)
/// (safetyFactor is TB_CONTINUOUS_FRACTION unless the game set another): cached in the body's first
/// cache line, where the narrow phase reads it per contact; refreshed whenever an input changes.
static void tbUpdateSpeculativeReach(tbBody* body)
{
	body->speculativeReach = tbMaxFloat(TB_SPECULATIVE_REACH, body->safetyFactor * body->minExtent);
}

/// One shape's part of the body's extents about the centre of mass `center` (body frame): the
/// smallest distance to its surface, the largest to its surface and the largest to its core.
static void tbShapeExtents(const tbGeometry* g, tbVec2 center, float* minExtent, float* maxExtent, float* coreExtent)
{
	tbShapeProxy proxy = tbMakeShapeProxy(g);
	float shapeMin = proxy.radius;
	if (g->type == tb_polygonShape)
	{
		float inner = TB_HUGE;
		for (int i = 0; i < g->polygon.count; ++i)
		{
			float d = tbDot(g->polygon.normals[i], tbSub(g->polygon.vertices[i], center));
			inner = tbMinFloat(inner, d);
		}
		shapeMin = tbMaxFloat(inner, 0.0f) + g->polygon.radius;
	}
	float core = 0.0f;
	for (int i = 0; i < proxy.count; ++i)
	{
		core = tbMaxFloat(core, tbDistance(proxy.points[i], center));
	}
	*minExtent = shapeMin;
	*maxExtent = core + proxy.radius;
	*coreExtent = core;
}

void tbComputeBodyExtents(const tbWorld* world, const tbBody* body, float* minExtentOut, float* maxExtentOut,
						  float* coreExtentOut)
{
	float minExtent = TB_HUGE, maxExtent = 0.0f, coreExtent = 0.0f;
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		float shapeMin, shapeMax, shapeCore;
		tbShapeExtents(&world->shapes[id].geometry, body->localCenter, &shapeMin, &shapeMax, &shapeCore);
		minExtent = tbMinFloat(minExtent, shapeMin);
		maxExtent = tbMaxFloat(maxExtent, shapeMax);
		coreExtent = tbMaxFloat(coreExtent, shapeCore);
	}
	*minExtentOut = minExtent < TB_HUGE ? minExtent : 0.0f;
	*maxExtentOut = maxExtent;
	*coreExtentOut = coreExtent;
}

void tbUpdateBodyDerived(tbBody* body)
{
	body->originExtent = body->maxExtent + tbLength(body->localCenter);
	body->solverMoves = body->type == tb_dynamicBody &&
						(body->invMass > 0.0f || (body->fixedRotation == false && body->invInertia > 0.0f));
}

/// Extents used by continuous collision (tbComputeBodyExtents) and the reach that follows from them.
static void tbComputeExtents(tbWorld* world, tbBody* body)
{
	tbComputeBodyExtents(world, body, &body->minExtent, &body->maxExtent, &body->coreExtent);
	tbUpdateSpeculativeReach(body);
	tbUpdateBodyDerived(body);
}

void tbAddShapeExtents(tbBody* body, const tbGeometry* geometry)
{
	float shapeMin, shapeMax, shapeCore;
	tbShapeExtents(geometry, body->localCenter, &shapeMin, &shapeMax, &shapeCore);
	// min and max are exact: the same as tbComputeBodyExtents over the shapes now on the body.
	body->minExtent = body->shapeCount > 1 ? tbMinFloat(body->minExtent, shapeMin) : shapeMin;
	body->maxExtent = body->shapeCount > 1 ? tbMaxFloat(body->maxExtent, shapeMax) : shapeMax;
	body->coreExtent = body->shapeCount > 1 ? tbMaxFloat(body->coreExtent, shapeCore) : shapeCore;
	tbUpdateSpeculativeReach(body);
	tbUpdateBodyDerived(body);
}

/// Keep the velocity of the body origin when the centre of mass moves from oldCenter to
/// body->center: v_center = v_old + ω × (c_new − c_old). When that overflows float (3e38 rad/s
/// times a shift of 1e6 m), it is redone in double and scaled down to a largest component of
/// FLT_MAX, keeping the direction that the step's speed clamp then keeps too.
static void tbKeepOriginVelocity(tbBody* body, tbPos oldCenter)
{
	tbVec2 v = tbAdd(body->linearVelocity, tbCrossSV(body->angularVelocity, tbSubPos(body->center, oldCenter)));
	if (tbIsValidVec2(v) == false)
	{
		double w = body->angularVelocity;
		double vx = body->linearVelocity.x - w * ((double)body->center.y - oldCenter.y);
		double vy = body->linearVelocity.y + w * ((double)body->center.x - oldCenter.x);
		double scale = FLT_MAX / fmax(fabs(vx), fabs(vy));
		v = tbMakeVec2((float)(scale * vx), (float)(scale * vy));
	}
	body->linearVelocity = v;
}

// A rotational inertia below FLT_MIN counts as none (the body does not turn, as with fixed
// rotation): 1/I would overflow to ∞ below 1/FLT_MAX ≈ 2.9e-39 kg m², or be a subnormal's rounding
// noise, and ∞ · 0 in a contact with no lever arm gives NaN.
static void tbSetMassInertia(tbBodyMass* mass, float inertia)
{
	mass->inertia = inertia >= FLT_MIN ? inertia : 0.0f;
	mass->invInertia = mass->inertia > 0.0f ? 1.0f / mass->inertia : 0.0f;
}

static void tbSetBodyInertia(tbBody* body, float inertia)
{
	tbBodyMass mass;
	tbSetMassInertia(&mass, inertia);
	body->inertia = mass.inertia;
	body->invInertia = mass.invInertia;
}

static float tbSaturateToFloat(double value)
{
	return value < (double)FLT_MAX ? (float)value : FLT_MAX;
}

// The float sums of tbComputeBodyMass overflowed (each shape's own mass and inertia are finite,
// tbCreateShape checks that, but their sum or a mass × centre product was not). Redo them in
// double, which cannot overflow for any number of float-sized terms, and saturate the mass and
// the rotational inertia at FLT_MAX: the body then barely responds to impulses, as an enormous
// mass should, and everything stays finite.
static tbBodyMass tbSaturatedBodyMass(const tbWorld* world, const tbBody* body)
{
	tbBodyMass result = {0.0f, 0.0f, 0.0f, 0.0f, {0.0f, 0.0f}};
	double mass = 0.0, cx = 0.0, cy = 0.0, inertia = 0.0;
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		const tbShape* shape = world->shapes + id;
		tbMassData md = tbComputeShapeMass(&shape->geometry, shape->density);
		double m = md.mass, x = md.center.x, y = md.center.y;
		mass += m;
		cx += m * x;
		cy += m * y;
		inertia += (double)md.rotationalInertia + m * (x * x + y * y);
	}
	cx /= mass;
	cy /= mass;
	result.mass = tbSaturateToFloat(mass);
	result.invMass = 1.0f / result.mass;
	result.localCenter = tbMakeVec2((float)cx, (float)cy);
	if (body->fixedRotation == false)
	{
		tbSetMassInertia(&result, tbSaturateToFloat(inertia - mass * (cx * cx + cy * cy)));
	}
	return result;
}

tbBodyMass tbComputeBodyMass(const tbWorld* world, const tbBody* body)
{
	tbBodyMass result = {0.0f, 0.0f, 0.0f, 0.0f, {0.0f, 0.0f}};
	if (body->type != tb_dynamicBody)
	{
		return result;
	}
	// Accumulate mass and first moment, then inertia about the origin by the parallel-axis theorem.
	float rotationalInertia = 0.0f;
	tbVec2 localCenter = tbVec2_zero;
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		const tbShape* shape = world->shapes + id;
		if (shape->density == 0.0f)
		{
			continue;
		}
		tbMassData md = tbComputeShapeMass(&shape->geometry, shape->density);
		result.mass += md.mass;
		localCenter = tbMulAdd(localCenter, md.mass, md.center);
		rotationalInertia += md.rotationalInertia + md.mass * tbDot(md.center, md.center);
	}
	if (tbIsValidFloat(result.mass) == false || tbIsValidVec2(localCenter) == false ||
		tbIsValidFloat(rotationalInertia) == false)
	{
		return tbSaturatedBodyMass(world, body);
	}
	if (result.mass >= FLT_MIN)
	{
		result.invMass = 1.0f / result.mass;
		localCenter = tbMulSV(result.invMass, localCenter);
	}
	else
	{
		// A dynamic body without mass behaves as 1 kg at its origin so that it still falls. A mass
		// below FLT_MIN (a 1e-20 m circle: π·1e-40 kg) counts as none: 1/mass overflows to ∞ below
		// 1/FLT_MAX and the centre ∞ · (mass · centre) became ∞ · 0 = NaN.
		result.mass = 1.0f;
		result.invMass = 1.0f;
		localCenter = tbVec2_zero;
		rotationalInertia = 0.0f;
	}
	if (rotationalInertia > 0.0f && body->fixedRotation == false)
	{
		// Shift the inertia from the body origin to the centre of mass.
		tbSetMassInertia(&result, rotationalInertia - result.mass * tbDot(localCenter, localCenter));
	}
	result.localCenter = localCenter;
	return result;
}

// The accumulated impulses of a body's contacts were found for its old mass: warm starting would
// re-apply them with the new 1/m (a body made 1e20 times lighter while touching another left at
// 1e13 m/s). Its contacts restart from zero impulse; the solver finds the new ones.
static void tbRestartBodyContacts(tbWorld* world, const tbBody* body)
{
	for (int key = body->headContactKey; key != TB_NULL_INDEX;)
	{
		tbContact* contact = world->contacts + (key >> 1);
		for (int i = 0; i < contact->manifold.pointCount; ++i)
		{
			contact->manifold.points[i].normalImpulse = 0.0f;
			contact->manifold.points[i].tangentImpulse = 0.0f;
		}
		key = contact->edges[key & 1].nextKey;
	}
}

void tbUpdateBodyMass(tbWorld* world, tbBody* body)
{
	tbRestartBodyContacts(world, body);
	tbPos oldCenter = body->center;
	tbBodyMass mass = tbComputeBodyMass(world, body);
	body->mass = mass.mass;
	body->invMass = mass.invMass;
	body->inertia = mass.inertia;
	body->invInertia = mass.invInertia;
	body->localCenter = mass.localCenter;
	body->center = tbTransformWorldPoint(body->transform, body->localCenter);
	if (body->type == tb_dynamicBody)
	{
		body->center0 = body->center;
	}
	tbKeepOriginVelocity(body, oldCenter);
	tbComputeExtents(world, body);
}

// --- getters and setters ----------------------------------------------------------------------

tbBodyType tbBody_GetType(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetType", NULL, false);
	return body != NULL ? (tbBodyType)body->type : tb_staticBody;
}

bool tbBody_SetType(tbBodyId bodyId, tbBodyType type)
{
	TB_RECORD(BodySetType, &bodyId, &type);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetType", &world, true);
	if (body == NULL)
	{
		return false;
	}
	if (tbStructureLocked(world, "tbBody_SetType", "change body types"))
	{
		return false;
	}
	if ((unsigned)type >= tb_bodyTypeCount)
	{
		tbReportError("tbBody_SetType", "type is %d; use tb_staticBody, tb_kinematicBody or tb_dynamicBody", (int)type);
		return false;
	}
	if (body->type == type)
	{
		return true;
	}
	tbDestroyBodyContacts(world, body, true);
	if (body->awakeIndex != TB_NULL_INDEX)
	{
		tbRemoveFromAwakeSet(world, body);
	}
	world->kinematicBodyCount += (type == tb_kinematicBody ? 1 : 0) - (body->type == tb_kinematicBody ? 1 : 0);
	world->staticBodyCount += (type == tb_staticBody ? 1 : 0) - (body->type == tb_staticBody ? 1 : 0);
	body->type = (uint8_t)type;
	if (type == tb_staticBody)
	{
		body->linearVelocity = tbVec2_zero;
		body->angularVelocity = 0.0f;
	}
	else
	{
		tbWakeBody(world, body);
	}
	// Proxies change kind (static proxies never pair with each other): re-create them.
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		tbDestroyShapeProxy(world, world->shapes + id);
		tbCreateShapeProxy(world, world->shapes + id, body, true);
	}
	tbUpdateBodyMass(world, body);
	return true;
}

static void tbDisableBody(tbWorld* world, tbBody* body)
{
	tbDestroyBodyContacts(world, body, true);
	if (body->awakeIndex != TB_NULL_INDEX)
	{
		tbRemoveFromAwakeSet(world, body);
	}
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		tbDestroyShapeProxy(world, world->shapes + id);
	}
	body->isDisabled = true;
}

void tbBody_Disable(tbBodyId bodyId)
{
	TB_RECORD(BodyDisable, &bodyId);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_Disable", &world, true);
	if (body == NULL || body->isDisabled || tbStructureLocked(world, "tbBody_Disable", "disable bodies"))
	{
		return;
	}
	tbDisableBody(world, body);
}

void tbBody_Enable(tbBodyId bodyId)
{
	TB_RECORD(BodyEnable, &bodyId);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_Enable", &world, true);
	if (body == NULL || body->isDisabled == false || tbStructureLocked(world, "tbBody_Enable", "enable bodies"))
	{
		return;
	}
	body->isDisabled = false;
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		tbCreateShapeProxy(world, world->shapes + id, body, true);
	}
	tbWakeBody(world, body);
}

bool tbBody_IsEnabled(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_IsEnabled", NULL, false);
	return body != NULL && body->isDisabled == false;
}

tbPos tbBody_GetPosition(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetPosition", NULL, false);
	return body != NULL ? body->transform.p : tbPos_zero;
}

tbRot tbBody_GetRotation(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetRotation", NULL, false);
	return body != NULL ? body->transform.q : tbRot_identity;
}

float tbBody_GetAngle(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetAngle", NULL, false);
	return body != NULL ? tbRot_GetAngle(body->transform.q) : 0.0f;
}

tbWorldTransform tbBody_GetTransform(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetTransform", NULL, false);
	return body != NULL ? body->transform : tbWorldTransform_identity;
}

/// Wake the bodies touching this one. A teleport takes their support away, and a contact between
/// two sleeping bodies (or a sleeping and a static one) is never updated: without this a box left
/// resting on a moved body would hang in the air.
static void tbWakeTouchingBodies(tbWorld* world, const tbBody* body)
{
	for (int key = body->headContactKey; key != TB_NULL_INDEX;)
	{
		const tbContact* contact = world->contacts + (key >> 1);
		if (contact->flags & tb_contactTouching)
		{
			tbWakeBody(world, world->bodies + contact->edges[(key & 1) ^ 1].bodyId);
		}
		key = contact->edges[key & 1].nextKey;
	}
}

bool tbBody_SetTransform(tbBodyId bodyId, tbPos position, tbRot rotation)
{
	TB_RECORD(BodySetTransform, &bodyId, &position, &rotation);
	const char* f = "tbBody_SetTransform";
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, f, &world, true);
	if (body == NULL || tbCheckPosition(f, "position", position) == false)
	{
		return false;
	}
	if (tbStructureLocked(world, f, "move bodies with SetTransform"))
	{
		return false;
	}
	if (tbIsValidRotation(rotation) == false)
	{
		tbReportError(f, "rotation is (%g, %g), not a unit rotation; make it with tbMakeRot(angle)", (double)rotation.c,
					  (double)rotation.s);
		return false;
	}
	body->transform.p = position;
	body->transform.q = rotation; // as given (a unit rotation to within tbIsValidRotation's bound): it reads back exactly
	body->center = tbTransformWorldPoint(body->transform, body->localCenter);
	body->center0 = body->center;
	body->rotation0 = body->transform.q;
	tbWakeBody(world, body);
	tbWakeTouchingBodies(world, body);
	tbUpdateBodyShapeBoxes(world, body, true);
	return true;
}

tbVec2 tbBody_GetLocalPoint(tbBodyId bodyId, tbPos worldPoint)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetLocalPoint", NULL, false);
	return body != NULL ? tbInvTransformWorldPoint(body->transform, worldPoint) : tbVec2_zero;
}

tbPos tbBody_GetWorldPoint(tbBodyId bodyId, tbVec2 localPoint)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetWorldPoint", NULL, false);
	return body != NULL ? tbTransformWorldPoint(body->transform, localPoint) : tbPos_zero;
}

tbVec2 tbBody_GetLocalVector(tbBodyId bodyId, tbVec2 worldVector)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetLocalVector", NULL, false);
	return body != NULL ? tbInvRotateVector(body->transform.q, worldVector) : tbVec2_zero;
}

tbVec2 tbBody_GetWorldVector(tbBodyId bodyId, tbVec2 localVector)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetWorldVector", NULL, false);
	return body != NULL ? tbRotateVector(body->transform.q, localVector) : tbVec2_zero;
}

tbVec2 tbBody_GetLinearVelocity(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetLinearVelocity", NULL, false);
	return body != NULL ? body->linearVelocity : tbVec2_zero;
}

float tbBody_GetAngularVelocity(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetAngularVelocity", NULL, false);
	return body != NULL ? body->angularVelocity : 0.0f;
}

bool tbBody_SetLinearVelocity(tbBodyId bodyId, tbVec2 v)
{
	TB_RECORD(BodySetLinearVelocity, &bodyId, &v);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetLinearVelocity", &world, true);
	if (body == NULL || tbCheckVec2("tbBody_SetLinearVelocity", "linearVelocity", v) == false)
	{
		return false;
	}
	if (body->type == tb_staticBody)
	{
		return true;
	}
	if (tbDot(v, v) > 0.0f)
	{
		tbWakeBody(world, body);
	}
	body->linearVelocity = v;
	return true;
}

bool tbBody_SetAngularVelocity(tbBodyId bodyId, float w)
{
	TB_RECORD(BodySetAngularVelocity, &bodyId, &w);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetAngularVelocity", &world, true);
	if (body == NULL || tbCheckFloat("tbBody_SetAngularVelocity", "angularVelocity", w) == false)
	{
		return false;
	}
	if (body->type == tb_staticBody || body->fixedRotation)
	{
		return true;
	}
	if (w != 0.0f)
	{
		tbWakeBody(world, body);
	}
	body->angularVelocity = w;
	return true;
}

/// The velocity that carries a body to `target` in one step of `timeStep` (for a kinematic body
/// driven along a path, as Box2D v3's b2Body_SetTargetTransform). Linear velocity is that of the
/// centre of mass, so it aims the centre: v = (c_t − c)/Δt with c_t = p_t + R(q_t)·localCenter.
/// Angular: ω = θ/Δt, θ = atan2(q × q_t, q · q_t) ∈ [−π, π], the shortest signed angle from q to q_t.
/// The solver moves the centre by Σ h·v = Δt·v (exact up to rounding), but turns by normalised
/// first-order steps (tbIntegrateRotation): n sub-steps turn by n·atan(θ/n), short of θ by at most
/// |θ|³/(3n²) (2.6e-6 rad for 0.05 rad a step with n = 4). The step's clamps still apply
/// (|ω|·Δt ≤ TB_MAX_ROTATION, |v| ≤ maximumLinearSpeed): a farther target is not reached in one step.
static bool tbTargetVelocity(const tbBody* body, tbWorldTransform target, float timeStep, tbVec2* v, float* w)
{
	tbPos targetCenter = tbTransformWorldPoint(target, body->localCenter);
	float invTimeStep = 1.0f / timeStep;
	*v = tbMulSV(invTimeStep, tbSubPos(targetCenter, body->center));
	*w = invTimeStep * tbRelativeAngle(body->transform.q, target.q);
	return tbIsValidVec2(*v) && tbIsValidFloat(*w);
}

bool tbBody_SetTargetTransform(tbBodyId bodyId, tbWorldTransform target, float timeStep, bool wake)
{
	TB_RECORD(BodySetTargetTransform, &bodyId, &target, &timeStep, &wake);
	const char* f = "tbBody_SetTargetTransform";
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, f, &world, true);
	if (body == NULL || tbCheckFinitePosition(f, "target.p", target.p) == false || tbCheckPositive(f, "timeStep", timeStep) == false)
	{
		return false;
	}
	if (tbIsValidRotation(target.q) == false)
	{
		tbReportError(f, "target.q is (%g, %g), not a unit rotation; make it with tbMakeRot(angle)", (double)target.q.c,
					  (double)target.q.s);
		return false;
	}
	if (body->type == tb_staticBody)
	{
		tbReportError(f, "the body is static and never moves; make it kinematic (tbBody_SetType) to drive it");
		return false;
	}
	target.q = tbNormalizeRot(target.q);
	tbVec2 v;
	float w;
	if (tbTargetVelocity(body, target, timeStep, &v, &w) == false)
	{
		tbReportError(f, "timeStep %g is too short for the distance to the target (the velocity overflows); pass the "
						 "step's length", (double)timeStep);
		return false;
	}
	w = body->fixedRotation ? 0.0f : w;
	if (body->awakeIndex == TB_NULL_INDEX)
	{
		// Asleep: the speed of its fastest point decides, as the sleep test's does.
		float speed = tbLength(v) + body->maxExtent * tbAbsFloat(w);
		if (wake == false || speed < body->sleepThreshold)
		{
			return true;
		}
		tbWakeBody(world, body);
	}
	body->linearVelocity = v;
	body->angularVelocity = w;
	return true;
}

/// Common checks for force and impulse calls: a dynamic body, finite input, wake handling.
static tbBody* tbGetDynamicForInput(tbBodyId bodyId, const char* f, bool wake, tbWorld** world)
{
	tbBody* body = tbGetBodyChecked(bodyId, f, world, true);
	if (body == NULL || body->type != tb_dynamicBody)
	{
		return NULL;
	}
	if (wake)
	{
		tbWakeBody(*world, body);
	}
	return body->awakeIndex != TB_NULL_INDEX ? body : NULL;
}

bool tbBody_ApplyForce(tbBodyId bodyId, tbVec2 force, tbPos point, bool wake)
{
	TB_RECORD(BodyApplyForce, &bodyId, &force, &point, &wake);
	const char* f = "tbBody_ApplyForce";
	if (tbCheckVec2(f, "force", force) == false || tbCheckFinitePosition(f, "point", point) == false)
	{
		return false;
	}
	tbWorld* world;
	tbBody* body = tbGetDynamicForInput(bodyId, f, wake, &world);
	if (body != NULL)
	{
		body->force = tbAdd(body->force, force);
		body->torque += tbCross(tbSubPos(point, body->center), force);
	}
	return body != NULL;
}

bool tbBody_ApplyForceToCenter(tbBodyId bodyId, tbVec2 force, bool wake)
{
	TB_RECORD(BodyApplyForceToCenter, &bodyId, &force, &wake);
	const char* f = "tbBody_ApplyForceToCenter";
	if (tbCheckVec2(f, "force", force) == false)
	{
		return false;
	}
	tbWorld* world;
	tbBody* body = tbGetDynamicForInput(bodyId, f, wake, &world);
	if (body != NULL)
	{
		body->force = tbAdd(body->force, force);
	}
	return body != NULL;
}

bool tbBody_ApplyTorque(tbBodyId bodyId, float torque, bool wake)
{
	TB_RECORD(BodyApplyTorque, &bodyId, &torque, &wake);
	const char* f = "tbBody_ApplyTorque";
	if (tbCheckFloat(f, "torque", torque) == false)
	{
		return false;
	}
	tbWorld* world;
	tbBody* body = tbGetDynamicForInput(bodyId, f, wake, &world);
	if (body != NULL)
	{
		body->torque += torque;
	}
	return body != NULL;
}

// The impulse calls: v += P/m and ω += L/I, with the angular impulse L = r × P for a linear impulse
// P at lever arm r from the centre of mass, the given L for an angular impulse and none for a
// linear impulse at the centre. A body that cannot turn (1/I = 0) ignores L, whose r × P may
// overflow (0 · ∞ = NaN). An impulse that
// would leave a velocity that is not a finite float is refused before the body is woken: the step
// clamps any finite speed, but no direction survives ∞ − ∞.
static bool tbApplyBodyImpulse(tbBodyId bodyId, const char* f, tbVec2 impulse, const tbPos* point, float angularImpulse,
							   bool wake)
{
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, f, &world, true);
	if (body == NULL || body->type != tb_dynamicBody)
	{
		return false;
	}
	tbVec2 v = tbMulAdd(body->linearVelocity, body->invMass, impulse);
	float w = body->angularVelocity;
	float angular = point != NULL ? tbCross(tbSubPos(*point, body->center), impulse) : angularImpulse;
	if (body->invInertia > 0.0f && angular != 0.0f)
	{
		w += body->invInertia * angular;
	}
	if (tbIsValidVec2(v) == false || tbIsValidFloat(w) == false)
	{
		tbReportError(f, "impulse would give the body a velocity of (%g, %g) m/s and %g rad/s, not finite floats; "
						 "apply a smaller impulse, or nearer the centre of mass",
					  (double)v.x, (double)v.y, (double)w);
		return false;
	}
	if (wake)
	{
		tbWakeBody(world, body);
	}
	if (body->awakeIndex == TB_NULL_INDEX)
	{
		return false;
	}
	body->linearVelocity = v;
	body->angularVelocity = w;
	return true;
}

bool tbBody_ApplyLinearImpulse(tbBodyId bodyId, tbVec2 impulse, tbPos point, bool wake)
{
	TB_RECORD(BodyApplyLinearImpulse, &bodyId, &impulse, &point, &wake);
	const char* f = "tbBody_ApplyLinearImpulse";
	if (tbCheckVec2(f, "impulse", impulse) == false || tbCheckFinitePosition(f, "point", point) == false)
	{
		return false;
	}
	return tbApplyBodyImpulse(bodyId, f, impulse, &point, 0.0f, wake);
}

bool tbBody_ApplyLinearImpulseToCenter(tbBodyId bodyId, tbVec2 impulse, bool wake)
{
	TB_RECORD(BodyApplyLinearImpulseToCenter, &bodyId, &impulse, &wake);
	const char* f = "tbBody_ApplyLinearImpulseToCenter";
	if (tbCheckVec2(f, "impulse", impulse) == false)
	{
		return false;
	}
	return tbApplyBodyImpulse(bodyId, f, impulse, NULL, 0.0f, wake);
}

bool tbBody_ApplyAngularImpulse(tbBodyId bodyId, float impulse, bool wake)
{
	TB_RECORD(BodyApplyAngularImpulse, &bodyId, &impulse, &wake);
	const char* f = "tbBody_ApplyAngularImpulse";
	if (tbCheckFloat(f, "impulse", impulse) == false)
	{
		return false;
	}
	return tbApplyBodyImpulse(bodyId, f, tbVec2_zero, NULL, impulse, wake);
}

float tbBody_GetMass(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetMass", NULL, false);
	return body != NULL && body->type == tb_dynamicBody ? body->mass : 0.0f;
}

float tbBody_GetRotationalInertia(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetRotationalInertia", NULL, false);
	return body != NULL ? body->inertia : 0.0f;
}

tbVec2 tbBody_GetLocalCenter(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetLocalCenter", NULL, false);
	return body != NULL ? body->localCenter : tbVec2_zero;
}

tbPos tbBody_GetWorldCenter(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetWorldCenter", NULL, false);
	return body != NULL ? body->center : tbPos_zero;
}

bool tbBody_SetMassData(tbBodyId bodyId, tbMassData massData)
{
	TB_RECORD(BodySetMassData, &bodyId, &massData);
	const char* f = "tbBody_SetMassData";
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, f, &world, true);
	if (body == NULL || tbCheckNonNegative(f, "massData.mass", massData.mass) == false ||
		tbCheckNonNegative(f, "massData.rotationalInertia", massData.rotationalInertia) == false ||
		tbCheckCoordinate(f, "massData.center", massData.center) == false)
	{
		return false;
	}
	if (body->type != tb_dynamicBody)
	{
		return true; // static and kinematic bodies have no mass (as tbUpdateBodyMass)
	}
	// Mass below FLT_MIN counts as none, as for shapes: the body then acts as 1 kg at its origin.
	tbRestartBodyContacts(world, body);
	tbPos oldCenter = body->center;
	body->mass = massData.mass >= FLT_MIN ? massData.mass : 1.0f;
	body->invMass = 1.0f / body->mass;
	tbSetBodyInertia(body, body->fixedRotation ? 0.0f : massData.rotationalInertia);
	body->localCenter = massData.mass >= FLT_MIN ? massData.center : tbVec2_zero;
	body->center = tbTransformWorldPoint(body->transform, body->localCenter);
	body->center0 = body->center;
	tbKeepOriginVelocity(body, oldCenter);
	tbComputeExtents(world, body);
	return true;
}

void tbBody_ApplyMassFromShapes(tbBodyId bodyId)
{
	TB_RECORD(BodyApplyMassFromShapes, &bodyId);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_ApplyMassFromShapes", &world, true);
	if (body != NULL)
	{
		tbUpdateBodyMass(world, body);
	}
}

void tbBody_SetName(tbBodyId bodyId, const char* name)
{
	TB_RECORD(BodySetName, &bodyId, name);
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetName", NULL, false);
	if (body != NULL)
	{
		body->name = name;
	}
}

/// Contact or hit events on or off for every shape of the body (tbShape_Enable*Events).
static void tbEnableBodyShapeEvents(tbBodyId bodyId, const char* f, bool hits, bool flag)
{
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, f, &world, true);
	for (int id = body != NULL ? body->headShapeId : TB_NULL_INDEX; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		tbSetShapeEventFlag(world, world->shapes + id, hits ? tb_shapeEventHits : tb_shapeEventContacts, flag);
	}
}

void tbBody_EnableContactEvents(tbBodyId bodyId, bool flag)
{
	TB_RECORD(BodyEnableContactEvents, &bodyId, &flag);
	tbEnableBodyShapeEvents(bodyId, "tbBody_EnableContactEvents", false, flag);
}

void tbBody_EnableHitEvents(tbBodyId bodyId, bool flag)
{
	TB_RECORD(BodyEnableHitEvents, &bodyId, &flag);
	tbEnableBodyShapeEvents(bodyId, "tbBody_EnableHitEvents", true, flag);
}

tbMassData tbBody_GetMassData(tbBodyId bodyId)
{
	tbMassData md = {0};
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetMassData", NULL, false);
	if (body != NULL && body->type == tb_dynamicBody)
	{
		md.mass = body->mass;
		md.center = body->localCenter;
		md.rotationalInertia = body->inertia;
	}
	return md;
}

bool tbBody_SetLinearDamping(tbBodyId bodyId, float value)
{
	TB_RECORD(BodySetLinearDamping, &bodyId, &value);
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetLinearDamping", NULL, true);
	if (body == NULL || tbCheckNonNegative("tbBody_SetLinearDamping", "linearDamping", value) == false)
	{
		return false;
	}
	body->linearDamping = value;
	return true;
}

float tbBody_GetLinearDamping(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetLinearDamping", NULL, false);
	return body != NULL ? body->linearDamping : 0.0f;
}

bool tbBody_SetAngularDamping(tbBodyId bodyId, float value)
{
	TB_RECORD(BodySetAngularDamping, &bodyId, &value);
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetAngularDamping", NULL, true);
	if (body == NULL || tbCheckNonNegative("tbBody_SetAngularDamping", "angularDamping", value) == false)
	{
		return false;
	}
	body->angularDamping = value;
	return true;
}

float tbBody_GetAngularDamping(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetAngularDamping", NULL, false);
	return body != NULL ? body->angularDamping : 0.0f;
}

bool tbBody_SetGravityScale(tbBodyId bodyId, float value)
{
	TB_RECORD(BodySetGravityScale, &bodyId, &value);
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetGravityScale", NULL, true);
	if (body == NULL || tbCheckFloat("tbBody_SetGravityScale", "gravityScale", value) == false)
	{
		return false;
	}
	body->gravityScale = value;
	return true;
}

float tbBody_GetGravityScale(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetGravityScale", NULL, false);
	return body != NULL ? body->gravityScale : 0.0f;
}

bool tbBody_IsAwake(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_IsAwake", NULL, false);
	return body != NULL && body->awakeIndex != TB_NULL_INDEX;
}

void tbBody_WakeTouching(tbBodyId bodyId)
{
	TB_RECORD(BodyWakeTouching, &bodyId);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_WakeTouching", &world, true);
	if (body == NULL)
	{
		return;
	}
	for (int key = body->headContactKey; key != TB_NULL_INDEX;)
	{
		const tbContact* contact = world->contacts + (key >> 1);
		tbWakeBody(world, world->bodies + contact->edges[(key & 1) ^ 1].bodyId); // static bodies stay as they are
		key = contact->edges[key & 1].nextKey;
	}
}

void tbBody_SetAwake(tbBodyId bodyId, bool awake)
{
	TB_RECORD(BodySetAwake, &bodyId, &awake);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetAwake", &world, true);
	if (body == NULL)
	{
		return;
	}
	if (awake)
	{
		tbWakeBody(world, body);
	}
	else
	{
		tbSleepBody(world, body);
	}
}

void tbBody_EnableSleep(tbBodyId bodyId, bool enableSleep)
{
	TB_RECORD(BodyEnableSleep, &bodyId, &enableSleep);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_EnableSleep", &world, true);
	if (body != NULL)
	{
		body->enableSleep = enableSleep;
		if (enableSleep == false)
		{
			tbWakeBody(world, body);
		}
	}
}

bool tbBody_IsSleepEnabled(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_IsSleepEnabled", NULL, false);
	return body != NULL && body->enableSleep;
}

bool tbBody_SetSleepThreshold(tbBodyId bodyId, float sleepThreshold)
{
	TB_RECORD(BodySetSleepThreshold, &bodyId, &sleepThreshold);
	const char* f = "tbBody_SetSleepThreshold";
	tbBody* body = tbGetBodyChecked(bodyId, f, NULL, true);
	if (body == NULL || tbCheckNonNegative(f, "sleepThreshold", sleepThreshold) == false)
	{
		return false;
	}
	body->sleepThreshold = sleepThreshold;
	return true;
}

float tbBody_GetSleepThreshold(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetSleepThreshold", NULL, false);
	return body != NULL ? body->sleepThreshold : 0.0f;
}

bool tbBody_SetSafetyFactor(tbBodyId bodyId, float safetyFactor)
{
	TB_RECORD(BodySetSafetyFactor, &bodyId, &safetyFactor);
	const char* f = "tbBody_SetSafetyFactor";
	tbBody* body = tbGetBodyChecked(bodyId, f, NULL, true);
	if (body == NULL || tbCheckNonNegative(f, "safetyFactor", safetyFactor) == false)
	{
		return false;
	}
	// Read through tbSpeculativeReach from the next step on (broad-phase boxes, speculative margins
	// and the continuous stage's test of fast bodies all take the new reach).
	body->safetyFactor = safetyFactor;
	tbUpdateSpeculativeReach(body);
	return true;
}

float tbBody_GetSafetyFactor(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetSafetyFactor", NULL, false);
	return body != NULL ? body->safetyFactor : 0.0f;
}

void tbBody_ClearForces(tbBodyId bodyId)
{
	TB_RECORD(BodyClearForces, &bodyId);
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_ClearForces", NULL, false);
	if (body != NULL)
	{
		body->force = tbVec2_zero;
		body->torque = 0.0f;
	}
}

tbVec2 tbBody_GetWorldPointVelocity(tbBodyId bodyId, tbPos worldPoint)
{
	const char* f = "tbBody_GetWorldPointVelocity";
	tbBody* body = tbGetBodyChecked(bodyId, f, NULL, false);
	if (body == NULL || tbCheckFinitePosition(f, "worldPoint", worldPoint) == false)
	{
		return tbVec2_zero;
	}
	tbVec2 r = tbSubPos(worldPoint, body->center);
	return tbAdd(body->linearVelocity, tbCrossSV(body->angularVelocity, r));
}

tbVec2 tbBody_GetLocalPointVelocity(tbBodyId bodyId, tbVec2 localPoint)
{
	const char* f = "tbBody_GetLocalPointVelocity";
	tbBody* body = tbGetBodyChecked(bodyId, f, NULL, false);
	if (body == NULL || tbCheckVec2(f, "localPoint", localPoint) == false)
	{
		return tbVec2_zero;
	}
	tbVec2 r = tbRotateVector(body->transform.q, tbSub(localPoint, body->localCenter));
	return tbAdd(body->linearVelocity, tbCrossSV(body->angularVelocity, r));
}

bool tbBody_IsBullet(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_IsBullet", NULL, false);
	return body != NULL && body->isBullet;
}

void tbBody_SetBullet(tbBodyId bodyId, bool flag)
{
	TB_RECORD(BodySetBullet, &bodyId, &flag);
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetBullet", NULL, true);
	if (body != NULL)
	{
		body->isBullet = flag;
	}
}

void tbBody_SetFixedRotation(tbBodyId bodyId, bool flag)
{
	TB_RECORD(BodySetFixedRotation, &bodyId, &flag);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetFixedRotation", &world, true);
	if (body != NULL && body->fixedRotation != flag)
	{
		body->fixedRotation = flag;
		body->angularVelocity = 0.0f;
		tbUpdateBodyMass(world, body);
	}
}

void tbBody_SetMotionLocks(tbBodyId bodyId, tbMotionLocks locks)
{
	TB_RECORD(BodySetMotionLocks, &bodyId, &locks);
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetMotionLocks", &world, true);
	if (body == NULL)
	{
		return;
	}
	world->linearLockCount -= body->lockLinearX || body->lockLinearY ? 1 : 0;
	body->lockLinearX = locks.linearX;
	body->lockLinearY = locks.linearY;
	world->linearLockCount += body->lockLinearX || body->lockLinearY ? 1 : 0;
	body->linearVelocity.x = locks.linearX ? 0.0f : body->linearVelocity.x;
	body->linearVelocity.y = locks.linearY ? 0.0f : body->linearVelocity.y;
	if (body->fixedRotation != locks.angularZ)
	{
		body->fixedRotation = locks.angularZ;
		body->angularVelocity = 0.0f;
		tbUpdateBodyMass(world, body);
	}
	if (body->type != tb_staticBody)
	{
		tbWakeBody(world, body);
	}
}

tbMotionLocks tbBody_GetMotionLocks(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetMotionLocks", NULL, false);
	tbMotionLocks locks = {false, false, false};
	if (body != NULL)
	{
		locks.linearX = body->lockLinearX;
		locks.linearY = body->lockLinearY;
		locks.angularZ = body->fixedRotation;
	}
	return locks;
}

void tbBody_EnableContactRecycling(tbBodyId bodyId, bool flag)
{
	TB_RECORD(BodyEnableContactRecycling, &bodyId, &flag);
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_EnableContactRecycling", NULL, true);
	if (body != NULL)
	{
		body->enableContactRecycling = flag;
	}
}

bool tbBody_IsContactRecyclingEnabled(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_IsContactRecyclingEnabled", NULL, false);
	return body != NULL && body->enableContactRecycling;
}

void tbBody_SetUserData(tbBodyId bodyId, void* userData)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_SetUserData", NULL, false);
	if (body != NULL)
	{
		body->userData = userData;
	}
}

void* tbBody_GetUserData(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetUserData", NULL, false);
	return body != NULL ? body->userData : NULL;
}

const char* tbBody_GetName(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetName", NULL, false);
	return body != NULL ? body->name : NULL;
}

tbWorldId tbBody_GetWorld(tbBodyId bodyId)
{
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetWorld", &world, false);
	if (body == NULL)
	{
		return TB_NULL_WORLD_ID;
	}
	tbWorldId id = {(uint16_t)(world->worldId + 1), world->generation};
	return id;
}

int tbBody_GetShapeCount(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetShapeCount", NULL, false);
	return body != NULL ? body->shapeCount : 0;
}

int tbBody_GetShapes(tbBodyId bodyId, tbShapeId* shapeArray, int capacity)
{
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetShapes", &world, false);
	if (body == NULL || tbCheckPointer("tbBody_GetShapes", "shapeArray", shapeArray) == false)
	{
		return 0;
	}
	int count = 0;
	for (int id = body->headShapeId; id != TB_NULL_INDEX && count < capacity; id = world->shapes[id].nextShapeId)
	{
		shapeArray[count++] = tbMakeShapeId(world, id);
	}
	return count;
}

tbAABB tbBody_ComputeAABB(tbBodyId bodyId)
{
	tbWorld* world;
	tbAABB box = {{0.0f, 0.0f}, {0.0f, 0.0f}};
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_ComputeAABB", &world, false);
	if (body == NULL || body->headShapeId == TB_NULL_INDEX)
	{
		if (body != NULL)
		{
			box = tbOffsetAABB(box, body->transform.p); // a point box at the origin
		}
		return box;
	}
	box = tbComputeShapeAABBInternal(world->shapes + body->headShapeId, body->transform);
	for (int id = world->shapes[body->headShapeId].nextShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		box = tbAABB_Union(box, tbComputeShapeAABBInternal(world->shapes + id, body->transform));
	}
	return box;
}

// --- the finalize stage -----------------------------------------------------------------------

static void tbUpdateSleepTime(const tbWorld* world, tbBody* body, float timeStep)
{
	if (world->def.enableSleep == false || body->enableSleep == false)
	{
		body->sleepTime = 0.0f;
		return;
	}
	// A body rests when its fastest point moves slower than the threshold: |v| + |ω|·maxExtent.
	// A body without extent (no shapes) has no fastest point but its centre: |v| alone, and its
	// spin is judged by the angular tolerance instead.
	// fabsf rather than tbAbsFloat's comparison, a branch on the spin's sign (see tbSpeculativeMargin).
	float speed = tbLength(body->linearVelocity) + fabsf(body->angularVelocity) * body->maxExtent;
	bool fastSpin = fabsf(body->angularVelocity) >= TB_ANGULAR_SLEEP_TOLERANCE;
	if (speed > body->sleepThreshold || (body->maxExtent == 0.0f && fastSpin))
	{
		body->sleepTime = 0.0f;
	}
	else
	{
		body->sleepTime += timeStep;
	}
}

static tbBodyMoveEvent tbMakeMoveEvent(const tbWorld* world, const tbBody* body, int bodyId)
{
	tbBodyMoveEvent event;
	event.transform = body->transform;
	event.bodyId = tbMakeBodyId(world, bodyId);
	event.userData = body->userData;
	event.fellAsleep = false;
	return event;
}

/// The body's origin is farther than TB_MAX_POSITION from the world's origin on some axis: only the
/// solver can take it there (every setter refuses such a position), by letting it fly at the speed
/// limit for minutes. Beyond it a float position is coarser than contacts can work with.
static bool tbIsBeyondBounds(const tbBody* body)
{
	return fabs((double)body->transform.p.x) > TB_MAX_POSITION || fabs((double)body->transform.p.y) > TB_MAX_POSITION;
}

void tbDisableBodiesBeyondBounds(tbWorld* world)
{
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		int bodyId = world->awakeBodies[i];
		tbBody* body = bodyId != TB_NULL_INDEX ? world->bodies + bodyId : NULL;
		if (body != NULL && tbIsBeyondBounds(body))
		{
			tbReportError("tbWorld_Step",
						  "body %d%s%s%s reached (%g, %g), farther than TB_MAX_POSITION = %g m from the origin; it is "
						  "disabled (tbBody_Enable, after moving it back with tbBody_SetTransform, or tbDestroyBody)",
						  bodyId + 1, body->name != NULL ? " (" : "", body->name != NULL ? body->name : "",
						  body->name != NULL ? ")" : "", (double)body->transform.p.x, (double)body->transform.p.y,
						  (double)TB_MAX_POSITION);
			tbDisableBody(world, body);
		}
	}
}

typedef struct tbFinalizeTaskContext
{
	tbWorld* world;
	float timeStep;
	tbBodyMoveEvent* events; ///< one per awake body, in awake order
	uint8_t* moved;			 ///< per awake body: bit 0, a proxy of its is to be moved; bit 1, beyond bounds
} tbFinalizeTaskContext;

/// Sleep timers, shape boxes and move events of awake bodies [start, end): each writes only its own
/// body, shapes, event slot and flag.
static void tbFinalizeTask(int start, int end, uint32_t workerIndex, void* context)
{
	(void)workerIndex;
	tbFinalizeTaskContext* task = context;
	tbWorld* world = task->world;
	for (int i = start; i < end; ++i)
	{
		int bodyId = world->awakeBodies[i];
		tbBody* body = world->bodies + bodyId;
		tbUpdateSleepTime(world, body, task->timeStep);
		task->moved[i] = (uint8_t)((tbComputeBodyShapeBoxes(world, body, false) ? 1u : 0u) |
								   (tbIsBeyondBounds(body) ? 2u : 0u));
		task->events[i] = tbMakeMoveEvent(world, body, bodyId);
	}
}

int tbFinalizeStage(tbWorld* world, float timeStep)
{
	int n = world->awakeBodyCount;
	int beyond = 0;
	if (n == 0)
	{
		return 0; // nothing awake: no boxes, no events (and no event array to point into)
	}
	if (tbWorkerCount(&world->def) > 1)
	{
		// On workers: everything per body, each move event written to its slot (awake order, as the
		// one-worker walk appends them); then, serially and in body order, only the bodies with a
		// re-made box move their proxies (the broad phase's move buffer keeps that order).
		TB_ARRAY_RESERVE(world->events.moveEvents, world->events.moveCapacity, world->events.moveCount + n);
		tbFinalizeTaskContext task = {world, timeStep, world->events.moveEvents + world->events.moveCount,
									  tbArenaAlloc(&world->stepArena, tbMaxInt(n, 1))};
		tbParallelFor(&world->def, tbFinalizeTask, n, 256, &task);
		world->events.moveCount += n;
		for (int i = 0; i < n; ++i)
		{
			if ((task.moved[i] & 1u) != 0u)
			{
				tbMoveFlaggedProxies(world, world->bodies + world->awakeBodies[i]);
			}
			beyond += task.moved[i] >> 1;
		}
		return beyond;
	}
	// One worker: one pass over the bodies (a second walk would only cost memory traffic).
	for (int i = 0; i < n; ++i)
	{
		int bodyId = world->awakeBodies[i];
		tbBody* body = world->bodies + bodyId;
		tbUpdateSleepTime(world, body, timeStep);
		if (tbComputeBodyShapeBoxes(world, body, false))
		{
			tbMoveFlaggedProxies(world, body); // only when some box was re-made
		}
		tbBodyMoveEvent event = tbMakeMoveEvent(world, body, bodyId);
		TB_ARRAY_PUSH(world->events.moveEvents, world->events.moveCount, world->events.moveCapacity, event);
		beyond += tbIsBeyondBounds(body) ? 1 : 0;
	}
	return beyond;
}
