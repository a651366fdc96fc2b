// Joint trees: the equality rows of the joints (a revolute joint's pin, a rigid weld, a prismatic
// joint's line and angle, a wheel joint's line, a rigid distance) solved exactly, all at once, over
// each tree of bodies they join, instead of one row at a time.
//
// Why. Gauss–Seidel passes information one constraint per pass, and a light body between heavy
// ones converges slowly: a chain of 30 light links holding a ball 100 times heavier stretches by
// 10 % or more at 4 sub-steps (Box2D v3 measures 9.6 % on such a set-up). Soft rows keep GS stable,
// but they settle where each row's spring, of stiffness K⁻¹·ω² with K the row's own (light)
// inverse mass, balances the load: the chain sags like a soft spring. An exact solve needs neither:
// the rows are rigid (bias β·C only, no compliance), so the chain settles at its length.
//
// What is solved. For the equality rows J (the velocity of their error, Ċ = J·v), with M the body
// masses, an impulse Δλ changes the velocities by Δv = M⁻¹·Jᵀ·Δλ, and the pass wants
// J·(v + Δv) + bias = 0. Written as one symmetric system in Δv and Δλ (Baraff, "Linear-Time
// Dynamics using Lagrange Multipliers", SIGGRAPH 1996):
//     [  M   −Jᵀ ] [Δv]   [      0     ]
//     [ −J    0  ] [Δλ] = [ J·v + bias ],
// whose sparsity is the graph of bodies and joints. When that graph is a tree, ordering every node
// after its children and eliminating leaves first makes no fill-in: H = L·D·Lᵀ with one block per
// node (3×3 for a body, 1–3 rows for a joint) and one block per tree edge, so factoring and
// solving are linear in the number of bodies. Only awake dynamic bodies are nodes; a static,
// kinematic or sleeping body is ground (a joint to it is a leaf), so a rope bridge pinned at both
// ends is one tree. A joint that would close a loop stays with Gauss–Seidel (a spanning tree is
// solved exactly, the loop closed iteratively).
//
// Per pass (tbSolveJoints): every tree is factored with the current anchors (positions change
// between passes), then the joints' other rows (springs, motors, limits) are solved by GS, then
// each tree is solved for the velocities the pass has reached, then the contacts. Biased pass:
// bias = β·C with β the joint's positional bias rate (soft step: ω/(2ζ + h·ω) from its
// constraintHertz and damping ratio; Baumgarte and NGS: TB_BAUMGARTE/h); relax pass: no bias, so
// the correction velocity is removed and the rows end each sub-step at Ċ = 0. The accumulated
// impulses are the joints' own, so warm starting and the reported forces are unchanged.
//
// Bodies that cannot turn (fixedRotation) keep a unit angular mass and no angular coupling in the
// tree, so their rotation never changes. A block that cannot be inverted (rows made redundant, as
// a prismatic joint between two bodies that cannot turn) leaves that tree to Gauss–Seidel for the
// pass.
#include "joint.h"

#include "array.h"

#include <string.h>

#define TB_TREE_MAX_GROUND 3 ///< joints to ground merged into one body node (more stay Gauss–Seidel)
#define TB_TREE_MAX_DIM (3 + 3 * TB_TREE_MAX_GROUND)

/// One node of a tree: a body (Δv, Δω, then the Δλ of its joints to ground) or a joint between
/// two tree bodies (the Δλ of its rows).
typedef struct tbTreeNode
{
	int parent; ///< node index of the parent, −1 for the root
	int dim;	///< body: 3 + rows of its ground joints; joint: 1–3
	int body;	///< solver body index (body node), −1 for a joint node
	int joint;	///< joint id (joint node), −1 for a body node
	int side;	///< joint node: side (0 = A, 1 = B) of its parent body; body node: its side in its parent joint
	int groundCount;					 ///< body node: joints to ground in this node
	int groundJoints[TB_TREE_MAX_GROUND]; ///< their ids
	int groundSides[TB_TREE_MAX_GROUND];  ///< this body's side in each
	float D[TB_TREE_MAX_DIM * TB_TREE_MAX_DIM]; ///< the pivot block (dim × dim), replaced by its inverse
	float H[TB_TREE_MAX_DIM * 3];		 ///< H(node, parent): dim × parent dim (one side is a joint: ≤ 3)
	float L[TB_TREE_MAX_DIM * 3];		 ///< D⁻¹·H(node, parent)
	float x[TB_TREE_MAX_DIM];			 ///< right-hand side, then the solution
	tbJointRows rows[TB_TREE_MAX_GROUND]; ///< joint node: rows[0]; body node: one per ground joint
} tbTreeNode;

