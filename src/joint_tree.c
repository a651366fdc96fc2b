// Joint trees: the equality rows of the joints (a revolute joint's pin, a rigid weld, a prismatic
// joint's line and angle, a wheel joint's line, a rigid distance) solved exactly, all at once, over
// each tree of bodies they join, instead of one row at a time.
//
// Why. Gauss–Seidel passes information one constraint per pass, and a light body between heavy
// ones converges slowly: a chain of 30 light links holding a ball 100 times heavier stretches by
// 10 % or more at 4 sub-steps (Box2D v3 measures 9.6 % on such a set-up). Soft rows keep GS stable,
// but they settle where each row's spring, of stiffness K⁻¹·ω² with K the row's own (light)
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
// Only awake dynamic bodies are nodes; static, kinematic and sleeping bodies are ground, so a rope
// bridge pinned at both ends is one tree. A joint to ground has only one neighbour: as the root
// its body is its child, eliminated before it; but as a leaf its pivot would be the zero block. So
// a tree hangs from one joint to ground when it has one, and the rows of any other joint to
// ground join its body's node, whose pivot becomes [M, −J_gᵀ; −J_g, 0] (invertible while those
// rows are independent; up to three such joints, at most 9 × 9, by Gauss–Jordan with pivoting). Every other joint node then has a body child
// eliminated before it, and its pivot −J·D⁻¹·Jᵀ is definite (closed-form inverse, as the bodies').
// A joint that would close a loop stays with Gauss–Seidel (a spanning tree is solved exactly, the
// loop closed iteratively), as do the fourth and later joints from one body to ground.
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
// pass.
#include "joint.h"

#include <string.h>

#define TB_TREE_MAX_GROUND 3 ///< joints to ground merged into one body node (more stay Gauss–Seidel)
#define TB_TREE_MAX_DIM (3 + 3 * TB_TREE_MAX_GROUND)

/// One node of a tree: a body (unknowns Δv, Δω, then the Δλ of its joints to ground) or a joint
/// between two tree bodies (the Δλ of its rows). Built once per step; the numbers live in the
/// step's float pool at `values` (tbNodeValues). H(node, parent) couples a joint's rows only with
/// its body's three velocity unknowns, so it is stored compactly: r × 3 for a joint node, 3 × r
/// for a body node (r the parent joint's rows).
typedef struct tbTreeNode
{
	int parent; ///< node index of the parent, −1 for the root
	int dim;	///< body: 3 + rows of its ground joints; joint: 1–3
	int body;	///< solver body index (body node), −1 for a joint node
	int joint;	///< joint id (joint node), −1 for a body node
	int side;	///< joint node: side (0 = A, 1 = B) of its parent body; body node: its side in its parent joint
				///< (a tree hanging from a joint to ground has that joint as its root)
	int groundCount;
	int groundJoints[TB_TREE_MAX_GROUND]; ///< body node: its joints to ground
	int groundSides[TB_TREE_MAX_GROUND];  ///< this body's side in each
	int values;							  ///< offset in the float pool
	int rows;							  ///< first of its tbJointRows (joint: 1, body: groundCount)
} tbTreeNode;

typedef struct tbTree
{
	int start, count; ///< nodes [start, start + count), children before parents (the root last)
	bool factored;	  ///< this pass: every pivot block inverted
} tbTree;

// --- small dense blocks (row-major, at most 9 × 9) ----------------------------------------------

/// C (n × m) = Aᵀ·B with A k × n, B k × m.
static void tbMulTN(const float* A, const float* B, float* C, int k, int n, int m)
{
	for (int i = 0; i < n; ++i)
	{
		for (int j = 0; j < m; ++j)
		{
			float sum = 0.0f;
			for (int r = 0; r < k; ++r)
			{
				sum += A[r * n + i] * B[r * m + j];
			}
			C[i * m + j] = sum;
		}
	}
}

/// C (n × m) = A·B with A n × k, B k × m.
static void tbMulNN(const float* A, const float* B, float* C, int n, int k, int m)
{
	for (int i = 0; i < n; ++i)
	{
		for (int j = 0; j < m; ++j)
		{
			float sum = 0.0f;
			for (int r = 0; r < k; ++r)
			{
				sum += A[i * k + r] * B[r * m + j];
			}
			C[i * m + j] = sum;
		}
	}
}

