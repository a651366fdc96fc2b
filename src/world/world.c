// The world: creation and destruction, the registry that turns handles into worlds, the step as
// a pipeline of named stages, settings, events, profile and counters.
//
// Handles: a world id is (slot + 1, generation). The registry below is the one piece of global
// state besides the hooks in core.c; it exists because value handles must be resolved without
// pointers. Body and shape ids carry the world slot too.
#include "world.h"

#include "chain.h"
#include "continuous.h"
#include "island.h"
#include "recording.h"

#include "joints/joint.h"
#include "solver/constraint_graph.h"
#include "solver/solver.h"

#include "core/array.h"
#include "core/sort.h"
#include "core/task.h"

#include <stddef.h>
#include <string.h>

static tbWorld* s_worlds[TB_MAX_WORLDS];
static uint16_t s_worldGenerations[TB_MAX_WORLDS];
// Per world slot: the largest body, shape, joint and chain generations handed out by the worlds
// that used the slot (see tbWorld::bodyGenerationBase). Generations wrap at 2^16, like every
// generation.
static uint16_t s_bodyGenerations[TB_MAX_WORLDS];
static uint16_t s_shapeGenerations[TB_MAX_WORLDS];
static uint16_t s_jointGenerations[TB_MAX_WORLDS];
static uint16_t s_chainGenerations[TB_MAX_WORLDS];

#define TB_WORLD_DEF_MAGIC 0x7B3A1C01

tbWorldDef tbDefaultWorldDef(void)
{
	tbWorldDef def;
	memset(&def, 0, sizeof(def));
	def.gravity = tbMakeVec2(0.0f, -10.0f);
	// Speeds in length units per second (tbSetLengthUnitsPerMeter; 1 by default).
	float units = tbGetLengthUnitsPerMeter();
	def.restitutionThreshold = 1.0f * units;
	def.hitEventThreshold = 1.0f * units;
	def.contactHertz = 30.0f;
	def.contactDampingRatio = 10.0f;
	def.settledHertzRatio = 1.75f;
	def.contactHertzFollowsSubStep = false;
	def.contactSpeed = 3.0f * units;
	def.maximumLinearSpeed = tbMinFloat(4000.0f * units, TB_MAX_LINEAR_SPEED);
	def.enableSleep = true;
	def.enableContinuous = true;
	def.enableContactSoftening = false;
	def.broadPhase = tb_broadPhaseAuto;
	def.narrowPhase = tb_narrowPhaseAuto;
	def.continuous = tb_continuousDefault;
	def.solver = tb_solverSoft;
	def.velocityIterations = 8;
	def.positionIterations = 3;
	def.relaxIterations = 1;
	def.finalRelaxIterations = 1;
	def.enableWideSolver = true;
	def.enableJointTrees = true;
	def.enableWarmStarting = true;
	def.enableManifoldRecycling = true;
	def.enableCentralFriction = true;
	def.workerCount = 1;
	def.internalValue = TB_WORLD_DEF_MAGIC;
	return def;
}

tbWorld* tbGetWorldFromIndex(int index)
{
	return s_worlds[index];
}

tbWorld* tbGetWorldChecked(tbWorldId id, const char* function)
{
	if (id.index1 == 0)
	{
		tbReportError(function, "worldId is null; create a world with tbCreateWorld first");
		return NULL;
	}
	int index = id.index1 - 1;
	if (index >= TB_MAX_WORLDS || s_worlds[index] == NULL || s_worlds[index]->generation != id.generation)
	{
		tbReportError(function, "worldId refers to a destroyed world; do not use a world id after tbDestroyWorld");
		return NULL;
	}
	return s_worlds[index];
}

static bool tbCheckMethods(const tbWorldDef* def, const char* function)
{
	if ((unsigned)def->broadPhase >= tb_broadPhaseMethodCount || (unsigned)def->continuous >= tb_continuousMethodCount ||
		(unsigned)def->solver >= tb_solverMethodCount || (unsigned)def->narrowPhase > tb_narrowPhaseGJK)
	{
		tbReportError(function, "def has an unknown method value; use the tb_broadPhase*/tb_narrowPhase*/tb_continuous*/"
								"tb_solver* enum values");
		return false;
	}
	if (def->velocityIterations < 1 || def->positionIterations < 0 || def->relaxIterations < 0 ||
		def->finalRelaxIterations < 0 || def->velocityIterations > TB_MAX_ITERATIONS ||
		def->positionIterations > TB_MAX_ITERATIONS || def->relaxIterations > TB_MAX_ITERATIONS ||
		def->finalRelaxIterations > TB_MAX_ITERATIONS)
	{
		tbReportError(function, "def iterations are %d velocity, %d position, %d relax, %d final relax (velocity must "
								"be 1..%d, the others 0..%d, TB_MAX_ITERATIONS)", def->velocityIterations,
					  def->positionIterations, def->relaxIterations, def->finalRelaxIterations, TB_MAX_ITERATIONS,
					  TB_MAX_ITERATIONS);
		return false;
	}
	if (!(def->settledHertzRatio > 0.0f && def->settledHertzRatio <= 1000.0f))
	{
		tbReportError(function, "def.settledHertzRatio is %g (must be above 0 and at most 1000; 1.75 by default: "
								"settled contacts at 1.75 × contactHertz)", (double)def->settledHertzRatio);
		return false;
	}
	return true;
}

static bool tbCheckMaximumSpeed(const char* f, float speed)
{
	if (tbCheckPositive(f, "def->maximumLinearSpeed", speed) == false)
	{
		return false;
	}
	if (speed > TB_MAX_LINEAR_SPEED)
	{
		tbReportError(f, "def->maximumLinearSpeed is %g m/s, above TB_MAX_LINEAR_SPEED (%g m/s); pass at most that",
					  (double)speed, (double)TB_MAX_LINEAR_SPEED);
		return false;
	}
	return true;
}

static bool tbCheckWorkers(const tbWorldDef* def, const char* f)
{
	if (def->workerCount < 1 || def->workerCount > TB_MAX_WORKERS)
	{
		tbReportError(f, "def->workerCount is %d; pass 1 to %d", def->workerCount, TB_MAX_WORKERS);
		return false;
	}
	if ((def->enqueueTask == NULL) != (def->finishTask == NULL))
	{
		tbReportError(f, "def->enqueueTask and def->finishTask must be given together (or neither)");
		return false;
	}
	return true; // without task callbacks the step runs on the caller, whatever the count
}

