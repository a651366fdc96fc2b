// Broad phase: the four methods (tree, sort-and-sweep, spatial hash, brute force) must report
// identical pair sets — same pairs, same order — on a moving scene, across method switches and
// destroys; brute force, the last, is the reference.
#include <criterion/criterion.h>

#include "broad_phase/broad_phase.h"
#include "test_helpers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

// Linear congruential generator, constants from Numerical Recipes (Press et al., §7.1).
static uint32_t s_seed = 1u;

#define METHOD_COUNT 4
#define REFERENCE (METHOD_COUNT - 1)
static const tbBroadPhaseMethod s_methods[METHOD_COUNT] = {tb_broadPhaseTree, tb_broadPhaseSortAndSweep,
															tb_broadPhaseSpatialHash, tb_broadPhaseBruteForce};

#define MAX_BODIES 2000

/// A moving scene as a world drives it: each body has a tight box and a fat box (tight box grown
/// by TB_AABB_MARGIN); a body whose tight box leaves its fat box gets a new fat box and is moved.
typedef struct Scene
{
	tbBroadPhase bp[METHOD_COUNT];
	int keys[METHOD_COUNT][MAX_BODIES];
	tbAABB tight[MAX_BODIES];
	tbAABB fat[MAX_BODIES];
	tbVec2 velocity[MAX_BODIES];
	bool isStatic[MAX_BODIES];
	bool alive[MAX_BODIES];
	int count;
	float halfWidth; ///< bodies drift inside [−halfWidth, halfWidth]²
} Scene;

static Scene s_scene;

/// Shape index of body i: a permutation (7919 is prime, coprime to 2000) so that pair order by
/// shape index differs from the order of proxy keys.
static int ShapeIndex(int i)
{
	return (i * 7919) % MAX_BODIES;
}

static void CreateScene(Scene* scene, int count, float halfWidth, float staticFraction)
{
	memset(scene, 0, sizeof(*scene));
	scene->count = count;
	scene->halfWidth = halfWidth;
	for (int m = 0; m < METHOD_COUNT; ++m)
	{
		tbBroadPhase_Create(&scene->bp[m], s_methods[m]);
	}
	for (int i = 0; i < count; ++i)
	{
		// Sizes from 0.2 m to 2 m: a factor of 10.
		float w = RandomFloat(&s_seed, 0.2f, 2.0f), h = RandomFloat(&s_seed, 0.2f, 2.0f);
		float x = RandomFloat(&s_seed, -halfWidth, halfWidth - w), y = RandomFloat(&s_seed, -halfWidth, halfWidth - h);
		scene->tight[i] = (tbAABB){{x, y}, {x + w, y + h}};
		scene->fat[i] = tbAABB_Fatten(scene->tight[i], TB_AABB_MARGIN);
		scene->isStatic[i] = RandomFloat(&s_seed, 0.0f, 1.0f) < staticFraction;
		scene->velocity[i] = scene->isStatic[i] ? tbVec2_zero
												: (tbVec2){RandomFloat(&s_seed, -3.0f, 3.0f),
														   RandomFloat(&s_seed, -3.0f, 3.0f)};
		scene->alive[i] = true;
		tbProxyType type = scene->isStatic[i] ? tb_proxyStatic : tb_proxyMovable;
		for (int m = 0; m < METHOD_COUNT; ++m)
		{
			scene->keys[m][i] = tbBroadPhase_CreateProxy(&scene->bp[m], scene->fat[i], (uint64_t)1 << (i % 4), ShapeIndex(i), type);
		}
	}
}

static void DestroyScene(Scene* scene)
{
	for (int m = 0; m < METHOD_COUNT; ++m)
	{
		tbBroadPhase_Destroy(&scene->bp[m]);
	}
}

static void MoveBody(Scene* scene, int i, tbAABB fat)
{
	scene->fat[i] = fat;
	for (int m = 0; m < METHOD_COUNT; ++m)
	{
		tbBroadPhase_MoveProxy(&scene->bp[m], scene->keys[m][i], fat);
	}
}

