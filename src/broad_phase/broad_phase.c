// Broad phase: the proxy table, the move buffer and the pair set, dispatching to one of four
// methods (dynamic tree, sort-and-sweep, spatial hash, brute force). See broad_phase.h for the contract; the
// pair set is the same under every method, so switching methods never changes a trajectory.
//
// Tree method: static proxies live in a static tree and movable ones in a movable tree, so the
// many static boxes of a level are never re-inserted and a moved static proxy queries only the
// movable tree (static–static pairs never exist). A batch of static inserts triggers one binned
// SAH rebuild of the static tree on the next UpdatePairs (a top-down build gives a better tree
// than incremental insertion, at O(n log n) once).
//
// Pair set: each moved proxy queries with its fat box. When both proxies of a pair moved, each
// finds the other; the one with the larger key skips it. UpdatePairs then sorts the pairs by
// (shapeIndexA, shapeIndexB) and drops duplicates, which makes the set independent of the method
// and of the order of the moves.
//
// Category bits: the broad phase does not filter pairs (the world does), but the trees prune
// user queries by mask. To let pair queries see proxies whose category bits are zero, the trees
// store categoryBits | TB_PAIR_QUERY_BIT and pair queries use that bit as their mask; user
// queries re-check the proxy's true bits before calling back.

#include "broad_phase.h"

#include "brute_force.h"
#include "collision/dynamic_tree_node.h"
#include "core/core.h"
#include "core/array.h"
#include "sort_and_sweep.h"
#include "spatial_hash.h"

#include <stdlib.h>
#include <string.h>

/// Static inserts since the last rebuild that trigger a static-tree rebuild: at least 16 and at
/// least half the static tree (a rebuild is O(n log n); small trickles are inserted one by one).
#define TB_STATIC_REBUILD_MIN 16

static tbDynamicTree* tbTreeOf(tbBroadPhase* bp, const tbBroadProxy* proxy)
{
	return proxy->type == tb_proxyStatic ? &bp->staticTree : &bp->movableTree;
}

// --------------------------------------------------------------------------------------------
// Method state

static void tbAddToMethod(tbBroadPhase* bp, int key)
{
	tbBroadProxy* p = bp->table.proxies + key;
	switch (bp->method)
	{
		case tb_broadPhaseTree:
			p->handle = tbDynamicTree_CreateProxy(tbTreeOf(bp, p), p->aabb, p->categoryBits | TB_PAIR_QUERY_BIT, (uint64_t)key);
			bp->staticInsertCount += p->type == tb_proxyStatic ? 1 : 0;
			break;
		case tb_broadPhaseSortAndSweep:
			tbSortAndSweep_AddProxy(bp->sweep, &bp->table, key);
			break;
		case tb_broadPhaseSpatialHash:
			tbSpatialHash_AddProxy(bp->hash, &bp->table, key);
			break;
		default:
			tbBruteForce_AddProxy(bp->brute, &bp->table, key);
			break;
	}
}

static void tbRemoveFromMethod(tbBroadPhase* bp, int key)
{
	tbBroadProxy* p = bp->table.proxies + key;
	switch (bp->method)
	{
		case tb_broadPhaseTree:
			tbDynamicTree_DestroyProxy(tbTreeOf(bp, p), p->handle);
			break;
		case tb_broadPhaseSortAndSweep:
			tbSortAndSweep_RemoveProxy(bp->sweep, key);
			break;
		case tb_broadPhaseSpatialHash:
			tbSpatialHash_RemoveProxy(bp->hash, &bp->table, key);
			break;
		default:
			tbBruteForce_RemoveProxy(bp->brute, key);
			break;
	}
	p->handle = -1;
}

/// Both trees built from every proxy of the table at once (a switch to the tree method): each
/// proxy's leaf made, then each tree built top down, as the static tree is after a batch of
/// inserts. Inserting a pile of 1,000 bodies leaf by leaf cost more than a step of the pile.
static void tbLoadTrees(tbBroadPhase* bp)
{
	for (int key = 0; key < bp->table.capacity; ++key)
	{
		tbBroadProxy* p = bp->table.proxies + key;
		if (p->isFree == false)
		{
			p->handle = tbDynamicTree_CreateProxyDeferred(tbTreeOf(bp, p), p->aabb, p->categoryBits | TB_PAIR_QUERY_BIT,
														  (uint64_t)key);
		}
	}
	tbDynamicTree_Rebuild(&bp->staticTree, true);
	tbDynamicTree_Rebuild(&bp->movableTree, true);
}

