// Speculative contacts with a velocity-dependent margin (contact.c, tbSpeculativeMargin): bodies
// too slow for continuous collision (they move less than TB_CONTINUOUS_FRACTION = 0.5 of their
// extent per step) must still be stopped at impact instead of landing deep and being pushed out.
//
// Sources of the expected numbers:
// - a body moving less than 0.5·minExtent per step is not swept (TB_CONTINUOUS_FRACTION); a 1 m
//   box (minExtent 0.5 m) at 60 Hz is swept above 0.5·0.5·60 = 15 m/s, so 2, 5.5, 10 and 14 m/s
//   impacts are speculative contacts' job;
// - with the fixed 0.02 m speculative distance, a body that starts its impact step a gap d above
//   the ground with 0.02 ≤ d < v·dt has no manifold point in that step and ends it up to
//   v·dt − 0.02 m deep (5.5/60 − 0.02 = 0.0717 m at most, 0.069 m measured at 5.5 m/s); the margin closes that gap;
// - the soft step (default solver) lets a contact settle up to TB_LINEAR_SLOP = 0.005 m deep
//   (its push-out only acts beyond the slop), and NGS's position pass likewise leaves the slop; an
//   impact caught by a speculative point is stopped at the surface, so the largest penetration
//   during and after impact must stay below TB_LINEAR_SLOP + 0.005 m (the extra 5 mm covers the
//   gravity of the impact step's sub-steps and the soft contact's compliance);
// - restitution: rebound speed e·v, rebound height e²·h for a drop from h (energy); the engine
//   takes the approach speed at the start of the contact's step, which differs from the true
//   impact speed by less than g·dt·(fraction of the step), so a 5 m drop (v = 10 m/s,
//   g·dt/v = 1.7 %) stays within 3 % of e²·h.
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include <math.h>
#include <stdio.h>

#define TIME_STEP (1.0f / 60.0f)
#define SUB_STEPS 4
#define GRAVITY 10.0f
#define PHASES 8 // drop heights per speed, spread over one step's travel (arrival phase)

static tbWorldId CreateWorld(tbSolverMethod solver)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = (tbVec2){0.0f, -GRAVITY};
	def.solver = solver;
	tbWorldId world = tbCreateWorld(&def);
	cr_assert(tbWorld_IsValid(world));
	return world;
}

/// Static ground box of half size (20, 1) whose top face is at y = 0.
static tbBodyId CreateGround(tbWorldId world, tbGeometry* geometry)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.position = (tbVec2){0.0f, -1.0f};
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef def = tbDefaultShapeDef();
	geometry->type = tb_polygonShape;
	geometry->polygon = tbMakeBox(20.0f, 1.0f);
	tbCreatePolygonShape(body, &def, &geometry->polygon);
	return body;
}

/// Largest penetration (m, ≥ 0) between two bodies' shapes, by the fixed-margin narrow phase.
static float Penetration(const tbGeometry* a, tbBodyId bodyA, const tbGeometry* b, tbBodyId bodyB)
{
	tbManifold m = tbCollideShapes(a, tbBody_GetTransform(bodyA), b, tbBody_GetTransform(bodyB), tb_narrowPhaseAuto);
	float deepest = 0.0f;
	for (int i = 0; i < m.pointCount; ++i)
	{
		deepest = fmaxf(deepest, -m.points[i].separation);
	}
	return deepest;
}

/// A 1 m box dropped flat so that it reaches the ground at `speed`, its height offset by
/// `phase`·(one step's travel) so that it arrives at a different point of a step. Returns the
/// largest penetration during the fall, the impact and 1 s after.
static float DropBox(tbSolverMethod solver, float speed, float phase)
{
	tbWorldId world = CreateWorld(solver);
	tbGeometry ground;
	tbBodyId groundBody = CreateGround(world, &ground);
	float gap = speed * speed / (2.0f * GRAVITY) + phase * speed * TIME_STEP;
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){0.0f, 0.5f + gap};
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbGeometry box = {.type = tb_polygonShape};
	box.polygon = tbMakeBox(0.5f, 0.5f);
	tbCreatePolygonShape(body, &shapeDef, &box.polygon);

	// Fall time √(2·gap/g) plus 1 s.
	int steps = (int)ceilf(sqrtf(2.0f * gap / GRAVITY) / TIME_STEP) + 60;
	float deepest = 0.0f;
	for (int step = 0; step < steps; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		deepest = fmaxf(deepest, Penetration(&ground, groundBody, &box, body));
	}
	tbDestroyWorld(world);
	return deepest;
}

