// tumble: run, draw, export and inspect catalogue scenes and scene files.
//
//   tumble list
//   tumble run SCENE [options]       step a scene; optional PNG frames, CSV trajectory, sheet
//   tumble export SCENE              print the scene file JSON
//   tumble sheet SCENE --out FILE.png [--frames N] [options]
//
// SCENE is a catalogue name or a path to a .json scene file. Errors print one line and exit 1.
#define _POSIX_C_SOURCE 200809L

#include "catalogue.h"
#include "render.h"
#include "scene_file.h"
#include "task_system.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

typedef struct Options
{
	int steps; ///< < 0: the scene's suggested count
	const char* pngDir;
	int every;
	int width, height;
	bool sizeGiven;
	const char* csvPath;
	const char* sheetPath;
	int frames;
	int workers; ///< --workers N: a task system of N workers
	bool viewGiven;
	tbAABB view;
	SceneOverrides overrides;
	RenderOptions render;
} Options;

static int Fail(const char* format, ...)
{
	va_list args;
	va_start(args, format);
	fprintf(stderr, "tumble: ");
	vfprintf(stderr, format, args);
	fprintf(stderr, "\n");
	va_end(args);
	return 1;
}

static void PrintUsage(void)
{
	printf("usage:\n"
		   "  tumble list\n"
		   "  tumble run SCENE [--steps N] [--png DIR] [--every K] [--size WxH] [--csv FILE]\n"
		   "                   [--view x0,y0,x1,y1] [--broadphase tree|sap|hash|brute|auto] [--narrowphase sat|gjk|auto]\n"
		   "                   [--toi off|quadratic|ca] [--solver baumgarte|ngs|soft] [--substeps N]\n"
		   "                   [--iterations N] [--relax N] [--final-relax N] [--settled-ratio X]\n"
		   "                   [--scalar-solver] [--no-recycle] [--point-friction] [--impact-propagation]\n"
		   "                   [--workers N]\n"
		   "                   [--sheet FILE.png] [--frames N] [--contacts]\n"
		   "                   [--aabbs] [--tree]\n"
		   "  tumble export SCENE\n"
		   "  tumble sheet SCENE --out FILE.png [--frames N] [run options]\n"
		   "SCENE is a catalogue name (see `tumble list`) or a path to a .json scene file.\n");
}

// ---------------------------------------------------------------------------------------------
// Options

static bool ParsePositiveInt(const char* text, int* out)
{
	char* end = NULL;
	errno = 0;
	long value = strtol(text, &end, 10);
	if (errno != 0 || end == text || *end != '\0' || value <= 0 || value > 100000000)
	{
		return false;
	}
	*out = (int)value;
	return true;
}

static bool ParseSize(const char* text, int* width, int* height)
{
	char extra = 0;
	if (sscanf(text, "%dx%d%c", width, height, &extra) != 2)
	{
		return false;
	}
	return *width > 0 && *height > 0 && *width <= 8192 && *height <= 8192;
}

static bool ParseView(const char* text, tbAABB* view)
{
	char extra = 0;
	float v[4];
	if (sscanf(text, "%f,%f,%f,%f%c", v, v + 1, v + 2, v + 3, &extra) != 4)
	{
		return false;
	}
	for (int i = 0; i < 4; ++i)
	{
		if (tbIsValidFloat(v[i]) == false)
		{
			return false;
		}
	}
	*view = (tbAABB){{v[0], v[1]}, {v[2], v[3]}};
	return v[2] > v[0] && v[3] > v[1];
}

static bool ParseMethodOption(const char* flag, const char* value, SceneMethods* methods)
{
	if (strcmp(flag, "--broadphase") == 0)
	{
		return (methods->hasBroadPhase = Scene_ParseBroadPhase(value, &methods->broadPhase));
	}
	if (strcmp(flag, "--narrowphase") == 0)
	{
		return (methods->hasNarrowPhase = Scene_ParseNarrowPhase(value, &methods->narrowPhase));
	}
	if (strcmp(flag, "--toi") == 0)
	{
		return (methods->hasContinuous = Scene_ParseContinuous(value, &methods->continuous));
	}
	return (methods->hasSolver = Scene_ParseSolver(value, &methods->solver));
}

