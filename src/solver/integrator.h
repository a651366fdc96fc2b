// Internal: body integration within the solve stage (integrator.c), shared by the position methods.
#pragma once

#include "solver_types.h"

#include <float.h>
#include <math.h>

/// |v| ≤ maxLinearSpeed (without overflow for any finite or infinite v), |ω| ≤ maxAngularSpeed, a
/// NaN spin cleared.
void tbClampSpeedsTo(tbSolverBody* sb, float maxLinearSpeed, float maxAngularSpeed);

/// |v| ≤ maximumLinearSpeed and |ω| ≤ the per-step rotation bound (no bound on ω for solver body
/// `index` when it allows fast rotation: a wheel keeps its spin, only NaN is cleared; continuous
/// collision's rotation bound then does not hold for it, which costs nothing for a round shape, as
/// Box2D v3.2 says of the option); applied to the velocities a step starts from and after each
/// update. Inline, the clamp called only beyond the limits (or for NaN and infinities): a body
/// within them, nearly every one, is left as it is, which the clamp would also do.
static inline void tbClampSpeeds(const tbStepContext* context, tbSolverBody* sb, int index)
{
	bool fast = context->fastRotation != NULL && context->fastRotation[index] != 0;
	float maxLinear = context->maxLinearSpeed;
	float maxAngular = fast ? FLT_MAX : context->maxAngularSpeed;
	tbVec2 v = sb->linearVelocity;
	if (!(tbDot(v, v) <= maxLinear * maxLinear && fabsf(sb->angularVelocity) <= maxAngular))
	{
		tbClampSpeedsTo(sb, maxLinear, maxAngular);
	}
}

/// Zero the components of v along the locked axes (1: x, 2: y; tbStepContext::linearLocks).
static inline void tbApplyLinearLocks(uint8_t locks, tbVec2* v)
{
	v->x = (locks & 1u) != 0u ? 0.0f : v->x;
	v->y = (locks & 2u) != 0u ? 0.0f : v->y;
}

/// Semi-implicit Euler velocity update of one sub-step, then the speed clamps.
void tbIntegrateVelocities(tbStepContext* context);

/// Position update of one sub-step: Δp += h·v, Δq ← integrate(Δq, h·ω).
void tbIntegratePositions(tbStepContext* context);
/// Bodies [start, end) only (a worker's share).
void tbIntegrateVelocitiesRange(tbStepContext* context, int start, int end);
void tbIntegratePositionsRange(tbStepContext* context, int start, int end);