typedef struct tbTree
{
	int start, count; ///< nodes [start, start + count), children before parents (the root last)
	bool factored;	  ///< this pass: every pivot block inverted
} tbTree;

// --- small dense blocks (row-major, at most 3 × 3) ----------------------------------------------

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

/// Invert an n × n block in place (n ≤ TB_TREE_MAX_DIM) by Gauss–Jordan elimination with partial
/// pivoting (the pivots of a saddle-point block are of both signs). False when a pivot vanishes
/// against its column (singular to float precision: redundant rows).
static bool tbInvertBlock(float* A, int n)
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
		float scale = 0.0f;
		for (int row = col; row < n; ++row)
		{
			float value = tbAbsFloat(A[row * n + col]);
			scale = tbMaxFloat(scale, value);
			pivot = value > tbAbsFloat(A[pivot * n + col]) ? row : pivot;
		}
		float columnScale = 0.0f;
		for (int row = 0; row < n; ++row)
		{
			columnScale = tbMaxFloat(columnScale, tbAbsFloat(A[row * n + col]));
		}
		if (!(scale > 1e-7f * columnScale) || scale == 0.0f)
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

static tbTreeNode tbMakeBodyNode(int parent, int bodyIndex, int side)
{
	tbTreeNode node;
	memset(&node, 0, sizeof(node));
	node.parent = parent;
	node.dim = 3;
	node.body = bodyIndex;
	node.joint = -1;
	node.side = side;
	return node;
}

/// Grow one tree from a root body by depth-first search, appending nodes in preorder (parents
/// before children) to `order`; returns the new count. bodyNode[solver index] marks the bodies
/// taken, joint->treeNode the joints (as positions in `order`).
static int tbGrowTree(tbStepContext* context, int rootBodyId, tbTreeNode* order, int count, int* bodyNode, int* stack)
{
	tbWorld* world = context->world;
	const tbBody* root = world->bodies + rootBodyId;
	int top = 0;
	order[count] = tbMakeBodyNode(-1, root->awakeIndex, 0);
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
					// A joint to ground: its rows join this body's node.
					joint->treeNode = bodyNodeIndex;
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
			tbTreeNode jointNode = tbMakeBodyNode(bodyNodeIndex, -1, side);
			jointNode.dim = rows;
			jointNode.joint = (int)(joint - world->joints);
			order[count++] = jointNode;
			bodyNode[other->awakeIndex] = count;
			order[count] = tbMakeBodyNode(count - 1, other->awakeIndex, side ^ 1);
			stack[top++] = count++;
		}
	}
	return count;
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
	int maxNodes = context->bodyCount + jointCount;
	tbArena* arena = &world->stepArena;
	tbTreeNode* preorder = tbArenaAlloc(arena, (int)sizeof(tbTreeNode) * maxNodes);
	int* bodyNode = tbArenaAlloc(arena, (int)sizeof(int) * (context->bodyCount + 1));
	int* stack = tbArenaAlloc(arena, (int)sizeof(int) * maxNodes);
	for (int i = 0; i <= context->bodyCount; ++i)
	{
		bodyNode[i] = TB_NULL_INDEX;
	}
	TB_ARRAY_RESERVE(world->jointTreeNodes, world->jointTreeNodeCapacity, maxNodes);
	TB_ARRAY_RESERVE(world->jointTrees, world->jointTreeCapacity, jointCount);
	tbTreeNode* nodes = world->jointTreeNodes;

	// Roots in joint-id order: the first awake dynamic body of a joint not yet in a tree.
	int count = 0;
	for (int i = 0; i < jointCount; ++i)
	{
		const tbJoint* joint = world->joints + world->solverJoints[i];
		if (joint->treeNode != TB_NULL_INDEX || tbJointEqualityRowCount(joint) == 0)
		{
			continue;
		}
		const tbBody* a = world->bodies + joint->edges[0].bodyId;
		int root = tbIsTreeBody(context, a) ? joint->edges[0].bodyId : joint->edges[1].bodyId;
		if (bodyNode[world->bodies[root].awakeIndex] != TB_NULL_INDEX)
		{
			continue;
		}
		int start = count;
		count = tbGrowTree(context, root, preorder, count, bodyNode, stack);
		// Reverse preorder: children before parents. Parent links are renumbered to match.
		int n = count - start;
		for (int k = 0; k < n; ++k)
		{
			tbTreeNode node = preorder[start + k];
			int parent = node.parent;
			node.parent = parent < 0 ? -1 : start + (n - 1 - (parent - start));
			nodes[start + n - 1 - k] = node;
		}
		tbTree tree = {start, n, false};
		world->jointTrees[world->jointTreeCount++] = tree;
	}
	world->jointTreeNodeCount = count;
	for (int i = 0; i < count; ++i)
	{
		if (nodes[i].joint >= 0)
		{
			world->joints[nodes[i].joint].treeNode = i;
		}
		for (int g = 0; g < nodes[i].groundCount; ++g)
		{
			world->joints[nodes[i].groundJoints[g]].treeNode = i;
		}
	}
}

