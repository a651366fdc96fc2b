// Tests of tbComputeHull (quickhull with welding) and tbValidateHull.
//
// Containment tolerance: welding (points within TB_LINEAR_SLOP merge into the first one), the
// quickhull step (points within TB_LINEAR_SLOP of an edge are dropped) and the collinear pass
// (vertices within TB_LINEAR_SLOP of their neighbours' chord are removed) can each leave an
// input point up to one slop outside the hull, so the bound is 3 × TB_LINEAR_SLOP = 0.015 m
// (see hull.c). Hull vertices themselves are input points, compared exactly.

#include "tumble/collision.h"
#include "test_helpers.h"

#include <criterion/criterion.h>
#include <math.h>

#define HULL_CONTAINMENT_TOL (3.0f * TB_LINEAR_SLOP)

static int s_errors;

static void countError(const char* message, void* context)
{
	(void)message;
	(void)context;
	++s_errors;
}

// Count errors instead of printing them; each test starts from zero.
static void silenceErrors(void)
{
	s_errors = 0;
	tbSetErrorCallback(countError, NULL);
}

static void restoreErrors(void)
{
	tbSetErrorCallback(NULL, NULL);
}

// Deterministic linear congruential generator (Numerical Recipes constants), uniform in [lo, hi].
static uint32_t s_seed;

// Twice the signed area (positive for counter-clockwise).
static float twiceSignedArea(const tbHull* hull)
{
	float sum = 0.0f;
	for (int i = 0; i < hull->count; ++i)
	{
		sum += tbCross(hull->points[i], hull->points[(i + 1) % hull->count]);
	}
	return sum;
}

// Largest distance of p outside any edge of the hull (≤ 0 when inside).
static float distanceOutside(const tbHull* hull, tbVec2 p)
{
	float worst = -FLT_MAX;
	for (int i = 0; i < hull->count; ++i)
	{
		tbVec2 a = hull->points[i];
		tbVec2 b = hull->points[(i + 1) % hull->count];
		tbVec2 normal = tbNormalize(tbRightPerp(tbSub(b, a)));
		worst = fmaxf(worst, tbDot(normal, tbSub(p, a)));
	}
	return worst;
}

static bool isInputPoint(tbVec2 p, const tbVec2* points, int count)
{
	for (int i = 0; i < count; ++i)
	{
		if (tbVec2Equals(p, points[i]))
		{
			return true;
		}
	}
	return false;
}

static void checkHullOfCloud(const tbHull* hull, const tbVec2* points, int count)
{
	cr_assert(hull->count >= 3 && hull->count <= count);
	cr_expect(tbValidateHull(hull));
	cr_expect(twiceSignedArea(hull) > 0.0f, "hull must be counter-clockwise");
	for (int i = 0; i < hull->count; ++i)
	{
		// Every corner turns left: (b − a) × (c − b) > 0.
		tbVec2 a = hull->points[i];
		tbVec2 b = hull->points[(i + 1) % hull->count];
		tbVec2 c = hull->points[(i + 2) % hull->count];
		cr_expect(tbCross(tbSub(b, a), tbSub(c, b)) > 0.0f, "convex, counter-clockwise corner");
		cr_expect(isInputPoint(a, points, count), "hull vertices are input points");
	}
	for (int i = 0; i < count; ++i)
	{
		float outside = distanceOutside(hull, points[i]);
		cr_expect(outside <= HULL_CONTAINMENT_TOL, "point %d lies %g outside the hull", i, (double)outside);
	}
}

Test(hull, random_clouds_are_convex_ccw_and_contain_every_point)
{
	s_seed = 12345u;
	int accepted = 0;
	const int cloudCount = 1000;
	for (int cloud = 0; cloud < cloudCount; ++cloud)
	{
		int count = 3 + (int)(RandomFloat(&s_seed, 0.0f, 5.999f));
		tbVec2 points[TB_MAX_POLYGON_VERTICES];
		for (int i = 0; i < count; ++i)
		{
			points[i] = tbMakeVec2(RandomFloat(&s_seed, -2.0f, 2.0f), RandomFloat(&s_seed, -1.0f, 1.0f));
		}
		tbHull hull = tbComputeHull(points, count);
		if (hull.count == 0)
		{
			continue;
		}
		++accepted;
		checkHullOfCloud(&hull, points, count);
	}
	// Random points in a 4 m × 2 m box are almost never within 5 mm of a line; a handful of
	// rejections would already mean a bug.
	cr_expect(accepted >= cloudCount - 5, "only %d of %d clouds gave a hull", accepted, cloudCount);
}

