// Tests of the inline value math in tumble/math_functions.h: vector and rotation identities,
// transforms, rotation integration, the 2×2 solve and bounding-box operations.
//
// Tolerances: a float has a unit roundoff of u = 2⁻²⁴ ≈ 6e-8. A rotation or transform of a
// vector of length ~1 costs a few roundings per component, so a round trip through two of them
// is exact to ~10u ≈ 6e-7; tests allow 1e-6 (times the magnitude of the numbers involved).

#include "core/arctangent.h"
#include "tumble/math_functions.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

// Round-trip tolerance for numbers of magnitude ~1 (see the header comment).
#define ROUND_TRIP_TOL 1e-6f

static void expectVec2Near(tbVec2 a, tbVec2 b, float tolerance)
{
	cr_expect(fabsf(a.x - b.x) <= tolerance && fabsf(a.y - b.y) <= tolerance,
			  "(%.9g, %.9g) differs from (%.9g, %.9g) by more than %g", (double)a.x, (double)a.y, (double)b.x,
			  (double)b.y, (double)tolerance);
}

static const tbVec2 s_vectors[] = {{1.0f, 0.0f}, {0.0f, 1.0f}, {0.3f, -0.7f}, {-2.5f, 1.25f}, {0.0f, 0.0f}};
static const float s_angles[] = {0.0f, 0.5f, -1.2f, 2.9f, -3.1f, 1.5707963f};

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

Test(math, rotate_and_inverse_rotate_are_inverses)
{
	for (int i = 0; i < COUNT(s_angles); ++i)
	{
		tbRot q = tbMakeRot(s_angles[i]);
		for (int j = 0; j < COUNT(s_vectors); ++j)
		{
			tbVec2 v = s_vectors[j];
			float scale = fmaxf(1.0f, tbLength(v));
			expectVec2Near(tbInvRotateVector(q, tbRotateVector(q, v)), v, ROUND_TRIP_TOL * scale);
			expectVec2Near(tbRotateVector(q, tbInvRotateVector(q, v)), v, ROUND_TRIP_TOL * scale);
			// A rotation preserves length: |Rv| = |v| to float rounding.
			cr_expect_float_eq(tbLength(tbRotateVector(q, v)), tbLength(v), ROUND_TRIP_TOL * scale);
		}
	}
}

Test(math, rotation_composition_adds_angles)
{
	for (int i = 0; i < COUNT(s_angles); ++i)
	{
		for (int j = 0; j < COUNT(s_angles); ++j)
		{
			tbRot q = tbMakeRot(s_angles[i]);
			tbRot r = tbMakeRot(s_angles[j]);
			// q·r is the rotation by a + b; qᵀ·r by b − a. Compare as rotations (angles wrap).
			tbRot sum = tbMakeRot(s_angles[i] + s_angles[j]);
			tbRot difference = tbMakeRot(s_angles[j] - s_angles[i]);
			tbRot qr = tbMulRot(q, r);
			tbRot qTr = tbInvMulRot(q, r);
			expectVec2Near(tbMakeVec2(qr.c, qr.s), tbMakeVec2(sum.c, sum.s), ROUND_TRIP_TOL);
			expectVec2Near(tbMakeVec2(qTr.c, qTr.s), tbMakeVec2(difference.c, difference.s), ROUND_TRIP_TOL);
			// tbRelativeAngle(q, r) is the angle of qᵀ·r.
			cr_expect_float_eq(tbRelativeAngle(q, r), tbRot_GetAngle(difference), 2.0f * ROUND_TRIP_TOL);
		}
	}
}

Test(math, transform_point_round_trip)
{
	tbTransform t = {{3.0f, -1.5f}, tbMakeRot(0.7f)};
	for (int j = 0; j < COUNT(s_vectors); ++j)
	{
		tbVec2 p = s_vectors[j];
		// Magnitudes reach |t.p| + |p| ≈ 6, so scale the tolerance by 6.
		expectVec2Near(tbInvTransformPoint(t, tbTransformPoint(t, p)), p, 6.0f * ROUND_TRIP_TOL);
		expectVec2Near(tbTransformPoint(t, tbInvTransformPoint(t, p)), p, 6.0f * ROUND_TRIP_TOL);
	}
	// Hand-computed: rotating (1, 0) by 90° gives (0, 1), then translating by (3, −1.5).
	tbTransform quarter = {{3.0f, -1.5f}, {0.0f, 1.0f}};
	expectVec2Near(tbTransformPoint(quarter, tbMakeVec2(1.0f, 0.0f)), tbMakeVec2(3.0f, -0.5f), 0.0f);
}

