// Internal: a contact as the world keeps it (a pair of shapes whose fat boxes overlap), its flags
// and recycling record, and the contact stages of the step (contact.c).
#pragma once

#include "core/core.h"

#include "tumble/collision.h"
#include "tumble/types.h"

typedef struct tbWorld tbWorld;

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
	tb_contactEnableEvents = 0x04,	///< either shape wants begin/end events
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
	/// A sensor contact whose sensor a fast shape's sweep crossed this step (continuous.c): the
	/// sensor stage counts the pair as overlapping for the step, whatever the final poses say.
	tb_contactSensorHit = 0x100,
	/// contact->apart holds the pose at which the narrow phase last found the shapes apart and how
	/// far apart they were at least: while the bodies move less than that less the margin, the
	/// narrow phase would find them apart again and is skipped (contact.c, tbStaysApart). Snapshots
	/// keep a contact's low eight flags only (snapshot.c): a restored contact runs the narrow phase
	/// again, with the same result, since keeping it apart is exact.
	tb_contactApart = 0x200,
	/// The contact's material as its solver key reads it (tbMixContactMaterials keeps them, and a
	/// snapshot's restore): tangent speed ≠ 0, restitution ≠ 0, rolling resistance > 0. They are
	/// tbContactKeyFlag's tb_keyScalarOnly, tb_keyBounces and tb_keyRolling shifted left by
	/// TB_CONTACT_MATERIAL_SHIFT, so the collide walk writes a key without loading the material.
	tb_contactTangentSpeed = 0x400,
	tb_contactBounces = 0x800,
	tb_contactRolls = 0x1000,
};

/// tbContactFlag's material bits are the solver key's material bits shifted by this much.
#define TB_CONTACT_MATERIAL_SHIFT 6

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

/// Where the narrow phase last found a pair apart (manifold empty): the relative pose then and a
/// distance the shapes were at least apart (tbShapeGapBound). Shares the bytes of tbManifoldBase:
/// a pair is touching or apart, never both.
typedef struct tbApartBase
{
	tbTransform relative; ///< pose of B's origin frame in A's, inv(xfA)·xfB
	float gap;			  ///< the shapes were at least this far apart (m)
} tbApartBase;

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
	union
	{
		tbManifoldBase base; ///< valid when flags has tb_contactRecyclable
		tbApartBase apart;	 ///< valid when flags has tb_contactApart
	};
	// The impact not yet reported as a hit event (tbReportHitEvents): its approach speed (0: none)
	// and where it happened.
	float hitSpeed;
	tbVec2 hitPoint;
	uint32_t generation; ///< bumped when the slot is freed: stale tbContactIds are refused
} tbContact;

/// Bits of a contact's solver key (tbContactKey).
typedef enum tbContactKeyFlag
{
	tb_keyMovesA = 1,	   ///< the solve can change A's velocity (awake, positive inverse mass or inertia)
	tb_keyMovesB = 2,
	tb_keyDynamicA = 4,	   ///< A is an awake dynamic body (picks the contact's softness)
	tb_keyDynamicB = 8,
	tb_keyScalarOnly = 16, ///< tangent speed: the wide blocks do not carry it
	tb_keyBounces = 32,	   ///< restitution > 0: the scalar constraint is kept for restitution
	tb_keyRolling = 64,	   ///< rolling resistance: its lane's rolling row is kept beside the block
} tbContactKeyFlag;

_Static_assert(tb_contactTangentSpeed == tb_keyScalarOnly << TB_CONTACT_MATERIAL_SHIFT &&
				   tb_contactBounces == tb_keyBounces << TB_CONTACT_MATERIAL_SHIFT &&
				   tb_contactRolls == tb_keyRolling << TB_CONTACT_MATERIAL_SHIFT,
			   "a contact's material bits are its key's, shifted");

/// The material bits of a contact's key (tb_keyScalarOnly, tb_keyBounces, tb_keyRolling).
static inline uint32_t tbContactMaterialKey(const tbContact* contact)
{
	const uint32_t material = tb_contactTangentSpeed | tb_contactBounces | tb_contactRolls;
	return (contact->flags & material) >> TB_CONTACT_MATERIAL_SHIFT;
}

/// Two body ids (contact.c's dense copy of each contact's bodies).
typedef struct tbBodyPair
{
	int bodyIdA, bodyIdB;
} tbBodyPair;

/// What the solver needs to order a contact: its two bodies' indices and tbContactKeyFlag bits. In
/// the solver (contact_solver.c) the indices are solver indices, the static stand-in for a static
/// body; in a tbCollideKey they are awake indices, TB_NULL_INDEX for a static body.
typedef struct tbContactKey
{
	int indexA, indexB;
	uint32_t flags;
} tbContactKey;

