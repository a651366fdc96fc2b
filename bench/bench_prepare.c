// Contact preparation on its own: what a batch of four contacts costs when everything it reads and
// writes stays in the first-level cache (64 contacts, 40 bodies, 16 blocks), so that the time is
// the batch's own instructions and none of the scene's memory traffic. Two ways of writing the
// same lanes (contact_solver.c): the four-wide batch (tbPrepareWideLanes, what the solver uses)
// and one contact at a time (tbPrepareWideLane, what a batch's remainder uses). Resting
// two-point contacts between dynamic boxes, settled, central friction, 60 Hz, 4 sub-steps: the
// pyramids' case. Best of 5 rounds of 200,000 passes over the 16 batches.
//
//   tumble-bench-prepare
//
// Output: CSV path,ns_per_contact

#include "solver/contact_solver.h"
#include "solver/solver_methods.h"
#include "world/world.h"

#include "tumble/base.h"

#include <stdio.h>
#include <string.h>

#define CONTACTS 64
#define BODIES 40
#define PASSES 200000
#define ROUNDS 5

typedef struct Bench
{
	tbWorld world;
	tbStepContext context;
	tbSolverBody bodies[BODIES + 1]; ///< the last is the static stand-in
	tbSolverMass masses[BODIES + 1];
	tbContact contacts[CONTACTS];
	tbWideContactConstraint blocks[CONTACTS / TB_SIMD_WIDTH];
	tbLaneBatch batches[CONTACTS / TB_SIMD_WIDTH];
} Bench;

static void MakeBench(Bench* b)
{
	memset(b, 0, sizeof(*b));
	b->world.def = tbDefaultWorldDef();
	tbStepContext* context = &b->context;
	context->world = &b->world;
	context->timeStep = 1.0f / 60.0f;
	context->subStepCount = 4;
	context->h = context->timeStep / 4.0f;
	context->inv_h = 1.0f / context->h;
	context->enableWarmStarting = true;
	context->centralFriction = true;
	tbSoftPrepare(context);
	for (int i = 0; i <= BODIES; ++i)
	{
		bool moving = i < BODIES;
		b->bodies[i].linearVelocity = tbMakeVec2(moving ? 0.001f * (float)(i % 7) : 0.0f, moving ? -0.01f : 0.0f);
		b->bodies[i].deltaRotation = tbRot_identity;
		b->masses[i].invMass = moving ? 1.0f : 0.0f;
		b->masses[i].invI = moving ? 6.0f : 0.0f;
		b->masses[i].gravityScale = 1.0f;
	}
	context->bodies = b->bodies;
	context->masses = b->masses;
	context->bodyCount = BODIES;
	context->wideConstraints = b->blocks;
	context->wideCount = CONTACTS / TB_SIMD_WIDTH;
	for (int c = 0; c < CONTACTS; ++c)
	{
		tbContact* contact = b->contacts + c;
		contact->manifold.normal = tbMakeVec2(0.0f, 1.0f);
		contact->manifold.pointCount = 2;
		contact->friction = 0.6f;
		contact->touchingSteps = 100; // settled
		for (int j = 0; j < 2; ++j)
		{
			tbManifoldPoint* mp = contact->manifold.points + j;
			float x = j == 0 ? -0.4f : 0.4f;
			mp->anchorA = tbMakeVec2(x, 0.5f);
			mp->anchorB = tbMakeVec2(x, -0.5f);
			mp->separation = -0.005f;
			mp->normalImpulse = 0.1f;
			mp->tangentImpulse = 0.001f;
		}
	}
	// Lanes spread over the blocks as the colouring spreads consecutive contacts (a batch's four
	// contacts go to four blocks), bodies as in a pile (no two lanes of a block share one).
	for (int k = 0; k < CONTACTS / TB_SIMD_WIDTH; ++k)
	{
		tbLaneBatch* batch = b->batches + k;
		batch->count = TB_SIMD_WIDTH;
		for (int l = 0; l < TB_SIMD_WIDTH; ++l)
		{
			int c = k * TB_SIMD_WIDTH + l;
			batch->contacts[l] = b->contacts + c;
			batch->keys[l].indexA = c % BODIES;
			batch->keys[l].indexB = (c * 7 + 3) % BODIES;
			batch->keys[l].flags = tb_keyMovesA | tb_keyMovesB | tb_keyDynamicA | tb_keyDynamicB;
			batch->locations[l] = (c * 5) % CONTACTS; // 5 is prime to 64: every lane once
			batch->slots[l] = c;
			batch->indices[l] = c;
		}
	}
}

/// ns per contact, best of ROUNDS; `wide`: the four-wide batch, else one contact at a time.
static double Time(Bench* b, bool wide)
{
	double best = 1e30;
	int sink = 0;
	for (int round = 0; round < ROUNDS; ++round)
	{
		uint64_t start = tbGetTicks();
		for (int pass = 0; pass < PASSES; ++pass)
		{
			for (int k = 0; k < CONTACTS / TB_SIMD_WIDTH; ++k)
			{
				const tbLaneBatch* batch = b->batches + k;
				if (wide)
				{
					sink += tbPrepareWideLanes(&b->context, batch);
					continue;
				}
				for (int l = 0; l < TB_SIMD_WIDTH; ++l)
				{
					int location = batch->locations[l];
					sink += tbPrepareWideLane(&b->context, batch->contacts[l], batch->keys[l],
											  b->blocks + location / TB_SIMD_WIDTH, location % TB_SIMD_WIDTH);
				}
			}
		}
		double ns = 1e6 * (double)tbGetMilliseconds(start) / ((double)PASSES * CONTACTS);
		best = ns < best ? ns : best;
	}
	if (sink != 0)
	{
		printf("# %d approaches at the restitution threshold (none expected)\n", sink);
	}
	return best;
}

int main(void)
{
	static Bench bench;
	MakeBench(&bench);
	printf("path,ns_per_contact\n");
	printf("four-wide batch,%.2f\n", Time(&bench, true));
	printf("one contact at a time,%.2f\n", Time(&bench, false));
	return 0;
}
