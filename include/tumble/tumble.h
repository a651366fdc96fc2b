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
#if defined(TUMBLE_DOUBLE_PRECISION)
// A program compiled for one precision and linked with a library built for the other would pass
// tbPos values of the wrong size; under this name the mismatch is a link error instead.
#define tbCreateWorld tbCreateWorldDoublePrecision
#endif
TB_API tbWorldId tbCreateWorld(const tbWorldDef* def);
/// Workers the step may use from now on, clamped to [1, TB_MAX_WORKERS]; without task callbacks
/// the step runs on the caller whatever the count. Not while the world steps or is queried.
TB_API void tbWorld_SetWorkerCount(tbWorldId worldId, int count);
TB_API int tbWorld_GetWorkerCount(tbWorldId worldId);

/// Destroy a world and everything in it. Its body, shape and joint ids become stale.
TB_API void tbDestroyWorld(tbWorldId worldId);

TB_API bool tbWorld_IsValid(tbWorldId worldId);

/// Advance the world by timeStep seconds in subStepCount sub-steps (≥ 1). Returns false and
/// changes nothing when an argument is bad (time step ≤ 0 or not finite, sub-steps < 1).
TB_API bool tbWorld_Step(tbWorldId worldId, float timeStep, int subStepCount);

TB_API void tbWorld_Draw(tbWorldId worldId, tbDebugDraw* draw);

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
TB_API float tbWorld_GetRestitutionThreshold(tbWorldId worldId);
TB_API float tbWorld_GetHitEventThreshold(tbWorldId worldId);
TB_API void tbWorld_SetFrictionCallback(tbWorldId worldId, tbFrictionCallback* callback);
TB_API void tbWorld_SetRestitutionCallback(tbWorldId worldId, tbRestitutionCallback* callback);
/// Register the custom filter (NULL removes it); see tbCustomFilterFcn.
TB_API void tbWorld_SetCustomFilterCallback(tbWorldId worldId, tbCustomFilterFcn* fcn, void* context);
/// Register the pre-solve and pre-continuous callbacks (either may be NULL); see tbPreSolveFcn.
TB_API void tbWorld_SetPreSolveCallback(tbWorldId worldId, tbPreSolveFcn* preSolveFcn,
										tbPreContinuousFcn* preContinuousFcn, void* context);
TB_API void* tbWorld_GetUserData(tbWorldId worldId);
TB_API void tbWorld_SetUserData(tbWorldId worldId, void* userData);
TB_API int tbWorld_GetAwakeBodyCount(tbWorldId worldId);
TB_API void tbWorld_EnableWarmStarting(tbWorldId worldId, bool flag);
TB_API bool tbWorld_IsWarmStartingEnabled(tbWorldId worldId);
/// Off: no time of impact (fast bodies may tunnel); on again restores the method that was in force.
TB_API void tbWorld_EnableContinuous(tbWorldId worldId, bool flag);
TB_API bool tbWorld_IsContinuousEnabled(tbWorldId worldId);
/// The speed clamp on every body (m/s, > 0 and ≤ TB_MAX_LINEAR_SPEED; refused otherwise).
TB_API void tbWorld_SetMaximumLinearSpeed(tbWorldId worldId, float maximumLinearSpeed);
TB_API float tbWorld_GetMaximumLinearSpeed(tbWorldId worldId);

/// Change methods between steps (the benchmark and verification tools use these).
TB_API bool tbWorld_SetBroadPhaseMethod(tbWorldId worldId, tbBroadPhaseMethod method);
TB_API bool tbWorld_SetNarrowPhaseMethod(tbWorldId worldId, tbNarrowPhaseMethod method);
TB_API bool tbWorld_SetContinuousMethod(tbWorldId worldId, tbContinuousMethod method);
TB_API bool tbWorld_SetSolverMethod(tbWorldId worldId, tbSolverMethod method, int velocityIterations,
									int positionIterations);
/// Manifold recycling on or off (tbWorldDef::enableManifoldRecycling).
TB_API void tbWorld_EnableManifoldRecycling(tbWorldId worldId, bool flag);
/// Central friction on or off (tbWorldDef::enableCentralFriction): one friction row per contact at
/// its centre of pressure, or one per manifold point. Refused during the step.
TB_API void tbWorld_EnableCentralFriction(tbWorldId worldId, bool flag);
/// The methods in force (after `auto` resolution).
TB_API tbWorldDef tbWorld_GetDef(tbWorldId worldId);

TB_API tbProfile tbWorld_GetProfile(tbWorldId worldId);
TB_API tbCounters tbWorld_GetCounters(tbWorldId worldId);

/// Manifold recycling's distance (m, Box2D v3.2's contact recycle distance): a touching polygon or
/// segment pair keeps its manifold while neither body moved more than this relative to the other
/// (and less than TB_RECYCLE_ANGLE, and less than the pair's margin allows, contact.c) since it was
/// computed. Default TB_RECYCLE_DISTANCE (0.02 m); 0 recomputes every manifold. Refused (false,
/// error hook): stale id, locked world, not finite and within 0..TB_MAX_COORDINATE.
TB_API bool tbWorld_SetContactRecycleDistance(tbWorldId worldId, float recycleDistance);
TB_API float tbWorld_GetContactRecycleDistance(tbWorldId worldId);

/// For tests (Box2D v3.2's switch): false drops, of a two-point manifold, a point more than
/// 1.5 × TB_LINEAR_SLOP apart, so the solver sees no speculative second point. Default true.
TB_API void tbWorld_EnableSpeculative(tbWorldId worldId, bool flag);

/// The union of every shape's broad-phase box (fat for movable shapes, tight for static ones);
/// all zero for a world without shapes in the broad phase. Refused (error hook, zero box) during the
/// step, e.g. from a pre-solve callback; allowed in a query callback.
TB_API tbAABB tbWorld_GetBounds(tbWorldId worldId);

/// The largest counts (static and dynamic-or-kinematic shapes in the broad phase and bodies, and
/// contacts) seen at the start of any step so far: a tbWorldDef::capacity with which the same run
/// allocates no more for these arrays.
TB_API tbCapacity tbWorld_GetMaxCapacity(tbWorldId worldId);

/// Rebuild the static shapes' tree now (binned SAH; tree broad phase only, otherwise nothing). The
/// tree is rebuilt on its own after bulk static insertions; trajectories do not depend on its shape.
/// Refused (error hook) during the step and inside query callbacks (the tree may be being walked).
TB_API void tbWorld_RebuildStaticTree(tbWorldId worldId);

/// A 64-bit hash of the simulation state for determinism checks (a desync between two runs, a
/// rollback): two worlds that simulated the same way bit for bit have the same hash. What it covers
/// (world_diagnostics.c): each live body in id order (id, type, awake, enabled,
/// transform, centre of mass, velocities, forces, sleep time), each live contact in id order (its
/// shapes, flags, and each manifold point's separation and impulses), each live joint in id order
/// (type, bodies, accumulated impulses of its kind) and the pools' counts and high-water marks.
/// Not user data, names, callbacks, settings, the broad phase's layout or free slots. FNV-1a
/// over the values' bytes. 0 for a refused id.
TB_API uint64_t tbWorld_GetStateHash(tbWorldId worldId);

// Recording (Box2D v3.2's recording group) -------------------------------------------------

/// A recording buffer (opaque): the bytes of a recorded session, which a world appends to while it
/// records. Create one, hand it to tbWorld_StartRecording, then save its bytes and destroy it.
typedef struct tbRecording tbRecording;

