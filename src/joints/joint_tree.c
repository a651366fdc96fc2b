// Joint trees: the equality rows of the joints (a revolute joint's pin, a rigid weld, a prismatic
// joint's line and angle, a wheel joint's line, a rigid distance) solved exactly, all at once, over
// each tree of bodies they join, instead of one row at a time.
//
// Why. Gauss–Seidel passes information one constraint per pass, and a light body between heavy
// ones converges slowly: a chain of 30 light links holding a ball 100 times heavier stretches
// visibly at 4 sub-steps, in Box2D v3 as here (docs/methods.md, "Joint trees"). Soft rows keep GS
// stable, but they settle where each row's spring, of stiffness K⁻¹·ω² with K the row's own (light)
// inverse mass, balances the load: the chain sags like a soft spring, and stiffer rows make GS
// unstable. An exact solve needs neither: the rows are rigid (a bias β·C, no compliance), so the
// chain settles at its length.
//
// What is solved. For the equality rows J (Ċ = J·v), with M the body masses, an impulse Δλ changes
// the velocities by Δv = M⁻¹·Jᵀ·Δλ, and the pass wants J·(v + Δv) + bias = 0. As one symmetric
// system in Δv and Δλ (Baraff, "Linear-Time Dynamics using Lagrange Multipliers", SIGGRAPH 1996):
//     [  M   −Jᵀ ] [Δv]   [      0     ]
//     [ −J    0  ] [Δλ] = [ J·v + bias ],
// whose sparsity is the graph of bodies and joints. When that graph is a tree, ordering every node
// after its children and eliminating leaves first makes no fill-in: H = L·D·Lᵀ with one pivot block
// per node and one block per tree edge, so factoring and solving are linear in the bodies:
//     factor (children first):  D(c) ← D(c)⁻¹,  L(c) = D(c)⁻¹·H(c, p),  D(p) −= H(c, p)ᵀ·L(c);
//     solve:  x(p) −= L(c)ᵀ·x(c) children first, then x(c) = D(c)⁻¹·x(c) − L(c)·x(p) from the root.
// Only awake dynamic bodies are nodes; static, kinematic and sleeping bodies are ground. A tree
// touches ground through one joint at most, its root: then every joint's pivot −J·K⁻¹·Jᵀ sees a
// free subtree below it and is definite, as is every body's (M plus definite terms), and the
// blocks are inverted in closed form (at most 3 × 3). A second joint to ground closes a loop
// through the ground (a rope bridge pinned at both ends): eliminated children first, the
// subtree pinned at its far end can only turn about that pin and a pivot becomes singular. Such
// joints, and joints that close a loop between bodies, stay with Gauss–Seidel: the spanning tree is
// solved exactly, the loop closed iteratively.
//
// Per sub-step each tree is factored once with the current anchors (positions change only between
// sub-steps). In each biased pass (tbSolveJoints) the joints' other rows (springs, motors, limits)
// are solved by GS, then each tree for the velocities the pass has reached, with the bias β·C
// (β the joint's positional bias rate: soft step ω/(2ζ + h·ω) from its constraintHertz and
// damping ratio; Baumgarte and NGS TB_BAUMGARTE/h), then the contacts. The relaxing pass solves
// the same rows one at a time, rigid and unbiased (joint.c says why). The accumulated impulses
// are the joints' own, so warm starting and the reported forces are unchanged.
//
// Bodies that cannot turn (fixedRotation) keep a unit angular mass and no angular coupling in the
// tree, so their rotation never changes. A pivot that cannot be inverted (rows made redundant, as
// a prismatic joint between two bodies that cannot turn) leaves that tree to Gauss–Seidel for the
// sub-step.
#include "joint.h"

#include "solver/constraint_graph.h"

#include <float.h>
#include <math.h>
#include <string.h>

/// The factorization and solve run in double precision. Eliminating a heavy body into a light one
/// subtracts nearly equal terms: for a 0.1 kg capsule pinned 60 m from the centre of an 8,171 kg
/// disc (mass ratio 8e4, inertia ratio 5e9) the joint's impulse came out of single precision 29
/// times too large, momentum was not conserved, and the warm start re-applied the error until the
/// velocities were NaN (tests/test_joint.c). The blocks are at most 3 × 3, so doubles cost little;
/// the rows (J, bias) and the velocities stay single precision.
typedef double tbTreeReal;