Test(hull, tiny_random_clouds_stay_valid)
{
	// Clouds only 3 cm across, a few slops wide: here welding and the collinear pass really act.
	s_seed = 777u;
	int accepted = 0;
	for (int cloud = 0; cloud < 1000; ++cloud)
	{
		int count = 3 + (int)(RandomFloat(&s_seed, 0.0f, 5.999f));
		tbVec2 points[TB_MAX_POLYGON_VERTICES];
		for (int i = 0; i < count; ++i)
		{
			points[i] = tbMakeVec2(RandomFloat(&s_seed, -0.015f, 0.015f), RandomFloat(&s_seed, -0.015f, 0.015f));
		}
		tbHull hull = tbComputeHull(points, count);
		if (hull.count > 0)
		{
			++accepted;
			checkHullOfCloud(&hull, points, count);
		}
	}
	// Both outcomes must occur at this scale, or the test exercises nothing.
	cr_expect(accepted > 0 && accepted < 1000, "%d of 1000 tiny clouds gave a hull", accepted);
}

Test(hull, square_with_interior_and_edge_points_has_four_vertices)
{
	// Corners in scrambled order, interior points, and edge midpoints (collinear, must vanish).
	tbVec2 points[8] = {{0.2f, 0.1f}, {1.0f, 1.0f}, {-1.0f, -1.0f}, {0.0f, 1.0f},
						{1.0f, -1.0f}, {-0.5f, 0.3f}, {-1.0f, 1.0f}, {1.0f, 0.0f}};
	tbHull hull = tbComputeHull(points, 8);
	cr_assert_eq(hull.count, 4);
	cr_expect(tbValidateHull(&hull));
	// Twice the area of the 2 × 2 square is 8, exactly in float.
	cr_expect(twiceSignedArea(&hull) == 8.0f);
	for (int i = 0; i < 4; ++i)
	{
		tbVec2 p = hull.points[i];
		cr_expect(fabsf(p.x) == 1.0f && fabsf(p.y) == 1.0f, "vertex %d (%g, %g) is not a corner", i, (double)p.x,
				  (double)p.y);
	}
}

Test(hull, rejects_too_few_and_too_many_points)
{
	silenceErrors();
	// A regular octagon on the unit circle (in scrambled order) and its centre.
	const float h = 0.70710678f;
	tbVec2 points[9] = {{1.0f, 0.0f}, {-h, h}, {0.0f, 1.0f}, {h, -h}, {-1.0f, 0.0f},
						{h, h}, {0.0f, -1.0f}, {-h, -h}, {0.0f, 0.0f}};
	cr_expect_eq(tbComputeHull(NULL, 0).count, 0);
	cr_expect_eq(tbComputeHull(points, 1).count, 0);
	cr_expect_eq(tbComputeHull(points, 2).count, 0);
	cr_expect_eq(s_errors, 0, "too few points is a degenerate cloud, not a caller error");
	cr_expect_eq(tbComputeHull(points, 3).count, 3);
	cr_expect_eq(tbComputeHull(points, 8).count, 8);
	cr_expect_eq(tbComputeHull(points, 9).count, 0, "more than TB_MAX_POLYGON_VERTICES points");
	cr_expect_eq(s_errors, 1, "too many points is reported");
	restoreErrors();
}

Test(hull, rejects_duplicate_points)
{
	tbVec2 same[4] = {{1.0f, 2.0f}, {1.0f, 2.0f}, {1.0f, 2.0f}, {1.0f, 2.0f}};
	cr_expect_eq(tbComputeHull(same, 4).count, 0);
	// Within the slop of each other: welded to one point.
	const float d = 0.4f * TB_LINEAR_SLOP;
	tbVec2 near[4] = {{0.0f, 0.0f}, {d, 0.0f}, {0.0f, d}, {-d, -d * 0.5f}};
	cr_expect_eq(tbComputeHull(near, 4).count, 0);
	// Two distinct points plus duplicates: still no area.
	tbVec2 two[5] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}, {1.0f, 0.0f}, {d, 0.0f}};
	cr_expect_eq(tbComputeHull(two, 5).count, 0);
	// Duplicates of a valid triangle are welded away.
	tbVec2 triangle[6] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, d}, {d, 1.0f}};
	tbHull hull = tbComputeHull(triangle, 6);
	cr_expect_eq(hull.count, 3);
	cr_expect(tbValidateHull(&hull));
}

