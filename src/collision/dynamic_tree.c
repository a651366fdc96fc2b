// Dynamic AABB tree: a bounding-volume hierarchy of fat boxes that supports insert, remove and
// move in O(log n) and prunes queries and ray casts by box.
//
// Cost model (surface-area heuristic, Goldsmith & Salmon 1987; MacDonald & Booth 1990): the
// expected cost of a query is proportional to the sum of the perimeters (the 2D "surface area")
// of the internal nodes. Inserting leaf L as the sibling of node S creates a new internal node
// of perimeter P(S ∪ L) and grows every ancestor A of S by P(A ∪ L) − P(A):
//
//     C(S) = P(S ∪ L) + Σ_{A ⊃ S} [P(A ∪ L) − P(A)]
//
// The sum over ancestors is the "inherited cost" I(S). Every node below S costs at least
// P(L) + I(S) + P(S ∪ L) − P(S), a lower bound that lets a branch-and-bound search skip whole
// subtrees and still return the sibling of least C (Bittner, Hapala & Havran 2013, "Fast
// insertion-based optimization of bounding volume hierarchies", §4.1). The search is depth first
// with the cheaper child visited first.
//
// Balance: after each insert or remove the ancestors are refitted bottom up, and at each one a
// rotation may swap a child with a grandchild on the other side (Kopta et al. 2012, "Fast,
// effective BVH updates for animated scenes"). In a tree whose children are unordered, this swap
// is the AVL single/double rotation (Adelson-Velsky & Landis 1962), so when the children's
// heights differ by more than one we take the swap that lowers the height; otherwise we take the
// swap that lowers the perimeter of the rebuilt child most, provided the height does not grow
// and both rebuilt nodes stay balanced. This keeps the height O(log n) even for a row of boxes
// inserted in order, the worst case for pure SAH insertion.
//
// Rebuild: top-down construction. By default by the binned SAH (Wald 2007, "On fast construction
// of SAH-based bounding volume hierarchies"): centroids are binned into 16 bins along the axis of
// largest centroid extent, and the split plane between bins minimising
// N_left·P(left) + N_right·P(right) is taken. Or by the spatial median, the middle of the centroid
// extent on its longer axis (Kay & Kajiya 1986 build their hierarchies so): one partition pass per
// level that also hands each side its centroid bounds, against the SAH's three passes with box
// unions, for a tree rebuilt every step; its trees cost a few percent more per query. A partial rebuild keeps every subtree that holds no
// leaf grown in place (tbDynamicTree_EnlargeProxy) and rebuilds only above them: its items are
// those whole subtrees and the grown leaves, about k·log n items for k grown leaves in n instead
// of n, and the kept subtrees are as good as before (their boxes did not change).
//
// Category bits: leaves store their shape's bits, internal nodes the OR of their children's, so a
// query with a mask skips a subtree that holds no matching category.

#include "dynamic_tree_node.h"

#include "core/core.h"

#include "tumble/collision.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

/// Initial node capacity: 16 nodes (768 bytes), doubled when full.
#define TB_TREE_INITIAL_CAPACITY 16

/// Fixed depth-first stack size. A depth-first traversal holds at most height + 2 entries, and the
/// balancing keeps the height near 1.44·log2(n) (AVL bound): 256 covers any tree that fits in
/// memory. When full, queries fall back to the heap (tbTreeStack) and the insertion search stops
/// descending (a valid, merely less optimal, sibling).
#define TB_TREE_STACK_SIZE 256

/// Bins of the binned SAH rebuild: 16 (Wald 2007 finds 16–32 within a few percent of a full sweep).
#define TB_TREE_BIN_COUNT 16

static bool tbIsLeaf(const tbTreeNode* node)
{
	return (node->flags & tb_leafNode) != 0;
}

// --------------------------------------------------------------------------------------------
// Rebuild scratch: the items of a rebuild (leaves, or whole subtrees kept as they are) in four
// parallel arrays: node index, box, box centre and bin.

#define TB_REBUILD_ITEM_BYTES ((int)(2 * sizeof(int32_t) + sizeof(tbAABB) + sizeof(tbVec2)))

static void tbFreeRebuild(tbDynamicTree* tree)
{
	int n = tree->rebuildCapacity;
	tbFree(tree->leafIndices, n * (int)sizeof(int32_t));
	tbFree(tree->leafBoxes, n * (int)sizeof(tbAABB));
	tbFree(tree->leafCenters, n * (int)sizeof(tbVec2));
	tbFree(tree->binIndices, n * (int)sizeof(int32_t));
	tree->leafIndices = NULL;
	tree->leafBoxes = NULL;
	tree->leafCenters = NULL;
	tree->binIndices = NULL;
	tree->rebuildCapacity = 0;
}

/// Exchange rebuild items i and j (their bins are the partition's business).
static TB_FORCE_INLINE void tbSwapRebuildItems(tbDynamicTree* tree, int i, int j)
{
	int32_t index = tree->leafIndices[i];
	tree->leafIndices[i] = tree->leafIndices[j];
	tree->leafIndices[j] = index;
	tbAABB box = tree->leafBoxes[i];
	tree->leafBoxes[i] = tree->leafBoxes[j];
	tree->leafBoxes[j] = box;
	tbVec2 center = tree->leafCenters[i];
	tree->leafCenters[i] = tree->leafCenters[j];
	tree->leafCenters[j] = center;
}

// --------------------------------------------------------------------------------------------
// Depth-first stack with a fixed part on the C stack and a heap overflow

typedef struct tbTreeStack
{
	int* items;
	int count;
	int capacity;
	int fixed[TB_TREE_STACK_SIZE];
} tbTreeStack;

static void tbTreeStackInit(tbTreeStack* stack)
{
	stack->items = stack->fixed;
	stack->count = 0;
	stack->capacity = TB_TREE_STACK_SIZE;
}