/// One node of a tree: a body (unknowns Δv, Δω) or a joint (the Δλ of its rows). Built once per
/// step; the numbers live in the step's tbTreeReal pool at `values` (tbNodeValues).
typedef struct tbJointTreeNode
{
	int parent; ///< node index of the parent, −1 for the root
	int dim;	///< body: 3; joint: its rows, 1–3
	int body;	///< solver body index (body node), −1 for a joint node
	int joint;	///< joint id (joint node), −1 for a body node
	int side;	///< joint node: side (0 = A, 1 = B) of its parent body; body node: its side in its parent joint
	int values; ///< offset in the tbTreeReal pool
	int rows;	///< joint node: its tbJointRows in the step's array; −1 for a body node
} tbJointTreeNode;

typedef struct tbTree
{
	int start, count; ///< nodes [start, start + count), children before parents (the root last)
	bool factored;	  ///< this pass: every pivot block inverted
} tbTree;

// --- small dense blocks (row-major, at most 3 × 3) ----------------------------------------------

/// C (n × m) = Aᵀ·B with A k × n, B k × m.
static void tbMulTN(const tbTreeReal* A, const tbTreeReal* B, tbTreeReal* C, int k, int n, int m)
{
	for (int i = 0; i < n; ++i)
	{
		for (int j = 0; j < m; ++j)
		{
			tbTreeReal sum = 0.0f;
			for (int r = 0; r < k; ++r)
			{
				sum += A[r * n + i] * B[r * m + j];
			}
			C[i * m + j] = sum;
		}
	}
}

/// C (n × m) = A·B with A n × k, B k × m.
static void tbMulNN(const tbTreeReal* A, const tbTreeReal* B, tbTreeReal* C, int n, int k, int m)
{
	for (int i = 0; i < n; ++i)
	{
		for (int j = 0; j < m; ++j)
		{
			tbTreeReal sum = 0.0f;
			for (int r = 0; r < k; ++r)
			{
				sum += A[i * k + r] * B[r * m + j];
			}
			C[i * m + j] = sum;
		}
	}
}

/// Invert a definite block of up to 3 × 3 by cofactors. False when it is singular to tbTreeReal
/// precision: |det| ≤ 1e-6 of the product of the diagonal magnitudes (redundant rows).
static bool tbInvertSmall(tbTreeReal* A, int n)
{
	if (n == 1)
	{
		if (A[0] == 0.0f)
		{
			return false;
		}
		A[0] = 1.0f / A[0];
		return true;
	}
	if (n == 2)
	{
		tbTreeReal a = A[0], b = A[1], c = A[2], d = A[3];
		tbTreeReal det = a * d - b * c;
		if (!(fabs(det) > 1e-6 * fabs(a * d)))
		{
			return false;
		}
		tbTreeReal inv = 1.0f / det;
		A[0] = d * inv;
		A[1] = -b * inv;
		A[2] = -c * inv;
		A[3] = a * inv;
		return true;
	}
	tbTreeReal c00 = A[4] * A[8] - A[5] * A[7];
	tbTreeReal c01 = A[5] * A[6] - A[3] * A[8];
	tbTreeReal c02 = A[3] * A[7] - A[4] * A[6];
	tbTreeReal det = A[0] * c00 + A[1] * c01 + A[2] * c02;
	if (!(fabs(det) > 1e-6 * fabs(A[0] * A[4] * A[8])))
	{
		return false;
	}
	tbTreeReal inv = 1.0f / det;
	tbTreeReal B[9] = {c00 * inv,
				  (A[2] * A[7] - A[1] * A[8]) * inv,
				  (A[1] * A[5] - A[2] * A[4]) * inv,
				  c01 * inv,
				  (A[0] * A[8] - A[2] * A[6]) * inv,
				  (A[2] * A[3] - A[0] * A[5]) * inv,
				  c02 * inv,
				  (A[1] * A[6] - A[0] * A[7]) * inv,
				  (A[0] * A[4] - A[1] * A[3]) * inv};
	memcpy(A, B, sizeof(B));
	return true;
}

// --- building the trees (once per step) ---------------------------------------------------------

static bool tbIsTreeBody(const tbStepContext* context, const tbBody* body)
{
	return body->type == tb_dynamicBody && body->awakeIndex != TB_NULL_INDEX && body->awakeIndex < context->bodyCount;
}

