// Manifold recycling (contact.c, tbRecycleManifold): a touching pair that barely moved since its
// manifold was computed keeps its points and only updates their separations.
//
// Set-up: no gravity, a static ground box whose top face is y = 0 and a dynamic box hovering a gap
// g = 0.01 m above it, square to it. The narrow phase gives two speculative points (g is inside
// the 0.02 m speculative distance) and, the bodies being at rest and apart, the solver applies no
// impulse, so the step leaves them where they were. The box is then moved by hand and the contact
// updated directly (tbUpdateContact, as the collide stage does), so the comparison with a fresh
// manifold sees exactly the transforms the update saw.
//
// Where the tolerance comes from (contact.c): a recycled separation is s0 + (xB − xA)·n with xA,
// xB the two bodies' material points that coincided when the manifold was computed and n the kept
// normal, the one the narrow phase gave (the normal and the anchors are kept, not turned with the
// bodies). The ground's face is the reference, so the kept normal is the true one here; the bound
// below still allows it to be off by half the box's turn θ: |xB − xA|·sin(θ/2) plus
// s0·(1 − cos(θ/2)) ≤ s0·θ²/8, with |xB − xA| ≤ |Δp| + θ·maxExtent (translation of the box's
// centre plus the arc of its farthest point). Float rounding of the transforms adds a few 1e-7 m;
// 1e-6 m covers it.
#include "world/world.h"

#include <criterion/criterion.h>

#include <math.h>

#define GAP 0.01f

typedef struct Pair
{
	tbWorldId worldId;
	tbBodyId box;
	tbWorld* world;
	tbContact* contact;
	float halfSize;
} Pair;

static tbContact* OnlyContact(tbWorld* world)
{
	for (int id = 0; id < world->contactPool.highWater; ++id)
	{
		if (world->contacts[id].inUse)
		{
			return world->contacts + id;
		}
	}
	return NULL;
}

