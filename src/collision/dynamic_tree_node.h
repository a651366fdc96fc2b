// Internal: a node of the dynamic tree (dynamic_tree.c), in a header of its own so that the world's
// snapshot (world/snapshot.c) can store and restore a tree node for node: the shape of a tree
// decides the order in which queries report proxies, so a restored tree must be the same tree.
#pragma once

#include "tumble/collision.h"

#include <stdint.h>

/// One node: a leaf (height 0, no children) holds a proxy; an internal node has two children.
/// A free node has height −1 and links the free list through `parent`. 48 bytes.
typedef struct tbTreeNode
{
	tbAABB aabb;		   ///< fat box of a leaf, union of the children for an internal node
	uint64_t categoryBits; ///< leaf: the proxy's bits; internal: OR of the children
	uint64_t userData;	   ///< leaf payload returned to queries
	int parent;			   ///< parent node, or next free node when free
	int child1;			   ///< TB_NULL_NODE for a leaf
	int child2;
	int16_t height;	  ///< 0 for a leaf, 1 + max(children) for an internal node, −1 when free
	int16_t enlarged; ///< a leaf grown in place since the last rebuild, or an ancestor of one
} tbTreeNode;

_Static_assert(sizeof(tbTreeNode) == 48, "tree node is 48 bytes");
