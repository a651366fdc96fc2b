// Events: contact begin/end/hit, sensor begin/end, body move and fell-asleep events, waking and
// collision filtering, each checked against free fall computed here in closed form.
//
// Sources of the expected numbers:
// - the step integrates each sub-step with symplectic Euler, v += g·h then y += v·h (h = dt/n),
//   so after m sub-steps from rest v = −g·h·m and y = y0 − g·h²·m(m+1)/2 (exact for constant g);
// - the step runs pairs → collide → solve, so a contact's manifold is computed from the positions
//   at the end of the previous step, and a point is kept while its separation is below
//   TB_SPECULATIVE_DISTANCE = 0.02 m (manifold.c): a falling ball begins touching at the first
//   step whose starting gap is below 0.02 m, up to 0.02 m before it reaches the ground;
// - hit events carry the approach speed at impact, √(2·g·h) for a drop of h from rest;
// - a body falls asleep after TB_TIME_TO_SLEEP = 0.5 s below the sleep tolerances;
// - filters as Box2D: (A.category & B.mask) && (B.category & A.mask) unless the group index is
//   shared: positive always collides, negative never.
#include <criterion/criterion.h>

#include "tumble/tumble.h"
#include "test_helpers.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/// The default shape definition with contact and sensor events on: Box2D v3.2's defaults have them
/// off, and these tests are about the events.
static const tbShapeDef* EventDef(void)
{
	static tbShapeDef def;
	def = tbDefaultShapeDef();
	def.enableContactEvents = true;
	def.enableSensorEvents = true;
	return &def;
}

#define TIME_STEP (1.0f / 60.0f)
#define SUB_STEPS 4
#define GRAVITY 10.0f

// --- helpers ----------------------------------------------------------------------------------

/// Free-fall height after `steps` steps from rest at y0 (symplectic Euler, SUB_STEPS sub-steps).
static double FreeFallHeight(double y0, int steps)
{
	double h = (double)TIME_STEP / SUB_STEPS;
	double m = (double)steps * SUB_STEPS;
	return y0 - GRAVITY * h * h * m * (m + 1.0) / 2.0;
}

static bool SamePair(tbShapeId a, tbShapeId b, tbShapeId x, tbShapeId y)
{
	return (TB_ID_EQUALS(a, x) && TB_ID_EQUALS(b, y)) || (TB_ID_EQUALS(a, y) && TB_ID_EQUALS(b, x));
}

/// Step a resting body until its move event says it fell asleep; returns the step index (1-based)
/// or −1 when it does not within maxSteps.
static int StepUntilAsleep(tbWorldId world, tbBodyId body, int maxSteps)
{
	for (int step = 1; step <= maxSteps; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbBodyEvents events = tbWorld_GetBodyEvents(world);
		for (int i = 0; i < events.moveCount; ++i)
		{
			if (TB_ID_EQUALS(events.moveEvents[i].bodyId, body) && events.moveEvents[i].fellAsleep)
			{
				return step;
			}
		}
	}
	return -1;
}

// --- contact events ---------------------------------------------------------------------------

// A ball r 0.5 dropped from a 1 m gap above the ground: one begin event, with the two shape ids,
// at the first step whose starting gap is below the speculative distance; touchingCount (contacts
// with manifold points) becomes 1 in that same step.
Test(events, contact_begin_touch_on_landing)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeId ground = CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
	const float radius = 0.5f;
	const double y0 = radius + 1.0;
	tbBodyId ball;
	tbShapeId ballShape = CreateBall(world, (tbVec2){0.0f, (float)y0}, tbVec2_zero, radius, EventDef(), &ball);

	// Expected step: first k with gap(k − 1) < TB_SPECULATIVE_DISTANCE.
	int expected = -1;
	for (int k = 1; k < 1000; ++k)
	{
		double gapBefore = FreeFallHeight(y0, k - 1) - radius;
		if (gapBefore < TB_SPECULATIVE_DISTANCE)
		{
			expected = k;
			// Not a knife-edge case: float rounding cannot move the crossing to another step.
			cr_assert(TB_SPECULATIVE_DISTANCE - gapBefore > 1e-3, "gap %g too close to the threshold", gapBefore);
			break;
		}
	}
	cr_assert(expected > 1);

	int beginTotal = 0;
	for (int step = 1; step <= expected + 60; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbContactEvents events = tbWorld_GetContactEvents(world);
		tbCounters counters = tbWorld_GetCounters(world);
		if (step < expected)
		{
			cr_assert_eq(events.beginCount, 0, "begin event at step %d, expected at %d", step, expected);
			cr_assert_eq(counters.touchingCount, 0, "manifold points at step %d, expected from %d", step, expected);
			// Free fall, except that a step whose free fall would end below the surface ends on it:
			// the speculative contact (its margin grows with the approach speed) stops the ball there.
			double y = fmax(FreeFallHeight(y0, step), (double)radius);
			cr_assert(fabs(tbBody_GetPosition(ball).y - y) < 1e-4, "step %d: y %g, expected %g", step,
					  (double)tbBody_GetPosition(ball).y, y);
		}
		else if (step == expected)
		{
			cr_assert_eq(events.beginCount, 1, "step %d: %d begin events, expected 1", step, events.beginCount);
			cr_assert(SamePair(events.beginEvents[0].shapeIdA, events.beginEvents[0].shapeIdB, ground, ballShape));
			cr_assert_eq(counters.touchingCount, 1, "step %d: touchingCount %d", step, counters.touchingCount);
		}
		beginTotal += events.beginCount;
		cr_assert_eq(events.endCount, 0, "end event at step %d while resting", step);
	}
	cr_assert_eq(beginTotal, 1, "%d begin events in all, expected exactly 1", beginTotal);
	// It rests on the ground (soft contact: within a few linear slops).
	cr_assert(fabsf(tbBody_GetPosition(ball).y - radius) < 4.0f * TB_LINEAR_SLOP);
	tbDestroyWorld(world);
}

