// Internal: a chain as the world keeps it, and what bodies and the world ask of chains (chain.c).
#pragma once

#include "tumble/types.h"

typedef struct tbWorld tbWorld;

/// A run of one-sided segments on one body: the ids of its segment shapes and its materials.
typedef struct tbChain
{
	int bodyId;
	int* shapeIds; ///< segmentCount shape ids, in chain order
	int segmentCount;
	tbSurfaceMaterial* materials;
	int materialCount;
	uint16_t generation;
	bool inUse;
} tbChain;

/// Destroy every chain of a body (tbDestroyBody frees the segment shapes with the body's shapes).
void tbDestroyBodyChains(tbWorld* world, int bodyIndex);
/// Free the chain pool (world destruction).
void tbFreeChains(tbWorld* world);
