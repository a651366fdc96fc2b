// Internal: what the engine outside dynamic_tree.c needs of a tree's insides. The flags of a node
// (tbTreeNode, in tumble/collision.h), so that the world's snapshot (world/snapshot.c) can store
// and restore a tree node for node: the shape of a tree decides the order in which queries report
// proxies, so a restored tree must be the same tree. And the bulk load the broad phase builds a
// whole tree with (broad_phase.c).
#pragma once

#include "tumble/collision.h"

/// tbTreeNode.flags. A free node has none and links the free list through `next`; a node in use
/// is allocated, and a leaf (height 0, `userData`) or internal (`children`).
enum
{
	tb_allocatedNode = 0x1,
	tb_enlargedNode = 0x2, ///< a leaf grown in place since the last rebuild, or an ancestor of one
	tb_leafNode = 0x4,
};

_Static_assert(sizeof(tbTreeNode) == 40, "tree node is 40 bytes");

/// A proxy's leaf, allocated and filled but not placed in the hierarchy: for loading many proxies
/// at once, after which a full rebuild (tbDynamicTree_Rebuild(tree, true)) links every leaf, in
/// O(n log n), where inserting them one by one costs a search from the root and a refit per leaf.
/// Until that rebuild the tree must not be queried, moved or checked.
int tbDynamicTree_CreateProxyDeferred(tbDynamicTree* tree, tbAABB aabb, uint64_t categoryBits, uint64_t userData);
