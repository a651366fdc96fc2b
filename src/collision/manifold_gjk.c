// Tumble: polygon contact manifold by GJK/EPA (the alternative to the SAT in manifold.c, behind
// the same signature and output conventions).
//
// 1. tbShapeSeparation (distance.c, epa.c) gives the normal n from A to B and the separation s
//    (radii included). GJK answers when the cores are apart, EPA when they overlap. EPA's normal
//    is always the normal of an edge of the Minkowski difference, i.e. a face normal of A or of
//    −B; GJK's is a face normal too unless a corner faces a corner across a gap.
// 2. Reference face: the face of A most aligned with n (max nA·n) and the face of B most aligned
//    with −n. Of the two, the one whose SAT separation along its own normal,
//        sF = min over vertices v of the other polygon of nF·(v − vF),
//    is larger is the reference, preferring A unless B's is larger by TB_GJK_REFERENCE_TOLERANCE:
//    the choice must not flicker between two nearly parallel faces (box resting on box), or the
//    feature ids and the warm start would be lost.
// 3. Corner facing corner across a gap: the cores are apart (s + rA + rB above
//    TB_GJK_CORNER_TOLERANCE) and the gap between them runs beside the reference face, its offset
//    along the face above TB_GJK_CORNER_TOLERANCE (manifold.c's tbIsVertexVertex, the same rule);
//    the manifold is then the single pair of GJK witness points with GJK's normal (a face normal
//    would misstate a rounded gap).
// 4. Otherwise the incident edge is the edge of the other polygon most anti-parallel to the
//    reference normal nR; its two ends are clipped to the slab between the side planes of the
//    reference face (Sutherland–Hodgman in one dimension: along the face tangent t the face is
//    [0, L] and the incident edge is the interval [a, b], each end more than TB_GJK_CLIP_SLACK
//    outside moved onto the plane it crosses). A surviving point p has core separation h = nR·(p − v1); its separation is
//    h − rA − rB, and its world point is midway between the surfaces:
//        point = p + ½(rR − rI − h)·nR.
//    Points are kept while the separation is below the keep distance: TB_SPECULATIVE_DISTANCE
//    for tbCollidePolygonsGJK, the caller's margin for tbPolygonsGJKFrameA.
// Feature ids: the point at the reference face's first end is (first vertex of the face, the
// incident vertex on that side) and likewise at the second end, whether or not it was clipped:
// the same corners and edges touching keep the same ids. Bytes are (vertex of A, vertex of B),
// the same pair whichever face is the reference, so a point keeps its id (and its warm start)
// when two near-parallel faces swap roles; corner–corner points carry TB_FEATURE_VERTEX on
// both bytes (manifold_internal.h, as manifold.c's), so they never share an id with a clipped point.
// Everything is computed in A's frame, where the result stays (Box2D v3.2's local manifold);
// callers move it to the world (precision far from the origin). anchorA and anchorB are left
// zero for the world to fill.

#include "core/core.h"
#include "manifold_internal.h"

#include "tumble/collision.h"

#include <float.h>

// Reference face hysteresis, 0.1 × linear slop = 0.0005 m (same reasoning as manifold.c): B's
// face wins only when its separation beats A's by more than this.
#define TB_GJK_REFERENCE_TOLERANCE (0.1f * TB_LINEAR_SLOP)

// Corner–corner threshold, 0.1 × linear slop = 0.0005 m: a GJK gap between cores that far
// apart and offset that far along the reference face is a corner facing a corner, not a face
// contact.
#define TB_GJK_CORNER_TOLERANCE (0.1f * TB_LINEAR_SLOP)

// Clip slack, 0.1 × linear slop = 0.0005 m: an incident corner this close outside a side plane
// is kept as it is, not clipped. It is the convention of manifold.c's SAT (flush stacked boxes
// keep their corners while wobbling by 1e-4 rad), adopted here so that the two interchangeable
// paths give the same points and can be compared and swapped point for point.
#define TB_GJK_CLIP_SLACK (0.1f * TB_LINEAR_SLOP)


