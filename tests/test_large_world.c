// Large worlds: the same scene at the origin and kilometres away. Built and run in both builds:
// the float build (positions are floats) and the large-world build (CMake option
// TUMBLE_DOUBLE_PRECISION, positions are doubles; scripts/run-tests.sh runs this file in it too).
//
// Where the numbers come from. A float spaces its values 2⁻¹⁰ m ≈ 0.98 mm apart between 8192 and
// 16384 m, so at 10 km a float world rounds every body position to about a millimetre each step;
// a double spaces them 1.8e-12 m apart there. The large-world build measures every contact and
// joint from differences of positions taken in double, so the solver sees the same small float
// numbers at 10 km as at the origin: measured, the stack's positions relative to its ground agree
// exactly at 1 and 10 km and to 2.3e-10 m at 100 km after 10 s.
#include "tumble/tumble.h"

#include <criterion/criterion.h>

#include "error_recorder.h"

#include <math.h>

#define STACK_COUNT 10

typedef struct StackResult
{
	tbVec2 position[STACK_COUNT]; ///< relative to the stack's base
	float angle[STACK_COUNT];
} StackResult;

// Ten unit boxes on a 40 m ground, the ground's top at base, stepped `steps` times at 60 Hz.
static StackResult RunStack(tbPos base, int steps)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbBodyDef groundDef = tbDefaultBodyDef();
	groundDef.position = tbOffsetPos(base, (tbVec2){0.0f, -0.5f});
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbPolygon groundBox = tbMakeBox(20.0f, 0.5f);
	tbCreatePolygonShape(ground, &shapeDef, &groundBox);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbBodyId boxes[STACK_COUNT];
	for (int i = 0; i < STACK_COUNT; ++i)
	{
		tbBodyDef bodyDef = tbDefaultBodyDef();
		bodyDef.type = tb_dynamicBody;
		bodyDef.position = tbOffsetPos(base, (tbVec2){0.0f, 0.5f + (float)i});
		boxes[i] = tbCreateBody(world, &bodyDef);
		tbCreatePolygonShape(boxes[i], &shapeDef, &box);
	}
	for (int step = 0; step < steps; ++step)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	StackResult result;
	for (int i = 0; i < STACK_COUNT; ++i)
	{
		result.position[i] = tbSubPos(tbBody_GetPosition(boxes[i]), base);
		result.angle[i] = tbRot_GetAngle(tbBody_GetRotation(boxes[i]));
	}
	tbDestroyWorld(world);
	return result;
}

// The same stack at the origin and 10 km away (both coordinates), 2 s. Large-world build: the
// positions relative to the ground agree to 1e-6 m and 1e-6 rad (measured: exactly; the bound is
// 5,000 times below the linear slop, 0.005 m). Float build: the far stack still stands, but each
// position is rounded to the float spacing there, 2⁻¹⁰ m, every step: it agrees only to 8
// spacings, 7.8 mm (measured 3.1 mm and 2.3e-4 rad).
Test(large_world, stack_far_from_origin_matches_the_origin)
{
	tbPos far = {10000.0, 10000.0};
	StackResult origin = RunStack(tbPos_zero, 120);
	StackResult moved = RunStack(far, 120);
#if defined(TUMBLE_DOUBLE_PRECISION)
	float positionTolerance = 1e-6f, angleTolerance = 1e-6f;
#else
	float positionTolerance = 8.0f * 0.0009765625f, angleTolerance = 1e-3f;
#endif
	for (int i = 0; i < STACK_COUNT; ++i)
	{
		cr_expect_float_eq(moved.position[i].x, origin.position[i].x, positionTolerance, "box %d x", i);
		cr_expect_float_eq(moved.position[i].y, origin.position[i].y, positionTolerance, "box %d y", i);
		cr_expect_float_eq(moved.angle[i], origin.angle[i], angleTolerance, "box %d angle", i);
	}
	// The stack stands at the origin: the top box sags by the contacts' slop, under 2 cm over
	// ten contacts (its rest height is 9.5 m).
	cr_expect_float_eq(origin.position[STACK_COUNT - 1].y, 9.5f, 0.02f);
}

// A ray cast down onto the top of a box 10 km away hits its face: the hit point, measured from
// the box, is on the face to 1e-6 m in the large-world build, to the float spacing (2⁻¹⁰ m, with
// the same 8-spacing allowance) in the float build.
Test(large_world, ray_cast_far_from_origin)
{
	tbPos far = {10000.0, 10000.0};
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.position = far;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbCreatePolygonShape(body, &shapeDef, &box);
	tbRayResult hit = tbWorld_CastRayClosest(world, tbOffsetPos(far, (tbVec2){0.25f, 3.0f}), (tbVec2){0.0f, -5.0f},
											 tbDefaultQueryFilter());
	cr_assert(hit.hit);
	tbVec2 local = tbSubPos(hit.point, far);
#if defined(TUMBLE_DOUBLE_PRECISION)
	float tolerance = 1e-6f;
#else
	float tolerance = 8.0f * 0.0009765625f;
#endif
	cr_expect_float_eq(local.x, 0.25f, tolerance);
	cr_expect_float_eq(local.y, 0.5f, tolerance);
	cr_expect_float_eq(hit.fraction, 0.5f, 1e-6f); // 2.5 m of the 5 m translation, closed form
	tbDestroyWorld(world);
}