static bool IsMethodFlag(const char* flag)
{
	return strcmp(flag, "--broadphase") == 0 || strcmp(flag, "--narrowphase") == 0 || strcmp(flag, "--toi") == 0 ||
		   strcmp(flag, "--solver") == 0;
}

static const char* MethodChoices(const char* flag)
{
	if (strcmp(flag, "--broadphase") == 0)
	{
		return "tree, sap, brute, auto";
	}
	if (strcmp(flag, "--narrowphase") == 0)
	{
		return "sat, gjk, auto";
	}
	return strcmp(flag, "--toi") == 0 ? "off, quadratic, ca" : "baumgarte, ngs, soft";
}

// An option with a value. Returns 0 on success, else the exit status after printing the error.
static int ParseValueOption(Options* options, const char* flag, const char* value)
{
	bool ok = true;
	if (IsMethodFlag(flag))
	{
		return ParseMethodOption(flag, value, &options->overrides.methods)
				   ? 0
				   : Fail("%s: '%s' is not one of %s", flag, value, MethodChoices(flag));
	}
	if (strcmp(flag, "--steps") == 0)
	{
		ok = ParsePositiveInt(value, &options->steps) || strcmp(value, "0") == 0;
		options->steps = strcmp(value, "0") == 0 ? 0 : options->steps;
	}
	else if (strcmp(flag, "--png") == 0)
	{
		options->pngDir = value;
	}
	else if (strcmp(flag, "--every") == 0)
	{
		ok = ParsePositiveInt(value, &options->every);
	}
	else if (strcmp(flag, "--size") == 0)
	{
		ok = options->sizeGiven = ParseSize(value, &options->width, &options->height);
	}
	else if (strcmp(flag, "--csv") == 0)
	{
		options->csvPath = value;
	}
	else if (strcmp(flag, "--view") == 0)
	{
		ok = options->viewGiven = ParseView(value, &options->view);
	}
	else if (strcmp(flag, "--substeps") == 0)
	{
		ok = ParsePositiveInt(value, &options->overrides.subSteps);
	}
	else if (strcmp(flag, "--iterations") == 0)
	{
		ok = ParsePositiveInt(value, &options->overrides.velocityIterations);
	}
	else if (strcmp(flag, "--relax") == 0)
	{
		ok = ParsePositiveInt(value, &options->overrides.relaxIterations);
	}
	else if (strcmp(flag, "--final-relax") == 0)
	{
		ok = options->overrides.finalRelaxGiven =
			ParsePositiveInt(value, &options->overrides.finalRelaxIterations) || strcmp(value, "0") == 0;
	}
	else if (strcmp(flag, "--settled-ratio") == 0)
	{
		char* end = NULL;
		float ratio = strtof(value, &end);
		ok = end != value && *end == '\0' && ratio > 0.0f && ratio <= 1000.0f;
		options->overrides.settledHertzRatio = ok ? ratio : 0.0f;
	}
	else if (strcmp(flag, "--sheet") == 0 || strcmp(flag, "--out") == 0)
	{
		options->sheetPath = value;
	}
	else if (strcmp(flag, "--frames") == 0)
	{
		ok = ParsePositiveInt(value, &options->frames);
	}
	else if (strcmp(flag, "--workers") == 0)
	{
		ok = ParsePositiveInt(value, &options->workers) && options->workers <= TB_MAX_WORKERS;
	}
	else
	{
		return Fail("unknown option '%s' (see tumble --help)", flag);
	}
	return ok ? 0 : Fail("%s: bad value '%s'", flag, value);
}