/// A new, empty recording buffer. It grows as needed; byteCapacity sizes it up front (0: a small
/// default). Returns NULL (error hook) for a negative byteCapacity. Free with tbDestroyRecording.
TB_API tbRecording* tbCreateRecording(int byteCapacity);

/// Free a recording buffer. A world still recording into it stops first. NULL is ignored.
TB_API void tbDestroyRecording(tbRecording* recording);

/// The recorded bytes (a sealed recording: header, checksum and all), to save or send. Valid until
/// the world records more or the buffer is destroyed. NULL (error hook) for a NULL recording.
TB_API const uint8_t* tbRecording_GetData(const tbRecording* recording);

/// Number of recorded bytes (0 before tbWorld_StartRecording).
TB_API int tbRecording_GetSize(const tbRecording* recording);

/// Start recording the world into an empty recording buffer: a snapshot of the world as it is now
/// (tbWorld_Snapshot), then every call that changes the world (creations, destructions, setters,
/// forces, impulses, explosions, world settings), the spatial queries with their results (for the
/// player to show), and every step with the state hash it ended on (tbWorld_GetStateHash).
/// Callbacks (custom filter, pre-solve, friction and restitution mixing) and user data are host
/// wiring, not recorded. Refused (error hook, nothing changes): stale id, NULL or non-empty
/// recording, a recording another world uses, a world already recording, a locked world (during
/// the step or inside a query callback).
TB_API void tbWorld_StartRecording(tbWorldId worldId, tbRecording* recording);

/// Stop recording. The buffer keeps its bytes; save and destroy it yourself. Refused (error hook)
/// for a stale id or a world that is not recording.
TB_API void tbWorld_StopRecording(tbWorldId worldId);

/// Write a recording's bytes to a file. Returns false (error hook) when it cannot be written.
TB_API bool tbSaveRecordingToFile(const tbRecording* recording, const char* path);

/// Read a recording from a file into a new recording buffer (free it with tbDestroyRecording).
/// The file is checked as tbRecPlayer_Create checks bytes (header, version, precision, length
/// units, size, checksum); returns NULL (error hook naming the problem) for a missing, unreadable,
/// truncated or corrupt file.
TB_API tbRecording* tbLoadRecordingFromFile(const char* path);

// Snapshots (Box2D v3.2's snapshot group) ---------------------------------------------------

/// Write the world's whole simulation state into image, a byte array the caller owns: pass NULL and
/// 0 first to learn the size, then a buffer of at least that size. Returns the size the image needs;
/// when it exceeds capacity nothing is written. Call between steps: a locked world (from inside the
/// step, e.g. a pre-solve callback) returns 0. The image holds what the next steps read (bodies,
/// shapes, chains, contacts with their manifolds and warm-start impulses, joints and their
/// impulses, the id pools with their free lists and generations, the awake list, the broad phase,
/// settings and the step index), so a world restored from it steps on bit for bit as the world it
/// was taken from. Not stored: host wiring (task system, worker count, user data of the world,
/// bodies, shapes and joints, callbacks) and the last step's events. An image starts with a header
/// (magic "TBSN", format version, float or double-precision build, size, length units, checksum)
/// and is only read by a build of the same precision in the same length units. Refused (0, error
/// hook): stale id, locked world, NULL image with a non-zero capacity, negative capacity.
TB_API int tbWorld_Snapshot(tbWorldId worldId, uint8_t* image, int capacity);

/// Restore the world in place from an image of size bytes made by tbWorld_Snapshot. The world keeps
/// its id and its host wiring (task system, worker count, world user data, custom filter, pre-solve,
/// friction and restitution callbacks); ids of bodies, shapes, joints and chains that existed when
/// the image was taken are valid again and name the same objects, ids made since are refused (until
/// the same objects are made again: the next body created gets the id it got after the snapshot was
/// taken), and body, shape and joint user data read NULL (as in Box2D v3.2). The whole image is
/// checked before anything changes: a refused image (truncated, corrupt: wrong checksum, made by
/// another format version, precision or length unit, or holding anything out of range) leaves the
/// world exactly as it was (Box2D v3.2 may leave it unusable). Returns false (error hook naming what
/// was wrong) for those, a stale id, a NULL image, a negative size, or a locked world (during the
/// step or inside a query callback).
TB_API bool tbWorld_Restore(tbWorldId worldId, const uint8_t* image, int size);

/// A new world (a new id, its host wiring the defaults of tbDefaultWorldDef) holding the state of an
/// image made by tbWorld_Snapshot: it steps on bit for bit as the world the image was taken from.
/// workerCount: 1 to TB_MAX_WORKERS, or 0 for 1 (without a task system every worker's share runs on
/// the caller). Ids from the original world do not name its objects. Returns TB_NULL_WORLD_ID (error
/// hook) for an image tbWorld_Restore refuses, a workerCount out of range, or TB_MAX_WORLDS worlds.
TB_API tbWorldId tbCreateWorldFromSnapshot(const uint8_t* image, int size, int workerCount);

/// Write the bytes each of the world's arrays holds, and their total, to tumble_memory.txt in
/// the current directory (Box2D v3.2 writes box2d_memory.txt). Refused (error hook): stale id;
/// a file that cannot be opened is reported too.
TB_API void tbWorld_DumpMemoryStats(tbWorldId worldId);

// Queries -------------------------------------------------------------------------------------

/// Overlap callback: return false to stop the query. Inside any query callback the world may be
/// changed as Box2D v3 allows (velocities, forces and impulses, materials, damping, awake state),
/// but not in ways that touch the broad phase being walked: creating or destroying bodies, shapes
/// or joints, tbBody_SetTransform, tbBody_SetType, tbShape_SetFilter, collideConnected and world
/// settings are refused with an error. Collect ids and make those changes after the query.
typedef bool tbOverlapResultFcn(tbShapeId shapeId, void* context);

/// Ray callback: return −1 to ignore this shape, 0 to stop, `fraction` to clip to this hit,
/// 1 to continue without clipping.
typedef float tbCastResultFcn(tbShapeId shapeId, tbPos point, tbVec2 normal, float fraction, void* context);
/// tbWorld_CollideMover's callback: one plane the mover touches (relative to the origin); return
/// false to stop.
typedef bool tbPlaneResultFcn(tbShapeId shapeId, const tbPlaneResult* plane, void* context);

typedef struct tbRayResult
{
	tbShapeId shapeId;
	tbPos point;
	tbVec2 normal;
	float fraction;
	int nodeVisits; ///< broad-phase tree nodes the cast visited (tbTreeStats)
	int leafVisits; ///< proxies it tested
	bool hit;
} tbRayResult;

/// The four queries below return what they visited (tbTreeStats, as Box2D v3.2's do: nodes and
/// leaves of the broad phase's trees; with the other broad-phase methods, no nodes and the proxies
/// offered as leaves). A refused call (stale world, non-finite input, no callback) visits nothing.
///
/// Shapes whose fat boxes overlap aabb, the box measured from origin (Box2D v3.2's form: near the
/// origin pass tbPos_zero and a world box).
TB_API tbTreeStats tbWorld_OverlapAABB(tbWorldId worldId, tbPos origin, tbAABB aabb, tbQueryFilter filter,
								tbOverlapResultFcn* fcn, void* context);
/// Apply an explosion's impulses (tbExplosionDef) to the dynamic bodies it reaches, waking them.
/// Refused (error hook, nothing changed) during the step and for a NULL def, a non-finite or
/// out-of-world position, a negative or non-finite radius or falloff, a non-finite impulse.
TB_API void tbWorld_Explode(tbWorldId worldId, const tbExplosionDef* def);

