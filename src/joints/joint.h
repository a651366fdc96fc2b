// Internal: joints. A pool in the world (like contacts: free list, generations), each joint linked
// into both bodies' joint lists. The common part (frames, thresholds, softness, the solver's view
// of the two bodies) lives in tbJoint; each kind's parameters and accumulated impulses live in a
// union member and in the kind's own file (revolute_joint.c, distance_joint.c, ...).
//
// Per step (joint.c): tbPrepareJoints gathers the joints with an awake dynamic body into
// world->cache.solverJoints (joint-id order) and computes anchors, masses and softness once;
// tbColorJoints (constraint_graph.c) puts them in solve order; each sub-step warm starts them before the contacts and solves them before the contacts in the biased
// and in the relaxing pass; tbFinishJoints reports joint events. Impulses stay in the joints for
// the next step's warm start.
#pragma once

#include "solver/solver_types.h"
#include "world/draw.h"

/// Set by tbDefault*JointDef(); a def without it was not made by them.
#define TB_JOINT_DEF_MAGIC 0x7B3A1C20

/// One end of a joint in a body's joint list; key = (jointId << 1) | edge.
typedef struct tbJointEdge
{
	int bodyId;
	int prevKey;
	int nextKey;
} tbJointEdge;

// What bodies, contacts, islands and the world ask of joints (joint.c).
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

// Impulses below are accumulated over one sub-step (N·s): the force is impulse/h.

typedef struct tbDistanceJoint
{
	float length, hertz, dampingRatio;
	float lowerSpringForce, upperSpringForce;
	float minLength, maxLength;
	float maxMotorForce, motorSpeed;
	bool enableSpring, enableLimit, enableMotor;
	float impulse, lowerImpulse, upperImpulse, motorImpulse;
	float axialMass;			///< kg, along the line at the start of the step
	tbSoftness distanceSoftness; ///< the spring's
} tbDistanceJoint;

typedef struct tbMotorJoint
{
	tbVec2 linearVelocity;
	float maxVelocityForce;
	float angularVelocity;
	float maxVelocityTorque;
	float linearHertz, linearDampingRatio, maxSpringForce;
	float angularHertz, angularDampingRatio, maxSpringTorque;
	tbVec2 linearVelocityImpulse, linearSpringImpulse;
	float angularVelocityImpulse, angularSpringImpulse;
	tbSoftness linearSpring, angularSpring;
	float angularMass; ///< kg·m²
} tbMotorJoint;

typedef struct tbMoverJoint
{
	tbVec2 linearVelocity;		 ///< m/s, target of vB − vA
	tbVec2 maxVelocityForce;	 ///< N, the cap on x and the cap on y
	tbVec2 linearVelocityImpulse; ///< N·s, (x, y), each within ±h·cap
	float linearMass;			 ///< kg, 1/(mA⁻¹ + mB⁻¹): the same on both axes
} tbMoverJoint;

typedef struct tbPogoJoint
{
	tbVec2 normal; ///< unit, world axes: the direction of the push on B
	float hertz, dampingRatio, restLength;
	float maxTensionForce, maxCompressionForce; ///< N
	float impulse;	  ///< N·s along the normal, in [−h·maxTension, h·maxCompression]
	float velocity;	  ///< m/s, the spring's velocity, advanced once per sub-step
	float normalMass; ///< kg, along the normal at the start of the step
} tbPogoJoint;

typedef struct tbPrismaticJoint
{
	float hertz, dampingRatio, targetTranslation;
	float lowerTranslation, upperTranslation;
	float maxMotorForce, motorSpeed;
	bool enableSpring, enableLimit, enableMotor;
	tbVec2 impulse; ///< (perpendicular, angular)
	float springImpulse, motorImpulse, lowerImpulse, upperImpulse;
	tbSoftness springSoftness;
} tbPrismaticJoint;

