// Shapes at run time: geometry by kind (get and set), and event flags switched after creation.
// Expected masses are the closed forms m = ρ·area (circle π·r², box w·h) and the rest height of a
// shape on flat ground (its half height, within the soft contact's sag of 0.01 m).
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include "error_recorder.h"

#include <math.h>

#define TIME_STEP (1.0f / 60.0f)

static tbWorldId CreateWorldWithGround(void)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, -10.0f);
	tbWorldId world = tbCreateWorld(&def);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.position = tbMakeVec2(0.0f, -1.0f);
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeBox(20.0f, 1.0f);
	tbCreatePolygonShape(ground, &shapeDef, &box);
	return world;
}

// A circle of radius 0.5 (mass π/4 at density 1) turned into a 2 × 1 box: the getters return
// what was set, the wrong-kind getter reports an error, the body's mass follows (2 kg), and the
// body comes to rest with its centre at the box's half height 0.5 m, not the circle's radius.
Test(shape, geometry_can_be_read_and_replaced, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorldWithGround();
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbMakeVec2(0.0f, 2.0f);
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbShapeId shape = tbCreateCircleShape(body, &shapeDef, &circle);
	cr_assert_float_eq(tbShape_GetCircle(shape).radius, 0.5f, 0.0f);
	cr_assert_float_eq(tbBody_GetMass(body), 3.14159265f * 0.25f, 1e-5f);
	int before = s_errors;
	tbPolygon wrong = tbShape_GetPolygon(shape);
	ExpectError(before, "tbShape_GetPolygon", "type");
	cr_assert_eq(wrong.count, 0);

	tbPolygon box = tbMakeBox(1.0f, 0.5f);
	cr_assert(tbShape_SetPolygon(shape, &box));
	cr_assert_eq(tbShape_GetType(shape), tb_polygonShape);
	cr_assert_eq(tbShape_GetPolygon(shape).count, 4);
	cr_assert_float_eq(tbBody_GetMass(body), 2.0f, 1e-5f);
	for (int step = 0; step < 120; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
	}
	cr_assert(fabsf(tbBody_GetPosition(body).y - 0.5f) < 0.01f, "rests at y %g, expected 0.5",
			  (double)tbBody_GetPosition(body).y);

	tbCapsule capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f};
	cr_assert(tbShape_SetCapsule(shape, &capsule));
	cr_assert_float_eq(tbShape_GetCapsule(shape).radius, 0.25f, 0.0f);
	tbSegment segment = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
	cr_assert(tbShape_SetSegment(shape, &segment));
	cr_assert_float_eq(tbShape_GetSegment(shape).point2.x, 1.0f, 0.0f);
	// Bad geometry is refused and nothing changes.
	tbCircle bad = {{0.0f, 0.0f}, -1.0f};
	before = s_errors;
	cr_assert(tbShape_SetCircle(shape, &bad) == false);
	cr_assert_eq(s_errors, before + 1);
	cr_assert_eq(tbShape_GetType(shape), tb_segmentShape);
	tbDestroyWorld(world);
}

// Contact events switched on after creation take effect on a contact that already exists: a box
// created with contact events off lands (no begin event); switching them on, lifting it and
// letting it land again gives one begin event. Hit events likewise.
Test(shape, event_flags_switch_at_run_time)
{
	tbWorldId world = CreateWorldWithGround();
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbMakeVec2(0.0f, 0.5f);
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.enableContactEvents = false;
	tbPolygon box = tbMakeSquare(0.5f);
	tbShapeId shape = tbCreatePolygonShape(body, &shapeDef, &box);
	int begins = 0, hits = 0;
	for (int step = 0; step < 30; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
		begins += tbWorld_GetContactEvents(world).beginCount;
	}
	cr_assert_eq(begins, 0);
	cr_assert(tbShape_AreContactEventsEnabled(shape) == false);
	tbShape_EnableContactEvents(shape, true);
	tbBody_EnableHitEvents(body, true);
	cr_assert(tbShape_AreContactEventsEnabled(shape) && tbShape_AreHitEventsEnabled(shape));
	cr_assert(tbBody_SetTransform(body, tbMakeVec2(0.0f, 2.5f), tbRot_identity));
	for (int step = 0; step < 90; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
		tbContactEvents events = tbWorld_GetContactEvents(world);
		begins += events.beginCount;
		hits += events.hitCount;
	}
	cr_assert_eq(begins, 1, "%d begin events after enabling", begins);
	cr_assert_eq(hits, 1, "%d hit events after enabling (a 2 m drop, √40 m/s > 1 m/s)", hits);
	tbShape_EnableSensorEvents(shape, false);
	cr_assert(tbShape_AreSensorEventsEnabled(shape) == false);
	tbDestroyWorld(world);
}

// tbShape_GetClosestPoint against closed forms: the closest point of an axis-aligned box to a point
// beside it is the point clamped to the box; of a circle, the centre plus the radius towards the
// point; a point inside is its own answer. GJK converges to float rounding here (1e-5 m).
Test(shape, closest_point_matches_closed_forms, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.position = tbMakeVec2(1.0f, 2.0f);
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeBox(0.5f, 0.25f);
	tbShapeId boxId = tbCreatePolygonShape(body, &shapeDef, &box);
	tbCircle circle = {{3.0f, 0.0f}, 1.0f}; // centred at (4, 2) in the world
	tbShapeId circleId = tbCreateCircleShape(body, &shapeDef, &circle);

	tbVec2 p = tbShape_GetClosestPoint(boxId, tbMakeVec2(-3.0f, 2.1f));
	cr_expect(fabsf(p.x - 0.5f) < 1e-5f && fabsf(p.y - 2.1f) < 1e-5f, "box, beside: (%g, %g)", (double)p.x, (double)p.y);
	p = tbShape_GetClosestPoint(boxId, tbMakeVec2(3.0f, 5.0f));
	cr_expect(fabsf(p.x - 1.5f) < 1e-5f && fabsf(p.y - 2.25f) < 1e-5f, "box, corner: (%g, %g)", (double)p.x, (double)p.y);
	p = tbShape_GetClosestPoint(boxId, tbMakeVec2(1.1f, 2.1f));
	cr_expect(p.x == 1.1f && p.y == 2.1f, "inside: the target itself, (%g, %g)", (double)p.x, (double)p.y);
	p = tbShape_GetClosestPoint(circleId, tbMakeVec2(4.0f, 7.0f));
	cr_expect(fabsf(p.x - 4.0f) < 1e-5f && fabsf(p.y - 3.0f) < 1e-5f, "circle: (%g, %g)", (double)p.x, (double)p.y);

	int before = s_errors;
	p = tbShape_GetClosestPoint(boxId, tbMakeVec2(NAN, 0.0f));
	ExpectError(before, "tbShape_GetClosestPoint", "target");
	cr_expect(p.x == 0.0f && p.y == 0.0f);
	tbDestroyWorld(world);
	before = s_errors;
	tbShape_GetClosestPoint(boxId, tbMakeVec2(0.0f, 0.0f));
	cr_expect_eq(s_errors, before + 1, "a stale shape id is refused");
}
