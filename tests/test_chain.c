// Chains: one-sided segments that shapes slide across without catching on the joints.
// The seam criterion is the one a platformer needs: a box or a capsule driven along flat ground
// made of 100 one-metre segments keeps |vertical velocity| ≤ 0.01 m/s at every step, at 1, 10 and
// 30 m/s (on flat ground the exact answer is 0; 0.01 m/s is a hundredth of the slowest drive and
// about what the soft contact's rest sag of a few millimetres can produce while settling).
#include <criterion/criterion.h>

#include "collide_world.h"
#include "tumble/tumble.h"

#include "error_recorder.h"
#include "test_helpers.h"

#include <math.h>

#define TIME_STEP (1.0f / 60.0f)
#define SEGMENTS 100

/// Flat ground from x = 0 to x = SEGMENTS at y = 0, solid below: points run right to left, with a
/// ghost point beyond each end.
static tbChainId CreateFlatChain(tbWorldId world)
{
	static tbVec2 points[SEGMENTS + 3];
	for (int i = 0; i < SEGMENTS + 3; ++i)
	{
		points[i] = tbMakeVec2((float)(SEGMENTS + 1 - i), 0.0f);
	}
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbChainDef def = tbDefaultChainDef();
	def.points = points;
	def.count = SEGMENTS + 3;
	return tbCreateChain(ground, &def);
}

typedef enum Mover
{
	MoverBox,
	MoverCapsule
} Mover;

static tbBodyId CreateMover(tbWorldId world, Mover kind)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.fixedRotation = true; // a character's body: the test is about normals, not tipping
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material.friction = 0.0f;
	tbBodyId body;
	if (kind == MoverBox)
	{
		bodyDef.position = tbMakeVec2(1.0f, 0.25f);
		body = tbCreateBody(world, &bodyDef);
		tbPolygon box = tbMakeBox(0.25f, 0.25f);
		tbCreatePolygonShape(body, &shapeDef, &box);
	}
	else
	{
		bodyDef.position = tbMakeVec2(1.0f, 0.25f);
		body = tbCreateBody(world, &bodyDef);
		tbCapsule capsule = {{-0.25f, 0.0f}, {0.25f, 0.0f}, 0.25f};
		tbCreateCapsuleShape(body, &shapeDef, &capsule);
	}
	return body;
}

/// Drive the mover at `speed` across the ground and return the largest |vertical velocity| seen
/// while it is over the interior seams (x in 2..SEGMENTS − 2).
static float MaxVerticalSpeed(tbWorldId world, tbBodyId body, float speed)
{
	for (int step = 0; step < 30; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4); // settle at rest first
	}
	float worst = 0.0f;
	for (int step = 0; step < 100000; ++step)
	{
		tbVec2 v = tbBody_GetLinearVelocity(body);
		tbBody_SetLinearVelocity(body, tbMakeVec2(speed, v.y));
		tbWorld_Step(world, TIME_STEP, 4);
		float x = tbBody_GetPosition(body).x;
		if (x > (float)SEGMENTS - 2.0f)
		{
			break;
		}
		if (x > 2.0f)
		{
			worst = fmaxf(worst, fabsf(tbBody_GetLinearVelocity(body).y));
		}
	}
	return worst;
}

Test(chain, box_and_capsule_cross_seams_without_bumps)
{
	const float speeds[3] = {1.0f, 10.0f, 30.0f};
	for (int kind = MoverBox; kind <= MoverCapsule; ++kind)
	{
		for (int s = 0; s < 3; ++s)
		{
			tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
			CreateFlatChain(world);
			tbBodyId body = CreateMover(world, (Mover)kind);
			float worst = MaxVerticalSpeed(world, body, speeds[s]);
			cr_assert(worst <= 0.01f, "%s at %g m/s: vertical speed %g m/s at a seam", kind == MoverBox ? "box" : "capsule",
					  (double)speeds[s], (double)worst);
			float y = tbBody_GetPosition(body).y;
			cr_assert(fabsf(y - 0.25f) < 0.01f, "rides at %g, expected 0.25 (half height)", (double)y);
			tbDestroyWorld(world);
		}
	}
}

