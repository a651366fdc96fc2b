// Internal: the data every piece of the solve stage shares: the per-step body state, the contact
// constraints (scalar and wide) and the step context. Types only: each piece declares its
// functions in its own header (integrator.h, contact_solver.h, constraint_graph.h,
// solver_methods.h) and includes this one, so no piece includes the stage driver (solver.c).
//
// Data layout. Each step the awake bodies are gathered into dense arrays in the awake set's order,
// indexed by tbBody::awakeIndex; one extra entry at the end (index bodyCount) is a motionless body
// with infinite mass that stands for every static or non-awake body, so the contact loops never
// branch on "is there a body here". Contacts become tbContactConstraint structs in the order of
// world->cache.solverContacts, with anchors, effective masses and softness precomputed once per step.
#pragma once

#include "core/simd.h"
#include "world/world.h"

/// Hot state of one body, touched by every contact in every iteration: 32 bytes, two per cache
/// line pair. Positions are kept as deltas from the start of the step (centre and rotation), which
/// keeps the linearised separation update exact to float rounding over large worlds.
typedef struct tbSolverBody
{
	tbVec2 linearVelocity; ///< m/s, of the centre of mass
	float angularVelocity; ///< rad/s
	float padding;		   ///< unused (keeps 32 bytes; the wide solver loads the first 16 as one row)
	tbVec2 deltaPosition;  ///< m, centre motion since the start of the step
	tbRot deltaRotation;   ///< rotation since the start of the step
} tbSolverBody;

_Static_assert(sizeof(tbSolverBody) == 32, "tbSolverBody is meant to be 32 bytes");

/// Per-body velocity increments of one sub-step, computed once per step (forces are constant
/// during a step): v ← (v + linearDelta)·linearDamping, ω ← (ω + angularDelta)·angularDamping.
/// 20 bytes; only read by the velocity integration.
typedef struct tbSolverMotion
{
	tbVec2 linearDelta;	  ///< m/s per sub-step: h·(gravityScale·g + invMass·F)
	float angularDelta;	  ///< rad/s per sub-step: h·invInertia·τ
	float linearDamping;  ///< 1/(1 + h·linearDamping), dimensionless
	float angularDamping; ///< 1/(1 + h·angularDamping), dimensionless
} tbSolverMotion;

_Static_assert(sizeof(tbSolverMotion) == 20, "tbSolverMotion is meant to be 20 bytes");

/// What the contact preparation needs of a body, read once per contact end: 16 bytes in solver
/// order, so that preparing a contact reads no tbBody beyond its awake index. Zero for
/// kinematic bodies and for the static stand-in (they do not respond); invI is 0 for a body with
/// fixed rotation.
typedef struct tbSolverMass
{
	float invMass;		///< 1/kg
	float invI;			///< 1/(kg·m²), about the centre of mass
	float gravityScale; ///< the body's, for the impact speed estimate of speculative points
	float padding;
} tbSolverMass;

_Static_assert(sizeof(tbSolverMass) == 16, "tbSolverMass is meant to be 16 bytes");

/// Soft constraint coefficients (Catto 2024, "soft step"), for one stiffness and sub-step h:
/// with ω = 2π·hertz, ζ the damping ratio and a = h·ω·(2ζ + h·ω),
/// biasRate = ω/(2ζ + h·ω) (1/s), massScale = a/(1 + a), impulseScale = 1/(1 + a).
/// Rigid: {0, 1, 0}.
typedef struct tbSoftness
{
	float biasRate;
	float massScale;
	float impulseScale;
} tbSoftness;

/// The coefficients for a stiffness in hertz (rigid when hertz ≤ 0), contacts and joints alike.
static inline tbSoftness tbMakeSoftness(float hertz, float dampingRatio, float h)
{
	if (hertz <= 0.0f)
	{
		tbSoftness rigid = {0.0f, 1.0f, 0.0f};
		return rigid;
	}
	float omega = 2.0f * TB_PI * hertz;
	float a1 = 2.0f * dampingRatio + h * omega;
	float a2 = h * omega * a1;
	float a3 = 1.0f / (1.0f + a2);
	tbSoftness soft = {omega / a1, a2 * a3, a3};
	return soft;
}

