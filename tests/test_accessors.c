// Public accessors that no other test exercised: each is checked for what it returns or what it
// does to the motion, with the closed form written beside the expected number.
#include <criterion/criterion.h>

#include "tumble/tumble.h"
#include "test_helpers.h"

#include <math.h>
#include <string.h>

#define TIME_STEP (1.0f / 60.0f)

// A unit box (m = 1 kg, I = m(w² + h²)/12 = 1/6 kg·m²) given torque 1 N·m for one step turns at
// Δω = τ·Δt/I = 6/60 = 0.1 rad/s. Damping, gravity scale, bullet and fixed rotation read back;
// fixed rotation then stops the turning. Vectors turn with the body (90°: local x is world y).
Test(accessors, body_settings_and_vectors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, 0.0f));
	tbBodyId body = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	cr_assert(tbBody_ApplyTorque(body, 1.0f, true));
	tbWorld_Step(world, TIME_STEP, 4);
	cr_assert_float_eq(tbBody_GetAngularVelocity(body), 0.1f, 1e-5f);

	tbBody_SetLinearDamping(body, 0.5f);
	tbBody_SetAngularDamping(body, 0.25f);
	tbBody_SetGravityScale(body, 2.0f);
	tbBody_SetBullet(body, true);
	cr_assert_float_eq(tbBody_GetLinearDamping(body), 0.5f, 0.0f);
	cr_assert_float_eq(tbBody_GetAngularDamping(body), 0.25f, 0.0f);
	cr_assert_float_eq(tbBody_GetGravityScale(body), 2.0f, 0.0f);
	cr_assert(tbBody_IsBullet(body));
	tbBody_SetFixedRotation(body, true);
	tbWorld_Step(world, TIME_STEP, 4);
	cr_assert_float_eq(tbBody_GetAngularVelocity(body), 0.0f, 0.0f);

	int marker = 7;
	tbBody_SetUserData(body, &marker);
	cr_assert(tbBody_GetUserData(body) == &marker);
	tbWorldId owner = tbBody_GetWorld(body);
	cr_assert(owner.index1 == world.index1 && owner.generation == world.generation);

	tbBody_SetTransform(body, tbMakeVec2(0.0f, 0.0f), tbMakeRot(0.5f * 3.14159265f));
	tbVec2 worldX = tbBody_GetWorldVector(body, tbMakeVec2(1.0f, 0.0f));
	cr_assert(fabsf(worldX.x) < 1e-6f && fabsf(worldX.y - 1.0f) < 1e-6f);
	tbVec2 localY = tbBody_GetLocalVector(body, tbMakeVec2(0.0f, 1.0f));
	cr_assert(fabsf(localY.x - 1.0f) < 1e-6f && fabsf(localY.y) < 1e-6f);
	tbDestroyWorld(world);
}

// Shape settings read back; the AABB of a unit box at (2, 3) is [1.5, 2.5] × [2.5, 3.5]; points
// inside and outside test as such; a sensor reports itself; a changed filter is read back.
Test(accessors, shape_settings)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, 0.0f));
	tbBodyId body = CreateBody(world, tb_dynamicBody, tbMakeVec2(2.0f, 3.0f));
	tbShapeId shape = AddBoxShape(body, 0.5f, 0.5f, NULL);
	cr_assert(tbShape_SetFriction(shape, 0.25f));
	cr_assert(tbShape_SetRestitution(shape, 0.75f));
	cr_assert_float_eq(tbShape_GetFriction(shape), 0.25f, 0.0f);
	cr_assert_float_eq(tbShape_GetRestitution(shape), 0.75f, 0.0f);
	cr_assert_float_eq(tbShape_GetDensity(shape), 1.0f, 0.0f);
	int marker = 3;
	tbShape_SetUserData(shape, &marker);
	cr_assert(tbShape_GetUserData(shape) == &marker);
	cr_assert(tbShape_IsSensor(shape) == false);
	tbFilter filter = {0x4, 0x2, -1};
	cr_assert(tbShape_SetFilter(shape, filter));
	tbFilter back = tbShape_GetFilter(shape);
	cr_assert(back.categoryBits == 0x4 && back.maskBits == 0x2 && back.groupIndex == -1);
	tbAABB box = tbShape_GetAABB(shape);
	cr_assert_float_eq(box.lowerBound.x, 1.5f, 1e-6f);
	cr_assert_float_eq(box.upperBound.y, 3.5f, 1e-6f);
	cr_assert(tbShape_TestPoint(shape, tbMakeVec2(2.2f, 3.2f)));
	cr_assert(tbShape_TestPoint(shape, tbMakeVec2(2.7f, 3.2f)) == false);
	cr_assert_eq(tbShape_GetContactCapacity(shape), 0, "nothing touches it");
	tbShape_EnableHitEvents(shape, true);
	cr_assert(tbShape_AreHitEventsEnabled(shape));
	tbBody_EnableContactEvents(body, false);
	cr_assert(tbShape_AreContactEventsEnabled(shape) == false);
	tbDestroyWorld(world);
}

