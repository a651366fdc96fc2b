// Contact manifolds: one function per shape pair, closed forms for round shapes and the
// separating axis test (SAT) with face clipping for polygons.
//
// Conventions (the solver relies on them):
// - the normal n is a unit vector from A to B, in A's frame (the pair routines, Box2D v3.2's
//   local form) or in the world (tbCollideShapes, and the narrow phase's tbCollideInWorld);
// - a point's separation is the signed surface gap, radii included (< 0 is penetration);
// - the point is the point midway between the two surfaces: if qA, qB are the closest
//   points of the cores (the shapes without their radii) then
//       surfaceA = qA + rA·n,  surfaceB = qB − rB·n,  point = ½(surfaceA + surfaceB),
//       separation = (qB − qA)·n − rA − rB;
// - points are kept while separation < keep (speculative contact), so the solver can stop an
//   approach before it turns into an overlap. keep is TB_SPECULATIVE_DISTANCE for the public
//   pair routines and tbCollideShapes, and the caller's margin for tbCollideShapesWithMargin
//   and tbCollideInWorld (the world passes a velocity-dependent one, contact.c); every
//   internal routine takes it as its last argument;
// - feature ids are TB_MAKE_FEATURE_ID(featureOnA, featureOnB) and stay the same while the
//   same features touch (warm starting). Pairs with a circle have one point and id 0.
//
// Every routine works in the frame of A (B is brought into it by the relative transform
// A⁻¹·B, which the narrow phase takes in the precision of world positions); the world forms
// move the result to world space at the end. The arithmetic then sees small coordinates even
// when the bodies sit kilometres from the origin.
//
// Polygons (Gregorius, "The Separating Axis Test between convex polyhedra", GDC 2013, in 2D):
// the cores of two convex polygons are separated along some face normal of either, or they
// overlap. The face of largest separation over both polygons is the reference face; the edge
// of the other polygon most anti-parallel to its normal is the incident edge; clipping the
// incident edge against the side planes of the reference face (Sutherland–Hodgman; Catto,
// "Contact manifolds", GDC 2007) gives up to two points. A pair that is no face contact (a
// corner facing a corner across a gap, or an incident edge wholly beside the reference face)
// gets one point between the closest features of the cores, found by GJK (distance.c).
// Capsules and segments are 2-vertex polygons (with radius and without), so one SAT serves
// every pair with a straight side.
// The alternative rejected here is GJK/EPA for all pairs (manifold_gjk.c offers it for
// polygons): it gives one normal but needs the same clipping afterwards and costs more.
#include "core/core.h"
#include "distance_internal.h"
#include "manifold_internal.h"

#include "tumble/collision.h"

#include <float.h>

// The public pair routines keep a point while its separation is below this (m):
// TB_SPECULATIVE_DISTANCE = 0.02 m.
#define TB_KEEP_DISTANCE TB_SPECULATIVE_DISTANCE

// Relative tolerance of the reference face choice, 0.1 × linear slop = 0.0005 m: B's face is
// the reference only when its separation exceeds A's by more than this, so that two
// near-parallel faces (a box resting on a box, turning by 1e-4 rad) do not swap roles from
// step to step and the feature ids, hence warm starting, survive.
#define TB_REFERENCE_TOLERANCE (0.1f * TB_LINEAR_SLOP)

// Core gap (m) above which polygons are "separated": 0.1 × linear slop = 0.0005 m, Box2D v3's
// threshold. Below it the clipped face contact is exact enough; above it a corner may face a
// corner, and the face normal would misstate the gap of rounded polygons, so the closest points
// decide. It is also the shortest vector qB − qA a normal is ever taken from: each coordinate
// carries its float rounding (6e-8 m at 1 m, 5e-7 m at 8 m from A's origin), which turns a
// vector of length d by up to about that over d, 1e-3 rad at d = 5e-4 m and worse below.
#define TB_GAP_TOLERANCE (0.1f * TB_LINEAR_SLOP)

// An incident corner up to this far (m) outside a side plane of the reference face is kept
// rather than clipped: 0.1 × linear slop = 0.0005 m. Equal-width boxes stacked flush put B's
// corners exactly on A's side planes; without slack a 1e-4 rad wobble would clip a corner one
// step and keep it the next, changing its feature id and losing the warm start. A corner
// 0.5 mm beyond the face costs nothing; clipped points still lie exactly on the plane.
#define TB_CLIP_SLACK (0.1f * TB_LINEAR_SLOP)

// Two capsule axes count as parallel when |sin θ| < 0.1 (θ < 5.7°). Beyond that a 1 m overlap
// lifts its far end by more than 0.1 m, five times the speculative distance, so a second
// point would be dropped anyway; below it the clipped second point keeps the capsule flat.
#define TB_PARALLEL_SINE 0.1f

// A capsule or segment shorter than this (m), 1e-3 × linear slop, has no axis: it is a circle.
#define TB_DEGENERATE_LENGTH (0.001f * TB_LINEAR_SLOP)

// Two points of a clipped manifold closer than this (m), 1e-3 × linear slop = 5e-6 m, are one
// point, as a segment that short is a point. The clip makes such pairs: an incident corner exactly on a
// side plane with its edge running outward comes out twice, as itself and as the crossing at
// t = 0, i.e. the same spot; so do an incident edge or a reference face of (nearly) zero length.
// Coincident points make the 2×2 block of the normal solver singular. Pairs further apart, yet
// close, are left as they are: solver_ngs.c's condition test (K11² < 1000·det K, as Box2D 2.4)
// solves the first point alone when the block is ill-conditioned.
#define TB_MERGE_DISTANCE TB_DEGENERATE_LENGTH

// Feature bytes name what touches, not how the clip found it: a plain index is a vertex of
// that polygon, TB_FEATURE_EDGE | i its edge from vertex i to i + 1, and a corner-to-corner
// point of separated polygons has TB_FEATURE_VERTEX on both bytes. A clipped point is a vertex
// of one polygon on an edge of the other whichever face is the reference: an incident vertex
// kept by the side planes is (reference edge, incident vertex), a crossing of a side plane with
// the incident edge is (reference vertex, incident edge). So when two near-parallel faces swap
// roles (A's face the reference one step, B's the next: a box in a sagging pyramid turns by a
// few milliradians, enough to move the separations by more than TB_REFERENCE_TOLERANCE), each
// point keeps its id and its warm start. Ids that carried the clip's roles lost the warm start of
// every point whose faces swapped, in every step, and a large pyramid spread at its flanks with
// them (docs/methods.md). The flags are manifold_internal.h's, shared with manifold_gjk.c.

static const tbManifold tb_emptyManifold = {0};

// ---------------------------------------------------------------------------------------------
// Shared helpers

// The manifold point of core points qA, qB along n with radii rA, rB (see the file comment).
static tbManifoldPoint tbMakeManifoldPoint(tbVec2 qA, tbVec2 qB, tbVec2 n, float rA, float rB, uint16_t id)
{
	tbManifoldPoint mp = {0};
	tbVec2 surfaceA = tbMulAdd(qA, rA, n);
	tbVec2 surfaceB = tbMulSub(qB, rB, n);
	mp.point = tbLerp(surfaceA, surfaceB, 0.5f);
	mp.separation = tbDot(tbSub(qB, qA), n) - rA - rB;
	mp.id = id;
	return mp;
}

