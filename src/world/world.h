// Internal: the world and the data it owns. Bodies, shapes, contacts, joints and chains live in
// arrays indexed by small integer ids from one id pool per kind (core/id_pool.h), each slot with a
// generation so that stale handles are refused. What the step's stages hand on to one another is
// in world->cache (step_cache.h); the definitions of each kind of object are in its own header.
#pragma once

#include "body.h"
#include "contact.h"
#include "shape.h"
#include "step_cache.h"

#include "broad_phase/broad_phase.h"
#include "core/arena.h"
#include "core/core.h"
#include "core/id_pool.h"
#include "core/table.h"

#include "tumble/tumble.h"

struct tbChain;
struct tbJoint;

/// The events of the last step, read by the game through tbWorld_Get*Events until the next step.
typedef struct tbEventBuffers
{
	tbContactBeginTouchEvent* beginEvents;
	int beginCount, beginCapacity;
	tbContactEndTouchEvent* endEvents;
	int endCount, endCapacity;
	tbContactHitEvent* hitEvents;
	int hitCount, hitCapacity;
	tbSensorBeginTouchEvent* sensorBeginEvents;
	int sensorBeginCount, sensorBeginCapacity;
	tbSensorEndTouchEvent* sensorEndEvents;
	int sensorEndCount, sensorEndCapacity;
	tbBodyMoveEvent* moveEvents;
	int moveCount, moveCapacity;
	tbJointEvent* jointEvents;
	int jointEventCount, jointEventCapacity;
	/// End events from changes between steps (destroying a body or shape, a new filter): held here
	/// so that the arrays the game is reading do not grow under it, and reported after the next step.
	tbContactEndTouchEvent* pendingEndEvents;
	int pendingEndCount, pendingEndCapacity;
	tbSensorEndTouchEvent* pendingSensorEndEvents;
	int pendingSensorEndCount, pendingSensorEndCapacity;
} tbEventBuffers;

/// What the automatic broad-phase choice has seen over its current window of steps (world.c).
typedef struct tbBroadPhaseVote
{
	int windowSteps;
	int movedProxies;
	int fastBodies;
	int votes; ///< consecutive windows that voted for a change
} tbBroadPhaseVote;

