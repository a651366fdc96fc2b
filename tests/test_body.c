// Bodies at run time: mass data set by hand and from the shapes, names, and the response to an
// impulse that follows from the mass data (Δv = J/m, Δω = (r × J)/I).
#include <criterion/criterion.h>

#include "tumble/tumble.h"
#include "world/world.h"

#include "error_recorder.h"

#include <math.h>
#include <string.h>

// A unit box (1 kg, I = 1/6 kg·m²) given mass 4 kg, inertia 2 kg·m² and centre (0.5, 0) by hand:
// an impulse (0, 4) N·s at the origin gives v = (0, 1) and ω = (r × J)/I with r = (−0.5, 0) from
// the centre of mass, (−0.5·4)/2 = −1 rad/s. ApplyMassFromShapes puts back 1 kg at the origin.
// Bad mass data is refused with the body unchanged.
Test(body, mass_data_by_hand_and_from_shapes, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = tbMakeVec2(0.0f, 0.0f);
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeSquare(0.5f);
	tbCreatePolygonShape(body, &shapeDef, &box);
	cr_assert_float_eq(tbBody_GetMass(body), 1.0f, 1e-6f);

	tbMassData md = {4.0f, {0.5f, 0.0f}, 2.0f};
	cr_assert(tbBody_SetMassData(body, md));
	tbMassData got = tbBody_GetMassData(body);
	cr_assert(got.mass == 4.0f && got.rotationalInertia == 2.0f && got.center.x == 0.5f && got.center.y == 0.0f);
	cr_assert(tbBody_ApplyLinearImpulse(body, tbMakeVec2(0.0f, 4.0f), tbMakeVec2(0.0f, 0.0f), true));
	cr_assert_float_eq(tbBody_GetLinearVelocity(body).y, 1.0f, 1e-6f);
	cr_assert_float_eq(tbBody_GetAngularVelocity(body), -1.0f, 1e-6f);

	int before = s_errors;
	tbMassData bad = {-1.0f, {0.0f, 0.0f}, 1.0f};
	cr_assert(tbBody_SetMassData(body, bad) == false);
	ExpectError(before, "tbBody_SetMassData", "massData.mass");
	cr_assert_float_eq(tbBody_GetMass(body), 4.0f, 0.0f);

	tbBody_ApplyMassFromShapes(body);
	got = tbBody_GetMassData(body);
	cr_assert_float_eq(got.mass, 1.0f, 1e-6f);
	cr_assert_float_eq(got.rotationalInertia, 1.0f / 6.0f, 1e-6f);
	cr_assert_float_eq(got.center.x, 0.0f, 1e-6f);

	tbBody_SetName(body, "crate");
	cr_assert_str_eq(tbBody_GetName(body), "crate");
	tbDestroyWorld(world);
}

static bool CountShapes(tbShapeId shapeId, void* context)
{
	(void)shapeId;
	*(int*)context += 1;
	return true;
}