/// Contacts: what a body or shape touches now (manifold points within the speculative distance of
/// the last step, sensors excluded). Capacity: an upper bound on what the matching GetContactData
/// writes; GetContactData writes at most `capacity` entries, in contact-id order, and returns how
/// many. A contact id from them or from a begin event is valid until the contact is destroyed.
TB_API int tbBody_GetContactCapacity(tbBodyId bodyId);
TB_API int tbBody_GetContactData(tbBodyId bodyId, tbContactData* contactData, int capacity);
TB_API int tbShape_GetContactCapacity(tbShapeId shapeId);
TB_API int tbShape_GetContactData(tbShapeId shapeId, tbContactData* contactData, int capacity);
/// A sensor shape's visitors (shapes overlapping it at the last step), as ids.
TB_API int tbShape_GetSensorCapacity(tbShapeId shapeId);
TB_API int tbShape_GetSensorData(tbShapeId shapeId, tbShapeId* visitorIds, int capacity);
TB_API bool tbContact_IsValid(tbContactId contactId);
/// The contact's data; all zero (and an error) for a stale id.
TB_API tbContactData tbContact_GetData(tbContactId contactId);
/// Shapes containing the point.
TB_API bool tbWorld_OverlapPoint(tbWorldId worldId, tbPos point, tbQueryFilter filter, tbOverlapResultFcn* fcn,
								 void* context);
/// Shapes overlapping the shape proxy (tbMakeProxy, tbMakeOffsetProxy), its points measured from
/// origin (near the origin pass tbPos_zero and world points).
TB_API tbTreeStats tbWorld_OverlapShape(tbWorldId worldId, tbPos origin, const tbShapeProxy* proxy, tbQueryFilter filter,
								 tbOverlapResultFcn* fcn, void* context);
/// Every shape hit by the ray origin → origin + translation, in no particular order, clipped by the callback.
TB_API tbTreeStats tbWorld_CastRay(tbWorldId worldId, tbPos origin, tbVec2 translation, tbQueryFilter filter,
							tbCastResultFcn* fcn, void* context);
/// The closest hit.
TB_API tbRayResult tbWorld_CastRayClosest(tbWorldId worldId, tbPos origin, tbVec2 translation, tbQueryFilter filter);
/// Every shape hit by a shape proxy (points measured from origin) moving by translation (GJK shape
/// cast); the callback's points are world positions.
TB_API tbTreeStats tbWorld_CastShape(tbWorldId worldId, tbPos origin, const tbShapeProxy* proxy, tbVec2 translation,
							  tbQueryFilter filter, tbCastResultFcn* fcn, void* context);
/// Sweep a capsule mover (relative to origin) along translation; returns the fraction it can go
/// (1: all the way). Shapes it already overlaps at the start are ignored, so a mover pressed into
/// a wall can still leave it; it may end closer than the linear slop (use tbWorld_CollideMover and
/// tbSolvePlanes to keep it out). Refused (returns 0, with a message) for bad input.
TB_API float tbWorld_CastMover(tbWorldId worldId, tbPos origin, const tbCapsule* mover, tbVec2 translation,
							   tbQueryFilter filter);
/// The planes a capsule mover (relative to origin) touches, one call per shape within its reach,
/// planes relative to origin. Returns false (with a message) for bad input.
TB_API bool tbWorld_CollideMover(tbWorldId worldId, tbPos origin, const tbCapsule* mover, tbQueryFilter filter,
								 tbPlaneResultFcn* fcn, void* context);

// ---------------------------------------------------------------------------------------------
// Bodies

TB_API tbBodyId tbCreateBody(tbWorldId worldId, const tbBodyDef* def);
/// Destroys the body, its shapes, its contacts and its joints (their ids become stale).
TB_API void tbDestroyBody(tbBodyId bodyId);
TB_API bool tbBody_IsValid(tbBodyId bodyId);

TB_API tbBodyType tbBody_GetType(tbBodyId bodyId);
TB_API bool tbBody_SetType(tbBodyId bodyId, tbBodyType type);
TB_API tbPos tbBody_GetPosition(tbBodyId bodyId);
TB_API tbRot tbBody_GetRotation(tbBodyId bodyId);
TB_API float tbBody_GetAngle(tbBodyId bodyId);
TB_API tbWorldTransform tbBody_GetTransform(tbBodyId bodyId);
/// Teleport. Wakes the body.
TB_API bool tbBody_SetTransform(tbBodyId bodyId, tbPos position, tbRot rotation);
TB_API tbVec2 tbBody_GetLocalPoint(tbBodyId bodyId, tbPos worldPoint);
TB_API tbPos tbBody_GetWorldPoint(tbBodyId bodyId, tbVec2 localPoint);
TB_API tbVec2 tbBody_GetLocalVector(tbBodyId bodyId, tbVec2 worldVector);
TB_API tbVec2 tbBody_GetWorldVector(tbBodyId bodyId, tbVec2 localVector);

TB_API tbVec2 tbBody_GetLinearVelocity(tbBodyId bodyId);
TB_API float tbBody_GetAngularVelocity(tbBodyId bodyId);
TB_API bool tbBody_SetLinearVelocity(tbBodyId bodyId, tbVec2 linearVelocity);
TB_API bool tbBody_SetAngularVelocity(tbBodyId bodyId, float angularVelocity);
/// Set the velocities that carry the body to `target` by the end of the next step of length
/// timeStep (for kinematic bodies driven along a path; wakes the body when it must move). The
/// angle takes the shortest way (|turn| ≤ π). The position is reached to rounding; the rotation
/// integrator turns n sub-steps by n·atan(θ/n), short of the turn θ by at most |θ|³/(3n²). The
/// step's clamps bound one step's travel (turn ≤ TB_MAX_ROTATION, speed ≤ maximumLinearSpeed).
/// A sleeping body is woken to move when wake is true and the motion is not slower than its sleep
/// threshold (a target it would creep to leaves it asleep); with wake false it stays asleep and
/// unchanged. Refused (false, error hook, nothing changed): stale id, locked world, static body,
/// non-finite or non-unit target, timeStep not finite and > 0.
TB_API bool tbBody_SetTargetTransform(tbBodyId bodyId, tbWorldTransform target, float timeStep, bool wake);

TB_API bool tbBody_ApplyForce(tbBodyId bodyId, tbVec2 force, tbPos point, bool wake);
TB_API bool tbBody_ApplyForceToCenter(tbBodyId bodyId, tbVec2 force, bool wake);
TB_API bool tbBody_ApplyTorque(tbBodyId bodyId, float torque, bool wake);
TB_API bool tbBody_ApplyLinearImpulse(tbBodyId bodyId, tbVec2 impulse, tbPos point, bool wake);
TB_API bool tbBody_ApplyLinearImpulseToCenter(tbBodyId bodyId, tbVec2 impulse, bool wake);
TB_API bool tbBody_ApplyAngularImpulse(tbBodyId bodyId, float impulse, bool wake);