typedef struct tbRevoluteJoint
{
	float targetAngle, hertz, dampingRatio;
	float lowerAngle, upperAngle;
	float maxMotorTorque, motorSpeed;
	bool enableSpring, enableLimit, enableMotor;
	tbVec2 linearImpulse;
	float springImpulse, motorImpulse, lowerImpulse, upperImpulse;
	float axialMass; ///< kg·m², 1/(IA⁻¹ + IB⁻¹)
	tbSoftness springSoftness;
} tbRevoluteJoint;

typedef struct tbWeldJoint
{
	float linearHertz, linearDampingRatio, angularHertz, angularDampingRatio;
	tbVec2 linearImpulse;
	float angularImpulse;
	float axialMass; ///< kg·m²
	tbSoftness linearSpring, angularSpring;
} tbWeldJoint;

typedef struct tbWheelJoint
{
	float hertz, dampingRatio;
	float lowerTranslation, upperTranslation;
	float maxMotorTorque, motorSpeed;
	bool enableSpring, enableLimit, enableMotor;
	float perpImpulse, springImpulse, motorImpulse, lowerImpulse, upperImpulse;
	float motorMass; ///< kg·m²
	tbSoftness springSoftness;
} tbWheelJoint;

typedef struct tbJoint
{
	// The solver's view of the step first, set by tbPrepareJoints, then the kind's part: what the
	// solve reads sits together at the front, the fields only the API reads at the back.
	uint8_t type;		   ///< tbJointType
	bool solvedInTree;	   ///< this pass: its equality rows are solved by its tree, not row by row
	bool loopyMechanism;   ///< this step: its mechanism has too many loops for a joint tree (constraint_graph.c)
	bool rigidPin;		   ///< this step: a revolute joint alone between ground and a body, its pin solved rigid (joint_tree.c)
	int indexA, indexB;	   ///< solver body indices (the static stand-in for static or sleeping bodies)
	float invMassA, invIA; ///< 0 unless the body is awake and dynamic
	float invMassB, invIB;
	tbTransform frameA;	   ///< world rotation of frame A; p: anchor minus centre of mass, world axes
	tbTransform frameB;
	tbVec2 deltaCenter;	   ///< m, centre of mass of B minus that of A at the start of the step
	tbSoftness constraintSoftness; ///< positional correction of the biased pass (method dependent)
	int treeNode;		   ///< node of its joint tree this step (joint_tree.c), or TB_NULL_INDEX

	union
	{
		tbDistanceJoint distance;
		tbMotorJoint motor;
		tbMoverJoint mover;
		tbPogoJoint pogo;
		tbPrismaticJoint prismatic;
		tbRevoluteJoint revolute;
		tbWeldJoint weld;
		tbWheelJoint wheel;
	};

	tbJointEdge edges[2]; ///< edges[0] on body A, edges[1] on body B
	bool inUse;
	bool collideConnected;
	uint16_t generation;
	void* userData;
	tbTransform localFrameA; ///< in body A's frame (relative to its origin)
	tbTransform localFrameB;
	float forceThreshold, torqueThreshold; ///< N, N·m
	float constraintHertz, constraintDampingRatio;
	float drawScale;
} tbJoint;

/// A joint's equality rows for one pass (joint_tree.c): Ċ = JA·(vA, ωA) + JB·(vB, ωB) per row,
/// the bias of the pass and where each row's accumulated impulse lives.
typedef struct tbJointRows
{
	float JA[9]; ///< rows × 3, row-major
	float JB[9];
	float bias[3]; ///< m/s or rad/s: β·C, the target of the biased pass (the relaxing pass has none)
	float* impulse[3];
} tbJointRows;

/// One Jacobian row against one body: (x, y) linear, w angular.
typedef struct tbVec3Row
{
	float x, y, w;
} tbVec3Row;

/// The velocities and position deltas of a joint's two bodies for one solve, loaded once and
/// stored once (the stand-in has zero inverse mass, so storing it back changes nothing).
typedef struct tbJointBodies
{
	tbSolverBody* sA;
	tbSolverBody* sB;
	tbVec2 vA, vB;
	float wA, wB;
} tbJointBodies;

// The hot helpers every kind's solve calls several times per sub-step; inline: each is a few loads,
// stores or multiplies, and as calls across files (no inlining between them) their call overhead
// was a large share of a joint grid's solve.