/// Build the selected method's state from the proxy table.
static void tbCreateMethodState(tbBroadPhase* bp)
{
	bp->staticTree = tbDynamicTree_Create(0);
	bp->movableTree = tbDynamicTree_Create(0);
	bp->movableTree.rebuildSplit = tb_splitMidpoint;
	bp->sweep = bp->method == tb_broadPhaseSortAndSweep ? tbSortAndSweep_Create() : NULL;
	bp->brute = bp->method == tb_broadPhaseBruteForce ? tbBruteForce_Create() : NULL;
	bp->hash = bp->method == tb_broadPhaseSpatialHash ? tbSpatialHash_Create() : NULL;
	bp->staticInsertCount = 0;
	bp->enlargedCount = 0;
	if (bp->method == tb_broadPhaseTree)
	{
		tbLoadTrees(bp);
		return;
	}
	for (int key = 0; key < bp->table.capacity; ++key)
	{
		if (bp->table.proxies[key].isFree == false)
		{
			tbAddToMethod(bp, key);
		}
	}
}

static void tbDestroyMethodState(tbBroadPhase* bp)
{
	bp->refreshPending = false; // a refresh of a tree that is gone
	tbDynamicTree_Destroy(&bp->staticTree);
	tbDynamicTree_Destroy(&bp->movableTree);
	if (bp->sweep != NULL)
	{
		tbSortAndSweep_Destroy(bp->sweep);
		bp->sweep = NULL;
	}
	if (bp->hash != NULL)
	{
		tbSpatialHash_Destroy(bp->hash);
		bp->hash = NULL;
	}
	if (bp->brute != NULL)
	{
		tbBruteForce_Destroy(bp->brute);
		bp->brute = NULL;
	}
}

static tbBroadPhaseMethod tbResolveMethod(tbBroadPhaseMethod method)
{
	if (method <= tb_broadPhaseAuto || method >= tb_broadPhaseMethodCount)
	{
		return tb_broadPhaseTree;
	}
	return method;
}

// --------------------------------------------------------------------------------------------
// Lifetime

void tbBroadPhase_Create(tbBroadPhase* bp, tbBroadPhaseMethod method)
{
	memset(bp, 0, sizeof(*bp));
	bp->method = tbResolveMethod(method);
	bp->freeProxy = -1;
	tbCreateMethodState(bp);
}

void tbBroadPhase_Destroy(tbBroadPhase* bp)
{
	tbDestroyMethodState(bp);
	tbFree(bp->table.proxies, bp->table.capacity * (int)sizeof(tbBroadProxy));
	tbFree(bp->moveBuffer, bp->moveCapacity * (int)sizeof(int));
	tbPairList_Destroy(&bp->pairList);
	for (int i = 0; i < TB_MAX_WORKERS; ++i)
	{
		tbPairList_Destroy(bp->workerPairs + i);
	}
	tbFree(bp->refreshKeys, bp->refreshKeyCapacity * (int)sizeof(int));
	memset(bp, 0, sizeof(*bp));
	bp->freeProxy = -1;
}

/// Put a proxy in the move buffer unless it is there already.
static void tbMarkMoved(tbBroadPhase* bp, int key)
{
	tbBroadProxy* p = bp->table.proxies + key;
	if (p->moveIndex >= 0)
	{
		return;
	}
	if (bp->moveCount == bp->moveCapacity)
	{
		int n = bp->moveCapacity;
		int m = tbMaxInt(16, 2 * n);
		bp->moveBuffer = tbGrowAlloc(bp->moveBuffer, n * (int)sizeof(int), m * (int)sizeof(int));
		bp->moveCapacity = m;
	}
	p->moveIndex = bp->moveCount;
	bp->moveBuffer[bp->moveCount++] = key;
}

static void tbClearMoveBuffer(tbBroadPhase* bp)
{
	for (int i = 0; i < bp->moveCount; ++i)
	{
		int key = bp->moveBuffer[i];
		if (key >= 0)
		{
			bp->table.proxies[key].moveIndex = -1;
		}
	}
	bp->moveCount = 0;
}

void tbBroadPhase_SwitchMethod(tbBroadPhase* bp, tbBroadPhaseMethod method)
{
	tbDestroyMethodState(bp);
	bp->method = tbResolveMethod(method);
	tbCreateMethodState(bp);
}

