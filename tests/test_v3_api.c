// Box2D v3.2 functions added to close the port's gaps (docs/porting.md, scripts/port-check.sh):
// each is checked against a closed form written beside the expected number, and each refuses bad
// input through the error hook and leaves the world as it was.
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include "error_recorder.h"
#include "test_helpers.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define DT (1.0f / 60.0f)
#define PI_F 3.14159265f

static tbShapeId AddCircle(tbBodyId body, tbVec2 center, float radius)
{
	tbShapeDef def = tbDefaultShapeDef();
	tbCircle circle = {center, radius};
	return tbCreateCircleShape(body, &def, &circle);
}

static void ExpectVec2(tbVec2 actual, float x, float y, float tolerance, const char* what)
{
	cr_assert(fabsf(actual.x - x) <= tolerance && fabsf(actual.y - y) <= tolerance, "%s: (%g, %g), expected (%g, %g)",
			  what, (double)actual.x, (double)actual.y, (double)x, (double)y);
}

// ---------------------------------------------------------------------------------------------
// Geometry: offset rounded boxes and polygons, offset proxies, ray validity

// A box of core half-widths (1, 0.5) turned 90° and moved to (2, 3): a rotation by 90° maps (x, y) to
// (−y, x), so corner (−1, −0.5) lands at (2.5, 2). Its area with radius r is the core plus the four
// sides pushed out by r plus the four quarter circles: 2·1·2·0.5 + 2r·(2 + 1) + πr².
Test(v3_api, offset_rounded_box_and_polygon, .init = SetupErrors, .fini = TeardownErrors)
{
	tbRot quarter = tbMakeRot(0.5f * PI_F);
	tbPolygon box = tbMakeOffsetRoundedBox(1.0f, 0.5f, tbMakeVec2(2.0f, 3.0f), quarter, 0.1f);
	cr_assert_eq(box.count, 4);
	ExpectVec2(box.vertices[0], 2.5f, 2.0f, 1e-6f, "corner 0");
	ExpectVec2(box.centroid, 2.0f, 3.0f, 1e-6f, "centroid");
	cr_assert_float_eq(box.radius, 0.1f, 0.0f);
	float area = 2.0f + 0.2f * 3.0f + PI_F * 0.01f;
	cr_assert_float_eq(tbComputePolygonMass(&box, 1.0f).mass, area, 1e-5f * area);
	tbPolygon plain = tbMakeOffsetBox(1.0f, 0.5f, tbMakeVec2(2.0f, 3.0f), quarter);
	for (int i = 0; i < 4; ++i)
	{
		ExpectVec2(box.vertices[i], plain.vertices[i].x, plain.vertices[i].y, 0.0f, "same corners as tbMakeOffsetBox");
	}

	tbVec2 square[4] = {{-1.0f, -0.5f}, {1.0f, -0.5f}, {1.0f, 0.5f}, {-1.0f, 0.5f}};
	tbHull hull = tbComputeHull(square, 4);
	tbPolygon polygon = tbMakeOffsetRoundedPolygon(&hull, tbMakeVec2(2.0f, 3.0f), quarter, 0.1f);
	cr_assert_eq(polygon.count, 4);
	ExpectVec2(polygon.centroid, 2.0f, 3.0f, 1e-5f, "polygon centroid");
	cr_assert_float_eq(tbComputePolygonMass(&polygon, 1.0f).mass, area, 1e-5f * area);

	int before = s_errors;
	cr_assert_eq(tbMakeOffsetRoundedBox(1.0f, 0.5f, tbVec2_zero, tbRot_identity, -0.1f).count, 0);
	ExpectError(before, "tbMakeOffsetRoundedBox", "radius");
	before = s_errors;
	cr_assert_eq(tbMakeOffsetRoundedBox(1.0f, 0.5f, tbMakeVec2(NAN, 0.0f), tbRot_identity, 0.1f).count, 0);
	ExpectError(before, "tbMakeOffsetRoundedBox", "center");
	before = s_errors;
	tbRot bad = {2.0f, 0.0f};
	cr_assert_eq(tbMakeOffsetRoundedPolygon(&hull, tbVec2_zero, bad, 0.1f).count, 0);
	ExpectError(before, "tbMakeOffsetRoundedPolygon", "rotation");
	before = s_errors;
	cr_assert_eq(tbMakeOffsetRoundedPolygon(&hull, tbVec2_zero, tbRot_identity, INFINITY).count, 0);
	ExpectError(before, "tbMakeOffsetRoundedPolygon", "radius");
}

// Points (1, 0) and (0, 1) turned 90° ((x, y) → (−y, x)) and moved by (1, 1): (1, 2) and (0, 1).
Test(v3_api, offset_proxy, .init = SetupErrors, .fini = TeardownErrors)
{
	tbVec2 points[2] = {{1.0f, 0.0f}, {0.0f, 1.0f}};
	tbShapeProxy proxy = tbMakeOffsetProxy(points, 2, 0.5f, tbMakeVec2(1.0f, 1.0f), tbMakeRot(0.5f * PI_F));
	cr_assert_eq(proxy.count, 2);
	cr_assert_float_eq(proxy.radius, 0.5f, 0.0f);
	ExpectVec2(proxy.points[0], 1.0f, 2.0f, 1e-6f, "point 0");
	ExpectVec2(proxy.points[1], 0.0f, 1.0f, 1e-6f, "point 1");

	int before = s_errors;
	tbRot bad = {2.0f, 0.0f};
	cr_assert_eq(tbMakeOffsetProxy(points, 2, 0.5f, tbVec2_zero, bad).count, 0);
	ExpectError(before, "tbMakeOffsetProxy", "rotation");
	before = s_errors;
	cr_assert_eq(tbMakeOffsetProxy(points, 0, 0.5f, tbVec2_zero, tbRot_identity).count, 0);
	ExpectError(before, "tbMakeOffsetProxy", "count");
	before = s_errors;
	cr_assert_eq(tbMakeOffsetProxy(points, 2, -1.0f, tbVec2_zero, tbRot_identity).count, 0);
	ExpectError(before, "tbMakeOffsetProxy", "radius");
	before = s_errors;
	cr_assert_eq(tbMakeOffsetProxy(NULL, 2, 0.5f, tbVec2_zero, tbRot_identity).count, 0);
	ExpectError(before, "tbMakeOffsetProxy", "points");
}

// Valid: finite origin and translation, 0 ≤ maxFraction < TB_HUGE (Box2D v3.2's test). A predicate:
// an invalid ray is answered, not reported; only a NULL input is an error.
Test(v3_api, ray_validity, .init = SetupErrors, .fini = TeardownErrors)
{
	tbRayCastInput ray = {{0.0f, 0.0f}, {1.0f, 0.0f}, 1.0f};
	cr_assert(tbIsValidRay(&ray));
	ray.translation = tbVec2_zero;
	cr_assert(tbIsValidRay(&ray), "a zero translation is a valid ray that hits nothing");
	tbRayCastInput bad[5] = {{{NAN, 0.0f}, {1.0f, 0.0f}, 1.0f},
							 {{0.0f, 0.0f}, {INFINITY, 0.0f}, 1.0f},
							 {{0.0f, 0.0f}, {1.0f, 0.0f}, -0.5f},
							 {{0.0f, 0.0f}, {1.0f, 0.0f}, NAN},
							 {{0.0f, 0.0f}, {1.0f, 0.0f}, TB_HUGE}};
	int before = s_errors;
	for (int i = 0; i < 5; ++i)
	{
		cr_assert_not(tbIsValidRay(bad + i), "ray %d", i);
	}
	cr_assert_eq(s_errors, before, "an invalid ray is not an error");
	cr_assert_not(tbIsValidRay(NULL));
	ExpectError(before, "tbIsValidRay", "input");
}