// A disabled body leaves the simulation: frozen where it was (a box held 2 m above the ground does
// not fall), invisible to ray casts and overlap queries, woken by nothing; enabled again it falls
// and comes to rest on the ground at its half height, 0.5 m (within the soft contact's 0.01 m).
Test(body, disabled_body_is_out_of_the_simulation)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef groundDef = tbDefaultBodyDef();
	groundDef.position = tbMakeVec2(0.0f, -1.0f);
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon groundBox = tbMakeBox(20.0f, 1.0f);
	tbCreatePolygonShape(ground, &shapeDef, &groundBox);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbMakeVec2(0.0f, 2.5f);
	tbBodyId box = tbCreateBody(world, &bodyDef);
	tbPolygon square = tbMakeSquare(0.5f);
	tbCreatePolygonShape(box, &shapeDef, &square);

	tbBody_Disable(box);
	cr_assert(tbBody_IsEnabled(box) == false);
	for (int step = 0; step < 60; ++step)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	cr_assert_eq(tbBody_GetPosition(box).y, 2.5f, "a disabled body does not move");
	tbRayResult ray = tbWorld_CastRayClosest(world, tbMakeVec2(0.0f, 5.0f), tbMakeVec2(0.0f, -10.0f), tbDefaultQueryFilter());
	cr_assert(ray.hit && fabsf(ray.point.y) < 1e-5f, "the ray passes the disabled box and hits the ground at y %g",
			  (double)ray.point.y);
	int found = 0;
	tbAABB around = {{-1.0f, 1.5f}, {1.0f, 3.5f}};
	cr_assert(tbWorld_OverlapAABB(world, tbPos_zero, around, tbDefaultQueryFilter(), CountShapes, &found).leafVisits == 0);
	cr_assert_eq(found, 0);
	tbBody_SetAwake(box, true);
	cr_assert(tbBody_IsAwake(box) == false, "nothing wakes a disabled body");

	tbBody_Enable(box);
	cr_assert(tbBody_IsEnabled(box) && tbBody_IsAwake(box));
	for (int step = 0; step < 120; ++step)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	cr_assert(fabsf(tbBody_GetPosition(box).y - 0.5f) < 0.01f, "rests at y %g", (double)tbBody_GetPosition(box).y);
	tbDestroyWorld(world);
}

// Box2D v3's smaller body, shape and world accessors. A body at the origin turning at ω = 2 rad/s
// and moving at (1, 0) m/s: the point (0, 1) moves at v + ω × r = (1, 0) + (−2, 0) = (−1, 0).
// Clearing a force before the step leaves the velocity as it was (no gravity); the sleep
// threshold is read back and a negative one refused; the world's thresholds read back.
Test(body, v3_accessors, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = tbMakeVec2(0.0f, 0.0f);
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.linearVelocity = tbMakeVec2(1.0f, 0.0f);
	bodyDef.angularVelocity = 2.0f;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbShapeId shape = tbCreateCircleShape(body, &shapeDef, &circle);

	tbVec2 v = tbBody_GetWorldPointVelocity(body, tbMakeVec2(0.0f, 1.0f));
	cr_assert_float_eq(v.x, -1.0f, 1e-6f);
	cr_assert_float_eq(v.y, 0.0f, 1e-6f);
	v = tbBody_GetLocalPointVelocity(body, tbMakeVec2(0.0f, 1.0f));
	cr_assert_float_eq(v.x, -1.0f, 1e-6f);

	tbBody_ApplyForce(body, tbMakeVec2(100.0f, 0.0f), tbBody_GetPosition(body), true);
	tbBody_ClearForces(body);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	cr_assert_float_eq(tbBody_GetLinearVelocity(body).x, 1.0f, 1e-6f);

	cr_assert(tbBody_IsSleepEnabled(body));
	cr_assert(tbBody_SetSleepThreshold(body, 0.2f));
	cr_assert_float_eq(tbBody_GetSleepThreshold(body), 0.2f, 0.0f);
	int before = s_errors;
	cr_assert(tbBody_SetSleepThreshold(body, -1.0f) == false);
	ExpectError(before, "tbBody_SetSleepThreshold", "sleepThreshold");
	cr_assert_float_eq(tbBody_GetSleepThreshold(body), 0.2f, 0.0f);

	cr_assert(tbWorld_SetRestitutionThreshold(world, 2.5f));
	cr_assert_float_eq(tbWorld_GetRestitutionThreshold(world), 2.5f, 0.0f);
	cr_assert(tbWorld_SetHitEventThreshold(world, 0.5f));
	cr_assert_float_eq(tbWorld_GetHitEventThreshold(world), 0.5f, 0.0f);
	tbWorldId owner = tbShape_GetWorld(shape);
	cr_assert(owner.index1 == world.index1 && owner.generation == world.generation);
	tbDestroyWorld(world);
}

