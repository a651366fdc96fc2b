// Graph colouring and the wide contact solver (constraint_graph.c, contact_solver_wide.c).
//
// 1. The colouring on hand-built constraints: every constraint lands exactly once (a lane or the
//    overflow list), no moving body appears twice in one colour, colours follow the solve order
//    and lanes within a colour the contact-id order, padding lanes are inert, and bodies that do
//    not move take no colour.
// 2. The wide solver against the scalar reference on whole worlds where both solve the contacts
//    in the same order (every contact in colour 0). The lanes run the scalar arithmetic operation
//    for operation (simd.h), so the trajectories must be equal, not just close: the tolerance is 0
//    (compared with ==, which ignores the sign of a zero: the wide code writes 0 − x where the
//    scalar writes −x, the one difference in the arithmetic). Soft step and Baumgarte, warm
//    starting on and off, and a friction so large that its mix is infinite (the clamp's NaN rule).
#include "solver/solver.h"

#include "tumble/tumble.h"

#include <criterion/criterion.h>

#include <math.h>
#include <stddef.h>
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

/// The constraint in lane `location` (block·TB_SIMD_WIDTH + lane), from the colouring's map the other
/// way (tbStepContext::wideLocation), or −1 for a padding lane.
static int LaneOwner(const tbStepContext* context, int location)
{
	for (int i = 0; i < context->constraintCount; ++i)
	{
		if (context->wideLocation[i] == location)
		{
			return i;
		}
	}
	return -1;
}

static bool Moves(int index)
{
	return index != STATIC_INDEX && index != KINEMATIC_BODY;
}

// What the step does around the colouring (solver.c): keys in contact-id order from the
// constraints (contact_solver.c computes them from the contacts), the colouring, then each constraint packed into the lane the
// colouring gave it (the preparation writes it there). `slots[i]` is the solve-order index of the
// i-th contact in contact-id order (island.c); NULL for the identity.
static void ColorAndPack(tbStepContext* context, tbWorld* world, const int* slots)
{
	int n = context->constraintCount;
	static tbContactKey keys[64], keysById[64];
	static int identity[64];
	for (int i = 0; i < n; ++i)
	{
		identity[i] = i;
	}
	const int* order = slots != NULL ? slots : identity;
	for (int i = 0; i < n; ++i)
	{
		const tbContactConstraint* c = context->constraints + order[i]; // the i-th in contact-id order
		keysById[i].indexA = c->indexA;
		keysById[i].indexB = c->indexB;
		keysById[i].flags = (c->invMassA > 0.0f || c->invIA > 0.0f ? (uint32_t)tb_keyMovesA : 0u) |
							(c->invMassB > 0.0f || c->invIB > 0.0f ? (uint32_t)tb_keyMovesB : 0u);
	}
	context->keys = keys; // filled in solve order by the colouring
	context->keysById = keysById;
	world->cache.solverSlots = (int*)order;
	tbColorConstraints(context);
	for (int i = 0; i < n; ++i)
	{
		int location = context->wideLocation[i];
		if (location >= 0)
		{
			tbPackWideLane(context->wideConstraints + location / TB_SIMD_WIDTH, location % TB_SIMD_WIDTH,
						   context->constraints + i);
		}
	}
	world->cache.solverSlots = NULL;
}