Test(hull, rejects_collinear_points)
{
	tbVec2 line[5] = {{0.0f, 0.0f}, {1.0f, 1.0f}, {2.0f, 2.0f}, {-3.0f, -3.0f}, {0.5f, 0.5f}};
	cr_expect_eq(tbComputeHull(line, 5).count, 0);
	// Nearly collinear: every point within half a slop of the x axis.
	const float e = 0.5f * TB_LINEAR_SLOP;
	tbVec2 nearly[5] = {{0.0f, 0.0f}, {1.0f, e}, {2.0f, -e}, {3.0f, 0.0f}, {1.5f, e}};
	cr_expect_eq(tbComputeHull(nearly, 5).count, 0);
	// Vertical line (leftmost and rightmost points share x).
	tbVec2 vertical[3] = {{0.0f, 0.0f}, {0.0f, 1.0f}, {0.0f, -2.0f}};
	cr_expect_eq(tbComputeHull(vertical, 3).count, 0);
}

// Three points a few centimetres apart and one a million metres away on both axes: quickhull
// kept all four, but checked again in float the small turns are lost to rounding, and
// tbValidateHull (so tbMakePolygon) refused the hull tbComputeHull had returned;
// tbDecomposePolygon then wrote a piece of 0 vertices (found by fuzz/fuzz_decompose.c). A hull is
// now returned only if it is valid.
Test(hull, a_hull_lost_to_rounding_is_not_returned)
{
	tbVec2 points[4] = {{-0.0123419305f, -0.036303062f},
						{-1000000.0f, -1000000.0f},
						{-0.0212976839f, 0.0318848565f},
						{0.0254818574f, -0.0185136516f}};
	tbHull hull = tbComputeHull(points, 4);
	cr_expect(hull.count == 0 || tbValidateHull(&hull), "a hull of %d points that tbValidateHull refuses",
			  hull.count);
	silenceErrors();
	tbPolygon pieces[2];
	int count = tbDecomposePolygon(points, 4, pieces, 2);
	for (int i = 0; i < count; ++i)
	{
		cr_expect(pieces[i].count >= 3, "piece %d has %d vertices", i, pieces[i].count);
	}
	cr_expect_eq(s_errors, count == 0 ? 1 : 0, "%d pieces and %d errors", count, s_errors);
	restoreErrors();
}

Test(hull, rejects_non_finite_points)
{
	silenceErrors();
	tbVec2 points[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}};
	points[2].x = NAN;
	cr_expect_eq(tbComputeHull(points, 4).count, 0);
	points[2].x = 0.0f;
	points[3].y = INFINITY;
	cr_expect_eq(tbComputeHull(points, 4).count, 0);
	points[3].y = -INFINITY;
	cr_expect_eq(tbComputeHull(points, 4).count, 0);
	cr_expect_eq(s_errors, 3, "each non-finite input is reported");
	restoreErrors();
}

Test(hull, validate_rejects_bad_hulls)
{
	tbHull ccw = {{{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}}, 4};
	cr_expect(tbValidateHull(&ccw));
	tbHull cw = {{{0.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}}, 4};
	cr_expect(tbValidateHull(&cw) == false, "clockwise");
	tbHull collinear = {{{0.0f, 0.0f}, {0.5f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}}, 4};
	cr_expect(tbValidateHull(&collinear) == false, "collinear vertex");
	tbHull duplicate = {{{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}}, 4};
	cr_expect(tbValidateHull(&duplicate) == false, "duplicate vertex");
	tbHull concave = {{{0.0f, 0.0f}, {2.0f, 0.0f}, {1.0f, 0.5f}, {2.0f, 2.0f}, {0.0f, 2.0f}}, 5};
	cr_expect(tbValidateHull(&concave) == false, "reflex vertex");
	tbHull tooSmall = {{{0.0f, 0.0f}, {1.0f, 0.0f}}, 2};
	cr_expect(tbValidateHull(&tooSmall) == false);
}