// One point between two core points (circle centres, closest points of segments), in A's frame.
// The normal is along qB − qA; when the cores touch (|qB − qA| < FLT_EPSILON) it is `fallback`,
// so coincident shapes still get a unit normal and never a NaN.
static void tbPointManifold(tbManifold* m, tbVec2 qA, float rA, tbVec2 qB, float rB, tbVec2 fallback, uint16_t id,
							float keep)
{
	*m = tb_emptyManifold;
	float distance;
	tbVec2 n = tbGetLengthAndNormalize(&distance, tbSub(qB, qA));
	if (distance - rA - rB >= keep)
	{
		return;
	}
	if (distance < FLT_EPSILON)
	{
		n = fallback;
	}
	m->normal = n;
	m->points[0] = tbMakeManifoldPoint(qA, qB, n, rA, rB, id);
	m->pointCount = 1;
}

// One point between a core point q on a face with unit normal n and a core point c of B, in
// A's frame. Unlike tbPointManifold the normal is the face's own, exact even when c is behind
// the face (then (c − q)·n < 0 and the separation says how deep).
static void tbFacePointManifold(tbManifold* m, tbVec2 q, float rA, tbVec2 c, float rB, tbVec2 n, uint16_t id,
								float keep)
{
	*m = tb_emptyManifold;
	tbManifoldPoint mp = tbMakeManifoldPoint(q, c, n, rA, rB, id);
	if (mp.separation >= keep)
	{
		return;
	}
	m->normal = n;
	m->points[0] = mp;
	m->pointCount = 1;
}

// A capsule core or a segment as a 2-vertex polygon, into *out: edge 0 runs p1 → p2 with outward
// normal n = rightPerp(p2 − p1)/|p2 − p1| and edge 1 runs back with −n. Needs |p2 − p1| > 0. Only
// the two vertices and normals, the centroid, radius and count are written: nothing reads a
// polygon past its count, and zeroing the other six slots and copying the whole polygon out cost
// more than the rest of this (a capsule meets a box through it in every step it is not recycled).
static void tbMakeSegmentPolygon(tbPolygon* out, tbVec2 p1, tbVec2 p2, float radius)
{
	tbVec2 n = tbNormalize(tbRightPerp(tbSub(p2, p1)));
	out->vertices[0] = p1;
	out->vertices[1] = p2;
	out->normals[0] = n;
	out->normals[1] = tbNeg(n);
	out->centroid = tbLerp(p1, p2, 0.5f);
	out->radius = radius;
	out->count = 2;
}

static bool tbIsDegenerateSegment(tbVec2 p1, tbVec2 p2)
{
	return tbDistanceSquared(p1, p2) < TB_DEGENERATE_LENGTH * TB_DEGENERATE_LENGTH;
}

// Polygon moved by a rigid transform into *out (vertices and normals up to its count; the slots
// beyond are not written). Written in place, field by field: a whole tbPolygon (144 bytes) copied
// and then overwritten point by point made the copy's 16-byte loads wait on the 8-byte stores
// before them (store forwarding fails), a stall on every polygon placed.
static void tbPlacePolygon(tbPolygon* out, const tbPolygon* polygon, tbTransform xf)
{
	int count = polygon->count;
	for (int i = 0; i < count; ++i)
	{
		out->vertices[i] = tbTransformPoint(xf, polygon->vertices[i]);
		out->normals[i] = tbRotateVector(xf.q, polygon->normals[i]);
	}
	out->centroid = tbTransformPoint(xf, polygon->centroid);
	out->radius = polygon->radius;
	out->count = count;
}

// ---------------------------------------------------------------------------------------------
// Circles and capsules: closed forms

static void tbCirclesFrameA(tbManifold* m, const tbCircle* circleA, const tbCircle* circleB, tbTransform xf, float keep)
{
	// Concentric circles push along A's x-axis: any unit vector is right, this one is defined.
	tbVec2 centerB = tbTransformPoint(xf, circleB->center);
	tbVec2 xAxis = {1.0f, 0.0f};
	tbPointManifold(m, circleA->center, circleA->radius, centerB, circleB->radius, xAxis, 0, keep);
}

// Capsule core a1–a2 against a point c with radius rB, in A's frame.
static void tbCapsuleAndPoint(tbManifold* m, tbVec2 a1, tbVec2 a2, float rA, tbVec2 c, float rB, float keep)
{
	// A centre on the core pushes out along the capsule's side normal (x-axis if no axis).
	tbVec2 side = tbNormalize(tbLeftPerp(tbSub(a2, a1)));
	tbVec2 fallback = tbIsDegenerateSegment(a1, a2) ? tbMakeVec2(1.0f, 0.0f) : side;
	float t;
	tbVec2 q = tbClosestPointOnSegment(&t, c, a1, a2);
	tbPointManifold(m, q, rA, c, rB, fallback, 0, keep);
}

static void tbCapsuleAndCircleFrameA(tbManifold* m, const tbCapsule* capsuleA, const tbCircle* circleB, tbTransform xf,
									 float keep)
{
	tbVec2 c = tbTransformPoint(xf, circleB->center);
	tbCapsuleAndPoint(m, capsuleA->center1, capsuleA->center2, capsuleA->radius, c, circleB->radius, keep);
}

static void tbCollidePolygonsInto(tbManifold* m, const tbPolygon* polygonA, const tbPolygon* polygonB, float keep);

// True when the capsule axes are parallel (|sin θ| < TB_PARALLEL_SINE) and B's axis projected on
// A's overlaps A's by more than the linear slop: then the contact is a side against a side.
static bool tbAxesOverlapInParallel(tbVec2 a1, tbVec2 a2, tbVec2 b1, tbVec2 b2)
{
	float lengthA, lengthB;
	tbVec2 u = tbGetLengthAndNormalize(&lengthA, tbSub(a2, a1));
	tbVec2 v = tbGetLengthAndNormalize(&lengthB, tbSub(b2, b1));
	if (tbAbsFloat(tbCross(u, v)) >= TB_PARALLEL_SINE)
	{
		return false;
	}
	float t1 = tbDot(tbSub(b1, a1), u);
	float t2 = tbDot(tbSub(b2, a1), u);
	float overlap = tbMinFloat(lengthA, tbMaxFloat(t1, t2)) - tbMaxFloat(0.0f, tbMinFloat(t1, t2));
	return overlap > TB_LINEAR_SLOP;
}