Test(constraint_graph, colours_are_independent_sets_in_input_order)
{
	tbContactConstraint constraints[64];
	tbWorld world; // only its step arena is used
	memset(&world, 0, sizeof(world));
	tbStepContext context;
	memset(&context, 0, sizeof(context));
	context.world = &world;
	context.bodyCount = BODY_COUNT;
	context.constraints = constraints;
	context.constraintCount = BuildConstraints(constraints);
	ColorAndPack(&context, &world, NULL);

	int seen[64] = {0};
	int colorOf[64];
	for (int i = 0; i < 64; ++i)
	{
		colorOf[i] = -1;
	}
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		int uses[BODY_COUNT + 1] = {0};
		int last = -1;
		for (int b = context.colorBlockStart[k]; b < context.colorBlockStart[k + 1]; ++b)
		{
			const tbWideContactConstraint* block = context.wideConstraints + b;
			for (int lane = 0; lane < TB_SIMD_WIDTH; ++lane)
			{
				int index = LaneOwner(&context, b * TB_SIMD_WIDTH + lane);
				if (index < 0)
				{
					// Padding: both bodies at the stand-in, every number 0, nothing to apply.
					cr_expect_eq(block->indexA[lane], STATIC_INDEX);
					cr_expect_eq(block->indexB[lane], STATIC_INDEX);
					const tbFloatW* first = &block->normalX;
					int fieldCount = (int)((sizeof(*block) - offsetof(tbWideContactConstraint, normalX)) / sizeof(tbFloatW));
					for (int f = 0; f < fieldCount; ++f)
					{
						cr_expect_eq(tbGetLaneW(first + f, lane), 0.0f, "padding lane %d field %d", lane, f);
					}
					continue;
				}
				colorOf[index] = k;
				cr_expect_gt(index, last, "colour %d: constraint %d after %d (input order kept)", k, index, last);
				last = index;
				seen[index] += 1;
				const tbContactConstraint* c = constraints + index;
				cr_expect_eq(block->indexA[lane], c->indexA);
				cr_expect_eq(block->indexB[lane], c->indexB);
				cr_expect_eq(tbGetLaneW(&block->normalY, lane), c->normal.y);
				cr_expect_eq(tbGetLaneW(&block->impulses[0].normalImpulse, lane), c->points[0].normalImpulse);
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
		int first = LaneOwner(&context, context.colorBlockStart[i] * TB_SIMD_WIDTH);
		cr_expect_eq(first, i, "colour %d starts with constraint %d", i, first);
	}
	// The static stand-in (10 contacts, from index 37) and the kinematic body (8, from index 47)
	// take no colour: their contacts share colours (a colour each would need 10 and 8 distinct
	// ones) and none overflows.
	int firstStatic = 30 + 7, firstKinematic = firstStatic + 10;
	int sharedStatic = 0, sharedKinematic = 0;
	for (int i = firstStatic; i < context.constraintCount; ++i)
	{
		cr_expect_geq(colorOf[i], 0, "constraint %d of a non-moving body overflowed", i);
		int end = i < firstKinematic ? firstKinematic : context.constraintCount;
		for (int j = i + 1; j < end; ++j)
		{
			if (colorOf[i] == colorOf[j])
			{
				sharedStatic += i < firstKinematic ? 1 : 0;
				sharedKinematic += i < firstKinematic ? 0 : 1;
			}
		}
	}
	cr_expect_gt(sharedStatic, 0, "static contacts never share a colour");
	cr_expect_gt(sharedKinematic, 0, "kinematic contacts never share a colour");
	cr_expect_eq(context.colorCount, TB_GRAPH_COLOR_COUNT);
	tbReleaseColors(&context);
	cr_expect_null(context.wideConstraints);
	tbArenaDestroy(&world.stepArena);
}

// Colour of each constraint after ColorAndPack (−1: overflow).
static void ColorsOf(const tbStepContext* context, int* colorOf)
{
	for (int i = 0; i < context->constraintCount; ++i)
	{
		colorOf[i] = -1;
	}
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		for (int b = context->colorBlockStart[k]; b < context->colorBlockStart[k + 1]; ++b)
		{
			for (int lane = 0; lane < TB_SIMD_WIDTH; ++lane)
			{
				int index = LaneOwner(context, b * TB_SIMD_WIDTH + lane);
				if (index >= 0)
				{
					colorOf[index] = k;
				}
			}
		}
	}
}

// Colours are assigned in the solve order (that is what Gauss–Seidel sees); the lanes of a colour
// are handed out in contact-id order, the order the preparation writes them. Here contact-id order
// is the solve order reversed: same colours as in input order, lanes in decreasing index.
Test(constraint_graph, lanes_follow_contact_id_order_colours_follow_solve_order)
{
	tbContactConstraint constraints[64];
	tbWorld world; // only its step arena is used
	memset(&world, 0, sizeof(world));
	tbStepContext context;
	memset(&context, 0, sizeof(context));
	context.world = &world;
	context.bodyCount = BODY_COUNT;
	context.constraints = constraints;
	context.constraintCount = BuildConstraints(constraints);
	int n = context.constraintCount;
	int reference[64], reversed[64], slots[64];
	ColorAndPack(&context, &world, NULL);
	ColorsOf(&context, reference);
	int overflow = context.overflowCount;
	tbReleaseColors(&context);

	for (int i = 0; i < n; ++i)
	{
		slots[i] = n - 1 - i;
	}
	ColorAndPack(&context, &world, slots);
	ColorsOf(&context, reversed);
	cr_expect_eq(context.overflowCount, overflow);
	for (int i = 0; i < n; ++i)
	{
		cr_expect_eq(reversed[i], reference[i], "constraint %d: colour %d, %d in input order", i, reversed[i],
					 reference[i]);
	}
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		int last = n;
		for (int b = context.colorBlockStart[k]; b < context.colorBlockStart[k + 1]; ++b)
		{
			for (int lane = 0; lane < TB_SIMD_WIDTH; ++lane)
			{
				int index = LaneOwner(&context, b * TB_SIMD_WIDTH + lane);
				if (index >= 0)
				{
					cr_expect_lt(index, last, "colour %d: constraint %d after %d", k, index, last);
					last = index;
				}
			}
		}
	}
	// The overflow stays in solve order.
	for (int i = 1; i < context.overflowCount; ++i)
	{
		cr_expect_gt(context.overflowConstraints[i], context.overflowConstraints[i - 1]);
	}
	tbReleaseColors(&context);
	tbArenaDestroy(&world.stepArena);
}