// --- each pass ----------------------------------------------------------------------------------

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

// The pivot blocks before elimination, D = H(node, node), and H(node, parent).
static void tbFillTree(tbStepContext* context, tbTreeNode* nodes, int start, int count)
{
	tbWorld* world = context->world;
	for (int i = start; i < start + count; ++i)
	{
		tbTreeNode* node = nodes + i;
		int n = node->dim;
		memset(node->D, 0, sizeof(float) * (size_t)(n * n));
		if (node->body < 0)
		{
			// Joint node: pivot −Γ = 0 (rigid rows); H(joint, body) = −J(joint, body), r × parent dim.
			const tbTreeNode* parent = nodes + node->parent;
			const tbBody* body = world->bodies + world->awakeBodies[parent->body];
			bool turns = tbTurns(body);
			memset(node->H, 0, sizeof(float) * (size_t)(n * parent->dim));
			for (int r = 0; r < n; ++r)
			{
				float J[3];
				tbRowAgainst(&node->rows[0], r, node->side, turns, J);
				for (int k = 0; k < 3; ++k)
				{
					node->H[r * parent->dim + k] = -J[k];
				}
			}
			continue;
		}
		// Body node: [M, −J_gᵀ; −J_g, 0] with its ground joints' rows.
		const tbBody* body = world->bodies + world->awakeBodies[node->body];
		bool turns = tbTurns(body);
		node->D[0] = 1.0f / body->invMass;
		node->D[n + 1] = node->D[0];
		node->D[2 * n + 2] = turns ? 1.0f / body->invInertia : 1.0f;
		int offset = 3;
		for (int g = 0; g < node->groundCount; ++g)
		{
			const tbJointRows* rows = node->rows + g;
			int r = tbJointEqualityRowCount(world->joints + node->groundJoints[g]);
			for (int row = 0; row < r; ++row)
			{
				float J[3];
				tbRowAgainst(rows, row, node->groundSides[g], turns, J);
				for (int k = 0; k < 3; ++k)
				{
					node->D[(offset + row) * n + k] = -J[k];
					node->D[k * n + offset + row] = -J[k];
				}
			}
			offset += r;
		}
		if (node->parent >= 0)
		{
			// H(body, joint) = −J(joint, body)ᵀ in the body's first three rows, dim × r.
			const tbTreeNode* parent = nodes + node->parent;
			int r = parent->dim;
			memset(node->H, 0, sizeof(float) * (size_t)(n * r));
			for (int row = 0; row < r; ++row)
			{
				float J[3];
				tbRowAgainst(&parent->rows[0], row, node->side, turns, J);
				for (int k = 0; k < 3; ++k)
				{
					node->H[k * r + row] = -J[k];
				}
			}
		}
	}
}

// H = L·D·Lᵀ, children before parents: D(p) −= H(c, p)ᵀ·D(c)⁻¹·H(c, p) for each child c.
static bool tbFactorTree(tbTreeNode* nodes, int start, int count)
{
	for (int i = start; i < start + count; ++i)
	{
		tbTreeNode* node = nodes + i;
		if (tbInvertBlock(node->D, node->dim) == false)
		{
			return false;
		}
		if (node->parent < 0)
		{
			continue;
		}
		tbTreeNode* parent = nodes + node->parent;
		int n = node->dim, m = parent->dim;
		tbMulNN(node->D, node->H, node->L, n, n, m);
		float update[TB_TREE_MAX_DIM * TB_TREE_MAX_DIM];
		tbMulTN(node->H, node->L, update, n, m, m);
		for (int k = 0; k < m * m; ++k)
		{
			parent->D[k] -= update[k];
		}
	}
	return true;
}

