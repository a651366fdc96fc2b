// Determinism: the same scene gives bit-identical trajectories whatever the broad phase (every
// method reports the same pairs in the same order), and stepping the same scene twice gives the
// same bits. The scene is the shared catalogue's rain of mixed shapes (rain_rigid), so contacts
// begin and end throughout.
#include <criterion/criterion.h>

#include "catalogue.h"
#include "scene.h"
#include "task_system.h"
#include "test_helpers.h"

#include "tumble/tumble.h"

#include <math.h>
#include <string.h>

/// FNV-1a over the bytes of every body's transform and velocities.
static uint64_t HashWorld(const SceneWorld* sw)
{
	uint64_t hash = 1469598103934665603ull;
	for (int i = 0; i < sw->bodyCount; ++i)
	{
		tbTransform xf = tbBody_GetTransform(sw->bodyIds[i]);
		tbVec2 v = tbBody_GetLinearVelocity(sw->bodyIds[i]);
		float w = tbBody_GetAngularVelocity(sw->bodyIds[i]);
		float values[7] = {xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y, w};
		const unsigned char* bytes = (const unsigned char*)values;
		for (size_t k = 0; k < sizeof(values); ++k)
		{
			hash = (hash ^ bytes[k]) * 1099511628211ull;
		}
	}
	return hash;
}

/// The scene's world with the broad phase `method`, on `tasks` (NULL: no task system).
static SceneWorld BuildWithBroadPhase(const Scene* scene, tbBroadPhaseMethod method, TaskSystem* tasks)
{
	SceneOverrides overrides;
	memset(&overrides, 0, sizeof(overrides));
	overrides.methods.broadPhase = method;
	overrides.methods.hasBroadPhase = true;
	overrides.tasks = tasks;
	SceneWorld sw = Scene_BuildWorld(scene, &overrides);
	cr_assert(tbWorld_IsValid(sw.worldId));
	return sw;
}

static uint64_t RunRain(tbBroadPhaseMethod method, int steps, int* contacts)
{
	Scene* scene = Catalogue_Build("rain_rigid");
	cr_assert_not_null(scene);
	SceneWorld sw = BuildWithBroadPhase(scene, method, NULL);
	cr_assert_eq(tbWorld_GetDef(sw.worldId).broadPhase, method == tb_broadPhaseAuto ? tb_broadPhaseTree : method);
	*contacts = 0;
	for (int i = 0; i < steps; ++i)
	{
		tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
		*contacts += tbWorld_GetCounters(sw.worldId).touchingCount;
	}
	uint64_t hash = HashWorld(&sw);
	SceneWorld_Destroy(&sw);
	Scene_Destroy(scene);
	return hash;
}

Test(determinism, trajectories_identical_under_every_broad_phase)
{
	int contactsTree, contactsSweep, contactsBrute, contactsHash;
	uint64_t tree = RunRain(tb_broadPhaseTree, 120, &contactsTree);
	uint64_t sweep = RunRain(tb_broadPhaseSortAndSweep, 120, &contactsSweep);
	uint64_t brute = RunRain(tb_broadPhaseBruteForce, 120, &contactsBrute);
	uint64_t hash = RunRain(tb_broadPhaseSpatialHash, 120, &contactsHash);
	// The scene must actually collide, or the comparison proves nothing.
	cr_assert_gt(contactsTree, 1000);
	cr_assert_eq(tree, sweep, "sort-and-sweep trajectory differs from the tree's");
	cr_assert_eq(tree, brute, "brute-force trajectory differs from the tree's");
	cr_assert_eq(tree, hash, "spatial-hash trajectory differs from the tree's");
	cr_assert_eq(contactsTree, contactsHash);
	cr_assert_eq(contactsTree, contactsSweep);
	cr_assert_eq(contactsTree, contactsBrute);
}

Test(determinism, same_scene_twice_gives_same_bits)
{
	int a, b;
	cr_assert_eq(RunRain(tb_broadPhaseAuto, 90, &a), RunRain(tb_broadPhaseAuto, 90, &b));
	cr_assert_eq(a, b);
}