// Capsule cores a1–a2 and b1–b2 in A's frame. The closest points of the two segments
// (tbSegmentDistance, Ericson §5.1.9) give one point along the line joining them. Two cases need
// the SAT on 2-vertex polygons instead: parallel sides overlapping along the axes (the clip
// gives two points, so a capsule lying on a capsule does not rock on one point), and crossing
// cores, whose closest points coincide and define no normal.
static void tbCapsulesLocal(tbManifold* m, tbVec2 a1, tbVec2 a2, float rA, tbVec2 b1, tbVec2 b2, float rB, float keep)
{
	if (tbIsDegenerateSegment(b1, b2))
	{
		tbCapsuleAndPoint(m, a1, a2, rA, tbLerp(b1, b2, 0.5f), rB, keep);
		return;
	}
	if (tbIsDegenerateSegment(a1, a2))
	{
		// B against the point A: collide B with A and flip the normal back to A → B.
		tbCapsuleAndPoint(m, b1, b2, rB, tbLerp(a1, a2, 0.5f), rA, keep);
		m->normal = tbNeg(m->normal);
		return;
	}

	tbSegmentDistanceResult r = tbSegmentDistance(a1, a2, b1, b2);
	float reach = rA + rB + keep;
	if (r.distanceSquared >= reach * reach)
	{
		*m = tb_emptyManifold;
		return;
	}

	bool crossing = r.distanceSquared < TB_GAP_TOLERANCE * TB_GAP_TOLERANCE;
	if (crossing || tbAxesOverlapInParallel(a1, a2, b1, b2))
	{
		tbPolygon polygonA;
		tbMakeSegmentPolygon(&polygonA, a1, a2, rA);
		tbPolygon polygonB;
		tbMakeSegmentPolygon(&polygonB, b1, b2, rB);
		tbCollidePolygonsInto(m, &polygonA, &polygonB, keep);
		return;
	}

	tbVec2 side = tbNormalize(tbLeftPerp(tbSub(a2, a1)));
	tbPointManifold(m, r.closest1, rA, r.closest2, rB, side, 0, keep);
}

static void tbCapsulesFrameA(tbManifold* m, const tbCapsule* capsuleA, const tbCapsule* capsuleB, tbTransform xf,
							 float keep)
{
	tbVec2 b1 = tbTransformPoint(xf, capsuleB->center1);
	tbVec2 b2 = tbTransformPoint(xf, capsuleB->center2);
	tbCapsulesLocal(m, capsuleA->center1, capsuleA->center2, capsuleA->radius, b1, b2, capsuleB->radius, keep);
}

// ---------------------------------------------------------------------------------------------
// Polygon and circle

// Polygon A against a circle centred at c (A's frame). Inside the core (every face separation
// ≤ 0) the face of largest separation is the way out (least penetration). Outside, the closest
// point of the boundary is found over all edges (at most 8): on an edge interior the normal is
// that edge's normal, exactly; at a vertex it is along c − vertex (Ericson §5.1.2 and the
// Voronoi regions of §5.2.7, without relying on the largest face being the closest).
static void tbPolygonAndPoint(tbManifold* m, const tbPolygon* polygon, tbVec2 c, float rB, float keep)
{
	int bestFace = 0;
	float maxSeparation = -FLT_MAX;
	for (int i = 0; i < polygon->count; ++i)
	{
		float s = tbDot(polygon->normals[i], tbSub(c, polygon->vertices[i]));
		if (s > maxSeparation)
		{
			maxSeparation = s;
			bestFace = i;
		}
	}
	float rA = polygon->radius;
	tbVec2 faceNormal = polygon->normals[bestFace];
	if (maxSeparation - rA - rB >= keep)
	{
		*m = tb_emptyManifold;
		return;
	}
	if (maxSeparation <= 0.0f)
	{
		tbVec2 q = tbMulSub(c, maxSeparation, faceNormal);
		tbFacePointManifold(m, q, rA, c, rB, faceNormal, 0, keep);
		return;
	}

	float bestDistanceSquared = FLT_MAX;
	float bestT = 0.0f;
	tbVec2 bestPoint = c;
	for (int i = 0; i < polygon->count; ++i)
	{
		int j = i + 1 < polygon->count ? i + 1 : 0;
		float t;
		tbVec2 q = tbClosestPointOnSegment(&t, c, polygon->vertices[i], polygon->vertices[j]);
		float dd = tbDistanceSquared(q, c);
		if (dd < bestDistanceSquared)
		{
			bestDistanceSquared = dd;
			bestPoint = q;
			bestT = t;
			bestFace = i;
		}
	}
	faceNormal = polygon->normals[bestFace];
	if (0.0f < bestT && bestT < 1.0f)
	{
		// Edge interior: project along the face normal, no normalisation noise.
		float h = tbDot(faceNormal, tbSub(c, bestPoint));
		tbVec2 q = tbMulSub(c, h, faceNormal);
		tbFacePointManifold(m, q, rA, c, rB, faceNormal, 0, keep);
		return;
	}
	tbPointManifold(m, bestPoint, rA, c, rB, faceNormal, 0, keep);
}

static void tbPolygonAndCircleFrameA(tbManifold* m, const tbPolygon* polygonA, const tbCircle* circleB, tbTransform xf,
									 float keep)
{
	tbVec2 c = tbTransformPoint(xf, circleB->center);
	tbPolygonAndPoint(m, polygonA, c, circleB->radius, keep);
}

// ---------------------------------------------------------------------------------------------
// Polygons: separating axis test and clipping

// Largest separation of polygon2 from the face planes of polygon1 (cores, no radii):
//     s(i) = min over j of nᵢ·(v2ⱼ − v1ᵢ),   result = max over i of s(i),
// with the face i that gives it. A positive result proves the cores apart by at least that.
static float tbFindMaxSeparation(int* edgeIndex, const tbPolygon* polygon1, const tbPolygon* polygon2)
{
	int bestIndex = 0;
	float maxSeparation = -FLT_MAX;
	for (int i = 0; i < polygon1->count; ++i)
	{
		tbVec2 n = polygon1->normals[i];
		tbVec2 v1 = polygon1->vertices[i];
		float si = FLT_MAX;
		for (int j = 0; j < polygon2->count; ++j)
		{
			si = tbMinFloat(si, tbDot(n, tbSub(polygon2->vertices[j], v1)));
		}
		if (si > maxSeparation)
		{
			maxSeparation = si;
			bestIndex = i;
		}
	}
	*edgeIndex = bestIndex;
	return maxSeparation;
}

// The edge of polygon most anti-parallel to the reference normal n: argmin over j of mⱼ·n.
// It holds the support vertex of polygon along −n (the deepest one).
static int tbFindIncidentEdge(const tbPolygon* polygon, tbVec2 n)
{
	int bestIndex = 0;
	float minDot = FLT_MAX;
	for (int j = 0; j < polygon->count; ++j)
	{
		float d = tbDot(polygon->normals[j], n);
		if (d < minDot)
		{
			minDot = d;
			bestIndex = j;
		}
	}
	return bestIndex;
}

// A point of the incident edge during clipping, with its feature bytes (reference, incident).
typedef struct tbClipVertex
{
	tbVec2 v;
	uint8_t featureRef;
	uint8_t featureInc;
} tbClipVertex;

