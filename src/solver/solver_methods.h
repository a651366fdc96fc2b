// Internal: the three position-error methods, one file each with the same functions in the same
// order (solver_soft.c, solver_baumgarte.c, solver_ngs.c); the solve stage (solver.c) picks one.
// Prepare: set the softness the constraints will copy (before tbPrepareContacts).
// SubStep: after velocity integration and warm starting, solve, integrate positions and correct.
#pragma once

#include "solver_types.h"

void tbSoftPrepare(tbStepContext* context);
void tbSoftSubStep(tbStepContext* context);
/// Relaxing passes of sub-step subStepIndex: relaxIterations, finalRelaxIterations more in the last
/// sub-step, and the joint trees' extra ones (joint.c).
int tbSoftRelaxIterations(const tbStepContext* context, int subStepIndex);
/// After tbPrepareContacts: the soft step's stiffness of each dynamic contact.

void tbBaumgartePrepare(tbStepContext* context);
void tbBaumgarteSubStep(tbStepContext* context);

void tbNGSPrepare(tbStepContext* context);
void tbNGSSubStep(tbStepContext* context);
