// The solve order of the step's constraints, by graph colouring: the contacts, for the wide
// solver (contact_solver_wide.c), split into island partitions where the workers can take whole
// piles (tbColorConstraints); and the joints (tbColorJoints, the second half of the file): small
// mechanisms in joint-id order, the joints of large ones by colour, and which mechanisms have too
// many loops for joint trees (tbMarkLoopyMechanisms). Both colourings are kept with their inputs
// and reused while those stay the same from step to step.
//
// Two constraints that share a body that moves cannot be solved at the same time: each reads the
// body's velocity that the other writes. Colouring the constraint graph (constraints are vertices,
// an edge joins two constraints on a common moving body) splits the constraints into sets in
// which no moving body appears twice; the constraints of one colour are then independent, and
// TB_SIMD_WIDTH of them (4 with SSE2 or plain floats, 8 with AVX2) can be solved at once in the
// lanes of a wide float, with exactly the result of solving them one after another in any order.
// Static, kinematic and sleeping bodies do not move in the solve (infinite mass: the solver writes
// back the velocity it read), so they do not take a colour: a ground box touching a hundred boxes
// costs nothing here.
//
// Greedy first fit, one pass: each body keeps a bit mask of the colours its constraints already
// took; a constraint takes the lowest colour free in both masks, found with one OR and a count of
// trailing zeros. Greedy colouring needs at most (largest degree + 1) colours, and a body in a pile
// touches few others, so TB_GRAPH_COLOR_COUNT leaves room. Constraints that find no free colour
// among TB_GRAPH_COLOR_COUNT (very crowded bodies: a body with many small neighbours) go to an
// overflow list that the scalar solver handles after the colours, and so do contacts with a
// tangent speed (a conveyor belt, tbSurfaceMaterial): the wide blocks do not carry it, so that the
// common contact pays nothing for it. Rolling resistance, common on balls and wheels, is solved in
// the lanes, its row kept beside the blocks (tbWideRolling) only in a step where some coloured
// contact has it.
//
// Order. Gauss–Seidel results depend on the order, and the order here is colour by colour; the
// colours are assigned greedily in the island stage's order (a hash of the contact id, island.c),
// which makes each colour a scattered set, not a sweep across the structure (island.c says why,
// docs/methods.md has the measurements). Within a colour the order does not matter (no moving body
// appears twice), so the lanes are handed out in contact-id order, the order in which the
// preparation reads the contacts and writes the lanes.
//
// The colours are computed before the contacts are prepared, from a small key per contact
// (tbContactKey: its two solver bodies and whether each moves); each contact is then prepared
// straight into its lane (contact_solver.c). They are recomputed from scratch whenever the keys
// or the solve order differ from the last step's in any byte, and reused from the last step
// otherwise (tbContactColorCache): nothing has to be kept consistent when contacts begin and end
// (Box2D v3 keeps its colours persistent and updates them instead). Colouring after preparing
// would write a 160-byte scalar constraint per contact and read it back to colour and pack it;
// colouring from the keys first writes each contact once, into its lane, which saves more cache
// misses than the few extra instructions cost (docs/architecture.md).
// Reference: the graph colouring used by Box2D v3's solver (Catto, "Solver2D" and "SIMD
// matters" blog posts, 2024).
#include "constraint_graph.h"

#include "contact_solver.h"
#include "joints/joint.h"
#include "core/task.h"
#include "core/union_find.h"

#include <string.h>

// Colour of each constraint (or TB_GRAPH_COLOR_COUNT for overflow); counts per colour. A body takes
// part when the constraint can change its velocity (tb_keyMovesA/B). Without branches on those
// flags: a side that does not move reads its mask as 0 and ORs 0 into it (its mask stays 0, the
// static stand-in's included), the same colours as testing the flags, and no mispredicted branch
// where ground contacts and contacts between bodies alternate in the solve order.
static void tbAssignColors(tbStepContext* context, uint32_t* bodyMasks, uint8_t* colors,
						   int counts[TB_GRAPH_COLOR_COUNT + 1])
{
	int rolling = 0;
	const uint32_t allColors = TB_GRAPH_COLOR_COUNT == 32 ? ~0u : ((1u << TB_GRAPH_COLOR_COUNT) - 1u);
	const tbContactKey* keys = context->keys; // locals: the colour stores (bytes) may alias anything
	int n = context->constraintCount;
	for (int i = 0; i < n; ++i)
	{
		tbContactKey key = keys[i];
		uint32_t onA = 0u - (key.flags & tb_keyMovesA);		   // all ones when A moves
		uint32_t onB = 0u - ((key.flags & tb_keyMovesB) >> 1); // all ones when B moves
		uint32_t used = (bodyMasks[key.indexA] & onA) | (bodyMasks[key.indexB] & onB);
		// the wide blocks carry no tangent speed: the scalar solver takes it (no free colour)
		uint32_t free = (key.flags & tb_keyScalarOnly) != 0u ? 0u : ~used & allColors;
		int color = TB_GRAPH_COLOR_COUNT;
		if (free != 0u)
		{
			color = tbLowestSetBit(free);
			uint32_t bit = 1u << color;
			bodyMasks[key.indexA] |= bit & onA;
			bodyMasks[key.indexB] |= bit & onB;
		}
		colors[i] = (uint8_t)color;
		counts[color] += 1;
		rolling += color != TB_GRAPH_COLOR_COUNT && (key.flags & tb_keyRolling) != 0u ? 1 : 0;
	}
	context->rollingCount = rolling;
}

/// Contacts of colour k in partition p: n[k][p].
typedef struct tbPartitionCounts
{
	int n[TB_GRAPH_COLOR_COUNT][TB_MAX_PARTITIONS];
} tbPartitionCounts;

