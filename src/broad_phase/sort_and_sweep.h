// Internal: the sort-and-sweep broad phase (sort_and_sweep.c). Same functions in the same order
// as brute_force.h.
#pragma once

#include "proxy_table.h"

typedef struct tbSortAndSweep tbSortAndSweep;

tbSortAndSweep* tbSortAndSweep_Create(void);
void tbSortAndSweep_Destroy(tbSortAndSweep* sweep);

/// Append the proxy's two endpoints (sorted on the next FindPairs).
void tbSortAndSweep_AddProxy(tbSortAndSweep* sweep, const tbProxyTable* table, int proxyKey);
/// Mark the proxy's endpoints dead (compacted on the next FindPairs).
void tbSortAndSweep_RemoveProxy(tbSortAndSweep* sweep, int proxyKey);

/// Re-sort the endpoints and append every overlapping pair with a moved member (not
/// static–static) through tbPairList_Add.
void tbSortAndSweep_FindPairs(tbSortAndSweep* sweep, const tbProxyTable* table, tbPairList* pairs);

/// Queries and ray casts scan the proxy table linearly (tbBruteForce_Query/RayCast): the sorted
/// endpoints would only prune one axis, and queries are rare next to pair updates.
void tbSortAndSweep_Query(const tbProxyTable* table, tbAABB aabb, uint64_t maskBits, tbProxyQueryFcn* callback,
						  void* context);
void tbSortAndSweep_RayCast(const tbProxyTable* table, const tbRayCastInput* input, uint64_t maskBits,
							tbProxyRayCastFcn* callback, void* context);

/// Endpoints sorted, two live endpoints per live proxy, values equal to the proxies' boxes.
bool tbSortAndSweep_Validate(const tbSortAndSweep* sweep, const tbProxyTable* table);