static void tbTreeStackPush(tbTreeStack* stack, int value)
{
	if (stack->count == stack->capacity)
	{
		int oldSize = stack->capacity * (int)sizeof(int);
		int* grown = tbAlloc(2 * oldSize);
		memcpy(grown, stack->items, (size_t)oldSize);
		if (stack->items != stack->fixed)
		{
			tbFree(stack->items, oldSize);
		}
		stack->items = grown;
		stack->capacity *= 2;
	}
	stack->items[stack->count++] = value;
}

static void tbTreeStackFree(tbTreeStack* stack)
{
	if (stack->items != stack->fixed)
	{
		tbFree(stack->items, stack->capacity * (int)sizeof(int));
	}
}

// --------------------------------------------------------------------------------------------
// Node allocation

/// Double the node array and thread the new nodes onto the free list.
static void tbGrowNodes(tbDynamicTree* tree)
{
	int oldCapacity = tree->nodeCapacity;
	int newCapacity = oldCapacity > 0 ? 2 * oldCapacity : TB_TREE_INITIAL_CAPACITY;
	tree->nodes = tbGrowAlloc(tree->nodes, oldCapacity * (int)sizeof(tbTreeNode), newCapacity * (int)sizeof(tbTreeNode));
	for (int i = oldCapacity; i < newCapacity; ++i)
	{
		tree->nodes[i].next = i + 1 < newCapacity ? i + 1 : tree->freeList;
		tree->nodes[i].flags = 0;
	}
	tree->freeList = oldCapacity;
	tree->nodeCapacity = newCapacity;
}

tbDynamicTree tbDynamicTree_Create(int proxyCapacity)
{
	tbDynamicTree tree;
	memset(&tree, 0, sizeof(tree));
	tree.root = TB_NULL_NODE;
	tree.freeList = TB_NULL_NODE;
	// n proxies make 2n − 1 nodes.
	while (proxyCapacity > 0 && tree.nodeCapacity < 2 * proxyCapacity)
	{
		tbGrowNodes(&tree);
	}
	return tree;
}

void tbDynamicTree_Destroy(tbDynamicTree* tree)
{
	tbFree(tree->nodes, tree->nodeCapacity * (int)sizeof(tbTreeNode));
	tbFreeRebuild(tree);
	*tree = tbDynamicTree_Create(0);
}

static int tbAllocateNode(tbDynamicTree* tree)
{
	if (tree->freeList == TB_NULL_NODE)
	{
		tbGrowNodes(tree);
	}
	int index = tree->freeList;
	tbTreeNode* node = tree->nodes + index;
	tree->freeList = node->next;
	memset(node, 0, sizeof(*node));
	node->parent = TB_NULL_NODE;
	node->children.child1 = TB_NULL_NODE;
	node->children.child2 = TB_NULL_NODE;
	node->flags = tb_allocatedNode;
	tree->nodeCount += 1;
	return index;
}

static void tbFreeNode(tbDynamicTree* tree, int index)
{
	TB_ASSERT(0 <= index && index < tree->nodeCapacity);
	tree->nodes[index].next = tree->freeList;
	tree->nodes[index].flags = 0;
	tree->freeList = index;
	tree->nodeCount -= 1;
}

// --------------------------------------------------------------------------------------------
// Refit and rotation

/// Recompute an internal node's box, category bits and height from its children.
static void tbRefitNode(tbDynamicTree* tree, int index)
{
	tbTreeNode* node = tree->nodes + index;
	const tbTreeNode* a = tree->nodes + node->children.child1;
	const tbTreeNode* b = tree->nodes + node->children.child2;
	node->aabb = tbAABB_Union(a->aabb, b->aabb);
	node->categoryBits = a->categoryBits | b->categoryBits;
	node->height = (uint16_t)(1 + tbMaxInt(a->height, b->height));
}

/// A candidate rotation at node A: swap A's child `upper` with `lower`, a child of A's other
/// child `other`; `kept` is other's remaining child.
typedef struct tbRotation
{
	int upper, other, lower, kept;
	int heightA;	///< A's height after the swap
	float cost;		///< P(upper ∪ kept) − P(other): change of total internal perimeter
	bool balanced;	///< both rebuilt nodes have children whose heights differ by at most one
} tbRotation;

static bool tbEvaluateRotation(const tbDynamicTree* tree, int upper, int other, int lower, tbRotation* rotation)
{
	const tbTreeNode* o = tree->nodes + other;
	if (tbIsLeaf(o))
	{
		return false;
	}
	int kept = o->children.child1 == lower ? o->children.child2 : o->children.child1;
	const tbTreeNode* u = tree->nodes + upper;
	const tbTreeNode* l = tree->nodes + lower;
	const tbTreeNode* k = tree->nodes + kept;
	int heightOther = 1 + tbMaxInt(u->height, k->height);
	rotation->upper = upper;
	rotation->other = other;
	rotation->lower = lower;
	rotation->kept = kept;
	rotation->heightA = 1 + tbMaxInt(l->height, heightOther);
	rotation->cost = tbAABB_Perimeter(tbAABB_Union(u->aabb, k->aabb)) - tbAABB_Perimeter(o->aabb);
	rotation->balanced = abs(l->height - heightOther) <= 1 && abs(u->height - k->height) <= 1;
	return true;
}

/// Replace child `oldChild` of `parent` by `newChild` (fixing newChild's parent link).
static void tbReplaceChild(tbDynamicTree* tree, int parent, int oldChild, int newChild)
{
	tbTreeNode* p = tree->nodes + parent;
	if (p->children.child1 == oldChild)
	{
		p->children.child1 = newChild;
	}
	else
	{
		TB_ASSERT(p->children.child2 == oldChild);
		p->children.child2 = newChild;
	}
	tree->nodes[newChild].parent = parent;
}

static void tbApplyRotation(tbDynamicTree* tree, int indexA, const tbRotation* rotation)
{
	tbReplaceChild(tree, indexA, rotation->upper, rotation->lower);
	tbReplaceChild(tree, rotation->other, rotation->lower, rotation->upper);
	tbRefitNode(tree, rotation->other);
	tbRefitNode(tree, indexA);
}