TB_API float tbBody_GetMass(tbBodyId bodyId);
/// Rotational inertia about the centre of mass (kg·m²).
TB_API float tbBody_GetRotationalInertia(tbBodyId bodyId);
/// The centre of mass in the body frame and in world space.
TB_API tbVec2 tbBody_GetLocalCenter(tbBodyId bodyId);
TB_API tbPos tbBody_GetWorldCenter(tbBodyId bodyId);
TB_API tbMassData tbBody_GetMassData(tbBodyId bodyId);
/// Override the mass from the shapes (mass and inertia ≥ 0, centre local); a later shape change,
/// tbBody_ApplyMassFromShapes or tbShape_SetDensity with updateBodyMass puts the shapes' back.
/// A mass below FLT_MIN counts as none (the body acts as 1 kg at its origin). Ignored for static
/// and kinematic bodies.
TB_API bool tbBody_SetMassData(tbBodyId bodyId, tbMassData massData);
TB_API void tbBody_ApplyMassFromShapes(tbBodyId bodyId);
/// Contact or hit events for every shape of the body (tbShape_EnableContactEvents, ...).
TB_API void tbBody_EnableContactEvents(tbBodyId bodyId, bool flag);
TB_API void tbBody_EnableHitEvents(tbBodyId bodyId, bool flag);

TB_API bool tbBody_SetLinearDamping(tbBodyId bodyId, float linearDamping);
TB_API float tbBody_GetLinearDamping(tbBodyId bodyId);
TB_API bool tbBody_SetAngularDamping(tbBodyId bodyId, float angularDamping);
TB_API float tbBody_GetAngularDamping(tbBodyId bodyId);
TB_API bool tbBody_SetGravityScale(tbBodyId bodyId, float gravityScale);
TB_API float tbBody_GetGravityScale(tbBodyId bodyId);
TB_API bool tbBody_IsAwake(tbBodyId bodyId);
TB_API void tbBody_SetAwake(tbBodyId bodyId, bool awake);
/// Wake every body this body has a contact with (not the body itself), as Box2D v3.2's
/// b2Body_WakeTouching: after moving a sleeping pile's support, for example.
TB_API void tbBody_WakeTouching(tbBodyId bodyId);
TB_API void tbBody_EnableSleep(tbBodyId bodyId, bool enableSleep);
TB_API bool tbBody_IsSleepEnabled(tbBodyId bodyId);
/// Speed (m/s) below which the body counts as resting (its fastest point: |v| + |ω|·extent).
TB_API bool tbBody_SetSleepThreshold(tbBodyId bodyId, float sleepThreshold);
TB_API float tbBody_GetSleepThreshold(tbBodyId bodyId);
/// Continuous collision safety factor (tbBodyDef::safetyFactor): finite and ≥ 0, non-dimensional.
/// The body is swept when it moves more than max(TB_SPECULATIVE_REACH, safetyFactor × its
/// thickness) in a step; smaller is safer, 0.01–0.5 typical, default 0.5.
TB_API bool tbBody_SetSafetyFactor(tbBodyId bodyId, float safetyFactor);
TB_API float tbBody_GetSafetyFactor(tbBodyId bodyId);
/// Drop the force and torque accumulated since the last step.
TB_API void tbBody_ClearForces(tbBodyId bodyId);
/// Velocity of a point fixed to the body: v + ω × r, r from the centre of mass (world axes).
TB_API tbVec2 tbBody_GetWorldPointVelocity(tbBodyId bodyId, tbPos worldPoint);
TB_API tbVec2 tbBody_GetLocalPointVelocity(tbBodyId bodyId, tbVec2 localPoint);
TB_API bool tbBody_IsBullet(tbBodyId bodyId);
TB_API void tbBody_SetBullet(tbBodyId bodyId, bool flag);
TB_API void tbBody_SetFixedRotation(tbBodyId bodyId, bool flag);
/// Manifold recycling for this body's contacts (tbBodyDef::enableContactRecycling), from the next step.
TB_API void tbBody_EnableContactRecycling(tbBodyId bodyId, bool flag);
TB_API bool tbBody_IsContactRecyclingEnabled(tbBodyId bodyId);
/// Locks (tbMotionLocks); angularZ is fixedRotation. Wakes the body.
TB_API void tbBody_SetMotionLocks(tbBodyId bodyId, tbMotionLocks locks);
TB_API tbMotionLocks tbBody_GetMotionLocks(tbBodyId bodyId);
TB_API void tbBody_SetUserData(tbBodyId bodyId, void* userData);
TB_API void* tbBody_GetUserData(tbBodyId bodyId);
TB_API const char* tbBody_GetName(tbBodyId bodyId);
/// The name is not copied: it must outlive the body (as tbBodyDef.name).
TB_API void tbBody_SetName(tbBodyId bodyId, const char* name);
/// Take the body out of the simulation (no contacts, not in queries, never awake; its joints hold
/// it as if it were static) and put it back; refused during the step and in query callbacks.
TB_API void tbBody_Disable(tbBodyId bodyId);
TB_API void tbBody_Enable(tbBodyId bodyId);
TB_API bool tbBody_IsEnabled(tbBodyId bodyId);
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
/// A one-sided segment with ghost points that no chain owns (tbShape_GetParentChain: null); the
/// caller keeps its neighbours' ghosts consistent. Its chainId is ignored (set to TB_NULL_INDEX).
TB_API tbShapeId tbCreateChainSegmentShape(tbBodyId bodyId, const tbShapeDef* def, const tbChainSegment* chainSegment);
TB_API tbShapeId tbCreateSegmentShape(tbBodyId bodyId, const tbShapeDef* def, const tbSegment* segment);
/// Any shape from a tagged union.
TB_API tbShapeId tbCreateShape(tbBodyId bodyId, const tbShapeDef* def, const tbGeometry* geometry);
TB_API void tbDestroyShape(tbShapeId shapeId, bool updateBodyMass);
TB_API bool tbShape_IsValid(tbShapeId shapeId);