// The resting ball is teleported 5 m up: exactly one end event, in the next step.
Test(events, contact_end_touch_when_lifted)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeId ground = CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
	tbBodyId ball;
	tbShapeId ballShape = CreateBall(world, (tbVec2){0.0f, 0.5f}, tbVec2_zero, 0.5f, EventDef(), &ball);
	int begins = 0;
	for (int step = 0; step < 20; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		begins += tbWorld_GetContactEvents(world).beginCount;
	}
	cr_assert_eq(begins, 1);
	cr_assert_eq(tbWorld_GetCounters(world).touchingCount, 1);

	cr_assert(tbBody_SetTransform(ball, (tbVec2){0.0f, 5.0f}, tbRot_identity));
	tbWorld_Step(world, TIME_STEP, SUB_STEPS);
	tbContactEvents events = tbWorld_GetContactEvents(world);
	cr_assert_eq(events.endCount, 1, "%d end events after the lift, expected 1", events.endCount);
	cr_assert(SamePair(events.endEvents[0].shapeIdA, events.endEvents[0].shapeIdB, ground, ballShape));
	cr_assert_eq(events.beginCount, 0);
	cr_assert_eq(tbWorld_GetCounters(world).touchingCount, 0);

	tbWorld_Step(world, TIME_STEP, SUB_STEPS);
	cr_assert_eq(tbWorld_GetContactEvents(world).endCount, 0, "a second end event");
	tbDestroyWorld(world);
}

// A ball dropped from a 2 m gap, hit events enabled: one hit whose approach speed is √(2·g·2)
// = 6.32 m/s within 5%, with the two shape ids and a vertical normal.
Test(events, hit_event_above_threshold)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeId ground = CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
	tbShapeDef def = *EventDef();
	def.enableHitEvents = true;
	tbBodyId ball;
	const float drop = 2.0f;
	tbShapeId ballShape = CreateBall(world, (tbVec2){0.0f, 0.5f + drop}, tbVec2_zero, 0.5f, &def, &ball);
	const float expected = sqrtf(2.0f * GRAVITY * drop);

	int hits = 0;
	for (int step = 0; step < 120; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbContactEvents events = tbWorld_GetContactEvents(world);
		for (int i = 0; i < events.hitCount; ++i)
		{
			const tbContactHitEvent* e = events.hitEvents + i;
			cr_assert(SamePair(e->shapeIdA, e->shapeIdB, ground, ballShape));
			cr_assert(fabsf(e->approachSpeed - expected) < 0.05f * expected, "approach %g, expected %g ± 5%%",
					  (double)e->approachSpeed, (double)expected);
			cr_assert(fabsf(fabsf(e->normal.y) - 1.0f) < 1e-3f, "normal (%g, %g)", (double)e->normal.x,
					  (double)e->normal.y);
			cr_assert(fabsf(e->point.y) < 0.05f, "hit point y %g, expected on the ground", (double)e->point.y);
		}
		hits += events.hitCount;
	}
	cr_assert_eq(hits, 1, "%d hit events, expected 1 (restitution 0: no bounce)", hits);
	tbDestroyWorld(world);
}

// The same 6.32 m/s landing with the threshold raised to 10 m/s: no hit event; and with hit
// events left disabled on both shapes (the default) at the default 1 m/s threshold: none either.
Test(events, no_hit_event_below_threshold)
{
	for (int variant = 0; variant < 2; ++variant)
	{
		tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
		CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
		tbShapeDef def = *EventDef();
		def.enableHitEvents = variant == 0;
		if (variant == 0)
		{
			cr_assert(tbWorld_SetHitEventThreshold(world, 10.0f));
		}
		tbBodyId ball;
		CreateBall(world, (tbVec2){0.0f, 2.5f}, tbVec2_zero, 0.5f, &def, &ball);
		int hits = 0, begins = 0;
		for (int step = 0; step < 120; ++step)
		{
			tbWorld_Step(world, TIME_STEP, SUB_STEPS);
			hits += tbWorld_GetContactEvents(world).hitCount;
			begins += tbWorld_GetContactEvents(world).beginCount;
		}
		cr_assert_eq(begins, 1, "variant %d: the ball must still land", variant);
		cr_assert_eq(hits, 0, "variant %d: %d hit events, expected none", variant, hits);
		tbDestroyWorld(world);
	}
}

// --- sensor events ----------------------------------------------------------------------------