// Face of polygon whose normal is most aligned with direction.
static int tbMostAlignedFace(const tbPolygon* polygon, tbVec2 direction)
{
	int best = 0;
	float bestDot = -FLT_MAX;
	for (int i = 0; i < polygon->count; ++i)
	{
		float d = tbDot(polygon->normals[i], direction);
		if (d > bestDot)
		{
			best = i;
			bestDot = d;
		}
	}
	return best;
}

// SAT separation of `other` from face `face` of polygon: min over v of n·(v − v_face).
static float tbFaceSeparation(const tbPolygon* polygon, int face, const tbPolygon* other)
{
	tbVec2 n = polygon->normals[face];
	tbVec2 v = polygon->vertices[face];
	float separation = FLT_MAX;
	for (int j = 0; j < other->count; ++j)
	{
		separation = tbMinFloat(separation, tbDot(n, tbSub(other->vertices[j], v)));
	}
	return separation;
}

// Manifold point from an incident core point p measured against the reference face (v1, nR).
static tbManifoldPoint tbMakeClipPoint(tbVec2 p, tbVec2 v1, tbVec2 nR, float radiusRef, float radiusInc,
									   uint16_t id)
{
	float h = tbDot(nR, tbSub(p, v1));
	tbManifoldPoint mp = {0};
	mp.point = tbMulAdd(p, 0.5f * (radiusRef - radiusInc - h), nR);
	mp.separation = h - radiusRef - radiusInc;
	mp.id = id;
	return mp;
}

// (vertex of A, vertex of B) from (reference vertex, incident vertex); flip: B is the reference.
static uint16_t tbClipFeatureId(int refVertex, int incVertex, bool flip)
{
	return flip ? TB_MAKE_FEATURE_ID(incVertex, refVertex) : TB_MAKE_FEATURE_ID(refVertex, incVertex);
}

// Clip the incident edge of `inc` against reference face `refEdge` of `ref` (both in A's
// frame). Returns the manifold in A's frame with normal nR (the caller flips it when B is the
// reference); pointCount 0 when the incident edge misses the face's slab.
static tbManifold tbClipToReferenceFace(const tbPolygon* ref, int refEdge, const tbPolygon* inc, bool flip,
										float keep)
{
	tbManifold m = {0};
	int refNext = refEdge + 1 < ref->count ? refEdge + 1 : 0;
	tbVec2 v1 = ref->vertices[refEdge];
	tbVec2 v2 = ref->vertices[refNext];
	tbVec2 nR = ref->normals[refEdge];
	tbVec2 t = tbLeftPerp(nR); // counter-clockwise: the face runs from v1 to v2 along left-perp(n)

	// Incident edge w1 → w2 runs against the face, so w2 sits at v1's end and w1 at v2's end.
	float minDot = FLT_MAX;
	int incEdge = 0;
	for (int j = 0; j < inc->count; ++j)
	{
		float d = tbDot(inc->normals[j], nR);
		if (d < minDot)
		{
			minDot = d;
			incEdge = j;
		}
	}
	int incNext = incEdge + 1 < inc->count ? incEdge + 1 : 0;
	tbVec2 w1 = inc->vertices[incEdge];
	tbVec2 w2 = inc->vertices[incNext];

	// interval of the incident edge along t, measured from v1: w2 at a, w1 at b; the face is [0, L]
	float a = tbDot(t, tbSub(w2, v1));
	float b = tbDot(t, tbSub(w1, v1));
	float L = tbDot(t, tbSub(v2, v1));
	if (b <= a || b < 0.0f || a > L)
	{
		return m; // edge-on or outside the slab
	}
	tbVec2 first = a < -TB_GJK_CLIP_SLACK ? tbLerp(w2, w1, (0.0f - a) / (b - a)) : w2;
	tbVec2 second = b > L + TB_GJK_CLIP_SLACK ? tbLerp(w2, w1, (L - a) / (b - a)) : w1;

	tbManifoldPoint points[2] = {
		tbMakeClipPoint(first, v1, nR, ref->radius, inc->radius, tbClipFeatureId(refEdge, incNext, flip)),
		tbMakeClipPoint(second, v1, nR, ref->radius, inc->radius, tbClipFeatureId(refNext, incEdge, flip)),
	};
	m.normal = nR;
	for (int i = 0; i < 2; ++i)
	{
		if (points[i].separation < keep)
		{
			m.points[m.pointCount++] = points[i];
		}
	}
	return m;
}