// Sutherland–Hodgman on a segment: keeps the part of in[0]–in[1] with plane·x ≤ offset. An
// endpoint within TB_CLIP_SLACK outside is kept as it is (stable ids); otherwise the crossing
// x = in0 + t·(in1 − in0), t = d0/(d0 − d1), replaces it and belongs to the reference vertex
// `refVertex` and the incident edge `incEdge`. Returns the number of points (0 to 2).
static TB_FORCE_INLINE int tbClipSegment(tbClipVertex out[2], const tbClipVertex in[2], tbVec2 plane, float offset,
										  int refVertex, int incEdge)
{
	float d0 = tbDot(plane, in[0].v) - offset;
	float d1 = tbDot(plane, in[1].v) - offset;
	bool keep0 = d0 <= TB_CLIP_SLACK;
	bool keep1 = d1 <= TB_CLIP_SLACK;
	int count = 0;
	if (keep0)
	{
		out[count++] = in[0];
	}
	if (keep1)
	{
		out[count++] = in[1];
	}
	float t = keep0 != keep1 ? d0 / (d0 - d1) : -1.0f;
	if (0.0f <= t && t <= 1.0f)
	{
		out[count].v = tbLerp(in[0].v, in[1].v, t);
		out[count].featureRef = (uint8_t)refVertex;
		out[count].featureInc = (uint8_t)(TB_FEATURE_EDGE | incEdge);
		++count;
	}
	return count;
}

// True when the closest points of the two edges are corners of both (fractions 0 or 1) and the
// incident corner lies beside the reference face, more than TB_GAP_TOLERANCE across its side
// plane: then the pair is a corner facing a corner, and clipping would cut off the very corner
// that is nearest. Parallel edges also report corner fractions (the closest pair is not unique),
// but with the two points straight across the face: those are face contacts.
// The test is on the sideways offset w, not on the corner distance sqrt(h² + w²) against the
// face separation h: that difference, about w²/(2h), lets w grow with h, and rounded shapes touch
// with h near the sum of their radii. A capsule of radius 0.25 m tilted 17° with its end 14 mm
// beside a box's corner passed as a face contact; the clip then measured the core at the side
// plane, 4.6 cm farther along the tilted axis, and said +0.026 m where the end's cap
// penetrated the corner by 0.019 m.
static bool tbIsVertexVertex(const tbPolygon* ref, const tbPolygon* inc, int refEdge, int incEdge)
{
	int refNext = refEdge + 1 < ref->count ? refEdge + 1 : 0;
	int incNext = incEdge + 1 < inc->count ? incEdge + 1 : 0;
	tbVec2 v11 = ref->vertices[refEdge], v12 = ref->vertices[refNext];
	tbSegmentDistanceResult r = tbSegmentDistance(v11, v12, inc->vertices[incEdge], inc->vertices[incNext]);
	bool endpoint1 = r.fraction1 <= 0.0f || r.fraction1 >= 1.0f;
	bool endpoint2 = r.fraction2 <= 0.0f || r.fraction2 >= 1.0f;
	// The face's unit tangent is the normal turned a quarter: n = rightPerp(t), t = leftPerp(n).
	float sideways = tbDot(tbSub(r.closest2, r.closest1), tbLeftPerp(ref->normals[refEdge]));
	return endpoint1 && endpoint2 && tbAbsFloat(sideways) > TB_GAP_TOLERANCE;
}

// Two clipped points closer than TB_MERGE_DISTANCE are one point; returns the number left (1 or
// 2), the survivor in points[0]. Ids are in (reference, incident) order, so the low byte holds
// the incident feature, an edge for a crossing. Which point survives is fixed by features, not
// by depth (depths that close swap with rounding from step to step, and the id with them): an
// incident vertex (unclipped, its id independent of the side planes) rather than a crossing,
// and points[0] when both are of the same kind. Their separations differ by at most twice
// TB_MERGE_DISTANCE.
static int tbMergeCoincidentPoints(tbManifoldPoint points[2])
{
	if (tbDistanceSquared(points[0].point, points[1].point) >= TB_MERGE_DISTANCE * TB_MERGE_DISTANCE)
	{
		return 2;
	}
	bool crossing0 = (points[0].id & TB_FEATURE_EDGE) != 0;
	bool crossing1 = (points[1].id & TB_FEATURE_EDGE) != 0;
	if (crossing0 && crossing1 == false)
	{
		points[0] = points[1];
	}
	return 1;
}

// Clips the incident edge against the two side planes of the reference face v11–v12 (tangent t):
//     −t·x ≤ −t·v11   and   t·x ≤ t·v12,
// then measures each survivor p against the face: h = n·(p − v11), core point on the face
// p − h·n, merges manifold points closer than TB_MERGE_DISTANCE and drops points with
// separation ≥ keep. Returns false, leaving m alone, when fewer than two points survive the planes: the
// incident edge lies wholly beside the face span (beyond a side plane by more than
// TB_CLIP_SLACK, or only one end inside the slack band) and this is no face contact. Not only a
// tolerance or a degenerate edge leads here: the reference face may be A's kept within
// TB_REFERENCE_TOLERANCE of B's larger separation, with a corner of A against a face of B; and
// the corner-to-corner test (tbIsVertexVertex) is skipped when the face separation is below
// TB_GAP_TOLERANCE and declines when the incident corner is within TB_GAP_TOLERANCE of the side plane.
static bool tbClipIncidentEdge(tbManifold* m, const tbPolygon* ref, const tbPolygon* inc, int refEdge, int incEdge,
							   float keep)
{
	int refNext = refEdge + 1 < ref->count ? refEdge + 1 : 0;
	int incNext = incEdge + 1 < inc->count ? incEdge + 1 : 0;
	tbVec2 v11 = ref->vertices[refEdge];
	tbVec2 v12 = ref->vertices[refNext];
	tbVec2 n = ref->normals[refEdge];
	tbVec2 t = tbNormalize(tbSub(v12, v11));

	tbClipVertex incident[2] = {
		{inc->vertices[incEdge], (uint8_t)(TB_FEATURE_EDGE | refEdge), (uint8_t)incEdge},
		{inc->vertices[incNext], (uint8_t)(TB_FEATURE_EDGE | refEdge), (uint8_t)incNext},
	};
	tbClipVertex clip1[2], clip2[2];
	int count = tbClipSegment(clip1, incident, tbNeg(t), -tbDot(t, v11), refEdge, incEdge);
	if (count == 2)
	{
		count = tbClipSegment(clip2, clip1, t, tbDot(t, v12), refNext, incEdge);
	}
	if (count < 2)
	{
		return false;
	}

	tbManifoldPoint points[2];
	for (int i = 0; i < 2; ++i)
	{
		tbVec2 p = clip2[i].v;
		tbVec2 q = tbMulSub(p, tbDot(n, tbSub(p, v11)), n);
		uint16_t id = TB_MAKE_FEATURE_ID(clip2[i].featureRef, clip2[i].featureInc);
		points[i] = tbMakeManifoldPoint(q, p, n, ref->radius, inc->radius, id);
	}
	count = tbMergeCoincidentPoints(points);

	*m = tb_emptyManifold;
	m->normal = n;
	for (int i = 0; i < count; ++i)
	{
		if (points[i].separation < keep)
		{
			m->points[m->pointCount++] = points[i];
		}
	}
	return true;
}