void tbBroadPhase_SetMethod(tbBroadPhase* bp, tbBroadPhaseMethod method)
{
	tbBroadPhase_SwitchMethod(bp, method);
	tbClearMoveBuffer(bp);
	for (int key = 0; key < bp->table.capacity; ++key)
	{
		if (bp->table.proxies[key].isFree == false)
		{
			tbMarkMoved(bp, key);
		}
	}
}

// --------------------------------------------------------------------------------------------
// Proxies

/// Take a slot from the free list, doubling the table when empty.
static int tbAllocateProxy(tbBroadPhase* bp)
{
	if (bp->freeProxy < 0)
	{
		int n = bp->table.capacity;
		int m = tbMaxInt(16, 2 * n);
		bp->table.proxies = tbGrowAlloc(bp->table.proxies, n * (int)sizeof(tbBroadProxy), m * (int)sizeof(tbBroadProxy));
		for (int i = n; i < m; ++i)
		{
			bp->table.proxies[i] = (tbBroadProxy){.handle = i + 1 < m ? i + 1 : -1, .moveIndex = -1, .isFree = true};
		}
		bp->freeProxy = n;
		bp->table.capacity = m;
	}
	int key = bp->freeProxy;
	bp->freeProxy = bp->table.proxies[key].handle;
	return key;
}

int tbBroadPhase_CreateProxy(tbBroadPhase* bp, tbAABB fatAABB, uint64_t categoryBits, int shapeIndex, tbProxyType type)
{
	return tbBroadPhase_CreateProxyMarked(bp, fatAABB, categoryBits, shapeIndex, type, true);
}

int tbBroadPhase_CreateProxyMarked(tbBroadPhase* bp, tbAABB fatAABB, uint64_t categoryBits, int shapeIndex,
								   tbProxyType type, bool markMoved)
{
	int key = tbAllocateProxy(bp);
	bp->table.proxies[key] = (tbBroadProxy){fatAABB, categoryBits, shapeIndex, type, -1, -1, false};
	bp->table.count += 1;
	tbAddToMethod(bp, key);
	if (markMoved)
	{
		tbMarkMoved(bp, key);
	}
	return key;
}

void tbBroadPhase_DestroyProxy(tbBroadPhase* bp, int proxyKey)
{
	TB_ASSERT(0 <= proxyKey && proxyKey < bp->table.capacity && bp->table.proxies[proxyKey].isFree == false);
	tbBroadProxy* p = bp->table.proxies + proxyKey;
	tbRemoveFromMethod(bp, proxyKey);
	if (p->moveIndex >= 0)
	{
		bp->moveBuffer[p->moveIndex] = -1;
		// Trailing holes are dropped, so that creating and destroying between steps (a proxy is
		// buffered when created) does not grow the buffer until the next step clears it.
		while (bp->moveCount > 0 && bp->moveBuffer[bp->moveCount - 1] == -1)
		{
			bp->moveCount -= 1;
		}
	}
	*p = (tbBroadProxy){.handle = bp->freeProxy, .moveIndex = -1, .isFree = true};
	bp->freeProxy = proxyKey;
	bp->table.count -= 1;
}

void tbBroadPhase_MoveProxy(tbBroadPhase* bp, int proxyKey, tbAABB fatAABB)
{
	TB_ASSERT(0 <= proxyKey && proxyKey < bp->table.capacity && bp->table.proxies[proxyKey].isFree == false);
	tbBroadProxy* p = bp->table.proxies + proxyKey;
	p->aabb = fatAABB;
	if (bp->method == tb_broadPhaseTree && p->type == tb_proxyStatic)
	{
		tbDynamicTree_MoveProxy(&bp->staticTree, p->handle, fatAABB);
	}
	else if (bp->method == tb_broadPhaseTree)
	{
		// Enlarge in place now; tbRefreshMovableTree re-inserts or rebuilds before pairs are found.
		tbDynamicTree_EnlargeProxy(&bp->movableTree, p->handle, fatAABB);
		bp->enlargedCount += 1;
	}
	else if (bp->method == tb_broadPhaseSpatialHash && p->type == tb_proxyStatic)
	{
		tbSpatialHash_MoveStaticProxy(bp->hash);
	}
	else if (bp->method == tb_broadPhaseSpatialHash)
	{
		tbSpatialHash_MoveMovableProxy(bp->hash, proxyKey);
	}
	// Sort-and-sweep reloads endpoint values from the table; brute force reads the table; the
	// spatial hash files the moved proxies again (tbBroadPhase_Settle or the next update).
	tbMarkMoved(bp, proxyKey);
}

