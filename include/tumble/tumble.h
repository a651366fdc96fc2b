// Tumble: a 2D rigid-body physics engine. The umbrella header: include this one.
// The API follows Box2D v3's grammar with the prefix tb (b2CreateWorld → tbCreateWorld).
#pragma once

#include "base.h"
#include "collision.h"
#include "constants.h"
#include "id.h"
#include "math_functions.h"
#include "types.h"

#ifdef __cplusplus
extern "C" {
#endif

// ---------------------------------------------------------------------------------------------
// World

/// Create a world. Returns a null id and reports an error on a bad definition or when
/// TB_MAX_WORLDS exist.
TB_API tbWorldId tbCreateWorld(const tbWorldDef* def);

/// Destroy a world and everything in it. Its body and shape ids become stale.
TB_API void tbDestroyWorld(tbWorldId worldId);

TB_API bool tbWorld_IsValid(tbWorldId worldId);

/// Advance the world by timeStep seconds in subStepCount sub-steps (≥ 1). Returns false and
/// changes nothing when an argument is bad (time step ≤ 0 or not finite, sub-steps < 1).
TB_API bool tbWorld_Step(tbWorldId worldId, float timeStep, int subStepCount);

TB_API void tbWorld_Draw(tbWorldId worldId, const tbDebugDraw* draw);

TB_API tbBodyEvents tbWorld_GetBodyEvents(tbWorldId worldId);
TB_API tbSensorEvents tbWorld_GetSensorEvents(tbWorldId worldId);
TB_API tbContactEvents tbWorld_GetContactEvents(tbWorldId worldId);

TB_API bool tbWorld_SetGravity(tbWorldId worldId, tbVec2 gravity);
TB_API tbVec2 tbWorld_GetGravity(tbWorldId worldId);
TB_API void tbWorld_EnableSleeping(tbWorldId worldId, bool flag);
TB_API bool tbWorld_IsSleepingEnabled(tbWorldId worldId);
TB_API bool tbWorld_SetContactTuning(tbWorldId worldId, float hertz, float dampingRatio, float pushSpeed);
TB_API bool tbWorld_SetRestitutionThreshold(tbWorldId worldId, float value);
TB_API bool tbWorld_SetHitEventThreshold(tbWorldId worldId, float value);
TB_API void tbWorld_SetFrictionCallback(tbWorldId worldId, tbFrictionCallback* callback);
TB_API void tbWorld_SetRestitutionCallback(tbWorldId worldId, tbRestitutionCallback* callback);
TB_API void* tbWorld_GetUserData(tbWorldId worldId);

/// Change methods between steps (the benchmark and verification tools use these).
TB_API bool tbWorld_SetBroadPhaseMethod(tbWorldId worldId, tbBroadPhaseMethod method);
TB_API bool tbWorld_SetNarrowPhaseMethod(tbWorldId worldId, tbNarrowPhaseMethod method);
TB_API bool tbWorld_SetContinuousMethod(tbWorldId worldId, tbContinuousMethod method);
TB_API bool tbWorld_SetSolverMethod(tbWorldId worldId, tbSolverMethod method, int velocityIterations,
									int positionIterations);
/// Manifold recycling on or off (tbWorldDef::enableManifoldRecycling).
TB_API void tbWorld_EnableManifoldRecycling(tbWorldId worldId, bool flag);
/// The methods in force (after `auto` resolution).
TB_API tbWorldDef tbWorld_GetDef(tbWorldId worldId);

TB_API tbProfile tbWorld_GetProfile(tbWorldId worldId);
TB_API tbCounters tbWorld_GetCounters(tbWorldId worldId);

// Queries -------------------------------------------------------------------------------------

/// Overlap callback: return false to stop the query.
typedef bool tbOverlapResultFcn(tbShapeId shapeId, void* context);

/// Ray callback: return −1 to ignore this shape, 0 to stop, `fraction` to clip to this hit,
/// 1 to continue without clipping.
typedef float tbCastResultFcn(tbShapeId shapeId, tbVec2 point, tbVec2 normal, float fraction, void* context);

typedef struct tbRayResult
{
	tbShapeId shapeId;
	tbVec2 point;
	tbVec2 normal;
	float fraction;
	bool hit;
} tbRayResult;

/// Shapes whose fat boxes overlap aabb.
TB_API bool tbWorld_OverlapAABB(tbWorldId worldId, tbAABB aabb, tbQueryFilter filter, tbOverlapResultFcn* fcn,
								void* context);
/// Shapes containing the point.
TB_API bool tbWorld_OverlapPoint(tbWorldId worldId, tbVec2 point, tbQueryFilter filter, tbOverlapResultFcn* fcn,
								 void* context);
/// Shapes overlapping a given shape placed at transform.
TB_API bool tbWorld_OverlapShape(tbWorldId worldId, const tbGeometry* shape, tbTransform transform,
								 tbQueryFilter filter, tbOverlapResultFcn* fcn, void* context);
/// Every shape hit by the ray origin → origin + translation, in no particular order, clipped by the callback.
TB_API bool tbWorld_CastRay(tbWorldId worldId, tbVec2 origin, tbVec2 translation, tbQueryFilter filter,
							tbCastResultFcn* fcn, void* context);
/// The closest hit.
TB_API tbRayResult tbWorld_CastRayClosest(tbWorldId worldId, tbVec2 origin, tbVec2 translation, tbQueryFilter filter);
/// Every shape hit by a shape moving by translation (GJK shape cast).
TB_API bool tbWorld_CastShape(tbWorldId worldId, const tbGeometry* shape, tbTransform transform, tbVec2 translation,
							  tbQueryFilter filter, tbCastResultFcn* fcn, void* context);

// ---------------------------------------------------------------------------------------------
// Bodies

TB_API tbBodyId tbCreateBody(tbWorldId worldId, const tbBodyDef* def);
/// Destroys the body, its shapes and its contacts.
TB_API void tbDestroyBody(tbBodyId bodyId);
TB_API bool tbBody_IsValid(tbBodyId bodyId);

TB_API tbBodyType tbBody_GetType(tbBodyId bodyId);
TB_API bool tbBody_SetType(tbBodyId bodyId, tbBodyType type);
TB_API tbVec2 tbBody_GetPosition(tbBodyId bodyId);
TB_API tbRot tbBody_GetRotation(tbBodyId bodyId);
TB_API float tbBody_GetAngle(tbBodyId bodyId);
TB_API tbTransform tbBody_GetTransform(tbBodyId bodyId);
/// Teleport. Wakes the body.
TB_API bool tbBody_SetTransform(tbBodyId bodyId, tbVec2 position, tbRot rotation);
TB_API tbVec2 tbBody_GetLocalPoint(tbBodyId bodyId, tbVec2 worldPoint);
TB_API tbVec2 tbBody_GetWorldPoint(tbBodyId bodyId, tbVec2 localPoint);
TB_API tbVec2 tbBody_GetLocalVector(tbBodyId bodyId, tbVec2 worldVector);
TB_API tbVec2 tbBody_GetWorldVector(tbBodyId bodyId, tbVec2 localVector);

TB_API tbVec2 tbBody_GetLinearVelocity(tbBodyId bodyId);
TB_API float tbBody_GetAngularVelocity(tbBodyId bodyId);
TB_API bool tbBody_SetLinearVelocity(tbBodyId bodyId, tbVec2 linearVelocity);
TB_API bool tbBody_SetAngularVelocity(tbBodyId bodyId, float angularVelocity);

TB_API bool tbBody_ApplyForce(tbBodyId bodyId, tbVec2 force, tbVec2 point, bool wake);
TB_API bool tbBody_ApplyForceToCenter(tbBodyId bodyId, tbVec2 force, bool wake);
TB_API bool tbBody_ApplyTorque(tbBodyId bodyId, float torque, bool wake);
TB_API bool tbBody_ApplyLinearImpulse(tbBodyId bodyId, tbVec2 impulse, tbVec2 point, bool wake);
TB_API bool tbBody_ApplyLinearImpulseToCenter(tbBodyId bodyId, tbVec2 impulse, bool wake);
TB_API bool tbBody_ApplyAngularImpulse(tbBodyId bodyId, float impulse, bool wake);

TB_API float tbBody_GetMass(tbBodyId bodyId);
/// Rotational inertia about the centre of mass (kg·m²).
TB_API float tbBody_GetRotationalInertia(tbBodyId bodyId);
TB_API tbVec2 tbBody_GetLocalCenterOfMass(tbBodyId bodyId);
TB_API tbVec2 tbBody_GetWorldCenterOfMass(tbBodyId bodyId);
TB_API tbMassData tbBody_GetMassData(tbBodyId bodyId);

TB_API bool tbBody_SetLinearDamping(tbBodyId bodyId, float linearDamping);
TB_API float tbBody_GetLinearDamping(tbBodyId bodyId);
TB_API bool tbBody_SetAngularDamping(tbBodyId bodyId, float angularDamping);
TB_API float tbBody_GetAngularDamping(tbBodyId bodyId);
TB_API bool tbBody_SetGravityScale(tbBodyId bodyId, float gravityScale);
TB_API float tbBody_GetGravityScale(tbBodyId bodyId);
TB_API bool tbBody_IsAwake(tbBodyId bodyId);
TB_API void tbBody_SetAwake(tbBodyId bodyId, bool awake);
TB_API void tbBody_EnableSleep(tbBodyId bodyId, bool enableSleep);
TB_API bool tbBody_IsBullet(tbBodyId bodyId);
TB_API void tbBody_SetBullet(tbBodyId bodyId, bool flag);
TB_API void tbBody_SetFixedRotation(tbBodyId bodyId, bool flag);
TB_API void tbBody_SetUserData(tbBodyId bodyId, void* userData);
TB_API void* tbBody_GetUserData(tbBodyId bodyId);
TB_API const char* tbBody_GetName(tbBodyId bodyId);
TB_API tbWorldId tbBody_GetWorld(tbBodyId bodyId);
TB_API int tbBody_GetShapeCount(tbBodyId bodyId);
/// Fill shapeArray with up to capacity shape ids; returns the number written.
TB_API int tbBody_GetShapes(tbBodyId bodyId, tbShapeId* shapeArray, int capacity);
/// Union of the body's shape boxes.
TB_API tbAABB tbBody_ComputeAABB(tbBodyId bodyId);

// ---------------------------------------------------------------------------------------------
// Shapes. Geometry is given in the body's frame and copied.

TB_API tbShapeId tbCreateCircleShape(tbBodyId bodyId, const tbShapeDef* def, const tbCircle* circle);
TB_API tbShapeId tbCreateCapsuleShape(tbBodyId bodyId, const tbShapeDef* def, const tbCapsule* capsule);
TB_API tbShapeId tbCreatePolygonShape(tbBodyId bodyId, const tbShapeDef* def, const tbPolygon* polygon);
TB_API tbShapeId tbCreateSegmentShape(tbBodyId bodyId, const tbShapeDef* def, const tbSegment* segment);
/// Any shape from a tagged union.
TB_API tbShapeId tbCreateShape(tbBodyId bodyId, const tbShapeDef* def, const tbGeometry* geometry);
TB_API void tbDestroyShape(tbShapeId shapeId, bool updateBodyMass);
TB_API bool tbShape_IsValid(tbShapeId shapeId);

TB_API tbShapeType tbShape_GetType(tbShapeId shapeId);
TB_API tbBodyId tbShape_GetBody(tbShapeId shapeId);
TB_API tbGeometry tbShape_GetGeometry(tbShapeId shapeId);
TB_API bool tbShape_IsSensor(tbShapeId shapeId);
TB_API bool tbShape_SetDensity(tbShapeId shapeId, float density, bool updateBodyMass);
TB_API float tbShape_GetDensity(tbShapeId shapeId);
TB_API bool tbShape_SetFriction(tbShapeId shapeId, float friction);
TB_API float tbShape_GetFriction(tbShapeId shapeId);
TB_API bool tbShape_SetRestitution(tbShapeId shapeId, float restitution);
TB_API float tbShape_GetRestitution(tbShapeId shapeId);
TB_API tbFilter tbShape_GetFilter(tbShapeId shapeId);
TB_API bool tbShape_SetFilter(tbShapeId shapeId, tbFilter filter);
TB_API void tbShape_SetUserData(tbShapeId shapeId, void* userData);
TB_API void* tbShape_GetUserData(tbShapeId shapeId);
TB_API tbAABB tbShape_GetAABB(tbShapeId shapeId);
TB_API bool tbShape_TestPoint(tbShapeId shapeId, tbVec2 point);
TB_API tbCastOutput tbShape_RayCast(tbShapeId shapeId, const tbRayCastInput* input);
TB_API tbMassData tbShape_GetMassData(tbShapeId shapeId);

#ifdef __cplusplus
}
#endif
