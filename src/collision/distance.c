// Tumble: distance between convex shapes: segment distance, GJK and the GJK shape cast.
//
// ---- Segment distance ----
// tbSegmentDistance: closest points of two segments (Ericson, "Real-Time Collision Detection",
// §5.1.9). The segments are S1(s) = p1 + s·d1 and S2(t) = p2 + t·d2 with s, t ∈ [0, 1]. The
// squared distance |S1(s) − S2(t)|² is a convex quadratic in (s, t); with r = p1 − p2,
// a = d1·d1, b = d1·d2, e = d2·d2, c = d1·r, f = d2·r its unconstrained minimum satisfies
//     a·s − b·t = −c,   b·s − e·t = −f,
// so s = (b·f − c·e) / (a·e − b²). Clamping s to [0, 1], then solving t = (b·s + f) / e and, when
// t leaves [0, 1], clamping t and re-solving s = (b·t − c) / a gives the constrained minimum
// because the function is convex along each axis.
//
// Degenerate cases: a segment shorter than a tiny length is treated as a point (its parameter is
// 0); parallel segments (a·e − b² ≈ 0 relative to a·e) have a whole interval of minima and any
// s works — we take s = 0 and let the clamping of t pick the matching point on S2.
//
// ---- GJK (van den Bergen, "Collision Detection in Interactive 3D Environments", 2003, §4.3;
// Ericson §9.5) ----
// The distance between convex A and B is the distance from the origin to the Minkowski
// difference D = B − A = { b − a }. Its support mapping is s_D(d) = s_B(d) − s_A(−d). GJK keeps a
// simplex W (1 to 3 points of D), finds the point v of conv(W) closest to the origin (Johnson's
// sub-algorithm: in 2D, the Voronoi regions of the vertices, edges and interior of W, written with
// barycentric coordinates), drops the vertices that do not support v, and adds w = s_D(−v).
// Each step strictly decreases |v| until w brings no progress along −v:
//     −v̂·w ≤ −v̂·v + ε   (the lower bound v̂·w on the distance meets the upper bound |v|).
// For an edge simplex the direction is taken as the edge perpendicular facing the origin, not
// −v: the perpendicular is exact even when v is tiny and has lost its digits.
// Termination, robust in float: (1) no progress as above, (2) a support point already in the
// simplex (cycling), (3) the origin inside the triangle (cores overlap), (4) v ≈ 0 (touching
// cores), (5) an iteration cap. The whole computation runs in A's local frame (B mapped by
// A⁻¹·B): at 1000 m from the origin a float has a resolution of 6e-5 m, which would swamp
// millimetre features, while in A's frame the coordinates are of the size of the shapes.
// The warm-start cache stores the support indices of the final simplex; the next call rebuilds
// that simplex, so a pair that moved a little converges in one or two iterations.
//
// ---- Shape cast (van den Bergen, "Ray casting against general convex objects with application
// to continuous collision detection", 2004; conservative advancement, Mirtich 1996) ----
// B translates by r over λ ∈ [0, 1]. The core distance d(λ) of two convex shapes under a
// translation is a convex function of λ with slope n·r, where n is the unit normal from A to B
// at λ. Convexity puts the tangent line below the curve, so stepping to its root with the target
// distance, λ += (d − target) / (−n·r), never passes the first contact: the advancement is
// conservative and converges monotonically. n·r ≥ 0 means the distance can no longer decrease:
// no hit.

#include "core/core.h"
#include "distance_internal.h"

#include "tumble/collision.h"

#include <float.h>
#include <string.h>

// Squared length below which a segment counts as a point: (1e-6 m)², far below any shape size
// Tumble is tuned for (0.1 m to 10 m) and still well above float underflow.
#define TB_SEGMENT_POINT_TOLERANCE_SQUARED (1e-12f)

// Relative tolerance on a·e − b² = a·e·sin²θ below which the segments count as parallel:
// sin²θ < 1e-6, about 0.06 degrees. Below that the 2×2 solve loses most of its digits in float.
#define TB_SEGMENT_PARALLEL_TOLERANCE (1e-6f)

static float tbClamp01(float x)
{
	return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x);
}

tbSegmentDistanceResult tbSegmentDistance(tbVec2 p1, tbVec2 q1, tbVec2 p2, tbVec2 q2)
{
	tbVec2 d1 = tbSub(q1, p1);
	tbVec2 d2 = tbSub(q2, p2);
	tbVec2 r = tbSub(p1, p2);
	float a = tbDot(d1, d1);
	float e = tbDot(d2, d2);
	float f = tbDot(d2, r);

	float s = 0.0f;
	float t = 0.0f;

	bool point1 = a < TB_SEGMENT_POINT_TOLERANCE_SQUARED;
	bool point2 = e < TB_SEGMENT_POINT_TOLERANCE_SQUARED;

	if (point1 && point2)
	{
		// both points: s = t = 0
	}
	else if (point1)
	{
		// S1 is the point p1: project onto S2
		t = tbClamp01(f / e);
	}
	else
	{
		float c = tbDot(d1, r);
		if (point2)
		{
			// S2 is the point p2: project onto S1
			s = tbClamp01(-c / a);
		}
		else
		{
			float b = tbDot(d1, d2);
			float denominator = a * e - b * b;
			if (denominator > TB_SEGMENT_PARALLEL_TOLERANCE * a * e)
			{
				s = tbClamp01((b * f - c * e) / denominator);
			}

			// best t for this s, then re-solve s if t had to be clamped
			t = (b * s + f) / e;
			if (t < 0.0f)
			{
				t = 0.0f;
				s = tbClamp01(-c / a);
			}
			else if (t > 1.0f)
			{
				t = 1.0f;
				s = tbClamp01((b - c) / a);
			}
		}
	}

	tbSegmentDistanceResult result;
	result.closest1 = tbMulAdd(p1, s, d1);
	result.closest2 = tbMulAdd(p2, t, d2);
	result.fraction1 = s;
	result.fraction2 = t;
	result.distanceSquared = tbDistanceSquared(result.closest1, result.closest2);
	return result;
}