/// Capacities are counts: ≥ 0, and small enough that the reserved arrays fit an int of bytes.
static bool tbCheckWorldCapacity(const char* f, const tbCapacity* c)
{
	const int counts[5] = {c->staticShapeCount, c->dynamicShapeCount, c->staticBodyCount, c->dynamicBodyCount,
						   c->contactCount};
	const char* const names[5] = {"staticShapeCount", "dynamicShapeCount", "staticBodyCount", "dynamicBodyCount",
								  "contactCount"};
	for (int i = 0; i < 5; ++i)
	{
		if (counts[i] < 0 || counts[i] > (1 << 22))
		{
			tbReportError(f, "def->capacity.%s is %d; it must be between 0 and %d", names[i], counts[i], 1 << 22);
			return false;
		}
	}
	return true;
}

/// Room for the expected counts (tbCapacity), so that reaching them allocates nothing more.
static void tbReserveCapacity(tbWorld* world, const tbCapacity* c)
{
	int bodies = c->staticBodyCount + c->dynamicBodyCount;
	int shapes = c->staticShapeCount + c->dynamicShapeCount;
	if (bodies > 0)
	{
		TB_ARRAY_RESERVE(world->bodies, world->bodyCapacity, bodies);
	}
	if (c->dynamicBodyCount > 0)
	{
		TB_ARRAY_RESERVE(world->awakeBodies, world->awakeBodyCapacity, c->dynamicBodyCount);
	}
	if (shapes > 0)
	{
		TB_ARRAY_RESERVE(world->shapes, world->shapeCapacity, shapes);
	}
	if (c->contactCount > 0)
	{
		TB_ARRAY_RESERVE(world->contacts, world->contactCapacity, c->contactCount);
	}
}

static bool tbCheckWorldDef(const tbWorldDef* def)
{
	const char* f = "tbCreateWorld";
	if (tbCheckPointer(f, "def", def) == false)
	{
		return false;
	}
	if (def->internalValue != TB_WORLD_DEF_MAGIC)
	{
		tbReportError(f, "def was not initialised by tbDefaultWorldDef(); start from tbDefaultWorldDef() and change "
						 "fields");
		return false;
	}
	return tbCheckVec2(f, "def->gravity", def->gravity) &&
		   tbCheckNonNegative(f, "def->restitutionThreshold", def->restitutionThreshold) &&
		   tbCheckNonNegative(f, "def->hitEventThreshold", def->hitEventThreshold) &&
		   tbCheckPositive(f, "def->contactHertz", def->contactHertz) &&
		   tbCheckNonNegative(f, "def->contactDampingRatio", def->contactDampingRatio) &&
		   tbCheckPositive(f, "def->contactSpeed", def->contactSpeed) &&
		   tbCheckMaximumSpeed(f, def->maximumLinearSpeed) && tbCheckMethods(def, f) && tbCheckWorkers(def, f) &&
		   tbCheckWorldCapacity(f, &def->capacity);
}

/// Auto starts with the dynamic tree: it costs nothing for sleeping and static bodies, handles any
/// size spread and answers queries in O(log n). tbUpdateAutoBroadPhase may switch later.
static tbBroadPhaseMethod tbResolveBroadPhase(tbBroadPhaseMethod method)
{
	return method == tb_broadPhaseAuto ? tb_broadPhaseTree : method;
}

// The automatic broad phase, from the scene's statistics over a window of steps, chosen from
// tumble-bench (catalogue scenes, every method) and tumble-bench-broadphase (boxes drifting;
// docs/methods.md has the figures): the spatial hash is the fastest when many proxies move each
// step and the boxes are of similar sizes (a box then covers few cells and meets only its near
// neighbours, where the tree pays a re-insertion or a rebuild per moved proxy), and the slowest
// when sizes spread widely (large boxes cover many cells, small ones crowd large cells). The tree
// wins when few proxies move (a settled pile: it does nothing for unmoved proxies while the hash
// re-hashes every movable proxy).
// Sort-and-sweep wins for few moving proxies: a nearly sorted list re-sorted by insertion and swept
// once has no per-update set-up, where the hash clears and refills its grid and the tree re-inserts
// or rebuilds (a world of 20 falling bodies: its pairs stage in half the hash's instructions), and
// for sparse similar-size boxes. So: sort-and-sweep when at most TB_AUTO_SWEEP_SMALL movable
// proxies mostly all move, static proxies do not dominate and fast bodies are rare (its queries
// scan linearly); else the hash when more than a quarter of the movable proxies move per step and
// the 90th percentile of their sizes is within TB_AUTO_HASH_SPREAD of the median (kept while more
// than TB_AUTO_HASH_KEEP move); else
// sort-and-sweep under the same conditions up to TB_AUTO_SWEEP_MAX_PROXIES; otherwise the tree. A
// switch needs two windows in a row that agree (hysteresis): windows of 60 steps, 5 while the world
// is young, whose first two windows decide alone.
// Every method reports identical pairs, so switching never changes a trajectory.
#define TB_AUTO_WINDOW 60
/// Windows are shorter while the world is young (its first TB_AUTO_WINDOW steps), so that a scene
/// that suits another method switches by step 10 rather than 120: a short-lived world (a world per
/// match or per training episode) pays the tree's start for few of its steps.
#define TB_AUTO_FIRST_WINDOW 5
#define TB_AUTO_SWEEP_MAX_PROXIES 4096
#define TB_AUTO_SWEEP_SMALL 128
#define TB_AUTO_HASH_SPREAD 4.0f
#define TB_AUTO_HASH_KEEP 0.125f

/// Movable proxies whose sizes the vote sorts at most (tbMovableSizeSpread): every k-th in key order.
/// The vote compares a ratio of percentiles with TB_AUTO_HASH_SPREAD, for which this many samples
/// are plenty; sorting every proxy's size made a vote in a pile of a thousand bodies cost a third of
/// a step, which a young world pays every TB_AUTO_FIRST_WINDOW steps.
#define TB_AUTO_SIZE_SAMPLES 256