// Face contact with `ref`'s face refEdge as reference (normal from ref to inc) into m.
// coreSeparation is the SAT separation of the cores along that face. Returns false when the pair
// is no face contact: a corner faces a corner across a gap (the true gap is the corner distance,
// larger than the face separation, and rounded polygons need it to place their round corners
// right), or the incident edge misses the face span (tbClipIncidentEdge).
static bool tbReferenceFaceManifold(tbManifold* m, const tbPolygon* ref, const tbPolygon* inc, int refEdge,
									float coreSeparation, float keep)
{
	int incEdge = tbFindIncidentEdge(inc, ref->normals[refEdge]);
	if (coreSeparation > TB_GAP_TOLERANCE && tbIsVertexVertex(ref, inc, refEdge, incEdge))
	{
		return false;
	}
	return tbClipIncidentEdge(m, ref, inc, refEdge, incEdge, keep);
}

// Swaps the bytes of a feature id: (featureOnA, featureOnB) → (featureOnB, featureOnA).
static uint16_t tbSwapFeatureId(uint16_t id)
{
	return (uint16_t)((id >> 8) | (id << 8));
}

// A manifold computed with B as the first polygon, turned to A → B: normal negated, feature
// bytes swapped.
static void tbFlipManifoldInPlace(tbManifold* m)
{
	m->normal = tbNeg(m->normal);
	for (int i = 0; i < m->pointCount; ++i)
	{
		m->points[i].id = tbSwapFeatureId(m->points[i].id);
	}
}


// One point on ref's face refEdge (normal n from ref to inc) at inc's deepest vertex p along −n:
// h = n·(p − v11), core point on the face p − h·n, id as an unclipped vertex of the clip.
static void tbDeepestVertexManifold(tbManifold* m, const tbPolygon* ref, const tbPolygon* inc, int refEdge, float keep)
{
	tbVec2 n = ref->normals[refEdge];
	tbVec2 v11 = ref->vertices[refEdge];
	int deepest = 0;
	float h = FLT_MAX;
	for (int j = 0; j < inc->count; ++j)
	{
		float hj = tbDot(n, tbSub(inc->vertices[j], v11));
		if (hj < h)
		{
			h = hj;
			deepest = j;
		}
	}
	tbVec2 p = inc->vertices[deepest];
	uint16_t id = TB_MAKE_FEATURE_ID(TB_FEATURE_EDGE | refEdge, deepest);
	tbFacePointManifold(m, tbMulSub(p, h, n), ref->radius, p, inc->radius, n, id, keep);
}

// One point between the closest features of the cores, for a pair that is no face contact: a
// corner faces a corner across a gap, or the incident edge misses the reference face span.
// The reference edge and the incident edge need not hold the closest features (the reference
// face may be A's kept by TB_REFERENCE_TOLERANCE while a corner of A faces a face of B, or the
// nearest corner of the incident polygon may be on its next edge), so they come from GJK on the
// cores (tbLocalShapeDistance, both polygons in A's frame). With d the core distance and s the
// largest SAT separation over the faces of both polygons, n that face's normal (A → B):
// - overlapping cores (GJK ends on a triangle): there are no closest points; n is the least
//   penetration and the other polygon's deepest vertex along it gives the point, at depth s, as
//   an unclipped vertex of the clip would;
// - d ≥ TB_GAP_TOLERANCE: GJK's normal, the edge's perpendicular for a vertex against an edge
//   (exact: it comes from the edge, not from qB − qA) and (qB − qA)/d for two vertices;
// - d < TB_GAP_TOLERANCE: the normal is n. For two vertices qB − qA is too short to give a
//   direction (see TB_GAP_TOLERANCE: 1.4e-3 rad of rounding for boxes of 3 m to 4 m at
//   d = 1.1e-4 m); Box2D v3 also keeps the face normal below 0.1 × linear slop. For a vertex
//   against an edge that edge is the face of largest separation (its separation is d, and none
//   exceeds d), so n is its normal, exact, and with its sign known (GJK's edge perpendicular
//   takes its sign from qB − qA). The separation (qB − qA)·n lies between s and d: the face's
//   own polygon lies behind the face line and the other at least s in front of it, so any two
//   of their points are at least s apart along n, and |qB − qA| = d.
// Ids: TB_FEATURE_VERTEX on both bytes, each naming its polygon's vertex of largest barycentric
// weight in GJK's final simplex (the nearest vertex), the same on both sides of the
// TB_GAP_TOLERANCE boundary so that warm starting carries over.
static void tbClosestFeaturesManifold(tbManifold* m, const tbPolygon* polygonA, const tbPolygon* polygonB, int edgeA,
									  float separationA, int edgeB, float separationB, float keep)
{
	bool faceOfB = separationB > separationA;
	tbShapeProxy proxyA = tbMakeValidProxy(polygonA->vertices, polygonA->count, 0.0f);
	tbShapeProxy proxyB = tbMakeValidProxy(polygonB->vertices, polygonB->count, 0.0f);
	tbSimplex simplex;
	tbDistanceOutput closest = tbLocalShapeDistance(&proxyA, &proxyB, NULL, &simplex);

	if (closest.simplexCount == 3)
	{
		if (faceOfB)
		{
			tbDeepestVertexManifold(m, polygonB, polygonA, edgeB, keep);
			tbFlipManifoldInPlace(m);
			return;
		}
		tbDeepestVertexManifold(m, polygonA, polygonB, edgeA, keep);
		return;
	}

	const tbSimplexVertex* nearest = &simplex.v1;
	if (simplex.count == 2 && simplex.v2.a > simplex.v1.a)
	{
		nearest = &simplex.v2;
	}
	uint16_t id = TB_MAKE_FEATURE_ID(TB_FEATURE_VERTEX | nearest->indexA, TB_FEATURE_VERTEX | nearest->indexB);
	tbVec2 n = faceOfB ? tbNeg(polygonB->normals[edgeB]) : polygonA->normals[edgeA];
	tbVec2 normal = closest.distance >= TB_GAP_TOLERANCE ? closest.normal : n;
	tbFacePointManifold(m, closest.pointA, polygonA->radius, closest.pointB, polygonB->radius, normal, id, keep);
}

// SAT of two polygons, both in A's frame, into *m. The reference face is A's unless B's separation
// is larger by TB_REFERENCE_TOLERANCE; with B as reference the normal and the feature bytes are
// flipped. A pair that is no face contact on the reference face gets the closest features of
// the cores instead (tbClosestFeaturesManifold).
// Written through a pointer all the way from the narrow phase (tbCollideInWorld): a manifold
// returned by value was built on the stack and copied out with 16-byte loads right after its 4- and
// 8-byte stores, which cannot forward, a stall per copy (three copies between here and the contact).
static void tbCollidePolygonsInto(tbManifold* m, const tbPolygon* polygonA, const tbPolygon* polygonB, float keep)
{
	int edgeA, edgeB;
	float separationA = tbFindMaxSeparation(&edgeA, polygonA, polygonB);
	float separationB = tbFindMaxSeparation(&edgeB, polygonB, polygonA);
	float radius = polygonA->radius + polygonB->radius;
	if (tbMaxFloat(separationA, separationB) - radius >= keep)
	{
		*m = tb_emptyManifold;
		return;
	}
	if (separationB <= separationA + TB_REFERENCE_TOLERANCE)
	{
		if (tbReferenceFaceManifold(m, polygonA, polygonB, edgeA, separationA, keep))
		{
			return;
		}
	}
	else if (tbReferenceFaceManifold(m, polygonB, polygonA, edgeB, separationB, keep))
	{
		tbFlipManifoldInPlace(m);
		return;
	}
	tbClosestFeaturesManifold(m, polygonA, polygonB, edgeA, separationA, edgeB, separationB, keep);
}