// ---------------------------------------------------------------------------------------------
// Proxies

tbShapeProxy tbMakeValidProxy(const tbVec2* points, int count, float radius)
{
	tbShapeProxy proxy = {0};
	for (int i = 0; i < count; ++i)
	{
		proxy.points[i] = points[i];
	}
	proxy.count = count;
	proxy.radius = radius;
	return proxy;
}

// tbMakeProxy's work, reporting errors under the caller's name f.
static tbShapeProxy tbMakeProxyNamed(const char* f, const tbVec2* points, int count, float radius)
{
	tbShapeProxy proxy = {0};
	if (count < 1 || count > TB_MAX_POLYGON_VERTICES)
	{
		tbReportError(f, "count is %d (must be 1..TB_MAX_POLYGON_VERTICES = %d; 0 is what a refused shape "
						 "constructor leaves); pass 1 to %d points", count, TB_MAX_POLYGON_VERTICES,
					  TB_MAX_POLYGON_VERTICES);
		return proxy;
	}
	if (tbCheckPointer(f, "points", points) == false || tbCheckPoints(f, "points", points, count) == false ||
		tbCheckLength(f, "radius", radius, false) == false)
	{
		return proxy;
	}
	return tbMakeValidProxy(points, count, radius);
}

tbShapeProxy tbMakeProxy(const tbVec2* points, int count, float radius)
{
	return tbMakeProxyNamed("tbMakeProxy", points, count, radius);
}

tbShapeProxy tbMakeOffsetProxy(const tbVec2* points, int count, float radius, tbVec2 position, tbRot rotation)
{
	const char* f = "tbMakeOffsetProxy";
	tbShapeProxy proxy = {0};
	if (tbCheckCoordinate(f, "position", position) == false)
	{
		return proxy;
	}
	if (tbIsValidRotation(rotation) == false)
	{
		tbReportError(f, "rotation is (%g, %g), not a unit rotation; make it with tbMakeRot", (double)rotation.c,
					  (double)rotation.s);
		return proxy;
	}
	proxy = tbMakeProxyNamed(f, points, count, radius); // checks the points and the radius
	tbTransform transform = {position, rotation};
	for (int i = 0; i < proxy.count; ++i)
	{
		proxy.points[i] = tbTransformPoint(transform, proxy.points[i]);
	}
	if (tbCheckPoints(f, "moved points", proxy.points, proxy.count) == false)
	{
		tbShapeProxy empty = {0};
		return empty;
	}
	return proxy;
}

// The core of a shape: its points without the radius, and the radius. Not checked here: a shape
// was checked when it was made, and tbMakeShapeProxy checks what it returns.
static tbShapeProxy tbGeometryCore(const tbGeometry* shape)
{
	tbShapeProxy core = {0};
	switch (shape->type)
	{
		case tb_circleShape:
			core.points[0] = shape->circle.center;
			core.count = 1;
			core.radius = shape->circle.radius;
			break;
		case tb_capsuleShape:
			core.points[0] = shape->capsule.center1;
			core.points[1] = shape->capsule.center2;
			core.count = 2;
			core.radius = shape->capsule.radius;
			break;
		case tb_segmentShape:
			core.points[0] = shape->segment.point1;
			core.points[1] = shape->segment.point2;
			core.count = 2;
			break;
		case tb_chainSegmentShape:
			core.points[0] = shape->chainSegment.segment.point1;
			core.points[1] = shape->chainSegment.segment.point2;
			core.count = 2;
			break;
		case tb_polygonShape:
			// A polygon a constructor refused has count 0: tbMakeShapeProxy's tbMakeProxy reports it.
			core.count = shape->polygon.count;
			if (0 < core.count && core.count <= TB_MAX_POLYGON_VERTICES)
			{
				memcpy(core.points, shape->polygon.vertices, (size_t)core.count * sizeof(tbVec2));
			}
			core.radius = shape->polygon.radius;
			break;
		default:
			TB_ASSERT(false);
			core.count = 1; // the origin
			break;
	}
	return core;
}

tbShapeProxy tbMakeShapeProxy(const tbGeometry* shape)
{
	tbShapeProxy core = tbGeometryCore(shape);
	return tbMakeProxy(core.points, core.count, core.radius);
}