// One-sided: a ball thrown up from below passes through the ground and lands on top of it; a ray
// from above hits the ground at y = 0, a ray from below does not.
Test(chain, is_one_sided)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	CreateFlatChain(world);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbMakeVec2(50.3f, -1.0f);
	bodyDef.linearVelocity = tbMakeVec2(0.0f, 8.0f); // rises to −1 + 8²/20 = 2.2 m
	tbBodyId ball = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, 0.2f};
	tbCreateCircleShape(ball, &shapeDef, &circle);
	for (int step = 0; step < 180; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
	}
	float y = tbBody_GetPosition(ball).y;
	cr_assert(fabsf(y - 0.2f) < 0.01f, "the ball rests at %g, expected on top at its radius 0.2", (double)y);

	tbRayResult down = tbWorld_CastRayClosest(world, tbMakeVec2(10.5f, 5.0f), tbMakeVec2(0.0f, -10.0f),
											   tbDefaultQueryFilter());
	cr_assert(down.hit);
	cr_assert_float_eq(down.point.y, 0.0f, 1e-5f);
	cr_assert_float_eq(down.normal.y, 1.0f, 1e-5f);
	tbRayResult up = tbWorld_CastRayClosest(world, tbMakeVec2(10.5f, -5.0f), tbMakeVec2(0.0f, 10.0f),
											 tbDefaultQueryFilter());
	cr_assert(up.hit == false, "a ray from below should pass through the one-sided ground");
	tbDestroyWorld(world);
}

// A loop given clockwise is solid outside: a container. A ball bouncing inside a 16-sided loop of
// radius 5 m (restitution 0.8) for 10 s stays inside it; a box dropped on a counter-clockwise
// square loop (solid inside) rests on its top face at the box's half height above it.
Test(chain, loops_hold_inside_or_outside)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbVec2 ring[16];
	for (int i = 0; i < 16; ++i)
	{
		float angle = -2.0f * 3.14159265f * (float)i / 16.0f; // clockwise
		ring[i] = tbMakeVec2(5.0f * cosf(angle), 5.0f * sinf(angle));
	}
	tbChainDef def = tbDefaultChainDef();
	def.points = ring;
	def.count = 16;
	def.isLoop = true;
	tbSurfaceMaterial bouncy = tbDefaultSurfaceMaterial();
	bouncy.restitution = 0.8f;
	def.materials = &bouncy;
	tbChainId container = tbCreateChain(ground, &def);
	cr_assert_eq(tbChain_GetSegmentCount(container), 16);

	tbVec2 square[4] = {{20.0f, 0.0f}, {22.0f, 0.0f}, {22.0f, 2.0f}, {20.0f, 2.0f}}; // counter-clockwise
	def = tbDefaultChainDef();
	def.points = square;
	def.count = 4;
	def.isLoop = true;
	tbCreateChain(ground, &def);

	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.linearVelocity = tbMakeVec2(17.0f, 9.0f);
	tbBodyId ball = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material.restitution = 0.8f;
	tbCircle circle = {{0.0f, 0.0f}, 0.3f};
	tbCreateCircleShape(ball, &shapeDef, &circle);
	bodyDef.linearVelocity = tbVec2_zero;
	bodyDef.position = tbMakeVec2(21.0f, 3.0f);
	tbBodyId box = tbCreateBody(world, &bodyDef);
	tbPolygon boxShape = tbMakeBox(0.5f, 0.5f);
	tbShapeDef boxDef = tbDefaultShapeDef();
	tbCreatePolygonShape(box, &boxDef, &boxShape);
	// The ball's centre gets farthest from the middle in a corner, touching both chords: on the
	// corner's bisector, 0.3 / sin(78.75°) from the corner (the 16-gon's inner angle is 157.5°).
	float inner = 5.0f - 0.3f / sinf(78.75f * 3.14159265f / 180.0f);
	for (int step = 0; step < 600; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
		float r = tbLength(tbBody_GetPosition(ball));
		cr_assert(r < inner + 0.02f, "step %d: the ball is %g m from the centre, outside the container", step,
				  (double)r);
	}
	cr_assert(fabsf(tbBody_GetPosition(box).y - 2.5f) < 0.01f, "the box rests at %g, expected 2.5",
			  (double)tbBody_GetPosition(box).y);
	tbDestroyWorld(world);
}

