// Internal: the world and the data it owns. Bodies, shapes and contacts live in pools indexed by
// small integers (ids); a free list recycles slots and a generation counter makes stale handles
// detectable. Hot per-step solver data is gathered into dense arrays by the solver stage.
#pragma once

#include "core/arena.h"
#include "broad_phase/broad_phase.h"
#include "core/core.h"
#include "shape.h"
#include "core/table.h"

#include "tumble/tumble.h"

// ---------------------------------------------------------------------------------------------
// Bodies (body.c)

/// A body. Cold fields (user data, name, lists) sit beside the state because the solver copies
/// what it touches into tbSolverBody arrays each step.
typedef struct tbBody
{
	// Hot in the collide and island stages (speculative margin, anchors, contact-list walks):
	// grouped at the front so a visit touches one or two cache lines.
	tbWorldTransform transform; ///< body origin and rotation
	tbPos center;				///< world centre of mass
	tbVec2 linearVelocity;
	float angularVelocity;
	/// Displacement per step its speculative contacts cover (tbSpeculativeReach, read per contact):
	/// max(TB_SPECULATIVE_REACH, safetyFactor × minExtent), kept current by body.c.
	float speculativeReach;
	float maxExtent;	///< largest distance from the centre of mass to any shape point
	float gravityScale;
	int headContactKey; ///< doubly linked contact edges; key = (contactId << 1) | edge
	int awakeIndex;		///< index in world->awakeBodies, or TB_NULL_INDEX when asleep or static
	int solverIndex;	///< index in the solver's body arrays this step, or TB_NULL_INDEX (read by
						///< the contact preparation for every contact: kept in this first line)
	uint8_t type;		///< tbBodyType
	bool isFast;		///< moved far this step: swept by continuous collision (read per contact: first line)
	bool enableContactRecycling; ///< read per contact by the narrow phase: first line

	tbPos center0;		///< centre of mass at the start of the step (continuous collision)
	tbRot rotation0;	///< rotation at the start of the step
	tbVec2 localCenter; ///< centre of mass in the body frame
	tbVec2 force;
	float torque;

	float mass, invMass;
	float inertia, invInertia; ///< about the centre of mass

	float minExtent;	///< smallest distance from the centre of mass to the surface (continuous collision)
	float safetyFactor; ///< continuous collision safety factor (tbBody_SetSafetyFactor), default 0.5
	float linearDamping;
	float angularDamping;
	float sleepThreshold;
	float sleepTime;

	int headShapeId; ///< singly linked through tbShape::nextShapeId
	int shapeCount;
	int contactCount;
	int headJointKey; ///< doubly linked joint edges (joint.h); key = (jointId << 1) | edge
	int jointCount;

	const char* name;
	void* userData;

	uint16_t generation;
	bool inUse;
	bool enableSleep;
	bool fixedRotation; ///< also motion lock angularZ
	bool lockLinearX;	///< motion locks (tbMotionLocks)
	bool lockLinearY;
	bool isBullet;
	bool isMarked;
	bool isDisabled; ///< out of the simulation (tbBody_Disable): no proxies, no contacts, never awake
} tbBody;

// ---------------------------------------------------------------------------------------------
// Contacts (contact.c)

/// One end of a contact in a body's contact list.
typedef struct tbContactEdge
{
	int bodyId;
	int prevKey;
	int nextKey;
} tbContactEdge;

enum tbContactFlags
{
	tb_contactTouching = 0x01,		///< the manifold has points (solver, islands, waking); sensors: overlap
	tb_contactSensor = 0x02,		///< one shape is a sensor: overlap only, no response
	tb_contactEnableEvents = 0x04,	///< both shapes want begin/end events
	tb_contactEnableHits = 0x08,	///< either shape wants hit events
	/// Begin/end events and counters.touchingCount: a point's separation is below the fixed
	/// TB_SPECULATIVE_DISTANCE (sensors: the shapes overlap). The manifold itself may hold points
	/// further apart (the velocity-dependent margin of tbUpdateContact), which would otherwise make
	/// event timing depend on speed.
	tb_contactReported = 0x10,
	/// contact->base holds the pose and points of the last computed manifold (a touching, non-sensor
	/// contact): manifold recycling may move those points instead of recomputing (contact.c).
	tb_contactRecyclable = 0x20,
	tb_contactEnablePreSolve = 0x40, ///< either shape enables pre-solve events
	/// The last narrow phase recycled the manifold: a hint for the collide walk's prefetch (a pair
	/// recycled once is most often recycled again, one recomputed most often recomputed).
	tb_contactRecycled = 0x80,
};