tbAABB tbBroadPhase_GetFatAABB(const tbBroadPhase* bp, int proxyKey)
{
	TB_ASSERT(0 <= proxyKey && proxyKey < bp->table.capacity);
	return bp->table.proxies[proxyKey].aabb;
}

void tbBroadPhase_SetPairFilter(tbBroadPhase* bp, tbPairFilterFcn* filter, tbPairPrefetchFcn* prefetch, void* context)
{
	bp->pairList.filter = filter;
	bp->pairList.prefetch = prefetch;
	bp->pairList.filterContext = context;
}


// --------------------------------------------------------------------------------------------
// Pairs

static int tbComparePairs(const void* left, const void* right)
{
	const tbShapePair* p = left;
	const tbShapePair* q = right;
	if (p->a != q->a)
	{
		return p->a < q->a ? -1 : 1;
	}
	return p->b < q->b ? -1 : (p->b > q->b ? 1 : 0);
}

/// Sort by (a, b) and drop repeats.
static void tbSortUniquePairs(tbBroadPhase* bp)
{
	if (bp->pairList.count < 2)
	{
		return;
	}
	qsort(bp->pairList.pairs, (size_t)bp->pairList.count, sizeof(tbShapePair), tbComparePairs);
	int n = 1;
	for (int i = 1; i < bp->pairList.count; ++i)
	{
		tbShapePair p = bp->pairList.pairs[i];
		if (p.a != bp->pairList.pairs[n - 1].a || p.b != bp->pairList.pairs[n - 1].b)
		{
			bp->pairList.pairs[n++] = p;
		}
	}
	bp->pairList.count = n;
}

typedef struct tbPairQueryContext
{
	tbBroadPhase* bp;
	tbPairList* list; ///< where this query's pairs go
	int queryKey;
} tbPairQueryContext;

static bool tbPairQueryCallback(int treeProxyId, uint64_t userData, void* context)
{
	(void)treeProxyId;
	int otherKey = (int)userData; // the tree's user data is the proxy key
	tbPairQueryContext* c = context;
	if (otherKey == c->queryKey)
	{
		return true;
	}
	// Both moved: both queries find the pair; the larger key reports it.
	if (c->bp->table.proxies[otherKey].moveIndex >= 0 && otherKey > c->queryKey)
	{
		return true;
	}
	tbPairList_Add(c->list, &c->bp->table, c->queryKey, otherKey);
	return true;
}

/// Moved movable proxies were enlarged in place (their ancestors only grew). When many moved, a
/// partial rebuild of the movable tree above the subtrees that hold none of them is cheaper than
/// re-inserting each (a branch-and-bound sibling search and rotations per proxy); when few moved,
/// re-insert those. Threshold: 1/16 of the movable proxies. Re-inserting k moved leaves costs k
/// searches down the tree and rotations up it, each O(log n) with a cache miss per level; the
/// partial rebuild sorts about k·log n items (the moved leaves and the unmoved subtrees beside
/// their paths) in passes over arrays, so it wins once k is a fair share of n, as in a tumbling
/// pile, where re-insertion was the dearest part of the step (docs/performance.md). The movable
/// tree is split at the spatial median, not by the binned SAH: one partition pass per level
/// against the SAH's three (dynamic_tree.c), for a tree rebuilt every step, at the price of
/// slightly looser nodes.
static void tbRefreshMovableTree(tbBroadPhase* bp)
{
	int movable = bp->movableTree.proxyCount;
	if (bp->enlargedCount == 0)
	{
		return;
	}
	uint64_t ticks = tbGetTicks();
	if (16 * bp->enlargedCount > movable)
	{
		tbDynamicTree_Rebuild(&bp->movableTree, false);
	}
	else
	{
		for (int i = 0; i < bp->moveCount; ++i)
		{
			int key = bp->moveBuffer[i];
			if (key >= 0 && bp->table.proxies[key].type != tb_proxyStatic)
			{
				tbDynamicTree_MoveProxy(&bp->movableTree, bp->table.proxies[key].handle, bp->table.proxies[key].aabb);
			}
		}
	}
	bp->enlargedCount = 0;
	bp->refitTime += tbGetMilliseconds(ticks);
}

