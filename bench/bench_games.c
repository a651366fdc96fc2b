// Game-scale scenes, Tumble against Box2D v3.2 in one process.
//
// The scenes (bench/game_scenes.c) are written once against the v3.2 API through a prefix macro and
// compiled twice, into gameEngineTumble and (when CMake is given TUMBLE_BOX2D3_SOURCE_DIR or finds
// an installed v3) gameEngineBox2D3; without v3 the program times Tumble alone. Every round builds,
// steps and destroys each scene on each engine in turn (the engine that goes first alternates from
// round to round), so the two engines share the machine's state over the run; each engine's time
// is the median over the rounds, and the ratio is the median over the rounds of each round's
// Tumble ÷ v3 (the two timings of a round ran back to back).
//
//   tumble-bench-games [--steps N] [--rounds R] [--scene NAME[,NAME...]] [--csv FILE]
//                      [--memory-csv FILE] [--no-memory] [--tumble-only] [--list] [--trace NAME [--trace-every N]]
//   tumble-bench-games --sweep [--sweep-max N] [--rounds R] [--csv FILE]
//
// --scene keeps the scenes named, or, for a word ending in '*', those whose names begin with it. After the table comes a
// check of the end states (bodies, awake bodies, touching contacts, joints, events read, the
// tracked body) so that neither engine can skip work unseen, then the bytes each kind of object
// costs (from each engine's allocator hook). --sweep times mixed bodies falling into a box at
// 1, 3, 10, 30, ... 20,000 bodies, awake over the fall and asleep after settling, as CSV.
#define _POSIX_C_SOURCE 200809L // clock_gettime

#include "game_scenes.h"
#include "task_system.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAX_ROUNDS 64
#define MAX_ENGINES 2

