// World callbacks called from the step: the custom filter and the pre-solve / pre-continuous
// callbacks (one-way platforms). Expected positions come from free fall in closed form
// (y = y0 + v0·t − ½·g·t²) and from resting contact: a body at rest on a surface sits on it within
// the soft contact's sag (a 0.25 m ball of 0.2 kg: well under 1 cm; 0.01 m is the bound used).
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include "error_recorder.h"
#include "test_helpers.h"

#include <math.h>
#include <string.h>

#define TIME_STEP (1.0f / 60.0f)
#define SUB_STEPS 4

static tbShapeId CreateStaticBox(tbWorldId world, tbVec2 position, float halfWidth, float halfHeight, tbShapeDef* def)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.position = position;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbPolygon box = tbMakeBox(halfWidth, halfHeight);
	return tbCreatePolygonShape(body, def, &box);
}

// --- custom filter -------------------------------------------------------------------------------

typedef struct FilterContext
{
	tbShapeId ghost;
	int calls;
} FilterContext;

static bool KeepGhostOut(tbShapeId shapeIdA, tbShapeId shapeIdB, void* context)
{
	FilterContext* c = context;
	c->calls += 1;
	return TB_ID_EQUALS(shapeIdA, c->ghost) == false && TB_ID_EQUALS(shapeIdB, c->ghost) == false;
}

// Two balls dropped from y = 3 onto the ground (top at y = 0); the custom filter refuses every pair
// of the second ("ghost") ball, which enables custom filtering. The first rests on the ground at
// y = 0.25 ± 0.01; the ghost falls freely through it: y = 3 − ½·10·2² = −17 m after 2 s, within the
// symplectic Euler error of 120 steps (½·g·t·dt/4 = 0.04 m).
Test(callbacks, custom_filter_keeps_shapes_apart)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbShapeDef groundDef = tbDefaultShapeDef();
	CreateStaticBox(world, tbMakeVec2(0.0f, -1.0f), 20.0f, 1.0f, &groundDef);
	tbShapeDef plain = tbDefaultShapeDef();
	tbShapeDef custom = tbDefaultShapeDef();
	custom.enableCustomFiltering = true;
	tbBodyId solid, ghost;
	CreateBall(world, tbMakeVec2(-2.0f, 3.0f), tbMakeVec2(0.0f, 0.0f), 0.25f, &plain, &solid);
	FilterContext context = {
		CreateBall(world, tbMakeVec2(2.0f, 3.0f), tbMakeVec2(0.0f, 0.0f), 0.25f, &custom, &ghost), 0};
	tbWorld_SetCustomFilterCallback(world, KeepGhostOut, &context);
	for (int step = 0; step < 120; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
	}
	cr_assert(context.calls >= 1, "the filter was never asked");
	cr_assert(fabsf(tbBody_GetPosition(solid).y - 0.25f) < 0.01f, "solid ball at y %g", (double)tbBody_GetPosition(solid).y);
	cr_assert(fabsf(tbBody_GetPosition(ghost).y + 17.0f) < 0.05f, "ghost ball at y %g, expected −17",
			  (double)tbBody_GetPosition(ghost).y);
	tbDestroyWorld(world);
}

// --- one-way platform ------------------------------------------------------------------------------

typedef struct PlatformContext
{
	tbShapeId platform;
	int disabled;
	int passedContinuous;
} PlatformContext;

// Normal from the platform to the other shape: the callback's normal points from A to B.
static tbVec2 NormalFromPlatform(const PlatformContext* c, tbShapeId shapeIdA, tbVec2 normal)
{
	return TB_ID_EQUALS(shapeIdA, c->platform) ? normal : tbNeg(normal);
}

static void OneWayPreSolve(tbShapeId shapeIdA, tbShapeId shapeIdB, tbManifold* manifold, void* context)
{
	(void)shapeIdB;
	PlatformContext* c = context;
	// Only a body above the platform (normal pointing up from it) is held.
	if (NormalFromPlatform(c, shapeIdA, manifold->normal).y < 0.5f)
	{
		manifold->pointCount = 0;
		c->disabled += 1;
	}
}