Test(math, transform_composition)
{
	tbTransform A = {{1.0f, 2.0f}, tbMakeRot(0.4f)};
	tbTransform B = {{-0.5f, 0.25f}, tbMakeRot(-1.1f)};
	tbTransform AB = tbMulTransforms(A, B);
	tbTransform AinvB = tbInvMulTransforms(A, B);
	for (int j = 0; j < COUNT(s_vectors); ++j)
	{
		tbVec2 p = s_vectors[j];
		// (A·B)(p) = A(B(p)) and (A⁻¹·B)(p) = A⁻¹(B(p)); magnitudes ≲ 6.
		expectVec2Near(tbTransformPoint(AB, p), tbTransformPoint(A, tbTransformPoint(B, p)), 6.0f * ROUND_TRIP_TOL);
		expectVec2Near(tbTransformPoint(AinvB, p), tbInvTransformPoint(A, tbTransformPoint(B, p)),
					   6.0f * ROUND_TRIP_TOL);
	}
	// A · (A⁻¹ · B) = B
	tbTransform back = tbMulTransforms(A, AinvB);
	expectVec2Near(back.p, B.p, 6.0f * ROUND_TRIP_TOL);
	expectVec2Near(tbMakeVec2(back.q.c, back.q.s), tbMakeVec2(B.q.c, B.q.s), ROUND_TRIP_TOL);
}

Test(math, integrate_rotation_is_third_order)
{
	// q2 = normalize(q1 + Δθ·perp(q1)) turns by exactly atan(Δθ) = Δθ − Δθ³/3 + O(Δθ⁵),
	// so the angle error is Δθ − atan(Δθ) ≈ Δθ³/3. Checked against the double-precision value
	// to 2e-6 (atan2f near 1 rad and the normalisation each round to ~1e-7), and the error
	// must shrink by ~8 when Δθ halves.
	const float theta = 0.8f;
	tbRot q1 = tbMakeRot(theta);
	float previousError = 0.0f;
	for (int k = 0; k < 4; ++k)
	{
		float dTheta = 0.2f / (float)(1 << k);
		tbRot q2 = tbIntegrateRotation(q1, dTheta);
		float error = (theta + dTheta) - tbRot_GetAngle(q2);
		double expected = (double)dTheta - atan((double)dTheta);
		cr_expect(fabs((double)error - expected) < 2e-6, "dθ=%g error %g expected %g", (double)dTheta, (double)error,
				  expected);
		cr_expect(error <= dTheta * dTheta * dTheta / 3.0f + 2e-6f);
		cr_expect(tbIsNormalized(tbMakeVec2(q2.c, q2.s)));
		if (k > 0 && k < 3)
		{
			float ratio = previousError / error;
			cr_expect(ratio > 7.0f && ratio < 9.0f, "error ratio %g, expected ~8 for third order", (double)ratio);
		}
		previousError = error;
	}
}

Test(math, normalize_is_never_nan)
{
	tbVec2 zero = tbNormalize(tbVec2_zero);
	cr_expect(zero.x == 0.0f && zero.y == 0.0f);
	tbVec2 tiny = tbNormalize(tbMakeVec2(1e-30f, -1e-30f));
	cr_expect(tiny.x == 0.0f && tiny.y == 0.0f);
	float length = -1.0f;
	tbVec2 n = tbGetLengthAndNormalize(&length, tbVec2_zero);
	cr_expect(n.x == 0.0f && n.y == 0.0f && length == 0.0f);
	// 3-4-5 triangle: exact up to one rounding of 0.6 and 0.8.
	n = tbGetLengthAndNormalize(&length, tbMakeVec2(3.0f, -4.0f));
	cr_expect_float_eq(length, 5.0f, 1e-6f);
	expectVec2Near(n, tbMakeVec2(0.6f, -0.8f), 1e-7f);
	tbRot q = tbNormalizeRot((tbRot){0.0f, 0.0f});
	cr_expect(q.c == 0.0f && q.s == 0.0f);
}