/// Is rotation r better than the best so far? When A is out of balance, lowest height wins (ties
/// by cost); otherwise the cheapest balanced swap that does not raise A wins.
static bool tbIsBetterRotation(const tbRotation* r, const tbRotation* best, bool hasBest, int heightA, bool unbalanced)
{
	if (unbalanced)
	{
		if (r->heightA >= heightA)
		{
			return false;
		}
		return hasBest == false || r->heightA < best->heightA || (r->heightA == best->heightA && r->cost < best->cost);
	}
	if (r->heightA > heightA || r->balanced == false || r->cost >= 0.0f)
	{
		return false;
	}
	return hasBest == false || r->cost < best->cost;
}

/// Try the four child–grandchild swaps at internal node A and apply the best, if any.
static void tbRotateNode(tbDynamicTree* tree, int indexA)
{
	const tbTreeNode* a = tree->nodes + indexA;
	int b = a->children.child1, c = a->children.child2;
	const tbTreeNode* nodeB = tree->nodes + b;
	const tbTreeNode* nodeC = tree->nodes + c;
	bool unbalanced = abs(nodeB->height - nodeC->height) > 1;
	int heightA = a->height;

	// Candidates: B with C's children, C with B's children.
	int uppers[4] = {b, b, c, c};
	int others[4] = {c, c, b, b};
	int lowers[4] = {nodeC->children.child1, nodeC->children.child2, nodeB->children.child1, nodeB->children.child2};

	tbRotation best = {0};
	bool hasBest = false;
	for (int i = 0; i < 4; ++i)
	{
		tbRotation r;
		if (tbEvaluateRotation(tree, uppers[i], others[i], lowers[i], &r) &&
			tbIsBetterRotation(&r, &best, hasBest, heightA, unbalanced))
		{
			best = r;
			hasBest = true;
		}
	}
	if (hasBest)
	{
		tbApplyRotation(tree, indexA, &best);
	}
}

/// Walk from index to the root, refitting and rotating each ancestor.
static void tbRefitUpward(tbDynamicTree* tree, int index)
{
	while (index != TB_NULL_NODE)
	{
		tbRefitNode(tree, index);
		tbRotateNode(tree, index);
		index = tree->nodes[index].parent;
	}
}

// --------------------------------------------------------------------------------------------
// Insertion by branch and bound

typedef struct tbCandidate
{
	int node;
	float inheritedCost; ///< I(S): growth of the strict ancestors of node
} tbCandidate;

/// Sibling of least C(S) for a leaf of box `box` (see the file header).
static int tbFindBestSibling(const tbDynamicTree* tree, tbAABB box)
{
	float leafPerimeter = tbAABB_Perimeter(box);
	tbCandidate stack[TB_TREE_STACK_SIZE];
	int count = 0;
	stack[count++] = (tbCandidate){tree->root, 0.0f};
	int bestNode = tree->root;
	float bestCost = tbAABB_Perimeter(tbAABB_Union(tree->nodes[tree->root].aabb, box));

	while (count > 0)
	{
		tbCandidate c = stack[--count];
		const tbTreeNode* node = tree->nodes + c.node;
		if (leafPerimeter + c.inheritedCost >= bestCost)
		{
			continue; // C(S) ≥ P(L) + I(S): cannot beat the best
		}
		float unionPerimeter = tbAABB_Perimeter(tbAABB_Union(node->aabb, box));
		float cost = unionPerimeter + c.inheritedCost;
		if (cost < bestCost)
		{
			bestCost = cost;
			bestNode = c.node;
		}
		if (tbIsLeaf(node))
		{
			continue;
		}
		float childInherited = c.inheritedCost + unionPerimeter - tbAABB_Perimeter(node->aabb);
		if (leafPerimeter + childInherited >= bestCost || count + 2 > TB_TREE_STACK_SIZE)
		{
			continue;
		}
		// Push the child whose union with the leaf is larger first, so the smaller is visited first.
		int first = node->children.child1, second = node->children.child2;
		float p1 = tbAABB_Perimeter(tbAABB_Union(tree->nodes[first].aabb, box));
		float p2 = tbAABB_Perimeter(tbAABB_Union(tree->nodes[second].aabb, box));
		if (p1 < p2)
		{
			first = node->children.child2;
			second = node->children.child1;
		}
		stack[count++] = (tbCandidate){first, childInherited};
		stack[count++] = (tbCandidate){second, childInherited};
	}
	return bestNode;
}

static void tbInsertLeaf(tbDynamicTree* tree, int leaf)
{
	if (tree->root == TB_NULL_NODE)
	{
		tree->root = leaf;
		tree->nodes[leaf].parent = TB_NULL_NODE;
		return;
	}
	int sibling = tbFindBestSibling(tree, tree->nodes[leaf].aabb);
	int oldParent = tree->nodes[sibling].parent;
	int newParent = tbAllocateNode(tree);
	tbTreeNode* p = tree->nodes + newParent;
	p->parent = oldParent;
	p->children.child1 = sibling;
	p->children.child2 = leaf;
	if (oldParent == TB_NULL_NODE)
	{
		tree->root = newParent;
	}
	else
	{
		tbReplaceChild(tree, oldParent, sibling, newParent);
	}
	tree->nodes[sibling].parent = newParent;
	tree->nodes[leaf].parent = newParent;
	tbRefitUpward(tree, newParent);
}

/// Detach a leaf: its sibling takes the parent's place and the parent is freed.
static void tbRemoveLeaf(tbDynamicTree* tree, int leaf)
{
	if (leaf == tree->root)
	{
		tree->root = TB_NULL_NODE;
		return;
	}
	int parent = tree->nodes[leaf].parent;
	int grandParent = tree->nodes[parent].parent;
	int sibling = tree->nodes[parent].children.child1 == leaf ? tree->nodes[parent].children.child2 : tree->nodes[parent].children.child1;
	if (grandParent == TB_NULL_NODE)
	{
		tree->root = sibling;
		tree->nodes[sibling].parent = TB_NULL_NODE;
	}
	else
	{
		tbReplaceChild(tree, grandParent, parent, sibling);
	}
	tbFreeNode(tree, parent);
	tree->nodes[leaf].parent = TB_NULL_NODE;
	tbRefitUpward(tree, grandParent);
}

