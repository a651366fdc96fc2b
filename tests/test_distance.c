// Tests for distance.c: segment distance (Ericson §5.1.9), GJK distance against brute force,
// warm starting, precision for tiny and far-away shapes, and the GJK shape cast.
//
// Tolerances: positions here are at most ~10 m, where a float has a resolution of 1e-6 m;
// GJK's result passes through a few dozen roundings, so 2e-5 m (about 20 ulps at 10 m) is used
// for distances unless a test says otherwise.

#include <criterion/criterion.h>

#include "collision/distance_internal.h"
#include "tumble/collision.h"
#include "test_helpers.h"

#include <math.h>
#include <stdio.h>

// 20 float ulps at 10 m, see above.
#define DISTANCE_TOLERANCE 2e-5f

// Deterministic linear congruential generator (Numerical Recipes constants), so every run tests
// the same configurations.
static uint32_t lcgState = 12345u;

// Random convex polygon of about `size` metres from 3 to 8 random points (tbComputeHull).
static tbPolygon randomPolygon(float size)
{
	for (;;)
	{
		tbVec2 points[TB_MAX_POLYGON_VERTICES];
		int count = 3 + (int)RandomFloat(&lcgState, 0.0f, 5.999f);
		for (int i = 0; i < count; ++i)
		{
			points[i] = tbMakeVec2(RandomFloat(&lcgState, -size, size), RandomFloat(&lcgState, -size, size));
		}
		tbHull hull = tbComputeHull(points, count);
		if (hull.count >= 3)
		{
			return tbMakePolygon(&hull, 0.0f);
		}
	}
}

static tbTransform randomTransform(float extent)
{
	tbTransform xf = {{RandomFloat(&lcgState, -extent, extent), RandomFloat(&lcgState, -extent, extent)},
					  tbMakeRot(RandomFloat(&lcgState, -TB_PI, TB_PI))};
	return xf;
}

static tbDistanceInput makeInput(const tbPolygon* a, tbTransform xfA, const tbPolygon* b, tbTransform xfB)
{
	tbDistanceInput input = {0};
	input.proxyA = tbMakeProxy(a->vertices, a->count, a->radius);
	input.proxyB = tbMakeProxy(b->vertices, b->count, b->radius);
	input.transform = tbInvMulTransforms(xfA, xfB);
	input.useRadii = true;
	return input;
}

/// tbShapeDistance answers in A's frame; these tests check against the world polygons.
static tbDistanceOutput distanceInWorld(const tbDistanceInput* input, tbTransform xfA)
{
	tbDistanceOutput out = tbShapeDistance(input, NULL, NULL, 0);
	out.pointA = tbTransformPoint(xfA, out.pointA);
	out.pointB = tbTransformPoint(xfA, out.pointB);
	out.normal = tbRotateVector(xfA.q, out.normal);
	return out;
}

static bool pointInsideWorldPolygon(tbVec2 p, const tbVec2* v, int count)
{
	for (int i = 0; i < count; ++i)
	{
		tbVec2 e = tbSub(v[(i + 1) % count], v[i]);
		if (tbCross(e, tbSub(p, v[i])) < 0.0f)
		{
			return false;
		}
	}
	return true;
}

// Brute force: 0 if a vertex of one polygon is inside the other, else the smallest
// edge–edge distance (for disjoint convex polygons the closest points lie on their boundaries).
static float bruteForceDistance(const tbPolygon* a, tbTransform xfA, const tbPolygon* b, tbTransform xfB)
{
	tbVec2 va[TB_MAX_POLYGON_VERTICES], vb[TB_MAX_POLYGON_VERTICES];
	for (int i = 0; i < a->count; ++i)
	{
		va[i] = tbTransformPoint(xfA, a->vertices[i]);
	}
	for (int i = 0; i < b->count; ++i)
	{
		vb[i] = tbTransformPoint(xfB, b->vertices[i]);
	}
	for (int i = 0; i < a->count; ++i)
	{
		if (pointInsideWorldPolygon(va[i], vb, b->count))
		{
			return 0.0f;
		}
	}
	for (int i = 0; i < b->count; ++i)
	{
		if (pointInsideWorldPolygon(vb[i], va, a->count))
		{
			return 0.0f;
		}
	}
	float best = FLT_MAX;
	for (int i = 0; i < a->count; ++i)
	{
		for (int j = 0; j < b->count; ++j)
		{
			tbSegmentDistanceResult r =
				tbSegmentDistance(va[i], va[(i + 1) % a->count], vb[j], vb[(j + 1) % b->count]);
			best = fminf(best, r.distanceSquared);
		}
	}
	return sqrtf(best);
}