/// 90th percentile over median of the movable proxies' largest box side (1 without proxies), from at
/// most TB_AUTO_SIZE_SAMPLES of them spread evenly over the table.
static float tbMovableSizeSpread(const tbBroadPhase* bp, int movable)
{
	if (movable == 0)
	{
		return 1.0f;
	}
	float sides[TB_AUTO_SIZE_SAMPLES];
	int stride = (movable + TB_AUTO_SIZE_SAMPLES - 1) / TB_AUTO_SIZE_SAMPLES;
	int n = 0, seen = 0;
	for (int key = 0; key < bp->table.capacity && n < TB_AUTO_SIZE_SAMPLES; ++key)
	{
		const tbBroadProxy* p = bp->table.proxies + key;
		if (p->isFree == false && p->type != tb_proxyStatic && seen++ % stride == 0)
		{
			tbVec2 d = tbSub(p->aabb.upperBound, p->aabb.lowerBound);
			sides[n++] = tbMaxFloat(d.x, d.y);
		}
	}
	if (n == 0)
	{
		return 1.0f;
	}
	tbSortFloats(sides, n);
	float median = sides[n / 2], high = sides[(9 * n) / 10];
	return median > 0.0f ? high / median : TB_AUTO_HASH_SPREAD + 1.0f;
}

static tbBroadPhaseMethod tbVoteBroadPhase(const tbWorld* world)
{
	const tbBroadPhase* bp = &world->broadPhase;
	int statics = world->staticProxyCount; // kept by tbCreateShapeProxy and tbDestroyShapeProxy
	int movable = bp->table.count - statics;
	float window = (float)world->broadPhaseVote.windowSteps;
	// A new world's first window counts the proxies that moved, not the moves per step: its bodies
	// start inside fresh fat boxes, which hide their first steps of motion (a pile dropped from rest
	// leaves them all together, once, at the window's last step), so per step it would look a fifth
	// as busy as it is and stay in the tree another window.
	float perStep = world->stepIndex <= TB_AUTO_FIRST_WINDOW ? 1.0f : window;
	float movedFraction = movable > 0 ? (float)world->broadPhaseVote.movedProxies / (perStep * (float)movable) : 0.0f;
	float fastFraction = movable > 0 ? (float)world->broadPhaseVote.fastBodies / (window * (float)movable) : 0.0f;
	bool sweep = movable <= TB_AUTO_SWEEP_MAX_PROXIES && movedFraction > 0.25f && statics <= movable &&
				 fastFraction < 0.01f;
	if (sweep && movable <= TB_AUTO_SWEEP_SMALL)
	{
		return tb_broadPhaseSortAndSweep;
	}
	// Hysteresis: the hash is kept while more than TB_AUTO_HASH_KEEP of the movable proxies move, so
	// a scene near the threshold (a car driving over a chain terrain, docs/methods.md) does not switch
	// back and forth, each switch a rebuild.
	float hashMoved = bp->method == tb_broadPhaseSpatialHash ? TB_AUTO_HASH_KEEP : 0.25f;
	if (movedFraction > hashMoved && tbMovableSizeSpread(bp, movable) <= TB_AUTO_HASH_SPREAD)
	{
		return tb_broadPhaseSpatialHash;
	}
	return sweep ? tb_broadPhaseSortAndSweep : tb_broadPhaseTree;
}

static void tbUpdateAutoBroadPhase(tbWorld* world)
{
	if (world->def.broadPhase != tb_broadPhaseAuto)
	{
		return;
	}
	world->broadPhaseVote.windowSteps += 1;
	world->broadPhaseVote.movedProxies += world->counters.proxyMoves;
	world->broadPhaseVote.fastBodies += world->counters.fastBodies;
	int window = world->stepIndex < TB_AUTO_WINDOW ? TB_AUTO_FIRST_WINDOW : TB_AUTO_WINDOW;
	if (world->broadPhaseVote.windowSteps < window)
	{
		return;
	}
	tbBroadPhaseMethod vote = tbVoteBroadPhase(world);
	world->broadPhaseVote.votes = vote != world->broadPhase.method ? world->broadPhaseVote.votes + 1 : 0;
	// A new world's first two windows decide alone: waiting for a second window that agreed kept a
	// falling pile of a thousand bodies in the tree until step 15 (its re-insertions cost twice the
	// hash's step), and the second window corrects a first that fresh fat boxes misled (see
	// tbVoteBroadPhase: the first window counts proxies, not moves per step).
	int needed = world->stepIndex <= 2 * TB_AUTO_FIRST_WINDOW ? 1 : 2;
	if (world->broadPhaseVote.votes >= needed)
	{
		tbBroadPhase_SwitchMethod(&world->broadPhase, vote);
		world->broadPhaseVote.votes = 0;
	}
	world->broadPhaseVote.windowSteps = 0;
	world->broadPhaseVote.movedProxies = 0;
	world->broadPhaseVote.fastBodies = 0;
}

bool tbSetLengthUnitsPerMeter(float lengthUnits)
{
	const char* f = "tbSetLengthUnitsPerMeter";
	if (tbIsValidFloat(lengthUnits) == false || lengthUnits < 0.001f || lengthUnits > 1000.0f)
	{
		tbReportError(f, "lengthUnits is %g (must be finite, 0.001 to 1000); pass your length units per metre, "
						 "e.g. 100 for centimetres", (double)lengthUnits);
		return false;
	}
	for (int i = 0; i < TB_MAX_WORLDS; ++i)
	{
		if (s_worlds[i] != NULL)
		{
			tbReportError(f, "a world exists; set the length units before creating any world (its tolerances "
							 "and definitions were made in the old units)");
			return false;
		}
	}
	tbSetLengthUnits(lengthUnits);
	return true;
}

