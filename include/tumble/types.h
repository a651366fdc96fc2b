// Tumble: definition structs, method selection, events, debug drawing, profile and counters.
#pragma once

#include "base.h"
#include "collision.h"
#include "id.h"
#include "math_functions.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Broad-phase method. Every method reports the same pairs in the same order.
typedef enum tbBroadPhaseMethod
{
	tb_broadPhaseAuto,		   ///< chosen from the scene: the tree, or the spatial hash or sort-and-sweep (docs/methods.md)
	tb_broadPhaseTree,		   ///< dynamic AABB tree (SAH insertion, rotations)
	tb_broadPhaseSortAndSweep, ///< sort-and-sweep on the axis of largest variance
	tb_broadPhaseBruteForce,   ///< all pairs, O(n²): the ground truth
	tb_broadPhaseSpatialHash,  ///< uniform grid hashed into buckets, cell twice the median box: many same-size bodies
	tb_broadPhaseMethodCount
} tbBroadPhaseMethod;

/// Continuous collision (time of impact) method.
typedef enum tbContinuousMethod
{
	tb_continuousDefault,	   ///< quadratic for circle pairs, conservative advancement for the rest
	tb_continuousOff,		   ///< no time of impact: fast bodies may tunnel
	tb_continuousConservative, ///< conservative advancement for every pair
	tb_continuousMethodCount
} tbContinuousMethod;

/// Contact solver and its position-error treatment.
typedef enum tbSolverMethod
{
	tb_solverSoft,		///< soft step: sub-stepped soft contacts with relaxation (Catto 2024, Box2D v3)
	tb_solverBaumgarte, ///< sequential impulses with a Baumgarte velocity bias
	tb_solverNGS,		///< sequential impulses plus a non-linear Gauss–Seidel position pass (Box2D 2.4)
	tb_solverMethodCount
} tbSolverMethod;

/// Friction mixing: return the friction of a pair (≥ 0; infinity never slides). Default
/// sqrt(frictionA · frictionB). A NaN or negative answer is reported and the default used.
typedef float tbFrictionCallback(float frictionA, uint64_t userMaterialIdA, float frictionB, uint64_t userMaterialIdB);

/// Restitution mixing: a finite number ≥ 0. Default max(restitutionA, restitutionB). Any other
/// answer is reported and the default used.
typedef float tbRestitutionCallback(float restitutionA, uint64_t userMaterialIdA, float restitutionB,
									uint64_t userMaterialIdB);

/// Custom filter (tbWorld_SetCustomFilterCallback): asked whether two shapes that pass their
/// filters may collide, when either shape enables custom filtering; false keeps them apart. Called
/// from the step's pair stage (and continuous collision); without task callbacks on the stepping
/// thread, with them possibly on several workers at once and in no fixed order: answer from the
/// arguments alone. The world is locked (do not change it).
typedef bool tbCustomFilterFcn(tbShapeId shapeIdA, tbShapeId shapeIdB, void* context);

/// Pre-solve (tbWorld_SetPreSolveCallback): called in the collide stage for each touching
/// non-sensor contact with a dynamic body when either shape enables pre-solve events, after its
/// manifold is updated and before it is solved: without task callbacks on the stepping thread in
/// contact-id order, with them possibly on several workers at once (write only the manifold given). It may change the manifold:
/// set pointCount to 0 to disable the contact for this step (a one-way platform), or remove a
/// point; it may not add points (pointCount is clamped to what it was) and a non-finite normal
/// or separation is refused (error hook, manifold restored). The world is locked; impulses in the
/// manifold are not final.
typedef void tbPreSolveFcn(tbShapeId shapeIdA, tbShapeId shapeIdB, tbManifold* manifold, void* context);

/// Pre-continuous: called when continuous collision would stop a fast body at a shape (A, the
/// other shape; B, the fast body's) whose pair enables pre-solve events, with the point and normal
/// (from A to B) at the time of impact; return false to let the body pass. Like pre-solve, it may
/// run on several workers at once when the world has task callbacks.
typedef bool tbPreContinuousFcn(tbShapeId shapeIdA, tbShapeId shapeIdB, tbPos point, tbVec2 normal, void* context);

/// Tasks (Box2D v3.2's interface): the game's task system runs parts of the step on its worker
/// threads. A task is one call of `task(taskContext)`, run exactly once per enqueue with the
/// taskContext given; the library splits the work itself and gives each task its worker index, so
/// the task system only runs callbacks.
typedef void tbTaskCallback(void* taskContext);

/// Start `task(taskContext)` on a worker and return a handle for finishTask; or run it before
/// returning and return NULL (then finishTask is not called). The tasks a step enqueues at once
/// (at most workerCount − 1) need not all run at the same time: the calling thread can do all the
/// work alone, so a system with fewer threads, or one that runs tasks in order, still finishes.
typedef void* tbEnqueueTaskCallback(tbTaskCallback* task, void* taskContext, void* userContext);

/// Wait until the task behind `userTask` (from enqueueTask) has run.
typedef void tbFinishTaskCallback(void* userTask, void* userContext);

/// World definition: start from tbDefaultWorldDef().
/// Expected sizes (Box2D v3.2's b2Capacity): the world reserves room for them when it is created,
/// so that filling it up to these counts allocates nothing more. Zero: grow as needed.
typedef struct tbCapacity
{
	int staticShapeCount;
	int dynamicShapeCount; ///< dynamic and kinematic
	int staticBodyCount;
	int dynamicBodyCount; ///< dynamic and kinematic
	int contactCount;
} tbCapacity;

