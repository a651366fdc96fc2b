// Islands: bodies linked by touching contacts (contacts with manifold points, speculative points
// included) and joints. Two stages live here.
//
// The island stage runs before the solve: it wakes every sleeping body touching an awake one
// (transitively, so a woken pile wakes whole) and gathers the touching, non-sensor contacts that
// the solver will see. The sleep stage runs after the solve: it finds the islands of awake bodies
// (not through static or kinematic bodies, which do not carry motion from one island to another)
// by union–find over the step's solver contacts and the joints, and puts to sleep each island whose
// every body, and every kinematic body it touches, has rested for TB_TIME_TO_SLEEP. Sleeping bodies
// leave the awake set, so they cost nothing in any stage. The islands are found again each step,
// from dense arrays, when some body has rested (persistent islands as in Box2D v3 would avoid
// even that, but need island splitting); the union–find below says why it replaced a search,
// and docs/methods.md ("Sleeping") compares the costs.
#include "island.h"

#include "world.h"

#include "core/arena.h"
#include "core/array.h"
#include "core/sort.h"
#include "core/union_find.h"
#include "joints/joint.h"

#include <stdint.h>
#include <string.h>

// Solve order of the contacts. Gauss–Seidel is order dependent: the contacts gathered body by
// body (bottom row first, left to right in a pyramid) form a sweep across the structure, and a
// fixed sweep direction biases the result sideways: in a tall pyramid the top drifts to one side
// (the reversed order drifts as far to the other). Orders with structure of their own keep a
// bias: sorting by contact id or by body pair, alternating the sweep direction per sub-step, a
// greedy colouring in gathered order, shuffling small blocks of neighbouring contacts. Scattering
// single contacts removes it, and the pile also sags less and holds less kinetic energy. So the
// contacts are bucketed by a hash of their id (stable while the contact lives, independent of
// memory addresses, so the order is deterministic) into TB_SOLVE_ORDER_BUCKETS buckets with a
// stable counting sort; within a bucket the gathered order (contact-id order: contacts made in
// one step get consecutive ids in shape-pair order, which keeps some locality) is kept. The cost
// is locality: the solve reaches its bodies in a scattered order. Fewer buckets keep more of the
// gathered sweep and leave more drift; 16 leave next to none.
// The wide solver (the default, constraint_graph.c) then solves colour by colour, the colours
// assigned greedily in this order, so each colour is a scattered set too; a large pyramid drifts
// somewhat more under the wide order than the scalar one, the pyramid of the stability table
// no more (docs/methods.md, "Wide or scalar contact solver").
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
	int n = world->cache.solverContactCount;
	TB_ARRAY_RESERVE(world->cache.solverContactsById, world->cache.solverContactsByIdCapacity, n);
	TB_ARRAY_RESERVE(world->cache.solverSlots, world->cache.solverSlotCapacity, n);
	int* ids = world->cache.solverContacts;
	int* byId = world->cache.solverContactsById;
	int* slots = world->cache.solverSlots;
	int offsets[TB_SOLVE_ORDER_BUCKETS] = {0};
	for (int i = 0; i < n; ++i)
	{
		int id = ids[i];
		int bucket = tbSolveOrderBucket(id);
		byId[i] = id;
		slots[i] = bucket; // until the scatter below turns it into the slot
		offsets[bucket] += 1;
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
		int slot = offsets[slots[i]]++;
		slots[i] = slot;
		ids[slot] = byId[i];
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
			TB_ARRAY_PUSH(world->cache.solverContacts, world->cache.solverContactCount, world->cache.solverContactCapacity, key >> 1);
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
	if (world->cache.gatheredRemovals != world->cache.awakeRemovals)
	{
		return false;
	}
	bool unchanged = world->cache.gatheredVersion == world->cache.awakeSetVersion;
	world->cache.solverContactCount = 0;
	TB_ARRAY_RESERVE(world->cache.solverContacts, world->cache.solverContactCapacity, world->cache.touchingContactCount);
	for (int i = 0; i < world->cache.touchingContactCount; ++i)
	{
		int entry = world->cache.touchingContacts[i];
		if (entry >= 0)
		{
			// Ready (contact.c): a dynamic side and both awake, so nothing to wake and no need to
			// stamp it: only bodies woken after the collide stage are walked below, and a contact of
			// such a body was not ready.
			TB_ARRAY_PUSH(world->cache.solverContacts, world->cache.solverContactCount, world->cache.solverContactCapacity, entry);
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
		TB_ARRAY_PUSH(world->cache.solverContacts, world->cache.solverContactCount, world->cache.solverContactCapacity, contactId);
	}
	if (unchanged && world->cache.gatheredVersion == world->cache.awakeSetVersion)
	{
		return true; // nobody woke: the recorded contacts, already in contact-id order
	}
	for (int i = world->cache.gatheredAwakeCount; i < world->awakeBodyCount; ++i)
	{
		tbWalkBodyContacts(world, world->bodies + world->awakeBodies[i], stamp);
	}
	TB_ARRAY_RESERVE(world->cache.islandStack, world->cache.islandStackCapacity, world->cache.solverContactCount);
	tbSortIndices(world->cache.solverContacts, world->cache.solverContactCount, world->cache.islandStack);
	return true;
}

/// A step like the last one: the collide stage recorded exactly the last step's solver contacts, all
/// ready (a dynamic side, both sides awake), and no body joined or left the awake set since. The
/// solve order and the id order depend on the contact ids alone, so the last step's arrays hold
/// as they are (a settled pile: large_pyramid, every step after the first few).
/// When the collide stage kept the last touching list (world->cache.touchingUnchanged) and the last step
/// found it equal to the solver contacts, it still is, without the comparison.
static bool tbSameSolverContacts(const tbWorld* world)
{
	int n = world->cache.touchingContactCount;
	bool sameAwake = world->cache.gatheredRemovals == world->cache.awakeRemovals && world->cache.gatheredVersion == world->cache.awakeSetVersion;
	if (sameAwake && world->cache.touchingUnchanged && world->cache.solverContactsUnchanged)
	{
		return true;
	}
	return sameAwake && n == world->cache.solverContactCount &&
		   (n == 0 || memcmp(world->cache.touchingContacts, world->cache.solverContactsById, sizeof(int) * (size_t)n) == 0);
}

void tbIslandStage(tbWorld* world)
{
	tbWakeJointPartners(world); // joint.c: before anything is gathered
	world->cache.solverContactsUnchanged = tbSameSolverContacts(world);
	if (world->cache.solverContactsUnchanged)
	{
		return;
	}
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
	world->cache.solverContactCount = 0;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		tbWalkBodyContacts(world, world->bodies + world->awakeBodies[i], stamp);
	}
	// Contact-id order, as the fast path (and the collide stage) gives: the solver order must not
	// depend on whether a body was woken this step.
	TB_ARRAY_RESERVE(world->cache.islandStack, world->cache.islandStackCapacity, world->cache.solverContactCount);
	tbSortIndices(world->cache.solverContacts, world->cache.solverContactCount, world->cache.islandStack);
	tbOrderSolverContacts(world);
}