Test(math, cross_product_identities)
{
	for (int i = 0; i < COUNT(s_vectors); ++i)
	{
		for (int j = 0; j < COUNT(s_vectors); ++j)
		{
			tbVec2 a = s_vectors[i], b = s_vectors[j];
			// Anti-symmetry, a × a = 0, a × b = leftPerp(a)·b, and Lagrange's identity
			// (a × b)² + (a·b)² = |a|²|b|² (magnitudes ≤ 7.8, rounding ≲ 1e-5).
			cr_expect(tbCross(a, b) == -tbCross(b, a));
			cr_expect(tbCross(a, a) == 0.0f);
			cr_expect_float_eq(tbCross(a, b), tbDot(tbLeftPerp(a), b), 1e-6f);
			float lhs = tbCross(a, b) * tbCross(a, b) + tbDot(a, b) * tbDot(a, b);
			cr_expect_float_eq(lhs, tbLengthSquared(a) * tbLengthSquared(b), 1e-5f);
		}
		// s × v is perpendicular to v and equals −(v × s); (s × v) × ... hand value for s = 2.
		tbVec2 v = s_vectors[i];
		tbVec2 sv = tbCrossSV(2.0f, v);
		tbVec2 vs = tbCrossVS(v, 2.0f);
		cr_expect(tbDot(sv, v) == 0.0f);
		expectVec2Near(sv, tbNeg(vs), 0.0f);
		expectVec2Near(sv, tbMakeVec2(-2.0f * v.y, 2.0f * v.x), 0.0f);
		expectVec2Near(tbRightPerp(v), tbNeg(tbLeftPerp(v)), 0.0f);
	}
}

Test(math, solve22)
{
	// A = [3 1; 2 4] (columns (3, 2) and (1, 4)), x = (1, −2) ⇒ b = A·x = (1, −6).
	tbMat22 A = {{3.0f, 2.0f}, {1.0f, 4.0f}};
	tbVec2 x = {1.0f, -2.0f};
	tbVec2 b = tbMulMV(A, x);
	expectVec2Near(b, tbMakeVec2(1.0f, -6.0f), 0.0f);
	// det = 10; Cramer's rule is exact up to a few roundings of numbers ~1.
	expectVec2Near(tbSolve22(A, b), x, 1e-6f);
	tbMat22 inverse = tbGetInverse22(A);
	expectVec2Near(tbMulMV(inverse, b), x, 1e-6f);
	// Singular matrix: zero, not NaN or infinity.
	tbMat22 singular = {{1.0f, 2.0f}, {2.0f, 4.0f}};
	tbVec2 zero = tbSolve22(singular, b);
	cr_expect(zero.x == 0.0f && zero.y == 0.0f);
}

Test(math, aabb_overlap_and_contains)
{
	tbAABB a = {{0.0f, 0.0f}, {2.0f, 1.0f}};
	tbAABB touching = {{2.0f, 0.5f}, {3.0f, 2.0f}};
	tbAABB apartX = {{2.1f, 0.0f}, {3.0f, 1.0f}};
	tbAABB apartY = {{0.0f, -2.0f}, {1.0f, -0.1f}};
	tbAABB inner = {{0.5f, 0.25f}, {1.5f, 0.75f}};
	cr_expect(tbAABB_Overlaps(a, touching) && tbAABB_Overlaps(touching, a));
	cr_expect(tbAABB_Overlaps(a, apartX) == false && tbAABB_Overlaps(apartX, a) == false);
	cr_expect(tbAABB_Overlaps(a, apartY) == false);
	cr_expect(tbAABB_Overlaps(a, inner));
	cr_expect(tbAABB_Contains(a, inner) && tbAABB_Contains(inner, a) == false);
	cr_expect(tbAABB_Contains(a, a), "touching boundaries count as inside");
	cr_expect(tbAABB_Contains(a, touching) == false);
}