/// One manifold point as the solver sees it: 44 bytes.
typedef struct tbContactConstraintPoint
{
	tbVec2 anchorA;			  ///< m, point − centre of mass of A at the start of the step
	tbVec2 anchorB;			  ///< m, point − centre of mass of B
	float baseSeparation;	  ///< m, separation − dot(anchorB − anchorA, normal): add the current
							  ///< dot(pB − pA, normal) to get the linearised separation
	float normalImpulse;	  ///< N·s, accumulated over the sub-step (warm start carries it)
	float tangentImpulse;	  ///< N·s, accumulated friction impulse
	float totalNormalImpulse; ///< N·s, the normal impulse the step applied (tbManifoldPoint's); 0: the point
							  ///< never pushed (restitution skips it)
	float normalMass;		  ///< kg, 1/K along the normal
	float tangentMass;		  ///< kg, 1/K along the tangent
	float relativeVelocity;	  ///< m/s, relative normal velocity at the start of the step (< 0 approaching)
} tbContactConstraintPoint;

_Static_assert(sizeof(tbContactConstraintPoint) == 44, "tbContactConstraintPoint is meant to be 44 bytes");

/// One contact as the solver sees it: 176 bytes.
typedef struct tbContactConstraint
{
	int indexA;				///< solver body index of A (bodyCount for the static stand-in)
	int indexB;				///< solver body index of B
	tbVec2 normal;			///< from A to B
	float invMassA, invIA;	///< 1/kg, 1/(kg·m²); 0 for static, kinematic or asleep
	float invMassB, invIB;
	float friction;			///< Coulomb coefficient, mixed
	float restitution;		///< coefficient of restitution, mixed
	tbSoftness softness;	///< used by the soft bias policy only
	int pointCount;
	tbContactConstraintPoint points[2];
	// Surface extras (tbSurfaceMaterial): a contact that has one is solved by the scalar solver
	// (constraint_graph.c sends it to the overflow list).
	float tangentSpeed;		 ///< m/s, target relative tangential speed (conveyor belts)
	float rollingResistance; ///< m: the resisting torque's bound per unit normal impulse
	float rollingMass;		 ///< kg·m², 1/(IA⁻¹ + IB⁻¹)
	float rollingImpulse;	 ///< N·m·s, accumulated over the sub-step
	/// Central friction (tbStepContext::centralFriction): the one friction row's anchors, at the
	/// manifold's centre of pressure; its mass and impulse are points[0]'s tangentMass and
	/// tangentImpulse, and points[1]'s stay 0 (contact_solver.c).
	tbVec2 frictionAnchorA, frictionAnchorB;
} tbContactConstraint;

_Static_assert(sizeof(tbContactConstraint) == 176, "tbContactConstraint is meant to be 176 bytes");

/// What colouring needs of a contact, known before the contact is prepared (contact_solver.c): the
/// wide solver colours first and then prepares each contact straight into its lane.

/// How the velocity solve treats separation. Speculative gaps (s > 0) always get bias s/h: the
/// constraint lets the bodies close exactly the gap in one sub-step and no more.
typedef enum tbBiasPolicy
{
	tb_biasSoft,		///< soft step, biased pass: soft spring-damper push-out of overlap
	tb_biasRelax,		///< soft step, relaxing pass: rigid, no push-out (removes the bias velocity)
	tb_biasRelaxRepeat, ///< a further relaxing pass of the same sub-step: the positions have not
						///< moved since the first, so the wide solver reuses its speculative bias
	tb_biasBaumgarte,	///< rigid with a Baumgarte velocity bias beyond the linear slop
	tb_biasSpeculative, ///< rigid, speculative gaps only (NGS corrects overlap on positions)
} tbBiasPolicy;

/// Colours of the constraint graph (constraint_graph.c); at most 32 (one bit each in a uint32_t
/// mask per body). Greedy colouring needs at most one more colour than a body has constraints, and
/// a body in a pile has few, so 24 leaves room for crowded bodies while the per-colour tables stay
/// small; a constraint that finds no colour goes to the scalar overflow.
#define TB_GRAPH_COLOR_COUNT 24

/// Most island partitions of a step (constraint_graph.c): one per worker, up to this many.
#define TB_MAX_PARTITIONS 8

/// The accumulated impulses of one manifold point of TB_SIMD_WIDTH contacts, lane by lane (N·s):
/// 12 bytes a lane (48 with four lanes).
typedef struct tbWideImpulses
{
	tbFloatW normalImpulse;
	tbFloatW tangentImpulse;
	tbFloatW totalNormalImpulse; ///< the normal impulse the step applied (tbManifoldPoint's)
} tbWideImpulses;

/// The rest of one manifold point of TB_SIMD_WIDTH contacts, lane by lane (structure of arrays): 32
/// bytes a lane (128 with four lanes).
typedef struct tbWideContactPoint
{
	tbFloatW anchorAX, anchorAY; ///< m, as tbContactConstraintPoint
	tbFloatW anchorBX, anchorBY;
	tbFloatW baseSeparation;
	tbFloatW normalMass; ///< 0 in a lane whose contact has fewer points: its impulses stay 0
	tbFloatW tangentMass;
	/// m/s, max(s, 0)/h from the sub-step's first relaxing pass (s fixed until the next); written by
	/// that pass before any pass reads it, so the preparation leaves it alone
	tbFloatW relaxBias;
} tbWideContactPoint;

