// Unit checks of the solve stage on a hand-built world (no broad phase, no narrow phase): one
// dynamic unit-mass body (B) touching the static ground (A) through a one-point manifold at B's
// centre of mass (anchorB zero, so B's rotation never enters), normal (0, 1) from A to B.
#include "solver/constraint_graph.h"
#include "solver/solver.h"

#include "tumble/constants.h"

#include <criterion/criterion.h>

#include <math.h>
#include <string.h>

typedef struct MiniWorld
{
	tbWorld world;
	tbBody bodies[2];  // 0: static ground, 1: dynamic unit mass
	tbShape shapes[2]; // shape i on body i
	tbContact contact;
	int awake[1];
	int solverContacts[1];
	int solverSlots[1];
} MiniWorld;

static void InitMini(MiniWorld* m, tbSolverMethod method, tbVec2 velocity, float separation)
{
	memset(m, 0, sizeof(*m));
	m->world.def = tbDefaultWorldDef();
	m->world.def.gravity = tbMakeVec2(0.0f, 0.0f);
	m->world.def.solver = method;
	m->world.bodies = m->bodies;
	m->world.shapes = m->shapes;
	m->world.contacts = &m->contact;
	m->world.awakeBodies = m->awake;
	m->world.awakeBodyCount = 1;
	m->world.cache.solverContacts = m->solverContacts;
	m->world.cache.solverContactsById = m->solverContacts; // one contact: both orders agree
	m->world.cache.solverSlots = m->solverSlots;
	m->world.cache.solverContactCount = 1;
	for (int i = 0; i < 2; ++i)
	{
		m->bodies[i].transform.q = tbRot_identity;
		m->bodies[i].awakeIndex = TB_NULL_INDEX;
		m->bodies[i].gravityScale = 1.0f;
		m->shapes[i].bodyId = i;
	}
	m->bodies[1].awakeIndex = 0; // awake[0]
	m->bodies[1].type = tb_dynamicBody;
	m->bodies[1].invMass = 1.0f;
	m->bodies[1].invInertia = 1.0f;
	m->bodies[1].linearVelocity = velocity;
	m->bodies[1].center = tbMakeVec2(0.0f, 0.5f);
	m->bodies[1].transform.p = m->bodies[1].center;
	m->awake[0] = 1;

	m->contact.shapeIdA = 0;
	m->contact.shapeIdB = 1;
	m->contact.edges[0].bodyId = 0;
	m->contact.edges[1].bodyId = 1;
	m->contact.friction = 0.1f;
	m->contact.manifold.normal = tbMakeVec2(0.0f, 1.0f);
	m->contact.manifold.pointCount = 1;
	m->contact.manifold.points[0].point = m->bodies[1].center;
	m->contact.manifold.points[0].anchorA = m->bodies[1].center; // ground centre at the origin
	m->contact.manifold.points[0].anchorB = tbVec2_zero;
	m->contact.manifold.points[0].separation = separation;
}

// The solve stage takes its arrays from the world's step arena; tbWorld_Step releases them when
// the step ends, which the mini world does here, and drops the colouring the world keeps for the
// next step (tbDestroyWorld frees it), so that a byte count before and after sees no difference.
static void SolveStage(MiniWorld* m, float timeStep, int subStepCount)
{
	tbSolveStage(&m->world, timeStep, subStepCount);
	tbArenaDestroy(&m->world.stepArena);
	tbDestroyContactColorCache(&m->world);
}

