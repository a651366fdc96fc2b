// Tumble: the stateless collision layer. Every function here works on shapes and transforms
// alone, without a world: geometry and mass, hulls, ray casts, GJK distance and EPA
// penetration, shape casts, contact manifolds (closed forms, SAT, GJK/EPA), time of impact
// (quadratic for circles, conservative advancement for any convex pair), and the dynamic AABB
// tree as a stand-alone structure.
#pragma once

#include "base.h"
#include "constants.h"
#include "math_functions.h"

#ifdef __cplusplus
extern "C" {
#endif

// ---------------------------------------------------------------------------------------------
// Shapes

/// Solid circle.
typedef struct tbCircle
{
	tbVec2 center;
	float radius;
} tbCircle;

/// Solid capsule: the points within `radius` of the segment center1–center2.
typedef struct tbCapsule
{
	tbVec2 center1, center2;
	float radius;
} tbCapsule;

/// Solid convex polygon, counter-clockwise, with an optional rounding radius (the polygon is
/// the core polygon inflated by radius). Make with tbMakePolygon / tbMakeBox; do not fill by hand.
typedef struct tbPolygon
{
	tbVec2 vertices[TB_MAX_POLYGON_VERTICES];
	tbVec2 normals[TB_MAX_POLYGON_VERTICES];
	tbVec2 centroid;
	float radius;
	int count;
} tbPolygon;

/// Line segment (two-sided, no thickness).
typedef struct tbSegment
{
	tbVec2 point1, point2;
} tbSegment;

/// One segment of a chain (tbCreateChain): one-sided, solid on the left of point1 → point2 (the
/// normal is the right perpendicular), with the neighbouring chain points as ghost vertices so
/// that a shape sliding across the joint between two segments meets no corner.
/// ghost1 → segment.point1 → segment.point2 → ghost2.
typedef struct tbChainSegment
{
	tbVec2 ghost1;
	tbSegment segment;
	tbVec2 ghost2;
	int chainId; ///< the owning chain's index (internal), or −1
} tbChainSegment;

/// Convex hull of a point cloud, counter-clockwise, from tbComputeHull.
typedef struct tbHull
{
	tbVec2 points[TB_MAX_POLYGON_VERTICES];
	int count;
} tbHull;

/// Mass, centre of mass (local) and rotational inertia about the centre of mass.
typedef struct tbMassData
{
	float mass;
	tbVec2 center;
	float rotationalInertia;
} tbMassData;

/// Shape kinds.
typedef enum tbShapeType
{
	tb_circleShape,
	tb_capsuleShape,
	tb_segmentShape,
	tb_polygonShape,
	tb_chainSegmentShape, ///< made by tbCreateChain
	tb_shapeTypeCount
} tbShapeType;

/// Any shape, as a tagged union. Lets stateless routines (AABB, ray cast, manifold dispatch,
/// scene files) take a shape without knowing its kind at compile time.
typedef struct tbGeometry
{
	tbShapeType type;
	union
	{
		tbCircle circle;
		tbCapsule capsule;
		tbSegment segment;
		tbPolygon polygon;
		tbChainSegment chainSegment;
	};
} tbGeometry;

// ---------------------------------------------------------------------------------------------
// Geometry helpers (geometry.c, hull.c)

/// Convex hull by quickhull. Returns count 0 when the points cannot make a polygon: fewer than 3,
/// more than TB_MAX_POLYGON_VERTICES, non-finite, or all (nearly) duplicate or collinear
/// (within TB_LINEAR_SLOP). Points closer than TB_LINEAR_SLOP are welded.
TB_API tbHull tbComputeHull(const tbVec2* points, int count);

/// True if the hull is convex, counter-clockwise, without duplicate or collinear points.
TB_API bool tbValidateHull(const tbHull* hull);

/// Polygon from a valid hull with a rounding radius ≥ 0.
TB_API tbPolygon tbMakePolygon(const tbHull* hull, float radius);

/// Cut a simple polygon (3 to TB_MAX_DECOMPOSE_POINTS points, either winding, no edge crossing
/// another, no duplicate points, non-zero area) into convex pieces of at most
/// TB_MAX_POLYGON_VERTICES vertices that cover it exactly: ear clipping, then Hertel–Mehlhorn
/// merging (at most four times the fewest pieces possible). Writes at most `capacity` pieces (count − 2
/// always suffices) and returns how many; 0 and an error naming the problem for bad input, or when
/// capacity is too small. Make them shapes of one body to get a concave body.
TB_API int tbDecomposePolygon(const tbVec2* points, int count, tbPolygon* pieces, int capacity);

/// Polygon from a hull, offset by a local transform.
TB_API tbPolygon tbMakeOffsetPolygon(const tbHull* hull, tbVec2 position, tbRot rotation);

/// Rounded polygon (radius ≥ 0) from a hull, offset by a local transform: the hull's points moved
/// by (position, rotation), then inflated by radius.
TB_API tbPolygon tbMakeOffsetRoundedPolygon(const tbHull* hull, tbVec2 position, tbRot rotation, float radius);

/// Square with half-width h.
TB_API tbPolygon tbMakeSquare(float halfWidth);

/// Box with half-widths hx, hy, centred on the body origin.
TB_API tbPolygon tbMakeBox(float halfWidth, float halfHeight);

/// Box with rounded corners: core half-widths plus radius.
TB_API tbPolygon tbMakeRoundedBox(float halfWidth, float halfHeight, float radius);

/// Box offset by a local position and rotation.
TB_API tbPolygon tbMakeOffsetBox(float halfWidth, float halfHeight, tbVec2 center, tbRot rotation);

/// Rounded box (core half-widths plus radius ≥ 0) offset by a local position and rotation.
TB_API tbPolygon tbMakeOffsetRoundedBox(float halfWidth, float halfHeight, tbVec2 center, tbRot rotation, float radius);

/// Polygon transformed by a rigid transform.
TB_API tbPolygon tbTransformPolygon(tbTransform transform, const tbPolygon* polygon);

/// Mass properties for a density in kg/m².
TB_API tbMassData tbComputeCircleMass(const tbCircle* shape, float density);
TB_API tbMassData tbComputeCapsuleMass(const tbCapsule* shape, float density);
TB_API tbMassData tbComputePolygonMass(const tbPolygon* shape, float density);

/// World-space bounding boxes. In the large-world build (TUMBLE_DOUBLE_PRECISION) each box is
/// found about the shape's position and moved out in double, rounded outwards: it contains the
/// shape however far from the origin.
TB_API tbAABB tbComputeCircleAABB(const tbCircle* shape, tbWorldTransform transform);
TB_API tbAABB tbComputeCapsuleAABB(const tbCapsule* shape, tbWorldTransform transform);
TB_API tbAABB tbComputePolygonAABB(const tbPolygon* shape, tbWorldTransform transform);
TB_API tbAABB tbComputeSegmentAABB(const tbSegment* shape, tbWorldTransform transform);
TB_API tbAABB tbComputeShapeAABB(const tbGeometry* shape, tbWorldTransform transform);

/// Mass of any solid shape (segments have no mass).
TB_API tbMassData tbComputeShapeMass(const tbGeometry* shape, float density);

/// Point-in-shape tests, point in the shape's local frame.
TB_API bool tbPointInCircle(const tbCircle* shape, tbVec2 point);
TB_API bool tbPointInCapsule(const tbCapsule* shape, tbVec2 point);
TB_API bool tbPointInPolygon(const tbPolygon* shape, tbVec2 point);
TB_API bool tbPointInShape(const tbGeometry* shape, tbVec2 point);

/// Ray cast input: the ray is origin + t·translation for t in [0, maxFraction].
typedef struct tbRayCastInput
{
	tbVec2 origin;
	tbVec2 translation;
	float maxFraction;
} tbRayCastInput;

/// True when a ray cast would take the input: origin and translation finite, maxFraction finite
/// with 0 ≤ maxFraction < TB_HUGE. A predicate: reports nothing (a NULL input is refused through
/// the error hook and is not valid).
TB_API bool tbIsValidRay(const tbRayCastInput* input);

/// Result of a ray or shape cast.
typedef struct tbCastOutput
{
	tbVec2 normal;	 ///< surface normal at the hit
	tbVec2 point;	 ///< hit point
	float fraction;	 ///< fraction of the translation at the hit
	int iterations;	 ///< iterations used (shape casts)
	bool hit;
} tbCastOutput;

#if defined(TUMBLE_DOUBLE_PRECISION)
/// A cast against the world's shapes (tbShape_RayCast): its hit point a world position.
typedef struct tbWorldCastOutput
{
	tbVec2 normal;	///< surface normal at the hit point
	tbPos point;	///< hit point, a world position
	float fraction; ///< fraction of the translation at the hit
	int iterations; ///< iterations used (GJK-based casts)
	bool hit;
} tbWorldCastOutput;
#else
/// A cast against the world's shapes (tbShape_RayCast): its hit point a world position.
typedef tbCastOutput tbWorldCastOutput;
#endif

/// Ray casts in the shape's local frame. A ray starting inside a solid shape does not hit it.
TB_API tbCastOutput tbRayCastCircle(const tbCircle* shape, const tbRayCastInput* input);
TB_API tbCastOutput tbRayCastCapsule(const tbCapsule* shape, const tbRayCastInput* input);
TB_API tbCastOutput tbRayCastSegment(const tbSegment* shape, const tbRayCastInput* input, bool oneSided);
TB_API tbCastOutput tbRayCastPolygon(const tbPolygon* shape, const tbRayCastInput* input);
TB_API tbCastOutput tbRayCastShape(const tbGeometry* shape, const tbRayCastInput* input);

// ---------------------------------------------------------------------------------------------
// Distance (distance.c: GJK) and penetration (epa.c: EPA)

/// Convex point cloud with a radius: what GJK sees of a shape.
typedef struct tbShapeProxy
{
	tbVec2 points[TB_MAX_POLYGON_VERTICES];
	int count;
	float radius;
} tbShapeProxy;

/// Proxy of count points (1..TB_MAX_POLYGON_VERTICES, finite, within TB_MAX_COORDINATE) and a
/// radius (0..TB_MAX_COORDINATE). Anything else is reported to the error hook and gives an empty
/// proxy (count 0), which the distance, separation, cast and TOI functions refuse in turn.
TB_API tbShapeProxy tbMakeProxy(const tbVec2* points, int count, float radius);

/// Proxy of any shape (circle: 1 point; capsule and segment: 2; polygon: its vertices).
TB_API tbShapeProxy tbMakeShapeProxy(const tbGeometry* shape);

/// Proxy of count points moved by a rigid transform (position, rotation), with a radius: the same
/// checks as tbMakeProxy on the points, the radius and the transform (finite position, unit
/// rotation); a refused input gives an empty proxy.
TB_API tbShapeProxy tbMakeOffsetProxy(const tbVec2* points, int count, float radius, tbVec2 position, tbRot rotation);

/// Warm-start cache for GJK: the support indices of the last simplex. Zero-initialise for a cold start.
typedef struct tbSimplexCache
{
	uint16_t count;
	uint8_t indexA[3];
	uint8_t indexB[3];
} tbSimplexCache;

/// Input to GJK (Box2D v3.2's form): shape B placed in shape A's frame, so the answer does not
/// depend on where the pair is in the world; the outputs are in A's frame.
typedef struct tbDistanceInput
{
	tbShapeProxy proxyA;
	tbShapeProxy proxyB;
	tbTransform transform; ///< B in A's frame: tbInvMulTransforms(transformA, transformB)
	bool useRadii;		   ///< subtract the radii (surface to surface) instead of core to core
} tbDistanceInput;

/// Output of GJK, in A's frame.
typedef struct tbDistanceOutput
{
	tbVec2 pointA;	   ///< closest point on A
	tbVec2 pointB;	   ///< closest point on B
	tbVec2 normal;	   ///< unit vector from A to B (zero when the cores overlap)
	float distance;	   ///< ≥ 0; zero when overlapping
	int iterations;	   ///< GJK iterations
	int simplexCount;  ///< vertices in the final simplex (3 means the cores overlap)
} tbDistanceOutput;

/// Vertex of the Minkowski difference B − A, with its support indices.
typedef struct tbSimplexVertex
{
	tbVec2 wA;	   ///< support point on A (A's frame)
	tbVec2 wB;	   ///< support point on B (A's frame)
	tbVec2 w;	   ///< wB − wA
	float a;	   ///< barycentric coordinate of the closest point
	int indexA;	   ///< index of wA in proxyA
	int indexB;	   ///< index of wB in proxyB
} tbSimplexVertex;

/// GJK's simplex (1 to 3 vertices).
typedef struct tbSimplex
{
	tbSimplexVertex v1, v2, v3;
	int count;
} tbSimplex;

/// GJK distance (van den Bergen, "Collision Detection in Interactive 3D Environments", §4.3;
/// Ericson, "Real-Time Collision Detection", §9.5), in A's frame. `cache` may be NULL; when given
/// it warm-starts this call and receives the final simplex. `simplexes` may be NULL; with a
/// capacity of 1 or more, simplexes[0] receives the final simplex (Box2D v3 records one per
/// iteration there, for debugging; Tumble keeps the final one, what EPA starts from).
TB_API tbDistanceOutput tbShapeDistance(const tbDistanceInput* input, tbSimplexCache* cache, tbSimplex* simplexes,
										int simplexCapacity);

/// Closest points between two segments p1–q1 and p2–q2 (Ericson §5.1.9).
typedef struct tbSegmentDistanceResult
{
	tbVec2 closest1, closest2;
	float fraction1, fraction2;
	float distanceSquared;
} tbSegmentDistanceResult;

TB_API tbSegmentDistanceResult tbSegmentDistance(tbVec2 p1, tbVec2 q1, tbVec2 p2, tbVec2 q2);

/// Signed separation of two convex shapes (radii included), in A's frame.
typedef struct tbSeparationOutput
{
	tbVec2 normal;	   ///< unit vector from A to B; always defined (never NaN), even for coincident shapes
	tbVec2 pointA;	   ///< deepest/closest point on A's surface
	tbVec2 pointB;	   ///< deepest/closest point on B's surface
	float separation;  ///< > 0 apart, < 0 penetrating (depth = −separation)
	int iterations;	   ///< GJK plus EPA iterations
	bool usedEPA;	   ///< true when the cores overlapped and EPA gave the answer
} tbSeparationOutput;

/// Separation by GJK when the cores are apart, else by EPA (expanding polytope; van den Bergen
/// 2001) from GJK's final simplex, with a tolerance and iteration cap.
TB_API tbSeparationOutput tbShapeSeparation(const tbDistanceInput* input, tbSimplexCache* cache);

/// Input of a shape cast (Box2D v3.2's form): B placed and moving in A's frame; the output point
/// and normal are in A's frame.
typedef struct tbShapeCastPairInput
{
	tbShapeProxy proxyA;
	tbShapeProxy proxyB;
	tbTransform transform; ///< B in A's frame: tbInvMulTransforms(transformA, transformB)
	tbVec2 translationB;   ///< B's motion, in A's frame
	float maxFraction;
	bool canEncroach;  ///< allow the final separation to be less than the radii (for speculative use)
} tbShapeCastPairInput;

/// Shape cast by conservative advancement on GJK distance (linear motion only). Shapes that
/// already touch or overlap at the start (within the target separation) report a hit at
/// fraction 0 with normal (0, 0) — there is no direction of first contact — and the point halfway
/// between the surfaces; this holds for a zero translation too (Box2D v3 answers the same). Apart
/// shapes that never close in (zero translation included) report no hit. A proxy with no points
/// is refused through the error hook (no hit).
TB_API tbCastOutput tbShapeCast(const tbShapeCastPairInput* input);

/// Input of a shape cast against one shape (Box2D v3.2's b2ShapeCastInput): a proxy moving by
/// translation, in the shape's frame.
typedef struct tbShapeCastInput
{
	tbShapeProxy proxy;	  ///< the moving shape, in the fixed shape's frame
	tbVec2 translation;	  ///< its motion
	float maxFraction;	  ///< of the translation, typically 1
	bool canEncroach;	  ///< allow the final separation to be less than the radii (as tbShapeCastPairInput)
} tbShapeCastInput;

/// A proxy swept against one shape in that shape's frame: tbShapeCast with the shape as proxy A at
/// the identity, so the output point and normal are in the shape's frame. Refused through the error
/// hook (no hit): a NULL pointer, a shape point that is not finite or beyond TB_MAX_COORDINATE, a
/// negative radius, a polygon count outside 3..TB_MAX_POLYGON_VERTICES, an empty proxy, a
/// non-finite translation, a maxFraction that is not finite and ≥ 0.
TB_API tbCastOutput tbShapeCastCircle(const tbCircle* shape, const tbShapeCastInput* input);
TB_API tbCastOutput tbShapeCastCapsule(const tbCapsule* shape, const tbShapeCastInput* input);
TB_API tbCastOutput tbShapeCastSegment(const tbSegment* shape, const tbShapeCastInput* input);
TB_API tbCastOutput tbShapeCastPolygon(const tbPolygon* shape, const tbShapeCastInput* input);

// ---------------------------------------------------------------------------------------------
// Character movers (mover.c), Box2D v3.2's kit for characters moved by the game, not by forces:
// collect the planes the mover's capsule touches (tbCollideMover, tbWorld_CollideMover), find the
// largest motion toward the target those planes allow (tbSolvePlanes), sweep it (tbWorld_CastMover)
// and keep the velocity out of the planes (tbClipVector).

/// A plane the mover touches: its outward normal (from the shape to the mover) and offset, so that
/// moving the mover by δ leaves dot(normal, δ) − offset of separation (negative: still overlapping).
typedef struct tbPlaneResult
{
	tbPlane plane;
	tbVec2 point; ///< closest point on the shape
	bool hit;	  ///< false: the shape is beyond the mover's reach; ignore the plane
} tbPlaneResult;

/// A plane for tbSolvePlanes, usually from a tbPlaneResult.
typedef struct tbCollisionPlane
{
	tbPlane plane;
	float pushLimit;   ///< m, largest push this plane may give (FLT_MAX: rigid; less: a soft plane)
	float push;		   ///< m, the push tbSolvePlanes found (output)
	bool clipVelocity; ///< whether tbClipVector removes velocity into this plane (false for soft planes)
} tbCollisionPlane;

typedef struct tbPlaneSolverResult
{
	tbVec2 delta;		///< the motion the planes allow
	int iterationCount; ///< diagnostics
} tbPlaneSolverResult;

/// The planes a capsule mover touches against one shape (shape placed by transform; the mover in
/// the same frame). Every kind of shape; a chain segment acts as a two-sided segment.
TB_API tbPlaneResult tbCollideMover(const tbCapsule* mover, const tbGeometry* shape, tbTransform transform);

/// The motion closest to targetDelta that leaves the mover outside every plane (within the linear
/// slop), each plane pushing at most its pushLimit: projected Gauss–Seidel on the pushes, at most
/// 20 sweeps. Writes each plane's push.
TB_API tbPlaneSolverResult tbSolvePlanes(tbVec2 targetDelta, tbCollisionPlane* planes, int count);

/// The vector without its components into the planes that pushed (push > 0) and clip velocity.
TB_API tbVec2 tbClipVector(tbVec2 vector, const tbCollisionPlane* planes, int count);

// ---------------------------------------------------------------------------------------------
// Contact manifolds (manifold.c: closed forms and SAT; manifold_gjk.c: GJK/EPA path)

/// Feature id of a manifold point: stays the same while the same features touch (warm starting).
#define TB_MAKE_FEATURE_ID(A, B) ((uint16_t)((uint8_t)(A) << 8 | (uint8_t)(B)))

/// A contact point.
typedef struct tbManifoldPoint
{
	tbVec2 point;			///< world point, midway between the two surfaces
	tbVec2 anchorA;			///< point relative to body A's centre of mass (filled by the world)
	tbVec2 anchorB;			///< point relative to body B's centre of mass (filled by the world)
	float separation;		///< > 0 speculative gap, < 0 penetration (m)
	float normalImpulse;	///< normal impulse (N·s) accumulated over the last sub-step, carried across steps
	float tangentImpulse;	///< accumulated friction impulse (N·s); with central friction (the default) the
							///< contact's one friction impulse, shared by the points in proportion to
							///< their normal impulses
	float totalNormalImpulse; ///< N·s, all the normal impulse the step applied (Box2D v3.2's): warm starts,
							  ///< sub-step and relaxing changes and restitution summed over the sub-steps; 0
							  ///< for a speculative point that never pushed. A resting body's points sum
							  ///< to about its weight × the step's Δt
	float normalVelocity;	///< relative normal velocity before the solve (m/s, < 0 approaching)
	float baseSeparation;	///< m, the separation when the narrow phase last computed this point; kept
							///< while the manifold is recycled (then `separation` is moved with the bodies)
	uint16_t id;			///< feature id
	bool persisted;			///< true if matched to a point of the previous step
} tbManifoldPoint;

/// Contact manifold between two shapes: a normal from A to B and up to two points.
typedef struct tbManifold
{
	tbVec2 normal;
	float rollingImpulse; ///< N·m·s, rolling resistance's angular impulse of the last sub-step (solver)
	tbManifoldPoint points[2];
	int pointCount;
} tbManifold;

/// Contact point in the frame of shape A (Box2D v3.2's local manifold point).
typedef struct tbLocalManifoldPoint
{
	tbVec2 point;	  ///< midway between the two surfaces, in A's frame
	float separation; ///< > 0 speculative gap, < 0 penetration (m)
	uint16_t id;	  ///< feature id, the same while the same features touch
} tbLocalManifoldPoint;

/// Contact manifold in the frame of shape A: a normal from A to B and up to two points.
typedef struct tbLocalManifold
{
	tbVec2 normal;
	tbLocalManifoldPoint points[2];
	int pointCount;
} tbLocalManifold;

/// Pair routines in Box2D v3.2's form: shape A in its own frame, shape B placed in it by the
/// relative transform xf = A⁻¹·B (tbInvMulTransforms(xfA, xfB), or tbInvMulWorldTransforms of
/// two world transforms), the manifold in A's frame. Closed forms for round shapes, SAT and
/// clipping for straight sides. Points are kept while separation < TB_SPECULATIVE_DISTANCE.
/// The normal points from A to B. tbCollideShapes is the world-frame form for any pair.
TB_API tbLocalManifold tbCollideCircles(const tbCircle* circleA, const tbCircle* circleB, tbTransform xf);
TB_API tbLocalManifold tbCollideCapsuleAndCircle(const tbCapsule* capsuleA, const tbCircle* circleB, tbTransform xf);
TB_API tbLocalManifold tbCollideSegmentAndCircle(const tbSegment* segmentA, const tbCircle* circleB, tbTransform xf);
TB_API tbLocalManifold tbCollidePolygonAndCircle(const tbPolygon* polygonA, const tbCircle* circleB, tbTransform xf);
TB_API tbLocalManifold tbCollideCapsules(const tbCapsule* capsuleA, const tbCapsule* capsuleB, tbTransform xf);
TB_API tbLocalManifold tbCollideSegmentAndCapsule(const tbSegment* segmentA, const tbCapsule* capsuleB, tbTransform xf);
TB_API tbLocalManifold tbCollidePolygonAndCapsule(const tbPolygon* polygonA, const tbCapsule* capsuleB, tbTransform xf);
TB_API tbLocalManifold tbCollidePolygons(const tbPolygon* polygonA, const tbPolygon* polygonB, tbTransform xf);
TB_API tbLocalManifold tbCollideSegmentAndPolygon(const tbSegment* segmentA, const tbPolygon* polygonB, tbTransform xf);

/// Chain segment against a shape: one-sided (nothing when B's centre is behind the segment) and
/// smooth (normals at a joint to a straight or concave neighbour are the face normal; at a convex
/// joint, each segment takes the normals up to the bisector of its and its neighbour's normals).
/// The simplex cache of Box2D v3.2's signature may be NULL; it is not read or written (the
/// chain routines use the SAT, which carries nothing between steps).
TB_API tbLocalManifold tbCollideChainSegmentAndCircle(const tbChainSegment* segmentA, const tbCircle* circleB,
													  tbTransform xf);
TB_API tbLocalManifold tbCollideChainSegmentAndCapsule(const tbChainSegment* segmentA, const tbCapsule* capsuleB,
													   tbTransform xf, tbSimplexCache* cache);
TB_API tbLocalManifold tbCollideChainSegmentAndPolygon(const tbChainSegment* segmentA, const tbPolygon* polygonB,
													   tbTransform xf, tbSimplexCache* cache);

/// Polygon pair by GJK/EPA (Tumble's alternative to tbCollidePolygons, same form): normal and
/// depth from tbShapeSeparation, points by clipping the incident edge against the reference face
/// chosen along that normal.
TB_API tbLocalManifold tbCollidePolygonsGJK(const tbPolygon* polygonA, const tbPolygon* polygonB, tbTransform xf);

/// Narrow-phase polygon method.
typedef enum tbNarrowPhaseMethod
{
	tb_narrowPhaseAuto,	 ///< closed forms, SAT for polygons (the cheapest accurate choice)
	tb_narrowPhaseSAT,	 ///< separating axis test with face clipping
	tb_narrowPhaseGJK,	 ///< GJK/EPA normal and depth, then clipping
} tbNarrowPhaseMethod;

/// Manifold for any pair of shapes, in either order: the routine for the pair is called with the
/// shapes swapped when needed and the normal flipped, so the normal always points from A to B.
/// Segment–segment pairs never touch (segments are for static geometry).
TB_API tbManifold tbCollideShapes(const tbGeometry* shapeA, tbTransform xfA, const tbGeometry* shapeB, tbTransform xfB,
								  tbNarrowPhaseMethod method);

/// tbCollideShapes with a caller's speculative distance (m): points are kept while their
/// separation is below speculativeDistance instead of TB_SPECULATIVE_DISTANCE (tbCollideShapes
/// is this function with TB_SPECULATIVE_DISTANCE). The world passes a margin that grows with
/// the pair's approach speed, so that a body closing more than 0.02 m in a step still gets
/// points before it reaches the other shape. A larger margin only adds points with positive
/// separation; the points of a smaller margin are unchanged.
TB_API tbManifold tbCollideShapesWithMargin(const tbGeometry* shapeA, tbTransform xfA, const tbGeometry* shapeB,
											tbTransform xfB, tbNarrowPhaseMethod method, float speculativeDistance);

// ---------------------------------------------------------------------------------------------
// Time of impact (toi_quadratic.c, toi_conservative.c)

/// Motion of a body over a step: centre of mass moves c1 → c2, rotation q1 → q2 (linearly in angle).
typedef struct tbSweep
{
	tbVec2 localCenter;	 ///< centre of mass in the body frame
	tbVec2 c1, c2;		 ///< world centre of mass at start and end
	tbRot q1, q2;		 ///< rotation at start and end
} tbSweep;

/// Body transform at time t ∈ [0, 1] of the sweep.
TB_API tbTransform tbGetSweepTransform(const tbSweep* sweep, float time);

typedef enum tbTOIState
{
	tb_toiStateUnknown,
	tb_toiStateFailed,	   ///< iteration cap reached; fraction is the last safe time
	tb_toiStateOverlapped, ///< already within the target at t = 0
	tb_toiStateHit,		   ///< reached the target separation at `fraction`
	tb_toiStateSeparated   ///< never reached the target before maxFraction
} tbTOIState;

typedef struct tbTOIInput
{
	tbShapeProxy proxyA;
	tbShapeProxy proxyB;
	tbSweep sweepA;
	tbSweep sweepB;
	float maxFraction; ///< sweep interval [0, maxFraction]
} tbTOIInput;

typedef struct tbTOIOutput
{
	tbTOIState state;
	float fraction;	 ///< time of impact as a fraction of the sweep, in [0, maxFraction]
	int iterations;
	tbVec2 normal;	 ///< contact normal from A to B at the time of impact
	tbVec2 point;	 ///< contact point at the time of impact
} tbTOIOutput;

/// Conservative advancement (Mirtich 1996; Coumans, "Continuous collision detection and physics",
/// 2005) for any convex pair with linear and angular motion, stopping when the surfaces are
/// TB_TOI_TARGET_SEPARATION apart.
TB_API tbTOIOutput tbTimeOfImpact(const tbTOIInput* input);

/// The same, stopping at a chosen surface separation (≥ 0; 0 for exact contact). Tumble's
/// addition: Box2D v3's input has no target, so it is an argument here, not a field.
TB_API tbTOIOutput tbTimeOfImpactToTarget(const tbTOIInput* input, float targetSeparation);

/// Two circles in linear motion: the earliest root of |Δp + Δv·t| = rA + rB + target, t in
/// [0, maxFraction], in closed form. Circle centres are local to their bodies; the circles must
/// sit on their bodies' centres of mass or the sweeps must not rotate (the motion is then linear).
TB_API tbTOIOutput tbTimeOfImpactCircles(const tbCircle* circleA, const tbSweep* sweepA, const tbCircle* circleB,
										 const tbSweep* sweepB, float maxFraction, float targetSeparation);

// ---------------------------------------------------------------------------------------------
// Dynamic AABB tree (dynamic_tree.c)

#define TB_NULL_NODE (-1)

/// The two children of an internal tree node.
typedef struct tbTreeNodeChildren
{
	int child1;
	int child2;
} tbTreeNodeChildren;

/// A node of the dynamic tree. Internal to the tree (public so that a tree can be held by value);
/// 40 bytes, so that a query's walk touches few cache lines.
typedef struct tbTreeNode
{
	tbAABB aabb;		   ///< fat box of a leaf; the union of the children's for an internal node
	uint64_t categoryBits; ///< a leaf's category bits; the OR of the children's for an internal node
	union
	{
		tbTreeNodeChildren children; ///< internal node
		uint64_t userData;			 ///< leaf: the payload returned to queries
	};
	union
	{
		int32_t parent; ///< node in use: its parent (TB_NULL_NODE at the root)
		int32_t next;	///< free node: the next free node
	};
	uint16_t height; ///< 0 for a leaf, 1 + the greater child's height for an internal node
	uint16_t flags;	 ///< in use, leaf, grown in place since the last rebuild (dynamic_tree.c)
} tbTreeNode;

/// How tbDynamicTree_Rebuild splits a set of leaves in two, on the longer axis of their centres.
typedef enum tbTreeSplit
{
	/// At the plane between 16 centroid bins that minimises N·perimeter summed over both sides
	/// (binned surface-area heuristic): the better tree for queries. The default.
	tb_splitBinnedSah,
	/// At the middle of the centres' extent: one pass per level against the SAH's three, so a
	/// faster build for slightly looser nodes and slower queries; for a tree rebuilt every step
	/// (the broad phase's tree of moving proxies).
	tb_splitMidpoint,
} tbTreeSplit;

/// Bounding-volume hierarchy of fat AABBs, balanced by rotations; insertion by the surface-area
/// heuristic (branch and bound over the sibling candidates). Usable on its own.
typedef struct tbDynamicTree
{
	struct tbTreeNode* nodes;
	int32_t root;
	int32_t nodeCount;
	int32_t nodeCapacity;
	int32_t freeList;
	int32_t proxyCount;
	// The rebuild's items (leaves or kept subtrees) in parallel arrays, rebuildCapacity long.
	int32_t* leafIndices; ///< an item's node
	tbAABB* leafBoxes;	  ///< an item's box
	tbVec2* leafCenters;  ///< the centre of an item's box
	int32_t* binIndices;  ///< an item's bin in the binned SAH split
	int32_t rebuildCapacity;
	tbTreeSplit rebuildSplit; ///< how tbDynamicTree_Rebuild splits; tb_splitBinnedSah from Create
} tbDynamicTree;

/// Work done by a query: internal nodes and leaves visited.
typedef struct tbTreeStats
{
	int nodeVisits;
	int leafVisits;
} tbTreeStats;

/// A tree with room for proxyCapacity proxies before it allocates (0: allocate on first insert).
TB_API tbDynamicTree tbDynamicTree_Create(int proxyCapacity);
TB_API void tbDynamicTree_Destroy(tbDynamicTree* tree);

/// Insert a proxy; returns its id (stable until destroyed). userData is returned by queries.
TB_API int tbDynamicTree_CreateProxy(tbDynamicTree* tree, tbAABB aabb, uint64_t categoryBits, uint64_t userData);
TB_API void tbDynamicTree_DestroyProxy(tbDynamicTree* tree, int proxyId);

/// Re-insert a proxy with a new box.
TB_API void tbDynamicTree_MoveProxy(tbDynamicTree* tree, int proxyId, tbAABB aabb);

/// Grow a proxy's box in place (refitting ancestors), without re-inserting; the proxy is placed
/// anew by the next tbDynamicTree_Rebuild, partial or full, or by tbDynamicTree_MoveProxy.
TB_API void tbDynamicTree_EnlargeProxy(tbDynamicTree* tree, int proxyId, tbAABB aabb);

/// A proxy's category bits (queries see them at once: the ancestors' unions are recomputed).
TB_API void tbDynamicTree_SetCategoryBits(tbDynamicTree* tree, int proxyId, uint64_t categoryBits);

/// Query callback: return false to stop.
typedef bool tbTreeQueryCallbackFcn(int proxyId, uint64_t userData, void* context);

/// Visit every proxy whose box overlaps aabb and whose category bits share a bit with maskBits.
TB_API tbTreeStats tbDynamicTree_Query(const tbDynamicTree* tree, tbAABB aabb, uint64_t maskBits,
									   tbTreeQueryCallbackFcn* callback, void* context);

/// Visit every proxy whose box overlaps aabb, whatever its category bits.
TB_API tbTreeStats tbDynamicTree_QueryAll(const tbDynamicTree* tree, tbAABB aabb, tbTreeQueryCallbackFcn* callback,
										  void* context);

/// Ray cast callback: return the new max fraction (0 stops, the input's maxFraction ignores
/// this proxy, a smaller value clips the ray).
typedef float tbTreeRayCastCallbackFcn(const tbRayCastInput* input, int proxyId, uint64_t userData, void* context);

TB_API tbTreeStats tbDynamicTree_RayCast(const tbDynamicTree* tree, const tbRayCastInput* input, uint64_t maskBits,
										 tbTreeRayCastCallbackFcn* callback, void* context);

/// A box swept along translation, up to maxFraction of it.
typedef struct tbBoxCastInput
{
	tbAABB box;
	tbVec2 translation;
	float maxFraction;
} tbBoxCastInput;

/// Box cast callback: as the ray cast's.
typedef float tbTreeBoxCastCallbackFcn(const tbBoxCastInput* input, int proxyId, uint64_t userData, void* context);

/// Visit the proxies whose boxes the swept box may touch, nearest-first clipping as the ray cast.
TB_API tbTreeStats tbDynamicTree_BoxCast(const tbDynamicTree* tree, const tbBoxCastInput* input, uint64_t maskBits,
										 tbTreeBoxCastCallbackFcn* callback, void* context);

/// Height of the tree (a single leaf has height 0).
TB_API int tbDynamicTree_GetHeight(const tbDynamicTree* tree);

/// Sum of internal node perimeters over the root perimeter (a quality measure).
TB_API float tbDynamicTree_GetAreaRatio(const tbDynamicTree* tree);

/// Check parent links, child boxes inside parents, stored heights and counts. True when valid.
TB_API bool tbDynamicTree_Validate(const tbDynamicTree* tree);
/// Validate, and no proxy grown in place is waiting for a rebuild. True when both hold.
TB_API bool tbDynamicTree_ValidateNoEnlarged(const tbDynamicTree* tree);
/// Box of the whole tree (an empty box at the origin when it has no proxy).
TB_API tbAABB tbDynamicTree_GetRootBounds(const tbDynamicTree* tree);
TB_API int tbDynamicTree_GetProxyCount(const tbDynamicTree* tree);
/// Bytes the tree holds (nodes and rebuild scratch).
TB_API int tbDynamicTree_GetByteCount(const tbDynamicTree* tree);

/// Rebuild the tree top-down, splitting by tree->rebuildSplit: all of it when fullBuild, else
/// only above the subtrees that hold no proxy grown by tbDynamicTree_EnlargeProxy since the last
/// rebuild (those are kept whole). Returns the number of leaves and kept subtrees it placed.
TB_API int tbDynamicTree_Rebuild(tbDynamicTree* tree, bool fullBuild);

TB_API uint64_t tbDynamicTree_GetUserData(const tbDynamicTree* tree, int proxyId);
TB_API tbAABB tbDynamicTree_GetAABB(const tbDynamicTree* tree, int proxyId);
TB_API uint64_t tbDynamicTree_GetCategoryBits(tbDynamicTree* tree, int proxyId);

/// Node boxes for debug drawing: calls fcn for every node with its depth.
typedef void tbTreeNodeFcn(tbAABB aabb, int depth, bool isLeaf, void* context);
TB_API void tbDynamicTree_VisitNodes(const tbDynamicTree* tree, tbTreeNodeFcn* fcn, void* context);

#ifdef __cplusplus
}
#endif