// The sleep stage's islands, found by union–find (core/union_find.h: Rem's splicing, the forest
// flattened once the links are in; each island's root is its smallest awake index) over the awake
// indices instead of a depth-first search from each rested body. The links are the ones a search
// would follow: this step's solver contacts whose both bodies are dynamic
// (world->cache.solverContacts, gathered by the island stage from the same touching flags, and read
// through the narrow phase's dense keys where they hold) and the joints between awake dynamic
// bodies. Static bodies link nothing; a kinematic body links nothing either (it does not carry
// motion from one island to another) but belongs to every island it touches. The cost is a pass
// over dense arrays: the search it replaces followed contact lists, a cache miss per link, and in a
// pile where rested and moving bodies mix (junkyard) it walked thousands of links a step to learn
// that nothing could sleep.

enum
{
	tb_sleepDynamic = 1,	   ///< an awake dynamic body
	tb_sleepRested = 2,		   ///< has rested for TB_TIME_TO_SLEEP
	tb_sleepKeepAwake = 4,	   ///< on a root: some member, or some kinematic body it touches, has not rested
	tb_sleepTouchesAwake = 8,  ///< on a kinematic body: touches an island that stays awake
};

// A dynamic body touching (or joined to) a kinematic one, by awake index.
typedef struct tbKinematicTouch
{
	int dynamicIndex, kinematicIndex;
} tbKinematicTouch;

