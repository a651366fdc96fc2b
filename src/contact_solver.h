// Internal: the sequential-impulse contact solver shared by the position methods, scalar
// (contact_solver.c) and four contacts of one colour at a time (contact_solver_wide.c).
#pragma once

#include "solver_types.h"

// contact_solver.c
tbSoftness tbMakeSoftness(float hertz, float dampingRatio, float h);
void tbPrepareContacts(tbStepContext* context);
void tbWarmStartContacts(tbStepContext* context);
void tbSolveContacts(tbStepContext* context, tbBiasPolicy policy);
void tbApplyRestitution(tbStepContext* context);
void tbStoreImpulses(tbStepContext* context);

// contact_solver_wide.c
void tbInitWideConstraint(tbWideContactConstraint* block, int staticIndex);
void tbPackWideLane(tbWideContactConstraint* block, int lane, const tbContactConstraint* c, int constraintIndex);
void tbWarmStartContactsWide(tbStepContext* context);
void tbSolveContactsWide(tbStepContext* context, tbBiasPolicy policy);
/// Copy the impulses of the lane at `location` into manifold points.
void tbLoadWideImpulses(const tbStepContext* context, int location, int pointCount, tbManifoldPoint* points);
/// Copy a constraint's impulses from its lane to the scalar constraint, which holds them from then on.
void tbUnpackWideConstraint(tbStepContext* context, int constraintIndex);