/// Advance one step of 1/60 s: drift, bounce off the region's walls, re-fatten when needed.
static void StepScene(Scene* scene)
{
	const float dt = 1.0f / 60.0f;
	float L = scene->halfWidth;
	for (int i = 0; i < scene->count; ++i)
	{
		if (scene->alive[i] == false || scene->isStatic[i])
		{
			continue;
		}
		tbVec2 d = tbMulSV(dt, scene->velocity[i]);
		tbAABB b = {tbAdd(scene->tight[i].lowerBound, d), tbAdd(scene->tight[i].upperBound, d)};
		if (b.lowerBound.x < -L || b.upperBound.x > L)
		{
			scene->velocity[i].x = -scene->velocity[i].x;
		}
		if (b.lowerBound.y < -L || b.upperBound.y > L)
		{
			scene->velocity[i].y = -scene->velocity[i].y;
		}
		scene->tight[i] = b;
		if (tbAABB_Contains(scene->fat[i], b) == false)
		{
			MoveBody(scene, i, tbAABB_Fatten(b, TB_AABB_MARGIN));
		}
	}
}

/// Update every method's pairs and require the same pairs in the same order; returns the count.
static int UpdateAndCompare(Scene* scene, int step)
{
	for (int m = 0; m < METHOD_COUNT; ++m)
	{
		tbBroadPhase_UpdatePairs(&scene->bp[m]);
	}
	const tbBroadPhase* reference = &scene->bp[METHOD_COUNT - 1];
	for (int m = 0; m < METHOD_COUNT - 1; ++m)
	{
		const tbBroadPhase* bp = &scene->bp[m];
		cr_assert_eq(bp->pairList.count, reference->pairList.count, "step %d: method %d found %d pairs, brute force %d", step,
					 (int)s_methods[m], bp->pairList.count, reference->pairList.count);
		cr_assert(memcmp(bp->pairList.pairs, reference->pairList.pairs, (size_t)bp->pairList.count * sizeof(tbShapePair)) == 0,
				  "step %d: method %d pairs differ from brute force", step, (int)s_methods[m]);
	}
	for (int k = 1; k < reference->pairList.count; ++k)
	{
		// Asserted only when it fails: a passing assertion per pair (hundreds of thousands over the
		// run) cost this test most of its 25 s, in Criterion's reporting.
		tbShapePair p = reference->pairList.pairs[k - 1], q = reference->pairList.pairs[k];
		if (!(p.a < q.a || (p.a == q.a && p.b < q.b)))
		{
			cr_assert_fail("step %d: pairs %d and %d not sorted and unique", step, k - 1, k);
		}
	}
	return reference->pairList.count;
}

static void ValidateAll(const Scene* scene)
{
	for (int m = 0; m < METHOD_COUNT; ++m)
	{
		cr_assert(tbBroadPhase_Validate(&scene->bp[m]), "method %d invalid", (int)s_methods[m]);
	}
}

Test(broad_phase, identical_pairs_2000_moving_boxes_200_steps)
{
	// Acceptance: 2,000 boxes (sizes 0.2–2 m), 10% static, drifting for 200 steps in a 70 m
	// square; every method reports the same pair set at every step.
	int startBytes = tbGetByteCount();
	s_seed = 2024u;
	Scene* scene = &s_scene;
	CreateScene(scene, 2000, 35.0f, 0.1f);
	int firstCount = UpdateAndCompare(scene, 0);
	cr_assert_gt(firstCount, 100, "the scene has overlaps (%d)", firstCount);
	long total = 0;
	for (int step = 1; step <= 200; ++step)
	{
		if (step % 50 == 0)
		{
			// A static body is teleported now and then: it pairs with movables only.
			for (int i = 0; i < scene->count; ++i)
			{
				if (scene->isStatic[i])
				{
					tbVec2 d = {RandomFloat(&s_seed, -2.0f, 2.0f), RandomFloat(&s_seed, -2.0f, 2.0f)};
					scene->tight[i] = (tbAABB){tbAdd(scene->tight[i].lowerBound, d), tbAdd(scene->tight[i].upperBound, d)};
					MoveBody(scene, i, tbAABB_Fatten(scene->tight[i], TB_AABB_MARGIN));
					break;
				}
			}
		}
		StepScene(scene);
		total += UpdateAndCompare(scene, step);
		if (step % 40 == 0)
		{
			ValidateAll(scene);
		}
	}
	cr_assert_gt(total, 0);
	cr_log_info("pairs reported over 200 steps: %ld; tree height %d", total, tbBroadPhase_GetTreeHeight(&scene->bp[0]));
	DestroyScene(scene);
	cr_assert_eq(tbGetByteCount(), startBytes, "bytes left: %d", (int)(tbGetByteCount() - startBytes));
}

