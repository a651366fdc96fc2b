// Islands: bodies linked by touching contacts (contacts with manifold points, speculative points
// included). Two stages live here.
//
// The island stage runs before the solve: it wakes every sleeping body touching an awake one
// (transitively, so a woken pile wakes whole) and gathers the touching, non-sensor contacts that
// the solver will see. The sleep stage runs after the solve: it finds the islands of awake bodies
// by depth-first search over touching contacts (not through static or kinematic bodies, which do
// not transmit motion between islands) and puts to sleep each island whose every body has rested
// for TB_TIME_TO_SLEEP. Sleeping bodies leave the awake set, so they cost nothing in any stage.
// (The per-step search follows Box2D 2.4's design; persistent islands as in Box2D v3 would
// avoid the search but need island splitting.) Only an island whose every body has rested can
// sleep, so the search starts only from rested bodies and gives up at the first body that has not
// rested: a pile where a few bodies rest and the rest move (the junkyard) costs a few visits per
// step instead of a walk over every awake body and contact (5 % of a junkyard step).
#include "world.h"

#include "array.h"
#include "sort.h"

#include <stdint.h>

// Solve order of the contacts. Gauss–Seidel is order dependent: the contacts gathered body by
// body (bottom row first, left to right in a pyramid) form a sweep across the structure, and a
// fixed sweep direction biases the result sideways. Measured on the 5,050-box pyramid (60 Hz, 4
// sub-steps, soft step): gathered order drifts the top box 0.98 m sideways in 5 s (the reversed
// order drifts −0.88 m); sorting by contact id or by body pair −0.37 m; alternating the sweep
// direction per sub-step 0.6–0.7 m; greedy graph colouring 0.97 m; shuffling blocks of 4–16
// neighbouring contacts 0.3–0.6 m. Scattering single contacts removes the bias: drift
// |0.01–0.05| m over 10 s for different hash seeds, sag 0.84 m instead of 0.91 m, kinetic
// energy 1 J instead of 27 J. So the contacts are bucketed by a hash of their id (stable while the
// contact lives, independent of memory addresses, so the order is deterministic) into
// TB_SOLVE_ORDER_BUCKETS buckets with a stable counting sort; within a bucket the gathered order
// (contact-id order: contacts made in one step get consecutive ids in shape-pair order, which keeps
// some locality) is kept (cost: about +10% solve time on the large pyramid, from the scattered
// body accesses). 4 buckets leave 0.11 m of drift, 8 0.05 m, 16 0.04 m.
// The wide solver (the default, constraint_graph.c) then solves colour by colour, the colours
// assigned greedily in this order, so each colour is a scattered set too. Measured 2026-11-24 on
// the same pyramid, sleep off: top box drift after 10 s and 20 s, scalar 0.09 and 0.11 m, wide
// 0.23 and 0.24 m (sag 0.33 m in both); the 210-box pyramid of the stability table drifts 0.025 m
// with either.
#define TB_SOLVE_ORDER_BUCKETS 16

static inline int tbSolveOrderBucket(int contactId)
{
	uint32_t x = (uint32_t)contactId * 2654435761u; // Knuth's multiplicative hash, then a mix
	x ^= x >> 15;
	x *= 2246822519u;
	x ^= x >> 13;
	return (int)(x & (TB_SOLVE_ORDER_BUCKETS - 1));
}

static void tbOrderSolverContacts(tbWorld* world)
{
	int n = world->solverContactCount;
	TB_ARRAY_RESERVE(world->solverContactsById, world->solverContactsByIdCapacity, n);
	TB_ARRAY_RESERVE(world->solverSlots, world->solverSlotCapacity, n);
	int* ids = world->solverContacts;
	int* byId = world->solverContactsById;
	int* slots = world->solverSlots;
	int offsets[TB_SOLVE_ORDER_BUCKETS] = {0};
	for (int i = 0; i < n; ++i)
	{
		int id = ids[i];
		byId[i] = id;
		offsets[tbSolveOrderBucket(id)] += 1;
	}
	int offset = 0;
	for (int k = 0; k < TB_SOLVE_ORDER_BUCKETS; ++k)
	{
		int count = offsets[k];
		offsets[k] = offset;
		offset += count;
	}
	// Stable scatter: contact byId[i] is solved at position slots[i].
	for (int i = 0; i < n; ++i)
	{
		int id = byId[i];
		int slot = offsets[tbSolveOrderBucket(id)]++;
		slots[i] = slot;
		ids[slot] = id;
	}
}

