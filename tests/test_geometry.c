// Tests of geometry.c: mass properties against closed forms, bounding boxes, point tests and
// ray casts against hand-computed answers.
//
// Tolerances: masses and inertias are sums of a handful of float products, each rounded to
// u = 2⁻²⁴ ≈ 6e-8 relative, so they match the double-precision closed forms to ~1e-6 relative;
// tests allow MASS_REL_TOL = 1e-5. Points, normals and fractions of order 1 that pass through a
// square root and a few products match hand values to ~1e-6; tests allow GEOMETRY_TOL = 1e-5.

#include "tumble/collision.h"

#include <criterion/criterion.h>
#include <math.h>

#define MASS_REL_TOL 1e-5
#define GEOMETRY_TOL 1e-5f
#define PI_D 3.14159265358979323846

static void expectRelative(float actual, double expected, double relative, const char* what)
{
	double error = fabs((double)actual - expected);
	double bound = relative * fmax(fabs(expected), 1e-12);
	cr_expect(error <= bound, "%s: %.9g, expected %.9g (relative error %.3g)", what, (double)actual, expected,
			  error / fmax(fabs(expected), 1e-12));
}

static void expectVec2Near(tbVec2 a, tbVec2 b, float tolerance, const char* what)
{
	cr_expect(fabsf(a.x - b.x) <= tolerance && fabsf(a.y - b.y) <= tolerance, "%s: (%.9g, %.9g), expected (%.9g, %.9g)",
			  what, (double)a.x, (double)a.y, (double)b.x, (double)b.y);
}

static void expectHit(tbCastOutput out, tbVec2 point, tbVec2 normal, float fraction)
{
	cr_assert(out.hit, "expected a hit");
	expectVec2Near(out.point, point, GEOMETRY_TOL, "hit point");
	expectVec2Near(out.normal, normal, GEOMETRY_TOL, "hit normal");
	cr_expect(fabsf(out.fraction - fraction) <= GEOMETRY_TOL, "fraction %.9g, expected %.9g", (double)out.fraction,
			  (double)fraction);
}

static tbRayCastInput makeRay(float ox, float oy, float dx, float dy)
{
	tbRayCastInput input = {{ox, oy}, {dx, dy}, 1.0f};
	return input;
}

static void expectAABB(tbAABB box, float lx, float ly, float ux, float uy)
{
	expectVec2Near(box.lowerBound, tbMakeVec2(lx, ly), GEOMETRY_TOL, "lower bound");
	expectVec2Near(box.upperBound, tbMakeVec2(ux, uy), GEOMETRY_TOL, "upper bound");
}

// ---------------------------------------------------------------------------------------------
// Mass

Test(geometry, disc_mass)
{
	// m = ρπr², centre at the circle centre, I = m r²/2.
	tbCircle circle = {{1.0f, -2.0f}, 0.5f};
	tbMassData md = tbComputeCircleMass(&circle, 2.0f);
	double m = 2.0 * PI_D * 0.25;
	expectRelative(md.mass, m, MASS_REL_TOL, "mass");
	expectRelative(md.rotationalInertia, m * 0.25 / 2.0, MASS_REL_TOL, "inertia");
	expectVec2Near(md.center, circle.center, 0.0f, "centre");
}

Test(geometry, box_mass_and_shape)
{
	// Box w × h = 3 × 1, ρ = 3: m = ρwh = 9, I = m(w² + h²)/12 = 9·10/12 = 7.5.
	tbPolygon box = tbMakeBox(1.5f, 0.5f);
	cr_assert_eq(box.count, 4);
	tbMassData md = tbComputePolygonMass(&box, 3.0f);
	expectRelative(md.mass, 9.0, MASS_REL_TOL, "mass");
	expectRelative(md.rotationalInertia, 7.5, MASS_REL_TOL, "inertia");
	expectVec2Near(md.center, tbVec2_zero, GEOMETRY_TOL, "centre");
	expectVec2Near(box.centroid, tbVec2_zero, 0.0f, "centroid");
	// Outward unit normals: each vertex lies on its edge's line n·x = offset.
	for (int i = 0; i < 4; ++i)
	{
		cr_expect(tbIsNormalized(box.normals[i]));
		tbVec2 next = box.vertices[(i + 1) % 4];
		cr_expect(fabsf(tbDot(box.normals[i], tbSub(next, box.vertices[i]))) <= GEOMETRY_TOL);
		cr_expect(tbDot(box.normals[i], box.vertices[i]) > 0.0f, "normal %d points outward", i);
	}
	tbPolygon square = tbMakeSquare(0.5f);
	expectRelative(tbComputePolygonMass(&square, 1.0f).rotationalInertia, 1.0 * 2.0 / 12.0, MASS_REL_TOL,
				   "unit square I = (1 + 1)/12");
}

