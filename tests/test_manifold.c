// Contact manifolds: every shape pair against closed-form answers (normal, separation, points,
// count), the dispatcher's order swap, and robustness (touching, deep, identical, tiny, large,
// far from the origin, near-parallel faces, the speculative margin, finiteness).
//
// Tolerances: TB_EPS = 1e-5 m is about 100 float ulps at 1 m (FLT_EPSILON ≈ 1.2e-7), room for
// the dozen operations of a manifold; scaled cases give their own, each with its reason.
#include <criterion/criterion.h>

#include "tumble/collision.h"

#include <math.h>

#define TB_EPS 1e-5f

static tbTransform tbMakeTransform(float x, float y, float angle)
{
	tbTransform xf = {{x, y}, tbMakeRot(angle)};
	return xf;
}

static tbGeometry tbCircleGeometry(float x, float y, float radius)
{
	tbGeometry g = {.type = tb_circleShape};
	g.circle = (tbCircle){{x, y}, radius};
	return g;
}

static tbGeometry tbCapsuleGeometry(tbVec2 c1, tbVec2 c2, float radius)
{
	tbGeometry g = {.type = tb_capsuleShape};
	g.capsule = (tbCapsule){c1, c2, radius};
	return g;
}

static tbGeometry tbSegmentGeometry(tbVec2 p1, tbVec2 p2)
{
	tbGeometry g = {.type = tb_segmentShape};
	g.segment = (tbSegment){p1, p2};
	return g;
}

static tbGeometry tbBoxGeometry(float hx, float hy)
{
	tbGeometry g = {.type = tb_polygonShape};
	g.polygon = tbMakeBox(hx, hy);
	return g;
}

static void tbExpectVec(tbVec2 actual, float x, float y, float tolerance)
{
	cr_expect_float_eq(actual.x, x, tolerance, "x: %.9g vs %.9g", (double)actual.x, (double)x);
	cr_expect_float_eq(actual.y, y, tolerance, "y: %.9g vs %.9g", (double)actual.y, (double)y);
}

// Finite numbers everywhere, a unit normal when there are points, at most two points.
static void tbExpectSane(const tbManifold* m)
{
	cr_expect(m->pointCount >= 0 && m->pointCount <= 2);
	cr_expect(isfinite(m->normal.x) && isfinite(m->normal.y));
	if (m->pointCount > 0)
	{
		// Unit length to 1e-5: a normalised float vector is within a few ulps of 1.
		cr_expect_float_eq(tbLength(m->normal), 1.0f, 1e-5f);
	}
	for (int i = 0; i < m->pointCount; ++i)
	{
		cr_expect(isfinite(m->points[i].point.x) && isfinite(m->points[i].point.y));
		cr_expect(isfinite(m->points[i].separation));
		cr_expect_lt(m->points[i].separation, TB_SPECULATIVE_DISTANCE);
	}
}

// The point of m whose x is nearest to x (two-point manifolds come in clip order).
static const tbManifoldPoint* tbPointNearX(const tbManifold* m, float x)
{
	const tbManifoldPoint* best = &m->points[0];
	for (int i = 1; i < m->pointCount; ++i)
	{
		if (fabsf(m->points[i].point.x - x) < fabsf(best->point.x - x))
		{
			best = &m->points[i];
		}
	}
	return best;
}

// ---------------------------------------------------------------------------------------------
// Closed forms