// --------------------------------------------------------------------------------------------
// Proxies

/// Clear the enlarged marks from a leaf up to the first unmarked node. When every grown leaf is
/// cleared (the broad phase re-inserts all of them), no mark is left; a mark left above a
/// cleared node only makes the next partial rebuild descend further, never wrong.
static void tbClearEnlargedPath(tbDynamicTree* tree, int index)
{
	tree->nodes[index].flags &= (uint16_t)~tb_enlargedNode;
	index = tree->nodes[index].parent;
	while (index != TB_NULL_NODE && (tree->nodes[index].flags & tb_enlargedNode) != 0)
	{
		tree->nodes[index].flags &= (uint16_t)~tb_enlargedNode;
		index = tree->nodes[index].parent;
	}
}

static int tbAllocateLeaf(tbDynamicTree* tree, tbAABB aabb, uint64_t categoryBits, uint64_t userData)
{
	int leaf = tbAllocateNode(tree);
	tbTreeNode* node = tree->nodes + leaf;
	node->aabb = aabb;
	node->categoryBits = categoryBits;
	node->userData = userData;
	node->height = 0;
	node->flags = tb_allocatedNode | tb_leafNode;
	tree->proxyCount += 1;
	return leaf;
}

int tbDynamicTree_CreateProxy(tbDynamicTree* tree, tbAABB aabb, uint64_t categoryBits, uint64_t userData)
{
	int leaf = tbAllocateLeaf(tree, aabb, categoryBits, userData);
	tbInsertLeaf(tree, leaf);
	return leaf;
}

int tbDynamicTree_CreateProxyDeferred(tbDynamicTree* tree, tbAABB aabb, uint64_t categoryBits, uint64_t userData)
{
	int leaf = tbAllocateLeaf(tree, aabb, categoryBits, userData);
	if (tree->root == TB_NULL_NODE)
	{
		tree->root = leaf; // a root for tbDynamicTree_Rebuild to start from; it collects every leaf
	}
	return leaf;
}

void tbDynamicTree_DestroyProxy(tbDynamicTree* tree, int proxyId)
{
	TB_ASSERT(0 <= proxyId && proxyId < tree->nodeCapacity && tbIsLeaf(tree->nodes + proxyId));
	tbRemoveLeaf(tree, proxyId);
	tbFreeNode(tree, proxyId);
	tree->proxyCount -= 1;
}

void tbDynamicTree_MoveProxy(tbDynamicTree* tree, int proxyId, tbAABB aabb)
{
	TB_ASSERT(0 <= proxyId && proxyId < tree->nodeCapacity && tbIsLeaf(tree->nodes + proxyId));
	tbClearEnlargedPath(tree, proxyId);
	tbRemoveLeaf(tree, proxyId);
	tree->nodes[proxyId].aabb = aabb;
	tbInsertLeaf(tree, proxyId);
}

void tbDynamicTree_EnlargeProxy(tbDynamicTree* tree, int proxyId, tbAABB aabb)
{
	TB_ASSERT(0 <= proxyId && proxyId < tree->nodeCapacity && tbIsLeaf(tree->nodes + proxyId));
	tbTreeNode* nodes = tree->nodes;
	nodes[proxyId].aabb = aabb;
	nodes[proxyId].flags |= tb_enlargedNode;
	int index = nodes[proxyId].parent;
	// Ancestors only ever grow; stop growing at the first one that already contains the new box.
	while (index != TB_NULL_NODE && tbAABB_Contains(nodes[index].aabb, aabb) == false)
	{
		nodes[index].aabb = tbAABB_Union(nodes[index].aabb, aabb);
		nodes[index].flags |= tb_enlargedNode;
		index = nodes[index].parent;
	}
	// Mark the rest of the path to the root for the partial rebuild (a tree height, ~20 nodes).
	while (index != TB_NULL_NODE)
	{
		nodes[index].flags |= tb_enlargedNode;
		index = nodes[index].parent;
	}
}

// --------------------------------------------------------------------------------------------
// Queries

/// Depth-first visit of the leaves whose boxes overlap aabb and, when filtered, whose category
/// bits meet maskBits (internal nodes hold the OR of their leaves' bits, so a subtree without the
/// bits is skipped whole). A node's two children are tested together, before either is pushed:
/// their two loads, most often misses in a large tree, are then in flight at once, where testing
/// each child as it is popped waited for one miss after another (the child popped next is the one
/// just tested, already in cache). The leaves are visited in the same order either way.
static tbTreeStats tbQueryTree(const tbDynamicTree* tree, tbAABB aabb, uint64_t maskBits, bool filtered,
							   tbTreeQueryCallbackFcn* callback, void* context)
{
	tbTreeStats stats = {0, 0};
	if (tree->root == TB_NULL_NODE)
	{
		return stats;
	}
	const tbTreeNode* nodes = tree->nodes;
	const tbTreeNode* root = nodes + tree->root;
	if ((filtered && (root->categoryBits & maskBits) == 0) || tbAABB_Overlaps(root->aabb, aabb) == false)
	{
		return stats;
	}
	tbTreeStack stack;
	tbTreeStackInit(&stack);
	tbTreeStackPush(&stack, tree->root);
	while (stack.count > 0)
	{
		int index = stack.items[--stack.count];
		const tbTreeNode* node = nodes + index;
		if (tbIsLeaf(node))
		{
			stats.leafVisits += 1;
			if (callback(index, node->userData, context) == false)
			{
				break;
			}
			continue;
		}
		stats.nodeVisits += 1;
		int index1 = node->children.child1, index2 = node->children.child2;
		const tbTreeNode* child1 = nodes + index1;
		const tbTreeNode* child2 = nodes + index2;
		bool in1 = (filtered == false || (child1->categoryBits & maskBits) != 0) && tbAABB_Overlaps(child1->aabb, aabb);
		bool in2 = (filtered == false || (child2->categoryBits & maskBits) != 0) && tbAABB_Overlaps(child2->aabb, aabb);
		if (in1)
		{
			tbTreeStackPush(&stack, index1);
		}
		if (in2)
		{
			tbTreeStackPush(&stack, index2);
		}
	}
	tbTreeStackFree(&stack);
	return stats;
}

