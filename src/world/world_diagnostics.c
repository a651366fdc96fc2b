// World diagnostics for games and tools: a hash of the simulation state (determinism checks) and a
// dump of the memory each array holds (Box2D v3.2's b2World_GetStateHash, b2World_DumpMemoryStats).
//
// The state hash is 64-bit FNV-1a (Fowler, Noll, Vo): h₀ = 14695981039346656037 and, per byte b,
// h ← (h xor b) · 1099511628211 mod 2^64. Values are fed one by one as their bytes, never whole
// structs, so padding and unused union members do not enter it; pools are walked in id order and
// free slots are skipped, so it is the same for any worker count and for two worlds built the same
// way whatever their allocation history beyond the ids. What it covers is what the next step reads:
// - bodies: id, type, awake, enabled, transform, centre of mass, velocities, the forces applied for
//   the next step, sleep time (not the id's generation: a world made in a slot an earlier world used
//   starts its generations past that world's, and would hash differently for the same state);
// - contacts: id, shapes, flags (touching, sensor), manifold normal, rolling impulse and per point
//   feature id, separation, normal and tangent impulses (the warm start);
// - joints: id, type, bodies, and the accumulated impulses of their kind (the warm start);
// - pool bookkeeping: live counts and high-water marks of bodies, shapes, contacts and joints.
// Not covered: user data, names, callbacks, world settings, shape geometry (it changes only through
// the API), the broad phase's internal layout.
#include "joints/joint.h"
#include "world.h"

#include <stdio.h>
#include <string.h>

#define TB_FNV_OFFSET 14695981039346656037ull
#define TB_FNV_PRIME 1099511628211ull

static uint64_t tbMixBytes(uint64_t hash, const void* data, size_t count)
{
	const uint8_t* bytes = data;
	for (size_t i = 0; i < count; ++i)
	{
		hash = (hash ^ bytes[i]) * TB_FNV_PRIME;
	}
	return hash;
}

static uint64_t tbMixInt(uint64_t hash, int value)
{
	return tbMixBytes(hash, &value, sizeof(value));
}

static uint64_t tbMixFloat(uint64_t hash, float value)
{
	return tbMixBytes(hash, &value, sizeof(value));
}

static uint64_t tbMixVec2(uint64_t hash, tbVec2 v)
{
	return tbMixFloat(tbMixFloat(hash, v.x), v.y);
}

// A position: its coordinates' bytes (doubles in the large-world build).
static uint64_t tbMixPos(uint64_t hash, tbPos p)
{
	return tbMixBytes(tbMixBytes(hash, &p.x, sizeof(p.x)), &p.y, sizeof(p.y));
}

static uint64_t tbHashBody(uint64_t hash, int id, const tbBody* b)
{
	hash = tbMixInt(hash, id);
	hash = tbMixInt(hash, b->type);
	hash = tbMixInt(hash, b->awakeIndex != TB_NULL_INDEX);
	hash = tbMixInt(hash, b->isDisabled);
	hash = tbMixPos(hash, b->transform.p);
	hash = tbMixFloat(tbMixFloat(hash, b->transform.q.c), b->transform.q.s);
	hash = tbMixPos(hash, b->center);
	hash = tbMixVec2(hash, b->linearVelocity);
	hash = tbMixFloat(hash, b->angularVelocity);
	hash = tbMixVec2(hash, b->force);
	hash = tbMixFloat(hash, b->torque);
	return tbMixFloat(hash, b->sleepTime);
}

static uint64_t tbHashContact(uint64_t hash, int id, const tbContact* c)
{
	hash = tbMixInt(hash, id);
	hash = tbMixInt(hash, c->shapeIdA);
	hash = tbMixInt(hash, c->shapeIdB);
	hash = tbMixInt(hash, (int)(c->flags & (tb_contactTouching | tb_contactSensor)));
	const tbManifold* m = &c->manifold;
	hash = tbMixInt(hash, m->pointCount);
	hash = tbMixVec2(hash, m->normal);
	hash = tbMixFloat(hash, m->rollingImpulse);
	for (int i = 0; i < m->pointCount; ++i)
	{
		const tbManifoldPoint* p = m->points + i;
		hash = tbMixInt(hash, p->id);
		hash = tbMixFloat(hash, p->separation);
		hash = tbMixFloat(hash, p->normalImpulse);
		hash = tbMixFloat(hash, p->tangentImpulse);
	}
	return hash;
}

/// The accumulated impulses of a joint's kind: what the next step warm starts from.
static uint64_t tbHashJointImpulses(uint64_t hash, const tbJoint* j)
{
	switch (j->type)
	{
		case tb_distanceJoint:
		{
			const tbDistanceJoint* d = &j->distance;
			float values[4] = {d->impulse, d->lowerImpulse, d->upperImpulse, d->motorImpulse};
			return tbMixBytes(hash, values, sizeof(values));
		}
		case tb_motorJoint:
		{
			const tbMotorJoint* m = &j->motor;
			hash = tbMixVec2(hash, m->linearVelocityImpulse);
			hash = tbMixVec2(hash, m->linearSpringImpulse);
			return tbMixFloat(tbMixFloat(hash, m->angularVelocityImpulse), m->angularSpringImpulse);
		}
		case tb_moverJoint:
			return tbMixVec2(hash, j->mover.linearVelocityImpulse);
		case tb_pogoJoint:
			return tbMixFloat(tbMixFloat(hash, j->pogo.impulse), j->pogo.velocity);
		case tb_prismaticJoint:
		{
			const tbPrismaticJoint* p = &j->prismatic;
			float values[4] = {p->springImpulse, p->motorImpulse, p->lowerImpulse, p->upperImpulse};
			return tbMixBytes(tbMixVec2(hash, p->impulse), values, sizeof(values));
		}
		case tb_revoluteJoint:
		{
			const tbRevoluteJoint* r = &j->revolute;
			float values[4] = {r->springImpulse, r->motorImpulse, r->lowerImpulse, r->upperImpulse};
			return tbMixBytes(tbMixVec2(hash, r->linearImpulse), values, sizeof(values));
		}
		case tb_weldJoint:
			return tbMixFloat(tbMixVec2(hash, j->weld.linearImpulse), j->weld.angularImpulse);
		case tb_wheelJoint:
		{
			const tbWheelJoint* w = &j->wheel;
			float values[5] = {w->perpImpulse, w->springImpulse, w->motorImpulse, w->lowerImpulse, w->upperImpulse};
			return tbMixBytes(hash, values, sizeof(values));
		}
		default:
			return hash; // the filter joint holds no impulse
	}
}