static tbJointTreeNode tbMakeNode(int parent, int dim, int body, int joint, int side)
{
	tbJointTreeNode node;
	memset(&node, 0, sizeof(node));
	node.parent = parent;
	node.dim = dim;
	node.body = body;
	node.joint = joint;
	node.side = side;
	node.rows = -1;
	return node;
}

/// Grow one tree by depth-first search from its root (a joint to ground, when it has one, then its
/// body; or a body), appending nodes in preorder (parents before children) from `count` on;
/// returns the new count. bodyNode[solver index] marks the bodies taken and joint->treeNode the
/// joints, by preorder position.
static int tbGrowTree(tbStepContext* context, tbJoint* rootJoint, int rootBodyId, tbJointTreeNode* order, int count,
					  int* bodyNode, int* stack)
{
	tbWorld* world = context->world;
	const tbBody* root = world->bodies + rootBodyId;
	int top = 0;
	int parent = -1, side = 0;
	if (rootJoint != NULL)
	{
		side = rootJoint->edges[0].bodyId == rootBodyId ? 0 : 1;
		rootJoint->treeNode = count;
		order[count] = tbMakeNode(-1, tbJointEqualityRowCount(rootJoint), -1, (int)(rootJoint - world->joints), 0);
		parent = count++;
	}
	order[count] = tbMakeNode(parent, 3, root->awakeIndex, -1, side);
	bodyNode[root->awakeIndex] = count;
	stack[top++] = count++;
	while (top > 0)
	{
		int bodyNodeIndex = stack[--top];
		const tbBody* body = world->bodies + world->awakeBodies[order[bodyNodeIndex].body];
		for (int key = body->headJointKey; key != TB_NULL_INDEX;)
		{
			tbJoint* joint = world->joints + (key >> 1);
			int edge = key & 1;
			key = joint->edges[edge].nextKey;
			const tbBody* other = world->bodies + joint->edges[edge ^ 1].bodyId;
			if (joint->treeNode != TB_NULL_INDEX || tbJointEqualityRowCount(joint) == 0 ||
				tbIsTreeBody(context, other) == false || bodyNode[other->awakeIndex] != TB_NULL_INDEX)
			{
				continue; // taken, no equality rows, or it closes a loop (through ground or not)
			}
			joint->treeNode = count;
			order[count++] = tbMakeNode(bodyNodeIndex, tbJointEqualityRowCount(joint), -1,
										(int)(joint - world->joints), edge);
			bodyNode[other->awakeIndex] = count;
			order[count] = tbMakeNode(count - 1, 3, other->awakeIndex, -1, edge ^ 1);
			stack[top++] = count++;
		}
	}
	return count;
}

/// Where Gauss–Seidel is enough, the exact solve only costs. Soft rows show as sag where a
/// mechanism hangs its weight on its joints (a tree rooted at a joint to ground: a cantilever, a
/// chain, a bridge), and Gauss–Seidel converges slowly along long runs of joints (a correction
/// crosses one joint per pass) and where light bodies carry heavy ones. A free, shallow tree of
/// similar bodies, a ragdoll, carries only its own motion through its joints and converges within
/// the sub-step's passes. So a tree is solved exactly when it is rooted at ground, or a path from
/// its root crosses at least TB_TREE_MIN_DEPTH joints, or its heaviest body is at least
/// TB_TREE_MIN_MASS_RATIO times its lightest. Leaving ragdolls to Gauss–Seidel saves most of what
/// the trees cost in a rain of ragdolls (docs/methods.md), and the ragdoll pile settles as before
/// (tests/test_joint.c).
#define TB_TREE_MIN_DEPTH 6
#define TB_TREE_MIN_MASS_RATIO 10.0f