TB_API tbShapeType tbShape_GetType(tbShapeId shapeId);
TB_API tbBodyId tbShape_GetBody(tbShapeId shapeId);
TB_API tbWorldId tbShape_GetWorld(tbShapeId shapeId);
TB_API tbGeometry tbShape_GetGeometry(tbShapeId shapeId);
/// The geometry of one kind (an error and zeros for a shape of another kind).
TB_API tbCircle tbShape_GetCircle(tbShapeId shapeId);
TB_API tbCapsule tbShape_GetCapsule(tbShapeId shapeId);
TB_API tbSegment tbShape_GetSegment(tbShapeId shapeId);
TB_API tbPolygon tbShape_GetPolygon(tbShapeId shapeId);
/// Replace the geometry (the kind may change): checked as at creation; the shape's contacts are
/// destroyed and found again next step, its body's mass recomputed and the body woken. Refused
/// during the step and in query callbacks.
TB_API bool tbShape_SetCircle(tbShapeId shapeId, const tbCircle* circle);
TB_API bool tbShape_SetCapsule(tbShapeId shapeId, const tbCapsule* capsule);
TB_API bool tbShape_SetSegment(tbShapeId shapeId, const tbSegment* segment);
/// Make the shape an orphan chain segment (or update one); a segment owned by a chain is refused.
TB_API bool tbShape_SetChainSegment(tbShapeId shapeId, const tbChainSegment* chainSegment);
TB_API bool tbShape_SetPolygon(tbShapeId shapeId, const tbPolygon* polygon);
/// Events at run time (the shape def's enable*Events): existing contacts follow at once.
TB_API void tbShape_EnableContactEvents(tbShapeId shapeId, bool flag);
TB_API bool tbShape_AreContactEventsEnabled(tbShapeId shapeId);
TB_API void tbShape_EnableHitEvents(tbShapeId shapeId, bool flag);
TB_API bool tbShape_AreHitEventsEnabled(tbShapeId shapeId);
TB_API void tbShape_EnableSensorEvents(tbShapeId shapeId, bool flag);
TB_API bool tbShape_AreSensorEventsEnabled(tbShapeId shapeId);
/// Pre-solve events (tbShapeDef::enablePreSolveEvents): the world's pre-solve callback sees the
/// contacts of this shape (either shape enabling them suffices); existing contacts follow from the
/// next step. Refused (error hook): stale id, locked world.
TB_API void tbShape_EnablePreSolveEvents(tbShapeId shapeId, bool flag);
TB_API bool tbShape_ArePreSolveEventsEnabled(tbShapeId shapeId);
TB_API bool tbShape_IsSensor(tbShapeId shapeId);
TB_API bool tbShape_SetDensity(tbShapeId shapeId, float density, bool updateBodyMass);
TB_API float tbShape_GetDensity(tbShapeId shapeId);
TB_API bool tbShape_SetFriction(tbShapeId shapeId, float friction);
TB_API float tbShape_GetFriction(tbShapeId shapeId);
TB_API bool tbShape_SetRestitution(tbShapeId shapeId, float restitution);
TB_API float tbShape_GetRestitution(tbShapeId shapeId);
/// Replaces the whole material (checked as in tbShapeDef); contacts use it from the next step.
TB_API bool tbShape_SetSurfaceMaterial(tbShapeId shapeId, const tbSurfaceMaterial* material);
TB_API tbSurfaceMaterial tbShape_GetSurfaceMaterial(tbShapeId shapeId);
TB_API void tbShape_SetUserMaterial(tbShapeId shapeId, uint64_t material);
TB_API uint64_t tbShape_GetUserMaterial(tbShapeId shapeId);
TB_API tbFilter tbShape_GetFilter(tbShapeId shapeId);
TB_API bool tbShape_SetFilter(tbShapeId shapeId, tbFilter filter);
TB_API void tbShape_SetUserData(tbShapeId shapeId, void* userData);
TB_API void* tbShape_GetUserData(tbShapeId shapeId);
TB_API tbAABB tbShape_GetAABB(tbShapeId shapeId);
TB_API bool tbShape_TestPoint(tbShapeId shapeId, tbPos point);
/// The point of the shape (radius included) closest to `target`, in world coordinates (GJK against
/// a point); a target inside the shape is returned as it is.
TB_API tbPos tbShape_GetClosestPoint(tbShapeId shapeId, tbPos target);
/// The ray origin → origin + translation against one shape; the hit point a world position.
TB_API tbWorldCastOutput tbShape_RayCast(tbShapeId shapeId, tbPos origin, tbVec2 translation);
/// The shape's mass, centre (body frame) and rotational inertia about that centre, from its
/// geometry and density.
TB_API tbMassData tbShape_ComputeMassData(tbShapeId shapeId);
/// Wind on a shape (Box2D v3.2's b2Shape_ApplyWind): a force from the air (1.225 kg/m³, unit depth)
/// flowing at u = wind − drag·v past the shape (v: the velocity of the shape's centroid; drag 0
/// ignores the shape's own motion, 1 makes u the true relative air velocity), added to the body's
/// force and torque for the next step. The pressure ½ρ|u|² acts on the width the shape shows the
/// flow: 2r for a circle (at its centre); for a capsule 2r plus its axis' projection, for a polygon
/// each face turned into the flow (the rounding radius ignored), each with a sideways part
/// lift × (n × û)·perp(û) (n: the face's normal). True when applied. Ignored (false, no error, as
/// the tbBody_Apply* functions): segments and chain segments (they catch no wind), static,
/// kinematic and disabled bodies, a sleeping body unless wake. Refused (false, error hook, nothing
/// changed): stale id, locked world, non-finite wind or lift, drag not finite and ≥ 0.
TB_API bool tbShape_ApplyWind(tbShapeId shapeId, tbVec2 wind, float drag, float lift, bool wake);
/// A chain segment's geometry with its ghost points (an error and zeros for another kind).
TB_API tbChainSegment tbShape_GetChainSegment(tbShapeId shapeId);
/// The chain a segment belongs to (null for any other shape).
TB_API tbChainId tbShape_GetParentChain(tbShapeId shapeId);

// ---------------------------------------------------------------------------------------------
// Chains (Box2D v3.2's grammar): one-sided segments on one body, smooth across their joints.
// Creating checks every point (finite, within TB_MAX_COORDINATE, consecutive points at least
// TB_LINEAR_SLOP apart, count ≥ 4) and the materials, and creates nothing on bad input. The
// segments are shapes (tbChain_GetSegments) that may not be destroyed or reshaped one by one.

TB_API tbChainId tbCreateChain(tbBodyId bodyId, const tbChainDef* def);
/// Destroys the chain and its segments (destroying its body does too).
TB_API void tbDestroyChain(tbChainId chainId);
TB_API bool tbChain_IsValid(tbChainId chainId);
TB_API tbWorldId tbChain_GetWorld(tbChainId chainId);
TB_API tbBodyId tbChain_GetBody(tbChainId chainId);
TB_API int tbChain_GetSegmentCount(tbChainId chainId);
/// Writes up to capacity segment shape ids; returns how many were written.
TB_API int tbChain_GetSegments(tbChainId chainId, tbShapeId* segmentArray, int capacity);
TB_API int tbChain_GetSurfaceMaterialCount(tbChainId chainId);
/// Sets material `materialIndex` (of tbChain_GetSurfaceMaterialCount) and the segments using it.
TB_API bool tbChain_SetSurfaceMaterial(tbChainId chainId, const tbSurfaceMaterial* material, int materialIndex);
TB_API tbSurfaceMaterial tbChain_GetSurfaceMaterial(tbChainId chainId, int materialIndex);

// ---------------------------------------------------------------------------------------------
// Joints. Every kind shares the tbJoint_* functions; tbRevoluteJoint_* and the like refuse a
// joint of another kind. Setters check their input, wake both bodies and return false (changing
// nothing) on bad input. Forces and torques are in N and N·m, averaged over the last step.

/// Destroys the joint; its id becomes stale. Wakes both bodies.
TB_API void tbDestroyJoint(tbJointId jointId);
TB_API bool tbJoint_IsValid(tbJointId jointId);
TB_API tbJointType tbJoint_GetType(tbJointId jointId);
TB_API tbBodyId tbJoint_GetBodyA(tbJointId jointId);
TB_API tbBodyId tbJoint_GetBodyB(tbJointId jointId);
TB_API tbWorldId tbJoint_GetWorld(tbJointId jointId);
TB_API bool tbJoint_SetLocalFrameA(tbJointId jointId, tbTransform localFrame);
TB_API tbTransform tbJoint_GetLocalFrameA(tbJointId jointId);
TB_API bool tbJoint_SetLocalFrameB(tbJointId jointId, tbTransform localFrame);
TB_API tbTransform tbJoint_GetLocalFrameB(tbJointId jointId);
/// Allowing collision lets the broad phase find the pair again; forbidding it destroys the
/// contacts between the two bodies.
TB_API void tbJoint_SetCollideConnected(tbJointId jointId, bool shouldCollide);
TB_API bool tbJoint_GetCollideConnected(tbJointId jointId);
TB_API void tbJoint_SetUserData(tbJointId jointId, void* userData);
TB_API void* tbJoint_GetUserData(tbJointId jointId);
TB_API void tbJoint_WakeBodies(tbJointId jointId);
/// Force the joint applies to body B (N, world axes); body A receives the opposite.
TB_API tbVec2 tbJoint_GetConstraintForce(tbJointId jointId);
/// Torque the joint applies to body B (N·m) besides the moment of its force.
TB_API float tbJoint_GetConstraintTorque(tbJointId jointId);
/// How far the joint is from holding now, from the bodies' transforms, not counting admissible
/// motion (Box2D v3.2's): linear in m, angular in rad. Distance: |length − rest length| when rigid,
/// else how far past an enabled limit. Prismatic and wheel: √(offset across the axis² + distance past
/// an enabled limit²). Revolute: the anchors' distance. Weld: the anchors' distance when linearHertz
/// is 0. Angular: prismatic, and weld when angularHertz is 0, the frames' relative angle (signed,
/// as v3); revolute, how far past an enabled limit. Every other case (motor, mover, pogo, filter
/// joints; wheel's angle) is 0. Frames include their local rotations (v3 reads the bodies'
/// rotations; the same for identity frames). 0 and the error hook for a stale id.
TB_API float tbJoint_GetLinearSeparation(tbJointId jointId);
TB_API float tbJoint_GetAngularSeparation(tbJointId jointId);
TB_API bool tbJoint_SetConstraintTuning(tbJointId jointId, float hertz, float dampingRatio);
TB_API void tbJoint_GetConstraintTuning(tbJointId jointId, float* hertz, float* dampingRatio);
TB_API bool tbJoint_SetForceThreshold(tbJointId jointId, float threshold);
TB_API float tbJoint_GetForceThreshold(tbJointId jointId);
TB_API bool tbJoint_SetTorqueThreshold(tbJointId jointId, float threshold);
TB_API float tbJoint_GetTorqueThreshold(tbJointId jointId);
TB_API bool tbJoint_SetDrawScale(tbJointId jointId, float drawScale);
TB_API float tbJoint_GetDrawScale(tbJointId jointId);