/// tbRefreshMovableTree's choice made now and its work left for tbBroadPhase_FinishRefresh: the
/// keys to re-insert are copied, since the move buffer is cleared before the refresh runs.
static void tbDeferMovableRefresh(tbBroadPhase* bp)
{
	if (bp->enlargedCount == 0)
	{
		return;
	}
	bp->refreshPending = true;
	bp->refreshRebuild = 16 * bp->enlargedCount > bp->movableTree.proxyCount;
	bp->refreshKeyCount = 0;
	if (bp->refreshRebuild == false)
	{
		TB_ARRAY_RESERVE(bp->refreshKeys, bp->refreshKeyCapacity, bp->moveCount);
		for (int i = 0; i < bp->moveCount; ++i)
		{
			int key = bp->moveBuffer[i];
			if (key >= 0 && bp->table.proxies[key].type != tb_proxyStatic)
			{
				bp->refreshKeys[bp->refreshKeyCount++] = key;
			}
		}
	}
	bp->enlargedCount = 0;
}

void tbBroadPhase_Settle(tbBroadPhase* bp)
{
	if (bp->method == tb_broadPhaseSpatialHash)
	{
		tbSpatialHash_Refresh(bp->hash, &bp->table);
	}
}

void tbBroadPhase_FinishRefresh(tbBroadPhase* bp)
{
	if (bp->refreshPending == false)
	{
		return;
	}
	bp->refreshPending = false;
	uint64_t ticks = tbGetTicks();
	if (bp->refreshRebuild)
	{
		tbDynamicTree_Rebuild(&bp->movableTree, false);
	}
	else
	{
		for (int i = 0; i < bp->refreshKeyCount; ++i)
		{
			const tbBroadProxy* p = bp->table.proxies + bp->refreshKeys[i];
			tbDynamicTree_MoveProxy(&bp->movableTree, p->handle, p->aabb);
		}
	}
	bp->refitTime += tbGetMilliseconds(ticks);
}

/// The pairs of moved proxies [start, end) of the move buffer, appended to `list` (read-only on
/// the trees and the table: several ranges may run at once).
static void tbQueryMovedProxies(tbBroadPhase* bp, tbPairList* list, int start, int end)
{
	for (int i = start; i < end; ++i)
	{
		int key = bp->moveBuffer[i];
		if (key < 0)
		{
			continue; // destroyed after it moved
		}
		const tbBroadProxy* p = bp->table.proxies + key;
		tbPairQueryContext context = {bp, list, key};
		tbDynamicTree_Query(&bp->movableTree, p->aabb, TB_PAIR_QUERY_BIT, tbPairQueryCallback, &context);
		if (p->type != tb_proxyStatic)
		{
			tbDynamicTree_Query(&bp->staticTree, p->aabb, TB_PAIR_QUERY_BIT, tbPairQueryCallback, &context);
		}
	}
}

/// The trees brought up to date before they are queried (serial: they change); the movable
/// tree's refresh may be deferred until after the queries (tbBroadPhase_FinishRefresh).
static void tbPrepareTrees(tbBroadPhase* bp, bool deferRefresh)
{
	tbBroadPhase_FinishRefresh(bp); // one left from an earlier call, if the caller never ran it
	if (deferRefresh)
	{
		tbDeferMovableRefresh(bp);
	}
	else
	{
		tbRefreshMovableTree(bp);
	}
	int staticCount = bp->staticTree.proxyCount;
	if (bp->staticInsertCount >= TB_STATIC_REBUILD_MIN && 2 * bp->staticInsertCount >= staticCount)
	{
		tbDynamicTree_Rebuild(&bp->staticTree, true);
		bp->staticInsertCount = 0;
	}
}

static void tbTreeFindPairs(tbBroadPhase* bp)
{
	tbPrepareTrees(bp, false);
	tbQueryMovedProxies(bp, &bp->pairList, 0, bp->moveCount);
}

static void tbFindPairsTask(int start, int end, uint32_t workerIndex, void* context)
{
	tbBroadPhase* bp = context;
	if (bp->method == tb_broadPhaseSpatialHash)
	{
		for (int i = start; i < end; ++i)
		{
			int key = bp->moveBuffer[i];
			if (key >= 0)
			{
				tbSpatialHash_QueryMoved(bp->hash, &bp->table, bp->workerPairs + workerIndex, key);
			}
		}
	}
	else
	{
		tbQueryMovedProxies(bp, bp->workerPairs + workerIndex, start, end);
	}
	tbPairList_Flush(bp->workerPairs + workerIndex);
}