/// 1,000 circles (r 0.5) in rows 2 m apart streaming past each other at ±12 m/s along x (rows
/// alternate direction; circles 2 m apart in a row, so nothing touches): each moves 0.2 m per step,
/// more than its fat box holds for long, so about half the proxies move every step, yet no body
/// moves more than the 0.25 m that speculative contacts cover, so none is fast; there is no static
/// geometry. This is the regime where the spatial hash (same sizes) or sort-and-sweep (spread
/// sizes) beats the tree (tumble-bench-broadphase). With spreadSizes every fifth circle has radius
/// 3 and the rows are 8 m apart.
static uint64_t RunDriftOf(int count, tbBroadPhaseMethod method, bool spreadSizes, tbBroadPhaseMethod* chosen)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, 0.0f);
	def.broadPhase = method;
	tbWorldId world = tbCreateWorld(&def);
	tbBodyId bodies[1000];
	for (int i = 0; i < count; ++i)
	{
		float direction = (i / 32) % 2 == 0 ? 1.0f : -1.0f;
		tbBodyDef bd = tbDefaultBodyDef();
		bd.type = tb_dynamicBody;
		float spacing = spreadSizes ? 8.0f : 2.0f;
		bd.position = tbMakeVec2(spacing * (float)(i % 32), spacing * (float)(i / 32));
		bd.linearVelocity = tbMakeVec2(12.0f * direction, 0.0f);
		bodies[i] = tbCreateBody(world, &bd);
		tbShapeDef sd = tbDefaultShapeDef();
		tbCircle circle = {{0.0f, 0.0f}, spreadSizes && i % 5 == 0 ? 3.0f : 0.5f};
		tbCreateCircleShape(bodies[i], &sd, &circle);
	}
	for (int i = 0; i < 240; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	*chosen = tbWorld_GetDef(world).broadPhase;
	uint64_t hash = 1469598103934665603ull;
	for (int i = 0; i < count; ++i)
	{
		tbTransform xf = tbBody_GetTransform(bodies[i]);
		const unsigned char* bytes = (const unsigned char*)&xf;
		for (size_t k = 0; k < sizeof(xf); ++k)
		{
			hash = (hash ^ bytes[k]) * 1099511628211ull;
		}
	}
	tbDestroyWorld(world);
	return hash;
}

static uint64_t RunDrift(tbBroadPhaseMethod method, bool spreadSizes, tbBroadPhaseMethod* chosen)
{
	return RunDriftOf(1000, method, spreadSizes, chosen);
}

// 1,000 moving circles of one size: auto switches from the tree to the spatial hash; with one in
// five six times wider (90th percentile of sizes 6× the median), to sort-and-sweep. Either way the
// trajectory is the tree's, bit for bit.
Test(determinism, auto_broad_phase_picks_hash_or_sweep_for_moving_scenes)
{
	for (int spread = 0; spread < 2; ++spread)
	{
		tbBroadPhaseMethod autoChoice, treeChoice;
		uint64_t autoHash = RunDrift(tb_broadPhaseAuto, spread == 1, &autoChoice);
		uint64_t treeHash = RunDrift(tb_broadPhaseTree, spread == 1, &treeChoice);
		tbBroadPhaseMethod expected = spread == 1 ? tb_broadPhaseSortAndSweep : tb_broadPhaseSpatialHash;
		cr_assert_eq(autoChoice, expected, "spread %d: auto chose %d", spread, (int)autoChoice);
		cr_assert_eq(treeChoice, tb_broadPhaseTree);
		cr_assert_eq(autoHash, treeHash, "switching broad phase changed the trajectory");
	}
}