static bool OneWayPreContinuous(tbShapeId shapeIdA, tbShapeId shapeIdB, tbVec2 point, tbVec2 normal, void* context)
{
	(void)shapeIdB;
	(void)point;
	PlatformContext* c = context;
	bool hold = NormalFromPlatform(c, shapeIdA, normal).y >= 0.5f;
	c->passedContinuous += hold ? 0 : 1;
	return hold;
}

// A ball thrown up at 12 m/s from y = 2 under a thin static platform (top at y = 5.1) passes up
// through it (the pre-solve callback disables the contact while the ball is below), rises to
// 2 + 12²/20 = 9.2 m, falls back and lands on top: at rest at 5.1 + 0.25 = 5.35 ± 0.01 m after 4 s.
// Without the callbacks it bounces off the underside and never rises above y = 4.65.
Test(callbacks, pre_solve_makes_a_one_way_platform)
{
	for (int variant = 0; variant < 2; ++variant)
	{
		tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
		tbShapeDef platformDef = tbDefaultShapeDef();
		platformDef.enablePreSolveEvents = true;
		PlatformContext context;
		memset(&context, 0, sizeof(context));
		context.platform = CreateStaticBox(world, tbMakeVec2(0.0f, 5.0f), 2.0f, 0.1f, &platformDef);
		if (variant == 0)
		{
			tbWorld_SetPreSolveCallback(world, OneWayPreSolve, OneWayPreContinuous, &context);
		}
		tbShapeDef ballDef = tbDefaultShapeDef();
		tbBodyId ball;
		CreateBall(world, tbMakeVec2(0.0f, 2.0f), tbMakeVec2(0.0f, 12.0f), 0.25f, &ballDef, &ball);
		float highest = 0.0f;
		for (int step = 0; step < 240; ++step)
		{
			tbWorld_Step(world, TIME_STEP, SUB_STEPS);
			highest = fmaxf(highest, tbBody_GetPosition(ball).y);
		}
		float y = tbBody_GetPosition(ball).y;
		if (variant == 0)
		{
			cr_assert(context.disabled > 0, "the callback never disabled the contact");
			cr_assert(fabsf(highest - 9.2f) < 0.1f, "apex %g, expected 9.2", (double)highest);
			cr_assert(fabsf(y - 5.35f) < 0.01f, "ball at y %g, expected 5.35 on the platform", (double)y);
			cr_assert(fabsf(tbBody_GetLinearVelocity(ball).y) < 0.01f);
		}
		else
		{
			cr_assert(highest < 4.66f, "without the callback the ball rose to %g", (double)highest);
		}
		tbDestroyWorld(world);
	}
}

static void BreakTheNormal(tbShapeId shapeIdA, tbShapeId shapeIdB, tbManifold* manifold, void* context)
{
	(void)shapeIdA;
	(void)shapeIdB;
	(void)context;
	manifold->normal = tbMakeVec2(NAN, 0.0f);
	manifold->pointCount = 5;
}

// A callback that leaves a NaN normal (and claims 5 points) is reported and its change undone: the
// ball still lands and rests on the ground at y = 0.25 ± 0.01.
Test(callbacks, a_broken_manifold_from_pre_solve_is_refused, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbShapeDef groundDef = tbDefaultShapeDef();
	groundDef.enablePreSolveEvents = true;
	CreateStaticBox(world, tbMakeVec2(0.0f, -1.0f), 20.0f, 1.0f, &groundDef);
	tbWorld_SetPreSolveCallback(world, BreakTheNormal, NULL, NULL);
	tbShapeDef ballDef = tbDefaultShapeDef();
	tbBodyId ball;
	CreateBall(world, tbMakeVec2(0.0f, 1.0f), tbMakeVec2(0.0f, 0.0f), 0.25f, &ballDef, &ball);
	int before = s_errors;
	for (int step = 0; step < 90; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
	}
	cr_assert(s_errors > before);
	cr_assert(strstr(s_lastError, "tbPreSolveFcn") != NULL && strstr(s_lastError, "normal") != NULL, "'%s'",
			  s_lastError);
	cr_assert(fabsf(tbBody_GetPosition(ball).y - 0.25f) < 0.01f, "ball at y %g", (double)tbBody_GetPosition(ball).y);
	tbDestroyWorld(world);
}

