// Behaviours Box2D v3.2's public API promises, checked on Tumble under the same names: orphan
// chain segments, the worker count at run time, per-body manifold recycling, reserved capacity,
// target transforms of sleeping bodies, null ids and the named colours. Box2D v3.2's own
// public-API tests, renamed b2 → tb, run by hand outside this repository (docs/porting.md says how);
// these tests keep the same behaviours checked here, with values worked out in each comment.
#include "collision/aabb.h"
#include "tumble/tumble.h"

#include <criterion/criterion.h>

#include "error_recorder.h"
#include "test_helpers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static tbChainSegment MakeChainSegment(float half, float ghost)
{
	// Solid below: the segment runs right to left, its ghosts continuing it.
	tbChainSegment cs;
	memset(&cs, 0, sizeof(cs));
	cs.ghost1 = (tbVec2){ghost, 0.0f};
	cs.segment.point1 = (tbVec2){half, 0.0f};
	cs.segment.point2 = (tbVec2){-half, 0.0f};
	cs.ghost2 = (tbVec2){-ghost, 0.0f};
	cs.chainId = 99; // ignored: an orphan belongs to no chain
	return cs;
}

// An orphan chain segment: a one-sided segment no chain owns. A ball of radius 0.5 dropped on it
// rests with its centre 0.5 m above (within the contact's slop and softness: 0.01 m).
Test(conformance, orphan_chain_segment_holds_a_ball_and_can_be_replaced, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbChainSegment cs = MakeChainSegment(1.0f, 2.0f);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbShapeId orphan = tbCreateChainSegmentShape(ground, &shapeDef, &cs);
	cr_assert(tbShape_IsValid(orphan));
	cr_assert_eq(tbShape_GetType(orphan), tb_chainSegmentShape);
	cr_assert(TB_IS_NULL(tbShape_GetParentChain(orphan)));
	tbChainSegment got = tbShape_GetChainSegment(orphan);
	cr_assert_eq(got.chainId, TB_NULL_INDEX);
	cr_assert(got.ghost1.x == 2.0f && got.segment.point1.x == 1.0f && got.segment.point2.x == -1.0f &&
			  got.ghost2.x == -2.0f);

	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){0.0f, 2.0f};
	tbBodyId ball = tbCreateBody(world, &bodyDef);
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbCreateCircleShape(ball, &shapeDef, &circle);
	StepWorld(world, 120, 1.0f / 60.0f, 4);
	cr_expect_float_eq(tbBody_GetPosition(ball).y, 0.5f, 0.01f, "ball at %.4f", (double)tbBody_GetPosition(ball).y);

	// Replaced by a longer one; an owned chain segment may not be replaced.
	tbChainSegment longer = MakeChainSegment(2.0f, 3.0f);
	cr_assert(tbShape_SetChainSegment(orphan, &longer));
	cr_expect_eq(tbShape_GetChainSegment(orphan).segment.point1.x, 2.0f);
	tbVec2 points[4] = {{3.0f, 1.0f}, {2.0f, 1.0f}, {-2.0f, 1.0f}, {-3.0f, 1.0f}};
	tbChainDef chainDef = tbDefaultChainDef();
	chainDef.points = points;
	chainDef.count = 4;
	tbChainId chain = tbCreateChain(ground, &chainDef);
	tbShapeId owned;
	cr_assert_eq(tbChain_GetSegments(chain, &owned, 1), 1);
	int before = s_errors;
	cr_expect_not(tbShape_SetChainSegment(owned, &longer));
	ExpectError(before, "tbShape_SetChainSegment", "chain");
	// A segment without length is refused.
	tbChainSegment point = MakeChainSegment(0.0f, 1.0f);
	before = s_errors;
	cr_expect(TB_IS_NULL(tbCreateChainSegmentShape(ground, &shapeDef, &point)));
	ExpectError(before, "tbCreateChainSegmentShape", "length");
	tbDestroyWorld(world);
}

/// Final position of a box dropped on a box ground after 90 steps, under a world definition.
static tbVec2 DropBox(tbWorldDef worldDef, int workerCountAfter)
{
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon floor = tbMakeBox(10.0f, 0.5f);
	tbCreatePolygonShape(ground, &shapeDef, &floor);
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){0.3f, 3.0f};
	bodyDef.rotation = tbMakeRot(0.4f);
	tbBodyId box = tbCreateBody(world, &bodyDef);
	tbPolygon square = tbMakeBox(0.5f, 0.5f);
	tbCreatePolygonShape(box, &shapeDef, &square);
	StepWorld(world, 30, 1.0f / 60.0f, 4);
	if (workerCountAfter > 0)
	{
		tbWorld_SetWorkerCount(world, workerCountAfter);
	}
	StepWorld(world, 60, 1.0f / 60.0f, 4);
	tbVec2 p = tbBody_GetPosition(box);
	tbDestroyWorld(world);
	return p;
}