Test(broad_phase, static_static_never_reported)
{
	for (int m = 0; m < METHOD_COUNT; ++m)
	{
		tbBroadPhase bp;
		tbBroadPhase_Create(&bp, s_methods[m]);
		// 40 overlapping static boxes: no pairs, even after moving one.
		int keys[40];
		for (int i = 0; i < 40; ++i)
		{
			keys[i] = tbBroadPhase_CreateProxy(&bp, (tbAABB){{(float)i * 0.5f, 0.0f}, {(float)i * 0.5f + 2.0f, 1.0f}}, 1, i,
											   tb_proxyStatic);
		}
		tbBroadPhase_UpdatePairs(&bp);
		cr_assert_eq(bp.pairList.count, 0, "method %d", (int)s_methods[m]);
		tbBroadPhase_MoveProxy(&bp, keys[3], (tbAABB){{1.0f, 0.0f}, {3.0f, 1.0f}});
		tbBroadPhase_UpdatePairs(&bp);
		cr_assert_eq(bp.pairList.count, 0, "method %d", (int)s_methods[m]);
		// One movable box over statics 0..4 (x in [0, 2.2]) pairs with them only.
		tbBroadPhase_CreateProxy(&bp, (tbAABB){{-1.0f, 0.5f}, {0.2f, 2.0f}}, 1, 100, tb_proxyMovable);
		tbBroadPhase_UpdatePairs(&bp);
		cr_assert_eq(bp.pairList.count, 1, "method %d: movable box overlaps static 0 only", (int)s_methods[m]);
		cr_assert_eq(bp.pairList.pairs[0].a, 0);
		cr_assert_eq(bp.pairList.pairs[0].b, 100);
		tbBroadPhase_Destroy(&bp);
	}
}

Test(broad_phase, set_method_mid_run_keeps_pairs_identical)
{
	int startBytes = tbGetByteCount();
	s_seed = 77u;
	Scene* scene = &s_scene;
	CreateScene(scene, 1000, 25.0f, 0.2f);
	UpdateAndCompare(scene, 0);
	for (int step = 1; step <= 120; ++step)
	{
		StepScene(scene);
		if (step % 30 == 0)
		{
			// Rotate the methods of the first two broad phases; re-set the reference so all count
			// as moved there too.
			int shift = step / 30;
			for (int m = 0; m < REFERENCE; ++m)
			{
				tbBroadPhase_SetMethod(&scene->bp[m], s_methods[(shift + m) % REFERENCE]);
			}
			tbBroadPhase_SetMethod(&scene->bp[REFERENCE], tb_broadPhaseBruteForce);
			ValidateAll(scene);
		}
		UpdateAndCompare(scene, step);
	}
	ValidateAll(scene);
	DestroyScene(scene);
	cr_assert_eq(tbGetByteCount(), startBytes);
}

static bool PairHasDeadBody(const tbBroadPhase* bp, const Scene* scene)
{
	for (int k = 0; k < bp->pairList.count; ++k)
	{
		for (int i = 0; i < scene->count; ++i)
		{
			if (scene->alive[i] == false && (bp->pairList.pairs[k].a == ShapeIndex(i) || bp->pairList.pairs[k].b == ShapeIndex(i)))
			{
				return true;
			}
		}
	}
	return false;
}