Test(manifold, circles)
{
	// Centres 1.5 apart, radii 1 and 1: overlap 0.5, surfaces at x = 1 (A) and 0.5 (B), midpoint 0.75.
	tbCircle a = {{0.0f, 0.0f}, 1.0f};
	tbCircle b = {{0.0f, 0.0f}, 1.0f};
	tbManifold m = tbCollideCircles(&a, tbMakeTransform(0, 0, 0), &b, tbMakeTransform(1.5f, 0, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 1.0f, 0.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.5f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.75f, 0.0f, TB_EPS);
	tbExpectVec(m.points[0].anchorA, 0.0f, 0.0f, 0.0f);

	// Off-centre circle on a rotated body: A's local centre (1, 0) turned by 90° sits at (0, 1);
	// B at (0, 3) radius 0.5: gap 3 − 1 − 1 − 0.5 = 0.5 → beyond the speculative distance.
	tbCircle offset = {{1.0f, 0.0f}, 1.0f};
	tbCircle small = {{0.0f, 0.0f}, 0.5f};
	m = tbCollideCircles(&offset, tbMakeTransform(0, 0, 0.5f * TB_PI), &small, tbMakeTransform(0, 3.0f, 0));
	cr_expect_eq(m.pointCount, 0);
	// B at (0, 2.49): gap −0.01, normal +y, surfaces at y = 2 and 1.99, midpoint 1.995.
	m = tbCollideCircles(&offset, tbMakeTransform(0, 0, 0.5f * TB_PI), &small, tbMakeTransform(0, 2.49f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.0f, 1.995f, TB_EPS);
}

Test(manifold, concentric_circles_defined_normal)
{
	// Same centre: the normal is A's x-axis (A turned by 0.3 rad), separation −(rA + rB).
	tbCircle a = {{0.0f, 0.0f}, 0.5f};
	tbCircle b = {{0.0f, 0.0f}, 0.25f};
	tbTransform xf = tbMakeTransform(2.0f, -1.0f, 0.3f);
	tbManifold m = tbCollideCircles(&a, xf, &b, xf);
	cr_assert_eq(m.pointCount, 1);
	tbExpectSane(&m);
	tbExpectVec(m.normal, cosf(0.3f), sinf(0.3f), TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.75f, TB_EPS);
}

Test(manifold, capsule_and_circle)
{
	tbCapsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
	tbTransform identity = tbMakeTransform(0, 0, 0);

	// Side region: circle (0.5, 0.5) r 0.2 → gap 0.5 − 0.45 = 0.05 > speculative: none.
	tbCircle side = {{0.0f, 0.0f}, 0.2f};
	tbManifold m = tbCollideCapsuleAndCircle(&capsule, identity, &side, tbMakeTransform(0.5f, 0.5f, 0));
	cr_expect_eq(m.pointCount, 0);
	// At y = 0.44: gap −0.01, surfaces at 0.25 and 0.24, midpoint 0.245.
	m = tbCollideCapsuleAndCircle(&capsule, identity, &side, tbMakeTransform(0.5f, 0.44f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.5f, 0.245f, TB_EPS);

	// End region: circle at (1.3, 0) r 0.2: distance 0.3 from the end cap centre, overlap 0.15.
	m = tbCollideCapsuleAndCircle(&capsule, identity, &side, tbMakeTransform(1.3f, 0.0f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 1.0f, 0.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.15f, TB_EPS);
	tbExpectVec(m.points[0].point, 1.175f, 0.0f, TB_EPS);

	// Centre on the core: the capsule's side normal (+y), separation −(0.25 + 0.2).
	m = tbCollideCapsuleAndCircle(&capsule, identity, &side, tbMakeTransform(0.3f, 0.0f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectSane(&m);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.45f, TB_EPS);
}

Test(manifold, capsules_crossing_and_end_to_end)
{
	tbCapsule a = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
	tbCapsule b = {{0.0f, 0.0f}, {0.0f, 1.4f}, 0.25f};
	tbTransform identity = tbMakeTransform(0, 0, 0);

	// B standing on A: closest points (0, 0) and (0, 0.49): gap 0.49 − 0.5 = −0.01, one point.
	tbManifold m = tbCollideCapsules(&a, identity, &b, tbMakeTransform(0, 0.49f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.0f, 0.245f, TB_EPS);

	// Crossing cores (an X): every SAT axis gives core separation −0.7 (B's lower half reaches
	// 0.7 below A's axis), so the answer is an axis normal with separation −0.7 − 0.5 = −1.2.
	m = tbCollideCapsules(&a, identity, &b, tbMakeTransform(0, -0.7f, 0));
	cr_assert_geq(m.pointCount, 1);
	tbExpectSane(&m);
	cr_expect_float_eq(fabsf(m.normal.x) + fabsf(m.normal.y), 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -1.2f, TB_EPS);

	// Collinear, end to end: B from (1.3, 0) to (2.7, 0), radii 0.1: gap 0.3 − 0.2 = 0.1 → none;
	// 0.18 apart: gap −0.02 along +x.
	tbCapsule thin = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.1f};
	tbCapsule thinB = {{0.0f, 0.0f}, {1.4f, 0.0f}, 0.1f};
	m = tbCollideCapsules(&thin, identity, &thinB, tbMakeTransform(1.3f, 0, 0));
	cr_expect_eq(m.pointCount, 0);
	m = tbCollideCapsules(&thin, identity, &thinB, tbMakeTransform(1.18f, 0, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 1.0f, 0.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.02f, TB_EPS);
	tbExpectVec(m.points[0].point, 1.09f, 0.0f, TB_EPS);
}

Test(manifold, capsules_parallel_two_points)
{
	// A on the x axis from −1 to 1, B from −0.5 to 1.5 at y = 0.45, radii 0.25: overlap 0.05.
	// Clipping B to A's extent gives x = −0.5 (B's end) and x = 1 (A's end), both at the
	// midpoint height (0.25 + 0.2)/2 = 0.225.
	tbCapsule a = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
	tbCapsule b = {{-0.5f, 0.0f}, {1.5f, 0.0f}, 0.25f};
	tbManifold m = tbCollideCapsules(&a, tbMakeTransform(0, 0, 0), &b, tbMakeTransform(0, 0.45f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	const tbManifoldPoint* left = tbPointNearX(&m, -0.5f);
	const tbManifoldPoint* right = tbPointNearX(&m, 1.0f);
	cr_expect_neq(left, right);
	tbExpectVec(left->point, -0.5f, 0.225f, TB_EPS);
	tbExpectVec(right->point, 1.0f, 0.225f, TB_EPS);
	cr_expect_float_eq(left->separation, -0.05f, TB_EPS);
	cr_expect_float_eq(right->separation, -0.05f, TB_EPS);
	cr_expect_neq(left->id, right->id);

	// B upside down (centres swapped) and below A: the normal follows, −y.
	tbCapsule flipped = {{1.5f, 0.0f}, {-0.5f, 0.0f}, 0.25f};
	m = tbCollideCapsules(&a, tbMakeTransform(0, 0, 0), &flipped, tbMakeTransform(0, -0.45f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, -1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.05f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -0.05f, TB_EPS);
}

// ---------------------------------------------------------------------------------------------
// Polygons

Test(manifold, polygon_and_circle_regions)
{
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbTransform identity = tbMakeTransform(0, 0, 0);

	// Face region: circle (0, 0.89) r 0.4: gap 0.39 − 0.4 = −0.01, midpoint y = (0.5 + 0.49)/2.
	tbCircle circle = {{0.0f, 0.0f}, 0.4f};
	tbManifold m = tbCollidePolygonAndCircle(&box, identity, &circle, tbMakeTransform(0.2f, 0.89f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.2f, 0.495f, TB_EPS);

	// Vertex region: circle at (0.8, 0.8) r 0.5: from corner (0.5, 0.5) the offset is (0.3, 0.3),
	// distance 0.3·√2, separation 0.3·√2 − 0.5, normal (1, 1)/√2.
	tbCircle big = {{0.0f, 0.0f}, 0.5f};
	m = tbCollidePolygonAndCircle(&box, identity, &big, tbMakeTransform(0.8f, 0.8f, 0));
	cr_assert_eq(m.pointCount, 1);
	float d = 0.3f * sqrtf(2.0f);
	tbExpectVec(m.normal, sqrtf(0.5f), sqrtf(0.5f), TB_EPS);
	cr_expect_float_eq(m.points[0].separation, d - 0.5f, TB_EPS);
	// Surfaces: the corner and the circle's point 0.5 back from its centre, midpoint between.
	float mid = 0.5f * (0.5f + 0.8f - 0.5f * sqrtf(0.5f));
	tbExpectVec(m.points[0].point, mid, mid, TB_EPS);

	// Centre inside the box at (0, 0.3): the nearest face is the top, depth 0.2 + 0.1.
	tbCircle inside = {{0.0f, 0.0f}, 0.1f};
	m = tbCollidePolygonAndCircle(&box, identity, &inside, tbMakeTransform(0.0f, 0.3f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.3f, TB_EPS);

	// Hull triangle (−1, 0), (1, 0), (0, 1): circle above the apex at (0, 1.2) r 0.21 sits in the
	// apex's vertex region: normal +y, separation 0.2 − 0.21.
	tbVec2 points[3] = {{-1.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
	tbHull hull = tbComputeHull(points, 3);
	cr_assert_eq(hull.count, 3);
	tbPolygon triangle = tbMakePolygon(&hull, 0.0f);
	tbCircle apex = {{0.0f, 0.0f}, 0.21f};
	m = tbCollidePolygonAndCircle(&triangle, identity, &apex, tbMakeTransform(0.0f, 1.2f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
}

Test(manifold, polygon_and_capsule)
{
	// Capsule lying on a box: core at y = 0.74, radius 0.25 → gap −0.01 at both ends x = ±0.3,
	// midpoint height (0.5 + 0.49)/2.
	tbPolygon box = tbMakeBox(1.0f, 0.5f);
	tbCapsule capsule = {{-0.3f, 0.0f}, {0.3f, 0.0f}, 0.25f};
	tbTransform identity = tbMakeTransform(0, 0, 0);
	tbManifold m = tbCollidePolygonAndCapsule(&box, identity, &capsule, tbMakeTransform(0, 0.74f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, -0.3f)->point, -0.3f, 0.495f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, 0.3f)->point, 0.3f, 0.495f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -0.01f, TB_EPS);

	// Capsule standing upright on the box (turned 90°): one point under its lower cap.
	m = tbCollidePolygonAndCapsule(&box, identity, &capsule, tbMakeTransform(0.1f, 1.04f, 0.5f * TB_PI));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.1f, 0.495f, TB_EPS);
}

Test(manifold, box_resting_on_box)
{
	// Ground 10 × 1 at the origin, unit box at y = 0.99: 0.01 overlap at x = ±0.5,
	// midpoint y = (0.5 + 0.49)/2.
	tbPolygon ground = tbMakeBox(5.0f, 0.5f);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbManifold m = tbCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0, 0.99f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, -0.5f)->point, -0.5f, 0.495f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, 0.5f)->point, 0.5f, 0.495f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -0.01f, TB_EPS);
	cr_expect_neq(m.points[0].id, m.points[1].id);

	// Box tilted by 0.1 rad: its low corner is 0.1 below the high one → separations differ by
	// 1·sin 0.1 along the normal; the lower corner is the deeper one.
	float c = cosf(0.1f), s = sinf(0.1f);
	// Corners of the tilted box relative to its centre: (−0.5, −0.5) → (−0.5c + 0.5s, −0.5s − 0.5c),
	// (0.5, −0.5) → (0.5c + 0.5s, 0.5s − 0.5c). Centre at y = 0.5 + 0.5c + 0.5s − 0.01 puts the
	// lower-left corner 0.01 into the ground.
	float cy = 0.5f + 0.5f * c + 0.5f * s - 0.01f;
	m = tbCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0, cy, 0.1f));
	cr_assert_eq(m.pointCount, 1); // the other corner is 0.09 up: beyond the speculative distance
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, -0.5f * c + 0.5f * s, 0.495f, TB_EPS);
}

Test(manifold, rotated_box_vertex_on_box)
{
	// Unit box turned 45° stands on its corner: corner 0.5·√2 below its centre, 0.01 deep.
	tbPolygon ground = tbMakeBox(5.0f, 0.5f);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	float cy = 0.5f + 0.5f * sqrtf(2.0f) - 0.01f;
	tbManifold m = tbCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.3f, cy, 0.25f * TB_PI));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.3f, 0.495f, TB_EPS);

	// Same with the roles swapped (the small box is A): its face is never the reference, the
	// ground's face is, so the normal is −y and the point the same.
	m = tbCollidePolygons(&box, tbMakeTransform(0.3f, cy, 0.25f * TB_PI), &ground, tbMakeTransform(0, 0, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, -1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.3f, 0.495f, TB_EPS);
}

Test(manifold, rounded_boxes_corner_to_corner_gap)
{
	// Rounded boxes, core half-width 0.5, radius 0.1, B's core corner at (0.6, 0.6) facing A's
	// at (0.5, 0.5): gap 0.1·√2 − 0.2, normal along the diagonal, midpoint (0.55, 0.55).
	tbPolygon a = tbMakeRoundedBox(0.5f, 0.5f, 0.1f);
	tbPolygon b = tbMakeRoundedBox(0.5f, 0.5f, 0.1f);
	tbManifold m = tbCollidePolygons(&a, tbMakeTransform(0, 0, 0), &b, tbMakeTransform(1.1f, 1.1f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, sqrtf(0.5f), sqrtf(0.5f), TB_EPS);
	cr_expect_float_eq(m.points[0].separation, 0.1f * sqrtf(2.0f) - 0.2f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.55f, 0.55f, TB_EPS);
}

// ---------------------------------------------------------------------------------------------
// Segments

Test(manifold, segment_pairs)
{
	tbSegment segment = {{-2.0f, 0.0f}, {2.0f, 0.0f}};
	tbTransform identity = tbMakeTransform(0, 0, 0);

	// Circle r 0.5 at (1, 0.49): gap −0.01 along +y, midpoint y = (0 + −0.01)/2.
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbManifold m = tbCollideSegmentAndCircle(&segment, identity, &circle, tbMakeTransform(1.0f, 0.49f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 1.0f, -0.005f, TB_EPS);

	// Capsule lying on the segment below it: two points at the capsule's ends.
	tbCapsule capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.2f};
	m = tbCollideSegmentAndCapsule(&segment, identity, &capsule, tbMakeTransform(0.0f, -0.19f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, -1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -0.01f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, 0.5f)->point, 0.5f, 0.005f, TB_EPS);

	// Box resting on the segment: two points at the box's bottom corners.
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	m = tbCollideSegmentAndPolygon(&segment, identity, &box, tbMakeTransform(0.0f, 0.49f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, -0.5f)->point, -0.5f, -0.005f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, 0.5f)->point, 0.5f, -0.005f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
}

// ---------------------------------------------------------------------------------------------
// Dispatch

Test(manifold, dispatch_order_swap_flips_normal)
{
	tbGeometry shapes[4] = {
		tbCircleGeometry(0.0f, 0.0f, 0.5f),
		tbCapsuleGeometry((tbVec2){-0.5f, 0.0f}, (tbVec2){0.5f, 0.0f}, 0.3f),
		tbSegmentGeometry((tbVec2){-1.0f, 0.0f}, (tbVec2){1.0f, 0.0f}),
		tbBoxGeometry(0.5f, 0.4f),
	};
	tbTransform xfA = tbMakeTransform(0.1f, 0.0f, 0.2f);
	tbTransform xfB = tbMakeTransform(0.3f, 0.4f, -0.1f);
	for (int i = 0; i < 4; ++i)
	{
		for (int j = 0; j < 4; ++j)
		{
			tbManifold ab = tbCollideShapes(&shapes[i], xfA, &shapes[j], xfB, tb_narrowPhaseSAT);
			tbManifold ba = tbCollideShapes(&shapes[j], xfB, &shapes[i], xfA, tb_narrowPhaseSAT);
			tbExpectSane(&ab);
			bool segments = shapes[i].type == tb_segmentShape && shapes[j].type == tb_segmentShape;
			if (segments)
			{
				cr_expect_eq(ab.pointCount, 0, "segment–segment has no contact");
				continue;
			}
			cr_assert_geq(ab.pointCount, 1, "pair %d, %d overlaps", i, j);
			cr_assert_eq(ab.pointCount, ba.pointCount, "pair %d, %d", i, j);
			// One routine serves both orders: the normal flips exactly, points and depths agree.
			tbExpectVec(ba.normal, -ab.normal.x, -ab.normal.y, TB_EPS);
			if (i == j)
			{
				continue; // same-kind pairs run the routine with A and B exchanged: no ordering
			}
			for (int k = 0; k < ab.pointCount; ++k)
			{
				tbExpectVec(ba.points[k].point, ab.points[k].point.x, ab.points[k].point.y, TB_EPS);
				cr_expect_float_eq(ba.points[k].separation, ab.points[k].separation, TB_EPS);
				uint16_t swapped = (uint16_t)((ab.points[k].id >> 8) | (ab.points[k].id << 8));
				cr_expect_eq(ba.points[k].id, swapped);
			}
		}
	}

	// Dispatch reaches the named routine: polygon–circle gives the same as the direct call.
	tbManifold direct = tbCollidePolygonAndCircle(&shapes[3].polygon, xfA, &shapes[0].circle, xfB);
	tbManifold viaDispatch = tbCollideShapes(&shapes[0], xfB, &shapes[3], xfA, tb_narrowPhaseAuto);
	cr_assert_eq(direct.pointCount, 1);
	cr_assert_eq(viaDispatch.pointCount, 1);
	tbExpectVec(viaDispatch.normal, -direct.normal.x, -direct.normal.y, 0.0f);
	cr_expect_float_eq(viaDispatch.points[0].separation, direct.points[0].separation, 0.0f);

	// The method picks the polygon routine: GJK → tbCollidePolygonsGJK, auto → SAT (bit-exact).
	tbManifold gjk = tbCollidePolygonsGJK(&shapes[3].polygon, xfA, &shapes[3].polygon, xfB);
	tbManifold gjkDispatch = tbCollideShapes(&shapes[3], xfA, &shapes[3], xfB, tb_narrowPhaseGJK);
	cr_expect_eq(gjkDispatch.pointCount, gjk.pointCount);
	tbExpectVec(gjkDispatch.normal, gjk.normal.x, gjk.normal.y, 0.0f);
	tbManifold sat = tbCollidePolygons(&shapes[3].polygon, xfA, &shapes[3].polygon, xfB);
	tbManifold autoDispatch = tbCollideShapes(&shapes[3], xfA, &shapes[3], xfB, tb_narrowPhaseAuto);
	cr_expect_eq(autoDispatch.pointCount, sat.pointCount);
	tbExpectVec(autoDispatch.normal, sat.normal.x, sat.normal.y, 0.0f);
}

// ---------------------------------------------------------------------------------------------
// Robustness

Test(manifold, touching_shapes_zero_separation)
{
	// Exactly touching: separation 0 (to float rounding of the inputs, 1e-6 m).
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbManifold m = tbCollideCircles(&circle, tbMakeTransform(0, 0, 0), &circle, tbMakeTransform(1.0f, 0, 0));
	cr_assert_eq(m.pointCount, 1);
	cr_expect_float_eq(m.points[0].separation, 0.0f, 1e-6f);
	tbExpectVec(m.points[0].point, 0.5f, 0.0f, 1e-6f);

	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	m = tbCollidePolygons(&box, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.25f, 1.0f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-6f);
	cr_expect_float_eq(m.points[0].separation, 0.0f, 1e-6f);
	cr_expect_float_eq(m.points[1].separation, 0.0f, 1e-6f);
}

Test(manifold, deep_and_identical_shapes)
{
	tbTransform xf = tbMakeTransform(3.0f, -2.0f, 0.7f);

	// Identical boxes, same place: a face normal, depth 2·0.5, two points, all finite.
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbManifold m = tbCollidePolygons(&box, xf, &box, xf);
	tbExpectSane(&m);
	cr_assert_eq(m.pointCount, 2);
	cr_expect_float_eq(m.points[0].separation, -1.0f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -1.0f, TB_EPS);

	// Identical capsules, identical circles, identical segment polygons.
	tbCapsule capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.2f};
	m = tbCollideCapsules(&capsule, xf, &capsule, xf);
	tbExpectSane(&m);
	cr_assert_geq(m.pointCount, 1);
	cr_expect_float_eq(m.points[0].separation, -0.4f, TB_EPS);
	tbCircle circle = {{0.0f, 0.0f}, 0.3f};
	m = tbCollidePolygonAndCircle(&box, xf, &circle, xf);
	tbExpectSane(&m);
	cr_assert_eq(m.pointCount, 1);
	cr_expect_float_eq(m.points[0].separation, -0.8f, TB_EPS);

	// Deep: a small box 0.8 into a big one: depth along the shortest way out (the top face).
	tbPolygon big = tbMakeBox(2.0f, 1.0f);
	tbPolygon small = tbMakeBox(0.25f, 0.25f);
	m = tbCollidePolygons(&big, tbMakeTransform(0, 0, 0), &small, tbMakeTransform(0.0f, 0.45f, 0));
	tbExpectSane(&m);
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.8f, TB_EPS);
}

Test(manifold, tiny_and_large_shapes)
{
	// 1 mm boxes, 0.1 mm overlap: tolerance 1e-8 m is ~100 ulps at 1e-3 m.
	tbPolygon tiny = tbMakeBox(0.0005f, 0.0005f);
	tbManifold m = tbCollidePolygons(&tiny, tbMakeTransform(0, 0, 0), &tiny, tbMakeTransform(0, 0.0009f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-6f);
	cr_expect_float_eq(m.points[0].separation, -0.0001f, 1e-8f);
	cr_expect_float_eq(m.points[1].separation, -0.0001f, 1e-8f);

	// 100 m boxes, 1 cm overlap: ulp at 100 m is 7.6e-6 m, allow 5e-5 m.
	tbPolygon large = tbMakeBox(50.0f, 50.0f);
	m = tbCollidePolygons(&large, tbMakeTransform(0, 0, 0), &large, tbMakeTransform(10.0f, 99.99f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-6f);
	cr_expect_float_eq(m.points[0].separation, -0.01f, 5e-5f);
	cr_expect_float_eq(m.points[1].separation, -0.01f, 5e-5f);

	// 1 mm circles: 0.01 mm overlap.
	tbCircle dot = {{0.0f, 0.0f}, 0.0005f};
	m = tbCollideCircles(&dot, tbMakeTransform(0, 0, 0), &dot, tbMakeTransform(0.00099f, 0, 0));
	cr_assert_eq(m.pointCount, 1);
	cr_expect_float_eq(m.points[0].separation, -0.00001f, 1e-9f);
}

Test(manifold, far_from_origin)
{
	// At (1000, 1000) the float ulp is 6.1e-5 m; working in A's frame keeps the separation to
	// the rounding of the input positions, allow 1.5e-4 m (2.5 ulps) and 1e-5 on the normal.
	float x = 1000.0f, y = 1000.0f;
	tbPolygon ground = tbMakeBox(5.0f, 0.5f);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbManifold m = tbCollidePolygons(&ground, tbMakeTransform(x, y, 0), &box, tbMakeTransform(x + 1.0f, y + 0.99f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-5f);
	cr_expect_float_eq(m.points[0].separation, -0.01f, 1.5e-4f);
	cr_expect_float_eq(m.points[1].separation, -0.01f, 1.5e-4f);
	tbExpectVec(tbPointNearX(&m, x + 0.5f)->point, x + 0.5f, y + 0.495f, 1.5e-4f);

	tbCapsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
	m = tbCollideCapsules(&capsule, tbMakeTransform(x, y, 0), &capsule, tbMakeTransform(x + 0.5f, y + 0.49f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-5f);
	cr_expect_float_eq(m.points[0].separation, -0.01f, 1.5e-4f);

	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	m = tbCollidePolygonAndCircle(&box, tbMakeTransform(-x, y, 0.3f), &circle, tbMakeTransform(-x, y + 0.99f, 0));
	tbExpectSane(&m);
	cr_assert_eq(m.pointCount, 1);
}

Test(manifold, near_parallel_reference_face_is_stable)
{
	// A unit box resting on a box of the same width: both faces are candidates for the
	// reference. Turning B by ±1e-4 rad changes separations by ~5e-5 m, below the 0.1 × slop
	// tolerance: the same features touch, so the feature ids must not change.
	tbPolygon ground = tbMakeBox(0.5f, 0.5f);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbManifold base = tbCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.0f, 0.995f, 0));
	cr_assert_eq(base.pointCount, 2);
	float angles[4] = {1e-4f, -1e-4f, 5e-5f, -5e-5f};
	for (int k = 0; k < 4; ++k)
	{
		tbManifold m =
			tbCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.0f, 0.995f, angles[k]));
		cr_assert_eq(m.pointCount, 2, "angle %g", (double)angles[k]);
		tbExpectVec(m.normal, base.normal.x, base.normal.y, TB_EPS);
		for (int i = 0; i < 2; ++i)
		{
			cr_expect_eq(m.points[i].id, base.points[i].id, "angle %g point %d", (double)angles[k], i);
		}
	}

	// Slightly offset (B overhangs by 0.1 on one side) with the same tiny rotations.
	tbManifold shifted = tbCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.1f, 0.995f, 0));
	cr_assert_eq(shifted.pointCount, 2);
	for (int k = 0; k < 4; ++k)
	{
		tbManifold m =
			tbCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.1f, 0.995f, angles[k]));
		cr_assert_eq(m.pointCount, 2);
		cr_expect_eq(m.points[0].id, shifted.points[0].id);
		cr_expect_eq(m.points[1].id, shifted.points[1].id);
	}
}

