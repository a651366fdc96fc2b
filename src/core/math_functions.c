// Math helpers that are not inline: an arctangent with a stated error that does not depend on the
// platform's libm, and the cosine/sine pair of an angle.
#include "tumble/math_functions.h"

#include <math.h>

// atan(t) for t in [0, 1] by an odd polynomial t·(a1 + a3·t² + … + a11·t¹⁰), a standard fit of atan
// on [0, 1] in the manner of Hastings (cf. Abramowitz & Stegun 4.4.47–4.4.49). Its error is
// checked, not assumed: tests/test_math.c holds it within the stated 3e-6 rad of atan2 in double
// over 10⁶ directions at three radii. Other octants by
// atan(t) = π/2 − atan(1/t) and the signs of x and y.
float tbAtan2(float y, float x)
{
	float ax = fabsf(x), ay = fabsf(y);
	float big = ax > ay ? ax : ay;
	float small = ax > ay ? ay : ax;
	if (big == 0.0f)
	{
		return 0.0f; // atan2(0, 0): 0 as the libm functions give for +0
	}
	float t = small / big;
	float t2 = t * t;
	float r = t * (0.99997726f + t2 * (-0.33262347f + t2 * (0.19354346f + t2 * (-0.11643287f + t2 * (0.05265332f + t2 * -0.01172120f)))));
	if (ay > ax)
	{
		r = 0.5f * TB_PI - r;
	}
	if (x < 0.0f)
	{
		r = TB_PI - r;
	}
	return y < 0.0f ? -r : r;
}

tbCosSin tbComputeCosSin(float radians)
{
	float c = cosf(radians), s = sinf(radians);
	float length = sqrtf(c * c + s * s);
	tbCosSin cs = {c / length, s / length};
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