// ---------------------------------------------------------------------------------------------
// Segment distance

Test(segment_distance, crossing)
{
	tbSegmentDistanceResult r =
		tbSegmentDistance(tbMakeVec2(-1.0f, 0.0f), tbMakeVec2(1.0f, 0.0f), tbMakeVec2(0.0f, -1.0f), tbMakeVec2(0.0f, 1.0f));
	cr_expect_float_eq(r.distanceSquared, 0.0f, 1e-12f);
	cr_expect_float_eq(r.fraction1, 0.5f, 1e-6f);
	cr_expect_float_eq(r.fraction2, 0.5f, 1e-6f);
}

Test(segment_distance, skew_interior)
{
	// S1 on the x axis, S2 from (0.25, 1) to (0.75, 3): closest is S2's start above S1
	tbSegmentDistanceResult r =
		tbSegmentDistance(tbMakeVec2(0.0f, 0.0f), tbMakeVec2(1.0f, 0.0f), tbMakeVec2(0.25f, 1.0f), tbMakeVec2(0.75f, 3.0f));
	cr_expect_float_eq(r.distanceSquared, 1.0f, 1e-6f);
	cr_expect_float_eq(r.fraction1, 0.25f, 1e-6f);
	cr_expect_float_eq(r.fraction2, 0.0f, 1e-6f);
}

Test(segment_distance, parallel_overlapping)
{
	// parallel at distance 0.5 with overlapping extents: any matching pair is a minimum
	tbSegmentDistanceResult r =
		tbSegmentDistance(tbMakeVec2(0.0f, 0.0f), tbMakeVec2(2.0f, 0.0f), tbMakeVec2(1.0f, 0.5f), tbMakeVec2(3.0f, 0.5f));
	cr_expect_float_eq(r.distanceSquared, 0.25f, 1e-6f);
	cr_expect_float_eq(r.closest2.y - r.closest1.y, 0.5f, 1e-6f);
	cr_expect_float_eq(r.closest1.x, r.closest2.x, 1e-6f);
	cr_expect(r.closest1.x >= 1.0f - 1e-6f && r.closest1.x <= 2.0f + 1e-6f);
}

Test(segment_distance, parallel_disjoint_and_antiparallel)
{
	// collinear, 1 m gap between the ends; second segment reversed
	tbSegmentDistanceResult r =
		tbSegmentDistance(tbMakeVec2(0.0f, 0.0f), tbMakeVec2(1.0f, 0.0f), tbMakeVec2(3.0f, 0.0f), tbMakeVec2(2.0f, 0.0f));
	cr_expect_float_eq(r.distanceSquared, 1.0f, 1e-6f);
	cr_expect_float_eq(r.fraction1, 1.0f, 1e-6f);
	cr_expect_float_eq(r.fraction2, 1.0f, 1e-6f);

	// nearly parallel (1e-5 rad): must not blow up
	tbSegmentDistanceResult s = tbSegmentDistance(tbMakeVec2(0.0f, 0.0f), tbMakeVec2(1.0f, 0.0f), tbMakeVec2(0.0f, 0.1f),
												  tbMakeVec2(1.0f, 0.10001f));
	cr_expect(isfinite(s.distanceSquared));
	cr_expect_float_eq(sqrtf(s.distanceSquared), 0.1f, 1e-5f);
}

