// Internal: the broad phase, one interface over four methods (dynamic tree, sort-and-sweep,
// spatial hash, brute force). Each method lives in its own file with the same functions in the same order:
// dynamic_tree.c (the stand-alone tree, used here through tbBroadPhase), sort_and_sweep.c,
// spatial_hash.c, brute_force.c; broad_phase.c dispatches and builds the pair set.
//
// Contract (what makes trajectories identical under every method):
// - A proxy is a fat AABB plus category bits plus an int shape index (the world's shape id).
// - tbBroadPhase_UpdatePairs reports every pair of proxies whose fat boxes overlap and of which at
//   least one was created or moved since the last UpdatePairs, exactly once, as (shapeIndexA <
//   shapeIndexB), in increasing order of (shapeIndexA, shapeIndexB). The world then filters
//   (same body, static–static, category/mask/group, existing contact).
// - Static proxies (bodyType static) never pair with each other.
#pragma once

#include "brute_force.h"
#include "proxy_table.h"
#include "sort_and_sweep.h"
#include "spatial_hash.h"

#include "core/task.h"

#include "tumble/constants.h"
#include "tumble/types.h"

/// Bit set in every tree leaf of the broad phase so pair queries (mask = this bit) see all proxies
/// (broad_phase.c says why; a snapshot predicts a leaf's bits with it).
#define TB_PAIR_QUERY_BIT (UINT64_C(1) << 63)

typedef struct tbBroadPhase
{
	tbBroadPhaseMethod method; ///< resolved (never auto)

	// Proxy table indexed by proxy key: the broad phase owns its proxies' boxes, categories and
	// shape indices whatever the method; free slots are chained through their handle.
	tbProxyTable table;
	int freeProxy;

	// Keys of proxies created or moved since the last UpdatePairs.
	int* moveBuffer;
	int moveCount;
	int moveCapacity;

	// Pairs found by the last UpdatePairs (sorted, unique), with the optional pair filter.
	tbPairList pairList;
	// Pairs each worker found (tree method on workers), merged into pairList before the sort.
	tbPairList workerPairs[TB_MAX_WORKERS]; ///< per worker slot (tbWorkerSlotCount, task.h)

	// Method state. Only the selected method's state is live.
	tbDynamicTree staticTree;
	tbDynamicTree movableTree;
	tbSortAndSweep* sweep;
	tbSpatialHash* hash;
	tbBruteForce* brute;

	// Static proxies inserted into the static tree since its last rebuild (tree method): a bulk
	// of them triggers a binned SAH rebuild on the next UpdatePairs.
	int staticInsertCount;
	int enlargedCount; ///< movable tree leaves enlarged in place since the last UpdatePairs

	// The movable tree's refresh left for after the queries (tbBroadPhase_UpdatePairsOnWorkers with
	// deferRefresh; tbBroadPhase_FinishRefresh): a rebuild, or the re-insertion of these proxies.
	bool refreshPending;
	bool refreshRebuild;
	int* refreshKeys;
	int refreshKeyCount;
	int refreshKeyCapacity;
	/// Milliseconds spent refreshing the movable tree (re-insertion or rebuild) since the owner last
	/// cleared it: the world's profile.refit.
	float refitTime;
} tbBroadPhase;

/// Install a pair filter. The world drops pairs that already have a contact or may not collide
/// (a moving pile re-finds mostly existing pairs: filtering first keeps the sort small). The
/// filter must depend only on the two shapes, so the sorted result is the same as filtering after.
void tbBroadPhase_SetPairFilter(tbBroadPhase* bp, tbPairFilterFcn* filter, tbPairPrefetchFcn* prefetch, void* context);

/// Create with a method (auto resolves to the tree).
void tbBroadPhase_Create(tbBroadPhase* bp, tbBroadPhaseMethod method);
void tbBroadPhase_Destroy(tbBroadPhase* bp);

/// Switch method, rebuilding method state from the proxy table; every proxy counts as moved.
void tbBroadPhase_SetMethod(tbBroadPhase* bp, tbBroadPhaseMethod method);
/// Switch method, rebuilding method state from the proxy table, keeping the moved proxies as they
/// are: for a caller that keeps every pair found so far (the world's contacts), whose next update
/// then needs only the pairs of the proxies that moved since.
void tbBroadPhase_SwitchMethod(tbBroadPhase* bp, tbBroadPhaseMethod method);

/// Add a proxy with a fat AABB; returns its key. The proxy counts as moved.
int tbBroadPhase_CreateProxy(tbBroadPhase* bp, tbAABB fatAABB, uint64_t categoryBits, int shapeIndex, tbProxyType type);

/// The same, counted as moved only when `markMoved`: a proxy not counted is paired only once another
/// proxy overlapping it moves (tbShapeDef::invokeContactCreation false on a static shape).
int tbBroadPhase_CreateProxyMarked(tbBroadPhase* bp, tbAABB fatAABB, uint64_t categoryBits, int shapeIndex,
								   tbProxyType type, bool markMoved);