// The worker count is the task system's: without task callbacks the step runs on the caller
// whatever the count, bit for bit as with one worker. Set at run time it is clamped to
// [1, TB_MAX_WORKERS].
Test(conformance, worker_count_at_run_time)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbVec2 one = DropBox(worldDef, 0);
	worldDef.workerCount = 4;
	tbVec2 four = DropBox(worldDef, 0);
	tbVec2 changed = DropBox(tbDefaultWorldDef(), 3);
	cr_expect(one.x == four.x && one.y == four.y, "4 workers without a task system differ");
	cr_expect(one.x == changed.x && one.y == changed.y, "changing the count mid-run changed the result");

	tbWorldId world = tbCreateWorld(&worldDef);
	cr_expect_eq(tbWorld_GetWorkerCount(world), 4);
	tbWorld_SetWorkerCount(world, 0);
	cr_expect_eq(tbWorld_GetWorkerCount(world), 1);
	tbWorld_SetWorkerCount(world, 1000);
	cr_expect_eq(tbWorld_GetWorkerCount(world), TB_MAX_WORKERS);
	tbDestroyWorld(world);
}

// Manifold recycling per body: on by default, off in the definition or at run time. A box resting
// on the ground comes to the same height either way (within 1e-4 m: recycled separations are
// exact to well under that for a resting pair, tests/test_contact.c).
Test(conformance, per_body_contact_recycling)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon floor = tbMakeBox(10.0f, 0.5f);
	tbCreatePolygonShape(ground, &shapeDef, &floor);
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){-2.0f, 1.0f};
	tbBodyId recycled = tbCreateBody(world, &bodyDef);
	cr_expect(tbBody_IsContactRecyclingEnabled(recycled));
	bodyDef.position = (tbVec2){2.0f, 1.0f};
	bodyDef.enableContactRecycling = false;
	tbBodyId fresh = tbCreateBody(world, &bodyDef);
	cr_expect_not(tbBody_IsContactRecyclingEnabled(fresh));
	tbPolygon square = tbMakeBox(0.5f, 0.5f);
	tbCreatePolygonShape(recycled, &shapeDef, &square);
	tbCreatePolygonShape(fresh, &shapeDef, &square);
	StepWorld(world, 60, 1.0f / 60.0f, 4);
	tbBody_EnableContactRecycling(fresh, true);
	cr_expect(tbBody_IsContactRecyclingEnabled(fresh));
	tbBody_EnableContactRecycling(recycled, false);
	StepWorld(world, 30, 1.0f / 60.0f, 4);
	cr_expect_float_eq(tbBody_GetPosition(recycled).y, tbBody_GetPosition(fresh).y, 1e-4f);
	tbDestroyWorld(world);
}

static int s_allocations;

static void* CountingAlloc(size_t size, int alignment)
{
	s_allocations += 1;
	return aligned_alloc((size_t)alignment, ((size_t)size + (size_t)alignment - 1) / (size_t)alignment * (size_t)alignment);
}

static void CountingFree(void* memory, size_t size)
{
	(void)size;
	free(memory);
}

// Reserved capacity: a world made for 200 dynamic bodies creates them without allocating; without
// the reservation the same bodies make the body and awake arrays grow several times. (Shapes
// reserve their array too; their broad-phase proxies grow with the broad phase's own tables.)
// Negative capacities are refused.
Test(conformance, capacity_is_reserved_and_checked, .init = SetupErrors, .fini = TeardownErrors)
{
	int counts[2];
	for (int reserved = 0; reserved < 2; ++reserved)
	{
		tbWorldDef worldDef = tbDefaultWorldDef();
		if (reserved)
		{
			worldDef.capacity = (tbCapacity){0, 200, 0, 200, 0};
		}
		tbWorldId world = tbCreateWorld(&worldDef);
		s_allocations = 0;
		tbSetAllocator(CountingAlloc, CountingFree);
		tbBodyDef bodyDef = tbDefaultBodyDef();
		bodyDef.type = tb_dynamicBody;
		for (int i = 0; i < 200; ++i)
		{
			bodyDef.position = (tbVec2){(float)i, 0.0f};
			tbCreateBody(world, &bodyDef);
		}
		counts[reserved] = s_allocations;
		tbSetAllocator(NULL, NULL);
		tbDestroyWorld(world);
	}
	cr_expect_eq(counts[1], 0, "%d allocations with room reserved", counts[1]);
	cr_expect_gt(counts[0], 0);

	tbWorldDef bad = tbDefaultWorldDef();
	bad.capacity.contactCount = -1;
	int before = s_errors;
	cr_expect(TB_IS_NULL(tbCreateWorld(&bad)));
	ExpectError(before, "tbCreateWorld", "capacity.contactCount");
}