// The colouring of the last step, kept with its inputs: the keys in contact-id order and each
// contact's place in the solve order (world->cache.solverSlots), which together are the keys in solve
// order. The colours are a function of exactly those (and of the body count, the static
// stand-in's index), so when this step's inputs are equal byte for byte the last step's lanes are
// this step's: a settled pile, whose touching contacts and awake bodies stay the same from step to
// step, reuses them instead of colouring (large_pyramid: every step after the first few). Any
// difference recolours; nothing else decides.
typedef struct tbContactColorCache
{
	int count;	  ///< constraints coloured; 0: nothing kept
	int capacity; ///< of the arrays
	int bodyCount;
	int bounceCount;		///< keys with tb_keyBounces among them
	int rollingCount;		///< coloured keys with tb_keyRolling among them
	tbContactKey* keysById; ///< context->keysById as coloured
	int* slots;				///< world->cache.solverSlots
	int* wideLocation;	///< the colouring's outputs: lane by solve slot,
	int* locationById;	///< and by contact-id order
	int counts[TB_GRAPH_COLOR_COUNT + 1];
	int partitionRequest; ///< tbPartitionRequest when the colours were made
	int partitionCount;	  ///< as tbStepContext (0: none)
	int partitionBodyStart[TB_MAX_PARTITIONS + 1];
	tbPartitionCounts partitionCounts;
} tbContactColorCache;

void tbDestroyContactColorCache(tbWorld* world)
{
	tbContactColorCache* cache = world->cache.contactColorCache;
	if (cache == NULL)
	{
		return;
	}
	if (cache->capacity > 0)
	{
		tbFree(cache->keysById, (int)sizeof(tbContactKey) * cache->capacity);
		tbFree(cache->slots, (int)sizeof(int) * cache->capacity);
		tbFree(cache->wideLocation, (int)sizeof(int) * cache->capacity);
		tbFree(cache->locationById, (int)sizeof(int) * cache->capacity);
	}
	tbFree(cache, (int)sizeof(tbContactColorCache));
	world->cache.contactColorCache = NULL;
}

static bool tbSameColorInputs(const tbStepContext* context, int partitionRequest)
{
	const tbContactColorCache* cache = context->world->cache.contactColorCache;
	if (context->keysFromCache)
	{
		// tbSteadyContactKeys: the same keys and solve order as the colours were made for; the
		// partitions also depend on the worker count (tbWorld_SetWorkerCount)
		return cache->partitionRequest == partitionRequest;
	}
	int n = context->constraintCount;
	return cache != NULL && cache->count == n && n > 0 && cache->bodyCount == context->bodyCount &&
		   cache->partitionRequest == partitionRequest &&
		   memcmp(cache->keysById, context->keysById, sizeof(tbContactKey) * (size_t)n) == 0 &&
		   memcmp(cache->slots, context->world->cache.solverSlots, sizeof(int) * (size_t)n) == 0;
}

bool tbGetContactGraphColors(const tbWorld* world, int* colors, int counts[TB_GRAPH_COLOR_COUNT + 1])
{
	const tbContactColorCache* cache = world->cache.contactColorCache;
	int n = world->cache.solverContactCount;
	// Kept colours describe the solver contacts only if this step made or reused them.
	if (cache == NULL || world->cache.colorCacheStep != world->stepIndex || cache->count != n || n == 0)
	{
		return false;
	}
	if (counts != NULL)
	{
		memcpy(counts, cache->counts, sizeof(cache->counts));
	}
	if (colors == NULL)
	{
		return true;
	}
	// The blocks are laid out colour after colour (tbLayOutColors): a lane's block says its colour.
	int blockStart[TB_GRAPH_COLOR_COUNT + 1];
	int partitions = tbMaxInt(cache->partitionCount, 1);
	int blockCount = 0;
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		blockStart[k] = blockCount;
		for (int p = 0; p < partitions; ++p)
		{
			blockCount += (cache->partitionCounts.n[k][p] + TB_SIMD_WIDTH - 1) / TB_SIMD_WIDTH;
		}
	}
	blockStart[TB_GRAPH_COLOR_COUNT] = blockCount;
	for (int i = 0; i < n; ++i)
	{
		int location = cache->locationById[i];
		int color = TB_GRAPH_COLOR_COUNT;
		if (location >= 0)
		{
			int block = location / TB_SIMD_WIDTH;
			color = 0;
			while (color + 1 < TB_GRAPH_COLOR_COUNT && blockStart[color + 1] <= block)
			{
				color += 1;
			}
		}
		colors[i] = color;
	}
	return true;
}

const tbContactKey* tbSteadyContactKeys(const tbStepContext* context)
{
	const tbWorld* world = context->world;
	const tbContactColorCache* cache = world->cache.contactColorCache;
	int n = context->constraintCount;
	// solverIsTouching: the solver contacts, hence their solve order (world->cache.solverSlots), are the
	// last step's; the cache then holds that step's keys and slots (checked or kept since).
	bool steady = world->cache.collideKeysUnchanged && world->cache.solverContactsUnchanged && cache != NULL && cache->count == n &&
				  n > 0 && cache->bodyCount == context->bodyCount && cache->bounceCount == 0 &&
				  world->cache.colorCacheStep == world->stepIndex - 1u;
	return steady ? cache->keysById : NULL;
}

