// Scene model: a plain-data description of a world (bodies, shapes, materials, methods) that the
// catalogue builds, scene files load and save, and Scene_BuildWorld turns into a tumble world.
// Nothing here holds a world: a Scene can be built, compared, exported and thrown away freely.
#pragma once

#include "tumble/tumble.h"

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SCENE_NAME_SIZE 32

/// Methods a scene asks for. A method applies only when its flag is set; otherwise the world
/// default (or a command-line override) is used.
typedef struct SceneMethods
{
	tbBroadPhaseMethod broadPhase;
	tbNarrowPhaseMethod narrowPhase;
	tbContinuousMethod continuous;
	tbSolverMethod solver;
	bool hasBroadPhase;
	bool hasNarrowPhase;
	bool hasContinuous;
	bool hasSolver;
} SceneMethods;

/// One shape: the library's tagged union plus its material.
typedef struct SceneShape
{
	tbGeometry geometry;
	float density;	   ///< kg/m², default 1
	float friction;	   ///< default 0.6
	float restitution; ///< default 0
	bool isSensor;
	bool enableHitEvents; ///< default false (tbShapeDef::enableHitEvents)
	int groupIndex; ///< collision group (tbFilter): shapes sharing a negative group never collide, default 0
	uint64_t categoryBits; ///< tbFilter's, default TB_DEFAULT_CATEGORY_BITS
	uint64_t maskBits;	   ///< tbFilter's, default TB_DEFAULT_MASK_BITS (all)
} SceneShape;

/// A scripted path for a kinematic body (Box2D v3's junkyard pusher): before step k (k = 0, 1, …)
/// the body's target pose is its initial position + amplitude·sin(angularFrequency·k·Δt) at its
/// initial angle, and the engine sets the velocity that reaches the target by the end of that
/// step (tbBody_SetTargetTransform). The body lags its path by one step, as in v3's benchmark.
typedef struct SceneDrive
{
	bool enabled;			///< default false: the body moves only by its own velocity
	tbVec2 amplitude;		///< m
	float angularFrequency; ///< rad/s
} SceneDrive;

/// One body and its shapes (geometry in the body frame).
typedef struct SceneBody
{
	tbBodyType type; ///< default static (as tbDefaultBodyDef)
	char name[SCENE_NAME_SIZE];
	tbVec2 position;
	float angle; ///< radians
	tbVec2 linearVelocity;
	float angularVelocity;
	float linearDamping;
	float angularDamping;
	float gravityScale; ///< default 1
	bool bullet;
	bool fixedRotation; ///< default false (tbBodyDef::fixedRotation): a character that stays upright
	bool isAwake; ///< default true
	float sleepThreshold; ///< m/s, default TB_LINEAR_SLEEP_TOLERANCE (tbBodyDef::sleepThreshold)
	SceneDrive drive;
	SceneShape* shapes;
	int shapeCount;
	int shapeCapacity;
} SceneBody;

/// One joint between two scene bodies: the library's definition of its kind, used as is when the
/// world is built (its body ids are filled in then). Start from Scene_AddJoint, which sets the
/// kind's defaults.
typedef struct SceneJoint
{
	tbJointType type;
	int bodyA; ///< scene body indices
	int bodyB;
	union
	{
		tbJointDef base; ///< the common part: every kind's definition starts with it
		tbDistanceJointDef distance;
		tbFilterJointDef filter;
		tbMotorJointDef motor;
		tbMoverJointDef mover;
		tbPogoJointDef pogo;
		tbPrismaticJointDef prismatic;
		tbRevoluteJointDef revolute;
		tbWeldJointDef weld;
		tbWheelJointDef wheel;
	} def;
} SceneJoint;

/// A chain (tbCreateChain) on a scene body: points in the body frame, one material for every
/// segment. An open chain's first and last points are ghosts (see tbChainDef).
typedef struct SceneChain
{
	int body; ///< scene body index
	tbVec2* points;
	int count;
	bool isLoop;
	float friction;	   ///< default 0.6
	float restitution; ///< default 0
} SceneChain;

struct Scene;

/// A group of bodies and joints built again and again by a spawner (Box2D v3's rain drops its
/// humans so): a scene of its own whose bodies and joints are placed relative to the spawn
/// point; its gravity, steps and methods are unused, and it may not hold chains or templates.
typedef struct SceneTemplate
{
	char name[SCENE_NAME_SIZE];
	struct Scene* parts;
} SceneTemplate;