Test(contact_solver, softness_coefficients)
{
	tbSoftness rigid = tbMakeSoftness(0.0f, 10.0f, 1.0f / 240.0f);
	cr_expect(rigid.biasRate == 0.0f && rigid.massScale == 1.0f && rigid.impulseScale == 0.0f);

	// 30 Hz, ζ = 10, h = 1/240: a = hω(2ζ + hω); massScale + impulseScale = 1 exactly in reals.
	float h = 1.0f / 240.0f;
	tbSoftness soft = tbMakeSoftness(30.0f, 10.0f, h);
	float omega = 2.0f * TB_PI * 30.0f;
	float a = h * omega * (20.0f + h * omega);
	cr_expect(fabsf(soft.biasRate - omega / (20.0f + h * omega)) < 1e-4f);
	cr_expect(fabsf(soft.massScale - a / (1.0f + a)) < 1e-6f);
	cr_expect(fabsf(soft.massScale + soft.impulseScale - 1.0f) < 1e-6f);
}

// Each rigid method must stop a unit mass arriving at 1 m/s at a touching contact in one step,
// with the impulse 1 N·s (the whole step applies 1 N·s: what the first sub-step applies the later ones
// warm start and take back), and report the approach speed.
Test(contact_solver, normal_impulse_stops_approach)
{
	for (int method = 0; method < tb_solverMethodCount; ++method)
	{
		MiniWorld m;
		InitMini(&m, (tbSolverMethod)method, tbMakeVec2(0.0f, -1.0f), 0.0f);
		int bytes = tbGetByteCount();
		SolveStage(&m, 1.0f / 60.0f, 4);
		cr_expect_eq(tbGetByteCount(), bytes, "solve stage leaked (method %d)", method);
		const tbManifoldPoint* mp = m.contact.manifold.points;
		// Soft contacts leave the push-out of overlap to later steps; at s = 0 all are rigid: 1e-4.
		cr_expect(fabsf(m.bodies[1].linearVelocity.y) < 1e-4f, "method %d: vy %f", method,
				  m.bodies[1].linearVelocity.y);
		cr_expect(fabsf(mp->totalNormalImpulse - 1.0f) < 1e-4f, "method %d: impulse %f", method, mp->totalNormalImpulse);
		cr_expect(mp->normalVelocity == -1.0f);
		cr_expect(m.bodies[1].center0.y == 0.5f);
	}
}

// Coulomb: a unit mass sliding at 5 m/s pressed with 1 N·s per sub-step loses μ·λn per sub-step.
Test(contact_solver, friction_is_clamped_to_the_cone)
{
	MiniWorld m;
	InitMini(&m, tb_solverBaumgarte, tbMakeVec2(5.0f, -1.0f), 0.0f);
	SolveStage(&m, 1.0f / 60.0f, 1);
	// One sub-step: λn = 1, |λt| = μ·λn = 0.1, so vx = 4.9 (float rounding only).
	cr_expect(fabsf(m.bodies[1].linearVelocity.x - 4.9f) < 1e-5f, "vx %f", m.bodies[1].linearVelocity.x);
	cr_expect(fabsf(fabsf(m.contact.manifold.points[0].tangentImpulse) - 0.1f) < 1e-6f);
}