static void CheckBoxDrops(tbSolverMethod solver, const char* name, float speed)
{
	const float limit = TB_LINEAR_SLOP + 0.005f;
	float worst = 0.0f;
	for (int k = 0; k < PHASES; ++k)
	{
		float phase = (float)k / (float)PHASES;
		float deepest = DropBox(solver, speed, phase);
		worst = fmaxf(worst, deepest);
		cr_expect(deepest < limit, "%s, %.1f m/s, phase %.3f: penetration %.4f m (limit %.4f m)", name,
				  (double)speed, (double)phase, (double)deepest, (double)limit);
	}
	printf("speculative: %s box %.1f m/s: largest penetration %.4f m over %d arrival phases\n", name, (double)speed,
		   (double)worst, PHASES);
}

/// A ball (r 0.5, e 0.5) dropped from a 5 m gap, offset by `phase` of a step's travel at impact.
/// Returns the rebound apex gap divided by e²·h.
static float BounceRatio(tbSolverMethod solver, float phase)
{
	const float e = 0.5f, radius = 0.5f, h = 5.0f;
	tbWorldId world = CreateWorld(solver);
	tbGeometry ground;
	CreateGround(world, &ground);
	float v = sqrtf(2.0f * GRAVITY * h);
	float gap = h + phase * v * TIME_STEP;
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){0.0f, radius + gap};
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material.restitution = e;
	tbCircle circle = {{0.0f, 0.0f}, radius};
	tbCreateCircleShape(body, &shapeDef, &circle);

	bool rising = false;
	float apex = 0.0f;
	for (int step = 0; step < 240; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		float vy = tbBody_GetLinearVelocity(body).y;
		float y = tbBody_GetPosition(body).y - radius;
		if (vy > 0.0f)
		{
			rising = true;
			apex = fmaxf(apex, y);
		}
		else if (rising)
		{
			break; // first apex passed
		}
	}
	tbDestroyWorld(world);
	return apex / (e * e * gap);
}

static void CheckBounces(tbSolverMethod solver, const char* name)
{
	for (int k = 0; k < PHASES; ++k)
	{
		float phase = (float)k / (float)PHASES;
		float ratio = BounceRatio(solver, phase);
		printf("speculative: %s bounce phase %.3f: apex / e²h = %.4f\n", name, (double)phase, (double)ratio);
		cr_expect(fabsf(ratio - 1.0f) < 0.03f, "%s phase %.3f: rebound apex / e²h = %.4f", name, (double)phase,
				  (double)ratio);
	}
}

// Broad-phase boxes reach as far as the body can move in a step and the speculative margin grows
// with the approach speed, so the box is stopped at the surface in its impact step (was 0.02–0.21 m).
Test(speculative, box_2_mps_soft)
{
	CheckBoxDrops(tb_solverSoft, "soft", 2.0f);
}

// Broad-phase boxes reach as far as the body can move in a step and the speculative margin grows
// with the approach speed, so the box is stopped at the surface in its impact step (was 0.02–0.21 m).
Test(speculative, box_5_5_mps_soft)
{
	CheckBoxDrops(tb_solverSoft, "soft", 5.5f);
}

// Broad-phase boxes reach as far as the body can move in a step and the speculative margin grows
// with the approach speed, so the box is stopped at the surface in its impact step (was 0.02–0.21 m).
Test(speculative, box_10_mps_soft)
{
	CheckBoxDrops(tb_solverSoft, "soft", 10.0f);
}

// Broad-phase boxes reach as far as the body can move in a step and the speculative margin grows
// with the approach speed, so the box is stopped at the surface in its impact step (was 0.02–0.21 m).
Test(speculative, box_14_mps_soft)
{
	CheckBoxDrops(tb_solverSoft, "soft", 14.0f);
}

// Restitution uses the estimated impact speed sqrt(v² + 2·g·s) of a speculative point, not the
// approach speed at the start of the step (which left the apex up to 4 % low).
Test(speculative, ball_rebound_soft)
{
	CheckBounces(tb_solverSoft, "soft");
}

// Broad-phase boxes reach as far as the body can move in a step and the speculative margin grows
// with the approach speed, so the box is stopped at the surface in its impact step (was 0.02–0.21 m).
Test(speculative, box_2_mps_ngs)
{
	CheckBoxDrops(tb_solverNGS, "ngs", 2.0f);
}

// Broad-phase boxes reach as far as the body can move in a step and the speculative margin grows
// with the approach speed, so the box is stopped at the surface in its impact step (was 0.02–0.21 m).
Test(speculative, box_5_5_mps_ngs)
{
	CheckBoxDrops(tb_solverNGS, "ngs", 5.5f);
}