/// Invert a definite block of up to 3 × 3 by cofactors. False when it is singular to float
/// precision: |det| ≤ 1e-6 of the product of the diagonal magnitudes (redundant rows).
static bool tbInvertSmall(float* A, int n)
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
		float a = A[0], b = A[1], c = A[2], d = A[3];
		float det = a * d - b * c;
		if (!(tbAbsFloat(det) > 1e-6f * tbAbsFloat(a * d)))
		{
			return false;
		}
		float inv = 1.0f / det;
		A[0] = d * inv;
		A[1] = -b * inv;
		A[2] = -c * inv;
		A[3] = a * inv;
		return true;
	}
	float c00 = A[4] * A[8] - A[5] * A[7];
	float c01 = A[5] * A[6] - A[3] * A[8];
	float c02 = A[3] * A[7] - A[4] * A[6];
	float det = A[0] * c00 + A[1] * c01 + A[2] * c02;
	if (!(tbAbsFloat(det) > 1e-6f * tbAbsFloat(A[0] * A[4] * A[8])))
	{
		return false;
	}
	float inv = 1.0f / det;
	float B[9] = {c00 * inv,
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

/// Invert a saddle-point block (a body with joints to ground, n ≤ 9) by Gauss–Jordan elimination
/// with partial pivoting: its pivots are of both signs. False when a pivot vanishes against its
/// column (redundant rows).
static bool tbInvertSaddle(float* A, int n)
{
	float inverse[TB_TREE_MAX_DIM * TB_TREE_MAX_DIM];
	memset(inverse, 0, sizeof(float) * (size_t)(n * n));
	for (int i = 0; i < n; ++i)
	{
		inverse[i * n + i] = 1.0f;
	}
	for (int col = 0; col < n; ++col)
	{
		int pivot = col;
		float columnScale = 0.0f;
		for (int row = 0; row < n; ++row)
		{
			float value = tbAbsFloat(A[row * n + col]);
			columnScale = tbMaxFloat(columnScale, value);
			if (row >= col && value > tbAbsFloat(A[pivot * n + col]))
			{
				pivot = row;
			}
		}
		if (!(tbAbsFloat(A[pivot * n + col]) > 1e-7f * columnScale))
		{
			return false;
		}
		if (pivot != col)
		{
			for (int k = 0; k < n; ++k)
			{
				float t = A[col * n + k];
				A[col * n + k] = A[pivot * n + k];
				A[pivot * n + k] = t;
				t = inverse[col * n + k];
				inverse[col * n + k] = inverse[pivot * n + k];
				inverse[pivot * n + k] = t;
			}
		}
		float inv = 1.0f / A[col * n + col];
		for (int k = 0; k < n; ++k)
		{
			A[col * n + k] *= inv;
			inverse[col * n + k] *= inv;
		}
		for (int row = 0; row < n; ++row)
		{
			float factor = A[row * n + col];
			if (row == col || factor == 0.0f)
			{
				continue;
			}
			for (int k = 0; k < n; ++k)
			{
				A[row * n + k] -= factor * A[col * n + k];
				inverse[row * n + k] -= factor * inverse[col * n + k];
			}
		}
	}
	memcpy(A, inverse, sizeof(float) * (size_t)(n * n));
	return true;
}

// --- building the trees (once per step) ---------------------------------------------------------

static bool tbIsTreeBody(const tbStepContext* context, const tbBody* body)
{
	return body->type == tb_dynamicBody && body->awakeIndex != TB_NULL_INDEX && body->awakeIndex < context->bodyCount;
}

static tbTreeNode tbMakeNode(int parent, int dim, int body, int joint, int side)
{
	tbTreeNode node;
	memset(&node, 0, sizeof(node));
	node.parent = parent;
	node.dim = dim;
	node.body = body;
	node.joint = joint;
	node.side = side;
	return node;
}

/// Grow one tree from a root body by depth-first search, appending nodes in preorder (parents
/// before children) from `count` on; returns the new count. bodyNode[solver index] marks the
/// bodies taken and joint->treeNode the joints, by preorder position.
static int tbGrowTree(tbStepContext* context, tbJoint* rootJoint, int rootBodyId, tbTreeNode* order, int count,
					  int* bodyNode, int* stack)
{
	tbWorld* world = context->world;
	const tbBody* root = world->bodies + rootBodyId;
	int top = 0;
	int parent = -1, side = 0;
	if (rootJoint != NULL)
	{
		// A joint to ground as the root: its body is its child, so its pivot is definite.
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
			int side = key & 1;
			key = joint->edges[side].nextKey;
			int rows = tbJointEqualityRowCount(joint);
			if (joint->treeNode != TB_NULL_INDEX || rows == 0)
			{
				continue;
			}
			const tbBody* other = world->bodies + joint->edges[side ^ 1].bodyId;
			tbTreeNode* node = order + bodyNodeIndex;
			if (tbIsTreeBody(context, other) == false)
			{
				if (node->groundCount < TB_TREE_MAX_GROUND)
				{
					joint->treeNode = bodyNodeIndex; // a joint to ground: its rows join this body's node
					node->groundJoints[node->groundCount] = (int)(joint - world->joints);
					node->groundSides[node->groundCount++] = side;
					node->dim += rows;
				}
				continue;
			}
			if (bodyNode[other->awakeIndex] != TB_NULL_INDEX)
			{
				continue; // it closes a loop: Gauss–Seidel
			}
			joint->treeNode = count;
			order[count++] = tbMakeNode(bodyNodeIndex, rows, -1, (int)(joint - world->joints), side);
			bodyNode[other->awakeIndex] = count;
			order[count] = tbMakeNode(count - 1, 3, other->awakeIndex, -1, side ^ 1);
			stack[top++] = count++;
		}
	}
	return count;
}