void tbBroadPhase_UpdatePairsOnWorkers(tbBroadPhase* bp, tbRangeRunnerFcn* run, void* runnerContext, int workerCount,
									   int slotCount, bool deferRefresh)
{
	bool tree = bp->method == tb_broadPhaseTree;
	if ((tree == false && bp->method != tb_broadPhaseSpatialHash) || workerCount <= 1)
	{
		tbBroadPhase_UpdatePairs(bp);
		return;
	}
	bp->pairList.count = 0;
	if (tree)
	{
		tbPrepareTrees(bp, deferRefresh);
	}
	else
	{
		tbSpatialHash_PrepareFind(bp->hash, &bp->table);
	}
	for (int w = 0; w < slotCount; ++w)
	{
		bp->workerPairs[w].count = 0;
		bp->workerPairs[w].filter = bp->pairList.filter;
		bp->workerPairs[w].prefetch = bp->pairList.prefetch;
		bp->workerPairs[w].filterContext = bp->pairList.filterContext;
		bp->workerPairs[w].pendingCount = 0;
	}
	run(tbFindPairsTask, bp->moveCount, 64, bp, runnerContext);
	for (int w = 0; w < slotCount; ++w)
	{
		const tbPairList* list = bp->workerPairs + w;
		for (int i = 0; i < list->count; ++i)
		{
			tbPairList_Append(&bp->pairList, list->pairs[i]);
		}
	}
	tbSortUniquePairs(bp);
	tbClearMoveBuffer(bp);
}

void tbBroadPhase_UpdatePairs(tbBroadPhase* bp)
{
	bp->pairList.count = 0;
	switch (bp->method)
	{
		case tb_broadPhaseTree:
			tbTreeFindPairs(bp);
			break;
		case tb_broadPhaseSortAndSweep:
			tbSortAndSweep_FindPairs(bp->sweep, &bp->table, &bp->pairList);
			break;
		case tb_broadPhaseSpatialHash:
			// The moved proxies from the move buffer, not a scan of the table: the pairs are sorted
			// below, so the order of the queries does not show.
			tbSpatialHash_PrepareFind(bp->hash, &bp->table);
			for (int i = 0; i < bp->moveCount; ++i)
			{
				if (bp->moveBuffer[i] >= 0)
				{
					tbSpatialHash_QueryMoved(bp->hash, &bp->table, &bp->pairList, bp->moveBuffer[i]);
				}
			}
			break;
		default:
			tbBruteForce_FindPairs(bp->brute, &bp->table, &bp->pairList);
			break;
	}
	tbPairList_Flush(&bp->pairList);
	tbSortUniquePairs(bp);
	tbClearMoveBuffer(bp);
}

// --------------------------------------------------------------------------------------------
// Queries (the tree prunes; the spatial hash looks up the cells of current grids; sort-and-sweep and
// brute force scan the table)

/// Translates tree callbacks (tree id, proxy key) into broad-phase ones (proxy key, shape index),
/// re-checks the true category bits, and carries stop and clip across the two trees.
typedef struct tbUserQueryContext
{
	const tbBroadPhase* bp;
	uint64_t maskBits;
	tbProxyQueryFcn* queryCallback;
	tbProxyRayCastFcn* rayCallback;
	void* userContext;
	float maxFraction;
	bool stopped;
} tbUserQueryContext;

static bool tbUserQueryCallback(int treeProxyId, uint64_t userData, void* context)
{
	(void)treeProxyId;
	int key = (int)userData;
	tbUserQueryContext* c = context;
	const tbBroadProxy* p = c->bp->table.proxies + key;
	if ((p->categoryBits & c->maskBits) == 0)
	{
		return true;
	}
	c->stopped = c->queryCallback(key, p->shapeIndex, c->userContext) == false;
	return c->stopped == false;
}

static tbTreeStats tbAddTreeStats(tbTreeStats a, tbTreeStats b)
{
	return (tbTreeStats){a.nodeVisits + b.nodeVisits, a.leafVisits + b.leafVisits};
}

/// The methods without a tree count the proxies they offer a query as its leaf visits.
typedef struct tbCountingQuery
{
	tbProxyQueryFcn* queryCallback;
	tbProxyRayCastFcn* rayCallback;
	void* userContext;
	int offered;
} tbCountingQuery;

static bool tbCountingQueryCallback(int key, int shapeIndex, void* context)
{
	tbCountingQuery* c = context;
	c->offered += 1;
	return c->queryCallback(key, shapeIndex, c->userContext);
}