tbTreeStats tbDynamicTree_Query(const tbDynamicTree* tree, tbAABB aabb, uint64_t maskBits,
								tbTreeQueryCallbackFcn* callback, void* context)
{
	return tbQueryTree(tree, aabb, maskBits, true, callback, context);
}

tbTreeStats tbDynamicTree_QueryAll(const tbDynamicTree* tree, tbAABB aabb, tbTreeQueryCallbackFcn* callback,
								   void* context)
{
	return tbQueryTree(tree, aabb, 0u, false, callback, context);
}

/// Bounding box of the ray p1 → p1 + fraction·d (the part of it still to be cast).
static tbAABB tbRayBox(tbVec2 p1, tbVec2 d, float fraction)
{
	tbVec2 p2 = tbMulAdd(p1, fraction, d);
	return (tbAABB){tbMin(p1, p2), tbMax(p1, p2)};
}

/// Separating-axis test of a segment against a box on the segment's normal n (Ericson 2005,
/// §5.3.3): the box of centre c and half extents h is off the line when
/// |n·(p1 − c)| > |n|·h, i.e. |n·(p1 − c)| > |n.x|·h.x + |n.y|·h.y.
static bool tbSegmentMissesBox(tbVec2 p1, tbVec2 normal, tbAABB box)
{
	tbVec2 c = tbAABB_Center(box);
	tbVec2 h = tbAABB_Extents(box);
	float separation = tbAbsFloat(tbDot(normal, tbSub(p1, c)));
	float radius = tbAbsFloat(normal.x) * h.x + tbAbsFloat(normal.y) * h.y;
	return separation > radius;
}

tbTreeStats tbDynamicTree_RayCast(const tbDynamicTree* tree, const tbRayCastInput* input, uint64_t maskBits,
								  tbTreeRayCastCallbackFcn* callback, void* context)
{
	tbTreeStats stats = {0, 0};
	if (tree->root == TB_NULL_NODE)
	{
		return stats;
	}
	tbVec2 p1 = input->origin;
	tbVec2 d = input->translation;
	tbVec2 normal = tbLeftPerp(d); // need not be unit: the test is homogeneous in |n|
	float maxFraction = input->maxFraction;
	tbAABB segmentBox = tbRayBox(p1, d, maxFraction);

	tbTreeStack stack;
	tbTreeStackInit(&stack);
	tbTreeStackPush(&stack, tree->root);
	while (stack.count > 0)
	{
		int index = stack.items[--stack.count];
		const tbTreeNode* node = tree->nodes + index;
		if ((node->categoryBits & maskBits) == 0 || tbAABB_Overlaps(node->aabb, segmentBox) == false ||
			tbSegmentMissesBox(p1, normal, node->aabb))
		{
			continue;
		}
		if (tbIsLeaf(node) == false)
		{
			stats.nodeVisits += 1;
			tbTreeStackPush(&stack, node->children.child1);
			tbTreeStackPush(&stack, node->children.child2);
			continue;
		}
		stats.leafVisits += 1;
		tbRayCastInput subInput = {p1, d, maxFraction};
		float value = callback(&subInput, index, node->userData, context);
		if (value == 0.0f)
		{
			break; // the client stopped the cast
		}
		if (0.0f < value && value < maxFraction)
		{
			maxFraction = value; // clip the ray: farther boxes can no longer be hit first
			segmentBox = tbRayBox(p1, d, maxFraction);
		}
	}
	tbTreeStackFree(&stack);
	return stats;
}

/// The box swept from its start to start + fraction·translation.
static tbAABB tbSweptBox(tbAABB box, tbVec2 translation, float fraction)
{
	tbVec2 t = tbMulSV(fraction, translation);
	tbAABB moved = {tbAdd(box.lowerBound, t), tbAdd(box.upperBound, t)};
	return tbAABB_Union(box, moved);
}

// A box moving along d is a ray for the boxes grown by its half extents (the Minkowski sum): a
// node is skipped when the swept box misses it or the centre's segment misses the node grown by
// the half extents (the separating-axis test on the segment's normal, as the ray cast).
tbTreeStats tbDynamicTree_BoxCast(const tbDynamicTree* tree, const tbBoxCastInput* input, uint64_t maskBits,
								  tbTreeBoxCastCallbackFcn* callback, void* context)
{
	tbTreeStats stats = {0, 0};
	if (tree->root == TB_NULL_NODE)
	{
		return stats;
	}
	tbVec2 p1 = tbAABB_Center(input->box);
	tbVec2 extents = tbAABB_Extents(input->box);
	tbVec2 d = input->translation;
	tbVec2 normal = tbLeftPerp(d);
	float maxFraction = input->maxFraction;
	tbAABB swept = tbSweptBox(input->box, d, maxFraction);

	tbTreeStack stack;
	tbTreeStackInit(&stack);
	tbTreeStackPush(&stack, tree->root);
	while (stack.count > 0)
	{
		int index = stack.items[--stack.count];
		const tbTreeNode* node = tree->nodes + index;
		tbAABB grown = {tbSub(node->aabb.lowerBound, extents), tbAdd(node->aabb.upperBound, extents)};
		if ((node->categoryBits & maskBits) == 0 || tbAABB_Overlaps(node->aabb, swept) == false ||
			tbSegmentMissesBox(p1, normal, grown))
		{
			continue;
		}
		if (tbIsLeaf(node) == false)
		{
			stats.nodeVisits += 1;
			tbTreeStackPush(&stack, node->children.child1);
			tbTreeStackPush(&stack, node->children.child2);
			continue;
		}
		stats.leafVisits += 1;
		tbBoxCastInput subInput = {input->box, d, maxFraction};
		float value = callback(&subInput, index, node->userData, context);
		if (value == 0.0f)
		{
			break;
		}
		if (0.0f < value && value < maxFraction)
		{
			maxFraction = value;
			swept = tbSweptBox(input->box, d, maxFraction);
		}
	}
	tbTreeStackFree(&stack);
	return stats;
}