typedef struct tbWorldDef
{
	tbVec2 gravity;					///< m/s², default (0, −10)
	float restitutionThreshold;		///< m/s: restitution applies above this approach speed, default 1
	float hitEventThreshold;		///< m/s: approach speed that makes a hit event, default 1
	float contactHertz;				///< soft contact stiffness of new dynamic contacts, default 30 Hz; static
									///< ones use twice this, at most ¼ of the sub-step rate
	float settledHertzRatio;		///< soft: a dynamic contact that has touched for 0.25 s stiffens to this ×
									///< contactHertz, at most ¼ of the sub-step rate; default 1.75
	float contactDampingRatio;		///< soft contact damping ratio, default 10
	bool contactHertzFollowsSubStep; ///< soft: stiffness = min(contactHertz·subSteps/4, ¼ sub-step rate)
	float contactSpeed;				///< m/s, largest speed at which overlap is pushed out (Box2D v3.2's name), default 3
	float maximumLinearSpeed;		///< m/s, clamp on body speed, default 4000
	bool enableSleep;				///< default true
	bool enableContinuous;			///< default true; false: no time of impact, fast bodies may tunnel (as
									///< tbWorld_EnableContinuous(false), which `continuous` is kept for)
	bool enableContactSoftening;	///< soft: contacts between bodies of very different mass are softened
									///< towards the lighter body's (Box2D v3.2's option, experimental there
									///< too); static contacts are not. Default false
	tbBroadPhaseMethod broadPhase;	///< default auto
	tbNarrowPhaseMethod narrowPhase; ///< default auto
	tbContinuousMethod continuous;	///< default: quadratic + conservative advancement
	tbSolverMethod solver;			///< default soft
	int velocityIterations;			///< Baumgarte/NGS iterations per sub-step, default 8
	int positionIterations;			///< NGS position iterations per sub-step, default 3
	int relaxIterations;			///< soft: relaxing iterations per sub-step, default 1
	int finalRelaxIterations;		///< soft: relaxing iterations added to the last sub-step, default 1
	bool enableWarmStarting;		///< default true
	bool enableWideSolver;			///< soft and Baumgarte: contacts graph-coloured and solved 4 at a time
									///< (SIMD; 8 in an AVX2 build); false: the scalar reference in hashed
									///< order. Default true
	bool enableJointTrees;			///< the equality rows of joints solved exactly over each tree of joined
									///< bodies (joint_tree.c); false: row by row (Gauss–Seidel). Default true
	bool enableCentralFriction;		///< soft and Baumgarte: one friction row per contact, at the manifold's
									///< centre of pressure (docs/methods.md); false: one row per manifold
									///< point. Same forces on a face, half the friction rows. NGS always
									///< solves per point. Default true
	bool enableManifoldRecycling;	///< touching pairs that barely moved since their manifold was computed keep
									///< its points and only update separations (contact.c). Default true
	bool enableImpactPropagation;	///< bouncing contacts (restitution > 0) take their impacts one pair at a
									///< time before the solve, so an impact travels along a chain of touching
									///< bodies (Newton's cradle). Default false (docs/methods.md)
	tbFrictionCallback* frictionCallback;
	tbRestitutionCallback* restitutionCallback;
	tbCapacity capacity;				///< expected sizes: room reserved at creation (default all 0)
	int workerCount;					///< 1 to TB_MAX_WORKERS, default 1; used with the task callbacks
	tbEnqueueTaskCallback* enqueueTask; ///< the game's task system, or NULL: the step runs on the caller
	tbFinishTaskCallback* finishTask;
	void* userTaskContext;
	void* userData;
	int internalValue; ///< set by tbDefaultWorldDef; checked to catch defs not made by it
} tbWorldDef;

TB_API tbWorldDef tbDefaultWorldDef(void);

typedef enum tbBodyType
{
	tb_staticBody = 0,
	tb_kinematicBody = 1,
	tb_dynamicBody = 2,
	tb_bodyTypeCount
} tbBodyType;

/// Motion locks (Box2D v3.2's b2MotionLocks): a locked linear axis keeps the body's velocity along
/// it at zero (applied after each sub-step's solve, a constraint that comes last: contacts along
/// that axis feel the body as free and may be softer); a locked rotation is fixedRotation.
typedef struct tbMotionLocks
{
	bool linearX;  ///< no translation along world x
	bool linearY;  ///< no translation along world y
	bool angularZ; ///< no rotation (the same as fixedRotation)
} tbMotionLocks;

/// Body definition: start from tbDefaultBodyDef().
typedef struct tbBodyDef
{
	tbBodyType type;		///< default static
	tbPos position;			///< world position of the body origin
	tbRot rotation;			///< default identity
	tbVec2 linearVelocity;	///< of the centre of mass, m/s
	float angularVelocity;	///< rad/s
	float linearDamping;	///< 1/s, ≥ 0
	float angularDamping;	///< 1/s, ≥ 0
	float gravityScale;		///< default 1
	float sleepThreshold;	///< m/s, default TB_LINEAR_SLEEP_TOLERANCE
	/// Continuous collision safety factor (Box2D v3.2's), default TB_CONTINUOUS_FRACTION = 0.5,
	/// finite and ≥ 0: the body is swept by continuous collision when it moves more than
	/// max(TB_SPECULATIVE_REACH, safetyFactor × its thickness) in a step. Smaller is safer and costs
	/// more sweeps (and the hitches of moving back to the time of impact); typical 0.01–0.5.
	float safetyFactor;
	void* userData;
	const char* name;		///< optional, not copied
	bool enableSleep;		///< default true
	bool isAwake;			///< default true
	bool fixedRotation;		///< default false; the same as motionLocks.angularZ (either locks rotation)
	tbMotionLocks motionLocks; ///< default none
	bool enableContactRecycling; ///< default true; false: its contacts never reuse an old manifold
								 ///< (tbWorldDef::enableManifoldRecycling), e.g. a character
	bool isBullet;			///< swept against dynamic and kinematic bodies too (not bullets), default false
	bool isEnabled;			///< default true; false: created disabled (tbBody_Disable), out of the broad
							///< phase and the simulation until tbBody_Enable
	bool allowFastRotation; ///< default false; true: no cap on the rotation per step (wheels; the cap is
							///< what keeps continuous collision's rotation bound, so a fast-turning
							///< long shape may tunnel). In a world with joints the guard against
							///< runaway joint speeds (16 times the cap) still holds it
	int internalValue;
} tbBodyDef;

