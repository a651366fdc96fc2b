// One build's side of scripts/ab-race.sh: a catalogue scene built and stepped through the samples'
// scene layer. scripts/ab-race.sh links this file with a build's libraries into one object and
// hides every symbol but these four, renamed A_* or B_*, so that two builds of Tumble can live in
// one process (ab_driver.c).
#include "catalogue.h"
#include "scene.h"
#include "task_system.h"
#include "tumble/tumble.h"

#include <stdlib.h>
#include <string.h>

typedef struct Run
{
	Scene* scene;
	SceneWorld world;
	struct TaskSystem* tasks;
} Run;

void* R_create(const char* name, int workers)
{
	Scene* scene = Catalogue_Build(name);
	if (scene == NULL)
	{
		return NULL;
	}
	Run* run = calloc(1, sizeof(*run));
	run->scene = scene;
	run->tasks = workers > 1 ? TaskSystem_Create(workers) : NULL;
	SceneOverrides overrides;
	memset(&overrides, 0, sizeof(overrides));
	overrides.tasks = run->tasks;
	run->world = Scene_BuildWorld(scene, &overrides);
	return run;
}

void R_step(void* run)
{
	Run* r = run;
	SceneWorld_Step(&r->world, r->scene, r->scene->subSteps);
}

unsigned long long R_hash(void* run)
{
	return tbWorld_GetStateHash(((Run*)run)->world.worldId);
}

void R_destroy(void* run)
{
	Run* r = run;
	SceneWorld_Destroy(&r->world);
	if (r->tasks != NULL)
	{
		TaskSystem_Destroy(r->tasks);
	}
	Scene_Destroy(r->scene);
	free(r);
}