Test(segment_distance, degenerate_points)
{
	tbVec2 p = {1.0f, 1.0f};
	tbVec2 q = {4.0f, 5.0f};
	tbSegmentDistanceResult both = tbSegmentDistance(p, p, q, q);
	cr_expect_float_eq(both.distanceSquared, 25.0f, 1e-5f);

	// point against segment: (0.5, 2) above the unit segment on the x axis
	tbSegmentDistanceResult first =
		tbSegmentDistance(tbMakeVec2(0.5f, 2.0f), tbMakeVec2(0.5f, 2.0f), tbMakeVec2(0.0f, 0.0f), tbMakeVec2(1.0f, 0.0f));
	cr_expect_float_eq(first.distanceSquared, 4.0f, 1e-6f);
	cr_expect_float_eq(first.fraction2, 0.5f, 1e-6f);

	tbSegmentDistanceResult second =
		tbSegmentDistance(tbMakeVec2(0.0f, 0.0f), tbMakeVec2(1.0f, 0.0f), tbMakeVec2(2.0f, 1.0f), tbMakeVec2(2.0f, 1.0f));
	cr_expect_float_eq(second.distanceSquared, 2.0f, 1e-6f);
	cr_expect_float_eq(second.fraction1, 1.0f, 1e-6f);
}

// ---------------------------------------------------------------------------------------------
// GJK

Test(gjk, proxies_of_shapes)
{
	tbGeometry circle = {.type = tb_circleShape, .circle = {{1.0f, 2.0f}, 0.5f}};
	tbShapeProxy p = tbMakeShapeProxy(&circle);
	cr_expect_eq(p.count, 1);
	cr_expect_float_eq(p.radius, 0.5f, 0.0f);

	tbGeometry capsule = {.type = tb_capsuleShape, .capsule = {{0.0f, 0.0f}, {1.0f, 0.0f}, 0.25f}};
	p = tbMakeShapeProxy(&capsule);
	cr_expect_eq(p.count, 2);
	cr_expect_float_eq(p.radius, 0.25f, 0.0f);

	tbGeometry segment = {.type = tb_segmentShape, .segment = {{0.0f, 0.0f}, {1.0f, 1.0f}}};
	p = tbMakeShapeProxy(&segment);
	cr_expect_eq(p.count, 2);
	cr_expect_float_eq(p.radius, 0.0f, 0.0f);

	tbGeometry box = {.type = tb_polygonShape, .polygon = tbMakeBox(1.0f, 2.0f)};
	p = tbMakeShapeProxy(&box);
	cr_expect_eq(p.count, 4);
}

Test(gjk, circle_circle_closed_form)
{
	for (int i = 0; i < 1000; ++i)
	{
		tbVec2 c1 = {RandomFloat(&lcgState, -5.0f, 5.0f), RandomFloat(&lcgState, -5.0f, 5.0f)};
		tbVec2 c2 = {RandomFloat(&lcgState, -5.0f, 5.0f), RandomFloat(&lcgState, -5.0f, 5.0f)};
		float r1 = RandomFloat(&lcgState, 0.05f, 1.0f), r2 = RandomFloat(&lcgState, 0.05f, 1.0f);
		tbDistanceInput input = {0};
		input.proxyA = tbMakeProxy(&c1, 1, r1);
		input.proxyB = tbMakeProxy(&c2, 1, r2);
		input.transform = tbTransform_identity;
		input.useRadii = true;
		tbDistanceOutput out = tbShapeDistance(&input, NULL, NULL, 0);

		float centres = tbDistance(c1, c2);
		float expected = fmaxf(centres - r1 - r2, 0.0f);
		cr_assert_float_eq(out.distance, expected, DISTANCE_TOLERANCE, "pair %d", i);
		if (expected > 0.0f)
		{
			tbVec2 n = tbNormalize(tbSub(c2, c1));
			cr_expect_float_eq(out.normal.x, n.x, 1e-5f);
			cr_expect_float_eq(out.normal.y, n.y, 1e-5f);
			tbVec2 pA = tbMulAdd(c1, r1, n);
			cr_expect_float_eq(out.pointA.x, pA.x, DISTANCE_TOLERANCE);
			cr_expect_float_eq(out.pointA.y, pA.y, DISTANCE_TOLERANCE);
		}
	}
}