// Bodies leaving the awake set leave holes in the awake list that the next step (or the next body
// to join) closes, keeping the order (body.c). Counts must be right in between, and the order of
// removals must not matter: two worlds that destroy the same bodies in opposite orders step
// bit-identically (the solver order follows the awake list).
static tbWorldId MakeRowOfBoxes(tbBodyId* bodies, int count)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.enableSleep = false; // only the removals below change the awake set
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon floor = tbMakeBox(50.0f, 0.5f);
	tbCreatePolygonShape(ground, &shapeDef, &floor);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	for (int i = 0; i < count; ++i)
	{
		tbBodyDef def = tbDefaultBodyDef();
		def.type = tb_dynamicBody;
		def.position = tbMakeVec2(-20.0f + 1.5f * (float)i, 1.0f + 0.3f * (float)(i % 3));
		bodies[i] = tbCreateBody(world, &def);
		tbCreatePolygonShape(bodies[i], &shapeDef, &box);
	}
	return world;
}

Test(body, awake_list_holes_keep_counts_and_order)
{
	tbBodyId a[10], b[10];
	tbWorldId worldA = MakeRowOfBoxes(a, 10);
	tbWorldId worldB = MakeRowOfBoxes(b, 10);
	tbDestroyBody(a[2]);
	tbDestroyBody(a[5]);
	tbBody_SetAwake(a[7], false);
	tbDestroyBody(b[5]);
	tbBody_SetAwake(b[7], false);
	tbDestroyBody(b[2]);
	cr_expect_eq(tbWorld_GetAwakeBodyCount(worldA), 7);
	cr_expect_eq(tbWorld_GetCounters(worldA).awakeBodyCount, 7);
	tbBody_SetAwake(a[7], true); // joins after the holes are closed
	tbBody_SetAwake(b[7], true);
	cr_expect_eq(tbWorld_GetAwakeBodyCount(worldA), 8);
	for (int step = 0; step < 30; ++step)
	{
		tbWorld_Step(worldA, 1.0f / 60.0f, 4);
		tbWorld_Step(worldB, 1.0f / 60.0f, 4);
	}
	cr_expect_eq(tbWorld_GetAwakeBodyCount(worldA), 8);
	for (int i = 0; i < 10; ++i)
	{
		if (i == 2 || i == 5)
		{
			cr_expect(tbBody_IsValid(a[i]) == false && tbBody_IsValid(b[i]) == false);
			continue;
		}
		tbVec2 pa = tbBody_GetPosition(a[i]), pb = tbBody_GetPosition(b[i]);
		cr_expect(pa.x == pb.x && pa.y == pb.y, "body %d: (%g, %g) and (%g, %g)", i, (double)pa.x, (double)pa.y,
				  (double)pb.x, (double)pb.y);
		cr_expect(tbBody_IsAwake(a[i]));
	}
	tbDestroyWorld(worldA);
	tbDestroyWorld(worldB);
}