// ---------------------------------------------------------------------------------------------
// Shape casts by kind

// The cast stops once the surfaces are within TB_TOI_TARGET_SEPARATION of touching (distance.c),
// so its fraction is short of the exact one by less than that over the translation's length.
static void ExpectCast(tbCastOutput out, float fraction, float translationLength, tbVec2 point, tbVec2 normal)
{
	float tolerance = TB_TOI_TARGET_SEPARATION / translationLength + 1e-6f;
	cr_assert(out.hit);
	cr_assert(out.fraction <= fraction + 1e-6f && out.fraction >= fraction - tolerance, "fraction %g, expected %g",
			  (double)out.fraction, (double)fraction);
	ExpectVec2(out.point, point.x, point.y, 2.0f * TB_TOI_TARGET_SEPARATION, "hit point");
	ExpectVec2(out.normal, normal.x, normal.y, 1e-3f, "normal");
}

static tbShapeCastInput PointCast(tbVec2 center, float radius, tbVec2 translation)
{
	tbShapeCastInput input;
	memset(&input, 0, sizeof(input));
	input.proxy = tbMakeProxy(&center, 1, radius);
	input.translation = translation;
	input.maxFraction = 1.0f;
	return input;
}

// Closed forms: a disc of radius 0.5 first touches when its centre is the sum of radii from the
// shape's nearest feature; the hit point is on the shape's surface, the normal points at the disc.
Test(v3_api, shape_casts_by_kind)
{
	// Circle r = 1 at the origin, disc from (−5, 0) moving (10, 0): touches at centre x = −1.5,
	// fraction 3.5/10, point (−1, 0), normal (−1, 0).
	tbCircle circle = {{0.0f, 0.0f}, 1.0f};
	tbShapeCastInput input = PointCast(tbMakeVec2(-5.0f, 0.0f), 0.5f, tbMakeVec2(10.0f, 0.0f));
	ExpectCast(tbShapeCastCircle(&circle, &input), 0.35f, 10.0f, tbMakeVec2(-1.0f, 0.0f), tbMakeVec2(-1.0f, 0.0f));

	// Capsule (−1, 0)–(1, 0), r = 0.5, disc from (0, 5) moving (0, −10): touches at y = 1, fraction 0.4.
	tbCapsule capsule = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
	input = PointCast(tbMakeVec2(0.0f, 5.0f), 0.5f, tbMakeVec2(0.0f, -10.0f));
	ExpectCast(tbShapeCastCapsule(&capsule, &input), 0.4f, 10.0f, tbMakeVec2(0.0f, 0.5f), tbMakeVec2(0.0f, 1.0f));

	// Segment (−1, 0)–(1, 0), disc r = 0.25 from (0.5, 3) moving (0, −4): y = 0.25, fraction 2.75/4.
	tbSegment segment = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
	input = PointCast(tbMakeVec2(0.5f, 3.0f), 0.25f, tbMakeVec2(0.0f, -4.0f));
	ExpectCast(tbShapeCastSegment(&segment, &input), 0.6875f, 4.0f, tbMakeVec2(0.5f, 0.0f), tbMakeVec2(0.0f, 1.0f));

	// Unit box (half-width 1), disc r = 0.5 from (4, 0) moving (−8, 0): x = 1.5, fraction 2.5/8; the
	// same box rounded by 0.1: x = 1.6, fraction 2.4/8, point on the rounded face (1.1, 0).
	tbPolygon box = tbMakeBox(1.0f, 1.0f);
	input = PointCast(tbMakeVec2(4.0f, 0.0f), 0.5f, tbMakeVec2(-8.0f, 0.0f));
	ExpectCast(tbShapeCastPolygon(&box, &input), 0.3125f, 8.0f, tbMakeVec2(1.0f, 0.0f), tbMakeVec2(1.0f, 0.0f));
	tbPolygon rounded = tbMakeRoundedBox(1.0f, 1.0f, 0.1f);
	ExpectCast(tbShapeCastPolygon(&rounded, &input), 0.3f, 8.0f, tbMakeVec2(1.1f, 0.0f), tbMakeVec2(1.0f, 0.0f));

	// Moving away, or stopping short (maxFraction 0.2 < 0.3125): no hit.
	input.translation = tbMakeVec2(8.0f, 0.0f);
	cr_assert_not(tbShapeCastPolygon(&box, &input).hit);
	input.translation = tbMakeVec2(-8.0f, 0.0f);
	input.maxFraction = 0.2f;
	cr_assert_not(tbShapeCastPolygon(&box, &input).hit);
}

Test(v3_api, shape_casts_refuse_bad_input, .init = SetupErrors, .fini = TeardownErrors)
{
	tbCircle circle = {{0.0f, 0.0f}, 1.0f};
	tbShapeCastInput input = PointCast(tbMakeVec2(-5.0f, 0.0f), 0.5f, tbMakeVec2(10.0f, 0.0f));
	int before = s_errors;
	cr_assert_not(tbShapeCastCircle(NULL, &input).hit);
	ExpectError(before, "tbShapeCastCircle", "shape");
	before = s_errors;
	cr_assert_not(tbShapeCastCircle(&circle, NULL).hit);
	ExpectError(before, "tbShapeCastCircle", "input");
	before = s_errors;
	tbCircle negative = {{0.0f, 0.0f}, -1.0f};
	cr_assert_not(tbShapeCastCircle(&negative, &input).hit);
	ExpectError(before, "tbShapeCastCircle", "radius");
	before = s_errors;
	tbCapsule nanCapsule = {{NAN, 0.0f}, {1.0f, 0.0f}, 0.5f};
	cr_assert_not(tbShapeCastCapsule(&nanCapsule, &input).hit);
	ExpectError(before, "tbShapeCastCapsule", "points");
	before = s_errors;
	tbPolygon empty = {0};
	cr_assert_not(tbShapeCastPolygon(&empty, &input).hit);
	ExpectError(before, "tbShapeCastPolygon", "count");

	tbSegment segment = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
	tbShapeCastInput bad = input;
	bad.translation = tbMakeVec2(INFINITY, 0.0f);
	before = s_errors;
	cr_assert_not(tbShapeCastSegment(&segment, &bad).hit);
	ExpectError(before, "tbShapeCastSegment", "translation");
	bad = input;
	bad.maxFraction = -1.0f;
	before = s_errors;
	cr_assert_not(tbShapeCastSegment(&segment, &bad).hit);
	ExpectError(before, "tbShapeCastSegment", "maxFraction");
	bad = input;
	bad.proxy.count = 0;
	before = s_errors;
	cr_assert_not(tbShapeCastSegment(&segment, &bad).hit);
	ExpectError(before, "tbShapeCastSegment", "proxyB");
}

// ---------------------------------------------------------------------------------------------
// Bodies and shapes