// Materials per segment: a box sliding at 3 m/s over a frictionless half of the ground keeps its
// speed and stops on the half with friction 1 within v²/(2μg) = 9/20 = 0.45 m of reaching it.
Test(chain, materials_per_segment)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbVec2 points[13];
	for (int i = 0; i < 13; ++i)
	{
		points[i] = tbMakeVec2((float)(11 - i), 0.0f); // segments from x = 10 down to x = 0
	}
	tbSurfaceMaterial materials[10];
	for (int i = 0; i < 10; ++i)
	{
		materials[i] = tbDefaultSurfaceMaterial();
		materials[i].friction = i < 5 ? 1.0f : 0.0f; // segment i runs from x = 10 − i to 9 − i
	}
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbChainDef def = tbDefaultChainDef();
	def.points = points;
	def.count = 13;
	def.materials = materials;
	def.materialCount = 10;
	tbChainId chain = tbCreateChain(ground, &def);
	cr_assert_eq(tbChain_GetSurfaceMaterialCount(chain), 10);
	cr_assert_float_eq(tbChain_GetSurfaceMaterial(chain, 2).friction, 1.0f, 0.0f);
	tbShapeId segments[10];
	cr_assert_eq(tbChain_GetSegments(chain, segments, 10), 10);
	cr_assert_float_eq(tbShape_GetFriction(segments[7]), 0.0f, 0.0f);
	cr_assert(tbShape_GetParentChain(segments[7]).index1 == chain.index1);
	tbChainSegment seg = tbShape_GetChainSegment(segments[0]);
	cr_assert_float_eq(seg.segment.point1.x, 10.0f, 0.0f);
	cr_assert_float_eq(seg.ghost1.x, 11.0f, 0.0f);
	cr_assert_float_eq(seg.ghost2.x, 8.0f, 0.0f);

	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.fixedRotation = true;
	bodyDef.position = tbMakeVec2(1.0f, 0.25f);
	bodyDef.linearVelocity = tbMakeVec2(3.0f, 0.0f);
	tbBodyId box = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material.friction = 1.0f; // friction mixes as sqrt(1 · μ_ground): 0 on the smooth half, 1 on the rough
	tbPolygon boxShape = tbMakeBox(0.25f, 0.25f);
	tbCreatePolygonShape(box, &shapeDef, &boxShape);
	for (int step = 0; step < 180; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
	}
	// The box's front reaches the rough half (x = 5) with its centre at 4.75 and it is wholly on
	// it from 5.25. With full friction from the first touch it would stop at 4.75 + 0.45 = 5.2;
	// with none until wholly on the rough half, at 5.25 + 0.45 = 5.7. (If the load moved over
	// linearly, friction would do 2.5 J/kg while it straddles and it would stop at 5.45.)
	float x = tbBody_GetPosition(box).x;
	cr_assert(x > 5.2f && x < 5.7f, "stopped at %g, expected 5.2 to 5.7", (double)x);
	cr_assert(fabsf(tbBody_GetLinearVelocity(box).x) < 0.01f);
	tbDestroyWorld(world);
}