Test(gjk, random_polygons_match_brute_force)
{
	float largest = 0.0f;
	int overlaps = 0;
	for (int i = 0; i < 5000; ++i)
	{
		tbPolygon a = randomPolygon(RandomFloat(&lcgState, 0.1f, 3.0f));
		tbPolygon b = randomPolygon(RandomFloat(&lcgState, 0.1f, 3.0f));
		tbTransform xfA = randomTransform(4.0f);
		tbTransform xfB = randomTransform(4.0f);
		tbDistanceInput input = makeInput(&a, xfA, &b, xfB);
		tbDistanceOutput out = distanceInWorld(&input, xfA);

		float expected = bruteForceDistance(&a, xfA, &b, xfB);
		overlaps += expected == 0.0f;
		largest = fmaxf(largest, fabsf(out.distance - expected));
		cr_assert_float_eq(out.distance, expected, DISTANCE_TOLERANCE, "pair %d: gjk %g brute %g", i, (double)out.distance,
						   (double)expected);
		if (expected > DISTANCE_TOLERANCE)
		{
			// the witness points are on the shapes and their distance is the distance
			cr_assert_float_eq(tbDistance(out.pointA, out.pointB), out.distance, DISTANCE_TOLERANCE);
			cr_assert(tbIsNormalized(out.normal));
			cr_assert(out.iterations <= 20);
		}
	}
	printf("gjk vs brute force: largest difference %g m, %d overlapping of 5000\n", (double)largest, overlaps);
}

Test(gjk, warm_start_same_answer_fewer_iterations)
{
	for (int i = 0; i < 2000; ++i)
	{
		tbPolygon a = randomPolygon(RandomFloat(&lcgState, 0.1f, 3.0f));
		tbPolygon b = randomPolygon(RandomFloat(&lcgState, 0.1f, 3.0f));
		tbDistanceInput input = makeInput(&a, randomTransform(4.0f), &b, randomTransform(4.0f));

		tbSimplexCache cache = {0};
		tbDistanceOutput cold = tbShapeDistance(&input, &cache, NULL, 0);
		cr_assert(cache.count >= 1 && cache.count <= 3);
		tbDistanceOutput warm = tbShapeDistance(&input, &cache, NULL, 0);
		cr_assert_float_eq(warm.distance, cold.distance, DISTANCE_TOLERANCE, "pair %d", i);
		cr_assert(warm.iterations <= cold.iterations, "pair %d: warm %d cold %d", i, warm.iterations, cold.iterations);
	}
}

Test(gjk, warm_start_after_small_motion)
{
	// a box sliding past another: the cache from the last position must give the right distance
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbSimplexCache cache = {0};
	for (int i = 0; i < 100; ++i)
	{
		tbTransform xfB = {{-2.0f + 0.04f * (float)i, 1.1f}, tbMakeRot(0.0f)};
		tbDistanceInput input = makeInput(&box, tbTransform_identity, &box, xfB);
		tbDistanceOutput warm = tbShapeDistance(&input, &cache, NULL, 0);
		tbDistanceOutput cold = tbShapeDistance(&input, NULL, NULL, 0);
		cr_assert_float_eq(warm.distance, cold.distance, DISTANCE_TOLERANCE, "step %d", i);
	}
}

Test(gjk, tiny_edges_do_not_overlap)
{
	// 1 mm squares (half-width 0.5 mm) with a 1 mm gap, in many orientations and offsets; also a
	// sliver polygon with a 2 mm edge. The distance must be the gap, never an overlap. The
	// tolerance is relative to the 1 mm size: 1e-7 m (~ 100 float ulps at 1 mm).
	tbPolygon tiny = tbMakeBox(0.0005f, 0.0005f);
	for (int i = 0; i < 360; ++i)
	{
		float slide = RandomFloat(&lcgState, -0.0009f, 0.0009f);
		tbTransform xfA = {{0.0f, 0.0f}, tbMakeRot(0.0f)};
		tbTransform xfB = {{slide, 0.002f}, tbMakeRot(0.0f)};
		tbRot turn = tbMakeRot((float)i * TB_PI / 180.0f);
		xfA.q = turn;
		xfB.q = turn;
		xfB.p = tbRotateVector(turn, xfB.p);
		tbDistanceInput input = makeInput(&tiny, xfA, &tiny, xfB);
		tbDistanceOutput out = distanceInWorld(&input, xfA);
		cr_assert(out.simplexCount < 3, "angle %d overlap reported", i);
		cr_assert_float_eq(out.distance, 0.001f, 1e-7f, "angle %d: %g", i, (double)out.distance);
	}

	// The hull routine welds points closer than TB_LINEAR_SLOP, so the sliver is a hand-built proxy.
	tbVec2 sliver[3] = {{0.0f, 0.0f}, {0.002f, 0.0f}, {0.001f, 0.0006f}};
	tbDistanceInput input = {0};
	input.proxyA = tbMakeProxy(sliver, 3, 0.0f);
	input.proxyB = tbMakeProxy(sliver, 3, 0.0f);
	input.transform = tbTransform_identity;
	for (int i = 0; i < 100; ++i)
	{
		// copy turned by π: its base runs 1 mm under A's base, parallel edges, 1 mm gap
		float slide = RandomFloat(&lcgState, -0.0009f, 0.0009f);
		input.transform = (tbTransform){{0.002f + slide, -0.001f}, tbMakeRot(TB_PI)}; // A at the origin
		tbDistanceOutput out = tbShapeDistance(&input, NULL, NULL, 0);
		cr_assert(out.simplexCount < 3);
		cr_assert_float_eq(out.distance, 0.001f, 1e-7f, "%g", (double)out.distance);
	}
}

