// Broad-phase micro-benchmark: milliseconds per step for the tree, sort-and-sweep, the spatial hash
// and brute force on 1k–64k moving boxes, in four mixes: uniform (1 m boxes, one per 4 m²), mixed
// (0.2–2 m, a factor 10), wide (0.1–10 m, a factor 100: where a grid suffers) and sparse (1 m boxes,
// one per 400 m²: mostly empty space).
//
// Each step moves every box a little (random velocity, bouncing in a square whose area grows with
// the body count so the density stays constant) and, as a world does, re-sends a box to the
// broad phase only when its tight box leaves its fat box (tight box grown by TB_AABB_MARGIN).
// The time covers those moves and UpdatePairs, the best of ROUNDS rounds in which the methods
// take turns. Brute force runs up to 16k bodies.
//
// Built with the Box2D v3 peer (bench/peers.cmake), a fifth method, box2d3_tree, runs Box2D v3's
// own b2DynamicTree on the same moves as a v3 world keeps its tree of moving proxies (peers.h,
// PeerTree: a re-made box enlarges its leaf, the pair update queries every moved box and then
// rebuilds the enlarged part of the tree). It finds the same pairs as Tumble's methods.
//
// Output: a human-readable table, then CSV lines "method,bodies,sizes,ms_per_step".
#include "broad_phase/broad_phase.h"

#ifdef TUMBLE_HAVE_BOX2D3
#include "peers.h"
#endif

#include <stdio.h>
#include <string.h>

static uint32_t s_seed = 1u;

// Linear congruential generator (Numerical Recipes, §7.1).
static float RandomFloat(float lower, float upper)
{
	s_seed = 1664525u * s_seed + 1013904223u;
	return lower + (upper - lower) * (float)(s_seed >> 8) / 16777216.0f;
}

// A method: one of Tumble's four through tbBroadPhase, or Box2D v3's tree (method == methodBox2D3).
#define methodBox2D3 ((tbBroadPhaseMethod)100)

typedef struct Broad
{
	tbBroadPhaseMethod method;
	tbBroadPhase bp;
#ifdef TUMBLE_HAVE_BOX2D3
	PeerTree* peer;
#endif
} Broad;

static void Broad_Create(Broad* broad, tbBroadPhaseMethod method, int capacity)
{
	broad->method = method;
#ifdef TUMBLE_HAVE_BOX2D3
	if (method == methodBox2D3)
	{
		broad->peer = PeerBox2D3_CreateTree(capacity);
		return;
	}
#endif
	(void)capacity;
	tbBroadPhase_Create(&broad->bp, method);
}

static int Broad_CreateProxy(Broad* broad, tbAABB fat, int index)
{
#ifdef TUMBLE_HAVE_BOX2D3
	if (broad->method == methodBox2D3)
	{
		return PeerBox2D3_TreeCreateProxy(broad->peer, fat);
	}
#endif
	return tbBroadPhase_CreateProxy(&broad->bp, fat, 1, index, tb_proxyMovable);
}

static void Broad_MoveProxy(Broad* broad, int key, tbAABB fat)
{
#ifdef TUMBLE_HAVE_BOX2D3
	if (broad->method == methodBox2D3)
	{
		PeerBox2D3_TreeMoveProxy(broad->peer, key, fat);
		return;
	}
#endif
	tbBroadPhase_MoveProxy(&broad->bp, key, fat);
}

/// The pair update; returns the number of pairs it reported.
static int Broad_UpdatePairs(Broad* broad)
{
#ifdef TUMBLE_HAVE_BOX2D3
	if (broad->method == methodBox2D3)
	{
		return PeerBox2D3_TreeUpdatePairs(broad->peer);
	}
#endif
	tbBroadPhase_UpdatePairs(&broad->bp);
	return broad->bp.pairList.count;
}

static void Broad_Destroy(Broad* broad)
{
#ifdef TUMBLE_HAVE_BOX2D3
	if (broad->method == methodBox2D3)
	{
		PeerBox2D3_DestroyTree(broad->peer);
		return;
	}
#endif
	tbBroadPhase_Destroy(&broad->bp);
}

typedef struct Body
{
	tbAABB tight;
	tbAABB fat;
	tbVec2 velocity;
	int key;
} Body;

#define MAX_BODIES 65536
#define ROUNDS 3 ///< rounds of every case; the best time of each method is reported
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
	if (method == methodBox2D3)
	{
		return "box2d3_tree";
	}
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

static void CreateBodies(Broad* bp, int count, Mix mix, float halfWidth)
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
		b->key = Broad_CreateProxy(bp, b->fat, i);
	}
}

static void MoveBodies(Broad* bp, int count, float halfWidth)
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
			Broad_MoveProxy(bp, b->key, b->fat);
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
	Broad bp;
	Broad_Create(&bp, method, count);
	CreateBodies(&bp, count, mix, halfWidth);
	for (int i = 0; i < 10; ++i)
	{
		MoveBodies(&bp, count, halfWidth);
		Broad_UpdatePairs(&bp);
	}
	uint64_t start = tbGetTicks();
	int pairs = 0;
	for (int i = 0; i < steps; ++i)
	{
		MoveBodies(&bp, count, halfWidth);
		pairs = Broad_UpdatePairs(&bp);
	}
	float ms = tbGetMilliseconds(start) / (float)steps;
	*pairCount = pairs;
	Broad_Destroy(&bp);
	return ms;
}

int main(void)
{
	const int counts[] = {1000, 4000, 16000, 64000};
	const tbBroadPhaseMethod methods[] = {tb_broadPhaseTree, tb_broadPhaseSortAndSweep, tb_broadPhaseSpatialHash,
										  tb_broadPhaseBruteForce,
#ifdef TUMBLE_HAVE_BOX2D3
										  methodBox2D3
#endif
	};
	const int methodCount = (int)(sizeof(methods) / sizeof(methods[0]));
	printf("%-15s %7s %7s %12s %8s\n", "method", "bodies", "sizes", "ms/step", "pairs");
	for (int s = 0; s < mixCount; ++s)
	{
		for (int c = 0; c < 4; ++c)
		{
			// Rounds with the methods in turn, the best of each kept: on a shared machine a burst
			// of load then falls on one round of every method rather than on one method.
			float best[8];
			int pairs[8] = {0};
			for (int m = 0; m < methodCount; ++m)
			{
				best[m] = 1e30f;
			}
			for (int round = 0; round < ROUNDS; ++round)
			{
				for (int m = 0; m < methodCount; ++m)
				{
					if (methods[m] == tb_broadPhaseBruteForce && counts[c] > 16000)
					{
						continue; // O(n²): 2·10⁹ tests per step at 64k
					}
					int steps = counts[c] >= 16000 ? 20 : 100;
					float ms = RunCase(methods[m], counts[c], (Mix)s, steps, pairs + m);
					best[m] = ms < best[m] ? ms : best[m];
				}
			}
			for (int m = 0; m < methodCount; ++m)
			{
				if (methods[m] == tb_broadPhaseBruteForce && counts[c] > 16000)
				{
					continue;
				}
				const char* sizes = s_mixNames[s];
				printf("%-15s %7d %7s %12.3f %8d\n", MethodName(methods[m]), counts[c], sizes, (double)best[m], pairs[m]);
				fflush(stdout);
				s_results[s_resultCount++] = (Result){MethodName(methods[m]), counts[c], sizes, best[m]};
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