void tbDynamicTree_SetCategoryBits(tbDynamicTree* tree, int proxyId, uint64_t categoryBits)
{
	TB_ASSERT(0 <= proxyId && proxyId < tree->nodeCapacity && tbIsLeaf(tree->nodes + proxyId));
	tbTreeNode* nodes = tree->nodes;
	nodes[proxyId].categoryBits = categoryBits;
	// The ancestors hold the OR of their leaves' bits: recompute them up the path (a tree height).
	for (int index = nodes[proxyId].parent; index != TB_NULL_NODE; index = nodes[index].parent)
	{
		nodes[index].categoryBits = nodes[nodes[index].children.child1].categoryBits | nodes[nodes[index].children.child2].categoryBits;
	}
}

tbAABB tbDynamicTree_GetRootBounds(const tbDynamicTree* tree)
{
	tbAABB empty = {{0.0f, 0.0f}, {0.0f, 0.0f}};
	return tree->root == TB_NULL_NODE ? empty : tree->nodes[tree->root].aabb;
}

int tbDynamicTree_GetProxyCount(const tbDynamicTree* tree)
{
	return tree->proxyCount;
}

int tbDynamicTree_GetByteCount(const tbDynamicTree* tree)
{
	return (int)sizeof(tbDynamicTree) + tree->nodeCapacity * (int)sizeof(tbTreeNode) +
		   tree->rebuildCapacity * TB_REBUILD_ITEM_BYTES;
}

// --------------------------------------------------------------------------------------------
// Statistics and validation

int tbDynamicTree_GetHeight(const tbDynamicTree* tree)
{
	return tree->root == TB_NULL_NODE ? 0 : tree->nodes[tree->root].height;
}

float tbDynamicTree_GetAreaRatio(const tbDynamicTree* tree)
{
	if (tree->root == TB_NULL_NODE)
	{
		return 0.0f;
	}
	float rootPerimeter = tbAABB_Perimeter(tree->nodes[tree->root].aabb);
	float total = 0.0f;
	for (int i = 0; i < tree->nodeCapacity; ++i)
	{
		const tbTreeNode* node = tree->nodes + i;
		if ((node->flags & tb_allocatedNode) != 0 && tbIsLeaf(node) == false)
		{
			total += tbAABB_Perimeter(node->aabb);
		}
	}
	return rootPerimeter > 0.0f ? total / rootPerimeter : 0.0f;
}

/// Check the subtree at index; counts its nodes and leaves. False at the first broken invariant.
static bool tbValidateNode(const tbDynamicTree* tree, int index, int parent, int* nodeCount, int* leafCount)
{
	if (index < 0 || index >= tree->nodeCapacity)
	{
		return false;
	}
	const tbTreeNode* node = tree->nodes + index;
	if (node->parent != parent || (node->flags & tb_allocatedNode) == 0)
	{
		return false;
	}
	*nodeCount += 1;
	if (tbIsLeaf(node))
	{
		*leafCount += 1;
		return node->height == 0;
	}
	if (tbValidateNode(tree, node->children.child1, index, nodeCount, leafCount) == false ||
		tbValidateNode(tree, node->children.child2, index, nodeCount, leafCount) == false)
	{
		return false;
	}
	const tbTreeNode* a = tree->nodes + node->children.child1;
	const tbTreeNode* b = tree->nodes + node->children.child2;
	return node->height == 1 + tbMaxInt(a->height, b->height) && tbAABB_Contains(node->aabb, a->aabb) &&
		   tbAABB_Contains(node->aabb, b->aabb) && node->categoryBits == (a->categoryBits | b->categoryBits);
}

bool tbDynamicTree_ValidateNoEnlarged(const tbDynamicTree* tree)
{
	if (tbDynamicTree_Validate(tree) == false)
	{
		return false;
	}
	for (int i = 0; i < tree->nodeCapacity; ++i)
	{
		if ((tree->nodes[i].flags & (tb_allocatedNode | tb_enlargedNode)) == (tb_allocatedNode | tb_enlargedNode))
		{
			return false;
		}
	}
	return true;
}

bool tbDynamicTree_Validate(const tbDynamicTree* tree)
{
	int nodeCount = 0, leafCount = 0;
	if (tree->root != TB_NULL_NODE && tbValidateNode(tree, tree->root, TB_NULL_NODE, &nodeCount, &leafCount) == false)
	{
		return false;
	}
	int freeCount = 0;
	for (int i = tree->freeList; i != TB_NULL_NODE && freeCount <= tree->nodeCapacity; i = tree->nodes[i].next)
	{
		freeCount += 1;
	}
	return leafCount == tree->proxyCount && nodeCount == tree->nodeCount &&
		   freeCount + nodeCount == tree->nodeCapacity;
}

// --------------------------------------------------------------------------------------------
// Binned SAH rebuild

static void tbReserveRebuild(tbDynamicTree* tree, int count)
{
	if (count <= tree->rebuildCapacity)
	{
		return;
	}
	tbFreeRebuild(tree);
	int n = count + count / 2;
	tree->leafIndices = tbAlloc(n * (int)sizeof(int32_t));
	tree->leafBoxes = tbAlloc(n * (int)sizeof(tbAABB));
	tree->leafCenters = tbAlloc(n * (int)sizeof(tbVec2));
	tree->binIndices = tbAlloc(n * (int)sizeof(int32_t));
	tree->rebuildCapacity = n;
}