static bool ParseFlagOption(Options* options, const char* flag)
{
	if (strcmp(flag, "--contacts") == 0)
	{
		options->render.drawContacts = true;
		options->render.drawNormals = true;
		return true;
	}
	if (strcmp(flag, "--aabbs") == 0)
	{
		return (options->render.drawAABBs = true);
	}
	if (strcmp(flag, "--tree") == 0)
	{
		return (options->render.drawTree = true);
	}
	if (strcmp(flag, "--scalar-solver") == 0)
	{
		return (options->overrides.scalarSolver = true);
	}
	if (strcmp(flag, "--no-recycle") == 0)
	{
		return (options->overrides.noRecycle = true);
	}
	if (strcmp(flag, "--point-friction") == 0)
	{
		return (options->overrides.pointFriction = true);
	}
	if (strcmp(flag, "--impact-propagation") == 0)
	{
		return (options->overrides.impactPropagation = true);
	}
	return false;
}

static int ParseOptions(Options* options, int argc, char** argv)
{
	memset(options, 0, sizeof(*options));
	options->steps = -1;
	options->every = 1;
	options->width = 800;
	options->height = 600;
	options->frames = 16;
	options->render = Render_DefaultOptions();
	for (int i = 0; i < argc; ++i)
	{
		if (ParseFlagOption(options, argv[i]))
		{
			continue;
		}
		if (strncmp(argv[i], "--", 2) != 0)
		{
			return Fail("unexpected argument '%s'", argv[i]);
		}
		if (i + 1 >= argc)
		{
			return Fail("%s needs a value", argv[i]);
		}
		int status = ParseValueOption(options, argv[i], argv[i + 1]);
		if (status != 0)
		{
			return status;
		}
		i += 1;
	}
	return 0;
}

// ---------------------------------------------------------------------------------------------
// Scenes

static Scene* LoadScene(const char* name)
{
	Scene* scene = Catalogue_Build(name);
	if (scene != NULL)
	{
		return scene;
	}
	struct stat info;
	if (stat(name, &info) != 0 && strchr(name, '/') == NULL && strstr(name, ".json") == NULL)
	{
		Fail("unknown scene '%s' (not in the catalogue and no such file; see tumble list)", name);
		return NULL;
	}
	char error[512];
	scene = SceneFile_Load(name, error, (int)sizeof(error));
	if (scene == NULL)
	{
		Fail("%s", error);
	}
	return scene;
}

static int List(void)
{
	for (int i = 0; i < Catalogue_Count(); ++i)
	{
		printf("%-18s %s\n", Catalogue_Name(i), Catalogue_Description(i));
	}
	return 0;
}

static int Export(const char* name)
{
	Scene* scene = LoadScene(name);
	if (scene == NULL)
	{
		return 1;
	}
	char error[256] = "";
	char* text = SceneFile_Export(scene, error, (int)sizeof(error));
	Scene_Destroy(scene);
	if (text == NULL)
	{
		return Fail("export: %s", error);
	}
	fputs(text, stdout);
	free(text);
	return 0;
}

// ---------------------------------------------------------------------------------------------
// Running

typedef struct Run
{
	const Options* options;
	const Scene* scene;
	SceneWorld world;
	int steps;
	int subSteps;
	tbAABB view;
	FILE* csv;
	RenderImage frame;
	RenderSheet sheet;
	double stepMilliseconds;
	bool interactive; ///< stderr is a terminal
} Run;

static void WriteCsvRows(Run* run, int step)
{
	for (int i = 0; i < run->world.bodyCount; ++i)
	{
		tbBodyId id = run->world.bodyIds[i];
		if (run->scene->bodies[i].type == tb_staticBody || tbBody_IsValid(id) == false)
		{
			continue;
		}
		tbVec2 p = tbBody_GetPosition(id);
		tbVec2 v = tbBody_GetLinearVelocity(id);
		fprintf(run->csv, "%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", step, i, (double)p.x, (double)p.y,
				(double)tbBody_GetAngle(id), (double)v.x, (double)v.y, (double)tbBody_GetAngularVelocity(id));
	}
}

static bool WriteFrame(Run* run, int step)
{
	char path[4096];
	snprintf(path, sizeof(path), "%s/frame_%05d.png", run->options->pngDir, step);
	Render_World(&run->frame, run->world.worldId, run->view, &run->options->render);
	if (RenderImage_WritePNG(&run->frame, path) == false)
	{
		Fail("cannot write %s", path);
		return false;
	}
	return true;
}

