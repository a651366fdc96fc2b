// Contact manifolds: every shape pair against closed-form answers (normal, separation, points,
// count), the dispatcher's order swap, and robustness (touching, deep, identical, tiny, large,
// far from the origin, near-parallel faces, the speculative margin, finiteness).
//
// Tolerances: TB_EPS = 1e-5 m is about 100 float ulps at 1 m (FLT_EPSILON ≈ 1.2e-7), room for
// the dozen operations of a manifold; scaled cases give their own, each with its reason.
#include <criterion/criterion.h>

#include "collide_world.h"
#include "tumble/collision.h"

#include <float.h>
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

// Two manifold points closer than 1e-3 × linear slop = 5e-6 m in A's frame are one point
// (manifold.c's TB_MERGE_DISTANCE): coincident points make the normal solver's 2×2 block
// singular. World points carry the rounding of the move out of A's frame, up to about an ulp
// per coordinate (FLT_EPSILON × |coordinate|, 4.8e-7 m at 4 m), so allow 4 of those.
static void tbExpectNoCoincidentPoints(const tbManifold* m)
{
	if (m->pointCount == 2)
	{
		tbVec2 p0 = m->points[0].point, p1 = m->points[1].point;
		float scale = fmaxf(fmaxf(fabsf(p0.x), fabsf(p0.y)), fmaxf(fabsf(p1.x), fabsf(p1.y)));
		float gap = tbDistance(p0, p1);
		cr_expect_geq(gap, 0.001f * TB_LINEAR_SLOP - 4.0f * FLT_EPSILON * scale,
					  "points %.3g m apart (ids 0x%04x, 0x%04x)", (double)gap, m->points[0].id, m->points[1].id);
	}
}

