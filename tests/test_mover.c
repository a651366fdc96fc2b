// Character movers: the plane solver and clipping against hand-worked cases, the mover's planes
// against closed-form distances, and a capsule character walking, stopping at a wall and climbing
// a slope through the world queries.
#include "tumble/tumble.h"

#include <criterion/criterion.h>

#include "error_recorder.h"

#include <float.h>
#include <math.h>

static tbCollisionPlane Plane(float nx, float ny, float offset, float pushLimit)
{
	tbCollisionPlane plane = {{{nx, ny}, offset}, pushLimit, 0.0f, true};
	return plane;
}

// One plane: the solver moves the target along the normal until the mover is a slop inside.
// Worked by hand: floor n = (0, 1), the mover 0.1 m deep (offset 0.1), target (1, −0.5): the push
// is 0.595 and δ = (1, 0.095).
Test(mover, solver_pushes_out_of_one_plane_to_the_slop)
{
	tbCollisionPlane floor = Plane(0.0f, 1.0f, 0.1f, FLT_MAX);
	tbPlaneSolverResult r = tbSolvePlanes((tbVec2){1.0f, -0.5f}, &floor, 1);
	cr_expect_float_eq(r.delta.x, 1.0f, 1e-6f);
	cr_expect_float_eq(r.delta.y, 0.1f - TB_LINEAR_SLOP, 1e-6f);
	cr_expect_float_eq(floor.push, 0.5f + 0.1f - TB_LINEAR_SLOP, 1e-6f);
	// A plane already satisfied pushes nothing (push ≥ 0: planes never pull).
	tbCollisionPlane below = Plane(0.0f, 1.0f, -1.0f, FLT_MAX);
	r = tbSolvePlanes((tbVec2){0.5f, 0.2f}, &below, 1);
	cr_expect_eq(r.delta.x, 0.5f);
	cr_expect_eq(r.delta.y, 0.2f);
	cr_expect_eq(below.push, 0.0f);
}

// A corner (floor and a wall facing −x): both constraints hold at once; orthogonal planes settle
// in one sweep. A soft plane pushes no more than its limit.
Test(mover, solver_handles_corners_and_soft_planes)
{
	tbCollisionPlane corner[2] = {Plane(0.0f, 1.0f, 0.0f, FLT_MAX), Plane(-1.0f, 0.0f, 0.0f, FLT_MAX)};
	tbPlaneSolverResult r = tbSolvePlanes((tbVec2){1.0f, -1.0f}, corner, 2);
	cr_expect_float_eq(r.delta.x, TB_LINEAR_SLOP, 1e-6f);
	cr_expect_float_eq(r.delta.y, -TB_LINEAR_SLOP, 1e-6f);
	cr_expect_leq(r.iterationCount, 1);

	// A 45° corner (floor and a wall leaning at 45°): Gauss–Seidel takes several sweeps; the answer
	// satisfies both planes within the slop.
	float s = sqrtf(0.5f);
	tbCollisionPlane wedge[2] = {Plane(0.0f, 1.0f, 0.0f, FLT_MAX), Plane(-s, s, 0.0f, FLT_MAX)};
	r = tbSolvePlanes((tbVec2){2.0f, -1.0f}, wedge, 2);
	for (int i = 0; i < 2; ++i)
	{
		float gap = wedge[i].plane.normal.x * r.delta.x + wedge[i].plane.normal.y * r.delta.y - wedge[i].plane.offset;
		cr_expect_geq(gap, -TB_LINEAR_SLOP - 1e-3f, "plane %d left %.5f deep", i, (double)gap);
	}

	tbCollisionPlane soft = Plane(0.0f, 1.0f, 0.0f, 0.1f);
	r = tbSolvePlanes((tbVec2){0.0f, -0.5f}, &soft, 1);
	cr_expect_float_eq(r.delta.y, -0.4f, 1e-6f);
	cr_expect_float_eq(soft.push, 0.1f, 1e-6f);
}

