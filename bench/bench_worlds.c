// Many worlds: the throughput of stepping many small, independent worlds at once, as parameter
// sweeps and training environments do. Each world runs on one worker (its own step is not split);
// the worlds are spread over the workers of the reference task system (samples/task_system.c),
// one task item per world. Each world is a base-10 pyramid of boxes hit by a ball whose speed
// differs from world to world (the swept parameter).
//
//   tumble-bench-worlds [--worlds N] [--steps S] [--workers W]
//
// Prints, for 1 worker and for W workers, worlds·steps per second, and checks that every world
// ends in the same state either way (a world's result does not depend on where it ran).

#include "task_system.h"

#include "tumble/tumble.h"

#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct Sweep
{
	tbWorldId* worlds;
	tbBodyId* balls;
	int count;
	atomic_int next; ///< the next world to step, claimed by whichever thread is free
} Sweep;

static tbWorldId CreatePyramidWorld(float ballSpeed, tbBodyId* ball)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, -10.0f);
	tbWorldId world = tbCreateWorld(&def);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbSegment floor = {{-40.0f, 0.0f}, {40.0f, 0.0f}};
	tbCreateSegmentShape(ground, &shapeDef, &floor);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	bodyDef.type = tb_dynamicBody;
	for (int row = 0; row < 10; ++row)
	{
		for (int i = 0; i < 10 - row; ++i)
		{
			bodyDef.position = tbMakeVec2((float)i - 0.5f * (float)(9 - row), 0.5f + (float)row);
			tbBodyId body = tbCreateBody(world, &bodyDef);
			tbCreatePolygonShape(body, &shapeDef, &box);
		}
	}
	bodyDef.position = tbMakeVec2(-20.0f, 2.0f);
	bodyDef.linearVelocity = tbMakeVec2(ballSpeed, 0.0f);
	*ball = tbCreateBody(world, &bodyDef);
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	shapeDef.density = 5.0f;
	tbCreateCircleShape(*ball, &shapeDef, &circle);
	return world;
}

/// One thread's part of a round: step worlds until none is left to claim.
static void StepWorldsTask(void* context)
{
	Sweep* sweep = context;
	for (int i = atomic_fetch_add(&sweep->next, 1); i < sweep->count; i = atomic_fetch_add(&sweep->next, 1))
	{
		tbWorld_Step(sweep->worlds[i], 1.0f / 60.0f, 4);
	}
}

/// Step every world `steps` times on `workers` workers; returns worlds·steps per second and fills
/// each ball's final position.
static double Run(int worldCount, int steps, int workers, tbVec2* finalPositions)
{
	Sweep sweep;
	sweep.count = worldCount;
	sweep.worlds = calloc((size_t)worldCount, sizeof(tbWorldId));
	sweep.balls = calloc((size_t)worldCount, sizeof(tbBodyId));
	for (int i = 0; i < worldCount; ++i)
	{
		sweep.worlds[i] = CreatePyramidWorld(5.0f + 0.25f * (float)i, sweep.balls + i);
	}
	TaskSystem* tasks = workers > 1 ? TaskSystem_Create(workers) : NULL;
	uint64_t start = tbGetTicks();
	for (int s = 0; s < steps; ++s)
	{
		atomic_store(&sweep.next, 0);
		void* handles[TB_MAX_WORKERS];
		for (int w = 1; w < workers && tasks != NULL; ++w)
		{
			handles[w] = TaskSystem_Enqueue(StepWorldsTask, &sweep, tasks);
		}
		StepWorldsTask(&sweep);
		for (int w = 1; w < workers && tasks != NULL; ++w)
		{
			if (handles[w] != NULL)
			{
				TaskSystem_Finish(handles[w], tasks);
			}
		}
	}
	double seconds = (double)tbGetMilliseconds(start) / 1000.0;
	for (int i = 0; i < worldCount; ++i)
	{
		finalPositions[i] = tbBody_GetPosition(sweep.balls[i]);
		tbDestroyWorld(sweep.worlds[i]);
	}
	TaskSystem_Destroy(tasks);
	free(sweep.worlds);
	free(sweep.balls);
	return (double)worldCount * (double)steps / seconds;
}

int main(int argc, char** argv)
{
	int worldCount = 64, steps = 300, workers = 2;
	for (int i = 1; i + 1 < argc; i += 2)
	{
		if (strcmp(argv[i], "--worlds") == 0)
		{
			worldCount = atoi(argv[i + 1]);
		}
		else if (strcmp(argv[i], "--steps") == 0)
		{
			steps = atoi(argv[i + 1]);
		}
		else if (strcmp(argv[i], "--workers") == 0)
		{
			workers = atoi(argv[i + 1]);
		}
	}
	if (worldCount < 1 || worldCount > TB_MAX_WORLDS - 1 || steps < 1 || workers < 1 || workers > TB_MAX_WORKERS)
	{
		fprintf(stderr, "usage: tumble-bench-worlds [--worlds 1..%d] [--steps S] [--workers 1..%d]\n",
				TB_MAX_WORLDS - 1, TB_MAX_WORKERS);
		return 1;
	}
	tbVec2* serial = calloc((size_t)worldCount, sizeof(tbVec2));
	tbVec2* parallel = calloc((size_t)worldCount, sizeof(tbVec2));
	double one = Run(worldCount, steps, 1, serial);
	double many = Run(worldCount, steps, workers, parallel);
	bool same = memcmp(serial, parallel, (size_t)worldCount * sizeof(tbVec2)) == 0;
	printf("worlds,steps,workers,world_steps_per_second\n");
	printf("%d,%d,1,%.0f\n%d,%d,%d,%.0f\n", worldCount, steps, one, worldCount, steps, workers, many);
	printf("speed-up %.2f; final states %s\n", many / one, same ? "identical" : "DIFFERENT");
	free(serial);
	free(parallel);
	return same ? 0 : 1;
}