TB_API tbBodyDef tbDefaultBodyDef(void);

/// Collision filter (as Box2D): A and B collide when (A.category & B.mask) && (B.category & A.mask),
/// unless they share a group index: positive always collides, negative never.
typedef struct tbFilter
{
	uint64_t categoryBits;
	uint64_t maskBits;
	int groupIndex;
} tbFilter;

TB_API tbFilter tbDefaultFilter(void);

/// Filter for queries.
typedef struct tbQueryFilter
{
	uint64_t categoryBits;
	uint64_t maskBits;
} tbQueryFilter;

TB_API tbQueryFilter tbDefaultQueryFilter(void);

/// An explosion (tbWorld_Explode): every dynamic shape whose category bits share a bit with
/// maskBits and whose surface is within radius + falloff of position receives, at its point
/// closest to position and directed away from it, the impulse impulsePerLength × the width the
/// shape shows the blast (its extent across the blast direction), scaled by 1 within radius and
/// falling linearly to 0 across falloff.
typedef struct tbExplosionDef
{
	uint64_t maskBits;		///< which shapes the blast reaches (default: all)
	tbPos position;			///< centre (m)
	float radius;			///< m, ≥ 0: full strength within this distance of the surface
	float falloff;			///< m, ≥ 0: beyond radius the strength falls to zero over this distance
	float impulsePerLength; ///< N·s per metre of exposed width; negative pulls towards the centre
} tbExplosionDef;

/// maskBits all set, everything else zero.
TB_API tbExplosionDef tbDefaultExplosionDef(void);

/// Surface material of a shape or a chain segment (Box2D v3.2's b2SurfaceMaterial). Mixed per
/// contact: friction and restitution by the world's callbacks (default sqrt(a·b) and max(a, b)),
/// rolling resistance max(a, b) times the larger shape radius, tangent speeds added.
typedef struct tbSurfaceMaterial
{
	float friction;			///< ≥ 0, default 0.6
	float restitution;		///< ≥ 0, default 0
	float rollingResistance; ///< ≥ 0, default 0: a rolling round shape of radius r on it feels a torque
							 ///< up to rollingResistance·r·(normal force) against its rolling
	float tangentSpeed;		///< m/s, default 0: the surface moves along itself (a conveyor belt);
							 ///< friction drives what touches it towards this speed
	uint64_t userMaterialId; ///< passed to the mixing callbacks
	uint32_t customColor;	///< debug draw colour (0xRRGGBB), 0: the default colours
} tbSurfaceMaterial;

TB_API tbSurfaceMaterial tbDefaultSurfaceMaterial(void);

/// Shape definition: start from tbDefaultShapeDef().
typedef struct tbShapeDef
{
	void* userData;
	tbSurfaceMaterial material; ///< friction, restitution, rolling resistance, tangent speed, ...
	float density;		 ///< kg/m², ≥ 0, default 1
	tbFilter filter;
	bool isSensor;			   ///< reports overlaps, no response
	bool enableSensorEvents;   ///< default false; a sensor reports a visitor (a sensor too) only when both enable it
	bool enableContactEvents;  ///< default false; begin/end events when either shape of a contact enables them
	bool enableHitEvents;	   ///< default false; one event per impact, with its begin-touch event or after it
	bool updateBodyMass;	   ///< recompute the body's mass, default true
	bool enableCustomFiltering; ///< ask the world's custom filter about this shape's pairs, default false
	bool enablePreSolveEvents;	///< call the world's pre-solve callback for this shape's contacts, default false
	bool invokeContactCreation; ///< default true: a shape on a static body looks for the shapes it overlaps at
								///< the next step, as a moving shape does; false: its contacts wait until
								///< another shape moves across it (cheaper for large static worlds built
								///< where nothing rests)
	int internalValue;
} tbShapeDef;

TB_API tbShapeDef tbDefaultShapeDef(void);


/// Chain definition: start from tbDefaultChainDef(). A chain is a run of one-sided segments, solid
/// on the left of each segment's direction (so an outline given counter-clockwise with isLoop is
/// solid inside; ground given right to left is solid below), that shapes slide across without
/// catching on the joints. An open chain of n points has n − 3 segments: the first and last points
/// only say which way the ground continues (ghost points). A loop of n points has n segments.
typedef struct tbChainDef
{
	void* userData;
	const tbVec2* points; ///< at least 4, copied; consecutive points at least TB_LINEAR_SLOP apart
	int count;
	const tbSurfaceMaterial* materials; ///< 1 (for every segment) or one per segment; copied
	int materialCount;
	tbFilter filter;
	bool isLoop;
	bool enableSensorEvents; ///< sensors see the chain; default false
	int internalValue;
} tbChainDef;

TB_API tbChainDef tbDefaultChainDef(void);

// ---------------------------------------------------------------------------------------------
// Joints (Box2D v3.2's grammar: b2RevoluteJointDef → tbRevoluteJointDef, and so on). Each kind's
// definition embeds the common part as `.base`. Start every definition from its
// tbDefault*JointDef(); the local frames are given relative to each body's origin (not its centre
// of mass), so adding shapes later does not move the joint.

typedef enum tbJointType
{
	tb_distanceJoint,
	tb_filterJoint,
	tb_motorJoint,
	tb_moverJoint,
	tb_pogoJoint,
	tb_prismaticJoint,
	tb_revoluteJoint,
	tb_weldJoint,
	tb_wheelJoint,
	tb_jointTypeCount
} tbJointType;