static void tbKeepColors(const tbStepContext* context, const int counts[TB_GRAPH_COLOR_COUNT + 1],
						 const tbPartitionCounts* partitionCounts, int partitionRequest,
						 int bounceCount)
{
	tbWorld* world = context->world;
	int n = context->constraintCount;
	if (world->cache.contactColorCache == NULL || n > world->cache.contactColorCache->capacity)
	{
		tbDestroyContactColorCache(world);
		tbContactColorCache* fresh = tbAlloc((int)sizeof(tbContactColorCache));
		memset(fresh, 0, sizeof(*fresh));
		int capacity = n + n / 4 + 16; // room for a pile that grows a little
		fresh->capacity = capacity;
		fresh->keysById = tbAlloc((int)sizeof(tbContactKey) * capacity);
		fresh->slots = tbAlloc((int)sizeof(int) * capacity);
		fresh->wideLocation = tbAlloc((int)sizeof(int) * capacity);
		fresh->locationById = tbAlloc((int)sizeof(int) * capacity);
		world->cache.contactColorCache = fresh;
	}
	tbContactColorCache* cache = world->cache.contactColorCache;
	cache->count = n;
	cache->bodyCount = context->bodyCount;
	cache->bounceCount = bounceCount;
	cache->rollingCount = context->rollingCount;
	if (cache->keysById != context->keysById) // a steady step recoloured for another worker count
	{
		memcpy(cache->keysById, context->keysById, sizeof(tbContactKey) * (size_t)n);
	}
	memcpy(cache->slots, world->cache.solverSlots, sizeof(int) * (size_t)n);
	memcpy(cache->wideLocation, context->wideLocation, sizeof(int) * (size_t)n);
	memcpy(cache->locationById, context->locationById, sizeof(int) * (size_t)n);
	memcpy(cache->counts, counts, sizeof(cache->counts));
	cache->partitionRequest = partitionRequest;
	cache->partitionCount = context->partitionCount;
	memcpy(cache->partitionBodyStart, context->partitionBodyStart, sizeof(cache->partitionBodyStart));
	cache->partitionCounts = *partitionCounts;
}

// The blocks, padding and overflow list for the per-colour counts, each colour's split over the
// context's partitions (partitionCounts->n[k][p]; one partition when context->partitionCount is 0);
// wideLocation allocated (filled by the caller, as is locationById).
static void tbLayOutColors(tbStepContext* context, const int counts[TB_GRAPH_COLOR_COUNT + 1],
						   const tbPartitionCounts* partitionCounts);

/// The keys in solve order (context->keys) from the keys in contact-id order; returns how many
/// bounce.
static int tbScatterKeys(const tbStepContext* context)
{
	const int* slots = context->world->cache.solverSlots;
	int bounceCount = 0;
	for (int i = 0; i < context->constraintCount; ++i)
	{
		tbContactKey key = context->keysById[i];
		context->keys[slots[i]] = key;
		bounceCount += (key.flags & tb_keyBounces) != 0u ? 1 : 0;
	}
	return bounceCount;
}

// Island partitions. The contacts of bodies that no contact links (separate piles: islands) can be
// solved apart with no barrier between them. When the solver order of the awake bodies keeps each
// island in one run (a scene's piles built one after another, woken together), cutting the order
// where no contact straddles the cut gives runs that share no body, and each worker can take one
// run through every sub-step stage on its own (solver_workers.c): no barrier per colour, and no
// body's state passes between the workers' caches. The results are the same bit for bit as with
// the shared stages or one worker: a body meets its contacts in the same colour order either way,
// and the contacts of one colour are independent whatever block they sit in.
// The cuts are taken nearest to equal contact counts (a sweep over the solver bodies with a
// difference array of the contacts' index spans); when the largest run holds more than 1/16 above
// an equal share, or the bodies do not fall into runs, there is one partition and the workers
// share every stage.

/// Steps between tries after a colouring that found no partitions (half a second at 60 Hz).
#define TB_PARTITION_RETRY_STEPS 30

/// How many partitions the step could use: one per worker (up to TB_MAX_PARTITIONS workers) when the
/// workers run the soft step's stages (tbSolveSubStepsOnWorkers) and no joint links bodies; else 1.
static int tbPartitionRequest(const tbStepContext* context)
{
	const tbWorld* world = context->world;
	int workers = tbWorkerCount(&world->def);
	if (workers < 2 || world->def.solver != tb_solverSoft || context->enableWarmStarting == false ||
		world->cache.solverJointCount > 0)
	{
		return 1;
	}
	return workers <= TB_MAX_PARTITIONS ? workers : 1;
}

/// The lowest solver index among a contact's bodies that are not the static stand-in (bodyCount
/// when neither is), and the highest (the lowest when only one is).
static inline void tbKeySpan(tbContactKey key, int bodyCount, int* lo, int* hi)
{
	int a = tbMinInt(key.indexA, key.indexB);
	int b = tbMaxInt(key.indexA, key.indexB);
	*lo = a;
	*hi = b < bodyCount ? b : a;
}

/// Cuts of the solver body order into `request` runs that no contact straddles, nearest to equal
/// contact counts: context->partitionBodyStart. Returns false when there are not enough cuts.
/// cover and weight: bodyCount + 1 ints each.
static bool tbCutPartitions(tbStepContext* context, int request, int* cover, int* weight)
{
	int n = context->constraintCount;
	int bodyCount = context->bodyCount;
	memset(cover, 0, sizeof(int) * (size_t)(bodyCount + 1));
	memset(weight, 0, sizeof(int) * (size_t)(bodyCount + 1));
	for (int i = 0; i < n; ++i)
	{
		int lo, hi;
		tbKeySpan(context->keys[i], bodyCount, &lo, &hi);
		weight[lo] += 1;
		if (hi > lo)
		{
			cover[lo + 1] += 1; // a cut before any body in (lo, hi] would split this contact
			cover[hi + 1] -= 1;
		}
	}
	int* start = context->partitionBodyStart;
	start[0] = 0;
	int found = 1;
	int target = (int)((int64_t)n * found / request);
	int open = 0;			// contacts straddling a cut before body s
	int before = weight[0]; // contacts whose lowest body is below s
	int candidate = -1, candidateBefore = 0; // the last valid cut below the target
	for (int s = 1; s < bodyCount && found < request; ++s)
	{
		open += cover[s];
		if (open == 0)
		{
			if (before < target)
			{
				candidate = s;
				candidateBefore = before;
			}
			else
			{
				bool below = candidate > start[found - 1] && target - candidateBefore < before - target;
				start[found++] = below ? candidate : s;
				target = (int)((int64_t)n * found / request);
				candidate = below ? s : -1;
				candidateBefore = before;
			}
		}
		before += weight[s];
	}
	if (found == request - 1 && candidate > start[found - 1])
	{
		start[found++] = candidate;
	}
	start[request] = bodyCount;
	return found == request;
}