// Finite numbers everywhere, a unit normal when there are points, at most two points, never
// two coincident points.
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
	tbExpectNoCoincidentPoints(m);
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
	tbManifold m = WorldCollideCircles(&a, tbMakeTransform(0, 0, 0), &b, tbMakeTransform(1.5f, 0, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 1.0f, 0.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.5f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.75f, 0.0f, TB_EPS);
	tbExpectVec(m.points[0].anchorA, 0.0f, 0.0f, 0.0f);

	// Off-centre circle on a rotated body: A's local centre (1, 0) turned by 90° sits at (0, 1);
	// B at (0, 3) radius 0.5: gap 3 − 1 − 1 − 0.5 = 0.5 → beyond the speculative distance.
	tbCircle offset = {{1.0f, 0.0f}, 1.0f};
	tbCircle small = {{0.0f, 0.0f}, 0.5f};
	m = WorldCollideCircles(&offset, tbMakeTransform(0, 0, 0.5f * TB_PI), &small, tbMakeTransform(0, 3.0f, 0));
	cr_expect_eq(m.pointCount, 0);
	// B at (0, 2.49): gap −0.01, normal +y, surfaces at y = 2 and 1.99, midpoint 1.995.
	m = WorldCollideCircles(&offset, tbMakeTransform(0, 0, 0.5f * TB_PI), &small, tbMakeTransform(0, 2.49f, 0));
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
	tbManifold m = WorldCollideCircles(&a, xf, &b, xf);
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
	tbManifold m = WorldCollideCapsuleAndCircle(&capsule, identity, &side, tbMakeTransform(0.5f, 0.5f, 0));
	cr_expect_eq(m.pointCount, 0);
	// At y = 0.44: gap −0.01, surfaces at 0.25 and 0.24, midpoint 0.245.
	m = WorldCollideCapsuleAndCircle(&capsule, identity, &side, tbMakeTransform(0.5f, 0.44f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.5f, 0.245f, TB_EPS);

	// End region: circle at (1.3, 0) r 0.2: distance 0.3 from the end cap centre, overlap 0.15.
	m = WorldCollideCapsuleAndCircle(&capsule, identity, &side, tbMakeTransform(1.3f, 0.0f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 1.0f, 0.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.15f, TB_EPS);
	tbExpectVec(m.points[0].point, 1.175f, 0.0f, TB_EPS);

	// Centre on the core: the capsule's side normal (+y), separation −(0.25 + 0.2).
	m = WorldCollideCapsuleAndCircle(&capsule, identity, &side, tbMakeTransform(0.3f, 0.0f, 0));
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
	tbManifold m = WorldCollideCapsules(&a, identity, &b, tbMakeTransform(0, 0.49f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.0f, 0.245f, TB_EPS);

	// Crossing cores (an X): every SAT axis gives core separation −0.7 (B's lower half reaches
	// 0.7 below A's axis), so the answer is an axis normal with separation −0.7 − 0.5 = −1.2.
	m = WorldCollideCapsules(&a, identity, &b, tbMakeTransform(0, -0.7f, 0));
	cr_assert_geq(m.pointCount, 1);
	tbExpectSane(&m);
	cr_expect_float_eq(fabsf(m.normal.x) + fabsf(m.normal.y), 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -1.2f, TB_EPS);

	// Collinear, end to end: B from (1.3, 0) to (2.7, 0), radii 0.1: gap 0.3 − 0.2 = 0.1 → none;
	// 0.18 apart: gap −0.02 along +x.
	tbCapsule thin = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.1f};
	tbCapsule thinB = {{0.0f, 0.0f}, {1.4f, 0.0f}, 0.1f};
	m = WorldCollideCapsules(&thin, identity, &thinB, tbMakeTransform(1.3f, 0, 0));
	cr_expect_eq(m.pointCount, 0);
	m = WorldCollideCapsules(&thin, identity, &thinB, tbMakeTransform(1.18f, 0, 0));
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
	tbManifold m = WorldCollideCapsules(&a, tbMakeTransform(0, 0, 0), &b, tbMakeTransform(0, 0.45f, 0));
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
	m = WorldCollideCapsules(&a, tbMakeTransform(0, 0, 0), &flipped, tbMakeTransform(0, -0.45f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, -1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.05f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -0.05f, TB_EPS);
}

Test(manifold, capsule_end_beside_a_corner_is_corner_to_corner)
{
	// A fat capsule (radius 0.25, core 0.5 long, tilted 0.3 rad) whose upper end c = (−0.58, 0.365)
	// lies 0.015 m above the top side plane of a 0.7 m box's left face, 0.23 m out from it. The
	// nearest features are c and the box's corner (−0.35, 0.35): the cap penetrates the corner by
	// 0.25 − |c − corner| = 0.25 − sqrt(0.23² + 0.015²) = 0.0195 m, along (c − corner)/|c − corner|.
	// The corner distance exceeds the face separation 0.23 by only 0.49 mm; clipping against
	// the face instead measured the core where it crosses the side plane, 0.05 m further along the
	// tilted axis, and reported the pair 0.026 m apart (no point at the default keep distance).
	// Tolerance TB_EPS = 1e-5 m (and rad): the closed form is evaluated in float from coordinates
	// below 1.1 m, whose rounding is about 1e-7 m; a face contact instead would be off by 0.045 m.
	tbPolygon box = tbMakeBox(0.35f, 0.35f);
	float c = cosf(0.3f), s = sinf(0.3f);
	tbVec2 end = {-0.58f, 0.365f};
	tbCapsule capsule = {{end.x - 0.5f * c, end.y - 0.5f * s}, end, 0.25f};
	tbManifold m = WorldCollidePolygonAndCapsule(&box, tbMakeTransform(0, 0, 0), &capsule, tbMakeTransform(0, 0, 0));
	cr_assert_eq(m.pointCount, 1);
	float d = sqrtf(0.23f * 0.23f + 0.015f * 0.015f);
	cr_expect_float_eq(m.points[0].separation, d - 0.25f, TB_EPS, "separation %g, expected %g",
					   (double)m.points[0].separation, (double)(d - 0.25f));
	tbExpectVec(m.normal, -0.23f / d, 0.015f / d, TB_EPS);
}

// ---------------------------------------------------------------------------------------------
// Polygons

Test(manifold, polygon_and_circle_regions)
{
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbTransform identity = tbMakeTransform(0, 0, 0);

	// Face region: circle (0, 0.89) r 0.4: gap 0.39 − 0.4 = −0.01, midpoint y = (0.5 + 0.49)/2.
	tbCircle circle = {{0.0f, 0.0f}, 0.4f};
	tbManifold m = WorldCollidePolygonAndCircle(&box, identity, &circle, tbMakeTransform(0.2f, 0.89f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.2f, 0.495f, TB_EPS);

	// Vertex region: circle at (0.8, 0.8) r 0.5: from corner (0.5, 0.5) the offset is (0.3, 0.3),
	// distance 0.3·√2, separation 0.3·√2 − 0.5, normal (1, 1)/√2.
	tbCircle big = {{0.0f, 0.0f}, 0.5f};
	m = WorldCollidePolygonAndCircle(&box, identity, &big, tbMakeTransform(0.8f, 0.8f, 0));
	cr_assert_eq(m.pointCount, 1);
	float d = 0.3f * sqrtf(2.0f);
	tbExpectVec(m.normal, sqrtf(0.5f), sqrtf(0.5f), TB_EPS);
	cr_expect_float_eq(m.points[0].separation, d - 0.5f, TB_EPS);
	// Surfaces: the corner and the circle's point 0.5 back from its centre, midpoint between.
	float mid = 0.5f * (0.5f + 0.8f - 0.5f * sqrtf(0.5f));
	tbExpectVec(m.points[0].point, mid, mid, TB_EPS);

	// Centre inside the box at (0, 0.3): the nearest face is the top, depth 0.2 + 0.1.
	tbCircle inside = {{0.0f, 0.0f}, 0.1f};
	m = WorldCollidePolygonAndCircle(&box, identity, &inside, tbMakeTransform(0.0f, 0.3f, 0));
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
	m = WorldCollidePolygonAndCircle(&triangle, identity, &apex, tbMakeTransform(0.0f, 1.2f, 0));
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
	tbManifold m = WorldCollidePolygonAndCapsule(&box, identity, &capsule, tbMakeTransform(0, 0.74f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, -0.3f)->point, -0.3f, 0.495f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, 0.3f)->point, 0.3f, 0.495f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -0.01f, TB_EPS);

	// Capsule standing upright on the box (turned 90°): one point under its lower cap.
	m = WorldCollidePolygonAndCapsule(&box, identity, &capsule, tbMakeTransform(0.1f, 1.04f, 0.5f * TB_PI));
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
	tbManifold m = WorldCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0, 0.99f, 0));
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
	m = WorldCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0, cy, 0.1f));
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
	tbManifold m = WorldCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.3f, cy, 0.25f * TB_PI));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.3f, 0.495f, TB_EPS);

	// Same with the roles swapped (the small box is A): its face is never the reference, the
	// ground's face is, so the normal is −y and the point the same.
	m = WorldCollidePolygons(&box, tbMakeTransform(0.3f, cy, 0.25f * TB_PI), &ground, tbMakeTransform(0, 0, 0));
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
	tbManifold m = WorldCollidePolygons(&a, tbMakeTransform(0, 0, 0), &b, tbMakeTransform(1.1f, 1.1f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, sqrtf(0.5f), sqrtf(0.5f), TB_EPS);
	cr_expect_float_eq(m.points[0].separation, 0.1f * sqrtf(2.0f) - 0.2f, TB_EPS);
	tbExpectVec(m.points[0].point, 0.55f, 0.55f, TB_EPS);
}