// A unit box (1 m × 1 m, 1 kg, I = 1/6 kg·m²) sliding at 5 m/s on the ground with a two-point
// manifold at its bottom corners, pressed with 1 N·s (it arrives at 1 m/s), μ = 0.1, one Baumgarte
// sub-step of 8 iterations. Closed form for the converged step: both points end at vn = 0, so
// λn₁ + λn₂ = 1 (the vertical momentum) and ω = 0; friction at its bound, λt = −μ·Σλn = −0.1,
// leaves vx = 4.9; its torque about the centre, −0.5·0.1, is balanced by the normal impulses,
// 0.5·(λn₊ − λn₋) = 0.05, so λn₊ = 0.55 at the leading corner and 0.45 at the trailing one, and
// each point's stored friction is −μ·λn (per point each row sits at its own bound; central
// friction splits its −0.1 by the normal impulses, tbSplitFriction). Both friction kinds must give
// these numbers. Tolerance 1e-3: eight Gauss–Seidel iterations leave the torque balance
// converged to about that.
Test(contact_solver, central_friction_matches_point_friction_on_a_face)
{
	cr_expect(tbDefaultWorldDef().enableCentralFriction, "central friction is the default");
	for (int central = 0; central < 2; ++central)
	{
		MiniWorld m;
		InitMini(&m, tb_solverBaumgarte, tbMakeVec2(5.0f, -1.0f), 0.0f);
		m.world.def.enableCentralFriction = central != 0;
		m.bodies[1].invInertia = 6.0f;
		m.contact.manifold.pointCount = 2;
		for (int j = 0; j < 2; ++j)
		{
			float x = j == 0 ? 0.5f : -0.5f; // leading corner first
			tbManifoldPoint* mp = m.contact.manifold.points + j;
			mp->point = tbMakeVec2(x, 0.0f);
			mp->anchorA = tbMakeVec2(x, 0.0f);
			mp->anchorB = tbMakeVec2(x, -0.5f);
			mp->separation = 0.0f;
			mp->id = (uint16_t)j;
		}
		SolveStage(&m, 1.0f / 60.0f, 1);
		const tbBody* box = m.bodies + 1;
		const tbManifoldPoint* p = m.contact.manifold.points;
		cr_expect(fabsf(box->linearVelocity.x - 4.9f) < 1e-3f, "central %d: vx %f", central, box->linearVelocity.x);
		cr_expect(fabsf(box->linearVelocity.y) < 1e-3f, "central %d: vy %f", central, box->linearVelocity.y);
		cr_expect(fabsf(box->angularVelocity) < 1e-3f, "central %d: ω %f", central, box->angularVelocity);
		cr_expect(fabsf(p[0].normalImpulse - 0.55f) < 1e-3f && fabsf(p[1].normalImpulse - 0.45f) < 1e-3f,
				  "central %d: normal impulses %f, %f", central, p[0].normalImpulse, p[1].normalImpulse);
		for (int j = 0; j < 2; ++j)
		{
			cr_expect(fabsf(p[j].tangentImpulse + 0.1f * p[j].normalImpulse) < 1e-3f,
					  "central %d, point %d: friction %f, normal %f", central, j, p[j].tangentImpulse, p[j].normalImpulse);
		}
		cr_expect(fabsf(p[0].tangentImpulse + p[1].tangentImpulse + 0.1f) < 1e-5f, "central %d: friction sum %f",
				  central, p[0].tangentImpulse + p[1].tangentImpulse);
	}
}

// Restitution: arriving at 4 m/s (above the 1 m/s threshold) with e = 0.5 leaves at 2 m/s.
Test(contact_solver, restitution_reverses_normal_velocity)
{
	for (int method = 0; method < tb_solverMethodCount; ++method)
	{
		MiniWorld m;
		InitMini(&m, (tbSolverMethod)method, tbMakeVec2(0.0f, -4.0f), 0.0f);
		m.contact.restitution = 0.5f;
		tbSetContactMaterialFlags(&m.contact); // as tbMixContactMaterials does for a world's contacts
		SolveStage(&m, 1.0f / 60.0f, 4);
		cr_expect(fabsf(m.bodies[1].linearVelocity.y - 2.0f) < 1e-4f, "method %d: vy %f", method,
				  m.bodies[1].linearVelocity.y);
	}
}

// Speculative gap: 0.1 m apart at 1 m/s cannot close in 1/60 s, so no impulse at all.
Test(contact_solver, speculative_gap_lets_bodies_approach)
{
	for (int method = 0; method < tb_solverMethodCount; ++method)
	{
		MiniWorld m;
		InitMini(&m, (tbSolverMethod)method, tbMakeVec2(0.0f, -1.0f), 0.1f);
		SolveStage(&m, 1.0f / 60.0f, 4);
		cr_expect(m.bodies[1].linearVelocity.y == -1.0f, "method %d", method);
		cr_expect(m.contact.manifold.points[0].totalNormalImpulse == 0.0f);
		// Moved by v·Δt (exact up to float rounding of four sub-steps).
		cr_expect(fabsf(m.bodies[1].center.y - (0.5f - 1.0f / 60.0f)) < 1e-6f);
	}
}

