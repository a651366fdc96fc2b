// Dynamic AABB tree: structure (Validate) under random edits, balance (height bounds), queries and
// ray casts against brute-force scans, the binned SAH rebuild, mask pruning and memory.
#include <criterion/criterion.h>

#include "tumble/collision.h"
#include "test_helpers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

// Linear congruential generator, constants from Numerical Recipes (Press et al., §7.1):
// x ← 1664525·x + 1013904223 mod 2^32.
static uint32_t s_seed = 12345u;

static tbAABB RandomBox(float range, float minSize, float maxSize)
{
	float x = RandomFloat(&s_seed, -range, range), y = RandomFloat(&s_seed, -range, range);
	float w = RandomFloat(&s_seed, minSize, maxSize), h = RandomFloat(&s_seed, minSize, maxSize);
	return (tbAABB){{x, y}, {x + w, y + h}};
}

#define MAX_PROXIES 2048

typedef struct Collector
{
	int ids[MAX_PROXIES];
	int count;
} Collector;

static bool CollectCallback(int proxyId, uint64_t userData, void* context)
{
	(void)userData;
	Collector* c = context;
	c->ids[c->count++] = proxyId;
	return true;
}

/// Tree query results (sorted) must equal a scan over all proxies.
static void CheckQuery(const tbDynamicTree* tree, const int* ids, const tbAABB* boxes, const uint64_t* bits, int count,
					   tbAABB query, uint64_t mask)
{
	static Collector fromTree, fromScan;
	fromTree.count = 0;
	fromScan.count = 0;
	tbDynamicTree_Query(tree, query, mask, CollectCallback, &fromTree);
	for (int i = 0; i < count; ++i)
	{
		if (ids[i] >= 0 && (bits[i] & mask) != 0 && tbAABB_Overlaps(boxes[i], query))
		{
			fromScan.ids[fromScan.count++] = ids[i];
		}
	}
	qsort(fromTree.ids, (size_t)fromTree.count, sizeof(int), CompareInts);
	qsort(fromScan.ids, (size_t)fromScan.count, sizeof(int), CompareInts);
	cr_assert_eq(fromTree.count, fromScan.count, "query found %d proxies, scan %d", fromTree.count, fromScan.count);
	cr_assert(memcmp(fromTree.ids, fromScan.ids, (size_t)fromTree.count * sizeof(int)) == 0);
}

Test(dynamic_tree, validate_after_random_insert_move_remove)
{
	s_seed = 1u;
	tbDynamicTree tree = tbDynamicTree_Create(0);
	static int ids[MAX_PROXIES];
	int count = 0;
	for (int i = 0; i < 300; ++i)
	{
		ids[count++] = tbDynamicTree_CreateProxy(&tree, RandomBox(50.0f, 0.5f, 5.0f), 1, i);
	}
	cr_assert(tbDynamicTree_Validate(&tree));
	for (int step = 0; step < 3000; ++step)
	{
		int i = (int)RandomFloat(&s_seed, 0.0f, (float)count);
		float op = RandomFloat(&s_seed, 0.0f, 1.0f);
		if (op < 0.5f && ids[i] >= 0)
		{
			tbDynamicTree_MoveProxy(&tree, ids[i], RandomBox(50.0f, 0.5f, 5.0f));
		}
		else if (op < 0.75f && ids[i] >= 0)
		{
			tbDynamicTree_DestroyProxy(&tree, ids[i]);
			ids[i] = -1;
		}
		else if (op < 0.9f && ids[i] >= 0)
		{
			tbAABB box = tbDynamicTree_GetAABB(&tree, ids[i]);
			tbDynamicTree_EnlargeProxy(&tree, ids[i], tbAABB_Fatten(box, 1.0f));
		}
		else if (ids[i] < 0)
		{
			ids[i] = tbDynamicTree_CreateProxy(&tree, RandomBox(50.0f, 0.5f, 5.0f), 1, i);
		}
		if (step % 97 == 0)
		{
			tbDynamicTree_Rebuild(&tree, step % 2 == 0);
		}
		cr_assert(tbDynamicTree_Validate(&tree), "invalid after step %d", step);
	}
	tbDynamicTree_Destroy(&tree);
}