/// Number of joints attached to the body.
TB_API int tbBody_GetJointCount(tbBodyId bodyId);
/// Fill jointArray with up to capacity joint ids; returns the number written.
TB_API int tbBody_GetJoints(tbBodyId bodyId, tbJointId* jointArray, int capacity);

/// Joints whose force or torque reached its threshold in the last step.
TB_API tbJointEvents tbWorld_GetJointEvents(tbWorldId worldId);

// Distance joint -------------------------------------------------------------------------------

TB_API tbJointId tbCreateDistanceJoint(tbWorldId worldId, const tbDistanceJointDef* def);
TB_API bool tbDistanceJoint_SetLength(tbJointId jointId, float length);
TB_API float tbDistanceJoint_GetLength(tbJointId jointId);
TB_API void tbDistanceJoint_EnableSpring(tbJointId jointId, bool enableSpring);
TB_API bool tbDistanceJoint_IsSpringEnabled(tbJointId jointId);
TB_API bool tbDistanceJoint_SetSpringForceRange(tbJointId jointId, float lowerForce, float upperForce);
TB_API void tbDistanceJoint_GetSpringForceRange(tbJointId jointId, float* lowerForce, float* upperForce);
TB_API bool tbDistanceJoint_SetSpringHertz(tbJointId jointId, float hertz);
TB_API float tbDistanceJoint_GetSpringHertz(tbJointId jointId);
TB_API bool tbDistanceJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio);
TB_API float tbDistanceJoint_GetSpringDampingRatio(tbJointId jointId);
TB_API void tbDistanceJoint_EnableLimit(tbJointId jointId, bool enableLimit);
TB_API bool tbDistanceJoint_IsLimitEnabled(tbJointId jointId);
TB_API bool tbDistanceJoint_SetLengthRange(tbJointId jointId, float minLength, float maxLength);
TB_API float tbDistanceJoint_GetMinLength(tbJointId jointId);
TB_API float tbDistanceJoint_GetMaxLength(tbJointId jointId);
/// Distance between the two anchors now (m).
TB_API float tbDistanceJoint_GetCurrentLength(tbJointId jointId);
TB_API void tbDistanceJoint_EnableMotor(tbJointId jointId, bool enableMotor);
TB_API bool tbDistanceJoint_IsMotorEnabled(tbJointId jointId);
TB_API bool tbDistanceJoint_SetMotorSpeed(tbJointId jointId, float motorSpeed);
TB_API float tbDistanceJoint_GetMotorSpeed(tbJointId jointId);
TB_API bool tbDistanceJoint_SetMaxMotorForce(tbJointId jointId, float force);
TB_API float tbDistanceJoint_GetMaxMotorForce(tbJointId jointId);
TB_API float tbDistanceJoint_GetMotorForce(tbJointId jointId);

// Filter joint ---------------------------------------------------------------------------------

TB_API tbJointId tbCreateFilterJoint(tbWorldId worldId, const tbFilterJointDef* def);

// Motor joint ----------------------------------------------------------------------------------

TB_API tbJointId tbCreateMotorJoint(tbWorldId worldId, const tbMotorJointDef* def);
TB_API bool tbMotorJoint_SetLinearVelocity(tbJointId jointId, tbVec2 velocity);
TB_API tbVec2 tbMotorJoint_GetLinearVelocity(tbJointId jointId);
TB_API bool tbMotorJoint_SetAngularVelocity(tbJointId jointId, float velocity);
TB_API float tbMotorJoint_GetAngularVelocity(tbJointId jointId);
TB_API bool tbMotorJoint_SetMaxVelocityForce(tbJointId jointId, float maxForce);
TB_API float tbMotorJoint_GetMaxVelocityForce(tbJointId jointId);
TB_API bool tbMotorJoint_SetMaxVelocityTorque(tbJointId jointId, float maxTorque);
TB_API float tbMotorJoint_GetMaxVelocityTorque(tbJointId jointId);
TB_API bool tbMotorJoint_SetLinearHertz(tbJointId jointId, float hertz);
TB_API float tbMotorJoint_GetLinearHertz(tbJointId jointId);
TB_API bool tbMotorJoint_SetLinearDampingRatio(tbJointId jointId, float damping);
TB_API float tbMotorJoint_GetLinearDampingRatio(tbJointId jointId);
TB_API bool tbMotorJoint_SetAngularHertz(tbJointId jointId, float hertz);
TB_API float tbMotorJoint_GetAngularHertz(tbJointId jointId);
TB_API bool tbMotorJoint_SetAngularDampingRatio(tbJointId jointId, float damping);
TB_API float tbMotorJoint_GetAngularDampingRatio(tbJointId jointId);
TB_API bool tbMotorJoint_SetMaxSpringForce(tbJointId jointId, float maxForce);
TB_API float tbMotorJoint_GetMaxSpringForce(tbJointId jointId);
TB_API bool tbMotorJoint_SetMaxSpringTorque(tbJointId jointId, float maxTorque);
TB_API float tbMotorJoint_GetMaxSpringTorque(tbJointId jointId);

// Mover joint ----------------------------------------------------------------------------------

TB_API tbJointId tbCreateMoverJoint(tbWorldId worldId, const tbMoverJointDef* def);
TB_API bool tbMoverJoint_SetLinearVelocity(tbJointId jointId, tbVec2 velocity);
TB_API tbVec2 tbMoverJoint_GetLinearVelocity(tbJointId jointId);
/// maxForce: the caps on x and on y (N, each ≥ 0).
TB_API bool tbMoverJoint_SetMaxVelocityForce(tbJointId jointId, tbVec2 maxForce);
TB_API tbVec2 tbMoverJoint_GetMaxVelocityForce(tbJointId jointId);

// Pogo joint -----------------------------------------------------------------------------------