/// Ground box (top face y = 0) and a dynamic box of half size h hovering GAP above it (or a circle
/// of radius h when `circle`); one step computes the first manifold.
static Pair MakePair(float h, bool circle, bool recycling)
{
	Pair p;
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbMakeVec2(0.0f, 0.0f);
	def.enableManifoldRecycling = recycling;
	p.worldId = tbCreateWorld(&def);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.position = tbMakeVec2(0.0f, -0.5f);
	tbBodyId ground = tbCreateBody(p.worldId, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	tbPolygon groundBox = tbMakeBox(5.0f, 0.5f);
	tbCreatePolygonShape(ground, &sd, &groundBox);
	bd.type = tb_dynamicBody;
	bd.position = tbMakeVec2(0.0f, h + GAP);
	p.box = tbCreateBody(p.worldId, &bd);
	if (circle)
	{
		tbCircle c = {{0.0f, 0.0f}, h};
		tbCreateCircleShape(p.box, &sd, &c);
	}
	else
	{
		tbPolygon box = tbMakeBox(h, h);
		tbCreatePolygonShape(p.box, &sd, &box);
	}
	tbWorld_Step(p.worldId, 1.0f / 60.0f, 4);
	p.world = tbGetWorldChecked(p.worldId, "test");
	p.contact = OnlyContact(p.world);
	p.halfSize = h;
	cr_assert_not_null(p.contact);
	cr_assert_eq(p.contact->manifold.pointCount, circle ? 1 : 2);
	tbVec2 position = tbBody_GetPosition(p.box);
	cr_assert_float_eq(position.y, h + GAP, 1e-7f, "the speculative points must not move the box");
	return p;
}

/// Move the box by (dx, dy) and turn it by angle, then update the contact as the collide stage
/// does. Returns true when the manifold was recycled.
static bool MoveAndUpdate(Pair* p, float dx, float dy, float angle)
{
	tbBody_SetTransform(p->box, tbMakeVec2(dx, p->halfSize + GAP + dy), tbMakeRot(angle));
	int before = p->world->counters.recycledContactCount;
	bool began = false;
	tbUpdateContact(p->world, p->contact, &began);
	return p->world->counters.recycledContactCount == before + 1;
}

/// The manifold the narrow phase computes now, with the margin the update used (at rest: the
/// speculative distance).
static tbManifold FreshManifold(const Pair* p)
{
	const tbShape* a = p->world->shapes + p->contact->shapeIdA;
	const tbShape* b = p->world->shapes + p->contact->shapeIdB;
	return tbCollideShapesWithMargin(&a->geometry, p->world->bodies[a->bodyId].transform, &b->geometry,
									 p->world->bodies[b->bodyId].transform, p->world->def.narrowPhase,
									 TB_SPECULATIVE_DISTANCE);
}

Test(contact, recycled_separation_matches_recomputed_for_small_motion)
{
	Pair p = MakePair(0.5f, false, true);
	float dx = 0.004f, dy = -0.003f, theta = 0.5f * TB_PI / 180.0f;
	tbManifold before = p.contact->manifold;
	cr_assert(MoveAndUpdate(&p, dx, dy, theta), "a 5 mm move and 0.5 degree turn must be recycled");
	tbManifold fresh = FreshManifold(&p);
	const tbManifold* kept = &p.contact->manifold;
	cr_assert_eq(fresh.pointCount, 2);
	float maxExtent = sqrtf(2.0f) * p.halfSize;
	float motion = sqrtf(dx * dx + dy * dy) + theta * maxExtent;
	float tolerance = motion * sinf(0.5f * theta) + GAP * theta * theta / 8.0f + 1e-6f;
	int matched = 0;
	for (int i = 0; i < kept->pointCount; ++i)
	{
		for (int j = 0; j < fresh.pointCount; ++j)
		{
			if (fresh.points[j].id == kept->points[i].id)
			{
				cr_expect_float_eq(kept->points[i].separation, fresh.points[j].separation, tolerance,
								   "point %d: recycled %.7f, recomputed %.7f, tolerance %.2e", i,
								   (double)kept->points[i].separation, (double)fresh.points[j].separation,
								   (double)tolerance);
				matched += 1;
			}
		}
	}
	cr_assert_eq(matched, 2, "the recycled points keep the feature ids the narrow phase gives");
	// The normal and the anchors (lever arms) are kept as the narrow phase gave them: lever arms that
	// turned with the small rocking of soft contacts would let a tall stack buckle (contact.c).
	cr_expect_eq(kept->normal.x, before.normal.x);
	cr_expect_eq(kept->normal.y, before.normal.y);
	for (int i = 0; i < kept->pointCount; ++i)
	{
		cr_expect_eq(kept->points[i].anchorA.x, before.points[i].anchorA.x);
		cr_expect_eq(kept->points[i].anchorA.y, before.points[i].anchorA.y);
		cr_expect_eq(kept->points[i].anchorB.x, before.points[i].anchorB.x);
		cr_expect_eq(kept->points[i].anchorB.y, before.points[i].anchorB.y);
	}
	// The separations moved: the turn lowered one corner and raised the other.
	cr_expect(fabsf(kept->points[0].separation - kept->points[1].separation) > 0.008f);
	tbDestroyWorld(p.worldId);
}

Test(contact, recomputed_past_the_distance_threshold)
{
	// 0.025 m sideways: every point of the box moved farther than TB_RECYCLE_DISTANCE (0.02 m).
	Pair p = MakePair(0.5f, false, true);
	cr_assert_not(MoveAndUpdate(&p, 0.025f, 0.0f, 0.0f));
	tbManifold fresh = FreshManifold(&p);
	const tbManifold* m = &p.contact->manifold;
	cr_assert_eq(m->pointCount, fresh.pointCount);
	for (int i = 0; i < m->pointCount; ++i)
	{
		cr_expect_eq(m->points[i].id, fresh.points[i].id);
		cr_expect_eq(m->points[i].separation, fresh.points[i].separation, "recomputed: the same numbers");
	}
	// Below the threshold the same move is recycled: 0.015 m < 0.02 m.
	Pair q = MakePair(0.5f, false, true);
	cr_expect(MoveAndUpdate(&q, 0.015f, 0.0f, 0.0f));
	tbDestroyWorld(p.worldId);
	tbDestroyWorld(q.worldId);
}

Test(contact, recomputed_past_the_angle_threshold)
{
	// A 0.1 m box turning 3 degrees: its corners move 0.0707 × 0.052 = 0.0037 m, well inside the
	// distance threshold, but the turn exceeds TB_RECYCLE_ANGLE (2 degrees).
	Pair p = MakePair(0.05f, false, true);
	cr_assert_not(MoveAndUpdate(&p, 0.0f, 0.0f, 3.0f * TB_PI / 180.0f));
	Pair q = MakePair(0.05f, false, true);
	cr_expect(MoveAndUpdate(&q, 0.0f, 0.0f, 1.5f * TB_PI / 180.0f));
	tbDestroyWorld(p.worldId);
	tbDestroyWorld(q.worldId);
}

Test(contact, recomputed_when_the_pair_turns_together)
{
	// The ground and the box turned together about the origin: their relative pose is unchanged, so
	// only each body's own turn since the narrow phase (5 degrees at most, contact.c) decides. Past
	// it the kept normal and lever arms would be too far off and the manifold is computed anew.
	for (int k = 0; k < 2; ++k)
	{
		float angle = (k == 0 ? 4.0f : 6.0f) * TB_PI / 180.0f;
		Pair p = MakePair(0.5f, false, true);
		tbRot q = tbMakeRot(angle);
		tbBodyId ground = tbShape_GetBody(tbMakeShapeId(p.world, p.contact->shapeIdA));
		tbBody_SetTransform(ground, tbRotateVector(q, tbMakeVec2(0.0f, -0.5f)), q);
		tbBody_SetTransform(p.box, tbRotateVector(q, tbMakeVec2(0.0f, p.halfSize + GAP)), q);
		int before = p.world->counters.recycledContactCount;
		bool began = false;
		tbUpdateContact(p.world, p.contact, &began);
		bool recycled = p.world->counters.recycledContactCount == before + 1;
		cr_expect(recycled == (k == 0), "turned together by %.0f degrees: %s", (double)(angle * 180.0f / TB_PI),
				  recycled ? "recycled" : "recomputed");
		tbDestroyWorld(p.worldId);
	}
}

Test(contact, round_pairs_recycle_under_the_same_bounds_and_disabled_recycling_recomputes)
{
	// A circle on a face is recycled as a box is, within the relative motion allowed (the recycle
	// distance, 0.02 m): 1 mm sideways keeps the manifold, and the kept normal is the one the narrow
	// phase gives (the face's); 25 mm from the base is beyond the allowance.
	// A sideways slide over a flat face leaves the separation as it was: the kept one must equal the
	// fresh one to float rounding of positions near 1 m (1e-6 m), the normals to rounding of a unit
	// vector (1e-6).
	Pair circle = MakePair(0.5f, true, true);
	cr_expect(MoveAndUpdate(&circle, 0.001f, 0.0f, 0.0f));
	tbManifold fresh = FreshManifold(&circle);
	cr_assert_eq(fresh.pointCount, 1);
	cr_expect_float_eq(circle.contact->manifold.normal.y, fresh.normal.y, 1e-6f);
	cr_expect_float_eq(circle.contact->manifold.points[0].separation, fresh.points[0].separation, 1e-6f);
	cr_expect_not(MoveAndUpdate(&circle, 0.025f, 0.0f, 0.0f));
	// Recycling off in the definition, then on again through the setter.
	Pair off = MakePair(0.5f, false, false);
	cr_expect_not(MoveAndUpdate(&off, 0.001f, 0.0f, 0.0f));
	tbWorld_EnableManifoldRecycling(off.worldId, true);
	cr_expect(tbWorld_GetDef(off.worldId).enableManifoldRecycling);
	// The base was stored by the last (recomputing) update, 1 mm away.
	cr_expect(MoveAndUpdate(&off, 0.002f, 0.0f, 0.0f));
	tbDestroyWorld(circle.worldId);
	tbDestroyWorld(off.worldId);
}

// Pairs apart (contact.c, tbStaysApart): a contact the narrow phase found apart keeps its empty
// manifold, without the narrow phase, while the bodies cannot have come within the margin. The claim
// is exactness: at every step of a falling pile of circles, capsules and boxes, each contact that
// holds an apart base is updated twice on copies, as the collide stage would (kept) and with the base
// dropped (the narrow phase runs); the two manifolds must be the same bytes. No tolerance: the
// keeping is exact by construction (the bound is a true lower bound on the distance).
Test(contact, a_pair_kept_apart_gets_the_manifold_the_narrow_phase_would_give)
{
	tbWorldDef def = tbDefaultWorldDef();
	tbWorldId worldId = tbCreateWorld(&def);
	tbBodyDef bd = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(worldId, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	tbPolygon floor = tbMakeOffsetBox(8.0f, 0.5f, tbMakeVec2(0.0f, -0.5f), tbMakeRot(0.0f));
	tbCreatePolygonShape(ground, &sd, &floor);
	bd.type = tb_dynamicBody;
	for (int i = 0; i < 60; ++i)
	{
		bd.position = tbMakeVec2(-5.0f + 1.1f * (float)(i % 10), 1.0f + 1.1f * (float)(i / 10));
		bd.rotation = tbMakeRot(0.3f * (float)i);
		tbBodyId body = tbCreateBody(worldId, &bd);
		if (i % 3 == 0)
		{
			tbCircle circle = {{0.0f, 0.0f}, 0.45f};
			tbCreateCircleShape(body, &sd, &circle);
		}
		else if (i % 3 == 1)
		{
			tbCapsule capsule = {{-0.3f, 0.0f}, {0.3f, 0.0f}, 0.2f};
			tbCreateCapsuleShape(body, &sd, &capsule);
		}
		else
		{
			tbPolygon box = tbMakeBox(0.4f, 0.4f);
			tbCreatePolygonShape(body, &sd, &box);
		}
	}
	tbWorld* world = tbGetWorldChecked(worldId, "test");
	int compared = 0, kept = 0;
	for (int step = 0; step < 240; ++step)
	{
		tbWorld_Step(worldId, 1.0f / 60.0f, 4);
		tbCounters saved = world->counters;
		for (int id = 0; id < world->contactPool.highWater; ++id)
		{
			const tbContact* contact = world->contacts + id;
			if (contact->inUse == false || (contact->flags & tb_contactApart) == 0)
			{
				continue;
			}
			tbContact asKept = *contact, recomputed = *contact;
			recomputed.flags &= ~(uint32_t)tb_contactApart;
			bool began = false;
			int before = world->counters.keptApartCount;
			tbUpdateContact(world, &asKept, &began);
			kept += world->counters.keptApartCount - before;
			tbUpdateContact(world, &recomputed, &began);
			// Field by field (the points beyond pointCount are unused); a pair not kept ran the
			// narrow phase in both copies.
			const tbManifold* r = &recomputed.manifold;
			const tbManifold* k = &asKept.manifold;
			cr_assert_eq(r->pointCount, k->pointCount, "step %d contact %d", step, id);
			cr_assert(r->normal.x == k->normal.x && r->normal.y == k->normal.y && r->rollingImpulse == k->rollingImpulse,
					  "step %d contact %d: the kept manifold differs from the narrow phase's", step, id);
			for (int i = 0; i < r->pointCount; ++i)
			{
				const tbManifoldPoint* pr = r->points + i;
				const tbManifoldPoint* pk = k->points + i;
				cr_assert(pr->id == pk->id && pr->separation == pk->separation && pr->anchorA.x == pk->anchorA.x &&
							  pr->anchorA.y == pk->anchorA.y && pr->normalImpulse == pk->normalImpulse,
						  "step %d contact %d point %d differs", step, id, i);
			}
			cr_assert_eq(recomputed.flags & ~(uint32_t)(tb_contactApart | tb_contactRecycled),
						 asKept.flags & ~(uint32_t)(tb_contactApart | tb_contactRecycled), "step %d contact %d", step, id);
			compared += 1;
		}
		world->counters = saved;
	}
	cr_assert_gt(compared, 1000, "pairs apart compared: %d", compared);
	cr_assert_gt(kept, 1000, "of %d pairs apart only %d kept", compared, kept);
	tbDestroyWorld(worldId);
}