float tbShapeGapBound(const tbGeometry* a, const tbGeometry* b, tbTransform relative)
{
	tbShapeProxy coreA = tbGeometryCore(a);
	tbShapeProxy coreB = tbGeometryCore(b);
	for (int i = 0; i < coreB.count; ++i)
	{
		coreB.points[i] = tbTransformPoint(relative, coreB.points[i]);
	}
	// The narrow phase works at these coordinates (A's frame), its rounding in proportion to them:
	// a ground's chain or boxes may lie kilometres from the ground body's origin.
	float scale = tbProxyScale(&coreA, &coreB);
	// The distance itself at small coordinates: both cores moved so that A's first point is the
	// origin (a translation keeps every distance).
	tbVec2 shift = coreA.points[0];
	for (int i = 0; i < coreA.count; ++i)
	{
		coreA.points[i] = tbSub(coreA.points[i], shift);
	}
	for (int i = 0; i < coreB.count; ++i)
	{
		coreB.points[i] = tbSub(coreB.points[i], shift);
	}
	float distance;
	if (coreA.count <= 2 && coreB.count <= 2)
	{
		// Points and segments (circles, capsules, segments): the closed form.
		tbSegmentDistanceResult r = tbSegmentDistance(coreA.points[0], coreA.points[coreA.count - 1], coreB.points[0],
													  coreB.points[coreB.count - 1]);
		distance = sqrtf(r.distanceSquared);
	}
	else
	{
		distance = tbLocalShapeDistance(&coreA, &coreB, NULL, NULL).distance;
	}
	return distance - coreA.radius - coreB.radius - TB_GAP_ALLOWANCE - TB_GAP_SCALE_ALLOWANCE * scale;
}

bool tbCheckProxyPair(const char* function, const tbShapeProxy* proxyA, const tbShapeProxy* proxyB)
{
	int countA = proxyA->count, countB = proxyB->count;
	bool validA = 1 <= countA && countA <= TB_MAX_POLYGON_VERTICES;
	if (validA && 1 <= countB && countB <= TB_MAX_POLYGON_VERTICES)
	{
		return true;
	}
	tbReportError(function, "%s has count %d (must be 1..%d); an empty proxy is what a refused tbMakeProxy returns: "
							"build proxies from valid shapes", validA ? "proxyB" : "proxyA", validA ? countB : countA,
				  TB_MAX_POLYGON_VERTICES);
	return false;
}

int tbFindSupport(const tbShapeProxy* proxy, tbVec2 direction)
{
	int best = 0;
	float bestValue = tbDot(proxy->points[0], direction);
	for (int i = 1; i < proxy->count; ++i)
	{
		float value = tbDot(proxy->points[i], direction);
		if (value > bestValue)
		{
			best = i;
			bestValue = value;
		}
	}
	return best;
}

tbShapeProxy tbMakeRelativeProxy(const tbShapeProxy* proxyB, tbTransform relative)
{
	tbShapeProxy local = *proxyB;
	for (int i = 0; i < proxyB->count; ++i)
	{
		local.points[i] = tbTransformPoint(relative, proxyB->points[i]);
	}
	return local;
}

float tbProxyScale(const tbShapeProxy* proxyA, const tbShapeProxy* proxyB)
{
	float scaleSquared = 0.0f;
	for (int i = 0; i < proxyA->count; ++i)
	{
		scaleSquared = tbMaxFloat(scaleSquared, tbLengthSquared(proxyA->points[i]));
	}
	for (int i = 0; i < proxyB->count; ++i)
	{
		scaleSquared = tbMaxFloat(scaleSquared, tbLengthSquared(proxyB->points[i]));
	}
	return sqrtf(scaleSquared);
}

// ---------------------------------------------------------------------------------------------
// GJK

// Iteration cap, 20: a pair of 8-gons has at most 16 Minkowski vertices and GJK adds one per
// iteration; warm-started pairs take 1 to 3.
#define TB_GJK_MAX_ITERATIONS 20

// Relative progress tolerance, 8 float ulps of the pair's length scale: a support point that
// advances less than this along the search direction is rounding noise, not progress.
#define TB_GJK_RELATIVE_TOLERANCE (8.0f * FLT_EPSILON)

static tbSimplexVertex tbMakeSimplexVertex(const tbShapeProxy* proxyA, const tbShapeProxy* proxyB, int indexA,
										   int indexB)
{
	tbSimplexVertex v;
	v.wA = proxyA->points[indexA];
	v.wB = proxyB->points[indexB];
	v.w = tbSub(v.wB, v.wA);
	v.a = 1.0f;
	v.indexA = indexA;
	v.indexB = indexB;
	return v;
}

// The i-th vertex of a simplex (v1, v2, v3 are separate members, so no array arithmetic).
static tbSimplexVertex* tbSimplexVertexAt(tbSimplex* simplex, int index)
{
	switch (index)
	{
		case 0:
			return &simplex->v1;
		case 1:
			return &simplex->v2;
		default:
			TB_ASSERT(index == 2);
			return &simplex->v3;
	}
}

tbSimplexVertex tbMakeSupportVertex(const tbShapeProxy* proxyA, const tbShapeProxy* proxyB, tbVec2 direction)
{
	int indexA = tbFindSupport(proxyA, tbNeg(direction));
	int indexB = tbFindSupport(proxyB, direction);
	return tbMakeSimplexVertex(proxyA, proxyB, indexA, indexB);
}