// ---------------------------------------------------------------------------------------------
// Rounded boxes where the incident edge misses the reference face (reviewer's cases, Box2D 2.4.1
// comparison over 1,000,000 random pairs). The exact answer is computed here in double precision
// from the same float inputs: world vertices from the float local vertices and the float
// transform, the closest features as the least point–segment distance over every vertex of one
// polygon against every edge of the other.

// Double-precision view of a manifold input: world vertices and face normals of both polygons.
typedef struct tbExactPair
{
	double a[TB_MAX_POLYGON_VERTICES][2], b[TB_MAX_POLYGON_VERTICES][2];
	double normalA[TB_MAX_POLYGON_VERTICES][2], normalB[TB_MAX_POLYGON_VERTICES][2];
	int countA, countB;
} tbExactPair;

// Closest core features: distance, unit normal from A to B, the vertex and the edge, and the
// fraction t of the closest point along the edge (interior when 0 < t < 1).
typedef struct tbExactClosest
{
	double distance;
	double normal[2];
	bool vertexOfA; // true: a vertex of A against an edge of B; false: a vertex of B against an edge of A
	int vertex, edge;
	double t;
} tbExactClosest;

static void tbExactWorld(double out[][2], double normals[][2], const tbPolygon* polygon, tbTransform xf)
{
	double c = xf.q.c, s = xf.q.s;
	for (int i = 0; i < polygon->count; ++i)
	{
		double x = polygon->vertices[i].x, y = polygon->vertices[i].y;
		out[i][0] = xf.p.x + c * x - s * y;
		out[i][1] = xf.p.y + s * x + c * y;
		double nx = polygon->normals[i].x, ny = polygon->normals[i].y;
		normals[i][0] = c * nx - s * ny;
		normals[i][1] = s * nx + c * ny;
	}
}

static tbExactPair tbMakeExactPair(const tbPolygon* a, tbTransform xfA, const tbPolygon* b, tbTransform xfB)
{
	tbExactPair pair;
	tbExactWorld(pair.a, pair.normalA, a, xfA);
	tbExactWorld(pair.b, pair.normalB, b, xfB);
	pair.countA = a->count;
	pair.countB = b->count;
	return pair;
}