/// Where a contact's manifold was last computed by the narrow phase (manifold recycling,
/// contact.c): the relative pose and the points fixed in each body, so that a later step can move
/// the points with the bodies. 76 bytes.
typedef struct tbManifoldBase
{
	tbTransform relative; ///< pose of B's origin frame in A's, inv(xfA)·xfB
	tbVec2 normalA;		  ///< the normal in A's frame
	tbVec2 normalB;		  ///< the normal in B's frame
	tbVec2 pointA[2];	  ///< each point (midway between the surfaces) in A's origin frame
	tbVec2 pointB[2];	  ///< the same points in B's origin frame
	float separation[2];  ///< their separations (m)
	float margin;		  ///< the speculative margin the manifold was computed with (m)
} tbManifoldBase;
_Static_assert(sizeof(tbManifoldBase) == 76, "tbManifoldBase is 76 bytes");

/// A pair of shapes whose fat boxes overlap. Exists from the step the boxes start to overlap
/// until the step they stop.
struct tbCollideTally;

typedef struct tbContact
{
	// Hot while walking a body's contact list (island and gather passes): the edges, flags and
	// stamp share the first cache line, so a walk touches one line per contact, not three.
	tbContactEdge edges[2];
	uint32_t flags;
	uint32_t stamp; ///< last step stamp at which this contact was gathered (unsigned: wraps)
	int shapeIdA;
	int shapeIdB;
	float friction;
	float restitution;
	float rollingResistance; ///< N·m per N of normal force: max of the shapes' × the larger radius
	float tangentSpeed;		 ///< m/s, the shapes' tangent speeds added
	bool inUse;
	tbSimplexCache cache; ///< GJK warm start for the GJK/EPA narrow phase
	tbManifold manifold;
	uint16_t touchingSteps; ///< steps in a row with manifold points (saturates): the soft step's settle clock
	tbManifoldBase base; ///< valid when flags has tb_contactRecyclable
	// The impact not yet reported as a hit event (tbReportHitEvents): its approach speed (0: none)
	// and where it happened.
	float hitSpeed;
	tbVec2 hitPoint;
	uint32_t generation; ///< bumped when the slot is freed: stale tbContactIds are refused
} tbContact;

/// Bits of a contact's solver key (solver_types.h, tbContactKey; contact.c fills them for ready
/// contacts during the narrow phase).
typedef enum tbContactKeyFlag
{
	tb_keyMovesA = 1,	   ///< the solve can change A's velocity (awake, positive inverse mass or inertia)
	tb_keyMovesB = 2,
	tb_keyDynamicA = 4,	   ///< A is an awake dynamic body (picks the contact's softness)
	tb_keyDynamicB = 8,
	tb_keyScalarOnly = 16, ///< rolling resistance or tangent speed: the wide blocks do not carry them
	tb_keyBounces = 32,	   ///< restitution > 0: the scalar constraint is kept for restitution
} tbContactKeyFlag;

/// Two body ids (contact.c's dense copy of each contact's bodies).
typedef struct tbBodyPair
{
	int bodyIdA, bodyIdB;
} tbBodyPair;

/// What the narrow phase learnt of a contact that is ready for the solver (a dynamic side, no
/// sleeping side), while it had both bodies in cache: their awake indices (TB_NULL_INDEX for a
/// static body), which are the solver indices of this step, and the key bits. Valid in the step
/// `step` only. A dense array by contact id, so the solver's key pass streams through it instead
/// of visiting two bodies per contact (contact_solver.c).
typedef struct tbCollideKey
{
	int indexA, indexB;
	uint32_t flags;
	uint32_t step;
} tbCollideKey;

// ---------------------------------------------------------------------------------------------
// The world (world.c)

