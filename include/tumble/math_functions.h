// Tumble: value math. Everything here is inline and has no side effects.
// Rotations are stored as a (cosine, sine) pair so that rotating a vector costs four multiplies
// and integrating an angular velocity needs no trigonometry.
#pragma once

#include "base.h"

#include <float.h>
#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TB_PI 3.14159265359f

/// 2D vector (also used for points).
typedef struct tbVec2
{
	float x, y;
} tbVec2;

/// Rotation as cosine and sine of the angle.
typedef struct tbRot
{
	float c, s;
} tbRot;

/// Rigid transform: translation then rotation.
typedef struct tbTransform
{
	tbVec2 p;
	tbRot q;
} tbTransform;

#if defined(TUMBLE_DOUBLE_PRECISION)
/// A world position (Box2D v3.2's b2Pos). In the large-world build (CMake option
/// TUMBLE_DOUBLE_PRECISION) its coordinates are doubles: a float holds a coordinate 10 km from the
/// origin to 1 mm (2⁻¹⁰ m), a double to 2e-12 m. Everything measured between two positions
/// (offsets from a body's centre, relative transforms, sweeps) is a float vector again, taken
/// as a difference of doubles (tbSubPos), so the solver and the collision routines stay in float.
typedef struct tbPos
{
	double x, y;
} tbPos;

/// A world transform: a double position and a float rotation (a rotation is the same anywhere).
typedef struct tbWorldTransform
{
	tbPos p;
	tbRot q;
} tbWorldTransform;
#else
/// A world position (Box2D v3.2's b2Pos): a plain vector, as v3.2 outside its large-world build
/// (the CMake option TUMBLE_DOUBLE_PRECISION makes it a pair of doubles). Functions that take an
/// origin (tbWorld_CastMover, tbWorld_CollideMover) measure their shapes from it.
typedef tbVec2 tbPos;
/// A world transform (Box2D v3.2's b2WorldTransform): a plain transform.
typedef tbTransform tbWorldTransform;
#endif

/// A line: the points x with dot(normal, x) = offset (normal of unit length).
typedef struct tbPlane
{
	tbVec2 normal;
	float offset;
} tbPlane;

/// 2×2 matrix stored by columns.
typedef struct tbMat22
{
	tbVec2 cx, cy;
} tbMat22;

/// Axis-aligned bounding box.
typedef struct tbAABB
{
	tbVec2 lowerBound;
	tbVec2 upperBound;
} tbAABB;

static const tbVec2 tbVec2_zero = {0.0f, 0.0f};
static const tbRot tbRot_identity = {1.0f, 0.0f};
static const tbTransform tbTransform_identity = {{0.0f, 0.0f}, {1.0f, 0.0f}};
static const tbMat22 tbMat22_zero = {{0.0f, 0.0f}, {0.0f, 0.0f}};
static const tbPos tbPos_zero = {0.0f, 0.0f};
static const tbWorldTransform tbWorldTransform_identity = {{0.0f, 0.0f}, {1.0f, 0.0f}};

/// True for a finite float (neither NaN nor infinity).
TB_INLINE bool tbIsValidFloat(float a)
{
	return isfinite(a) != 0;
}

TB_INLINE bool tbIsValidVec2(tbVec2 v)
{
	return tbIsValidFloat(v.x) && tbIsValidFloat(v.y);
}

/// A valid rotation is finite and normalised to 1e-4 (after tbNormalizeRot it is to float rounding).
TB_INLINE bool tbIsValidRotation(tbRot q)
{
	if (tbIsValidFloat(q.c) == false || tbIsValidFloat(q.s) == false)
	{
		return false;
	}
	float d = q.c * q.c + q.s * q.s - 1.0f;
	return -6e-4f < d && d < 6e-4f;
}

TB_INLINE float tbMinFloat(float a, float b)
{
	return a < b ? a : b;
}

TB_INLINE float tbMaxFloat(float a, float b)
{
	return a > b ? a : b;
}

TB_INLINE float tbAbsFloat(float a)
{
	return a < 0.0f ? -a : a;
}

TB_INLINE float tbClampFloat(float a, float lower, float upper)
{
	return a < lower ? lower : (a > upper ? upper : a);
}