Test(gjk, far_from_origin)
{
	// unit boxes 1 cm apart near (1000, -1000): the answer must match the same pair at the
	// origin. At 1000 m a float resolves 6e-5 m, so a world-frame GJK would be off by that much;
	// in A's frame the error stays at the 1e-6 level (tolerance 2e-6 m).
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	for (int i = 0; i < 100; ++i)
	{
		float angle = RandomFloat(&lcgState, -TB_PI, TB_PI);
		tbVec2 offset = tbRotateVector(tbMakeRot(angle), tbMakeVec2(1.01f, RandomFloat(&lcgState, -0.5f, 0.5f)));
		tbTransform xfA = {{1000.0f, -1000.0f}, tbMakeRot(angle)};
		tbTransform xfB = {tbAdd(xfA.p, offset), tbMakeRot(angle)};
		tbTransform nearA = {{0.0f, 0.0f}, tbMakeRot(angle)};
		tbTransform nearB = {offset, tbMakeRot(angle)};

		tbDistanceInput far = makeInput(&box, xfA, &box, xfB);
		tbDistanceInput near = makeInput(&box, nearA, &box, nearB);
		tbDistanceOutput outFar = distanceInWorld(&far, xfA);
		tbDistanceOutput outNear = distanceInWorld(&near, nearA);
		cr_assert(outFar.simplexCount < 3);
		// xfB.p was rounded at 1000 m (6e-5 m): compare with the gap it actually encodes
		tbVec2 actualOffset = tbInvRotateVector(xfA.q, tbSub(xfB.p, xfA.p));
		cr_assert_float_eq(outFar.distance, actualOffset.x - 1.0f, 2e-6f, "case %d", i);
		cr_assert_float_eq(outNear.distance, 0.01f, 2e-6f, "case %d", i);
	}
}

// ---------------------------------------------------------------------------------------------
// Shape cast

Test(shape_cast, circles_match_closed_form)
{
	// B (radius rB at cB) moves by r; first contact at the smallest t with |cB + t·r − cA| = rA + rB.
	// The cast stops within TB_TOI_TARGET_SEPARATION (1.25 mm) before touching, never after.
	int hits = 0;
	for (int i = 0; i < 1000; ++i)
	{
		tbVec2 cA = {0.0f, 0.0f};
		tbVec2 cB = {RandomFloat(&lcgState, -5.0f, 5.0f), RandomFloat(&lcgState, -5.0f, 5.0f)};
		float rA = RandomFloat(&lcgState, 0.1f, 1.0f), rB = RandomFloat(&lcgState, 0.1f, 1.0f);
		if (tbLength(cB) < rA + rB + 0.01f)
		{
			continue;
		}
		tbVec2 r = {RandomFloat(&lcgState, -10.0f, 10.0f), RandomFloat(&lcgState, -10.0f, 10.0f)};

		tbShapeCastPairInput input = {0};
		input.proxyA = tbMakeProxy(&cA, 1, rA);
		input.proxyB = tbMakeProxy(&cB, 1, rB);
		input.transform = tbTransform_identity;
		input.translationB = r;
		input.maxFraction = 1.0f;
		tbCastOutput out = tbShapeCast(&input);

		// |d + t·r|² = R² with d = cB − cA: (r·r)t² + 2(d·r)t + d·d − R² = 0
		float R = rA + rB;
		float qa = tbDot(r, r), qb = 2.0f * tbDot(cB, r), qc = tbDot(cB, cB) - R * R;
		float disc = qb * qb - 4.0f * qa * qc;
		float t = disc >= 0.0f ? (-qb - sqrtf(disc)) / (2.0f * qa) : 2.0f;
		bool expectHit = disc >= 0.0f && t >= 0.0f && t <= 1.0f;

		// near-grazing paths are ambiguous within the tolerance: skip them
		float closest = fabsf(tbCross(cB, tbNormalize(r)));
		if (fabsf(closest - R) < 2.0f * TB_TOI_TARGET_SEPARATION || fabsf(t - 1.0f) < 1e-3f)
		{
			continue;
		}
		cr_assert_eq(out.hit, expectHit, "case %d", i);
		if (expectHit)
		{
			++hits;
			cr_assert(out.fraction <= t + 1e-5f, "case %d: %g > %g", i, (double)out.fraction, (double)t);
			float gap = tbLength(tbMulAdd(cB, out.fraction, r)) - R;
			cr_assert(gap >= -1e-5f && gap <= TB_TOI_TARGET_SEPARATION + 1e-5f, "case %d gap %g", i, (double)gap);
			tbVec2 n = tbNormalize(tbMulAdd(cB, out.fraction, r));
			cr_assert_float_eq(out.normal.x, n.x, 1e-4f);
			cr_assert_float_eq(out.normal.y, n.y, 1e-4f);
			cr_assert_float_eq(out.point.x, rA * n.x, 1e-4f);
		}
	}
	cr_assert(hits > 50);
}