/// Bin the leaves [start, start + count) on the axis of largest centroid extent and return the
/// number that go left under the best SAH plane, or 0 when the centroids cannot be separated.
static int tbPartitionBinned(tbDynamicTree* tree, int start, int count)
{
	const tbVec2* centers = tree->leafCenters + start;
	const tbAABB* boxes = tree->leafBoxes + start;
	int32_t* bins = tree->binIndices + start;
	tbVec2 lower = centers[0], upper = lower;
	for (int i = 1; i < count; ++i)
	{
		lower = tbMin(lower, centers[i]);
		upper = tbMax(upper, centers[i]);
	}
	tbVec2 extent = tbSub(upper, lower);
	bool useX = extent.x >= extent.y;
	float minC = useX ? lower.x : lower.y;
	float width = useX ? extent.x : extent.y;
	if (width <= 0.0f)
	{
		return 0;
	}

	// Bin k covers centroids in [minC + k·w/B, minC + (k+1)·w/B). Bin boxes start inverted (empty),
	// so adding a leaf is a plain min/max.
	tbAABB binBoxes[TB_TREE_BIN_COUNT];
	int binCounts[TB_TREE_BIN_COUNT] = {0};
	for (int k = 0; k < TB_TREE_BIN_COUNT; ++k)
	{
		binBoxes[k].lowerBound = tbMakeVec2(FLT_MAX, FLT_MAX);
		binBoxes[k].upperBound = tbMakeVec2(-FLT_MAX, -FLT_MAX);
	}
	float scale = (float)TB_TREE_BIN_COUNT / width;
	for (int i = 0; i < count; ++i)
	{
		float c = useX ? centers[i].x : centers[i].y;
		// Clamp in float before converting: when the centres span more than FLT_MAX the width is
		// infinite, scale is 0 and scale·(c − minC) can be 0·∞ = NaN, which no int can hold
		// (NaN fails the first test and lands in bin 0).
		float position = scale * (c - minC);
		int bin = position > 0.0f ? (position < (float)(TB_TREE_BIN_COUNT - 1) ? (int)position : TB_TREE_BIN_COUNT - 1) : 0;
		bins[i] = bin;
		binBoxes[bin].lowerBound = tbMin(binBoxes[bin].lowerBound, boxes[i].lowerBound);
		binBoxes[bin].upperBound = tbMax(binBoxes[bin].upperBound, boxes[i].upperBound);
		binCounts[bin] += 1;
	}

	// Sweep from the right storing N·P of the right side, then from the left to find the plane.
	float rightCost[TB_TREE_BIN_COUNT];
	tbAABB box = {{0.0f, 0.0f}, {0.0f, 0.0f}};
	int n = 0;
	for (int k = TB_TREE_BIN_COUNT - 1; k > 0; --k)
	{
		if (binCounts[k] > 0)
		{
			box = n == 0 ? binBoxes[k] : tbAABB_Union(box, binBoxes[k]);
			n += binCounts[k];
		}
		rightCost[k] = n > 0 ? (float)n * tbAABB_Perimeter(box) : 0.0f;
	}
	int bestPlane = -1;
	float bestCost = 0.0f;
	n = 0;
	for (int k = 0; k < TB_TREE_BIN_COUNT - 1; ++k)
	{
		if (binCounts[k] > 0)
		{
			box = n == 0 ? binBoxes[k] : tbAABB_Union(box, binBoxes[k]);
			n += binCounts[k];
		}
		if (n == 0 || n == count)
		{
			continue;
		}
		float cost = (float)n * tbAABB_Perimeter(box) + rightCost[k + 1];
		if (bestPlane < 0 || cost < bestCost)
		{
			bestPlane = k;
			bestCost = cost;
		}
	}
	if (bestPlane < 0)
	{
		return 0;
	}

	// Partition in place: bins ≤ bestPlane to the left.
	int left = 0, right = count - 1;
	while (left <= right)
	{
		if (bins[left] <= bestPlane)
		{
			left += 1;
		}
		else
		{
			tbSwapRebuildItems(tree, start + left, start + right);
			bins[left] = bins[right];
			right -= 1;
		}
	}
	return left;
}

/// Split [start, start + count) at the middle of its centroid bounds (lower, upper) on their
/// longer axis, in place, in one pass that also gathers each side's centroid bounds for the next
/// level. Returns the count on the left, 0 when every centroid falls on one side.
static int tbPartitionMid(tbDynamicTree* tree, int start, int count, tbVec2 lower, tbVec2 upper, tbVec2* leftLower,
						  tbVec2* leftUpper, tbVec2* rightLower, tbVec2* rightUpper)
{
	const tbVec2* centers = tree->leafCenters + start;
	tbVec2 extent = tbSub(upper, lower);
	int axis = extent.x >= extent.y ? 0 : 1;
	float split = 0.5f * (axis == 0 ? lower.x + upper.x : lower.y + upper.y);
	tbVec2 lLo = {FLT_MAX, FLT_MAX}, lHi = {-FLT_MAX, -FLT_MAX};
	tbVec2 rLo = lLo, rHi = lHi;
	int left = 0, right = count - 1;
	while (left <= right)
	{
		tbVec2 c = centers[left];
		if ((axis == 0 ? c.x : c.y) < split)
		{
			lLo = tbMin(lLo, c);
			lHi = tbMax(lHi, c);
			left += 1;
		}
		else
		{
			rLo = tbMin(rLo, c);
			rHi = tbMax(rHi, c);
			tbSwapRebuildItems(tree, start + left, start + right);
			right -= 1;
		}
	}
	*leftLower = lLo;
	*leftUpper = lHi;
	*rightLower = rLo;
	*rightUpper = rHi;
	return left;
}

/// Centroid bounds of [start, start + count).
static void tbCentroidBounds(const tbDynamicTree* tree, int start, int count, tbVec2* lower, tbVec2* upper)
{
	const tbVec2* centers = tree->leafCenters + start;
	tbVec2 lo = centers[0], hi = lo;
	for (int i = 1; i < count; ++i)
	{
		lo = tbMin(lo, centers[i]);
		hi = tbMax(hi, centers[i]);
	}
	*lower = lo;
	*upper = hi;
}

