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
} SceneShape;

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
	bool isAwake; ///< default true
	SceneShape* shapes;
	int shapeCount;
	int shapeCapacity;
} SceneBody;

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

/// Total shape count over every body.
int Scene_ShapeCount(const Scene* scene);

/// Overrides applied on top of the scene when a world is built. Zero-initialise, then set.
typedef struct SceneOverrides
{
	SceneMethods methods;	///< a method applies when its flag is set
	int velocityIterations; ///< > 0 replaces the world default
	int subSteps;			///< > 0 replaces the scene's sub-step count (for callers that step)
	bool scalarSolver;		///< true: the scalar reference contact solver (tbWorldDef::enableWideSolver off)
	bool noRecycle;			///< true: every manifold recomputed (tbWorldDef::enableManifoldRecycling off)
} SceneOverrides;

/// World definition for the scene: defaults, then the scene's gravity, sleep and methods, then overrides.
tbWorldDef Scene_MakeWorldDef(const Scene* scene, const SceneOverrides* overrides);

/// A built world and the mapping from scene body index to body id.
typedef struct SceneWorld
{
	tbWorldId worldId;
	tbBodyId* bodyIds; ///< bodyCount entries, index = scene body index
	int bodyCount;
	char (*names)[SCENE_NAME_SIZE]; ///< body names (the library does not copy them)
} SceneWorld;

/// Build a world from the scene. overrides may be NULL. worldId is null on failure.
SceneWorld Scene_BuildWorld(const Scene* scene, const SceneOverrides* overrides);

/// Build into a world made from def (start it from Scene_MakeWorldDef).
SceneWorld Scene_BuildWorldWithDef(const Scene* scene, const tbWorldDef* def);

/// Destroy the world and free the mapping.
void SceneWorld_Destroy(SceneWorld* world);

/// Σ ½mv² + ½Iω² over the bodies of the world (J).
float SceneWorld_KineticEnergy(const SceneWorld* world);

/// Number of awake non-static bodies.
int SceneWorld_AwakeCount(const SceneWorld* world);

/// Largest penetration depth (m, ≥ 0) over all touching shape pairs, found by querying the
/// world for shapes overlapping each non-static shape's box and colliding the pair. For summaries.
float SceneWorld_LargestPenetration(const SceneWorld* world);

/// Method names as used by scene files and the command line. NULL for an unknown value.
const char* Scene_BroadPhaseName(tbBroadPhaseMethod method);
const char* Scene_NarrowPhaseName(tbNarrowPhaseMethod method);
const char* Scene_ContinuousName(tbContinuousMethod method);
const char* Scene_SolverName(tbSolverMethod method);
const char* Scene_BodyTypeName(tbBodyType type);

/// Parse a method name; false when unknown.
bool Scene_ParseBroadPhase(const char* text, tbBroadPhaseMethod* method);
bool Scene_ParseNarrowPhase(const char* text, tbNarrowPhaseMethod* method);
bool Scene_ParseContinuous(const char* text, tbContinuousMethod* method);
bool Scene_ParseSolver(const char* text, tbSolverMethod* method);
bool Scene_ParseBodyType(const char* text, tbBodyType* type);

#ifdef __cplusplus
}
#endif