TB_INLINE int tbMinInt(int a, int b)
{
	return a < b ? a : b;
}

TB_INLINE int tbMaxInt(int a, int b)
{
	return a > b ? a : b;
}

TB_INLINE tbVec2 tbMakeVec2(float x, float y)
{
	tbVec2 v = {x, y};
	return v;
}

TB_INLINE float tbDot(tbVec2 a, tbVec2 b)
{
	return a.x * b.x + a.y * b.y;
}

/// 2D cross product a × b (the z component of the 3D cross product).
TB_INLINE float tbCross(tbVec2 a, tbVec2 b)
{
	return a.x * b.y - a.y * b.x;
}

/// v × s = (s·v.y, −s·v.x).
TB_INLINE tbVec2 tbCrossVS(tbVec2 v, float s)
{
	tbVec2 r = {s * v.y, -s * v.x};
	return r;
}

/// s × v = (−s·v.y, s·v.x): the velocity of a point at offset v on a body turning at rate s.
TB_INLINE tbVec2 tbCrossSV(float s, tbVec2 v)
{
	tbVec2 r = {-s * v.y, s * v.x};
	return r;
}

/// Counter-clockwise perpendicular (−y, x).
TB_INLINE tbVec2 tbLeftPerp(tbVec2 v)
{
	tbVec2 r = {-v.y, v.x};
	return r;
}

/// Clockwise perpendicular (y, −x).
TB_INLINE tbVec2 tbRightPerp(tbVec2 v)
{
	tbVec2 r = {v.y, -v.x};
	return r;
}

TB_INLINE tbVec2 tbAdd(tbVec2 a, tbVec2 b)
{
	tbVec2 r = {a.x + b.x, a.y + b.y};
	return r;
}

TB_INLINE tbVec2 tbSub(tbVec2 a, tbVec2 b)
{
	tbVec2 r = {a.x - b.x, a.y - b.y};
	return r;
}

TB_INLINE tbVec2 tbNeg(tbVec2 a)
{
	tbVec2 r = {-a.x, -a.y};
	return r;
}

/// Linear interpolation a + t·(b − a).
TB_INLINE tbVec2 tbLerp(tbVec2 a, tbVec2 b, float t)
{
	tbVec2 r = {(1.0f - t) * a.x + t * b.x, (1.0f - t) * a.y + t * b.y};
	return r;
}

/// Component-wise product.
TB_INLINE tbVec2 tbMul(tbVec2 a, tbVec2 b)
{
	tbVec2 r = {a.x * b.x, a.y * b.y};
	return r;
}

/// s·v
TB_INLINE tbVec2 tbMulSV(float s, tbVec2 v)
{
	tbVec2 r = {s * v.x, s * v.y};
	return r;
}

/// a + s·b
TB_INLINE tbVec2 tbMulAdd(tbVec2 a, float s, tbVec2 b)
{
	tbVec2 r = {a.x + s * b.x, a.y + s * b.y};
	return r;
}

/// a − s·b
TB_INLINE tbVec2 tbMulSub(tbVec2 a, float s, tbVec2 b)
{
	tbVec2 r = {a.x - s * b.x, a.y - s * b.y};
	return r;
}

TB_INLINE tbVec2 tbAbs(tbVec2 a)
{
	tbVec2 r = {tbAbsFloat(a.x), tbAbsFloat(a.y)};
	return r;
}

TB_INLINE tbVec2 tbMin(tbVec2 a, tbVec2 b)
{
	tbVec2 r = {tbMinFloat(a.x, b.x), tbMinFloat(a.y, b.y)};
	return r;
}

TB_INLINE tbVec2 tbMax(tbVec2 a, tbVec2 b)
{
	tbVec2 r = {tbMaxFloat(a.x, b.x), tbMaxFloat(a.y, b.y)};
	return r;
}

TB_INLINE tbVec2 tbClamp(tbVec2 v, tbVec2 lower, tbVec2 upper)
{
	tbVec2 r = {tbClampFloat(v.x, lower.x, upper.x), tbClampFloat(v.y, lower.y, upper.y)};
	return r;
}

TB_INLINE float tbLength(tbVec2 v)
{
	return sqrtf(v.x * v.x + v.y * v.y);
}