Test(geometry, offset_rotated_box_mass)
{
	// Offsetting and rotating moves the centre of mass but not the inertia about it:
	// 2 × 1 box, ρ = 2: m = 4, I = 4·(4 + 1)/12 = 5/3, centre (2, 1).
	tbRot q = tbMakeRot(0.6f);
	tbPolygon box = tbMakeOffsetBox(1.0f, 0.5f, tbMakeVec2(2.0f, 1.0f), q);
	tbMassData md = tbComputePolygonMass(&box, 2.0f);
	expectRelative(md.mass, 4.0, MASS_REL_TOL, "mass");
	expectRelative(md.rotationalInertia, 5.0 / 3.0, MASS_REL_TOL, "inertia");
	expectVec2Near(md.center, tbMakeVec2(2.0f, 1.0f), GEOMETRY_TOL, "centre");
	expectVec2Near(box.centroid, tbMakeVec2(2.0f, 1.0f), GEOMETRY_TOL, "centroid");
	// Normal 1 is the box's +x axis rotated by 0.6 rad.
	expectVec2Near(box.normals[1], tbMakeVec2(q.c, q.s), GEOMETRY_TOL, "rotated normal");

	// tbTransformPolygon of the centred box gives the same polygon.
	tbTransform xf = {{2.0f, 1.0f}, q};
	tbPolygon moved = tbTransformPolygon(xf, (const tbPolygon[]){tbMakeBox(1.0f, 0.5f)});
	for (int i = 0; i < 4; ++i)
	{
		expectVec2Near(moved.vertices[i], box.vertices[i], GEOMETRY_TOL, "transformed vertex");
	}
}

// Capsule closed form: rectangle L × 2r plus two half discs. About the capsule centre,
// rectangle I = m_rect(L² + (2r)²)/12; each half disc has I = m_half r²/2 about its flat-side
// centre and its centroid d = 4r/(3π) beyond the end, so by the parallel axis theorem
// I_half = m_half(r²/2 − d²) + m_half(L/2 + d)².
static void capsuleClosedForm(double L, double r, double rho, double* mass, double* inertia)
{
	double mRect = rho * L * 2.0 * r;
	double mHalf = rho * PI_D * r * r / 2.0;
	double d = 4.0 * r / (3.0 * PI_D);
	*mass = mRect + 2.0 * mHalf;
	double iRect = mRect * (L * L + 4.0 * r * r) / 12.0;
	double iHalf = mHalf * (r * r / 2.0 - d * d) + mHalf * (L / 2.0 + d) * (L / 2.0 + d);
	*inertia = iRect + 2.0 * iHalf;
}

Test(geometry, capsule_mass)
{
	// Tilted capsule of length L = 2.5 (3-4-5 direction), r = 0.4, ρ = 1.5.
	tbCapsule capsule = {{1.0f, 1.0f}, {1.0f + 1.5f, 1.0f + 2.0f}, 0.4f};
	double m, I;
	capsuleClosedForm(2.5, 0.4, 1.5, &m, &I);
	tbMassData md = tbComputeCapsuleMass(&capsule, 1.5f);
	expectRelative(md.mass, m, MASS_REL_TOL, "mass");
	expectRelative(md.rotationalInertia, I, MASS_REL_TOL, "inertia");
	expectVec2Near(md.center, tbMakeVec2(1.75f, 2.0f), GEOMETRY_TOL, "centre");

	// Zero length: a disc, I = m r²/2.
	tbCapsule dot = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.4f};
	md = tbComputeCapsuleMass(&dot, 1.0f);
	expectRelative(md.rotationalInertia, PI_D * 0.16 * 0.16 / 2.0, MASS_REL_TOL, "disc limit");
}