static bool tbTreeNeedsExactSolve(const tbStepContext* context, const tbJointTreeNode* preorder, int start, int count,
								  int* depth)
{
	const tbWorld* world = context->world;
	float lightest = FLT_MAX, heaviest = 0.0f;
	int deepest = 0;
	for (int k = 0; k < count; ++k)
	{
		// Preorder: a node's parent (an index into preorder) comes before it. depth: joints on the
		// path from the root to the node, itself included.
		const tbJointTreeNode* node = preorder + start + k;
		depth[k] = (node->parent < 0 ? 0 : depth[node->parent - start]) + (node->joint >= 0 ? 1 : 0);
		if (node->joint >= 0)
		{
			deepest = tbMaxInt(deepest, depth[k]);
			continue;
		}
		const tbBody* body = world->bodies + world->awakeBodies[node->body];
		float mass = body->invMass > 0.0f ? 1.0f / body->invMass : FLT_MAX;
		lightest = tbMinFloat(lightest, mass);
		heaviest = tbMaxFloat(heaviest, mass);
	}
	bool grounded = preorder[start].joint >= 0; // rooted at a joint to ground: it hangs on its joints
	return grounded || deepest >= TB_TREE_MIN_DEPTH || heaviest >= TB_TREE_MIN_MASS_RATIO * lightest;
}

/// Floats of a node in the pool: D (n²), H (3 × n or n × 3), L (the same), x (n).
static int tbNodeFloatCount(const tbJointTreeNode* node, int parentDim)
{
	int n = node->dim;
	int r = node->body < 0 ? n : parentDim;
	return n * n + 3 * r + 3 * r + n;
}

void tbBuildJointTrees(tbStepContext* context)
{
	tbWorld* world = context->world;
	world->cache.jointTreeCount = 0;
	world->cache.jointTreeNodeCount = 0;
	int jointCount = world->cache.solverJointCount;
	if (jointCount == 0 || world->def.enableJointTrees == false || context->jointTreeCandidates == 0 ||
		context->jointTreesKnownAbsent)
	{
		return; // no joint can be in a tree (constraint_graph.c counted them), or none was, the joints unchanged
	}
	tbArena* arena = &world->stepArena;
	int maxNodes = context->bodyCount + jointCount;
	tbJointTreeNode* preorder = tbArenaAlloc(arena, (int)sizeof(tbJointTreeNode) * maxNodes);
	tbJointTreeNode* nodes = tbArenaAlloc(arena, (int)sizeof(tbJointTreeNode) * maxNodes);
	tbTree* trees = tbArenaAlloc(arena, (int)sizeof(tbTree) * jointCount);
	int* bodyNode = tbArenaAlloc(arena, (int)sizeof(int) * (context->bodyCount + 1));
	int* stack = tbArenaAlloc(arena, (int)sizeof(int) * maxNodes);
	for (int i = 0; i <= context->bodyCount; ++i)
	{
		bodyNode[i] = TB_NULL_INDEX;
	}

	// Roots in the solve order (joint-id order within a small mechanism): first the joints to ground (the tree hangs from one of them), then
	// an awake dynamic body of any joint still outside a tree. Each tree is stored in reverse
	// preorder (children before parents), its parent links renumbered to match.
	int count = 0, treeCount = 0, rigidPins = 0;
	for (int pass = 0; pass < 2 * jointCount; ++pass)
	{
		tbJoint* joint = world->joints + world->cache.solverJoints[pass % jointCount];
		if (joint->treeNode != TB_NULL_INDEX || joint->loopyMechanism || tbJointEqualityRowCount(joint) == 0)
		{
			continue; // in a tree, in a mechanism left to Gauss–Seidel (constraint_graph.c), or no rows
		}
		bool treeA = tbIsTreeBody(context, world->bodies + joint->edges[0].bodyId);
		bool treeB = tbIsTreeBody(context, world->bodies + joint->edges[1].bodyId);
		bool toGround = treeA != treeB;
		if (pass < jointCount && toGround == false)
		{
			continue;
		}
		int root = treeA ? joint->edges[0].bodyId : joint->edges[1].bodyId;
		if (bodyNode[world->bodies[root].awakeIndex] != TB_NULL_INDEX)
		{
			continue; // its body is in a tree already: the joint closes a loop
		}
		int start = count;
		count = tbGrowTree(context, toGround ? joint : NULL, root, preorder, count, bodyNode, stack);
		int n = count - start;
		// One revolute joint between ground and one body (a flipper, a door, a pendulum): its exact
		// solve is its own 2 × 2 pin solve made rigid (tbSolveRevoluteJoint), with no tree and no
		// symmetric sweep or extra relaxing that trees need.
		bool rigidPin = n == 2 && preorder[start].joint >= 0 && world->joints[preorder[start].joint].type == tb_revoluteJoint;
		if (rigidPin || tbTreeNeedsExactSolve(context, preorder, start, n, stack) == false)
		{
			if (rigidPin)
			{
				world->joints[preorder[start].joint].rigidPin = true;
				rigidPins += 1;
			}
			for (int k = start; k < count; ++k)
			{
				if (preorder[k].joint >= 0)
				{
					world->joints[preorder[k].joint].treeNode = TB_NULL_INDEX;
				}
			}
			count = start; // its bodies stay marked: no other tree is rooted among them
			continue;
		}
		for (int k = 0; k < n; ++k)
		{
			tbJointTreeNode node = preorder[start + k];
			node.parent = node.parent < 0 ? -1 : start + (n - 1 - (node.parent - start));
			nodes[start + n - 1 - k] = node;
		}
		trees[treeCount++] = (tbTree){start, n, false};
	}

	// The tbTreeReal pool and the rows (one per joint node), sized node by node.
	int floats = 0, rows = 0;
	for (int i = 0; i < count; ++i)
	{
		tbJointTreeNode* node = nodes + i;
		node->values = floats;
		floats += tbNodeFloatCount(node, node->parent >= 0 ? nodes[node->parent].dim : 0);
		if (node->joint >= 0)
		{
			node->rows = rows++;
			world->joints[node->joint].treeNode = i;
		}
	}
	world->cache.jointTreeNodes = nodes;
	world->cache.jointTreeNodeCount = count;
	world->cache.jointTrees = trees;
	world->cache.jointTreeCount = treeCount;
	world->cache.jointTreeValues = tbArenaAlloc(arena, (int)sizeof(tbTreeReal) * floats);
	world->cache.jointTreeRows = tbArenaAlloc(arena, (int)sizeof(tbJointRows) * rows);
	tbNoteJointTrees(context, treeCount == 0 && rigidPins == 0);
}