// A ball r 0.25 falls from y = 8 through a static sensor box half (1, 0.5) at y = 5: one begin
// and one end event with (sensor, visitor) ids. A sensor pair overlaps when a manifold point has
// separation < 0 (contact.c), judged on the poses at the end of the step (tbSensorStage): the
// event of step k reports the change between the ends of steps k − 1 and k, as Box2D v3.2 does for
// a body that moves less than half its thickness a step (this ball: 0.11 m a step on its way in;
// on its way out 0.14 m, more than half its radius, where v3.2's swept test of fast bodies would
// report the end a step later). The sensor does not touch the ball: its velocity stays −g·t
// within 1e-4.
// A kinematic box half 0.5 at 4 m/s from x = −6 crosses a static sensor box half 1 at the origin:
// x(k) = −6 + 4·k/60 after step k, so the overlap begins in the first step with x + 0.5 > −1
// (k = 68, x = −1.467) and ends in the first with x − 0.5 > 1 (k = 113). The steps are
// computed here from x(k) in double, so the test holds the rule (the step whose end poses
// overlap), not a number copied from a run; Box2D v3.2 reports this crossing at the same steps.
Test(events, sensor_events_in_the_step_the_overlap_changes)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, 0.0f});
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbShapeDef sensorDef = *EventDef();
	sensorDef.isSensor = true;
	sensorDef.enableSensorEvents = true;
	tbPolygon sensorBox = tbMakeBox(1.0f, 1.0f);
	tbShapeId sensor = tbCreatePolygonShape(ground, &sensorDef, &sensorBox);
	tbBodyDef moverDef = tbDefaultBodyDef();
	moverDef.type = tb_kinematicBody;
	moverDef.position = (tbVec2){-6.0f, 0.0f};
	moverDef.linearVelocity = (tbVec2){4.0f, 0.0f};
	tbBodyId mover = tbCreateBody(world, &moverDef);
	tbPolygon moverBox = tbMakeBox(0.5f, 0.5f);
	tbShapeId moverShape = tbCreatePolygonShape(mover, EventDef(), &moverBox);
	int expectedBegin = -1, expectedEnd = -1;
	for (int k = 1; k <= 200; ++k)
	{
		double x = -6.0 + 4.0 * k / 60.0;
		expectedBegin = expectedBegin < 0 && x + 0.5 > -1.0 ? k : expectedBegin;
		expectedEnd = expectedEnd < 0 && x - 0.5 > 1.0 ? k : expectedEnd;
	}
	int beginStep = -1, endStep = -1;
	for (int step = 1; step <= 200; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbSensorEvents events = tbWorld_GetSensorEvents(world);
		for (int i = 0; i < events.beginCount; ++i)
		{
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].sensorShapeId, sensor));
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].visitorShapeId, moverShape));
			cr_assert_eq(beginStep, -1, "a second begin event at step %d", step);
			beginStep = step;
		}
		for (int i = 0; i < events.endCount; ++i)
		{
			cr_assert(TB_ID_EQUALS(events.endEvents[i].visitorShapeId, moverShape));
			cr_assert_eq(endStep, -1, "a second end event at step %d", step);
			endStep = step;
		}
		// Between the events the sensor lists the mover as its visitor.
		tbShapeId visitors[2];
		int count = tbShape_GetSensorData(sensor, visitors, 2);
		bool inside = beginStep > 0 && endStep < 0;
		cr_assert_eq(count, inside ? 1 : 0, "step %d: %d visitors", step, count);
	}
	cr_assert_eq(beginStep, expectedBegin, "begin at step %d, the overlap begins in step %d", beginStep, expectedBegin);
	cr_assert_eq(endStep, expectedEnd, "end at step %d, the overlap ends in step %d", endStep, expectedEnd);
	tbDestroyWorld(world);
}

// A ball dropped through a static sensor: begin in the step that makes the overlap, end as the
// continuous rule below says (Box2D v3.2 reports this scene's begin at step 41 and end at step 53).
Test(events, sensor_begin_end_ball_falls_through)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbBodyDef sensorBodyDef = tbDefaultBodyDef();
	sensorBodyDef.position = (tbVec2){0.0f, 5.0f};
	tbBodyId sensorBody = tbCreateBody(world, &sensorBodyDef);
	tbShapeDef sensorDef = *EventDef();
	sensorDef.isSensor = true;
	sensorDef.enableSensorEvents = true;
	tbPolygon box = tbMakeBox(1.0f, 0.5f);
	tbShapeId sensor = tbCreatePolygonShape(sensorBody, &sensorDef, &box);

	const float radius = 0.25f;
	const double y0 = 8.0;
	tbBodyId ball;
	tbShapeId ballShape = CreateBall(world, (tbVec2){0.0f, (float)y0}, tbVec2_zero, radius, EventDef(), &ball);

	int beginStep = -1, endStep = -1;
	const float top = 5.5f, bottom = 4.5f;
	// The ball's height at the end of the previous step, and of the one before.
	float previousY = (float)y0, beforeY = (float)y0;
	for (int step = 1; step <= 90; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		float y = tbBody_GetPosition(ball).y;
		float vy = tbBody_GetLinearVelocity(ball).y;
		double expectedV = -GRAVITY * (double)TIME_STEP * step;
		cr_assert(fabs(vy - expectedV) < 1e-4 * fmax(1.0, fabs(expectedV)), "step %d: vy %.6f, free fall %.6f",
				  step, (double)vy, expectedV);
		cr_assert(fabs(y - FreeFallHeight(y0, step)) < 1e-3, "step %d: y %g, free fall %g", step, (double)y,
				  FreeFallHeight(y0, step));
		cr_assert_eq(tbWorld_GetContactEvents(world).beginCount, 0, "a sensor must not make contacts");

		tbSensorEvents events = tbWorld_GetSensorEvents(world);
		for (int i = 0; i < events.beginCount; ++i)
		{
			cr_assert_eq(beginStep, -1, "a second begin event at step %d", step);
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].sensorShapeId, sensor));
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].visitorShapeId, ballShape));
			beginStep = step;
			// Reported in the step that makes the overlap (Box2D v3.2's rule): overlapping at the
			// end of this step, not at the end of the last.
			cr_assert(y - radius < top, "begin at step %d: y is %g, not overlapping", step, (double)y);
			cr_assert(previousY - radius >= top, "begin at step %d: late, y was already %g", step, (double)previousY);
		}
		for (int i = 0; i < events.endCount; ++i)
		{
			cr_assert_eq(endStep, -1, "a second end event at step %d", step);
			cr_assert(TB_ID_EQUALS(events.endEvents[i].sensorShapeId, sensor));
			cr_assert(TB_ID_EQUALS(events.endEvents[i].visitorShapeId, ballShape));
			endStep = step;
			// The ball leaves at 8.7 m/s, 0.145 m a step, more than half its radius (0.125 m): it is
			// swept by the continuous stage, and a sensor its sweep touches counts it as a visitor for
			// that step from the sweep's start (Box2D v3.2's rule, which reports this end in the same
			// step). So the end comes in the first step that both starts and ends clear of the sensor.
			cr_assert(y + radius < bottom, "end at step %d: y is %g, still overlapping", step, (double)y);
			cr_assert(previousY + radius < bottom, "end at step %d: early, the step began at y %g, overlapping", step,
					  (double)previousY);
			cr_assert(beforeY + radius >= bottom, "end at step %d: late, y was already %g a step before", step,
					  (double)beforeY);
		}
		beforeY = previousY;
		previousY = y;
	}
	cr_assert(beginStep > 0, "no sensor begin event");
	cr_assert(endStep > beginStep, "no sensor end event after the begin (begin %d, end %d)", beginStep, endStep);
	tbDestroyWorld(world);
}

