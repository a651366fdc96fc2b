// Body integration within the solve stage: semi-implicit Euler, one sub-step at a time, on the
// dense solver body arrays (solver_types.h).
//
// Velocities: v ← (v + h·(gravityScale·g + F/m))·1/(1 + h·c_lin), ω ← (ω + h·τ/I)·1/(1 + h·c_ang),
// with the per-body increments precomputed once per step (tbSolverMotion: forces are constant
// during a step); then |v| ≤ maximumLinearSpeed and |ω|·Δt ≤ TB_MAX_ROTATION. Positions are kept
// as deltas from the start of the step: Δp += h·v, Δq ← integrate(Δq, h·ω).
#include "integrator.h"

#include "tumble/constants.h"

#include <math.h>

// The speed clamp when |v|² is not a finite float: a speed above ~1.8e19 m/s (a velocity of
// 1e20 set by the user, gravity 3e38 m/s²) squares to infinity, and the plain clamp's factor
// max/|v| would be 0, stopping the body. Scale v by its largest component first, so the length
// is computed without overflow; an infinite component (the sum overflowed) gives the direction
// alone, and a NaN component (∞ − ∞) has no direction and counts as 0.
static tbVec2 tbClampHugeSpeed(tbVec2 v, float maxSpeed)
{
	float x = v.x == v.x ? v.x : 0.0f;
	float y = v.y == v.y ? v.y : 0.0f;
	bool infinite = isinf(x) || isinf(y);
	if (infinite)
	{
		x = isinf(x) ? copysignf(1.0f, x) : 0.0f;
		y = isinf(y) ? copysignf(1.0f, y) : 0.0f;
	}
	float scale = tbMaxFloat(tbAbsFloat(x), tbAbsFloat(y));
	if (scale == 0.0f)
	{
		return tbVec2_zero;
	}
	tbVec2 scaled = tbMakeVec2(x / scale, y / scale); // largest component ±1: |scaled| in [1, √2]
	float length = tbLength(scaled);
	float speed = infinite ? maxSpeed : tbMinFloat(maxSpeed, scale * length);
	return tbMulSV(speed / length, scaled);
}

// Speeds limited to maxLinearSpeed and maxAngularSpeed (NaN spin: none).
void tbClampSpeedsTo(tbSolverBody* sb, float maxLinearSpeed, float maxAngularSpeed)
{
	tbVec2 v = sb->linearVelocity;
	float w = sb->angularVelocity;
	float speedSquared = tbDot(v, v);
	if (tbIsValidFloat(speedSquared) == false)
	{
		v = tbClampHugeSpeed(v, maxLinearSpeed);
	}
	else if (speedSquared > maxLinearSpeed * maxLinearSpeed)
	{
		v = tbMulSV(maxLinearSpeed / sqrtf(speedSquared), v);
	}
	w = w == w ? tbClampFloat(w, -maxAngularSpeed, maxAngularSpeed) : 0.0f; // NaN (0 · ∞ torque): no direction
	sb->linearVelocity = v;
	sb->angularVelocity = w;
}

// The solve may leave a body far faster than the limits the integration of velocities keeps: a
// joint whose anchors start far apart asks for their gap divided by the spring time (a fuzzed
// anchor 290 km from its body gave 7e7 m/s and 8e17 rad/s, then non-finite positions). Positions
// are integrated with speeds at most TB_SPEED_GUARD times the limits. The factor leaves every
// scene that stays near its limits as it was (the solve of a sub-step overshoots them only
// briefly, by a few times at most), and bounds the motion of the rest.
#define TB_SPEED_GUARD 16.0f

/// maxLinearSpeed, maxAngularSpeed: the guarded limits, found once per range by the caller.
static inline void tbGuardSpeeds(tbSolverBody* sb, float maxLinearSpeed, float maxAngularSpeed)
{
	float w = sb->angularVelocity;
	float speedSquared = tbDot(sb->linearVelocity, sb->linearVelocity);
	// Written so that NaN and infinities take the clamping path.
	if (!(speedSquared <= maxLinearSpeed * maxLinearSpeed && tbAbsFloat(w) <= maxAngularSpeed))
	{
		tbClampSpeedsTo(sb, maxLinearSpeed, maxAngularSpeed);
	}
}

void tbIntegrateVelocities(tbStepContext* context)
{
	tbIntegrateVelocitiesRange(context, 0, context->bodyCount);
}

void tbIntegrateVelocitiesRange(tbStepContext* context, int start, int end)
{
	for (int i = start; i < end; ++i)
	{
		tbSolverBody* sb = context->bodies + i;
		const tbSolverMotion* m = context->motions + i;
		sb->linearVelocity = tbMulSV(m->linearDamping, tbAdd(sb->linearVelocity, m->linearDelta));
		sb->angularVelocity = m->angularDamping * (sb->angularVelocity + m->angularDelta);
		tbClampSpeeds(context, sb, i);
	}
}

void tbIntegratePositions(tbStepContext* context)
{
	tbIntegratePositionsRange(context, 0, context->bodyCount);
}

void tbIntegratePositionsRange(tbStepContext* context, int start, int end)
{
	float h = context->h;
	// Only joints can ask for unbounded speeds (contacts push out at most contactSpeed and
	// rebound at most 2·maxLinearSpeed, docs/limits.md): a world without them skips the guard, a
	// squared speed and two compares per body and sub-step that a pile of boxes never needs.
	bool guard = context->world->jointPool.count > 0;
	float guardLinear = TB_SPEED_GUARD * context->maxLinearSpeed;
	float guardAngular = TB_SPEED_GUARD * context->maxAngularSpeed;
	const uint8_t* locks = context->linearLocks;
	for (int i = start; i < end; ++i)
	{
		tbSolverBody* sb = context->bodies + i;
		if (locks != NULL && locks[i] != 0)
		{
			// Motion locks act as a constraint solved last (Box2D v3.2 does the same): the body
			// never moves along a locked axis; the contacts solved before saw it free along it.
			tbApplyLinearLocks(locks[i], &sb->linearVelocity);
		}
		if (guard)
		{
			tbGuardSpeeds(sb, guardLinear, guardAngular);
		}
		sb->deltaPosition = tbMulAdd(sb->deltaPosition, h, sb->linearVelocity);
		sb->deltaRotation = tbIntegrateRotation(sb->deltaRotation, h * sb->angularVelocity);
	}
}