// Speculative gap that does close: 0.005 m at 3 m/s. The body must stop at the surface, not in it.
Test(contact_solver, speculative_gap_stops_at_contact)
{
	for (int method = 0; method < tb_solverMethodCount; ++method)
	{
		MiniWorld m;
		InitMini(&m, (tbSolverMethod)method, tbMakeVec2(0.0f, -3.0f), 0.005f);
		SolveStage(&m, 1.0f / 60.0f, 4);
		float travel = 0.5f - m.bodies[1].center.y;
		cr_expect(fabsf(travel - 0.005f) < 1e-5f, "method %d: travelled %f", method, travel);
	}
}

// Warm starting off: stored impulses are ignored (no push from a stale 100 N·s impulse).
Test(contact_solver, warm_start_off_ignores_stored_impulse)
{
	MiniWorld m;
	InitMini(&m, tb_solverSoft, tbMakeVec2(0.0f, 0.0f), 0.0f);
	m.world.def.enableWarmStarting = false;
	m.contact.manifold.points[0].normalImpulse = 100.0f;
	SolveStage(&m, 1.0f / 60.0f, 4);
	cr_expect(fabsf(m.bodies[1].linearVelocity.y) < 1e-6f);

	InitMini(&m, tb_solverSoft, tbMakeVec2(0.0f, 0.0f), 0.0f);
	m.contact.manifold.points[0].normalImpulse = 100.0f;
	SolveStage(&m, 1.0f / 60.0f, 4);
	// With warm starting the stale impulse is applied, then the solve takes back what it can:
	// the body must not leave faster than the relax pass allows (it ends separating, > 0).
	cr_expect(m.bodies[1].linearVelocity.y >= 0.0f);
}

// Forces are consumed and the transform follows the centre of mass.
Test(contact_solver, forces_cleared_and_transform_written)
{
	MiniWorld m;
	InitMini(&m, tb_solverSoft, tbMakeVec2(1.0f, 0.0f), 0.05f);
	m.bodies[1].force = tbMakeVec2(6.0f, 0.0f);
	m.bodies[1].localCenter = tbMakeVec2(0.25f, 0.0f);
	m.bodies[1].angularVelocity = 1.0f;
	SolveStage(&m, 1.0f / 60.0f, 4);
	cr_expect(m.bodies[1].force.x == 0.0f && m.bodies[1].torque == 0.0f);
	// v = 1 + F/m·Δt = 1.1 m/s after the step.
	cr_expect(fabsf(m.bodies[1].linearVelocity.x - 1.1f) < 1e-5f);
	tbVec2 p = tbAdd(m.bodies[1].transform.p, tbRotateVector(m.bodies[1].transform.q, m.bodies[1].localCenter));
	cr_expect(fabsf(p.x - m.bodies[1].center.x) < 1e-6f && fabsf(p.y - m.bodies[1].center.y) < 1e-6f);
	cr_expect(fabsf(tbRot_GetAngle(m.bodies[1].transform.q) - 1.0f / 60.0f) < 1e-5f);
}

// The wide preparation (tbPrepareWideLanes: TB_SIMD_WIDTH contacts at once in wide floats) against
// the one-lane path (tbPrepareWideLane) on the same inputs: every byte of the blocks, every
// approach speed and every lane's may-rebound answer must be equal (tolerance 0: the lanes run the scalar expressions in the same
// order, simd.h). The inputs cover each branch: one- and two-point manifolds (the absent second
// point holds NaN, which must be masked out), a static side (no mass, no gravity), overlaps past
// the deep-overlap depth (stay soft), speculative points approaching under gravity (the impact
// speed estimate), separating ones, and contacts young, settling and settled (the stiffness ramp).
#define PREP_BODIES 6

