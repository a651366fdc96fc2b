// World queries micro-benchmark: microseconds per ray cast (tbWorld_CastRay) and per box query
// (tbWorld_OverlapAABB) on each broad-phase method, in a world of drifting circles of one size (the
// scene auto hands to the spatial hash), and whether every method gives the tree's closest hits.
//
// Set-up: `bodies` circles of radius 0.5 m on a 2 m grid, drifting at (3, 1) m/s without gravity,
// stepped 120 times at 60 Hz (so the broad phase has updated and moved its proxies); then, between
// steps as a game asks, RAYS rays of (8, 3) m and RAYS boxes of 4 × 4 m from points spread over the
// world, each callback counting. The time is the best of ROUNDS rounds. Then RAYS closest-hit rays of
// random directions on each method, compared with the tree's.
//
// Output: a table, then CSV lines "method,chosen,bodies,ray_us,box_us,closest_differing".
#include "tumble/tumble.h"

#include <stdio.h>
#include <stdlib.h>

#define RAYS 20000
#define ROUNDS 3


static float CountHit(tbShapeId shape, tbPos point, tbVec2 normal, float fraction, void* context)
{
	(void)shape;
	(void)point;
	(void)normal;
	*(int*)context += 1;
	return fraction;
}

static bool CountShape(tbShapeId shape, void* context)
{
	(void)shape;
	*(int*)context += 1;
	return true;
}

static tbWorldId MakeWorld(tbBroadPhaseMethod method, int bodies)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, 0.0f);
	def.broadPhase = method;
	tbWorldId world = tbCreateWorld(&def);
	for (int i = 0; i < bodies; ++i)
	{
		tbBodyDef bd = tbDefaultBodyDef();
		bd.type = tb_dynamicBody;
		bd.position = tbMakeVec2(2.0f * (float)(i % 100), 2.0f * (float)(i / 100));
		bd.linearVelocity = tbMakeVec2(3.0f, 1.0f);
		tbBodyId body = tbCreateBody(world, &bd);
		tbShapeDef sd = tbDefaultShapeDef();
		tbCircle circle = {{0.0f, 0.0f}, 0.5f};
		tbCreateCircleShape(body, &sd, &circle);
	}
	for (int i = 0; i < 120; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	return world;
}

static tbPos QueryPoint(int r, int bodies)
{
	float rows = (float)(bodies / 100 + 1);
	tbPos p = {(float)(r % 97) * 2.0f, (float)(r % 89) / 89.0f * 2.0f * rows};
	return p;
}

int main(int argc, char** argv)
{
	int bodies = argc > 1 ? atoi(argv[1]) : 5000;
	if (bodies < 100 || bodies > 100000)
	{
		fprintf(stderr, "usage: tumble-bench-queries [BODIES (100..100000, default 5000)]\n");
		return 2;
	}
	const tbBroadPhaseMethod methods[] = {tb_broadPhaseTree, tb_broadPhaseSortAndSweep, tb_broadPhaseSpatialHash,
										  tb_broadPhaseAuto};
	const char* names[] = {"tree", "sap", "hash", "auto"};
	const char* chosenNames[] = {"auto", "tree", "sap", "brute", "hash"};
	tbWorldId tree = MakeWorld(tb_broadPhaseTree, bodies);
	printf("World queries among %d drifting circles (r 0.5 m), us per query, best of %d rounds of %d\n\n", bodies,
		   ROUNDS, RAYS);
	printf("| method | runs on | ray (8.5 m) | box (4 m) | closest hits unlike the tree's |\n|---|---|---|---|---|\n");
	char csv[4][160];
	for (int m = 0; m < 4; ++m)
	{
		tbWorldId world = MakeWorld(methods[m], bodies);
		double bestRay = 1e30, bestBox = 1e30;
		int hits = 0;
		for (int round = 0; round < ROUNDS; ++round)
		{
			uint64_t t0 = tbGetTicks();
			for (int r = 0; r < RAYS; ++r)
			{
				tbWorld_CastRay(world, QueryPoint(r, bodies), tbMakeVec2(8.0f, 3.0f), tbDefaultQueryFilter(), CountHit,
								&hits);
			}
			double rayMs = tbGetMilliseconds(t0);
			uint64_t t1 = tbGetTicks();
			for (int r = 0; r < RAYS; ++r)
			{
				tbPos p = QueryPoint(r, bodies);
				tbAABB box = {{p.x, p.y}, {p.x + 4.0f, p.y + 4.0f}};
				tbWorld_OverlapAABB(world, tbPos_zero, box, tbDefaultQueryFilter(), CountShape, &hits);
			}
			double boxMs = tbGetMilliseconds(t1);
			bestRay = rayMs < bestRay ? rayMs : bestRay;
			bestBox = boxMs < bestBox ? boxMs : bestBox;
		}
		int differing = 0;
		for (int r = 0; r < RAYS; ++r)
		{
			tbVec2 d = tbMakeVec2(-20.0f + (float)(r % 41), -15.0f + (float)(r % 31));
			tbRayResult a = tbWorld_CastRayClosest(tree, QueryPoint(r, bodies), d, tbDefaultQueryFilter());
			tbRayResult b = tbWorld_CastRayClosest(world, QueryPoint(r, bodies), d, tbDefaultQueryFilter());
			differing += a.hit != b.hit || a.fraction != b.fraction ? 1 : 0;
		}
		int chosen = (int)tbWorld_GetDef(world).broadPhase;
		double ray = bestRay / RAYS * 1e3, box = bestBox / RAYS * 1e3;
		printf("| %s | %s | %.2f | %.2f | %d of %d |\n", names[m], chosenNames[chosen], ray, box, differing, RAYS);
		snprintf(csv[m], sizeof(csv[m]), "%s,%s,%d,%.4f,%.4f,%d", names[m], chosenNames[chosen], bodies, ray, box,
				 differing);
		tbDestroyWorld(world);
	}
	tbDestroyWorld(tree);
	printf("\nmethod,chosen,bodies,ray_us,box_us,closest_differing\n");
	for (int m = 0; m < 4; ++m)
	{
		printf("%s\n", csv[m]);
	}
	return 0;
}
