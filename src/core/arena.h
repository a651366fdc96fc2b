// Internal: the step arena, a bump allocator for the temporaries of one step.
//
// Every temporary array of a step (solver bodies and constraints, colour blocks, NGS scratch) is
// taken from the world's arena and released all at once when the next step begins, so a step
// makes no call to the allocator hook once the arena is big enough. The arena cannot know in
// advance how much a step needs: an allocation that does not fit is served from the heap and
// remembered, and at the next reset the arena grows to the largest total seen. From then on the
// same scene allocates nothing (tests/test_arena.c counts the hook's calls).
#pragma once

#include "core.h"

typedef struct tbArenaBlock
{
	void* memory;
	int bytes;
} tbArenaBlock;

typedef struct tbArena
{
	char* data;
	int capacity;	///< bytes in data
	int offset;		///< bytes handed out from data this step
	int needed;		///< bytes this step would have needed (data plus overflow): the next capacity
	/// Heap blocks of this step that did not fit, and their sizes.
	struct tbArenaBlock* overflow;
	int overflowCount, overflowCapacity;
} tbArena;

/// Release everything (the arena can be used again).
void tbArenaDestroy(tbArena* arena);

/// Start a step: forget this step's allocations, free the overflow blocks and grow the arena to
/// what the last step needed.
void tbArenaReset(tbArena* arena);

/// size bytes, 32-byte aligned, valid until the next reset. Never NULL for size >= 0.
void* tbArenaAlloc(tbArena* arena, int size);
