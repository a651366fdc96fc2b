// Tests for epa.c (tbShapeSeparation): penetration depth and normal against closed forms.
//
// Tolerances: coordinates here are at most ~100 m; EPA's answer is exact for polygons up to
// rounding (its Minkowski difference is a polygon and the closest edge is found exactly), so
// the tolerance is a few float ulps of the shape size: 1e-5 m for shapes of ~1 m, scaled with
// the size elsewhere, as each test states.

#include <criterion/criterion.h>

#include "tumble/collision.h"

#include <math.h>

static tbDistanceInput makeBoxInput(float hx, float hy, tbTransform xfA, float hx2, float hy2, tbTransform xfB)
{
	tbPolygon a = tbMakeBox(hx, hy);
	tbPolygon b = tbMakeBox(hx2, hy2);
	tbDistanceInput input = {0};
	input.proxyA = tbMakeProxy(a.vertices, a.count, 0.0f);
	input.proxyB = tbMakeProxy(b.vertices, b.count, 0.0f);
	input.transform = tbInvMulTransforms(xfA, xfB); // the answer comes in A's frame
	input.useRadii = true;
	return input;
}

static tbTransform at(float x, float y, float angle)
{
	tbTransform xf = {{x, y}, tbMakeRot(angle)};
	return xf;
}

static void expectUnit(tbVec2 n)
{
	cr_assert(isfinite(n.x) && isfinite(n.y));
	cr_assert_float_eq(tbLength(n), 1.0f, 1e-5f);
}

Test(epa, box_box_axis_aligned)
{
	// unit boxes (half 0.5) with B at (0.8, 0.1): overlap 0.2 along x, 0.9 along y -> depth 0.2, +x
	tbDistanceInput input = makeBoxInput(0.5f, 0.5f, at(0.0f, 0.0f, 0.0f), 0.5f, 0.5f, at(0.8f, 0.1f, 0.0f));
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	cr_assert(out.usedEPA);
	cr_assert_float_eq(out.separation, -0.2f, 1e-5f);
	cr_assert_float_eq(out.normal.x, 1.0f, 1e-5f);
	cr_assert_float_eq(out.normal.y, 0.0f, 1e-5f);
	// deepest points: B's left face at x = 0.3 and A's right face at x = 0.5, along the normal
	cr_assert_float_eq(out.pointA.x, 0.5f, 1e-5f);
	cr_assert_float_eq(out.pointB.x, 0.3f, 1e-5f);
	cr_assert(out.iterations > 0);

	// each of the four directions, with different box sizes: depth = (hxA + hxB) − |dx|
	float offsets[4][2] = {{1.2f, 0.3f}, {-1.2f, -0.2f}, {0.1f, 0.9f}, {-0.3f, -0.95f}};
	for (int i = 0; i < 4; ++i)
	{
		input = makeBoxInput(1.0f, 0.5f, at(0.0f, 0.0f, 0.0f), 0.3f, 0.6f, at(offsets[i][0], offsets[i][1], 0.0f));
		out = tbShapeSeparation(&input, NULL);
		float depthX = 1.3f - fabsf(offsets[i][0]);
		float depthY = 1.1f - fabsf(offsets[i][1]);
		float depth = fminf(depthX, depthY);
		cr_assert_float_eq(out.separation, -depth, 1e-5f, "case %d: %g", i, (double)out.separation);
		tbVec2 expected = depthX < depthY ? tbMakeVec2(copysignf(1.0f, offsets[i][0]), 0.0f)
										  : tbMakeVec2(0.0f, copysignf(1.0f, offsets[i][1]));
		cr_assert_float_eq(out.normal.x, expected.x, 1e-5f, "case %d", i);
		cr_assert_float_eq(out.normal.y, expected.y, 1e-5f, "case %d", i);
	}
}

Test(epa, rotated_frame_gives_rotated_answer)
{
	// the same overlap as above with both boxes turned by 0.7 rad: in A's frame, where the answer
	// comes, nothing changed (normal +x, depth 0.2); turned back to the world, the normal turns
	tbRot q = tbMakeRot(0.7f);
	tbVec2 pB = tbRotateVector(q, tbMakeVec2(0.8f, 0.1f));
	tbDistanceInput input = makeBoxInput(0.5f, 0.5f, at(0.0f, 0.0f, 0.7f), 0.5f, 0.5f, at(pB.x, pB.y, 0.7f));
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	cr_assert_float_eq(out.separation, -0.2f, 1e-5f);
	tbVec2 world = tbRotateVector(q, out.normal);
	cr_assert_float_eq(world.x, q.c, 1e-5f);
	cr_assert_float_eq(world.y, q.s, 1e-5f);
}