Test(broad_phase, destroyed_proxies_never_pair)
{
	s_seed = 31u;
	Scene* scene = &s_scene;
	CreateScene(scene, 600, 15.0f, 0.1f);
	UpdateAndCompare(scene, 0);
	for (int step = 1; step <= 60; ++step)
	{
		StepScene(scene);
		if (step % 10 == 0)
		{
			// Destroy every 7th live body, including some just moved (still in the move buffer).
			for (int i = step / 10; i < scene->count; i += 7)
			{
				if (scene->alive[i])
				{
					scene->alive[i] = false;
					for (int m = 0; m < METHOD_COUNT; ++m)
					{
						tbBroadPhase_DestroyProxy(&scene->bp[m], scene->keys[m][i]);
					}
				}
			}
			ValidateAll(scene);
		}
		UpdateAndCompare(scene, step);
		for (int m = 0; m < METHOD_COUNT; ++m)
		{
			cr_assert_not(PairHasDeadBody(&scene->bp[m], scene), "method %d reports a destroyed proxy",
						  (int)s_methods[m]);
		}
	}
	DestroyScene(scene);
}

typedef struct QueryResult
{
	int shapes[MAX_BODIES];
	int count;
} QueryResult;

static bool CollectShape(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	QueryResult* r = context;
	r->shapes[r->count++] = shapeIndex;
	return true;
}

typedef struct ClosestHit
{
	const tbBroadPhase* bp;
	float fraction;
} ClosestHit;