/// The part every joint definition shares.
typedef struct tbJointDef
{
	void* userData;
	tbBodyId bodyIdA;
	tbBodyId bodyIdB;
	tbTransform localFrameA;	  ///< joint frame in body A's frame (origin: the anchor; rotation normalised)
	tbTransform localFrameB;	  ///< joint frame in body B's frame
	float forceThreshold;		  ///< N, ≥ 0: a joint event when the constraint force reaches it; default FLT_MAX (never)
	float torqueThreshold;		  ///< N·m, ≥ 0: the same for the constraint torque; default FLT_MAX
	float constraintHertz;		  ///< Hz, ≥ 0: stiffness of the positional correction (soft step), default 60,
								  ///< capped at a quarter of the sub-step rate like contacts
	float constraintDampingRatio; ///< ≥ 0, default 2 (Box2D v3's values)
	float drawScale;			  ///< m, > 0: size of the joint's debug drawing, default 1
	bool collideConnected;		  ///< may the two bodies collide? Default false
} tbJointDef;

/// Distance joint: keeps a point of each body at a fixed distance (rigid), or joins them by a
/// spring, optionally within [minLength, maxLength] (a rope when only maxLength matters), with an
/// optional motor along the line.
typedef struct tbDistanceJointDef
{
	tbJointDef base;
	float length;		   ///< m, ≥ 0, rest length (raised to TB_LINEAR_SLOP when below), default 1
	bool enableSpring;	   ///< false: rigid (limit and motor are then ignored)
	float lowerSpringForce; ///< N, the largest pulling force (negative), default −FLT_MAX
	float upperSpringForce; ///< N, the largest pushing force, default FLT_MAX; lower ≤ upper
	float hertz;		   ///< Hz, ≥ 0, spring stiffness (0: no spring force)
	float dampingRatio;	   ///< ≥ 0
	bool enableLimit;
	float minLength;	   ///< m, ≥ 0 (clamped below to TB_LINEAR_SLOP), default 0
	float maxLength;	   ///< m, ≥ minLength, default TB_HUGE
	bool enableMotor;
	float maxMotorForce;   ///< N, ≥ 0
	float motorSpeed;	   ///< m/s, rate of change of the length
	int internalValue;
} tbDistanceJointDef;

TB_API tbDistanceJointDef tbDefaultDistanceJointDef(void);

/// Filter joint: no constraint; only stops the two bodies colliding.
typedef struct tbFilterJointDef
{
	tbJointDef base;
	int internalValue;
} tbFilterJointDef;

TB_API tbFilterJointDef tbDefaultFilterJointDef(void);

/// Motor joint: drives the relative velocity of body B's frame with respect to body A's frame
/// (force and torque capped), and pulls frame B towards frame A with linear and angular springs
/// (also capped). With body A static and frame A moved each step, it drags body B around (how
/// Box2D v3.2 replaces 3.1's mouse joint).
typedef struct tbMotorJointDef
{
	tbJointDef base;
	tbVec2 linearVelocity;	   ///< m/s, target velocity of frame B relative to frame A (world axes)
	float maxVelocityForce;	   ///< N, ≥ 0 (0: no velocity control)
	float angularVelocity;	   ///< rad/s
	float maxVelocityTorque;   ///< N·m, ≥ 0
	float linearHertz;		   ///< Hz, ≥ 0, spring pulling frame B's origin onto frame A's (0: none)
	float linearDampingRatio;  ///< ≥ 0
	float maxSpringForce;	   ///< N, ≥ 0
	float angularHertz;		   ///< Hz, ≥ 0, spring turning frame B onto frame A (0: none)
	float angularDampingRatio; ///< ≥ 0
	float maxSpringTorque;	   ///< N·m, ≥ 0
	int internalValue;
} tbMotorJointDef;

TB_API tbMotorJointDef tbDefaultMotorJointDef(void);

/// Mover joint: drives the linear velocity of body B relative to body A towards linearVelocity,
/// x and y separately, each capped by its own force; rotation is left alone. Made for a dynamic
/// character moved by velocity commands (body A usually static), as in Box2D v3.2.
typedef struct tbMoverJointDef
{
	tbJointDef base;
	tbVec2 linearVelocity;	 ///< m/s, target velocity of body B relative to body A (world axes)
	tbVec2 maxVelocityForce; ///< N, each ≥ 0: the cap on x and the cap on y (0 on both: no control)
	int internalValue;
} tbMoverJointDef;

TB_API tbMoverJointDef tbDefaultMoverJointDef(void);

/// Pogo joint: a one-sided spring leg for a dynamic character (Box2D v3.2). Its length is the
/// distance from anchor A to anchor B along the y-axis of frame B; it pushes along `normal`
/// (usually the ground normal, from body A to body B) so that the length follows a damped
/// oscillator towards restLength, with the push and the pull each capped. The pogo is typically
/// created again every step where the character stands; impulse and velocity carry its state over.
typedef struct tbPogoJointDef
{
	tbJointDef base;
	tbVec2 normal;			   ///< unit vector along which the pogo pushes B (and A back), default (0, 1)
	float hertz;			   ///< Hz, ≥ 0, the spring's frequency (0: the pogo is off)
	float dampingRatio;		   ///< ≥ 0 (0: no damping but the integrator's own)
	float restLength;		   ///< m, ≥ 0
	float maxTensionForce;	   ///< N, ≥ 0: the largest pull, how hard the character sticks to the ground
	float maxCompressionForce; ///< N, ≥ 0: the largest push, how hard the pogo lifts the character
	float impulse;			   ///< N·s, the accumulated impulse to start from (a re-created pogo's last)
	float velocity;			   ///< m/s, the spring's velocity to start from (a re-created pogo's last)
	int internalValue;
} tbPogoJointDef;

TB_API tbPogoJointDef tbDefaultPogoJointDef(void);