// The links and kinematic touches of the sleep stage, gathered from one step's solver contacts and
// the joints.
typedef struct tbSleepLinks
{
	int* parent; ///< union–find forest over the awake indices
	tbKinematicTouch* touches;
	int touchCount;
} tbSleepLinks;

// A link between awake indices a and b (TB_NULL_INDEX: static, or asleep) with their dynamic flags:
// two dynamic bodies join islands; a dynamic and a kinematic body are remembered as a touch.
static inline void tbAddSleepLink(tbSleepLinks* links, int a, bool dynamicA, int b, bool dynamicB)
{
	if (a == TB_NULL_INDEX || b == TB_NULL_INDEX)
	{
		return;
	}
	if (dynamicA && dynamicB)
	{
		tbLinkRoots(links->parent, a, b);
	}
	else if (dynamicA != dynamicB)
	{
		tbKinematicTouch* touch = links->touches + links->touchCount++;
		touch->dynamicIndex = dynamicA ? a : b;
		touch->kinematicIndex = dynamicA ? b : a;
	}
}

/// The island of awake index i, once the links are in and the forest flattened (tbFlattenRoots).
static inline int tbRootOf(const tbSleepLinks* links, int i)
{
	return links->parent[i];
}

static void tbAddBodyLink(tbSleepLinks* links, const tbBody* a, const tbBody* b)
{
	tbAddSleepLink(links, a->awakeIndex, a->type == tb_dynamicBody, b->awakeIndex, b->type == tb_dynamicBody);
}

// The solver contacts in contact-id order, each through the narrow phase's key where it was written
// this step (its awake indices still hold when no body left the awake set since), else through
// its bodies; then the joints (a pool in id order, few).
static void tbGatherSleepLinks(tbWorld* world, tbSleepLinks* links)
{
	bool useCollideKeys = world->cache.gatheredRemovals == world->cache.awakeRemovals;
	for (int i = 0; i < world->cache.solverContactCount; ++i)
	{
		int contactId = world->cache.solverContactsById[i];
		const tbCollideKey* written = world->cache.collideKeys + contactId;
		if (useCollideKeys && contactId < world->cache.collideKeyCount && written->step == world->stepIndex)
		{
			const tbContactKey* key = &written->key;
			tbAddSleepLink(links, key->indexA, (key->flags & tb_keyDynamicA) != 0u, key->indexB,
						   (key->flags & tb_keyDynamicB) != 0u);
			continue;
		}
		const tbContact* contact = world->contacts + contactId;
		tbAddBodyLink(links, world->bodies + contact->edges[0].bodyId, world->bodies + contact->edges[1].bodyId);
	}
	for (int id = 0; id < world->jointPool.highWater && world->jointPool.count > 0; ++id)
	{
		const tbJoint* joint = world->joints + id;
		if (joint->inUse && joint->type != tb_filterJoint)
		{
			tbAddBodyLink(links, world->bodies + joint->edges[0].bodyId, world->bodies + joint->edges[1].bodyId);
		}
	}
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
	tbStepCache_AwakeSetChanged(&world->cache, true);
}

static void tbPutBodyToSleep(tbWorld* world, tbBody* body)
{
	if (body->awakeIndex < world->events.moveCount)
	{
		world->events.moveEvents[body->awakeIndex].fellAsleep = true;
	}
	body->isMarked = true;
	body->linearVelocity = tbVec2_zero;
	body->angularVelocity = 0.0f;
	body->force = tbVec2_zero;
	body->torque = 0.0f;
}

