// Internal: small integer ids for the objects of a world (bodies, shapes, contacts, joints,
// chains). An object lives in slot `id` of its kind's array; a freed id is handed out again before
// a new one, most recently freed first, so the arrays stay dense and a world that creates and
// destroys objects in the same order reuses the same slots (the results depend on ids: contacts are
// collided and solved in id order). The pool knows only the ids; the caller grows its array when an
// id is new and keeps a generation per slot to refuse stale handles.
#pragma once

#include <stdbool.h>

typedef struct tbIdPool
{
	int* freeIds; ///< freed ids, the next one to reuse last
	int freeCount, freeCapacity;
	int highWater; ///< ids handed out so far: every id in use is below it
	int count;	   ///< ids in use
} tbIdPool;

/// Take an id: the most recently freed one, else highWater (then *isNew is set: the caller's array
/// must grow to highWater entries and the slot be initialised).
int tbIdPool_Alloc(tbIdPool* pool, bool* isNew);

/// Give an id back (it must be in use).
void tbIdPool_Free(tbIdPool* pool, int id);

/// Release the free list (the world is being destroyed).
void tbIdPool_Destroy(tbIdPool* pool);

/// Bytes the pool holds.
int tbIdPool_ByteCount(const tbIdPool* pool);