/// Load the velocities of the joint's two bodies (stored once with tbStoreJointBodies; the
/// static stand-in has zero inverse mass, so storing it back changes nothing).
static inline tbJointBodies tbLoadJointBodies(const tbStepContext* context, const tbJoint* joint)
{
	tbJointBodies b;
	b.sA = context->bodies + joint->indexA;
	b.sB = context->bodies + joint->indexB;
	b.vA = b.sA->linearVelocity;
	b.wA = b.sA->angularVelocity;
	b.vB = b.sB->linearVelocity;
	b.wB = b.sB->angularVelocity;
	return b;
}

/// A side the solve can move: an awake dynamic body (a body that cannot turn still translates).
static inline bool tbJointMovesA(const tbJoint* joint)
{
	return joint->invMassA > 0.0f || joint->invIA > 0.0f;
}

static inline bool tbJointMovesB(const tbJoint* joint)
{
	return joint->invMassB > 0.0f || joint->invIB > 0.0f;
}

/// Store back only what can have changed: a side that cannot move (static stand-in, kinematic
/// body) is shared by joints of one colour solved at the same time on different workers, and its
/// velocity is theirs to read, not to write.
static inline void tbStoreJointBodies(const tbJoint* joint, tbJointBodies* b)
{
	if (tbJointMovesA(joint))
	{
		b->sA->linearVelocity = b->vA;
		b->sA->angularVelocity = b->wA;
	}
	if (tbJointMovesB(joint))
	{
		b->sB->linearVelocity = b->vB;
		b->sB->angularVelocity = b->wB;
	}
}

/// Current anchors (relative to the centres of mass, rotated with the bodies since the start of
/// the step) and the vector from anchor A to anchor B.
static inline void tbJointAnchors(const tbJoint* joint, const tbJointBodies* b, tbVec2* rA, tbVec2* rB, tbVec2* d)
{
	*rA = tbRotateVector(b->sA->deltaRotation, joint->frameA.p);
	*rB = tbRotateVector(b->sB->deltaRotation, joint->frameB.p);
	tbVec2 dc = tbSub(b->sB->deltaPosition, b->sA->deltaPosition);
	*d = tbAdd(tbAdd(dc, joint->deltaCenter), tbSub(*rB, *rA));
}

/// Apply impulse P at the anchors (B receives +P, A −P) plus an angular impulse L (B +L, A −L).
static inline void tbApplyJointImpulse(const tbJoint* joint, tbJointBodies* b, tbVec2 rA, tbVec2 rB, tbVec2 P, float L)
{
	b->vA = tbMulSub(b->vA, joint->invMassA, P);
	b->wA -= joint->invIA * (tbCross(rA, P) + L);
	b->vB = tbMulAdd(b->vB, joint->invMassB, P);
	b->wB += joint->invIB * (tbCross(rB, P) + L);
}

/// Set row `row` of a rows block: JA = (ax, ay, aw), JB = (bx, by, bw), position error C (the
/// pass's bias is applied later), accumulated impulse at `impulse`.
void tbSetJointRow(tbJointRows* rows, int row, tbVec3Row a, tbVec3Row b, float C, float* impulse);

/// Number of equality rows (0–3): the rows a joint tree solves exactly.
int tbJointEqualityRowCount(const tbJoint* joint);
void tbGetJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows);

// joint_tree.c: the equality rows of each tree of joined bodies solved exactly.
/// Once per step, after the joints are prepared and ordered (tbColorJoints): the trees (spanning
/// trees of the joint graph of awake dynamic bodies) of the mechanisms that are mostly trees.
void tbBuildJointTrees(tbStepContext* context);
/// Once per sub-step, before the first biased pass: rows and factorisation with the current anchors.
void tbFactorJointTrees(tbStepContext* context);
/// Each pass: which joints leave their equality rows to their tree (biased passes, factored trees).
void tbMarkTreeRows(tbStepContext* context, bool useBias);
/// Each biased pass, after the joints' other rows: the exact impulses of the tree rows.
void tbSolveJointTrees(tbStepContext* context);

