// Internal: the spatial-hash broad phase (spatial_hash.c), a uniform grid hashed into buckets.
// Same functions in the same order as sort_and_sweep.h, plus the static-only query continuous
// collision uses.
#pragma once

#include "proxy_table.h"

typedef struct tbSpatialHash tbSpatialHash;

tbSpatialHash* tbSpatialHash_Create(void);
void tbSpatialHash_Destroy(tbSpatialHash* hash);

/// A static proxy added, removed or moved makes the static grid be rebuilt on the next FindPairs;
/// a movable proxy added or removed, the movable grid.
void tbSpatialHash_AddProxy(tbSpatialHash* hash, const tbProxyTable* table, int proxyKey);
void tbSpatialHash_RemoveProxy(tbSpatialHash* hash, const tbProxyTable* table, int proxyKey);
void tbSpatialHash_MoveStaticProxy(tbSpatialHash* hash);

/// Hash the proxies and append every overlapping pair with a moved member (not static–static)
/// through tbPairList_Add.
void tbSpatialHash_FindPairs(tbSpatialHash* hash, const tbProxyTable* table, tbPairList* pairs);
/// FindPairs in two parts, for workers: hash the proxies (serial), then the queries of moved
/// proxies, each appending to its own list (read-only on the grids: several may run at once).
void tbSpatialHash_PrepareFind(tbSpatialHash* hash, const tbProxyTable* table);
void tbSpatialHash_QueryMoved(const tbSpatialHash* hash, const tbProxyTable* table, tbPairList* pairs, int proxyKey);

/// At the end of a step, its proxies moved (tbBroadPhase_Settle): the grids rebuilt where stale, so
/// that queries between steps look up cells and the next update reuses them.
void tbSpatialHash_Refresh(tbSpatialHash* hash, const tbProxyTable* table);
/// A movable proxy moved: the movable grid is stale until the next update or refresh, which files
/// the moved proxies again (or builds the grid afresh when many moved).
void tbSpatialHash_MoveMovableProxy(tbSpatialHash* hash, int proxyKey);

/// Queries: each grid looked up when it is current (a grid holds every proxy of its kind where its
/// box is now), the table scanned for a kind whose grid is not.
void tbSpatialHash_Query(const tbSpatialHash* hash, const tbProxyTable* table, tbAABB aabb, uint64_t maskBits,
						 bool staticOnly, tbProxyQueryFcn* callback, void* context);
/// A ray cast through the cells of both grids when both are current and the ray crosses fewer cells
/// than there are proxies; false (nothing done) otherwise, and the caller scans the table.
bool tbSpatialHash_RayCast(const tbSpatialHash* hash, const tbProxyTable* table, const tbRayCastInput* input,
						   uint64_t maskBits, tbProxyRayCastFcn* callback, void* context);

/// What a spatial hash carries from one update to the next besides the proxy table (a world's
/// snapshot stores it): the cell size, whether the static grid must be rebuilt, and the update
/// count that times the cell size's re-check. The grids themselves follow from these and the table.
typedef struct tbSpatialHashState
{
	float cellSize; ///< 0 before the first update
	bool staticDirty;
	int updateCount;
} tbSpatialHashState;

tbSpatialHashState tbSpatialHash_GetState(const tbSpatialHash* hash);
/// Take a state (a restored snapshot's): a current static grid is built again from the table, the
/// same grid, since it depends only on the cell size and the static proxies.
void tbSpatialHash_SetState(tbSpatialHash* hash, const tbProxyTable* table, tbSpatialHashState state);

/// The static grid, when current, holds every small static proxy in every cell its box covers.
bool tbSpatialHash_Validate(const tbSpatialHash* hash, const tbProxyTable* table);
