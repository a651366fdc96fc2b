// Surface materials (tbSurfaceMaterial: tangent speed, rolling resistance, user material, custom
// colour, changes at run time) and motion locks (tbMotionLocks), each against its closed form.
#include "tumble/tumble.h"

#include <criterion/criterion.h>

#include "error_recorder.h"
#include "test_helpers.h"

#include <math.h>
#include <string.h>

static const float s_dt = 1.0f / 60.0f;

/// A static box of half extents (50, 0.5) whose top face is y = 0, with the given material.
static tbShapeId MakeGround(tbWorldId world, const tbSurfaceMaterial* material)
{
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material = *material;
	return CreateGround(world, (tbVec2){0.0f, -0.5f}, 50.0f, 0.5f, &shapeDef);
}

// A conveyor belt: friction drives what rests on the belt to the belt's tangent speed. The
// closed form is the belt speed itself; the bound, 1 %, is the (measured: exactly 2 m/s
// after 2 s: static friction holds the box at the belt's speed).
Test(materials, box_on_a_conveyor_reaches_the_belt_speed)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbSurfaceMaterial belt = tbDefaultSurfaceMaterial();
	belt.tangentSpeed = 2.0f;
	MakeGround(world, &belt);
	tbBodyId box = CreateBox(world, tb_dynamicBody, (tbVec2){0.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
	StepWorld(world, 120, s_dt, 4);
	tbVec2 v = tbBody_GetLinearVelocity(box);
	cr_expect(fabsf(v.x - 2.0f) <= 0.02f, "box moves at %.4f m/s on a 2 m/s belt", (double)v.x);
	cr_expect(fabsf(v.y) <= 0.01f, "vertical speed %.4f", (double)v.y);
	tbDestroyWorld(world);
}

// The same belt, reversed at run time through tbShape_SetSurfaceMaterial: the box follows.
Test(materials, changing_the_belt_at_run_time_reaches_existing_contacts)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbSurfaceMaterial belt = tbDefaultSurfaceMaterial();
	belt.tangentSpeed = 2.0f;
	tbShapeId beltShape = MakeGround(world, &belt);
	tbBodyId box = CreateBox(world, tb_dynamicBody, (tbVec2){0.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
	StepWorld(world, 60, s_dt, 4);
	belt.tangentSpeed = -1.0f;
	cr_assert(tbShape_SetSurfaceMaterial(beltShape, &belt));
	StepWorld(world, 120, s_dt, 4);
	float vx = tbBody_GetLinearVelocity(box).x;
	cr_expect(fabsf(vx + 1.0f) <= 0.01f, "box moves at %.4f m/s on a belt reversed to -1 m/s", (double)vx);
	cr_expect_eq(tbShape_GetSurfaceMaterial(beltShape).tangentSpeed, -1.0f);

	// Friction set to 0 on the belt: nothing drives the box any more, it keeps its speed.
	cr_assert(tbShape_SetFriction(beltShape, 0.0f));
	StepWorld(world, 60, s_dt, 4);
	float coast = tbBody_GetLinearVelocity(box).x;
	cr_expect(fabsf(coast - vx) <= 1e-3f, "frictionless belt: %.4f m/s, was %.4f", (double)coast, (double)vx);
	tbDestroyWorld(world);
}

// Restitution given to a ball resting on the ground, whose contact exists, makes it bounce: the
// contact's material, and the solver key built from it, must follow the change (contact.c keeps
// the material as flag bits). Sent down at 5 m/s with e = 1, the ball leaves at 5 m/s less the
// gravity of the step of the bounce, g·dt = 0.16 m/s (restitution targets the approach speed at the
// start of that step): 4.84 m/s, asserted as at least 4.75 m/s; and not faster than it arrived but
// for the push out of its overlap (bounded at 0.05 m/s). Left with its material bits stale (the
// restitution of 0 it was created with), it leaves at 0 m/s and the test fails.
Test(materials, restitution_set_on_an_existing_contact_bounces)
{
	tbWorldId world = CreateWorld((tbVec2){0.0f, -9.8f});
	tbSurfaceMaterial ground = tbDefaultSurfaceMaterial();
	MakeGround(world, &ground);
	tbBodyId ball;
	tbShapeId ballShape = CreateBall(world, (tbVec2){0.0f, 0.25f}, (tbVec2){0.0f, 0.0f}, 0.25f, NULL, &ball);
	StepWorld(world, 30, s_dt, 4);
	cr_assert(tbShape_GetContactCapacity(ballShape) > 0, "the ball rests on the ground");
	cr_assert(tbShape_SetRestitution(ballShape, 1.0f));
	tbBody_SetLinearVelocity(ball, (tbVec2){0.0f, -5.0f});
	float fastestUp = 0.0f;
	for (int i = 0; i < 30; ++i)
	{
		StepWorld(world, 1, s_dt, 4);
		fastestUp = fmaxf(fastestUp, tbBody_GetLinearVelocity(ball).y);
	}
	cr_expect(fastestUp >= 4.75f && fastestUp <= 5.05f, "leaves at %.3f m/s after arriving at 5 m/s",
			  (double)fastestUp);
	tbDestroyWorld(world);
}

// A belt started under a box that has rested on it long enough for the steps to be steady (the
// solver then takes the last step's contact keys instead of rebuilding them, while none changes):
// the started belt changes the contact's key (a tangent speed sends it to the scalar solver, which
// carries it), so the kept keys must not be taken. Sleep is off, so the box stays awake and the
// steps stay steady until the belt starts. Closed form and bound as for the belt that always ran:
// the belt speed, 1 %.
Test(materials, a_belt_started_under_a_resting_box_drives_it)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.enableSleep = false;
	tbWorldId world = tbCreateWorld(&worldDef);
	tbSurfaceMaterial belt = tbDefaultSurfaceMaterial();
	tbShapeId beltShape = MakeGround(world, &belt);
	tbBodyId box = CreateBox(world, tb_dynamicBody, (tbVec2){0.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
	StepWorld(world, 120, s_dt, 4);
	cr_assert(fabsf(tbBody_GetLinearVelocity(box).x) <= 1e-4f, "the box rests before the belt starts");
	belt.tangentSpeed = 2.0f;
	cr_assert(tbShape_SetSurfaceMaterial(beltShape, &belt));
	StepWorld(world, 120, s_dt, 4);
	float vx = tbBody_GetLinearVelocity(box).x;
	cr_expect(fabsf(vx - 2.0f) <= 0.02f, "box moves at %.4f m/s on a belt started at 2 m/s", (double)vx);
	tbDestroyWorld(world);
}

// Rolling resistance: a disc of radius r rolling without slipping on level ground feels a torque
// up to c·r·N against its rolling (c the larger coefficient, r the larger rounding radius, N the
// normal force). Energy: d/dt(½mv² + ½Iω²) = −c·r·m·g·ω with ω = v/r and I = ½mr², so the disc
// decelerates at a = c·g/(1 + I/(m·r²)) = (2/3)·c·g. The tolerance, 1 %, covers the sub-step
// discretisation of the soft contact (measured: 1.3362 against 1.3333 m/s², 0.2 %; the average is
// taken after 0.5 s, once the contact has settled).
/// Deceleration of a rolling disc with rolling resistance c under a world definition (m/s²), and
/// its rolling mismatch |v + ω·r| at the end of the measurement.
static float MeasureRollingDeceleration(tbWorldDef worldDef, float c, float* slip, float* finalSpeed)
{
	tbWorldId world = tbCreateWorld(&worldDef);
	tbSurfaceMaterial ground = tbDefaultSurfaceMaterial();
	MakeGround(world, &ground);
	const float radius = 0.5f, v0 = 4.0f;
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){-40.0f, radius};
	bodyDef.linearVelocity = (tbVec2){v0, 0.0f};
	bodyDef.angularVelocity = -v0 / radius; // rolling already
	tbBodyId ball = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material.rollingResistance = c;
	tbCircle circle = {tbVec2_zero, radius};
	tbShapeId ballShape = tbCreateCircleShape(ball, &shapeDef, &circle);
	cr_assert_eq(tbShape_GetSurfaceMaterial(ballShape).rollingResistance, c);
	StepWorld(world, 30, s_dt, 4);
	float v1 = tbBody_GetLinearVelocity(ball).x;
	StepWorld(world, 60, s_dt, 4);
	float v2 = tbBody_GetLinearVelocity(ball).x;
	*slip = fabsf(v2 + tbBody_GetAngularVelocity(ball) * radius);
	StepWorld(world, 240, s_dt, 4);
	*finalSpeed = fabsf(tbBody_GetLinearVelocity(ball).x);
	tbDestroyWorld(world);
	return (v1 - v2) / (60.0f * s_dt);
}

// Rolling resistance: a disc of radius r rolling without slipping on level ground feels a torque
// up to c·r·N against its rolling (c the larger coefficient, r the larger rounding radius, N the
// normal force). Energy: d/dt(½mv² + ½Iω²) = −c·r·m·g·ω with ω = v/r and I = ½mr², so the disc
// decelerates at a = c·g/(1 + I/(m·r²)) = (2/3)·c·g, then stops and stays stopped. Under every
// solver method (the wide soft step solves the row in its lanes, the scalar soft step, Baumgarte
// and NGS one contact at a time, with the same arithmetic). The tolerance, 1 %, covers the sub-step
// discretisation of the contact (measured: the soft step 1.3362 against 1.3333 m/s², 0.2 %; the
// average is taken after 0.5 s, once the contact has settled).
Test(materials, rolling_resistance_decelerates_a_rolling_disc_at_the_closed_form_rate)
{
	const float c = 0.2f, expected = 2.0f / 3.0f * c * 10.0f;
	const char* names[4] = {"soft step", "soft step, scalar solver", "Baumgarte", "NGS"};
	for (int method = 0; method < 4; ++method)
	{
		tbWorldDef worldDef = tbDefaultWorldDef();
		worldDef.enableWideSolver = method != 1;
		worldDef.solver = method == 2 ? tb_solverBaumgarte : method == 3 ? tb_solverNGS : tb_solverSoft;
		float slip, finalSpeed;
		float measured = MeasureRollingDeceleration(worldDef, c, &slip, &finalSpeed);
		cr_expect(fabsf(measured - expected) <= 0.01f * expected, "%s: deceleration %.4f m/s², closed form %.4f",
				  names[method], (double)measured, (double)expected);
		cr_expect(slip <= 0.01f, "%s: |v + ω·r| = %.4f m/s", names[method], (double)slip);
		cr_expect(finalSpeed <= 1e-3f, "%s: still rolling at %.4f m/s", names[method], (double)finalSpeed);
	}

	// Without rolling resistance the same disc keeps its speed (no other loss on level ground).
	float slip, finalSpeed;
	float none = MeasureRollingDeceleration(tbDefaultWorldDef(), 0.0f, &slip, &finalSpeed);
	cr_expect(fabsf(none) <= 1e-3f, "free disc decelerates at %.4f m/s²", (double)none);
}

// Motion locks: a locked axis keeps its coordinate, whatever gravity and contacts do.
Test(materials, motion_locks_hold_their_axes)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbSurfaceMaterial ground = tbDefaultSurfaceMaterial();
	MakeGround(world, &ground);

	// x locked, thrown sideways: falls straight down onto the ground, x unchanged to the bit.
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){1.0f, 5.0f};
	bodyDef.linearVelocity = (tbVec2){3.0f, 0.0f};
	bodyDef.motionLocks.linearX = true;
	tbBodyId lockedX = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbCreatePolygonShape(lockedX, &shapeDef, &box);

	// y locked: floats at its height and slides at its speed (no gravity along y, no contact).
	bodyDef.position = (tbVec2){-10.0f, 5.0f};
	bodyDef.motionLocks = (tbMotionLocks){false, true, false};
	tbBodyId lockedY = tbCreateBody(world, &bodyDef);
	tbCreatePolygonShape(lockedY, &shapeDef, &box);

	// rotation locked: spun, it never turns.
	bodyDef.position = (tbVec2){10.0f, 5.0f};
	bodyDef.linearVelocity = tbVec2_zero;
	bodyDef.angularVelocity = 5.0f;
	bodyDef.motionLocks = (tbMotionLocks){false, false, true};
	tbBodyId lockedZ = tbCreateBody(world, &bodyDef);
	tbCreatePolygonShape(lockedZ, &shapeDef, &box);

	StepWorld(world, 60, s_dt, 4);
	tbVec2 px = tbBody_GetPosition(lockedX);
	cr_expect_eq(px.x, 1.0f, "x-locked body at x = %.7f", (double)px.x);
	cr_expect_eq(tbBody_GetLinearVelocity(lockedX).x, 0.0f);
	// Free fall for 1 s from 5 m would end below the ground: it rests on it (centre at 0.5 m).
	cr_expect(fabsf(px.y - 0.5f) <= 0.02f, "x-locked body rests at y = %.4f", (double)px.y);

	tbVec2 py = tbBody_GetPosition(lockedY);
	cr_expect_eq(py.y, 5.0f, "y-locked body at y = %.7f", (double)py.y);
	cr_expect(fabsf(py.x - (-10.0f + 3.0f * 60.0f * s_dt)) <= 1e-3f, "y-locked body at x = %.4f", (double)py.x);

	cr_expect_eq(tbRot_GetAngle(tbBody_GetRotation(lockedZ)), 0.0f);
	cr_expect_eq(tbBody_GetAngularVelocity(lockedZ), 0.0f);
	cr_expect(tbBody_GetMotionLocks(lockedZ).angularZ);

	// Unlocking y at run time lets it fall; locking x stops its slide.
	tbBody_SetMotionLocks(lockedY, (tbMotionLocks){true, false, false});
	tbMotionLocks locks = tbBody_GetMotionLocks(lockedY);
	cr_expect(locks.linearX && !locks.linearY && !locks.angularZ);
	float x = tbBody_GetPosition(lockedY).x;
	StepWorld(world, 30, s_dt, 4);
	cr_expect_eq(tbBody_GetPosition(lockedY).x, x);
	cr_expect(tbBody_GetPosition(lockedY).y < 4.0f, "unlocked in y, it fell to %.3f", (double)tbBody_GetPosition(lockedY).y);
	tbDestroyWorld(world);
}

