// Internal: the flags of a dynamic tree node (tbTreeNode, in tumble/collision.h), in a header of
// their own so that the world's snapshot (world/snapshot.c) can store and restore a tree node for
// node: the shape of a tree decides the order in which queries report proxies, so a restored tree
// must be the same tree.
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
