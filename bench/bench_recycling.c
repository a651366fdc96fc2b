// Manifold recycling accuracy: how far a recycled manifold (contact.c, tbRecycleManifold) is from
// the one the narrow phase would compute at the same moment. Each catalogue scene runs with
// recycling on; after every step, each touching contact that may be recycled (all but chain segments') is updated twice on copies, once
// as the collide stage would (recycled when it qualifies) and once forced to recompute, and the
// two are compared: the smallest separation of the pair (what the solver stops on), the normal,
// and how often the recycled pair looks farther apart than it is while the pair penetrates (the
// error that could let it sink). Nothing of the world changes (copies; counters restored).
//
//   tumble-bench-recycling [SCENE...] [--steps N]
//
// Output: one CSV line per scene: scene,steps,touching,recycled,err_gt_1mm,err_gt_5mm,err_gt_1cm,
// max_err_m,max_over_when_penetrating_m,normal_gt_5deg,max_normal_deg (counts are over recycled
// manifolds, summed over steps; touching counts the touching contacts visited).

#include "catalogue.h"
#include "scene.h"
#include "world/world.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct Stats
{
	long touching, recycled, over1mm, over5mm, over1cm, normalOver5;
	float maxError, maxOverWhenPenetrating, maxNormalDegrees;
} Stats;

static float SmallestSeparation(const tbManifold* m)
{
	float s = INFINITY;
	for (int i = 0; i < m->pointCount; ++i)
	{
		s = fminf(s, m->points[i].separation);
	}
	return s;
}

static bool MayRecycle(const tbShape* shape)
{
	return shape->geometry.type != tb_chainSegmentShape;
}

static void Compare(tbWorld* world, const tbContact* contact, Stats* stats)
{
	tbCounters saved = world->counters;
	tbContact recycled = *contact;
	tbContact fresh = *contact;
	fresh.flags &= ~(uint32_t)tb_contactRecyclable;
	bool began = false;
	tbUpdateContact(world, &recycled, &began);
	bool wasRecycled = world->counters.recycledContactCount > saved.recycledContactCount;
	tbUpdateContact(world, &fresh, &began);
	world->counters = saved;
	stats->touching += 1;
	if (wasRecycled == false || fresh.manifold.pointCount == 0)
	{
		return;
	}
	stats->recycled += 1;
	float kept = SmallestSeparation(&recycled.manifold);
	float exact = SmallestSeparation(&fresh.manifold);
	float error = fabsf(kept - exact);
	stats->over1mm += error > 0.001f ? 1 : 0;
	stats->over5mm += error > 0.005f ? 1 : 0;
	stats->over1cm += error > 0.01f ? 1 : 0;
	stats->maxError = fmaxf(stats->maxError, error);
	if (exact < 0.0f)
	{
		stats->maxOverWhenPenetrating = fmaxf(stats->maxOverWhenPenetrating, kept - exact);
	}
	float c = tbDot(recycled.manifold.normal, fresh.manifold.normal);
	float degrees = acosf(fminf(1.0f, c)) * 180.0f / TB_PI;
	stats->normalOver5 += degrees > 5.0f ? 1 : 0;
	stats->maxNormalDegrees = fmaxf(stats->maxNormalDegrees, degrees);
}

static void RunScene(const char* name, int steps)
{
	Scene* scene = Catalogue_Build(name);
	if (scene == NULL)
	{
		fprintf(stderr, "tumble-bench-recycling: unknown scene '%s'\n", name);
		return;
	}
	SceneWorld sw = Scene_BuildWorld(scene, NULL);
	tbWorld* world = tbGetWorldChecked(sw.worldId, "tumble-bench-recycling");
	int n = steps > 0 ? steps : scene->steps;
	Stats stats;
	memset(&stats, 0, sizeof(stats));
	for (int step = 0; step < n; ++step)
	{
		tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
		for (int id = 0; id < world->contactPool.highWater; ++id)
		{
			const tbContact* contact = world->contacts + id;
			if (contact->inUse == false || (contact->flags & tb_contactTouching) == 0 ||
				(contact->flags & tb_contactSensor) != 0 ||
				MayRecycle(world->shapes + contact->shapeIdA) == false ||
				MayRecycle(world->shapes + contact->shapeIdB) == false)
			{
				continue;
			}
			const tbBody* a = world->bodies + world->shapes[contact->shapeIdA].bodyId;
			const tbBody* b = world->bodies + world->shapes[contact->shapeIdB].bodyId;
			if (a->awakeIndex == TB_NULL_INDEX && b->awakeIndex == TB_NULL_INDEX)
			{
				continue; // the collide stage does not visit sleeping pairs
			}
			Compare(world, contact, &stats);
		}
	}
	printf("%s,%d,%ld,%ld,%ld,%ld,%ld,%.5f,%.5f,%ld,%.3f\n", name, n, stats.touching, stats.recycled, stats.over1mm,
		   stats.over5mm, stats.over1cm, (double)stats.maxError, (double)stats.maxOverWhenPenetrating,
		   stats.normalOver5, (double)stats.maxNormalDegrees);
	fflush(stdout);
	SceneWorld_Destroy(&sw);
	Scene_Destroy(scene);
}

int main(int argc, char** argv)
{
	const char* scenes[32];
	int sceneCount = 0;
	int steps = 0;
	for (int i = 1; i < argc; ++i)
	{
		if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc)
		{
			steps = atoi(argv[++i]);
		}
		else if (sceneCount < 32)
		{
			scenes[sceneCount++] = argv[i];
		}
	}
	static const char* defaults[] = {"pyramid", "large_pyramid", "many_pyramids", "tumbler", "smash", "card_house",
									 "spinner", "confined", "ragdolls"};
	if (sceneCount == 0)
	{
		sceneCount = (int)(sizeof(defaults) / sizeof(defaults[0]));
		for (int i = 0; i < sceneCount; ++i)
		{
			scenes[i] = defaults[i];
		}
	}
	printf("scene,steps,touching,recycled,err_gt_1mm,err_gt_5mm,err_gt_1cm,max_err_m,max_over_when_penetrating_m,"
		   "normal_gt_5deg,max_normal_deg\n");
	for (int i = 0; i < sceneCount; ++i)
	{
		RunScene(scenes[i], steps);
	}
	return 0;
}