// --- body events and sleep --------------------------------------------------------------------

// Three falling boxes: one move event per awake body each step, carrying its id and transform.
Test(events, body_move_events_for_awake_bodies)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
	tbBodyId boxes[3];
	for (int i = 0; i < 3; ++i)
	{
		boxes[i] = CreateBox(world, tb_dynamicBody, (tbVec2){-3.0f + 3.0f * (float)i, 5.0f}, 0.5f, 0.5f, 1.0f);
	}
	for (int step = 0; step < 30; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbBodyEvents events = tbWorld_GetBodyEvents(world);
		cr_assert_eq(events.moveCount, 3, "step %d: %d move events, expected 3", step, events.moveCount);
		for (int i = 0; i < 3; ++i)
		{
			int found = 0;
			for (int j = 0; j < events.moveCount; ++j)
			{
				const tbBodyMoveEvent* e = events.moveEvents + j;
				if (TB_ID_EQUALS(e->bodyId, boxes[i]))
				{
					found += 1;
					tbTransform t = tbBody_GetTransform(boxes[i]);
					cr_assert_eq(e->transform.p.x, t.p.x);
					cr_assert_eq(e->transform.p.y, t.p.y);
					cr_assert_eq(e->transform.q.c, t.q.c);
					cr_assert_eq(e->transform.q.s, t.q.s);
					cr_assert_not(e->fellAsleep);
				}
			}
			cr_assert_eq(found, 1, "step %d: box %d has %d move events", step, i, found);
		}
	}
	tbDestroyWorld(world);
}

// A box resting on the ground: one fellAsleep move event after TB_TIME_TO_SLEEP = 0.5 s of rest
// (30 steps at 60 Hz; allow 15 more for the first steps of settling), then no more move events.
Test(events, fell_asleep_event_after_time_to_sleep)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
	tbBodyId box = CreateBox(world, tb_dynamicBody, (tbVec2){0.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
	int minSteps = (int)floorf(TB_TIME_TO_SLEEP / TIME_STEP);
	int step = StepUntilAsleep(world, box, 120);
	cr_assert(step >= minSteps && step <= minSteps + 15, "fell asleep at step %d, expected %d..%d", step, minSteps,
			  minSteps + 15);
	cr_assert_not(tbBody_IsAwake(box));
	for (int i = 0; i < 10; ++i)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		cr_assert_eq(tbWorld_GetBodyEvents(world).moveCount, 0, "a sleeping body reported a move");
	}
	tbDestroyWorld(world);
}

// A row of six unit boxes touching side by side on the ground is one island; one of them may not
// sleep (tbBody_EnableSleep false), so none of the six may, while a lone box beside the row falls
// asleep as usual. Checked for the non-sleeper at each place in the row (the islands must not
// depend on which body the sleep stage looks at first), for 2 s (4 × the sleep time).
Test(events, one_body_that_may_not_sleep_keeps_its_island_awake)
{
	for (int keeper = 0; keeper < 6; ++keeper)
	{
		tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
		CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
		tbBodyId row[6];
		for (int i = 0; i < 6; ++i)
		{
			row[i] = CreateBox(world, tb_dynamicBody, (tbVec2){-5.0f + 1.0f * (float)i, 0.5f}, 0.5f, 0.5f, 1.0f);
		}
		tbBody_EnableSleep(row[keeper], false);
		tbBodyId lone = CreateBox(world, tb_dynamicBody, (tbVec2){8.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
		for (int step = 0; step < 120; ++step)
		{
			tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		}
		cr_expect_not(tbBody_IsAwake(lone), "keeper %d: the lone box did not fall asleep", keeper);
		for (int i = 0; i < 6; ++i)
		{
			cr_expect(tbBody_IsAwake(row[i]), "keeper %d: box %d of the row fell asleep", keeper, i);
		}
		tbDestroyWorld(world);
	}
}

/// A kinematic body: a box of half size (hx, hy) at position moving at velocity.
static tbBodyId CreateKinematicBox(tbWorldId world, tbVec2 position, float hx, float hy, tbVec2 velocity)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_kinematicBody;
	bodyDef.position = position;
	bodyDef.linearVelocity = velocity;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef def = *EventDef();
	def.material.friction = 0.0f;
	tbPolygon box = tbMakeBox(hx, hy);
	tbCreatePolygonShape(body, &def, &box);
	return body;
}

// A frictionless kinematic platform 40 m long slides sideways at 1 m/s under two boxes 4 m apart:
// the boxes rest on it (friction mixes to 0, so it does not carry them), but a moving kinematic
// body keeps what it touches awake, so both stay awake at every step from 1 s to 2 s (sleep would
// come at 0.5 s). The boxes are separate islands touching the same platform: neither may sleep
// however the sleep stage orders them.
Test(events, moving_kinematic_body_keeps_every_island_it_touches_awake)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	CreateKinematicBox(world, (tbVec2){0.0f, 1.0f}, 20.0f, 0.25f, (tbVec2){1.0f, 0.0f});
	tbBodyId left = CreateBox(world, tb_dynamicBody, (tbVec2){-2.0f, 1.75f}, 0.5f, 0.5f, 1.0f);
	tbBodyId right = CreateBox(world, tb_dynamicBody, (tbVec2){2.0f, 1.75f}, 0.5f, 0.5f, 1.0f);
	for (int step = 1; step <= 120; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		if (step >= 60)
		{
			cr_assert(tbBody_IsAwake(left), "step %d: the left box fell asleep on the moving platform", step);
			cr_assert(tbBody_IsAwake(right), "step %d: the right box fell asleep on the moving platform", step);
		}
	}
	// Frictionless, the platform's 1 m/s passes nothing to the box: it rests. 0.01 m/s is a fifth of
	// the sleep speed (TB_LINEAR_SLEEP_TOLERANCE, 0.05 m/s), so the box rests by the library's measure
	// and the test is about the platform keeping it awake, not about its motion.
	tbVec2 v = tbBody_GetLinearVelocity(right);
	cr_assert(fabsf(v.x) < 0.01f && fabsf(v.y) < 0.01f, "the platform moved the box: v = (%g, %g)", (double)v.x,
			  (double)v.y);
	tbDestroyWorld(world);
}