tbWorldId tbCreateWorld(const tbWorldDef* def)
{
	if (tbCheckWorldDef(def) == false)
	{
		return TB_NULL_WORLD_ID;
	}
	int slot = -1;
	for (int i = 0; i < TB_MAX_WORLDS; ++i)
	{
		if (s_worlds[i] == NULL)
		{
			slot = i;
			break;
		}
	}
	if (slot < 0)
	{
		tbReportError("tbCreateWorld", "%d worlds exist already (TB_MAX_WORLDS); destroy one first", TB_MAX_WORLDS);
		return TB_NULL_WORLD_ID;
	}
	tbWorld* world = tbAlloc((int)sizeof(tbWorld));
	memset(world, 0, sizeof(tbWorld));
	world->def = *def;
	// enableContinuous is v3.2's switch, `continuous` Tumble's method: off by either is off, and the
	// method is kept aside for tbWorld_EnableContinuous(true), as that function does.
	world->continuousWhenEnabled = def->continuous != tb_continuousOff ? def->continuous : tb_continuousDefault;
	if (def->enableContinuous == false)
	{
		world->def.continuous = tb_continuousOff;
	}
	world->def.enableContinuous = world->def.continuous != tb_continuousOff;
	world->gravityLength = tbLength(def->gravity);
	world->worldId = (uint16_t)slot;
	world->generation = (uint16_t)(s_worldGenerations[slot] + 1);
	s_worldGenerations[slot] = world->generation;
	// One past every generation the slot's earlier worlds handed out.
	world->bodyGenerationBase = (uint16_t)(s_bodyGenerations[slot] + 1);
	world->shapeGenerationBase = (uint16_t)(s_shapeGenerations[slot] + 1);
	world->jointGenerationBase = (uint16_t)(s_jointGenerations[slot] + 1);
	world->chainGenerationBase = (uint16_t)(s_chainGenerations[slot] + 1);
	world->userData = def->userData;
	tbHashSet_Create(&world->pairSet, 64);
	tbBroadPhase_Create(&world->broadPhase, tbResolveBroadPhase(def->broadPhase));
	tbBroadPhase_SetPairFilter(&world->broadPhase, tbContactPairFilter, tbContactPairPrefetch, world);
	tbReserveCapacity(world, &def->capacity);
	world->contactRecycleDistance = TB_RECYCLE_DISTANCE;
	world->enableSpeculative = true;
	s_worlds[slot] = world;
	tbWorldId id = {(uint16_t)(slot + 1), world->generation};
	return id;
}

// The largest generation of the slots, counted from base (generations wrap at 2^16): a destroyed
// object's slot holds its id's generation + 1, so this bounds every id the world handed out.
static uint16_t tbLargestGeneration(uint16_t base, const void* slots, int count, size_t stride, size_t offset)
{
	uint16_t largest = 0;
	for (int i = 0; i < count; ++i)
	{
		uint16_t generation;
		memcpy(&generation, (const char*)slots + (size_t)i * stride + offset, sizeof(generation));
		uint16_t sinceBase = (uint16_t)(generation - base);
		largest = sinceBase > largest ? sinceBase : largest;
	}
	return (uint16_t)(base + largest);
}

static void tbFreeWorldArrays(tbWorld* w)
{
	tbArenaDestroy(&w->stepArena);
	TB_ARRAY_FREE(w->bodies, w->bodyCapacity);
	tbIdPool_Destroy(&w->bodyPool);
	TB_ARRAY_FREE(w->shapes, w->shapeCapacity);
	tbIdPool_Destroy(&w->shapePool);
	TB_ARRAY_FREE(w->contacts, w->contactCapacity);
	tbIdPool_Destroy(&w->contactPool);
	TB_ARRAY_FREE(w->awakeBodies, w->awakeBodyCapacity);
	TB_ARRAY_FREE(w->cache.stepContacts, w->cache.stepContactCapacity);
	TB_ARRAY_FREE(w->cache.collideResults, w->cache.collideResultCapacity);
	TB_ARRAY_FREE(w->cache.solverContacts, w->cache.solverContactCapacity);
	TB_ARRAY_FREE(w->cache.solverContactsById, w->cache.solverContactsByIdCapacity);
	TB_ARRAY_FREE(w->cache.solverSlots, w->cache.solverSlotCapacity);
	TB_ARRAY_FREE(w->cache.touchingContacts, w->cache.touchingContactCapacity);
	TB_ARRAY_FREE(w->cache.collideKeys, w->cache.collideKeyCapacity);
	TB_ARRAY_FREE(w->cache.contactBodies, w->cache.contactBodyCapacity);
	tbDestroyJointOrderCache(w);
	tbDestroyContactColorCache(w);
	TB_ARRAY_FREE(w->cache.islandStack, w->cache.islandStackCapacity);
	TB_ARRAY_FREE(w->events.beginEvents, w->events.beginCapacity);
	TB_ARRAY_FREE(w->events.endEvents, w->events.endCapacity);
	TB_ARRAY_FREE(w->events.hitEvents, w->events.hitCapacity);
	TB_ARRAY_FREE(w->events.sensorBeginEvents, w->events.sensorBeginCapacity);
	TB_ARRAY_FREE(w->events.sensorEndEvents, w->events.sensorEndCapacity);
	TB_ARRAY_FREE(w->events.moveEvents, w->events.moveCapacity);
	TB_ARRAY_FREE(w->events.pendingEndEvents, w->events.pendingEndCapacity);
	TB_ARRAY_FREE(w->events.pendingSensorEndEvents, w->events.pendingSensorEndCapacity);
	tbFreeJoints(w);
	tbFreeChains(w);
}

void tbNoteGenerationPeaks(tbWorld* world)
{
	const uint16_t bases[4] = {world->bodyGenerationBase, world->shapeGenerationBase, world->jointGenerationBase,
							   world->chainGenerationBase};
	const uint16_t largest[4] = {
		tbLargestGeneration(bases[0], world->bodies, world->bodyPool.highWater, sizeof(tbBody), offsetof(tbBody, generation)),
		tbLargestGeneration(bases[1], world->shapes, world->shapePool.highWater, sizeof(tbShape),
							offsetof(tbShape, generation)),
		tbLargestGeneration(bases[2], world->joints, world->jointPool.highWater, sizeof(tbJoint),
							offsetof(tbJoint, generation)),
		tbLargestGeneration(bases[3], world->chains, world->chainPool.highWater, sizeof(tbChain),
							offsetof(tbChain, generation))};
	for (int k = 0; k < 4; ++k)
	{
		uint16_t peak = (uint16_t)(largest[k] - bases[k]);
		world->generationPeaks[k] = peak > world->generationPeaks[k] ? peak : world->generationPeaks[k];
	}
}

void tbFreeWorldContents(tbWorld* world)
{
	tbBroadPhase_Destroy(&world->broadPhase);
	tbHashSet_Destroy(&world->pairSet);
	tbFreeWorldArrays(world);
	tbFree(world->snapshotNames, world->snapshotNamesSize);
	world->snapshotNames = NULL;
	world->snapshotNamesSize = 0;
}

