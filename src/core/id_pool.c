// The id pool of every object kind (id_pool.h).
#include "id_pool.h"

#include "array.h"

int tbIdPool_Alloc(tbIdPool* pool, bool* isNew)
{
	pool->count += 1;
	if (pool->freeCount > 0)
	{
		*isNew = false;
		return pool->freeIds[--pool->freeCount];
	}
	*isNew = true;
	return pool->highWater++;
}

void tbIdPool_Free(tbIdPool* pool, int id)
{
	TB_ARRAY_PUSH(pool->freeIds, pool->freeCount, pool->freeCapacity, id);
	pool->count -= 1;
}

void tbIdPool_Destroy(tbIdPool* pool)
{
	TB_ARRAY_FREE(pool->freeIds, pool->freeCapacity);
	pool->freeCount = 0;
	pool->highWater = 0;
	pool->count = 0;
}

int tbIdPool_ByteCount(const tbIdPool* pool)
{
	return pool->freeCapacity * (int)sizeof(int);
}
