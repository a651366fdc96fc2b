// Internal: body integration within the solve stage (integrator.c), shared by the position methods.
#pragma once

#include "solver_types.h"

/// |v| ≤ maximumLinearSpeed (without overflow for any finite or infinite v) and |ω| ≤ the
/// per-step rotation bound (no bound on ω for solver body `index` when it allows fast rotation);
/// applied to the velocities a step starts from and after each update.
void tbClampSpeeds(const tbStepContext* context, tbSolverBody* sb, int index);

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
