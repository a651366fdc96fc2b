// World-level checks of the contact solver against closed forms and the stress criteria of
// the stress criteria of docs/stability.md: sliding distance, bounce apex, slope creep and slide, stacks,
// mass ratio, overlap recovery. 60 Hz, 4 sub-steps, g = 10 m/s², unless a test says otherwise.
// Each scene runs with the default soft step; the rigid methods run where they are expected to
// pass (failures of Baumgarte/NGS on the hard scenes are documented in docs/stability.md, not asserted).
#include "collide_world.h"
#include "tumble/tumble.h"

#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>

#define TIME_STEP (1.0f / 60.0f)
#define SUB_STEPS 4
#define GRAVITY 10.0f
#define MAX_BODIES 16

static const char* s_methodNames[tb_solverMethodCount] = {"soft", "baumgarte", "ngs"};

typedef struct Scene
{
	tbWorldId worldId;
	tbBodyId ground;
	tbPolygon groundBox;
	tbBodyId bodies[MAX_BODIES];
	tbPolygon boxes[MAX_BODIES];
	int bodyCount;
} Scene;

static Scene CreateScene(tbSolverMethod method, bool enableSleep)
{
	Scene scene = {0};
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, -GRAVITY);
	def.solver = method;
	def.enableSleep = enableSleep;
	scene.worldId = tbCreateWorld(&def);
	cr_assert(tbWorld_IsValid(scene.worldId));
	return scene;
}