Test(geometry, rounded_box_tends_to_capsule)
{
	// Independent cross-check of the capsule and rounded-polygon paths: a rounded box with core
	// half-height ε → 0 is a capsule with L = 2·hx. The difference is the strip of area
	// 2ε(2hx + 2r) = 6e-3 m² (ε = 1e-3, hx = 1, r = 0.5) against 2.79 m², so ~0.2 %; allow 0.5 %.
	tbPolygon thin = tbMakeRoundedBox(1.0f, 1e-3f, 0.5f);
	tbCapsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
	tbMassData a = tbComputePolygonMass(&thin, 1.0f);
	tbMassData b = tbComputeCapsuleMass(&capsule, 1.0f);
	expectRelative(a.mass, b.mass, 5e-3, "mass");
	expectRelative(a.rotationalInertia, b.rotationalInertia, 5e-3, "inertia");
}

Test(geometry, triangle_mass)
{
	// Right triangle (0,0), (3,0), (0,2), ρ = 1: area = 3, centroid = mean of the vertices
	// = (1, 2/3), and about the centroid I = m(a² + b² + c²)/36 with sides² 9, 4, 13:
	// I = 3·26/36 = 13/6.
	tbVec2 points[3] = {{0.0f, 2.0f}, {3.0f, 0.0f}, {0.0f, 0.0f}};
	tbHull hull = tbComputeHull(points, 3);
	cr_assert_eq(hull.count, 3);
	tbPolygon triangle = tbMakePolygon(&hull, 0.0f);
	tbMassData md = tbComputePolygonMass(&triangle, 1.0f);
	expectRelative(md.mass, 3.0, MASS_REL_TOL, "mass");
	expectRelative(md.rotationalInertia, 13.0 / 6.0, MASS_REL_TOL, "inertia");
	expectVec2Near(md.center, tbMakeVec2(1.0f, 2.0f / 3.0f), GEOMETRY_TOL, "centre");
	expectVec2Near(triangle.centroid, tbMakeVec2(1.0f, 2.0f / 3.0f), GEOMETRY_TOL, "centroid");
}

Test(geometry, rounded_box_mass)
{
	// Core 2hx × 2hy plus skin r: four edge strips and four quarter discs (one full disc).
	//   m/ρ = 4hx·hy + 2r(2hx + 2hy) + πr²
	//   I/ρ = core  A₀(w² + h²)/12                             (w = 2hx, h = 2hy, A₀ = wh)
	//       + top/bottom strips 2·[wr(w² + r²)/12 + wr(hy + r/2)²]
	//       + side strips       2·[hr(h² + r²)/12 + hr(hx + r/2)²]
	//       + quarter discs     πr⁴/2 + (8/3)r³(hx + hy) + πr²(hx² + hy²)
	// (each quarter disc: πr⁴/8 about its corner, centroid 4r/(3π) out along both axes,
	// moved to the origin with ∫|x|² = I_v + 2·m·v·(c − v) + m|v|²).
	const double hx = 1.0, hy = 0.5, r = 0.25, rho = 2.0;
	double w = 2.0 * hx, h = 2.0 * hy;
	double area = w * h + 2.0 * r * (w + h) + PI_D * r * r;
	double inertia = w * h * (w * w + h * h) / 12.0;
	inertia += 2.0 * (w * r * (w * w + r * r) / 12.0 + w * r * (hy + r / 2.0) * (hy + r / 2.0));
	inertia += 2.0 * (h * r * (h * h + r * r) / 12.0 + h * r * (hx + r / 2.0) * (hx + r / 2.0));
	inertia += PI_D * r * r * r * r / 2.0 + 8.0 / 3.0 * r * r * r * (hx + hy) + PI_D * r * r * (hx * hx + hy * hy);

	tbPolygon box = tbMakeRoundedBox((float)hx, (float)hy, (float)r);
	tbMassData md = tbComputePolygonMass(&box, (float)rho);
	expectRelative(md.mass, rho * area, MASS_REL_TOL, "mass");
	expectRelative(md.rotationalInertia, rho * inertia, MASS_REL_TOL, "inertia");
	expectVec2Near(md.center, tbVec2_zero, GEOMETRY_TOL, "centre");

	// The same rounded box moved off the origin and turned keeps m and I about its centre.
	tbTransform xf = {{-3.0f, 2.0f}, tbMakeRot(1.1f)};
	tbPolygon moved = tbTransformPolygon(xf, &box);
	md = tbComputePolygonMass(&moved, (float)rho);
	expectRelative(md.mass, rho * area, MASS_REL_TOL, "moved mass");
	// Moments about a point 3.6 m away: cancellation in I_o − m|c − o|² costs a few more bits.
	expectRelative(md.rotationalInertia, rho * inertia, 1e-4, "moved inertia");
	expectVec2Near(md.center, xf.p, GEOMETRY_TOL, "moved centre");
}