// Clipping removes the velocity into the planes that pushed, and only those.
Test(mover, clip_removes_velocity_into_pushing_planes)
{
	tbCollisionPlane planes[2] = {Plane(0.0f, 1.0f, 0.0f, FLT_MAX), Plane(-1.0f, 0.0f, 0.0f, FLT_MAX)};
	planes[0].push = 0.01f;
	tbVec2 v = tbClipVector((tbVec2){3.0f, -2.0f}, planes, 2);
	cr_expect_eq(v.x, 3.0f); // the wall did not push: its plane is left alone
	cr_expect_eq(v.y, 0.0f);
	planes[1].push = 0.01f;
	v = tbClipVector((tbVec2){3.0f, -2.0f}, planes, 2);
	cr_expect_eq(v.x, 0.0f);
	cr_expect_eq(v.y, 0.0f);
	v = tbClipVector((tbVec2){-3.0f, 2.0f}, planes, 2); // moving away: kept
	cr_expect_eq(v.x, -3.0f);
	cr_expect_eq(v.y, 2.0f);
	planes[0].clipVelocity = false;
	planes[1].clipVelocity = false;
	v = tbClipVector((tbVec2){3.0f, -2.0f}, planes, 2);
	cr_expect_eq(v.x, 3.0f);
	cr_expect_eq(v.y, -2.0f);
}

// The mover's plane against each kind of shape: an upright capsule (radius 0.5, centres 1 m apart)
// whose bottom is 0.05 m inside the shape's top gets the plane n = (0, 1), offset 0.05, and the
// point on the shape's surface below it.
Test(mover, mover_planes_against_every_shape_kind)
{
	tbCapsule mover = {{0.0f, 0.45f}, {0.0f, 1.45f}, 0.5f};
	tbGeometry shapes[4];
	shapes[0].type = tb_polygonShape;
	shapes[0].polygon = tbMakeOffsetBox(2.0f, 0.5f, (tbVec2){0.0f, -0.5f}, tbRot_identity); // top y = 0
	shapes[1].type = tb_circleShape;
	shapes[1].circle = (tbCircle){{0.0f, -1.0f}, 1.0f}; // top y = 0
	shapes[2].type = tb_segmentShape;
	shapes[2].segment = (tbSegment){{-2.0f, 0.0f}, {2.0f, 0.0f}};
	shapes[3].type = tb_capsuleShape;
	shapes[3].capsule = (tbCapsule){{-2.0f, -0.25f}, {2.0f, -0.25f}, 0.25f}; // top y = 0
	for (int i = 0; i < 4; ++i)
	{
		tbPlaneResult r = tbCollideMover(&mover, shapes + i, tbTransform_identity);
		cr_expect(r.hit, "shape %d: no plane", i);
		cr_expect_float_eq(r.plane.normal.x, 0.0f, 1e-5f, "shape %d", i);
		cr_expect_float_eq(r.plane.normal.y, 1.0f, 1e-5f, "shape %d", i);
		cr_expect_float_eq(r.plane.offset, 0.05f, 1e-5f, "shape %d", i);
		cr_expect_float_eq(r.point.y, 0.0f, 1e-5f, "shape %d: point y %.6f", i, (double)r.point.y);
	}
	// Out of reach: no plane.
	tbCapsule high = {{0.0f, 0.6f}, {0.0f, 1.6f}, 0.5f};
	cr_expect_not(tbCollideMover(&high, shapes, tbTransform_identity).hit);
	// The shape's transform places it: the box lifted by 0.1 m gives offset 0.15.
	tbTransform lifted = {{0.0f, 0.1f}, tbRot_identity};
	cr_expect_float_eq(tbCollideMover(&mover, shapes, lifted).plane.offset, 0.15f, 1e-5f);
}

// A level: ground top y = 0 from x = −10 to 30, a wall (x from 10 to 11, 3 m high), a 30° ramp
// starting at x = 15.
static tbWorldId MakeLevel(void)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon floor = tbMakeOffsetBox(20.0f, 0.5f, (tbVec2){10.0f, -0.5f}, tbRot_identity);
	tbCreatePolygonShape(ground, &shapeDef, &floor);
	tbPolygon wall = tbMakeOffsetBox(0.5f, 1.5f, (tbVec2){10.5f, 1.5f}, tbRot_identity);
	tbCreatePolygonShape(ground, &shapeDef, &wall);
	tbSegment ramp = {{15.0f, 0.0f}, {15.0f + 10.0f * cosf(TB_PI / 6.0f), 10.0f * sinf(TB_PI / 6.0f)}};
	tbCreateSegmentShape(ground, &shapeDef, &ramp);
	return world;
}