void tbDestroyWorld(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbDestroyWorld");
	if (world == NULL)
	{
		return;
	}
	if (tbStructureLocked(world, "tbDestroyWorld", "destroy it"))
	{
		return;
	}
	tbRecordingDetach(world);
	int slot = world->worldId;
	tbNoteGenerationPeaks(world);
	s_bodyGenerations[slot] = (uint16_t)(world->bodyGenerationBase + world->generationPeaks[0]);
	s_shapeGenerations[slot] = (uint16_t)(world->shapeGenerationBase + world->generationPeaks[1]);
	s_jointGenerations[slot] = (uint16_t)(world->jointGenerationBase + world->generationPeaks[2]);
	s_chainGenerations[slot] = (uint16_t)(world->chainGenerationBase + world->generationPeaks[3]);
	tbFreeWorldContents(world);
	s_worlds[world->worldId] = NULL;
	tbFree(world, (int)sizeof(tbWorld));
}

bool tbWorld_IsValid(tbWorldId id)
{
	if (id.index1 == 0 || id.index1 > TB_MAX_WORLDS)
	{
		return false;
	}
	tbWorld* world = s_worlds[id.index1 - 1];
	return world != NULL && world->generation == id.generation;
}

static void tbClearEvents(tbWorld* world)
{
	world->events.beginCount = 0;
	world->events.endCount = 0;
	world->events.hitCount = 0;
	world->events.sensorBeginCount = 0;
	world->events.sensorEndCount = 0;
	world->events.moveCount = 0;
	// End events from changes since the last step are reported with this step's events.
	for (int i = 0; i < world->events.pendingEndCount; ++i)
	{
		TB_ARRAY_PUSH(world->events.endEvents, world->events.endCount, world->events.endCapacity, world->events.pendingEndEvents[i]);
	}
	for (int i = 0; i < world->events.pendingSensorEndCount; ++i)
	{
		TB_ARRAY_PUSH(world->events.sensorEndEvents, world->events.sensorEndCount, world->events.sensorEndCapacity,
					  world->events.pendingSensorEndEvents[i]);
	}
	world->events.pendingEndCount = 0;
	world->events.pendingSensorEndCount = 0;
}

static void tbUpdateCounters(tbWorld* world)
{
	tbCounters* c = &world->counters;
	c->bodyCount = world->bodyPool.count;
	c->shapeCount = world->shapePool.count;
	c->contactCount = world->contactPool.count;
	c->awakeBodyCount = tbAwakeBodyCount(world);
	c->jointCount = world->jointPool.count;
	c->stackUsed = world->stepArena.needed;
	c->awakeContactCount = world->cache.stepContactCount;
	int counts[TB_GRAPH_COLOR_COUNT + 1] = {0};
	tbGetContactGraphColors(world, NULL, counts); // zeros when the last step did not colour
	memcpy(c->colorCounts, counts, sizeof(c->colorCounts));
	c->overflowCount = counts[TB_GRAPH_COLOR_COUNT];
	// touchingCount: set by the collide stage (contact.c), which reads every step contact's flags.
}

/// The counts the broad-phase vote and settle can change, taken after them: a switch of method
/// builds other structures (and a tree's heights go to 0 under another method).
static void tbUpdateBroadPhaseCounters(tbWorld* world)
{
	tbCounters* c = &world->counters;
	c->treeHeight = tbBroadPhase_GetTreeHeight(&world->broadPhase);
	c->staticTreeHeight = tbBroadPhase_GetStaticTreeHeight(&world->broadPhase);
	c->byteCount = tbGetByteCount();
}

/// The counts tbWorldDef::capacity describes, kept at their largest (tbWorld_GetMaxCapacity).
static void tbRecordMaxCapacity(tbWorld* world)
{
	tbCapacity* c = &world->maxCapacity;
	int movableProxies = world->broadPhase.table.count - world->staticProxyCount;
	c->staticShapeCount = tbMaxInt(c->staticShapeCount, world->staticProxyCount);
	c->dynamicShapeCount = tbMaxInt(c->dynamicShapeCount, movableProxies);
	c->staticBodyCount = tbMaxInt(c->staticBodyCount, world->staticBodyCount);
	c->dynamicBodyCount = tbMaxInt(c->dynamicBodyCount, world->bodyPool.count - world->staticBodyCount);
	c->contactCount = tbMaxInt(c->contactCount, world->contactPool.count);
}

/// What every step ends with, a pause too: counters, the broad-phase vote, the broad phase settled
/// for the queries between steps (after the vote and after bodies beyond the bounds left it, either
/// of which would throw a fresh grid away), the step arena.
static void tbFinishStep(tbWorld* world, uint64_t stepTicks)
{
	tbCountTasksInto(NULL);
	tbUpdateCounters(world); // the vote reads this step's counts
	tbUpdateAutoBroadPhase(world);
	tbBroadPhase_Settle(&world->broadPhase);
	tbUpdateBroadPhaseCounters(world);
	tbArenaReset(&world->stepArena);
	world->profile.step = tbGetMilliseconds(stepTicks);
	world->locked = false;
}