// Rebuild the cached simplex; fall back to a single vertex when the cache is empty, out of range
// or has become degenerate (coincident points, flat triangle) since it was written.
static tbSimplex tbReadCache(const tbSimplexCache* cache, const tbShapeProxy* proxyA, const tbShapeProxy* proxyB,
							 float scale)
{
	tbSimplex simplex = {0};
	int count = cache != NULL ? cache->count : 0;
	if (count > 3)
	{
		count = 0;
	}
	for (int i = 0; i < count; ++i)
	{
		int indexA = cache->indexA[i];
		int indexB = cache->indexB[i];
		if (indexA >= proxyA->count || indexB >= proxyB->count)
		{
			count = 0;
			break;
		}
		*tbSimplexVertexAt(&simplex, i) = tbMakeSimplexVertex(proxyA, proxyB, indexA, indexB);
	}

	float tinySquared = (TB_GJK_RELATIVE_TOLERANCE * scale) * (TB_GJK_RELATIVE_TOLERANCE * scale);
	if (count == 2 && tbDistanceSquared(simplex.v1.w, simplex.v2.w) <= tinySquared)
	{
		count = 1;
	}
	else if (count == 3)
	{
		tbVec2 e12 = tbSub(simplex.v2.w, simplex.v1.w);
		tbVec2 e13 = tbSub(simplex.v3.w, simplex.v1.w);
		float area = tbAbsFloat(tbCross(e12, e13));
		if (area <= TB_GJK_RELATIVE_TOLERANCE * (tbLengthSquared(e12) + tbLengthSquared(e13)) + tinySquared)
		{
			count = 1;
		}
	}

	if (count == 0)
	{
		simplex.v1 = tbMakeSimplexVertex(proxyA, proxyB, 0, 0);
		count = 1;
	}
	simplex.count = count;
	return simplex;
}

static void tbWriteCache(tbSimplexCache* cache, tbSimplex* simplex)
{
	cache->count = (uint16_t)simplex->count;
	for (int i = 0; i < simplex->count; ++i)
	{
		const tbSimplexVertex* vertex = tbSimplexVertexAt(simplex, i);
		cache->indexA[i] = (uint8_t)vertex->indexA;
		cache->indexB[i] = (uint8_t)vertex->indexB;
	}
}

// Closest point of the segment w1–w2 to the origin. With e = w2 − w1 the closest point is
// w1 + t·e with t = −w1·e / e·e; the barycentric weights are a1 = w2·e / e·e (weight of w1) and
// a2 = −w1·e / e·e (weight of w2). A non-positive weight means the origin is in the Voronoi
// region of the other vertex, which alone remains.
static void tbSolveSegment(tbSimplex* simplex)
{
	tbVec2 w1 = simplex->v1.w;
	tbVec2 w2 = simplex->v2.w;
	tbVec2 e12 = tbSub(w2, w1);

	float d12Weight2 = -tbDot(w1, e12);
	if (d12Weight2 <= 0.0f)
	{
		simplex->v1.a = 1.0f;
		simplex->count = 1;
		return;
	}

	float d12Weight1 = tbDot(w2, e12);
	if (d12Weight1 <= 0.0f)
	{
		simplex->v1 = simplex->v2;
		simplex->v1.a = 1.0f;
		simplex->count = 1;
		return;
	}

	// Both weights are squared lengths; below FLT_MIN (shapes of ~1e-19 m) 1/sum overflows to
	// infinity: such an edge is a point at this precision, keep w1.
	float sum = d12Weight1 + d12Weight2;
	if (sum < FLT_MIN)
	{
		simplex->v1.a = 1.0f;
		simplex->count = 1;
		return;
	}
	float inverse = 1.0f / sum;
	simplex->v1.a = d12Weight1 * inverse;
	simplex->v2.a = d12Weight2 * inverse;
	simplex->count = 2;
}