// A disc of radius 0.5 centred at (1, 0) in a body at (2, 3) turned 90°: its centre of mass is (1, 0)
// in the body and (2, 3) + (0, 1) in the world, where the body carries its local centre.
Test(v3_api, body_center_names, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	def.position = tbMakeVec2(2.0f, 3.0f);
	def.rotation = tbMakeRot(0.5f * PI_F);
	tbBodyId body = tbCreateBody(world, &def);
	AddCircle(body, tbMakeVec2(1.0f, 0.0f), 0.5f);
	ExpectVec2(tbBody_GetLocalCenter(body), 1.0f, 0.0f, 1e-6f, "local centre");
	ExpectVec2(tbBody_GetWorldCenter(body), 2.0f, 4.0f, 1e-6f, "world centre");
	tbPos carried = tbBody_GetWorldPoint(body, tbBody_GetLocalCenter(body));
	ExpectVec2(tbBody_GetWorldCenter(body), carried.x, carried.y, 1e-6f, "the local centre carried by the body");
	tbDestroyBody(body);
	int before = s_errors;
	ExpectVec2(tbBody_GetLocalCenter(body), 0.0f, 0.0f, 0.0f, "stale id");
	ExpectError(before, "tbBody_GetLocalCenter", "");
	before = s_errors;
	ExpectVec2(tbBody_GetWorldCenter(body), 0.0f, 0.0f, 0.0f, "stale id");
	ExpectError(before, "tbBody_GetWorldCenter", "");
	tbDestroyWorld(world);
}

// Circle r = 0.5, density 2: m = ρπr² = π/2, I = m·r²/2 about its centre (1, 0) (Tumble's mass data
// give the rotational inertia about the shape's centre of mass).
Test(v3_api, shape_compute_mass_data, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId body = CreateBody(world, tb_dynamicBody, tbVec2_zero);
	tbShapeDef def = tbDefaultShapeDef();
	def.density = 2.0f;
	tbCircle circle = {{1.0f, 0.0f}, 0.5f};
	tbShapeId shape = tbCreateCircleShape(body, &def, &circle);
	tbMassData md = tbShape_ComputeMassData(shape);
	float mass = 2.0f * PI_F * 0.25f;
	cr_assert_float_eq(md.mass, mass, 1e-6f * mass);
	ExpectVec2(md.center, 1.0f, 0.0f, 0.0f, "centre");
	tbMassData same = tbComputeCircleMass(&circle, def.density);
	cr_assert(memcmp(&md, &same, sizeof(md)) == 0, "the same as tbComputeCircleMass");
	cr_assert_float_eq(md.rotationalInertia, same.rotationalInertia, 0.0f);
	tbDestroyShape(shape, true);
	int before = s_errors;
	float staleMass = tbShape_ComputeMassData(shape).mass;
	ExpectError(before, "tbShape_ComputeMassData", "");
	cr_assert_float_eq(staleMass, 0.0f, 0.0f);
	tbDestroyWorld(world);
}

static int s_preSolveCalls;

static void CountPreSolve(tbShapeId a, tbShapeId b, tbManifold* manifold, void* context)
{
	(void)a;
	(void)b;
	(void)manifold;
	(void)context;
	s_preSolveCalls += 1;
}

// A box resting on the ground: the world's pre-solve callback sees a contact made while one of the
// two shapes enables pre-solve events. As in Box2D v3.2 a contact takes the flag when it is made:
// switching it on or off leaves the existing contact as it was, and the contacts made after
// (the body disabled and enabled, its contacts made again) follow the switch.
Test(v3_api, shape_pre_solve_switch, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbWorld_SetPreSolveCallback(world, CountPreSolve, NULL, NULL);
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, -0.5f));
	AddBoxShape(ground, 5.0f, 0.5f, NULL);
	tbBodyId body = CreateBody(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.5f));
	tbShapeId box = AddBoxShape(body, 0.5f, 0.5f, NULL);
	cr_assert_not(tbShape_ArePreSolveEventsEnabled(box), "off by default");
	s_preSolveCalls = 0;
	for (int i = 0; i < 5; ++i)
	{
		tbWorld_Step(world, DT, 4);
	}
	cr_assert_eq(s_preSolveCalls, 0);
	tbShape_EnablePreSolveEvents(box, true);
	cr_assert(tbShape_ArePreSolveEventsEnabled(box));
	tbWorld_Step(world, DT, 4);
	cr_assert_eq(s_preSolveCalls, 0, "the contact was made before the switch");
	tbBody_Disable(body);
	tbBody_Enable(body);
	tbWorld_Step(world, DT, 4);
	cr_assert_eq(s_preSolveCalls, 1, "one touching contact made after the switch, one call per step");
	tbShape_EnablePreSolveEvents(box, false);
	tbWorld_Step(world, DT, 4);
	cr_assert_eq(s_preSolveCalls, 2, "the contact keeps the flag it was made with");
	tbBody_Disable(body);
	tbBody_Enable(body);
	tbWorld_Step(world, DT, 4);
	cr_assert_eq(s_preSolveCalls, 2, "made again after the switch off: no call");
	tbDestroyShape(box, true);
	int before = s_errors;
	tbShape_EnablePreSolveEvents(box, true);
	ExpectError(before, "tbShape_EnablePreSolveEvents", "");
	before = s_errors;
	cr_assert_not(tbShape_ArePreSolveEventsEnabled(box));
	ExpectError(before, "tbShape_ArePreSolveEventsEnabled", "");
	tbDestroyWorld(world);
}

// Wind on bodies at rest without gravity: after one step v = F·dt/m and ω = τ·dt/I (the force is
// constant over the step's sub-steps). Dynamic pressure q = ½·1.225·|u|², u = wind (the body is at
// rest, so drag does not matter).
Test(v3_api, shape_wind_closed_forms)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	float q = 0.5f * 1.225f * 100.0f; // |wind| = 10 m/s

	// Disc r = 0.5: width 2r = 1, F = q along the wind, no torque (it acts at the centre).
	tbBodyId disc = CreateBody(world, tb_dynamicBody, tbMakeVec2(-10.0f, 0.0f));
	tbShapeId discShape = AddCircle(disc, tbVec2_zero, 0.5f);
	// Unit box: one face (width 1) meets the wind square on: F = q, no lift, no torque.
	tbBodyId box = CreateBody(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.0f));
	tbShapeId boxShape = AddBoxShape(box, 0.5f, 0.5f, NULL);
	// Capsule of axis length L = 1 tilted 45° (d = (c, s), c = s = √½), r = 0.1: the flat side facing
	// the wind has normal n = (−s, c); width w = 2r + L·s; lift direction (n × û)·perp(û) = (0, −c).
	// With lift 1: F = q·w·(1, −c); it acts at r·n from the centroid, the centre of mass, so
	// τ = r·(n × F).
	tbBodyId stick = CreateBody(world, tb_dynamicBody, tbMakeVec2(10.0f, 0.0f));
	tbShapeDef def = tbDefaultShapeDef();
	float h = 0.5f * sqrtf(0.5f);
	tbCapsule capsule = {{-h, -h}, {h, h}, 0.1f};
	tbShapeId stickShape = tbCreateCapsuleShape(stick, &def, &capsule);

	tbVec2 wind = tbMakeVec2(10.0f, 0.0f);
	cr_assert(tbShape_ApplyWind(discShape, wind, 1.0f, 0.0f, true));
	cr_assert(tbShape_ApplyWind(boxShape, wind, 1.0f, 0.0f, true));
	cr_assert(tbShape_ApplyWind(stickShape, wind, 1.0f, 1.0f, true));
	tbWorld_Step(world, DT, 4);

	float discMass = tbBody_GetMass(disc);
	ExpectVec2(tbBody_GetLinearVelocity(disc), q * DT / discMass, 0.0f, 1e-5f, "disc");
	cr_assert_float_eq(tbBody_GetAngularVelocity(disc), 0.0f, 1e-6f);
	ExpectVec2(tbBody_GetLinearVelocity(box), q * DT / 1.0f, 0.0f, 1e-5f, "box");
	cr_assert_float_eq(tbBody_GetAngularVelocity(box), 0.0f, 1e-5f);

	float c = sqrtf(0.5f);
	float w = 0.2f + c;
	tbVec2 force = tbMakeVec2(q * w, -q * w * c);
	tbVec2 n = tbMakeVec2(-c, c);
	float torque = 0.1f * tbCross(n, force);
	float m = tbBody_GetMass(stick), inertia = tbBody_GetRotationalInertia(stick);
	ExpectVec2(tbBody_GetLinearVelocity(stick), force.x * DT / m, force.y * DT / m, 1e-4f, "capsule");
	cr_assert_float_eq(tbBody_GetAngularVelocity(stick), torque * DT / inertia, 1e-3f * fabsf(torque * DT / inertia));
	tbDestroyWorld(world);
}