// The stateless AABB and point tests by shape kind, against hand-computed boxes: a circle of
// radius 1 at (1, 0) moved by (2, 0) spans [2, 4] × [−1, 1]; a capsule (0,0)–(2,0) of radius 0.5
// spans [−0.5, 2.5] × [−0.5, 0.5]; a segment (0,0)–(1,1) spans [0, 1]²; a unit box turned 45°
// spans ±√2/2. Offset polygons keep their offset.
Test(accessors, geometry_boxes_and_points)
{
	tbTransform moved = {{2.0f, 0.0f}, tbMakeRot(0.0f)};
	tbCircle circle = {{1.0f, 0.0f}, 1.0f};
	tbAABB a = tbComputeCircleAABB(&circle, moved);
	cr_assert(a.lowerBound.x == 2.0f && a.upperBound.x == 4.0f && a.lowerBound.y == -1.0f && a.upperBound.y == 1.0f);
	tbCapsule capsule = {{0.0f, 0.0f}, {2.0f, 0.0f}, 0.5f};
	a = tbComputeCapsuleAABB(&capsule, tbTransform_identity);
	cr_assert(a.lowerBound.x == -0.5f && a.upperBound.x == 2.5f && a.upperBound.y == 0.5f);
	tbSegment segment = {{0.0f, 0.0f}, {1.0f, 1.0f}};
	a = tbComputeSegmentAABB(&segment, tbTransform_identity);
	cr_assert(a.lowerBound.x == 0.0f && a.upperBound.x == 1.0f && a.upperBound.y == 1.0f);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbTransform turned = {{0.0f, 0.0f}, tbMakeRot(0.25f * 3.14159265f)};
	a = tbComputePolygonAABB(&box, turned);
	cr_assert_float_eq(a.upperBound.x, 0.70710678f, 1e-5f);
	cr_assert(tbPointInCircle(&circle, tbMakeVec2(1.5f, 0.5f)));
	cr_assert(tbPointInCircle(&circle, tbMakeVec2(2.5f, 0.0f)) == false);
	cr_assert(tbPointInCapsule(&capsule, tbMakeVec2(1.0f, 0.4f)));
	cr_assert(tbPointInCapsule(&capsule, tbMakeVec2(1.0f, 0.6f)) == false);
	cr_assert(tbPointInPolygon(&box, tbMakeVec2(0.4f, -0.4f)));
	cr_assert(tbPointInPolygon(&box, tbMakeVec2(0.6f, 0.0f)) == false);
	tbVec2 points[3] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};
	tbHull hull = tbComputeHull(points, 3);
	tbPolygon offset = tbMakeOffsetPolygon(&hull, tbMakeVec2(10.0f, 0.0f), tbMakeRot(0.0f));
	cr_assert_float_eq(offset.centroid.x, 10.0f + 1.0f / 3.0f, 1e-5f);
}

static float MaxFriction(float frictionA, uint64_t materialA, float frictionB, uint64_t materialB)
{
	(void)materialA;
	(void)materialB;
	return fmaxf(frictionA, frictionB);
}

static float NoBounce(float restitutionA, uint64_t materialA, float restitutionB, uint64_t materialB)
{
	(void)restitutionA;
	(void)materialA;
	(void)restitutionB;
	(void)materialB;
	return 0.0f;
}