Test(manifold, speculative_margin)
{
	// TB_SPECULATIVE_DISTANCE = 0.02 m: a gap of 0.015 is reported (positive separation), a gap
	// of 0.025 is not. Checked for each closed form and for SAT.
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbCapsule capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.5f};
	tbTransform identity = tbMakeTransform(0, 0, 0);
	float gaps[2] = {0.015f, 0.025f};
	int expected[2][4] = {{1, 2, 1, 2}, {0, 0, 0, 0}};
	for (int g = 0; g < 2; ++g)
	{
		tbTransform up = tbMakeTransform(0.0f, 1.0f + gaps[g], 0);
		tbManifold m[4] = {
			tbCollideCircles(&circle, identity, &circle, up),
			tbCollidePolygons(&box, identity, &box, up),
			tbCollidePolygonAndCircle(&box, identity, &circle, up),
			tbCollideCapsules(&capsule, identity, &capsule, up),
		};
		for (int k = 0; k < 4; ++k)
		{
			tbExpectSane(&m[k]);
			cr_expect_eq(m[k].pointCount, expected[g][k], "gap %g routine %d", (double)gaps[g], k);
			for (int i = 0; i < m[k].pointCount; ++i)
			{
				// The gap itself, to 1e-6 m (inputs near 1 m).
				cr_expect_float_eq(m[k].points[i].separation, gaps[g], 1e-6f);
			}
		}
	}
}