typedef struct Planes
{
	tbCollisionPlane planes[8];
	int count;
} Planes;

static bool CollectPlane(tbShapeId shapeId, const tbPlaneResult* result, void* context)
{
	(void)shapeId;
	Planes* p = context;
	if (p->count < 8)
	{
		p->planes[p->count++] = (tbCollisionPlane){result->plane, FLT_MAX, 0.0f, true};
	}
	return true;
}

/// One frame of a mover character, as a game runs it: the planes around it, the motion they
/// allow toward the target, the sweep of that motion (a few rounds, as the planes change on the
/// way), and the velocity clipped by the planes. Returns the new position (capsule origin).
static tbVec2 MoverFrame(tbWorldId world, tbVec2 position, const tbCapsule* capsule, tbVec2* velocity, float dt)
{
	tbQueryFilter filter = tbDefaultQueryFilter();
	tbVec2 target = tbMulAdd(position, dt, *velocity);
	Planes planes = {0};
	for (int round = 0; round < 5; ++round)
	{
		planes.count = 0;
		cr_assert(tbWorld_CollideMover(world, position, capsule, filter, CollectPlane, &planes));
		tbPlaneSolverResult solved = tbSolvePlanes(tbSub(target, position), planes.planes, planes.count);
		float fraction = tbWorld_CastMover(world, position, capsule, solved.delta, filter);
		tbVec2 step = tbMulSV(fraction, solved.delta);
		position = tbAdd(position, step);
		if (tbLengthSquared(step) < TB_LINEAR_SLOP * TB_LINEAR_SLOP)
		{
			break;
		}
	}
	*velocity = tbClipVector(*velocity, planes.planes, planes.count);
	return position;
}

// Walking at 3 m/s under gravity on level ground for 2 s covers 6 m and stays on the ground; then
// the wall stops it (its side at x = 10, so the capsule's centre line stops at 10 − r), and it
// never sinks: the plane solver allows a slop's overlap, no more.
Test(mover, character_walks_stops_at_a_wall_and_climbs_a_slope)
{
	tbWorldId world = MakeLevel();
	const float r = 0.3f, dt = 1.0f / 60.0f, g = 10.0f, speed = 3.0f;
	tbCapsule capsule = {{0.0f, r}, {0.0f, r + 1.0f}, r}; // relative to the character's feet point
	tbVec2 position = {0.0f, 0.0f};
	tbVec2 velocity = {speed, 0.0f};
	for (int i = 0; i < 120; ++i)
	{
		velocity.x = speed;
		velocity.y -= g * dt;
		position = MoverFrame(world, position, &capsule, &velocity, dt);
		cr_assert_geq(position.y, -TB_LINEAR_SLOP - 1e-4f, "sank to %.5f at frame %d", (double)position.y, i);
		cr_assert_leq(position.y, 1e-3f, "left the ground: %.5f at frame %d", (double)position.y, i);
	}
	cr_expect_float_eq(position.x, 2.0f * speed, 0.01f, "walked to x = %.4f in 2 s", (double)position.x);

	for (int i = 0; i < 120; ++i)
	{
		velocity.x = speed;
		velocity.y -= g * dt;
		position = MoverFrame(world, position, &capsule, &velocity, dt);
	}
	cr_expect_float_eq(position.x, 10.0f - r, TB_LINEAR_SLOP + 1e-4f, "stopped at x = %.4f at the wall",
					   (double)position.x);
	cr_expect_float_eq(position.y, 0.0f, TB_LINEAR_SLOP + 1e-4f);
	cr_expect_float_eq(velocity.x, 0.0f, 1e-6f, "velocity into the wall clipped: %.4f", (double)velocity.x);

	// Over the wall (placed beyond it) and up the 30° ramp: the capsule's bottom circle rests on
	// the ramp, its centre r / cos 30° above the ramp line at its x (within the slop).
	position = (tbVec2){12.0f, 0.0f};
	velocity = (tbVec2){speed, 0.0f};
	for (int i = 0; i < 150; ++i)
	{
		velocity.x = speed;
		velocity.y -= g * dt;
		position = MoverFrame(world, position, &capsule, &velocity, dt);
	}
	float rampY = (position.x - 15.0f) * tanf(TB_PI / 6.0f);
	float centreY = position.y + r;
	cr_expect_gt(position.x, 16.0f, "climbed to x = %.3f", (double)position.x);
	cr_expect_float_eq(centreY, rampY + r / cosf(TB_PI / 6.0f), 2.0f * TB_LINEAR_SLOP, "centre %.4f, ramp %.4f",
					   (double)centreY, (double)rampY);
	tbDestroyWorld(world);
}