// Corner facing corner across a gap: one point from the GJK witness points (A's frame).
static tbManifold tbCornerManifold(const tbSeparationOutput* separation, const tbPolygon* polygonA,
								   const tbPolygon* localB, tbVec2 localNormal)
{
	int cornerA = 0, cornerB = 0;
	float bestA = -FLT_MAX, bestB = -FLT_MAX;
	for (int i = 0; i < polygonA->count; ++i)
	{
		float d = tbDot(polygonA->vertices[i], localNormal);
		if (d > bestA)
		{
			bestA = d;
			cornerA = i;
		}
	}
	for (int j = 0; j < localB->count; ++j)
	{
		float d = -tbDot(localB->vertices[j], localNormal);
		if (d > bestB)
		{
			bestB = d;
			cornerB = j;
		}
	}

	tbManifold m = {0};
	m.normal = separation->normal;
	m.points[0].point = tbLerp(separation->pointA, separation->pointB, 0.5f);
	m.points[0].separation = separation->separation;
	m.points[0].id = TB_MAKE_FEATURE_ID(cornerA | TB_FEATURE_VERTEX, cornerB | TB_FEATURE_VERTEX);
	m.pointCount = 1;
	return m;
}

tbLocalManifold tbCollidePolygonsGJK(const tbPolygon* polygonA, const tbPolygon* polygonB, tbTransform xf)
{
	tbManifold m = tbPolygonsGJKFrameA(polygonA, polygonB, xf, TB_SPECULATIVE_DISTANCE);
	return tbMakeLocalManifold(&m);
}

tbManifold tbPolygonsGJKFrameA(const tbPolygon* polygonA, const tbPolygon* polygonB, tbTransform xf, float keep)
{
	tbManifold empty = {0};

	tbDistanceInput input = {0};
	input.proxyA = tbMakeProxy(polygonA->vertices, polygonA->count, polygonA->radius);
	input.proxyB = tbMakeProxy(polygonB->vertices, polygonB->count, polygonB->radius);
	input.transform = xf;
	input.useRadii = true;
	tbSeparationOutput separation = tbShapeSeparation(&input, NULL); // in A's frame
	if (separation.separation >= keep)
	{
		return empty;
	}

	// B and the normal in A's frame
	tbPolygon localB = tbTransformPolygon(xf, polygonB);
	tbVec2 n = separation.normal;

	int faceA = tbMostAlignedFace(polygonA, n);
	int faceB = tbMostAlignedFace(&localB, tbNeg(n));
	float separationA = tbFaceSeparation(polygonA, faceA, &localB);
	float separationB = tbFaceSeparation(&localB, faceB, polygonA);

	float coreSeparation = separation.separation + polygonA->radius + polygonB->radius;
	bool faceOfB = separationB > separationA + TB_GJK_REFERENCE_TOLERANCE;
	// The core gap's offset along the reference face: the gap runs along n, so it is d·|n × nF|.
	tbVec2 faceNormal = faceOfB ? localB.normals[faceB] : polygonA->normals[faceA];
	float sideways = coreSeparation * tbAbsFloat(tbCross(n, faceNormal));
	if (coreSeparation > TB_GJK_CORNER_TOLERANCE && sideways > TB_GJK_CORNER_TOLERANCE)
	{
		return tbCornerManifold(&separation, polygonA, &localB, n);
	}

	tbManifold m;
	if (faceOfB)
	{
		m = tbClipToReferenceFace(&localB, faceB, polygonA, true, keep);
		m.normal = tbNeg(m.normal);
	}
	else
	{
		m = tbClipToReferenceFace(polygonA, faceA, &localB, false, keep);
	}
	if (m.pointCount == 0)
	{
		// the incident edge is edge-on to the face or misses its slab (only within the
		// tolerances above): the GJK/EPA witness pair is still a valid single contact
		return tbCornerManifold(&separation, polygonA, &localB, n);
	}
	return m;
}