// A kinematic platform at rest (created first) carries two boxes 4 m apart, one of which may not
// sleep. The other box's island sleeps after 0.5 s; the platform, rested but touching an island that
// stays awake, stays awake at every step from 1 s to 2 s. Once the second box may sleep, everything
// sleeps within 1 s (0.5 s of sleep time, counted from when the box is allowed to sleep).
Test(events, rested_kinematic_body_sleeps_with_the_last_island_it_touches)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbBodyId platform = CreateKinematicBox(world, (tbVec2){0.0f, 1.0f}, 4.0f, 0.25f, tbVec2_zero);
	tbBodyId sleeper = CreateBox(world, tb_dynamicBody, (tbVec2){-2.0f, 1.75f}, 0.5f, 0.5f, 1.0f);
	tbBodyId keeper = CreateBox(world, tb_dynamicBody, (tbVec2){2.0f, 1.75f}, 0.5f, 0.5f, 1.0f);
	tbBody_EnableSleep(keeper, false);
	for (int step = 1; step <= 120; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		if (step >= 60)
		{
			cr_assert(tbBody_IsAwake(platform), "step %d: the platform fell asleep under an awake box", step);
			cr_assert(tbBody_IsAwake(keeper), "step %d: the box that may not sleep fell asleep", step);
			cr_assert_not(tbBody_IsAwake(sleeper), "step %d: the resting box is awake", step);
		}
	}
	tbBody_EnableSleep(keeper, true);
	for (int step = 1; step <= 60; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
	}
	cr_assert_not(tbBody_IsAwake(keeper), "the second box did not fall asleep once allowed");
	cr_assert_not(tbBody_IsAwake(platform), "the platform did not fall asleep with the last island on it");
	cr_assert_not(tbBody_IsAwake(sleeper));
	tbDestroyWorld(world);
}

// --- waking -----------------------------------------------------------------------------------

// A sleeping box is woken by a ball landing on it: awake no later than the step after the ball's
// begin-touch event, and the ball comes to rest on it (centre at 1 + 0.25 m).
Test(events, sleeping_box_woken_by_landing_ball)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
	tbBodyId box = CreateBox(world, tb_dynamicBody, (tbVec2){0.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
	cr_assert(StepUntilAsleep(world, box, 120) > 0);
	cr_assert_not(tbBody_IsAwake(box));

	tbBodyId ball;
	tbShapeId ballShape = CreateBall(world, (tbVec2){0.0f, 2.25f}, tbVec2_zero, 0.25f, EventDef(), &ball);
	int beginStep = -1, wokenStep = -1;
	for (int step = 1; step <= 60; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbContactEvents events = tbWorld_GetContactEvents(world);
		for (int i = 0; i < events.beginCount; ++i)
		{
			if (TB_ID_EQUALS(events.beginEvents[i].shapeIdA, ballShape) ||
				TB_ID_EQUALS(events.beginEvents[i].shapeIdB, ballShape))
			{
				beginStep = beginStep < 0 ? step : beginStep;
			}
		}
		if (wokenStep < 0 && tbBody_IsAwake(box))
		{
			wokenStep = step;
		}
	}
	cr_assert(beginStep > 0, "the ball never touched the box");
	cr_assert(wokenStep > 0, "the box never woke");
	cr_assert(wokenStep <= beginStep + 1, "woke at step %d, touch began at %d", wokenStep, beginStep);
	cr_assert(fabsf(tbBody_GetPosition(ball).y - 1.25f) < 0.02f, "ball at %g", (double)tbBody_GetPosition(ball).y);
	tbDestroyWorld(world);
}

// An upward impulse of 5 N·s on a sleeping 1 kg box wakes it at once and lifts it
// (Δv = 5 m/s: after one step it has risen by about 5/60 m).
Test(events, impulse_wakes_sleeping_body)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
	tbBodyId box = CreateBox(world, tb_dynamicBody, (tbVec2){0.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
	cr_assert(StepUntilAsleep(world, box, 120) > 0);
	cr_assert_not(tbBody_IsAwake(box));
	float y0 = tbBody_GetPosition(box).y;
	cr_assert(tbBody_ApplyLinearImpulseToCenter(box, (tbVec2){0.0f, 5.0f * tbBody_GetMass(box)}, true));
	cr_assert(tbBody_IsAwake(box), "the impulse did not wake the box");
	tbWorld_Step(world, TIME_STEP, SUB_STEPS);
	float rise = tbBody_GetPosition(box).y - y0;
	cr_assert(fabsf(rise - 5.0f * TIME_STEP) < 0.01f, "rose %g m in one step, expected ~%g", (double)rise,
			  (double)(5.0f * TIME_STEP));
	cr_assert_eq(tbWorld_GetBodyEvents(world).moveCount, 1);
	tbDestroyWorld(world);
}

// --- filtering --------------------------------------------------------------------------------

/// Drop a ball r 0.5 from a 1 m gap onto the ground for 1.5 s with the given filters; returns
/// its final height and the number of begin events.
static float DropWithFilters(tbFilter groundFilter, tbFilter ballFilter, int* beginsOut)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeDef groundDef = *EventDef();
	groundDef.filter = groundFilter;
	CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, &groundDef);
	tbShapeDef ballDef = *EventDef();
	ballDef.filter = ballFilter;
	tbBodyId ball;
	CreateBall(world, (tbVec2){0.0f, 1.5f}, tbVec2_zero, 0.5f, &ballDef, &ball);
	int begins = 0;
	for (int step = 0; step < 90; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		begins += tbWorld_GetContactEvents(world).beginCount;
	}
	float y = tbBody_GetPosition(ball).y;
	tbDestroyWorld(world);
	*beginsOut = begins;
	return y;
}