typedef struct tbWorld
{
	tbWorldDef def; ///< methods and tuning in force (auto resolved where it must be)
	uint16_t worldId;
	uint16_t generation;
	// First generation of a body or shape slot used for the first time in this world: one past the
	// largest generation any earlier world in the same slot handed out, so an id kept from a
	// destroyed world never matches an object of a new world that took its slot.
	uint16_t bodyGenerationBase;
	uint16_t shapeGenerationBase;
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

	tbBody* bodies;
	int bodyCapacity;
	int bodyCount; ///< live bodies
	int bodyHighWater;
	int* bodyFree;
	int bodyFreeCount, bodyFreeCapacity;

	tbShape* shapes;
	int shapeCapacity;
	int shapeCount;
	int shapeHighWater;
	int* shapeFree;
	int shapeFreeCount, shapeFreeCapacity;

	tbContact* contacts;
	int contactCapacity;
	int contactCount;
	int contactHighWater;
	int* contactFree;
	int contactFreeCount, contactFreeCapacity;

	// Narrow-phase results of the contacts in stepContacts (contact.c, tbCollideStage).
	uint16_t* collideResults;
	int collideResultCapacity;

	// Chains (chain.c): a pool; each chain owns its segment shapes' ids and its materials.
	struct tbChain* chains;
	int chainCapacity;
	int chainCount;
	int chainHighWater;
	int* chainFree;
	int chainFreeCount, chainFreeCapacity;

	// Joints (joint.c): a pool like the contacts; the joints the solver sees this step (joint-id
	// order); joint events of the last step; a stack for waking joined bodies.
	struct tbJoint* joints;
	int jointCapacity;
	int jointCount;
	int jointHighWater;
	int* jointFree;
	int jointFreeCount, jointFreeCapacity;
	int linearLockCount; ///< bodies with a linear motion lock (the solver skips the locks when 0)
	int* solverJoints;
	int solverJointCount, solverJointCapacity;
	tbJointEvent* jointEvents;
	int jointEventCount, jointEventCapacity;
	int* jointWakeStack;
	int jointWakeCount, jointWakeCapacity;
	bool jointWakeActive;
	float jointInvH; ///< 1/s, inverse sub-step of the last step: joint force = impulse·jointInvH
	// joint_tree.c: this step's joint trees, from the step arena (valid during the step).
	struct tbTreeNode* jointTreeNodes;
	int jointTreeNodeCount;
	struct tbTree* jointTrees;
	int jointTreeCount;
	double* jointTreeValues; ///< joint_tree.c works in double precision
	struct tbJointRows* jointTreeRows;
	bool jointTreesStale; ///< the bodies moved since the trees were last factored

	tbHashSet pairSet; ///< shape pairs that have a contact
	tbBroadPhase broadPhase;

	/// Awake non-static bodies, in a deterministic order.
	int* awakeBodies;
	int awakeBodyCount, awakeBodyCapacity;
	int awakeHoles; ///< removed bodies' slots (TB_NULL_INDEX) in awakeBodies, closed by tbCompactAwakeSet

	/// Per-step scratch: contacts gathered for the narrow phase, touching contacts for the solver.
	int* stepContacts;
	int stepContactCount, stepContactCapacity;
	int* solverContacts; ///< in solve order (island.c): constraint i is contact solverContacts[i]
	int solverContactCount, solverContactCapacity;
	/// The same contacts in contact-id order, and each one's index in solverContacts: the solver
	/// prepares and stores by walking contact memory in order (island.c, contact_solver.c).
	int* solverContactsById;
	int solverContactsByIdCapacity;
	int* solverSlots;
	int solverSlotCapacity;
	/// Touching non-sensor contacts in stepContacts order, recorded by the collide stage, and the
	/// awake-set version at its gather: the island stage's fast path (island.c). An entry is the
	/// contact id when the contact is ready for the solver as it stands (a dynamic side, no sleeping
	/// side), −1 − id when the island stage must look at its bodies.
	int* touchingContacts;
	int touchingContactCount, touchingContactCapacity;
	/// By contact id: the two bodies, or TB_NULL_INDEX for a free slot (up to contactHighWater). A
	/// dense copy of what the collide stage's scan of the contact pool reads (contact.c), so the scan
	/// does not walk 276-byte contacts for three fields.
	tbBodyPair* contactBodies;
	int contactBodyCapacity;
	tbCollideKey* collideKeys; ///< by contact id, up to collideKeyCount (entries past it never written)
	int collideKeyCount, collideKeyCapacity;
	uint32_t awakeSetVersion;  ///< bumped whenever a body joins or leaves the awake set
	uint32_t gatheredVersion; ///< awakeSetVersion when the collide stage gathered its contacts
	uint32_t awakeRemovals;	  ///< bumped whenever bodies leave the awake set
	/// A body joined or left the awake set since the joints were last checked for a sleeping
	/// partner of an awake body (tbWakeJointPartners); with no kinematic body that is the only
	/// way such a joint appears.
	bool jointWakeDirty;
	struct tbJointOrderCache* jointOrderCache; ///< the joints' solve order of the last step (constraint_graph.c)
	struct tbContactColorCache* contactColorCache; ///< the contacts' colours of the last step (constraint_graph.c)
	int kinematicBodyCount; ///< kinematic bodies in the world (a moving one wakes its joined bodies)
	int staticBodyCount;	///< static bodies in the world (tbWorld_GetMaxCapacity)
	int staticProxyCount;	///< broad-phase proxies of static shapes (the rest are movable)
	/// Largest counts seen at the start of any step (tbWorld_GetMaxCapacity: a tbWorldDef::capacity
	/// that makes a rerun allocate nothing more).
	tbCapacity maxCapacity;
	/// Manifold recycling's distance allowance (m): TB_RECYCLE_DISTANCE unless the game set another
	/// (tbWorld_SetContactRecycleDistance); 0 recomputes every manifold (contact.c).
	float contactRecycleDistance;
	/// False only for tests (tbWorld_EnableSpeculative): a two-point manifold drops a point more
	/// than 1.5 × TB_LINEAR_SLOP apart, so the solver sees no speculative second point (contact.c).
	bool enableSpeculative;
	uint32_t gatheredRemovals; ///< awakeRemovals when the collide stage gathered its contacts
	// A steady step (a settled pile) repeats the last step's lists, which the collide stage then
	// keeps instead of rebuilding (contact.c, tbCollideStage; island.c; contact_solver.c):
	uint32_t contactEpoch;	///< bumped by every contact created or destroyed
	uint32_t touchingEpoch; ///< contactEpoch when the touching list was last built
	bool touchingAllReady;	///< every entry of that list was ready then
	bool touchingUnchanged; ///< this step's collide stage kept the last touching list
	bool collideKeysUnchanged; ///< and every solver contact's key is the last step's
	bool solverIsTouching;	///< this step's island stage found its solver contacts unchanged
	uint32_t colorCacheStep; ///< step of the last colouring, or reuse, of contactColorCache
	/// constraint_graph.c: after a colouring that found no island partitions, none is looked for
	/// before this step (TB_PARTITION_RETRY_STEPS later)
	uint32_t partitionRetryStep;
	struct tbCollideTally* collideTallies; ///< per worker, this step's (contact.c, from the step arena)
	int gatheredAwakeCount;	  ///< awakeBodyCount then: bodies woken since are appended after it
	int* islandStack;
	int islandStackCapacity;
	tbArena stepArena; ///< temporaries of the step (solver arrays, colours), reset when it ends

	// Events of the last step.
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
	/// End events from changes between steps (destroying a body or shape, a new filter): held here
	/// so that the arrays the user is reading do not grow under them, and reported after the next step.
	tbContactEndTouchEvent* pendingEndEvents;
	int pendingEndCount, pendingEndCapacity;
	tbSensorEndTouchEvent* pendingSensorEndEvents;
	int pendingSensorEndCount, pendingSensorEndCapacity;

	// Statistics for the automatic broad-phase choice, accumulated over a window of steps.
	int autoWindowSteps;
	int autoMovedProxies;
	int autoFastBodies;
	int autoVotes; ///< consecutive windows that voted for a change

	uint32_t stepIndex; ///< steps taken (unsigned: wraps after 2^32 steps without overflow)
	uint32_t fastMarkedStep; ///< step whose solve marked its fast bodies (tbMarkFastBody in the scatter)
	int fastMarkedCount;	 ///< bodies it marked fast
	float stepTime;		///< time step of the current (or last) tbWorld_Step (s); 0 before the first
	float gravityLength; ///< |def.gravity| for the current step (read per contact by the narrow phase)
	tbProfile profile;
	tbCounters counters;
	int hitContactCount; ///< contacts with tb_contactEnableHits (hit events are gathered only when > 0)
	void* userData;
} tbWorld;