/// The partition of a contact: the run holding its lowest body.
static inline int tbKeyPartition(const tbStepContext* context, tbContactKey key)
{
	int lo = tbMinInt(key.indexA, key.indexB);
	int p = 0;
	while (p + 1 < context->partitionCount && lo >= context->partitionBodyStart[p + 1])
	{
		p += 1;
	}
	return p;
}

/// Partitions for the step (context->partitionCount, 0 when none) and each colour's contacts per
/// partition. cover and weight: bodyCount + 1 ints each (request > 1).
static void tbPartitionColors(tbStepContext* context, int request, const uint8_t* colors,
							  const int counts[TB_GRAPH_COLOR_COUNT + 1],
							  tbPartitionCounts* partitionCounts, int* cover, int* weight)
{
	int n = context->constraintCount;
	memset(partitionCounts, 0, sizeof(*partitionCounts));
	context->partitionCount = 0;
	// Contacts without a colour are solved in one stage after the colours: no partitions then. A
	// scene whose last try found none (one pile, a kinematic body across the piles) tries again
	// only after TB_PARTITION_RETRY_STEPS, not at every colouring (the sweep is a pass over the
	// contacts and one over the bodies; the tumbler colours every step).
	tbWorld* world = context->world;
	bool worth = request > 1 && counts[TB_GRAPH_COLOR_COUNT] == 0 && context->bodyCount >= 2 * request &&
				 (int32_t)(world->stepIndex - world->cache.partitionRetryStep) >= 0;
	if (worth && tbCutPartitions(context, request, cover, weight) == false)
	{
		world->cache.partitionRetryStep = world->stepIndex + TB_PARTITION_RETRY_STEPS;
	}
	else if (worth)
	{
		context->partitionCount = request;
		int load[TB_MAX_PARTITIONS] = {0};
		for (int i = 0; i < n; ++i)
		{
			int p = tbKeyPartition(context, context->keys[i]);
			partitionCounts->n[colors[i]][p] += 1;
			load[p] += 1;
		}
		int largest = 0;
		for (int p = 0; p < request; ++p)
		{
			largest = tbMaxInt(largest, load[p]);
		}
		if ((int64_t)largest * request * 16 <= (int64_t)n * 17)
		{
			return;
		}
		context->partitionCount = 0; // too uneven: the shared stages balance better
		world->cache.partitionRetryStep = world->stepIndex + TB_PARTITION_RETRY_STEPS;
		memset(partitionCounts, 0, sizeof(*partitionCounts));
	}
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		partitionCounts->n[k][0] = counts[k];
	}
}

void tbColorConstraints(tbStepContext* context)
{
	int n = context->constraintCount;
	int bodyCount = context->bodyCount;
	int counts[TB_GRAPH_COLOR_COUNT + 1] = {0};
	tbPartitionCounts partitionCounts;
	int request = tbPartitionRequest(context);
	context->world->cache.colorCacheStep = context->world->stepIndex; // kept or made below
	if (tbSameColorInputs(context, request))
	{
		const tbContactColorCache* cache = context->world->cache.contactColorCache;
		context->partitionCount = cache->partitionCount;
		memcpy(context->partitionBodyStart, cache->partitionBodyStart, sizeof(context->partitionBodyStart));
		context->rollingCount = cache->rollingCount;
		tbLayOutColors(context, cache->counts, &cache->partitionCounts);
		memcpy(context->wideLocation, cache->wideLocation, sizeof(int) * (size_t)n);
		context->locationById = cache->locationById; // read only until the next colouring
		for (int i = 0; i < n && context->overflowCount < cache->counts[TB_GRAPH_COLOR_COUNT]; ++i)
		{
			if (context->wideLocation[i] < 0)
			{
				context->overflowConstraints[context->overflowCount++] = i; // in solve order
			}
		}
		if (cache->bounceCount > 0)
		{
			tbScatterKeys(context); // restitution reads them (tbConstraintBounces)
		}
		return;
	}
	int bounceCount = tbScatterKeys(context);

	int maskBytes = (int)sizeof(uint32_t) * (bodyCount + 1);
	int colorBytes = (n + 3) & ~3;
	int scratchBytes = maskBytes + colorBytes + (request > 1 ? (int)sizeof(int) * (bodyCount + 1) : 0);
	char* scratch = tbArenaAlloc(&context->world->stepArena, scratchBytes);
	uint32_t* bodyMasks = (uint32_t*)scratch;
	uint8_t* colors = (uint8_t*)(scratch + maskBytes);
	memset(bodyMasks, 0, (size_t)maskBytes);
	tbAssignColors(context, bodyMasks, colors, counts);
	// The masks are done with: their bodyCount + 1 ints and the ones after the colours are the
	// partition sweep's.
	tbPartitionColors(context, request, colors, counts, &partitionCounts, (int*)scratch,
					  (int*)(scratch + maskBytes + colorBytes));
	tbLayOutColors(context, counts, &partitionCounts);
	context->locationById = tbArenaAlloc(&context->world->stepArena, (int)sizeof(int) * tbMaxInt(n, 1));
	// The overflow is solved one constraint at a time, in the solve order.
	for (int i = 0; i < n && context->overflowCount < counts[TB_GRAPH_COLOR_COUNT]; ++i)
	{
		if (colors[i] == TB_GRAPH_COLOR_COUNT)
		{
			context->overflowConstraints[context->overflowCount++] = i;
			context->wideLocation[i] = -1;
		}
	}
	// Within a colour no moving body appears twice, so where a constraint sits among its colour's
	// lanes does not change the result. The lanes are handed out in contact-id order, the order in
	// which the preparation reads the contacts and writes the lanes (contact_solver.c): each
	// colour's blocks are then written front to back, one stream per colour (and partition). Handed
	// out in solve order (a hash of the contact id, island.c), every block was written lane by lane
	// from sixteen places at once and fell out of the cache between its lanes.
	// next[k][p]: the next free lane of colour k in partition p, counted from its first block.
	const int* slots = context->world->cache.solverSlots;
	int* wideLocation = context->wideLocation;
	int* locationById = context->locationById;
	int next[TB_GRAPH_COLOR_COUNT][TB_MAX_PARTITIONS];
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		for (int p = 0; p < TB_MAX_PARTITIONS; ++p)
		{
			next[k][p] = context->partitionBlockStart[k][p] * TB_SIMD_WIDTH;
		}
	}
	bool partitioned = context->partitionCount > 0;
	for (int i = 0; i < n; ++i)
	{
		int index = slots[i];
		int k = colors[index];
		int location = -1;
		if (k != TB_GRAPH_COLOR_COUNT)
		{
			int p = partitioned ? tbKeyPartition(context, context->keys[index]) : 0;
			location = next[k][p]++;
			wideLocation[index] = location;
		}
		locationById[i] = location;
	}
	if (n > 0)
	{
		tbKeepColors(context, counts, &partitionCounts, request, bounceCount);
	}
}