TB_INLINE float tbLengthSquared(tbVec2 v)
{
	return v.x * v.x + v.y * v.y;
}

TB_INLINE float tbDistance(tbVec2 a, tbVec2 b)
{
	float dx = b.x - a.x, dy = b.y - a.y;
	return sqrtf(dx * dx + dy * dy);
}

TB_INLINE float tbDistanceSquared(tbVec2 a, tbVec2 b)
{
	float dx = b.x - a.x, dy = b.y - a.y;
	return dx * dx + dy * dy;
}

/// Unit vector along v, or zero when |v| < FLT_EPSILON (never NaN).
TB_INLINE tbVec2 tbNormalize(tbVec2 v)
{
	float length = tbLength(v);
	if (length < FLT_EPSILON)
	{
		return tbVec2_zero;
	}
	float inv = 1.0f / length;
	tbVec2 n = {inv * v.x, inv * v.y};
	return n;
}

TB_INLINE bool tbIsNormalized(tbVec2 a)
{
	float aa = tbDot(a, a);
	return tbAbsFloat(1.0f - aa) < 100.0f * FLT_EPSILON;
}

/// Unit vector along v and the length of v (length zero and zero vector when |v| < FLT_EPSILON).
TB_INLINE tbVec2 tbGetLengthAndNormalize(float* length, tbVec2 v)
{
	*length = tbLength(v);
	if (*length < FLT_EPSILON)
	{
		return tbVec2_zero;
	}
	float inv = 1.0f / *length;
	tbVec2 n = {inv * v.x, inv * v.y};
	return n;
}

TB_INLINE bool tbVec2Equals(tbVec2 a, tbVec2 b)
{
	return a.x == b.x && a.y == b.y;
}

/// Rotation from an angle in radians.
/// Cosine and sine of an angle, normalised so that c² + s² = 1 to float precision; computed without
/// the C library (math_functions.c), so the same on every platform. tbMakeRot uses it.
typedef struct tbCosSin
{
	float cosine;
	float sine;
} tbCosSin;

TB_API tbCosSin tbComputeCosSin(float radians);

/// Arctangent of y/x in [−π, π] by a polynomial (error below 3e-6 rad), the same on every
/// platform. tbRelativeAngle uses it (the joints ask for an angle in every pass, where the C
/// library's atan2f cost a fifth of a small jointed scene's step); tbRot_GetAngle uses atan2f.
TB_API float tbAtan2(float y, float x);

/// The angle brought into [−π, π] by whole turns.
TB_INLINE float tbUnwindAngle(float radians)
{
	if (radians < -TB_PI)
	{
		return radians + 2.0f * TB_PI * ceilf((-TB_PI - radians) / (2.0f * TB_PI));
	}
	if (radians > TB_PI)
	{
		return radians - 2.0f * TB_PI * ceilf((radians - TB_PI) / (2.0f * TB_PI));
	}
	return radians;
}

TB_INLINE tbRot tbMakeRot(float radians)
{
	tbCosSin cs = tbComputeCosSin(radians); // the same bits on every platform, unlike libm's
	tbRot q = {cs.cosine, cs.sine};
	return q;
}

/// Renormalise a rotation (after integration).
TB_INLINE tbRot tbNormalizeRot(tbRot q)
{
	float mag = sqrtf(q.s * q.s + q.c * q.c);
	float inv = mag > 0.0f ? 1.0f / mag : 0.0f;
	tbRot qn = {q.c * inv, q.s * inv};
	return qn;
}

/// Integrate a rotation by an angle increment without trigonometry:
/// q2 = normalize(q1 + Δθ·perp(q1)), exact to O(Δθ³) in angle.
/// Normalised linear interpolation of two rotations (t in [0, 1]): the shorter way when they are
/// less than half a turn apart.
TB_INLINE tbRot tbNLerp(tbRot q1, tbRot q2, float t)
{
	float u = 1.0f - t;
	tbRot q = {u * q1.c + t * q2.c, u * q1.s + t * q2.s};
	return tbNormalizeRot(q);
}

TB_INLINE tbRot tbIntegrateRotation(tbRot q1, float deltaAngle)
{
	tbRot q2 = {q1.c - deltaAngle * q1.s, q1.s + deltaAngle * q1.c};
	return tbNormalizeRot(q2);
}