// Static ground box of half extents (50, 1) whose top surface is y = 0, turned by angle about the
// origin (the top surface still passes through the origin).
static void AddGround(Scene* scene, float angle, float friction, float restitution)
{
	tbBodyDef bd = tbDefaultBodyDef();
	bd.rotation = tbMakeRot(angle);
	scene->ground = tbCreateBody(scene->worldId, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	sd.material.friction = friction;
	sd.material.restitution = restitution;
	scene->groundBox = tbMakeOffsetBox(50.0f, 1.0f, tbMakeVec2(0.0f, -1.0f), tbRot_identity);
	tbCreatePolygonShape(scene->ground, &sd, &scene->groundBox);
}

static tbBodyId AddBox(Scene* scene, tbVec2 position, float angle, float halfWidth, float density, float friction)
{
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	bd.position = position;
	bd.rotation = tbMakeRot(angle);
	tbBodyId id = tbCreateBody(scene->worldId, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	sd.density = density;
	sd.material.friction = friction;
	tbPolygon box = tbMakeBox(halfWidth, halfWidth);
	tbCreatePolygonShape(id, &sd, &box);
	cr_assert(scene->bodyCount < MAX_BODIES);
	scene->bodies[scene->bodyCount] = id;
	scene->boxes[scene->bodyCount] = box;
	scene->bodyCount += 1;
	return id;
}

static void Step(Scene* scene, int stepCount)
{
	for (int i = 0; i < stepCount; ++i)
	{
		tbWorld_Step(scene->worldId, TIME_STEP, SUB_STEPS);
	}
}

// Deepest overlap (m, ≥ 0) among the boxes and between each box and the ground, measured with the
// public manifold function on the current transforms (independent of the solver's own numbers).
static float MaxPenetration(const Scene* scene)
{
	float deepest = 0.0f;
	tbTransform groundXf = tbBody_GetTransform(scene->ground);
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		tbTransform xfA = tbBody_GetTransform(scene->bodies[i]);
		tbManifold m = WorldCollidePolygons(&scene->groundBox, groundXf, scene->boxes + i, xfA);
		for (int k = 0; k < m.pointCount; ++k)
		{
			deepest = fmaxf(deepest, -m.points[k].separation);
		}
		for (int j = i + 1; j < scene->bodyCount; ++j)
		{
			tbTransform xfB = tbBody_GetTransform(scene->bodies[j]);
			m = WorldCollidePolygons(scene->boxes + i, xfA, scene->boxes + j, xfB);
			for (int k = 0; k < m.pointCount; ++k)
			{
				deepest = fmaxf(deepest, -m.points[k].separation);
			}
		}
	}
	return deepest;
}

// ---------------------------------------------------------------------------------------------
// Sliding box: 1 m box at 5 m/s, μ = 0.6, stops after v²/(2μg) = 25/12 = 2.083 m.

static void SlidingBox(tbSolverMethod method)
{
	Scene scene = CreateScene(method, true);
	AddGround(&scene, 0.0f, 0.6f, 0.0f);
	tbBodyId box = AddBox(&scene, tbMakeVec2(0.0f, 0.5f), 0.0f, 0.5f, 1.0f, 0.6f);
	tbBody_SetLinearVelocity(box, tbMakeVec2(5.0f, 0.0f));
	Step(&scene, 120); // 2 s; the slide takes v/(μg) = 0.83 s
	float distance = tbBody_GetPosition(box).x;
	float expected = 25.0f / (2.0f * 0.6f * GRAVITY);
	fprintf(stderr, "slide[%s]: %.4f m (closed form %.4f, error %.2f%%), v = %.4f\n", s_methodNames[method], distance,
			expected, 100.0f * (distance - expected) / expected, tbBody_GetLinearVelocity(box).x);
	// 3%: the stop is resolved to one step of 1/60 s, whose travel at the mean speed (2.5/60 m) is 2% of
	// the 2.08 m; Box2D 2.4.1 gives −2% on this set-up (friction acting from the first step).
	cr_expect(fabsf(distance - expected) < 0.03f * expected, "slide %f vs %f", distance, expected);
	cr_expect(fabsf(tbBody_GetLinearVelocity(box).x) < 1e-3f, "box still moving");
	tbDestroyWorld(scene.worldId);
}

Test(solver, slide_soft)
{
	SlidingBox(tb_solverSoft);
}

Test(solver, slide_baumgarte)
{
	SlidingBox(tb_solverBaumgarte);
}

Test(solver, slide_ngs)
{
	SlidingBox(tb_solverNGS);
}

// ---------------------------------------------------------------------------------------------
// Bounce: ball r = 0.5 with its bottom 5 m above the ground; apex after the first bounce e²·5 m.

static float BounceApex(tbSolverMethod method, float restitution, float* finalHeight)
{
	Scene scene = CreateScene(method, true);
	AddGround(&scene, 0.0f, 0.6f, 0.0f);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	bd.position = tbMakeVec2(0.0f, 5.5f);
	tbBodyId ball = tbCreateBody(scene.worldId, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	sd.material.restitution = restitution; // mixed with the ground's 0 by max
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbCreateCircleShape(ball, &sd, &circle);

	// Fall (≈ 1 s), then follow the rebound until it turns down again.
	bool rebounded = false;
	float apex = 0.0f;
	for (int i = 0; i < 180; ++i)
	{
		Step(&scene, 1);
		float vy = tbBody_GetLinearVelocity(ball).y;
		float bottom = tbBody_GetPosition(ball).y - 0.5f;
		if (vy > 0.0f)
		{
			rebounded = true;
		}
		if (rebounded)
		{
			apex = fmaxf(apex, bottom);
		}
		if (rebounded && vy < 0.0f)
		{
			break;
		}
	}
	Step(&scene, 180);
	*finalHeight = tbBody_GetPosition(ball).y - 0.5f;
	tbDestroyWorld(scene.worldId);
	return apex;
}

static void Bounce(tbSolverMethod method)
{
	float finalHeight;
	float apex = BounceApex(method, 0.5f, &finalHeight);
	float expected = 0.25f * 5.0f;
	fprintf(stderr, "bounce[%s]: apex %.4f m (closed form %.4f, error %.2f%%)\n", s_methodNames[method], apex, expected,
			100.0f * (apex - expected) / expected);
	// 3%: the impact falls inside one step of 1/60 s, which moves the apex by up to v·Δt·e/2 ≈ 2% of
	// 1.25 m (v = 5 m/s at impact); Box2D 2.4.1 gives +1% on this set-up.
	cr_expect(fabsf(apex - expected) < 0.03f * expected, "apex %f vs %f", apex, expected);

	apex = BounceApex(method, 0.0f, &finalHeight);
	fprintf(stderr, "bounce[%s] e=0: apex %.5f m, rest %.5f m\n", s_methodNames[method], apex, finalHeight);
	// e = 0: no rebound beyond the speculative margin (0.02 m), and it rests on the surface
	// within 1 cm (soft contacts settle a fraction of a millimetre in).
	cr_expect(apex < 0.02f, "e = 0 ball rebounded to %f", apex);
	cr_expect(fabsf(finalHeight) < 0.01f, "e = 0 ball rests at %f", finalHeight);
}

Test(solver, bounce_soft)
{
	Bounce(tb_solverSoft);
}

Test(solver, bounce_baumgarte)
{
	Bounce(tb_solverBaumgarte);
}

Test(solver, bounce_ngs)
{
	Bounce(tb_solverNGS);
}

// ---------------------------------------------------------------------------------------------
// A tall block on a slope: where friction acts when one corner carries the load.
//
// A block 0.5 m wide and 2 m tall, μ = 1, stands on a slope of angle θ. Statics: it tips once the
// line of its weight leaves its base, tan θ > w/h = 0.25 (θ > 14.0°), and slides only once
// tan θ > μ (45°). At 10° it stands; at 20° it tips over its downhill corner without sliding.
// While it tips, that corner carries all the normal impulse and the uphill one hovers a speculative
// gap above the slope: central friction's row sits at the centre of pressure, the loaded corner,
// where per-point rows put all the friction too. (Where on the base the row sits changes its torque
// by at most that gap times the friction force: measured, a row at the middle of the base slips
// 0.43 mm against 0.40, so this checks the one-corner case's outcome, not the weighting, which
// central_friction_acts_at_the_centre_of_pressure checks.) Both friction kinds must give the
// closed-form answer.

typedef struct TipResult
{
	float turn;	 ///< rad, the block's turn relative to the slope after 3 s
	float slip;	 ///< m, how far the downhill corner moved along the slope before the turn reached 30°
} TipResult;

static TipResult TipBlock(float slopeDegrees, bool centralFriction)
{
	float slope = slopeDegrees * TB_PI / 180.0f;
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, -GRAVITY);
	def.enableSleep = false;
	def.enableCentralFriction = centralFriction;
	tbWorldId world = tbCreateWorld(&def);
	Scene scene = {0};
	scene.worldId = world;
	AddGround(&scene, slope, 1.0f, 0.0f);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	tbRot q = tbMakeRot(slope);
	bd.position = tbRotateVector(q, tbMakeVec2(0.0f, 1.0f)); // base on the slope
	bd.rotation = q;
	tbBodyId block = tbCreateBody(world, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	sd.material.friction = 1.0f;
	tbPolygon box = tbMakeBox(0.25f, 1.0f);
	tbCreatePolygonShape(block, &sd, &box);

	tbVec2 corner = tbMakeVec2(-0.25f, -1.0f); // downhill: the slope rises towards +x
	tbVec2 along = tbRot_GetXAxis(q);
	float start = tbDot(tbBody_GetWorldPoint(block, corner), along);
	TipResult result = {0.0f, 0.0f};
	for (int i = 0; i < 180; ++i)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		float turn = tbRelativeAngle(q, tbBody_GetRotation(block));
		if (fabsf(turn) < 30.0f * TB_PI / 180.0f)
		{
			result.slip = fmaxf(result.slip, fabsf(tbDot(tbBody_GetWorldPoint(block, corner), along) - start));
		}
		result.turn = turn;
	}
	tbDestroyWorld(world);
	return result;
}

Test(solver, tall_block_tips_over_its_loaded_corner)
{
	for (int central = 1; central >= 0; --central)
	{
		TipResult stand = TipBlock(10.0f, central != 0);
		TipResult tip = TipBlock(20.0f, central != 0);
		fprintf(stderr, "tall block [%s friction]: 10° turn %.4f rad slip %.5f m; 20° turn %.3f rad slip %.5f m\n",
				central ? "central" : "point", stand.turn, stand.slip, tip.turn, tip.slip);
		// 10°: stands. Turn within 0.01 rad and slip within 1 mm in 3 s (the slope test's creep bound).
		cr_expect(fabsf(stand.turn) < 0.01f && stand.slip < 1e-3f, "10°: turn %f rad, slip %f m", stand.turn, stand.slip);
		// 20°: falls onto its side, a quarter turn downhill (within 0.1 rad: it rests on the slope),
		// and the corner it tips over holds (within 1 cm: the soft contact's give, no sliding).
		cr_expect(fabsf(tip.turn - 0.5f * TB_PI) < 0.1f, "20°: turn %f rad", tip.turn);
		cr_expect(tip.slip < 0.01f, "20°: the tipping corner slipped %f m", tip.slip);
	}
}

// ---------------------------------------------------------------------------------------------
// Slope of 20°: a 1 m box resting on it. Distance is measured along the slope.

#define SLOPE_ANGLE (20.0f * TB_PI / 180.0f)

static float SlopeTravel(tbSolverMethod method, float friction, int stepCount)
{
	Scene scene = CreateScene(method, false); // no sleep: creep must not hide behind sleeping
	AddGround(&scene, SLOPE_ANGLE, friction, 0.0f);
	tbRot q = tbMakeRot(SLOPE_ANGLE);
	tbVec2 start = tbRotateVector(q, tbMakeVec2(0.0f, 0.5f));
	tbBodyId box = AddBox(&scene, start, SLOPE_ANGLE, 0.5f, 1.0f, friction);
	Step(&scene, stepCount);
	tbVec2 d = tbSub(tbBody_GetPosition(box), start);
	float downSlope = -tbDot(d, tbRot_GetXAxis(q));
	tbDestroyWorld(scene.worldId);
	return downSlope;
}

static void SlopeHold(tbSolverMethod method)
{
	float travel = SlopeTravel(method, tanf(SLOPE_ANGLE) + 0.05f, 600);
	fprintf(stderr, "slope hold[%s]: creep %.6f m in 10 s\n", s_methodNames[method], travel);
	// 1 mm in 10 s: the "slope" pass criterion (docs/stability.md).
	cr_expect(fabsf(travel) < 1e-3f, "creep %f m", travel);
}

static void SlopeSlide(tbSolverMethod method)
{
	float mu = 0.2f;
	float travel = SlopeTravel(method, mu, 60);
	float expected = 0.5f * GRAVITY * (sinf(SLOPE_ANGLE) - mu * cosf(SLOPE_ANGLE));
	fprintf(stderr, "slope slide[%s]: %.4f m in 1 s (closed form %.4f, error %.2f%%)\n", s_methodNames[method], travel,
			expected, 100.0f * (travel - expected) / expected);
	// 2%: semi-implicit Euler runs ½·a·Δt·t ahead of the closed form, +0.8% at t = 1 s and Δt = 1/60 s;
	// the rest covers the soft contact's first steps.
	cr_expect(fabsf(travel - expected) < 0.02f * expected, "slide %f vs %f", travel, expected);
}

Test(solver, slope_hold_soft)
{
	SlopeHold(tb_solverSoft);
}

Test(solver, slope_hold_baumgarte)
{
	SlopeHold(tb_solverBaumgarte);
}

Test(solver, slope_hold_ngs)
{
	SlopeHold(tb_solverNGS);
}

Test(solver, slope_slide_soft)
{
	SlopeSlide(tb_solverSoft);
}

Test(solver, slope_slide_baumgarte)
{
	SlopeSlide(tb_solverBaumgarte);
}

Test(solver, slope_slide_ngs)
{
	SlopeSlide(tb_solverNGS);
}

// ---------------------------------------------------------------------------------------------
// Stack of ten 1 m boxes resting exactly on each other, 10 s, sleep off.

static void Stack(tbSolverMethod method)
{
	Scene scene = CreateScene(method, false);
	AddGround(&scene, 0.0f, 0.6f, 0.0f);
	for (int i = 0; i < 10; ++i)
	{
		AddBox(&scene, tbMakeVec2(0.0f, 0.5f + (float)i), 0.0f, 0.5f, 1.0f, 0.6f);
	}
	tbVec2 top0 = tbBody_GetPosition(scene.bodies[9]);
	float worst = 0.0f;
	for (int i = 0; i < 600; ++i)
	{
		Step(&scene, 1);
		worst = fmaxf(worst, MaxPenetration(&scene));
	}
	float drift = tbDistance(tbBody_GetPosition(scene.bodies[9]), top0);
	fprintf(stderr, "stack[%s]: top drift %.4f m, worst penetration %.4f m\n", s_methodNames[method], drift, worst);
	// Brief: top drift < 0.05 m (soft sag ≈ Σ g/ω² ≈ 0.01 m at 30 Hz), penetration < 0.02 m.
	cr_expect(drift < 0.05f, "top drift %f", drift);
	cr_expect(worst < 0.02f, "penetration %f", worst);
	tbDestroyWorld(scene.worldId);
}

Test(solver, stack_soft)
{
	Stack(tb_solverSoft);
}

Test(solver, stack_baumgarte)
{
	Stack(tb_solverBaumgarte);
}

Test(solver, stack_ngs)
{
	Stack(tb_solverNGS);
}

// ---------------------------------------------------------------------------------------------
// Mass ratio 100:1: a 100 kg 1 m box on a 1 kg 1 m box, 5 s.

static void HeavyOnLight(tbSolverMethod method)
{
	Scene scene = CreateScene(method, false);
	AddGround(&scene, 0.0f, 0.6f, 0.0f);
	tbBodyId light = AddBox(&scene, tbMakeVec2(0.0f, 0.5f), 0.0f, 0.5f, 1.0f, 0.6f);
	tbBodyId heavy = AddBox(&scene, tbMakeVec2(0.0f, 1.5f), 0.0f, 0.5f, 100.0f, 0.6f);
	float worst = 0.0f;
	for (int i = 0; i < 300; ++i)
	{
		Step(&scene, 1);
		worst = fmaxf(worst, MaxPenetration(&scene));
	}
	tbVec2 pl = tbBody_GetPosition(light);
	tbVec2 ph = tbBody_GetPosition(heavy);
	fprintf(stderr, "heavy on light[%s]: heavy at (%.4f, %.4f), light at (%.4f, %.4f), worst penetration %.4f m\n",
			s_methodNames[method], ph.x, ph.y, pl.x, pl.y, worst);
	// Stays stacked: heavy above light, both still near x = 0 (0.05 m: nothing pushes sideways).
	cr_expect(ph.y > pl.y + 0.9f && fabsf(ph.x) < 0.05f && fabsf(pl.x) < 0.05f, "stack fell");
	// Brief: penetration < 0.05 m.
	cr_expect(worst < 0.05f, "penetration %f", worst);
	tbDestroyWorld(scene.worldId);
}

Test(solver, heavy_on_light_soft)
{
	HeavyOnLight(tb_solverSoft);
}

Test(solver, heavy_on_light_baumgarte)
{
	HeavyOnLight(tb_solverBaumgarte);
}

Test(solver, heavy_on_light_ngs)
{
	HeavyOnLight(tb_solverNGS);
}

// ---------------------------------------------------------------------------------------------
// Overlap recovery (docs/stability.md): a 4-base pyramid of ten 1 m boxes with centres 0.75 m apart in x
// and y (25% overlap). Must separate within 1 s without flinging anything.

static void OverlapRecovery(tbSolverMethod method)
{
	Scene scene = CreateScene(method, false);
	AddGround(&scene, 0.0f, 0.6f, 0.0f);
	for (int row = 0; row < 4; ++row)
	{
		int count = 4 - row;
		for (int col = 0; col < count; ++col)
		{
			float x = 0.75f * ((float)col - 0.5f * (float)(count - 1));
			AddBox(&scene, tbMakeVec2(x, 0.5f + 0.75f * (float)row), 0.0f, 0.5f, 1.0f, 0.6f);
		}
	}
	float peakSpeed = 0.0f;
	for (int i = 0; i < 60; ++i)
	{
		Step(&scene, 1);
		for (int k = 0; k < scene.bodyCount; ++k)
		{
			peakSpeed = fmaxf(peakSpeed, tbLength(tbBody_GetLinearVelocity(scene.bodies[k])));
		}
	}
	float overlap = MaxPenetration(&scene);
	fprintf(stderr, "overlap recovery[%s]: overlap after 1 s %.4f m, peak speed %.3f m/s\n", s_methodNames[method],
			overlap, peakSpeed);
	// Brief: < 0.01 m within 1 s, no body above 4 m/s (measured: soft solvers 3 m/s, projection 8–12).
	cr_expect(overlap < 0.01f, "overlap %f", overlap);
	cr_expect(peakSpeed < 4.0f, "peak speed %f", peakSpeed);
	tbDestroyWorld(scene.worldId);
}

Test(solver, overlap_recovery_soft)
{
	OverlapRecovery(tb_solverSoft);
}

Test(solver, overlap_recovery_ngs)
{
	OverlapRecovery(tb_solverNGS);
}

// Not asserted for Baumgarte: the velocity bias (β/h)·overlap = 0.2·240·0.25 = 12 m/s per
// sub-step flings the boxes (measured peak 33 m/s), the failure docs/stability.md records.

// ---------------------------------------------------------------------------------------------
// Determinism, settling and sleep. The solve order (island.c, tbOrderSolverContacts) must not
// depend on addresses, and a pyramid must come to rest without the sideways drift that a fixed
// Gauss–Seidel sweep causes ("pyramid" criterion, docs/stability.md: top drift < 0.1 m).

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

// Pyramid of 1 m boxes (base `base`, friction `friction`) on the ground of AddGround; returns the
// body ids (row by row, bottom first; the last is the top box). Free with free().
static tbBodyId* AddPyramid(tbWorldId worldId, int base, float friction)
{
	int count = base * (base + 1) / 2;
	tbBodyId* ids = malloc(sizeof(tbBodyId) * (size_t)count);
	cr_assert(ids != NULL);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbShapeDef sd = tbDefaultShapeDef();
	sd.material.friction = friction;
	int n = 0;
	for (int row = 0; row < base; ++row)
	{
		int rowCount = base - row;
		for (int j = 0; j < rowCount; ++j)
		{
			tbBodyDef bd = tbDefaultBodyDef();
			bd.type = tb_dynamicBody;
			bd.position = tbMakeVec2((float)j - 0.5f * (float)(rowCount - 1), 0.5f + (float)row);
			ids[n] = tbCreateBody(worldId, &bd);
			tbCreatePolygonShape(ids[n], &sd, &box);
			n += 1;
		}
	}
	return ids;
}

// A 10-base pyramid (55 boxes) with four tilted boxes dropped onto it, sleep off: contacts begin
// and end during the run, so the test covers contact creation order as well as the solve.
static tbBodyId* BuildDeterminismScene(Scene* scene, int* bodyCount)
{
	*scene = CreateScene(tb_solverSoft, false);
	AddGround(scene, 0.0f, 0.6f, 0.0f);
	tbBodyId* pyramid = AddPyramid(scene->worldId, 10, 0.6f);
	tbBodyId* ids = malloc(sizeof(tbBodyId) * 59);
	cr_assert(ids != NULL);
	memcpy(ids, pyramid, sizeof(tbBodyId) * 55);
	free(pyramid);
	for (int i = 0; i < 4; ++i)
	{
		tbBodyDef bd = tbDefaultBodyDef();
		bd.type = tb_dynamicBody;
		bd.position = tbMakeVec2(-3.0f + 2.0f * (float)i, 12.0f + 1.5f * (float)i);
		bd.rotation = tbMakeRot(0.3f * (float)i + 0.1f);
		ids[55 + i] = tbCreateBody(scene->worldId, &bd);
		tbShapeDef sd = tbDefaultShapeDef();
		tbPolygon box = tbMakeBox(0.4f, 0.25f);
		tbCreatePolygonShape(ids[55 + i], &sd, &box);
	}
	*bodyCount = 59;
	return ids;
}

// FNV-1a (32 bit) over the bytes of every body's transform, in body creation order.
static uint32_t HashTransforms(const tbBodyId* ids, int count)
{
	uint32_t hash = 2166136261u;
	for (int i = 0; i < count; ++i)
	{
		tbTransform xf = tbBody_GetTransform(ids[i]);
		unsigned char bytes[sizeof(tbTransform)];
		memcpy(bytes, &xf, sizeof(xf));
		for (size_t k = 0; k < sizeof(bytes); ++k)
		{
			hash = (hash ^ bytes[k]) * 16777619u;
		}
	}
	return hash;
}

static uint32_t RunDeterminismScene(void)
{
	Scene scene;
	int count = 0;
	tbBodyId* ids = BuildDeterminismScene(&scene, &count);
	Step(&scene, 120);
	uint32_t hash = HashTransforms(ids, count);
	free(ids);
	tbDestroyWorld(scene.worldId);
	return hash;
}

Test(solver, determinism_repeatable)
{
	// The same scene stepped twice in one process: bit-identical transforms (hash over all bytes).
	uint32_t first = RunDeterminismScene();
	uint32_t second = RunDeterminismScene();
	cr_expect_eq(first, second, "run 1 hash %08x, run 2 hash %08x", first, second);
}

// Golden hash of the determinism scene after 120 steps (60 Hz, 4 sub-steps, soft step, this
// build's -ffp-contract=off). It changes only when the maths changes: solver, collision, solve
// order, integration or constants. After such a deliberate change, run this test, check that
// determinism_repeatable still passes and that the other solver tests still pass, then paste the
// printed hash here and say so in the commit message. It must never change from a refactoring.
#define GOLDEN_DETERMINISM_HASH 0xb0f2bff0u

Test(solver, determinism_golden_hash)
{
	uint32_t hash = RunDeterminismScene();
	fprintf(stderr, "determinism scene hash after 120 steps: 0x%08xu\n", hash);
	cr_expect_eq(hash, GOLDEN_DETERMINISM_HASH, "hash 0x%08x, golden 0x%08x (see comment to update)", hash,
				 GOLDEN_DETERMINISM_HASH);
}

Test(solver, pyramid_20_settles_and_sleeps)
{
	// "pyramid" (docs/stability.md): base 20 (210 boxes), friction 0.6, touching. Brief: fully asleep within
	// 5 s, top box within 0.05 m of its start height (default soft step, sleep on).
	Scene scene = CreateScene(tb_solverSoft, true);
	AddGround(&scene, 0.0f, 0.6f, 0.0f);
	tbBodyId* ids = AddPyramid(scene.worldId, 20, 0.6f);
	tbBodyId top = ids[209];
	tbVec2 top0 = tbBody_GetPosition(top);
	Step(&scene, 300);
	tbVec2 top1 = tbBody_GetPosition(top);
	int awake = 0;
	for (int i = 0; i < 210; ++i)
	{
		awake += tbBody_IsAwake(ids[i]) ? 1 : 0;
	}
	fprintf(stderr, "pyramid 20: top sag %.4f m, drift %.4f m, awake %d\n", top0.y - top1.y, top1.x - top0.x, awake);
	cr_expect(fabsf(top1.y - top0.y) < 0.05f, "top height change %f m", top1.y - top0.y);
	cr_expect(fabsf(top1.x - top0.x) < 0.1f, "top drift %f m", top1.x - top0.x);
	cr_expect_eq(awake, 0, "%d boxes still awake after 5 s", awake);
	free(ids);
	tbDestroyWorld(scene.worldId);
}

Test(solver, stack_sleeps)
{
	// Stack of ten 1 m boxes as in Stack(), sleep on: every box asleep at the end of 10 s.
	Scene scene = CreateScene(tb_solverSoft, true);
	AddGround(&scene, 0.0f, 0.6f, 0.0f);
	for (int i = 0; i < 10; ++i)
	{
		AddBox(&scene, tbMakeVec2(0.0f, 0.5f + (float)i), 0.0f, 0.5f, 1.0f, 0.6f);
	}
	Step(&scene, 600);
	int awake = 0;
	for (int i = 0; i < scene.bodyCount; ++i)
	{
		awake += tbBody_IsAwake(scene.bodies[i]) ? 1 : 0;
	}
	cr_expect_eq(awake, 0, "%d boxes still awake after 10 s", awake);
	tbDestroyWorld(scene.worldId);
}

// ---------------------------------------------------------------------------------------------
// Soft step: touching stack of 20 (docs/stability.md). At 30 Hz the soft contacts make the column sway
// and, with one relax pass, buckle (critical stiffness ≈ 45–50 Hz); settled contacts take the
// resting stiffness (2 × 30 Hz, at most ¼ of the sub-step rate, solver_soft.c), which keeps it
// standing, and more sub-steps must not be worse than fewer.

static float TouchingStack20(int subSteps, float* slide)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, -GRAVITY);
	def.enableSleep = false;
	tbWorldId worldId = tbCreateWorld(&def);
	tbBodyDef gd = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(worldId, &gd);
	tbShapeDef sd = tbDefaultShapeDef();
	sd.material.friction = 0.6f;
	tbPolygon groundBox = tbMakeOffsetBox(50.0f, 1.0f, tbMakeVec2(0.0f, -1.0f), tbRot_identity);
	tbCreatePolygonShape(ground, &sd, &groundBox);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbBodyId top = tbCreateBody(worldId, &gd);
	for (int i = 0; i < 20; ++i)
	{
		tbBodyDef bd = tbDefaultBodyDef();
		bd.type = tb_dynamicBody;
		bd.position = tbMakeVec2(0.0f, 0.5f + (float)i);
		top = tbCreateBody(worldId, &bd);
		tbCreatePolygonShape(top, &sd, &box);
	}
	for (int i = 0; i < 600; ++i)
	{
		tbWorld_Step(worldId, TIME_STEP, subSteps);
	}
	tbVec2 p = tbBody_GetPosition(top);
	tbDestroyWorld(worldId);
	*slide = p.x;
	return 19.5f - p.y;
}