static void tbLayOutColors(tbStepContext* context, const int counts[TB_GRAPH_COLOR_COUNT + 1],
						   const tbPartitionCounts* partitionCounts)
{
	int n = context->constraintCount;
	int bodyCount = context->bodyCount;
	int partitions = tbMaxInt(context->partitionCount, 1);

	// Blocks of TB_SIMD_WIDTH lanes, colour after colour, and within a colour partition after
	// partition; the last block of each is padded.
	int* blockStart = context->colorBlockStart;
	int blockCount = 0;
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		blockStart[k] = blockCount;
		for (int p = 0; p < partitions; ++p)
		{
			context->partitionBlockStart[k][p] = blockCount;
			blockCount += (partitionCounts->n[k][p] + TB_SIMD_WIDTH - 1) / TB_SIMD_WIDTH;
		}
		context->partitionBlockStart[k][partitions] = blockCount;
	}
	blockStart[TB_GRAPH_COLOR_COUNT] = blockCount;
	int overflowCount = counts[TB_GRAPH_COLOR_COUNT];

	// One piece of the step arena: wide blocks, then the overflow list. The arena hands out 32-byte
	// aligned memory; the blocks start on a 64-byte line so that each block's impulses fill whole
	// lines (solver_types.h).
	int wideBytes = (int)sizeof(tbWideContactConstraint) * blockCount;
	int overflowBytes = (int)sizeof(int) * overflowCount;
	context->wideLocation = tbArenaAlloc(&context->world->stepArena, (int)sizeof(int) * n);
	context->wideMemoryBytes = tbMaxInt(wideBytes + overflowBytes, 1);
	context->wideMemory = tbArenaAlloc(&context->world->stepArena, context->wideMemoryBytes + 32);
	context->wideMemory = (void*)(((uintptr_t)context->wideMemory + 63) & ~(uintptr_t)63);
	context->wideConstraints = (tbWideContactConstraint*)context->wideMemory;
	context->wideCount = blockCount;
	context->overflowConstraints = (int*)((char*)context->wideMemory + wideBytes);
	context->overflowCount = 0;
	context->wideRolling = NULL;
	if (context->rollingCount > 0 && blockCount > 0)
	{
		// Zeroed: a lane without rolling resistance (and a padding lane) must hold 0 everywhere.
		int rollingBytes = (int)sizeof(tbWideRolling) * blockCount;
		context->wideRolling = tbArenaAlloc(&context->world->stepArena, rollingBytes);
		memset(context->wideRolling, 0, (size_t)rollingBytes);
	}
	context->colorCount = 0;
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		context->colorCount += counts[k] > 0 ? 1 : 0;
	}

	// Only the last block of a colour's partition can have padding lanes; the preparation
	// (contact_solver.c) then writes every field of each contact's lane.
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		for (int p = 0; p < partitions; ++p)
		{
			if (partitionCounts->n[k][p] % TB_SIMD_WIDTH != 0)
			{
				tbInitWideConstraint(context->wideConstraints + context->partitionBlockStart[k][p + 1] - 1, bodyCount);
			}
		}
	}
}

void tbReleaseColors(tbStepContext* context)
{
	if (context->wideMemory != NULL)
	{
		context->wideMemory = NULL; // step arena memory: released when the step ends
		context->wideLocation = NULL;
		context->locationById = NULL;
		context->wideConstraints = NULL;
		context->wideRolling = NULL;
		context->wideCount = 0;
		context->overflowCount = 0;
	}
}

// Joints. Gauss–Seidel in joint-id order sweeps a mechanism the way it was built (a ragdoll from
// the torso out, a chain link after link), passing a correction along the whole mechanism in one
// pass; in colour order the same joints take turns, and a correction advances a joint or two per
// pass: a pile of ragdolls that falls asleep in joint-id order does not in colour order
// (docs/methods.md, "Solve order of the joints"). So the joints are split by mechanism, the groups
// of awake dynamic bodies they join (union–find on the solver bodies):
// - small mechanisms (at most TB_JOINT_SMALL_GROUP joints: ragdolls, vehicles, chains, bridges)
//   keep joint-id order; they share no moving body with one another, so they run side by side on
//   the workers, a few whole mechanisms per unit (context->jointUnitStart);
// - the joints of larger ones (a mesh, a grid) are coloured like the contacts, in a graph of their
//   own: every pass solves all joints before the contacts (joint.c says why), so a joint and a
//   contact never run in the same stage and need not avoid each other's bodies. Colours let the
//   workers share the pass and let one worker overlap consecutive joints, where in joint-id order
//   each joint waits for the velocity the previous one stored. A mesh closes its loops by
//   iterating whatever the order, so there colour order holds its pins as joint-id order does.
// world->cache.solverJoints becomes: the small mechanisms, then colour after colour (joint-id order
// within each), then the joints that found no colour; the same order on any number of workers.
// Rejected, each with the same results and no faster step: sweeping the mechanisms of a unit joint
// by joint in turn (a ragdoll's joints wait on each other through its torso, another ragdoll's
// could run alongside); solving copies of the coloured joints laid out in solve order (the passes
// ran faster on a large grid, the copying cost more than that); joints aligned to cache lines.
#define TB_JOINT_SMALL_GROUP 64
#define TB_JOINTS_PER_MECHANISM_UNIT 16

