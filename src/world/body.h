// Internal: a body as the world keeps it, and what the other parts of the world ask of bodies
// (body.c).
#pragma once

#include "core/core.h"

#include "tumble/types.h"

typedef struct tbWorld tbWorld;

/// A body. Cold fields (user data, name, lists) sit beside the state because the solver copies
/// what it touches into tbSolverBody arrays each step.
typedef struct tbBody
{
	// Hot in the collide and island stages (speculative margin, motion bounds, solver key, anchors,
	// contact-list walks): grouped at the front, through solverMoves, so that a visit touches the
	// first cache line only (allocations are line-aligned, a body three lines long on 64-bit
	// targets; with double-precision positions the group spills into the second line).
	tbWorldTransform transform; ///< body origin and rotation
	tbPos center;				///< world centre of mass
	tbVec2 linearVelocity;
	float angularVelocity;
	/// Displacement per step its speculative contacts cover (tbSpeculativeReach, read per contact):
	/// max(TB_SPECULATIVE_REACH, safetyFactor × minExtent), kept current by body.c.
	float speculativeReach;
	/// Largest distance from the centre of mass to a point of a shape's core (a circle's centre, a
	/// capsule's segment, a polygon's vertices before rounding): a turn about the centre of mass
	/// moves the surface, as any distance to it sees it, only as far as it moves the core (a rounded
	/// surface keeps its distance to its core). The speculative margin reads it per contact.
	float coreExtent;
	float gravityScale;
	int headContactKey; ///< doubly linked contact edges; key = (contactId << 1) | edge
	int awakeIndex;		///< index in world->awakeBodies, or TB_NULL_INDEX when asleep or static
	/// maxExtent + |localCenter|: the farthest shape point from the body origin (m), which the narrow
	/// phase's motion bounds read per contact (tbUpdateBodyDerived keeps it current)
	float originExtent;
	uint8_t type;		///< tbBodyType
	bool isFast;		///< moved far this step: swept by continuous collision (read per contact: first line)
	bool enableContactRecycling; ///< read per contact by the narrow phase: first line
	/// The solve can change its velocity: dynamic with a positive inverse mass or (rotation not
	/// fixed) inverse inertia. Read per contact by the narrow phase for the solver key.
	bool solverMoves;

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

	float maxExtent; ///< largest distance from the centre of mass to any shape point
	uint16_t generation;
	bool inUse;
	bool enableSleep;
	bool fixedRotation; ///< also motion lock angularZ
	bool lockLinearX;	///< motion locks (tbMotionLocks)
	bool lockLinearY;
	bool isBullet;
	bool isMarked;
	bool isDisabled; ///< out of the simulation (tbBody_Disable): no proxies, no contacts, never awake
	bool allowFastRotation; ///< tbBodyDef::allowFastRotation: the solver does not cap its spin
} tbBody;

#if !defined(TUMBLE_DOUBLE_PRECISION)
_Static_assert(offsetof(tbBody, solverMoves) < 64, "tbBody: what the narrow phase reads fits its first cache line");
_Static_assert(sizeof(void*) != 8 || sizeof(tbBody) % 64 == 0, "tbBody: whole cache lines on 64-bit targets");
#endif

/// The body's cached derived fields (originExtent, solverMoves) from its type, mass and extents:
/// called wherever those change.
void tbUpdateBodyDerived(tbBody* body);

/// The body for a body id and its world, or NULL after reporting an error naming `function`; also
/// refuses a locked world when `mutating`.
tbBody* tbGetBodyChecked(tbBodyId id, const char* function, tbWorld** world, bool mutating);
tbBodyId tbMakeBodyId(const tbWorld* world, int bodyId);

/// A body's mass properties as its shapes give them (tbUpdateBodyMass): none for a static or
/// kinematic body; a dynamic body without mass weighs 1 kg at its origin.
typedef struct tbBodyMass
{
	float mass, invMass;
	float inertia, invInertia; ///< about the centre of mass
	tbVec2 localCenter;
} tbBodyMass;

/// Reads the body's shapes and fixed rotation, writes nothing (snapshot.c predicts the stored
/// mass with it).
tbBodyMass tbComputeBodyMass(const tbWorld* world, const tbBody* body);
/// Apply tbComputeBodyMass: the centre moves, the origin keeps its velocity, contacts restart.
void tbUpdateBodyMass(tbWorld* world, tbBody* body);
/// Extents over the body's shapes in list order, about its centre of mass now (writes nothing:
/// snapshot.c predicts the stored values with it): the smallest distance to the surface (a
/// conservative "thickness", continuous collision), the largest to any point of any shape, and the
/// largest to a point of a core (coreExtent). The body's coreExtent always equals what this gives
/// (set with the extents, and again when a shape is removed without a mass update), so a snapshot
/// restore recomputes it rather than storing it.
void tbComputeBodyExtents(const tbWorld* world, const tbBody* body, float* minExtent, float* maxExtent, float* coreExtent);
/// A shape just linked to the body without a mass update (updateBodyMass false: a chain's segments)
/// still counts in its extents, which bound how far its points move (the narrow phase's motion
/// bounds, continuous collision, sleep): they grow to take it in, about the current centre. A shape
/// removed without a mass update leaves them as they are, still bounds.
void tbAddShapeExtents(tbBody* body, const tbGeometry* geometry);
void tbWakeBody(tbWorld* world, tbBody* body);
/// Close the holes bodies that left the awake set left in it; the step starts with it.
void tbCompactAwakeSet(tbWorld* world);
void tbSleepBody(tbWorld* world, tbBody* body);
void tbDestroyBodyContacts(tbWorld* world, tbBody* body, bool wakeBodies);

/// Displacement per step that a body's speculative contacts cover (m): max(TB_SPECULATIVE_REACH,
/// safetyFactor × minExtent), the body's safety factor TB_CONTINUOUS_FRACTION by default. Beyond it
/// the body is swept by continuous collision. Kept in the body (tbUpdateSpeculativeReach); inline,
/// since the narrow phase reads it twice per contact.
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

/// The finalize stage of the step: shape boxes, proxies, sleep timers, move events. Returns how
/// many awake bodies the step carried farther than TB_MAX_POSITION from the origin.
int tbFinalizeStage(tbWorld* world, float timeStep);
/// Take every awake body beyond TB_MAX_POSITION out of the simulation (as tbBody_Disable does) and
/// report each: the step's last stage when the finalize stage found one.
void tbDisableBodiesBeyondBounds(tbWorld* world);
