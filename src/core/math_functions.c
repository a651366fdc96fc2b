// Math helpers that are not inline: the exported arctangent with a stated error (its body is
// core/arctangent.h) and the cosine/sine pair of an angle, neither of which depends on the
// platform's libm.
#include "core/arctangent.h"
#include "tumble/math_functions.h"

#include <math.h>

float tbAtan2(float y, float x)
{
	return tbArctangent(y, x);
}

// Sine and cosine without the C library, whose last bits differ between platforms (glibc's and
// wasi-libc's sinf disagree on many arguments), so that a rotation made from an angle is the same
// float pair everywhere. The angle, exact in double, is reduced by the nearest multiple k of π/2,
// r = x − k·π/2 with |r| ≤ π/4 (to a few ulps of double; a billion radians and beyond are first
// brought into one turn by fmod, where float angles no longer mean anything). On that interval
// the Taylor series to r¹³ and r¹⁴ are within 1e-14 of sin and cos, far below a float's ulp, and
// the one rounding to float gives the float nearest the true value but in rare ties. Every operation is an
// IEEE 754 double + − × /, floor or fmod, exact to the bit on every platform (no contraction:
// -ffp-contract=off).
static double tbSinSeries(double r)
{
	// r·(1 − r²/(2·3)·(1 − r²/(4·5)·(… (1 − r²/(12·13))))), each 1/(n·(n+1)) a constant: a product
	// where a division would cost the continuous stage, which turns sweeps by angle, a fifth more.
	static const double k[6] = {1.0 / 156.0, 1.0 / 110.0, 1.0 / 72.0, 1.0 / 42.0, 1.0 / 20.0, 1.0 / 6.0};
	// Below 1/8 rad (a sweep's turn, most often) the terms past r⁷ are under 2e-15: left out.
	double r2 = r * r, sum = 1.0;
	for (int i = fabs(r) < 0.125 ? 3 : 0; i < 6; ++i)
	{
		sum = 1.0 - r2 * k[i] * sum;
	}
	return r * sum;
}

static double tbCosSeries(double r)
{
	// 1 − r²/(1·2)·(1 − r²/(3·4)·(… (1 − r²/(13·14))))
	static const double k[7] = {1.0 / 182.0, 1.0 / 132.0, 1.0 / 90.0, 1.0 / 56.0, 1.0 / 30.0, 1.0 / 12.0, 1.0 / 2.0};
	double r2 = r * r, sum = 1.0; // below 1/8 rad the terms past r⁸ are under 3e-16
	for (int i = fabs(r) < 0.125 ? 3 : 0; i < 7; ++i)
	{
		sum = 1.0 - r2 * k[i] * sum;
	}
	return sum;
}

tbCosSin tbComputeCosSin(float radians)
{
	double x0 = radians;
	if (fabs(x0) < 0.125)
	{
		// A sweep's turn, most often: the short series of tbSinSeries and tbCosSeries written out,
		// the same operations in the same order (so the same bits), without the loops' bounds.
		double r2 = x0 * x0;
		double s = x0 * (1.0 - r2 * (1.0 / 6.0) * (1.0 - r2 * (1.0 / 20.0) * (1.0 - r2 * (1.0 / 42.0) * 1.0)));
		double c = 1.0 - r2 * (1.0 / 2.0) *
							 (1.0 - r2 * (1.0 / 12.0) * (1.0 - r2 * (1.0 / 30.0) * (1.0 - r2 * (1.0 / 56.0) * 1.0)));
		tbCosSin small = {(float)c, (float)s};
		return small;
	}
	if (isfinite(radians) == false)
	{
		tbCosSin nan = {radians - radians, radians - radians};
		return nan;
	}
	const double halfPi = 1.57079632679489661923, twoPi = 6.28318530717958647692;
	double x = radians;
	if (fabs(x) > 1.0e9)
	{
		x = fmod(x, twoPi); // exact, as the C standard has every fmod
	}
	// Within a quarter turn of 0 there is nothing to reduce (the common case: a sweep's turn).
	double k = fabs(x) <= 0.5 * halfPi ? 0.0 : floor(x / halfPi + 0.5);
	double r = x - k * halfPi;
	double s = tbSinSeries(r), c = tbCosSeries(r);
	// cos and sin of r + q·π/2 for the quarter turn q = k mod 4 (|k| < 2^30: an int holds it)
	int quarter = (int)k & 3;
	double cq = quarter == 0 ? c : quarter == 1 ? -s : quarter == 2 ? -c : s;
	double sq = quarter == 0 ? s : quarter == 1 ? c : quarter == 2 ? -s : -c;
	// Rounded once from double, each is the float nearest the true value (within 1e-14 before the
	// rounding), whose pair is as unit as floats allow; a normalisation in float moved them by up
	// to an ulp, and a resting contact on a slope made from the angle shifted with it.
	tbCosSin cs = {(float)cq, (float)sq};
	return cs;
}

tbRot tbComputeRotationBetweenUnitVectors(tbVec2 v1, tbVec2 v2)
{
	tbRot q = {tbDot(v1, v2), tbCross(v1, v2)};
	return tbNormalizeRot(q);
}

bool tbIsValidPlane(tbPlane plane)
{
	return tbIsValidVec2(plane.normal) && tbIsNormalized(plane.normal) && tbIsValidFloat(plane.offset);
}

bool tbIsValidPosition(tbPos p)
{
#if defined(TUMBLE_DOUBLE_PRECISION)
	return isfinite(p.x) && isfinite(p.y);
#else
	return tbIsValidVec2(p);
#endif
}

bool tbIsValidWorldTransform(tbWorldTransform t)
{
	return tbIsValidPosition(t.p) && tbIsValidRotation(t.q);
}
