// Internal: what the broad phase shares with its methods (sort_and_sweep.c, brute_force.c): the
// proxy table they read and the pair list they append to. It sits below broad_phase.h, so the
// method files depend on this alone and the dispatcher (broad_phase.c) on them: no include loop.
#pragma once

#include "tumble/collision.h"

/// The broad phase's query callbacks (every method's): a proxy by its key in the proxy table and
/// the shape it belongs to; return false to stop. (The dynamic tree's own callbacks carry its
/// 64-bit user data; the tree method adapts them in broad_phase.c.)
typedef bool tbProxyQueryFcn(int proxyKey, int shapeIndex, void* context);
/// Ray cast callback: the new max fraction (0 stops, the input's maxFraction ignores the proxy).
typedef float tbProxyRayCastFcn(const tbRayCastInput* input, int proxyKey, int shapeIndex, void* context);

/// A candidate pair: shape indices with a < b.
typedef struct tbShapePair
{
	int a, b;
} tbShapePair;

/// Proxy kinds: static proxies are kept apart (static tree) and never pair with each other.
typedef enum tbProxyType
{
	tb_proxyStatic = 0,
	tb_proxyMovable = 1,
} tbProxyType;

/// One slot of the proxy table, shared by the method files. 48 bytes.
typedef struct tbBroadProxy
{
	tbAABB aabb;		   ///< fat box
	uint64_t categoryBits; ///< passed to queries (pairs are not filtered here)
	int shapeIndex;		   ///< the world's shape index: pairs are named and ordered by it
	tbProxyType type;
	int handle;	   ///< method-specific: tree proxy id (tree method); next free slot when free
	int moveIndex; ///< index in moveBuffer, or -1 when not moved since the last UpdatePairs
	bool isFree;
} tbBroadProxy;


/// Pair filter: return false to drop the pair of two shapes (shape indices).
typedef bool tbPairFilterFcn(int shapeIndexA, int shapeIndexB, void* context);

/// Optional companion of a pair filter: asks the memory system for what the filter will read of
/// the pair (a hint only; tbPairList calls it TB_PAIR_BATCH pairs before the filter).
typedef void tbPairPrefetchFcn(int shapeIndexA, int shapeIndexB, void* context);

/// Pairs a list holds back before filtering them: the filter's loads (a hash probe into the set of
/// pairs that have a contact, the shapes) miss the cache one by one, and asked for this many pairs
/// ahead they arrive together.
#define TB_PAIR_BATCH 16

/// The proxy slots, indexed by proxy key (free slots have isFree set).
typedef struct tbProxyTable
{
	tbBroadProxy* proxies;
	int capacity; ///< slots
	int count;	  ///< live proxies
} tbProxyTable;

/// Pairs found by an update, named by shape index with a < b (sorted and made unique afterwards
/// by the broad phase), and the optional filter applied as each is found.
typedef struct tbPairList
{
	tbShapePair* pairs;
	int count;
	int capacity;
	tbPairFilterFcn* filter;	 ///< NULL keeps every pair
	tbPairPrefetchFcn* prefetch; ///< NULL: no hint
	void* filterContext;
	tbShapePair pending[TB_PAIR_BATCH]; ///< found, not yet filtered (shape indices in query order)
	int pendingCount;
} tbPairList;

/// Append the pair of two proxies unless the filter drops it. With a filter the pair may wait in
/// `pending` (tbPairList_Flush): the pairs come out in the order they went in.
void tbPairList_Add(tbPairList* list, const tbProxyTable* table, int proxyKeyA, int proxyKeyB);

/// Filter and append the pairs still pending. Whoever fills a list calls this before reading it.
void tbPairList_Flush(tbPairList* list);

/// Append a pair as it is (no filter).
void tbPairList_Append(tbPairList* list, tbShapePair pair);

/// Release the list's memory.
void tbPairList_Destroy(tbPairList* list);