static float Hash01(uint32_t x)
{
	x ^= x >> 16;
	x *= 0x7feb352dU;
	x ^= x >> 15;
	x *= 0x846ca68bU;
	x ^= x >> 16;
	return (float)(x & 0xffffu) / 65535.0f;
}

static void MakePrepContact(tbContact* contact, uint32_t seed)
{
	memset(contact, 0, sizeof(*contact));
	float angle = 6.2831853f * Hash01(seed);
	contact->manifold.normal = tbMakeVec2(cosf(angle), sinf(angle));
	contact->manifold.pointCount = 1 + (int)(seed % 2u);
	contact->friction = 0.6f * Hash01(seed + 1u);
	static const float separations[] = {-0.3f, -0.01f, 0.004f, 0.02f};
	static const uint16_t ages[] = {0, 5, 20, 25, 40};
	contact->touchingSteps = ages[seed % 5u];
	for (int j = 0; j < 2; ++j)
	{
		tbManifoldPoint* mp = contact->manifold.points + j;
		uint32_t s = seed * 7u + (uint32_t)j;
		mp->anchorA = tbMakeVec2(Hash01(s + 2u) - 0.5f, Hash01(s + 3u) - 0.5f);
		mp->anchorB = tbMakeVec2(Hash01(s + 4u) - 0.5f, Hash01(s + 5u) - 0.5f);
		mp->separation = separations[(seed / 2u + (uint32_t)j) % 4u];
		mp->normalImpulse = 3.0f * Hash01(s + 6u);
		mp->tangentImpulse = Hash01(s + 7u) - 0.5f;
		if (j >= contact->manifold.pointCount)
		{
			mp->anchorA = tbMakeVec2(NAN, NAN); // whatever an absent point holds must not leak
			mp->separation = NAN;
			mp->normalImpulse = INFINITY;
		}
	}
}

/// A step context for preparing contacts by hand: the default world, 60 Hz, 4 sub-steps, warm
/// starting, the soft step's stiffness (bodies and masses are the caller's).
static void InitPrepContext(tbWorld* world, tbStepContext* context, bool centralFriction)
{
	memset(world, 0, sizeof(*world));
	world->def = tbDefaultWorldDef();
	memset(context, 0, sizeof(*context));
	context->world = world;
	context->timeStep = 1.0f / 60.0f;
	context->subStepCount = 4;
	context->h = context->timeStep / 4.0f;
	context->inv_h = 1.0f / context->h;
	context->enableWarmStarting = true;
	context->centralFriction = centralFriction;
	tbSoftPrepare(context);
}