/// Floats of a node in the pool: D (n²), H, L and x (tbNodeValues).
static int tbNodeFloatCount(const tbTreeNode* node, int parentDim)
{
	int n = node->dim;
	if (node->body < 0)
	{
		return n * n + 3 * n + 3 * n + n; // H, L: r × 3
	}
	return n * n + 3 * parentDim + n * parentDim + n; // H: 3 × r, L: n × r
}

/// Number of tbJointRows a node needs.
static int tbNodeRowCount(const tbTreeNode* node)
{
	return node->joint >= 0 ? 1 : node->groundCount;
}

void tbBuildJointTrees(tbStepContext* context)
{
	tbWorld* world = context->world;
	world->jointTreeCount = 0;
	world->jointTreeNodeCount = 0;
	int jointCount = world->solverJointCount;
	if (jointCount == 0 || world->def.enableJointTrees == false)
	{
		return;
	}
	tbArena* arena = &world->stepArena;
	int maxNodes = context->bodyCount + jointCount;
	tbTreeNode* preorder = tbArenaAlloc(arena, (int)sizeof(tbTreeNode) * maxNodes);
	tbTreeNode* nodes = tbArenaAlloc(arena, (int)sizeof(tbTreeNode) * maxNodes);
	tbTree* trees = tbArenaAlloc(arena, (int)sizeof(tbTree) * jointCount);
	int* bodyNode = tbArenaAlloc(arena, (int)sizeof(int) * (context->bodyCount + 1));
	int* stack = tbArenaAlloc(arena, (int)sizeof(int) * maxNodes);
	for (int i = 0; i <= context->bodyCount; ++i)
	{
		bodyNode[i] = TB_NULL_INDEX;
	}

	// Roots in joint-id order: first the joints to ground (the tree hangs from one of them), then
	// an awake dynamic body of any joint still outside a tree. Each tree is stored in reverse
	// preorder (children before parents), its parent links renumbered to match.
	int count = 0, treeCount = 0;
	for (int pass = 0; pass < 2 * jointCount; ++pass)
	{
		tbJoint* joint = world->joints + world->solverJoints[pass % jointCount];
		if (joint->treeNode != TB_NULL_INDEX || tbJointEqualityRowCount(joint) == 0)
		{
			continue;
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
			continue; // its body is in a tree already (a joint it could not take: loop or fourth to ground)
		}
		int start = count;
		count = tbGrowTree(context, toGround ? joint : NULL, root, preorder, count, bodyNode, stack);
		int n = count - start;
		for (int k = 0; k < n; ++k)
		{
			tbTreeNode node = preorder[start + k];
			node.parent = node.parent < 0 ? -1 : start + (n - 1 - (node.parent - start));
			nodes[start + n - 1 - k] = node;
		}
		trees[treeCount++] = (tbTree){start, n, false};
	}

	// The float pool and the rows, sized node by node.
	int floats = 0, rows = 0;
	for (int i = 0; i < count; ++i)
	{
		tbTreeNode* node = nodes + i;
		node->values = floats;
		floats += tbNodeFloatCount(node, node->parent >= 0 ? nodes[node->parent].dim : 0);
		node->rows = rows;
		rows += tbNodeRowCount(node);
		if (node->joint >= 0)
		{
			world->joints[node->joint].treeNode = i;
		}
		for (int g = 0; g < node->groundCount; ++g)
		{
			world->joints[node->groundJoints[g]].treeNode = i;
		}
	}
	world->jointTreeNodes = nodes;
	world->jointTreeNodeCount = count;
	world->jointTrees = trees;
	world->jointTreeCount = treeCount;
	world->jointTreeValues = tbArenaAlloc(arena, (int)sizeof(float) * floats);
	world->jointTreeRows = tbArenaAlloc(arena, (int)sizeof(tbJointRows) * rows);
}