// --- each pass ----------------------------------------------------------------------------------

/// The numbers of a node: D (n × n, replaced by its inverse), H = H(node, parent) stored compactly
/// (a joint's rows couple only with a body's three velocity unknowns: r × 3 for a joint node,
/// 3 × r for a body node under a joint of r rows), L = D⁻¹·H (same shape), x (n: right-hand side,
/// then solution).
typedef struct tbNodeValues
{
	tbTreeReal* D;
	tbTreeReal* H;
	tbTreeReal* L;
	tbTreeReal* x;
} tbNodeValues;

static tbNodeValues tbGetValues(const tbWorld* world, const tbJointTreeNode* node)
{
	int n = node->dim;
	int r = node->body < 0 ? n : (node->parent >= 0 ? world->cache.jointTreeNodes[node->parent].dim : 0);
	tbTreeReal* base = world->cache.jointTreeValues + node->values;
	tbNodeValues v = {base, base + n * n, base + n * n + 3 * r, base + n * n + 6 * r};
	return v;
}

static bool tbTurns(const tbBody* body)
{
	return body->fixedRotation == false && body->invInertia > 0.0f;
}

/// Row r of a joint's rows against one side: (x, y, angular), the angular part dropped for a body
/// that cannot turn.
static void tbRowAgainst(const tbJointRows* rows, int r, int side, bool turns, tbTreeReal out[3])
{
	const float* J = (side == 0 ? rows->JA : rows->JB) + 3 * r;
	out[0] = J[0];
	out[1] = J[1];
	out[2] = turns ? J[2] : 0.0f;
}

// A joint node: pivot −Γ = 0 (rigid rows); H = −J(joint, parent body), r × 3 (a root joint to
// ground has no parent block).
static void tbFillJointNode(const tbWorld* world, const tbJointTreeNode* node, tbNodeValues v)
{
	int n = node->dim;
	memset(v.D, 0, sizeof(tbTreeReal) * (size_t)(n * n));
	if (node->parent < 0)
	{
		return;
	}
	const tbJointTreeNode* parent = world->cache.jointTreeNodes + node->parent;
	bool turns = tbTurns(world->bodies + world->awakeBodies[parent->body]);
	const tbJointRows* rows = world->cache.jointTreeRows + node->rows;
	for (int r = 0; r < n; ++r)
	{
		tbTreeReal J[3];
		tbRowAgainst(rows, r, node->side, turns, J);
		v.H[3 * r + 0] = -J[0];
		v.H[3 * r + 1] = -J[1];
		v.H[3 * r + 2] = -J[2];
	}
}

