// Graph colouring and the wide contact solver (constraint_graph.c, contact_solver_wide.c).
//
// 1. The colouring on hand-built constraints: every constraint lands exactly once (a lane or the
//    overflow list), no moving body appears twice in one colour, the order within a colour is the
//    input order, padding lanes are inert, and bodies that do not move take no colour.
// 2. The wide solver against the scalar reference on whole worlds where both solve the contacts
//    in the same order (every contact in colour 0). The lanes run the scalar arithmetic operation
//    for operation (simd.h), so the trajectories must be equal, not just close: the tolerance is 0
//    (compared with ==, which ignores the sign of a zero, the one thing the two may differ in).
#include "solver.h"

#include "tumble/tumble.h"

#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#define BODY_COUNT 40
#define STATIC_INDEX BODY_COUNT
#define KINEMATIC_BODY 39

static tbContactConstraint MakeConstraint(int indexA, int indexB)
{
	tbContactConstraint c;
	memset(&c, 0, sizeof(c));
	c.indexA = indexA;
	c.indexB = indexB;
	bool movesA = indexA != STATIC_INDEX && indexA != KINEMATIC_BODY;
	bool movesB = indexB != STATIC_INDEX && indexB != KINEMATIC_BODY;
	c.invMassA = movesA ? 1.0f : 0.0f;
	c.invIA = movesA ? 6.0f : 0.0f;
	c.invMassB = movesB ? 1.0f : 0.0f;
	c.invIB = movesB ? 6.0f : 0.0f;
	c.normal = tbMakeVec2(0.6f, 0.8f);
	c.friction = 0.5f;
	c.pointCount = 1 + (indexA + indexB) % 2;
	for (int j = 0; j < c.pointCount; ++j)
	{
		c.points[j].anchorA = tbMakeVec2(0.1f * (float)indexA, (float)j);
		c.points[j].normalMass = 0.25f + (float)indexB;
		c.points[j].normalImpulse = 0.01f * (float)(indexA + indexB);
	}
	return c;
}

// A star (body 0 against bodies 1..30: more constraints on one body than there are colours), a
// chain 31–32–…–38, static contacts of bodies 1..10, and a kinematic body touching 31..38.
static int BuildConstraints(tbContactConstraint* constraints)
{
	int n = 0;
	for (int i = 1; i <= 30; ++i)
	{
		constraints[n++] = MakeConstraint(0, i);
	}
	for (int i = 31; i < 38; ++i)
	{
		constraints[n++] = MakeConstraint(i, i + 1);
	}
	for (int i = 1; i <= 10; ++i)
	{
		constraints[n++] = MakeConstraint(STATIC_INDEX, i);
	}
	for (int i = 31; i <= 38; ++i)
	{
		constraints[n++] = MakeConstraint(KINEMATIC_BODY, i);
	}
	return n;
}

static bool Moves(int index)
{
	return index != STATIC_INDEX && index != KINEMATIC_BODY;
}