// joint.c: the step's pieces (solver.c, solver_soft.c, solver_baumgarte.c, solver_ngs.c call them).
void tbPrepareJoints(tbStepContext* context);
void tbWarmStartJoints(tbStepContext* context);
/// One pass over the joints. useBias: the positional correction of the biased pass (soft step's
/// soft spring, or the Baumgarte bias); false: the relaxing pass (rigid, no correction). User
/// springs, motors and the speculative side of limits act in both.
void tbSolveJoints(tbStepContext* context, bool useBias);
// The pieces of those two passes for the workers (solver_workers.c): ranges of world->cache.solverJoints
// within one colour, and the joint trees' serial part. tbSolveJoints(useBias) is: begin the pass,
// rows of every colour, then (biased, with trees) the trees and the rows again.
void tbWarmStartJointRange(tbStepContext* context, int begin, int end);
void tbBeginJointPass(tbStepContext* context, bool useBias);
void tbSolveJointRowRange(tbStepContext* context, int begin, int end, bool useBias);
/// Extra relaxing iterations the soft step needs this step: 1 with joint trees (joint.c says why).
int tbJointTreeRelaxIterations(const tbStepContext* context);
/// Whether the relaxing iteration `iteration` (0 first) of a sub-step solves the joints.
bool tbRelaxJointsInIteration(const tbStepContext* context, int iteration);
/// After the sub-steps: joint events and the sub-step length that converts impulses to forces.
void tbFinishJoints(tbStepContext* context);

// joint.c: shared by the kind files.
/// The joint for an id and its world, or NULL after an error naming `function`: a stale id, the
/// world locked when `mutating`, or a joint of another kind (type < 0 accepts any kind).
tbJoint* tbGetJointChecked(tbJointId id, const char* function, tbWorld** world, int type, bool mutating);
/// The world's joint for a created slot, set up from a checked base definition (NULL on error).
tbJoint* tbCreateJointInternal(tbWorldId worldId, const tbJointDef* def, tbJointType type, const char* function,
							   tbJointId* id);
tbJointId tbMakeJointId(const tbWorld* world, const tbJoint* joint);
/// A def pointer that is not NULL and was made by `defaultName` (reports an error naming f).
bool tbCheckJointDefPointer(const char* f, const void* def, int internalValue, const char* defaultName);
void tbWakeJoint(tbWorld* world, const tbJoint* joint);
/// Checks for defs: a float that must be finite and ≥ 0, a pair lower ≤ upper.
bool tbCheckRange(const char* function, const char* lowerName, float lower, const char* upperName, float upper);
/// Frames of the joint in world space now (frame origins and rotations).
tbWorldTransform tbJointWorldFrameA(const tbWorld* world, const tbJoint* joint);
tbWorldTransform tbJointWorldFrameB(const tbWorld* world, const tbJoint* joint);

// The geometry of a joint that slides along frame A's x-axis (prismatic and wheel joints, derived in
// prismatic_joint.c) for one solve: anchors, d = anchor B − anchor A, the axis, its normal and the
// lever arms a1 = (d + rA) × axis, a2 = rB × axis, s1 = (d + rA) × perp, s2 = rB × perp.
typedef struct tbAxisFrame
{
	tbVec2 rA, rB, d;
	tbVec2 axis, perp;
	float a1, a2, s1, s2;
	float translation; ///< m, axis·d
} tbAxisFrame;

// Inline for the reason the helpers above are: the wheel joint's solve calls them up to six
// times a pass, each a few multiplies.
static inline tbAxisFrame tbMakeAxisFrame(const tbJoint* joint, const tbJointBodies* b)
{
	tbAxisFrame g;
	tbJointAnchors(joint, b, &g.rA, &g.rB, &g.d);
	g.axis = tbRotateVector(b->sA->deltaRotation, tbRot_GetXAxis(joint->frameA.q));
	g.perp = tbLeftPerp(g.axis);
	tbVec2 leverA = tbAdd(g.d, g.rA);
	g.a1 = tbCross(leverA, g.axis);
	g.a2 = tbCross(g.rB, g.axis);
	g.s1 = tbCross(leverA, g.perp);
	g.s2 = tbCross(g.rB, g.perp);
	g.translation = tbDot(g.axis, g.d);
	return g;
}