// Bad chains are refused with one error naming the problem, and nothing is created.
Test(chain, bad_input_is_refused, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbVec2 good[5] = {{4, 0}, {3, 0}, {2, 0}, {1, 0}, {0, 0}};
	tbVec2 nan[5] = {{4, 0}, {3, 0}, {NAN, 0}, {1, 0}, {0, 0}};
	tbVec2 duplicate[5] = {{4, 0}, {3, 0}, {3, 0.001f}, {1, 0}, {0, 0}};
	tbSurfaceMaterial negative = tbDefaultSurfaceMaterial();
	negative.friction = -1.0f;
	tbSurfaceMaterial two[2] = {tbDefaultSurfaceMaterial(), tbDefaultSurfaceMaterial()};
	two[0].friction = two[1].friction = 0.5f;
	int shapesBefore = tbWorld_GetCounters(world).shapeCount;

	tbChainDef def = tbDefaultChainDef();
	def.points = good;
	def.count = 3;
	int before = s_errors;
	cr_assert(TB_IS_NULL(tbCreateChain(ground, &def)));
	ExpectError(before, "tbCreateChain", "at least 4");

	def.count = 5;
	def.points = nan;
	before = s_errors;
	cr_assert(TB_IS_NULL(tbCreateChain(ground, &def)));
	ExpectError(before, "tbCreateChain", "points[2]");

	def.points = duplicate;
	before = s_errors;
	cr_assert(TB_IS_NULL(tbCreateChain(ground, &def)));
	ExpectError(before, "tbCreateChain", "duplicate");

	def.points = good;
	def.materials = &negative;
	before = s_errors;
	cr_assert(TB_IS_NULL(tbCreateChain(ground, &def)));
	ExpectError(before, "tbCreateChain", "materials[0]");

	def.materials = two; // an open chain of 5 points has 2 segments: 2 materials are fine
	def.materialCount = 2;
	tbChainId chain = tbCreateChain(ground, &def);
	cr_assert(tbChain_IsValid(chain));
	def.materialCount = 3;
	before = s_errors;
	cr_assert(TB_IS_NULL(tbCreateChain(ground, &def)));
	ExpectError(before, "tbCreateChain", "materialCount");

	tbChainDef uninitialised = {0};
	before = s_errors;
	cr_assert(TB_IS_NULL(tbCreateChain(ground, &uninitialised)));
	ExpectError(before, "tbCreateChain", "tbDefaultChainDef");
	cr_assert_eq(tbWorld_GetCounters(world).shapeCount, shapesBefore + 2, "only the good chain's 2 segments");

	// Its segments are changed only through the chain.
	tbShapeId segments[2];
	cr_assert_eq(tbChain_GetSegments(chain, segments, 2), 2);
	before = s_errors;
	tbDestroyShape(segments[0], false);
	ExpectError(before, "tbDestroyShape", "chain");
	tbCircle circle = {{0.0f, 0.0f}, 1.0f};
	before = s_errors;
	cr_assert(tbShape_SetCircle(segments[0], &circle) == false);
	ExpectError(before, "tbShape_SetCircle", "chain");
	cr_assert(tbShape_IsValid(segments[0]));

	// Destroying the chain destroys its segments; its id and theirs go stale.
	tbDestroyChain(chain);
	cr_assert(tbChain_IsValid(chain) == false);
	cr_assert(tbShape_IsValid(segments[1]) == false);
	before = s_errors;
	cr_assert_eq(tbChain_GetSegmentCount(chain), 0);
	ExpectError(before, "tbChain_GetSegmentCount", "chainId");
	cr_assert_eq(tbWorld_GetCounters(world).shapeCount, shapesBefore);

	// Destroying the body destroys its chains.
	def.materials = two;
	def.materialCount = 1;
	chain = tbCreateChain(ground, &def);
	cr_assert(tbChain_IsValid(chain));
	tbDestroyBody(ground);
	cr_assert(tbChain_IsValid(chain) == false);
	tbDestroyWorld(world);
}

// A world with chains gives back every byte it took.
Test(chain, memory_is_returned)
{
	int before = tbGetByteCount();
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	CreateFlatChain(world);
	tbBodyId body = CreateMover(world, MoverBox);
	(void)body;
	for (int step = 0; step < 10; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
	}
	tbDestroyWorld(world);
	cr_assert_eq(tbGetByteCount(), before);
}