/// Mechanism of each solver joint (a root solver body), and the joints per root.
static void tbFindMechanisms(const tbStepContext* context, int* parent, int* jointRoot, int* size)
{
	const tbWorld* world = context->world;
	int n = world->cache.solverJointCount;
	for (int i = 0; i <= context->bodyCount; ++i)
	{
		parent[i] = i;
		size[i] = 0;
	}
	for (int i = 0; i < n; ++i)
	{
		const tbJoint* joint = world->joints + world->cache.solverJoints[i];
		if (tbJointMovesA(joint) && tbJointMovesB(joint))
		{
			tbLinkRoots(parent, joint->indexA, joint->indexB);
		}
	}
	for (int i = 0; i < n; ++i)
	{
		const tbJoint* joint = world->joints + world->cache.solverJoints[i];
		jointRoot[i] = tbFindRoot(parent, tbJointMovesA(joint) ? joint->indexA : joint->indexB);
		size[jointRoot[i]] += 1;
	}
}

/// Units of whole small mechanisms, at least TB_JOINTS_PER_MECHANISM_UNIT joints each but the last.
static void tbPackMechanismUnits(tbStepContext* context, const int* orderedRoot, int small)
{
	context->jointSmallCount = small;
	if (small == 0)
	{
		return;
	}
	int* unitStart = tbArenaAlloc(&context->world->stepArena, (int)sizeof(int) * (small + 1));
	int units = 0;
	unitStart[units++] = 0;
	for (int i = 1; i < small; ++i)
	{
		if (orderedRoot[i] != orderedRoot[i - 1] && i - unitStart[units - 1] >= TB_JOINTS_PER_MECHANISM_UNIT)
		{
			unitStart[units++] = i;
		}
	}
	unitStart[units] = small;
	context->jointUnitStart = unitStart;
	context->jointUnitCount = units;
}

/// Joint trees (joint_tree.c) pay where a mechanism is mostly a tree: chains, ragdolls, bridges,
/// vehicles. Where loops are many (a mesh or a grid of joints: about one loop per tree joint)
/// Gauss–Seidel closes them anyway and the tree only adds its cost: on a 100 × 100 grid of
/// revolute joints the exact spanning tree narrowed the largest pin gap but made the step much
/// longer and took two more relaxing iterations (docs/methods.md). So a mechanism
/// gets trees when the joints closing loops in it are few: counted from its equality joints (the
/// rows a tree solves) as the cycle rank, E_inner − (V − 1) between its V bodies plus the ground
/// joints after the first, with a loop between bodies weighing twice a loop through ground (it
/// couples two tree paths), at most a quarter of the tree's joints. Equality joints that do not
/// connect the whole mechanism make the count low, never high: such a mechanism keeps its trees.
static void tbMarkLoopyMechanisms(const tbStepContext* context, int* parent, const int* jointRoot, const int* size)
{
	tbWorld* world = context->world;
	int n = world->cache.solverJointCount;
	int bodies = context->bodyCount + 1;
	tbArena* arena = &world->stepArena;
	int* bodyCount = tbArenaAlloc(arena, (int)sizeof(int) * bodies);
	int* inner = tbArenaAlloc(arena, (int)sizeof(int) * bodies);
	int* ground = tbArenaAlloc(arena, (int)sizeof(int) * bodies);
	memset(bodyCount, 0, sizeof(int) * (size_t)bodies);
	memset(inner, 0, sizeof(int) * (size_t)bodies);
	memset(ground, 0, sizeof(int) * (size_t)bodies);
	for (int i = 0; i < context->bodyCount; ++i)
	{
		int root = tbFindRoot(parent, i);
		bodyCount[root] += size[root] > 0 ? 1 : 0;
	}
	for (int i = 0; i < n; ++i)
	{
		const tbJoint* joint = world->joints + world->cache.solverJoints[i];
		if (tbJointEqualityRowCount(joint) > 0)
		{
			bool both = tbJointMovesA(joint) && tbJointMovesB(joint);
			inner[jointRoot[i]] += both ? 1 : 0;
			ground[jointRoot[i]] += both ? 0 : 1;
		}
	}
	for (int i = 0; i < n; ++i)
	{
		int root = jointRoot[i];
		int treeJoints = bodyCount[root] - 1 + (ground[root] > 0 ? 1 : 0);
		int innerLoops = tbMaxInt(inner[root] - (bodyCount[root] - 1), 0);
		int groundLoops = tbMaxInt(ground[root] - 1, 0);
		world->joints[world->cache.solverJoints[i]].loopyMechanism = 4 * innerLoops + 2 * groundLoops > treeJoints;
	}
}

// The joints' solve order depends only on which joints are prepared, their solver bodies, which
// sides move and how many equality rows each has (the loop count of its mechanism). Those rarely
// change from one step to the next (a grid or a chain that stays awake), so the order of the last
// step is kept with a 64-bit fingerprint of its inputs and reused when the fingerprint matches:
// a union–find and a colouring of every joint each step (a large grid of joints pays for both)
// become one pass over the joints and a copy. A different fingerprint recomputes; nothing else
// decides.
typedef struct tbJointOrderCache
{
	uint64_t fingerprint;
	int count;			  ///< joints ordered; 0: nothing kept
	int capacity;		  ///< of ordered and loopy
	int* ordered;		  ///< world->cache.solverJoints after ordering
	uint8_t* loopy;		  ///< tbJoint::loopyMechanism of each, in that order
	int* unitStart;		  ///< jointUnitCount + 1 entries (capacity + 1 allocated)
	int unitCount, smallCount, colorCount, treeCandidates;
	bool overflow;
	bool noTrees; ///< the tree build found no tree and no rigid pin for this fingerprint
	int colorStart[TB_GRAPH_COLOR_COUNT + 2];
} tbJointOrderCache;

