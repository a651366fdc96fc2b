// Islands: bodies linked by touching contacts. Two stages live here.
//
// The island stage runs before the solve: it wakes every sleeping body touching an awake one
// (transitively, so a woken pile wakes whole) and gathers the touching, non-sensor contacts that
// the solver will see. The sleep stage runs after the solve: it finds the islands of awake bodies
// by depth-first search over touching contacts (not through static or kinematic bodies, which do
// not transmit motion between islands) and puts to sleep each island whose every body has rested
// for TB_TIME_TO_SLEEP. Sleeping bodies leave the awake set, so they cost nothing in any stage.
// (The per-step search follows Box2D 2.4's design; persistent islands as in Box2D v3 would
// avoid the search but need island splitting.)
#include "world.h"

#include "array.h"

#include <stdlib.h>
#include <stdio.h>
#include <stdint.h>
static tbWorld* s_sortWorld;
static uint64_t tbExpKey(int id, int mode)
{
	const tbContact* c = s_sortWorld->contacts + id;
	uint32_t a = (uint32_t)c->edges[0].bodyId, b = (uint32_t)c->edges[1].bodyId;
	if (a > b) { uint32_t t = a; a = b; b = t; }
	if (mode == 1) return (uint64_t)id;
	if (mode == 2) return ((uint64_t)a << 32) | b;
	if (mode == 5) return ((uint64_t)b << 32) | a;
	static uint32_t seed = 0xFFFFFFFFu; if (seed == 0xFFFFFFFFu) { const char* e = getenv("TB_SEED"); seed = e ? (uint32_t)atoi(e) : 0; }
	uint32_t x = ((uint32_t)id + seed * 7919u) * 2654435761u; x ^= x >> 15; x *= 2246822519u; x ^= x >> 13;
	return ((uint64_t)x << 32) | (uint32_t)id;
}
static int s_mode;
static int tbExpCmp(const void* x, const void* y)
{
	uint64_t a = tbExpKey(*(const int*)x, s_mode), b = tbExpKey(*(const int*)y, s_mode);
	return a < b ? -1 : a > b;
}
static void tbExpOrder(tbWorld* world)
{
	static int mode = -1;
	if (mode < 0) { const char* e = getenv("TB_ORDER"); mode = e ? atoi(e) : 0; }
	s_mode = mode; s_sortWorld = world;
	int n = world->solverContactCount; int* ids = world->solverContacts;
	if (mode == 3) { for (int i = 0; i < n / 2; ++i) { int t = ids[i]; ids[i] = ids[n - 1 - i]; ids[n - 1 - i] = t; } return; }
	if (mode == 0) return;
	if (mode >= 10)
	{
		int B = 1 << (mode - 10);
		int counts[1025] = {0};
		int* sorted = tbAlloc((int)sizeof(int) * (n > 0 ? n : 1));
		for (int i = 0; i < n; ++i) counts[(tbExpKey(ids[i], 4) >> 32) & (uint64_t)(B - 1)] += 1;
		int off = 0; for (int k = 0; k < B; ++k) { int c = counts[k]; counts[k] = off; off += c; }
		for (int i = 0; i < n; ++i) sorted[counts[(tbExpKey(ids[i], 4) >> 32) & (uint64_t)(B - 1)]++] = ids[i];
		for (int i = 0; i < n; ++i) ids[i] = sorted[i];
		tbFree(sorted, (int)sizeof(int) * (n > 0 ? n : 1));
		return;
	}
	if (mode == 6 || mode == 7)
	{
		int bodyCount = world->awakeBodyCount;
		uint64_t* masks = tbAlloc((int)sizeof(uint64_t) * (bodyCount > 0 ? bodyCount : 1));
		for (int i = 0; i < bodyCount; ++i) masks[i] = 0;
		unsigned char* colors = tbAlloc(n > 0 ? n : 1);
		int counts[65] = {0};
		for (int i = 0; i < n; ++i)
		{
			const tbContact* c = world->contacts + ids[i];
			const tbBody* a = world->bodies + c->edges[0].bodyId;
			const tbBody* b = world->bodies + c->edges[1].bodyId;
			int ia = a->type == tb_dynamicBody ? a->awakeIndex : -1;
			int ib = b->type == tb_dynamicBody ? b->awakeIndex : -1;
			uint64_t used = (ia >= 0 ? masks[ia] : 0) | (ib >= 0 ? masks[ib] : 0);
			int color = 64;
			if (~used != 0) { color = __builtin_ctzll(~used); uint64_t bit = (uint64_t)1 << color; if (ia >= 0) masks[ia] |= bit; if (ib >= 0) masks[ib] |= bit; }
			colors[i] = (unsigned char)color; counts[color] += 1;
		}
		int offsets[66]; offsets[0] = 0;
		for (int k = 0; k < 65; ++k) offsets[k + 1] = offsets[k] + counts[k];
		int* sorted = tbAlloc((int)sizeof(int) * (n > 0 ? n : 1));
		for (int i = 0; i < n; ++i) sorted[offsets[colors[i]]++] = ids[i];
		for (int i = 0; i < n; ++i) ids[i] = sorted[i];
		tbFree(sorted, (int)sizeof(int) * (n > 0 ? n : 1));
		tbFree(colors, n > 0 ? n : 1);
		tbFree(masks, (int)sizeof(uint64_t) * (bodyCount > 0 ? bodyCount : 1));
		if (getenv("TB_COLORS")) { int used = 0; for (int k = 0; k < 65; ++k) used += counts[k] > 0; fprintf(stderr, "colors %d (c0 %d c1 %d c2 %d overflow %d)\n", used, counts[0], counts[1], counts[2], counts[64]); }
		return;
	}
	qsort(ids, (size_t)n, sizeof(int), tbExpCmp);
}