typedef struct tbWorld
{
	tbWorldDef def; ///< methods and tuning in force (auto resolved where it must be)
	uint16_t worldId;
	uint16_t generation;
	// First generation of a body, shape, joint or chain slot used for the first time in this world:
	// one past the largest generation any earlier world in the same slot handed out, so an id kept
	// from a destroyed world never matches an object of a new world that took its slot.
	uint16_t bodyGenerationBase;
	uint16_t shapeGenerationBase;
	uint16_t jointGenerationBase;
	uint16_t chainGenerationBase;
	/// The largest generations this world handed out, counted from the bases (body, shape, joint,
	/// chain), as they were before a restore took the slots back to older ones
	/// (tbNoteGenerationPeaks): the next world in the slot starts past them too.
	uint16_t generationPeaks[4];
	bool locked; ///< true during the step: the API refuses every change
	/// Query callbacks running (nested queries count): the API refuses what would change the
	/// broad phase being walked (create, destroy, SetTransform, SetType, filters, collideConnected)
	/// and allows the rest (velocities, impulses, materials, awake state), as Box2D v3 does.
	int queryDepth;
	tbContinuousMethod continuousWhenEnabled; ///< the method tbWorld_EnableContinuous(true) restores
	tbCustomFilterFcn* customFilterFcn;
	void* customFilterContext;
	tbPreSolveFcn* preSolveFcn;
	tbPreContinuousFcn* preContinuousFcn;
	void* preSolveContext;

	// The objects, each kind an array indexed by id (up to its pool's high water).
	tbBody* bodies;
	int bodyCapacity;
	tbIdPool bodyPool;
	tbShape* shapes;
	int shapeCapacity;
	tbIdPool shapePool;
	tbContact* contacts;
	int contactCapacity;
	tbIdPool contactPool;
	struct tbJoint* joints;
	int jointCapacity;
	tbIdPool jointPool;
	struct tbChain* chains;
	int chainCapacity;
	tbIdPool chainPool;

	int kinematicBodyCount; ///< kinematic bodies in the world (a moving one wakes its joined bodies)
	int staticBodyCount;	///< static bodies in the world (tbWorld_GetMaxCapacity)
	int staticProxyCount;	///< broad-phase proxies of static shapes (the rest are movable)
	int linearLockCount;	///< bodies with a linear motion lock (the solver skips the locks when 0)
	int fastRotationCount;	///< bodies that allow fast rotation (the solver's spin cap is uniform when 0)
	int hitContactCount;	///< contacts with tb_contactEnableHits (hit events are gathered only when > 0)
	int sensorContactCount; ///< contacts with tb_contactSensor (the sensor stage runs only when > 0)

	tbHashSet pairSet; ///< shape pairs that have a contact
	tbBroadPhase broadPhase;
	tbBroadPhaseVote broadPhaseVote;

	/// Awake non-static bodies, in a deterministic order.
	int* awakeBodies;
	int awakeBodyCount, awakeBodyCapacity;
	int awakeHoles; ///< removed bodies' slots (TB_NULL_INDEX) in awakeBodies, closed by tbCompactAwakeSet

	tbStepCache cache; ///< the stages' lists and whether the last step's still hold
	tbArena stepArena; ///< temporaries of the step (solver arrays, colours), reset when it ends
	tbEventBuffers events;

	/// Largest counts seen at the start of any step (tbWorld_GetMaxCapacity: a tbWorldDef::capacity
	/// that makes a rerun allocate nothing more).
	tbCapacity maxCapacity;
	/// Manifold recycling's distance allowance (m): TB_RECYCLE_DISTANCE unless the game set another
	/// (tbWorld_SetContactRecycleDistance); 0 recomputes every manifold (contact.c).
	float contactRecycleDistance;
	/// False only for tests (tbWorld_EnableSpeculative): a two-point manifold drops a point more
	/// than 1.5 × TB_LINEAR_SLOP apart, so the solver sees no speculative second point (contact.c).
	bool enableSpeculative;

	uint32_t stepIndex;	 ///< steps taken (unsigned: wraps after 2^32 steps without overflow)
	float stepTime;		 ///< time step of the current (or last) tbWorld_Step (s); 0 before the first
	float gravityLength; ///< |def.gravity| for the current step (read per contact by the narrow phase)
	float jointInvH;	 ///< 1/s, inverse sub-step of the last step: joint force = impulse·jointInvH
	tbProfile profile;
	tbCounters counters;
	void* userData;
	/// The names of the bodies of a restored snapshot (snapshot.c): copies the world owns, where a
	/// body's name is otherwise the game's string (tbBodyDef::name, not copied).
	char* snapshotNames;
	int snapshotNamesSize;
	/// The recording this world appends its calls and steps to (recording.c), or NULL.
	struct tbRecording* recording;
} tbWorld;

/// The world for an id, or NULL (reports an error naming `function` when the id is stale or null).
tbWorld* tbGetWorldChecked(tbWorldId id, const char* function);
/// Free everything a world holds but the world itself (tbDestroyWorld; a snapshot's restore frees the
/// state it replaces with it).
void tbFreeWorldContents(tbWorld* world);
/// Remember the largest generations the world's body, shape, joint and chain slots hold (a restore
/// is about to replace them with older ones).
void tbNoteGenerationPeaks(tbWorld* world);
/// The world by index (no checks).
tbWorld* tbGetWorldFromIndex(int index);

/// The world cannot change structure now (stepping, or inside a query callback). Reports why to
/// `function` (what it is about to do: `action`) and returns true when so.
bool tbStructureLocked(tbWorld* world, const char* function, const char* action);

/// Bodies awake now (the awake list less its holes).
static inline int tbAwakeBodyCount(const tbWorld* world)
{
	return world->awakeBodyCount - world->awakeHoles;
}