Test(shape_cast, box_drop_onto_box_far_away)
{
	// a unit box 1 m above another at (1000, 1000), falling 2 m: hit after 1 m of the 2 m drop
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbShapeCastPairInput input = {0};
	input.proxyA = tbMakeProxy(box.vertices, 4, 0.0f);
	input.proxyB = tbMakeProxy(box.vertices, 4, 0.0f);
	tbTransform xfA = {{1000.0f, 1000.0f}, tbRot_identity}, xfB = {{1000.0f, 1002.0f}, tbRot_identity};
	input.transform = tbInvMulTransforms(xfA, xfB); // exact here: the answer does not depend on where the pair is
	input.translationB = tbMakeVec2(0.0f, -2.0f);
	input.maxFraction = 1.0f;
	tbCastOutput out = tbShapeCast(&input);
	cr_assert(out.hit);
	// the cast stops at a gap in [target, target + tolerance] = [1.25 mm, 2.5 mm]
	cr_assert(out.fraction <= 0.5f && out.fraction >= 0.5f - 2.0f * TB_TOI_TARGET_SEPARATION / 2.0f,
			  "%g", (double)out.fraction);
	cr_assert_float_eq(out.normal.y, 1.0f, 1e-5f);

	input.translationB = tbMakeVec2(0.0f, 2.0f); // moving away
	out = tbShapeCast(&input);
	cr_assert(out.hit == false);
}

// Shapes that start within the target separation have no direction of first contact. The
// defined answer (Box2D v3's): hit at fraction 0, normal (0, 0), the point halfway between the
// surfaces. Before: concentric circles and a zero translation gave a hit with a zero normal and a
// point on A's core, touching boxes a normal along −translation; now every such start answers
// the same documented way.
static tbShapeCastPairInput CircleCast(tbVec2 centerB, float radiusA, float radiusB, tbVec2 translation)
{
	tbVec2 origin = {0.0f, 0.0f};
	tbShapeCastPairInput input = {0};
	input.proxyA = tbMakeProxy(&origin, 1, radiusA);
	input.proxyB = tbMakeProxy(&origin, 1, radiusB);
	input.transform = (tbTransform){centerB, tbRot_identity}; // A at the origin
	input.translationB = translation;
	input.maxFraction = 1.0f;
	return input;
}