void tbBroadPhase_DestroyProxy(tbBroadPhase* bp, int proxyKey);

/// Replace a proxy's fat AABB; the proxy counts as moved.
void tbBroadPhase_MoveProxy(tbBroadPhase* bp, int proxyKey, tbAABB fatAABB);

/// Fill bp->pairList with the pair set described above and clear the move buffer.
void tbBroadPhase_UpdatePairs(tbBroadPhase* bp);

/// Runs task over items [0, itemCount) on up to workerCount workers and returns when all ran
/// (the world's tbParallelFor, handed in so that the broad phase needs no world).
typedef void tbRangeRunnerFcn(tbRangeTask* task, int itemCount, int minRange, void* taskContext,
							  void* runnerContext);

/// The same, the queries of moved proxies (tree and spatial hash) spread over workers (each worker
/// keeps its own pairs; the merged list is sorted, so the result does not depend on the split).
/// deferRefresh (tree method): the movable tree is queried as the moves left it (each moved leaf
/// already holds its new box and its ancestors were grown to contain it, so every query finds what
/// it would after the refresh) and its refresh, a serial rebuild or re-insertion, is left to
/// tbBroadPhase_FinishRefresh, which the caller runs while the workers do other work (the narrow
/// phase). The refreshed tree is the same either way: nothing it depends on changes in between.
/// slotCount: the worker indices the runner's tasks may see (tbWorkerSlotCount, task.h).
void tbBroadPhase_UpdatePairsOnWorkers(tbBroadPhase* bp, tbRangeRunnerFcn* run, void* runnerContext,
									   int workerCount, int slotCount, bool deferRefresh);
/// Whether a deferred refresh is waiting (tbBroadPhase_FinishRefresh).
static inline bool tbBroadPhase_RefreshPending(const tbBroadPhase* bp)
{
	return bp->refreshPending;
}
/// Runs the refresh UpdatePairsOnWorkers deferred, if any. Touches the movable tree only: the proxy
/// table (and so tbBroadPhase_TestOverlap) may be read meanwhile.
void tbBroadPhase_FinishRefresh(tbBroadPhase* bp);

/// At the end of a step, its proxies moved: the spatial hash rebuilds its stale grids now
/// rather than at the next update, so that queries and ray casts between steps look up cells (the
/// next update reuses them: the same work, done earlier). Nothing for the other methods.
void tbBroadPhase_Settle(tbBroadPhase* bp);

tbAABB tbBroadPhase_GetFatAABB(const tbBroadPhase* bp, int proxyKey);
static inline bool tbBroadPhase_TestOverlap(const tbBroadPhase* bp, int proxyKeyA, int proxyKeyB)
{
	// Inline: the narrow phase asks this for every contact every step.
	return tbAABB_Overlaps(bp->table.proxies[proxyKeyA].aabb, bp->table.proxies[proxyKeyB].aabb);
}

/// Visit proxies overlapping aabb whose category bits share a bit with maskBits (callback gets
/// proxy key and shape index; return false to stop).
tbTreeStats tbBroadPhase_Query(const tbBroadPhase* bp, tbAABB aabb, uint64_t maskBits, tbProxyQueryFcn* callback,
						void* context);

/// tbBroadPhase_Query restricted to static proxies (continuous collision of non-bullets, which
/// only stop at static geometry). The tree method walks the static tree alone; the others scan
/// their table and skip movable proxies. Same proxies, same order as Query's static part.
void tbBroadPhase_QueryStatic(const tbBroadPhase* bp, tbAABB aabb, uint64_t maskBits, tbProxyQueryFcn* callback,
							  void* context);

/// Ray cast over the proxies (callback as for the tree).
tbTreeStats tbBroadPhase_RayCast(const tbBroadPhase* bp, const tbRayCastInput* input, uint64_t maskBits,
						  tbProxyRayCastFcn* callback, void* context);

/// Height of the movable tree, or 0 for other methods.
int tbBroadPhase_GetTreeHeight(const tbBroadPhase* bp);
/// The static tree's height (tree method), else 0.
int tbBroadPhase_GetStaticTreeHeight(const tbBroadPhase* bp);
/// Rebuild the static tree from scratch (binned SAH) now; the tree method only (the others keep
/// no static tree).
void tbBroadPhase_RebuildStaticTree(tbBroadPhase* bp);

/// Debug drawing of the tree nodes (tree method only).
void tbBroadPhase_VisitTreeNodes(const tbBroadPhase* bp, tbTreeNodeFcn* fcn, void* context);

/// Checks internal consistency (tests). True when valid.
bool tbBroadPhase_Validate(const tbBroadPhase* bp);