TB_API tbJointId tbCreatePogoJoint(tbWorldId worldId, const tbPogoJointDef* def);
TB_API bool tbPogoJoint_SetRestLength(tbJointId jointId, float length);
TB_API float tbPogoJoint_GetRestLength(tbJointId jointId);
TB_API bool tbPogoJoint_SetSpringHertz(tbJointId jointId, float hertz);
TB_API float tbPogoJoint_GetSpringHertz(tbJointId jointId);
TB_API bool tbPogoJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio);
TB_API float tbPogoJoint_GetSpringDampingRatio(tbJointId jointId);
/// Length now (m): anchor B minus anchor A along the y-axis of frame B.
TB_API float tbPogoJoint_GetLength(tbJointId jointId);
/// The spring's velocity (m/s), the rate of change of the length it commands.
TB_API float tbPogoJoint_GetVelocity(tbJointId jointId);
/// The accumulated impulse of the last sub-step (N·s, positive pushes): force = impulse/h.
TB_API float tbPogoJoint_GetImpulse(tbJointId jointId);

// Prismatic joint ------------------------------------------------------------------------------

TB_API tbJointId tbCreatePrismaticJoint(tbWorldId worldId, const tbPrismaticJointDef* def);
TB_API void tbPrismaticJoint_EnableSpring(tbJointId jointId, bool enableSpring);
TB_API bool tbPrismaticJoint_IsSpringEnabled(tbJointId jointId);
TB_API bool tbPrismaticJoint_SetSpringHertz(tbJointId jointId, float hertz);
TB_API float tbPrismaticJoint_GetSpringHertz(tbJointId jointId);
TB_API bool tbPrismaticJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio);
TB_API float tbPrismaticJoint_GetSpringDampingRatio(tbJointId jointId);
TB_API bool tbPrismaticJoint_SetTargetTranslation(tbJointId jointId, float translation);
TB_API float tbPrismaticJoint_GetTargetTranslation(tbJointId jointId);
TB_API void tbPrismaticJoint_EnableLimit(tbJointId jointId, bool enableLimit);
TB_API bool tbPrismaticJoint_IsLimitEnabled(tbJointId jointId);
TB_API float tbPrismaticJoint_GetLowerLimit(tbJointId jointId);
TB_API float tbPrismaticJoint_GetUpperLimit(tbJointId jointId);
TB_API bool tbPrismaticJoint_SetLimits(tbJointId jointId, float lower, float upper);
TB_API void tbPrismaticJoint_EnableMotor(tbJointId jointId, bool enableMotor);
TB_API bool tbPrismaticJoint_IsMotorEnabled(tbJointId jointId);
TB_API bool tbPrismaticJoint_SetMotorSpeed(tbJointId jointId, float motorSpeed);
TB_API float tbPrismaticJoint_GetMotorSpeed(tbJointId jointId);
TB_API bool tbPrismaticJoint_SetMaxMotorForce(tbJointId jointId, float force);
TB_API float tbPrismaticJoint_GetMaxMotorForce(tbJointId jointId);
TB_API float tbPrismaticJoint_GetMotorForce(tbJointId jointId);
/// Position of frame B's origin along the axis, relative to frame A's origin (m).
TB_API float tbPrismaticJoint_GetTranslation(tbJointId jointId);
/// Rate of change of the translation (m/s).
TB_API float tbPrismaticJoint_GetSpeed(tbJointId jointId);

// Revolute joint -------------------------------------------------------------------------------

TB_API tbJointId tbCreateRevoluteJoint(tbWorldId worldId, const tbRevoluteJointDef* def);
TB_API void tbRevoluteJoint_EnableSpring(tbJointId jointId, bool enableSpring);
TB_API bool tbRevoluteJoint_IsSpringEnabled(tbJointId jointId);
TB_API bool tbRevoluteJoint_SetSpringHertz(tbJointId jointId, float hertz);
TB_API float tbRevoluteJoint_GetSpringHertz(tbJointId jointId);
TB_API bool tbRevoluteJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio);
TB_API float tbRevoluteJoint_GetSpringDampingRatio(tbJointId jointId);
TB_API bool tbRevoluteJoint_SetTargetAngle(tbJointId jointId, float angle);
TB_API float tbRevoluteJoint_GetTargetAngle(tbJointId jointId);
/// Rotation of frame B relative to frame A (rad, in [−π, π]).
TB_API float tbRevoluteJoint_GetAngle(tbJointId jointId);
TB_API void tbRevoluteJoint_EnableLimit(tbJointId jointId, bool enableLimit);
TB_API bool tbRevoluteJoint_IsLimitEnabled(tbJointId jointId);
TB_API float tbRevoluteJoint_GetLowerLimit(tbJointId jointId);
TB_API float tbRevoluteJoint_GetUpperLimit(tbJointId jointId);
TB_API bool tbRevoluteJoint_SetLimits(tbJointId jointId, float lower, float upper);
TB_API void tbRevoluteJoint_EnableMotor(tbJointId jointId, bool enableMotor);
TB_API bool tbRevoluteJoint_IsMotorEnabled(tbJointId jointId);
TB_API bool tbRevoluteJoint_SetMotorSpeed(tbJointId jointId, float motorSpeed);
TB_API float tbRevoluteJoint_GetMotorSpeed(tbJointId jointId);
TB_API float tbRevoluteJoint_GetMotorTorque(tbJointId jointId);
TB_API bool tbRevoluteJoint_SetMaxMotorTorque(tbJointId jointId, float torque);
TB_API float tbRevoluteJoint_GetMaxMotorTorque(tbJointId jointId);

// Weld joint -----------------------------------------------------------------------------------

TB_API tbJointId tbCreateWeldJoint(tbWorldId worldId, const tbWeldJointDef* def);
TB_API bool tbWeldJoint_SetLinearHertz(tbJointId jointId, float hertz);
TB_API float tbWeldJoint_GetLinearHertz(tbJointId jointId);
TB_API bool tbWeldJoint_SetLinearDampingRatio(tbJointId jointId, float dampingRatio);
TB_API float tbWeldJoint_GetLinearDampingRatio(tbJointId jointId);
TB_API bool tbWeldJoint_SetAngularHertz(tbJointId jointId, float hertz);
TB_API float tbWeldJoint_GetAngularHertz(tbJointId jointId);
TB_API bool tbWeldJoint_SetAngularDampingRatio(tbJointId jointId, float dampingRatio);
TB_API float tbWeldJoint_GetAngularDampingRatio(tbJointId jointId);

// Wheel joint ----------------------------------------------------------------------------------

TB_API tbJointId tbCreateWheelJoint(tbWorldId worldId, const tbWheelJointDef* def);
TB_API void tbWheelJoint_EnableSpring(tbJointId jointId, bool enableSpring);
TB_API bool tbWheelJoint_IsSpringEnabled(tbJointId jointId);
TB_API bool tbWheelJoint_SetSpringHertz(tbJointId jointId, float hertz);
TB_API float tbWheelJoint_GetSpringHertz(tbJointId jointId);
TB_API bool tbWheelJoint_SetSpringDampingRatio(tbJointId jointId, float dampingRatio);
TB_API float tbWheelJoint_GetSpringDampingRatio(tbJointId jointId);
TB_API void tbWheelJoint_EnableLimit(tbJointId jointId, bool enableLimit);
TB_API bool tbWheelJoint_IsLimitEnabled(tbJointId jointId);
TB_API float tbWheelJoint_GetLowerLimit(tbJointId jointId);
TB_API float tbWheelJoint_GetUpperLimit(tbJointId jointId);
TB_API bool tbWheelJoint_SetLimits(tbJointId jointId, float lower, float upper);
TB_API void tbWheelJoint_EnableMotor(tbJointId jointId, bool enableMotor);
TB_API bool tbWheelJoint_IsMotorEnabled(tbJointId jointId);
TB_API bool tbWheelJoint_SetMotorSpeed(tbJointId jointId, float motorSpeed);
TB_API float tbWheelJoint_GetMotorSpeed(tbJointId jointId);
TB_API bool tbWheelJoint_SetMaxMotorTorque(tbJointId jointId, float torque);
TB_API float tbWheelJoint_GetMaxMotorTorque(tbJointId jointId);
TB_API float tbWheelJoint_GetMotorTorque(tbJointId jointId);