/// TB_SIMD_WIDTH contacts of one graph colour, solved together (contact_solver_wide.c): 608 bytes
/// with four lanes (SSE2), 1,216 with eight (AVX2); the array starts on a 64-byte line
/// (constraint_graph.c). Padding lanes have both bodies at the static stand-in and every number 0.
/// The impulses of both points come first, in the block's first 24·TB_SIMD_WIDTH bytes: the store
/// after the solve, which reads only them, lane by lane in contact-id order and so from blocks long
/// gone from the cache, then reads the lines of those bytes per contact instead of lines spread
/// over the whole block. Which constraint a lane
/// holds is tbStepContext::wideLocation's inverse; the blocks do not repeat it.
typedef struct tbWideContactConstraint
{
	tbWideImpulses impulses[2]; ///< point 0, point 1
	int indexA[TB_SIMD_WIDTH];			///< solver body indices, as tbContactConstraint
	int indexB[TB_SIMD_WIDTH];
	tbFloatW normalX, normalY;
	tbFloatW friction;
	tbFloatW invMassA, invIA, invMassB, invIB;
	tbFloatW biasRate, massScale, impulseScale; ///< tbSoftness, lane by lane
	tbWideContactPoint points[2];
	/// Central friction: the friction row's anchors (tbContactConstraint::frictionAnchorA/B); its
	/// mass is points[0].tangentMass, its impulse impulses[0].tangentImpulse (impulses[1]'s stays 0).
	tbFloatW frictionAnchorAX, frictionAnchorAY;
	tbFloatW frictionAnchorBX, frictionAnchorBY;
} tbWideContactConstraint;

_Static_assert(sizeof(tbWideContactConstraint) == 152 * TB_SIMD_WIDTH,
			   "tbWideContactConstraint is meant to be 152 bytes a lane (608 with four lanes)");

/// The rolling-resistance row of a block's lanes (contact_solver.c: an angular impulse against the
/// relative spin, bounded by rollingResistance × the normal impulse), one per block beside the
/// blocks when some contact of the step has rolling resistance: most blocks have none, and the
/// block itself keeps its size. A lane without rolling resistance has 0 in every field and is
/// left untouched by the row (a select, so not even the sign of a zero changes).
typedef struct tbWideRolling
{
	tbFloatW resistance; ///< rollingResistance, 0 in a lane without
	tbFloatW mass;		 ///< 1/(invIA + invIB), 0 when neither body can turn
	tbFloatW impulse;	 ///< accumulated over the step, warm started
} tbWideRolling;