// A new world's first vote window (5 steps) counts the proxies that moved in it, not the moves per
// step, and decides alone: 1,000 circles of one size dropped from rest leave their fresh fat boxes
// together at the window's last step, every proxy once, so auto is on the spatial hash after step 5.
// Counted per step (a fifth of the proxies) the first window kept it on the tree until step 10.
// The counters are taken after the switch: the tree's heights are 0 and the bytes are the world's
// after it. A pyramid built at rest moves no proxy and stays on the tree.
Test(determinism, auto_broad_phase_leaves_the_tree_after_the_first_window)
{
	tbWorldDef def = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&def);
	tbShapeDef sd = tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	for (int i = 0; i < 1000; ++i)
	{
		tbVec2 p = tbMakeVec2(2.0f * (float)(i % 40), 2.0f * (float)(i / 40));
		tbCreateCircleShape(CreateBody(world, tb_dynamicBody, p), &sd, &circle);
	}
	StepWorld(world, 4, 1.0f / 60.0f, 4);
	cr_expect_eq(tbWorld_GetDef(world).broadPhase, tb_broadPhaseTree, "before the first vote: %d",
				 (int)tbWorld_GetDef(world).broadPhase);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	cr_expect_eq(tbWorld_GetDef(world).broadPhase, tb_broadPhaseSpatialHash, "after the first window: %d",
				 (int)tbWorld_GetDef(world).broadPhase);
	tbCounters c = tbWorld_GetCounters(world);
	cr_expect(c.treeHeight == 0 && c.staticTreeHeight == 0, "tree heights %d, %d", c.treeHeight, c.staticTreeHeight);
	cr_expect_eq(c.byteCount, tbGetByteCount());
	tbDestroyWorld(world);

	world = tbCreateWorld(&def);
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 20.0f, 0.5f, NULL);
	for (int row = 0; row < 10; ++row)
	{
		for (int i = 0; i < 10 - row; ++i)
		{
			tbVec2 p = {(float)i * 1.05f + 0.525f * (float)row - 5.0f, 0.5f + (float)row};
			CreateBox(world, tb_dynamicBody, p, 0.5f, 0.5f, 1.0f);
		}
	}
	StepWorld(world, 10, 1.0f / 60.0f, 4);
	cr_expect_eq(tbWorld_GetDef(world).broadPhase, tb_broadPhaseTree, "resting pyramid: %d",
				 (int)tbWorld_GetDef(world).broadPhase);
	tbDestroyWorld(world);
}

// A small world, 64 moving circles of one size (a game's room, a world per match): auto switches from
// the tree to sort-and-sweep, which costs least when few proxies all move (world.c), and the
// trajectory is the tree's, bit for bit.
Test(determinism, auto_broad_phase_picks_sweep_for_a_small_moving_world)
{
	tbBroadPhaseMethod autoChoice, treeChoice;
	uint64_t autoHash = RunDriftOf(64, tb_broadPhaseAuto, false, &autoChoice);
	uint64_t treeHash = RunDriftOf(64, tb_broadPhaseTree, false, &treeChoice);
	cr_assert_eq(autoChoice, tb_broadPhaseSortAndSweep, "auto chose %d", (int)autoChoice);
	cr_assert_eq(autoHash, treeHash, "switching broad phase changed the trajectory");
}

/// A scene stepped on a reference task system of `threads` threads (1: no task system), the world
/// told to use `workers` of them (tbWorld_SetWorkerCount; a pool of more threads than that breaks
/// the task callback's contract); the hash of every body's state at the end, and the events
/// counted on the way.
static uint64_t RunScene(const Scene* scene, int threads, int workers, int steps, int* events)
{
	SceneOverrides overrides;
	memset(&overrides, 0, sizeof(overrides));
	overrides.tasks = threads > 1 ? TaskSystem_Create(threads) : NULL;
	cr_assert(threads == 1 || overrides.tasks != NULL);
	SceneWorld sw = Scene_BuildWorld(scene, &overrides);
	cr_assert(tbWorld_IsValid(sw.worldId));
	if (workers != threads)
	{
		tbWorld_SetWorkerCount(sw.worldId, workers);
	}
	*events = 0;
	for (int i = 0; i < steps; ++i)
	{
		tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
		tbContactEvents e = tbWorld_GetContactEvents(sw.worldId);
		*events += e.beginCount + 3 * e.endCount;
	}
	uint64_t hash = HashWorld(&sw);
	SceneWorld_Destroy(&sw);
	TaskSystem_Destroy(overrides.tasks);
	return hash;
}

/// A scene on a reference task system of `workers` workers, as RunScene.
static uint64_t RunSceneOnWorkers(const Scene* scene, int workers, int steps, int* events)
{
	return RunScene(scene, workers, workers, steps, events);
}

/// A catalogue scene, as RunSceneOnWorkers.
static uint64_t RunOnWorkers(const char* name, int workers, int steps, int* events)
{
	Scene* scene = Catalogue_Build(name);
	cr_assert_not_null(scene);
	uint64_t hash = RunSceneOnWorkers(scene, workers, steps, events);
	Scene_Destroy(scene);
	return hash;
}

