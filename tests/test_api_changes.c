// Changes made through the API between and during steps: teleports, type changes and moving kinematic
// bodies wake what they touch, destroyed shapes end their contacts with an event, event arrays stay
// valid while the game destroys what they name, query callbacks cannot change the broad phase.
// The scenes are tiny (a ground and a few boxes) so every test runs in well under a second.
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include <math.h>
#include <string.h>

// --- error recording --------------------------------------------------------------------------

#include "error_recorder.h"

// --- scene helpers ----------------------------------------------------------------------------

#include "test_helpers.h"

// --- teleporting wakes what rests on the body --------------------------------------------------

// A sleeping box rests on a static ground. Moving the ground away with tbBody_SetTransform must
// wake the box: otherwise neither body is awake, the contact is never updated, and the box hangs
// in the air forever. After 1 s of free fall from rest a box drops g·t²/2 = 5 m; we ask for > 2 m.
Test(api_changes, teleport_wakes_resting_neighbours)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyId ground = tbShape_GetBody(CreateGround(world, tbMakeVec2(0.0f, -0.5f), 50.0f, 0.5f, NULL));
	tbBodyId box = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.5f), 0.5f, 0.5f, 1.0f);
	StepWorld(world, 90, 1.0f / 60.0f, 4); // 1.5 s: the box settles and, after TB_TIME_TO_SLEEP = 0.5 s at rest, sleeps
	cr_assert(tbBody_IsAwake(box) == false, "the resting box should be asleep before the teleport");
	cr_assert(tbBody_SetTransform(ground, tbMakeVec2(0.0f, -20.0f), tbRot_identity));
	StepWorld(world, 60, 1.0f / 60.0f, 4);
	float y = tbBody_GetPosition(box).y;
	cr_assert_lt(y, 0.5f - 2.0f, "the box should fall once its support is gone; it is at y = %g", (double)y);
	tbDestroyWorld(world);
}

// --- end events from destroying bodies between steps ---------------------------------------------

// Destroying a body that touches another between steps ends the touch. The end event must reach
// the user after the next step (it used to be pushed and then cleared at the start of that step,
// so it was never seen).
Test(api_changes, destroy_end_event_reported_after_next_step)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbShapeDef groundDef = tbDefaultShapeDef();
	groundDef.enableContactEvents = true; // one shape of a contact enabling them reports its events
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 50.0f, 0.5f, &groundDef);
	tbBodyId box = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.5f), 0.5f, 0.5f, 1.0f);
	StepWorld(world, 10, 1.0f / 60.0f, 4);
	cr_assert_eq(tbWorld_GetContactEvents(world).endCount, 0, "the box is still resting: no end events yet");
	tbShapeId boxShape;
	cr_assert_eq(tbBody_GetShapes(box, &boxShape, 1), 1);
	tbDestroyBody(box);
	StepWorld(world, 1, 1.0f / 60.0f, 4);
	tbContactEvents events = tbWorld_GetContactEvents(world);
	cr_assert_eq(events.endCount, 1, "destroying the touching box must report one end event, got %d", events.endCount);
	bool namesBox = memcmp(&events.endEvents[0].shapeIdA, &boxShape, sizeof(boxShape)) == 0 ||
					memcmp(&events.endEvents[0].shapeIdB, &boxShape, sizeof(boxShape)) == 0;
	cr_assert(namesBox, "the end event should name the destroyed box's shape");
	cr_assert(tbShape_IsValid(events.endEvents[0].shapeIdA) == false || tbShape_IsValid(events.endEvents[0].shapeIdB) == false,
			  "one shape of the event is destroyed, and its id says so");
	StepWorld(world, 1, 1.0f / 60.0f, 4);
	cr_assert_eq(tbWorld_GetContactEvents(world).endCount, 0, "the event is reported once");
	tbDestroyWorld(world);
}