/// The world for an id, or NULL (reports an error naming `function` when the id is stale or null).
tbWorld* tbGetWorldChecked(tbWorldId id, const char* function);
/// The world by index (no checks).
tbWorld* tbGetWorldFromIndex(int index);
/// The world, body for a body id, or NULL after reporting an error; also refuses a locked world
/// when `mutating`.
tbBody* tbGetBodyChecked(tbBodyId id, const char* function, tbWorld** world, bool mutating);
tbShape* tbGetShapeChecked(tbShapeId id, const char* function, tbWorld** world, bool mutating);

tbBodyId tbMakeBodyId(const tbWorld* world, int bodyId);
tbShapeId tbMakeShapeId(const tbWorld* world, int shapeId);
tbContactId tbMakeContactId(const tbWorld* world, int contactId);

/// Which event flag of a shape tbSetShapeEventFlag changes.
typedef enum tbShapeEventKind
{
	tb_shapeEventContacts,
	tb_shapeEventHits,
	tb_shapeEventSensors,
	tb_shapeEventPreSolve,
} tbShapeEventKind;

/// Turn one of a shape's event flags on or off and refresh the flags its contacts hold (contact.c).
void tbSetShapeEventFlag(tbWorld* world, tbShape* shape, tbShapeEventKind kind, bool flag);