// Ground category 1; the ball's category 2 and mask 2 exclude it: the ball falls through
// (free fall for 1.5 s: y = 1.5 − ½·10·1.5² ≈ −9.8 m) and no contact ever begins.
Test(filter, category_mask_exclusion_falls_through)
{
	tbFilter ground = tbDefaultFilter();
	ground.categoryBits = 0x1;
	tbFilter ball = tbDefaultFilter();
	ball.categoryBits = 0x2;
	ball.maskBits = 0x2;
	int begins;
	float y = DropWithFilters(ground, ball, &begins);
	cr_assert_eq(begins, 0);
	cr_assert(y < -9.0f, "ball at y %g, expected to fall through", (double)y);

	// Control: the default filters collide and the ball rests on the ground.
	y = DropWithFilters(tbDefaultFilter(), tbDefaultFilter(), &begins);
	cr_assert_eq(begins, 1);
	cr_assert(fabsf(y - 0.5f) < 0.02f, "ball at y %g, expected resting at 0.5", (double)y);
}

// Same negative group index on both shapes (categories and masks would collide): never collide.
Test(filter, negative_group_never_collides)
{
	tbFilter filter = tbDefaultFilter();
	filter.groupIndex = -3;
	int begins;
	float y = DropWithFilters(filter, filter, &begins);
	cr_assert_eq(begins, 0);
	cr_assert(y < -9.0f, "ball at y %g, expected to fall through", (double)y);
}

// Same positive group index on both shapes while categories and masks exclude each other:
// always collide, the ball rests on the ground.
Test(filter, positive_group_always_collides)
{
	tbFilter ground = tbDefaultFilter();
	ground.categoryBits = 0x1;
	ground.maskBits = 0x1;
	ground.groupIndex = 3;
	tbFilter ball = tbDefaultFilter();
	ball.categoryBits = 0x2;
	ball.maskBits = 0x2;
	ball.groupIndex = 3;
	int begins;
	float y = DropWithFilters(ground, ball, &begins);
	cr_assert_eq(begins, 1);
	cr_assert(fabsf(y - 0.5f) < 0.02f, "ball at y %g, expected resting at 0.5", (double)y);
}

// One landing, one hit event, in the step of its begin event or later: a box and a ball dropped
// 2 m with hit events on. A speculative point meets the body a step before it is within the fixed
// distance that makes begin events (TB_SPECULATIVE_DISTANCE); the impact it takes is reported with
// the begin event. Approach speed √(2·g·2) = 6.32 m/s within 5 % (the landing happens part way
// through a step: at most g·dt = 0.17 m/s, 2.6 %, off the closed form).
Test(events, one_landing_gives_one_hit_event_with_its_begin_event)
{
	for (int shapeKind = 0; shapeKind < 2; ++shapeKind)
	{
		tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
		tbShapeId ground = CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
		const float drop = 2.0f, half = 0.5f;
		tbBodyDef bodyDef = tbDefaultBodyDef();
		bodyDef.type = tb_dynamicBody;
		bodyDef.position = (tbVec2){0.0f, half + drop};
		tbBodyId body = tbCreateBody(world, &bodyDef);
		tbShapeDef def = *EventDef();
		def.enableHitEvents = true;
		tbPolygon box = tbMakeSquare(half);
		tbCircle circle = {{0.0f, 0.0f}, half};
		tbShapeId shape = shapeKind == 0 ? tbCreatePolygonShape(body, &def, &box) : tbCreateCircleShape(body, &def, &circle);
		const float expected = sqrtf(2.0f * GRAVITY * drop);
		int beginStep = -1, hitStep = -1, hits = 0;
		for (int step = 1; step <= 120; ++step)
		{
			tbWorld_Step(world, TIME_STEP, SUB_STEPS);
			tbContactEvents events = tbWorld_GetContactEvents(world);
			if (events.beginCount > 0 && beginStep < 0)
			{
				beginStep = step;
			}
			for (int i = 0; i < events.hitCount; ++i)
			{
				const tbContactHitEvent* e = events.hitEvents + i;
				cr_assert(SamePair(e->shapeIdA, e->shapeIdB, ground, shape));
				cr_assert(fabsf(e->approachSpeed - expected) < 0.05f * expected, "%s: approach %g, expected %g ± 5%%",
						  shapeKind == 0 ? "box" : "ball", (double)e->approachSpeed, (double)expected);
				cr_assert(fabsf(e->point.y) < 0.05f, "hit point y %g, expected on the ground", (double)e->point.y);
				hitStep = step;
			}
			hits += events.hitCount;
		}
		const char* name = shapeKind == 0 ? "box" : "ball";
		cr_assert_eq(hits, 1, "%s: %d hit events for one landing", name, hits);
		cr_assert(beginStep > 0 && hitStep >= beginStep, "%s: hit at step %d, begin at step %d", name, hitStep,
				  beginStep);
		tbDestroyWorld(world);
	}
}

/// A static sensor box (half size 1 × 0.5) at height 5 and a visitor passing through it.
static tbShapeId CreateStaticSensor(tbWorldId world)
{
	tbBodyDef sensorBodyDef = tbDefaultBodyDef();
	sensorBodyDef.position = (tbVec2){0.0f, 5.0f};
	tbBodyId sensorBody = tbCreateBody(world, &sensorBodyDef);
	tbShapeDef sensorDef = *EventDef();
	sensorDef.isSensor = true;
	sensorDef.enableSensorEvents = true;
	tbPolygon box = tbMakeBox(1.0f, 0.5f);
	return tbCreatePolygonShape(sensorBody, &sensorDef, &box);
}