/// Build the subtree over leaves [start, start + count) and return its root.
static int tbBuildSubtree(tbDynamicTree* tree, int start, int count, tbVec2 lower, tbVec2 upper)
{
	if (count == 1)
	{
		return tree->leafIndices[start];
	}
	tbVec2 lLo, lHi, rLo, rHi;
	int leftCount;
	if (tree->rebuildSplit == tb_splitMidpoint)
	{
		leftCount = tbPartitionMid(tree, start, count, lower, upper, &lLo, &lHi, &rLo, &rHi);
	}
	else
	{
		leftCount = tbPartitionBinned(tree, start, count);
	}
	if (leftCount == 0 || leftCount == count)
	{
		leftCount = count / 2; // coincident centroids: any balanced split is as good
		if (tree->rebuildSplit == tb_splitMidpoint)
		{
			tbCentroidBounds(tree, start, leftCount, &lLo, &lHi);
			tbCentroidBounds(tree, start + leftCount, count - leftCount, &rLo, &rHi);
		}
	}
	int index = tbAllocateNode(tree);
	int child1 = tbBuildSubtree(tree, start, leftCount, lLo, lHi);
	int child2 = tbBuildSubtree(tree, start + leftCount, count - leftCount, rLo, rHi);
	tbTreeNode* node = tree->nodes + index;
	node->children.child1 = child1;
	node->children.child2 = child2;
	tree->nodes[child1].parent = index;
	tree->nodes[child2].parent = index;
	tbRefitNode(tree, index);
	return index;
}

/// Add one rebuild item: a leaf or a whole subtree kept as it is.
static void tbAddRebuildItem(tbDynamicTree* tree, int index, int itemCount)
{
	tbAABB box = tree->nodes[index].aabb;
	tree->leafIndices[itemCount] = index;
	tree->leafBoxes[itemCount] = box;
	tree->leafCenters[itemCount] = tbAABB_Center(box);
	tree->binIndices[itemCount] = 0;
	tree->nodes[index].flags &= (uint16_t)~tb_enlargedNode;
}

/// Every leaf is an item and every internal node is freed.
static int tbCollectAllLeaves(tbDynamicTree* tree)
{
	int itemCount = 0;
	for (int i = 0; i < tree->nodeCapacity; ++i)
	{
		const tbTreeNode* node = tree->nodes + i;
		if ((node->flags & tb_allocatedNode) == 0)
		{
			continue;
		}
		if (tbIsLeaf(node))
		{
			tbAddRebuildItem(tree, i, itemCount++);
		}
		else
		{
			tbFreeNode(tree, i);
		}
	}
	return itemCount;
}

/// Depth first from the root: an unmarked node (its subtree holds no grown leaf) or a leaf is an
/// item; a marked internal node is freed and its children visited. The order is the tree's own,
/// so the rebuild is deterministic.
static int tbCollectEnlargedItems(tbDynamicTree* tree)
{
	int itemCount = 0;
	tbTreeStack stack;
	tbTreeStackInit(&stack);
	tbTreeStackPush(&stack, tree->root);
	while (stack.count > 0)
	{
		int index = stack.items[--stack.count];
		tbTreeNode* node = tree->nodes + index;
		if ((node->flags & (tb_leafNode | tb_enlargedNode)) != tb_enlargedNode)
		{
			tbAddRebuildItem(tree, index, itemCount++);
			continue;
		}
		tbTreeStackPush(&stack, node->children.child2);
		tbTreeStackPush(&stack, node->children.child1);
		tbFreeNode(tree, index);
	}
	tbTreeStackFree(&stack);
	return itemCount;
}

int tbDynamicTree_Rebuild(tbDynamicTree* tree, bool fullBuild)
{
	if (tree->root == TB_NULL_NODE || (fullBuild == false && (tree->nodes[tree->root].flags & tb_enlargedNode) == 0))
	{
		return 0;
	}
	tbReserveRebuild(tree, tree->proxyCount);
	int itemCount = fullBuild ? tbCollectAllLeaves(tree) : tbCollectEnlargedItems(tree);
	TB_ASSERT(itemCount <= tree->proxyCount);
	tbVec2 lower, upper;
	tbCentroidBounds(tree, 0, itemCount, &lower, &upper);
	tree->root = tbBuildSubtree(tree, 0, itemCount, lower, upper);
	tree->nodes[tree->root].parent = TB_NULL_NODE;
	return itemCount;
}

// --------------------------------------------------------------------------------------------
// Accessors

uint64_t tbDynamicTree_GetUserData(const tbDynamicTree* tree, int proxyId)
{
	TB_ASSERT(0 <= proxyId && proxyId < tree->nodeCapacity);
	return tree->nodes[proxyId].userData;
}

tbAABB tbDynamicTree_GetAABB(const tbDynamicTree* tree, int proxyId)
{
	TB_ASSERT(0 <= proxyId && proxyId < tree->nodeCapacity);
	return tree->nodes[proxyId].aabb;
}

uint64_t tbDynamicTree_GetCategoryBits(tbDynamicTree* tree, int proxyId)
{
	TB_ASSERT(0 <= proxyId && proxyId < tree->nodeCapacity);
	return tree->nodes[proxyId].categoryBits;
}

static void tbVisitNode(const tbDynamicTree* tree, int index, int depth, tbTreeNodeFcn* fcn, void* context)
{
	const tbTreeNode* node = tree->nodes + index;
	fcn(node->aabb, depth, tbIsLeaf(node), context);
	if (tbIsLeaf(node) == false)
	{
		tbVisitNode(tree, node->children.child1, depth + 1, fcn, context);
		tbVisitNode(tree, node->children.child2, depth + 1, fcn, context);
	}
}

void tbDynamicTree_VisitNodes(const tbDynamicTree* tree, tbTreeNodeFcn* fcn, void* context)
{
	if (tree->root != TB_NULL_NODE)
	{
		tbVisitNode(tree, tree->root, 0, fcn, context);
	}
}