// SAT separation of the other polygon from face i of A (ofA) or of B: min over j of nᵢ·(xⱼ − vᵢ).
static double tbExactFaceSeparation(const tbExactPair* pair, bool ofA, int i)
{
	const double* v = ofA ? pair->a[i] : pair->b[i];
	const double* n = ofA ? pair->normalA[i] : pair->normalB[i];
	int otherCount = ofA ? pair->countB : pair->countA;
	double separation = HUGE_VAL;
	for (int j = 0; j < otherCount; ++j)
	{
		const double* x = ofA ? pair->b[j] : pair->a[j];
		separation = fmin(separation, n[0] * (x[0] - v[0]) + n[1] * (x[1] - v[1]));
	}
	return separation;
}

static tbExactClosest tbExactClosestFeatures(const tbExactPair* pair)
{
	tbExactClosest best = {.distance = HUGE_VAL};
	for (int pass = 0; pass < 2; ++pass)
	{
		const double(*points)[2] = pass == 0 ? pair->a : pair->b;
		const double(*edges)[2] = pass == 0 ? pair->b : pair->a;
		int pointCount = pass == 0 ? pair->countA : pair->countB;
		int edgeCount = pass == 0 ? pair->countB : pair->countA;
		for (int i = 0; i < pointCount; ++i)
		{
			for (int j = 0; j < edgeCount; ++j)
			{
				const double* e1 = edges[j];
				const double* e2 = edges[j + 1 < edgeCount ? j + 1 : 0];
				double ex = e2[0] - e1[0], ey = e2[1] - e1[1];
				double t = ((points[i][0] - e1[0]) * ex + (points[i][1] - e1[1]) * ey) / (ex * ex + ey * ey);
				double clamped = fmin(fmax(t, 0.0), 1.0);
				// From A's feature to B's: edge point → vertex of B, or vertex of A → edge point.
				double dx = points[i][0] - (e1[0] + clamped * ex);
				double dy = points[i][1] - (e1[1] + clamped * ey);
				if (pass == 0)
				{
					dx = -dx;
					dy = -dy;
				}
				double distance = sqrt(dx * dx + dy * dy);
				if (distance < best.distance)
				{
					best = (tbExactClosest){distance, {dx / distance, dy / distance}, pass == 0, i, j, t};
				}
			}
		}
	}
	return best;
}

// Angle (rad) between the float normal n and the double unit vector u.
static double tbAngleTo(tbVec2 n, const double u[2])
{
	double cross = (double)n.x * u[1] - (double)n.y * u[0];
	double dot = (double)n.x * u[0] + (double)n.y * u[1];
	return fabs(atan2(cross, dot));
}

// One of the reviewer's cases: two boxes rounded by 0.01 m, transforms p = position,
// q = (cos angle, sin angle) in float; the exact (double) pair and closest features, and
// Tumble's manifold, checked sane, with one point and no two points at the same spot.
typedef struct tbReviewCase
{
	tbExactPair pair;
	tbExactClosest exact;
	tbManifold manifold;
} tbReviewCase;

static tbReviewCase tbRunReviewCase(const float boxA[5], const float boxB[5])
{
	tbPolygon a = tbMakeRoundedBox(boxA[0], boxA[1], 0.01f);
	tbPolygon b = tbMakeRoundedBox(boxB[0], boxB[1], 0.01f);
	tbTransform xfA = {{boxA[2], boxA[3]}, {cosf(boxA[4]), sinf(boxA[4])}};
	tbTransform xfB = {{boxB[2], boxB[3]}, {cosf(boxB[4]), sinf(boxB[4])}};
	tbReviewCase c;
	c.pair = tbMakeExactPair(&a, xfA, &b, xfB);
	c.exact = tbExactClosestFeatures(&c.pair);
	c.manifold = WorldCollidePolygons(&a, xfA, &b, xfB);
	tbExpectSane(&c.manifold);
	cr_assert_eq(c.manifold.pointCount, 1, "one point expected, got %d", c.manifold.pointCount);
	return c;
}