typedef struct DeepContext
{
	float separation;
	int calls;
} DeepContext;

static void WriteSeparation(tbShapeId shapeIdA, tbShapeId shapeIdB, tbManifold* manifold, void* context)
{
	(void)shapeIdA;
	(void)shapeIdB;
	DeepContext* c = context;
	c->calls += 1;
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		manifold->points[i].separation = c->separation;
	}
}

// A callback that writes a finite but impossible overlap (−1e30 m) into a ball's contact with the
// ground is reported and undone, for every solver: the ball rests at y = 0.25 ± 0.01 (as in the test
// above) and a box resting on the same ground beside it stays where it was within 1 cm. An overlap
// deeper than the smaller shape's box (the 0.5 m ball: 0.71 m) is one no two shapes can have.
Test(callbacks, an_impossible_overlap_from_pre_solve_is_refused, .init = SetupErrors, .fini = TeardownErrors)
{
	tbSolverMethod methods[3] = {tb_solverSoft, tb_solverBaumgarte, tb_solverNGS};
	for (int k = 0; k < 3; ++k)
	{
		tbWorldDef worldDef = tbDefaultWorldDef();
		worldDef.solver = methods[k];
		tbWorldId world = tbCreateWorld(&worldDef);
		tbShapeDef groundDef = tbDefaultShapeDef();
		CreateStaticBox(world, tbMakeVec2(0.0f, -1.0f), 20.0f, 1.0f, &groundDef);
		tbShapeDef ballDef = tbDefaultShapeDef();
		ballDef.enablePreSolveEvents = true;
		tbBodyId ball;
		CreateBall(world, tbMakeVec2(0.0f, 0.25f), tbMakeVec2(0.0f, 0.0f), 0.25f, &ballDef, &ball);
		tbBodyDef boxDef = tbDefaultBodyDef();
		boxDef.type = tb_dynamicBody;
		boxDef.position = tbMakeVec2(2.0f, 0.5f);
		tbBodyId box = tbCreateBody(world, &boxDef);
		tbPolygon square = tbMakeSquare(0.5f);
		tbShapeDef boxShapeDef = tbDefaultShapeDef();
		tbCreatePolygonShape(box, &boxShapeDef, &square);
		DeepContext context = {-1e30f, 0};
		tbWorld_SetPreSolveCallback(world, WriteSeparation, NULL, &context);
		int before = s_errors;
		for (int step = 0; step < 60; ++step)
		{
			tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		}
		cr_assert(context.calls > 0);
		cr_assert(s_errors > before, "solver %d: no error", k);
		cr_assert(strstr(s_lastError, "separation") != NULL, "'%s'", s_lastError);
		tbVec2 p = tbBody_GetPosition(ball);
		cr_assert(fabsf(p.y - 0.25f) < 0.01f && fabsf(p.x) < 0.01f, "solver %d: ball at (%g, %g)", k, (double)p.x,
				  (double)p.y);
		tbVec2 q = tbBody_GetPosition(box);
		cr_assert(fabsf(q.y - 0.5f) < 0.01f && fabsf(q.x - 2.0f) < 0.01f, "solver %d: box at (%g, %g)", k,
				  (double)q.x, (double)q.y);
		tbDestroyWorld(world);
	}
}