static void CheckWidePreparation(bool centralFriction)
{
	tbWorld world;
	tbStepContext context;
	InitPrepContext(&world, &context, centralFriction);
	cr_assert(context.settleSteps > 0.0f, "the stiffness ramp is on by default");

	// Bodies 0..4 dynamic (body 4 without rotation), the static stand-in last.
	tbSolverBody bodies[PREP_BODIES];
	tbSolverMass masses[PREP_BODIES];
	memset(bodies, 0, sizeof(bodies));
	memset(masses, 0, sizeof(masses));
	for (int i = 0; i < PREP_BODIES - 1; ++i)
	{
		bodies[i].linearVelocity = tbMakeVec2(Hash01(100u + (uint32_t)i) - 0.5f, -3.0f * Hash01(200u + (uint32_t)i));
		bodies[i].angularVelocity = 2.0f * Hash01(300u + (uint32_t)i) - 1.0f;
		masses[i].invMass = 0.5f + (float)i;
		masses[i].invI = i == 4 ? 0.0f : 2.0f + (float)i;
		masses[i].gravityScale = i == 3 ? 0.0f : 1.0f;
	}
	context.bodies = bodies;
	context.masses = masses;
	context.bodyCount = PREP_BODIES - 1;

	tbWideContactConstraint wide[2], single[2];
	int reboundCount = 0;
	for (uint32_t round = 0; round < 40; ++round)
	{
		tbContact contacts[TB_SIMD_WIDTH], copies[TB_SIMD_WIDTH];
		tbLaneBatch batch;
		batch.count = TB_SIMD_WIDTH;
		for (int l = 0; l < TB_SIMD_WIDTH; ++l)
		{
			uint32_t seed = round * 31u + (uint32_t)l;
			MakePrepContact(contacts + l, seed);
			copies[l] = contacts[l];
			int indexA = (int)(seed % (uint32_t)PREP_BODIES); // the static stand-in among them
			int indexB = (indexA + 1 + (int)(seed / 3u % 4u)) % (PREP_BODIES - 1);
			tbContactKey key;
			key.indexA = indexA;
			key.indexB = indexB;
			bool staticA = indexA == context.bodyCount;
			key.flags = (staticA ? 0u : (uint32_t)(tb_keyMovesA | tb_keyDynamicA)) |
						(uint32_t)(tb_keyMovesB | tb_keyDynamicB);
			batch.contacts[l] = contacts + l;
			batch.keys[l] = key;
			batch.locations[l] = (l % 2) * TB_SIMD_WIDTH + (TB_SIMD_WIDTH - 1 - l / 2); // lanes of two blocks
			batch.slots[l] = 10 * (int)round + l;
		}
		memset(wide, 0xab, sizeof(wide)); // the lanes not written stay so in both
		memset(single, 0xab, sizeof(single));
		context.wideConstraints = wide;
		int rebound = tbPrepareWideLanes(&context, &batch);
		for (int l = 0; l < TB_SIMD_WIDTH; ++l)
		{
			int location = batch.locations[l];
			bool approaching = tbPrepareWideLane(&context, copies + l, batch.keys[l], single + location / TB_SIMD_WIDTH,
												 location % TB_SIMD_WIDTH);
			cr_assert_eq((rebound >> l) & 1, approaching ? 1 : 0, "round %u, lane %d: rebound bit against the one-lane path",
						 round, l);
			reboundCount += approaching ? 1 : 0;
		}
		cr_assert(memcmp(wide, single, sizeof(wide)) == 0, "round %u: the wide lanes differ from the one-lane path",
				  round);
		for (int l = 0; l < TB_SIMD_WIDTH; ++l)
		{
			for (int j = 0; j < contacts[l].manifold.pointCount; ++j)
			{
				float a = contacts[l].manifold.points[j].normalVelocity;
				float b = copies[l].manifold.points[j].normalVelocity;
				cr_assert(memcmp(&a, &b, sizeof(a)) == 0, "round %u, lane %d, point %d: approach %g against %g",
						  round, l, j, (double)a, (double)b);
			}
		}
	}
	// Both answers occur (restitution threshold 1 m/s; approaches up to about 3 m/s), so the bits are
	// tested both ways.
	cr_expect(reboundCount > 0 && reboundCount < 40 * TB_SIMD_WIDTH, "%d of %d lanes may rebound", reboundCount,
			  40 * TB_SIMD_WIDTH);
}

Test(contact_solver, wide_preparation_matches_one_lane_at_a_time)
{
	CheckWidePreparation(false); // a friction row per point
	CheckWidePreparation(true);	 // central friction (the absent second point's NaN and ∞ masked out too)
}