static void tbPolygonsInto(tbManifold* m, const tbPolygon* polygonA, const tbPolygon* polygonB, tbTransform xf,
						   float keep)
{
	tbPolygon localB;
	tbPlacePolygon(&localB, polygonB, xf);
	tbCollidePolygonsInto(m, polygonA, &localB, keep);
}

static void tbPolygonAndCapsuleFrameA(tbManifold* m, const tbPolygon* polygonA, const tbCapsule* capsuleB,
									  tbTransform xf, float keep)
{
	tbVec2 b1 = tbTransformPoint(xf, capsuleB->center1);
	tbVec2 b2 = tbTransformPoint(xf, capsuleB->center2);
	if (tbIsDegenerateSegment(b1, b2))
	{
		tbPolygonAndPoint(m, polygonA, tbLerp(b1, b2, 0.5f), capsuleB->radius, keep);
		return;
	}
	tbPolygon polygonB;
	tbMakeSegmentPolygon(&polygonB, b1, b2, capsuleB->radius);
	tbCollidePolygonsInto(m, polygonA, &polygonB, keep);
}

// ---------------------------------------------------------------------------------------------
// Segments: a segment is a capsule of radius zero, i.e. a 2-vertex polygon without radius

static void tbSegmentAndCircleFrameA(tbManifold* m, const tbSegment* segmentA, const tbCircle* circleB, tbTransform xf,
									 float keep)
{
	tbCapsule capsuleA = {segmentA->point1, segmentA->point2, 0.0f};
	tbCapsuleAndCircleFrameA(m, &capsuleA, circleB, xf, keep);
}

static void tbSegmentAndCapsuleFrameA(tbManifold* m, const tbSegment* segmentA, const tbCapsule* capsuleB,
									  tbTransform xf, float keep)
{
	tbCapsule capsuleA = {segmentA->point1, segmentA->point2, 0.0f};
	tbCapsulesFrameA(m, &capsuleA, capsuleB, xf, keep);
}

static void tbSegmentAndPolygonFrameA(tbManifold* m, const tbSegment* segmentA, const tbPolygon* polygonB,
									  tbTransform xf, float keep)
{
	tbPolygon localB;
	tbPlacePolygon(&localB, polygonB, xf);
	if (tbIsDegenerateSegment(segmentA->point1, segmentA->point2))
	{
		// A point against B: collide B with it and turn the normal back to A → B.
		tbPolygonAndPoint(m, &localB, tbLerp(segmentA->point1, segmentA->point2, 0.5f), 0.0f, keep);
		m->normal = tbNeg(m->normal);
		return;
	}
	tbPolygon polygonA;
	tbMakeSegmentPolygon(&polygonA, segmentA->point1, segmentA->point2, 0.0f);
	tbCollidePolygonsInto(m, &polygonA, &localB, keep);
}

// ---------------------------------------------------------------------------------------------
// Chain segments: one-sided, smooth across joints
//
// A shape sliding along a chain must not feel the joints. Collided alone, the segment ahead
// offers its end point as a corner, and a box whose bottom sags by the contact slop meets that
// corner with a normal tilted back against its motion: a bump. The ghost vertices (the chain's
// neighbouring points) say what each joint is. At a straight or concave joint no normal other
// than the face's belongs to the segment: the neighbour's face covers the rest, so a tilted
// normal is replaced by the face normal and the points are clipped to the segment's span. At a
// convex joint (the surface turns away from the solid side, a hill top) the corner is real and
// its normals are shared out: this segment takes those up to the bisector of its normal and the
// neighbour's, the neighbour the rest, so the corner is reported once. The segment is one-sided:
// a shape whose centre is behind it (on the solid side) gets nothing, so a shape can pass up
// through a floor. Same idea as Box2D's ghost vertices (Catto, "Ghost vertices", 2010 blog note).

/// A chain segment's frame in A's frame: unit direction e, normal n = rightPerp(e), and for each
/// end whether the joint is convex and the bisector normal there.
typedef struct tbChainFrame
{
	tbVec2 v1, v2, e, n;
	bool convex1, convex2;
	float split1, split2; ///< e·(bisector) at each end: the last normal this segment owns
} tbChainFrame;

/// Turn (sine of the angle) above which a joint counts as convex: about 0.6°.
#define TB_CHAIN_CONVEX_SINE 0.01f

static tbChainFrame tbMakeChainFrame(const tbChainSegment* chain)
{
	tbChainFrame f;
	f.v1 = chain->segment.point1;
	f.v2 = chain->segment.point2;
	f.e = tbNormalize(tbSub(f.v2, f.v1));
	f.n = tbRightPerp(f.e);
	tbVec2 e0 = tbNormalize(tbSub(f.v1, chain->ghost1));
	tbVec2 e2 = tbNormalize(tbSub(chain->ghost2, f.v2));
	// Convex where the path turns left, towards the solid side: cross(e_before, e_after) > 0.
	f.convex1 = tbCross(e0, f.e) > TB_CHAIN_CONVEX_SINE;
	f.convex2 = tbCross(f.e, e2) > TB_CHAIN_CONVEX_SINE;
	f.split1 = tbDot(tbNormalize(tbAdd(tbRightPerp(e0), f.n)), f.e);
	f.split2 = tbDot(tbNormalize(tbAdd(f.n, tbRightPerp(e2))), f.e);
	return f;
}

typedef enum tbChainRegion
{
	tb_chainFace,	  ///< the normal belongs to this segment as it is
	tb_chainFlatten,  ///< a tilted normal at a straight or concave joint: use the face normal
	tb_chainNeighbour ///< past the bisector of a convex joint: the neighbour reports it
} tbChainRegion;

static tbChainRegion tbClassifyChainNormal(const tbChainFrame* f, tbVec2 normal)
{
	float along = tbDot(normal, f->e);
	if (tbDot(normal, f->n) <= 0.0f)
	{
		return tb_chainFlatten; // deep: the two-sided test chose the back face
	}
	if (tbAbsFloat(along) <= 1e-4f)
	{
		return tb_chainFace;
	}
	bool atEnd = along > 0.0f;
	if ((atEnd ? f->convex2 : f->convex1) == false)
	{
		return tb_chainFlatten;
	}
	bool beyond = atEnd ? along > f->split2 : along < f->split1;
	return beyond ? tb_chainNeighbour : tb_chainFace;
}

/// Face contact of the segment (reference) with polygon B (incident), points clipped to the span.
static void tbChainFaceManifold(tbManifold* m, const tbPolygon* segment, const tbPolygon* localB, float keep)
{
	*m = tb_emptyManifold;
	int incEdge = tbFindIncidentEdge(localB, segment->normals[0]);
	tbClipIncidentEdge(m, segment, localB, 0, incEdge, keep); // leaves m empty when it fails
}