/// The step: each stage is a function in the file of its concept, run top to bottom.
static bool tbStepWorld(tbWorldId worldId, float timeStep, int subStepCount)
{
	const char* f = "tbWorld_Step";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL)
	{
		return false;
	}
	// 0 is a pause (Box2D v3.2's): contacts and their events update, nothing moves.
	if (tbIsValidFloat(timeStep) == false || (timeStep != 0.0f && timeStep < TB_MIN_TIME_STEP) ||
		timeStep > TB_MAX_TIME_STEP)
	{
		tbReportError(f, "timeStep is %g (must be 0, a pause, or TB_MIN_TIME_STEP = %g s to TB_MAX_TIME_STEP = %g s); "
						 "pass the frame time in seconds, e.g. 1/60, and step a longer span in several calls",
					  (double)timeStep, (double)TB_MIN_TIME_STEP, (double)TB_MAX_TIME_STEP);
		return false;
	}
	if (subStepCount < 1 || subStepCount > TB_MAX_SUB_STEPS)
	{
		tbReportError(f, "subStepCount is %d (must be 1..%d, TB_MAX_SUB_STEPS); 4 is typical", subStepCount,
					  TB_MAX_SUB_STEPS);
		return false;
	}
	if (tbStructureLocked(world, f, "step it"))
	{
		return false;
	}
	world->locked = true;
	tbRecordMaxCapacity(world);
	tbCompactAwakeSet(world); // every stage walks the awake list without holes
	world->stepIndex += 1;
	world->stepTime = timeStep;
	world->gravityLength = tbLength(world->def.gravity);
	tbClearEvents(world);
	memset(&world->profile, 0, sizeof(world->profile));
	int64_t byteCount = world->counters.byteCount;
	memset(&world->counters, 0, sizeof(world->counters));
	world->counters.byteCount = byteCount;
	tbCountTasksInto(&world->counters.taskCount); // until tbFinishStep

	// Each stage's time is the lap since the last (one clock read a stage).
	uint64_t stepTicks = tbGetTicks();
	uint64_t t = stepTicks;
	tbUpdatePairsStage(world);
	world->profile.pairs = tbGetMillisecondsAndReset(&t);
	tbCollideStage(world);
	world->profile.collide = tbGetMillisecondsAndReset(&t);
	world->profile.refit = world->broadPhase.refitTime;
	world->broadPhase.refitTime = 0.0f;
	tbIslandStage(world);
	world->profile.islands = tbGetMillisecondsAndReset(&t);
	if (timeStep == 0.0f)
	{
		tbSolveStage(world, timeStep, subStepCount); // solves nothing; clears the last step's joint events
		tbSensorStage(world);
		tbFinishStep(world, stepTicks); // a pause: no body moves, sleeps or reports a move
		return true;
	}
	tbSolveStage(world, timeStep, subStepCount);
	world->profile.solve = tbGetMillisecondsAndReset(&t);
	// Box2D v3.2's constraints: its solver stages from preparation to storing the impulses, the solve
	// but its set-up and the scatter of the bodies; here the sum of those parts as timed.
	const tbProfile* p = &world->profile;
	world->profile.constraints = p->prepareConstraints + p->integrateVelocities + p->warmStart + p->solveImpulses +
								 p->integratePositions + p->relaxImpulses + p->applyRestitution + p->storeImpulses;
	// A stage with nothing to do is neither called nor timed (its time stays 0): in a world at rest
	// most stages are idle, and a clock read then costs as much as the stage.
	if (world->awakeBodyCount > 0)
	{
		tbContinuousStage(world);
		world->profile.continuous = tbGetMillisecondsAndReset(&t);
	}
	int beyondBounds = tbFinalizeStage(world, timeStep);
	world->profile.finalize = tbGetMillisecondsAndReset(&t);
	world->profile.transforms = world->profile.finalize; // Box2D v3.2's name for this stage
	if (world->hitContactCount > 0)
	{
		tbReportHitEvents(world);
		world->profile.hitEvents = tbGetMillisecondsAndReset(&t);
	}
	if (world->sensorContactCount > 0)
	{
		tbSensorStage(world);
		world->profile.sensors = tbGetMillisecondsAndReset(&t);
	}
	if (world->awakeBodyCount > 0)
	{
		tbSleepStage(world, timeStep);
		world->profile.sleepIslands = tbGetMillisecondsAndReset(&t);
	}
	if (beyondBounds > 0)
	{
		tbDisableBodiesBeyondBounds(world);
	}

	tbFinishStep(world, stepTicks);
	return true;
}

bool tbWorld_Step(tbWorldId worldId, float timeStep, int subStepCount)
{
	if (tbStepWorld(worldId, timeStep, subStepCount) == false)
	{
		return false;
	}
	tbWorld* world = tbGetWorldFromIndex(worldId.index1 - 1);
	if (world->recording != NULL)
	{
		tbRecordStep(world, timeStep, subStepCount);
	}
	return true;
}

tbBodyEvents tbWorld_GetBodyEvents(tbWorldId worldId)
{
	tbBodyEvents events = {0};
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetBodyEvents");
	if (world != NULL)
	{
		events.moveEvents = world->events.moveEvents;
		events.moveCount = world->events.moveCount;
	}
	return events;
}

tbSensorEvents tbWorld_GetSensorEvents(tbWorldId worldId)
{
	tbSensorEvents events = {0};
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetSensorEvents");
	if (world != NULL)
	{
		events.beginEvents = world->events.sensorBeginEvents;
		events.beginCount = world->events.sensorBeginCount;
		events.endEvents = world->events.sensorEndEvents;
		events.endCount = world->events.sensorEndCount;
	}
	return events;
}

tbContactEvents tbWorld_GetContactEvents(tbWorldId worldId)
{
	tbContactEvents events = {0};
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetContactEvents");
	if (world != NULL)
	{
		events.beginEvents = world->events.beginEvents;
		events.beginCount = world->events.beginCount;
		events.endEvents = world->events.endEvents;
		events.endCount = world->events.endCount;
		events.hitEvents = world->events.hitEvents;
		events.hitCount = world->events.hitCount;
	}
	return events;
}

bool tbStructureLocked(tbWorld* world, const char* function, const char* action)
{
	if (world->locked)
	{
		tbReportError(function, "the world is locked (stepping); %s between steps", action);
		return true;
	}
	if (world->queryDepth > 0)
	{
		tbReportError(function, "inside a query callback; %s after the query returns (velocities, impulses, "
								"materials and awake state may change inside it)", action);
		return true;
	}
	return false;
}

static tbWorld* tbGetUnlockedWorld(tbWorldId worldId, const char* function)
{
	tbWorld* world = tbGetWorldChecked(worldId, function);
	if (world != NULL && tbStructureLocked(world, function, "change the world's settings"))
	{
		return NULL;
	}
	return world;
}

bool tbWorld_SetGravity(tbWorldId worldId, tbVec2 gravity)
{
	TB_RECORD(WorldSetGravity, &worldId, &gravity);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_SetGravity");
	if (world == NULL || tbCheckVec2("tbWorld_SetGravity", "gravity", gravity) == false)
	{
		return false;
	}
	world->def.gravity = gravity;
	world->gravityLength = tbLength(gravity);
	return true;
}

tbVec2 tbWorld_GetGravity(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetGravity");
	return world != NULL ? world->def.gravity : tbVec2_zero;
}

void tbWorld_EnableSleeping(tbWorldId worldId, bool flag)
{
	TB_RECORD(WorldEnableSleeping, &worldId, &flag);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_EnableSleeping");
	if (world == NULL)
	{
		return;
	}
	world->def.enableSleep = flag;
	if (flag == false)
	{
		for (int i = 0; i < world->bodyPool.highWater; ++i)
		{
			tbBody* body = world->bodies + i;
			if (body->inUse && body->type != tb_staticBody)
			{
				tbWakeBody(world, body);
			}
		}
	}
}

bool tbWorld_IsSleepingEnabled(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_IsSleepingEnabled");
	return world != NULL && world->def.enableSleep;
}

