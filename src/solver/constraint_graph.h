// Internal: graph colouring of the contact constraints for the wide solver (constraint_graph.c).
#pragma once

#include "solver_types.h"

/// Colour the contacts from their keys (tbKeyContacts) and hand out their wide lanes (before the
/// contacts are prepared into them).
void tbColorConstraints(tbStepContext* context);
/// The last step's keys in contact-id order, kept with its colours, when this step's are known to
/// equal them without computing them: the collide stage kept the touching list and found every
/// solver contact's key unchanged (world->cache.collideKeysUnchanged), the island stage kept the solver
/// contacts, the colours are the last step's and no contact bounces. NULL otherwise.
const tbContactKey* tbSteadyContactKeys(const tbStepContext* context);
/// Colour the prepared joints in a graph of their own and reorder world->cache.solverJoints colour by
/// colour (context->jointColorStart); after tbPrepareJoints, whatever the solver method.
void tbColorJoints(tbStepContext* context);
/// Release the joint order kept from the last step (world destruction).
void tbDestroyJointOrderCache(tbWorld* world);
/// Keep what this step's tree build found (joint_tree.c): none, while the joints keep their
/// fingerprint, lets the next steps skip the build (tbStepContext.jointTreesKnownAbsent).
void tbNoteJointTrees(tbStepContext* context, bool none);
void tbDestroyContactColorCache(tbWorld* world);
/// The graph colour of each solver contact of the last step, in contact-id order
/// (world->cache.solverContactsById): 0 .. TB_GRAPH_COLOR_COUNT − 1, or TB_GRAPH_COLOR_COUNT for the
/// overflow, and how many had each (either pointer may be NULL). False when the last step did not
/// colour its contacts (the scalar solver, or no touching contact): nothing is written then.
bool tbGetContactGraphColors(const tbWorld* world, int* colors, int counts[TB_GRAPH_COLOR_COUNT + 1]);
/// Forget the blocks (their memory is the step arena's).
void tbReleaseColors(tbStepContext* context);