// types.h promises that event arrays stay valid until the next step. A game that reacts to end
// events by destroying bodies pushes more end events while it reads the array; that must not
// reallocate the array in its hands. 16 boxes are lifted off the ground (16 end events fill the
// array's first allocation of 16), then reading them while destroying a 17th touching box must
// keep the array readable (AddressSanitizer reports a use after free otherwise).
Test(api_changes, event_array_stays_valid_while_destroying)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbShapeDef groundDef = tbDefaultShapeDef();
	groundDef.enableContactEvents = true; // one shape of a contact enabling them reports its events
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 50.0f, 0.5f, &groundDef);
	tbBodyId boxes[17];
	for (int i = 0; i < 17; ++i)
	{
		boxes[i] = CreateBox(world, tb_dynamicBody, tbMakeVec2(2.0f * (float)i - 16.0f, 0.5f), 0.5f, 0.5f, 1.0f);
	}
	StepWorld(world, 5, 1.0f / 60.0f, 4);
	for (int i = 0; i < 16; ++i)
	{
		tbVec2 p = tbBody_GetPosition(boxes[i]);
		tbBody_SetTransform(boxes[i], tbMakeVec2(p.x, 10.0f), tbRot_identity);
	}
	StepWorld(world, 1, 1.0f / 60.0f, 4);
	tbContactEvents events = tbWorld_GetContactEvents(world);
	cr_assert_eq(events.endCount, 16, "the 16 lifted boxes end their touches, got %d", events.endCount);
	tbDestroyBody(boxes[16]);
	int valid = 0;
	for (int i = 0; i < events.endCount; ++i)
	{
		valid += tbShape_IsValid(events.endEvents[i].shapeIdA) ? 1 : 0;
	}
	cr_assert_eq(valid, 16, "the ground shape is shapeIdA of each of the 16 events and is alive");
	tbDestroyWorld(world);
}

// --- query callbacks may not change the world ----------------------------------------------------

typedef struct DestroyContext
{
	int calls;
	int invalidReported;
} DestroyContext;

static bool DestroyInCallback(tbShapeId shapeId, void* context)
{
	DestroyContext* c = context;
	c->calls += 1;
	if (tbShape_IsValid(shapeId) == false)
	{
		c->invalidReported += 1;
		return true;
	}
	tbDestroyBody(tbShape_GetBody(shapeId));
	return true;
}

// Destroying bodies from inside a query callback frees broad-phase nodes that the query is still
// walking. The world is locked during a query: the destroy is refused with an error that names the
// function, every reported shape is alive, and the world keeps its 21 bodies.
Test(api_changes, query_callback_cannot_mutate, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbShapeDef groundDef = tbDefaultShapeDef();
	groundDef.enableContactEvents = true; // one shape of a contact enabling them reports its events
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 50.0f, 0.5f, &groundDef);
	for (int i = 0; i < 20; ++i)
	{
		CreateBox(world, tb_dynamicBody, tbMakeVec2(2.0f * (float)i - 20.0f, 0.5f), 0.5f, 0.5f, 1.0f);
	}
	StepWorld(world, 1, 1.0f / 60.0f, 4);
	DestroyContext c = {0, 0};
	tbAABB all = {{-60.0f, -5.0f}, {60.0f, 5.0f}};
	int before = s_errors;
	cr_assert(tbWorld_OverlapAABB(world, tbPos_zero, all, tbDefaultQueryFilter(), DestroyInCallback, &c).leafVisits > 0);
	cr_assert_eq(c.calls, 21, "21 shapes (ground and 20 boxes) overlap the box, got %d", c.calls);
	cr_assert_eq(c.invalidReported, 0, "a query must never report a destroyed shape");
	cr_assert_eq(tbWorld_GetCounters(world).bodyCount, 21, "the destroys are refused; all 21 bodies remain");
	cr_assert_eq(s_errors, before + 21, "each refused destroy reports an error");
	cr_assert(strstr(s_lastError, "tbDestroyBody") != NULL, "message '%s' names the function", s_lastError);
	cr_assert(strstr(s_lastError, "callback") != NULL, "message '%s' says a callback holds the lock", s_lastError);
	// After the query the world is unlocked again.
	tbBodyDef def = tbDefaultBodyDef();
	cr_assert(tbBody_IsValid(tbCreateBody(world, &def)), "the world accepts changes after the query");
	tbDestroyWorld(world);
}

// --- shape queries check their geometry -------------------------------------------------------

static float CountCast(tbShapeId shapeId, tbPos point, tbVec2 normal, float fraction, void* context)
{
	(void)shapeId;
	(void)point;
	(void)normal;
	*(int*)context += 1;
	return fraction;
}