Test(dynamic_tree, height_of_row_and_grid)
{
	// Acceptance: height < 2·log2(n) after inserting a row of 200 unit boxes (15.3) and a 20×20
	// grid (17.3), and < 3·log2(n) after moving every proxy of the grid (25.9). An AVL-balanced
	// tree stays below 1.44·log2(n + 2) (Knuth, TAOCP vol. 3, §6.2.3).
	tbDynamicTree row = tbDynamicTree_Create(0);
	for (int i = 0; i < 200; ++i)
	{
		tbAABB box = {{(float)i, 0.0f}, {(float)i + 1.0f, 1.0f}};
		tbDynamicTree_CreateProxy(&row, box, 1, i);
	}
	cr_assert(tbDynamicTree_Validate(&row));
	int rowHeight = tbDynamicTree_GetHeight(&row);
	cr_assert_lt((float)rowHeight, 2.0f * log2f(200.0f), "row height %d", rowHeight);
	tbDynamicTree_Destroy(&row);

	tbDynamicTree grid = tbDynamicTree_Create(0);
	int ids[400];
	for (int i = 0; i < 20; ++i)
	{
		for (int j = 0; j < 20; ++j)
		{
			tbAABB box = {{(float)i, (float)j}, {(float)i + 1.0f, (float)j + 1.0f}};
			ids[20 * i + j] = tbDynamicTree_CreateProxy(&grid, box, 1, 20 * i + j);
		}
	}
	cr_assert(tbDynamicTree_Validate(&grid));
	int gridHeight = tbDynamicTree_GetHeight(&grid);
	cr_assert_lt((float)gridHeight, 2.0f * log2f(400.0f), "grid height %d", gridHeight);

	for (int k = 0; k < 400; ++k)
	{
		tbAABB box = tbDynamicTree_GetAABB(&grid, ids[k]);
		tbVec2 shift = {0.3f, -0.2f};
		tbDynamicTree_MoveProxy(&grid, ids[k], (tbAABB){tbAdd(box.lowerBound, shift), tbAdd(box.upperBound, shift)});
	}
	cr_assert(tbDynamicTree_Validate(&grid));
	int movedHeight = tbDynamicTree_GetHeight(&grid);
	cr_assert_lt((float)movedHeight, 3.0f * log2f(400.0f), "moved grid height %d", movedHeight);
	cr_log_info("heights: row %d, grid %d, moved grid %d; area ratio %g", rowHeight, gridHeight, movedHeight,
				(double)tbDynamicTree_GetAreaRatio(&grid));
	tbDynamicTree_Destroy(&grid);
}

Test(dynamic_tree, query_matches_brute_force)
{
	s_seed = 7u;
	tbDynamicTree tree = tbDynamicTree_Create(0);
	static int ids[1000];
	static tbAABB boxes[1000];
	static uint64_t bits[1000];
	for (int i = 0; i < 1000; ++i)
	{
		boxes[i] = RandomBox(100.0f, 0.2f, 8.0f);
		bits[i] = 1;
		ids[i] = tbDynamicTree_CreateProxy(&tree, boxes[i], 1, i);
	}
	for (int q = 0; q < 200; ++q)
	{
		CheckQuery(&tree, ids, boxes, bits, 1000, RandomBox(100.0f, 0.1f, 30.0f), 1);
	}
	tbDynamicTree_Destroy(&tree);
}