// Central friction's row sits at the centre of pressure of the warm start's normal impulses
// (tbPressureWeight): 3 and 1 N·s put it a quarter of the way from point 0 to point 1, none at
// point 1 puts it on point 0 (a box resting on one corner), none at all at the middle. Its
// impulse is the points' friction summed, and point 1 keeps no row of its own. Tolerance 1e-6 m:
// a weighted mean of anchors within 1 m, in float.
Test(contact_solver, central_friction_acts_at_the_centre_of_pressure)
{
	tbWorld world;
	tbStepContext context;
	InitPrepContext(&world, &context, true);
	tbSolverBody bodies[2];
	tbSolverMass masses[2];
	memset(bodies, 0, sizeof(bodies));
	memset(masses, 0, sizeof(masses));
	masses[0].invMass = 1.0f;
	masses[0].invI = 6.0f;
	context.bodies = bodies;
	context.masses = masses;
	context.bodyCount = 1; // body 0 dynamic, body 1 the static stand-in

	static const float normal0[] = {3.0f, 2.0f, 0.0f};
	static const float normal1[] = {1.0f, 0.0f, 0.0f};
	static const float share0[] = {0.75f, 1.0f, 0.5f};
	for (int c = 0; c < 3; ++c)
	{
		tbContact contact;
		memset(&contact, 0, sizeof(contact));
		contact.friction = 0.6f;
		contact.manifold.normal = tbMakeVec2(0.0f, -1.0f); // from the box (A) down to the ground (B)
		contact.manifold.pointCount = 2;
		tbVec2 anchorA[2] = {tbMakeVec2(0.5f, -0.5f), tbMakeVec2(-0.5f, -0.5f)};
		tbVec2 anchorB[2] = {tbMakeVec2(2.5f, 0.0f), tbMakeVec2(1.5f, 0.0f)};
		float friction[2] = {0.25f, -0.125f};
		for (int j = 0; j < 2; ++j)
		{
			contact.manifold.points[j].anchorA = anchorA[j];
			contact.manifold.points[j].anchorB = anchorB[j];
			contact.manifold.points[j].normalImpulse = j == 0 ? normal0[c] : normal1[c];
			contact.manifold.points[j].tangentImpulse = friction[j];
		}
		tbContactKey key = {0, 1, (uint32_t)(tb_keyMovesA | tb_keyDynamicA)};
		tbWideContactConstraint block;
		tbInitWideConstraint(&block, 1);
		tbPrepareWideLane(&context, &contact, key, &block, 2);
		float w = share0[c];
		tbVec2 expectA = tbAdd(tbMulSV(w, anchorA[0]), tbMulSV(1.0f - w, anchorA[1]));
		tbVec2 expectB = tbAdd(tbMulSV(w, anchorB[0]), tbMulSV(1.0f - w, anchorB[1]));
		cr_expect(fabsf(tbGetLaneW(&block.frictionAnchorAX, 2) - expectA.x) < 1e-6f &&
					  fabsf(tbGetLaneW(&block.frictionAnchorAY, 2) - expectA.y) < 1e-6f,
				  "case %d: anchor on A (%f, %f), expected (%f, %f)", c, tbGetLaneW(&block.frictionAnchorAX, 2),
				  tbGetLaneW(&block.frictionAnchorAY, 2), expectA.x, expectA.y);
		cr_expect(fabsf(tbGetLaneW(&block.frictionAnchorBX, 2) - expectB.x) < 1e-6f &&
					  fabsf(tbGetLaneW(&block.frictionAnchorBY, 2) - expectB.y) < 1e-6f,
				  "case %d: anchor on B", c);
		cr_expect(tbGetLaneW(&block.impulses[0].tangentImpulse, 2) == 0.125f, "case %d: the friction impulses summed",
				  c);
		cr_expect(tbGetLaneW(&block.impulses[1].tangentImpulse, 2) == 0.0f &&
					  tbGetLaneW(&block.points[1].tangentMass, 2) == 0.0f,
				  "case %d: point 1 has no friction row", c);
		// The row's mass: 1/(1/m + (r × t)²/I) with t = (−1, 0) and r on A at height −0.5: 1/(1 + 6·0.25).
		cr_expect(fabsf(tbGetLaneW(&block.points[0].tangentMass, 2) - 0.4f) < 1e-6f, "case %d: mass %f", c,
				  tbGetLaneW(&block.points[0].tangentMass, 2));
	}
}