Test(constraint_graph, no_constraints_no_blocks)
{
	tbWorld world; // only its step arena is used
	memset(&world, 0, sizeof(world));
	tbStepContext context;
	memset(&context, 0, sizeof(context));
	context.world = &world;
	context.bodyCount = 3;
	tbColorConstraints(&context);
	cr_expect_eq(context.wideCount, 0);
	cr_expect_eq(context.overflowCount, 0);
	cr_expect_eq(context.colorCount, 0);
	tbReleaseColors(&context);
	tbArenaDestroy(&world.stepArena);
}

// ---------------------------------------------------------------------------------------------
// Island partitions (constraint_graph.c, tbCutPartitions): with workers, separate runs of the
// solver bodies become partitions, each colour's blocks holding one run's contacts after another.

static void* NeverCalledEnqueue(tbTaskCallback* task, void* taskContext, void* userContext)
{
	(void)task, (void)taskContext, (void)userContext;
	return NULL;
}

static void NeverCalledFinish(void* userTask, void* userContext)
{
	(void)userTask, (void)userContext;
}

/// Two chains on the ground: bodies [0, firstRun) and [firstRun, 20), each body also on the static
/// stand-in; bodies 20..38 touch nothing. Optionally one more contact, linkA–linkB.
static int BuildTwoRuns(tbContactConstraint* constraints, int firstRun, int linkA, int linkB)
{
	int n = 0;
	for (int i = 0; i < 20; ++i)
	{
		if (i + 1 != firstRun && i + 1 < 20)
		{
			constraints[n++] = MakeConstraint(i, i + 1);
		}
		constraints[n++] = MakeConstraint(STATIC_INDEX, i);
	}
	if (linkA >= 0)
	{
		constraints[n++] = MakeConstraint(linkA, linkB);
	}
	return n;
}

/// The colouring of BuildTwoRuns' contacts for a world of two workers.
static void ColorForTwoWorkers(tbStepContext* context, tbWorld* world, tbContactConstraint* constraints, int firstRun,
							   int linkA, int linkB)
{
	memset(world, 0, sizeof(*world));
	world->def.enqueueTask = NeverCalledEnqueue; // only their presence counts: the colouring calls no task
	world->def.finishTask = NeverCalledFinish;
	world->def.workerCount = 2;
	world->def.solver = tb_solverSoft;
	memset(context, 0, sizeof(*context));
	context->world = world;
	context->enableWarmStarting = true;
	context->bodyCount = BODY_COUNT;
	context->constraints = constraints;
	context->constraintCount = BuildTwoRuns(constraints, firstRun, linkA, linkB);
	ColorAndPack(context, world, NULL);
}