// Deterministic pseudo-random numbers in [lo, hi] (a linear congruential generator, Numerical
// Recipes constants) so the sweep below is the same on every run.
static float tbRandom(uint32_t* state, float lo, float hi)
{
	*state = *state * 1664525u + 1013904223u;
	return lo + (hi - lo) * (float)(*state >> 8) / 16777216.0f;
}

Test(manifold, all_outputs_finite)
{
	// Every pair, both orders and both polygon methods that need no other file (SAT and auto),
	// over 2,000 random placements near and far from the origin: finite numbers, unit normals.
	tbVec2 hullPoints[5] = {{-0.4f, -0.2f}, {0.5f, -0.3f}, {0.6f, 0.2f}, {0.0f, 0.5f}, {-0.5f, 0.3f}};
	tbHull hull = tbComputeHull(hullPoints, 5);
	cr_assert_eq(hull.count, 5);
	tbGeometry pentagon = {.type = tb_polygonShape};
	pentagon.polygon = tbMakePolygon(&hull, 0.05f);
	tbGeometry shapes[6] = {
		tbCircleGeometry(0.1f, 0.0f, 0.3f),
		tbCapsuleGeometry((tbVec2){-0.5f, 0.0f}, (tbVec2){0.5f, 0.1f}, 0.2f),
		tbSegmentGeometry((tbVec2){-1.0f, 0.0f}, (tbVec2){1.0f, 0.0f}),
		tbBoxGeometry(0.5f, 0.25f),
		pentagon,
		tbCapsuleGeometry((tbVec2){0.0f, 0.0f}, (tbVec2){0.0f, 0.0f}, 0.2f), // zero-length capsule
	};
	uint32_t state = 12345u;
	int contacts = 0;
	for (int n = 0; n < 2000; ++n)
	{
		float origin = n % 2 == 0 ? 0.0f : 1000.0f;
		float ax = origin + tbRandom(&state, -0.1f, 0.1f);
		tbTransform xfA = tbMakeTransform(ax, origin, tbRandom(&state, -3.2f, 3.2f));
		float bx = origin + tbRandom(&state, -1.2f, 1.2f);
		float by = origin + tbRandom(&state, -1.2f, 1.2f);
		tbTransform xfB = tbMakeTransform(bx, by, tbRandom(&state, -3.2f, 3.2f));
		int i = n % 6, j = (n / 6) % 6;
		tbManifold m = tbCollideShapes(&shapes[i], xfA, &shapes[j], xfB, tb_narrowPhaseSAT);
		tbExpectSane(&m);
		contacts += m.pointCount > 0;
	}
	cr_expect_gt(contacts, 200, "the sweep must exercise contacts, got %d", contacts);
}