// Replay (Box2D v3.2's replay group) ------------------------------------------------------

/// Replay a recording (the bytes of tbRecording_GetData or a loaded file) in a new world on
/// workerCount workers (0 or 1: on the caller) and compare the state hash after every step with
/// the one recorded. Returns true when every step reproduced; false when the recording is refused
/// (error hook naming the problem) or the replay diverged (error hook naming the first step whose
/// hash differs).
TB_API bool tbValidateReplay(const void* data, int size, int workerCount);

/// A replay player (opaque): plays a recording step by step in a world of its own.
typedef struct tbRecPlayer tbRecPlayer;

/// What a recording holds, read once when the player opens it.
typedef struct tbRecPlayerInfo
{
	int frameCount;	   ///< steps recorded
	int workerCount;   ///< workers of the replay world
	float timeStep;	   ///< time step of the first recorded step (s)
	int subStepCount;  ///< sub-steps of the first recorded step
	float lengthScale; ///< length units per metre the recording was made in
	tbAABB bounds;	   ///< union of the world's bounds over the recorded steps (zero if no step)
} tbRecPlayerInfo;

/// Open a recording for playback: the player copies the bytes (the caller may free them), checks
/// them (header, version, precision, length units, size, checksum), and makes the replay world from
/// the recording's snapshot, before the first step. Returns NULL (error hook naming the problem)
/// for NULL data, a negative size, a refused recording or a workerCount out of range.
TB_API tbRecPlayer* tbRecPlayer_Create(const void* data, int size, int workerCount);

/// Replay the calls up to the next recorded step and take it. Returns true when a step ran, false
/// at the end of the recording (or after a malformed record, reported through the error hook).
TB_API bool tbRecPlayer_StepFrame(tbRecPlayer* player);

/// The replay world's id (the same across restarts and seeks).
TB_API tbWorldId tbRecPlayer_GetWorldId(const tbRecPlayer* player);

/// Back to the state before the first step, in the same world.
TB_API void tbRecPlayer_Restart(tbRecPlayer* player);

/// Go to the state after targetFrame steps (clamped to 0 and the frame count). Backwards, the player
/// restores the nearest keyframe before the target and replays from there.
TB_API void tbRecPlayer_SeekFrame(tbRecPlayer* player, int targetFrame);

/// Steps replayed so far.
TB_API int tbRecPlayer_GetFrame(const tbRecPlayer* player);

/// What the recording holds (frame count, time step, sub-steps, length scale, bounds).
TB_API tbRecPlayerInfo tbRecPlayer_GetInfo(const tbRecPlayer* player);

/// True once every recorded step has been replayed.
TB_API bool tbRecPlayer_IsAtEnd(const tbRecPlayer* player);

/// True once a replayed step ended on a state hash other than the recorded one.
TB_API bool tbRecPlayer_HasDiverged(const tbRecPlayer* player);

/// The first step (1 for the first) whose state hash differed from the recorded one, or -1.
TB_API int tbRecPlayer_GetDivergeFrame(const tbRecPlayer* player);

/// Keyframes: snapshots the player takes while playing forward, so a backward seek replays from
/// the nearest one instead of from the start. budgetBytes caps their memory (the spacing doubles
/// to stay under it); minIntervalFrames is the finest spacing. 0 (or a negative interval) keeps a
/// value. Clears the keyframes taken so far.
TB_API void tbRecPlayer_SetKeyframePolicy(tbRecPlayer* player, size_t budgetBytes, int minIntervalFrames);

/// The keyframe memory budget (bytes).
TB_API size_t tbRecPlayer_GetKeyframeBudget(const tbRecPlayer* player);

/// The finest keyframe spacing (frames).
TB_API int tbRecPlayer_GetKeyframeMinInterval(const tbRecPlayer* player);

/// The keyframe spacing now (frames): the finest, doubled each time the budget was reached.
TB_API int tbRecPlayer_GetKeyframeInterval(const tbRecPlayer* player);

/// Bytes the keyframes hold now.
TB_API size_t tbRecPlayer_GetKeyframeBytes(const tbRecPlayer* player);

/// Free the player, its world and its copy of the recording. NULL is ignored.
TB_API void tbRecPlayer_Destroy(tbRecPlayer* player);

/// Draw the spatial queries recorded before the step of the frame replayed last (after
/// tbWorld_Draw): each query's box, ray or sweep, and each result's point and normal. queryIndex:
/// one query, or -1 for all. NULL draw functions are skipped. Refused (error hook) for an index out
/// of range.
TB_API void tbRecPlayer_DrawFrameQueries(tbRecPlayer* player, tbDebugDraw* draw, int queryIndex);

/// The kind of a recorded spatial query (Box2D v3.2's list).
typedef enum tbRecQueryType
{
	tb_recQueryOverlapAABB,
	tb_recQueryOverlapShape,
	tb_recQueryCastRay,
	tb_recQueryCastShape,
	tb_recQueryCollideMover,
	tb_recQueryCastRayClosest,
	tb_recQueryCastMover,
	tb_recQueryShapeTestPoint,
	tb_recQueryShapeRayCast,
} tbRecQueryType;

/// A recorded spatial query.
typedef struct tbRecQueryInfo
{
	tbRecQueryType type;
	tbQueryFilter filter; ///< zero for the shape's own tests
	tbAABB aabb;		  ///< overlap box, relative to origin
	tbPos origin;		  ///< where the query starts
	tbVec2 translation;	  ///< of a ray or a cast
	tbShapeId shape;	  ///< the shape tested, for the shape's own tests
	int hitCount;		  ///< results recorded
} tbRecQueryInfo;

/// One result of a recorded spatial query.
typedef struct tbRecQueryHit
{
	tbShapeId shape;
	tbPos point;
	tbVec2 normal;
	float fraction;
} tbRecQueryHit;

/// Number of spatial queries recorded before the step of the frame replayed last (before the first
/// step, until the first StepFrame). Queries change nothing: replay shows them, it does not run them.
/// A seek backwards that restores a keyframe starts with none.
TB_API int tbRecPlayer_GetFrameQueryCount(const tbRecPlayer* player);

/// A recorded query of the frame replayed last; a zeroed one (error hook) for an index out of range.
TB_API tbRecQueryInfo tbRecPlayer_GetFrameQuery(const tbRecPlayer* player, int index);

/// A result of a recorded query; a zeroed one (error hook) for an index out of range.
TB_API tbRecQueryHit tbRecPlayer_GetFrameQueryHit(const tbRecPlayer* player, int queryIndex, int hitIndex);

/// Bodies created so far in the replay, destroyed ones included: the span of creation ordinals
/// (bodies of the recording's snapshot first, in id order). Only grows as the replay goes forward.
TB_API int tbRecPlayer_GetBodyCount(const tbRecPlayer* player);

/// The body of a creation ordinal; tb_nullBodyId once destroyed, not yet created at this frame, or
/// out of range.
TB_API tbBodyId tbRecPlayer_GetBodyId(const tbRecPlayer* player, int index);

#ifdef __cplusplus
}
#endif