// body.c
void tbUpdateBodyMass(tbWorld* world, tbBody* body);
void tbWakeBody(tbWorld* world, tbBody* body);
/// Close the holes bodies that left the awake set left in it (body.c); the step starts with it.
void tbCompactAwakeSet(tbWorld* world);
/// Bodies awake now (the awake list less its holes).
static inline int tbAwakeBodyCount(const tbWorld* world)
{
	return world->awakeBodyCount - world->awakeHoles;
}
void tbSleepBody(tbWorld* world, tbBody* body);
void tbDestroyBodyContacts(tbWorld* world, tbBody* body, bool wakeBodies);

// shape.c (tbComputeShapeAABBInternal, tbComputeFatShapeAABB: shape.h)
void tbCreateShapeProxy(tbWorld* world, tbShape* shape, tbBody* body);
void tbDestroyShapeProxy(tbWorld* world, tbShape* shape);
bool tbShouldShapesCollide(tbFilter a, tbFilter b);
/// Check user geometry (finite, positive radii, valid polygon); reports an error naming `f`.
bool tbCheckGeometry(const char* f, const tbGeometry* geometry);
/// Displacement per step that a body's speculative contacts cover (m): max(TB_SPECULATIVE_REACH,
/// safetyFactor × minExtent), the body's safety factor TB_CONTINUOUS_FRACTION by default. Beyond it
/// the body is swept by continuous collision. Kept in the body (body.c, tbUpdateSpeculativeReach);
/// inline, since the narrow phase reads it twice per contact (a call each: 5 % of the collide stage
/// on the pyramid).
static inline float tbSpeculativeReach(const tbBody* body)
{
	return body->speculativeReach;
}
/// Refresh the shape boxes of a body and move broad-phase proxies that left their fat boxes.
void tbUpdateBodyShapeBoxes(tbWorld* world, tbBody* body, bool forceMove);
/// The two halves of tbUpdateBodyShapeBoxes: boxes computed and proxies flagged (per body, on
/// any worker), then the flagged proxies moved (in body order, on the caller).
/// True when the fat box of some shape was re-made (flagged for tbMoveFlaggedProxies).
bool tbComputeBodyShapeBoxes(const tbWorld* world, tbBody* body, bool forceMove);
void tbMoveFlaggedProxies(tbWorld* world, const tbBody* body);