/// Impulse `axial` along the axis and (perp, angular) across it and in angle, to both bodies.
static inline void tbApplyAxisImpulse(const tbJoint* joint, tbJointBodies* b, const tbAxisFrame* g, float axial,
									  float perp, float angular)
{
	tbVec2 P = tbAdd(tbMulSV(axial, g->axis), tbMulSV(perp, g->perp));
	float LA = axial * g->a1 + perp * g->s1 + angular;
	float LB = axial * g->a2 + perp * g->s2 + angular;
	b->vA = tbMulSub(b->vA, joint->invMassA, P);
	b->wA -= joint->invIA * LA;
	b->vB = tbMulAdd(b->vB, joint->invMassB, P);
	b->wB += joint->invIB * LB;
}

/// Relative speed along the axis (m/s).
static inline float tbAxialSpeedOf(const tbJointBodies* b, const tbAxisFrame* g)
{
	return tbDot(g->axis, tbSub(b->vB, b->vA)) + g->a2 * b->wB - g->a1 * b->wA;
}

/// The effective mass along the axis (kg).
static inline float tbAxialMassOf(const tbJoint* joint, const tbAxisFrame* g)
{
	float k = joint->invMassA + joint->invMassB + joint->invIA * g->a1 * g->a1 + joint->invIB * g->a2 * g->a2;
	return k > 0.0f ? 1.0f / k : 0.0f;
}

/// A one-sided row (a limit: C ≥ 0, its accumulated impulse ≥ 0) with effective mass `mass` and
/// velocity Cdot along it: speculative while C > 0 (the bias C/h lets the gap close within this
/// sub-step, no further), the joint's positional softness when violated in the biased pass, rigid
/// in the relaxing pass. Accumulates into *accumulated and returns the impulse to apply.
static inline float tbOneSidedImpulse(const tbJoint* joint, float C, float Cdot, float mass, float* accumulated,
									  const tbStepContext* context, bool useBias)
{
	tbSoftness soft = {0.0f, 1.0f, 0.0f};
	float bias = 0.0f;
	if (C > 0.0f)
	{
		bias = C * context->inv_h;
	}
	else if (useBias)
	{
		soft = joint->constraintSoftness;
		bias = soft.biasRate * C;
	}
	float impulse = -soft.massScale * mass * (Cdot + bias) - soft.impulseScale * *accumulated;
	float newImpulse = tbMaxFloat(*accumulated + impulse, 0.0f);
	impulse = newImpulse - *accumulated;
	*accumulated = newImpulse;
	return impulse;
}

/// A one-sided axial row: C = sign·(translation − limit) ≥ 0 (tbOneSidedImpulse).
static inline void tbSolveAxisLimit(const tbJoint* joint, tbJointBodies* b, const tbAxisFrame* g, float axialMass,
									float C, float sign, float* accumulated, const tbStepContext* context,
									bool useBias)
{
	float impulse = tbOneSidedImpulse(joint, C, sign * tbAxialSpeedOf(b, g), axialMass, accumulated, context, useBias);
	tbApplyAxisImpulse(joint, b, g, sign * impulse, 0.0f, 0.0f);
}

// Separation of a joint's frames (tbJoint_GetLinearSeparation, tbJoint_GetAngularSeparation): how far
// the joint's rigid rows and active limits are from holding now, from the bodies' transforms (m and
// rad; springs, motors and the admissible range of a limit count as no error). In the kind files.
float tbDistanceJointLinearSeparation(const tbWorld* world, const tbJoint* joint);
/// Prismatic and wheel joints: the anchor offset across the axis and beyond the limits, combined.
float tbAxisJointLinearSeparation(const tbWorld* world, const tbJoint* joint, bool enableLimit, float lower,
								  float upper);