// Closest point of the triangle w1 w2 w3 to the origin by its seven Voronoi regions. Edge
// weights as in tbSolveSegment; the interior weights are the signed areas of the sub-triangles
// opposite each vertex, taken with the sign of the whole triangle: a1 ∝ n·(w2 × w3) and so on
// with n = (w2 − w1) × (w3 − w1). An edge region holds when both its edge weights are positive and
// the interior weight of the opposite vertex is not.
static void tbSolveTriangle(tbSimplex* simplex)
{
	tbVec2 w1 = simplex->v1.w;
	tbVec2 w2 = simplex->v2.w;
	tbVec2 w3 = simplex->v3.w;

	tbVec2 e12 = tbSub(w2, w1);
	float d12Weight1 = tbDot(w2, e12);
	float d12Weight2 = -tbDot(w1, e12);

	tbVec2 e13 = tbSub(w3, w1);
	float d13Weight1 = tbDot(w3, e13);
	float d13Weight2 = -tbDot(w1, e13);

	tbVec2 e23 = tbSub(w3, w2);
	float d23Weight1 = tbDot(w3, e23);
	float d23Weight2 = -tbDot(w2, e23);

	// Each edge's two weights sum to its squared length. An edge shorter than √FLT_MIN (~1e-19 m)
	// would make 1/sum overflow: the triangle is a segment at this precision.
	if (tbMinFloat(tbLengthSquared(e12), tbMinFloat(tbLengthSquared(e13), tbLengthSquared(e23))) < FLT_MIN)
	{
		simplex->count = 2;
		tbSolveSegment(simplex);
		return;
	}

	float n123 = tbCross(e12, e13);
	float d123Weight1 = n123 * tbCross(w2, w3);
	float d123Weight2 = n123 * tbCross(w3, w1);
	float d123Weight3 = n123 * tbCross(w1, w2);

	// vertex regions
	if (d12Weight2 <= 0.0f && d13Weight2 <= 0.0f)
	{
		simplex->v1.a = 1.0f;
		simplex->count = 1;
		return;
	}
	if (d12Weight1 <= 0.0f && d23Weight2 <= 0.0f)
	{
		simplex->v1 = simplex->v2;
		simplex->v1.a = 1.0f;
		simplex->count = 1;
		return;
	}
	if (d13Weight1 <= 0.0f && d23Weight1 <= 0.0f)
	{
		simplex->v1 = simplex->v3;
		simplex->v1.a = 1.0f;
		simplex->count = 1;
		return;
	}

	// edge regions
	if (d12Weight1 > 0.0f && d12Weight2 > 0.0f && d123Weight3 <= 0.0f)
	{
		float inverse = 1.0f / (d12Weight1 + d12Weight2);
		simplex->v1.a = d12Weight1 * inverse;
		simplex->v2.a = d12Weight2 * inverse;
		simplex->count = 2;
		return;
	}
	if (d13Weight1 > 0.0f && d13Weight2 > 0.0f && d123Weight2 <= 0.0f)
	{
		float inverse = 1.0f / (d13Weight1 + d13Weight2);
		simplex->v1.a = d13Weight1 * inverse;
		simplex->v3.a = d13Weight2 * inverse;
		simplex->v2 = simplex->v3;
		simplex->count = 2;
		return;
	}
	if (d23Weight1 > 0.0f && d23Weight2 > 0.0f && d123Weight1 <= 0.0f)
	{
		float inverse = 1.0f / (d23Weight1 + d23Weight2);
		simplex->v2.a = d23Weight1 * inverse;
		simplex->v3.a = d23Weight2 * inverse;
		simplex->v1 = simplex->v3;
		simplex->count = 2;
		return;
	}

	// interior: the origin is inside, the cores overlap. The weights sum to n123² > 0 in exact
	// arithmetic; a sum that is not positive comes from rounding in a nearly flat triangle or from
	// input beyond the float range (coordinates near FLT_MAX, NaN). No interior answer is then
	// trustworthy: keep the edge w1–w2, whose solution is always defined.
	float sum = d123Weight1 + d123Weight2 + d123Weight3;
	if ((sum >= FLT_MIN) == false)
	{
		simplex->count = 2;
		tbSolveSegment(simplex);
		return;
	}
	float inverse = 1.0f / sum;
	simplex->v1.a = d123Weight1 * inverse;
	simplex->v2.a = d123Weight2 * inverse;
	simplex->v3.a = d123Weight3 * inverse;
	simplex->count = 3;
}

static void tbSolveSimplex(tbSimplex* simplex)
{
	if (simplex->count == 2)
	{
		tbSolveSegment(simplex);
	}
	else if (simplex->count == 3)
	{
		tbSolveTriangle(simplex);
	}
	else
	{
		simplex->v1.a = 1.0f;
	}
}

// Direction from the simplex towards the origin (not normalised): −w1 for a vertex, the edge
// perpendicular on the origin's side for an edge.
static tbVec2 tbSearchDirection(const tbSimplex* simplex)
{
	if (simplex->count == 1)
	{
		return tbNeg(simplex->v1.w);
	}
	tbVec2 e12 = tbSub(simplex->v2.w, simplex->v1.w);
	float side = tbCross(e12, tbNeg(simplex->v1.w));
	return side > 0.0f ? tbLeftPerp(e12) : tbRightPerp(e12);
}

// Closest points on A and B from the barycentric weights: pA = Σ aᵢ·wAᵢ, pB = Σ aᵢ·wBᵢ.
static void tbWitnessPoints(tbVec2* pointA, tbVec2* pointB, tbSimplex* simplex)
{
	tbVec2 a = tbVec2_zero;
	tbVec2 b = tbVec2_zero;
	for (int i = 0; i < simplex->count; ++i)
	{
		const tbSimplexVertex* vertex = tbSimplexVertexAt(simplex, i);
		a = tbMulAdd(a, vertex->a, vertex->wA);
		b = tbMulAdd(b, vertex->a, vertex->wB);
	}
	*pointA = a;
	*pointB = simplex->count == 3 ? a : b;
}

