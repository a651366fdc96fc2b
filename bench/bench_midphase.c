// Mid phase: does a body with many shapes cost in proportion to the shapes near the bodies that
// touch it, or to all its shapes? Every shape of a body has its own broad-phase proxy, so a pair
// is found per shape and only nearby segments are ever visited. Measured: 200 balls (radius 0.25)
// rolling on one chain of N one-metre segments (the balls always over the same 20 m), N from 100
// to 100,000, and the same ground as N separate segment shapes on one body. Sleep off, 60 Hz,
// 4 sub-steps, 300 steps after 60 to settle; best of 3 runs per N.
//
//   tumble-bench-midphase
//
// Output: CSV ground,segments,ms_per_step,shapes_on_ground_body

#include "tumble/tumble.h"

#include <stdio.h>
#include <stdlib.h>

#define BALLS 200

static float Run(int segments, bool chain)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = tbMakeVec2(0.0f, -10.0f);
	worldDef.enableSleep = false;
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	if (chain)
	{
		tbVec2* points = malloc(sizeof(tbVec2) * (size_t)(segments + 3));
		for (int i = 0; i < segments + 3; ++i)
		{
			float x = (float)(segments + 1 - i) - 10.0f; // from x = −10 onwards, right to left
			points[i] = tbMakeVec2(x, 0.1f * (float)(i % 2)); // a 0.1 m zigzag: every joint matters
		}
		tbChainDef def = tbDefaultChainDef();
		def.points = points;
		def.count = segments + 3;
		tbCreateChain(ground, &def);
		free(points);
	}
	else
	{
		for (int i = 0; i < segments; ++i)
		{
			float x1 = (float)i - 10.0f;
			tbSegment segment = {{x1, 0.1f * (float)((segments - i) % 2)}, {x1 + 1.0f, 0.1f * (float)((segments - i + 1) % 2)}};
			tbCreateSegmentShape(ground, &shapeDef, &segment);
		}
	}
	tbCircle circle = {{0.0f, 0.0f}, 0.25f};
	for (int i = 0; i < BALLS; ++i)
	{
		bodyDef = tbDefaultBodyDef();
		bodyDef.type = tb_dynamicBody;
		bodyDef.position = tbMakeVec2(-8.0f + 0.6f * (float)(i % 30), 1.0f + 0.6f * (float)(i / 30));
		tbBodyId ball = tbCreateBody(world, &bodyDef);
		tbCreateCircleShape(ball, &shapeDef, &circle);
	}
	for (int step = 0; step < 60; ++step)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	uint64_t start = tbGetTicks();
	for (int step = 0; step < 300; ++step)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	float ms = tbGetMilliseconds(start) / 300.0f;
	tbDestroyWorld(world);
	return ms;
}

int main(void)
{
	printf("ground,segments,ms_per_step,shapes_on_ground_body\n");
	const int counts[4] = {100, 1000, 10000, 100000};
	for (int kind = 0; kind < 2; ++kind)
	{
		for (int c = 0; c < 4; ++c)
		{
			float best = 1e30f;
			for (int run = 0; run < 3; ++run)
			{
				float ms = Run(counts[c], kind == 0);
				best = ms < best ? ms : best;
			}
			printf("%s,%d,%.3f,%d\n", kind == 0 ? "chain" : "segments", counts[c], (double)best, counts[c]);
		}
	}
	return 0;
}