// A shape's world box contains the shape however far from the origin: in the large-world build,
// at 1e7 m (float spacing 1 m there), the box is found about the body and moved out with outward
// rounding, so it contains the exact extent. In the float build, at 10 km, the box and the shape
// are both float arithmetic: it contains the extent to the float spacing there, 2⁻¹⁰ m.
Test(large_world, shape_box_contains_the_shape)
{
#if defined(TUMBLE_DOUBLE_PRECISION)
	double d = 1.0e7, slack = 0.0;
#else
	double d = 1.0e4, slack = 0.0009765625;
#endif
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.position = (tbPos){d, d};
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeRoundedBox(0.5f, 0.5f, 0.1f); // 0.6 m from the centre each way
	tbShapeId shape = tbCreatePolygonShape(body, &shapeDef, &box);
	tbAABB aabb = tbShape_GetAABB(shape);
	cr_expect((double)aabb.lowerBound.x <= d - 0.6 + slack && (double)aabb.lowerBound.y <= d - 0.6 + slack);
	cr_expect((double)aabb.upperBound.x >= d + 0.6 - slack && (double)aabb.upperBound.y >= d + 0.6 - slack);
	tbDestroyWorld(world);
}

// Which positions a world accepts: 1e7 m is refused in the float build (beyond TB_MAX_POSITION,
// 1e6 m, where a float's spacing is 6 cm) and accepted in the large-world build (limit 1e9 m).
Test(large_world, position_limit, .init = SetupErrors, .fini = TeardownErrors)
{
	cr_expect_eq(tbIsDoublePrecision(), TB_MAX_POSITION > TB_MAX_COORDINATE);
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.position = (tbPos){1.0e7, 0.0};
	int before = s_errors;
	tbBodyId body = tbCreateBody(world, &bodyDef);
#if defined(TUMBLE_DOUBLE_PRECISION)
	cr_expect(tbBody_IsValid(body));
	cr_expect_eq(s_errors, before);
	cr_expect(tbBody_GetPosition(body).x == 1.0e7);
#else
	cr_expect_not(tbBody_IsValid(body));
	ExpectError(before, "tbCreateBody", "def->position");
#endif
	bodyDef.position = (tbPos){2.0 * (double)TB_MAX_POSITION, 0.0};
	before = s_errors;
	cr_expect_not(tbBody_IsValid(tbCreateBody(world, &bodyDef)));
	ExpectError(before, "tbCreateBody", "def->position");
	tbDestroyWorld(world);
}

// A pendulum (a 1 m box on a revolute joint 2 m from its pivot, released horizontally) at the
// origin and 10 km away, 1 s: the joints' anchors and the pivot's offsets are differences of
// positions too. Large-world build: the bob's position relative to the pivot agrees to 1e-6 m;
// float build: to 8 spacings (7.8 mm), as the stack.
static tbVec2 SwingPendulum(tbPos pivot)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef anchorDef = tbDefaultBodyDef();
	anchorDef.position = pivot;
	tbBodyId anchor = tbCreateBody(world, &anchorDef);
	tbBodyDef bobDef = tbDefaultBodyDef();
	bobDef.type = tb_dynamicBody;
	bobDef.position = tbOffsetPos(pivot, (tbVec2){2.0f, 0.0f});
	tbBodyId bob = tbCreateBody(world, &bobDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbCreatePolygonShape(bob, &shapeDef, &box);
	tbRevoluteJointDef jointDef = tbDefaultRevoluteJointDef();
	jointDef.base.bodyIdA = anchor;
	jointDef.base.bodyIdB = bob;
	jointDef.base.localFrameB.p = (tbVec2){-2.0f, 0.0f};
	tbCreateRevoluteJoint(world, &jointDef);
	for (int step = 0; step < 60; ++step)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	tbVec2 offset = tbSubPos(tbBody_GetPosition(bob), pivot);
	tbDestroyWorld(world);
	return offset;
}

Test(large_world, pendulum_far_from_origin_matches_the_origin)
{
	tbVec2 origin = SwingPendulum(tbPos_zero);
	tbVec2 far = SwingPendulum((tbPos){10000.0, 10000.0});
#if defined(TUMBLE_DOUBLE_PRECISION)
	float tolerance = 1e-6f;
#else
	float tolerance = 8.0f * 0.0009765625f;
#endif
	cr_expect_float_eq(far.x, origin.x, tolerance);
	cr_expect_float_eq(far.y, origin.y, tolerance);
	// It swung: after 1 s the bob is below the pivot, on the 2 m circle (the joint holds to 1 cm).
	cr_expect(origin.y < -1.0f);
	cr_expect_float_eq(sqrtf(origin.x * origin.x + origin.y * origin.y), 2.0f, 0.01f);
}