// Unit normal from A to B: the edge perpendicular (pointing away from the origin's side, i.e.
// along v) for an edge simplex, v/|v| for a vertex, zero for an overlapping triangle.
static tbVec2 tbSimplexNormal(const tbSimplex* simplex)
{
	if (simplex->count == 1)
	{
		return tbNormalize(simplex->v1.w);
	}
	if (simplex->count == 2)
	{
		tbVec2 n = tbNormalize(tbLeftPerp(tbSub(simplex->v2.w, simplex->v1.w)));
		return tbDot(n, simplex->v1.w) < 0.0f ? tbNeg(n) : n;
	}
	return tbVec2_zero;
}

static bool tbIsRepeatedSupport(const tbSimplexVertex* saved, int savedCount, int indexA, int indexB)
{
	for (int i = 0; i < savedCount; ++i)
	{
		if (saved[i].indexA == indexA && saved[i].indexB == indexB)
		{
			return true;
		}
	}
	return false;
}

// The GJK iterations proper. Returns the iteration count; the simplex holds the final simplex.
static int tbRunGJK(tbSimplex* simplex, const tbShapeProxy* proxyA, const tbShapeProxy* proxyB, float scale)
{
	float tolerance = TB_GJK_RELATIVE_TOLERANCE * scale;
	int iteration = 0;

	while (iteration < TB_GJK_MAX_ITERATIONS)
	{
		++iteration;

		tbSimplexVertex saved[3] = {simplex->v1, simplex->v2, simplex->v3};
		int savedCount = simplex->count;

		tbSolveSimplex(simplex);
		if (simplex->count == 3)
		{
			break; // origin inside: cores overlap
		}

		tbVec2 direction = tbSearchDirection(simplex);
		float directionLength = tbLength(direction);
		if (directionLength <= FLT_MIN)
		{
			break; // v = 0 or a collapsed edge: the cores touch
		}
		tbVec2 unit = tbMulSV(1.0f / directionLength, direction);

		// current distance along the search direction: −d̂·w1 = |v|
		float current = -tbDot(unit, simplex->v1.w);
		if (current <= tolerance)
		{
			break; // the origin lies on the simplex within rounding: touching cores
		}

		int indexA = tbFindSupport(proxyA, tbNeg(direction));
		int indexB = tbFindSupport(proxyB, direction);
		if (tbIsRepeatedSupport(saved, savedCount, indexA, indexB))
		{
			break; // cycling: no new support point exists
		}

		tbSimplexVertex vertex = tbMakeSimplexVertex(proxyA, proxyB, indexA, indexB);
		float support = -tbDot(unit, vertex.w);
		if (current - support <= tolerance)
		{
			break; // no progress: |v| is the distance within rounding
		}

		*tbSimplexVertexAt(simplex, simplex->count) = vertex;
		simplex->count += 1;
	}

	return iteration;
}

tbDistanceOutput tbLocalShapeDistance(const tbShapeProxy* proxyA, const tbShapeProxy* proxyB, tbSimplexCache* cache,
									  tbSimplex* simplexOut)
{
	float scale = tbProxyScale(proxyA, proxyB);
	tbSimplex simplex = tbReadCache(cache, proxyA, proxyB, scale);

	tbDistanceOutput output = {0};
	output.iterations = tbRunGJK(&simplex, proxyA, proxyB, scale);

	tbWitnessPoints(&output.pointA, &output.pointB, &simplex);
	output.distance = simplex.count == 3 ? 0.0f : tbDistance(output.pointA, output.pointB);
	output.normal = tbSimplexNormal(&simplex);
	output.simplexCount = simplex.count;

	if (cache != NULL)
	{
		tbWriteCache(cache, &simplex);
	}
	if (simplexOut != NULL)
	{
		*simplexOut = simplex;
	}
	return output;
}

// Move the closest points from the cores to the surfaces: pA += rA·n, pB −= rB·n; when the
// radii overlap both become the midpoint and the distance is zero.
static void tbApplyRadii(tbDistanceOutput* output, float radiusA, float radiusB)
{
	float radii = radiusA + radiusB;
	if (output->distance > radii && output->simplexCount < 3)
	{
		output->distance -= radii;
		output->pointA = tbMulAdd(output->pointA, radiusA, output->normal);
		output->pointB = tbMulSub(output->pointB, radiusB, output->normal);
		return;
	}
	tbVec2 middle = tbLerp(output->pointA, output->pointB, 0.5f);
	output->pointA = middle;
	output->pointB = middle;
	output->distance = 0.0f;
}

static void tbSimplexToWorld(tbSimplex* simplex, tbTransform transformA)
{
	for (int i = 0; i < simplex->count; ++i)
	{
		tbSimplexVertex* vertex = tbSimplexVertexAt(simplex, i);
		vertex->wA = tbTransformPoint(transformA, vertex->wA);
		vertex->wB = tbTransformPoint(transformA, vertex->wB);
		vertex->w = tbSub(vertex->wB, vertex->wA);
	}
}

tbDistanceOutput tbShapeDistance(const tbDistanceInput* input, tbSimplexCache* cache, tbSimplex* simplexes,
								 int simplexCapacity)
{
	tbSimplex* simplex = simplexes != NULL && simplexCapacity > 0 ? simplexes : NULL;
	if (tbCheckProxyPair("tbShapeDistance", &input->proxyA, &input->proxyB) == false)
	{
		tbDistanceOutput refused = {0};
		if (simplex != NULL)
		{
			memset(simplex, 0, sizeof(*simplex));
		}
		return refused;
	}
	tbShapeProxy localB = tbMakeRelativeProxy(&input->proxyB, input->transform);
	tbDistanceOutput output = tbLocalShapeDistance(&input->proxyA, &localB, cache, simplex);
	if (input->useRadii)
	{
		tbApplyRadii(&output, input->proxyA.radius, input->proxyB.radius);
	}
	return output;
}