Test(solver, touching_stack_20_soft_more_substeps_not_worse)
{
	float slide4 = 0.0f, slide8 = 0.0f, slide16 = 0.0f;
	float sink4 = TouchingStack20(4, &slide4);
	float sink8 = TouchingStack20(8, &slide8);
	float sink16 = TouchingStack20(16, &slide16);
	fprintf(stderr, "touching stack 20: sink/slide 4: %.3f/%.3f, 8: %.3f/%.3f, 16: %.3f/%.3f m\n", sink4, slide4, sink8,
			slide8, sink16, slide16);
	// docs/stability.md: top within 0.1 m of its rigid height (and standing).
	cr_expect(sink4 < 0.1f && fabsf(slide4) < 0.1f, "4 sub-steps: sink %f slide %f", sink4, slide4);
	cr_expect(sink8 < 0.1f && fabsf(slide8) < 0.1f, "8 sub-steps: sink %f slide %f", sink8, slide8);
	cr_expect(sink16 < 0.1f && fabsf(slide16) < 0.1f, "16 sub-steps: sink %f slide %f", sink16, slide16);
	cr_expect(sink8 <= sink4 + 0.01f, "8 sub-steps sink %f worse than 4 (%f)", sink8, sink4);
}

Test(solver, heavy_on_light_soft_rests_at_the_spring_depth)
{
	// 1:100 (a 100 kg box on a 1 kg box on the ground) at the default 4 sub-steps. Settled dynamic
	// contacts are springs of the settled stiffness ω = 2π·min(1.75·30 Hz, ¼·240 Hz) = 2π·52.5 Hz
	// (tbWorldDef::settledHertzRatio), and a spring
	// point carrying the force F rests at the depth F/(m_eff·ω²) (solver_soft.c). Each of the two
	// points of the heavy-on-light contact carries half the heavy box's weight, F = 500 N, with
	// m_eff = 1/(1/mA + 1/mB + (rA × n)²/IA + (rB × n)²/IB), rA = (±0.5, 0.5), rB = (±0.5, −0.5):
	// 1/(1 + 0.01 + 0.25/(1/6) + 0.25/(100/6)) = 0.396 kg, so the depth is 11.6 mm. After 2 s
	// (settled), the measured depth must be that within 10 % (the boxes' tilt of a few 1e-4 rad and
	// the relax passes move it by less; the contact's own 2 points share the load within 1 %).
	Scene scene = CreateScene(tb_solverSoft, false);
	AddGround(&scene, 0.0f, 0.6f, 0.0f);
	tbBodyId light = AddBox(&scene, tbMakeVec2(0.0f, 0.5f), 0.0f, 0.5f, 1.0f, 0.6f);
	tbBodyId heavy = AddBox(&scene, tbMakeVec2(0.0f, 1.5f), 0.0f, 0.5f, 100.0f, 0.6f);
	Step(&scene, 120);
	tbManifold m = WorldCollidePolygons(scene.boxes + 0, tbBody_GetTransform(light), scene.boxes + 1,
									 tbBody_GetTransform(heavy));
	cr_assert_eq(m.pointCount, 2);
	float depth = -0.5f * (m.points[0].separation + m.points[1].separation);
	float invK = 1.0f + 0.01f + 0.25f * 6.0f + 0.25f * 6.0f / 100.0f;
	float omega = 2.0f * TB_PI * 52.5f;
	float expected = 500.0f / ((1.0f / invK) * omega * omega);
	fprintf(stderr, "heavy on light soft: resting depth %.5f m, spring depth %.5f m\n", depth, expected);
	cr_expect(fabsf(depth - expected) < 0.1f * expected, "depth %f, expected %f", depth, expected);
	tbDestroyWorld(scene.worldId);
}