Test(manifold, missed_face_uses_true_closest_features)
{
	// A's face 3 (core separation 4.8e-5 m) is kept as the reference over B's face 3 (3.7e-4 m,
	// within TB_REFERENCE_TOLERANCE = 5e-4 m), B's incident edge lies wholly beside A's face, and
	// the closest features are A's vertex 0 against B's edge 3, not A's edge 3 against B's
	// incident edge (which gave (−0.821, 0.570), 0.63 rad off, 8.8e-5 m too much separation).
	const float boxA[5] = {0.0250000004f, 0.0317549706f, 3.52464867f, -0.438999653f, -2.0730238f};
	const float boxB[5] = {0.0250000004f, 0.0314549468f, 3.52990651f, -0.367553622f, 1.90732837f};
	tbReviewCase c = tbRunReviewCase(boxA, boxB); // a corner against a face: one point
	const tbExactPair pair = c.pair;
	const tbExactClosest exact = c.exact;
	const tbManifold m = c.manifold;
	// The input is what the case says: A's vertex 0 inside B's edge 3, core gap 3.73e-4 m.
	cr_assert(exact.vertexOfA && exact.vertex == 0 && exact.edge == 3 && exact.t > 0.0 && exact.t < 1.0);
	cr_assert(fabs(exact.distance - 3.73e-4) < 1e-6, "core gap %.9g", exact.distance);
	// Normal (−0.330, 0.944): B's face normal, computed from B's stored normal by two float
	// rotations (into A's frame and back); allow 1e-6 rad, about 8 float roundings.
	double angle = tbAngleTo(m.normal, exact.normal);
	cr_expect(angle < 1e-6, "normal (%.9g, %.9g) is %.3g rad off the exact (%.9g, %.9g)", (double)m.normal.x,
			  (double)m.normal.y, angle, exact.normal[0], exact.normal[1]);
	// Separation: the core gap less both radii. The pair's relative coordinates are below 0.1 m
	// (float rounding ~1e-8 m); allow 1e-6 m.
	cr_expect_float_eq(m.points[0].separation, (float)(exact.distance - 0.02), 1e-6f);
	// The point lies midway between the surfaces: A's vertex pushed out by 0.01 along n and B's
	// face point pushed back by 0.01, i.e. A's vertex + ½(gap)·n. World coordinates near 3.5 m
	// (ulp 2.4e-7 m): allow 1e-6 m.
	double half = 0.5 * exact.distance;
	tbExpectVec(m.points[0].point, (float)(pair.a[0][0] + half * exact.normal[0]),
				(float)(pair.a[0][1] + half * exact.normal[1]), 1e-6f);
}

Test(manifold, missed_face_short_vector_keeps_face_normal)
{
	// Corner against corner 1.1e-4 m apart, below TB_GAP_TOLERANCE = 0.1 × linear slop: the
	// direction between the two corners is not resolvable in float (they sit 3.8 m from A's
	// origin, ulp 4.8e-7 m; the old closest-points normal was 1.4e-3 rad off the exact
	// direction), so the normal is the SAT face's, here A's face 0 (largest separation), as
	// Box2D v3 does below 0.1 × linear slop.
	const float boxA[5] = {0.386531144f, 3.78882146f, 4.01262474f, -2.9321785f, -0.751027107f};
	const float boxB[5] = {1.21687388f, 3.31934595f, 3.12804008f, -9.20401764f, 0.764200449f};
	tbReviewCase c = tbRunReviewCase(boxA, boxB);
	const tbExactPair pair = c.pair;
	const tbExactClosest exact = c.exact;
	const tbManifold m = c.manifold;
	cr_assert(exact.distance < 0.1 * TB_LINEAR_SLOP, "core gap %.9g", exact.distance);
	cr_assert(exact.t <= 0.0 || exact.t >= 1.0, "closest features are two corners (t = %.9g)", exact.t);
	double separationA = tbExactFaceSeparation(&pair, true, 0);
	for (int i = 0; i < pair.countA; ++i)
	{
		cr_assert(tbExactFaceSeparation(&pair, true, i) <= separationA);
	}
	for (int i = 0; i < pair.countB; ++i)
	{
		cr_assert(tbExactFaceSeparation(&pair, false, i) < separationA);
	}
	// A's face 0 normal is A's stored normal rotated once in float: allow 1e-6 rad (a few
	// roundings of FLT_EPSILON = 1.2e-7). Same inputs, same answer: no rounding noise left.
	double angle = tbAngleTo(m.normal, pair.normalA[0]);
	cr_expect(angle < 1e-6, "normal (%.9g, %.9g) is %.3g rad off A's face normal (%.9g, %.9g)", (double)m.normal.x,
			  (double)m.normal.y, angle, pair.normalA[0][0], pair.normalA[0][1]);
	// The separation along the face normal lies between the face separation (1.2e-5 m below the
	// gap here) and the gap: conservative, never more than the true gap. Tolerance 1e-6 m: the
	// closest points lie 3.8 m from A's origin (ulp 4.8e-7 m).
	double lower = separationA - 0.02, upper = exact.distance - 0.02;
	cr_expect(m.points[0].separation >= lower - 1e-6 && m.points[0].separation <= upper + 1e-6,
			  "separation %.9g outside [%.9g, %.9g]", (double)m.points[0].separation, lower, upper);
}