// An island sleeps when every body in it has rested for TB_TIME_TO_SLEEP, and so has every
// kinematic body it touches (a moving platform or pusher keeps what it touches awake). A rested
// kinematic body sleeps when no island it touches stays awake. Returns whether anything sleeps.
static bool tbMarkSleepingIslands(tbWorld* world, const tbSleepLinks* links, uint8_t* state)
{
	int n = world->awakeBodyCount;
	for (int i = 0; i < n; ++i)
	{
		if ((state[i] & (tb_sleepDynamic | tb_sleepRested)) == tb_sleepDynamic)
		{
			state[tbRootOf(links, i)] |= tb_sleepKeepAwake;
		}
	}
	for (int t = 0; t < links->touchCount; ++t)
	{
		const tbKinematicTouch* touch = links->touches + t;
		if ((state[touch->kinematicIndex] & tb_sleepRested) == 0)
		{
			state[tbRootOf(links, touch->dynamicIndex)] |= tb_sleepKeepAwake;
		}
	}
	for (int t = 0; t < links->touchCount; ++t)
	{
		const tbKinematicTouch* touch = links->touches + t;
		if ((state[tbRootOf(links, touch->dynamicIndex)] & tb_sleepKeepAwake) != 0)
		{
			state[touch->kinematicIndex] |= tb_sleepTouchesAwake;
		}
	}
	bool anySleep = false;
	for (int i = 0; i < n; ++i)
	{
		bool sleeps = (state[i] & tb_sleepDynamic) != 0
						  ? (state[tbRootOf(links, i)] & tb_sleepKeepAwake) == 0
						  : (state[i] & (tb_sleepRested | tb_sleepTouchesAwake)) == tb_sleepRested;
		if (sleeps)
		{
			tbPutBodyToSleep(world, world->bodies + world->awakeBodies[i]);
			anySleep = true;
		}
	}
	return anySleep;
}

// Islands that hold a rested body (tbCounters.islandCount): the roots with a rested member.
static int tbCountRestedIslands(const tbWorld* world, const tbSleepLinks* links, const uint8_t* state, uint8_t* counted)
{
	int islands = 0;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		if ((state[i] & tb_sleepRested) == 0)
		{
			continue;
		}
		int root = (state[i] & tb_sleepDynamic) != 0 ? tbRootOf(links, i) : i;
		islands += counted[root] == 0 ? 1 : 0;
		counted[root] = 1;
	}
	return islands;
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

	uint64_t ticks = tbGetTicks();
	int n = world->awakeBodyCount;
	tbSleepLinks links;
	links.parent = tbArenaAlloc(&world->stepArena, (int)sizeof(int) * n);
	links.touches = tbArenaAlloc(&world->stepArena, (int)sizeof(tbKinematicTouch) *
															tbMaxInt(world->cache.solverContactCount + world->jointPool.count, 1));
	links.touchCount = 0;
	uint8_t* state = tbArenaAlloc(&world->stepArena, 2 * n);
	memset(state, 0, 2 * (size_t)n);
	for (int i = 0; i < n; ++i)
	{
		const tbBody* body = world->bodies + world->awakeBodies[i];
		links.parent[i] = i;
		state[i] |= body->type == tb_dynamicBody ? (uint8_t)tb_sleepDynamic : 0u;
		state[i] |= body->sleepTime >= TB_TIME_TO_SLEEP ? (uint8_t)tb_sleepRested : 0u;
	}
	tbGatherSleepLinks(world, &links);
	tbFlattenRoots(links.parent, n); // from here on links.parent[i] is i's root (tbRootOf)
	world->counters.islandCount = tbCountRestedIslands(world, &links, state, state + n);
	world->profile.splitIslands = tbGetMilliseconds(ticks);
	if (tbMarkSleepingIslands(world, &links, state))
	{
		tbRemoveMarkedFromAwakeSet(world);
	}
}
