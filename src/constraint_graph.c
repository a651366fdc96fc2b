// Graph colouring of the contact constraints, for the wide solver (contact_solver_wide.c).
//
// Two constraints that share a body that moves cannot be solved at the same time: each reads the
// body's velocity that the other writes. Colouring the constraint graph (constraints are vertices,
// an edge joins two constraints on a common moving body) splits the constraints into sets in
// which no moving body appears twice; the constraints of one colour are then independent, and
// four of them can be solved at once in the lanes of a wide float, with exactly the result of
// solving them one after another in any order. Static, kinematic and sleeping bodies do not move
// in the solve (infinite mass: the solver writes back the velocity it read), so they do not take
// a colour: a ground box touching a hundred boxes costs nothing here.
//
// Greedy first fit, one pass: each body keeps a bit mask of the colours its constraints already
// took; a constraint takes the lowest colour free in both masks, found with one OR and a count of
// trailing zeros. Greedy colouring needs at most (largest degree + 1) colours; measured on the
// benchmark scenes: at most 9 on the pyramids, 11 on the tumbler, none overflowing. Constraints that find no free colour among
// TB_GRAPH_COLOR_COUNT (very crowded bodies: a body with many small neighbours) go to an overflow
// list that the scalar solver handles after the colours.
//
// Order. Gauss–Seidel results depend on the order, and the order here is colour by colour,
// within a colour the island stage's order (a hash of the contact id, island.c). Colouring in
// that scattered order makes each colour a scattered set, not a sweep across the structure; the
// measurements behind this choice are in island.c and docs/methods.md.
//
// The colours are recomputed every step from scratch (colouring and packing together cost about
// 2 % of a tumbler step, perf), so nothing has to be kept consistent when contacts begin and end
// (Box2D v3 keeps them persistent instead).
// Reference: the graph colouring used by Box2D v3's solver (Catto, "Solver2D" and "SIMD
// matters" blog posts, 2024).
#include "constraint_graph.h"

#include "contact_solver.h"

#include <string.h>

static inline int tbLowestSetBit(uint32_t x)
{
#if defined(__GNUC__) || defined(__clang__)
	return __builtin_ctz(x);
#else
	int n = 0;
	while ((x & 1u) == 0u)
	{
		x >>= 1;
		n += 1;
	}
	return n;
#endif
}

// A body takes part in colouring when the constraint can change its velocity.
static inline bool tbMovesA(const tbContactConstraint* c)
{
	return c->invMassA > 0.0f || c->invIA > 0.0f;
}

static inline bool tbMovesB(const tbContactConstraint* c)
{
	return c->invMassB > 0.0f || c->invIB > 0.0f;
}

// Colour of each constraint (or TB_GRAPH_COLOR_COUNT for overflow); counts per colour.
static void tbAssignColors(const tbStepContext* context, uint32_t* bodyMasks, uint8_t* colors,
						   int counts[TB_GRAPH_COLOR_COUNT + 1])
{
	const uint32_t allColors = TB_GRAPH_COLOR_COUNT == 32 ? ~0u : ((1u << TB_GRAPH_COLOR_COUNT) - 1u);
	for (int i = 0; i < context->constraintCount; ++i)
	{
		const tbContactConstraint* c = context->constraints + i;
		bool movesA = tbMovesA(c);
		bool movesB = tbMovesB(c);
		uint32_t used = (movesA ? bodyMasks[c->indexA] : 0u) | (movesB ? bodyMasks[c->indexB] : 0u);
		uint32_t free = ~used & allColors;

		int color = TB_GRAPH_COLOR_COUNT;
		if (free != 0u)
		{
			color = tbLowestSetBit(free);
			uint32_t bit = 1u << color;
			if (movesA)
			{
				bodyMasks[c->indexA] |= bit;
			}
			if (movesB)
			{
				bodyMasks[c->indexB] |= bit;
			}
		}
		colors[i] = (uint8_t)color;
		counts[color] += 1;
	}
}

void tbColorConstraints(tbStepContext* context)
{
	int n = context->constraintCount;
	int bodyCount = context->bodyCount;
	int counts[TB_GRAPH_COLOR_COUNT + 1] = {0};

	int maskBytes = (int)sizeof(uint32_t) * (bodyCount + 1);
	int colorBytes = n;
	int scratchBytes = maskBytes + colorBytes;
	char* scratch = tbArenaAlloc(&context->world->stepArena, scratchBytes);
	uint32_t* bodyMasks = (uint32_t*)scratch;
	uint8_t* colors = (uint8_t*)(scratch + maskBytes);
	memset(bodyMasks, 0, (size_t)maskBytes);
	tbAssignColors(context, bodyMasks, colors, counts);

	// Blocks of TB_SIMD_WIDTH lanes, colour after colour; the last block of a colour is padded.
	int* blockStart = context->colorBlockStart;
	int blockCount = 0;
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		blockStart[k] = blockCount;
		blockCount += (counts[k] + TB_SIMD_WIDTH - 1) / TB_SIMD_WIDTH;
	}
	blockStart[TB_GRAPH_COLOR_COUNT] = blockCount;
	int overflowCount = counts[TB_GRAPH_COLOR_COUNT];

	// One piece of the step arena: wide blocks, then the overflow list. The arena hands out
	// 32-byte aligned memory, enough for the 16-byte wide floats.
	int wideBytes = (int)sizeof(tbWideContactConstraint) * blockCount;
	int overflowBytes = (int)sizeof(int) * overflowCount;
	context->wideLocation = tbArenaAlloc(&context->world->stepArena, (int)sizeof(int) * n);
	context->wideMemoryBytes = tbMaxInt(wideBytes + overflowBytes, 1);
	context->wideMemory = tbArenaAlloc(&context->world->stepArena, context->wideMemoryBytes);
	context->wideConstraints = (tbWideContactConstraint*)context->wideMemory;
	context->wideCount = blockCount;
	context->overflowConstraints = (int*)((char*)context->wideMemory + wideBytes);
	context->overflowCount = 0;
	context->colorCount = 0;
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		context->colorCount += counts[k] > 0 ? 1 : 0;
	}

	// Only the last block of a colour can have padding lanes; packing writes every field of a lane.
	int filled[TB_GRAPH_COLOR_COUNT] = {0};
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		if (counts[k] % TB_SIMD_WIDTH != 0)
		{
			tbInitWideConstraint(context->wideConstraints + blockStart[k + 1] - 1, bodyCount);
		}
	}
	for (int i = 0; i < n; ++i)
	{
		int k = colors[i];
		if (k == TB_GRAPH_COLOR_COUNT)
		{
			context->overflowConstraints[context->overflowCount++] = i;
			context->wideLocation[i] = -1;
			continue;
		}
		int slot = filled[k]++;
		int location = blockStart[k] * TB_SIMD_WIDTH + slot;
		context->wideLocation[i] = location;
		tbPackWideLane(context->wideConstraints + location / TB_SIMD_WIDTH, location % TB_SIMD_WIDTH,
					   context->constraints + i, i);
	}
}

void tbReleaseColors(tbStepContext* context)
{
	if (context->wideMemory != NULL)
	{
		context->wideMemory = NULL; // step arena memory: released when the step ends
		context->wideLocation = NULL;
		context->wideConstraints = NULL;
		context->wideCount = 0;
		context->overflowCount = 0;
	}
}