// The collision routine on its own (stateless). Ground solid below runs right to left: segment
// (1, 0) → (0, 0) with the ground continuing to (−1, 0) (a straight joint at the origin).
// A capsule (half length 0.25, radius 0.25) sagging 1 mm into the ground slides across the joint:
// collided as a plain segment its round end meets the segment's end point and the normal tilts
// (22° at worst here: the bump, which at speed throws a capsule metres up, see docs/methods.md);
// as a chain segment the normal is the face's (0, 1) at every position.
Test(chain, straight_joint_gives_the_face_normal)
{
	tbChainSegment chain = {{2.0f, 0.0f}, {{1.0f, 0.0f}, {0.0f, 0.0f}}, {-1.0f, 0.0f}, -1};
	tbSegment plain = chain.segment;
	tbCapsule capsule = {{-0.25f, 0.0f}, {0.25f, 0.0f}, 0.25f};
	float worstPlain = 1.0f;
	int touching = 0;
	for (int i = 0; i <= 120; ++i)
	{
		float x = -0.6f + 0.01f * (float)i;
		tbTransform xf = {{x, 0.249f}, tbMakeRot(0.0f)};
		tbManifold m = WorldCollideChainSegmentAndCapsule(&chain, tbTransform_identity, &capsule, xf);
		if (m.pointCount > 0)
		{
			touching += 1;
			cr_assert(m.normal.y >= 1.0f - 1e-6f, "x = %g: chain normal (%g, %g)", (double)x, (double)m.normal.x,
					  (double)m.normal.y);
		}
		tbManifold p = WorldCollideSegmentAndCapsule(&plain, tbTransform_identity, &capsule, xf);
		if (p.pointCount > 0)
		{
			worstPlain = fminf(worstPlain, p.normal.y);
		}
	}
	cr_assert(touching > 50, "the capsule should touch the segment over half the positions (%d)", touching);
	cr_assert(worstPlain < cosf(10.0f * 3.14159265f / 180.0f), "the plain segment should tilt the normal by > 10° (y = %g)",
			  (double)worstPlain);
}

// A convex joint (a crest): flat ground (1, 0) → (0, 0), then a 45° slope down to (−1, −1). A
// circle of radius 0.5 rolling over the crest touches the corner with normal (−sin θ, cos θ) for θ
// from 0 to 45°; the flat segment reports it up to the bisector of the two faces' normals
// (θ = 22.5°), the slope from there on, so exactly one of them does, with the corner's normal.
Test(chain, convex_joint_is_reported_once)
{
	tbChainSegment flat = {{2.0f, 0.0f}, {{1.0f, 0.0f}, {0.0f, 0.0f}}, {-1.0f, -1.0f}, -1};
	tbChainSegment slope = {{1.0f, 0.0f}, {{0.0f, 0.0f}, {-1.0f, -1.0f}}, {-2.0f, -2.0f}, -1};
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	for (int degrees = 1; degrees < 45; ++degrees)
	{
		if (degrees >= 22 && degrees <= 23)
		{
			continue; // at the bisector itself either may take it
		}
		float theta = (float)degrees * 3.14159265f / 180.0f;
		tbVec2 normal = {-sinf(theta), cosf(theta)};
		tbTransform xf = {tbMulSV(0.499f, normal), tbMakeRot(0.0f)};
		tbManifold a = WorldCollideChainSegmentAndCircle(&flat, tbTransform_identity, &circle, xf);
		tbManifold b = WorldCollideChainSegmentAndCircle(&slope, tbTransform_identity, &circle, xf);
		cr_assert_eq((a.pointCount > 0) + (b.pointCount > 0), 1, "%d°: reported by %d segments", degrees,
					 (a.pointCount > 0) + (b.pointCount > 0));
		tbManifold m = a.pointCount > 0 ? a : b;
		cr_assert(tbDot(m.normal, normal) > 1.0f - 1e-5f, "%d°: normal (%g, %g)", degrees, (double)m.normal.x,
				  (double)m.normal.y);
		cr_assert_eq(a.pointCount > 0, degrees < 22, "%d°: the flat segment owns normals up to 22.5°", degrees);
	}
}