static uint64_t s_seenMaterials[2];

static float RecordMaterials(float frictionA, uint64_t materialA, float frictionB, uint64_t materialB)
{
	s_seenMaterials[0] = materialA < materialB ? materialA : materialB;
	s_seenMaterials[1] = materialA < materialB ? materialB : materialA;
	return frictionA < frictionB ? frictionA : frictionB;
}

static uint32_t s_drawnColor;

static void RecordPolygonColor(tbWorldTransform transform, const tbVec2* vertices, int vertexCount, float radius,
							   tbHexColor color, void* context)
{
	(void)transform;
	(void)vertices;
	(void)vertexCount;
	(void)radius;
	(void)context;
	s_drawnColor = color;
}

// 64-bit user material ids reach the mixing callbacks; a custom colour reaches the debug draw.
Test(materials, user_material_ids_and_custom_colours)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.frictionCallback = RecordMaterials;
	tbWorldId world = tbCreateWorld(&worldDef);
	tbSurfaceMaterial ground = tbDefaultSurfaceMaterial();
	ground.userMaterialId = 0x100000000ull; // above 32 bits
	tbShapeId groundShape = MakeGround(world, &ground);
	tbBodyId box = CreateBox(world, tb_dynamicBody, (tbVec2){0.0f, 0.5f}, 0.5f, 0.5f, 1.0f);
	tbShapeId boxShape;
	cr_assert_eq(tbBody_GetShapes(box, &boxShape, 1), 1);
	tbShape_SetUserMaterial(boxShape, 7u);
	cr_expect_eq(tbShape_GetUserMaterial(boxShape), 7u);
	cr_expect_eq(tbShape_GetUserMaterial(groundShape), 0x100000000ull);
	StepWorld(world, 2, s_dt, 4);
	cr_expect_eq(s_seenMaterials[0], 7u);
	cr_expect_eq(s_seenMaterials[1], 0x100000000ull);

	tbSurfaceMaterial painted = tbShape_GetSurfaceMaterial(boxShape);
	painted.customColor = 0x123456u;
	cr_assert(tbShape_SetSurfaceMaterial(boxShape, &painted));
	tbDebugDraw draw = tbDefaultDebugDraw();
	draw.DrawSolidPolygonFcn = RecordPolygonColor;
	draw.drawShapes = true;
	tbShape_SetSurfaceMaterial(groundShape, &ground); // the ground draws first, in its default colour
	s_drawnColor = 0u;
	tbWorld_Draw(world, &draw);
	cr_expect_eq(s_drawnColor, 0x123456u, "last polygon drawn in %06x", s_drawnColor);
	tbDestroyWorld(world);
}

