// Narrow-phase micro-benchmark: nanoseconds per pair for the SAT manifold (manifold.c) against
// the GJK/EPA manifold (manifold_gjk.c) on polygon pairs, and for the circle–polygon closed form
// against a GJK-based separation, for reference. Configurations are generated up front with a
// fixed seed (from touching to deep overlap, random hulls and rotations) so both methods see the
// same pairs and generation is not timed. Output: CSV lines "pair,method,ns_per_pair,touching".

#include "tumble/collision.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PAIR_COUNT 4096
#define REPEATS 50

static uint32_t lcgState = 2024u;

static float randomFloat(float lower, float upper)
{
	lcgState = 1664525u * lcgState + 1013904223u;
	return lower + (upper - lower) * (float)(lcgState >> 8) * (1.0f / 16777216.0f);
}

static tbPolygon randomPolygon(float size)
{
	for (;;)
	{
		tbVec2 points[TB_MAX_POLYGON_VERTICES];
		int count = 3 + (int)randomFloat(0.0f, 5.999f);
		for (int i = 0; i < count; ++i)
		{
			float angle = randomFloat(-TB_PI, TB_PI);
			float r = size * randomFloat(0.3f, 1.0f);
			points[i] = tbMakeVec2(r * cosf(angle), r * sinf(angle));
		}
		tbHull hull = tbComputeHull(points, count);
		if (hull.count >= 3)
		{
			return tbMakePolygon(&hull, 0.0f);
		}
	}
}

typedef struct PolygonPair
{
	tbPolygon a, b;
	tbTransform xfA, xfB;
} PolygonPair;

typedef struct CirclePolygonPair
{
	tbPolygon polygon;
	tbCircle circle;
	tbTransform xfA, xfB;
} CirclePolygonPair;

// Centres 0.6 to 1.9 polygon radii apart: from deep overlap to just apart.
static void makePairs(PolygonPair* pairs, CirclePolygonPair* circles)
{
	for (int i = 0; i < PAIR_COUNT; ++i)
	{
		float size = randomFloat(0.2f, 2.0f);
		pairs[i].a = randomPolygon(size);
		pairs[i].b = randomPolygon(size);
		pairs[i].xfA = (tbTransform){{randomFloat(-50.0f, 50.0f), randomFloat(-50.0f, 50.0f)}, tbMakeRot(randomFloat(-TB_PI, TB_PI))};
		tbVec2 u = tbRotateVector(tbMakeRot(randomFloat(-TB_PI, TB_PI)), tbMakeVec2(1.0f, 0.0f));
		pairs[i].xfB = (tbTransform){tbMulAdd(pairs[i].xfA.p, size * randomFloat(0.6f, 1.9f), u), tbMakeRot(randomFloat(-TB_PI, TB_PI))};

		circles[i].polygon = pairs[i].a;
		circles[i].circle = (tbCircle){{0.0f, 0.0f}, 0.5f * size};
		circles[i].xfA = pairs[i].xfA;
		circles[i].xfB = (tbTransform){tbMulAdd(pairs[i].xfA.p, size * randomFloat(0.6f, 1.6f), u), tbRot_identity};
	}
}

// start: tbGetTicks() before the loop; tbGetMilliseconds gives the time elapsed since then
static void report(const char* pair, const char* method, uint64_t start, int touching)
{
	double ns = 1.0e6 * (double)tbGetMilliseconds(start) / ((double)PAIR_COUNT * REPEATS);
	printf("%s,%s,%.1f,%d\n", pair, method, ns, touching);
}

static void benchPolygons(const PolygonPair* pairs, bool useGJK)
{
	int touching = 0;
	uint64_t start = tbGetTicks();
	for (int r = 0; r < REPEATS; ++r)
	{
		for (int i = 0; i < PAIR_COUNT; ++i)
		{
			const PolygonPair* p = &pairs[i];
			tbTransform xf = tbInvMulTransforms(p->xfA, p->xfB);
			tbLocalManifold m = useGJK ? tbCollidePolygonsGJK(&p->a, &p->b, xf) : tbCollidePolygons(&p->a, &p->b, xf);
			touching += m.pointCount > 0;
		}
	}
	report("polygon-polygon", useGJK ? "gjk-epa" : "sat", start, touching / REPEATS);
}

static void benchCirclePolygon(const CirclePolygonPair* pairs, bool useGJK)
{
	int touching = 0;
	uint64_t start = tbGetTicks();
	for (int r = 0; r < REPEATS; ++r)
	{
		for (int i = 0; i < PAIR_COUNT; ++i)
		{
			const CirclePolygonPair* p = &pairs[i];
			if (useGJK)
			{
				// reference only: separation and normal, no manifold assembly
				tbDistanceInput input = {0};
				input.proxyA = tbMakeProxy(p->polygon.vertices, p->polygon.count, p->polygon.radius);
				input.proxyB = tbMakeProxy(&p->circle.center, 1, p->circle.radius);
				input.transform = tbInvMulTransforms(p->xfA, p->xfB);
				tbSeparationOutput s = tbShapeSeparation(&input, NULL);
				touching += s.separation < TB_SPECULATIVE_DISTANCE;
			}
			else
			{
				tbLocalManifold m =
					tbCollidePolygonAndCircle(&p->polygon, &p->circle, tbInvMulTransforms(p->xfA, p->xfB));
				touching += m.pointCount > 0;
			}
		}
	}
	report("circle-polygon", useGJK ? "gjk-separation" : "closed-form", start, touching / REPEATS);
}

int main(void)
{
	PolygonPair* pairs = malloc(sizeof(PolygonPair) * PAIR_COUNT);
	CirclePolygonPair* circles = malloc(sizeof(CirclePolygonPair) * PAIR_COUNT);
	if (pairs == NULL || circles == NULL)
	{
		return 1;
	}
	makePairs(pairs, circles);

	printf("pair,method,ns_per_pair,touching_of_%d\n", PAIR_COUNT);
	benchPolygons(pairs, false);
	benchPolygons(pairs, true);
	benchCirclePolygon(circles, false);
	benchCirclePolygon(circles, true);

	free(pairs);
	free(circles);
	return 0;
}
