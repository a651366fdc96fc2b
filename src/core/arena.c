// The step arena (arena.h).
#include "arena.h"

#include "array.h"

#include <stddef.h>

#define TB_ARENA_ALIGNMENT 32

static int tbRoundUp(int size)
{
	return ((tbMaxInt(size, 1) - 1) | (TB_ARENA_ALIGNMENT - 1)) + 1;
}

static void tbFreeOverflow(tbArena* arena)
{
	for (int i = 0; i < arena->overflowCount; ++i)
	{
		tbFree(arena->overflow[i].memory, arena->overflow[i].bytes);
	}
	arena->overflowCount = 0;
}

void tbArenaDestroy(tbArena* arena)
{
	tbFreeOverflow(arena);
	TB_ARRAY_FREE(arena->overflow, arena->overflowCapacity);
	tbFree(arena->data, arena->capacity);
	arena->data = NULL;
	arena->capacity = 0;
	arena->offset = 0;
	arena->needed = 0;
}

void tbArenaReset(tbArena* arena)
{
	tbFreeOverflow(arena);
	if (arena->needed > arena->capacity)
	{
		// Grow by half again so that a scene whose needs creep up does not reallocate each step.
		int capacity = arena->needed + arena->needed / 2;
		tbFree(arena->data, arena->capacity);
		arena->data = tbAlloc(capacity);
		arena->capacity = capacity;
	}
	arena->offset = 0;
	arena->needed = 0;
}

void* tbArenaAlloc(tbArena* arena, int size)
{
	int bytes = tbRoundUp(size);
	arena->needed += bytes;
	if (arena->offset + bytes <= arena->capacity)
	{
		void* p = arena->data + arena->offset;
		arena->offset += bytes;
		return p;
	}
	// Does not fit: serve from the heap until the next reset grows the arena. The heap block is
	// at least 32-byte aligned too (tbAlloc aligns to 64).
	tbArenaBlock block = {tbAlloc(bytes), bytes};
	TB_ARRAY_PUSH(arena->overflow, arena->overflowCount, arena->overflowCapacity, block);
	return block.memory;
}