// Loop-the-loop: a frictionless ball (radius r = 0.25) sliding inside a vertical loop of radius
// R = 5 (a clockwise loop chain, solid outside, 1,024 segments) stays on the track over the top
// only if its speed at the bottom is at least v = √(5 g (R − r)) = 15.41 m/s (at the top the track
// must still push: v_top² ≥ g (R − r), with v_top² = v² − 4 g (R − r)). Each joint of the polygonal
// track turns the velocity by 2π/1024 inelastically, keeping cos² of it as kinetic energy:
// exp(−2π²/1024) ≈ 98 % over the half loop, so 5 % above v it completes the loop (centre reaches the
// top, R − r above the middle) and 5 % below it leaves the track before the top and falls inside.
static float HighestPoint(float speedFraction)
{
	const float R = 5.0f, r = 0.25f, g = 10.0f;
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	static tbVec2 loop[1024];
	for (int i = 0; i < 1024; ++i)
	{
		float angle = -2.0f * 3.14159265f * (float)i / 1024.0f; // clockwise: solid outside
		loop[i] = tbMakeVec2(R * cosf(angle), R + R * sinf(angle));
	}
	tbChainDef def = tbDefaultChainDef();
	def.points = loop;
	def.count = 1024;
	def.isLoop = true;
	tbSurfaceMaterial smooth = tbDefaultSurfaceMaterial();
	smooth.friction = 0.0f;
	def.materials = &smooth;
	tbCreateChain(ground, &def);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbMakeVec2(0.0f, r);
	bodyDef.linearVelocity = tbMakeVec2(speedFraction * sqrtf(5.0f * g * (R - r)), 0.0f);
	tbBodyId ball = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material.friction = 0.0f;
	tbCircle circle = {{0.0f, 0.0f}, r};
	tbCreateCircleShape(ball, &shapeDef, &circle);
	float highest = 0.0f;
	for (int step = 0; step < 90; ++step) // 1.5 s: the loop takes about 1.2 s
	{
		tbWorld_Step(world, TIME_STEP, 4);
		highest = fmaxf(highest, tbBody_GetPosition(ball).y);
	}
	tbDestroyWorld(world);
	return highest;
}

Test(chain, loop_the_loop_needs_the_closed_form_speed)
{
	float top = 2.0f * 5.0f - 0.25f; // the centre's height at the top of the track
	float above = HighestPoint(1.05f);
	cr_assert(above > top - 0.01f, "at 1.05 v the ball should go over the top (reached %g of %g)", (double)above,
			  (double)top);
	float below = HighestPoint(0.95f);
	cr_assert(below < top - 0.2f, "at 0.95 v the ball should leave the track before the top (reached %g)",
			  (double)below);
}

// Robustness of the chain collider: 20,000 random placements of circles, capsules, boxes and
// rounded polygons (random size, angle, position, up to 0.5 m inside the surface) around a joint
// of random angle between two segments give manifolds with at most 2 points, a finite unit
// normal and finite separations, never below the deepest overlap the placement allows (the
// shape's own size plus the speculative distance), and nothing for a centre behind the segment.
Test(chain, random_placements_give_valid_manifolds)
{
	unsigned seed = 2026u;
#define RANDOM(lo, hi) (seed = seed * 1664525u + 1013904223u, (lo) + ((hi) - (lo)) * (float)(seed >> 8) / 16777216.0f)
	for (int trial = 0; trial < 20000; ++trial)
	{
		float turn = RANDOM(-1.2f, 1.2f);
		tbChainSegment segment = {{2.0f, 0.0f}, {{1.0f, 0.0f}, {0.0f, 0.0f}}, {-cosf(turn), -sinf(turn)}, -1};
		tbTransform xf = {{RANDOM(-1.0f, 2.0f), RANDOM(-0.5f, 1.0f)}, tbMakeRot(RANDOM(-3.2f, 3.2f))};
		float size = RANDOM(0.05f, 0.6f);
		int kind = trial % 4;
		tbManifold m;
		if (kind == 0)
		{
			tbCircle circle = {{0.0f, 0.0f}, size};
			m = WorldCollideChainSegmentAndCircle(&segment, tbTransform_identity, &circle, xf);
		}
		else if (kind == 1)
		{
			tbCapsule capsule = {{-size, 0.0f}, {size, 0.0f}, 0.5f * size};
			m = WorldCollideChainSegmentAndCapsule(&segment, tbTransform_identity, &capsule, xf);
		}
		else
		{
			tbPolygon box = kind == 2 ? tbMakeBox(size, 0.5f * size) : tbMakeRoundedBox(size, 0.5f * size, 0.1f * size);
			m = WorldCollideChainSegmentAndPolygon(&segment, tbTransform_identity, &box, xf);
		}
		cr_assert(m.pointCount >= 0 && m.pointCount <= 2);
		if (xf.p.y < 0.0f)
		{
			cr_assert_eq(m.pointCount, 0, "trial %d: centre behind the segment, yet %d points", trial, m.pointCount);
		}
		if (m.pointCount == 0)
		{
			continue;
		}
		cr_assert(isfinite(m.normal.x) && isfinite(m.normal.y), "trial %d: normal not finite", trial);
		cr_assert(fabsf(tbLength(m.normal) - 1.0f) < 1e-4f, "trial %d: normal not unit", trial);
		for (int i = 0; i < m.pointCount; ++i)
		{
			float s = m.points[i].separation;
			cr_assert(isfinite(s), "trial %d: separation not finite", trial);
			cr_assert(s > -2.5f * size - 0.05f && s < TB_SPECULATIVE_DISTANCE + 1e-4f, "trial %d: separation %g",
					  trial, (double)s);
		}
	}
#undef RANDOM
}