// A unit box turned 0.3 rad in a wind (10, −3) with drag 1 and lift 0.7: two faces meet the flow,
// each with lift. Reference: Box2D v3.2 (the 2026-11 snapshot, b2Shape_ApplyWind) on the same set-up,
// rotation given as (cos 0.3, sin 0.3) in both, one step of 1/60 s with 4 sub-steps, no gravity:
// v = (1.47898519, −0.443695545) m/s, ω = −0.29478544 rad/s. Tolerance 1e-5 relative: float rounding
// of the two implementations (they agreed to 2e-6).
Test(v3_api, shape_wind_matches_box2d_v3_with_lift)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	bd.rotation.c = cosf(0.3f);
	bd.rotation.s = sinf(0.3f);
	tbBodyId body = tbCreateBody(world, &bd);
	tbShapeId shape = AddBoxShape(body, 0.5f, 0.5f, NULL);
	cr_assert(tbShape_ApplyWind(shape, tbMakeVec2(10.0f, -3.0f), 1.0f, 0.7f, true));
	tbWorld_Step(world, DT, 4);
	tbVec2 v = tbBody_GetLinearVelocity(body);
	cr_assert_float_eq(v.x, 1.47898519f, 1e-5f * 1.48f);
	cr_assert_float_eq(v.y, -0.443695545f, 1e-5f * 0.444f);
	cr_assert_float_eq(tbBody_GetAngularVelocity(body), -0.29478544f, 1e-5f * 0.295f);
	tbDestroyWorld(world);
}

// A body moving with the wind at drag 1 feels none (u = wind − v = 0); one at rest against a static
// body, a segment, and a sleeping body with wake false are left alone; bad input is refused.
Test(v3_api, shape_wind_refusals_and_no_ops, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	bd.linearVelocity = tbMakeVec2(10.0f, 0.0f);
	tbBodyId rider = tbCreateBody(world, &bd);
	tbShapeId riderShape = AddCircle(rider, tbVec2_zero, 0.5f);
	cr_assert(tbShape_ApplyWind(riderShape, tbMakeVec2(10.0f, 0.0f), 1.0f, 0.0f, true));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, -5.0f));
	tbShapeDef sd = tbDefaultShapeDef();
	tbSegment segment = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
	tbShapeId groundShape = tbCreateSegmentShape(ground, &sd, &segment);
	cr_assert_not(tbShape_ApplyWind(groundShape, tbMakeVec2(10.0f, 0.0f), 1.0f, 0.0f, true), "ignored, no error");
	bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	bd.position = tbMakeVec2(0.0f, 5.0f);
	bd.isAwake = false;
	tbBodyId sleeper = tbCreateBody(world, &bd);
	tbShapeId sleeperShape = AddCircle(sleeper, tbVec2_zero, 0.5f);
	cr_assert_not(tbShape_ApplyWind(sleeperShape, tbMakeVec2(10.0f, 0.0f), 1.0f, 0.0f, false));
	cr_assert_not(tbBody_IsAwake(sleeper), "wake false leaves it asleep");
	cr_assert_eq(s_errors, 0, "ignoring is not an error");

	int before = s_errors;
	cr_assert_not(tbShape_ApplyWind(riderShape, tbMakeVec2(NAN, 0.0f), 1.0f, 0.0f, true));
	ExpectError(before, "tbShape_ApplyWind", "wind");
	before = s_errors;
	cr_assert_not(tbShape_ApplyWind(riderShape, tbMakeVec2(1.0f, 0.0f), -1.0f, 0.0f, true));
	ExpectError(before, "tbShape_ApplyWind", "drag");
	before = s_errors;
	cr_assert_not(tbShape_ApplyWind(riderShape, tbMakeVec2(1.0f, 0.0f), 1.0f, INFINITY, true));
	ExpectError(before, "tbShape_ApplyWind", "lift");

	tbWorld_Step(world, DT, 4);
	ExpectVec2(tbBody_GetLinearVelocity(rider), 10.0f, 0.0f, 0.0f, "no relative wind, refused calls: unchanged");
	ExpectVec2(tbBody_GetLinearVelocity(sleeper), 0.0f, 0.0f, 0.0f, "asleep");
	cr_assert(tbShape_ApplyWind(sleeperShape, tbMakeVec2(10.0f, 0.0f), 1.0f, 0.0f, true));
	cr_assert(tbBody_IsAwake(sleeper), "wake true wakes it");

	tbDestroyShape(riderShape, true);
	before = s_errors;
	cr_assert_not(tbShape_ApplyWind(riderShape, tbMakeVec2(1.0f, 0.0f), 1.0f, 0.0f, true));
	ExpectError(before, "tbShape_ApplyWind", "");
	tbDestroyWorld(world);
}

// ---------------------------------------------------------------------------------------------
// Joint separations: body A static at the origin, body B placed by SetTransform (no step), both
// frames at the bodies' origins, so anchor B − anchor A is B's position.

typedef struct JointPair
{
	tbWorldId world;
	tbBodyId a, b;
} JointPair;

static JointPair MakePair(void)
{
	JointPair p;
	p.world = CreateWorld(tbVec2_zero);
	p.a = CreateBody(p.world, tb_staticBody, tbVec2_zero);
	p.b = CreateBody(p.world, tb_dynamicBody, tbVec2_zero);
	AddBoxShape(p.b, 0.25f, 0.25f, NULL);
	return p;
}

static void Place(const JointPair* p, float x, float y, float angle)
{
	tbBody_SetTransform(p->b, tbMakeVec2(x, y), tbMakeRot(angle));
}