// A body node: pivot M = diag(m, m, I); H = −J(parent joint, body)ᵀ, 3 × r.
static void tbFillBodyNode(const tbWorld* world, const tbJointTreeNode* node, tbNodeValues v)
{
	const tbBody* body = world->bodies + world->awakeBodies[node->body];
	bool turns = tbTurns(body);
	memset(v.D, 0, sizeof(tbTreeReal) * 9);
	v.D[0] = 1.0f / body->invMass;
	v.D[4] = v.D[0];
	v.D[8] = turns ? 1.0f / body->invInertia : 1.0f;
	if (node->parent < 0)
	{
		return;
	}
	const tbJointTreeNode* parent = world->cache.jointTreeNodes + node->parent;
	const tbJointRows* rows = world->cache.jointTreeRows + parent->rows;
	int r = parent->dim;
	for (int row = 0; row < r; ++row)
	{
		tbTreeReal J[3];
		tbRowAgainst(rows, row, node->side, turns, J);
		v.H[0 * r + row] = -J[0];
		v.H[1 * r + row] = -J[1];
		v.H[2 * r + row] = -J[2];
	}
}

// L = D⁻¹·H and the parent's pivot update D(p) −= Hᵀ·L. A joint child touches only the 3 × 3
// velocity block of its body, which is all a body has.
static void tbEliminate(const tbJointTreeNode* node, tbNodeValues v, tbTreeReal* parentD, int m)
{
	int n = node->dim;
	int k = node->body < 0 ? 3 : m; // columns of H and L
	tbMulNN(v.D, v.H, v.L, n, n, k);
	tbTreeReal update[9];
	tbMulTN(v.H, v.L, update, n, k, k);
	for (int i = 0; i < k * k; ++i)
	{
		parentD[i] -= update[i];
	}
}

// A tree of one joint to ground and one body (a flipper, a door, a pendulum, a weld to the
// ground), nodes [body, joint]: the general elimination written out for its two nodes, the same
// products in the same order (so the same numbers), without the general loops' bounds and
// lookups. Body: D = M⁻¹ (diagonal), L = M⁻¹·H with H = −Jᵀ; joint: D = (0 − Hᵀ·L)⁻¹ = (−K)⁻¹,
// K = J·M⁻¹·Jᵀ.
static bool tbFactorPair(tbWorld* world, const tbJointTreeNode* bodyNode, const tbJointTreeNode* jointNode)
{
	const tbBody* body = world->bodies + world->awakeBodies[bodyNode->body];
	bool turns = tbTurns(body);
	tbNodeValues vb = tbGetValues(world, bodyNode);
	tbNodeValues vj = tbGetValues(world, jointNode);
	const tbJointRows* rows = world->cache.jointTreeRows + jointNode->rows;
	int r = jointNode->dim;
	// M = diag(m, m, I) inverted by tbInvertSmall's cofactors, its zero terms left out.
	tbTreeReal m0 = 1.0f / body->invMass, m1 = m0, m2 = turns ? 1.0f / body->invInertia : 1.0f;
	tbTreeReal c00 = m1 * m2 - 0.0f;
	tbTreeReal det = m0 * c00;
	if (!(fabs(det) > 1e-6 * fabs(m0 * m1 * m2)))
	{
		return false;
	}
	tbTreeReal invDet = 1.0f / det;
	tbTreeReal inverse[3] = {c00 * invDet, (m0 * m2 - 0.0f) * invDet, (m0 * m1 - 0.0f) * invDet};
	for (int row = 0; row < r; ++row)
	{
		tbTreeReal J[3];
		tbRowAgainst(rows, row, bodyNode->side, turns, J);
		for (int c = 0; c < 3; ++c)
		{
			vb.H[c * r + row] = -J[c];
		}
	}
	// L = D·H with D diagonal: the general product's zero terms add nothing (x + 0 = x).
	for (int c = 0; c < 3; ++c)
	{
		for (int j = 0; j < r; ++j)
		{
			tbTreeReal sum = 0.0f;
			sum += inverse[c] * vb.H[c * r + j];
			vb.L[c * r + j] = sum;
		}
	}
	for (int i = 0; i < r; ++i)
	{
		for (int j = 0; j < r; ++j)
		{
			tbTreeReal sum = 0.0f;
			for (int c = 0; c < 3; ++c)
			{
				sum += vb.H[c * r + i] * vb.L[c * r + j];
			}
			vj.D[i * r + j] = 0.0f - sum;
		}
	}
	vb.D[0] = inverse[0];
	vb.D[4] = inverse[1];
	vb.D[8] = inverse[2];
	return tbInvertSmall(vj.D, r);
}