// Sheet frames are spread evenly over the run, first and last step included.
static bool IsSheetStep(const Run* run, int step)
{
	int frames = run->sheet.frameCount;
	if (frames <= 1)
	{
		return step == 0;
	}
	int k = run->sheet.added;
	long long target = ((long long)k * run->steps + (frames - 1) / 2) / (frames - 1);
	return k < frames && step >= target;
}

static bool Observe(Run* run, int step)
{
	if (run->csv != NULL)
	{
		WriteCsvRows(run, step);
	}
	if (run->options->pngDir != NULL && step % run->options->every == 0 && WriteFrame(run, step) == false)
	{
		return false;
	}
	while (run->sheet.image.pixels != NULL && IsSheetStep(run, step) &&
		   RenderSheet_Add(&run->sheet, run->world.worldId, run->view, &run->options->render))
	{
	}
	return true;
}

static double WallSeconds(void)
{
	struct timespec now;
	clock_gettime(CLOCK_MONOTONIC, &now);
	return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

static bool StepAll(Run* run)
{
	double lastReport = WallSeconds();
	bool reported = false;
	for (int step = 1; step <= run->steps; ++step)
	{
		uint64_t ticks = tbGetTicks();
		if (SceneWorld_Step(&run->world, run->scene, run->subSteps) == false)
		{
			Fail("step %d failed", step);
			return false;
		}
		run->stepMilliseconds += tbGetMilliseconds(ticks);
		if (Observe(run, step) == false)
		{
			return false;
		}
		// progress: in place each second on a terminal, one line each 10 s otherwise
		double interval = run->interactive ? 1.0 : 10.0;
		if (WallSeconds() - lastReport > interval)
		{
			fprintf(stderr, run->interactive ? "\rstep %d/%d" : "step %d/%d\n", step, run->steps);
			lastReport = WallSeconds();
			reported = true;
		}
	}
	if (reported && run->interactive)
	{
		fprintf(stderr, "\rstep %d/%d\n", run->steps, run->steps);
	}
	return true;
}

static void PrintSummary(const Run* run, const char* name)
{
	tbCounters counters = tbWorld_GetCounters(run->world.worldId);
	int moving = 0;
	for (int i = 0; i < run->scene->bodyCount; ++i)
	{
		moving += run->scene->bodies[i].type != tb_staticBody ? 1 : 0;
	}
	printf("scene: %s\n", name);
	printf("steps: %d (dt %.6g s, %d sub-steps)\n", run->steps, (double)run->scene->timeStep, run->subSteps);
	printf("bodies: %d (%d non-static)\n", run->world.bodyCount, moving);
	printf("awake bodies: %d\n", SceneWorld_AwakeCount(&run->world));
	printf("contacts: %d touching, %d pairs\n", counters.touchingCount, counters.contactCount);
	printf("mean step: %.4f ms\n", run->steps > 0 ? run->stepMilliseconds / run->steps : 0.0);
	printf("largest penetration: %.6f m\n", (double)SceneWorld_LargestPenetration(&run->world));
	printf("kinetic energy: %.6g J\n", (double)SceneWorld_KineticEnergy(&run->world));
	// The same scene and methods give the same hash on every platform (the browser build's test
	// compares it with this line).
	printf("state hash: %016llx\n", (unsigned long long)tbWorld_GetStateHash(run->world.worldId));
}

static bool OpenOutputs(Run* run)
{
	const Options* options = run->options;
	if (options->pngDir != NULL)
	{
		if (mkdir(options->pngDir, 0777) != 0 && errno != EEXIST)
		{
			Fail("cannot create directory %s (%s)", options->pngDir, strerror(errno));
			return false;
		}
		run->frame = RenderImage_Create(options->width, options->height, options->render.background);
	}
	if (options->sheetPath != NULL)
	{
		int tileWidth = options->sizeGiven ? options->width : 320;
		int tileHeight = options->sizeGiven ? options->height : 240;
		run->sheet = RenderSheet_Create(options->frames, tileWidth, tileHeight, options->render.background);
		if (run->sheet.image.pixels == NULL)
		{
			Fail("contact sheet too large (%d frames of %dx%d)", options->frames, tileWidth, tileHeight);
			return false;
		}
	}
	if (options->csvPath != NULL)
	{
		run->csv = fopen(options->csvPath, "w");
		if (run->csv == NULL)
		{
			Fail("cannot write %s (%s)", options->csvPath, strerror(errno));
			return false;
		}
		fprintf(run->csv, "step,body,x,y,angle,vx,vy,omega\n");
	}
	return true;
}

static bool CloseOutputs(Run* run, bool ok)
{
	if (run->csv != NULL && fclose(run->csv) != 0 && ok)
	{
		ok = Fail("cannot write %s", run->options->csvPath) == 0;
	}
	if (ok && run->sheet.image.pixels != NULL && RenderImage_WritePNG(&run->sheet.image, run->options->sheetPath) == false)
	{
		ok = Fail("cannot write %s", run->options->sheetPath) == 0;
	}
	RenderImage_Destroy(&run->frame);
	RenderSheet_Destroy(&run->sheet);
	return ok;
}

static int RunScene(const char* name, const Options* options, bool summary)
{
	Scene* scene = LoadScene(name);
	if (scene == NULL)
	{
		return 1;
	}
	Run run;
	memset(&run, 0, sizeof(run));
	run.options = options;
	run.scene = scene;
	run.interactive = isatty(fileno(stderr)) != 0;
	run.steps = options->steps >= 0 ? options->steps : scene->steps;
	run.subSteps = options->overrides.subSteps > 0 ? options->overrides.subSteps : scene->subSteps;
	SceneOverrides overrides = options->overrides;
	overrides.tasks = options->workers > 1 ? TaskSystem_Create(options->workers) : NULL;
	if (options->workers > 1 && overrides.tasks == NULL)
	{
		Scene_Destroy(scene);
		return Fail("--workers %d: could not start the threads", options->workers);
	}
	run.world = Scene_BuildWorld(scene, &overrides);
	bool ok = TB_IS_NON_NULL(run.world.worldId);
	if (ok == false)
	{
		Fail("%s: the world could not be created", name);
	}
	int width = run.sheet.tile.width > 0 ? run.sheet.tile.width : options->width;
	run.view = options->viewGiven ? options->view : Render_FitView(&run.world, width, options->height);
	ok = ok && OpenOutputs(&run) && Observe(&run, 0) && StepAll(&run);
	ok = CloseOutputs(&run, ok);
	if (ok && summary)
	{
		PrintSummary(&run, name);
	}
	SceneWorld_Destroy(&run.world);
	TaskSystem_Destroy(overrides.tasks);
	Scene_Destroy(scene);
	return ok ? 0 : 1;
}

int main(int argc, char** argv)
{
	if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)
	{
		PrintUsage();
		return argc < 2 ? 1 : 0;
	}
	const char* command = argv[1];
	if (strcmp(command, "list") == 0)
	{
		return argc == 2 ? List() : Fail("list takes no arguments");
	}
	if (argc < 3)
	{
		return Fail("%s needs a SCENE (see tumble --help)", command);
	}
	if (strcmp(command, "export") == 0)
	{
		return argc == 3 ? Export(argv[2]) : Fail("export takes only a SCENE");
	}
	bool isSheet = strcmp(command, "sheet") == 0;
	if (strcmp(command, "run") != 0 && isSheet == false)
	{
		return Fail("unknown command '%s' (list, run, export, sheet)", command);
	}
	Options options;
	int status = ParseOptions(&options, argc - 3, argv + 3);
	if (status != 0)
	{
		return status;
	}
	if (isSheet && options.sheetPath == NULL)
	{
		return Fail("sheet needs --out FILE.png");
	}
	return RunScene(argv[2], &options, isSheet == false);
}