/// Prismatic joint: body B slides along the x-axis of frame A and cannot turn relative to A. The
/// translation is 0 when the frame origins coincide.
typedef struct tbPrismaticJointDef
{
	tbJointDef base;
	bool enableSpring;
	float hertz;			 ///< Hz, ≥ 0
	float dampingRatio;		 ///< ≥ 0
	float targetTranslation; ///< m, where the spring pulls to
	bool enableLimit;
	float lowerTranslation;	 ///< m, ≤ upperTranslation
	float upperTranslation;	 ///< m
	bool enableMotor;
	float maxMotorForce;	 ///< N, ≥ 0
	float motorSpeed;		 ///< m/s
	int internalValue;
} tbPrismaticJointDef;

TB_API tbPrismaticJointDef tbDefaultPrismaticJointDef(void);

/// Revolute joint: the frame origins are pinned together; the bodies turn about that point. The
/// angle is the rotation of frame B relative to frame A.
typedef struct tbRevoluteJointDef
{
	tbJointDef base;
	float targetAngle;	  ///< rad, where the spring pulls to
	bool enableSpring;
	float hertz;		  ///< Hz, ≥ 0
	float dampingRatio;	  ///< ≥ 0
	bool enableLimit;
	float lowerAngle;	  ///< rad, in [−π, π], ≤ upperAngle (clamped to ±0.99π as Box2D v3)
	float upperAngle;	  ///< rad, in [−π, π]
	bool enableMotor;
	float maxMotorTorque; ///< N·m, ≥ 0
	float motorSpeed;	  ///< rad/s
	int internalValue;
} tbRevoluteJointDef;

TB_API tbRevoluteJointDef tbDefaultRevoluteJointDef(void);

/// Weld joint: holds frame B on frame A, rigidly (hertz 0) or through linear and angular springs.
typedef struct tbWeldJointDef
{
	tbJointDef base;
	float linearHertz;		   ///< Hz, ≥ 0; 0: as stiff as the constraint softness allows
	float angularHertz;		   ///< Hz, ≥ 0; 0: as stiff as the constraint softness allows
	float linearDampingRatio;  ///< ≥ 0
	float angularDampingRatio; ///< ≥ 0
	int internalValue;
} tbWeldJointDef;

TB_API tbWeldJointDef tbDefaultWeldJointDef(void);

/// Wheel joint: body B (the wheel) slides along the x-axis of frame A on a suspension spring and
/// turns freely, optionally driven by a motor.
typedef struct tbWheelJointDef
{
	tbJointDef base;
	bool enableSpring;	  ///< default true
	float hertz;		  ///< Hz, ≥ 0, default 1
	float dampingRatio;	  ///< ≥ 0, default 0.7
	bool enableLimit;
	float lowerTranslation; ///< m, ≤ upperTranslation
	float upperTranslation; ///< m
	bool enableMotor;
	float maxMotorTorque; ///< N·m, ≥ 0
	float motorSpeed;	  ///< rad/s
	int internalValue;
} tbWheelJointDef;

TB_API tbWheelJointDef tbDefaultWheelJointDef(void);

// ---------------------------------------------------------------------------------------------
// Events, read after the step. Arrays stay valid until the next step or world destruction. The
// arrays are not const, as in Box2D v3.2, so ported code that keeps them in plain pointers compiles;
// the library does not read them back, so writing to them changes nothing.

typedef struct tbContactBeginTouchEvent
{
	tbShapeId shapeIdA;
	tbShapeId shapeIdB;
	tbContactId contactId; ///< the contact, for tbContact_GetData (its manifold) while it lives
} tbContactBeginTouchEvent;

/// A touching contact as tbBody_GetContactData, tbShape_GetContactData and tbContact_GetData
/// report it: the shapes (normal from A to B) and the manifold of the last step.
typedef struct tbContactData
{
	tbContactId contactId;
	tbShapeId shapeIdA;
	tbShapeId shapeIdB;
	tbManifold manifold;
} tbContactData;

typedef struct tbContactEndTouchEvent
{
	tbShapeId shapeIdA;
	tbShapeId shapeIdB;
	tbContactId contactId; ///< the contact that stopped touching; still valid when it goes on overlapping
						   ///< (tbContact_IsValid), invalid when it was destroyed with the pair
} tbContactEndTouchEvent;

typedef struct tbContactHitEvent
{
	tbShapeId shapeIdA;
	tbShapeId shapeIdB;
	tbContactId contactId; ///< the contact that was hit, for tbContact_GetData while it lives
	tbPos point;
	tbVec2 normal;
	float approachSpeed; ///< m/s, > hitEventThreshold
} tbContactHitEvent;

typedef struct tbContactEvents
{
	tbContactBeginTouchEvent* beginEvents;
	tbContactEndTouchEvent* endEvents;
	tbContactHitEvent* hitEvents;
	int beginCount;
	int endCount;
	int hitCount;
} tbContactEvents;

typedef struct tbSensorBeginTouchEvent
{
	tbShapeId sensorShapeId;
	tbShapeId visitorShapeId;
} tbSensorBeginTouchEvent;

typedef struct tbSensorEndTouchEvent
{
	tbShapeId sensorShapeId;
	tbShapeId visitorShapeId;
} tbSensorEndTouchEvent;

typedef struct tbSensorEvents
{
	tbSensorBeginTouchEvent* beginEvents;
	tbSensorEndTouchEvent* endEvents;
	int beginCount;
	int endCount;
} tbSensorEvents;

/// A body that moved in the step (awake bodies), or fell asleep.
typedef struct tbBodyMoveEvent
{
	tbWorldTransform transform;
	tbBodyId bodyId;
	void* userData;
	bool fellAsleep;
} tbBodyMoveEvent;

typedef struct tbBodyEvents
{
	tbBodyMoveEvent* moveEvents;
	int moveCount;
} tbBodyEvents;

/// A joint whose constraint force or torque reached its threshold in the step (joints of awake
/// bodies only).
typedef struct tbJointEvent
{
	tbJointId jointId;
	void* userData;
} tbJointEvent;

typedef struct tbJointEvents
{
	tbJointEvent* jointEvents;
	int count;
} tbJointEvents;