Test(constraint_graph, separate_runs_become_partitions)
{
	tbContactConstraint constraints[64];
	tbWorld world;
	tbStepContext context;
	ColorForTwoWorkers(&context, &world, constraints, 10, -1, -1);
	int n = context.constraintCount;
	// 19 contacts on bodies 0..9 and 19 on 10..19: the cut at 10 splits them evenly; the bodies
	// touching nothing go with the last run.
	cr_assert_eq(context.partitionCount, 2);
	cr_expect_eq(context.partitionBodyStart[0], 0);
	cr_expect_eq(context.partitionBodyStart[1], 10);
	cr_expect_eq(context.partitionBodyStart[2], BODY_COUNT);
	int seen[64] = {0};
	for (int k = 0; k < TB_GRAPH_COLOR_COUNT; ++k)
	{
		cr_expect_eq(context.partitionBlockStart[k][0], context.colorBlockStart[k]);
		cr_expect_eq(context.partitionBlockStart[k][2], context.colorBlockStart[k + 1]);
		for (int p = 0; p < 2; ++p)
		{
			for (int b = context.partitionBlockStart[k][p]; b < context.partitionBlockStart[k][p + 1]; ++b)
			{
				for (int lane = 0; lane < TB_SIMD_WIDTH; ++lane)
				{
					int index = LaneOwner(&context, b * TB_SIMD_WIDTH + lane);
					if (index < 0)
					{
						cr_expect_eq(context.wideConstraints[b].indexA[lane], STATIC_INDEX, "padding lane");
						cr_expect_eq(context.wideConstraints[b].indexB[lane], STATIC_INDEX, "padding lane");
						continue;
					}
					seen[index] += 1;
					const tbContactConstraint* c = constraints + index;
					int body = c->indexA != STATIC_INDEX ? c->indexA : c->indexB;
					cr_expect_eq(body >= 10, p == 1, "colour %d: constraint %d (body %d) in partition %d", k, index,
								 body, p);
				}
			}
		}
	}
	for (int i = 0; i < n; ++i)
	{
		cr_expect_eq(seen[i], 1, "constraint %d in %d lanes", i, seen[i]);
	}
	tbReleaseColors(&context);
	tbDestroyContactColorCache(&world);
	tbArenaDestroy(&world.stepArena);
}

// No partitions when a contact links the runs (between two dynamic bodies, or through a kinematic
// body, whose state the other run would read while its owner integrates it), or when the only cut
// leaves one run with more than 1/16 above half the contacts (27 against 11).
Test(constraint_graph, linked_or_uneven_runs_share_the_stages)
{
	const int cases[3][3] = {{10, 9, 10}, {10, 5, KINEMATIC_BODY}, {14, -1, -1}};
	for (int c = 0; c < 3; ++c)
	{
		tbContactConstraint constraints[64];
		tbWorld world;
		tbStepContext context;
		ColorForTwoWorkers(&context, &world, constraints, cases[c][0], cases[c][1], cases[c][2]);
		cr_expect_eq(context.partitionCount, 0, "case %d", c);
		cr_expect(context.wideCount > 0, "case %d: still coloured", c);
		tbReleaseColors(&context);
		tbDestroyContactColorCache(&world);
		tbArenaDestroy(&world.stepArena);
	}
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

static float s_friction = 0.6f;

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
	sd.material.friction = s_friction;
	sd.material.restitution = restitution;
	tbPolygon box = tbMakeBox(halfWidth, 0.5f);
	tbCreatePolygonShape(id, &sd, &box);
	return id;
}

// Boxes 3 m apart, each touching only the support below it (static ground or a kinematic
// platform moving sideways): every contact has one moving body of its own, so the colouring
// puts them all in colour 0, in the scalar solver's order. Tilted, spinning and bouncing boxes
// exercise two-point manifolds, friction, rotation and restitution.
typedef struct Variant
{
	bool kinematicSupport;
	tbSolverMethod solver;
	bool noWarmStarting;
	float friction;
} Variant;