/// One word into a stream of the fingerprint: for a given h, distinct words give distinct results.
static inline uint64_t tbMixFingerprint(uint64_t h, uint64_t value)
{
	h = (h ^ value) * 0x9E3779B97F4A7C15ull;
	return h ^ (h >> 29);
}

/// A joint's share of the fingerprint: its id, solver bodies, which sides move, its equality rows
/// and kind, and the inverse masses (which decide the trees that need an exact solve, joint_tree.c:
/// the tree build's verdict is kept under this fingerprint), mixed into h.
static inline uint64_t tbMixJoint(uint64_t h, const tbWorld* world, int jointId)
{
	const tbJoint* joint = world->joints + jointId;
	uint32_t bits = (tbJointMovesA(joint) ? 1u : 0u) | (tbJointMovesB(joint) ? 2u : 0u) |
					((uint32_t)tbJointEqualityRowCount(joint) << 2) | ((uint32_t)joint->type << 4);
	uint32_t massA, massB;
	memcpy(&massA, &joint->invMassA, sizeof(massA));
	memcpy(&massB, &joint->invMassB, sizeof(massB));
	h = tbMixFingerprint(h, (uint64_t)(uint32_t)jointId | (uint64_t)(uint32_t)joint->indexA << 32);
	h = tbMixFingerprint(h, (uint64_t)(uint32_t)joint->indexB | (uint64_t)bits << 32);
	return tbMixFingerprint(h, (uint64_t)massA | (uint64_t)massB << 32);
}

// The joints are mixed into four streams, joint i into stream i mod 4, joined at the end: each mix
// waits on the multiply before it, and in one stream that chain through every joint was the
// longest part of ordering a large grid's joints; four streams run side by side.
static uint64_t tbJointOrderFingerprint(const tbStepContext* context)
{
	const tbWorld* world = context->world;
	const int* joints = world->cache.solverJoints;
	int n = world->cache.solverJointCount;
	uint64_t h = tbMixFingerprint(0x243F6A8885A308D3ull, (uint64_t)(uint32_t)n | (uint64_t)(uint32_t)context->bodyCount << 32);
	h = tbMixFingerprint(h, world->def.enableJointTrees ? 1u : 0u);
	uint64_t s0 = h, s1 = h ^ 0x13198A2E03707344ull, s2 = h ^ 0xA4093822299F31D0ull, s3 = h ^ 0x082EFA98EC4E6C89ull;
	int i = 0;
	for (; i + 4 <= n; i += 4)
	{
		s0 = tbMixJoint(s0, world, joints[i]);
		s1 = tbMixJoint(s1, world, joints[i + 1]);
		s2 = tbMixJoint(s2, world, joints[i + 2]);
		s3 = tbMixJoint(s3, world, joints[i + 3]);
	}
	for (; i < n; ++i)
	{
		s0 = tbMixJoint(s0, world, joints[i]);
	}
	return tbMixFingerprint(tbMixFingerprint(tbMixFingerprint(s0, s1), s2), s3);
}

static bool tbReuseJointOrder(tbStepContext* context, uint64_t fingerprint)
{
	tbWorld* world = context->world;
	const tbJointOrderCache* cache = world->cache.jointOrderCache;
	int n = world->cache.solverJointCount;
	if (cache == NULL || cache->count != n || cache->fingerprint != fingerprint)
	{
		return false;
	}
	memcpy(world->cache.solverJoints, cache->ordered, sizeof(int) * (size_t)n);
	for (int i = 0; i < n; ++i)
	{
		world->joints[cache->ordered[i]].loopyMechanism = cache->loopy[i] != 0;
	}
	context->jointSmallCount = cache->smallCount;
	context->jointUnitCount = cache->unitCount;
	context->jointUnitStart = cache->unitCount > 0 ? cache->unitStart : NULL;
	context->jointColorCount = cache->colorCount;
	context->jointOverflow = cache->overflow;
	context->jointTreeCandidates = cache->treeCandidates;
	context->jointTreesKnownAbsent = cache->noTrees;
	memcpy(context->jointColorStart, cache->colorStart, sizeof(cache->colorStart));
	return true;
}

static void tbKeepJointOrder(const tbStepContext* context, uint64_t fingerprint)
{
	tbWorld* world = context->world;
	int n = world->cache.solverJointCount;
	if (world->cache.jointOrderCache == NULL)
	{
		world->cache.jointOrderCache = tbAlloc((int)sizeof(tbJointOrderCache));
		memset(world->cache.jointOrderCache, 0, sizeof(tbJointOrderCache));
	}
	tbJointOrderCache* cache = world->cache.jointOrderCache;
	if (n > cache->capacity)
	{
		tbDestroyJointOrderCache(world);
		world->cache.jointOrderCache = tbAlloc((int)sizeof(tbJointOrderCache));
		memset(world->cache.jointOrderCache, 0, sizeof(tbJointOrderCache));
		cache = world->cache.jointOrderCache;
		cache->capacity = n;
		cache->ordered = tbAlloc((int)sizeof(int) * n);
		cache->loopy = tbAlloc(n);
		cache->unitStart = tbAlloc((int)sizeof(int) * (n + 1));
	}
	cache->fingerprint = fingerprint;
	cache->count = n;
	memcpy(cache->ordered, world->cache.solverJoints, sizeof(int) * (size_t)n);
	for (int i = 0; i < n; ++i)
	{
		cache->loopy[i] = world->joints[world->cache.solverJoints[i]].loopyMechanism ? 1 : 0;
	}
	cache->smallCount = context->jointSmallCount;
	cache->unitCount = context->jointUnitCount;
	if (context->jointUnitCount > 0)
	{
		memcpy(cache->unitStart, context->jointUnitStart, sizeof(int) * (size_t)(context->jointUnitCount + 1));
	}
	cache->colorCount = context->jointColorCount;
	cache->overflow = context->jointOverflow;
	cache->treeCandidates = context->jointTreeCandidates;
	cache->noTrees = false;
	memcpy(cache->colorStart, context->jointColorStart, sizeof(cache->colorStart));
}