Test(shape_cast, initial_overlap_hits_at_zero_with_zero_normal)
{
	// concentric circles, moving or not
	tbVec2 moves[2] = {{1.0f, 0.0f}, {0.0f, 0.0f}};
	for (int i = 0; i < 2; ++i)
	{
		tbShapeCastPairInput input = CircleCast(tbMakeVec2(0.0f, 0.0f), 0.5f, 0.25f, moves[i]);
		tbCastOutput out = tbShapeCast(&input);
		cr_assert(out.hit);
		cr_assert(out.fraction == 0.0f && out.normal.x == 0.0f && out.normal.y == 0.0f);
		cr_assert(out.point.x == 0.0f && out.point.y == 0.0f, "the common centre");
	}

	// circles overlapping by 0.25 m (centres 0.5 m apart, radii 0.5 + 0.25): the point is halfway
	// between A's surface point (0.5, 0) and B's (0.5 − 0.25, 0), i.e. x = 0.375, exact in float
	tbShapeCastPairInput input = CircleCast(tbMakeVec2(0.5f, 0.0f), 0.5f, 0.25f, tbMakeVec2(-1.0f, 0.0f));
	tbCastOutput out = tbShapeCast(&input);
	cr_assert(out.hit && out.fraction == 0.0f && out.normal.x == 0.0f && out.normal.y == 0.0f);
	cr_assert_float_eq(out.point.x, 0.375f, 1e-6f);
	cr_assert_float_eq(out.point.y, 0.0f, 1e-6f);

	// boxes touching face to face, B moving along the face: the same answer, in A's frame
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	input = (tbShapeCastPairInput){0};
	input.proxyA = tbMakeProxy(box.vertices, 4, 0.0f);
	input.proxyB = tbMakeProxy(box.vertices, 4, 0.0f);
	input.transform = tbInvMulTransforms((tbTransform){{10.0f, 20.0f}, tbRot_identity},
										 (tbTransform){{10.0f, 21.0f}, tbRot_identity});
	input.translationB = tbMakeVec2(1.0f, 0.0f);
	input.maxFraction = 1.0f;
	out = tbShapeCast(&input);
	cr_assert(out.hit && out.fraction == 0.0f && out.normal.x == 0.0f && out.normal.y == 0.0f);
	cr_assert_float_eq(out.point.y, 0.5f, 1e-5f, "on the shared face (A's frame)");

	// apart and not moving: no hit
	input = CircleCast(tbMakeVec2(2.0f, 0.0f), 0.5f, 0.25f, tbMakeVec2(0.0f, 0.0f));
	cr_assert_not(tbShapeCast(&input).hit);
}

// ---------------------------------------------------------------------------------------------
// The gap bound the narrow phase keeps pairs apart on (tbShapeGapBound, contact.c tbStaysApart)

// One of the five kinds of shape the narrow phase meets, about `size` metres, kind by index.
static tbGeometry randomGeometry(int kind, float size)
{
	tbGeometry g = {0};
	tbVec2 p = {RandomFloat(&lcgState, -0.2f * size, 0.2f * size), RandomFloat(&lcgState, -0.2f * size, 0.2f * size)};
	tbVec2 q = {RandomFloat(&lcgState, -size, size), RandomFloat(&lcgState, -size, size)};
	float radius = RandomFloat(&lcgState, 0.05f, 0.5f) * size;
	switch (kind % 5)
	{
		case 0:
			g.type = tb_circleShape;
			g.circle = (tbCircle){p, radius};
			break;
		case 1:
			g.type = tb_capsuleShape;
			g.capsule = (tbCapsule){p, q, radius};
			break;
		case 2:
			g.type = tb_segmentShape;
			g.segment = (tbSegment){p, q};
			break;
		case 3:
			g.type = tb_polygonShape;
			g.polygon = randomPolygon(size);
			break;
		default:
			g.type = tb_polygonShape;
			g.polygon = randomPolygon(size);
			g.polygon.radius = 0.2f * radius; // rounded
			break;
	}
	return g;
}

static tbShapeProxy geometryProxy(const tbGeometry* g)
{
	return tbMakeShapeProxy(g);
}

