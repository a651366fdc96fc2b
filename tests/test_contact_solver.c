// Unit checks of the solve stage on a hand-built world (no broad phase, no narrow phase): one
// dynamic unit-mass body (B) touching the static ground (A) through a one-point manifold at B's
// centre of mass (anchorB zero, so B's rotation never enters), normal (0, 1) from A to B.
#include "constraint_graph.h"
#include "solver.h"

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
	m->world.solverContacts = m->solverContacts;
	m->world.solverContactsById = m->solverContacts; // one contact: both orders agree
	m->world.solverSlots = m->solverSlots;
	m->world.solverContactCount = 1;
	for (int i = 0; i < 2; ++i)
	{
		m->bodies[i].transform.q = tb_rot_identity;
		m->bodies[i].solverIndex = TB_NULL_INDEX;
		m->bodies[i].gravityScale = 1.0f;
		m->shapes[i].bodyId = i;
	}
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
	m->contact.manifold.points[0].anchorB = tb_vec2_zero;
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
// with the impulse 1 N·s, and report the approach speed.
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
		cr_expect(fabsf(mp->maxNormalImpulse - 1.0f) < 1e-4f, "method %d: impulse %f", method, mp->maxNormalImpulse);
		cr_expect(mp->normalVelocity == -1.0f);
		cr_expect(m.bodies[1].solverIndex == 0 && m.bodies[0].solverIndex == TB_NULL_INDEX);
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

// Restitution: arriving at 4 m/s (above the 1 m/s threshold) with e = 0.5 leaves at 2 m/s.
Test(contact_solver, restitution_reverses_normal_velocity)
{
	for (int method = 0; method < tb_solverMethodCount; ++method)
	{
		MiniWorld m;
		InitMini(&m, (tbSolverMethod)method, tbMakeVec2(0.0f, -4.0f), 0.0f);
		m.contact.restitution = 0.5f;
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
		cr_expect(m.contact.manifold.points[0].maxNormalImpulse == 0.0f);
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