void tbNoteJointTrees(tbStepContext* context, bool none)
{
	tbJointOrderCache* cache = context->world->cache.jointOrderCache;
	if (cache != NULL && cache->count == context->world->cache.solverJointCount)
	{
		cache->noTrees = none;
	}
}

void tbDestroyJointOrderCache(tbWorld* world)
{
	tbJointOrderCache* cache = world->cache.jointOrderCache;
	if (cache == NULL)
	{
		return;
	}
	if (cache->capacity > 0)
	{
		tbFree(cache->ordered, (int)sizeof(int) * cache->capacity);
		tbFree(cache->loopy, cache->capacity);
		tbFree(cache->unitStart, (int)sizeof(int) * (cache->capacity + 1));
	}
	tbFree(cache, (int)sizeof(tbJointOrderCache));
	world->cache.jointOrderCache = NULL;
}

static void tbComputeJointOrder(tbStepContext* context);

void tbColorJoints(tbStepContext* context)
{
	tbWorld* world = context->world;
	int n = world->cache.solverJointCount;
	context->jointColorCount = 0;
	context->jointOverflow = false;
	context->jointUnitCount = 0;
	context->jointSmallCount = 0;
	context->jointTreeCandidates = 0;
	if (n == 0)
	{
		return;
	}
	uint64_t fingerprint = tbJointOrderFingerprint(context);
	if (tbReuseJointOrder(context, fingerprint))
	{
		return;
	}
	tbComputeJointOrder(context);
	// What joint_tree.c can root a tree at: without any, it skips its walks over the joints.
	context->jointTreeCandidates = 0;
	for (int i = 0; i < n; ++i)
	{
		const tbJoint* joint = world->joints + world->cache.solverJoints[i];
		context->jointTreeCandidates += joint->loopyMechanism == false && tbJointEqualityRowCount(joint) > 0 ? 1 : 0;
	}
	tbKeepJointOrder(context, fingerprint);
}

// The order from scratch (see above tbColorJoints).
static void tbComputeJointOrder(tbStepContext* context)
{
	tbWorld* world = context->world;
	int n = world->cache.solverJointCount;
	tbArena* arena = &world->stepArena;
	int bodies = context->bodyCount + 1;
	int* parent = tbArenaAlloc(arena, (int)sizeof(int) * bodies);
	int* size = tbArenaAlloc(arena, (int)sizeof(int) * bodies);
	int* jointRoot = tbArenaAlloc(arena, (int)sizeof(int) * n);
	uint32_t* bodyMasks = tbArenaAlloc(arena, (int)sizeof(uint32_t) * bodies);
	uint8_t* colors = tbArenaAlloc(arena, n);
	int* ordered = tbArenaAlloc(arena, (int)sizeof(int) * n);
	int* orderedRoot = tbArenaAlloc(arena, (int)sizeof(int) * n);
	tbFindMechanisms(context, parent, jointRoot, size);
	if (world->def.enableJointTrees)
	{
		tbMarkLoopyMechanisms(context, parent, jointRoot, size);
	}
	memset(bodyMasks, 0, sizeof(uint32_t) * (size_t)bodies);

	// Small mechanisms: each root's slot in order of its first joint (parent[] is reused for the
	// slot, size[] for the running offset). Large ones: first-fit colours.
	int counts[TB_GRAPH_COLOR_COUNT + 1] = {0};
	int small = 0;
	const uint32_t allColors = (1u << TB_GRAPH_COLOR_COUNT) - 1u;
	for (int i = 0; i < n; ++i)
	{
		int root = jointRoot[i];
		if (size[root] <= TB_JOINT_SMALL_GROUP)
		{
			if (size[root] > 0)
			{
				int count = size[root];
				size[root] = -small - 1; // from now on: −(offset of its next joint) − 1
				small += count;
			}
			ordered[-size[root] - 1] = world->cache.solverJoints[i];
			orderedRoot[-size[root] - 1] = root;
			size[root] -= 1;
			colors[i] = 0xFF;
			continue;
		}
		const tbJoint* joint = world->joints + world->cache.solverJoints[i];
		bool movesA = tbJointMovesA(joint), movesB = tbJointMovesB(joint);
		uint32_t used = (movesA ? bodyMasks[joint->indexA] : 0u) | (movesB ? bodyMasks[joint->indexB] : 0u);
		uint32_t available = ~used & allColors;
		int k = available != 0u ? tbLowestSetBit(available) : TB_GRAPH_COLOR_COUNT;
		if (k < TB_GRAPH_COLOR_COUNT)
		{
			bodyMasks[joint->indexA] |= movesA ? 1u << k : 0u;
			bodyMasks[joint->indexB] |= movesB ? 1u << k : 0u;
		}
		colors[i] = (uint8_t)k;
		counts[k] += 1;
	}
	tbPackMechanismUnits(context, orderedRoot, small);

	// First fit fills colours from 0 up, so the colours in use are 0 … m − 1; the overflow follows.
	int groups = 0, start = small;
	int offsets[TB_GRAPH_COLOR_COUNT + 1];
	for (int k = 0; k <= TB_GRAPH_COLOR_COUNT; ++k)
	{
		offsets[k] = start;
		if (counts[k] > 0)
		{
			context->jointColorStart[groups++] = start;
			start += counts[k];
		}
	}
	context->jointColorStart[groups] = n;
	context->jointColorCount = groups;
	context->jointOverflow = counts[TB_GRAPH_COLOR_COUNT] > 0;
	for (int i = 0; i < n; ++i)
	{
		if (colors[i] != 0xFF)
		{
			ordered[offsets[colors[i]]++] = world->cache.solverJoints[i];
		}
	}
	memcpy(world->cache.solverJoints, ordered, sizeof(int) * (size_t)n);
}