// Rows of the current anchors, then H = L·D·Lᵀ children first (the header comment).
static bool tbFactorTree(tbStepContext* context, const tbTree* tree)
{
	tbWorld* world = context->world;
	tbJointTreeNode* nodes = world->cache.jointTreeNodes;
	int end = tree->start + tree->count;
	for (int i = tree->start; i < end; ++i)
	{
		const tbJointTreeNode* node = nodes + i;
		if (node->joint >= 0)
		{
			tbJoint* joint = world->joints + node->joint;
			tbJointBodies b = tbLoadJointBodies(context, joint);
			tbGetJointEqualityRows(joint, &b, world->cache.jointTreeRows + node->rows);
		}
	}
	if (tree->count == 2)
	{
		return tbFactorPair(world, nodes + tree->start, nodes + tree->start + 1);
	}
	// Fill every node before eliminating any: a child's update lands on its parent's pivot.
	for (int i = tree->start; i < end; ++i)
	{
		const tbJointTreeNode* node = nodes + i;
		if (node->body >= 0)
		{
			tbFillBodyNode(world, node, tbGetValues(world, node));
		}
		else
		{
			tbFillJointNode(world, node, tbGetValues(world, node));
		}
	}
	for (int i = tree->start; i < end; ++i)
	{
		const tbJointTreeNode* node = nodes + i;
		tbNodeValues v = tbGetValues(world, node);
		if (tbInvertSmall(v.D, node->dim) == false)
		{
			return false;
		}
		if (node->parent >= 0)
		{
			tbEliminate(node, v, tbGetValues(world, nodes + node->parent).D, nodes[node->parent].dim);
		}
	}
	return true;
}

void tbFactorJointTrees(tbStepContext* context)
{
	tbWorld* world = context->world;
	for (int t = 0; t < world->cache.jointTreeCount; ++t)
	{
		world->cache.jointTrees[t].factored = tbFactorTree(context, world->cache.jointTrees + t);
	}
}

void tbMarkTreeRows(tbStepContext* context, bool useBias)
{
	tbWorld* world = context->world;
	for (int t = 0; t < world->cache.jointTreeCount; ++t)
	{
		const tbTree* tree = world->cache.jointTrees + t;
		for (int i = tree->start; i < tree->start + tree->count; ++i)
		{
			const tbJointTreeNode* node = world->cache.jointTreeNodes + i;
			if (node->joint >= 0)
			{
				world->joints[node->joint].solvedInTree = useBias && tree->factored;
			}
		}
	}
}

/// Right-hand side of a node: 0 for a body, J·v + bias for a joint's rows (the velocities of both
/// its bodies, ground included).
static void tbLoadResiduals(const tbStepContext* context, const tbJointTreeNode* node, tbTreeReal* x)
{
	const tbWorld* world = context->world;
	if (node->joint < 0)
	{
		x[0] = x[1] = x[2] = 0.0f;
		return;
	}
	const tbJoint* joint = world->joints + node->joint;
	const tbJointRows* rows = world->cache.jointTreeRows + node->rows;
	const tbSolverBody* sA = context->bodies + joint->indexA;
	const tbSolverBody* sB = context->bodies + joint->indexB;
	for (int r = 0; r < node->dim; ++r)
	{
		const float* ja = rows->JA + 3 * r;
		const float* jb = rows->JB + 3 * r;
		x[r] = ja[0] * sA->linearVelocity.x + ja[1] * sA->linearVelocity.y + ja[2] * sA->angularVelocity +
			   jb[0] * sB->linearVelocity.x + jb[1] * sB->linearVelocity.y + jb[2] * sB->angularVelocity + rows->bias[r];
	}
}