Test(epa, circle_circle_overlap)
{
	// circles as one-point proxies: separation = |c2 − c1| − r1 − r2 (cores apart, no EPA)
	tbVec2 c1 = {0.0f, 0.0f}, c2 = {0.3f, 0.4f};
	tbDistanceInput input = {0};
	input.proxyA = tbMakeProxy(&c1, 1, 0.5f);
	input.proxyB = tbMakeProxy(&c2, 1, 0.25f);
	input.transform = tbTransform_identity;
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	cr_assert_float_eq(out.separation, 0.5f - 0.75f, 1e-6f);
	cr_assert_float_eq(out.normal.x, 0.6f, 1e-6f);
	cr_assert_float_eq(out.normal.y, 0.8f, 1e-6f);
	cr_assert_float_eq(out.pointA.x, 0.3f, 1e-6f); // c1 + r1·n
	cr_assert_float_eq(out.pointB.y, 0.4f - 0.2f, 1e-6f); // c2 − r2·n
	cr_assert(out.usedEPA == false);

	// concentric circles: depth r1 + r2, any unit normal
	input.proxyB = tbMakeProxy(&c1, 1, 0.25f);
	out = tbShapeSeparation(&input, NULL);
	cr_assert_float_eq(out.separation, -0.75f, 1e-6f);
	expectUnit(out.normal);
}

Test(epa, rounded_boxes_add_radii)
{
	// rounded boxes: core overlap 0.1 along x, radii 0.05 each -> separation −0.2
	tbDistanceInput input = makeBoxInput(0.5f, 0.5f, at(0.0f, 0.0f, 0.0f), 0.5f, 0.5f, at(0.9f, 0.0f, 0.0f));
	input.proxyA.radius = 0.05f;
	input.proxyB.radius = 0.05f;
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	cr_assert_float_eq(out.separation, -0.2f, 1e-5f);
	cr_assert_float_eq(out.pointA.x, 0.55f, 1e-5f); // A's surface: core face 0.5 + radius
	cr_assert_float_eq(out.pointB.x, 0.35f, 1e-5f); // B's surface: core face 0.4 − radius
}

Test(epa, deep_overlap)
{
	// small box deep inside a large one: B (half 0.2) at (1.5, 0.4) in A (half 2 × 1):
	// distances to A's faces: right 2 − 1.5 + 0.2 = 0.7, top 1 − 0.4 + 0.2 = 0.8 -> depth 0.7, +x
	tbDistanceInput input = makeBoxInput(2.0f, 1.0f, at(0.0f, 0.0f, 0.0f), 0.2f, 0.2f, at(1.5f, 0.4f, 0.0f));
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	cr_assert(out.usedEPA);
	cr_assert_float_eq(out.separation, -0.7f, 1e-5f);
	cr_assert_float_eq(out.normal.x, 1.0f, 1e-5f);
}

Test(epa, identical_coincident_shapes)
{
	// identical boxes, identical transforms: depth is the smaller full width (1.0 for a 2 × 1 box
	// of half-widths 1 × 0.5); the normal must be a finite unit vector along ±y
	tbDistanceInput input = makeBoxInput(1.0f, 0.5f, at(3.0f, -2.0f, 0.3f), 1.0f, 0.5f, at(3.0f, -2.0f, 0.3f));
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	expectUnit(out.normal);
	cr_assert_float_eq(out.separation, -1.0f, 1e-5f);
	tbVec2 localNormal = out.normal; // A's frame
	cr_assert_float_eq(fabsf(localNormal.y), 1.0f, 1e-5f);

	// coincident points (two zero-radius point proxies): a defined unit normal, separation 0
	tbVec2 p = {1.0f, 1.0f};
	tbDistanceInput points = {0};
	points.proxyA = tbMakeProxy(&p, 1, 0.0f);
	points.proxyB = tbMakeProxy(&p, 1, 0.0f);
	points.transform = tbTransform_identity;
	out = tbShapeSeparation(&points, NULL);
	expectUnit(out.normal);
	cr_assert_float_eq(out.separation, 0.0f, 1e-6f);

	// collinear overlapping segments: flat Minkowski difference, depth 0 across it
	tbVec2 segment[2] = {{0.0f, 0.0f}, {1.0f, 0.0f}};
	points.proxyA = tbMakeProxy(segment, 2, 0.0f);
	points.proxyB = tbMakeProxy(segment, 2, 0.0f);
	points.transform = at(0.5f, 0.0f, 0.0f);
	out = tbShapeSeparation(&points, NULL);
	expectUnit(out.normal);
	cr_assert_float_eq(out.separation, 0.0f, 1e-6f);
	cr_assert_float_eq(fabsf(out.normal.y), 1.0f, 1e-6f);
}