Test(geometry, shape_mass_dispatch)
{
	tbGeometry segment = {.type = tb_segmentShape, .segment = {{0.0f, 0.0f}, {2.0f, 0.0f}}};
	tbMassData md = tbComputeShapeMass(&segment, 1.0f);
	cr_expect(md.mass == 0.0f && md.rotationalInertia == 0.0f, "segments have no mass");
	tbGeometry circle = {.type = tb_circleShape, .circle = {{0.0f, 0.0f}, 1.0f}};
	expectRelative(tbComputeShapeMass(&circle, 1.0f).mass, PI_D, MASS_REL_TOL, "circle via tagged union");
	tbGeometry box = {.type = tb_polygonShape, .polygon = tbMakeBox(1.0f, 1.0f)};
	expectRelative(tbComputeShapeMass(&box, 0.5f).mass, 2.0, MASS_REL_TOL, "box via tagged union");
}

// ---------------------------------------------------------------------------------------------
// Bounding boxes

Test(geometry, shape_aabbs)
{
	// Box 2 × 1 turned 45° at (1, 2): half extent on each axis (hx + hy)·cos 45° = 1.5·√½.
	tbGeometry box = {.type = tb_polygonShape, .polygon = tbMakeBox(1.0f, 0.5f)};
	tbTransform xf45 = {{1.0f, 2.0f}, tbMakeRot(0.25f * TB_PI)};
	float e = 1.5f * 0.70710678f;
	expectAABB(tbComputeShapeAABB(&box, xf45), 1.0f - e, 2.0f - e, 1.0f + e, 2.0f + e);

	// Capsule (−1,0)–(1,0), r = 0.5, turned 90° and raised by 1: centres (0,0) and (0,2).
	tbGeometry capsule = {.type = tb_capsuleShape, .capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f}};
	tbTransform xf90 = {{0.0f, 1.0f}, {0.0f, 1.0f}};
	expectAABB(tbComputeShapeAABB(&capsule, xf90), -0.5f, -0.5f, 0.5f, 2.5f);

	// Circle at local (1, 0), r = 0.25, body at (2, 3) turned 90°: centre (2, 4).
	tbGeometry circle = {.type = tb_circleShape, .circle = {{1.0f, 0.0f}, 0.25f}};
	tbTransform xfCircle = {{2.0f, 3.0f}, {0.0f, 1.0f}};
	expectAABB(tbComputeShapeAABB(&circle, xfCircle), 1.75f, 3.75f, 2.25f, 4.25f);

	// Segment (0,0)–(2,1) turned 180° and moved by (1,1): ends (1,1) and (−1,0).
	tbGeometry segment = {.type = tb_segmentShape, .segment = {{0.0f, 0.0f}, {2.0f, 1.0f}}};
	tbTransform xf180 = {{1.0f, 1.0f}, {-1.0f, 0.0f}};
	expectAABB(tbComputeShapeAABB(&segment, xf180), -1.0f, 0.0f, 1.0f, 1.0f);

	// Rounded box: core plus radius on every side.
	tbGeometry rounded = {.type = tb_polygonShape, .polygon = tbMakeRoundedBox(1.0f, 0.5f, 0.1f)};
	expectAABB(tbComputeShapeAABB(&rounded, tbTransform_identity), -1.1f, -0.6f, 1.1f, 0.6f);
}

// ---------------------------------------------------------------------------------------------
// Point tests