Test(v3_api, joint_separations_revolute_prismatic_wheel)
{
	JointPair p = MakePair();
	tbRevoluteJointDef rd = tbDefaultRevoluteJointDef();
	rd.base.bodyIdA = p.a;
	rd.base.bodyIdB = p.b;
	rd.enableLimit = true;
	rd.lowerAngle = -0.5f;
	rd.upperAngle = 0.5f;
	tbJointId revolute = tbCreateRevoluteJoint(p.world, &rd);
	// Anchors 5 m apart (3-4-5); angle 1 rad is 0.5 past the upper limit, −0.75 is 0.25 below.
	Place(&p, 3.0f, 4.0f, 1.0f);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(revolute), 5.0f, 1e-5f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(revolute), 0.5f, 1e-5f);
	Place(&p, 0.0f, 0.0f, -0.75f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(revolute), 0.25f, 1e-5f);
	tbRevoluteJoint_EnableLimit(revolute, false);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(revolute), 0.0f, 0.0f);
	tbDestroyJoint(revolute);

	// Prismatic along x with limits [−1, 1]: B at (3, 4) is 4 across the axis and 2 past the upper
	// limit, √(4² + 2²); turned by −0.3 rad the angular separation is the signed relative angle.
	tbPrismaticJointDef pd = tbDefaultPrismaticJointDef();
	pd.base.bodyIdA = p.a;
	pd.base.bodyIdB = p.b;
	pd.enableLimit = true;
	pd.lowerTranslation = -1.0f;
	pd.upperTranslation = 1.0f;
	tbJointId prismatic = tbCreatePrismaticJoint(p.world, &pd);
	Place(&p, 3.0f, 4.0f, -0.3f);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(prismatic), sqrtf(20.0f), 1e-5f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(prismatic), -0.3f, 1e-5f);
	Place(&p, 0.5f, 0.0f, 0.0f);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(prismatic), 0.0f, 1e-6f);
	tbDestroyJoint(prismatic);

	// A prismatic whose frame A is turned 90°: the axis is world y, so B at (3, 0) is 3 across it.
	pd.enableLimit = false;
	pd.base.localFrameA.q = tbMakeRot(0.5f * PI_F);
	pd.base.localFrameB.q = tbMakeRot(0.5f * PI_F);
	prismatic = tbCreatePrismaticJoint(p.world, &pd);
	Place(&p, 3.0f, 7.0f, 0.0f);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(prismatic), 3.0f, 1e-5f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(prismatic), 0.0f, 1e-6f);
	tbDestroyJoint(prismatic);

	// Wheel: the same linear measure along its axis (no limit: only the 4 across), turning is free.
	tbWheelJointDef wd = tbDefaultWheelJointDef();
	wd.base.bodyIdA = p.a;
	wd.base.bodyIdB = p.b;
	tbJointId wheel = tbCreateWheelJoint(p.world, &wd);
	Place(&p, 3.0f, 4.0f, 2.0f);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(wheel), 4.0f, 1e-5f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(wheel), 0.0f, 0.0f);
	tbDestroyJoint(wheel);
	tbDestroyWorld(p.world);
}

Test(v3_api, joint_separations_distance_weld_and_the_rest, .init = SetupErrors, .fini = TeardownErrors)
{
	JointPair p = MakePair();
	// Distance joint of length 2 with B 5 m away: rigid, |5 − 2| = 3; spring with limits [1, 4]: 5 − 4;
	// spring without limit: 0.
	tbDistanceJointDef dd = tbDefaultDistanceJointDef();
	dd.base.bodyIdA = p.a;
	dd.base.bodyIdB = p.b;
	dd.length = 2.0f;
	dd.minLength = 1.0f;
	dd.maxLength = 4.0f;
	tbJointId distance = tbCreateDistanceJoint(p.world, &dd);
	Place(&p, 3.0f, 4.0f, 0.0f);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(distance), 3.0f, 1e-5f);
	tbDistanceJoint_EnableSpring(distance, true);
	tbDistanceJoint_EnableLimit(distance, true);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(distance), 1.0f, 1e-5f);
	tbDistanceJoint_EnableLimit(distance, false);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(distance), 0.0f, 0.0f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(distance), 0.0f, 0.0f);
	tbDestroyJoint(distance);

	// Rigid weld: the anchors' distance and the signed relative angle; a soft weld reports none.
	tbWeldJointDef wd = tbDefaultWeldJointDef();
	wd.base.bodyIdA = p.a;
	wd.base.bodyIdB = p.b;
	tbJointId weld = tbCreateWeldJoint(p.world, &wd);
	Place(&p, 3.0f, 4.0f, -0.4f);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(weld), 5.0f, 1e-5f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(weld), -0.4f, 1e-5f);
	tbDestroyJoint(weld);
	wd.linearHertz = 5.0f;
	wd.angularHertz = 5.0f;
	weld = tbCreateWeldJoint(p.world, &wd);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(weld), 0.0f, 0.0f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(weld), 0.0f, 0.0f);
	tbDestroyJoint(weld);

	// Motor and filter joints hold nothing rigid.
	tbMotorJointDef md = tbDefaultMotorJointDef();
	md.base.bodyIdA = p.a;
	md.base.bodyIdB = p.b;
	tbJointId motor = tbCreateMotorJoint(p.world, &md);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(motor), 0.0f, 0.0f);
	cr_assert_float_eq(tbJoint_GetAngularSeparation(motor), 0.0f, 0.0f);
	tbFilterJointDef fd = tbDefaultFilterJointDef();
	fd.base.bodyIdA = p.a;
	fd.base.bodyIdB = p.b;
	tbJointId filter = tbCreateFilterJoint(p.world, &fd);
	cr_assert_float_eq(tbJoint_GetLinearSeparation(filter), 0.0f, 0.0f);
	tbDestroyJoint(filter);
	int before = s_errors;
	float linear = tbJoint_GetLinearSeparation(filter);
	ExpectError(before, "tbJoint_GetLinearSeparation", "");
	before = s_errors;
	float angular = tbJoint_GetAngularSeparation(filter);
	ExpectError(before, "tbJoint_GetAngularSeparation", "");
	cr_assert(linear == 0.0f && angular == 0.0f);
	tbDestroyWorld(p.world);
}

// ---------------------------------------------------------------------------------------------
// World

/// A pyramid of 10 rows of unit boxes on a ground box: the recycling scene (touching polygon pairs).
static tbWorldId MakePyramid(void)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, -0.5f));
	AddBoxShape(ground, 20.0f, 0.5f, NULL);
	for (int row = 0; row < 10; ++row)
	{
		for (int i = 0; i < 10 - row; ++i)
		{
			float x = (float)i - 0.5f * (float)(9 - row);
			tbBodyId body = CreateBody(world, tb_dynamicBody, tbMakeVec2(x * 1.05f, 0.5f + (float)row));
			AddBoxShape(body, 0.5f, 0.5f, NULL);
		}
	}
	return world;
}

static int StepRecycled(tbWorldId world, int steps)
{
	int recycled = 0;
	for (int i = 0; i < steps; ++i)
	{
		tbWorld_Step(world, DT, 4);
		recycled += tbWorld_GetCounters(world).recycledContactCount;
	}
	return recycled;
}

// Default TB_RECYCLE_DISTANCE; set explicitly to that value the run is bit-identical (same state
// hash); 0 recomputes every manifold (no recycled manifold in 120 steps of a settling pyramid).
Test(v3_api, world_contact_recycle_distance, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId a = MakePyramid();
	tbWorldId b = MakePyramid();
	tbWorldId off = MakePyramid();
	cr_assert_float_eq(tbWorld_GetContactRecycleDistance(a), TB_RECYCLE_DISTANCE, 0.0f);
	cr_assert(tbWorld_SetContactRecycleDistance(b, TB_RECYCLE_DISTANCE));
	cr_assert(tbWorld_SetContactRecycleDistance(off, 0.0f));
	cr_assert_float_eq(tbWorld_GetContactRecycleDistance(off), 0.0f, 0.0f);
	int recycledA = StepRecycled(a, 120);
	StepRecycled(b, 120);
	cr_assert_gt(recycledA, 0, "the pyramid recycles at the default distance");
	cr_assert_eq(StepRecycled(off, 120), 0);
	cr_assert_eq(tbWorld_GetStateHash(a), tbWorld_GetStateHash(b), "the default set explicitly changes nothing");

	int before = s_errors;
	cr_assert_not(tbWorld_SetContactRecycleDistance(a, -0.01f));
	ExpectError(before, "tbWorld_SetContactRecycleDistance", "recycleDistance");
	before = s_errors;
	cr_assert_not(tbWorld_SetContactRecycleDistance(a, NAN));
	ExpectError(before, "tbWorld_SetContactRecycleDistance", "recycleDistance");
	cr_assert_float_eq(tbWorld_GetContactRecycleDistance(a), TB_RECYCLE_DISTANCE, 0.0f, "unchanged");
	tbDestroyWorld(a);
	tbDestroyWorld(b);
	tbDestroyWorld(off);
	before = s_errors;
	cr_assert_not(tbWorld_SetContactRecycleDistance(a, 0.01f));
	ExpectError(before, "tbWorld_SetContactRecycleDistance", "");
	before = s_errors;
	float stale = tbWorld_GetContactRecycleDistance(a);
	ExpectError(before, "tbWorld_GetContactRecycleDistance", "");
	cr_assert_float_eq(stale, 0.0f, 0.0f);
}