// A visitor whose shape disables sensor events is not reported: the ball of the test above
// falls through the same sensor with enableSensorEvents = false on its own shape and produces
// no sensor event at all, while a second ball beside it with the flag on produces one begin and
// one end.
Test(events, sensor_ignores_a_visitor_that_disables_sensor_events)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeId sensor = CreateStaticSensor(world);
	tbShapeDef quiet = *EventDef();
	quiet.enableSensorEvents = false;
	tbBodyId quietBall, seenBall;
	tbShapeId quietShape = CreateBall(world, (tbVec2){-0.5f, 8.0f}, tbVec2_zero, 0.25f, &quiet, &quietBall);
	tbShapeId seenShape = CreateBall(world, (tbVec2){0.5f, 8.0f}, tbVec2_zero, 0.25f, EventDef(), &seenBall);
	int begins = 0, ends = 0;
	for (int step = 0; step < 90; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbSensorEvents events = tbWorld_GetSensorEvents(world);
		for (int i = 0; i < events.beginCount; ++i)
		{
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].sensorShapeId, sensor));
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].visitorShapeId, seenShape), "the quiet ball was reported");
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].visitorShapeId, quietShape) == false);
		}
		for (int i = 0; i < events.endCount; ++i)
		{
			cr_assert(TB_ID_EQUALS(events.endEvents[i].visitorShapeId, seenShape), "the quiet ball was reported");
		}
		begins += events.beginCount;
		ends += events.endCount;
	}
	cr_assert_eq(begins, 1);
	cr_assert_eq(ends, 1);
	tbDestroyWorld(world);
}

// A kinematic body (a lift) moving up at 2 m/s through a static sensor: one begin event when its
// box (half size 0.25) first overlaps the sensor's [4.5, 5.5] band and one end event when it has
// left it. It starts at y = 3, so its top reaches 4.5 after (4.5 − 3.25)/2 = 0.625 s (step 38) and
// its bottom leaves 5.5 after (5.5 + 0.25 − 3)/2 = 1.375 s (step 83); the events come one step
// later (the collide stage sees the positions of the previous step), within a step either way.
Test(events, kinematic_body_passing_a_static_sensor_is_reported)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeId sensor = CreateStaticSensor(world);
	tbBodyDef liftDef = tbDefaultBodyDef();
	liftDef.type = tb_kinematicBody;
	liftDef.position = (tbVec2){0.0f, 3.0f};
	liftDef.linearVelocity = (tbVec2){0.0f, 2.0f};
	tbBodyId lift = tbCreateBody(world, &liftDef);
	tbShapeDef def = *EventDef();
	tbPolygon box = tbMakeSquare(0.25f);
	tbShapeId liftShape = tbCreatePolygonShape(lift, &def, &box);
	int beginStep = -1, endStep = -1;
	for (int step = 1; step <= 120; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbSensorEvents events = tbWorld_GetSensorEvents(world);
		for (int i = 0; i < events.beginCount; ++i)
		{
			cr_assert_eq(beginStep, -1, "a second begin event at step %d", step);
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].sensorShapeId, sensor));
			cr_assert(TB_ID_EQUALS(events.beginEvents[i].visitorShapeId, liftShape));
			beginStep = step;
		}
		for (int i = 0; i < events.endCount; ++i)
		{
			cr_assert_eq(endStep, -1, "a second end event at step %d", step);
			cr_assert(TB_ID_EQUALS(events.endEvents[i].visitorShapeId, liftShape));
			endStep = step;
		}
	}
	cr_assert(abs(beginStep - 39) <= 1, "begin at step %d, expected 39 ± 1", beginStep);
	cr_assert(abs(endStep - 84) <= 1, "end at step %d, expected 84 ± 1", endStep);
	tbDestroyWorld(world);
}

// Contact data: a unit box resting on the ground reports one touching contact, from the body, from
// its shape and through the begin event's contact id, with a unit normal along y and two points
// on the ground's top face (y = 0 within the soft contact's sag, 0.01 m) at the box's corners
// x = ±0.5; its normal impulses (accumulated over one sub-step, as the solver keeps them) carry the
// box's weight over a sub-step, m·g·dt/4 = 1 × 10 / 240 N·s, within 5 % (a resting solve
// converges to it). Lifting the box away ends the contact: the
// kept id goes stale.
Test(events, contact_data_of_a_resting_box)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeId ground = CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, EventDef());
	tbBodyId box = CreateBox(world, tb_dynamicBody, (tbVec2){0.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
	tbShapeId boxShape;
	cr_assert_eq(tbBody_GetShapes(box, &boxShape, 1), 1);
	tbContactId fromEvent = TB_NULL_CONTACT_ID;
	for (int step = 0; step < 60; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		tbContactEvents events = tbWorld_GetContactEvents(world);
		if (events.beginCount > 0)
		{
			fromEvent = events.beginEvents[0].contactId;
		}
	}
	cr_assert(tbContact_IsValid(fromEvent), "the begin event's contact id is valid while the box rests");
	tbContactData data[4];
	cr_assert_geq(tbBody_GetContactCapacity(box), 1);
	cr_assert_eq(tbBody_GetContactData(box, data, 4), 1);
	cr_assert(TB_ID_EQUALS(data[0].contactId, fromEvent) && data[0].contactId.generation == fromEvent.generation);
	cr_assert(SamePair(data[0].shapeIdA, data[0].shapeIdB, ground, boxShape));
	const tbManifold* m = &data[0].manifold;
	cr_assert_eq(m->pointCount, 2);
	cr_assert(fabsf(fabsf(m->normal.y) - 1.0f) < 1e-4f);
	float impulse = 0.0f;
	for (int i = 0; i < 2; ++i)
	{
		cr_assert(fabsf(m->points[i].point.y) < 0.01f, "point y %g", (double)m->points[i].point.y);
		cr_assert(fabsf(fabsf(m->points[i].point.x) - 0.5f) < 0.01f, "point x %g", (double)m->points[i].point.x);
		impulse += m->points[i].normalImpulse;
	}
	float weight = 1.0f * GRAVITY * TIME_STEP / SUB_STEPS;
	cr_assert(fabsf(impulse - weight) < 0.05f * weight, "normal impulse %g N·s, weight over a sub-step %g", (double)impulse,
			  (double)weight);
	tbContactData viaShape[4];
	cr_assert_eq(tbShape_GetContactData(boxShape, viaShape, 4), 1);
	cr_assert_eq(tbShape_GetContactData(ground, viaShape, 4), 1, "the ground's shape sees the same contact");
	tbContactData viaId = tbContact_GetData(fromEvent);
	cr_assert_eq(viaId.manifold.pointCount, 2);
	cr_assert_eq(tbBody_GetContactData(box, data, 0), 0, "capacity 0 writes nothing");

	cr_assert(tbBody_SetTransform(box, (tbVec2){0.0f, 10.0f}, tbRot_identity));
	tbWorld_Step(world, TIME_STEP, SUB_STEPS);
	cr_assert(tbContact_IsValid(fromEvent) == false, "the contact ended: its id is stale");
	cr_assert_eq(tbBody_GetContactData(box, data, 4), 0);
	tbDestroyWorld(world);
}

// Sensor data: a static sensor reports the ball inside it, and nothing once it has fallen out.
Test(events, sensor_data_lists_visitors)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeId sensor = CreateStaticSensor(world);
	tbBodyId ball;
	tbShapeId ballShape = CreateBall(world, (tbVec2){0.0f, 6.0f}, tbVec2_zero, 0.25f, EventDef(), &ball);
	tbShapeId visitors[4];
	int inside = 0;
	for (int step = 0; step < 90; ++step)
	{
		tbWorld_Step(world, TIME_STEP, SUB_STEPS);
		int n = tbShape_GetSensorData(sensor, visitors, 4);
		cr_assert(n <= tbShape_GetSensorCapacity(sensor));
		if (n == 1)
		{
			cr_assert(TB_ID_EQUALS(visitors[0], ballShape));
			inside += 1;
		}
	}
	cr_assert_gt(inside, 0, "the ball was never reported inside");
	cr_assert_eq(tbShape_GetSensorData(sensor, visitors, 4), 0, "the ball has left");
	cr_assert_eq(tbShape_GetSensorData(ballShape, visitors, 4), 0, "a non-sensor has no visitors");
	tbDestroyWorld(world);
}