/// Does this awake body wake what touches it? A dynamic body does; a kinematic one only while
/// moving (a resting kinematic platform does not wake what sleeps on it).
static bool tbWakesTouchingBodies(const tbBody* body)
{
	bool moving = tbLengthSquared(body->linearVelocity) > 0.0f || body->angularVelocity != 0.0f;
	return body->type == tb_dynamicBody || (body->type == tb_kinematicBody && moving);
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

/// Gather the solver contacts of body (awake) not gathered yet this step (stamp), waking the
/// sleeping bodies it touches through them when it wakes what it touches (they are appended to
/// the awake list and walked in turn by the caller).
static void tbWalkBodyContacts(tbWorld* world, const tbBody* body, uint32_t stamp)
{
	bool wakes = tbWakesTouchingBodies(body);
	for (int key = body->headContactKey; key != TB_NULL_INDEX;)
	{
		tbContact* contact = world->contacts + (key >> 1);
		int next = contact->edges[key & 1].nextKey;
		if (contact->stamp == stamp || tbIsSolverContact(world, contact) == false)
		{
			key = next;
			continue;
		}
		tbBody* other = world->bodies + contact->edges[(key & 1) ^ 1].bodyId;
		bool otherAsleep = other->type != tb_staticBody && other->awakeIndex == TB_NULL_INDEX;
		if (otherAsleep && wakes)
		{
			tbWakeBody(world, other);
			otherAsleep = false;
		}
		if (otherAsleep == false)
		{
			contact->stamp = stamp;
			TB_ARRAY_PUSH(world->solverContacts, world->solverContactCount, world->solverContactCapacity, key >> 1);
		}
		key = next;
	}
}

/// The solver contacts from the touching contacts the collide stage recorded, when bodies have only
/// joined the awake set since (the collide stage wakes both bodies of a contact that begins to
/// touch). A recorded contact with a sleeping side is kept, and the sleeper woken, when its awake
/// side wakes what it touches, as the walk in tbIslandStage decides; then only the bodies woken
/// since the collide stage have their contact lists walked. The same set as walking every awake
/// body's list, at the cost of the woken part only (smash: a wave of waking boxes every step).
/// Returns false (nothing gathered) when a body left the awake set since.
static bool tbGatherRecordedContacts(tbWorld* world, uint32_t stamp)
{
	if (world->gatheredRemovals != world->awakeRemovals)
	{
		return false;
	}
	bool unchanged = world->gatheredVersion == world->awakeSetVersion;
	world->solverContactCount = 0;
	TB_ARRAY_RESERVE(world->solverContacts, world->solverContactCapacity, world->touchingContactCount);
	for (int i = 0; i < world->touchingContactCount; ++i)
	{
		int entry = world->touchingContacts[i];
		if (entry >= 0)
		{
			// Ready (contact.c): a dynamic side and both awake, so nothing to wake and no need to
			// stamp it: only bodies woken after the collide stage are walked below, and a contact of
			// such a body was not ready.
			TB_ARRAY_PUSH(world->solverContacts, world->solverContactCount, world->solverContactCapacity, entry);
			continue;
		}
		int contactId = -1 - entry;
		tbContact* contact = world->contacts + contactId;
		const tbBody* a = world->bodies + contact->edges[0].bodyId;
		tbBody* b = world->bodies + contact->edges[1].bodyId;
		if (a->type != tb_dynamicBody && b->type != tb_dynamicBody)
		{
			continue;
		}
		bool asleepA = a->type != tb_staticBody && a->awakeIndex == TB_NULL_INDEX;
		bool asleepB = b->type != tb_staticBody && b->awakeIndex == TB_NULL_INDEX;
		if (asleepA || asleepB)
		{
			if (tbWakesTouchingBodies(asleepA ? b : a) == false)
			{
				continue; // a resting kinematic body on a sleeping one: nothing to solve
			}
			tbWakeBody(world, asleepA ? world->bodies + contact->edges[0].bodyId : b);
		}
		contact->stamp = stamp;
		TB_ARRAY_PUSH(world->solverContacts, world->solverContactCount, world->solverContactCapacity, contactId);
	}
	if (unchanged && world->gatheredVersion == world->awakeSetVersion)
	{
		return true; // nobody woke: the recorded contacts, already in contact-id order
	}
	for (int i = world->gatheredAwakeCount; i < world->awakeBodyCount; ++i)
	{
		tbWalkBodyContacts(world, world->bodies + world->awakeBodies[i], stamp);
	}
	TB_ARRAY_RESERVE(world->islandStack, world->islandStackCapacity, world->solverContactCount);
	tbSortIndices(world->solverContacts, world->solverContactCount, world->islandStack);
	return true;
}

void tbIslandStage(tbWorld* world)
{
	tbWakeJointPartners(world); // joint.c: before anything is gathered
	uint32_t stamp = 2u * world->stepIndex + 1u;
	if (tbGatherRecordedContacts(world, stamp))
	{
		tbOrderSolverContacts(world);
		return;
	}

	// One walk over the awake list, which grows while we walk it: a sleeping body touching an
	// awake dynamic or moving kinematic body through a solver contact is woken on the spot (so a
	// woken pile wakes whole: it is appended and walked in turn), and each solver contact is
	// gathered at its first visit. Touching means "has manifold points", speculative ones
	// included (contact.c keeps points up to a speed-dependent margin). A resting kinematic body
	// wakes nothing; a contact whose other side is still asleep after that (it touches only static
	// bodies or a resting kinematic one) has nothing to solve (both sides would be treated as
	// immovable) and is left out, so the solver never sees a sleeping non-static body. One walk
	// does both (the walk is bound by cache misses on the contact lists).
	world->solverContactCount = 0;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		tbWalkBodyContacts(world, world->bodies + world->awakeBodies[i], stamp);
	}
	// Contact-id order, as the fast path (and the collide stage) gives: the solver order must not
	// depend on whether a body was woken this step.
	TB_ARRAY_RESERVE(world->islandStack, world->islandStackCapacity, world->solverContactCount);
	tbSortIndices(world->solverContacts, world->solverContactCount, world->islandStack);
	tbOrderSolverContacts(world);
}