// A unit box tilted 0.8° over a ground box, its low corner 1 mm up: without gravity nothing moves.
// Its far corner is sin(0.8°) ≈ 0.014 m higher, within the speculative distance (0.02 m) but more
// than 1.5 × TB_LINEAR_SLOP (0.0075 m) apart: two manifold points, one with speculation off.
static int ContactPoints(bool speculative)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbWorld_EnableSpeculative(world, speculative);
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, -0.5f));
	AddBoxShape(ground, 5.0f, 0.5f, NULL);
	float angle = 0.8f * PI_F / 180.0f;
	// Lowest corner (−0.5, −0.5) turned by the angle lies 0.5·(cos + sin)… below the centre: put it at 1 mm.
	float drop = 0.5f * cosf(angle) + 0.5f * sinf(angle);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	bd.position = tbMakeVec2(0.0f, drop + 0.001f);
	bd.rotation = tbMakeRot(angle);
	tbBodyId box = tbCreateBody(world, &bd);
	AddBoxShape(box, 0.5f, 0.5f, NULL);
	tbWorld_Step(world, DT, 4);
	tbContactData data[2];
	int count = tbBody_GetContactData(box, data, 2);
	int points = count == 1 ? data[0].manifold.pointCount : -1;
	tbDestroyWorld(world);
	return points;
}

Test(v3_api, world_enable_speculative)
{
	cr_assert_eq(ContactPoints(true), 2);
	cr_assert_eq(ContactPoints(false), 1);
}

// Ground box half-widths (5, 0.5) at (0, −0.5): static boxes are tight, (−5, −1)–(5, 0). A new disc
// r = 0.5 at (0, 3) has a fat box grown by TB_AABB_MARGIN: (−0.55, 2.45)–(0.55, 3.55).
Test(v3_api, world_bounds, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbAABB empty = tbWorld_GetBounds(world);
	ExpectVec2(empty.lowerBound, 0.0f, 0.0f, 0.0f, "empty world");
	ExpectVec2(empty.upperBound, 0.0f, 0.0f, 0.0f, "empty world");
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, -0.5f));
	AddBoxShape(ground, 5.0f, 0.5f, NULL);
	tbBodyId ball = CreateBody(world, tb_dynamicBody, tbMakeVec2(0.0f, 3.0f));
	AddCircle(ball, tbVec2_zero, 0.5f);
	tbAABB bounds = tbWorld_GetBounds(world);
	ExpectVec2(bounds.lowerBound, -5.0f, -1.0f, 1e-6f, "lower");
	ExpectVec2(bounds.upperBound, 5.0f, 3.0f + 0.5f + TB_AABB_MARGIN, 1e-6f, "upper");
	tbDestroyWorld(world);
	int before = s_errors;
	tbWorld_GetBounds(world);
	ExpectError(before, "tbWorld_GetBounds", "");
}

// Counts are taken at the start of each step: contacts made during step 1 are counted at step 2.
Test(v3_api, world_max_capacity, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbCapacity zero = tbWorld_GetMaxCapacity(world);
	cr_assert_eq(zero.staticShapeCount + zero.dynamicShapeCount + zero.staticBodyCount + zero.dynamicBodyCount +
					 zero.contactCount,
				 0);
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, -0.5f));
	AddBoxShape(ground, 5.0f, 0.5f, NULL);
	tbShapeDef sd = tbDefaultShapeDef();
	tbSegment wall = {{-5.0f, 0.0f}, {-5.0f, 5.0f}};
	tbCreateSegmentShape(ground, &sd, &wall);
	tbBodyId bodies[3];
	for (int i = 0; i < 3; ++i)
	{
		bodies[i] = CreateBody(world, tb_dynamicBody, tbMakeVec2(-2.0f + 2.0f * (float)i, 0.5f));
		AddBoxShape(bodies[i], 0.5f, 0.5f, NULL);
	}
	tbWorld_Step(world, DT, 4);
	tbCapacity c = tbWorld_GetMaxCapacity(world);
	cr_assert_eq(c.staticShapeCount, 2);
	cr_assert_eq(c.dynamicShapeCount, 3);
	cr_assert_eq(c.staticBodyCount, 1);
	cr_assert_eq(c.dynamicBodyCount, 3);
	cr_assert_eq(c.contactCount, 0, "no contact existed when step 1 began");
	int contacts = tbWorld_GetCounters(world).contactCount;
	cr_assert_eq(contacts, 3);
	tbWorld_Step(world, DT, 4);
	cr_assert_eq(tbWorld_GetMaxCapacity(world).contactCount, contacts);
	tbDestroyBody(bodies[0]);
	tbWorld_Step(world, DT, 4);
	c = tbWorld_GetMaxCapacity(world);
	cr_assert_eq(c.dynamicBodyCount, 3, "a maximum: it does not drop");
	cr_assert_eq(c.dynamicShapeCount, 3);
	tbDestroyWorld(world);
	int before = s_errors;
	tbWorld_GetMaxCapacity(world);
	ExpectError(before, "tbWorld_GetMaxCapacity", "");
}

static float FirstHit(tbShapeId shape, tbVec2 point, tbVec2 normal, float fraction, void* context)
{
	(void)shape;
	(void)point;
	(void)normal;
	*(float*)context = fraction;
	return fraction;
}

/// A row of static boxes under falling balls; the static tree is rebuilt at step 30 or not at all.
static uint64_t RunStaticRow(bool rebuild, float* rayFraction)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	for (int i = 0; i < 40; ++i)
	{
		tbBodyId block = CreateBody(world, tb_staticBody, tbMakeVec2((float)i - 20.0f, (float)(i % 3) * 0.2f));
		AddBoxShape(block, 0.45f, 0.5f, NULL);
	}
	for (int i = 0; i < 20; ++i)
	{
		tbBodyId ball = CreateBody(world, tb_dynamicBody, tbMakeVec2(2.0f * (float)i - 19.5f, 3.0f));
		AddCircle(ball, tbVec2_zero, 0.3f);
	}
	for (int step = 0; step < 90; ++step)
	{
		if (rebuild && step == 30)
		{
			tbWorld_RebuildStaticTree(world);
		}
		tbWorld_Step(world, DT, 4);
	}
	*rayFraction = -1.0f;
	tbWorld_CastRay(world, tbMakeVec2(0.0f, 10.0f), tbMakeVec2(0.0f, -20.0f), tbDefaultQueryFilter(), FirstHit,
					rayFraction);
	uint64_t hash = tbWorld_GetStateHash(world);
	tbDestroyWorld(world);
	return hash;
}