/// The order in which a query over the whole world visits the shapes (FNV-1a over their ids): the
/// order follows the broad phase's tree, so two trees built differently visit differently.
static bool HashVisit(tbShapeId shapeId, void* context)
{
	uint64_t* hash = context;
	*hash = (*hash ^ (uint64_t)(uint32_t)shapeId.index1) * 1099511628211ull;
	return true;
}

// On workers the movable tree is queried before its refresh, which runs beside the narrow phase
// (broad_phase.h, tbBroadPhase_UpdatePairsOnWorkers); on one worker it is refreshed first. The
// pairs, and so the trajectory, must be the same, and so must the refreshed tree: a query after
// every step visits the shapes in the tree's order, and that order is hashed step by step. The
// tumbler (tree broad phase forced) moves hundreds of proxies a step: both the re-insertion and
// the partial rebuild run.
Test(determinism, tree_refreshed_beside_the_narrow_phase_is_the_same_tree)
{
	uint64_t bodies[2] = {0, 0}, visits[2] = {0, 0};
	for (int run = 0; run < 2; ++run)
	{
		Scene* scene = Catalogue_Build("tumbler");
		cr_assert_not_null(scene);
		TaskSystem* tasks = run == 1 ? TaskSystem_Create(2) : NULL;
		cr_assert(run == 0 || tasks != NULL);
		SceneWorld sw = BuildWithBroadPhase(scene, tb_broadPhaseTree, tasks);
		uint64_t visit = 1469598103934665603ull;
		for (int i = 0; i < 90; ++i)
		{
			tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
			tbWorld_OverlapAABB(sw.worldId, tbPos_zero, tbWorld_GetBounds(sw.worldId), tbDefaultQueryFilter(), HashVisit,
								&visit);
		}
		bodies[run] = HashWorld(&sw);
		visits[run] = visit;
		SceneWorld_Destroy(&sw);
		TaskSystem_Destroy(tasks);
		Scene_Destroy(scene);
	}
	cr_expect_eq(bodies[1], bodies[0], "2 workers: other trajectories than 1");
	cr_expect_eq(visits[1], visits[0], "2 workers: the tree visits the shapes in another order than 1's");
}

// On workers the sub-step parts of the profile are timed by whichever thread leads the stages
// (solver_workers.c): each part is still part of the solve, and the passes of a pile are there.
Test(determinism, solve_profile_parts_on_workers)
{
	Scene* scene = Catalogue_Build("tumbler");
	cr_assert_not_null(scene);
	SceneOverrides overrides;
	memset(&overrides, 0, sizeof(overrides));
	overrides.tasks = TaskSystem_Create(2);
	cr_assert_not_null(overrides.tasks);
	SceneWorld sw = Scene_BuildWorld(scene, &overrides);
	for (int i = 0; i < 30; ++i)
	{
		tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
	}
	tbProfile p = tbWorld_GetProfile(sw.worldId);
	const float parts[10] = {p.solverSetup,	  p.prepareConstraints, p.integrateVelocities, p.warmStart,
							 p.solveImpulses, p.integratePositions, p.relaxImpulses,	   p.applyRestitution,
							 p.storeImpulses, p.scatterBodies};
	float sum = 0.0f;
	for (int i = 0; i < 10; ++i)
	{
		cr_assert(parts[i] >= 0.0f, "part %d: %g ms", i, (double)parts[i]);
		sum += parts[i];
	}
	cr_assert(sum <= p.solve * 1.0001f + 1e-6f, "parts %g ms of a %g ms solve", (double)sum, (double)p.solve);
	cr_assert(p.solveImpulses > 0.0f && p.relaxImpulses > 0.0f && p.warmStart > 0.0f,
			  "2,025 boxes in contact: solve %g, relax %g, warm start %g ms", (double)p.solveImpulses,
			  (double)p.relaxImpulses, (double)p.warmStart);
	SceneWorld_Destroy(&sw);
	TaskSystem_Destroy(overrides.tasks);
	Scene_Destroy(scene);
}