/// A spawn schedule: instance n (n = 0, 1, …) of template `templateIndex` is built before step
/// firstStep + n·interval, its bodies translated by origin + (n mod slotCount)·slotStep, until
/// `count` instances have been built (count 0: no end). With lifetime L > 0 an instance built
/// before step s is destroyed (its joints, then its bodies) before step s + L. With keep > 0 at
/// most `keep` instances live at once: building instance n first destroys instance n − keep, so a
/// new instance takes the slot of the oldest. Within a step, spawners act in order, each
/// destroying before it builds; everything happens before the world steps.
typedef struct SceneSpawner
{
	int templateIndex; ///< index in Scene::templates
	int firstStep;	   ///< ≥ 0
	int interval;	   ///< steps between two spawns, ≥ 1
	int count;		   ///< ≥ 0, 0 = no end (then keep or lifetime must be > 0)
	int keep;		   ///< ≥ 0, 0 = no recycling
	int lifetime;	   ///< steps, ≥ 0, 0 = an instance lives until recycled or the end
	int slotCount;	   ///< ≥ 1 spawn points, used in turn
	tbVec2 origin;	   ///< m, the first spawn point
	tbVec2 slotStep;   ///< m, from one spawn point to the next
} SceneSpawner;

typedef struct Scene
{
	tbVec2 gravity;	  ///< default (0, −10)
	float timeStep;	  ///< s, default 1/60
	int subSteps;	  ///< default 4
	int steps;		  ///< suggested step count, default 600
	bool enableSleep; ///< default true
	SceneMethods methods;
	SceneBody* bodies;
	int bodyCount;
	int bodyCapacity;
	SceneJoint* joints;
	int jointCount;
	int jointCapacity;
	SceneChain* chains;
	int chainCount;
	int chainCapacity;
	SceneTemplate* templates;
	int templateCount;
	int templateCapacity;
	SceneSpawner* spawners;
	int spawnerCount;
	int spawnerCapacity;
} Scene;

/// Empty scene with the defaults above.
Scene* Scene_Create(void);
void Scene_Destroy(Scene* scene);

/// Body with the defaults above; returns its index.
int Scene_AddBody(Scene* scene, tbBodyType type, tbVec2 position, float angle);

/// Shape default material (density 1, friction 0.6, restitution 0, not a sensor).
SceneShape Scene_DefaultShape(void);

/// Append a copy of shape to body bodyIndex; returns the shape index within the body.
int Scene_AddShape(Scene* scene, int bodyIndex, const SceneShape* shape);

/// Convenience: a shape from geometry with the default material changed by density and friction.
int Scene_AddGeometry(Scene* scene, int bodyIndex, const tbGeometry* geometry, float density, float friction);

tbGeometry Scene_MakeBoxGeometry(float halfWidth, float halfHeight, tbVec2 center, float angle);
tbGeometry Scene_MakeCircleGeometry(tbVec2 center, float radius);
tbGeometry Scene_MakeCapsuleGeometry(tbVec2 center1, tbVec2 center2, float radius);
tbGeometry Scene_MakeSegmentGeometry(tbVec2 point1, tbVec2 point2);
tbGeometry Scene_MakePolygonGeometry(const tbVec2* points, int count, float radius);

/// A joint of the given kind between bodies bodyA and bodyB with the kind's defaults; returns it
/// (valid until the next joint is added).
SceneJoint* Scene_AddJoint(Scene* scene, tbJointType type, int bodyA, int bodyB);

/// Put both joint frames' origins at a world point (from the bodies' placement in the scene).
void Scene_SetJointAnchor(const Scene* scene, SceneJoint* joint, tbVec2 worldPoint);

/// The default definition of a joint kind, as tbDefault*JointDef gives it (in SceneJoint's union).
void Scene_DefaultJointDef(tbJointType type, SceneJoint* joint);

/// Append a chain (points copied) on body bodyIndex with friction 0.6; returns it (valid until
/// the next chain is added).
SceneChain* Scene_AddChain(Scene* scene, int bodyIndex, const tbVec2* points, int count, bool isLoop);

/// Append an empty template (its parts a new scene to fill with Scene_AddBody, Scene_AddJoint…);
/// returns its index.
int Scene_AddTemplate(Scene* scene, const char* name);