Test(geometry, point_in_shape)
{
	tbGeometry circle = {.type = tb_circleShape, .circle = {{1.0f, 0.0f}, 0.5f}};
	cr_expect(tbPointInShape(&circle, tbMakeVec2(1.4f, 0.0f)));
	cr_expect(tbPointInShape(&circle, tbMakeVec2(1.4f, 0.4f)) == false);

	tbGeometry capsule = {.type = tb_capsuleShape, .capsule = {{0.0f, 0.0f}, {2.0f, 0.0f}, 0.5f}};
	cr_expect(tbPointInShape(&capsule, tbMakeVec2(1.0f, 0.45f)));
	cr_expect(tbPointInShape(&capsule, tbMakeVec2(-0.45f, 0.0f)));
	cr_expect(tbPointInShape(&capsule, tbMakeVec2(-0.4f, 0.4f)) == false, "outside the end cap (0.566 > 0.5)");

	tbGeometry box = {.type = tb_polygonShape, .polygon = tbMakeBox(1.0f, 0.5f)};
	cr_expect(tbPointInShape(&box, tbMakeVec2(0.9f, -0.4f)));
	cr_expect(tbPointInShape(&box, tbMakeVec2(1.1f, 0.0f)) == false);

	// Rounded box, core 1 × 1 with r = 0.5: the corner is a quarter disc about (1, 1).
	tbGeometry rounded = {.type = tb_polygonShape, .polygon = tbMakeRoundedBox(1.0f, 1.0f, 0.5f)};
	cr_expect(tbPointInShape(&rounded, tbMakeVec2(1.3f, 1.3f)), "0.42 from the corner");
	cr_expect(tbPointInShape(&rounded, tbMakeVec2(1.4f, 1.4f)) == false, "0.57 from the corner");
	cr_expect(tbPointInShape(&rounded, tbMakeVec2(0.0f, 1.45f)));

	tbGeometry segment = {.type = tb_segmentShape, .segment = {{0.0f, 0.0f}, {1.0f, 0.0f}}};
	cr_expect(tbPointInShape(&segment, tbMakeVec2(0.5f, 0.0f)) == false, "segments are not solid");
}

// ---------------------------------------------------------------------------------------------
// Ray casts

Test(geometry, ray_cast_circle)
{
	tbCircle circle = {{2.0f, 0.0f}, 1.0f};
	// Head-on along x from (−1, 0), length 4: surface at x = 1, fraction (1 − (−1))/4 = 0.5.
	tbRayCastInput input = makeRay(-1.0f, 0.0f, 4.0f, 0.0f);
	expectHit(tbRayCastCircle(&circle, &input), tbMakeVec2(1.0f, 0.0f), tbMakeVec2(-1.0f, 0.0f), 0.5f);
	// At height 0.6: x = 2 − √(1 − 0.36) = 1.2, fraction 2.2/4 = 0.55, normal (−0.8, 0.6).
	input = makeRay(-1.0f, 0.6f, 4.0f, 0.0f);
	expectHit(tbRayCastCircle(&circle, &input), tbMakeVec2(1.2f, 0.6f), tbMakeVec2(-0.8f, 0.6f), 0.55f);
	// Misses: passes above; too short (maxFraction 0.4 < 0.5); pointing away; zero length.
	input = makeRay(-1.0f, 1.5f, 4.0f, 0.0f);
	cr_expect(tbRayCastCircle(&circle, &input).hit == false);
	input = makeRay(-1.0f, 0.0f, 4.0f, 0.0f);
	input.maxFraction = 0.4f;
	cr_expect(tbRayCastCircle(&circle, &input).hit == false);
	input = makeRay(-1.0f, 0.0f, -4.0f, 0.0f);
	cr_expect(tbRayCastCircle(&circle, &input).hit == false);
	input = makeRay(-1.0f, 0.0f, 0.0f, 0.0f);
	cr_expect(tbRayCastCircle(&circle, &input).hit == false);
	// Starting inside: no hit.
	input = makeRay(2.0f, 0.5f, 4.0f, 0.0f);
	cr_expect(tbRayCastCircle(&circle, &input).hit == false);
}