Test(math, aabb_union_perimeter_and_fatten)
{
	tbAABB a = {{0.0f, 0.0f}, {2.0f, 1.0f}};
	tbAABB b = {{-1.0f, 0.5f}, {1.0f, 3.0f}};
	tbAABB u = tbAABB_Union(a, b);
	expectVec2Near(u.lowerBound, tbMakeVec2(-1.0f, 0.0f), 0.0f);
	expectVec2Near(u.upperBound, tbMakeVec2(2.0f, 3.0f), 0.0f);
	cr_expect(tbAABB_Contains(u, a) && tbAABB_Contains(u, b));
	// Perimeter 2(w + h): a is 2 × 1 → 6, the union is 3 × 3 → 12 (exact in float).
	cr_expect(tbAABB_Perimeter(a) == 6.0f);
	cr_expect(tbAABB_Perimeter(u) == 12.0f);
	expectVec2Near(tbAABB_Center(a), tbMakeVec2(1.0f, 0.5f), 0.0f);
	expectVec2Near(tbAABB_Extents(a), tbMakeVec2(1.0f, 0.5f), 0.0f);
	tbAABB fat = tbAABB_Fatten(a, 0.25f);
	cr_expect(tbAABB_Perimeter(fat) == 8.0f);
	cr_expect(tbIsValidAABB(fat));
	tbAABB inverted = {{1.0f, 0.0f}, {0.0f, 1.0f}};
	cr_expect(tbIsValidAABB(inverted) == false);
}

// tbAtan2 against atan2 in double over 10⁶ directions on the unit circle and at radii 1e-3 and
// 1e3: the polynomial's stated bound, 3e-6 rad (measured 1.96e-6), holds everywhere, and the axes and (0, 0) are exact.
Test(math, atan2_approximation_within_its_stated_error)
{
	double worst = 0.0;
	const int n = 1000000;
	for (int i = 0; i < n; ++i)
	{
		double angle = -3.14159265358979 + 6.28318530717959 * (i + 0.5) / n;
		for (int k = 0; k < 3; ++k)
		{
			double radius = k == 0 ? 1.0 : (k == 1 ? 1e-3 : 1e3);
			float x = (float)(radius * cos(angle)), y = (float)(radius * sin(angle));
			double error = fabs((double)tbAtan2(y, x) - atan2((double)y, (double)x));
			worst = error > worst ? error : worst;
		}
	}
	cr_log_info("tbAtan2 largest error %.3g rad", worst);
	cr_assert_lt(worst, 3e-6);
	cr_assert_eq(tbAtan2(0.0f, 0.0f), 0.0f);
	cr_assert_eq(tbAtan2(0.0f, 1.0f), 0.0f);
	cr_assert_float_eq(tbAtan2(1.0f, 0.0f), 0.5f * TB_PI, 1e-6f);
	cr_assert_float_eq(tbAtan2(0.0f, -1.0f), TB_PI, 1e-6f);
}

// Below t = 2⁻¹³ the arctangent takes a1·t instead of the polynomial, whose t⁸ term would be a
// subnormal there (a microcode assist per operation on x86): every term after a1 is below half an
// ulp of a1, so the two must agree bit for bit. Checked through tbAtan2(t, 1) (t = |y|/|x| exactly)
// against the polynomial on every 61st float from the smallest subnormal up to 2⁻¹⁰, every binade
// on both sides of the switch (4.1 million of them), and on the 4,096 floats just below 2⁻¹³.
Test(math, arctangent_small_argument_is_the_polynomial)
{
	float switchAt = 0x1p-13f, limit = 0x1p-10f;
	uint32_t top, nearSwitch;
	memcpy(&top, &limit, sizeof(top));
	memcpy(&nearSwitch, &switchAt, sizeof(nearSwitch));
	nearSwitch -= 4096u;
	int checked = 0, differing = 0;
	float first = 0.0f; // the first t that differs, if any
	for (uint32_t bits = 1; bits < top; bits += (bits >= nearSwitch && bits < nearSwitch + 4096u ? 1u : 61u))
	{
		float t;
		memcpy(&t, &bits, sizeof(t));
		float viaAtan2 = tbAtan2(t, 1.0f);
		float polynomial = tbArctangentOctant(t);
		if (memcmp(&viaAtan2, &polynomial, sizeof(float)) != 0)
		{
			first = differing == 0 ? t : first;
			++differing;
		}
		++checked;
	}
	cr_assert_gt(checked, 4000000);
	cr_assert_eq(differing, 0, "%d of %d differ, the first at t = %a", differing, checked, (double)first);
	// The other quadrants of a tiny angle take the same octant value.
	float y = 3.0e-6f, x = 0.75f;
	float t = y / x;
	cr_assert_eq(tbAtan2(-y, x), -tbArctangentOctant(t));
	cr_assert_eq(tbAtan2(y, -x), TB_PI - tbArctangentOctant(t));
	cr_assert_eq(tbAtan2(x, y), 0.5f * TB_PI - tbArctangentOctant(t));
}