static void tbChainAndPolygonLocal(tbManifold* m, const tbChainSegment* chain, const tbPolygon* localB, float keep)
{
	tbChainFrame f = tbMakeChainFrame(chain);
	if (tbDot(tbSub(localB->centroid, f.v1), f.n) < 0.0f)
	{
		*m = tb_emptyManifold;
		return;
	}
	tbPolygon segment;
	tbMakeSegmentPolygon(&segment, f.v1, f.v2, 0.0f);
	tbCollidePolygonsInto(m, &segment, localB, keep);
	if (m->pointCount == 0)
	{
		return;
	}
	switch (tbClassifyChainNormal(&f, m->normal))
	{
		case tb_chainFace:
			return;
		case tb_chainFlatten:
			tbChainFaceManifold(m, &segment, localB, keep);
			return;
		default:
			*m = tb_emptyManifold;
			return;
	}
}

static void tbChainAndPointLocal(tbManifold* m, const tbChainSegment* chain, tbVec2 c, float radius, float keep)
{
	tbChainFrame f = tbMakeChainFrame(chain);
	if (tbDot(tbSub(c, f.v1), f.n) < 0.0f)
	{
		*m = tb_emptyManifold;
		return;
	}
	float t = tbDot(tbSub(c, f.v1), f.e);
	float length = tbDot(tbSub(f.v2, f.v1), f.e);
	if (0.0f <= t && t <= length)
	{
		tbFacePointManifold(m, tbMulAdd(f.v1, t, f.e), 0.0f, c, radius, f.n, TB_MAKE_FEATURE_ID(0, 0), keep);
		return;
	}
	tbVec2 corner = t < 0.0f ? f.v1 : f.v2;
	tbVec2 normal = tbNormalize(tbSub(c, corner));
	if (tbClassifyChainNormal(&f, normal) != tb_chainFace)
	{
		*m = tb_emptyManifold; // past a straight or concave joint, or a convex one's bisector
		return;
	}
	uint16_t id = TB_MAKE_FEATURE_ID(TB_FEATURE_VERTEX | (t < 0.0f ? 0 : 1), 0);
	tbPointManifold(m, corner, 0.0f, c, radius, f.n, id, keep);
}

static void tbChainSegmentAndCircleFrameA(tbManifold* m, const tbChainSegment* segmentA, const tbCircle* circleB,
										  tbTransform xf, float keep)
{
	tbVec2 c = tbTransformPoint(xf, circleB->center);
	tbChainAndPointLocal(m, segmentA, c, circleB->radius, keep);
}

static void tbChainSegmentAndCapsuleFrameA(tbManifold* m, const tbChainSegment* segmentA, const tbCapsule* capsuleB,
										   tbTransform xf, float keep)
{
	tbVec2 b1 = tbTransformPoint(xf, capsuleB->center1);
	tbVec2 b2 = tbTransformPoint(xf, capsuleB->center2);
	if (tbIsDegenerateSegment(b1, b2))
	{
		tbChainAndPointLocal(m, segmentA, tbLerp(b1, b2, 0.5f), capsuleB->radius, keep);
		return;
	}
	tbPolygon polygonB;
	tbMakeSegmentPolygon(&polygonB, b1, b2, capsuleB->radius);
	tbChainAndPolygonLocal(m, segmentA, &polygonB, keep);
}

static void tbChainSegmentAndPolygonFrameA(tbManifold* m, const tbChainSegment* segmentA, const tbPolygon* polygonB,
										   tbTransform xf, float keep)
{
	tbPolygon localB;
	tbPlacePolygon(&localB, polygonB, xf);
	tbChainAndPolygonLocal(m, segmentA, &localB, keep);
}

// ---------------------------------------------------------------------------------------------
// Dispatch

// Role of a shape kind as the first argument of a pair routine: the routines take A as the
// shape with the larger rank (segment > polygon > capsule > circle), e.g. tbCollidePolygonAndCircle.
static int tbDispatchRank(tbShapeType type)
{
	switch (type)
	{
		case tb_circleShape:
			return 0;
		case tb_capsuleShape:
			return 1;
		case tb_polygonShape:
			return 2;
		case tb_segmentShape:
			return 3;
		case tb_chainSegmentShape:
			return 4;
		default:
			return -1;
	}
}

// Pair in routine order, rank(A) ≥ rank(B); B placed in A's frame by xf = A⁻¹·B; the manifold in
// A's frame, into *m. Every routine writes through the pointer (see tbCollidePolygonsInto for why).
void tbCollideOrderedInto(tbManifold* m, const tbGeometry* a, const tbGeometry* b, tbTransform xf,
						  tbNarrowPhaseMethod method, float keep)
{
	switch (a->type)
	{
		case tb_circleShape:
			tbCirclesFrameA(m, &a->circle, &b->circle, xf, keep);
			return;
		case tb_capsuleShape:
			if (b->type == tb_circleShape)
			{
				tbCapsuleAndCircleFrameA(m, &a->capsule, &b->circle, xf, keep);
			}
			else
			{
				tbCapsulesFrameA(m, &a->capsule, &b->capsule, xf, keep);
			}
			return;
		case tb_polygonShape:
			if (b->type == tb_circleShape)
			{
				tbPolygonAndCircleFrameA(m, &a->polygon, &b->circle, xf, keep);
			}
			else if (b->type == tb_capsuleShape)
			{
				tbPolygonAndCapsuleFrameA(m, &a->polygon, &b->capsule, xf, keep);
			}
			else if (method == tb_narrowPhaseGJK)
			{
				*m = tbPolygonsGJKFrameA(&a->polygon, &b->polygon, xf, keep);
			}
			else
			{
				tbPolygonsInto(m, &a->polygon, &b->polygon, xf, keep);
			}
			return;
		case tb_segmentShape:
			if (b->type == tb_circleShape)
			{
				tbSegmentAndCircleFrameA(m, &a->segment, &b->circle, xf, keep);
			}
			else if (b->type == tb_capsuleShape)
			{
				tbSegmentAndCapsuleFrameA(m, &a->segment, &b->capsule, xf, keep);
			}
			else if (b->type == tb_polygonShape)
			{
				tbSegmentAndPolygonFrameA(m, &a->segment, &b->polygon, xf, keep);
			}
			else
			{
				*m = tb_emptyManifold; // two segments have no area: no contact
			}
			return;
		case tb_chainSegmentShape:
			if (b->type == tb_circleShape)
			{
				tbChainSegmentAndCircleFrameA(m, &a->chainSegment, &b->circle, xf, keep);
			}
			else if (b->type == tb_capsuleShape)
			{
				tbChainSegmentAndCapsuleFrameA(m, &a->chainSegment, &b->capsule, xf, keep);
			}
			else if (b->type == tb_polygonShape)
			{
				tbChainSegmentAndPolygonFrameA(m, &a->chainSegment, &b->polygon, xf, keep);
			}
			else
			{
				*m = tb_emptyManifold; // segments against segments: no area, no contact
			}
			return;
		default:
			*m = tb_emptyManifold;
			return;
	}
}

tbManifold tbSwapManifoldRoles(tbManifold m)
{
	m.normal = tbNeg(m.normal);
	for (int i = 0; i < m.pointCount; ++i)
	{
		m.points[i].id = tbSwapFeatureId(m.points[i].id);
	}
	return m;
}