Test(geometry, ray_cast_capsule)
{
	tbCapsule capsule = {{0.0f, 0.0f}, {2.0f, 0.0f}, 0.5f};
	// Down onto the flat side: y = 0.5 at fraction 2.5/4.
	tbRayCastInput input = makeRay(1.0f, 3.0f, 0.0f, -4.0f);
	expectHit(tbRayCastCapsule(&capsule, &input), tbMakeVec2(1.0f, 0.5f), tbMakeVec2(0.0f, 1.0f), 0.625f);
	// Along the axis into the end cap: x = −0.5 at fraction 1.5/4.
	input = makeRay(-2.0f, 0.0f, 4.0f, 0.0f);
	expectHit(tbRayCastCapsule(&capsule, &input), tbMakeVec2(-0.5f, 0.0f), tbMakeVec2(-1.0f, 0.0f), 0.375f);
	// Into the cap at height 0.3: x = −√(0.25 − 0.09) = −0.4, fraction 1.6/4, normal (−0.8, 0.6).
	input = makeRay(-2.0f, 0.3f, 4.0f, 0.0f);
	expectHit(tbRayCastCapsule(&capsule, &input), tbMakeVec2(-0.4f, 0.3f), tbMakeVec2(-0.8f, 0.6f), 0.4f);
	// From the far side (+x), into the other cap: x = 2.5, fraction 1.5/4.
	input = makeRay(4.0f, 0.0f, -4.0f, 0.0f);
	expectHit(tbRayCastCapsule(&capsule, &input), tbMakeVec2(2.5f, 0.0f), tbMakeVec2(1.0f, 0.0f), 0.375f);
	// Miss: parallel just above; inside: no hit.
	input = makeRay(-2.0f, 0.6f, 6.0f, 0.0f);
	cr_expect(tbRayCastCapsule(&capsule, &input).hit == false);
	input = makeRay(1.0f, 0.2f, 0.0f, 4.0f);
	cr_expect(tbRayCastCapsule(&capsule, &input).hit == false);
}

Test(geometry, ray_cast_polygon)
{
	tbPolygon box = tbMakeBox(1.0f, 1.0f);
	// Into the left face at (−1, 0.5), fraction 2/4.
	tbRayCastInput input = makeRay(-3.0f, 0.5f, 4.0f, 0.0f);
	expectHit(tbRayCastPolygon(&box, &input), tbMakeVec2(-1.0f, 0.5f), tbMakeVec2(-1.0f, 0.0f), 0.5f);
	// Slanted from (3, 1.5) by (−4, −2): reaches x = 1 at t = 0.5 (y = 0.5) before y = 1 matters.
	input = makeRay(3.0f, 1.5f, -4.0f, -2.0f);
	expectHit(tbRayCastPolygon(&box, &input), tbMakeVec2(1.0f, 0.5f), tbMakeVec2(1.0f, 0.0f), 0.5f);
	// Miss above; too short; starting inside.
	input = makeRay(-3.0f, 2.0f, 4.0f, 0.0f);
	cr_expect(tbRayCastPolygon(&box, &input).hit == false);
	input = makeRay(-3.0f, 0.5f, 4.0f, 0.0f);
	input.maxFraction = 0.45f;
	cr_expect(tbRayCastPolygon(&box, &input).hit == false);
	input = makeRay(0.0f, 0.0f, 4.0f, 0.0f);
	cr_expect(tbRayCastPolygon(&box, &input).hit == false);

	// Offset, rotated box: 90° turns the 2 × 1 box upright at (5, 0); its left face is x = 4.5.
	tbPolygon offset = tbMakeOffsetBox(1.0f, 0.5f, tbMakeVec2(5.0f, 0.0f), tbMakeRot(0.5f * TB_PI));
	input = makeRay(0.0f, 0.25f, 9.0f, 0.0f);
	expectHit(tbRayCastPolygon(&offset, &input), tbMakeVec2(4.5f, 0.25f), tbMakeVec2(-1.0f, 0.0f), 0.5f);
}