/// Index of the template called name, −1 when there is none.
int Scene_FindTemplate(const Scene* scene, const char* name);

/// Append a spawner of template templateIndex starting at step 0 every `interval` steps, one
/// spawn point (origin), no end and no recycling; returns it (valid until the next is added).
SceneSpawner* Scene_AddSpawner(Scene* scene, int templateIndex, int interval, tbVec2 origin);

/// Instance built before step `step` by the spawner, or −1 when it builds none then.
int SceneSpawner_InstanceAt(const SceneSpawner* spawner, int step);

/// Instance whose lifetime ends before step `step` (built before step − lifetime), or −1.
int SceneSpawner_ExpiryAt(const SceneSpawner* spawner, int step);

/// Most instances alive at once (keep, count, lifetime / interval rounded up: the least that
/// applies); 1 when nothing bounds them (scene files refuse such a spawner).
int SceneSpawner_Capacity(const SceneSpawner* spawner);

/// Translation of instance n's bodies.
tbVec2 SceneSpawner_Offset(const SceneSpawner* spawner, int instance);

/// Bodies and joints alive after `steps` steps (spawns before steps 0 … steps − 1 done), counted
/// in closed form from the schedule: the scene's own plus every living instance's.
void Scene_LiveCounts(const Scene* scene, int steps, int* bodyCount, int* jointCount);

/// Total shape count over every body.
int Scene_ShapeCount(const Scene* scene);

/// Target pose of driven body bodyIndex before step `step` (see SceneDrive); false when the body
/// is not driven.
bool Scene_DriveTarget(const Scene* scene, int bodyIndex, int step, tbTransform* target);

/// Velocities that carry a body from its current pose to `target` in one step of timeStep, for
/// engines without a target-transform call: v = (c_t − c)/Δt for the centre of mass c (localCenter
/// in the body frame), ω = shortest signed angle from q to q_t over Δt (tbBody_SetTargetTransform's rule).
void Scene_TargetVelocity(tbTransform current, tbVec2 localCenter, tbTransform target, float timeStep,
						  tbVec2* linearVelocity, float* angularVelocity);

/// Overrides applied on top of the scene when a world is built. Zero-initialise, then set.
typedef struct SceneOverrides
{
	SceneMethods methods;	///< a method applies when its flag is set
	int velocityIterations; ///< > 0 replaces the world default
	int subSteps;			///< > 0 replaces the scene's sub-step count (for callers that step)
	int relaxIterations;	///< > 0 replaces tbWorldDef::relaxIterations (soft step's relaxing passes)
	int finalRelaxIterations; ///< with finalRelaxGiven, replaces tbWorldDef::finalRelaxIterations
	bool finalRelaxGiven;
	float settledHertzRatio; ///< > 0 replaces tbWorldDef::settledHertzRatio
	bool scalarSolver;		///< true: the scalar reference contact solver (tbWorldDef::enableWideSolver off)
	bool noRecycle;			///< true: every manifold recomputed (tbWorldDef::enableManifoldRecycling off)
	bool pointFriction;		///< true: a friction row per manifold point (tbWorldDef::enableCentralFriction off)
	bool impactPropagation; ///< true: tbWorldDef::enableImpactPropagation (Newton's cradle)
	struct TaskSystem* tasks; ///< non-null: the world runs on its workers (task_system.h)
	/// Another task system (when tasks is NULL and enqueueTask is set): its callbacks, context and
	/// worker count go into the world definition as they are.
	tbEnqueueTaskCallback* enqueueTask;
	tbFinishTaskCallback* finishTask;
	void* userTaskContext;
	int workerCount;
} SceneOverrides;

/// World definition for the scene: defaults, then the scene's gravity, sleep and methods, then overrides.
tbWorldDef Scene_MakeWorldDef(const Scene* scene, const SceneOverrides* overrides);

/// The living instances of one spawner in a built world: a ring of SceneSpawner_Capacity
/// instances, each `bodiesPer` body ids and `jointsPer` joint ids.
typedef struct SpawnedInstances
{
	tbBodyId* bodyIds;	 ///< capacity × bodiesPer
	tbJointId* jointIds; ///< capacity × jointsPer
	int bodiesPer;
	int jointsPer;
	int capacity;
	int built; ///< instances built so far (instance n sits in slot n mod capacity)
	SceneSpawner schedule;
} SpawnedInstances;

