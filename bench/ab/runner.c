// One build's side of scripts/ab-race.sh: a catalogue scene built and stepped through the samples'
// scene layer, or (a name "game:NAME", when the build has tumble-bench-games) one of the game
// scenes of bench/game_scenes.c. scripts/ab-race.sh links this file with a build's libraries into one object and
// hides every symbol but these four, renamed A_* or B_*, so that two builds of Tumble can live in
// one process (ab_driver.c).
#include "catalogue.h"
#include "scene.h"
#include "task_system.h"
#include "tumble/tumble.h"
#ifdef AB_GAMES
#include "game_scenes.h"
#include <math.h>
#include <time.h>
#endif

#include <stdlib.h>
#include <string.h>

typedef struct Run
{
	Scene* scene;
	SceneWorld world;
	struct TaskSystem* tasks;
#ifdef AB_GAMES
	const GameScene* game; ///< a game scene instead (scene NULL)
	Game* gameState;
#endif
} Run;

#ifdef AB_GAMES
// bench_games.c's clock, which the self-timing game scenes call.
double GameClockSeconds(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static Run* CreateGame(const char* name, int workers)
{
	const GameEngine* engine = &gameEngineTumble;
	for (int i = 0; i < engine->sceneCount; ++i)
	{
		const GameScene* game = engine->scenes + i;
		if (strcmp(game->name, name) == 0)
		{
			Run* run = calloc(1, sizeof(*run));
			run->tasks = workers > 1 || game->usesWorkers ? TaskSystem_Create(workers > 1 ? workers : 2) : NULL;
			GameOptions options = {game->param, run->tasks};
			run->game = game;
			run->gameState = game->create(&options);
			return run;
		}
	}
	return NULL;
}

// The game's end state folded into a number (game scenes expose no world): equal states give
// equal numbers.
static unsigned long long HashGame(const Run* run)
{
	GameStats s = run->game->stats(run->gameState);
	unsigned long long h = 1469598103934665603ull;
	double fields[] = {s.bodies, s.awake, s.touching, s.joints, (double)s.events, isnan(s.x) ? 0.0 : s.x,
					   isnan(s.y) ? 0.0 : s.y, s.contacts, s.recycled, s.fastest, s.fastestBody};
	const unsigned char* bytes = (const unsigned char*)fields;
	for (size_t i = 0; i < sizeof(fields); ++i)
	{
		h = (h ^ bytes[i]) * 1099511628211ull;
	}
	return h;
}
#endif

void* R_create(const char* name, int workers)
{
#ifdef AB_GAMES
	if (strncmp(name, "game:", 5) == 0)
	{
		return CreateGame(name + 5, workers);
	}
#endif
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
#ifdef AB_GAMES
	if (r->game != NULL)
	{
		r->game->step(r->gameState);
		return;
	}
#endif
	SceneWorld_Step(&r->world, r->scene, r->scene->subSteps);
}

unsigned long long R_hash(void* run)
{
#ifdef AB_GAMES
	if (((Run*)run)->game != NULL)
	{
		return HashGame(run);
	}
#endif
	return tbWorld_GetStateHash(((Run*)run)->world.worldId);
}

void R_destroy(void* run)
{
	Run* r = run;
#ifdef AB_GAMES
	if (r->game != NULL)
	{
		r->game->destroy(r->gameState);
		if (r->tasks != NULL)
		{
			TaskSystem_Destroy(r->tasks);
		}
		free(r);
		return;
	}
#endif
	SceneWorld_Destroy(&r->world);
	if (r->tasks != NULL)
	{
		TaskSystem_Destroy(r->tasks);
	}
	Scene_Destroy(r->scene);
	free(r);
}