// --- each pass ----------------------------------------------------------------------------------

/// The numbers of a node: D (n × n, replaced by its inverse), H (compact, see tbTreeNode),
/// L = D⁻¹·H (joint node: r × 3; body node: n × r), x (n: right-hand side, then solution).
typedef struct tbNodeValues
{
	float* D;
	float* H;
	float* L;
	float* x;
} tbNodeValues;

static tbNodeValues tbGetValues(const tbWorld* world, const tbTreeNode* node)
{
	int n = node->dim;
	int r = node->body < 0 ? n : (node->parent >= 0 ? world->jointTreeNodes[node->parent].dim : 0);
	float* base = world->jointTreeValues + node->values;
	int lSize = node->body < 0 ? 3 * n : n * r;
	tbNodeValues v = {base, base + n * n, base + n * n + 3 * r, base + n * n + 3 * r + lSize};
	return v;
}

static bool tbTurns(const tbBody* body)
{
	return body->fixedRotation == false && body->invInertia > 0.0f;
}

/// Row r of a joint's rows against one side: (x, y, angular), the angular part dropped for a body
/// that cannot turn.
static void tbRowAgainst(const tbJointRows* rows, int r, int side, bool turns, float out[3])
{
	const float* J = (side == 0 ? rows->JA : rows->JB) + 3 * r;
	out[0] = J[0];
	out[1] = J[1];
	out[2] = turns ? J[2] : 0.0f;
}

// A joint node: pivot −Γ = 0 (rigid rows); H = −J(joint, parent body), r × 3.
static void tbFillJointNode(const tbWorld* world, const tbTreeNode* node, tbNodeValues v, const tbJointRows* rows)
{
	int n = node->dim;
	memset(v.D, 0, sizeof(float) * (size_t)(n * n));
	if (node->parent < 0)
	{
		return; // a root joint to ground: no parent block
	}
	const tbTreeNode* parent = world->jointTreeNodes + node->parent;
	bool turns = tbTurns(world->bodies + world->awakeBodies[parent->body]);
	for (int r = 0; r < n; ++r)
	{
		float J[3];
		tbRowAgainst(rows, r, node->side, turns, J);
		v.H[3 * r + 0] = -J[0];
		v.H[3 * r + 1] = -J[1];
		v.H[3 * r + 2] = -J[2];
	}
}

// A body node: [M, −J_gᵀ; −J_g, 0] with its ground joints' rows; H = −J(parent joint, body)ᵀ, 3 × r
// (the rows of H for the ground rows are zero and not stored).
static void tbFillBodyNode(const tbWorld* world, const tbTreeNode* node, tbNodeValues v, const tbJointRows* rows)
{
	const tbBody* body = world->bodies + world->awakeBodies[node->body];
	bool turns = tbTurns(body);
	int n = node->dim;
	memset(v.D, 0, sizeof(float) * (size_t)(n * n));
	v.D[0] = 1.0f / body->invMass;
	v.D[n + 1] = v.D[0];
	v.D[2 * n + 2] = turns ? 1.0f / body->invInertia : 1.0f;
	int offset = 3;
	for (int g = 0; g < node->groundCount; ++g)
	{
		int r = tbJointEqualityRowCount(world->joints + node->groundJoints[g]);
		for (int row = 0; row < r; ++row)
		{
			float J[3];
			tbRowAgainst(rows + g, row, node->groundSides[g], turns, J);
			for (int k = 0; k < 3; ++k)
			{
				v.D[(offset + row) * n + k] = -J[k];
				v.D[k * n + offset + row] = -J[k];
			}
		}
		offset += r;
	}
	if (node->parent >= 0)
	{
		const tbTreeNode* parent = world->jointTreeNodes + node->parent;
		const tbJointRows* parentRows = world->jointTreeRows + parent->rows;
		int r = parent->dim;
		for (int row = 0; row < r; ++row)
		{
			float J[3];
			tbRowAgainst(parentRows, row, node->side, turns, J);
			v.H[0 * r + row] = -J[0];
			v.H[1 * r + row] = -J[1];
			v.H[2 * r + row] = -J[2];
		}
	}
}