// The step on 1, 2, 4 and 8 workers gives the same bits: every unit of parallel work writes only
// its own data (contacts, bodies, blocks of one colour), and everything appended or counted is
// done afterwards in a fixed order. Scenes: rain_rigid (shapes of every kind, joints off), ragdolls
// (small mechanisms: joint trees, whole mechanisms per unit), tumbler (a kinematic body in many
// blocks of one colour), joint_grid (one mechanism of 19,800 joints, solved colour by colour).
Test(determinism, identical_on_any_number_of_workers)
{
	const char* names[4] = {"rain_rigid", "ragdolls", "tumbler", "joint_grid"};
	for (int n = 0; n < 4; ++n)
	{
		int events1;
		uint64_t one = RunOnWorkers(names[n], 1, 120, &events1);
		for (int workers = 2; workers <= 8; workers *= 2)
		{
			int events;
			uint64_t hash = RunOnWorkers(names[n], workers, 120, &events);
			cr_assert_eq(hash, one, "%s: %d workers differ from 1", names[n], workers);
			cr_assert_eq(events, events1, "%s: %d workers report other events", names[n], workers);
		}
	}
}

// Separate piles are solved in island partitions on workers (constraint_graph.c): each worker takes
// its own run of bodies through every sub-step stage with no barrier. Four pyramids of 21 boxes,
// built one after another, sleep off: 2 and 4 workers cut them into 2 and 4 even runs; 8 workers
// cannot (four piles), so they share the stages. Every count must give 1 worker's bits.
Test(determinism, separate_piles_identical_on_any_number_of_workers)
{
	Scene* scene = Scene_Create();
	cr_assert_not_null(scene);
	scene->enableSleep = false;
	int ground = Scene_AddBody(scene, tb_staticBody, tbMakeVec2(0.0f, -0.5f), 0.0f);
	tbGeometry floor = Scene_MakeBoxGeometry(60.0f, 0.5f, tbMakeVec2(0.0f, 0.0f), 0.0f);
	Scene_AddGeometry(scene, ground, &floor, 0.0f, 0.6f);
	tbGeometry box = Scene_MakeBoxGeometry(0.5f, 0.5f, tbMakeVec2(0.0f, 0.0f), 0.0f);
	for (int pile = 0; pile < 4; ++pile)
	{
		float x0 = -36.0f + 24.0f * (float)pile;
		for (int row = 0; row < 6; ++row)
		{
			for (int i = 0; i < 6 - row; ++i)
			{
				float x = x0 + (float)i * 1.05f + 0.525f * (float)row;
				int body = Scene_AddBody(scene, tb_dynamicBody, tbMakeVec2(x, 0.5f + (float)row), 0.0f);
				Scene_AddGeometry(scene, body, &box, 1.0f, 0.6f);
			}
		}
	}
	int events1;
	uint64_t one = RunSceneOnWorkers(scene, 1, 120, &events1);
	for (int workers = 2; workers <= 8; workers *= 2)
	{
		int events;
		uint64_t hash = RunSceneOnWorkers(scene, workers, 120, &events);
		cr_assert_eq(hash, one, "%d workers differ from 1", workers);
		cr_assert_eq(events, events1, "%d workers report other events", workers);
	}
	// The partitions follow the worker count when it changes on a steady pile (the colours are
	// kept from step to step, and made again for the new count).
	SceneOverrides overrides;
	memset(&overrides, 0, sizeof(overrides));
	overrides.tasks = TaskSystem_Create(2);
	cr_assert_not_null(overrides.tasks);
	SceneWorld sw = Scene_BuildWorld(scene, &overrides);
	for (int i = 0; i < 120; ++i)
	{
		tbWorld_SetWorkerCount(sw.worldId, i < 40 || i >= 80 ? 2 : 1);
		tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
	}
	cr_assert_eq(HashWorld(&sw), one, "worker count changed on the way: other bits than 1 worker's");
	SceneWorld_Destroy(&sw);
	TaskSystem_Destroy(overrides.tasks);
	Scene_Destroy(scene);
}

static void CountError(const char* message, void* context)
{
	int* count = context;
	*count += strstr(message, "worker index") != NULL ? 1 : 0;
}

// A task system that hands out worker indices at or beyond the world's worker count breaks the
// callback's contract (a pool of 4 threads serving a world told to use 2, tbWorld_SetWorkerCount):
// the step's per-worker buffers must not be overrun. The ranges run in spare slots, each step
// reports the broken contract, and the results are 1 worker's bits.
// The task interface leaves the splitting and the worker indices to the library, so any task system
// that runs each callback once gives 1 worker's bits: a pool with more threads than the world's
// workers; one that runs every task inside enqueue; one that runs none until it is asked to finish
// it, and then the last enqueued first (the caller has done all the work by then).
typedef struct LazyTasks
{
	tbTaskCallback* task[64];
	void* context[64];
	bool done[64];
	int count;
} LazyTasks;