double GameClockSeconds(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int CompareDoubles(const void* a, const void* b)
{
	double x = *(const double*)a, y = *(const double*)b;
	return (x > y) - (x < y);
}

static double Median(const double* values, int count)
{
	double sorted[MAX_ROUNDS];
	memcpy(sorted, values, (size_t)count * sizeof(double));
	qsort(sorted, (size_t)count, sizeof(double), CompareDoubles);
	return count % 2 == 1 ? sorted[count / 2] : 0.5 * (sorted[count / 2 - 1] + sorted[count / 2]);
}

typedef struct Options
{
	int steps; // 0: each scene's own
	int rounds;
	const char* filter;
	const char* csv;
	const char* memoryCsv;
	bool memory;
	bool tumbleOnly;
	bool sweep;
	int sweepMax;
} Options;

static bool Selected(const char* name, const char* filter)
{
	if (filter == NULL)
	{
		return true;
	}
	char words[512];
	snprintf(words, sizeof(words), "%s", filter);
	for (char* word = strtok(words, ","); word != NULL; word = strtok(NULL, ","))
	{
		size_t n = strlen(word);
		bool prefix = n > 0 && word[n - 1] == '*';
		if (prefix ? strncmp(name, word, n - 1) == 0 : strcmp(name, word) == 0)
		{
			return true;
		}
	}
	return false;
}

/// Seconds of `steps` frames of one fresh game; fills its end state.
static double TimeScene(const GameScene* scene, const GameOptions* options, int steps, GameStats* stats)
{
	Game* game = scene->create(options);
	double seconds;
	if (scene->run != NULL)
	{
		seconds = scene->run(game, steps);
	}
	else
	{
		double start = GameClockSeconds();
		for (int s = 0; s < steps; ++s)
		{
			scene->step(game);
		}
		seconds = GameClockSeconds() - start;
	}
	*stats = scene->stats(game);
	scene->destroy(game);
	return seconds;
}

static bool Near(int a, int b, double fraction, int slack)
{
	int larger = a > b ? a : b;
	return abs(a - b) <= slack || (double)abs(a - b) <= fraction * (double)larger;
}

/// What differs between the two engines' end states, or "ok".
static const char* CheckStates(const GameScene* scene, const GameStats* t, const GameStats* v, char* text, size_t size)
{
	text[0] = '\0';
	size_t used = 0;
#define ADD(...) used += (size_t)snprintf(text + used, used < size ? size - used : 0, __VA_ARGS__)
	if (t->bodies != v->bodies)
	{
		ADD("bodies ");
	}
	if (t->joints != v->joints)
	{
		ADD("joints ");
	}
	if (!Near(t->awake, v->awake, 0.2, 3))
	{
		ADD("awake ");
	}
	if (!Near(t->touching, v->touching, 0.25, 4))
	{
		ADD("touching ");
	}
	if ((t->events > 0) != (v->events > 0))
	{
		ADD("events ");
	}
	bool tracked = !isnan(t->x) || !isnan(v->x);
	if (tracked)
	{
		double d = hypot(t->x - v->x, t->y - v->y);
		if (isfinite(t->x) == false || isfinite(v->x) == false || (scene->tolerance > 0.0 && d > scene->tolerance))
		{
			ADD("position ");
		}
	}
#undef ADD
	if (used == 0)
	{
		return "ok";
	}
	text[(used < size ? used : size) - 1] = '\0'; // the last word's space (or the end of a full buffer)
	return text;
}

static void Usage(void)
{
	fprintf(stderr, "usage: tumble-bench-games [--steps N] [--rounds R] [--scene NAME[,NAME...]] [--csv FILE]\n"
					"                          [--memory-csv FILE] [--no-memory] [--tumble-only] [--list]\n"
					"       tumble-bench-games --sweep [--sweep-max N] [--rounds R] [--csv FILE]\n");
}

static int RunScenes(const GameEngine** engines, int engineCount, const Options* o, TaskSystem* tasks)
{
	const GameEngine* first = engines[0];
	int sceneCount = first->sceneCount;
	double* times = calloc((size_t)(sceneCount * MAX_ENGINES * MAX_ROUNDS), sizeof(double));
	GameStats* stats = calloc((size_t)(sceneCount * MAX_ENGINES), sizeof(GameStats));
#define T(s, e, r) times[((s) * MAX_ENGINES + (e)) * MAX_ROUNDS + (r)]
	for (int r = 0; r < o->rounds; ++r)
	{
		for (int s = 0; s < sceneCount; ++s)
		{
			if (!Selected(first->scenes[s].name, o->filter))
			{
				continue;
			}
			for (int k = 0; k < engineCount; ++k)
			{
				int e = (k + r) % engineCount; // A B, then B A: neither engine always goes first
				const GameScene* scene = engines[e]->scenes + s;
				GameOptions options = {scene->param, tasks};
				int steps = o->steps > 0 ? o->steps : scene->steps;
				double seconds = TimeScene(scene, &options, steps, stats + s * MAX_ENGINES + e);
				T(s, e, r) = 1e6 * seconds / steps;
			}
		}
		fprintf(stderr, "round %d of %d done\n", r + 1, o->rounds);
	}

	FILE* csv = o->csv != NULL ? fopen(o->csv, "w") : NULL;
	if (csv != NULL)
	{
		fprintf(csv, "scene,steps,rounds,tumble_us,box2d3_us,ratio,ratio_low,ratio_high,bodies_tumble,bodies_box2d3,awake_tumble,awake_box2d3,"
					 "touching_tumble,touching_box2d3,joints_tumble,joints_box2d3,events_tumble,events_box2d3,"
					 "x_tumble,y_tumble,x_box2d3,y_box2d3,check\n");
	}
	printf("Game-scale scenes: µs per step, median of %d rounds (engines interleaved in one process); Tumble ÷ v3: "
		   "median of the rounds' ratios\n\n",
		   o->rounds);
	printf("| scene | steps | Tumble µs | v3.2 µs | Tumble ÷ v3 | range over rounds | end state |\n|---|---|---|---|---|---|---|\n");
	for (int s = 0; s < sceneCount; ++s)
	{
		const GameScene* scene = first->scenes + s;
		if (!Selected(scene->name, o->filter))
		{
			continue;
		}
		int steps = o->steps > 0 ? o->steps : scene->steps;
		double median[MAX_ENGINES] = {NAN, NAN};
		for (int e = 0; e < engineCount; ++e)
		{
			median[e] = Median(&T(s, e, 0), o->rounds);
		}
		const GameStats* t = stats + s * MAX_ENGINES;
		const GameStats* v = engineCount > 1 ? t + 1 : NULL;
		char text[128];
		const char* check = v != NULL ? CheckStates(scene, t, v, text, sizeof(text)) : "—";
		// The ratio is paired: each round's two timings ran back to back, so the median of the
		// rounds' ratios follows the machine's load less than the ratio of the two medians does.
		double ratios[MAX_ROUNDS];
		for (int r = 0; r < o->rounds; ++r)
		{
			ratios[r] = engineCount > 1 ? T(s, 0, r) / T(s, 1, r) : NAN;
		}
		double ratio = Median(ratios, o->rounds);
		double low = ratios[0], high = ratios[0]; // the rounds' spread, to read the median against
		for (int r = 1; r < o->rounds; ++r)
		{
			low = fmin(low, ratios[r]);
			high = fmax(high, ratios[r]);
		}
		if (engineCount > 1)
		{
			printf("| %s | %d | %.2f | %.2f | **%.2f** | %.2f–%.2f | %s |\n", scene->name, steps, median[0], median[1], ratio, low,
				   high, check);
		}
		else
		{
			printf("| %s | %d | %.2f | — | — | — | — |\n", scene->name, steps, median[0]);
		}
		if (csv != NULL)
		{
			GameStats none = {0, 0, 0, 0, 0, NAN, NAN, 0, 0, 0.0f, -1};
			const GameStats* w = v != NULL ? v : &none;
			fprintf(csv, "%s,%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%d,%d,%d,%d,%d,%d,%d,%d,%lld,%lld,%.4f,%.4f,%.4f,%.4f,%s\n", scene->name,
					steps, o->rounds, median[0], median[1], ratio, low, high, t->bodies, w->bodies, t->awake, w->awake, t->touching, w->touching,
					t->joints, w->joints, (long long)t->events, (long long)w->events, t->x, t->y, w->x, w->y, check);
		}
	}
	printf("\nEnd states (last round), Tumble / v3.2:\n\n");
	printf("| scene | bodies | awake | touching contacts | joints | events read | tracked body x, y |\n|---|---|---|---|---|---|---|\n");
	for (int s = 0; s < sceneCount; ++s)
	{
		const GameScene* scene = first->scenes + s;
		if (!Selected(scene->name, o->filter))
		{
			continue;
		}
		const GameStats* t = stats + s * MAX_ENGINES;
		if (engineCount > 1)
		{
			const GameStats* v = t + 1;
			char where[96] = "—";
			if (!isnan(t->x))
			{
				snprintf(where, sizeof(where), "%.2f, %.2f / %.2f, %.2f", t->x, t->y, v->x, v->y);
			}
			printf("| %s | %d / %d | %d / %d | %d / %d | %d / %d | %lld / %lld | %s |\n", scene->name, t->bodies, v->bodies,
				   t->awake, v->awake, t->touching, v->touching, t->joints, v->joints, (long long)t->events,
				   (long long)v->events, where);
		}
		else
		{
			printf("| %s | %d | %d | %d | %d | %lld | %.2f, %.2f |\n", scene->name, t->bodies, t->awake, t->touching, t->joints,
				   (long long)t->events, t->x, t->y);
		}
	}
	if (csv != NULL)
	{
		fclose(csv);
	}
#undef T
	free(times);
	free(stats);
	return 0;
}

static void RunMemory(const GameEngine** engines, int engineCount, const char* path)
{
	const int count = 10000;
	printf("\nBytes per object from each engine's allocator hook (%d of each; arrays grow by doubling, so spare "
		   "capacity counts):\n\n",
		   count);
	printf("| engine | body | shape (circle) | contact (touching) | joint (revolute) | joint_grid peak | many_pyramids peak |\n"
		   "|---|---|---|---|---|---|---|\n");
	FILE* csv = path != NULL ? fopen(path, "w") : NULL;
	if (csv != NULL)
	{
		fprintf(csv, "engine,count,body,shape,contact,joint,contacts,joint_grid_peak,many_pyramids_peak\n");
	}
	for (int e = 0; e < engineCount; ++e)
	{
		GameMemory m = engines[e]->measureMemory(count);
		printf("| %s | %.0f | %.0f | %.0f | %.0f | %.1f MB | %.1f MB |\n", engines[e]->name, m.body, m.shape, m.contact,
			   m.joint, (double)m.jointGridPeak / 1e6, (double)m.manyPyramidsPeak / 1e6);
		if (csv != NULL)
		{
			fprintf(csv, "%s,%d,%.1f,%.1f,%.1f,%.1f,%d,%lld,%lld\n", engines[e]->name, m.count, m.body, m.shape, m.contact,
					m.joint, m.contacts, (long long)m.jointGridPeak, (long long)m.manyPyramidsPeak);
		}
	}
	if (csv != NULL)
	{
		fclose(csv);
	}
}

// Size sweep: per size and engine, the awake frames (the fall and the landing) are timed, the world
// settles untimed, then the asleep frames are timed.
static int RunSweep(const GameEngine** engines, int engineCount, const Options* o)
{
	static const int sizes[] = {1, 3, 10, 30, 100, 300, 1000, 3000, 10000, 20000};
	enum
	{
		sizeCount = (int)(sizeof(sizes) / sizeof(sizes[0])),
		awakeSteps = 120,
		asleepSteps = 600
	};
	double awake[sizeCount][MAX_ENGINES][MAX_ROUNDS], asleep[sizeCount][MAX_ENGINES][MAX_ROUNDS];
	int left[sizeCount][MAX_ENGINES];
	for (int r = 0; r < o->rounds; ++r)
	{
		for (int i = 0; i < sizeCount && sizes[i] <= o->sweepMax; ++i)
		{
			for (int k = 0; k < engineCount; ++k)
			{
				int e = (k + r) % engineCount;
				const GameScene* scene = engines[e]->sweep;
				// Small worlds step in microseconds: they are made and timed several times a round.
				int reps = sizes[i] >= 300 ? 1 : (300 / sizes[i] < 20 ? 300 / sizes[i] : 20);
				double awakeSeconds = 0.0, asleepSeconds = 0.0;
				for (int rep = 0; rep < reps; ++rep)
				{
					GameOptions options = {sizes[i], NULL};
					Game* game = scene->create(&options);
					double start = GameClockSeconds();
					for (int s = 0; s < awakeSteps; ++s)
					{
						scene->step(game);
					}
					awakeSeconds += GameClockSeconds() - start;
					left[i][e] = engines[e]->settle(game, GAME_SETTLE_STEPS);
					start = GameClockSeconds();
					for (int s = 0; s < asleepSteps; ++s)
					{
						scene->step(game);
					}
					asleepSeconds += GameClockSeconds() - start;
					scene->destroy(game);
				}
				awake[i][e][r] = 1e6 * awakeSeconds / (reps * awakeSteps);
				asleep[i][e][r] = 1e6 * asleepSeconds / (reps * asleepSteps);
			}
		}
		fprintf(stderr, "sweep round %d of %d done\n", r + 1, o->rounds);
	}
	FILE* csv = o->csv != NULL ? fopen(o->csv, "w") : stdout;
	fprintf(csv, "bodies,tumble_awake_us,box2d3_awake_us,awake_ratio,tumble_asleep_us,box2d3_asleep_us,asleep_ratio,"
				 "tumble_awake_left,box2d3_awake_left\n");
	for (int i = 0; i < sizeCount && sizes[i] <= o->sweepMax; ++i)
	{
		double ta = Median(awake[i][0], o->rounds), ts = Median(asleep[i][0], o->rounds);
		double va = engineCount > 1 ? Median(awake[i][1], o->rounds) : NAN;
		double vs = engineCount > 1 ? Median(asleep[i][1], o->rounds) : NAN;
		double awakeRatios[MAX_ROUNDS], asleepRatios[MAX_ROUNDS]; // paired by round, as in RunScenes
		for (int r = 0; r < o->rounds; ++r)
		{
			awakeRatios[r] = engineCount > 1 ? awake[i][0][r] / awake[i][1][r] : NAN;
			asleepRatios[r] = engineCount > 1 ? asleep[i][0][r] / asleep[i][1][r] : NAN;
		}
		fprintf(csv, "%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%d\n", sizes[i], ta, va, Median(awakeRatios, o->rounds), ts, vs,
				Median(asleepRatios, o->rounds), left[i][0],
				engineCount > 1 ? left[i][1] : -1);
	}
	if (csv != stdout)
	{
		fclose(csv);
		printf("wrote %s\n", o->csv);
	}
	return 0;
}

// --trace NAME [--trace-every N]: the end state of one scene every N frames (60 unless given) on
// each engine, side by side (untimed; for checking that a scene plays the same game on both
// engines, and when each comes to rest).
static int Trace(const GameEngine** engines, int engineCount, const char* name, int steps, int every)
{
	int s = 0;
	while (s < engines[0]->sceneCount && strcmp(engines[0]->scenes[s].name, name) != 0)
	{
		++s;
	}
	if (s == engines[0]->sceneCount)
	{
		fprintf(stderr, "no scene %s (see --list)\n", name);
		return 1;
	}
	Game* games[MAX_ENGINES];
	TaskSystem* tasks = TaskSystem_Create(2);
	for (int e = 0; e < engineCount; ++e)
	{
		GameOptions options = {engines[e]->scenes[s].param, tasks};
		games[e] = engines[e]->scenes[s].create(&options);
	}
	for (int step = 0; step <= steps; ++step)
	{
		if (step % every == 0)
		{
			printf("%5d", step);
			for (int e = 0; e < engineCount; ++e)
			{
				GameStats st = engines[e]->scenes[s].stats(games[e]);
				printf(" | %s awake %d touching %d events %lld at %.2f, %.2f contacts %d recycled %d fastest %.3f (body %d)",
					   engines[e]->name, st.awake, st.touching, (long long)st.events, st.x, st.y, st.contacts, st.recycled,
					   (double)st.fastest, st.fastestBody);
			}
			printf("\n");
		}
		for (int e = 0; e < engineCount && step < steps; ++e)
		{
			engines[e]->scenes[s].step(games[e]);
		}
	}
	for (int e = 0; e < engineCount; ++e)
	{
		engines[e]->scenes[s].destroy(games[e]);
	}
	TaskSystem_Destroy(tasks);
	return 0;
}

int main(int argc, char** argv)
{
	Options o = {0, 3, NULL, NULL, NULL, true, false, false, 20000};
	bool list = false;
	const char* trace = NULL;
	int traceEvery = 60;
	for (int i = 1; i < argc; ++i)
	{
		const char* a = argv[i];
		const char* next = i + 1 < argc ? argv[i + 1] : NULL;
		if (strcmp(a, "--steps") == 0 && next != NULL)
		{
			o.steps = atoi(argv[++i]);
		}
		else if (strcmp(a, "--rounds") == 0 && next != NULL)
		{
			o.rounds = atoi(argv[++i]);
		}
		else if (strcmp(a, "--scene") == 0 && next != NULL)
		{
			o.filter = argv[++i];
		}
		else if (strcmp(a, "--csv") == 0 && next != NULL)
		{
			o.csv = argv[++i];
		}
		else if (strcmp(a, "--memory-csv") == 0 && next != NULL)
		{
			o.memoryCsv = argv[++i];
		}
		else if (strcmp(a, "--sweep-max") == 0 && next != NULL)
		{
			o.sweepMax = atoi(argv[++i]);
		}
		else if (strcmp(a, "--no-memory") == 0)
		{
			o.memory = false;
		}
		else if (strcmp(a, "--tumble-only") == 0)
		{
			o.tumbleOnly = true;
		}
		else if (strcmp(a, "--sweep") == 0)
		{
			o.sweep = true;
		}
		else if (strcmp(a, "--trace") == 0 && next != NULL)
		{
			trace = argv[++i];
		}
		else if (strcmp(a, "--trace-every") == 0 && next != NULL)
		{
			traceEvery = atoi(argv[++i]) > 0 ? atoi(argv[i]) : 60;
		}
		else if (strcmp(a, "--list") == 0)
		{
			list = true;
		}
		else
		{
			Usage();
			return 1;
		}
	}
	if (o.rounds < 1 || o.rounds > MAX_ROUNDS || o.steps < 0)
	{
		Usage();
		return 1;
	}

	const GameEngine* engines[MAX_ENGINES] = {&gameEngineTumble};
	int engineCount = 1;
#if defined(TUMBLE_HAVE_BOX2D3)
	if (o.tumbleOnly == false)
	{
		engines[engineCount++] = &gameEngineBox2D3;
	}
#endif
	if (list)
	{
		for (int s = 0; s < engines[0]->sceneCount; ++s)
		{
			printf("%s (%d steps)\n", engines[0]->scenes[s].name, engines[0]->scenes[s].steps);
		}
		return 0;
	}
	if (trace != NULL)
	{
		return Trace(engines, engineCount, trace, o.steps > 0 ? o.steps : 600, traceEvery);
	}
	// Hooks first: every allocation either engine makes goes through them, so each block is freed
	// by the hook that made it.
	for (int e = 0; e < engineCount; ++e)
	{
		engines[e]->installAllocator();
	}
	printf("engines:");
	for (int e = 0; e < engineCount; ++e)
	{
		printf(" %s", engines[e]->name);
	}
	printf("; frame 1/60 s, 4 sub-steps, sleep on\n");
	fflush(stdout);
	if (o.sweep)
	{
		return RunSweep(engines, engineCount, &o);
	}

	bool workers = false, any = false;
	for (int s = 0; s < engines[0]->sceneCount; ++s)
	{
		bool selected = Selected(engines[0]->scenes[s].name, o.filter);
		any = any || selected;
		workers = workers || (engines[0]->scenes[s].usesWorkers && selected);
	}
	if (any == false)
	{
		fprintf(stderr, "tumble-bench-games: no scene is named %s (see --list; a word ending in '*' matches a prefix)\n",
				o.filter);
		return 1;
	}
	TaskSystem* tasks = workers ? TaskSystem_Create(2) : NULL;
	int status = RunScenes(engines, engineCount, &o, tasks);
	TaskSystem_Destroy(tasks);
	if (o.memory)
	{
		RunMemory(engines, engineCount, o.memoryCsv);
	}
	return status;
}