/// A built world and the mapping from scene body index to body id.
typedef struct SceneWorld
{
	tbWorldId worldId;
	tbBodyId* bodyIds; ///< bodyCount entries, index = scene body index
	int bodyCount;
	tbJointId* jointIds; ///< jointCount entries, index = scene joint index
	int jointCount;
	char (*names)[SCENE_NAME_SIZE]; ///< body names (the library does not copy them)
	int* drivenBodies;				///< scene indices of the driven bodies (SceneDrive)
	int drivenCount;
	int stepIndex; ///< steps taken by SceneWorld_Step
	SpawnedInstances* spawned; ///< one per scene spawner
	int spawnerCount;
} SceneWorld;

/// Build a world from the scene. overrides may be NULL. worldId is null on failure.
SceneWorld Scene_BuildWorld(const Scene* scene, const SceneOverrides* overrides);

/// Build into a world made from def (start it from Scene_MakeWorldDef).
SceneWorld Scene_BuildWorldWithDef(const Scene* scene, const tbWorldDef* def);

/// Build the scene into a scratch world; true when the library refuses a body or shape, with its
/// path ("bodies[2].shapes[0]") in item. The library's error hook has then received the reason.
bool Scene_FindRefusedItem(const Scene* scene, char* item, int itemSize);

/// Body ids of instance n of spawner s (bodiesPer of them, in template order), or NULL when the
/// instance is not alive (not built yet, recycled or past its lifetime: copy ids to keep them).
const tbBodyId* SceneWorld_InstanceBodies(const SceneWorld* world, int spawner, int instance);

/// Every living body of the world, the scene's first (scene order), then the spawned ones
/// (spawner by spawner, slot by slot): writes at most capacity ids into out, returns how many.
/// SceneWorld_BodyCapacity bounds the count.
int SceneWorld_CollectBodies(const SceneWorld* world, tbBodyId* out, int capacity);
int SceneWorld_BodyCapacity(const SceneWorld* world);

/// One step of the scene: the spawners destroy and build their instances for this step (see
/// SceneSpawner), the driven bodies get their target for this step, then the world
/// steps by the scene's time step with subSteps sub-steps. Returns tbWorld_Step's answer.
bool SceneWorld_Step(SceneWorld* world, const Scene* scene, int subSteps);

/// Destroy the world and free the mapping.
void SceneWorld_Destroy(SceneWorld* world);

/// Σ ½mv² + ½Iω² over the bodies of the world (J).
float SceneWorld_KineticEnergy(const SceneWorld* world);

/// Number of awake non-static bodies.
int SceneWorld_AwakeCount(const SceneWorld* world);

/// Largest penetration depth (m, ≥ 0) over all touching shape pairs, found by querying the
/// world for shapes overlapping each non-static shape's box and colliding the pair. For summaries.
float SceneWorld_LargestPenetration(const SceneWorld* world);
/// Whether shapes with these filters collide, by tbFilter's rule (a shared non-zero group decides,
/// negative never; otherwise each category in the other's mask). For measures that must skip the
/// pairs a scene keeps apart on purpose.
bool Scene_FiltersCollide(int groupA, uint64_t categoryA, uint64_t maskA, int groupB, uint64_t categoryB,
						  uint64_t maskB);

/// Method names as used by scene files and the command line. NULL for an unknown value.
const char* Scene_BroadPhaseName(tbBroadPhaseMethod method);
const char* Scene_NarrowPhaseName(tbNarrowPhaseMethod method);
const char* Scene_ContinuousName(tbContinuousMethod method);
const char* Scene_SolverName(tbSolverMethod method);
const char* Scene_BodyTypeName(tbBodyType type);
const char* Scene_JointTypeName(tbJointType type);

/// Parse a method name; false when unknown.
bool Scene_ParseBroadPhase(const char* text, tbBroadPhaseMethod* method);
bool Scene_ParseNarrowPhase(const char* text, tbNarrowPhaseMethod* method);
bool Scene_ParseContinuous(const char* text, tbContinuousMethod* method);
bool Scene_ParseSolver(const char* text, tbSolverMethod* method);
bool Scene_ParseBodyType(const char* text, tbBodyType* type);
bool Scene_ParseJointType(const char* text, tbJointType* type);

#ifdef __cplusplus
}
#endif