static void* InlineEnqueue(tbTaskCallback* task, void* taskContext, void* userContext)
{
	(void)userContext;
	task(taskContext);
	return NULL;
}

static void* LazyEnqueue(tbTaskCallback* task, void* taskContext, void* userContext)
{
	LazyTasks* lazy = userContext;
	if (lazy->count == 64)
	{
		task(taskContext);
		return NULL;
	}
	int i = lazy->count++;
	lazy->task[i] = task;
	lazy->context[i] = taskContext;
	lazy->done[i] = false;
	return lazy->done + i;
}

static void LazyFinish(void* userTask, void* userContext)
{
	LazyTasks* lazy = userContext;
	for (int i = lazy->count - 1; i >= 0; --i) // the last enqueued first
	{
		if (lazy->done[i] == false)
		{
			lazy->done[i] = true;
			lazy->task[i](lazy->context[i]);
		}
	}
	(void)userTask;
	lazy->count = 0;
}

static uint64_t RunWithTasks(const Scene* scene, tbEnqueueTaskCallback* enqueue, tbFinishTaskCallback* finish,
							 void* user, int workers, int* events)
{
	SceneOverrides overrides;
	memset(&overrides, 0, sizeof(overrides));
	overrides.enqueueTask = enqueue;
	overrides.finishTask = finish;
	overrides.userTaskContext = user;
	overrides.workerCount = workers;
	SceneWorld sw = Scene_BuildWorld(scene, &overrides);
	cr_assert(tbWorld_IsValid(sw.worldId));
	*events = 0;
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
		tbContactEvents e = tbWorld_GetContactEvents(sw.worldId);
		*events += e.beginCount + 3 * e.endCount;
	}
	uint64_t hash = HashWorld(&sw);
	SceneWorld_Destroy(&sw);
	return hash;
}

Test(determinism, any_task_system_gives_one_workers_bits)
{
	Scene* scene = Catalogue_Build("rain_rigid");
	cr_assert_not_null(scene);
	int events1, events;
	uint64_t one = RunSceneOnWorkers(scene, 1, 60, &events1);
	int errors = 0;
	tbSetErrorCallback(CountError, &errors);
	uint64_t hash = RunScene(scene, 4, 2, 60, &events); // a pool of 4 threads, 2 workers
	cr_expect_eq(hash, one, "a larger pool: other bits than 1 worker's");
	cr_expect_eq(events, events1);
	hash = RunWithTasks(scene, InlineEnqueue, LazyFinish, NULL, 4, &events);
	cr_expect_eq(hash, one, "tasks run inside enqueue: other bits than 1 worker's");
	cr_expect_eq(events, events1);
	LazyTasks lazy = {0};
	hash = RunWithTasks(scene, LazyEnqueue, LazyFinish, &lazy, 4, &events);
	cr_expect_eq(hash, one, "tasks run late and backwards: other bits than 1 worker's");
	cr_expect_eq(events, events1);
	tbSetErrorCallback(NULL, NULL);
	cr_expect_eq(errors, 0);
	Scene_Destroy(scene);
}

