// Internal: graph colouring of the contact constraints for the wide solver (constraint_graph.c).
#pragma once

#include "solver_types.h"

/// Colour the contacts from their keys (tbKeyContacts) and hand out their wide lanes (before the
/// contacts are prepared into them).
void tbColorConstraints(tbStepContext* context);
/// Colour the prepared joints in a graph of their own and reorder world->solverJoints colour by
/// colour (context->jointColorStart); after tbPrepareJoints, whatever the solver method.
void tbColorJoints(tbStepContext* context);
/// Release the joint order kept from the last step (world destruction).
void tbDestroyJointOrderCache(tbWorld* world);
void tbDestroyContactColorCache(tbWorld* world);
/// Forget the blocks (their memory is the step arena's).
void tbReleaseColors(tbStepContext* context);