/// Angle in radians in [−π, π].
TB_INLINE float tbRot_GetAngle(tbRot q)
{
	return atan2f(q.s, q.c);
}

TB_INLINE tbVec2 tbRot_GetXAxis(tbRot q)
{
	tbVec2 v = {q.c, q.s};
	return v;
}

TB_INLINE tbVec2 tbRot_GetYAxis(tbRot q)
{
	tbVec2 v = {-q.s, q.c};
	return v;
}

/// q · r (compose: rotate by r, then by q).
TB_INLINE tbRot tbMulRot(tbRot q, tbRot r)
{
	tbRot qr = {q.c * r.c - q.s * r.s, q.s * r.c + q.c * r.s};
	return qr;
}

/// qᵀ · r (the rotation from q to r).
TB_INLINE tbRot tbInvMulRot(tbRot q, tbRot r)
{
	tbRot qr = {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c};
	return qr;
}

/// Relative angle of b with respect to a, in [−π, π].
TB_INLINE float tbRelativeAngle(tbRot a, tbRot b)
{
	float s = a.c * b.s - a.s * b.c;
	float c = a.c * b.c + a.s * b.s;
	return tbAtan2(s, c);
}

TB_INLINE tbVec2 tbRotateVector(tbRot q, tbVec2 v)
{
	tbVec2 r = {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
	return r;
}

TB_INLINE tbVec2 tbInvRotateVector(tbRot q, tbVec2 v)
{
	tbVec2 r = {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
	return r;
}

TB_INLINE tbVec2 tbTransformPoint(tbTransform t, const tbVec2 p)
{
	float x = (t.q.c * p.x - t.q.s * p.y) + t.p.x;
	float y = (t.q.s * p.x + t.q.c * p.y) + t.p.y;
	tbVec2 r = {x, y};
	return r;
}

TB_INLINE tbVec2 tbInvTransformPoint(tbTransform t, const tbVec2 p)
{
	float vx = p.x - t.p.x;
	float vy = p.y - t.p.y;
	tbVec2 r = {t.q.c * vx + t.q.s * vy, -t.q.s * vx + t.q.c * vy};
	return r;
}

/// A · B
TB_INLINE tbTransform tbMulTransforms(tbTransform A, tbTransform B)
{
	tbTransform C;
	C.q = tbMulRot(A.q, B.q);
	C.p = tbAdd(tbRotateVector(A.q, B.p), A.p);
	return C;
}

/// A⁻¹ · B (B expressed in the frame of A).
TB_INLINE tbTransform tbInvMulTransforms(tbTransform A, tbTransform B)
{
	tbTransform C;
	C.q = tbInvMulRot(A.q, B.q);
	C.p = tbInvRotateVector(A.q, tbSub(B.p, A.p));
	return C;
}

TB_INLINE bool tbIsValidTransform(tbTransform t)
{
	return tbIsValidVec2(t.p) && tbIsValidRotation(t.q);
}

TB_INLINE tbVec2 tbMulMV(tbMat22 A, tbVec2 v)
{
	tbVec2 u = {A.cx.x * v.x + A.cy.x * v.y, A.cx.y * v.x + A.cy.y * v.y};
	return u;
}

/// Inverse of a 2×2 matrix (zero matrix when singular).
TB_INLINE tbMat22 tbGetInverse22(tbMat22 A)
{
	float a = A.cx.x, b = A.cy.x, c = A.cx.y, d = A.cy.y;
	float det = a * d - b * c;
	if (det != 0.0f)
	{
		det = 1.0f / det;
	}
	tbMat22 B = {{det * d, -det * c}, {-det * b, det * a}};
	return B;
}

/// Solve A·x = b (zero when A is singular).
TB_INLINE tbVec2 tbSolve22(tbMat22 A, tbVec2 b)
{
	float a11 = A.cx.x, a12 = A.cy.x, a21 = A.cx.y, a22 = A.cy.y;
	float det = a11 * a22 - a12 * a21;
	if (det != 0.0f)
	{
		det = 1.0f / det;
	}
	tbVec2 x = {det * (a22 * b.x - a12 * b.y), det * (a11 * b.y - a21 * b.x)};
	return x;
}

/// True when the boxes overlap: they are disjoint exactly when separated on either axis.
TB_INLINE bool tbAABB_Overlaps(tbAABB a, tbAABB b)
{
	return !(b.lowerBound.x > a.upperBound.x || b.lowerBound.y > a.upperBound.y || a.lowerBound.x > b.upperBound.x ||
			 a.lowerBound.y > b.upperBound.y);
}

/// True when a contains b (touching boundaries count as inside).
TB_INLINE bool tbAABB_Contains(tbAABB a, tbAABB b)
{
	return a.lowerBound.x <= b.lowerBound.x && a.lowerBound.y <= b.lowerBound.y && b.upperBound.x <= a.upperBound.x &&
		   b.upperBound.y <= a.upperBound.y;
}

TB_INLINE tbVec2 tbAABB_Center(tbAABB a)
{
	tbVec2 c = {0.5f * (a.lowerBound.x + a.upperBound.x), 0.5f * (a.lowerBound.y + a.upperBound.y)};
	return c;
}

/// Half widths.
TB_INLINE tbVec2 tbAABB_Extents(tbAABB a)
{
	tbVec2 e = {0.5f * (a.upperBound.x - a.lowerBound.x), 0.5f * (a.upperBound.y - a.lowerBound.y)};
	return e;
}

TB_INLINE tbAABB tbAABB_Union(tbAABB a, tbAABB b)
{
	tbAABB c;
	c.lowerBound = tbMin(a.lowerBound, b.lowerBound);
	c.upperBound = tbMax(a.upperBound, b.upperBound);
	return c;
}

/// Perimeter: the 2D surface-area heuristic's cost measure.
TB_INLINE float tbAABB_Perimeter(tbAABB a)
{
	return 2.0f * ((a.upperBound.x - a.lowerBound.x) + (a.upperBound.y - a.lowerBound.y));
}

/// Box enlarged by margin on every side.
TB_INLINE tbAABB tbAABB_Fatten(tbAABB a, float margin)
{
	tbAABB c = {{a.lowerBound.x - margin, a.lowerBound.y - margin}, {a.upperBound.x + margin, a.upperBound.y + margin}};
	return c;
}

TB_INLINE bool tbIsValidAABB(tbAABB a)
{
	tbVec2 d = tbSub(a.upperBound, a.lowerBound);
	return d.x >= 0.0f && d.y >= 0.0f && tbIsValidVec2(a.lowerBound) && tbIsValidVec2(a.upperBound);
}

// --- Box2D v3.2's smaller helpers --------------------------------------------------------------

TB_INLINE int tbAbsInt(int a)
{
	return a < 0 ? -a : a;
}

TB_INLINE int tbClampInt(int a, int lower, int upper)
{
	return a < lower ? lower : (a > upper ? upper : a);
}

/// ⌈numerator / denominator⌉ for positive operands.
TB_INLINE int tbCeilingInt(int numerator, int denominator)
{
	return (numerator + denominator - 1) / denominator;
}

/// The rotation whose (cos, sin) is the given unit vector.
TB_INLINE tbRot tbMakeRotFromUnitVector(tbVec2 unitVector)
{
	tbRot q = {unitVector.x, unitVector.y};
	return q;
}

/// cos² + sin² within 6e-4 of 1 (tbIsValidRotation also asks for finite numbers).
TB_INLINE bool tbIsNormalizedRot(tbRot q)
{
	float d = q.c * q.c + q.s * q.s - 1.0f;
	return -6e-4f < d && d < 6e-4f;
}

/// The opposite rotation (its transpose).
TB_INLINE tbRot tbInvertRot(tbRot q)
{
	tbRot r = {q.c, -q.s};
	return r;
}

/// Angular velocity that turns q1 into q2 in time 1/inv_h, to first order: with q2 ≈ q1 + ω·h·q1⊥,
/// ω·h = sin(θ2 − θ1) = q1.c·q2.s − q1.s·q2.c.
TB_INLINE float tbComputeAngularVelocity(tbRot q1, tbRot q2, float inv_h)
{
	return inv_h * (q1.c * q2.s - q1.s * q2.c);
}

/// The rotation taking unit vector v1 to unit vector v2: cos = v1·v2, sin = v1 × v2.
TB_API tbRot tbComputeRotationBetweenUnitVectors(tbVec2 v1, tbVec2 v2);
TB_API bool tbIsValidPlane(tbPlane plane);
TB_API bool tbIsValidPosition(tbPos p);
TB_API bool tbIsValidWorldTransform(tbWorldTransform t);

/// Signed distance of a point from a plane (positive on the normal's side).
TB_INLINE float tbPlaneSeparation(tbPlane plane, tbVec2 point)
{
	return tbDot(plane.normal, point) - plane.offset;
}

/// Box of points inflated by radius.
TB_INLINE tbAABB tbMakeAABB(const tbVec2* points, int count, float radius)
{
	tbAABB box = {points[0], points[0]};
	for (int i = 1; i < count; ++i)
	{
		box.lowerBound = tbMin(box.lowerBound, points[i]);
		box.upperBound = tbMax(box.upperBound, points[i]);
	}
	tbVec2 r = {radius, radius};
	box.lowerBound = tbSub(box.lowerBound, r);
	box.upperBound = tbAdd(box.upperBound, r);
	return box;
}

/// The velocity, after one implicit step, of a unit mass on a spring of the given frequency and
/// damping ratio pulled back to 0: v' = (v − ω²h·x)/(1 + 2ζωh + ω²h²). Position += h·v' after it.
TB_INLINE float tbSpringDamper(float hertz, float dampingRatio, float position, float velocity, float timeStep)
{
	float omega = 2.0f * TB_PI * hertz;
	float omegaH = omega * timeStep;
	return (velocity - omega * omegaH * position) / (1.0f + 2.0f * dampingRatio * omegaH + omegaH * omegaH);
}

#if defined(TUMBLE_DOUBLE_PRECISION)
// World positions in the large-world build. The rule that keeps precision: a position is only
// ever added to or subtracted from another position (in double), and only the difference, a
// small vector, meets float arithmetic. Rotations apply to float vectors only.

/// The vector v as a position (exact).
TB_INLINE tbPos tbToPos(tbVec2 v)
{
	tbPos p = {v.x, v.y};
	return p;
}

/// The position p rounded to float (loses precision far from the origin; for drawing and for
/// values near the origin).
TB_INLINE tbVec2 tbToVec2(tbPos p)
{
	tbVec2 v = {(float)p.x, (float)p.y};
	return v;
}

/// x rounded to a float at or below it: with tbRoundUpFloat, a float box that contains a double
/// one. The float nearest x may lie on either side; one step of nextafterf (exact, the same on
/// every IEEE machine) moves it below.
TB_INLINE float tbRoundDownFloat(double x)
{
	float f = (float)x;
	return (double)f > x ? nextafterf(f, -FLT_MAX) : f;
}

/// x rounded to a float at or above it.
TB_INLINE float tbRoundUpFloat(double x)
{
	float f = (float)x;
	return (double)f < x ? nextafterf(f, FLT_MAX) : f;
}

/// a − b, subtracted in double, then rounded to a float vector.
TB_INLINE tbVec2 tbSubPos(tbPos a, tbPos b)
{
	tbVec2 d = {(float)(a.x - b.x), (float)(a.y - b.y)};
	return d;
}

/// p + d.
TB_INLINE tbPos tbOffsetPos(tbPos p, tbVec2 d)
{
	tbPos q = {p.x + (double)d.x, p.y + (double)d.y};
	return q;
}

/// (1 − t)·a + t·b.
TB_INLINE tbPos tbLerpPosition(tbPos a, tbPos b, float t)
{
	double u = (double)t;
	tbPos p = {(1.0 - u) * a.x + u * b.x, (1.0 - u) * a.y + u * b.y};
	return p;
}

/// The local point p placed by t: rotated in float, then offset from t's position in double.
TB_INLINE tbPos tbTransformWorldPoint(tbWorldTransform t, tbVec2 p)
{
	return tbOffsetPos(t.p, tbRotateVector(t.q, p));
}

/// The position p in t's frame: the offset from t's position in double, then rotated back.
TB_INLINE tbVec2 tbInvTransformWorldPoint(tbWorldTransform t, tbPos p)
{
	return tbInvRotateVector(t.q, tbSubPos(p, t.p));
}

/// Frame B seen from frame A: A⁻¹·B, its offset B.p − A.p taken in double.
TB_INLINE tbTransform tbInvMulWorldTransforms(tbWorldTransform A, tbWorldTransform B)
{
	tbTransform C = {tbInvRotateVector(A.q, tbSubPos(B.p, A.p)), tbInvMulRot(A.q, B.q)};
	return C;
}

/// A local transform B carried into the world by A.
TB_INLINE tbWorldTransform tbMulWorldTransforms(tbWorldTransform A, tbTransform B)
{
	tbWorldTransform C = {tbOffsetPos(A.p, tbRotateVector(A.q, B.p)), tbMulRot(A.q, B.q)};
	return C;
}

/// The transform with its position measured from base.
TB_INLINE tbTransform tbToRelativeTransform(tbWorldTransform t, tbPos base)
{
	tbTransform r = {tbSubPos(t.p, base), t.q};
	return r;
}

/// A float transform as a world transform (exact).
TB_INLINE tbWorldTransform tbMakeWorldTransform(tbTransform t)
{
	tbWorldTransform w = {tbToPos(t.p), t.q};
	return w;
}

/// The box b measured from base, as a world box that contains it: each bound offset in double
/// and rounded outwards, so a shape stays inside its box however far from the origin.
TB_INLINE tbAABB tbOffsetAABB(tbAABB b, tbPos base)
{
	tbAABB r = {{tbRoundDownFloat(base.x + b.lowerBound.x), tbRoundDownFloat(base.y + b.lowerBound.y)},
				{tbRoundUpFloat(base.x + b.upperBound.x), tbRoundUpFloat(base.y + b.upperBound.y)}};
	return r;
}
#else
// World positions (tbPos) are plain vectors in Tumble (Box2D v3.2 outside its large-world build):
// these conversions are exact and cost nothing; they let v3.2 code written for positions port.
TB_INLINE tbPos tbToPos(tbVec2 v)
{
	return v;
}

TB_INLINE tbVec2 tbToVec2(tbPos p)
{
	return p;
}

TB_INLINE float tbRoundDownFloat(double x)
{
	return (float)x;
}

TB_INLINE float tbRoundUpFloat(double x)
{
	return (float)x;
}

/// a − b as a vector.
TB_INLINE tbVec2 tbSubPos(tbPos a, tbPos b)
{
	return tbSub(a, b);
}

/// p + d.
TB_INLINE tbPos tbOffsetPos(tbPos p, tbVec2 d)
{
	return tbAdd(p, d);
}

TB_INLINE tbPos tbLerpPosition(tbPos a, tbPos b, float t)
{
	tbPos p = {(1.0f - t) * a.x + t * b.x, (1.0f - t) * a.y + t * b.y};
	return p;
}

TB_INLINE tbPos tbTransformWorldPoint(tbWorldTransform t, tbVec2 p)
{
	return tbTransformPoint(t, p);
}

TB_INLINE tbVec2 tbInvTransformWorldPoint(tbWorldTransform t, tbPos p)
{
	return tbInvTransformPoint(t, p);
}

/// Frame B seen from frame A.
TB_INLINE tbTransform tbInvMulWorldTransforms(tbWorldTransform A, tbWorldTransform B)
{
	return tbInvMulTransforms(A, B);
}

/// A local transform B carried into the world by A.
TB_INLINE tbWorldTransform tbMulWorldTransforms(tbWorldTransform A, tbTransform B)
{
	return tbMulTransforms(A, B);
}

/// The transform with its position measured from base.
TB_INLINE tbTransform tbToRelativeTransform(tbWorldTransform t, tbPos base)
{
	tbTransform r = {tbSub(t.p, base), t.q};
	return r;
}

TB_INLINE tbWorldTransform tbMakeWorldTransform(tbTransform t)
{
	return t;
}

/// The box b measured from base, as a world box.
TB_INLINE tbAABB tbOffsetAABB(tbAABB b, tbPos base)
{
	tbAABB r = {tbAdd(b.lowerBound, base), tbAdd(b.upperBound, base)};
	return r;
}
#endif

#ifdef __cplusplus
}
#endif