// L = D⁻¹·H and the parent's pivot update D(p) −= Hᵀ·L, on the compact blocks: a joint child
// touches only its body's 3 × 3 velocity block; a body child's H has only its velocity rows.
static void tbEliminate(const tbTreeNode* node, tbNodeValues v, float* parentD, int m)
{
	int n = node->dim;
	if (node->body < 0)
	{
		tbMulNN(v.D, v.H, v.L, n, n, 3); // r × 3
		float update[9];
		tbMulTN(v.H, v.L, update, n, 3, 3);
		for (int i = 0; i < 3; ++i)
		{
			for (int j = 0; j < 3; ++j)
			{
				parentD[i * m + j] -= update[i * 3 + j];
			}
		}
		return;
	}
	// L (n × m) = D⁻¹(:, 0:3)·H (3 × m); update (m × m) = Hᵀ·L(0:3, :).
	for (int i = 0; i < n; ++i)
	{
		for (int j = 0; j < m; ++j)
		{
			v.L[i * m + j] = v.D[i * n + 0] * v.H[0 * m + j] + v.D[i * n + 1] * v.H[1 * m + j] + v.D[i * n + 2] * v.H[2 * m + j];
		}
	}
	float update[9];
	tbMulTN(v.H, v.L, update, 3, m, m);
	for (int k = 0; k < m * m; ++k)
	{
		parentD[k] -= update[k];
	}
}