void tbWorld_EnableManifoldRecycling(tbWorldId worldId, bool flag)
{
	TB_RECORD(WorldEnableManifoldRecycling, &worldId, &flag);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_EnableManifoldRecycling");
	if (world != NULL)
	{
		world->def.enableManifoldRecycling = flag;
	}
}

void tbWorld_EnableCentralFriction(tbWorldId worldId, bool flag)
{
	TB_RECORD(WorldEnableCentralFriction, &worldId, &flag);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_EnableCentralFriction");
	if (world != NULL)
	{
		world->def.enableCentralFriction = flag;
	}
}

bool tbWorld_SetContactTuning(tbWorldId worldId, float hertz, float dampingRatio, float pushSpeed)
{
	TB_RECORD(WorldSetContactTuning, &worldId, &hertz, &dampingRatio, &pushSpeed);
	const char* f = "tbWorld_SetContactTuning";
	tbWorld* world = tbGetUnlockedWorld(worldId, f);
	if (world == NULL || tbCheckPositive(f, "hertz", hertz) == false ||
		tbCheckNonNegative(f, "dampingRatio", dampingRatio) == false || tbCheckPositive(f, "pushSpeed", pushSpeed) == false)
	{
		return false;
	}
	world->def.contactHertz = hertz;
	world->def.contactDampingRatio = dampingRatio;
	world->def.contactSpeed = pushSpeed;
	return true;
}

bool tbWorld_SetContactRecycleDistance(tbWorldId worldId, float recycleDistance)
{
	TB_RECORD(WorldSetContactRecycleDistance, &worldId, &recycleDistance);
	const char* f = "tbWorld_SetContactRecycleDistance";
	tbWorld* world = tbGetUnlockedWorld(worldId, f);
	if (world == NULL || tbCheckLength(f, "recycleDistance", recycleDistance, false) == false)
	{
		return false;
	}
	world->contactRecycleDistance = recycleDistance;
	return true;
}

float tbWorld_GetContactRecycleDistance(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetContactRecycleDistance");
	return world != NULL ? world->contactRecycleDistance : 0.0f;
}

void tbWorld_EnableSpeculative(tbWorldId worldId, bool flag)
{
	TB_RECORD(WorldEnableSpeculative, &worldId, &flag);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_EnableSpeculative");
	if (world != NULL)
	{
		world->enableSpeculative = flag;
	}
}

tbAABB tbWorld_GetBounds(tbWorldId worldId)
{
	const char* f = "tbWorld_GetBounds";
	tbAABB bounds = {{0.0f, 0.0f}, {0.0f, 0.0f}};
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL)
	{
		return bounds;
	}
	if (world->locked)
	{
		// During the step the proxies are being moved (Box2D v3.2 refuses it too); a query callback may.
		tbReportError(f, "the world is locked (stepping); read the bounds between steps");
		return bounds;
	}
	// The union of the broad phase's boxes (fat for movable shapes, tight for static ones), as
	// Box2D v3.2 takes its trees' root boxes; the same whatever the broad-phase method.
	const tbProxyTable* table = &world->broadPhase.table;
	bool any = false;
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		if (p->isFree == false)
		{
			bounds = any ? tbAABB_Union(bounds, p->aabb) : p->aabb;
			any = true;
		}
	}
	return bounds;
}

tbCapacity tbWorld_GetMaxCapacity(tbWorldId worldId)
{
	tbCapacity none = {0};
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetMaxCapacity");
	return world != NULL ? world->maxCapacity : none;
}

void tbWorld_RebuildStaticTree(tbWorldId worldId)
{
	TB_RECORD(WorldRebuildStaticTree, &worldId);
	const char* f = "tbWorld_RebuildStaticTree";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world != NULL && tbStructureLocked(world, f, "rebuild the static tree") == false)
	{
		tbBroadPhase_RebuildStaticTree(&world->broadPhase);
	}
}

bool tbWorld_SetRestitutionThreshold(tbWorldId worldId, float value)
{
	TB_RECORD(WorldSetRestitutionThreshold, &worldId, &value);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_SetRestitutionThreshold");
	if (world == NULL || tbCheckNonNegative("tbWorld_SetRestitutionThreshold", "value", value) == false)
	{
		return false;
	}
	world->def.restitutionThreshold = value;
	return true;
}

float tbWorld_GetRestitutionThreshold(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetRestitutionThreshold");
	return world != NULL ? world->def.restitutionThreshold : 0.0f;
}

float tbWorld_GetHitEventThreshold(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetHitEventThreshold");
	return world != NULL ? world->def.hitEventThreshold : 0.0f;
}

bool tbWorld_SetHitEventThreshold(tbWorldId worldId, float value)
{
	TB_RECORD(WorldSetHitEventThreshold, &worldId, &value);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_SetHitEventThreshold");
	if (world == NULL || tbCheckNonNegative("tbWorld_SetHitEventThreshold", "value", value) == false)
	{
		return false;
	}
	world->def.hitEventThreshold = value;
	return true;
}

void tbWorld_SetCustomFilterCallback(tbWorldId worldId, tbCustomFilterFcn* fcn, void* context)
{
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_SetCustomFilterCallback");
	if (world != NULL)
	{
		world->customFilterFcn = fcn;
		world->customFilterContext = context;
	}
}

void tbWorld_SetPreSolveCallback(tbWorldId worldId, tbPreSolveFcn* preSolveFcn, tbPreContinuousFcn* preContinuousFcn,
								 void* context)
{
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_SetPreSolveCallback");
	if (world != NULL)
	{
		world->preSolveFcn = preSolveFcn;
		world->preContinuousFcn = preContinuousFcn;
		world->preSolveContext = context;
	}
}

void tbWorld_SetFrictionCallback(tbWorldId worldId, tbFrictionCallback* callback)
{
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_SetFrictionCallback");
	if (world != NULL)
	{
		world->def.frictionCallback = callback;
	}
}

void tbWorld_SetRestitutionCallback(tbWorldId worldId, tbRestitutionCallback* callback)
{
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_SetRestitutionCallback");
	if (world != NULL)
	{
		world->def.restitutionCallback = callback;
	}
}

void tbWorld_SetUserData(tbWorldId worldId, void* userData)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_SetUserData");
	if (world != NULL)
	{
		world->userData = userData;
	}
}