/// Clip by the hit fraction of the fat box itself (slab test): the closest box wins.
static float ClosestBoxCallback(const tbRayCastInput* input, int proxyKey, int shapeIndex, void* context)
{
	(void)shapeIndex;
	ClosestHit* hit = context;
	tbAABB box = tbBroadPhase_GetFatAABB(hit->bp, proxyKey);
	float t0 = 0.0f, t1 = input->maxFraction;
	float p[2] = {input->origin.x, input->origin.y}, d[2] = {input->translation.x, input->translation.y};
	float lo[2] = {box.lowerBound.x, box.lowerBound.y}, hi[2] = {box.upperBound.x, box.upperBound.y};
	for (int k = 0; k < 2; ++k)
	{
		float a = (lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
		t0 = fmaxf(t0, fminf(a, b));
		t1 = fminf(t1, fmaxf(a, b));
	}
	if (t0 > t1 || t0 <= 0.0f)
	{
		return input->maxFraction;
	}
	hit->fraction = fminf(hit->fraction, t0);
	return t0;
}

static float CollectEveryBox(const tbRayCastInput* input, int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	QueryResult* r = context;
	r->shapes[r->count++] = shapeIndex;
	return input->maxFraction; // no clipping: every box the ray meets, each once
}

/// 50 random box queries and rays (long ones of up to 42 m and short ones of up to 4 m) on every
/// method, compared with brute force: the same shapes, the same closest box, and every box a ray
/// meets reported once.
static void CompareQueries(Scene* scene, const char* when)
{
	static QueryResult every[METHOD_COUNT];
	static QueryResult results[METHOD_COUNT];
	for (int q = 0; q < 50; ++q)
	{
		float x = RandomFloat(&s_seed, -20.0f, 20.0f), y = RandomFloat(&s_seed, -20.0f, 20.0f);
		tbAABB box = {{x, y}, {x + RandomFloat(&s_seed, 0.5f, 6.0f), y + RandomFloat(&s_seed, 0.5f, 6.0f)}};
		float reach = q % 2 == 0 ? 30.0f : 3.0f;
		tbRayCastInput ray = {{x, y}, {RandomFloat(&s_seed, -reach, reach), RandomFloat(&s_seed, -reach, reach)}, 1.0f};
		float fractions[METHOD_COUNT];
		for (int m = 0; m < METHOD_COUNT; ++m)
		{
			results[m].count = 0;
			tbBroadPhase_Query(&scene->bp[m], box, 0x5, CollectShape, &results[m]);
			qsort(results[m].shapes, (size_t)results[m].count, sizeof(int), CompareInts);
			ClosestHit hit = {&scene->bp[m], 2.0f};
			tbBroadPhase_RayCast(&scene->bp[m], &ray, 0x3, ClosestBoxCallback, &hit);
			fractions[m] = hit.fraction;
			every[m].count = 0;
			tbBroadPhase_RayCast(&scene->bp[m], &ray, 0x3, CollectEveryBox, &every[m]);
			qsort(every[m].shapes, (size_t)every[m].count, sizeof(int), CompareInts);
		}
		for (int m = 0; m < METHOD_COUNT - 1; ++m)
		{
			cr_assert_eq(results[m].count, results[REFERENCE].count, "%s: query %d method %d", when, q, (int)s_methods[m]);
			cr_assert(memcmp(results[m].shapes, results[REFERENCE].shapes, (size_t)results[m].count * sizeof(int)) == 0,
					  "%s: query %d method %d", when, q, (int)s_methods[m]);
			cr_assert_float_eq(fractions[m], fractions[REFERENCE], 1e-6f, "%s: ray %d method %d", when, q,
							   (int)s_methods[m]);
			cr_assert(every[m].count == every[REFERENCE].count &&
						  memcmp(every[m].shapes, every[REFERENCE].shapes, (size_t)every[m].count * sizeof(int)) == 0,
					  "%s: ray %d method %d met %d boxes, brute force %d", when, q, (int)s_methods[m], every[m].count,
					  every[REFERENCE].count);
		}
	}
}

// Right after an update (the spatial hash's grids current), after proxies moved with no update
// (its movable grid stale: the table is scanned) and after tbBroadPhase_Settle (the grid rebuilt
// where the proxies are now: cells looked up, rays walked through them); the update after a settle
// reuses the grid and must still find brute force's pairs.
Test(broad_phase, queries_and_ray_casts_agree_across_methods)
{
	s_seed = 4u;
	Scene* scene = &s_scene;
	CreateScene(scene, 800, 20.0f, 0.3f);
	UpdateAndCompare(scene, 0);
	CompareQueries(scene, "after an update");
	for (int step = 1; step <= 20; ++step)
	{
		StepScene(scene);
		CompareQueries(scene, "moved, no update");
		for (int m = 0; m < METHOD_COUNT; ++m)
		{
			tbBroadPhase_Settle(&scene->bp[m]);
		}
		ValidateAll(scene);
		CompareQueries(scene, "settled");
		UpdateAndCompare(scene, step);
	}
	DestroyScene(scene);
}

typedef struct StaticHits
{
	const tbBroadPhase* bp;
	int shapes[MAX_BODIES];
	int count;
} StaticHits;

static bool CollectStatic(int proxyKey, int shapeIndex, void* context)
{
	StaticHits* hits = context;
	cr_assert(hits->bp->table.proxies[proxyKey].type == tb_proxyStatic, "a static query returned a movable proxy");
	hits->shapes[hits->count++] = shapeIndex;
	return true;
}

// Sizes the spatial hash handles worst: a 400 × 2 m static ground and a 60 × 60 m static wall
// (thousands of cells: kept apart as large proxies), a 30 m box moving through 0.05 m grains,
// proxies created and destroyed between updates. Every method must still report brute force's
// pairs, and static-only queries (continuous collision's) must return brute force's statics.
Test(broad_phase, mixed_sizes_and_huge_proxies_agree)
{
	int startBytes = tbGetByteCount();
	s_seed = 99u;
	Scene* scene = &s_scene;
	CreateScene(scene, 600, 30.0f, 0.1f);
	tbAABB huge[3] = {{{-200.0f, -32.0f}, {200.0f, -30.0f}}, {{31.0f, -30.0f}, {91.0f, 30.0f}}, {{-15.0f, -15.0f}, {15.0f, 15.0f}}};
	int hugeKeys[METHOD_COUNT][3];
	for (int m = 0; m < METHOD_COUNT; ++m)
	{
		for (int h = 0; h < 3; ++h)
		{
			hugeKeys[m][h] = tbBroadPhase_CreateProxy(&scene->bp[m], huge[h], 1, MAX_BODIES + h,
													  h < 2 ? tb_proxyStatic : tb_proxyMovable);
		}
	}
	for (int i = 0; i < 100; ++i)
	{
		float x = RandomFloat(&s_seed, -29.0f, 29.0f), y = RandomFloat(&s_seed, -29.0f, 29.0f);
		scene->tight[i] = (tbAABB){{x, y}, {x + 0.05f, y + 0.05f}}; // grains among the boxes
		MoveBody(scene, i, tbAABB_Fatten(scene->tight[i], 0.01f));
	}
	static StaticHits hits[METHOD_COUNT];
	for (int step = 0; step < 90; ++step)
	{
		StepScene(scene);
		float t = (float)step / 90.0f;
		tbAABB moving = {{-45.0f + 60.0f * t, -15.0f}, {-15.0f + 60.0f * t, 15.0f}};
		for (int m = 0; m < METHOD_COUNT; ++m)
		{
			tbBroadPhase_MoveProxy(&scene->bp[m], hugeKeys[m][2], moving);
		}
		UpdateAndCompare(scene, step);
		ValidateAll(scene);
		tbAABB box = {{RandomFloat(&s_seed, -40.0f, 20.0f), RandomFloat(&s_seed, -40.0f, 20.0f)}, {0.0f, 0.0f}};
		box.upperBound =
			tbAdd(box.lowerBound, (tbVec2){RandomFloat(&s_seed, 0.1f, 20.0f), RandomFloat(&s_seed, 0.1f, 20.0f)});
		for (int m = 0; m < METHOD_COUNT; ++m)
		{
			hits[m].bp = &scene->bp[m];
			hits[m].count = 0;
			tbBroadPhase_QueryStatic(&scene->bp[m], box, UINT64_MAX, CollectStatic, hits + m);
			qsort(hits[m].shapes, (size_t)hits[m].count, sizeof(int), CompareInts);
		}
		for (int m = 0; m < REFERENCE; ++m)
		{
			cr_assert_eq(hits[m].count, hits[REFERENCE].count, "step %d method %d static query", step, (int)s_methods[m]);
			cr_assert(memcmp(hits[m].shapes, hits[REFERENCE].shapes, (size_t)hits[m].count * sizeof(int)) == 0);
		}
	}
	DestroyScene(scene);
	cr_assert_eq(tbGetByteCount(), startBytes);
}

/// The same box queries and rays on two spatial hashes over one table: the same proxies, met in the
/// same order (the order a game's query callbacks see).
static void CompareHashOrder(const tbSpatialHash* a, const tbSpatialHash* b, const tbProxyTable* table, int step)
{
	static QueryResult orderA, orderB; // shape indices, one per proxy
	for (int q = 0; q < 30; ++q)
	{
		float x = RandomFloat(&s_seed, -30.0f, 30.0f), y = RandomFloat(&s_seed, -30.0f, 30.0f);
		tbAABB box = {{x, y}, {x + RandomFloat(&s_seed, 0.5f, 8.0f), y + RandomFloat(&s_seed, 0.5f, 8.0f)}};
		tbRayCastInput ray = {{x, y}, {RandomFloat(&s_seed, -20.0f, 20.0f), RandomFloat(&s_seed, -20.0f, 20.0f)}, 1.0f};
		orderA.count = 0;
		orderB.count = 0;
		tbSpatialHash_Query(a, table, box, UINT64_MAX, false, CollectShape, &orderA);
		tbSpatialHash_Query(b, table, box, UINT64_MAX, false, CollectShape, &orderB);
		cr_assert(orderA.count == orderB.count && memcmp(orderA.shapes, orderB.shapes, sizeof(int) * (size_t)orderA.count) == 0,
				  "step %d query %d: %d and %d proxies, or another order", step, q, orderA.count, orderB.count);
		orderA.count = 0;
		orderB.count = 0;
		bool walkedA = tbSpatialHash_RayCast(a, table, &ray, UINT64_MAX, CollectEveryBox, &orderA);
		bool walkedB = tbSpatialHash_RayCast(b, table, &ray, UINT64_MAX, CollectEveryBox, &orderB);
		cr_assert(walkedA == walkedB && orderA.count == orderB.count &&
					  memcmp(orderA.shapes, orderB.shapes, sizeof(int) * (size_t)orderA.count) == 0,
				  "step %d ray %d: %d and %d proxies, or another order", step, q, orderA.count, orderB.count);
	}
}

// The spatial hash files the few movable proxies that moved again in place (out of their old cells,
// into their new ones) instead of building the movable grid afresh. The grid must be the one a
// build makes: a second hash built from the same table and cell size meets the same proxies in the
// same order in every query and ray. Moves: short drifts within a cell, jumps of up to 10 m, and a
// proxy growing past TB_HASH_MAX_CELLS cells and back (a large proxy: the grid is built afresh);
// 40 of 540 movable proxies a step (below a quarter, so in place), and every tenth step 200 of them
// (above, built afresh).
Test(broad_phase, spatial_hash_grid_filed_in_place_is_the_built_grid)
{
	s_seed = 11u;
	enum { count = 600 };
	static tbAABB boxes[count];
	static int keys[count];
	static bool isStatic[count];
	tbBroadPhase bp;
	tbBroadPhase_Create(&bp, tb_broadPhaseSpatialHash);
	for (int i = 0; i < count; ++i)
	{
		float w = RandomFloat(&s_seed, 0.2f, 2.0f), h = RandomFloat(&s_seed, 0.2f, 2.0f);
		float x = RandomFloat(&s_seed, -30.0f, 28.0f), y = RandomFloat(&s_seed, -30.0f, 28.0f);
		boxes[i] = (tbAABB){{x, y}, {x + w, y + h}};
		isStatic[i] = i % 10 == 0;
		keys[i] = tbBroadPhase_CreateProxy(&bp, boxes[i], 1u, i, isStatic[i] ? tb_proxyStatic : tb_proxyMovable);
	}
	tbBroadPhase_UpdatePairs(&bp);
	tbBroadPhase_Settle(&bp);
	for (int step = 1; step <= 40; ++step)
	{
		int moves = step % 10 == 0 ? 200 : 40;
		for (int k = 0; k < moves; ++k)
		{
			int i = (int)RandomFloat(&s_seed, 0.0f, (float)count - 0.01f);
			if (isStatic[i])
			{
				continue;
			}
			float reach = k % 2 == 0 ? 0.1f : 10.0f;
			tbVec2 d = {RandomFloat(&s_seed, -reach, reach), RandomFloat(&s_seed, -reach, reach)};
			tbAABB b = {tbAdd(boxes[i].lowerBound, d), tbAdd(boxes[i].upperBound, d)};
			if (k == 7 && step % 3 == 0)
			{
				b.upperBound = tbAdd(b.lowerBound, (tbVec2){25.0f, 25.0f}); // large
			}
			else if (b.upperBound.x - b.lowerBound.x > 2.0f)
			{
				b.upperBound = tbAdd(b.lowerBound, (tbVec2){1.0f, 1.0f}); // small again
			}
			boxes[i] = b;
			tbBroadPhase_MoveProxy(&bp, keys[i], b);
		}
		tbBroadPhase_Settle(&bp);
		cr_assert(tbBroadPhase_Validate(&bp), "step %d: the movable grid does not hold every proxy", step);
		tbSpatialHash* built = tbSpatialHash_Create();
		tbSpatialHash_SetState(built, &bp.table, tbSpatialHash_GetState(bp.hash));
		tbSpatialHash_Refresh(built, &bp.table);
		CompareHashOrder(bp.hash, built, &bp.table, step);
		tbSpatialHash_Destroy(built);
		tbBroadPhase_UpdatePairs(&bp);
	}
	tbBroadPhase_Destroy(&bp);
}
