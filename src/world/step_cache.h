// Internal: what one stage of the step hands to the next and one step to the next, in one place:
// the per-step lists (contacts to collide, contacts and joints to solve, the joint trees), the
// scratch they are built in, and the stamps that say whether the last step's lists still hold.
//
// A settled pile repeats the last step's lists, so each stage first asks whether its inputs changed
// and, when they did not, keeps its last output instead of rebuilding it (contact.c's collide stage,
// island.c, contact_solver.c's keys, constraint_graph.c's colours and joint order). The inputs are
// the awake set and the contact pool; everything that changes them goes through the invalidation
// functions at the end of this file, and nothing else writes the version counters.
#pragma once

#include "contact.h"

#include <stdbool.h>
#include <stdint.h>

struct tbCollideTally;
struct tbJointOrderCache;
struct tbContactColorCache;
struct tbJointTreeNode;
struct tbTree;
struct tbJointRows;

typedef struct tbStepCache
{
	// The collide stage (contact.c): contacts of awake bodies gathered for the narrow phase, each
	// one's result, and per-worker tallies (from the step arena).
	int* stepContacts;
	int stepContactCount, stepContactCapacity;
	uint16_t* collideResults;
	int collideResultCapacity;
	struct tbCollideTally* collideTallies;
	/// By contact id: the two bodies, or TB_NULL_INDEX for a free slot (up to the contact pool's
	/// high water). A dense copy of what the collide stage's scan of the contact pool reads, so the
	/// scan does not walk whole contacts for three fields.
	tbBodyPair* contactBodies;
	int contactBodyCapacity;
	tbCollideKey* collideKeys; ///< by contact id, up to collideKeyCount (entries past it never written)
	int collideKeyCount, collideKeyCapacity;
	/// Touching non-sensor contacts in stepContacts order, recorded by the collide stage: the island
	/// stage's fast path (island.c). An entry is the contact id when the contact is ready for the
	/// solver as it stands (a dynamic side, no sleeping side), −1 − id when the island stage must
	/// look at its bodies.
	int* touchingContacts;
	int touchingContactCount, touchingContactCapacity;
	/// Sensor contacts whose sensor a fast shape crossed this step (continuous.c), each marked
	/// tb_contactSensorHit, for the sensor stage; from the step arena.
	int* sensorHitContacts;
	int sensorHitCount;

	// The island stage (island.c): the contacts the solver sees, in solve order (constraint i is
	// contact solverContacts[i]); the same contacts in contact-id order and each one's index in
	// solverContacts, so that the solver prepares and stores by walking contact memory in order.
	int* solverContacts;
	int solverContactCount, solverContactCapacity;
	int* solverContactsById;
	int solverContactsByIdCapacity;
	int* solverSlots;
	int solverSlotCapacity;
	int* islandStack;
	int islandStackCapacity;

	// Joints (joint.c, joint_tree.c): the joints the solver sees this step in joint-id order, a stack
	// for waking joined bodies, and this step's joint trees (from the step arena).
	int* solverJoints;
	int solverJointCount, solverJointCapacity;
	int* jointWakeStack;
	int jointWakeCount, jointWakeCapacity;
	bool jointWakeActive;
	struct tbJointTreeNode* jointTreeNodes;
	int jointTreeNodeCount;
	struct tbTree* jointTrees;
	int jointTreeCount;
	double* jointTreeValues; ///< joint_tree.c works in double precision
	struct tbJointRows* jointTreeRows;

	// The solver's orderings of the last step (constraint_graph.c).
	struct tbJointOrderCache* jointOrderCache;
	struct tbContactColorCache* contactColorCache;

	// Versions of the inputs: bumped by the invalidation functions below.
	uint32_t awakeSetVersion; ///< a body joined or left the awake set
	uint32_t awakeRemovals;	  ///< a body left the awake set
	uint32_t contactEpoch;	  ///< a contact was created or destroyed

	// Stamps of what each stage last built from those inputs.
	uint32_t gatheredVersion;  ///< awakeSetVersion when the collide stage gathered stepContacts
	uint32_t gatheredRemovals; ///< awakeRemovals then
	int gatheredAwakeCount;	   ///< the awake count then: bodies woken since are appended after it
	uint32_t touchingEpoch;	   ///< contactEpoch when touchingContacts was last built
	bool touchingAllReady;	   ///< every entry of touchingContacts was ready then
	bool touchingUnchanged;	   ///< this step's collide stage kept the last touching list
	bool collideKeysUnchanged; ///< and every solver contact's key is the last step's
	bool solverContactsUnchanged; ///< this step's island stage found its solver contacts unchanged
	uint32_t colorCacheStep;	  ///< step of the last colouring, or reuse, of contactColorCache
	/// After a colouring that found no island partitions, none is looked for before this step
	/// (TB_PARTITION_RETRY_STEPS later).
	uint32_t partitionRetryStep;
	/// A body joined or left the awake set since the joints were last checked for a sleeping partner
	/// of an awake body (tbWakeJointPartners); with no kinematic body that is the only way such a
	/// joint appears.
	bool jointWakeDirty;
	bool jointTreesStale;	 ///< the bodies moved since the joint trees were last factored
	uint32_t fastMarkedStep; ///< step whose solve marked its fast bodies (tbMarkFastBody in the scatter)
	int fastMarkedCount;	 ///< bodies it marked fast
} tbStepCache;

/// A body joined the awake set (`removal` false) or left it (true).
static inline void tbStepCache_AwakeSetChanged(tbStepCache* cache, bool removal)
{
	cache->awakeSetVersion += 1;
	cache->awakeRemovals += removal ? 1u : 0u;
	cache->jointWakeDirty = true;
}

/// A contact was created or destroyed.
static inline void tbStepCache_ContactsChanged(tbStepCache* cache)
{
	cache->contactEpoch += 1;
}

/// The bodies moved (a new sub-step): the joint trees must be factored again before use.
static inline void tbStepCache_BodiesMoved(tbStepCache* cache)
{
	cache->jointTreesStale = true;
}