int tbWorld_GetAwakeBodyCount(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetAwakeBodyCount");
	return world != NULL ? tbAwakeBodyCount(world) : 0;
}

void tbWorld_EnableWarmStarting(tbWorldId worldId, bool flag)
{
	TB_RECORD(WorldEnableWarmStarting, &worldId, &flag);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_EnableWarmStarting");
	if (world != NULL)
	{
		world->def.enableWarmStarting = flag;
	}
}

bool tbWorld_IsWarmStartingEnabled(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_IsWarmStartingEnabled");
	return world != NULL && world->def.enableWarmStarting;
}

void tbWorld_EnableContinuous(tbWorldId worldId, bool flag)
{
	TB_RECORD(WorldEnableContinuous, &worldId, &flag);
	tbWorld* world = tbGetUnlockedWorld(worldId, "tbWorld_EnableContinuous");
	if (world == NULL)
	{
		return;
	}
	// Off keeps the method in force, so that on restores it (conservative advancement stays so).
	if (flag == false && world->def.continuous != tb_continuousOff)
	{
		world->continuousWhenEnabled = world->def.continuous;
		world->def.continuous = tb_continuousOff;
	}
	else if (flag && world->def.continuous == tb_continuousOff)
	{
		world->def.continuous = world->continuousWhenEnabled;
	}
	world->def.enableContinuous = world->def.continuous != tb_continuousOff;
}

bool tbWorld_IsContinuousEnabled(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_IsContinuousEnabled");
	return world != NULL && world->def.continuous != tb_continuousOff;
}

void tbWorld_SetMaximumLinearSpeed(tbWorldId worldId, float maximumLinearSpeed)
{
	TB_RECORD(WorldSetMaximumLinearSpeed, &worldId, &maximumLinearSpeed);
	const char* f = "tbWorld_SetMaximumLinearSpeed";
	tbWorld* world = tbGetUnlockedWorld(worldId, f);
	if (world != NULL && tbCheckMaximumSpeed(f, maximumLinearSpeed))
	{
		world->def.maximumLinearSpeed = maximumLinearSpeed;
	}
}

float tbWorld_GetMaximumLinearSpeed(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetMaximumLinearSpeed");
	return world != NULL ? world->def.maximumLinearSpeed : 0.0f;
}

void* tbWorld_GetUserData(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetUserData");
	return world != NULL ? world->userData : NULL;
}

bool tbWorld_SetBroadPhaseMethod(tbWorldId worldId, tbBroadPhaseMethod method)
{
	TB_RECORD(WorldSetBroadPhaseMethod, &worldId, &method);
	const char* f = "tbWorld_SetBroadPhaseMethod";
	tbWorld* world = tbGetUnlockedWorld(worldId, f);
	if (world == NULL)
	{
		return false;
	}
	if ((unsigned)method >= tb_broadPhaseMethodCount)
	{
		tbReportError(f, "method is %d; use a tb_broadPhase* value", (int)method);
		return false;
	}
	world->def.broadPhase = method;
	tbBroadPhase_SetMethod(&world->broadPhase, tbResolveBroadPhase(method));
	return true;
}

bool tbWorld_SetNarrowPhaseMethod(tbWorldId worldId, tbNarrowPhaseMethod method)
{
	TB_RECORD(WorldSetNarrowPhaseMethod, &worldId, &method);
	const char* f = "tbWorld_SetNarrowPhaseMethod";
	tbWorld* world = tbGetUnlockedWorld(worldId, f);
	if (world == NULL)
	{
		return false;
	}
	if ((unsigned)method > tb_narrowPhaseGJK)
	{
		tbReportError(f, "method is %d; use a tb_narrowPhase* value", (int)method);
		return false;
	}
	world->def.narrowPhase = method;
	return true;
}

bool tbWorld_SetContinuousMethod(tbWorldId worldId, tbContinuousMethod method)
{
	TB_RECORD(WorldSetContinuousMethod, &worldId, &method);
	const char* f = "tbWorld_SetContinuousMethod";
	tbWorld* world = tbGetUnlockedWorld(worldId, f);
	if (world == NULL)
	{
		return false;
	}
	if ((unsigned)method >= tb_continuousMethodCount)
	{
		tbReportError(f, "method is %d; use a tb_continuous* value", (int)method);
		return false;
	}
	world->def.continuous = method;
	world->def.enableContinuous = method != tb_continuousOff;
	return true;
}

bool tbWorld_SetSolverMethod(tbWorldId worldId, tbSolverMethod method, int velocityIterations, int positionIterations)
{
	TB_RECORD(WorldSetSolverMethod, &worldId, &method, &velocityIterations, &positionIterations);
	const char* f = "tbWorld_SetSolverMethod";
	tbWorld* world = tbGetUnlockedWorld(worldId, f);
	if (world == NULL)
	{
		return false;
	}
	tbWorldDef def = world->def;
	def.solver = method;
	def.velocityIterations = velocityIterations;
	def.positionIterations = positionIterations;
	if (tbCheckMethods(&def, f) == false)
	{
		return false;
	}
	world->def = def;
	return true;
}

tbWorldDef tbWorld_GetDef(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetDef");
	if (world == NULL)
	{
		return tbDefaultWorldDef();
	}
	tbWorldDef def = world->def;
	def.broadPhase = world->broadPhase.method;
	return def;
}

tbProfile tbWorld_GetProfile(tbWorldId worldId)
{
	tbProfile profile = {0};
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetProfile");
	return world != NULL ? world->profile : profile;
}

tbCounters tbWorld_GetCounters(tbWorldId worldId)
{
	tbCounters counters = {0};
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetCounters");
	if (world == NULL)
	{
		return counters;
	}
	world->counters.bodyCount = world->bodyPool.count;
	world->counters.shapeCount = world->shapePool.count;
	world->counters.contactCount = world->contactPool.count;
	world->counters.jointCount = world->jointPool.count;
	world->counters.awakeBodyCount = tbAwakeBodyCount(world);
	return world->counters;
}

void tbWorld_SetWorkerCount(tbWorldId worldId, int count)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_SetWorkerCount");
	if (world == NULL || tbStructureLocked(world, "tbWorld_SetWorkerCount", "change the worker count"))
	{
		return;
	}
	world->def.workerCount = tbClampInt(count, 1, TB_MAX_WORKERS);
}

int tbWorld_GetWorkerCount(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_GetWorkerCount");
	return world != NULL ? world->def.workerCount : 0;
}