// World switches: sleeping off keeps a resting box awake; the mixing callbacks decide a box's
// friction (max(0, 1) = 1: a box sliding at 2 m/s stops within v²/(2μg) = 0.2 m, where the default
// mix sqrt(0·1) = 0 lets it slide on) and restitution (0: no bounce); every method can be switched
// at run time and the step still runs; the profile's stages add up to no more than the step;
// the version is 0.1.0; the tick counter does not run backwards.
Test(accessors, world_switches_and_callbacks)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbWorld_EnableSleeping(world, false);
	cr_assert(tbWorld_IsSleepingEnabled(world) == false);
	tbWorld_SetFrictionCallback(world, MaxFriction);
	tbWorld_SetRestitutionCallback(world, NoBounce);
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbShapeDef groundShape = tbDefaultShapeDef();
	groundShape.material.friction = 0.0f;
	groundShape.material.restitution = 1.0f;
	tbSegment floor = {{-50.0f, 0.0f}, {50.0f, 0.0f}};
	tbCreateSegmentShape(ground, &groundShape, &floor);
	tbBodyId box = CreateBody(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.5f));
	tbShapeId shape = AddBoxShape(box, 0.5f, 0.5f, NULL);
	tbShape_SetFriction(shape, 1.0f);
	tbBody_SetLinearVelocity(box, tbMakeVec2(2.0f, 0.0f));
	for (int step = 0; step < 120; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
	}
	cr_assert(tbBody_GetPosition(box).x < 0.25f, "slid %g m; max friction 1 stops it within 0.2 m",
			  (double)tbBody_GetPosition(box).x);
	cr_assert(tbBody_IsAwake(box), "sleeping is off");
	cr_assert(fabsf(tbBody_GetLinearVelocity(box).y) < 0.01f, "no bounce");
	cr_assert(tbWorld_SetBroadPhaseMethod(world, tb_broadPhaseSpatialHash));
	cr_assert(tbWorld_SetNarrowPhaseMethod(world, tb_narrowPhaseGJK));
	cr_assert(tbWorld_SetContinuousMethod(world, tb_continuousConservative));
	cr_assert(tbWorld_SetContactTuning(world, 20.0f, 5.0f, 2.0f));
	tbWorld_Step(world, TIME_STEP, 4);
	cr_assert(fabsf(tbBody_GetPosition(box).y - 0.5f) < 0.02f, "still resting after the switches");
	// The profile's stages are parts of the step (not a timing claim: only their sum is bounded).
	tbProfile profile = tbWorld_GetProfile(world);
	float parts = profile.pairs + profile.collide + profile.islands + profile.solve + profile.continuous +
				  profile.finalize + profile.hitEvents + profile.sleepIslands;
	cr_assert(profile.solve > 0.0f && parts <= profile.step * 1.0001f + 1e-6f, "stages %g ms of a %g ms step",
			  (double)parts, (double)profile.step);
	// And the solve's parts are parts of the solve (each timed from the end of the one before).
	const float solveParts[10] = {profile.solverSetup,	 profile.prepareConstraints, profile.integrateVelocities,
								  profile.warmStart,	 profile.solveImpulses,		 profile.integratePositions,
								  profile.relaxImpulses, profile.applyRestitution,	 profile.storeImpulses,
								  profile.scatterBodies};
	float solveSum = 0.0f;
	for (int i = 0; i < 10; ++i)
	{
		cr_assert(solveParts[i] >= 0.0f, "solve part %d: %g ms", i, (double)solveParts[i]);
		solveSum += solveParts[i];
	}
	cr_assert(solveSum <= profile.solve * 1.0001f + 1e-6f, "solve parts %g ms of a %g ms solve", (double)solveSum,
			  (double)profile.solve);
	tbVersion version = tbGetVersion(); // 0.1.0, as CHANGELOG.md's heading
	cr_assert(version.major == 0 && version.minor == 1 && version.revision == 0);
	uint64_t first = tbGetTicks(), second = tbGetTicks();
	cr_assert(second >= first, "the tick counter runs backwards");
	float elapsed = tbGetMilliseconds(first); // time since `first`: finite and not negative
	cr_assert(isfinite(elapsed) && elapsed >= 0.0f, "elapsed %g ms", (double)elapsed);
	tbDestroyWorld(world);
}