// ---------------------------------------------------------------------------------------------
// Profile and counters

/// Milliseconds spent in each stage of the last step (tbWorld_Step's pipeline, in order).
typedef struct tbProfile
{
	float step;		  ///< the whole step
	float pairs;	  ///< broad phase: new pairs from moved proxies, contacts created
	float collide;	  ///< narrow phase: manifolds, begin/end touch, contacts destroyed
	float islands;	  ///< awake bodies and touching contacts gathered, constraint graph coloured
	float solve;	  ///< contact and joint preparation, sub-steps, impulses stored
	float continuous; ///< time of impact of fast bodies
	float finalize;	  ///< sleep timers, bounding boxes, proxies moved, move events
	float hitEvents;	///< hit events gathered (0 when no contact enables them)
	float sensors;		///< sensor overlaps on the final poses, sensor events (0 with no sensor contact)
	float sleepIslands; ///< islands put to sleep

	// The parts of `solve`, named as Box2D v3.2's profile names them so that the two compare part
	// by part; the sub-step parts are summed over the sub-steps. With workers the sub-step parts
	// are timed by the thread that leads the stages, from opening a stage until it is done.
	float solverSetup;		   ///< solver bodies gathered, contact keys, graph colours
	float constraints;		   ///< the parts below from prepareConstraints to storeImpulses, summed
	float prepareConstraints;  ///< contacts and joints prepared (and joint trees built)
	float integrateVelocities; ///< gravity, forces and damping into the velocities
	float warmStart;		   ///< the last step's impulses applied again
	float solveImpulses;	   ///< the biased passes (the whole sub-step for Baumgarte and NGS)
	float integratePositions;  ///< velocities into the position deltas
	float relaxImpulses;	   ///< the relaxing passes, the last sub-step's extra ones included
	float applyRestitution;	   ///< restitution after the sub-steps
	float storeImpulses;	   ///< impulses back to the contacts for the next warm start, joint events
	float jointEvents;		   ///< the joint events, a part of storeImpulses
	float bullets;			   ///< the bullets' time of impact, a part of continuous
	float sensorHits;		   ///< sensors crossed by fast shapes marked for the sensor stage, a part of continuous
	float transforms;		   ///< the bodies' final transforms, boxes, sleep timers and move events: finalize
	float refit;			   ///< the broad phase's tree of moving proxies refreshed, a part of pairs or collide
	float splitIslands;		   ///< the islands of the awake bodies found, a part of sleepIslands
	float scatterBodies;	   ///< velocities and transforms back to the bodies, fast bodies marked
} tbProfile;

/// Counts from the last step (Box2D v3.2's b2Counters, then Tumble's own).
typedef struct tbCounters
{
	int64_t byteCount;		 ///< bytes allocated by Tumble (all worlds: tbGetByteCount)
	int bodyCount;
	int shapeCount;
	int contactCount;		 ///< contacts whose fat boxes overlap
	int jointCount;
	int islandCount;		 ///< islands holding a rested body, found by the sleep stage (0 when no body has
							 ///< rested; Tumble keeps no islands between steps, v3.2 counts all of its own)
	int stackUsed;			 ///< bytes of the step's scratch memory (the step arena) the last step needed
	int staticTreeHeight;	 ///< height of the static bodies' tree (0 when another broad phase runs)
	int treeHeight;			 ///< height of the moving bodies' tree (0 when another broad phase runs)
	int taskCount;			 ///< tasks handed to the game's task system in the last step (0 without one)
	int colorCounts[24];	 ///< contact constraints of each graph colour in the last step (tbGetGraphColor);
							 ///< those beyond the colours are overflowCount
	int awakeContactCount;	 ///< contacts the collide stage updated (those of awake bodies)
	int recycledContactCount; ///< touching manifolds recycled (points moved with the bodies, not recomputed)

	// Tumble's own.
	int overflowCount;		 ///< contact constraints no colour could take (solved one at a time)
	int touchingCount;		 ///< contacts with manifold points among awake bodies (sleeping islands are not visited)
	int awakeBodyCount;
	int pairCandidates;		 ///< new pairs found by the broad phase this step
	int proxyMoves;			 ///< proxies whose fat box was updated this step
	int fastBodies;			 ///< bodies swept by continuous collision this step
	int toiCalls;			 ///< time-of-impact queries this step (0 when nothing is fast)
	int toiIterationsMax;	 ///< largest conservative-advancement iteration count this step
	int toiFailures;		 ///< time-of-impact queries that hit the iteration cap
	int gjkManifolds;		 ///< manifolds computed by the GJK/EPA path
	int satManifolds;		 ///< manifolds computed by SAT
	int keptApartCount;		 ///< contacts whose shapes were known to stay apart: no narrow phase ran
} tbCounters;

// ---------------------------------------------------------------------------------------------
// Debug drawing