// Forward: x(p) −= L(c)ᵀ·x(c); then backward from the root: x(c) = D(c)⁻¹·x(c) − L(c)·x(p).
static void tbSolveTree(tbTreeNode* nodes, int start, int count)
{
	for (int i = start; i < start + count; ++i)
	{
		const tbTreeNode* node = nodes + i;
		if (node->parent >= 0)
		{
			tbTreeNode* parent = nodes + node->parent;
			float update[TB_TREE_MAX_DIM];
			tbMulTN(node->L, node->x, update, node->dim, parent->dim, 1);
			for (int k = 0; k < parent->dim; ++k)
			{
				parent->x[k] -= update[k];
			}
		}
	}
	for (int i = start + count - 1; i >= start; --i)
	{
		tbTreeNode* node = nodes + i;
		float y[TB_TREE_MAX_DIM];
		tbMulNN(node->D, node->x, y, node->dim, node->dim, 1);
		if (node->parent >= 0)
		{
			const tbTreeNode* parent = nodes + node->parent;
			float correction[TB_TREE_MAX_DIM];
			tbMulNN(node->L, parent->x, correction, node->dim, parent->dim, 1);
			for (int k = 0; k < node->dim; ++k)
			{
				y[k] -= correction[k];
			}
		}
		memcpy(node->x, y, sizeof(float) * (size_t)node->dim);
	}
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

void tbFactorJointTrees(tbStepContext* context, bool useBias)
{
	tbWorld* world = context->world;
	tbTreeNode* nodes = world->jointTreeNodes;
	for (int t = 0; t < world->jointTreeCount; ++t)
	{
		tbTree* tree = world->jointTrees + t;
		for (int i = tree->start; i < tree->start + tree->count; ++i)
		{
			tbTreeNode* node = nodes + i;
			int jointCount = node->joint >= 0 ? 1 : node->groundCount;
			for (int j = 0; j < jointCount; ++j)
			{
				tbJoint* joint = world->joints + (node->joint >= 0 ? node->joint : node->groundJoints[j]);
				tbJointBodies b = tbLoadJointBodies(context, joint);
				tbGetJointEqualityRows(joint, &b, node->rows + j, useBias);
			}
		}
		tbFillTree(context, nodes, tree->start, tree->count);
		tree->factored = tbFactorTree(nodes, tree->start, tree->count);
		for (int i = tree->start; i < tree->start + tree->count; ++i)
		{
			tbSetSolvedInTree(world, nodes + i, tree->factored);
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

/// Right-hand side of a node: body rows 0; joint rows J·v + bias.
static void tbLoadResiduals(const tbStepContext* context, tbTreeNode* node)
{
	const tbWorld* world = context->world;
	if (node->joint >= 0)
	{
		tbRowResiduals(context, world->joints + node->joint, node->rows, node->dim, node->x);
		return;
	}
	node->x[0] = node->x[1] = node->x[2] = 0.0f;
	int offset = 3;
	for (int g = 0; g < node->groundCount; ++g)
	{
		const tbJoint* joint = world->joints + node->groundJoints[g];
		int r = tbJointEqualityRowCount(joint);
		tbRowResiduals(context, joint, node->rows + g, r, node->x + offset);
		offset += r;
	}
}

/// Apply a node's solution: a body's velocity change and the impulses of its rows.
static void tbApplySolution(tbStepContext* context, const tbTreeNode* node)
{
	tbWorld* world = context->world;
	if (node->joint >= 0)
	{
		for (int r = 0; r < node->dim; ++r)
		{
			*node->rows[0].impulse[r] += node->x[r];
		}
		return;
	}
	tbSolverBody* sb = context->bodies + node->body;
	sb->linearVelocity.x += node->x[0];
	sb->linearVelocity.y += node->x[1];
	if (tbTurns(world->bodies + world->awakeBodies[node->body]))
	{
		sb->angularVelocity += node->x[2];
	}
	int offset = 3;
	for (int g = 0; g < node->groundCount; ++g)
	{
		int r = tbJointEqualityRowCount(world->joints + node->groundJoints[g]);
		for (int row = 0; row < r; ++row)
		{
			*node->rows[g].impulse[row] += node->x[offset + row];
		}
		offset += r;
	}
}

void tbSolveJointTrees(tbStepContext* context)
{
	tbWorld* world = context->world;
	tbTreeNode* nodes = world->jointTreeNodes;
	for (int t = 0; t < world->jointTreeCount; ++t)
	{
		const tbTree* tree = world->jointTrees + t;
		if (tree->factored == false)
		{
			continue;
		}
		for (int i = tree->start; i < tree->start + tree->count; ++i)
		{
			tbLoadResiduals(context, nodes + i);
		}
		tbSolveTree(nodes, tree->start, tree->count);
		for (int i = tree->start; i < tree->start + tree->count; ++i)
		{
			tbApplySolution(context, nodes + i);
		}
	}
}

void tbFreeJointTrees(tbWorld* world)
{
	TB_ARRAY_FREE(world->jointTreeNodes, world->jointTreeNodeCapacity);
	TB_ARRAY_FREE(world->jointTrees, world->jointTreeCapacity);
}