/// Exact ray–box hit fraction by slabs (Kay & Kajiya 1986), or −1 when missed.
static float RayBoxFraction(const tbRayCastInput* input, tbAABB box)
{
	float t0 = 0.0f, t1 = input->maxFraction;
	float p[2] = {input->origin.x, input->origin.y};
	float d[2] = {input->translation.x, input->translation.y};
	float lo[2] = {box.lowerBound.x, box.lowerBound.y};
	float hi[2] = {box.upperBound.x, box.upperBound.y};
	for (int k = 0; k < 2; ++k)
	{
		if (d[k] == 0.0f)
		{
			if (p[k] < lo[k] || p[k] > hi[k])
			{
				return -1.0f;
			}
			continue;
		}
		float a = (lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
		t0 = fmaxf(t0, fminf(a, b));
		t1 = fminf(t1, fmaxf(a, b));
		if (t0 > t1)
		{
			return -1.0f;
		}
	}
	return t0;
}

typedef struct RayContext
{
	const tbDynamicTree* tree;
	float closest;
	int closestId;
	int calls;
} RayContext;

static float ClosestRayCallback(const tbRayCastInput* input, int proxyId, uint64_t userData, void* context)
{
	(void)userData;
	RayContext* c = context;
	c->calls += 1;
	float t = RayBoxFraction(input, tbDynamicTree_GetAABB(c->tree, proxyId));
	if (t <= 0.0f)
	{
		return input->maxFraction; // missed (or starts inside): leave the ray as it is
	}
	if (t < c->closest)
	{
		c->closest = t;
		c->closestId = proxyId;
	}
	return t; // clip: nothing farther can be the closest
}

Test(dynamic_tree, ray_cast_closest_matches_brute_force)
{
	s_seed = 99u;
	tbDynamicTree tree = tbDynamicTree_Create(0);
	static tbAABB boxes[800];
	static int ids[800];
	for (int i = 0; i < 800; ++i)
	{
		boxes[i] = RandomBox(100.0f, 0.5f, 6.0f);
		ids[i] = tbDynamicTree_CreateProxy(&tree, boxes[i], 1, i);
	}
	for (int r = 0; r < 200; ++r)
	{
		tbVec2 origin = {RandomFloat(&s_seed, -120.0f, 120.0f), RandomFloat(&s_seed, -120.0f, 120.0f)};
		tbVec2 target = {RandomFloat(&s_seed, -120.0f, 120.0f), RandomFloat(&s_seed, -120.0f, 120.0f)};
		tbRayCastInput input = {origin, tbSub(target, origin), 1.0f};
		RayContext c = {&tree, 2.0f, -1, 0};
		tbDynamicTree_RayCast(&tree, &input, 1, ClosestRayCallback, &c);

		float best = 2.0f;
		for (int i = 0; i < 800; ++i)
		{
			float t = RayBoxFraction(&input, boxes[i]);
			if (t > 0.0f && t < best)
			{
				best = t;
			}
		}
		if (best <= 1.0f)
		{
			cr_assert_float_eq(c.closest, best, 1e-6f, "ray %d: tree %g, scan %g", r, (double)c.closest, (double)best);
		}
		else
		{
			cr_assert(c.closest > 1.0f, "ray %d: tree hit %g but scan none", r, (double)c.closest);
		}
	}
	(void)ids;
	tbDynamicTree_Destroy(&tree);
}

static float StopRayCallback(const tbRayCastInput* input, int proxyId, uint64_t userData, void* context)
{
	(void)input;
	(void)proxyId;
	(void)userData;
	*(int*)context += 1;
	return 0.0f;
}

Test(dynamic_tree, ray_cast_zero_stops)
{
	tbDynamicTree tree = tbDynamicTree_Create(0);
	for (int i = 0; i < 10; ++i)
	{
		tbDynamicTree_CreateProxy(&tree, (tbAABB){{(float)i * 2.0f, -1.0f}, {(float)i * 2.0f + 1.0f, 1.0f}}, 1, i);
	}
	tbRayCastInput input = {{-5.0f, 0.0f}, {30.0f, 0.0f}, 1.0f};
	int calls = 0;
	tbDynamicTree_RayCast(&tree, &input, 1, StopRayCallback, &calls);
	cr_assert_eq(calls, 1);
	tbDynamicTree_Destroy(&tree);
}

Test(dynamic_tree, rebuild_is_valid_and_queries_match)
{
	s_seed = 2024u;
	tbDynamicTree tree = tbDynamicTree_Create(0);
	static int ids[1000];
	static tbAABB boxes[1000];
	static uint64_t bits[1000];
	for (int i = 0; i < 1000; ++i)
	{
		boxes[i] = RandomBox(200.0f, 0.3f, 3.0f);
		bits[i] = (uint64_t)1 << (i % 3);
		ids[i] = tbDynamicTree_CreateProxy(&tree, boxes[i], bits[i], i);
	}
	// Remove a few so the node array has holes.
	for (int i = 0; i < 1000; i += 7)
	{
		tbDynamicTree_DestroyProxy(&tree, ids[i]);
		ids[i] = -1;
	}
	int leaves = tbDynamicTree_Rebuild(&tree, true);
	cr_assert_eq(leaves, tree.proxyCount);
	cr_assert(tbDynamicTree_Validate(&tree));
	for (int i = 0; i < 1000; ++i)
	{
		if (ids[i] >= 0)
		{
			cr_assert_eq(tbDynamicTree_GetUserData(&tree, ids[i]), i);
			cr_assert_eq(tbDynamicTree_GetCategoryBits(&tree, ids[i]), bits[i]);
		}
	}
	for (int q = 0; q < 200; ++q)
	{
		CheckQuery(&tree, ids, boxes, bits, 1000, RandomBox(200.0f, 1.0f, 40.0f), 7);
	}
	cr_log_info("rebuilt height %d, area ratio %g", tbDynamicTree_GetHeight(&tree),
				(double)tbDynamicTree_GetAreaRatio(&tree));
	// Edits after a rebuild keep the tree valid.
	for (int i = 1; i < 1000; i += 5)
	{
		if (ids[i] >= 0)
		{
			boxes[i] = RandomBox(200.0f, 0.3f, 3.0f);
			tbDynamicTree_MoveProxy(&tree, ids[i], boxes[i]);
		}
	}
	cr_assert(tbDynamicTree_Validate(&tree));
	CheckQuery(&tree, ids, boxes, bits, 1000, RandomBox(200.0f, 50.0f, 100.0f), 7);
	tbDynamicTree_Destroy(&tree);
}

// A partial rebuild places only the grown leaves and the whole subtrees beside their paths:
// k grown leaves in a tree of height h give at most k·(h + 1) items (each path from the root has
// h + 1 nodes and contributes one sibling subtree per level), and far fewer than the n leaves of
// a full rebuild. The tree it gives must answer queries exactly as brute force does, and place
// the moved leaves about as well as a full rebuild (area ratio within 25 %; a bound with room,
// measured 1.06 with either split for 20 of 1,000 boxes moved across the world).
static void CheckPartialRebuild(tbTreeSplit split)
{
	s_seed = 777u;
	tbDynamicTree tree = tbDynamicTree_Create(0);
	tree.rebuildSplit = split;
	static int ids[1000];
	static tbAABB boxes[1000];
	static uint64_t bits[1000];
	for (int i = 0; i < 1000; ++i)
	{
		boxes[i] = RandomBox(200.0f, 0.3f, 3.0f);
		bits[i] = (uint64_t)1 << (i % 3);
		ids[i] = tbDynamicTree_CreateProxy(&tree, boxes[i], bits[i], i);
	}
	tbDynamicTree_Rebuild(&tree, true);
	cr_assert_eq(tbDynamicTree_Rebuild(&tree, false), 0, "nothing grown: nothing to rebuild");
	int height = tbDynamicTree_GetHeight(&tree);
	for (int i = 0; i < 1000; i += 50)
	{
		boxes[i] = RandomBox(200.0f, 0.3f, 3.0f);
		tbDynamicTree_EnlargeProxy(&tree, ids[i], boxes[i]);
	}
	float grownRatio = tbDynamicTree_GetAreaRatio(&tree);
	int items = tbDynamicTree_Rebuild(&tree, false);
	cr_assert(items >= 20 && items <= 20 * (height + 1), "items %d, height %d", items, height);
	cr_assert_lt(items, 1000 / 2);
	cr_assert(tbDynamicTree_Validate(&tree));
	cr_assert_eq(tree.proxyCount, 1000);
	for (int q = 0; q < 200; ++q)
	{
		CheckQuery(&tree, ids, boxes, bits, 1000, RandomBox(200.0f, 1.0f, 40.0f), 7);
	}
	float partialRatio = tbDynamicTree_GetAreaRatio(&tree);
	cr_assert_lt(partialRatio, grownRatio, "the rebuild must undo the growth (%g, %g)", (double)partialRatio,
				 (double)grownRatio);
	cr_assert_eq(tbDynamicTree_Rebuild(&tree, false), 0, "a rebuild clears every mark");
	tbDynamicTree_Rebuild(&tree, true);
	float fullRatio = tbDynamicTree_GetAreaRatio(&tree);
	cr_assert_lt(partialRatio, 1.25f * fullRatio, "partial %g, full %g", (double)partialRatio, (double)fullRatio);
	cr_log_info("partial rebuild: %d items, area ratio grown %g, partial %g, full %g", items, (double)grownRatio,
				(double)partialRatio, (double)fullRatio);
	// Grown leaves re-inserted one by one leave no mark behind either.
	tbDynamicTree_EnlargeProxy(&tree, ids[3], tbAABB_Fatten(boxes[3], 1.0f));
	tbDynamicTree_EnlargeProxy(&tree, ids[4], tbAABB_Fatten(boxes[4], 1.0f));
	tbDynamicTree_MoveProxy(&tree, ids[3], boxes[3]);
	tbDynamicTree_MoveProxy(&tree, ids[4], boxes[4]);
	cr_assert_eq(tbDynamicTree_Rebuild(&tree, false), 0);
	cr_assert(tbDynamicTree_Validate(&tree));
	tbDynamicTree_Destroy(&tree);
}

Test(dynamic_tree, partial_rebuild_places_only_grown_leaves)
{
	CheckPartialRebuild(tb_splitBinnedSah);
	CheckPartialRebuild(tb_splitMidpoint);
}

static int s_visited;

static bool CountingCallback(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	(void)userData;
	(void)context;
	s_visited += 1;
	return true;
}

Test(dynamic_tree, mask_bits_prune)
{
	s_seed = 5u;
	tbDynamicTree tree = tbDynamicTree_Create(0);
	static int ids[600];
	static tbAABB boxes[600];
	static uint64_t bits[600];
	for (int i = 0; i < 600; ++i)
	{
		boxes[i] = RandomBox(50.0f, 0.5f, 4.0f);
		bits[i] = i < 300 ? 0x1 : 0x2; // two categories
		ids[i] = tbDynamicTree_CreateProxy(&tree, boxes[i], bits[i], i);
	}
	tbAABB everything = {{-100.0f, -100.0f}, {100.0f, 100.0f}};
	CheckQuery(&tree, ids, boxes, bits, 600, everything, 0x2);
	CheckQuery(&tree, ids, boxes, bits, 600, everything, 0x1);
	s_visited = 0;
	tbDynamicTree_Query(&tree, everything, 0x4, CountingCallback, NULL);
	cr_assert_eq(s_visited, 0, "no proxy has category 0x4");
	cr_assert_eq(tbDynamicTree_GetCategoryBits(&tree, ids[0]), 0x1);
	tbDynamicTree_Destroy(&tree);
}

static void CountNode(tbAABB aabb, int depth, bool isLeaf, void* context)
{
	(void)aabb;
	(void)depth;
	int* counts = context;
	counts[isLeaf ? 1 : 0] += 1;
}

Test(dynamic_tree, visit_nodes_and_no_bytes_left)
{
	int startBytes = tbGetByteCount();
	s_seed = 11u;
	tbDynamicTree tree = tbDynamicTree_Create(0);
	for (int i = 0; i < 500; ++i)
	{
		tbDynamicTree_CreateProxy(&tree, RandomBox(40.0f, 0.5f, 2.0f), 1, i);
	}
	tbDynamicTree_Rebuild(&tree, true);
	int counts[2] = {0, 0};
	tbDynamicTree_VisitNodes(&tree, CountNode, counts);
	// A full binary tree with n leaves has n − 1 internal nodes.
	cr_assert_eq(counts[1], 500);
	cr_assert_eq(counts[0], 499);
	cr_assert_gt(tbGetByteCount(), startBytes);
	tbDynamicTree_Destroy(&tree);
	cr_assert_eq(tbGetByteCount(), startBytes, "bytes left after destroy: %d", (int)(tbGetByteCount() - startBytes));
}

typedef struct BoxCastHits
{
	int order[8];
	int count;
	int beyondReach; ///< candidates reported although the clipped sweep could not reach them
	float nearest;
} BoxCastHits;

/// Each candidate clips the cast at its own box: the fraction where the moving box's right side
/// reaches the candidate's left side (boxes on one row, the cast along +x).
static float ClipAtBox(const tbBoxCastInput* input, int proxyId, uint64_t userData, void* context)
{
	BoxCastHits* hits = context;
	hits->order[hits->count++] = (int)userData;
	float left = 2.0f * (float)userData - 0.5f; // proxy k spans [2k − 0.5, 2k + 0.5]
	float reach = input->box.upperBound.x + input->maxFraction * input->translation.x;
	hits->beyondReach += left > reach ? 1 : 0;
	float fraction = (left - input->box.upperBound.x) / input->translation.x;
	hits->nearest = fraction > 0.0f && fraction < hits->nearest ? fraction : hits->nearest;
	(void)proxyId;
	return fraction > 0.0f ? fraction : input->maxFraction;
}

static bool CountInto(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	(void)userData;
	*(int*)context += 1;
	return true;
}

// Tree extras in Box2D v3.2's grammar: box cast (candidates beyond the nearest hit are clipped
// away), query-all ignoring categories, category changes, root bounds, proxy and byte counts, and
// validation that no grown proxy waits for a rebuild.
Test(dynamic_tree, box_cast_query_all_and_bookkeeping)
{
	tbDynamicTree tree = tbDynamicTree_Create(8);
	cr_assert_geq(tree.nodeCapacity, 15, "room for 8 proxies: 2·8 − 1 nodes");
	int bytes = tbDynamicTree_GetByteCount(&tree);
	cr_assert_gt(bytes, 15 * 40);
	int proxies[6];
	for (int k = 0; k < 6; ++k)
	{
		tbAABB box = {{2.0f * (float)k - 0.5f, -0.5f}, {2.0f * (float)k + 0.5f, 0.5f}};
		proxies[k] = tbDynamicTree_CreateProxy(&tree, box, k == 3 ? 2u : 1u, (uint64_t)k);
	}
	cr_assert_eq(tbDynamicTree_GetProxyCount(&tree), 6);
	tbAABB root = tbDynamicTree_GetRootBounds(&tree);
	cr_assert(root.lowerBound.x == -0.5f && root.upperBound.x == 10.5f && root.upperBound.y == 0.5f);

	// A box of half height 0.25 starting between boxes 0 and 1 and moving 10 m along +x reaches
	// boxes 2…5 (box 1 overlaps its start: its fraction is not positive and it does not clip).
	// The nearest, box 2, is hit at (3.5 − 1.5)/10 = 0.2; no box is reported once the clipped
	// sweep can no longer reach it (the order of the others depends on the tree's shape).
	tbBoxCastInput cast = {{{1.0f, -0.25f}, {1.5f, 0.25f}}, {10.0f, 0.0f}, 1.0f};
	BoxCastHits hits = {{0}, 0, 0, 1.0f};
	tbTreeStats stats = tbDynamicTree_BoxCast(&tree, &cast, ~0ull, ClipAtBox, &hits);
	cr_assert_eq(hits.beyondReach, 0);
	cr_assert_float_eq(hits.nearest, 0.2f, 1e-6f);
	cr_assert_geq(hits.count, 1);
	cr_assert_leq(hits.count, 5);
	cr_assert_eq(stats.leafVisits, hits.count);
	// Box 3 has category 2: a mask without it skips it; query-all sees it.
	int seen = 0;
	tbAABB around3 = {{5.9f, -0.1f}, {6.1f, 0.1f}};
	tbDynamicTree_Query(&tree, around3, 1u, CountInto, &seen);
	cr_assert_eq(seen, 0);
	stats = tbDynamicTree_QueryAll(&tree, around3, CountInto, &seen);
	cr_assert_eq(seen, 1);
	cr_assert_eq(stats.leafVisits, 1);
	tbDynamicTree_SetCategoryBits(&tree, proxies[3], 1u);
	cr_assert_eq(tbDynamicTree_GetCategoryBits(&tree, proxies[3]), 1u);
	tbDynamicTree_Query(&tree, around3, 1u, CountInto, &seen);
	cr_assert_eq(seen, 2, "box 3 found under its new category");

	// A proxy grown in place waits for a rebuild.
	cr_assert(tbDynamicTree_ValidateNoEnlarged(&tree));
	tbDynamicTree_EnlargeProxy(&tree, proxies[0], (tbAABB){{-1.0f, -1.0f}, {1.0f, 1.0f}});
	cr_assert(tbDynamicTree_Validate(&tree));
	cr_assert_not(tbDynamicTree_ValidateNoEnlarged(&tree));
	tbDynamicTree_Rebuild(&tree, false);
	cr_assert(tbDynamicTree_ValidateNoEnlarged(&tree));
	tbDynamicTree_Destroy(&tree);
}
