// Internal: the brute-force broad phase (brute_force.c), O(n²) all pairs, the ground truth the
// other methods are tested against. Same functions in the same order as sort_and_sweep.h.
#pragma once

#include "proxy_table.h"

typedef struct tbBruteForce tbBruteForce;

tbBruteForce* tbBruteForce_Create(void);
void tbBruteForce_Destroy(tbBruteForce* brute);

/// Brute force keeps no per-proxy state: adding and removing are no-ops kept for symmetry.
void tbBruteForce_AddProxy(tbBruteForce* brute, const tbProxyTable* table, int proxyKey);
void tbBruteForce_RemoveProxy(tbBruteForce* brute, int proxyKey);

/// Append every overlapping pair with a moved member (not static–static) through tbPairList_Add.
void tbBruteForce_FindPairs(tbBruteForce* brute, const tbProxyTable* table, tbPairList* pairs);

/// Linear scans over the proxy table (also used by sort-and-sweep). Callbacks get the proxy key
/// and the shape index.
void tbBruteForce_Query(const tbProxyTable* table, tbAABB aabb, uint64_t maskBits, tbProxyQueryFcn* callback,
						void* context);
void tbBruteForce_RayCast(const tbProxyTable* table, const tbRayCastInput* input, uint64_t maskBits,
						  tbProxyRayCastFcn* callback, void* context);

/// Whether the segment p + t·d, 0 ≤ t ≤ maxFraction, meets the box (slab test).
bool tbSegmentHitsBox(tbVec2 p, tbVec2 d, float maxFraction, tbAABB box);

bool tbBruteForce_Validate(const tbBruteForce* brute, const tbProxyTable* table);
