// Internal: graph colouring of the contact constraints for the wide solver (constraint_graph.c).
#pragma once

#include "solver_types.h"

/// Colour the prepared constraints and pack them into wide blocks (after all preparation).
void tbColorConstraints(tbStepContext* context);
/// Forget the blocks (their memory is the step arena's).
void tbReleaseColors(tbStepContext* context);