typedef enum tbHexColor
{
	tb_colorBox = 0x4E79A7,
	tb_colorSleeping = 0x9C9C9C,
	tb_colorStatic = 0x59A14F,
	tb_colorKinematic = 0x76B7B2,
	tb_colorContact = 0xE15759,
	tb_colorNormal = 0xF28E2B,
	tb_colorAABB = 0xB07AA1,
	tb_colorTree = 0xBAB0AC,
	tb_colorJoint = 0x8FBC8F,

	// The named colours of SVG and CSS (W3C CSS Color Module Level 3), as Box2D v3 names them.
	tb_colorAliceBlue = 0xF0F8FF,
	tb_colorAntiqueWhite = 0xFAEBD7,
	tb_colorAqua = 0x00FFFF,
	tb_colorAquamarine = 0x7FFFD4,
	tb_colorAzure = 0xF0FFFF,
	tb_colorBeige = 0xF5F5DC,
	tb_colorBisque = 0xFFE4C4,
	tb_colorBlack = 0x000000,
	tb_colorBlanchedAlmond = 0xFFEBCD,
	tb_colorBlue = 0x0000FF,
	tb_colorBlueViolet = 0x8A2BE2,
	tb_colorBrown = 0xA52A2A,
	tb_colorBurlywood = 0xDEB887,
	tb_colorCadetBlue = 0x5F9EA0,
	tb_colorChartreuse = 0x7FFF00,
	tb_colorChocolate = 0xD2691E,
	tb_colorCoral = 0xFF7F50,
	tb_colorCornflowerBlue = 0x6495ED,
	tb_colorCornsilk = 0xFFF8DC,
	tb_colorCrimson = 0xDC143C,
	tb_colorCyan = 0x00FFFF,
	tb_colorDarkBlue = 0x00008B,
	tb_colorDarkCyan = 0x008B8B,
	tb_colorDarkGoldenRod = 0xB8860B,
	tb_colorDarkGray = 0xA9A9A9,
	tb_colorDarkGreen = 0x006400,
	tb_colorDarkKhaki = 0xBDB76B,
	tb_colorDarkMagenta = 0x8B008B,
	tb_colorDarkOliveGreen = 0x556B2F,
	tb_colorDarkOrange = 0xFF8C00,
	tb_colorDarkOrchid = 0x9932CC,
	tb_colorDarkRed = 0x8B0000,
	tb_colorDarkSalmon = 0xE9967A,
	tb_colorDarkSeaGreen = 0x8FBC8F,
	tb_colorDarkSlateBlue = 0x483D8B,
	tb_colorDarkSlateGray = 0x2F4F4F,
	tb_colorDarkTurquoise = 0x00CED1,
	tb_colorDarkViolet = 0x9400D3,
	tb_colorDeepPink = 0xFF1493,
	tb_colorDeepSkyBlue = 0x00BFFF,
	tb_colorDimGray = 0x696969,
	tb_colorDodgerBlue = 0x1E90FF,
	tb_colorFireBrick = 0xB22222,
	tb_colorFloralWhite = 0xFFFAF0,
	tb_colorForestGreen = 0x228B22,
	tb_colorFuchsia = 0xFF00FF,
	tb_colorGainsboro = 0xDCDCDC,
	tb_colorGhostWhite = 0xF8F8FF,
	tb_colorGold = 0xFFD700,
	tb_colorGoldenRod = 0xDAA520,
	tb_colorGray = 0x808080,
	tb_colorGreen = 0x008000,
	tb_colorGreenYellow = 0xADFF2F,
	tb_colorHoneyDew = 0xF0FFF0,
	tb_colorHotPink = 0xFF69B4,
	tb_colorIndianRed = 0xCD5C5C,
	tb_colorIndigo = 0x4B0082,
	tb_colorIvory = 0xFFFFF0,
	tb_colorKhaki = 0xF0E68C,
	tb_colorLavender = 0xE6E6FA,
	tb_colorLavenderBlush = 0xFFF0F5,
	tb_colorLawnGreen = 0x7CFC00,
	tb_colorLemonChiffon = 0xFFFACD,
	tb_colorLightBlue = 0xADD8E6,
	tb_colorLightCoral = 0xF08080,
	tb_colorLightCyan = 0xE0FFFF,
	tb_colorLightGoldenRodYellow = 0xFAFAD2,
	tb_colorLightGray = 0xD3D3D3,
	tb_colorLightGreen = 0x90EE90,
	tb_colorLightPink = 0xFFB6C1,
	tb_colorLightSalmon = 0xFFA07A,
	tb_colorLightSeaGreen = 0x20B2AA,
	tb_colorLightSkyBlue = 0x87CEFA,
	tb_colorLightSlateGray = 0x778899,
	tb_colorLightSteelBlue = 0xB0C4DE,
	tb_colorLightYellow = 0xFFFFE0,
	tb_colorLime = 0x00FF00,
	tb_colorLimeGreen = 0x32CD32,
	tb_colorLinen = 0xFAF0E6,
	tb_colorMagenta = 0xFF00FF,
	tb_colorMaroon = 0x800000,
	tb_colorMediumAquaMarine = 0x66CDAA,
	tb_colorMediumBlue = 0x0000CD,
	tb_colorMediumOrchid = 0xBA55D3,
	tb_colorMediumPurple = 0x9370DB,
	tb_colorMediumSeaGreen = 0x3CB371,
	tb_colorMediumSlateBlue = 0x7B68EE,
	tb_colorMediumSpringGreen = 0x00FA9A,
	tb_colorMediumTurquoise = 0x48D1CC,
	tb_colorMediumVioletRed = 0xC71585,
	tb_colorMidnightBlue = 0x191970,
	tb_colorMintCream = 0xF5FFFA,
	tb_colorMistyRose = 0xFFE4E1,
	tb_colorMoccasin = 0xFFE4B5,
	tb_colorNavajoWhite = 0xFFDEAD,
	tb_colorNavy = 0x000080,
	tb_colorOldLace = 0xFDF5E6,
	tb_colorOlive = 0x808000,
	tb_colorOliveDrab = 0x6B8E23,
	tb_colorOrange = 0xFFA500,
	tb_colorOrangeRed = 0xFF4500,
	tb_colorOrchid = 0xDA70D6,
	tb_colorPaleGoldenRod = 0xEEE8AA,
	tb_colorPaleGreen = 0x98FB98,
	tb_colorPaleTurquoise = 0xAFEEEE,
	tb_colorPaleVioletRed = 0xDB7093,
	tb_colorPapayaWhip = 0xFFEFD5,
	tb_colorPeachPuff = 0xFFDAB9,
	tb_colorPeru = 0xCD853F,
	tb_colorPink = 0xFFC0CB,
	tb_colorPlum = 0xDDA0DD,
	tb_colorPowderBlue = 0xB0E0E6,
	tb_colorPurple = 0x800080,
	tb_colorRebeccaPurple = 0x663399,
	tb_colorRed = 0xFF0000,
	tb_colorRosyBrown = 0xBC8F8F,
	tb_colorRoyalBlue = 0x4169E1,
	tb_colorSaddleBrown = 0x8B4513,
	tb_colorSalmon = 0xFA8072,
	tb_colorSandyBrown = 0xF4A460,
	tb_colorSeaGreen = 0x2E8B57,
	tb_colorSeaShell = 0xFFF5EE,
	tb_colorSienna = 0xA0522D,
	tb_colorSilver = 0xC0C0C0,
	tb_colorSkyBlue = 0x87CEEB,
	tb_colorSlateBlue = 0x6A5ACD,
	tb_colorSlateGray = 0x708090,
	tb_colorSnow = 0xFFFAFA,
	tb_colorSpringGreen = 0x00FF7F,
	tb_colorSteelBlue = 0x4682B4,
	tb_colorTan = 0xD2B48C,
	tb_colorTeal = 0x008080,
	tb_colorThistle = 0xD8BFD8,
	tb_colorTomato = 0xFF6347,
	tb_colorTurquoise = 0x40E0D0,
	tb_colorViolet = 0xEE82EE,
	tb_colorWheat = 0xF5DEB3,
	tb_colorWhite = 0xFFFFFF,
	tb_colorWhiteSmoke = 0xF5F5F5,
	tb_colorYellow = 0xFFFF00,
	tb_colorYellowGreen = 0x9ACD32,

	// Box2D v3.2's own colours.
	tb_colorBox2DRed = 0xDC3132,
	tb_colorBox2DBlue = 0x30AEBF,
	tb_colorBox2DGreen = 0x8CC924,
	tb_colorBox2DYellow = 0xFFEE8C,
} tbHexColor;