/// Everything the pieces of one step share. Lives on the stack of tbSolveStage.
typedef struct tbStepContext
{
	tbWorld* world;
	float timeStep;		///< s
	float h;			///< s, sub-step
	float inv_h;		///< 1/s
	int subStepCount;

	tbSolverBody* bodies; ///< bodyCount + 1 (the last is the static stand-in)
	tbSolverMotion* motions;
	tbSolverMass* masses; ///< bodyCount + 1, as bodies
	uint8_t* linearLocks; ///< per solver body: 1 x locked, 2 y locked (motion locks); NULL when no body has one
	uint8_t* fastRotation; ///< per solver body: 1 when its spin is not capped (tbBodyDef::allowFastRotation);
						   ///< NULL when no body allows it
	int bodyCount;

	tbContactConstraint* constraints; ///< in the order of world->cache.solverContacts; with the wide
									  ///< solver only the overflow's and the bouncing ones are written
	/// Wide solver only (NULL for the scalar one): each contact's key in contact-id order
	/// (world->cache.solverContactsById), written by the key pass, and the same keys in solve order, filled
	/// only when the colouring runs or some contact bounces (constraint_graph.c, tbScatterKeys).
	tbContactKey* keys;
	tbContactKey* keysById;
	/// A steady step: keysById is the colour cache's copy of the last step's keys, which these
	/// equal (tbSteadyContactKeys); read only (no contact bounces, so nothing writes them).
	bool keysFromCache;
	int constraintCount;
	int restitutionCount; ///< constraints with restitution > 0 (tbApplyRestitution skips when 0)

	// Wide solver (null when the scalar reference solver runs): constraints grouped by colour in
	// blocks of TB_SIMD_WIDTH, and the constraints that found no colour, by index.
	tbWideContactConstraint* wideConstraints;
	int wideCount;
	tbWideRolling* wideRolling; ///< one per block, zeroed; NULL when no coloured contact rolls (tb_keyRolling)
	int rollingCount;			///< coloured contacts with tb_keyRolling
	int* overflowConstraints;
	int overflowCount;
	int* wideLocation; ///< per constraint: block·TB_SIMD_WIDTH + lane, or −1 (overflow, or unpacked)
	/// The same in contact-id order (world->cache.solverContactsById), for the passes that walk the
	/// contacts in that order; not updated when restitution unpacks a bouncing constraint.
	int* locationById;
	int colorCount;											///< colours in use this step
	int colorBlockStart[TB_GRAPH_COLOR_COUNT + 1]; ///< blocks of colour k: [start[k], start[k + 1])
	/// Island partitions (constraint_graph.c, tbCutPartitions), 0 when there are none: partition p
	/// is the solver bodies [partitionBodyStart[p], partitionBodyStart[p + 1]) and the contacts on
	/// them, which no contact links to another partition's bodies. Each colour's blocks then hold
	/// one partition's contacts after another: partition p's blocks of colour k are
	/// [partitionBlockStart[k][p], partitionBlockStart[k][p + 1]).
	int partitionCount;
	int partitionBodyStart[TB_MAX_PARTITIONS + 1];
	int partitionBlockStart[TB_GRAPH_COLOR_COUNT][TB_MAX_PARTITIONS + 1];
	// Joints (constraint_graph.c): world->cache.solverJoints reordered. First the joints of small
	// mechanisms, [0, jointSmallCount), in units of whole mechanisms [jointUnitStart[u],
	// jointUnitStart[u + 1]) for u < jointUnitCount; then colour groups: group k holds
	// [jointColorStart[k], jointColorStart[k + 1]) for k < jointColorCount, the last group being the
	// joints that found no colour (solved alone, after the colours).
	int jointSmallCount;
	int* jointUnitStart; ///< step arena
	bool jointThresholds; ///< some joint of this step has a force or torque threshold (joint events)
	int jointUnitCount;
	int jointColorStart[TB_GRAPH_COLOR_COUNT + 2];
	int jointColorCount; ///< groups in use, the overflow group included when it is not empty
	bool jointOverflow;	 ///< the last group is the joints without a colour
	int jointTreeCandidates; ///< joints with equality rows outside loopy mechanisms (0: no joint tree to build)
	/// The joints are as they were when the last tree build found no tree and no rigid pin
	/// (constraint_graph.c's fingerprint, masses included): this step's build would find none either.
	bool jointTreesKnownAbsent;
	void* wideMemory; ///< step arena
	int wideMemoryBytes;
	void* ngsScratch; ///< solver_ngs.c's constraints, step arena (taken at the first sub-step)

	tbSoftness contactSoftness; ///< dynamic vs dynamic, new or deep (soft step: contactHertz)
	tbSoftness staticSoftness;	///< dynamic vs static or kinematic (soft step: restHertz)
	tbSoftness settledSoftness; ///< settled dynamic (soft step: settledHertz)
	float contactHertz;			///< soft step: Hz, stiffness of new and deep dynamic contacts
	float restHertz;			///< soft step: Hz, stiffness of static and kinematic contacts
	float settledHertz;			///< soft step: Hz, stiffness of dynamic contacts once settled
	int subStepIndex;			///< the sub-step being solved, 0 .. subStepCount − 1
	float settleSteps;			///< soft step: steps a new dynamic contact stays at contactHertz (0: no ramp)
	float deepOverlap;			///< soft step: m, start-of-step overlap beyond which it stays at contactHertz
	float dampingRatio;			///< soft step: of the ramped stiffness
	bool contactSoftening;		///< soft step: tbWorldDef::enableContactSoftening (tbSoftenedSoftness)
	float softeningHertz;		///< soft step: Hz, the softened pairs' stiffness before the mass ratio
	float contactSpeed;	///< m/s
	float maxLinearSpeed;		///< m/s
	float maxAngularSpeed;		///< rad/s: TB_MAX_ROTATION per step
	bool enableWarmStarting;
	bool centralFriction; ///< one friction row per contact (tbWorldDef::enableCentralFriction; not NGS)
	uint64_t lapTicks; ///< when the solve stage's current part began (tbProfileLap)
} tbStepContext;

/// Adds the milliseconds since *ticks to a part of the step's profile and starts the next part.
static inline void tbProfileLap(float* part, uint64_t* ticks)
{
	*part += tbGetMillisecondsAndReset(ticks);
}