Test(constraint_graph, colours_are_independent_sets_in_input_order)
{
	tbContactConstraint constraints[64];
	tbStepContext context;
	memset(&context, 0, sizeof(context));
	context.bodyCount = BODY_COUNT;
	context.constraints = constraints;
	context.constraintCount = BuildConstraints(constraints);
	tbColorConstraints(&context);

	int seen[64] = {0};
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		int uses[BODY_COUNT + 1] = {0};
		int last = -1;
		for (int b = context.colorBlockStart[k]; b < context.colorBlockStart[k + 1]; ++b)
		{
			const tbWideContactConstraint* block = context.wideConstraints + b;
			for (int lane = 0; lane < TB_SIMD_WIDTH; ++lane)
			{
				int index = block->constraintIndex[lane];
				if (index < 0)
				{
					// Padding: both bodies at the stand-in, nothing to apply.
					cr_expect_eq(block->indexA[lane], STATIC_INDEX);
					cr_expect_eq(block->indexB[lane], STATIC_INDEX);
					cr_expect_eq(((const float*)&block->points[0].normalMass)[lane], 0.0f);
					cr_expect_eq(((const float*)&block->invMassB)[lane], 0.0f);
					continue;
				}
				cr_expect_gt(index, last, "colour %d: constraint %d after %d (input order kept)", k, index, last);
				last = index;
				seen[index] += 1;
				const tbContactConstraint* c = constraints + index;
				cr_expect_eq(block->indexA[lane], c->indexA);
				cr_expect_eq(block->indexB[lane], c->indexB);
				cr_expect_eq(((const float*)&block->normalY)[lane], c->normal.y);
				cr_expect_eq(((const float*)&block->points[0].normalImpulse)[lane], c->points[0].normalImpulse);
				if (Moves(c->indexA))
				{
					uses[c->indexA] += 1;
				}
				if (Moves(c->indexB))
				{
					uses[c->indexB] += 1;
				}
			}
		}
		for (int body = 0; body <= BODY_COUNT; ++body)
		{
			cr_expect_leq(uses[body], 1, "colour %d holds moving body %d %d times", k, body, uses[body]);
		}
	}

	// The star's centre can take each colour once: constraints 24..29 overflow, in order.
	cr_assert_eq(context.overflowCount, 30 - TB_GRAPH_COLOR_COUNT);
	for (int i = 0; i < context.overflowCount; ++i)
	{
		cr_expect_eq(context.overflowConstraints[i], TB_GRAPH_COLOR_COUNT + i);
		seen[context.overflowConstraints[i]] += 1;
	}
	for (int i = 0; i < context.constraintCount; ++i)
	{
		cr_expect_eq(seen[i], 1, "constraint %d placed %d times", i, seen[i]);
	}
	// Star constraint i can only take colour i (body 0 holds colours 0..i−1 already).
	for (int i = 0; i < TB_GRAPH_COLOR_COUNT; ++i)
	{
		const tbWideContactConstraint* first = context.wideConstraints + context.colorBlockStart[i];
		cr_expect_eq(first->constraintIndex[0], i, "colour %d starts with constraint %d", i, first->constraintIndex[0]);
	}
	// The kinematic body takes no colour: its eight contacts share colour blocks freely, and all
	// of them fit in the colours the chain left free.
	cr_expect_eq(context.colorCount, TB_GRAPH_COLOR_COUNT);
	tbReleaseColors(&context);
	cr_expect_null(context.wideConstraints);
}

Test(constraint_graph, no_constraints_no_blocks)
{
	tbStepContext context;
	memset(&context, 0, sizeof(context));
	context.bodyCount = 3;
	tbColorConstraints(&context);
	cr_expect_eq(context.wideCount, 0);
	cr_expect_eq(context.overflowCount, 0);
	cr_expect_eq(context.colorCount, 0);
	tbReleaseColors(&context);
}

// ---------------------------------------------------------------------------------------------
// Wide against scalar on whole worlds

#define TIME_STEP (1.0f / 60.0f)
#define SUB_STEPS 4
#define BOX_COUNT 24

typedef struct Run
{
	tbVec2 position[BOX_COUNT];
	float angle[BOX_COUNT];
	tbVec2 velocity[BOX_COUNT];
	float angularVelocity[BOX_COUNT];
	int touching;
} Run;