/// The colour a debug view gives graph colour `index` of the contact solver (Box2D v3.2's
/// b2GetGraphColor): 0..TB_GRAPH_COLOR_COUNT − 1 the colours, TB_GRAPH_COLOR_COUNT the overflow
/// (contacts solved one at a time). Another index is refused through the error hook (black).
TB_API tbHexColor tbGetGraphColor(int index);

/// Debug drawing (Box2D v3.2's b2DebugDraw): tbWorld_Draw walks the world and calls these with world
/// coordinates (tbPos and tbWorldTransform: doubles in the large-world build). tbDefaultDebugDraw
/// sets every function to one that draws nothing, so a game implements only the ones it wants; a
/// function set to NULL is skipped.
typedef struct tbDebugDraw
{
	/// Closed polygon outline, vertices in the frame of `transform`, counter-clockwise.
	void (*DrawPolygonFcn)(tbWorldTransform transform, const tbVec2* vertices, int vertexCount, tbHexColor color,
						   void* context);
	/// Filled polygon, vertices in the frame of `transform`, rounded by radius.
	void (*DrawSolidPolygonFcn)(tbWorldTransform transform, const tbVec2* vertices, int vertexCount, float radius,
								tbHexColor color, void* context);
	/// Circle outline.
	void (*DrawCircleFcn)(tbPos center, float radius, tbHexColor color, void* context);
	/// Filled circle, its centre in the frame of `transform` (whose rotation shows the body's turn).
	void (*DrawSolidCircleFcn)(tbWorldTransform transform, tbVec2 center, float radius, tbHexColor color, void* context);
	/// Filled capsule.
	void (*DrawSolidCapsuleFcn)(tbPos p1, tbPos p2, float radius, tbHexColor color, void* context);
	/// Line segment.
	void (*DrawLineFcn)(tbPos p1, tbPos p2, tbHexColor color, void* context);
	/// A frame's axes; the length is the game's to choose.
	void (*DrawTransformFcn)(tbWorldTransform transform, void* context);
	/// Point of a given size in pixels.
	void (*DrawPointFcn)(tbPos p, float size, tbHexColor color, void* context);
	/// Text at a world point.
	void (*DrawStringFcn)(tbPos p, const char* s, tbHexColor color, void* context);
	/// Axis-aligned box.
	void (*DrawBoundsFcn)(tbAABB aabb, tbHexColor color, void* context);

	tbAABB drawingBounds; ///< only shapes whose fat boxes overlap this are drawn; default: everything
	float forceScale;	  ///< m per N of the force lines (contact, friction and joint forces), default 1
	float jointScale;	  ///< joints are drawn at their drawScale times this, default 1
	bool drawContacts;	  ///< contact points: new (green), persisted (blue) and speculative (grey)
	bool drawAnchorA;	  ///< contact points at body A's anchor (default: at body B's)
	bool drawShapes;	  ///< default true
	bool drawChainNormals; ///< each chain segment's outward normal from its middle
	bool drawJoints;	   ///< anchors and links of joints
	bool drawJointExtras;  ///< with drawJoints: each joint's constraint force at its anchor B
	bool drawBounds;	   ///< the shapes' fat boxes (the broad phase's)
	bool drawMass;		   ///< dynamic bodies: the centre of mass frame, its path this step, the mass
	bool drawBodyNames;	   ///< the names of bodies that have one
	bool drawGraphColors;  ///< contact points in their constraint graph colour (tbGetGraphColor), when the
						   ///< last step coloured them
	bool drawContactFeatures; ///< the feature id of each contact point
	bool drawContactNormals;  ///< contact normals, with the separation
	bool drawContactForces;	  ///< contact normal forces (totalNormalImpulse / Δt), with their value
	bool drawFrictionForces;  ///< friction forces (tangentImpulse / sub-step), with their value
	bool drawIslands;		  ///< the box of each island of awake bodies (joined by touching contacts and
							  ///< joints)
	bool drawTree;			  ///< Tumble: the broad phase's tree nodes
	void* context;			  ///< passed to every function
} tbDebugDraw;

TB_API tbDebugDraw tbDefaultDebugDraw(void);

#ifdef __cplusplus
}
#endif