// The bound is the shapes' distance less the allowance: checked against GJK with radii (the
// independent path of tbShapeDistance, DISTANCE_TOLERANCE as above). And a manifold computed with a
// keep distance just under the bound has no point: the narrow phase, SAT or GJK, agrees that the
// pair is apart (what tbStaysApart relies on). Pairs are placed 0 to 1 m apart, most within reach of
// a margin.
Test(gap_bound, is_the_distance_less_the_allowance_and_no_manifold_point_lies_within_it)
{
	lcgState = 777u;
	int checked = 0, apart = 0;
	for (int trial = 0; trial < 4000; ++trial)
	{
		tbGeometry a = randomGeometry(trial, 1.0f);
		tbGeometry b = randomGeometry(trial / 5, 1.0f);
		if (a.type == tb_segmentShape && b.type == tb_segmentShape)
		{
			continue; // the narrow phase has no segment–segment pair
		}
		tbTransform xfA = randomTransform(3.0f);
		tbTransform xfB = randomTransform(3.0f);
		tbTransform relative = tbInvMulTransforms(xfA, xfB);
		float gap = tbShapeGapBound(&a, &b, relative);

		tbDistanceInput input = {0};
		input.proxyA = geometryProxy(&a);
		input.proxyB = geometryProxy(&b);
		input.transform = relative;
		input.useRadii = true;
		float distance = tbShapeDistance(&input, NULL, NULL, 0).distance;
		if (distance > 0.0f)
		{
			cr_assert_float_eq(gap, distance - TB_GAP_ALLOWANCE, DISTANCE_TOLERANCE,
							   "trial %d (types %d, %d): bound %g, distance %g", trial, a.type, b.type, (double)gap,
							   (double)distance);
			checked += 1;
		}
		else
		{
			cr_assert_leq(gap, DISTANCE_TOLERANCE - TB_GAP_ALLOWANCE, "trial %d: overlapping shapes, bound %g", trial,
						  (double)gap);
		}
		if (gap <= 0.0f)
		{
			continue;
		}
		apart += 1;
		float keep = gap * (1.0f - 1e-6f);
		for (int method = 0; method < 2; ++method)
		{
			tbManifold m = tbCollideShapesWithMargin(&a, xfA, &b, xfB, method == 0 ? tb_narrowPhaseSAT : tb_narrowPhaseGJK,
													 keep);
			cr_assert_eq(m.pointCount, 0, "trial %d (types %d, %d, method %d): a point %g m apart under a bound of %g m",
						 trial, a.type, b.type, method, (double)m.points[0].separation, (double)gap);
		}
	}
	cr_assert_gt(checked, 2000);
	cr_assert_gt(apart, 1000);
}

// Far from A's body origin (a ground whose boxes or chain lie kilometres from the ground body's
// origin) the narrow phase's separations carry the rounding of those coordinates; the bound takes it
// off (TB_GAP_SCALE_ALLOWANCE). A box 1 km and 5 km from its origin, a capsule lying nearly flat
// 2 to 6 cm above its top face: no SAT or GJK manifold point may lie within the bound.
Test(gap_bound, holds_far_from_the_first_shapes_origin)
{
	lcgState = 99u;
	int apart = 0;
	const float offsets[2] = {1000.0f, 5000.0f};
	for (int k = 0; k < 2; ++k)
	{
		float R = offsets[k];
		for (int trial = 0; trial < 2000; ++trial)
		{
			tbGeometry a = {0};
			a.type = tb_polygonShape;
			a.polygon = tbMakeOffsetBox(RandomFloat(&lcgState, 0.5f, 3.0f), 0.5f, tbMakeVec2(R, 0.0f), tbMakeRot(0.0f));
			tbGeometry b = {0};
			b.type = tb_capsuleShape;
			float radius = RandomFloat(&lcgState, 0.05f, 0.3f);
			b.capsule = (tbCapsule){{-0.6f, 0.0f}, {0.6f, 0.0f}, radius};
			float gap = RandomFloat(&lcgState, 0.02f, 0.06f);
			tbTransform xfA = tbTransform_identity;
			tbTransform xfB = {{R + RandomFloat(&lcgState, -1.0f, 1.0f), 0.5f + radius + gap},
							   tbMakeRot(RandomFloat(&lcgState, -0.02f, 0.02f))};
			float bound = tbShapeGapBound(&a, &b, tbInvMulTransforms(xfA, xfB));
			if (bound <= 0.0f)
			{
				continue;
			}
			apart += 1;
			for (int method = 0; method < 2; ++method)
			{
				tbManifold m = tbCollideShapesWithMargin(&a, xfA, &b, xfB, method == 0 ? tb_narrowPhaseSAT : tb_narrowPhaseGJK,
														 bound * (1.0f - 1e-6f));
				cr_assert_eq(m.pointCount, 0, "R %g trial %d method %d: a point %g m apart under a bound of %g m",
							 (double)R, trial, method, (double)m.points[0].separation, (double)bound);
			}
		}
	}
	cr_assert_gt(apart, 3000);
}