/// Apply a node's solution: a body's velocity change, or a joint's impulses.
static void tbApplySolution(tbStepContext* context, const tbJointTreeNode* node, const tbTreeReal* x)
{
	tbWorld* world = context->world;
	if (node->joint >= 0)
	{
		const tbJointRows* rows = world->cache.jointTreeRows + node->rows;
		for (int r = 0; r < node->dim; ++r)
		{
			*rows->impulse[r] += x[r];
		}
		return;
	}
	tbSolverBody* sb = context->bodies + node->body;
	sb->linearVelocity.x += x[0];
	sb->linearVelocity.y += x[1];
	if (tbTurns(world->bodies + world->awakeBodies[node->body]))
	{
		sb->angularVelocity += x[2];
	}
}

/// tbSolveTree for nodes [body, joint] (tbFactorPair): the body's right-hand side is 0, so the
/// forward pass changes nothing; the joint's Δλ = D·(J·v + bias), then the body's Δv = 0 − L·Δλ.
static void tbSolvePair(tbStepContext* context, const tbJointTreeNode* bodyNode, const tbJointTreeNode* jointNode)
{
	tbWorld* world = context->world;
	tbNodeValues vj = tbGetValues(world, jointNode);
	tbNodeValues vb = tbGetValues(world, bodyNode);
	int r = jointNode->dim;
	tbTreeReal x[3];
	tbLoadResiduals(context, jointNode, x);
	for (int i = 0; i < r; ++i)
	{
		tbTreeReal sum = 0.0f;
		for (int j = 0; j < r; ++j)
		{
			sum += vj.D[i * r + j] * x[j];
		}
		vj.x[i] = sum;
	}
	tbApplySolution(context, jointNode, vj.x);
	tbTreeReal dv[3];
	for (int c = 0; c < 3; ++c)
	{
		tbTreeReal sum = 0.0f;
		for (int j = 0; j < r; ++j)
		{
			sum += vb.L[c * r + j] * vj.x[j];
		}
		dv[c] = 0.0f - sum;
	}
	tbApplySolution(context, bodyNode, dv);
}

static void tbSolveTree(tbStepContext* context, const tbTree* tree)
{
	tbWorld* world = context->world;
	const tbJointTreeNode* nodes = world->cache.jointTreeNodes;
	int end = tree->start + tree->count;
	if (tree->count == 2)
	{
		tbSolvePair(context, nodes + tree->start, nodes + tree->start + 1);
		return;
	}
	for (int i = tree->start; i < end; ++i)
	{
		tbLoadResiduals(context, nodes + i, tbGetValues(world, nodes + i).x);
	}
	// Forward: x(p) −= L(c)ᵀ·x(c), children first.
	for (int i = tree->start; i < end; ++i)
	{
		const tbJointTreeNode* node = nodes + i;
		if (node->parent < 0)
		{
			continue;
		}
		tbNodeValues v = tbGetValues(world, node);
		tbTreeReal* parentX = tbGetValues(world, nodes + node->parent).x;
		int m = nodes[node->parent].dim;
		tbTreeReal update[3];
		tbMulTN(v.L, v.x, update, node->dim, m, 1);
		for (int k = 0; k < m; ++k)
		{
			parentX[k] -= update[k];
		}
	}
	// Backward from the root: x(c) = D(c)⁻¹·x(c) − L(c)·x(p), then apply it.
	for (int i = end - 1; i >= tree->start; --i)
	{
		const tbJointTreeNode* node = nodes + i;
		tbNodeValues v = tbGetValues(world, node);
		tbTreeReal y[3];
		tbMulNN(v.D, v.x, y, node->dim, node->dim, 1);
		if (node->parent >= 0)
		{
			tbTreeReal correction[3];
			tbMulNN(v.L, tbGetValues(world, nodes + node->parent).x, correction, node->dim, nodes[node->parent].dim, 1);
			for (int k = 0; k < node->dim; ++k)
			{
				y[k] -= correction[k];
			}
		}
		memcpy(v.x, y, sizeof(tbTreeReal) * (size_t)node->dim);
		tbApplySolution(context, node, v.x);
	}
}

void tbSolveJointTrees(tbStepContext* context)
{
	tbWorld* world = context->world;
	for (int t = 0; t < world->cache.jointTreeCount; ++t)
	{
		if (world->cache.jointTrees[t].factored)
		{
			tbSolveTree(context, world->cache.jointTrees + t);
		}
	}
}