// Pairs are reported sorted whatever the tree's shape (broad_phase.h), so a rebuild changes no
// trajectory; the rebuilt tree still answers queries (the ray down x = 0 meets a block or a ball).
Test(v3_api, world_rebuild_static_tree, .init = SetupErrors, .fini = TeardownErrors)
{
	float plain, rebuilt;
	uint64_t a = RunStaticRow(false, &plain);
	uint64_t b = RunStaticRow(true, &rebuilt);
	cr_assert_eq(a, b);
	cr_assert_gt(rebuilt, 0.0f);
	cr_assert_float_eq(plain, rebuilt, 0.0f);
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbDestroyWorld(world);
	int before = s_errors;
	tbWorld_RebuildStaticTree(world);
	ExpectError(before, "tbWorld_RebuildStaticTree", "");
}

// Two pyramids built alike hash alike step for step; a nudge to one body of one of them shows at once.
Test(v3_api, world_state_hash, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId a = MakePyramid();
	tbWorldId b = MakePyramid();
	cr_assert_eq(tbWorld_GetStateHash(a), tbWorld_GetStateHash(b));
	cr_assert_neq(tbWorld_GetStateHash(a), 0u);
	for (int i = 0; i < 30; ++i)
	{
		tbWorld_Step(a, DT, 4);
	}
	cr_assert_neq(tbWorld_GetStateHash(a), tbWorld_GetStateHash(b), "a stepped world differs");
	for (int i = 0; i < 30; ++i)
	{
		tbWorld_Step(b, DT, 4);
	}
	cr_assert_eq(tbWorld_GetStateHash(a), tbWorld_GetStateHash(b));
	tbBodyId first = tbShape_GetBody(tbWorld_CastRayClosest(a, tbMakeVec2(0.0f, 20.0f), tbMakeVec2(0.0f, -30.0f),
															tbDefaultQueryFilter())
										 .shapeId);
	cr_assert(tbBody_IsValid(first));
	tbBody_ApplyLinearImpulseToCenter(first, tbMakeVec2(1e-3f, 0.0f), true);
	cr_assert_neq(tbWorld_GetStateHash(a), tbWorld_GetStateHash(b), "one impulse differs");
	tbDestroyWorld(a);
	tbDestroyWorld(b);
	int before = s_errors;
	cr_assert_eq(tbWorld_GetStateHash(a), 0u);
	ExpectError(before, "tbWorld_GetStateHash", "");
}

Test(v3_api, world_dump_memory_stats, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = MakePyramid();
	tbWorld_Step(world, DT, 4);
	remove("tumble_memory.txt");
	tbWorld_DumpMemoryStats(world);
	FILE* file = fopen("tumble_memory.txt", "r");
	cr_assert_not_null(file, "the dump is written to the current directory");
	char text[4096];
	size_t n = fread(text, 1, sizeof(text) - 1, file);
	text[n] = 0;
	fclose(file);
	cr_assert(strstr(text, "bodies: ") != NULL && strstr(text, "total of the above: ") != NULL, "%s", text);
	remove("tumble_memory.txt");
	tbDestroyWorld(world);
	int before = s_errors;
	tbWorld_DumpMemoryStats(world);
	ExpectError(before, "tbWorld_DumpMemoryStats", "");
}

// ---------------------------------------------------------------------------------------------
// Base: hash, log hook, lap timer, yield, graph colours, the assert entry point

// djb2 (h ← 33·h + byte, from 5381) of "abc": ((5381·33 + 97)·33 + 98)·33 + 99 = 193485963, and
// hashing "ab" then "c" gives the same.
Test(v3_api, base_hash, .init = SetupErrors, .fini = TeardownErrors)
{
	const uint8_t abc[3] = {'a', 'b', 'c'};
	cr_assert_eq(tbHash(TB_HASH_INIT, abc, 3), 193485963u);
	cr_assert_eq(tbHash(tbHash(TB_HASH_INIT, abc, 2), abc + 2, 1), 193485963u);
	cr_assert_eq(tbHash(TB_HASH_INIT, NULL, 0), (uint32_t)TB_HASH_INIT);
	int before = s_errors;
	cr_assert_eq(tbHash(7u, abc, -1), 7u);
	ExpectError(before, "tbHash", "count");
	before = s_errors;
	cr_assert_eq(tbHash(7u, NULL, 3), 7u);
	ExpectError(before, "tbHash", "data");
}

static char s_logLine[600];
static int s_logLines;

static void RecordLog(const char* message)
{
	strncpy(s_logLine, message, sizeof(s_logLine) - 1);
	s_logLines += 1;
}

// Without an error hook, refusals go to the log hook; with one, to the error hook only.
Test(v3_api, base_log_hook)
{
	s_logLines = 0;
	tbSetErrorCallback(NULL, NULL);
	tbSetLogFcn(RecordLog);
	tbHash(0u, NULL, -1);
	cr_assert_eq(s_logLines, 1);
	cr_assert(strstr(s_logLine, "tumble error: tbHash: count is -1") == s_logLine, "%s", s_logLine);
	SetupErrors();
	int before = s_errors;
	tbHash(0u, NULL, -1);
	cr_assert_eq(s_logLines, 1, "the error hook takes it");
	ExpectError(before, "tbHash", "count");
	TeardownErrors();
	tbSetLogFcn(NULL);
}

static int s_asserts;
static int s_assertLine;

static int RecordAssert(const char* condition, const char* fileName, int lineNumber)
{
	(void)condition;
	(void)fileName;
	s_asserts += 1;
	s_assertLine = lineNumber;
	return 0;
}

Test(v3_api, base_timer_yield_colors_assert, .init = SetupErrors, .fini = TeardownErrors)
{
	uint64_t ticks = tbGetTicks();
	uint64_t start = ticks;
	tbYield();
	float ms = tbGetMillisecondsAndReset(&ticks);
	cr_assert(ms >= 0.0f && ticks >= start, "a lap is not negative and the start moves on");
	int before = s_errors;
	float refused = tbGetMillisecondsAndReset(NULL);
	ExpectError(before, "tbGetMillisecondsAndReset", "ticks");
	cr_assert_float_eq(refused, 0.0f, 0.0f);

	cr_assert_eq(tbGetGraphColor(0), tb_colorRed);
	cr_assert_eq(tbGetGraphColor(TB_GRAPH_COLOR_COUNT), tb_colorGray, "the overflow");
	for (int i = 0; i <= TB_GRAPH_COLOR_COUNT; ++i)
	{
		for (int j = 0; j < i; ++j)
		{
			cr_assert_neq(tbGetGraphColor(i), tbGetGraphColor(j), "colours %d and %d", i, j);
		}
	}
	before = s_errors;
	cr_assert_eq(tbGetGraphColor(TB_GRAPH_COLOR_COUNT + 1), tb_colorBlack);
	ExpectError(before, "tbGetGraphColor", "index");
	before = s_errors;
	cr_assert_eq(tbGetGraphColor(-1), tb_colorBlack);
	ExpectError(before, "tbGetGraphColor", "index");

	s_asserts = 0;
	tbSetAssertFcn(RecordAssert);
	cr_assert_eq(tbInternalAssert("1 == 2", "here.c", 42), 0, "the hook's answer is returned");
	cr_assert_eq(s_asserts, 1);
	cr_assert_eq(s_assertLine, 42);
	tbSetAssertFcn(NULL);
}

// ---------------------------------------------------------------------------------------------
// Length units