Test(geometry, ray_cast_rounded_polygon)
{
	// Core 2 × 2 box with r = 0.5.
	tbPolygon rounded = tbMakeRoundedBox(1.0f, 1.0f, 0.5f);
	// Flat face pushed out to x = −1.5: fraction 1.5/4.
	tbRayCastInput input = makeRay(-3.0f, 0.0f, 4.0f, 0.0f);
	expectHit(tbRayCastPolygon(&rounded, &input), tbMakeVec2(-1.5f, 0.0f), tbMakeVec2(-1.0f, 0.0f), 0.375f);
	// Down the diagonal onto the corner arc about (1, 1): hit at 1 + 0.5·√½ on both axes,
	// fraction (3 − 1.3535534)/2, normal (√½, √½).
	input = makeRay(3.0f, 3.0f, -2.0f, -2.0f);
	float c = 1.0f + 0.5f * 0.70710678f;
	expectHit(tbRayCastPolygon(&rounded, &input), tbMakeVec2(c, c), tbMakeVec2(0.70710678f, 0.70710678f),
			  (3.0f - c) / 2.0f);
	// Passing the corner where a sharp box would be hit: y = 1.45 at x = 1.45 is 0.636 from (1, 1).
	input = makeRay(3.0f, 1.45f, 0.0f, 0.0f);
	input.translation = tbMakeVec2(-1.55f, 0.0f);
	cr_expect(tbRayCastPolygon(&rounded, &input).hit == false);
	// Inside the skin: no hit.
	input = makeRay(1.2f, 0.0f, 4.0f, 0.0f);
	cr_expect(tbRayCastPolygon(&rounded, &input).hit == false);
}

Test(geometry, ray_cast_segment)
{
	tbSegment segment = {{0.0f, -1.0f}, {0.0f, 1.0f}};
	// From the left, crossing at (0, 0.5), fraction 0.5; the normal faces the ray.
	tbRayCastInput input = makeRay(-2.0f, 0.5f, 4.0f, 0.0f);
	expectHit(tbRayCastSegment(&segment, &input, false), tbMakeVec2(0.0f, 0.5f), tbMakeVec2(-1.0f, 0.0f), 0.5f);
	// One-sided: solid only on the right of point1 → point2, i.e. the +x side here.
	cr_expect(tbRayCastSegment(&segment, &input, true).hit == false);
	input = makeRay(2.0f, 0.5f, -4.0f, 0.0f);
	expectHit(tbRayCastSegment(&segment, &input, true), tbMakeVec2(0.0f, 0.5f), tbMakeVec2(1.0f, 0.0f), 0.5f);
	// Misses: past the end, parallel, too short.
	input = makeRay(-2.0f, 1.5f, 4.0f, 0.0f);
	cr_expect(tbRayCastSegment(&segment, &input, false).hit == false);
	input = makeRay(0.0f, -3.0f, 0.0f, 6.0f);
	cr_expect(tbRayCastSegment(&segment, &input, false).hit == false);
	input = makeRay(-2.0f, 0.5f, 4.0f, 0.0f);
	input.maxFraction = 0.4f;
	cr_expect(tbRayCastSegment(&segment, &input, false).hit == false);
	// Through the tagged union (two-sided).
	tbGeometry shape = {.type = tb_segmentShape, .segment = segment};
	input = makeRay(2.0f, -0.5f, -4.0f, 0.0f);
	expectHit(tbRayCastShape(&shape, &input), tbMakeVec2(0.0f, -0.5f), tbMakeVec2(1.0f, 0.0f), 0.5f);
}

static void ignoreError(const char* message, void* context)
{
	(void)message;
	(void)context;
}

Test(geometry, invalid_input_is_reported_not_nan)
{
	int before = tbGetErrorCount();
	tbSetErrorCallback(ignoreError, NULL);
	tbHull bad = {{{0.0f, 0.0f}, {1.0f, 0.0f}}, 2};
	cr_expect_eq(tbMakePolygon(&bad, 0.0f).count, 0);
	cr_expect_eq(tbMakeBox(-1.0f, 1.0f).count, 0);
	tbCircle circle = {{0.0f, 0.0f}, 1.0f};
	tbRayCastInput input = makeRay(NAN, 0.0f, 1.0f, 0.0f);
	tbCastOutput out = tbRayCastCircle(&circle, &input);
	cr_expect(out.hit == false && out.fraction == 0.0f);
	cr_expect_eq(tbGetErrorCount() - before, 3, "each bad call is reported once");
	tbSetErrorCallback(NULL, NULL);
	// Degenerate but valid input gives numbers, never NaN: an empty polygon has zero mass.
	tbPolygon empty = {0};
	tbMassData md = tbComputePolygonMass(&empty, 1.0f);
	cr_expect(md.mass == 0.0f && md.rotationalInertia == 0.0f && isfinite(md.center.x));
}
