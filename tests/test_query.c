// World queries: ray casts (closest and all hits with clipping), AABB, point and shape overlap,
// shape casts, and query filters. Expected answers are hand-computed from the scene geometry.
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include "error_recorder.h"
#include "test_helpers.h"

#include <math.h>
#include <string.h>

/// Ground box top at y = 0 from x = −10 to 10; a unit box centred at (3, 0.5) resting on it (category 2);
/// a circle of radius 0.5 at (−3, 2) (category 4).
typedef struct Scene
{
	tbWorldId world;
	tbShapeId ground, box, ball;
} Scene;

static Scene MakeScene(void)
{
	Scene s;
	tbWorldDef def = tbDefaultWorldDef();
	s.world = tbCreateWorld(&def);
	tbBodyDef bd = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(s.world, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	tbPolygon groundBox = tbMakeOffsetBox(10.0f, 1.0f, tbMakeVec2(0.0f, -1.0f), tbRot_identity);
	s.ground = tbCreatePolygonShape(ground, &sd, &groundBox);

	bd.type = tb_dynamicBody;
	bd.position = tbMakeVec2(3.0f, 0.5f);
	tbBodyId box = tbCreateBody(s.world, &bd);
	sd.filter.categoryBits = 2;
	tbPolygon square = tbMakeSquare(0.5f);
	s.box = tbCreatePolygonShape(box, &sd, &square);

	bd.position = tbMakeVec2(-3.0f, 2.0f);
	tbBodyId ball = tbCreateBody(s.world, &bd);
	sd.filter.categoryBits = 4;
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	s.ball = tbCreateCircleShape(ball, &sd, &circle);
	return s;
}

Test(query, ray_closest_hits_box_face)
{
	// A ray from (0, 0.5) to (10, 0.5) meets the box's left face x = 2.5 at fraction 0.25.
	Scene s = MakeScene();
	tbRayResult r = tbWorld_CastRayClosest(s.world, tbMakeVec2(0.0f, 0.5f), tbMakeVec2(10.0f, 0.0f), tbDefaultQueryFilter());
	cr_assert(r.hit);
	cr_assert(TB_ID_EQUALS(r.shapeId, s.box));
	cr_assert_float_eq(r.fraction, 0.25f, 1e-6f);
	cr_assert_float_eq(r.point.x, 2.5f, 1e-5f);
	cr_assert_float_eq(r.normal.x, -1.0f, 1e-6f);
	tbDestroyWorld(s.world);
}

Test(query, ray_closest_hits_circle_then_ground)
{
	// Straight down through the circle centre at x = −3: top of the circle y = 2.5 from origin y = 5
	// over a 10 m ray is fraction 0.25; with the circle filtered out, the ground at y = 0 (0.5).
	Scene s = MakeScene();
	tbRayResult r = tbWorld_CastRayClosest(s.world, tbMakeVec2(-3.0f, 5.0f), tbMakeVec2(0.0f, -10.0f), tbDefaultQueryFilter());
	cr_assert(r.hit && TB_ID_EQUALS(r.shapeId, s.ball));
	cr_assert_float_eq(r.fraction, 0.25f, 1e-6f);
	cr_assert_float_eq(r.normal.y, 1.0f, 1e-6f);
	tbQueryFilter noBalls = {TB_DEFAULT_CATEGORY_BITS, ~(uint64_t)4};
	r = tbWorld_CastRayClosest(s.world, tbMakeVec2(-3.0f, 5.0f), tbMakeVec2(0.0f, -10.0f), noBalls);
	cr_assert(r.hit && TB_ID_EQUALS(r.shapeId, s.ground));
	cr_assert_float_eq(r.fraction, 0.5f, 1e-6f);
	tbDestroyWorld(s.world);
}

typedef struct Hits
{
	int count;
	float fractions[8];
	float returnValue; // what the callback returns: 1 continue, 0 stop, −1 ignore, fraction clip
} Hits;

static float CollectHit(tbShapeId shapeId, tbPos point, tbVec2 normal, float fraction, void* context)
{
	(void)shapeId;
	(void)point;
	(void)normal;
	Hits* hits = context;
	if (hits->count < 8)
	{
		hits->fractions[hits->count] = fraction;
	}
	hits->count += 1;
	return hits->returnValue < -0.5f ? -1.0f : (hits->returnValue > 0.5f ? 1.0f : hits->returnValue);
}

Test(query, ray_all_hits_continue_and_stop)
{
	// A horizontal ray at y = 0.25 from x = −20 to 20 crosses the ball? No (ball spans y 1.5..2.5);
	// it crosses the box (x 2.5..3.5) only. At y = −0.5 it starts outside the ground (x −20) and
	// enters the ground at x = −10 (fraction 0.25).
	Scene s = MakeScene();
	Hits hits = {0, {0}, 1.0f};
	tbWorld_CastRay(s.world, tbMakeVec2(-20.0f, 0.25f), tbMakeVec2(40.0f, 0.0f), tbDefaultQueryFilter(), CollectHit, &hits);
	cr_assert_eq(hits.count, 1);
	cr_assert_float_eq(hits.fractions[0], (2.5f + 20.0f) / 40.0f, 1e-6f);
	Hits ground = {0, {0}, 1.0f};
	tbWorld_CastRay(s.world, tbMakeVec2(-20.0f, -0.5f), tbMakeVec2(40.0f, 0.0f), tbDefaultQueryFilter(), CollectHit, &ground);
	cr_assert_eq(ground.count, 1);
	cr_assert_float_eq(ground.fractions[0], 0.25f, 1e-6f);
	// A ray through ball (top) and then box is impossible; use a diagonal hitting both ball and ground:
	// from (−3, 5) down: ball at 0.25 and ground at 0.5. With "continue" both are reported.
	Hits both = {0, {0}, 1.0f};
	tbWorld_CastRay(s.world, tbMakeVec2(-3.0f, 5.0f), tbMakeVec2(0.0f, -10.0f), tbDefaultQueryFilter(), CollectHit, &both);
	cr_assert_eq(both.count, 2);
	// With "stop" (return 0) exactly one is reported.
	Hits stop = {0, {0}, 0.0f};
	tbWorld_CastRay(s.world, tbMakeVec2(-3.0f, 5.0f), tbMakeVec2(0.0f, -10.0f), tbDefaultQueryFilter(), CollectHit, &stop);
	cr_assert_eq(stop.count, 1);
	tbDestroyWorld(s.world);
}

Test(query, overlap_aabb_point_and_shape)
{
	Scene s = MakeScene();
	// A box around the ball only (fat boxes are 0.1 m larger than the ball's tight box [−3.5, −2.5]×[1.5, 2.5]).
	int count = 0;
	tbAABB box = {{-4.0f, 1.0f}, {-2.0f, 3.0f}};
	tbWorld_OverlapAABB(s.world, tbPos_zero, box, tbDefaultQueryFilter(), CountOverlap, &count);
	cr_assert_eq(count, 1);
	// A box covering everything finds all three shapes.
	count = 0;
	tbAABB all = {{-20.0f, -5.0f}, {20.0f, 5.0f}};
	tbWorld_OverlapAABB(s.world, tbPos_zero, all, tbDefaultQueryFilter(), CountOverlap, &count);
	cr_assert_eq(count, 3);
	// Point inside the box body (3, 0.5) and one just outside its corner (3.6, 1.1).
	count = 0;
	tbWorld_OverlapPoint(s.world, tbMakeVec2(3.0f, 0.5f), tbDefaultQueryFilter(), CountOverlap, &count);
	cr_assert_eq(count, 1);
	count = 0;
	tbWorld_OverlapPoint(s.world, tbMakeVec2(3.6f, 1.1f), tbDefaultQueryFilter(), CountOverlap, &count);
	cr_assert_eq(count, 0);
	// A circle of radius 0.3 at (−3, 2.7) overlaps the ball (centre distance 0.7 < 0.8); at (−3, 2.9) it does not (0.9 > 0.8).
	// The probe is a proxy (one point, radius 0.3) measured from the query's origin: once in world
	// points from the world's origin, once as a point at the origin placed by the origin.
	tbVec2 centre = {-3.0f, 2.7f};
	tbShapeProxy probe = tbMakeProxy(&centre, 1, 0.3f);
	count = 0;
	tbWorld_OverlapShape(s.world, tbPos_zero, &probe, tbDefaultQueryFilter(), CountOverlap, &count);
	cr_assert_eq(count, 1);
	tbVec2 zero = {0.0f, 0.0f};
	tbShapeProxy atOrigin = tbMakeProxy(&zero, 1, 0.3f);
	count = 0;
	tbWorld_OverlapShape(s.world, (tbPos){-3.0f, 2.9f}, &atOrigin, tbDefaultQueryFilter(), CountOverlap, &count);
	cr_assert_eq(count, 0);
	tbDestroyWorld(s.world);
}

static float ClosestCast(tbShapeId shapeId, tbPos point, tbVec2 normal, float fraction, void* context)
{
	(void)point;
	(void)normal;
	tbRayResult* r = context;
	r->shapeId = shapeId;
	r->fraction = fraction;
	r->hit = true;
	return fraction;
}

Test(query, shape_cast_circle_onto_box)
{
	// A circle of radius 0.25 at (0, 0.5) moving +10 m in x touches the box's left face x = 2.5
	// when its centre reaches x = 2.25: fraction 0.225 (shape casts stop within a linear slop).
	Scene s = MakeScene();
	tbVec2 zero = {0.0f, 0.0f};
	tbShapeProxy probe = tbMakeProxy(&zero, 1, 0.25f);
	tbRayResult r;
	memset(&r, 0, sizeof(r));
	tbQueryFilter onlyBox = {TB_DEFAULT_CATEGORY_BITS, 2};
	tbWorld_CastShape(s.world, (tbPos){0.0f, 0.5f}, &probe, tbMakeVec2(10.0f, 0.0f), onlyBox, ClosestCast, &r);
	cr_assert(r.hit && TB_ID_EQUALS(r.shapeId, s.box));
	cr_assert_float_eq(r.fraction, 0.225f, TB_LINEAR_SLOP / 10.0f);
	tbDestroyWorld(s.world);
}

// v3.2's forms: tbShape_RayCast from an origin and a translation (the box's left face x = 2.5,
// from (0, 0.5) by 10 m: fraction 0.25, point (2.5, 0.5), normal −x); tbWorld_OverlapAABB with a box
// measured from an origin (the unit box at (3, 0.5): a 0.2 m box around it found, one 1 m off not).
Test(query, ray_cast_one_shape_and_box_from_an_origin)
{
	Scene s = MakeScene();
	tbWorldCastOutput hit = tbShape_RayCast(s.box, (tbPos){0.0f, 0.5f}, tbMakeVec2(10.0f, 0.0f));
	cr_assert(hit.hit);
	cr_expect_float_eq(hit.fraction, 0.25f, 1e-6f);
	cr_expect_float_eq(hit.point.x, 2.5f, 1e-6f);
	cr_expect_float_eq(hit.point.y, 0.5f, 1e-6f);
	cr_expect_float_eq(hit.normal.x, -1.0f, 1e-6f);
	cr_expect_not(tbShape_RayCast(s.box, (tbPos){0.0f, 3.0f}, tbMakeVec2(10.0f, 0.0f)).hit); // passes above
	tbQueryFilter onlyBox = {TB_DEFAULT_CATEGORY_BITS, 2};
	tbAABB small = {{-0.1f, -0.1f}, {0.1f, 0.1f}};
	int count = 0;
	tbWorld_OverlapAABB(s.world, (tbPos){3.0f, 0.5f}, small, onlyBox, CountOverlap, &count);
	cr_expect_eq(count, 1);
	count = 0;
	tbWorld_OverlapAABB(s.world, (tbPos){5.0f, 0.5f}, small, onlyBox, CountOverlap, &count);
	cr_expect_eq(count, 0);
	tbDestroyWorld(s.world);
}

Test(query, bad_query_input_rejected)
{
	Scene s = MakeScene();
	int before = tbGetErrorCount();
	tbRayResult r = tbWorld_CastRayClosest(s.world, tbMakeVec2(NAN, 0.0f), tbMakeVec2(1.0f, 0.0f), tbDefaultQueryFilter());
	cr_assert_not(r.hit);
	tbAABB bad = {{1.0f, 1.0f}, {0.0f, 0.0f}};
	int count = 0;
	cr_assert(tbWorld_OverlapAABB(s.world, tbPos_zero, bad, tbDefaultQueryFilter(), CountOverlap, &count).leafVisits == 0);
	cr_assert_not(tbWorld_OverlapPoint(s.world, tbMakeVec2(0.0f, 0.0f), tbDefaultQueryFilter(), NULL, NULL));
	cr_assert_eq(tbGetErrorCount(), before + 3);
	cr_assert_eq(count, 0);
	tbDestroyWorld(s.world);
}

// --- what a query callback may change ------------------------------------------------------------

typedef struct BlastContext
{
	tbVec2 centre;
	float impulse; ///< N·s given to each dynamic body, away from the centre
	int pushed;
	int refusedMoves;
} BlastContext;

static bool BlastCallback(tbShapeId shapeId, void* context)
{
	BlastContext* c = context;
	tbBodyId body = tbShape_GetBody(shapeId);
	if (tbBody_GetType(body) != tb_dynamicBody)
	{
		return true;
	}
	tbVec2 away = tbNormalize(tbSub(tbBody_GetWorldCenter(body), c->centre));
	tbBody_ApplyLinearImpulseToCenter(body, tbMulSV(c->impulse, away), true);
	tbBody_SetAngularVelocity(body, 1.0f);
	c->pushed += 1;
	// Moving it would move the broad-phase node the query is walking: refused, nothing changed.
	tbVec2 before = tbBody_GetPosition(body);
	if (tbBody_SetTransform(body, tbMakeVec2(50.0f, 50.0f), tbRot_identity) == false)
	{
		c->refusedMoves += 1;
	}
	cr_assert(tbBody_GetPosition(body).x == before.x && tbBody_GetPosition(body).y == before.y);
	return true;
}

// An explosion written in a query callback, as a game does it: each dynamic body in the blast box
// receives an impulse P away from the centre inside the callback, so its speed is exactly P/m
// (box: 1 kg, 1 m²; ball: π·0.25 kg) and its angular velocity the 1 rad/s set there; the
// SetTransform tried in the same callback is refused with a message that says why, and the body
// stays where it was. (Box2D v3 allows the same: changes that do not touch the broad phase.)
Test(query, callback_may_apply_impulses_but_not_move_bodies, .init = SetupErrors, .fini = TeardownErrors)
{
	Scene s = MakeScene();
	BlastContext c = {tbMakeVec2(0.0f, 0.0f), 2.0f, 0, 0};
	tbAABB blast = {{-5.0f, -0.5f}, {5.0f, 5.0f}};
	int before = s_errors;
	cr_assert(tbWorld_OverlapAABB(s.world, tbPos_zero, blast, tbDefaultQueryFilter(), BlastCallback, &c).leafVisits > 0);
	cr_assert_eq(c.pushed, 2, "the box and the ball are in the blast");
	cr_assert_eq(c.refusedMoves, 2);
	cr_assert_eq(s_errors, before + 2);
	cr_assert(strstr(s_lastError, "tbBody_SetTransform") != NULL && strstr(s_lastError, "query callback") != NULL,
			  "message '%s'", s_lastError);
	tbBodyId box = tbShape_GetBody(s.box), ball = tbShape_GetBody(s.ball);
	float boxSpeed = tbLength(tbBody_GetLinearVelocity(box));
	float ballSpeed = tbLength(tbBody_GetLinearVelocity(ball));
	cr_assert_float_eq(boxSpeed, 2.0f / tbBody_GetMass(box), 1e-5f);
	cr_assert_float_eq(ballSpeed, 2.0f / tbBody_GetMass(ball), 1e-5f);
	cr_assert_float_eq(tbBody_GetMass(ball), 3.14159265f * 0.25f, 1e-5f);
	cr_assert_float_eq(tbBody_GetAngularVelocity(box), 1.0f, 1e-6f);
	cr_assert(tbBody_GetLinearVelocity(box).x > 0.0f && tbBody_GetLinearVelocity(ball).x < 0.0f, "pushed apart");
	// After the query the world takes structural changes again.
	cr_assert(tbBody_SetTransform(box, tbMakeVec2(3.0f, 3.0f), tbRot_identity));
	tbDestroyWorld(s.world);
}
