// Internal: graph colouring of the contact constraints for the wide solver (constraint_graph.c).
#pragma once

#include "solver_types.h"

/// Colour the prepared constraints and pack them into wide blocks (after all preparation).
void tbColorConstraints(tbStepContext* context);
/// Colour the prepared joints in a graph of their own and reorder world->solverJoints colour by
/// colour (context->jointColorStart); after tbPrepareJoints, whatever the solver method.
void tbColorJoints(tbStepContext* context);
/// Forget the blocks (their memory is the step arena's).
void tbReleaseColors(tbStepContext* context);
