// The arctangent, inline for the joints' solves; tbAtan2 (math_functions.c) exports the same
// function. Inside a joint's rows a call costs more than the arithmetic: every XMM register is
// caller-saved in the x86-64 System V ABI, so the velocities the rows carry go to the stack and back
// around it, in every pass over every joint with a limit or a spring.
#pragma once

#include "core.h"

#include "tumble/math_functions.h"

#include <math.h>

// atan(t) for t in [0, 1] by an odd polynomial t·(a1 + a3·t² + … + a11·t¹⁰), a standard fit of atan
// on [0, 1] in the manner of Hastings (cf. Abramowitz & Stegun 4.4.47–4.4.49). Its error is
// checked, not assumed: tests/test_math.c holds it within the stated 3e-6 rad of atan2 in double
// over 10⁶ directions at three radii.
static TB_FORCE_INLINE float tbArctangentOctant(float t)
{
	// The polynomial in u = t² evaluated in Estrin's scheme, (a1 + a3·u) + u²·(a5 + a7·u) + u⁴·(a9 + a11·u):
	// three independent pairs and three levels instead of Horner's chain of six multiply-adds, whose
	// latency a joint's angle waits on in every solve.
	float u = t * t, u2 = u * u, u4 = u2 * u2;
	float p01 = 0.99997726f + -0.33262347f * u;
	float p23 = 0.19354346f + -0.11643287f * u;
	float p45 = 0.05265332f + -0.01172120f * u;
	return t * (p01 + u2 * p23 + u4 * p45);
}

/// atan2(y, x): the first octant's t = min/max of |x| and |y|, the others by atan(t) = π/2 − atan(1/t)
/// and the signs of x and y.
static TB_FORCE_INLINE float tbArctangent(float y, float x)
{
	float ax = fabsf(x), ay = fabsf(y);
	float big = ax > ay ? ax : ay;
	float small = ax > ay ? ay : ax;
	if (big == 0.0f)
	{
		return 0.0f; // atan2(0, 0): 0 as the libm functions give for +0
	}
	float t = small / big;
	float r;
	if (t < 0x1p-13f)
	{
		// A joint at rest near its zero angle (a ragdoll's limbs in free fall): t⁸ below would be a
		// subnormal, and an arithmetic instruction with a subnormal operand or result takes a
		// microcode assist on x86 (tens to hundreds of cycles), in every pass over every such joint.
		// For t < 2⁻¹³ every term after a1 is below half an ulp of a1 (|a3|·t² < 2⁻²⁶, half an ulp
		// is 2⁻²⁵), so tbArctangentOctant's sum rounds to a1 exactly: the same number, bit for bit
		// (tests/test_math.c checks it).
		r = t * 0.99997726f;
	}
	else
	{
		r = tbArctangentOctant(t);
	}
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
