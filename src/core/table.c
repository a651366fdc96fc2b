// Hash set of non-zero 64-bit keys: open addressing with linear probing and backward-shift
// deletion (no tombstones, so lookups stay short after many removals).
#include "table.h"

#include "core.h"

#include <string.h>

static uint32_t tbHashKey(uint64_t key)
{
	// 64-bit finaliser of MurmurHash3 (Appleby), folded to 32 bits.
	key ^= key >> 33;
	key *= 0xff51afd7ed558ccdULL;
	key ^= key >> 33;
	key *= 0xc4ceb9fe1a85ec53ULL;
	key ^= key >> 33;
	return (uint32_t)key;
}

void tbHashSet_Create(tbHashSet* set, int capacity)
{
	int c = 16;
	while (c < capacity)
	{
		c *= 2;
	}
	set->capacity = c;
	set->count = 0;
	set->keys = tbAlloc(c * (int)sizeof(uint64_t));
	memset(set->keys, 0, (size_t)c * sizeof(uint64_t));
}

void tbHashSet_Destroy(tbHashSet* set)
{
	tbFree(set->keys, set->capacity * (int)sizeof(uint64_t));
	set->keys = NULL;
	set->capacity = 0;
	set->count = 0;
}

static int tbFindSlot(const tbHashSet* set, uint64_t key)
{
	uint32_t mask = (uint32_t)set->capacity - 1;
	uint32_t i = tbHashKey(key) & mask;
	while (set->keys[i] != 0 && set->keys[i] != key)
	{
		i = (i + 1) & mask;
	}
	return (int)i;
}

static void tbGrowSet(tbHashSet* set)
{
	tbHashSet bigger;
	tbHashSet_Create(&bigger, 2 * set->capacity);
	for (int i = 0; i < set->capacity; ++i)
	{
		if (set->keys[i] != 0)
		{
			bigger.keys[tbFindSlot(&bigger, set->keys[i])] = set->keys[i];
			bigger.count += 1;
		}
	}
	tbHashSet_Destroy(set);
	*set = bigger;
}

bool tbHashSet_Add(tbHashSet* set, uint64_t key)
{
	TB_ASSERT(key != 0);
	if (2 * (set->count + 1) > set->capacity)
	{
		tbGrowSet(set);
	}
	int i = tbFindSlot(set, key);
	if (set->keys[i] == key)
	{
		return true;
	}
	set->keys[i] = key;
	set->count += 1;
	return false;
}

bool tbHashSet_Contains(const tbHashSet* set, uint64_t key)
{
	return set->keys[tbFindSlot(set, key)] == key;
}

void tbHashSet_Prefetch(const tbHashSet* set, uint64_t key)
{
	tbPrefetch(set->keys + (tbHashKey(key) & ((uint32_t)set->capacity - 1)), (int)sizeof(uint64_t));
}

bool tbHashSet_Remove(tbHashSet* set, uint64_t key)
{
	int i = tbFindSlot(set, key);
	if (set->keys[i] != key)
	{
		return false;
	}
	// Backward-shift: move later entries of the probe run into the hole when their home slot
	// is at or before the hole (cyclically).
	uint32_t mask = (uint32_t)set->capacity - 1;
	uint32_t hole = (uint32_t)i;
	uint32_t j = hole;
	for (;;)
	{
		j = (j + 1) & mask;
		if (set->keys[j] == 0)
		{
			break;
		}
		uint32_t home = tbHashKey(set->keys[j]) & mask;
		bool movable = ((j - home) & mask) >= ((j - hole) & mask);
		if (movable)
		{
			set->keys[hole] = set->keys[j];
			hole = j;
		}
	}
	set->keys[hole] = 0;
	set->count -= 1;
	return true;
}