static float tbCountingRayCallback(const tbRayCastInput* input, int key, int shapeIndex, void* context)
{
	tbCountingQuery* c = context;
	c->offered += 1;
	return c->rayCallback(input, key, shapeIndex, c->userContext);
}

tbTreeStats tbBroadPhase_Query(const tbBroadPhase* bp, tbAABB aabb, uint64_t maskBits, tbProxyQueryFcn* callback,
							   void* context)
{
	if (bp->method == tb_broadPhaseTree)
	{
		tbUserQueryContext c = {bp, maskBits, callback, NULL, context, 0.0f, false};
		tbTreeStats stats = tbDynamicTree_Query(&bp->staticTree, aabb, maskBits, tbUserQueryCallback, &c);
		if (c.stopped == false)
		{
			stats = tbAddTreeStats(stats, tbDynamicTree_Query(&bp->movableTree, aabb, maskBits, tbUserQueryCallback, &c));
		}
		return stats;
	}
	tbCountingQuery c = {callback, NULL, context, 0};
	switch (bp->method)
	{
		case tb_broadPhaseSortAndSweep:
			tbSortAndSweep_Query(&bp->table, aabb, maskBits, tbCountingQueryCallback, &c);
			break;
		case tb_broadPhaseSpatialHash:
			tbSpatialHash_Query(bp->hash, &bp->table, aabb, maskBits, false, tbCountingQueryCallback, &c);
			break;
		default:
			tbBruteForce_Query(&bp->table, aabb, maskBits, tbCountingQueryCallback, &c);
			break;
	}
	return (tbTreeStats){0, c.offered};
}

/// Table scans (sort-and-sweep, brute force) see every proxy: pass on the static ones only.
typedef struct tbStaticQueryContext
{
	const tbBroadPhase* bp;
	tbProxyQueryFcn* callback;
	void* userContext;
} tbStaticQueryContext;

static bool tbStaticQueryCallback(int key, int shapeIndex, void* context)
{
	tbStaticQueryContext* c = context;
	if (c->bp->table.proxies[key].type != tb_proxyStatic)
	{
		return true;
	}
	return c->callback(key, shapeIndex, c->userContext);
}

void tbBroadPhase_QueryStatic(const tbBroadPhase* bp, tbAABB aabb, uint64_t maskBits, tbProxyQueryFcn* callback,
							  void* context)
{
	if (bp->method == tb_broadPhaseTree)
	{
		tbUserQueryContext c = {bp, maskBits, callback, NULL, context, 0.0f, false};
		tbDynamicTree_Query(&bp->staticTree, aabb, maskBits, tbUserQueryCallback, &c);
		return;
	}
	if (bp->method == tb_broadPhaseSpatialHash)
	{
		tbSpatialHash_Query(bp->hash, &bp->table, aabb, maskBits, true, callback, context);
		return;
	}
	tbStaticQueryContext c = {bp, callback, context};
	tbBroadPhase_Query(bp, aabb, maskBits, tbStaticQueryCallback, &c);
}

static float tbUserRayCastCallback(const tbRayCastInput* input, int treeProxyId, uint64_t userData, void* context)
{
	(void)treeProxyId;
	int key = (int)userData;
	tbUserQueryContext* c = context;
	const tbBroadProxy* p = c->bp->table.proxies + key;
	if ((p->categoryBits & c->maskBits) == 0)
	{
		return input->maxFraction;
	}
	float value = c->rayCallback(input, key, p->shapeIndex, c->userContext);
	if (value == 0.0f)
	{
		c->stopped = true;
	}
	else if (0.0f < value && value < c->maxFraction)
	{
		c->maxFraction = value;
	}
	return value;
}

tbTreeStats tbBroadPhase_RayCast(const tbBroadPhase* bp, const tbRayCastInput* input, uint64_t maskBits,
								 tbProxyRayCastFcn* callback, void* context)
{
	if (bp->method == tb_broadPhaseTree)
	{
		tbUserQueryContext c = {bp, maskBits, NULL, callback, context, input->maxFraction, false};
		tbTreeStats stats = tbDynamicTree_RayCast(&bp->staticTree, input, maskBits, tbUserRayCastCallback, &c);
		if (c.stopped == false)
		{
			// The movable tree sees the ray as clipped by hits in the static tree.
			tbRayCastInput clipped = *input;
			clipped.maxFraction = c.maxFraction;
			stats = tbAddTreeStats(stats,
								   tbDynamicTree_RayCast(&bp->movableTree, &clipped, maskBits, tbUserRayCastCallback, &c));
		}
		return stats;
	}
	tbCountingQuery c = {NULL, callback, context, 0};
	switch (bp->method)
	{
		case tb_broadPhaseSortAndSweep:
			tbSortAndSweep_RayCast(&bp->table, input, maskBits, tbCountingRayCallback, &c);
			break;
		case tb_broadPhaseSpatialHash:
			if (tbSpatialHash_RayCast(bp->hash, &bp->table, input, maskBits, tbCountingRayCallback, &c) == false)
			{
				tbBruteForce_RayCast(&bp->table, input, maskBits, tbCountingRayCallback, &c);
			}
			break;
		default:
			tbBruteForce_RayCast(&bp->table, input, maskBits, tbCountingRayCallback, &c);
			break;
	}
	return (tbTreeStats){0, c.offered};
}