// contact.c
void tbCreateContact(tbWorld* world, int shapeIdA, int shapeIdB);
/// The contact's mixed friction, restitution, rolling resistance and tangent speed from its shapes.
void tbMixContactMaterials(const tbWorld* world, tbContact* contact);
/// shape.c: a surface material's values are usable (finite; friction, restitution, rolling
/// resistance ≥ 0), or an error naming `name`'s field.
bool tbCheckSurfaceMaterial(const char* function, const char* name, const tbSurfaceMaterial* material);
/// shape.c: the shape's contacts remix their materials (after the shape's material changed).
void tbRemixShapeContacts(tbWorld* world, const tbShape* shape);
void tbDestroyContact(tbWorld* world, int contactId, bool wakeBodies);
/// Narrow phase for one contact: recompute its manifold and its touching and reported flags.
/// Returns the reported flag change (begin/end events): +1 began, −1 stopped, 0 no change; sets
/// *beganTouching when the manifold gained points (the bodies must be woken).
int tbUpdateContact(tbWorld* world, tbContact* contact, bool* beganTouching);

// joint.c: what bodies, contacts, islands and the world need of joints.
/// Wake the sleeping bodies joined to this (just woken) body, transitively through dynamic bodies.
void tbWakeJointedBodies(tbWorld* world, tbBody* body);
/// Island stage, first thing: a joint with one side awake wakes the other (the rule contacts use).
void tbWakeJointPartners(tbWorld* world);
/// Pair filter: true when a joint between the two bodies forbids their collision.
bool tbJointBlocksCollision(const tbWorld* world, int bodyIdA, int bodyIdB);
/// Destroy every joint of a body (tbDestroyBody); the other bodies are woken.
void tbDestroyBodyJoints(tbWorld* world, tbBody* body);
/// Free the joint pool and arrays (world destruction).
void tbFreeJoints(tbWorld* world);
/// Draw every joint (draw.c).
void tbDrawJoints(tbWorld* world, const tbDebugDraw* draw);

// shape.c: shapes added and removed without the public checks (chains check their own input).
/// Add a shape to a body (geometry and def already checked); returns its index.
int tbAddShape(tbWorld* world, int bodyIndex, const tbShapeDef* def, const tbGeometry* geometry);
/// Remove a shape: its contacts, proxy and slot.
void tbRemoveShape(tbWorld* world, int shapeIndex, bool updateBodyMass);

// chain.c: what bodies and the world need of chains.
/// Destroy every chain of a body (tbDestroyBody frees the segment shapes with the body's shapes).
void tbDestroyBodyChains(tbWorld* world, int bodyIndex);
/// Free the chain pool (world destruction).
void tbFreeChains(tbWorld* world);

// Stages of the step, in order (world.c drives them; each lives in the file of its concept).
bool tbContactPairFilter(int shapeIdA, int shapeIdB, void* world); // contact.c: broad-phase pair filter
void tbContactPairPrefetch(int shapeIdA, int shapeIdB, void* world); // contact.c: its prefetch hint
void tbUpdatePairsStage(tbWorld* world);		// contact.c: broad-phase pairs → new contacts
void tbCollideStage(tbWorld* world);			// contact.c: narrow phase, begin/end events
void tbIslandStage(tbWorld* world);				// island.c: wake touching neighbours, gather solver contacts
void tbSolveStage(tbWorld* world, float timeStep, int subStepCount); // solver.c: integrate and solve
void tbFinalizeStage(tbWorld* world, float timeStep);	// body.c: boxes, proxies, sleep timers, move events
void tbContinuousStage(tbWorld* world);					// continuous.c: time of impact for fast bodies
bool tbMarkFastBody(const tbWorld* world, tbBody* body); // continuous.c: sets and returns body->isFast
void tbSleepStage(tbWorld* world, float timeStep);		// island.c: islands that stayed slow fall asleep
void tbReportHitEvents(tbWorld* world); // contact.c: after the solve

/// The world cannot change structure now (stepping, or inside a query callback). Reports why to
/// `function` (what it is about to do: `action`) and returns true when so.
bool tbStructureLocked(tbWorld* world, const char* function, const char* action);