// The sweep: a capsule 1 m above the floor moved 2 m down gets half way (less the speculative
// closeness it may keep: within a slop of 0.5); one starting inside a shape ignores it.
Test(mover, cast_mover_stops_at_the_first_shape_and_ignores_initial_overlap)
{
	tbWorldId world = MakeLevel();
	tbCapsule capsule = {{0.0f, 0.3f}, {0.0f, 1.3f}, 0.3f};
	float fraction = tbWorld_CastMover(world, (tbPos){0.0f, 1.0f}, &capsule, (tbVec2){0.0f, -2.0f},
									   tbDefaultQueryFilter());
	cr_expect_float_eq(fraction, 0.5f, TB_LINEAR_SLOP / 2.0f + 1e-4f, "fraction %.5f", (double)fraction);
	float inside = tbWorld_CastMover(world, (tbPos){10.5f, 0.5f}, &capsule, (tbVec2){-3.0f, 0.0f},
									 tbDefaultQueryFilter());
	cr_expect_eq(inside, 1.0f);
	tbDestroyWorld(world);
}

Test(mover, bad_mover_input_is_refused, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = MakeLevel();
	tbCapsule capsule = {{0.0f, 0.3f}, {0.0f, 1.3f}, 0.3f};
	Planes planes = {0};
	tbQueryFilter filter = tbDefaultQueryFilter();
	int before = s_errors;
	cr_expect_not(tbWorld_CollideMover(world, tbPos_zero, NULL, filter, CollectPlane, &planes));
	ExpectError(before, "tbWorld_CollideMover", "mover");
	before = s_errors;
	cr_expect_not(tbWorld_CollideMover(world, tbPos_zero, &capsule, filter, NULL, NULL));
	ExpectError(before, "tbWorld_CollideMover", "fcn");
	tbCapsule thin = {{0.0f, 0.3f}, {0.0f, 1.3f}, TB_LINEAR_SLOP};
	before = s_errors;
	cr_expect_eq(tbWorld_CastMover(world, tbPos_zero, &thin, (tbVec2){1.0f, 0.0f}, filter), 0.0f);
	ExpectError(before, "tbWorld_CastMover", "radius");
	before = s_errors;
	cr_expect_eq(tbWorld_CastMover(world, (tbPos){NAN, 0.0f}, &capsule, (tbVec2){1.0f, 0.0f}, filter), 0.0f);
	ExpectError(before, "tbWorld_CastMover", "origin");
	before = s_errors;
	cr_expect_eq(tbWorld_CastMover(world, tbPos_zero, &capsule, (tbVec2){INFINITY, 0.0f}, filter), 0.0f);
	ExpectError(before, "tbWorld_CastMover", "translation");
	cr_expect_eq(planes.count, 0);
	before = s_errors;
	tbSolvePlanes((tbVec2){1.0f, 0.0f}, NULL, 2);
	ExpectError(before, "tbSolvePlanes", "planes");
	before = s_errors;
	tbVec2 v = tbClipVector((tbVec2){1.0f, 0.0f}, NULL, 1);
	ExpectError(before, "tbClipVector", "planes");
	cr_expect_eq(v.x, 1.0f);
	before = s_errors;
	tbPlaneResult none = tbCollideMover(NULL, NULL, tbTransform_identity);
	ExpectError(before, "tbCollideMover", "mover");
	cr_expect_not(none.hit);
	tbDestroyWorld(world);
}