void tbBroadPhase_RebuildStaticTree(tbBroadPhase* bp)
{
	// Pairs are reported sorted, so the tree's shape changes no trajectory, only query speed.
	if (bp->method == tb_broadPhaseTree)
	{
		tbDynamicTree_Rebuild(&bp->staticTree, true);
		bp->staticInsertCount = 0;
	}
}

int tbBroadPhase_GetTreeHeight(const tbBroadPhase* bp)
{
	return bp->method == tb_broadPhaseTree ? tbDynamicTree_GetHeight(&bp->movableTree) : 0;
}

int tbBroadPhase_GetStaticTreeHeight(const tbBroadPhase* bp)
{
	return bp->method == tb_broadPhaseTree ? tbDynamicTree_GetHeight(&bp->staticTree) : 0;
}

void tbBroadPhase_VisitTreeNodes(const tbBroadPhase* bp, tbTreeNodeFcn* fcn, void* context)
{
	if (bp->method == tb_broadPhaseTree)
	{
		tbDynamicTree_VisitNodes(&bp->staticTree, fcn, context);
		tbDynamicTree_VisitNodes(&bp->movableTree, fcn, context);
	}
}

// --------------------------------------------------------------------------------------------
// Validation

/// Each live proxy is a leaf of the right tree carrying its key and box.
static bool tbValidateTreeProxies(const tbBroadPhase* bp)
{
	if (tbDynamicTree_Validate(&bp->staticTree) == false || tbDynamicTree_Validate(&bp->movableTree) == false ||
		bp->staticTree.proxyCount + bp->movableTree.proxyCount != bp->table.count)
	{
		return false;
	}
	for (int key = 0; key < bp->table.capacity; ++key)
	{
		const tbBroadProxy* p = bp->table.proxies + key;
		if (p->isFree)
		{
			continue;
		}
		const tbDynamicTree* tree = p->type == tb_proxyStatic ? &bp->staticTree : &bp->movableTree;
		tbAABB box = tbDynamicTree_GetAABB(tree, p->handle);
		if (tbDynamicTree_GetUserData(tree, p->handle) != (uint64_t)key || memcmp(&box, &p->aabb, sizeof(box)) != 0)
		{
			return false;
		}
	}
	return true;
}

/// Live count, free list and move buffer agree with the table.
static bool tbValidateProxyTable(const tbBroadPhase* bp)
{
	int live = 0;
	for (int key = 0; key < bp->table.capacity; ++key)
	{
		const tbBroadProxy* p = bp->table.proxies + key;
		live += p->isFree ? 0 : 1;
		if (p->moveIndex >= 0 && (p->moveIndex >= bp->moveCount || bp->moveBuffer[p->moveIndex] != key))
		{
			return false;
		}
	}
	int freeCount = 0;
	for (int key = bp->freeProxy; key >= 0 && freeCount <= bp->table.capacity; key = bp->table.proxies[key].handle)
	{
		freeCount += bp->table.proxies[key].isFree ? 1 : bp->table.capacity + 1;
	}
	return live == bp->table.count && live + freeCount == bp->table.capacity;
}

bool tbBroadPhase_Validate(const tbBroadPhase* bp)
{
	if (tbValidateProxyTable(bp) == false)
	{
		return false;
	}
	switch (bp->method)
	{
		case tb_broadPhaseTree:
			return tbValidateTreeProxies(bp);
		case tb_broadPhaseSortAndSweep:
			return tbSortAndSweep_Validate(bp->sweep, &bp->table);
		case tb_broadPhaseSpatialHash:
			return tbSpatialHash_Validate(bp->hash, &bp->table);
		default:
			return tbBruteForce_Validate(bp->brute, &bp->table);
	}
}