Test(manifold, clip_merges_coincident_points)
{
	// A's vertex 0 lies exactly (in A's frame, float) on the side plane through B's vertex 0 of
	// B's reference face 3, and A's incident edge runs outward: the clip kept the vertex and also
	// added the crossing at the same spot (ids 0x0083 and 0x8300). One point remains, the vertex:
	// its id, (A's vertex 0, B's reference face 3) = 0x0083, does not depend on the side plane.
	const float boxA[5] = {0.236609891f, 0.798745811f, 1.37965298f, -0.343814373f, -2.97580791f};
	const float boxB[5] = {0.0525781885f, 0.795801938f, 0.982432842f, 1.10550523f, 0.743678808f};
	tbReviewCase c = tbRunReviewCase(boxA, boxB); // the vertex and the crossing are one point
	const tbExactPair pair = c.pair;
	const tbExactClosest exact = c.exact;
	const tbManifold m = c.manifold;
	double separationB = tbExactFaceSeparation(&pair, false, 3);
	cr_expect_eq(m.points[0].id, TB_MAKE_FEATURE_ID(0x00, 0x83), "id 0x%04x", m.points[0].id);
	// Normal: B's face 3 (from A to B, so −n), B's stored normal rotated twice in float: 1e-6 rad.
	double faceNormal[2] = {-pair.normalB[3][0], -pair.normalB[3][1]};
	double angle = tbAngleTo(m.normal, faceNormal);
	cr_expect(angle < 1e-6, "normal is %.3g rad off B's face normal", angle);
	// The exact closest direction differs from the face normal only by where float put A's vertex
	// relative to the side plane: within one rounding of its world coordinates (ulp 1.2e-7 m at
	// 1.4 m) over the gap of 1.75e-3 m, i.e. 7e-5 rad; allow 1e-4 rad.
	angle = tbAngleTo(m.normal, exact.normal);
	cr_expect(angle < 1e-4, "normal is %.3g rad off the exact closest direction", angle);
	// Separation: B's face separation less both radii (relative coordinates ~1.5 m, allow 1e-6 m).
	cr_expect_float_eq(m.points[0].separation, (float)(separationB - 0.02), 1e-6f);
	cr_expect(fabs(separationB - exact.distance) < 1e-6, "face separation %.9g, gap %.9g", separationB,
			  exact.distance);
}

// ---------------------------------------------------------------------------------------------
// Segments