/// What the narrow phase learnt of a contact that is ready for the solver (a dynamic side, no
/// sleeping side), while it had both bodies in cache: its key with awake indices, which are the
/// solver indices of this step. Valid in the step `step` only. A dense array by contact id, so the
/// solver's key pass streams through it instead of visiting two bodies per contact.
typedef struct tbCollideKey
{
	tbContactKey key;
	uint32_t step;
} tbCollideKey;

tbContactId tbMakeContactId(const tbWorld* world, int contactId);

int tbCreateContact(tbWorld* world, int shapeIdA, int shapeIdB);
/// The contact of a sensor and a shape whose sweep crossed it this step, made if the pair has none
/// and may have one, marked tb_contactSensorHit; its id, or TB_NULL_INDEX when the pair may not
/// touch or is marked already.
int tbMarkSensorHit(tbWorld* world, int sensorShapeId, int visitorShapeId);
/// The contact's mixed friction, restitution, rolling resistance and tangent speed from its shapes
/// (and its material bits, as tbSetContactMaterialFlags).
void tbMixContactMaterials(const tbWorld* world, tbContact* contact);
/// The contact's material bits (tb_contactTangentSpeed, tb_contactBounces, tb_contactRolls) from its
/// tangent speed, restitution and rolling resistance.
void tbSetContactMaterialFlags(tbContact* contact);
void tbDestroyContact(tbWorld* world, int contactId, bool wakeBodies);
/// The base of a manifold computed with its bodies at xfA and xfB (its margin aside): the relative
/// pose, the normal in each body's frame, and each point (`points`, midway between the surfaces)
/// and separation in each body's origin frame. The recycling (contact.c) and a snapshot's restore
/// (snapshot.c) make it with this.
static inline void tbFillManifoldBase(tbManifoldBase* base, const tbManifold* m, tbWorldTransform xfA,
									  tbWorldTransform xfB, const tbPos points[2])
{
	base->relative = tbInvMulWorldTransforms(xfA, xfB);
	base->normalA = tbInvRotateVector(xfA.q, m->normal);
	base->normalB = tbInvRotateVector(xfB.q, m->normal);
	for (int i = 0; i < m->pointCount; ++i)
	{
		base->pointA[i] = tbInvTransformWorldPoint(xfA, points[i]);
		base->pointB[i] = tbInvTransformWorldPoint(xfB, points[i]);
		base->separation[i] = m->points[i].separation;
	}
}

/// A recycled manifold's points and separations moved with its bodies now at xfA and xfB, from the
/// points fixed in each body when the narrow phase computed it (its normal and anchors are kept).
/// xB − xA is taken from the origin offset and the rotated local points: no large world
/// coordinates are subtracted, so far from the origin the difference keeps its precision. The
/// recycling (contact.c) and a snapshot's restore (snapshot.c) remake the points with it.
static inline void tbMoveRecycledPoints(tbManifold* m, const tbManifoldBase* base, tbWorldTransform xfA,
										tbWorldTransform xfB)
{
	tbVec2 dp = tbSubPos(xfB.p, xfA.p);
	for (int i = 0; i < m->pointCount; ++i)
	{
		tbManifoldPoint* mp = m->points + i;
		tbVec2 rA = tbRotateVector(xfA.q, base->pointA[i]);
		tbVec2 rB = tbRotateVector(xfB.q, base->pointB[i]);
		tbVec2 gap = tbAdd(dp, tbSub(rB, rA));
		mp->separation = base->separation[i] + tbDot(gap, m->normal);
		tbPos pointA = tbOffsetPos(xfA.p, rA);
		mp->point = tbToVec2(tbOffsetPos(pointA, tbMulSV(0.5f, gap)));
	}
}

/// Narrow phase for one contact: recompute its manifold and its touching and reported flags.
/// Returns the reported flag change (begin/end events): +1 began, −1 stopped, 0 no change; sets
/// *beganTouching when the manifold gained points (the bodies must be woken).
int tbUpdateContact(tbWorld* world, tbContact* contact, bool* beganTouching);

/// The broad phase's pair filter and its prefetch hint (context: the world).
bool tbContactPairFilter(int shapeIdA, int shapeIdB, void* world);
void tbContactPairPrefetch(int shapeIdA, int shapeIdB, void* world);

/// The update-pairs stage of the step: broad-phase pairs become new contacts.
void tbUpdatePairsStage(tbWorld* world);
/// The collide stage: the narrow phase on every contact of an awake body, begin/end events.
void tbCollideStage(tbWorld* world);
/// After the solve: the impacts of the step become hit events.
void tbReportHitEvents(tbWorld* world);
/// The sensor stage: sensor contacts collided on the step's final poses, their events.
void tbSensorStage(tbWorld* world);