// Rows of the current anchors, then H = L·D·Lᵀ children first (the header comment).
static bool tbFactorTree(tbStepContext* context, const tbTree* tree)
{
	tbWorld* world = context->world;
	tbTreeNode* nodes = world->jointTreeNodes;
	for (int i = tree->start; i < tree->start + tree->count; ++i)
	{
		const tbTreeNode* node = nodes + i;
		tbJointRows* rows = world->jointTreeRows + node->rows;
		for (int j = 0; j < tbNodeRowCount(node); ++j)
		{
			tbJoint* joint = world->joints + (node->joint >= 0 ? node->joint : node->groundJoints[j]);
			tbJointBodies b = tbLoadJointBodies(context, joint);
			tbGetJointEqualityRows(joint, &b, rows + j);
		}
	}
	// Fill every node before eliminating any: a child's update lands on its parent's pivot.
	for (int i = tree->start; i < tree->start + tree->count; ++i)
	{
		const tbTreeNode* node = nodes + i;
		if (node->body >= 0)
		{
			tbFillBodyNode(world, node, tbGetValues(world, node), world->jointTreeRows + node->rows);
		}
		else
		{
			tbFillJointNode(world, node, tbGetValues(world, node), world->jointTreeRows + node->rows);
		}
	}
	for (int i = tree->start; i < tree->start + tree->count; ++i)
	{
		const tbTreeNode* node = nodes + i;
		tbNodeValues v = tbGetValues(world, node);
		bool inverted = node->dim <= 3 ? tbInvertSmall(v.D, node->dim) : tbInvertSaddle(v.D, node->dim);
		if (inverted == false)
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

static void tbSetSolvedInTree(tbWorld* world, const tbTreeNode* node, bool solved)
{
	if (node->joint >= 0)
	{
		world->joints[node->joint].solvedInTree = solved;
	}
	for (int g = 0; g < node->groundCount; ++g)
	{
		world->joints[node->groundJoints[g]].solvedInTree = solved;
	}
}

void tbFactorJointTrees(tbStepContext* context)
{
	tbWorld* world = context->world;
	for (int t = 0; t < world->jointTreeCount; ++t)
	{
		world->jointTrees[t].factored = tbFactorTree(context, world->jointTrees + t);
	}
}

void tbMarkTreeRows(tbStepContext* context, bool useBias)
{
	tbWorld* world = context->world;
	for (int t = 0; t < world->jointTreeCount; ++t)
	{
		const tbTree* tree = world->jointTrees + t;
		for (int i = tree->start; i < tree->start + tree->count; ++i)
		{
			tbSetSolvedInTree(world, world->jointTreeNodes + i, useBias && tree->factored);
		}
	}
}

/// J·v + bias for each row of a joint (both sides' velocities, ground included).
static void tbRowResiduals(const tbStepContext* context, const tbJoint* joint, const tbJointRows* rows, int count,
						   float* out)
{
	const tbSolverBody* sA = context->bodies + joint->indexA;
	const tbSolverBody* sB = context->bodies + joint->indexB;
	for (int r = 0; r < count; ++r)
	{
		const float* ja = rows->JA + 3 * r;
		const float* jb = rows->JB + 3 * r;
		out[r] = ja[0] * sA->linearVelocity.x + ja[1] * sA->linearVelocity.y + ja[2] * sA->angularVelocity +
				 jb[0] * sB->linearVelocity.x + jb[1] * sB->linearVelocity.y + jb[2] * sB->angularVelocity +
				 rows->bias[r];
	}
}

/// Right-hand side of a node: 0 for a body's velocity rows, J·v + bias for joint rows.
static void tbLoadResiduals(const tbStepContext* context, const tbTreeNode* node, float* x)
{
	const tbWorld* world = context->world;
	const tbJointRows* rows = world->jointTreeRows + node->rows;
	if (node->joint >= 0)
	{
		tbRowResiduals(context, world->joints + node->joint, rows, node->dim, x);
		return;
	}
	x[0] = x[1] = x[2] = 0.0f;
	int offset = 3;
	for (int g = 0; g < node->groundCount; ++g)
	{
		const tbJoint* joint = world->joints + node->groundJoints[g];
		int r = tbJointEqualityRowCount(joint);
		tbRowResiduals(context, joint, rows + g, r, x + offset);
		offset += r;
	}
}

/// Apply a node's solution: a body's velocity change and the impulses of its rows.
static void tbApplySolution(tbStepContext* context, const tbTreeNode* node, const float* x)
{
	tbWorld* world = context->world;
	const tbJointRows* rows = world->jointTreeRows + node->rows;
	if (node->joint >= 0)
	{
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
	int offset = 3;
	for (int g = 0; g < node->groundCount; ++g)
	{
		int r = tbJointEqualityRowCount(world->joints + node->groundJoints[g]);
		for (int row = 0; row < r; ++row)
		{
			*rows[g].impulse[row] += x[offset + row];
		}
		offset += r;
	}
}

static void tbSolveTree(tbStepContext* context, const tbTree* tree)
{
	tbWorld* world = context->world;
	const tbTreeNode* nodes = world->jointTreeNodes;
	int end = tree->start + tree->count;
	for (int i = tree->start; i < end; ++i)
	{
		tbLoadResiduals(context, nodes + i, tbGetValues(world, nodes + i).x);
	}
	// Forward: x(p) −= L(c)ᵀ·x(c). A joint child's L is r × 3 (the parent's velocity rows only).
	for (int i = tree->start; i < end; ++i)
	{
		const tbTreeNode* node = nodes + i;
		if (node->parent < 0)
		{
			continue;
		}
		tbNodeValues v = tbGetValues(world, node);
		float* parentX = tbGetValues(world, nodes + node->parent).x;
		int m = node->body < 0 ? 3 : nodes[node->parent].dim;
		float update[TB_TREE_MAX_DIM];
		tbMulTN(v.L, v.x, update, node->dim, m, 1);
		for (int k = 0; k < m; ++k)
		{
			parentX[k] -= update[k];
		}
	}
	// Backward from the root: x(c) = D(c)⁻¹·x(c) − L(c)·x(p), then apply it.
	for (int i = end - 1; i >= tree->start; --i)
	{
		const tbTreeNode* node = nodes + i;
		tbNodeValues v = tbGetValues(world, node);
		float y[TB_TREE_MAX_DIM];
		tbMulNN(v.D, v.x, y, node->dim, node->dim, 1);
		if (node->parent >= 0)
		{
			int m = node->body < 0 ? 3 : nodes[node->parent].dim;
			float correction[TB_TREE_MAX_DIM];
			tbMulNN(v.L, tbGetValues(world, nodes + node->parent).x, correction, node->dim, m, 1);
			for (int k = 0; k < node->dim; ++k)
			{
				y[k] -= correction[k];
			}
		}
		memcpy(v.x, y, sizeof(float) * (size_t)node->dim);
		tbApplySolution(context, node, v.x);
	}
}

void tbSolveJointTrees(tbStepContext* context)
{
	tbWorld* world = context->world;
	for (int t = 0; t < world->jointTreeCount; ++t)
	{
		if (world->jointTrees[t].factored)
		{
			tbSolveTree(context, world->jointTrees + t);
		}
	}
}