/// Newton's cradle as the catalogue builds it (five touching balls of radius 0.5, e = 1, no
/// friction or gravity, a sixth striking at v0 = 2.71 m/s): the velocities after 3 s, last ball
/// and the largest of the others, as fractions of v0.
static void RunCradle(bool propagate, float* last, float* others)
{
	const float v0 = 2.71f;
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, 0.0f);
	def.enableImpactPropagation = propagate;
	tbWorldId world = tbCreateWorld(&def);
	tbBodyId balls[6];
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material.friction = 0.0f;
	shapeDef.material.restitution = 1.0f;
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	for (int i = 0; i < 6; ++i)
	{
		tbBodyDef bodyDef = tbDefaultBodyDef();
		bodyDef.type = tb_dynamicBody;
		bodyDef.position = tbMakeVec2(i < 5 ? (float)i : -3.0f, 0.0f);
		bodyDef.linearVelocity = tbMakeVec2(i < 5 ? 0.0f : v0, 0.0f);
		balls[i] = tbCreateBody(world, &bodyDef);
		tbCreateCircleShape(balls[i], &shapeDef, &circle);
	}
	for (int step = 0; step < 180; ++step)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	*last = tbBody_GetLinearVelocity(balls[4]).x / v0;
	*others = 0.0f;
	for (int i = 0; i < 6; ++i)
	{
		*others = i == 4 ? *others : fmaxf(*others, tbLength(tbBody_GetLinearVelocity(balls[i])) / v0);
	}
	tbDestroyWorld(world);
}

// Newton's cradle: equal masses and e = 1 make each collision of two balls swap their velocities,
// so the striker stops and the last ball leaves at v0 with the others at rest (momentum and energy
// both conserved). Solved together, as the sequential-impulse solver does, the contacts share the
// striker's momentum among the chain: the last ball leaves at about 0.35 v0 (as Box2D v3's). With
// impact propagation (collisions taken one pair at a time) it leaves at ≥ 0.95 v0 and every other
// ball moves at ≤ 0.05 v0 (the 5 % allow for the soft contacts' slight overlap at impact).
Test(solver, newtons_cradle_with_impact_propagation)
{
	float last, others;
	RunCradle(false, &last, &others);
	cr_assert(last < 0.5f, "without propagation the last ball was expected to share the momentum (%.2f v0)",
			  (double)last);
	RunCradle(true, &last, &others);
	cr_assert(last >= 0.95f, "last ball %.3f v0, expected >= 0.95", (double)last);
	cr_assert(others <= 0.05f, "other balls up to %.3f v0, expected <= 0.05", (double)others);
}