// A chain on a moving body turns with it. A kinematic square drum (a clockwise loop, solid outside,
// walls 2 m from its centre) turns at 3 rad/s about its centre, with a ball of radius 0.25 m at rest
// inside, off-centre at (1.5, 1) and 0.25 m from the wall x = 2, no gravity. In the drum's frame the
// ball's distance along the wall's normal, 1.5·cos θ + sin θ, reaches the wall less the radius,
// 1.75 m, after θ ≈ 0.36 rad (7 steps at 60 Hz): from then on the wall pushes the ball. A soft
// contact lets the wall sink into the ball by about the linear slop (0.005 m), so the ball's centre
// must stay within its radius less the speculative distance (0.02 m, four slops) of the nearest
// wall, in the drum's frame, for 2 s. The drum's extent once stayed 0 (a body with chain shapes only
// gets no mass update), which let the pair be kept apart while the wall swept 0.053 m into the ball.
Test(chain, a_turning_chain_pushes_what_it_meets)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, 0.0f));
	tbBodyDef drumDef = tbDefaultBodyDef();
	drumDef.type = tb_kinematicBody;
	drumDef.angularVelocity = 3.0f;
	tbBodyId drum = tbCreateBody(world, &drumDef);
	tbVec2 square[4] = {{-2.0f, -2.0f}, {-2.0f, 2.0f}, {2.0f, 2.0f}, {2.0f, -2.0f}}; // clockwise: solid outside
	tbChainDef def = tbDefaultChainDef();
	def.points = square;
	def.count = 4;
	def.isLoop = true;
	tbCreateChain(drum, &def);

	tbBodyId ball;
	CreateBall(world, tbMakeVec2(1.5f, 1.0f), tbVec2_zero, 0.25f, NULL, &ball);

	float deepest = 0.0f;
	for (int step = 0; step < 120; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
		// The ball's centre in the drum's frame, and its depth past the nearest wall less its radius.
		tbVec2 p = tbInvRotateVector(tbBody_GetRotation(drum), tbSub(tbBody_GetPosition(ball), tbBody_GetPosition(drum)));
		float depth = fmaxf(fabsf(p.x), fabsf(p.y)) - (2.0f - 0.25f);
		deepest = fmaxf(deepest, depth);
		cr_assert(depth < 0.02f, "step %d: the ball's centre (%g, %g) in the drum's frame is %g m past its wall",
				  step, (double)p.x, (double)p.y, (double)depth);
	}
	cr_assert(deepest > -0.1f, "the wall never reached the ball (deepest %g): the set-up is wrong", (double)deepest);
	tbDestroyWorld(world);
}