// tbBody_WakeTouching wakes the bodies this one has contacts with, not itself and not the rest of
// the pile: a stack of three asleep on the ground; waking the middle box's neighbours wakes the
// bottom and top boxes (its contacts), the middle one stays asleep until the next step's island
// stage (which wakes what touches an awake body), and a box far away sleeps on.
Test(body, wake_touching_wakes_the_contact_partners, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon floor = tbMakeBox(50.0f, 0.5f);
	tbCreatePolygonShape(ground, &shapeDef, &floor);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbBodyId stack[3], far;
	for (int i = 0; i < 3; ++i)
	{
		tbBodyDef def = tbDefaultBodyDef();
		def.type = tb_dynamicBody;
		def.position = tbMakeVec2(0.0f, 1.0f + (float)i);
		stack[i] = tbCreateBody(world, &def);
		tbCreatePolygonShape(stack[i], &shapeDef, &box);
	}
	tbBodyDef farDef = tbDefaultBodyDef();
	farDef.type = tb_dynamicBody;
	farDef.position = tbMakeVec2(20.0f, 1.0f);
	far = tbCreateBody(world, &farDef);
	tbCreatePolygonShape(far, &shapeDef, &box);
	for (int i = 0; i < 300 && (tbBody_IsAwake(stack[1]) || tbBody_IsAwake(far)); ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	cr_assert(tbBody_IsAwake(stack[0]) == false && tbBody_IsAwake(stack[1]) == false && tbBody_IsAwake(far) == false,
			  "the boxes fell asleep");
	tbBody_WakeTouching(stack[1]);
	cr_expect(tbBody_IsAwake(stack[0]) && tbBody_IsAwake(stack[2]), "its contact partners woke");
	cr_expect(tbBody_IsAwake(stack[1]) == false, "not the body itself");
	cr_expect(tbBody_IsAwake(far) == false, "nor a body it does not touch");
	tbBodyId gone = stack[2];
	tbDestroyBody(gone);
	int before = s_errors;
	tbBody_WakeTouching(gone);
	cr_expect_eq(s_errors, before + 1, "a stale body id is refused with a message");
	cr_expect(tbBody_IsAwake(far) == false, "and nothing else changes");
	tbDestroyWorld(world);
}

// A destroyed body's id, and its shape's, never pass validation again, however often the slot is
// reused: each destruction advances the slot's 16-bit generation once, and a slot whose next
// generation would come round to its first is retired (never reused), after 65,535 bodies. 70,000
// create/destroy cycles: the first ids stay invalid throughout, ids handed out are never repeated,
// the slot is retired once (the 65,536th body takes a new slot), and the world's memory stays flat.
Test(body, destroyed_ids_never_come_back, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbBodyId firstBody = tbCreateBody(world, &bodyDef);
	tbShapeId firstShape = tbCreateCircleShape(firstBody, &shapeDef, &circle);
	tbDestroyBody(firstBody);
	int64_t bytes = tbGetByteCount();
	int firstSlotUses = 1, newSlots = 0, failedAt = -1;
	// Checked with plain comparisons (an assertion per cycle would cost more than the cycles).
	for (int i = 1; i < 70000 && failedAt < 0; ++i)
	{
		tbBodyId body = tbCreateBody(world, &bodyDef);
		tbShapeId shape = tbCreateCircleShape(body, &shapeDef, &circle);
		bool sameSlot = body.index1 == firstBody.index1;
		firstSlotUses += sameSlot ? 1 : 0;
		newSlots += sameSlot ? 0 : 1;
		bool ok = tbShape_IsValid(shape) && (sameSlot == false || body.generation != firstBody.generation) &&
				  tbBody_IsValid(firstBody) == false && tbShape_IsValid(firstShape) == false &&
				  tbBody_SetLinearVelocity(firstBody, tbMakeVec2(1.0f, 0.0f)) == false;
		failedAt = ok ? -1 : i;
		tbDestroyBody(body);
	}
	cr_assert_eq(failedAt, -1, "cycle %d: a destroyed id matched again", failedAt);
	cr_expect_eq(firstSlotUses, 65535);
	cr_expect_eq(newSlots, 70000 - 65535);
	// The retired slot's neighbour took over: one more body and shape slot (no more arrays).
	cr_expect(tbGetByteCount() - bytes < 4096, "memory grew by %lld bytes", (long long)(tbGetByteCount() - bytes));
	tbDestroyWorld(world);
}

// A rotation given to tbCreateBody or tbBody_SetTransform reads back bit for bit (Box2D v3.2 keeps
// it as given; a rollback that restores bodies through the setters must get what it saved). 1,000
// rotations from tbMakeRot, whose cosine and sine are a unit vector only to rounding.
Test(body, rotations_read_back_exactly, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	int created = 0, set = 0;
	for (int i = 0; i < 1000; ++i)
	{
		tbRot q = tbMakeRot(-3.14f + 0.00628f * (float)i);
		cr_assert(tbBody_SetTransform(body, tbMakeVec2(0.001f * (float)i, 2.0f), q));
		tbRot back = tbBody_GetRotation(body);
		set += memcmp(&back, &q, sizeof(q)) == 0 ? 1 : 0;
		bodyDef.rotation = q;
		tbBodyId other = tbCreateBody(world, &bodyDef);
		tbRot made = tbBody_GetRotation(other);
		created += memcmp(&made, &q, sizeof(q)) == 0 ? 1 : 0;
		tbDestroyBody(other);
	}
	cr_expect_eq(set, 1000);
	cr_expect_eq(created, 1000);
	cr_expect_eq(s_errors, 0);
	tbDestroyWorld(world);
}

// The narrow phase reads two body fields derived from others, kept in the body's first cache line
// (body.h): originExtent, the farthest shape point from the body origin (maxExtent + |localCenter|),
// and solverMoves, whether the solve can change the body's velocity (dynamic with a positive
// inverse mass, or inverse inertia when its rotation is free). Each must equal its definition after
// every call that changes an input, exactly: the narrow phase's results are bit for bit those it
// gave when it computed them per contact.
static void ExpectDerived(tbWorldId worldId, tbBodyId bodyId, const char* after)
{
	const tbWorld* world = tbGetWorldChecked(worldId, "test");
	const tbBody* b = world->bodies + (bodyId.index1 - 1);
	float originExtent = b->maxExtent + tbLength(b->localCenter);
	bool moves = b->type == tb_dynamicBody && (b->invMass > 0.0f || (b->fixedRotation == false && b->invInertia > 0.0f));
	cr_expect(b->originExtent == originExtent, "after %s: originExtent %.9g, defined %.9g", after,
			  (double)b->originExtent, (double)originExtent);
	cr_expect(b->solverMoves == moves, "after %s: solverMoves %d, defined %d", after, b->solverMoves, moves);
}

Test(body, derived_fields_follow_their_inputs, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	ExpectDerived(world, body, "tbCreateBody");
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeOffsetBox(0.5f, 0.25f, tbMakeVec2(1.0f, 0.5f), tbMakeRot(0.3f));
	tbCreatePolygonShape(body, &shapeDef, &box);
	ExpectDerived(world, body, "a shape off the origin");
	cr_assert(tbLength(tbBody_GetLocalCenter(body)) > 1.0f); // the centre's offset counts

	tbBody_SetFixedRotation(body, true);
	ExpectDerived(world, body, "tbBody_SetFixedRotation(true)");
	tbBody_SetFixedRotation(body, false);
	ExpectDerived(world, body, "tbBody_SetFixedRotation(false)");
	tbMassData md = {2.0f, {0.3f, -0.1f}, 0.5f};
	cr_assert(tbBody_SetMassData(body, md));
	ExpectDerived(world, body, "tbBody_SetMassData");
	cr_assert(tbBody_SetType(body, tb_kinematicBody));
	ExpectDerived(world, body, "tbBody_SetType(kinematic)");
	cr_assert(tbBody_SetType(body, tb_staticBody));
	ExpectDerived(world, body, "tbBody_SetType(static)");
	cr_assert(tbBody_SetType(body, tb_dynamicBody));
	ExpectDerived(world, body, "tbBody_SetType(dynamic)");

	// A shape that leaves the mass alone leaves the extents alone too (as Box2D v3.2): the derived
	// field follows the stored extent, not the shapes.
	shapeDef.updateBodyMass = false;
	tbCircle far = {{3.0f, 0.0f}, 0.5f};
	tbCreateCircleShape(body, &shapeDef, &far);
	ExpectDerived(world, body, "a shape with updateBodyMass false");
	tbBody_ApplyMassFromShapes(body);
	ExpectDerived(world, body, "tbBody_ApplyMassFromShapes");
	tbBody_SetMotionLocks(body, (tbMotionLocks){false, false, true});
	ExpectDerived(world, body, "tbBody_SetMotionLocks(angularZ)");

	uint8_t image[1 << 14];
	int size = tbWorld_Snapshot(world, image, (int)sizeof(image));
	cr_assert(size > 0 && size <= (int)sizeof(image));
	tbBody_SetMotionLocks(body, (tbMotionLocks){false, false, false});
	cr_assert(tbWorld_Restore(world, image, size));
	ExpectDerived(world, body, "tbWorld_Restore");
	tbDestroyWorld(world);
}