// A sleeping kinematic body given a target: with wake false it stays asleep where it is; with wake
// true a target it would creep to (slower than its sleep threshold) leaves it asleep, and a real
// move wakes it with the velocity that reaches the target in one step.
Test(conformance, target_transform_of_a_sleeping_body)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_kinematicBody;
	bodyDef.isAwake = false;
	tbBodyId platform = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon slab = tbMakeBox(1.0f, 0.1f);
	tbCreatePolygonShape(platform, &shapeDef, &slab);
	cr_assert_not(tbBody_IsAwake(platform));
	float dt = 1.0f / 60.0f;
	tbTransform far = {{1.0f, 0.0f}, tbRot_identity};
	cr_assert(tbBody_SetTargetTransform(platform, far, dt, false));
	cr_expect_not(tbBody_IsAwake(platform));
	cr_expect_eq(tbBody_GetLinearVelocity(platform).x, 0.0f);
	tbTransform creep = {{1e-4f, 0.0f}, tbRot_identity}; // 6 mm/s, below the 0.05 m/s threshold
	cr_assert(tbBody_SetTargetTransform(platform, creep, dt, true));
	cr_expect_not(tbBody_IsAwake(platform));
	cr_assert(tbBody_SetTargetTransform(platform, far, dt, true));
	cr_expect(tbBody_IsAwake(platform));
	cr_expect_float_eq(tbBody_GetLinearVelocity(platform).x, 60.0f, 1e-3f);
	tbWorld_Step(world, dt, 4);
	cr_expect_float_eq(tbBody_GetPosition(platform).x, 1.0f, 1e-5f);
	tbDestroyWorld(world);
}

// Null ids and v3.2's named values.
Test(conformance, null_ids_and_named_values)
{
	cr_expect(TB_IS_NULL(tb_nullWorldId) && TB_IS_NULL(tb_nullBodyId) && TB_IS_NULL(tb_nullShapeId));
	cr_expect(TB_IS_NULL(tb_nullChainId) && TB_IS_NULL(tb_nullJointId) && TB_IS_NULL(tb_nullContactId));
	cr_expect_not(tbBody_IsValid(tb_nullBodyId));
	cr_expect_eq(TB_NULL_INDEX, -1);
	cr_expect_eq(tb_colorCornflowerBlue, 0x6495ED); // CSS Color Level 3 values
	cr_expect_eq(tb_colorGreen, 0x008000);
	cr_expect_eq(tb_colorRebeccaPurple, 0x663399);
	cr_expect(tbVec2_zero.x == 0.0f && tbRot_identity.c == 1.0f && tbTransform_identity.q.s == 0.0f);
}