static bool tbIsSolverContact(const tbWorld* world, const tbContact* contact)
{
	if ((contact->flags & tb_contactTouching) == 0 || (contact->flags & tb_contactSensor) != 0)
	{
		return false;
	}
	const tbBody* a = world->bodies + contact->edges[0].bodyId;
	const tbBody* b = world->bodies + contact->edges[1].bodyId;
	return a->type == tb_dynamicBody || b->type == tb_dynamicBody;
}

void tbIslandStage(tbWorld* world)
{
	// The awake list grows while we walk it: bodies woken here are visited too.
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		const tbBody* body = world->bodies + world->awakeBodies[i];
		if (body->type != tb_dynamicBody)
		{
			continue; // kinematic bodies do not wake what they touch through islands
		}
		for (int key = body->headContactKey; key != TB_NULL_INDEX;)
		{
			const tbContact* contact = world->contacts + (key >> 1);
			if (tbIsSolverContact(world, contact))
			{
				tbBody* other = world->bodies + contact->edges[(key & 1) ^ 1].bodyId;
				if (other->type != tb_staticBody && other->awakeIndex == TB_NULL_INDEX)
				{
					tbWakeBody(world, other);
				}
			}
			key = contact->edges[key & 1].nextKey;
		}
	}
	// Solver contacts: each touching contact of an awake body once.
	int stamp = 2 * world->stepIndex + 1;
	world->solverContactCount = 0;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		const tbBody* body = world->bodies + world->awakeBodies[i];
		for (int key = body->headContactKey; key != TB_NULL_INDEX;)
		{
			tbContact* contact = world->contacts + (key >> 1);
			if (contact->stamp != stamp && tbIsSolverContact(world, contact))
			{
				contact->stamp = stamp;
				TB_ARRAY_PUSH(world->solverContacts, world->solverContactCount, world->solverContactCapacity, key >> 1);
			}
			key = contact->edges[key & 1].nextKey;
		}
	}
	tbExpOrder(world);
}

/// Depth-first search from a seed: collects the island's bodies in world->islandBodies and
/// returns their count and the smallest sleep time among them.
static int tbCollectIsland(tbWorld* world, int seed, int stamp, float* minSleepTime)
{
	int count = 0, top = 0;
	TB_ARRAY_RESERVE(world->islandStack, world->islandStackCapacity, 1);
	world->islandStack[top++] = seed;
	world->bodies[seed].islandStamp = stamp;
	*minSleepTime = TB_HUGE;
	while (top > 0)
	{
		int bodyId = world->islandStack[--top];
		tbBody* body = world->bodies + bodyId;
		TB_ARRAY_RESERVE(world->islandBodies, world->islandBodyCapacity, count + 1);
		world->islandBodies[count++] = bodyId;
		*minSleepTime = tbMinFloat(*minSleepTime, body->sleepTime);
		if (body->type != tb_dynamicBody)
		{
			continue; // kinematic: member of the island, but the search does not pass through it
		}
		for (int key = body->headContactKey; key != TB_NULL_INDEX;)
		{
			const tbContact* contact = world->contacts + (key >> 1);
			int otherId = contact->edges[(key & 1) ^ 1].bodyId;
			tbBody* other = world->bodies + otherId;
			if (other->type != tb_staticBody && other->islandStamp != stamp && other->awakeIndex != TB_NULL_INDEX &&
				tbIsSolverContact(world, contact))
			{
				other->islandStamp = stamp;
				TB_ARRAY_RESERVE(world->islandStack, world->islandStackCapacity, top + 1);
				world->islandStack[top++] = otherId;
			}
			key = contact->edges[key & 1].nextKey;
		}
	}
	return count;
}

/// Remove the marked bodies from the awake set in one pass (order preserved).
static void tbCompactAwakeSet(tbWorld* world)
{
	int kept = 0;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		int bodyId = world->awakeBodies[i];
		tbBody* body = world->bodies + bodyId;
		if (body->isMarked)
		{
			body->isMarked = false;
			body->awakeIndex = TB_NULL_INDEX;
			continue;
		}
		body->awakeIndex = kept;
		world->awakeBodies[kept++] = bodyId;
	}
	world->awakeBodyCount = kept;
}

static void tbPutIslandToSleep(tbWorld* world, int count)
{
	for (int i = 0; i < count; ++i)
	{
		tbBody* body = world->bodies + world->islandBodies[i];
		if (body->awakeIndex < world->moveCount)
		{
			world->moveEvents[body->awakeIndex].fellAsleep = true;
		}
		body->isMarked = true;
		body->linearVelocity = tb_vec2_zero;
		body->angularVelocity = 0.0f;
		body->force = tb_vec2_zero;
		body->torque = 0.0f;
	}
}

void tbSleepStage(tbWorld* world, float timeStep)
{
	(void)timeStep;
	// Stamps: a fresh value per step, distinct from the contact stamps.
	int stamp = world->stepIndex;
	int islands = 0;
	bool anySleep = false;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		int seed = world->awakeBodies[i];
		if (world->bodies[seed].islandStamp == stamp)
		{
			continue;
		}
		float minSleepTime;
		int count = tbCollectIsland(world, seed, stamp, &minSleepTime);
		islands += 1;
		if (world->def.enableSleep && minSleepTime >= TB_TIME_TO_SLEEP)
		{
			tbPutIslandToSleep(world, count);
			anySleep = true;
		}
	}
	world->counters.islandCount = islands;
	if (anySleep)
	{
		tbCompactAwakeSet(world);
	}
}