static Run RunBoxes(bool wide, Variant variant, int stepCount)
{
	bool kinematicSupport = variant.kinematicSupport;
	s_friction = variant.friction > 0.0f ? variant.friction : 0.6f;
	tbWorldDef def = tbDefaultWorldDef();
	def.enableWideSolver = wide;
	def.solver = variant.solver;
	def.enableWarmStarting = variant.noWarmStarting == false;
	def.enableSleep = false;
	tbWorldId worldId = tbCreateWorld(&def);
	if (kinematicSupport)
	{
		AddBox(worldId, tb_kinematicBody, tbMakeVec2(0.0f, -0.5f), 0.0f, tbMakeVec2(0.7f, 0.0f), 0.0f, 100.0f, 0.0f);
	}
	else
	{
		AddBox(worldId, tb_staticBody, tbMakeVec2(0.0f, -0.5f), 0.0f, tbVec2_zero, 0.0f, 100.0f, 0.0f);
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
		cr_expect(isfinite(wide->position[i].x) && isfinite(wide->position[i].y), "box %d not finite", i);
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

// Runs the variant with both solvers, expects equal trajectories and returns the wide run.
static Run ExpectWideEqualsScalar(Variant variant, int stepCount)
{
	Run wide = RunBoxes(true, variant, stepCount);
	Run scalar = RunBoxes(false, variant, stepCount);
	ExpectSameRun(&wide, &scalar);
	return wide;
}

Test(constraint_graph, wide_equals_scalar_on_static_ground)
{
	ExpectWideEqualsScalar((Variant){false, tb_solverSoft, false, 0.0f}, 120);
}

Test(constraint_graph, wide_equals_scalar_baumgarte)
{
	ExpectWideEqualsScalar((Variant){false, tb_solverBaumgarte, false, 0.0f}, 120);
}

Test(constraint_graph, wide_equals_scalar_without_warm_starting)
{
	ExpectWideEqualsScalar((Variant){false, tb_solverSoft, true, 0.0f}, 120);
	ExpectWideEqualsScalar((Variant){false, tb_solverBaumgarte, true, 0.0f}, 120);
}

Test(constraint_graph, wide_equals_scalar_with_infinite_mixed_friction)
{
	// sqrt(1e20 · 1e20) overflows to +inf: μ·λn is NaN where λn = 0 (the second point of a
	// one-point contact, a point before it pushes). The scalar clamp lets the impulse through there;
	// the wide clamp must do the same rather than return the NaN bound.
	ExpectWideEqualsScalar((Variant){false, tb_solverSoft, false, 1e20f}, 60);
}

Test(constraint_graph, wide_equals_scalar_with_a_shared_kinematic_body)
{
	// The platform appears in every lane of every block (it takes no colour); a lane that wrote
	// anything but the velocity it read would change the platform and every box after it.
	Run wide = ExpectWideEqualsScalar((Variant){true, tb_solverSoft, false, 0.0f}, 120);

	// The boxes ride the platform. Closed form: a box sliding relative to it at most about 1.1 m/s
	// (launch speed plus the platform's 0.7) stops sliding after Δv/(μg) = 1.1/6 ≈ 0.2 s; from then
	// the sticking contact holds the relative velocity at zero (measured: exactly 0). Bound: 1 mm/s,
	// the rest threshold used below.
	for (int i = 0; i < BOX_COUNT; ++i)
	{
		cr_expect(fabsf(wide.velocity[i].x - 0.7f) < 1e-3f, "box %d moves at %f m/s, platform 0.7", i,
				  wide.velocity[i].x);
	}
}

Test(constraint_graph, a_body_with_more_contacts_than_colours_rests)
{
	// 30 boxes (0.5 m × 1 m) 1 m apart on one 40 m dynamic plank lying on the ground: the plank's 31
	// contacts (30 boxes and the ground, which takes no colour) need more than the 24 colours, so 6
	// run in the scalar overflow. After 3 s everything rests: speeds below 1 mm/s (the soft
	// contacts settle within about a second: the settling time of the pyramid in test_solver.c) and each box at its resting height within
	// 0.01 m (twice the linear slop, the depth soft contacts settle at under load).
	tbWorldDef def = tbDefaultWorldDef();
	def.enableSleep = false;
	tbWorldId worldId = tbCreateWorld(&def);
	s_friction = 0.6f;
	AddBox(worldId, tb_staticBody, tbMakeVec2(0.0f, -0.5f), 0.0f, tbVec2_zero, 0.0f, 100.0f, 0.0f);
	tbBodyDef bd = tbDefaultBodyDef();
	bd.type = tb_dynamicBody;
	bd.position = tbMakeVec2(0.0f, 0.1f);
	tbBodyId plank = tbCreateBody(worldId, &bd);
	tbShapeDef sd = tbDefaultShapeDef();
	tbPolygon plankBox = tbMakeBox(20.0f, 0.1f);
	tbCreatePolygonShape(plank, &sd, &plankBox);
	tbBodyId boxes[30];
	for (int i = 0; i < 30; ++i)
	{
		boxes[i] = AddBox(worldId, tb_dynamicBody, tbMakeVec2(-14.5f + (float)i, 0.7f), 0.0f, tbVec2_zero, 0.0f, 0.25f,
						  0.0f);
	}
	for (int i = 0; i < 180; ++i)
	{
		tbWorld_Step(worldId, TIME_STEP, SUB_STEPS);
	}
	float maxSpeed = tbLength(tbBody_GetLinearVelocity(plank));
	for (int i = 0; i < 30; ++i)
	{
		tbVec2 p = tbBody_GetPosition(boxes[i]);
		maxSpeed = tbMaxFloat(maxSpeed, tbLength(tbBody_GetLinearVelocity(boxes[i])));
		cr_expect(fabsf(p.y - 0.7f) < 0.01f, "box %d at height %f, rests at 0.7", i, p.y);
		cr_expect(fabsf(p.x - (-14.5f + (float)i)) < 0.01f, "box %d slid to x %f", i, p.x);
	}
	cr_expect_lt(maxSpeed, 1e-3f, "largest speed %f m/s after 3 s", maxSpeed);
	tbDestroyWorld(worldId);
}