float tbPrismaticJointAngularSeparation(const tbWorld* world, const tbJoint* joint);
float tbRevoluteJointLinearSeparation(const tbWorld* world, const tbJoint* joint);
float tbRevoluteJointAngularSeparation(const tbWorld* world, const tbJoint* joint);
float tbWeldJointLinearSeparation(const tbWorld* world, const tbJoint* joint);
float tbWeldJointAngularSeparation(const tbWorld* world, const tbJoint* joint);

// One file per kind, the same functions in the same order: prepare (once per step), warm start
// and solve (each sub-step), the constraint force and torque (impulses/h), drawing.
void tbPrepareDistanceJoint(tbJoint* joint, const tbStepContext* context);
void tbWarmStartDistanceJoint(tbJoint* joint, tbStepContext* context);
void tbSolveDistanceJoint(tbJoint* joint, tbStepContext* context, bool useBias);
void tbGetDistanceJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque);
void tbDrawDistanceJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint);
int tbDistanceJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows);
/// Rigid: no spring, or the limits pin the length.
bool tbDistanceJointIsRigid(const tbJoint* joint);

void tbPrepareMotorJoint(tbJoint* joint, const tbStepContext* context);
void tbWarmStartMotorJoint(tbJoint* joint, tbStepContext* context);
void tbSolveMotorJoint(tbJoint* joint, tbStepContext* context, bool useBias);
void tbGetMotorJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque);
void tbDrawMotorJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint);

void tbPrepareMoverJoint(tbJoint* joint, const tbStepContext* context);
void tbWarmStartMoverJoint(tbJoint* joint, tbStepContext* context);
void tbSolveMoverJoint(tbJoint* joint, tbStepContext* context, bool useBias);
void tbGetMoverJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque);
void tbDrawMoverJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint);

void tbPreparePogoJoint(tbJoint* joint, const tbStepContext* context);
/// Also advances the pogo's spring by one sub-step (once per sub-step, whatever the method's passes).
void tbWarmStartPogoJoint(tbJoint* joint, tbStepContext* context);
void tbSolvePogoJoint(tbJoint* joint, tbStepContext* context, bool useBias);
void tbGetPogoJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque);
void tbDrawPogoJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint);

void tbPreparePrismaticJoint(tbJoint* joint, const tbStepContext* context);
void tbWarmStartPrismaticJoint(tbJoint* joint, tbStepContext* context);
void tbSolvePrismaticJoint(tbJoint* joint, tbStepContext* context, bool useBias);
void tbGetPrismaticJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque);
void tbDrawPrismaticJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint);
int tbPrismaticJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows);

void tbPrepareRevoluteJoint(tbJoint* joint, const tbStepContext* context);
void tbWarmStartRevoluteJoint(tbJoint* joint, tbStepContext* context);
void tbSolveRevoluteJoint(tbJoint* joint, tbStepContext* context, bool useBias);
void tbGetRevoluteJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque);
void tbDrawRevoluteJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint);
int tbRevoluteJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows);

void tbPrepareWeldJoint(tbJoint* joint, const tbStepContext* context);
void tbWarmStartWeldJoint(tbJoint* joint, tbStepContext* context);
void tbSolveWeldJoint(tbJoint* joint, tbStepContext* context, bool useBias);
void tbGetWeldJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque);
void tbDrawWeldJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint);
int tbWeldJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows);

void tbPrepareWheelJoint(tbJoint* joint, const tbStepContext* context);
void tbWarmStartWheelJoint(tbJoint* joint, tbStepContext* context);
void tbSolveWheelJoint(tbJoint* joint, tbStepContext* context, bool useBias);
void tbGetWheelJointReaction(const tbWorld* world, const tbJoint* joint, float inv_h, tbVec2* force, float* torque);
void tbDrawWheelJoint(const tbDebugDraw* draw, const tbWorld* world, const tbJoint* joint);
int tbWheelJointEqualityRows(tbJoint* joint, const tbJointBodies* b, tbJointRows* rows);