// A NaN radius or a polygon with 100 vertices (the arrays hold 8) used to reach the narrow phase:
// NaN distances, or reads past the vertex arrays. Both shape queries refuse them with an error
// that names the function and the bad field, and report nothing.
Test(api_changes, shape_queries_check_geometry, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbShapeDef groundDef = tbDefaultShapeDef();
	groundDef.enableContactEvents = true; // one shape of a contact enabling them reports its events
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 50.0f, 0.5f, &groundDef);
	tbVec2 zero = {0.0f, 0.0f};
	tbShapeProxy circle = tbMakeProxy(&zero, 1, 0.5f);
	circle.radius = NAN;
	tbPolygon box = tbMakeBox(1.0f, 1.0f);
	tbShapeProxy polygon = tbMakeProxy(box.vertices, box.count, 0.0f);
	polygon.count = 100;
	int count = 0;
	int before = s_errors;
	cr_assert(tbWorld_OverlapShape(world, tbPos_zero, &circle, tbDefaultQueryFilter(), CountOverlap, &count).leafVisits == 0);
	cr_assert_eq(s_errors, before + 1);
	cr_assert(strstr(s_lastError, "tbWorld_OverlapShape") != NULL && strstr(s_lastError, "radius") != NULL, "'%s'",
			  s_lastError);
	cr_assert(tbWorld_CastShape(world, tbPos_zero, &polygon, tbMakeVec2(0.0f, -1.0f), tbDefaultQueryFilter(),
								CountCast, &count).leafVisits == 0);
	cr_assert_eq(s_errors, before + 2);
	cr_assert(strstr(s_lastError, "tbWorld_CastShape") != NULL && strstr(s_lastError, "count") != NULL, "'%s'",
			  s_lastError);
	cr_assert_eq(count, 0, "a refused query reports nothing");
	tbDestroyWorld(world);
}

// --- mass updates keep the velocity of the body origin -------------------------------------------

// A dynamic body whose centre of mass is 1 m from its origin spins at ω = 2 rad/s with its centre
// of mass at rest, so its origin moves at ω × (origin − centre) = 2 × (−1, 0) = (0, −2) m/s.
// Making it kinematic moves its centre to the origin; the origin must keep (0, −2) m/s (it used to
// take the old centre's velocity, 0).
Test(api_changes, set_type_keeps_origin_velocity)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = tbVec2_zero;
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	tbBodyId body = tbCreateBody(world, &def);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle circle = {{1.0f, 0.0f}, 0.25f};
	tbCreateCircleShape(body, &shapeDef, &circle);
	tbBody_SetLinearVelocity(body, tbVec2_zero);
	tbBody_SetAngularVelocity(body, 2.0f);
	cr_assert(tbBody_SetType(body, tb_kinematicBody));
	tbVec2 v = tbBody_GetLinearVelocity(body);
	cr_assert(fabsf(v.x) < 1e-5f && fabsf(v.y + 2.0f) < 1e-5f, "origin velocity should stay (0, -2), got (%g, %g)",
			  (double)v.x, (double)v.y);
	cr_assert_float_eq(tbBody_GetAngularVelocity(body), 2.0f, 1e-6f, "the spin is kept");
	tbDestroyWorld(world);
}

Test(api_changes, moving_kinematic_wakes_resting_bodies)
{
	// A box falls asleep on a kinematic platform at rest; the platform then moves up at 2 m/s. The
	// box must wake and ride up with it: after 1 s the platform has risen 2 m (kinematic motion is
	// exact), and the box rests on it (its centre 1 m above the platform's, within the 0.005 m slop
	// plus the soft contact's compliance, 0.02 m).
	tbWorldDef def = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&def);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_kinematicBody;
	tbBodyId platform = tbCreateBody(world, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	tbPolygon slab = tbMakeBox(2.0f, 0.5f);
	tbCreatePolygonShape(platform, &sd, &slab);
	bd.type = tb_dynamicBody;
	bd.position = tbMakeVec2(0.0f, 1.0f);
	tbBodyId box = tbCreateBody(world, &bd);
	tbPolygon square = tbMakeSquare(0.5f);
	tbCreatePolygonShape(box, &sd, &square);
	for (int i = 0; i < 120; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	cr_assert_not(tbBody_IsAwake(box), "the box should have fallen asleep on the resting platform");
	tbBody_SetLinearVelocity(platform, tbMakeVec2(0.0f, 2.0f));
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	float platformY = tbBody_GetPosition(platform).y;
	float boxY = tbBody_GetPosition(box).y;
	cr_assert_float_eq(platformY, 2.0f, 1e-4f);
	cr_assert(tbBody_IsAwake(box));
	cr_assert_float_eq(boxY - platformY, 1.0f, 0.02f, "box at %.4f, platform at %.4f", (double)boxY, (double)platformY);
	tbDestroyWorld(world);
}