// Within the contract a callback may still ask for a deep overlap: 0.7 m on the 0.5 m ball (just
// inside the 0.71 m bound). No solver then pushes the ball faster than the world's speed limit,
// here maximumLinearSpeed = 10 m/s: below the Baumgarte solver's push for that overlap,
// β/h·0.7 m = 0.2 × 240/s × 0.7 m ≈ 34 m/s, so the limit is what holds it.
Test(callbacks, a_deep_overlap_from_pre_solve_stays_under_the_speed_limit, .init = SetupErrors,
	 .fini = TeardownErrors)
{
	tbSolverMethod methods[3] = {tb_solverSoft, tb_solverBaumgarte, tb_solverNGS};
	for (int k = 0; k < 3; ++k)
	{
		tbWorldDef worldDef = tbDefaultWorldDef();
		worldDef.solver = methods[k];
		worldDef.maximumLinearSpeed = 10.0f;
		tbWorldId world = tbCreateWorld(&worldDef);
		tbShapeDef groundDef = tbDefaultShapeDef();
		CreateStaticBox(world, tbMakeVec2(0.0f, -1.0f), 20.0f, 1.0f, &groundDef);
		tbShapeDef ballDef = tbDefaultShapeDef();
		ballDef.enablePreSolveEvents = true;
		tbBodyId ball;
		CreateBall(world, tbMakeVec2(0.0f, 0.25f), tbMakeVec2(0.0f, 0.0f), 0.25f, &ballDef, &ball);
		DeepContext context = {-0.7f, 0};
		tbWorld_SetPreSolveCallback(world, WriteSeparation, NULL, &context);
		int before = s_errors;
		for (int step = 0; step < 30; ++step)
		{
			tbWorld_Step(world, TIME_STEP, SUB_STEPS);
			float speed = tbLength(tbBody_GetLinearVelocity(ball));
			cr_assert(speed <= 10.0f * 1.0001f, "solver %d step %d: speed %g", k, step, (double)speed);
		}
		cr_assert_eq(s_errors, before, "'%s'", s_lastError);
		tbDestroyWorld(world);
	}
}

typedef struct FarContext
{
	int field; ///< 0: anchors, 1: impulses, 2: both
	int calls;
} FarContext;

static void WriteFarAnchorsAndImpulses(tbShapeId shapeIdA, tbShapeId shapeIdB, tbManifold* manifold, void* context)
{
	(void)shapeIdA;
	(void)shapeIdB;
	FarContext* c = context;
	c->calls += 1;
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		if (c->field != 1)
		{
			manifold->points[i].anchorA = tbMakeVec2(1e30f, 0.0f);
		}
		if (c->field != 0)
		{
			manifold->points[i].normalImpulse = -1e30f;
			manifold->points[i].tangentImpulse = 1e30f;
		}
	}
}

// Anchors finite but 1e30 m from the body (no manifold point can be farther from its body than the
// body's extent plus the speculative margin), impulses set to ±1e30 N·s (warm starting applies
// them at the anchors), and both. Each was accepted, and a callback doing both left the ball's
// position NaN with every solver (found by fuzz/fuzz_api.c). Each is now reported and undone: the
// ball rests at y = 0.25 ± 0.01 as in the tests above.
Test(callbacks, far_anchors_and_changed_impulses_from_pre_solve_are_refused, .init = SetupErrors,
	 .fini = TeardownErrors)
{
	tbSolverMethod methods[3] = {tb_solverSoft, tb_solverBaumgarte, tb_solverNGS};
	for (int field = 0; field < 3; ++field)
	{
		for (int k = 0; k < 3; ++k)
		{
			tbWorldDef worldDef = tbDefaultWorldDef();
			worldDef.solver = methods[k];
			tbWorldId world = tbCreateWorld(&worldDef);
			tbShapeDef groundDef = tbDefaultShapeDef();
			CreateStaticBox(world, tbMakeVec2(0.0f, -1.0f), 20.0f, 1.0f, &groundDef);
			tbShapeDef ballDef = tbDefaultShapeDef();
			ballDef.enablePreSolveEvents = true;
			tbBodyId ball;
			CreateBall(world, tbMakeVec2(0.0f, 0.5f), tbMakeVec2(0.0f, 0.0f), 0.25f, &ballDef, &ball);
			FarContext context = {field, 0};
			tbWorld_SetPreSolveCallback(world, WriteFarAnchorsAndImpulses, NULL, &context);
			int before = s_errors;
			for (int step = 0; step < 60; ++step)
			{
				tbWorld_Step(world, TIME_STEP, SUB_STEPS);
			}
			cr_assert(context.calls > 0);
			cr_assert(s_errors > before, "field %d solver %d: no error", field, k);
			cr_assert(strstr(s_lastError, field == 0 ? "anchor" : "impulse") != NULL, "'%s'", s_lastError);
			tbVec2 p = tbBody_GetPosition(ball);
			cr_assert(fabsf(p.y - 0.25f) < 0.01f && fabsf(p.x) < 0.01f, "field %d solver %d: ball at (%g, %g)", field,
					  k, (double)p.x, (double)p.y);
			tbDestroyWorld(world);
		}
	}
}
