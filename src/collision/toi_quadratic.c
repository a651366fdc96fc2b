// Time of impact of two circles in linear motion, in closed form.
//
// Each circle centre moves on a straight line over the sweep, t in [0, 1]:
//   pA(t) = pA0 + t·(pA1 − pA0),   pB(t) = pB0 + t·(pB1 − pB0)
// where pX0 and pX1 are the world centres from the sweep transforms at t = 0 and t = 1. This is
// exact when the circle sits on its body's centre of mass (the centre of mass moves linearly by
// the definition of tbSweep) or when the sweep does not rotate. Otherwise the true path of an
// off-centre circle is an arc and this routine only approximates it by its chord: use the
// conservative-advancement routine (toi_conservative.c) for such bodies.
//
// With the relative motion Δp = pB0 − pA0, Δv = (pB1 − pB0) − (pA1 − pA0) and the contact
// distance R = rA + rB + target, the circles are at the target separation when
//   |Δp + Δv·t|² = R²   ⇔   a·t² + 2β·t + c = 0,   a = Δv·Δv,  β = Δp·Δv,  c = Δp·Δp − R².
// (Ericson, "Real-Time Collision Detection", §5.5.8, moving sphere against moving sphere.)
//
// Cases, in the order they are decided:
//   c < 0        the circles start closer than R: overlapped, fraction 0.
//   β ≥ 0        not approaching (receding, sliding tangentially, or Δv = 0 so that a = β = 0):
//                |Δp + Δv·t|² = c + R² + 2β·t + a·t² only grows, no root in t > 0: separated.
//   β² − a·c < 0 the relative path misses the contact circle: separated.
//   otherwise    the earliest root. The textbook t = (−β − √(β² − ac))/a cancels badly when
//                a·c ≪ β² (a fast, nearly head-on approach from far away) and divides by a
//                when a is tiny. The stable form (Press et al., "Numerical Recipes", §5.6):
//                q = −(β + sign(β)·√disc) = −β + √disc > 0 for β < 0, roots q/a and c/q;
//                since c ≥ 0 the earlier root is c/q, and q ≥ −β > 0 so the division is safe
//                (no NaN, no infinity). A grazing double root (disc = 0) gives c/q = −β/a = the
//                time of closest approach, which is the right answer.

#include "core/core.h"

#include "tumble/collision.h"

// Circle centre in world space at sweep time t (0 or 1).
static tbVec2 tbSweptCircleCenter(const tbCircle* circle, const tbSweep* sweep, float time)
{
	tbTransform xf = tbGetSweepTransform(sweep, time);
	return tbTransformPoint(xf, circle->center);
}

// Unit vector along v, or the x axis when v is zero (coincident centres have no preferred
// direction; any unit vector keeps the output finite).
static tbVec2 tbSafeNormal(tbVec2 v)
{
	float length = tbLength(v);
	if (length > 0.0f)
	{
		return tbMulSV(1.0f / length, v);
	}
	return tbMakeVec2(1.0f, 0.0f);
}

// Fill normal and contact point at time t. The point is midway between the two surfaces along
// the line of centres, like a manifold point.
static void tbSetCircleContact(tbTOIOutput* output, tbVec2 centerA, tbVec2 centerB, float radiusA, float radiusB)
{
	tbVec2 delta = tbSub(centerB, centerA);
	tbVec2 normal = tbSafeNormal(delta);
	float gap = tbDot(delta, normal) - radiusA - radiusB;
	output->normal = normal;
	output->point = tbMulAdd(centerA, radiusA + 0.5f * gap, normal);
}

// Earliest root in [0, ∞) of a·t² + 2β·t + c, for c ≥ 0 and β < 0; −1 when there is none.
static float tbEarliestRoot(float a, float beta, float c)
{
	float disc = beta * beta - a * c;
	if (disc < 0.0f)
	{
		return -1.0f;
	}
	float q = -beta + sqrtf(disc);
	return c / q;
}

static bool tbValidTOIArguments(const char* function, float maxFraction, float targetSeparation)
{
	if (tbCheckNonNegative(function, "targetSeparation", targetSeparation) == false ||
		tbCheckNonNegative(function, "maxFraction", maxFraction) == false)
	{
		return false;
	}
	if (maxFraction > 1.0f)
	{
		tbReportError(function, "maxFraction is %g; it must lie in [0, 1], a fraction of the sweep.", (double)maxFraction);
		return false;
	}
	return true;
}

tbTOIOutput tbTimeOfImpactCircles(const tbCircle* circleA, const tbSweep* sweepA, const tbCircle* circleB,
								  const tbSweep* sweepB, float maxFraction, float targetSeparation)
{
	const char* function = "tbTimeOfImpactCircles";
	tbTOIOutput output = {tb_toiStateUnknown, 0.0f, 0, {0.0f, 0.0f}, {0.0f, 0.0f}};
	if (tbValidTOIArguments(function, maxFraction, targetSeparation) == false)
	{
		return output;
	}

	tbVec2 pA0 = tbSweptCircleCenter(circleA, sweepA, 0.0f);
	tbVec2 pA1 = tbSweptCircleCenter(circleA, sweepA, 1.0f);
	tbVec2 pB0 = tbSweptCircleCenter(circleB, sweepB, 0.0f);
	tbVec2 pB1 = tbSweptCircleCenter(circleB, sweepB, 1.0f);
	tbVec2 dA = tbSub(pA1, pA0);
	tbVec2 dB = tbSub(pB1, pB0);

	tbVec2 dp = tbSub(pB0, pA0);
	tbVec2 dv = tbSub(dB, dA);
	float contactDistance = circleA->radius + circleB->radius + targetSeparation;

	// c = Δp·Δp − R² directly rather than (|Δp| − R)(|Δp| + R): both carry a rounding error of
	// a few ulps of |Δp|², but this form has no square root and is exact for exactly representable
	// inputs, so an exact graze gives disc = 0 and the double root (tested).
	float c = tbDot(dp, dp) - contactDistance * contactDistance;
	float a = tbDot(dv, dv);
	float beta = tbDot(dp, dv);
	output.iterations = 1;

	float time;
	if (c < 0.0f)
	{
		output.state = tb_toiStateOverlapped;
		time = 0.0f;
	}
	else
	{
		time = beta < 0.0f ? tbEarliestRoot(a, beta, c) : -1.0f;
		output.state = (time < 0.0f || time > maxFraction) ? tb_toiStateSeparated : tb_toiStateHit;
	}

	if (output.state == tb_toiStateSeparated)
	{
		time = maxFraction;
	}
	output.fraction = time;
	tbVec2 centerA = tbMulAdd(pA0, time, dA);
	tbVec2 centerB = tbMulAdd(pB0, time, dB);
	tbSetCircleContact(&output, centerA, centerB, circleA->radius, circleB->radius);
	return output;
}