static tbBodyId AddBox(tbWorldId worldId, tbBodyType type, tbVec2 position, float angle, tbVec2 velocity,
					   float angularVelocity, float halfWidth, float restitution)
{
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = type;
	bd.position = position;
	bd.rotation = tbMakeRot(angle);
	bd.linearVelocity = velocity;
	bd.angularVelocity = angularVelocity;
	tbBodyId id = tbCreateBody(worldId, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	sd.friction = 0.6f;
	sd.restitution = restitution;
	tbPolygon box = tbMakeBox(halfWidth, 0.5f);
	tbCreatePolygonShape(id, &sd, &box);
	return id;
}

// Boxes 3 m apart, each touching only the support below it (static ground or a kinematic
// platform moving sideways): every contact has one moving body of its own, so the colouring
// puts them all in colour 0, in the scalar solver's order. Tilted, spinning and bouncing boxes
// exercise two-point manifolds, friction, rotation and restitution.
static Run RunBoxes(bool wide, bool kinematicSupport, int stepCount)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.enableWideSolver = wide;
	def.enableSleep = false;
	tbWorldId worldId = tbCreateWorld(&def);
	if (kinematicSupport)
	{
		AddBox(worldId, tb_kinematicBody, tbMakeVec2(0.0f, -0.5f), 0.0f, tbMakeVec2(0.7f, 0.0f), 0.0f, 100.0f, 0.0f);
	}
	else
	{
		AddBox(worldId, tb_staticBody, tbMakeVec2(0.0f, -0.5f), 0.0f, tb_vec2_zero, 0.0f, 100.0f, 0.0f);
	}
	tbBodyId ids[BOX_COUNT];
	for (int i = 0; i < BOX_COUNT; ++i)
	{
		float x = -36.0f + 3.0f * (float)i;
		float angle = 0.07f * (float)i;
		tbVec2 velocity = tbMakeVec2(0.2f * (float)(i % 5) - 0.4f, -(float)(i % 4));
		float restitution = (i % 3 == 0) ? 0.5f : 0.0f;
		ids[i] = AddBox(worldId, tb_dynamicBody, tbMakeVec2(x, 0.6f + 0.1f * (float)(i % 7)), angle, velocity,
						0.3f * (float)(i % 3) - 0.3f, 0.5f, restitution);
	}
	for (int i = 0; i < stepCount; ++i)
	{
		tbWorld_Step(worldId, TIME_STEP, SUB_STEPS);
	}
	Run run;
	for (int i = 0; i < BOX_COUNT; ++i)
	{
		run.position[i] = tbBody_GetPosition(ids[i]);
		run.angle[i] = tbRot_GetAngle(tbBody_GetRotation(ids[i]));
		run.velocity[i] = tbBody_GetLinearVelocity(ids[i]);
		run.angularVelocity[i] = tbBody_GetAngularVelocity(ids[i]);
	}
	run.touching = tbWorld_GetCounters(worldId).touchingCount;
	tbDestroyWorld(worldId);
	return run;
}

static void ExpectSameRun(const Run* wide, const Run* scalar)
{
	cr_expect_eq(wide->touching, scalar->touching);
	cr_expect_geq(wide->touching, BOX_COUNT, "every box should touch its support (%d touching)", wide->touching);
	for (int i = 0; i < BOX_COUNT; ++i)
	{
		cr_expect(wide->position[i].x == scalar->position[i].x && wide->position[i].y == scalar->position[i].y,
				  "box %d at (%.9g, %.9g) wide, (%.9g, %.9g) scalar", i, wide->position[i].x, wide->position[i].y,
				  scalar->position[i].x, scalar->position[i].y);
		cr_expect(wide->angle[i] == scalar->angle[i], "box %d angle %.9g wide, %.9g scalar", i, wide->angle[i],
				  scalar->angle[i]);
		cr_expect(wide->velocity[i].x == scalar->velocity[i].x && wide->velocity[i].y == scalar->velocity[i].y,
				  "box %d velocity differs", i);
		cr_expect(wide->angularVelocity[i] == scalar->angularVelocity[i], "box %d angular velocity differs", i);
	}
}

Test(constraint_graph, wide_equals_scalar_on_static_ground)
{
	Run wide = RunBoxes(true, false, 120);
	Run scalar = RunBoxes(false, false, 120);
	ExpectSameRun(&wide, &scalar);
}

Test(constraint_graph, wide_equals_scalar_with_a_shared_kinematic_body)
{
	// The platform appears in every lane of every block (it takes no colour); a lane that wrote
	// anything but the velocity it read would change the platform and every box after it.
	Run wide = RunBoxes(true, true, 120);
	Run scalar = RunBoxes(false, true, 120);
	ExpectSameRun(&wide, &scalar);
	// The boxes ride the platform: friction brings them to its 0.7 m/s within 2 s.
	for (int i = 0; i < BOX_COUNT; ++i)
	{
		cr_expect(fabsf(wide.velocity[i].x - 0.7f) < 1e-3f, "box %d moves at %f m/s, platform 0.7", i,
				  wide.velocity[i].x);
	}
}