tbDistanceOutput tbShapeDistanceBetween(const tbShapeProxy* proxyA, tbTransform transformA, const tbShapeProxy* proxyB,
										tbTransform transformB, bool useRadii, tbSimplexCache* cache, tbSimplex* simplex)
{
	tbDistanceInput input = {*proxyA, *proxyB, tbInvMulTransforms(transformA, transformB), useRadii};
	tbDistanceOutput output = tbShapeDistance(&input, cache, simplex, simplex != NULL ? 1 : 0);
	output.pointA = tbTransformPoint(transformA, output.pointA);
	output.pointB = tbTransformPoint(transformA, output.pointB);
	output.normal = tbRotateVector(transformA.q, output.normal);
	if (simplex != NULL)
	{
		tbSimplexToWorld(simplex, transformA);
	}
	return output;
}

// ---------------------------------------------------------------------------------------------
// Shape cast

// Advancement stops when the core distance is within this of the target: TB_TOI_TARGET_SEPARATION
// (0.25 × linear slop = 1.25 mm), the accuracy continuous collision needs.
#define TB_CAST_TOLERANCE TB_TOI_TARGET_SEPARATION

static tbCastOutput tbMakeCastHit(const tbDistanceOutput* distance, tbTransform transformA, float radiusA,
								  float fraction, int iterations)
{
	tbCastOutput output = {0};
	output.normal = tbRotateVector(transformA.q, distance->normal);
	output.point = tbTransformPoint(transformA, tbMulAdd(distance->pointA, radiusA, distance->normal));
	output.fraction = fraction;
	output.iterations = iterations;
	output.hit = true;
	return output;
}

// Shapes already within the target at λ = 0: a hit at fraction 0 with a zero normal, because no
// direction of first contact exists (the shapes touch or overlap before moving), and the point
// halfway between the two surface points (the cores' common point when they overlap). This is
// Box2D v3's answer for an initial overlap, so code written for it reads ours the same way.
static tbCastOutput tbMakeInitialOverlap(const tbDistanceOutput* distance, tbTransform transformA, float radiusA,
										 float radiusB)
{
	tbVec2 surfaceA = tbMulAdd(distance->pointA, radiusA, distance->normal);
	tbVec2 surfaceB = tbMulSub(distance->pointB, radiusB, distance->normal);
	tbCastOutput output = {0};
	output.point = tbTransformPoint(transformA, tbLerp(surfaceA, surfaceB, 0.5f));
	output.iterations = 1;
	output.hit = true;
	return output;
}

tbCastOutput tbShapeCast(const tbShapeCastPairInput* input)
{
	tbCastOutput output = {0};
	if (tbCheckProxyPair("tbShapeCast", &input->proxyA, &input->proxyB) == false)
	{
		return output;
	}

	// Everything in A's frame: B's proxy at λ = 0 and its translation.
	tbShapeProxy proxyB = tbMakeRelativeProxy(&input->proxyB, input->transform);
	tbVec2 translation = input->translationB;
	const tbShapeProxy* proxyA = &input->proxyA;

	// Target core distance: the radii (surfaces touching), less one linear slop when the caller
	// allows encroaching, and never below the tolerance, because at zero core distance the
	// normal is undefined.
	float radii = proxyA->radius + proxyB.radius;
	float target = input->canEncroach ? radii - TB_LINEAR_SLOP : radii;
	target = tbMaxFloat(target, TB_CAST_TOLERANCE);

	tbSimplexCache cache = {0};
	tbVec2 offset = tbVec2_zero; // B's displacement λ·r so far
	float fraction = 0.0f;

	for (int iteration = 1; iteration <= TB_TOI_MAX_ITERATIONS; ++iteration)
	{
		tbShapeProxy movedB = proxyB;
		for (int i = 0; i < movedB.count; ++i)
		{
			movedB.points[i] = tbAdd(proxyB.points[i], offset);
		}

		tbDistanceOutput distance = tbLocalShapeDistance(proxyA, &movedB, &cache, NULL);
		if (distance.distance < target + TB_CAST_TOLERANCE)
		{
			if (iteration == 1)
			{
				return tbMakeInitialOverlap(&distance, tbTransform_identity, proxyA->radius, proxyB.radius);
			}
			return tbMakeCastHit(&distance, tbTransform_identity, proxyA->radius, fraction, iteration);
		}

		// closing speed along the normal; convexity of d(λ) makes the tangent step conservative
		float closing = -tbDot(distance.normal, translation);
		if (closing <= 0.0f)
		{
			output.iterations = iteration;
			return output; // moving apart or sliding: the distance never reaches the target
		}

		fraction += (distance.distance - target) / closing;
		if (fraction >= input->maxFraction)
		{
			output.iterations = iteration;
			return output;
		}
		offset = tbMulSV(fraction, translation);
	}

	// Iteration cap: report no hit rather than a guess (only pathological inputs get here).
	output.iterations = TB_TOI_MAX_ITERATIONS;
	return output;
}