Test(manifold, segment_pairs)
{
	tbSegment segment = {{-2.0f, 0.0f}, {2.0f, 0.0f}};
	tbTransform identity = tbMakeTransform(0, 0, 0);

	// Circle r 0.5 at (1, 0.49): gap −0.01 along +y, midpoint y = (0 + −0.01)/2.
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbManifold m = WorldCollideSegmentAndCircle(&segment, identity, &circle, tbMakeTransform(1.0f, 0.49f, 0));
	cr_assert_eq(m.pointCount, 1);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	tbExpectVec(m.points[0].point, 1.0f, -0.005f, TB_EPS);

	// Capsule lying on the segment below it: two points at the capsule's ends.
	tbCapsule capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.2f};
	m = WorldCollideSegmentAndCapsule(&segment, identity, &capsule, tbMakeTransform(0.0f, -0.19f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, -1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.01f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -0.01f, TB_EPS);
	tbExpectVec(tbPointNearX(&m, 0.5f)->point, 0.5f, 0.005f, TB_EPS);

	// Box resting on the segment: two points at the box's bottom corners.
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	m = WorldCollideSegmentAndPolygon(&segment, identity, &box, tbMakeTransform(0.0f, 0.49f, 0));
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
	tbManifold direct = WorldCollidePolygonAndCircle(&shapes[3].polygon, xfA, &shapes[0].circle, xfB);
	tbManifold viaDispatch = tbCollideShapes(&shapes[0], xfB, &shapes[3], xfA, tb_narrowPhaseAuto);
	cr_assert_eq(direct.pointCount, 1);
	cr_assert_eq(viaDispatch.pointCount, 1);
	tbExpectVec(viaDispatch.normal, -direct.normal.x, -direct.normal.y, 0.0f);
	cr_expect_float_eq(viaDispatch.points[0].separation, direct.points[0].separation, 0.0f);

	// The method picks the polygon routine: GJK → tbCollidePolygonsGJK, auto → SAT (bit-exact).
	tbManifold gjk = WorldCollidePolygonsGJK(&shapes[3].polygon, xfA, &shapes[3].polygon, xfB);
	tbManifold gjkDispatch = tbCollideShapes(&shapes[3], xfA, &shapes[3], xfB, tb_narrowPhaseGJK);
	cr_expect_eq(gjkDispatch.pointCount, gjk.pointCount);
	tbExpectVec(gjkDispatch.normal, gjk.normal.x, gjk.normal.y, 0.0f);
	tbManifold sat = WorldCollidePolygons(&shapes[3].polygon, xfA, &shapes[3].polygon, xfB);
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
	tbManifold m = WorldCollideCircles(&circle, tbMakeTransform(0, 0, 0), &circle, tbMakeTransform(1.0f, 0, 0));
	cr_assert_eq(m.pointCount, 1);
	cr_expect_float_eq(m.points[0].separation, 0.0f, 1e-6f);
	tbExpectVec(m.points[0].point, 0.5f, 0.0f, 1e-6f);

	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	m = WorldCollidePolygons(&box, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.25f, 1.0f, 0));
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
	tbManifold m = WorldCollidePolygons(&box, xf, &box, xf);
	tbExpectSane(&m);
	cr_assert_eq(m.pointCount, 2);
	cr_expect_float_eq(m.points[0].separation, -1.0f, TB_EPS);
	cr_expect_float_eq(m.points[1].separation, -1.0f, TB_EPS);

	// Identical capsules, identical circles, identical segment polygons.
	tbCapsule capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.2f};
	m = WorldCollideCapsules(&capsule, xf, &capsule, xf);
	tbExpectSane(&m);
	cr_assert_geq(m.pointCount, 1);
	cr_expect_float_eq(m.points[0].separation, -0.4f, TB_EPS);
	tbCircle circle = {{0.0f, 0.0f}, 0.3f};
	m = WorldCollidePolygonAndCircle(&box, xf, &circle, xf);
	tbExpectSane(&m);
	cr_assert_eq(m.pointCount, 1);
	cr_expect_float_eq(m.points[0].separation, -0.8f, TB_EPS);

	// Deep: a small box 0.8 into a big one: depth along the shortest way out (the top face).
	tbPolygon big = tbMakeBox(2.0f, 1.0f);
	tbPolygon small = tbMakeBox(0.25f, 0.25f);
	m = WorldCollidePolygons(&big, tbMakeTransform(0, 0, 0), &small, tbMakeTransform(0.0f, 0.45f, 0));
	tbExpectSane(&m);
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, TB_EPS);
	cr_expect_float_eq(m.points[0].separation, -0.8f, TB_EPS);
}

Test(manifold, tiny_and_large_shapes)
{
	// 1 mm boxes, 0.1 mm overlap: tolerance 1e-8 m is ~100 ulps at 1e-3 m.
	tbPolygon tiny = tbMakeBox(0.0005f, 0.0005f);
	tbManifold m = WorldCollidePolygons(&tiny, tbMakeTransform(0, 0, 0), &tiny, tbMakeTransform(0, 0.0009f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-6f);
	cr_expect_float_eq(m.points[0].separation, -0.0001f, 1e-8f);
	cr_expect_float_eq(m.points[1].separation, -0.0001f, 1e-8f);

	// 100 m boxes, 1 cm overlap: ulp at 100 m is 7.6e-6 m, allow 5e-5 m.
	tbPolygon large = tbMakeBox(50.0f, 50.0f);
	m = WorldCollidePolygons(&large, tbMakeTransform(0, 0, 0), &large, tbMakeTransform(10.0f, 99.99f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-6f);
	cr_expect_float_eq(m.points[0].separation, -0.01f, 5e-5f);
	cr_expect_float_eq(m.points[1].separation, -0.01f, 5e-5f);

	// 1 mm circles: 0.01 mm overlap.
	tbCircle dot = {{0.0f, 0.0f}, 0.0005f};
	m = WorldCollideCircles(&dot, tbMakeTransform(0, 0, 0), &dot, tbMakeTransform(0.00099f, 0, 0));
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
	tbManifold m = WorldCollidePolygons(&ground, tbMakeTransform(x, y, 0), &box, tbMakeTransform(x + 1.0f, y + 0.99f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-5f);
	cr_expect_float_eq(m.points[0].separation, -0.01f, 1.5e-4f);
	cr_expect_float_eq(m.points[1].separation, -0.01f, 1.5e-4f);
	tbExpectVec(tbPointNearX(&m, x + 0.5f)->point, x + 0.5f, y + 0.495f, 1.5e-4f);

	tbCapsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f};
	m = WorldCollideCapsules(&capsule, tbMakeTransform(x, y, 0), &capsule, tbMakeTransform(x + 0.5f, y + 0.49f, 0));
	cr_assert_eq(m.pointCount, 2);
	tbExpectVec(m.normal, 0.0f, 1.0f, 1e-5f);
	cr_expect_float_eq(m.points[0].separation, -0.01f, 1.5e-4f);

	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	m = WorldCollidePolygonAndCircle(&box, tbMakeTransform(-x, y, 0.3f), &circle, tbMakeTransform(-x, y + 0.99f, 0));
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
	tbManifold base = WorldCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.0f, 0.995f, 0));
	cr_assert_eq(base.pointCount, 2);
	float angles[4] = {1e-4f, -1e-4f, 5e-5f, -5e-5f};
	for (int k = 0; k < 4; ++k)
	{
		tbManifold m =
			WorldCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.0f, 0.995f, angles[k]));
		cr_assert_eq(m.pointCount, 2, "angle %g", (double)angles[k]);
		tbExpectVec(m.normal, base.normal.x, base.normal.y, TB_EPS);
		for (int i = 0; i < 2; ++i)
		{
			cr_expect_eq(m.points[i].id, base.points[i].id, "angle %g point %d", (double)angles[k], i);
		}
	}

	// Slightly offset (B overhangs by 0.1 on one side) with the same tiny rotations.
	tbManifold shifted = WorldCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.1f, 0.995f, 0));
	cr_assert_eq(shifted.pointCount, 2);
	for (int k = 0; k < 4; ++k)
	{
		tbManifold m =
			WorldCollidePolygons(&ground, tbMakeTransform(0, 0, 0), &box, tbMakeTransform(0.1f, 0.995f, angles[k]));
		cr_assert_eq(m.pointCount, 2);
		cr_expect_eq(m.points[0].id, shifted.points[0].id);
		cr_expect_eq(m.points[1].id, shifted.points[1].id);
	}
}