// A world on workers with nothing awake (ground only, then a body that has fallen asleep) steps
// and reports no move events. The finalize stage once offset a NULL move-event array by zero
// there, undefined behaviour that the sanitizer build of the test command stops at.
Test(determinism, workers_step_a_world_with_nothing_awake)
{
	TaskSystem* tasks = TaskSystem_Create(2);
	cr_assert(tasks != NULL);
	tbWorldDef def = tbDefaultWorldDef();
	def.workerCount = TaskSystem_WorkerCount(tasks);
	def.enqueueTask = TaskSystem_Enqueue;
	def.finishTask = TaskSystem_Finish;
	def.userTaskContext = tasks;
	tbWorldId world = tbCreateWorld(&def);
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon floor = tbMakeBox(10.0f, 0.5f);
	tbCreatePolygonShape(ground, &shapeDef, &floor);
	for (int i = 0; i < 5; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
		cr_expect_eq(tbWorld_GetBodyEvents(world).moveCount, 0);
	}
	tbBodyDef boxDef = tbDefaultBodyDef();
	boxDef.type = tb_dynamicBody;
	boxDef.position = tbMakeVec2(0.0f, 1.0f);
	tbBodyId box = tbCreateBody(world, &boxDef);
	tbPolygon square = tbMakeSquare(0.5f);
	tbCreatePolygonShape(box, &shapeDef, &square);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	cr_expect_eq(tbWorld_GetBodyEvents(world).moveCount, 1);
	// Resting on the ground it falls asleep after TB_TIME_TO_SLEEP (0.5 s): give it 2 s.
	for (int i = 0; i < 120; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	cr_expect(tbBody_IsAwake(box) == false);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	cr_expect_eq(tbWorld_GetBodyEvents(world).moveCount, 0);
	tbDestroyWorld(world);
	TaskSystem_Destroy(tasks);
}

// The hash's hysteresis (world.c, TB_AUTO_HASH_KEEP): 200 circles in ten rows drifting alike, beside
// 300 static boxes (so not sort-and-sweep: statics outnumber the movable proxies). All drifting,
// auto takes the spatial hash; with two rows still drifting (20 % of the movable proxies moved a step, between
// TB_AUTO_HASH_KEEP and the 25 % that picks the hash) it keeps the hash instead of switching back and
// forth; with all stopped it returns to the tree. The trajectory is the tree's, bit for bit.
static uint64_t RunHysteresis(tbBroadPhaseMethod method, tbBroadPhaseMethod chosen[3])
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, 0.0f);
	def.enableSleep = false;
	def.broadPhase = method;
	tbWorldId world = tbCreateWorld(&def);
	tbBodyDef bd = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	for (int i = 0; i < 300; ++i)
	{
		tbPolygon box = tbMakeOffsetBox(0.5f, 0.5f, tbMakeVec2(3.0f * (float)(i % 30), -20.0f - 3.0f * (float)(i / 30)),
										tbMakeRot(0.0f));
		tbCreatePolygonShape(ground, &sd, &box);
	}
	tbBodyId bodies[200];
	bd.type = tb_dynamicBody;
	for (int i = 0; i < 200; ++i)
	{
		bd.position = tbMakeVec2(2.0f * (float)(i % 20), 2.0f * (float)(i / 20));
		bd.linearVelocity = tbMakeVec2(12.0f, 0.0f); // all alike: they never meet
		bodies[i] = tbCreateBody(world, &bd);
		tbCircle circle = {{0.0f, 0.0f}, 0.5f};
		tbCreateCircleShape(bodies[i], &sd, &circle);
	}
	for (int phase = 0; phase < 3; ++phase)
	{
		for (int i = 0; i < 200 && phase > 0; ++i)
		{
			bool drifts = phase == 1 && (i / 20) % 5 == 0; // two rows of ten: a fifth
			tbVec2 v = tbBody_GetLinearVelocity(bodies[i]);
			tbBody_SetLinearVelocity(bodies[i], drifts ? v : tbMakeVec2(0.0f, 0.0f));
		}
		for (int step = 0; step < 240; ++step)
		{
			tbWorld_Step(world, 1.0f / 60.0f, 4);
		}
		chosen[phase] = tbWorld_GetDef(world).broadPhase;
	}
	uint64_t hash = tbWorld_GetStateHash(world);
	tbDestroyWorld(world);
	return hash;
}

Test(determinism, auto_broad_phase_keeps_the_hash_near_its_threshold)
{
	tbBroadPhaseMethod autoChoice[3], treeChoice[3];
	uint64_t autoHash = RunHysteresis(tb_broadPhaseAuto, autoChoice);
	uint64_t treeHash = RunHysteresis(tb_broadPhaseTree, treeChoice);
	cr_assert_eq(autoChoice[0], tb_broadPhaseSpatialHash, "all drifting: auto chose %d", (int)autoChoice[0]);
	cr_assert_eq(autoChoice[1], tb_broadPhaseSpatialHash, "a fifth drifting: auto chose %d", (int)autoChoice[1]);
	cr_assert_eq(autoChoice[2], tb_broadPhaseTree, "all stopped: auto chose %d", (int)autoChoice[2]);
	cr_assert_eq(autoHash, treeHash, "switching broad phase changed the trajectory");
}