// Chain accessors: the body and world it belongs to; a material changed at run time reaches the
// segments.
Test(accessors, chain_settings)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbVec2 points[5] = {{4, 0}, {3, 0}, {2, 0}, {1, 0}, {0, 0}};
	tbChainDef def = tbDefaultChainDef();
	def.points = points;
	def.count = 5;
	tbChainId chain = tbCreateChain(ground, &def);
	tbBodyId owner = tbChain_GetBody(chain);
	cr_assert(owner.index1 == ground.index1);
	cr_assert(tbChain_GetWorld(chain).index1 == world.index1);
	tbSurfaceMaterial ice = tbDefaultSurfaceMaterial();
	ice.friction = 0.05f;
	cr_assert(tbChain_SetSurfaceMaterial(chain, &ice, 0));
	tbShapeId segments[2];
	cr_assert_eq(tbChain_GetSegments(chain, segments, 2), 2);
	cr_assert_float_eq(tbShape_GetFriction(segments[1]), 0.05f, 0.0f);
	tbDestroyWorld(world);
}

/// A disc of radius 0.5 at the origin, no gravity, joined to a static ground at its centre.
static tbBodyId CreateDisc(tbWorldId world, tbBodyId* ground)
{
	tbBodyDef groundDef = tbDefaultBodyDef();
	*ground = tbCreateBody(world, &groundDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	tbBodyId disc = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbCreateCircleShape(disc, &shapeDef, &circle);
	return disc;
}

/// Hold a steady external load for a second (the motor's speed is 0) and return the motor's
/// reaction through `read`.
static float HoldAgainst(tbWorldId world, tbBodyId body, float torque, tbVec2 force, tbJointId joint,
						 float (*read)(tbJointId))
{
	for (int step = 0; step < 60; ++step)
	{
		tbBody_ApplyTorque(body, torque, true);
		tbBody_ApplyForce(body, force, tbBody_GetWorldCenter(body), true);
		tbWorld_Step(world, TIME_STEP, 4);
	}
	return read(joint);
}

// Motors at speed 0 hold a steady load, so the motor's reaction equals the load (Newton's third
// law; 2 % covers the soft step's last sub-step): a torque of 2 N·m on a revolute joint, 3 N·m on a
// wheel joint, a force of 5 N along a distance joint.
Test(accessors, joint_motors_report_the_load_they_hold)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, 0.0f));
	tbBodyId ground;
	tbBodyId disc = CreateDisc(world, &ground);
	tbRevoluteJointDef revolute = tbDefaultRevoluteJointDef();
	revolute.base.bodyIdA = ground;
	revolute.base.bodyIdB = disc;
	revolute.enableMotor = true;
	revolute.maxMotorTorque = 100.0f;
	tbJointId joint = tbCreateRevoluteJoint(world, &revolute);
	float torque = HoldAgainst(world, disc, 2.0f, tbVec2_zero, joint, tbRevoluteJoint_GetMotorTorque);
	cr_assert(fabsf(fabsf(torque) - 2.0f) < 0.04f, "revolute motor torque %g, load 2 N·m", (double)torque);
	tbDestroyWorld(world);

	world = CreateWorld(tbMakeVec2(0.0f, 0.0f));
	disc = CreateDisc(world, &ground);
	tbWheelJointDef wheel = tbDefaultWheelJointDef();
	wheel.base.bodyIdA = ground;
	wheel.base.bodyIdB = disc;
	wheel.enableMotor = true;
	wheel.maxMotorTorque = 100.0f;
	joint = tbCreateWheelJoint(world, &wheel);
	torque = HoldAgainst(world, disc, 3.0f, tbVec2_zero, joint, tbWheelJoint_GetMotorTorque);
	cr_assert(fabsf(fabsf(torque) - 3.0f) < 0.06f, "wheel motor torque %g, load 3 N·m", (double)torque);
	tbDestroyWorld(world);

	world = CreateWorld(tbMakeVec2(0.0f, 0.0f));
	tbBodyDef groundDef = tbDefaultBodyDef();
	ground = tbCreateBody(world, &groundDef);
	tbBodyId box = CreateBox(world, tb_dynamicBody, tbMakeVec2(2.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	tbDistanceJointDef distance = tbDefaultDistanceJointDef();
	distance.base.bodyIdA = ground;
	distance.base.bodyIdB = box;
	distance.length = 2.0f;
	distance.enableSpring = true;
	distance.hertz = 0.0f; // no spring force: the motor alone holds the length
	distance.enableMotor = true;
	distance.maxMotorForce = 100.0f;
	joint = tbCreateDistanceJoint(world, &distance);
	float force = HoldAgainst(world, box, 0.0f, tbMakeVec2(5.0f, 0.0f), joint, tbDistanceJoint_GetMotorForce);
	cr_assert(fabsf(fabsf(force) - 5.0f) < 0.1f, "distance motor force %g, load 5 N", (double)force);
	cr_assert(fabsf(tbBody_GetPosition(box).x - 2.0f) < 0.01f, "the motor holds the length");

	tbTransform frame = {{0.1f, -0.2f}, tbMakeRot(0.0f)};
	cr_assert(tbJoint_SetLocalFrameB(joint, frame));
	tbTransform back = tbJoint_GetLocalFrameB(joint);
	cr_assert(back.p.x == 0.1f && back.p.y == -0.2f);
	tbBody_SetAwake(box, false);
	cr_assert(tbBody_IsAwake(box) == false);
	tbJoint_WakeBodies(joint);
	cr_assert(tbBody_IsAwake(box));
	tbDestroyWorld(world);
}

typedef struct DrawCounts
{
	int circles, segments, polygons;
} DrawCounts;

static void CountCircle(tbWorldTransform transform, tbVec2 center, float radius, tbHexColor color, void* context)
{
	(void)transform;
	(void)center;
	(void)radius;
	(void)color;
	((DrawCounts*)context)->circles += 1;
}

static void CountSegment(tbPos p1, tbPos p2, tbHexColor color, void* context)
{
	(void)p1;
	(void)p2;
	(void)color;
	((DrawCounts*)context)->segments += 1;
}

static void CountPolygon(tbWorldTransform transform, const tbVec2* vertices, int count, float radius, tbHexColor color,
						 void* context)
{
	(void)transform;
	(void)vertices;
	(void)count;
	(void)radius;
	(void)color;
	((DrawCounts*)context)->polygons += 1;
}

// Debug drawing visits each shape once with its kind's callback: one disc, one box, one ground
// segment (joints and the rest are off in this draw).
Test(accessors, debug_draw_visits_every_shape)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, 0.0f));
	tbBodyId ground;
	CreateDisc(world, &ground);
	CreateBox(world, tb_dynamicBody, tbMakeVec2(3.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbSegment floor = {{-5.0f, -2.0f}, {5.0f, -2.0f}};
	tbCreateSegmentShape(ground, &shapeDef, &floor);
	DrawCounts counts = {0, 0, 0};
	tbDebugDraw draw = tbDefaultDebugDraw();
	draw.DrawSolidCircleFcn = CountCircle;
	draw.DrawLineFcn = CountSegment;
	draw.DrawSolidPolygonFcn = CountPolygon;
	draw.drawShapes = true;
	draw.drawJoints = false;
	draw.context = &counts;
	tbWorld_Draw(world, &draw);
	cr_assert_eq(counts.circles, 1);
	cr_assert_eq(counts.polygons, 1);
	cr_assert_eq(counts.segments, 1);
	tbDestroyWorld(world);
}

// A 0.5 m box resting on a chain segment (ground solid below, straight joints on both sides)
// touches it along its bottom face: two points, normal straight up, separations 0.
Test(accessors, chain_segment_and_polygon_manifold)
{
	tbChainSegment segment = {{2.0f, 0.0f}, {{1.0f, 0.0f}, {0.0f, 0.0f}}, {-1.0f, 0.0f}, -1};
	tbPolygon box = tbMakeBox(0.25f, 0.25f);
	tbTransform xf = {{0.5f, 0.25f}, tbMakeRot(0.0f)};
	tbLocalManifold m = tbCollideChainSegmentAndPolygon(&segment, &box, xf, NULL);
	cr_assert_eq(m.pointCount, 2);
	cr_assert_float_eq(m.normal.y, 1.0f, 1e-6f);
	cr_assert_float_eq(m.points[0].separation, 0.0f, 1e-5f);
	cr_assert_float_eq(m.points[1].separation, 0.0f, 1e-5f);
}