Test(epa, touching_shapes)
{
	// face to face, exactly touching (B at x = 1): separation 0, normal +x
	tbDistanceInput input = makeBoxInput(0.5f, 0.5f, at(0.0f, 0.0f, 0.0f), 0.5f, 0.5f, at(1.0f, 0.3f, 0.0f));
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	expectUnit(out.normal);
	cr_assert_float_eq(out.separation, 0.0f, 1e-6f);
	cr_assert_float_eq(out.normal.x, 1.0f, 1e-5f);

	// corner to corner, exactly touching at (0.5, 0.5): separation 0, some unit normal
	input = makeBoxInput(0.5f, 0.5f, at(0.0f, 0.0f, 0.0f), 0.5f, 0.5f, at(1.0f, 1.0f, 0.0f));
	out = tbShapeSeparation(&input, NULL);
	expectUnit(out.normal);
	cr_assert_float_eq(out.separation, 0.0f, 1e-6f);
	cr_assert(out.normal.x >= 0.0f && out.normal.y >= 0.0f);

	// touching and just apart / just overlapping by 1 µm: continuous through zero
	for (int k = -1; k <= 1; ++k)
	{
		float gap = 1e-6f * (float)k;
		input = makeBoxInput(0.5f, 0.5f, at(0.0f, 0.0f, 0.0f), 0.5f, 0.5f, at(0.0f, 1.0f + gap, 0.0f));
		out = tbShapeSeparation(&input, NULL);
		cr_assert_float_eq(out.separation, gap, 2e-7f, "gap %g: %g", (double)gap, (double)out.separation);
		cr_assert_float_eq(out.normal.y, 1.0f, 1e-5f);
	}
}

Test(epa, large_shapes)
{
	// 100 m boxes (half 50) overlapping by 0.01 m along y, 200 m from the origin. At 100 m a
	// float resolves 7.6e-6 m, so the tolerance is 1e-4 m (~ 13 ulps).
	tbDistanceInput input = makeBoxInput(50.0f, 50.0f, at(200.0f, 200.0f, 0.0f), 50.0f, 50.0f, at(230.0f, 299.99f, 0.0f));
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	cr_assert_float_eq(out.separation, -0.01f, 1e-4f, "%g", (double)out.separation);
	cr_assert_float_eq(out.normal.y, 1.0f, 1e-5f);

	// deep: 30 m along x (B at +70 m) is shallower than 100 m along y
	input = makeBoxInput(50.0f, 50.0f, at(0.0f, 0.0f, 0.0f), 50.0f, 50.0f, at(70.0f, 0.0f, 0.0f));
	out = tbShapeSeparation(&input, NULL);
	cr_assert_float_eq(out.separation, -30.0f, 1e-4f);
	cr_assert_float_eq(out.normal.x, 1.0f, 1e-5f);
}

Test(epa, millimetre_shapes)
{
	// 1 mm boxes (half 0.5 mm) overlapping by 0.1 mm, 10 m from the origin. Work in A's frame
	// keeps ~1e-10 m relative precision; tolerance 1e-8 m (1e-5 of the size).
	tbDistanceInput input =
		makeBoxInput(0.0005f, 0.0005f, at(10.0f, 0.0f, 0.0f), 0.0005f, 0.0005f, at(10.0f, 0.0009f, 0.0f));
	tbSeparationOutput out = tbShapeSeparation(&input, NULL);
	// B sits 0.9 mm above A as rounded at 10 m (resolution 9.5e-7 m): depth from the actual offset
	float actual = input.transform.p.y;
	cr_assert_float_eq(out.separation, actual - 0.001f, 1e-8f, "%g", (double)out.separation);
	cr_assert_float_eq(out.normal.y, 1.0f, 1e-5f);

	// and apart by 0.1 mm: GJK answers, no overlap reported
	input = makeBoxInput(0.0005f, 0.0005f, at(0.0f, 0.0f, 0.0f), 0.0005f, 0.0005f, at(0.0f, 0.0011f, 0.0f));
	out = tbShapeSeparation(&input, NULL);
	cr_assert(out.usedEPA == false);
	cr_assert_float_eq(out.separation, 0.0001f, 1e-8f);
}

Test(epa, warm_cache_and_rotated_overlaps)
{
	// square B turned by 45° poking into A's top face: tip depth 0.1 -> separation −0.1, +y
	float h = 0.5f;
	float tip = h * sqrtf(2.0f);
	tbDistanceInput input = makeBoxInput(h, h, at(0.0f, 0.0f, 0.0f), h, h, at(0.0f, h + tip - 0.1f, 0.25f * TB_PI));
	tbSimplexCache cache = {0};
	tbSeparationOutput cold = tbShapeSeparation(&input, &cache);
	tbSeparationOutput warm = tbShapeSeparation(&input, &cache);
	cr_assert_float_eq(cold.separation, -0.1f, 1e-5f);
	cr_assert_float_eq(cold.normal.y, 1.0f, 1e-5f);
	cr_assert_float_eq(warm.separation, cold.separation, 1e-6f);
}