// ---------------------------------------------------------------------------------------------
// Shape casts against one shape (Box2D v3.2's b2ShapeCastCircle and kin): the shape is proxy A at
// the identity, the input's proxy is B moving by the translation, so tbShapeCast answers in the
// shape's frame.

// The cast of input->proxy against proxyA, after the input's own checks (naming f).
static tbCastOutput tbShapeCastAgainst(const char* f, const tbShapeProxy* proxyA, const tbShapeCastInput* input)
{
	tbCastOutput output = {0};
	if (tbCheckVec2(f, "input->translation", input->translation) == false ||
		tbCheckNonNegative(f, "input->maxFraction", input->maxFraction) == false)
	{
		return output;
	}
	tbShapeCastPairInput pair;
	pair.proxyA = *proxyA;
	pair.proxyB = input->proxy;
	pair.transform = tbTransform_identity;
	pair.translationB = input->translation;
	pair.maxFraction = input->maxFraction;
	pair.canEncroach = input->canEncroach;
	if (tbCheckProxyPair(f, &pair.proxyA, &pair.proxyB) == false)
	{
		return output;
	}
	return tbShapeCast(&pair);
}

// The proxy of count shape points and a radius when they are usable (reported naming f), else an
// empty proxy (count 0).
static tbShapeProxy tbCheckedShapeProxy(const char* f, const tbVec2* points, int count, float radius)
{
	tbShapeProxy empty = {0};
	if (tbCheckPoints(f, "shape points", points, count) == false ||
		tbCheckLength(f, "shape->radius", radius, false) == false)
	{
		return empty;
	}
	return tbMakeValidProxy(points, count, radius);
}

// The checks and the cast shared by the four: pointers, the shape's proxy, then the sweep.
static tbCastOutput tbShapeCastShape(const char* f, const void* shape, const tbVec2* points, int count, float radius,
									 const tbShapeCastInput* input)
{
	tbCastOutput output = {0};
	if (tbCheckPointer(f, "shape", shape) == false || tbCheckPointer(f, "input", input) == false)
	{
		return output;
	}
	tbShapeProxy proxyA = tbCheckedShapeProxy(f, points, count, radius);
	return proxyA.count > 0 ? tbShapeCastAgainst(f, &proxyA, input) : output;
}

tbCastOutput tbShapeCastCircle(const tbCircle* shape, const tbShapeCastInput* input)
{
	const char* f = "tbShapeCastCircle";
	return tbShapeCastShape(f, shape, shape != NULL ? &shape->center : NULL, 1, shape != NULL ? shape->radius : 0.0f,
							input);
}

tbCastOutput tbShapeCastCapsule(const tbCapsule* shape, const tbShapeCastInput* input)
{
	const char* f = "tbShapeCastCapsule";
	tbVec2 points[2] = {tbVec2_zero, tbVec2_zero};
	if (shape != NULL)
	{
		points[0] = shape->center1;
		points[1] = shape->center2;
	}
	return tbShapeCastShape(f, shape, points, 2, shape != NULL ? shape->radius : 0.0f, input);
}

tbCastOutput tbShapeCastSegment(const tbSegment* shape, const tbShapeCastInput* input)
{
	const char* f = "tbShapeCastSegment";
	tbVec2 points[2] = {tbVec2_zero, tbVec2_zero};
	if (shape != NULL)
	{
		points[0] = shape->point1;
		points[1] = shape->point2;
	}
	return tbShapeCastShape(f, shape, points, 2, 0.0f, input);
}

tbCastOutput tbShapeCastPolygon(const tbPolygon* shape, const tbShapeCastInput* input)
{
	const char* f = "tbShapeCastPolygon";
	if (shape != NULL && (shape->count < 3 || shape->count > TB_MAX_POLYGON_VERTICES))
	{
		tbReportError(f, "shape->count is %d (must be 3..%d); build polygons with tbMakePolygon(tbComputeHull(...))",
					  shape->count, TB_MAX_POLYGON_VERTICES);
		tbCastOutput output = {0};
		return output;
	}
	return tbShapeCastShape(f, shape, shape != NULL ? shape->vertices : NULL, shape != NULL ? shape->count : 0,
							shape != NULL ? shape->radius : 0.0f, input);
}

tbCastOutput tbShapeCastBetween(const tbShapeProxy* proxyA, tbTransform transformA, const tbShapeProxy* proxyB,
								tbTransform transformB, tbVec2 translationB, float maxFraction, bool canEncroach)
{
	tbShapeCastPairInput input;
	input.proxyA = *proxyA;
	input.proxyB = *proxyB;
	input.transform = tbInvMulTransforms(transformA, transformB);
	input.translationB = tbInvRotateVector(transformA.q, translationB);
	input.maxFraction = maxFraction;
	input.canEncroach = canEncroach;
	tbCastOutput output = tbShapeCast(&input);
	output.point = tbTransformPoint(transformA, output.point);
	output.normal = tbRotateVector(transformA.q, output.normal);
	return output;
}