/// A unit box (1 m, or 100 cm) slid at 3 m/s along a ground box with friction 0.6 under g = 10 m/s²,
/// in the given units: where it is after 2 s, in its units (it stops after v²/(2μg) = 0.75 m and
/// rests into the ground by the contact's softness and slop), and the step it fell asleep at.
static tbVec2 SlideBox(float units, int* sleepStep)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, -10.0f * units);
	tbWorldId world = tbCreateWorld(&def);
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, -0.5f * units));
	tbShapeDef sd = tbDefaultShapeDef();
	sd.material.friction = 0.6f;
	tbPolygon groundBox = tbMakeBox(20.0f * units, 0.5f * units);
	tbCreatePolygonShape(ground, &sd, &groundBox);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	bd.position = tbMakeVec2(0.0f, 0.5f * units);
	bd.linearVelocity = tbMakeVec2(3.0f * units, 0.0f);
	tbBodyId body = tbCreateBody(world, &bd);
	sd.density = 1.0f / (units * units); // 1 kg whatever the units
	tbPolygon box = tbMakeBox(0.5f * units, 0.5f * units);
	tbCreatePolygonShape(body, &sd, &box);
	*sleepStep = -1;
	for (int i = 0; i < 120; ++i)
	{
		tbWorld_Step(world, DT, 4);
		*sleepStep = *sleepStep < 0 && tbBody_IsAwake(body) == false ? i : *sleepStep;
	}
	tbVec2 p = tbBody_GetPosition(body);
	tbDestroyWorld(world);
	return p;
}

// The same scene in metres and in centimetres: every length the library compares against scales
// with the units, so the centimetre run is the metre run × 100 up to float rounding (1e-4 of the
// 0.75 m slide; the resting depth within 1 %), and the box falls asleep at the same step (it
// does so 2 steps later when the centimetre scene runs with units 1: the sleep speed, 0.05 cm/s
// instead of 5 cm/s, is the most sensitive of the scaled values here). The defaults made after the
// change are in centimetres.
Test(v3_api, length_units_scale_the_tolerances, .init = SetupErrors, .fini = TeardownErrors)
{
	cr_assert_float_eq(tbGetLengthUnitsPerMeter(), 1.0f, 0.0f);
	cr_assert_float_eq(TB_LINEAR_SLOP, 0.005f, 0.0f);
	int sleepMetres, sleepCentimetres;
	tbVec2 metres = SlideBox(1.0f, &sleepMetres);
	cr_assert_gt(sleepMetres, 0);
	cr_assert(metres.x > 0.7f && metres.x < 0.8f, "slid %g m", (double)metres.x);

	cr_assert(tbSetLengthUnitsPerMeter(100.0f));
	cr_assert_float_eq(TB_LINEAR_SLOP, 0.5f, 0.0f);
	cr_assert_float_eq(TB_SPECULATIVE_DISTANCE, 2.0f, 0.0f);
	tbWorldDef def = tbDefaultWorldDef();
	cr_assert_float_eq(def.maximumLinearSpeed, 400000.0f, 0.0f);
	cr_assert_float_eq(def.hitEventThreshold, 100.0f, 0.0f);
	cr_assert_float_eq(tbDefaultBodyDef().sleepThreshold, 5.0f, 0.0f);
	cr_assert_float_eq(tbDefaultRevoluteJointDef().base.drawScale, 100.0f, 0.0f);
	tbVec2 centimetres = SlideBox(100.0f, &sleepCentimetres);
	cr_assert_eq(sleepCentimetres, sleepMetres);
	cr_assert_float_eq(centimetres.x / 100.0f, metres.x, 1e-4f);
	float depthMetres = 0.5f - metres.y, depthCentimetres = 50.0f - centimetres.y;
	cr_assert(depthMetres > 0.0f);
	cr_assert_float_eq(depthCentimetres / 100.0f, depthMetres, 0.01f * depthMetres);

	// Refused while a world exists, and out of range; the units stay.
	tbWorldId world = CreateWorld(tbVec2_zero);
	int before = s_errors;
	cr_assert_not(tbSetLengthUnitsPerMeter(32.0f));
	ExpectError(before, "tbSetLengthUnitsPerMeter", "world exists");
	tbDestroyWorld(world);
	float bad[4] = {0.0f, -1.0f, NAN, 2000.0f};
	for (int i = 0; i < 4; ++i)
	{
		before = s_errors;
		cr_assert_not(tbSetLengthUnitsPerMeter(bad[i]));
		ExpectError(before, "tbSetLengthUnitsPerMeter", "lengthUnits");
	}
	cr_assert_float_eq(tbGetLengthUnitsPerMeter(), 100.0f, 0.0f);
	cr_assert(tbSetLengthUnitsPerMeter(1.0f));
}

typedef struct LockProbe
{
	tbWorldId world;
	int errorsBefore;
	int errorsAfter;
	tbAABB bounds;
} LockProbe;

static bool ProbeInQuery(tbShapeId shape, void* context)
{
	(void)shape;
	LockProbe* probe = context;
	probe->errorsBefore = s_errors;
	probe->bounds = tbWorld_GetBounds(probe->world); // allowed: reading
	tbWorld_RebuildStaticTree(probe->world);		  // refused: the tree is being walked
	probe->errorsAfter = s_errors;
	return false;
}

static void ProbeInPreSolve(tbShapeId a, tbShapeId b, tbManifold* manifold, void* context)
{
	(void)a;
	(void)b;
	(void)manifold;
	LockProbe* probe = context;
	if (probe->errorsBefore < 0)
	{
		probe->errorsBefore = s_errors;
		probe->bounds = tbWorld_GetBounds(probe->world); // refused: the step is moving proxies
		probe->errorsAfter = s_errors;
	}
}

// Inside a query callback the bounds may be read but the static tree not rebuilt; during the step
// (a pre-solve callback) the bounds are refused.
Test(v3_api, world_bounds_and_rebuild_while_locked, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, -0.5f));
	AddBoxShape(ground, 5.0f, 0.5f, NULL);
	tbBodyId body = CreateBody(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.5f));
	tbShapeDef sd = tbDefaultShapeDef();
	sd.enablePreSolveEvents = true;
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbCreatePolygonShape(body, &sd, &box);

	LockProbe probe = {world, 0, 0, {{0.0f, 0.0f}, {0.0f, 0.0f}}};
	tbAABB all = {{-10.0f, -10.0f}, {10.0f, 10.0f}};
	tbWorld_OverlapAABB(world, tbPos_zero, all, tbDefaultQueryFilter(), ProbeInQuery, &probe);
	cr_assert_eq(probe.errorsAfter, probe.errorsBefore + 1, "only the rebuild is refused");
	cr_assert(strstr(s_lastError, "tbWorld_RebuildStaticTree") != NULL, "%s", s_lastError);
	ExpectVec2(probe.bounds.lowerBound, -5.0f, -1.0f, 1e-6f, "bounds read in a query");

	probe.errorsBefore = -1;
	tbWorld_SetPreSolveCallback(world, ProbeInPreSolve, NULL, &probe);
	tbWorld_Step(world, DT, 4);
	cr_assert_eq(probe.errorsAfter, probe.errorsBefore + 1);
	cr_assert(strstr(s_lastError, "tbWorld_GetBounds") != NULL, "%s", s_lastError);
	ExpectVec2(probe.bounds.upperBound, 0.0f, 0.0f, 0.0f, "a refused read gives the zero box");
	tbDestroyWorld(world);
}
