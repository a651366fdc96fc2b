// Internal: a hash set of 64-bit keys (open addressing, linear probing) for the pair set.
#pragma once

#include <stdbool.h>
#include <stdint.h>

typedef struct tbHashSet
{
	uint64_t* keys; ///< 0 marks an empty slot, so keys must be non-zero
	int capacity;	///< power of two
	int count;
} tbHashSet;

void tbHashSet_Create(tbHashSet* set, int capacity);
void tbHashSet_Destroy(tbHashSet* set);
/// Returns true if the key was already present.
bool tbHashSet_Add(tbHashSet* set, uint64_t key);
/// Returns true if the key was present.
bool tbHashSet_Remove(tbHashSet* set, uint64_t key);
bool tbHashSet_Contains(const tbHashSet* set, uint64_t key);
/// Ask for the slot where a lookup of key starts (a hint; nothing changes).
void tbHashSet_Prefetch(const tbHashSet* set, uint64_t key);

/// Pair key of two shape ids, order-independent and never zero.
static inline uint64_t tbShapePairKey(int a, int b)
{
	uint64_t lo = (uint64_t)(uint32_t)(a < b ? a : b);
	uint64_t hi = (uint64_t)(uint32_t)(a < b ? b : a);
	return ((hi + 1) << 32) | lo;
}