/// Begin events of a world where a 1 m box lands on the ground from 0.5 m, counted over 1 s.
static int CountLandingBegins(bool groundEvents, bool boxEvents)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
	tbShapeDef groundDef = tbDefaultShapeDef();
	groundDef.enableContactEvents = groundEvents;
	CreateGround(world, (tbVec2){0.0f, -1.0f}, 20.0f, 1.0f, &groundDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){0.0f, 1.0f};
	tbBodyId box = tbCreateBody(world, &bodyDef);
	tbShapeDef boxDef = tbDefaultShapeDef();
	boxDef.enableContactEvents = boxEvents;
	tbPolygon square = tbMakeSquare(0.5f);
	tbCreatePolygonShape(box, &boxDef, &square);
	int begins = 0;
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
		begins += tbWorld_GetContactEvents(world).beginCount;
	}
	tbDestroyWorld(world);
	return begins;
}

// Box2D v3.2's rule: a contact reports begin and end when either of its shapes enables contact
// events, and shapes default to off. One landing is one begin event whichever shape asks.
Test(events, contact_events_when_either_shape_enables_them)
{
	cr_expect_eq(CountLandingBegins(false, false), 0, "the defaults report nothing");
	cr_expect_eq(CountLandingBegins(true, false), 1);
	cr_expect_eq(CountLandingBegins(false, true), 1);
	cr_expect_eq(CountLandingBegins(true, true), 1);
	tbShapeDef def = tbDefaultShapeDef();
	cr_expect(def.enableContactEvents == false && def.enableSensorEvents == false && def.enableHitEvents == false);
}

// Two sensors that overlap see each other (Box2D v3.2 reports a sensor visiting a sensor): a
// sensor disc falls through a static sensor box; each reports the other once on the way in and
// once on the way out. With sensor events off on either shape, nothing is reported.
Test(events, overlapping_sensors_see_each_other)
{
	for (int k = 0; k < 2; ++k)
	{
		tbWorldId world = CreateWorld((tbVec2){0.0f, -GRAVITY});
		tbBodyDef groundDef = tbDefaultBodyDef();
		tbBodyId ground = tbCreateBody(world, &groundDef);
		tbShapeDef zoneDef = tbDefaultShapeDef();
		zoneDef.isSensor = true;
		zoneDef.enableSensorEvents = true;
		tbPolygon zone = tbMakeBox(2.0f, 0.5f);
		tbShapeId zoneShape = tbCreatePolygonShape(ground, &zoneDef, &zone);
		tbBodyDef bodyDef = tbDefaultBodyDef();
		bodyDef.type = tb_dynamicBody;
		bodyDef.position = (tbVec2){0.0f, 3.0f};
		tbBodyId ball = tbCreateBody(world, &bodyDef);
		tbShapeDef ballDef = tbDefaultShapeDef();
		ballDef.isSensor = true;
		ballDef.enableSensorEvents = k == 0;
		tbCircle circle = {{0.0f, 0.0f}, 0.25f};
		tbShapeId ballShape = tbCreateCircleShape(ball, &ballDef, &circle);
		int zoneSeesBall = 0, ballSeesZone = 0, ends = 0;
		for (int i = 0; i < 120; ++i) // 2 s: it falls 20 m, through the zone and out below
		{
			tbWorld_Step(world, 1.0f / 60.0f, 4);
			tbSensorEvents e = tbWorld_GetSensorEvents(world);
			for (int j = 0; j < e.beginCount; ++j)
			{
				zoneSeesBall += TB_ID_EQUALS(e.beginEvents[j].sensorShapeId, zoneShape) &&
										TB_ID_EQUALS(e.beginEvents[j].visitorShapeId, ballShape)
									? 1
									: 0;
				ballSeesZone += TB_ID_EQUALS(e.beginEvents[j].sensorShapeId, ballShape) &&
										TB_ID_EQUALS(e.beginEvents[j].visitorShapeId, zoneShape)
									? 1
									: 0;
			}
			ends += e.endCount;
		}
		cr_expect_eq(zoneSeesBall, k == 0 ? 1 : 0, "events %s", k == 0 ? "on" : "off");
		cr_expect_eq(ballSeesZone, k == 0 ? 1 : 0);
		cr_expect_eq(ends, k == 0 ? 2 : 0);
		tbDestroyWorld(world);
	}
}
