// Internal: the sequential-impulse contact solver shared by the position methods, scalar
// (contact_solver.c) and four contacts of one colour at a time (contact_solver_wide.c).
#pragma once

#include "solver_types.h"

/// Restitution's rebound speed −e·Ċ0 for an approach at Ċ0 < 0, at most the approach speed or
/// twice maximumLinearSpeed, whichever is larger: e > 1 (a bumper) still rebounds faster than it
/// came, but a huge e (3e38) cannot overflow the impulse or store one that warm starting would
/// re-apply after the speed clamp. For e ≤ 1 the bound never acts.
static inline float tbReboundSpeed(float restitution, float approach, float maxLinearSpeed)
{
	return tbMinFloat(-restitution * approach, tbMaxFloat(-approach, 2.0f * maxLinearSpeed));
}

// contact_solver.c
void tbPrepareContacts(tbStepContext* context);
void tbWarmStartContacts(tbStepContext* context);
void tbSolveContacts(tbStepContext* context, tbBiasPolicy policy);
void tbApplyRestitution(tbStepContext* context);
/// Impact propagation before the solve (tbWorldDef::enableImpactPropagation; contact_solver.c).
void tbPropagateImpacts(tbStepContext* context);
void tbStoreImpulses(tbStepContext* context);

// contact_solver_wide.c
void tbInitWideConstraint(tbWideContactConstraint* block, int staticIndex);
void tbPackWideLane(tbWideContactConstraint* block, int lane, const tbContactConstraint* c, int constraintIndex);
void tbWarmStartContactsWide(tbStepContext* context);
void tbSolveContactsWide(tbStepContext* context, tbBiasPolicy policy);
/// Blocks [start, end) of the wide constraints (one colour's, for a worker). `shared`: other
/// workers solve other blocks of the colour at the same time, so bodies that do not move are not
/// written (the same result, without two threads storing to one body).
void tbWarmStartWideRange(tbStepContext* context, int start, int end, bool shared);
void tbSolveWideRange(tbStepContext* context, tbBiasPolicy policy, int start, int end, bool shared);
/// The wide solver's overflow (constraints that found no colour), one at a time after the colours.
void tbWarmStartOverflow(tbStepContext* context);
void tbSolveOverflow(tbStepContext* context, tbBiasPolicy policy);
/// Copy the impulses of the lane at `location` into manifold points.
void tbLoadWideImpulses(const tbStepContext* context, int location, int pointCount, tbManifoldPoint* points);
/// Copy a constraint's impulses from its lane to the scalar constraint, which holds them from then on.
void tbUnpackWideConstraint(tbStepContext* context, int constraintIndex);