// v3.2's local manifold form: B placed in A's frame by xf = A⁻¹·B, the manifold in A's frame.
// Two unit boxes whose centres are 0.9 m apart overlap by 0.1 m (closed form): two points on the
// overlap's mid-plane x = 0.45 (surfaces at 0.5 and 0.4), at the shared corners y = ±0.5,
// separation −0.1, normal +x. The same pair placed anywhere in the world, turned by any angle,
// gives the same local manifold to float rounding of the relative transform (1e-5 m at 3 m from
// the origin), while the world form turns its normal with A.
Test(conformance, local_manifold_form)
{
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbTransform offset = {{0.9f, 0.0f}, tbRot_identity};
	tbLocalManifold m = tbCollidePolygons(&box, &box, offset);
	cr_assert_eq(m.pointCount, 2);
	cr_expect_float_eq(m.normal.x, 1.0f, 1e-6f);
	cr_expect_float_eq(m.normal.y, 0.0f, 1e-6f);
	for (int i = 0; i < 2; ++i)
	{
		cr_expect_float_eq(m.points[i].separation, -0.1f, 1e-6f);
		cr_expect_float_eq(m.points[i].point.x, 0.45f, 1e-6f);
		cr_expect_float_eq(fabsf(m.points[i].point.y), 0.5f, 1e-6f);
	}
	cr_expect_neq(m.points[0].id, m.points[1].id);

	tbTransform xfA = {{3.0f, -2.0f}, tbMakeRot(0.7f)};
	tbTransform xfB = tbMulTransforms(xfA, offset);
	tbLocalManifold moved = tbCollidePolygons(&box, &box, tbInvMulTransforms(xfA, xfB));
	cr_assert_eq(moved.pointCount, 2);
	for (int i = 0; i < 2; ++i)
	{
		cr_expect_float_eq(moved.points[i].separation, m.points[i].separation, 1e-5f);
		cr_expect_float_eq(moved.points[i].point.x, m.points[i].point.x, 1e-5f);
		cr_expect_float_eq(moved.points[i].point.y, m.points[i].point.y, 1e-5f);
		cr_expect_eq(moved.points[i].id, m.points[i].id);
	}
	tbGeometry a = {.type = tb_polygonShape, .polygon = box};
	tbManifold world = tbCollideShapes(&a, xfA, &a, xfB, tb_narrowPhaseAuto);
	tbVec2 turned = tbRotateVector(xfA.q, moved.normal);
	cr_expect_float_eq(world.normal.x, turned.x, 1e-6f);
	cr_expect_float_eq(world.normal.y, turned.y, 1e-6f);

	// Circles of radii 0.5 and 0.25, centres 0.7 apart: separation 0.7 − 0.75 = −0.05, the point
	// midway between the surfaces at 0.5 and 0.45. Beyond the speculative distance, no point.
	tbCircle big = {{0.0f, 0.0f}, 0.5f};
	tbCircle small = {{0.0f, 0.0f}, 0.25f};
	tbLocalManifold c = tbCollideCircles(&big, &small, (tbTransform){{0.0f, 0.7f}, tbRot_identity});
	cr_assert_eq(c.pointCount, 1);
	cr_expect_float_eq(c.normal.y, 1.0f, 1e-6f);
	cr_expect_float_eq(c.points[0].separation, -0.05f, 1e-6f);
	cr_expect_float_eq(c.points[0].point.y, 0.475f, 1e-6f);
	tbTransform apart = {{0.0f, 0.75f + TB_SPECULATIVE_DISTANCE + 0.001f}, tbRot_identity};
	cr_expect_eq(tbCollideCircles(&big, &small, apart).pointCount, 0);

	// The chain routines take v3.2's simplex cache and leave it as it was.
	tbChainSegment floor = {{2.0f, 0.0f}, {{1.0f, 0.0f}, {-1.0f, 0.0f}}, {-2.0f, 0.0f}, -1}; // solid below
	tbSimplexCache cache = {0};
	tbTransform resting = {{0.0f, 0.49f}, tbRot_identity};
	tbLocalManifold onFloor = tbCollideChainSegmentAndPolygon(&floor, &box, resting, &cache);
	cr_expect_eq(onFloor.pointCount, 2);
	cr_expect_float_eq(onFloor.points[0].separation, -0.01f, 1e-6f);
	cr_expect_eq(cache.count, 0);
}

// The segment-into-box cast by slabs (aabb.h): entry fraction, the face's outward normal and the
// point, all closed forms for the box [−1, 1]²; no hit when the segment starts inside, stops
// short, or runs parallel outside; a segment along a face counts (the slab is closed).
Test(conformance, aabb_ray_cast)
{
	tbAABB box = {{-1.0f, -1.0f}, {1.0f, 1.0f}};
	tbCastOutput hit = tbAABB_RayCast(box, (tbVec2){-3.0f, 0.0f}, (tbVec2){3.0f, 0.0f});
	cr_assert(hit.hit);
	cr_expect_float_eq(hit.fraction, 1.0f / 3.0f, 1e-6f);
	cr_expect(hit.normal.x == -1.0f && hit.normal.y == 0.0f);
	cr_expect_float_eq(hit.point.x, -1.0f, 1e-6f);
	hit = tbAABB_RayCast(box, (tbVec2){0.5f, 4.0f}, (tbVec2){0.5f, -4.0f});
	cr_assert(hit.hit);
	cr_expect_float_eq(hit.fraction, 3.0f / 8.0f, 1e-6f);
	cr_expect(hit.normal.x == 0.0f && hit.normal.y == 1.0f);
	cr_expect_float_eq(hit.point.x, 0.5f, 1e-6f);
	cr_expect_float_eq(hit.point.y, 1.0f, 1e-6f);
	hit = tbAABB_RayCast(box, (tbVec2){-2.0f, 1.0f}, (tbVec2){2.0f, 1.0f}); // along the top face
	cr_expect(hit.hit && hit.normal.x == -1.0f);
	cr_expect_float_eq(hit.fraction, 0.25f, 1e-6f);
	cr_expect_not(tbAABB_RayCast(box, (tbVec2){0.0f, 0.0f}, (tbVec2){2.0f, 0.0f}).hit);	  // starts inside
	cr_expect_not(tbAABB_RayCast(box, (tbVec2){-3.0f, 0.0f}, (tbVec2){-1.5f, 0.0f}).hit); // stops short
	cr_expect_not(tbAABB_RayCast(box, (tbVec2){-3.0f, 1.5f}, (tbVec2){3.0f, 1.5f}).hit);  // parallel, outside
	cr_expect_not(tbAABB_RayCast(box, (tbVec2){0.0f, 0.0f}, (tbVec2){0.0f, 0.0f}).hit);	  // a point
}