// Bad materials are refused with a message naming the field, and change nothing.
Test(materials, bad_materials_and_locks_are_refused_without_change, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbSurfaceMaterial ground = tbDefaultSurfaceMaterial();
	tbShapeId shape = MakeGround(world, &ground);

	const char* fields[4] = {"friction", "restitution", "rollingResistance", "tangentSpeed"};
	for (int i = 0; i < 4; ++i)
	{
		for (int k = 0; k < 2; ++k)
		{
			tbSurfaceMaterial bad = tbDefaultSurfaceMaterial();
			float value = k == 0 ? NAN : (i == 3 ? INFINITY : -1.0f);
			float* field = i == 0 ? &bad.friction : i == 1 ? &bad.restitution : i == 2 ? &bad.rollingResistance : &bad.tangentSpeed;
			*field = value;
			int before = s_errors;
			cr_expect_not(tbShape_SetSurfaceMaterial(shape, &bad));
			ExpectError(before, "tbShape_SetSurfaceMaterial", fields[i]);
			tbSurfaceMaterial now = tbShape_GetSurfaceMaterial(shape);
			cr_expect(memcmp(&now, &ground, sizeof(now)) == 0, "material changed by a refused call");

			// The same material in a shape definition: no shape is created.
			tbBodyDef bodyDef = tbDefaultBodyDef();
			tbBodyId body = tbCreateBody(world, &bodyDef);
			tbShapeDef shapeDef = tbDefaultShapeDef();
			shapeDef.material = bad;
			tbCircle circle = {tbVec2_zero, 0.5f};
			before = s_errors;
			tbShapeId none = tbCreateCircleShape(body, &shapeDef, &circle);
			cr_expect_not(tbShape_IsValid(none));
			ExpectError(before, "tbCreateCircleShape", fields[i]);
			cr_expect_eq(tbBody_GetShapeCount(body), 0);
		}
	}
	int before = s_errors;
	cr_expect_not(tbShape_SetSurfaceMaterial(shape, NULL));
	ExpectError(before, "tbShape_SetSurfaceMaterial", "material");
	before = s_errors;
	cr_expect_not(tbShape_SetFriction(shape, -0.5f));
	ExpectError(before, "tbShape_SetFriction", "friction");
	cr_expect_eq(tbShape_GetFriction(shape), ground.friction);

	// Stale ids.
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbDestroyBody(body);
	before = s_errors;
	tbBody_SetMotionLocks(body, (tbMotionLocks){true, true, true});
	ExpectError(before, "tbBody_SetMotionLocks", "bodyId");
	before = s_errors;
	tbMotionLocks none = tbBody_GetMotionLocks(body);
	cr_expect(!none.linearX && !none.linearY && !none.angularZ);
	cr_expect_eq(s_errors, before + 1);
	tbDestroyWorld(world);
}