// tbUnwindAngle brings angles into [−π, π] by whole turns (to float precision of the turn count);
// tbNLerp halfway between 0 and 90° is 45°; tbComputeCosSin is a unit pair equal to cos, sin.
Test(math, unwind_nlerp_and_cos_sin)
{
	cr_assert_float_eq(tbUnwindAngle(0.5f), 0.5f, 0.0f);
	cr_assert_float_eq(tbUnwindAngle(0.5f + 2.0f * TB_PI), 0.5f, 1e-5f);
	cr_assert_float_eq(tbUnwindAngle(0.5f - 6.0f * TB_PI), 0.5f, 1e-5f);
	cr_assert_float_eq(tbUnwindAngle(-3.0f * TB_PI / 2.0f), TB_PI / 2.0f, 1e-5f);
	for (float a = -100.0f; a <= 100.0f; a += 0.37f)
	{
		float u = tbUnwindAngle(a);
		cr_assert(u >= -TB_PI - 1e-6f && u <= TB_PI + 1e-6f, "unwind(%g) = %g", (double)a, (double)u);
		cr_assert_float_eq(sinf(u), sinf(a), 1e-4f);
	}
	tbRot q = tbNLerp(tbMakeRot(0.0f), tbMakeRot(0.5f * TB_PI), 0.5f);
	cr_assert_float_eq(tbRot_GetAngle(q), 0.25f * TB_PI, 1e-6f);
	tbCosSin cs = tbComputeCosSin(1.0f);
	cr_assert_float_eq(cs.cosine, cosf(1.0f), 1e-6f);
	cr_assert_float_eq(cs.sine, sinf(1.0f), 1e-6f);
	cr_assert_float_eq(cs.cosine * cs.cosine + cs.sine * cs.sine, 1.0f, 1e-6f);
}

// tbComputeCosSin computes its own sine and cosine (no libm, so the same bits on every platform):
// over ±100 rad each float is the one nearest to sin and cos in double (the series are within 1e-14
// and the pair is normalised in double before its one rounding), so within half a float ulp below
// 1, 2.98e-8; the quarter turns are exact; angles past a billion radians, which the reduction brings
// into one turn by fmod, still give a unit pair; non-finite angles give NaN.
Test(math, compute_cos_sin_is_accurate_everywhere)
{
	double worst = 0.0, worstAngle = 0.0; // one assertion: Criterion reports each one to its runner
	int notNearest = 0;
	for (int i = -1000000; i <= 1000000; ++i)
	{
		float a = 1.0e-4f * (float)i;
		tbCosSin cs = tbComputeCosSin(a);
		double error = fmax(fabs(cs.cosine - cos((double)a)), fabs(cs.sine - sin((double)a)));
		worstAngle = error > worst ? (double)a : worstAngle;
		worst = fmax(worst, error);
		notNearest += cs.cosine != (float)cos((double)a) || cs.sine != (float)sin((double)a) ? 1 : 0;
	}
	cr_assert(worst <= 2.99e-8 && notNearest == 0, "error %.3g at angle %.9g; %d angles not rounded to nearest", worst,
			  worstAngle, notNearest);
	cr_assert_eq(tbComputeCosSin(0.0f).cosine, 1.0f);
	cr_assert_eq(tbComputeCosSin(0.0f).sine, 0.0f);
	cr_assert_float_eq(tbComputeCosSin(0.5f * TB_PI).sine, 1.0f, 0.0f);
	cr_assert_float_eq(tbComputeCosSin(TB_PI).cosine, -1.0f, 0.0f);
	const float huge[] = {1.5e9f, -3.0e12f, 1.0e30f, -3.4e38f};
	for (int i = 0; i < 4; ++i)
	{
		tbCosSin cs = tbComputeCosSin(huge[i]);
		float length = cs.cosine * cs.cosine + cs.sine * cs.sine;
		cr_assert(isfinite(cs.cosine) && isfinite(cs.sine) && fabsf(length - 1.0f) < 1e-6f, "angle %g", (double)huge[i]);
	}
	cr_assert(isnan(tbComputeCosSin(INFINITY).cosine) && isnan(tbComputeCosSin(NAN).sine));
}

