// Broad-phase micro-benchmark: milliseconds per step for the tree, sort-and-sweep, the spatial hash
// and brute force on 1k–64k moving boxes, in four mixes: uniform (1 m boxes, one per 4 m²), mixed
// (0.2–2 m, a factor 10), wide (0.1–10 m, a factor 100: where a grid suffers) and sparse (1 m boxes,
// one per 400 m²: mostly empty space).
//
// Each step moves every box a little (random velocity, bouncing in a square whose area grows with
// the body count so the density stays constant) and, as a world does, re-sends a box to the
// broad phase only when its tight box leaves its fat box (tight box grown by TB_AABB_MARGIN).
// The time covers those moves and UpdatePairs. Brute force runs up to 16k bodies.
//
// Output: a human-readable table, then CSV lines "method,bodies,sizes,ms_per_step".
#include "broad_phase/broad_phase.h"

#include <stdio.h>
#include <string.h>

static uint32_t s_seed = 1u;

// Linear congruential generator (Numerical Recipes, §7.1).
static float RandomFloat(float lower, float upper)
{
	s_seed = 1664525u * s_seed + 1013904223u;
	return lower + (upper - lower) * (float)(s_seed >> 8) / 16777216.0f;
}

typedef struct Body
{
	tbAABB tight;
	tbAABB fat;
	tbVec2 velocity;
	int key;
} Body;

#define MAX_BODIES 65536
static Body s_bodies[MAX_BODIES];

typedef struct Result
{
	const char* method;
	int bodies;
	const char* sizes;
	float msPerStep;
} Result;

#define MAX_RESULTS 128
static Result s_results[MAX_RESULTS];
static int s_resultCount;

static const char* MethodName(tbBroadPhaseMethod method)
{
	switch (method)
	{
		case tb_broadPhaseTree:
			return "tree";
		case tb_broadPhaseSortAndSweep:
			return "sort_and_sweep";
		case tb_broadPhaseSpatialHash:
			return "spatial_hash";
		default:
			return "brute_force";
	}
}

typedef enum Mix
{
	mixUniform,
	mixMixed,
	mixWide,
	mixSparse,
	mixCount
} Mix;

static const char* const s_mixNames[mixCount] = {"uniform", "mixed", "wide", "sparse"};

static float RandomSize(Mix mix)
{
	switch (mix)
	{
		case mixMixed:
			return RandomFloat(0.2f, 2.0f);
		case mixWide:
			return RandomFloat(0.1f, 1.0f) * (RandomFloat(0.0f, 1.0f) < 0.1f ? 10.0f : 1.0f);
		default:
			return 1.0f;
	}
}

static void CreateBodies(tbBroadPhase* bp, int count, Mix mix, float halfWidth)
{
	s_seed = 12345u;
	for (int i = 0; i < count; ++i)
	{
		float w = RandomSize(mix);
		float h = RandomSize(mix);
		float x = RandomFloat(-halfWidth, halfWidth - w), y = RandomFloat(-halfWidth, halfWidth - h);
		Body* b = s_bodies + i;
		b->tight = (tbAABB){{x, y}, {x + w, y + h}};
		b->fat = tbAABB_Fatten(b->tight, TB_AABB_MARGIN);
		b->velocity = (tbVec2){RandomFloat(-3.0f, 3.0f), RandomFloat(-3.0f, 3.0f)};
		b->key = tbBroadPhase_CreateProxy(bp, b->fat, 1, i, tb_proxyMovable);
	}
}

static void MoveBodies(tbBroadPhase* bp, int count, float halfWidth)
{
	const float dt = 1.0f / 60.0f;
	for (int i = 0; i < count; ++i)
	{
		Body* b = s_bodies + i;
		tbVec2 d = tbMulSV(dt, b->velocity);
		b->tight.lowerBound = tbAdd(b->tight.lowerBound, d);
		b->tight.upperBound = tbAdd(b->tight.upperBound, d);
		if (b->tight.lowerBound.x < -halfWidth || b->tight.upperBound.x > halfWidth)
		{
			b->velocity.x = -b->velocity.x;
		}
		if (b->tight.lowerBound.y < -halfWidth || b->tight.upperBound.y > halfWidth)
		{
			b->velocity.y = -b->velocity.y;
		}
		if (tbAABB_Contains(b->fat, b->tight) == false)
		{
			b->fat = tbAABB_Fatten(b->tight, TB_AABB_MARGIN);
			tbBroadPhase_MoveProxy(bp, b->key, b->fat);
		}
	}
}

/// Time `steps` steps after a warm-up of 10 (first sort, static rebuild, allocation growth).
static float RunCase(tbBroadPhaseMethod method, int count, Mix mix, int steps, int* pairCount)
{
	// Density: one body per 4 m² (sparse: per 400 m²), so the square's side is 2·sqrt(count) m (20·).
	float area = (mix == mixSparse ? 400.0f : 4.0f) * (float)count;
	float halfWidth = 1.0f;
	while (4.0f * halfWidth * halfWidth < area)
	{
		halfWidth *= 1.05f;
	}
	tbBroadPhase bp;
	tbBroadPhase_Create(&bp, method);
	CreateBodies(&bp, count, mix, halfWidth);
	for (int i = 0; i < 10; ++i)
	{
		MoveBodies(&bp, count, halfWidth);
		tbBroadPhase_UpdatePairs(&bp);
	}
	uint64_t start = tbGetTicks();
	for (int i = 0; i < steps; ++i)
	{
		MoveBodies(&bp, count, halfWidth);
		tbBroadPhase_UpdatePairs(&bp);
	}
	float ms = tbGetMilliseconds(start) / (float)steps;
	*pairCount = bp.pairList.count;
	tbBroadPhase_Destroy(&bp);
	return ms;
}

int main(void)
{
	const int counts[] = {1000, 4000, 16000, 64000};
	const tbBroadPhaseMethod methods[] = {tb_broadPhaseTree, tb_broadPhaseSortAndSweep, tb_broadPhaseSpatialHash,
										  tb_broadPhaseBruteForce};
	printf("%-15s %7s %7s %12s %8s\n", "method", "bodies", "sizes", "ms/step", "pairs");
	for (int s = 0; s < mixCount; ++s)
	{
		for (int c = 0; c < 4; ++c)
		{
			for (int m = 0; m < 4; ++m)
			{
				if (methods[m] == tb_broadPhaseBruteForce && counts[c] > 16000)
				{
					continue; // O(n²): 2·10⁹ tests per step at 64k
				}
				int steps = counts[c] >= 16000 ? 20 : 100;
				int pairs = 0;
				float ms = RunCase(methods[m], counts[c], (Mix)s, steps, &pairs);
				const char* sizes = s_mixNames[s];
				printf("%-15s %7d %7s %12.3f %8d\n", MethodName(methods[m]), counts[c], sizes, (double)ms, pairs);
				fflush(stdout);
				s_results[s_resultCount++] = (Result){MethodName(methods[m]), counts[c], sizes, ms};
			}
		}
	}
	printf("\nmethod,bodies,sizes,ms_per_step\n");
	for (int i = 0; i < s_resultCount; ++i)
	{
		printf("%s,%d,%s,%.4f\n", s_results[i].method, s_results[i].bodies, s_results[i].sizes,
			   (double)s_results[i].msPerStep);
	}
	return 0;
}