// The points of two consecutive manifolds of a turning pair, matched by position (within
// 2 mm: a turn of 5e-4 rad moves a point 0.5 m from the centre by 0.25 mm), must have the same
// feature ids. Returns the number of reference-face swaps seen (normal direction jumps).
static int tbCountSwapsKeepingIds(tbManifold (*collide)(const tbPolygon*, tbTransform, const tbPolygon*, tbTransform))
{
	tbPolygon a = tbMakeBox(0.5f, 0.5f);
	tbPolygon b = tbMakeBox(0.5f, 0.5f);
	int swaps = 0;
	tbManifold previous = {0};
	for (int k = 0; k <= 40; ++k)
	{
		float angle = -0.01f + 0.0005f * (float)k;
		tbManifold m = collide(&a, tbMakeTransform(0, 0, 0), &b, tbMakeTransform(0.5f, 0.99f, angle));
		cr_assert_eq(m.pointCount, 2, "angle %g", (double)angle);
		if (k > 0 && fabsf(m.normal.x - previous.normal.x) > 1e-4f)
		{
			swaps += 1;
			for (int i = 0; i < 2; ++i)
			{
				int j = tbDistance(m.points[i].point, previous.points[0].point) < 2e-3f ? 0 : 1;
				cr_assert(tbDistance(m.points[i].point, previous.points[j].point) < 2e-3f, "angle %g point %d moved",
						  (double)angle, i);
				cr_expect_eq(m.points[i].id, previous.points[j].id, "angle %g: id 0x%04x was 0x%04x", (double)angle,
							 m.points[i].id, previous.points[j].id);
			}
		}
		previous = m;
	}
	return swaps;
}

Test(manifold, reference_face_swap_keeps_ids)
{
	// A box on two boxes (a pyramid) sags by 1 cm and turns by a few milliradians, which moves the
	// two faces' separations apart by more than the reference hysteresis: the reference face
	// swaps between A's top and B's bottom. The points are the same corners on the same edges, so
	// their ids, hence their warm starts, must not change. Both polygon paths (SAT, GJK/EPA).
	int satSwaps = tbCountSwapsKeepingIds(WorldCollidePolygons);
	int gjkSwaps = tbCountSwapsKeepingIds(WorldCollidePolygonsGJK);
	cr_expect_gt(satSwaps, 0, "the sweep must swap the reference face (SAT)");
	cr_expect_gt(gjkSwaps, 0, "the sweep must swap the reference face (GJK)");
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
			WorldCollideCircles(&circle, identity, &circle, up),
			WorldCollidePolygons(&box, identity, &box, up),
			WorldCollidePolygonAndCircle(&box, identity, &circle, up),
			WorldCollideCapsules(&capsule, identity, &capsule, up),
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