uint64_t tbWorld_GetStateHash(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetStateHash");
	if (world == NULL)
	{
		return 0;
	}
	uint64_t hash = TB_FNV_OFFSET;
	for (int id = 0; id < world->bodyPool.highWater; ++id)
	{
		hash = world->bodies[id].inUse ? tbHashBody(hash, id, world->bodies + id) : hash;
	}
	for (int id = 0; id < world->contactPool.highWater; ++id)
	{
		hash = world->contacts[id].inUse ? tbHashContact(hash, id, world->contacts + id) : hash;
	}
	for (int id = 0; id < world->jointPool.highWater; ++id)
	{
		const tbJoint* j = world->joints + id;
		if (j->inUse)
		{
			hash = tbMixInt(tbMixInt(tbMixInt(hash, id), j->type), j->edges[0].bodyId);
			hash = tbHashJointImpulses(tbMixInt(hash, j->edges[1].bodyId), j);
		}
	}
	int counts[8] = {world->bodyPool.count,	  world->bodyPool.highWater,	  world->shapePool.count, world->shapePool.highWater,
					 world->contactPool.count, world->contactPool.highWater, world->jointPool.count, world->jointPool.highWater};
	return tbMixBytes(hash, counts, sizeof(counts));
}

// ---------------------------------------------------------------------------------------------
// Memory

/// One line of the dump: an array's name and its bytes (capacity × element size), added to *total.
static void tbDumpArray(FILE* file, const char* name, long long bytes, long long* total)
{
	fprintf(file, "%s: %lld\n", name, bytes);
	*total += bytes;
}

void tbWorld_DumpMemoryStats(tbWorldId worldId)
{
	const char* f = "tbWorld_DumpMemoryStats";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL)
	{
		return;
	}
	FILE* file = fopen("tumble_memory.txt", "w");
	if (file == NULL)
	{
		tbReportError(f, "cannot open tumble_memory.txt for writing in the current directory; run from a "
						 "writable directory");
		return;
	}
	long long total = 0;
	fprintf(file, "world pools (capacity x element size, bytes)\n");
	tbDumpArray(file, "bodies", (long long)world->bodyCapacity * (long long)sizeof(tbBody), &total);
	tbDumpArray(file, "shapes", (long long)world->shapeCapacity * (long long)sizeof(tbShape), &total);
	tbDumpArray(file, "contacts", (long long)world->contactCapacity * (long long)sizeof(tbContact), &total);
	tbDumpArray(file, "joints", (long long)world->jointCapacity * (long long)sizeof(tbJoint), &total);
	tbDumpArray(file, "free lists",
				(long long)(world->bodyPool.freeCapacity + world->shapePool.freeCapacity + world->contactPool.freeCapacity +
							world->jointPool.freeCapacity + world->chainPool.freeCapacity) *
					(long long)sizeof(int),
				&total);
	fprintf(file, "\nper-step arrays\n");
	tbDumpArray(file, "awake bodies", (long long)world->awakeBodyCapacity * (long long)sizeof(int), &total);
	tbDumpArray(file, "step contacts", (long long)world->cache.stepContactCapacity * (long long)sizeof(int), &total);
	tbDumpArray(file, "solver contacts",
				(long long)(world->cache.solverContactCapacity + world->cache.solverContactsByIdCapacity +
							world->cache.solverSlotCapacity + world->cache.touchingContactCapacity) *
					(long long)sizeof(int),
				&total);
	tbDumpArray(file, "contact bodies", (long long)world->cache.contactBodyCapacity * (long long)sizeof(tbBodyPair), &total);
	tbDumpArray(file, "collide keys", (long long)world->cache.collideKeyCapacity * (long long)sizeof(tbCollideKey), &total);
	tbDumpArray(file, "broad-phase proxies",
				(long long)world->broadPhase.table.capacity * (long long)sizeof(tbBroadProxy), &total);
	fprintf(file, "\nevents\n");
	tbDumpArray(file, "contact begin", (long long)world->events.beginCapacity * (long long)sizeof(tbContactBeginTouchEvent),
				&total);
	tbDumpArray(file, "contact end", (long long)world->events.endCapacity * (long long)sizeof(tbContactEndTouchEvent), &total);
	tbDumpArray(file, "contact hit", (long long)world->events.hitCapacity * (long long)sizeof(tbContactHitEvent), &total);
	tbDumpArray(file, "body move", (long long)world->events.moveCapacity * (long long)sizeof(tbBodyMoveEvent), &total);
	tbDumpArray(file, "joint", (long long)world->events.jointEventCapacity * (long long)sizeof(tbJointEvent), &total);
	fprintf(file, "\ntotal of the above: %lld\n", total);
	fprintf(file, "bytes allocated by Tumble (all worlds, tbGetByteCount): %lld\n", (long long)tbGetByteCount());
	fclose(file);
}