// Broad-phase boxes reach as far as the body can move in a step and the speculative margin grows
// with the approach speed, so the box is stopped at the surface in its impact step (was 0.02–0.21 m).
Test(speculative, box_10_mps_ngs)
{
	CheckBoxDrops(tb_solverNGS, "ngs", 10.0f);
}

// Broad-phase boxes reach as far as the body can move in a step and the speculative margin grows
// with the approach speed, so the box is stopped at the surface in its impact step (was 0.02–0.21 m).
Test(speculative, box_14_mps_ngs)
{
	CheckBoxDrops(tb_solverNGS, "ngs", 14.0f);
}

Test(speculative, ball_rebound_ngs)
{
	CheckBounces(tb_solverNGS, "ngs");
}

/// Pre-solve counter: manifolds handed to the solver with points (speculative ones included).
static void CountManifolds(tbShapeId shapeIdA, tbShapeId shapeIdB, tbManifold* manifold, void* context)
{
	(void)shapeIdA;
	(void)shapeIdB;
	*(int*)context += manifold->pointCount > 0 ? 1 : 0;
}

/// What one step of a body spinning at 20 rad/s in place does, without gravity, its lowest point
/// 0.03 m above the ground (beyond the fixed 0.02 m): a ball of radius 0.5 or a box of half size
/// 0.5, unturned.
typedef struct Spin
{
	int manifolds;	 ///< manifolds handed to the solver with points (speculative ones included)
	float spin;		 ///< rad/s after the step
	float penetration; ///< m below the ground of the body's deepest point after the step (≤ 0: above)
} Spin;

static Spin SpinInPlace(bool ball)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = (tbVec2){0.0f, 0.0f};
	tbWorldId world = tbCreateWorld(&worldDef);
	Spin result = {0, 0.0f, 0.0f};
	tbWorld_SetPreSolveCallback(world, CountManifolds, NULL, &result.manifolds);
	tbGeometry ground;
	CreateGround(world, &ground);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){0.0f, 0.53f};
	bodyDef.angularVelocity = 20.0f;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef def = tbDefaultShapeDef();
	def.enablePreSolveEvents = true;
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	if (ball)
	{
		tbCircle circle = {{0.0f, 0.0f}, 0.5f};
		tbCreateCircleShape(body, &def, &circle);
	}
	else
	{
		tbCreatePolygonShape(body, &def, &box);
	}
	tbWorld_Step(world, TIME_STEP, SUB_STEPS);
	result.spin = tbBody_GetAngularVelocity(body);
	float lowest = tbBody_GetPosition(body).y - 0.5f; // the ball's lowest point
	for (int i = 0; ball == false && i < box.count; ++i)
	{
		lowest = i == 0 ? tbBody_GetWorldPoint(body, box.vertices[i]).y
						: fminf(lowest, tbBody_GetWorldPoint(body, box.vertices[i]).y);
	}
	result.penetration = -lowest;
	tbDestroyWorld(world);
	return result;
}

// The margin's turn term counts how far a body's shape cores reach (contact.c, tbSpeculativeMargin):
// a ball spinning in place closes on nothing, so 0.03 m above the ground its contact gets no
// manifold point and nothing acts on it: its spin stays 20 rad/s (1e-5: float rounding; there is
// no damping) and it does not move. A box spinning as fast swings a corner down by up to
// dt·|ω|·0.707 = 0.24 m in a step: turning freely by 1/3 rad its corner would end 0.106 m below the
// ground; its speculative point stops it, so its deepest point stays within this file's impact
// bound, TB_LINEAR_SLOP + 0.005 m (header). The counts are exact.
Test(speculative, a_spinning_ball_closes_on_nothing)
{
	Spin ball = SpinInPlace(true);
	Spin box = SpinInPlace(false);
	cr_expect_eq(ball.manifolds, 0, "spinning ball 0.03 m above the ground: %d manifolds with points", ball.manifolds);
	cr_expect_float_eq(ball.spin, 20.0f, 1e-5f, "spinning ball: %.6f rad/s after the step", (double)ball.spin);
	cr_expect_float_eq(ball.penetration, -0.03f, 1e-6f, "spinning ball moved: lowest point %.7f m", (double)-ball.penetration);
	cr_expect_eq(box.manifolds, 1, "spinning box 0.03 m above the ground: %d manifolds with points", box.manifolds);
	cr_expect_leq(box.penetration, TB_LINEAR_SLOP + 0.005f, "spinning box: a corner %.4f m below the ground",
				  (double)box.penetration);
}