void tbCollideInWorld(tbManifold* m, const tbGeometry* a, tbWorldTransform xfA, const tbGeometry* b,
					  tbWorldTransform xfB, tbNarrowPhaseMethod method, float keep, tbPos points[2])
{
	bool ordered = tbDispatchRank(a->type) >= tbDispatchRank(b->type);
	tbWorldTransform frame = ordered ? xfA : xfB;
	if (ordered)
	{
		tbCollideOrderedInto(m, a, b, tbInvMulWorldTransforms(xfA, xfB), method, keep);
	}
	else
	{
		tbCollideOrderedInto(m, b, a, tbInvMulWorldTransforms(xfB, xfA), method, keep);
	}
	m->normal = tbRotateVector(frame.q, m->normal);
	for (int i = 0; i < m->pointCount; ++i)
	{
		points[i] = tbTransformWorldPoint(frame, m->points[i].point);
		m->points[i].point = tbToVec2(points[i]);
	}
	if (ordered == false)
	{
		tbFlipManifoldInPlace(m); // the normal turned to A → B, the feature bytes swapped
	}
}

tbManifold tbCollideShapesWithMargin(const tbGeometry* shapeA, tbTransform xfA, const tbGeometry* shapeB,
									 tbTransform xfB, tbNarrowPhaseMethod method, float speculativeDistance)
{
	const char* f = "tbCollideShapesWithMargin";
	int rankA = tbDispatchRank(shapeA->type);
	int rankB = tbDispatchRank(shapeB->type);
	if (rankA < 0 || rankB < 0)
	{
		tbReportError(f, "unknown shape type %d or %d; use a tbShapeType value.", (int)shapeA->type,
					  (int)shapeB->type);
		return tb_emptyManifold;
	}
	if (tbIsValidFloat(speculativeDistance) == false)
	{
		tbReportError(f, "speculativeDistance is %g (must be finite); TB_SPECULATIVE_DISTANCE is the default",
					  (double)speculativeDistance);
		return tb_emptyManifold;
	}
	float keep = speculativeDistance;
	if (rankA >= rankB)
	{
		tbManifold m;
	tbCollideOrderedInto(&m, shapeA, shapeB, tbInvMulTransforms(xfA, xfB), method, keep);
		return tbManifoldToWorld(m, xfA);
	}

	// B → A in routine order, then the normal turned to A → B and the feature bytes swapped so
	// the first byte still names a feature of A. Points and separations do not depend on order.
	tbManifold m;
	tbCollideOrderedInto(&m, shapeB, shapeA, tbInvMulTransforms(xfB, xfA), method, keep);
	return tbSwapManifoldRoles(tbManifoldToWorld(m, xfB));
}

tbManifold tbCollideShapes(const tbGeometry* shapeA, tbTransform xfA, const tbGeometry* shapeB, tbTransform xfB,
						   tbNarrowPhaseMethod method)
{
	int rankA = tbDispatchRank(shapeA->type);
	int rankB = tbDispatchRank(shapeB->type);
	if (rankA < 0 || rankB < 0)
	{
		// Same message and function name as before the margin variant existed.
		tbReportError("tbCollideShapes", "unknown shape type %d or %d; use a tbShapeType value.",
					  (int)shapeA->type, (int)shapeB->type);
		return tb_emptyManifold;
	}
	return tbCollideShapesWithMargin(shapeA, xfA, shapeB, xfB, method, TB_SPECULATIVE_DISTANCE);
}

// ---------------------------------------------------------------------------------------------
// Public pair routines, Box2D v3.2's local form: B placed in A's frame by xf = A⁻¹·B, the
// manifold in A's frame, points kept while closer than TB_SPECULATIVE_DISTANCE.

tbLocalManifold tbMakeLocalManifold(const tbManifold* m)
{
	tbLocalManifold local = {0};
	local.normal = m->normal;
	local.pointCount = m->pointCount;
	for (int i = 0; i < m->pointCount; ++i)
	{
		local.points[i].point = m->points[i].point;
		local.points[i].separation = m->points[i].separation;
		local.points[i].id = m->points[i].id;
	}
	return local;
}

tbLocalManifold tbCollideCircles(const tbCircle* circleA, const tbCircle* circleB, tbTransform xf)
{
	tbManifold m;
	tbCirclesFrameA(&m, circleA, circleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollideCapsuleAndCircle(const tbCapsule* capsuleA, const tbCircle* circleB, tbTransform xf)
{
	tbManifold m;
	tbCapsuleAndCircleFrameA(&m, capsuleA, circleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollideSegmentAndCircle(const tbSegment* segmentA, const tbCircle* circleB, tbTransform xf)
{
	tbManifold m;
	tbSegmentAndCircleFrameA(&m, segmentA, circleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollidePolygonAndCircle(const tbPolygon* polygonA, const tbCircle* circleB, tbTransform xf)
{
	tbManifold m;
	tbPolygonAndCircleFrameA(&m, polygonA, circleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollideCapsules(const tbCapsule* capsuleA, const tbCapsule* capsuleB, tbTransform xf)
{
	tbManifold m;
	tbCapsulesFrameA(&m, capsuleA, capsuleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollideSegmentAndCapsule(const tbSegment* segmentA, const tbCapsule* capsuleB, tbTransform xf)
{
	tbManifold m;
	tbSegmentAndCapsuleFrameA(&m, segmentA, capsuleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollidePolygonAndCapsule(const tbPolygon* polygonA, const tbCapsule* capsuleB, tbTransform xf)
{
	tbManifold m;
	tbPolygonAndCapsuleFrameA(&m, polygonA, capsuleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollidePolygons(const tbPolygon* polygonA, const tbPolygon* polygonB, tbTransform xf)
{
	tbManifold m;
	tbPolygonsInto(&m, polygonA, polygonB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollideSegmentAndPolygon(const tbSegment* segmentA, const tbPolygon* polygonB, tbTransform xf)
{
	tbManifold m;
	tbSegmentAndPolygonFrameA(&m, segmentA, polygonB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollideChainSegmentAndCircle(const tbChainSegment* segmentA, const tbCircle* circleB, tbTransform xf)
{
	tbManifold m;
	tbChainSegmentAndCircleFrameA(&m, segmentA, circleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

// The simplex cache of Box2D v3's signature is accepted and left as it is: Tumble's chain
// routines use the separating axis test, which has no simplex to carry between steps.
tbLocalManifold tbCollideChainSegmentAndCapsule(const tbChainSegment* segmentA, const tbCapsule* capsuleB,
												tbTransform xf, tbSimplexCache* cache)
{
	(void)cache;
	tbManifold m;
	tbChainSegmentAndCapsuleFrameA(&m, segmentA, capsuleB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbLocalManifold tbCollideChainSegmentAndPolygon(const tbChainSegment* segmentA, const tbPolygon* polygonB,
												tbTransform xf, tbSimplexCache* cache)
{
	(void)cache;
	tbManifold m;
	tbChainSegmentAndPolygonFrameA(&m, segmentA, polygonB, xf, TB_KEEP_DISTANCE);
	return tbMakeLocalManifold(&m);
}