/// Depth-first search from a rested seed with a fresh stamp (stamps given since `firstStamp`
/// belong to this step's searches): collects the island's bodies in world->islandBodies and
/// returns their count, or −1 as soon as the island cannot sleep: it holds a body that has not
/// rested, or it reaches a dynamic body an earlier search of this step gave up in (that search
/// stopped part way, so its island — this island — holds a body that has not rested). A search
/// that gives up leaves its bodies stamped; one that completes has visited its whole island,
/// exactly as a search that never gives up would, in the same order.
static int tbCollectIsland(tbWorld* world, int seed, uint32_t firstStamp, uint32_t stamp)
{
	int count = 0, top = 0;
	TB_ARRAY_RESERVE(world->islandStack, world->islandStackCapacity, 1);
	world->islandStack[top++] = seed;
	world->bodies[seed].islandStamp = stamp;
	while (top > 0)
	{
		int bodyId = world->islandStack[--top];
		tbBody* body = world->bodies + bodyId;
		if (!(body->sleepTime >= TB_TIME_TO_SLEEP))
		{
			return -1;
		}
		TB_ARRAY_RESERVE(world->islandBodies, world->islandBodyCapacity, count + 1);
		world->islandBodies[count++] = bodyId;
		if (body->type != tb_dynamicBody)
		{
			continue; // kinematic: member of the island, but the search does not pass through it
		}
		for (int key = body->headContactKey; key != TB_NULL_INDEX;)
		{
			const tbContact* contact = world->contacts + (key >> 1);
			int otherId = contact->edges[(key & 1) ^ 1].bodyId;
			tbBody* other = world->bodies + otherId;
			key = contact->edges[key & 1].nextKey;
			if (other->type == tb_staticBody || other->islandStamp == stamp || other->awakeIndex == TB_NULL_INDEX ||
				tbIsSolverContact(world, contact) == false)
			{
				continue;
			}
			if ((uint32_t)(other->islandStamp - firstStamp) < (uint32_t)(stamp - firstStamp))
			{
				if (other->type == tb_dynamicBody)
				{
					return -1; // an earlier search of this step gave up in this island
				}
				continue; // a kinematic body another island already holds
			}
			other->islandStamp = stamp;
			TB_ARRAY_RESERVE(world->islandStack, world->islandStackCapacity, top + 1);
			world->islandStack[top++] = otherId;
		}
		top = tbPushJointedBodies(world, body, stamp, top); // joint.c: joints link islands too
	}
	return count;
}

/// Remove the marked bodies from the awake set in one pass (order preserved).
static void tbRemoveMarkedFromAwakeSet(tbWorld* world)
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
	world->awakeSetVersion += 1;
	world->awakeRemovals += 1;
	world->jointWakeDirty = true;
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
	// No island can sleep unless some awake body has rested long enough: then skip the search
	// (a scene in motion, like a turning drum, pays one comparison per awake body).
	bool anyRested = false;
	for (int i = 0; i < world->awakeBodyCount && world->def.enableSleep; ++i)
	{
		anyRested = anyRested || world->bodies[world->awakeBodies[i]].sleepTime >= TB_TIME_TO_SLEEP;
	}
	if (anyRested == false)
	{
		world->counters.islandCount = 0;
		return;
	}
	// Stamps: a fresh value per search; those from firstStamp on were given in this step.
	uint32_t firstStamp = world->islandSearchStamp + 1;
	int islands = 0;
	bool anySleep = false;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		int seed = world->awakeBodies[i];
		const tbBody* body = world->bodies + seed;
		if (!(body->sleepTime >= TB_TIME_TO_SLEEP) ||
			(uint32_t)(body->islandStamp - firstStamp) < (uint32_t)(world->islandSearchStamp + 1u - firstStamp))
		{
			continue; // has not rested (its island cannot sleep), or a search of this step visited it
		}
		world->islandSearchStamp += 1;
		int count = tbCollectIsland(world, seed, firstStamp, world->islandSearchStamp);
		islands += 1;
		if (count > 0)
		{
			tbPutIslandToSleep(world, count);
			anySleep = true;
		}
	}
	world->counters.islandCount = islands;
	if (anySleep)
	{
		tbRemoveMarkedFromAwakeSet(world);
	}
}