// Box2D v3.2's helpers under their v3.2 names: the rotation between unit vectors, validity tests,
// the implicit spring-damper step, and the position helpers (plain vectors in Tumble).
Test(math, v3_helpers_match_their_closed_forms)
{
	tbRot q = tbComputeRotationBetweenUnitVectors((tbVec2){1.0f, 0.0f}, (tbVec2){0.0f, 1.0f});
	cr_expect_float_eq(q.c, 0.0f, 1e-7f);
	cr_expect_float_eq(q.s, 1.0f, 1e-7f);
	tbVec2 u = {cosf(0.3f), sinf(0.3f)}, v = {cosf(1.1f), sinf(1.1f)};
	cr_expect_float_eq(tbRot_GetAngle(tbComputeRotationBetweenUnitVectors(u, v)), 0.8f, 1e-6f);

	cr_expect(tbIsValidRotation(tbRot_identity));
	cr_expect_not(tbIsValidRotation((tbRot){2.0f, 0.0f}));
	cr_expect_not(tbIsValidRotation((tbRot){NAN, 0.0f}));
	cr_expect(tbIsValidPlane((tbPlane){{0.0f, 1.0f}, -3.0f}));
	cr_expect_not(tbIsValidPlane((tbPlane){{0.0f, 2.0f}, 0.0f}));
	cr_expect_not(tbIsValidPlane((tbPlane){{0.0f, 1.0f}, INFINITY}));
	cr_expect(tbIsValidPosition((tbPos){1e6f, -1e6f}));
	cr_expect_not(tbIsValidPosition((tbPos){NAN, 0.0f}));
	cr_expect(tbIsValidWorldTransform(tbWorldTransform_identity));
	cr_expect_not(tbIsValidWorldTransform((tbWorldTransform){{0.0f, INFINITY}, {1.0f, 0.0f}}));

	// Implicit step of x'' = −ω²x − 2ζωx': v' = (v − ω²h·x)/(1 + 2ζωh + ω²h²).
	float omega = 2.0f * TB_PI * 2.0f, h = 0.01f;
	float expected = (0.5f - omega * omega * h * 0.1f) / (1.0f + 2.0f * 0.7f * omega * h + omega * omega * h * h);
	cr_expect_float_eq(tbSpringDamper(2.0f, 0.7f, 0.1f, 0.5f, h), expected, 1e-6f);
	// ω·h = sin(Δθ) to first order.
	cr_expect_float_eq(tbComputeAngularVelocity(tbMakeRot(0.2f), tbMakeRot(0.21f), 100.0f), 100.0f * sinf(0.01f), 1e-3f);
	cr_expect_eq(tbPlaneSeparation((tbPlane){{0.0f, 1.0f}, 2.0f}, (tbVec2){5.0f, 3.5f}), 1.5f);
	tbVec2 pts[2] = {{1.0f, 2.0f}, {-1.0f, 4.0f}};
	tbAABB box = tbMakeAABB(pts, 2, 0.5f);
	cr_expect(box.lowerBound.x == -1.5f && box.lowerBound.y == 1.5f && box.upperBound.x == 1.5f && box.upperBound.y == 4.5f);
	tbPos p = tbOffsetPos(tbToPos((tbVec2){1.0f, 2.0f}), (tbVec2){0.5f, 0.5f});
	cr_expect(tbSubPos(p, tbPos_zero).x == 1.5f && tbToVec2(p).y == 2.5f);
	cr_expect_eq(tbAbsInt(-3), 3);
	cr_expect_eq(tbClampInt(9, 0, 4), 4);
	cr_expect_eq(tbCeilingInt(7, 2), 4);
	cr_expect_eq(tbInvertRot(tbMakeRot(0.5f)).s, -tbMakeRot(0.5f).s);
}
