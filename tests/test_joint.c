// Joints: closed forms (pendulum periods, spring and suspension frequencies, motor speeds, a
// limit under load, a welded cantilever's sag, a motor joint's target), forces, events, and the
// bookkeeping (bad input refused with no change, stale ids after body destruction, joined bodies
// sleeping and waking together, collideConnected, determinism). Each tolerance says where it
// comes from. Worlds step at 60 Hz with 4 sub-steps (h = 1/240 s) unless a test says otherwise.
#include <criterion/criterion.h>

#include "catalogue.h"
#include "error_recorder.h"

#include "tumble/tumble.h"
#include "test_helpers.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define DT (1.0f / 60.0f)
#define SUB_STEPS 4

/// Mean period of a signal from its upward zero crossings (linear interpolation between samples).
typedef struct PeriodMeter
{
	float previous;
	float lastCrossing;
	float firstCrossing;
	int crossings;
	bool started;
} PeriodMeter;

static void Meter_Add(PeriodMeter* meter, float t, float value)
{
	if (meter->started && meter->previous < 0.0f && value >= 0.0f)
	{
		float crossing = t - DT * value / (value - meter->previous);
		if (meter->crossings == 0)
		{
			meter->firstCrossing = crossing;
		}
		meter->lastCrossing = crossing;
		meter->crossings += 1;
	}
	meter->previous = value;
	meter->started = true;
}

static float Meter_Period(const PeriodMeter* meter)
{
	cr_assert(meter->crossings >= 3, "only %d zero crossings", meter->crossings);
	return (meter->lastCrossing - meter->firstCrossing) / (float)(meter->crossings - 1);
}

// ---------------------------------------------------------------------------------------------
// Closed forms

// A point mass on a rigid distance joint: T = 2π·sqrt(L/g)·(1 + θ0²/16 + ...). With θ0 = 0.1 the
// amplitude term is 0.06 %; the soft joint stretches by g/ω² = 0.07 mm at 60 Hz (0.007 % of L)
// and symplectic Euler at h = 1/240 s shifts the frequency by O((hω)²) ≈ 1e-4. The 1 % of the
// issue covers these with room; it runs under every solver method.
Test(joint, point_mass_pendulum_period)
{
	const float L = 1.0f, g = 10.0f, theta0 = 0.1f;
	float expected = 2.0f * TB_PI * sqrtf(L / g) * (1.0f + theta0 * theta0 / 16.0f);
	for (int method = 0; method < tb_solverMethodCount; ++method)
	{
		tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -g));
		tbWorld_SetSolverMethod(world, (tbSolverMethod)method, 8, 3);
		tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, 0.0f));
		tbVec2 start = {L * sinf(theta0), -L * cosf(theta0)};
		tbBodyId bob = CreateDiscOfMass(world, start, 0.05f, 1.0f);
		tbDistanceJointDef def = tbDefaultDistanceJointDef();
		def.base.bodyIdA = ground;
		def.base.bodyIdB = bob;
		def.length = L;
		tbJointId joint = tbCreateDistanceJoint(world, &def);
		cr_assert(tbJoint_IsValid(joint));

		PeriodMeter meter = {0};
		for (int i = 0; i < 480; ++i)
		{
			tbWorld_Step(world, DT, SUB_STEPS);
			Meter_Add(&meter, (float)(i + 1) * DT, tbBody_GetPosition(bob).x);
		}
		float period = Meter_Period(&meter);
		cr_expect(fabsf(period - expected) < 0.01f * expected, "method %d: period %.4f s, expected %.4f s", method,
				  (double)period, (double)expected);
		float length = tbDistanceJoint_GetCurrentLength(joint);
		cr_expect(fabsf(length - L) < 0.002f, "method %d: length %.5f m", method, (double)length);
		tbDestroyWorld(world);
	}
}

// A disc of radius R hung from a point of its rim on a revolute joint: a physical pendulum with
// I_pivot = I_cm + m·d² = (1/2 + 1)·m·R², d = R, so T = 2π·sqrt(I_pivot/(m·g·d)) = 2π·sqrt(1.5·R/g).
// Tolerance 1 % as above (θ0 = 0.1: amplitude term 0.06 %).
Test(joint, disc_pendulum_period)
{
	const float R = 0.5f, g = 10.0f, theta0 = 0.1f;
	float expected = 2.0f * TB_PI * sqrtf(1.5f * R / g) * (1.0f + theta0 * theta0 / 16.0f);
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -g));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbMakeVec2(0.0f, 0.0f));
	// The disc's centre hangs R below the pivot, turned by θ0 about it.
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbMakeVec2(R * sinf(theta0), -R * cosf(theta0));
	bodyDef.rotation = tbMakeRot(theta0);
	tbBodyId disc = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, R};
	tbCreateCircleShape(disc, &shapeDef, &circle);

	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = disc;
	def.base.localFrameB.p = tbMakeVec2(0.0f, R); // the rim point above the centre
	tbJointId joint = tbCreateRevoluteJoint(world, &def);
	cr_assert_float_eq(tbRevoluteJoint_GetAngle(joint), theta0, 1e-5f);

	PeriodMeter meter = {0};
	for (int i = 0; i < 480; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
		Meter_Add(&meter, (float)(i + 1) * DT, tbRevoluteJoint_GetAngle(joint));
	}
	float period = Meter_Period(&meter);
	cr_expect(fabsf(period - expected) < 0.01f * expected, "period %.4f s, expected %.4f s", (double)period,
			  (double)expected);
	tbDestroyWorld(world);
}

// A mass on an undamped distance-joint spring (no gravity, the other end static, the anchor at the
// centre of mass, so the effective mass is m): it oscillates at the set frequency f. The spring is
// solved implicitly each sub-step, which shifts the frequency by O((h·2πf)²) = 0.3 % at 2 Hz and
// h = 1/240 s; the 2 % covers it.
Test(joint, distance_spring_frequency)
{
	const float f = 2.0f, L = 1.0f;
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId body = CreateDiscOfMass(world, tbMakeVec2(L + 0.1f, 0.0f), 0.1f, 2.0f);
	tbDistanceJointDef def = tbDefaultDistanceJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = body;
	def.length = L;
	def.enableSpring = true;
	def.hertz = f;
	def.dampingRatio = 0.0f;
	tbJointId joint = tbCreateDistanceJoint(world, &def);

	PeriodMeter meter = {0};
	for (int i = 0; i < 180; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
		Meter_Add(&meter, (float)(i + 1) * DT, tbDistanceJoint_GetCurrentLength(joint) - L);
	}
	float period = Meter_Period(&meter);
	cr_expect(fabsf(period * f - 1.0f) < 0.02f, "period %.4f s, expected %.4f s", (double)period, (double)(1.0f / f));
	tbDestroyWorld(world);
}

// A box on a horizontal prismatic joint with a motor: gravity acts across the axis (held by the
// joint), nothing resists along it, so the motor reaches its speed exactly once the force needed
// (m·v/t) is within its cap. The 1 %.
Test(joint, prismatic_motor_reaches_speed)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId box = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 1.0f), 0.5f, 0.25f, 2.0f);
	tbPrismaticJointDef def = tbDefaultPrismaticJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = box;
	def.base.localFrameA.p = tbMakeVec2(0.0f, 1.0f);
	def.enableMotor = true;
	def.motorSpeed = 2.0f;
	def.maxMotorForce = 50.0f;
	tbJointId joint = tbCreatePrismaticJoint(world, &def);
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}
	float speed = tbPrismaticJoint_GetSpeed(joint);
	cr_expect(fabsf(speed - 2.0f) < 0.02f, "speed %.4f m/s", (double)speed);
	cr_expect(fabsf(tbBody_GetLinearVelocity(box).x - 2.0f) < 0.02f);
	cr_expect(fabsf(tbBody_GetPosition(box).y - 1.0f) < 0.001f, "the joint holds the box on its axis");
	cr_expect(fabsf(tbBody_GetAngle(box)) < 0.001f, "and keeps its angle");
	// At speed the motor pushes nothing (nothing resists).
	cr_expect(fabsf(tbPrismaticJoint_GetMotorForce(joint)) < 0.5f, "motor force %.3f N",
			  (double)tbPrismaticJoint_GetMotorForce(joint));
	tbDestroyWorld(world);
}

// A 2 m beam (4 kg) on a revolute joint at its left end, a 20 kg ball hung from its tip (its swing
// damped), and the limit at [−0.3, 0.3] rad: the load drives the beam onto the lower limit, which
// must hold within the 0.5° under every solver method once settled (after 2 s; the
// impact itself bounces). Under soft step the limit row settles where its soft impulse stops
// changing, C = −τ/(m_eff·ω²) with m_eff = I_cm of the beam (the row's K is IB⁻¹; the ground does
// not turn), ω = 2π·60 Hz, and τ = (m_beam·g·L/2 + m_ball·g·L)·cos 0.3 = 420 N·m: 0.126°. Checked
// within 5 % (the load's lever arm moves with the small sag itself). Baumgarte and NGS hold the
// limit rigidly with a bias that chatters by a fraction of a degree.
Test(joint, revolute_limit_holds_under_load)
{
	const float lower = -0.3f, g = 10.0f;
	for (int method = 0; method < tb_solverMethodCount; ++method)
	{
		tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -g));
		tbWorld_SetSolverMethod(world, (tbSolverMethod)method, 8, 3);
		tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
		tbBodyId beam = CreateBox(world, tb_dynamicBody, tbMakeVec2(1.0f, 0.0f), 1.0f, 0.1f, 10.0f);
		tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
		def.base.bodyIdA = ground;
		def.base.bodyIdB = beam;
		def.base.localFrameB.p = tbMakeVec2(-1.0f, 0.0f);
		def.enableLimit = true;
		def.lowerAngle = lower;
		def.upperAngle = -lower;
		tbJointId hinge = tbCreateRevoluteJoint(world, &def);

		tbBodyId ball = CreateDiscOfMass(world, tbMakeVec2(2.0f, -0.5f), 0.25f, 20.0f);
		tbBody_SetLinearDamping(ball, 3.0f);
		tbDistanceJointDef rope = tbDefaultDistanceJointDef();
		rope.base.bodyIdA = beam;
		rope.base.bodyIdB = ball;
		rope.base.localFrameA.p = tbMakeVec2(1.0f, 0.0f);
		rope.length = 0.5f;
		tbCreateDistanceJoint(world, &rope);

		float worst = 0.0f;
		for (int i = 0; i < 180; ++i)
		{
			tbWorld_Step(world, DT, SUB_STEPS);
			if (i >= 120)
			{
				worst = fmaxf(worst, fabsf(lower - tbRevoluteJoint_GetAngle(hinge)));
			}
		}
		cr_expect(worst < 0.5f * TB_PI / 180.0f, "method %d: the limit gave %.3f degrees", method,
				  (double)(worst * 180.0f / TB_PI));
		if (method == tb_solverSoft)
		{
			float inertia = tbBody_GetRotationalInertia(beam);
			float omega = 2.0f * TB_PI * 60.0f;
			float torque = (4.0f * g * 1.0f + 20.0f * g * 2.0f) * cosf(lower);
			float expected = torque / (inertia * omega * omega);
			float sag = lower - tbRevoluteJoint_GetAngle(hinge);
			cr_expect(fabsf(sag - expected) < 0.05f * expected, "soft limit sag %.4f degrees, derived %.4f", 
					  (double)(sag * 180.0f / TB_PI), (double)(expected * 180.0f / TB_PI));
		}
		tbDestroyWorld(world);
	}
}

/// Largest pin gap of a 2 m, 10 kg beam pinned at one end to the ground by a revolute joint and
/// released level, over 3 s; its final angle in *angle.
static float SwingingBeamPinGap(bool jointTrees, float* angle)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = tbMakeVec2(0.0f, -10.0f);
	worldDef.enableJointTrees = jointTrees;
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbMakeVec2(1.0f, 0.0f);
	tbBodyId beam = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.density = 50.0f;
	tbPolygon box = tbMakeBox(1.0f, 0.05f);
	tbCreatePolygonShape(beam, &shapeDef, &box);
	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = beam;
	def.base.localFrameB.p = tbMakeVec2(-1.0f, 0.0f);
	tbJointId hinge = tbCreateRevoluteJoint(world, &def);
	float worst = 0.0f;
	for (int i = 0; i < 180; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
		worst = fmaxf(worst, tbJoint_GetLinearSeparation(hinge));
	}
	*angle = tbRevoluteJoint_GetAngle(hinge);
	tbDestroyWorld(world);
	return worst;
}

// A revolute joint alone between the ground and one body (a flipper, a door) is a joint tree of one
// joint, and its exact solve is the joint's own 2 × 2 pin solve made rigid (joint_tree.c). A rigid
// row with bias β·C leaves open what the load moves the pin in a sub-step before the row corrects
// it, about a·h/β: at the bottom of the swing the pin carries the weight and the centripetal load,
// a = g + ω²·(L/2) = 10 + 15 m/s² (ω² = 1.5·g/(L/2) from the energy of a 2 m beam released level,
// I = m·L²/3), with h = 1/240 s and β = ω0/(2ζ + h·ω0) = 67.7 /s (60 Hz, ζ = 2): 1.5 mm. The soft
// row gives more, its spring yielding too (measured 0.46 mm rigid against 0.58 mm soft: the bound
// asks for a tenth less). Both swing alike: pin gaps a fraction of a millimetre on a 2 m beam turn
// it by about 1e-4 rad, and the angles must agree within ten times that.
Test(joint, revolute_alone_to_ground_is_solved_rigid)
{
	float rigidAngle, softAngle;
	float rigid = SwingingBeamPinGap(true, &rigidAngle);
	float soft = SwingingBeamPinGap(false, &softAngle);
	cr_expect(rigid < 0.9f * soft, "pin gap %.3g m rigid, %.3g m soft", (double)rigid, (double)soft);
	cr_expect(rigid < 1.5e-3f, "pin gap %.3g m, over a·h/β = 1.5 mm", (double)rigid);
	cr_expect(fabsf(rigidAngle - softAngle) < 1e-3f, "angle %.5f rigid, %.5f soft", (double)rigidAngle,
			  (double)softAngle);
}

// A wheel (disc, 5 kg) on a wheel joint with a vertical axis to a static chassis, spring 4 Hz
// undamped, no gravity: displaced along the axis it oscillates at 4 Hz (the anchor is at its
// centre, so the effective mass along the axis is m). Implicit-spring error O((h·2πf)²) = 1 % at
// h = 1/240 s; the 5 %.
Test(joint, wheel_suspension_frequency)
{
	const float f = 4.0f;
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId chassis = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId wheel = CreateDiscOfMass(world, tbMakeVec2(0.0f, 0.05f), 0.4f, 5.0f);
	tbWheelJointDef def = tbDefaultWheelJointDef();
	def.base.bodyIdA = chassis;
	def.base.bodyIdB = wheel;
	def.base.localFrameA.q = tbMakeRot(0.5f * TB_PI); // axis straight up
	def.hertz = f;
	def.dampingRatio = 0.0f;
	tbCreateWheelJoint(world, &def);
	PeriodMeter meter = {0};
	for (int i = 0; i < 90; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
		Meter_Add(&meter, (float)(i + 1) * DT, tbBody_GetPosition(wheel).y);
		cr_assert(fabsf(tbBody_GetPosition(wheel).x) < 1e-4f, "the wheel stays on its line");
	}
	float period = Meter_Period(&meter);
	cr_expect(fabsf(period * f - 1.0f) < 0.05f, "period %.4f s, expected %.4f s", (double)period, (double)(1.0f / f));
	tbDestroyWorld(world);
}

// A beam of length L and mass m welded at its left end to a static wall.
// Row by row (enableJointTrees = false), each soft row settles where its impulse stops changing:
// C = −λ/(m_eff·h·ω²), a spring of stiffness m_eff·ω² per row (ω = 2π·60 Hz, the default joint
// hertz, under the ¼-sub-step-rate cap). The linear row at the anchor carries m·g with
// m_eff = 1/K_yy = m/4 (K_yy = 1/m + (L/2)²/I_cm, I_cm = m·L²/12): the anchor drops 4·g/ω². The
// angular row carries m·g·L/2 with m_eff = I_cm: the beam turns by 6·g/(L·ω²). Tip sag =
// 4·g/ω² + L·6·g/(L·ω²) = 10·g/ω² = 0.70 mm; measured within 10 % (rounding, settling after 3 s).
// In a joint tree (the default) the rows are rigid with a bias β·C and no compliance: they settle
// at C = 0, so the sag is float rounding at the 2 m scale: below 10 µm.
Test(joint, weld_cantilever_sag)
{
	const float L = 2.0f, g = 10.0f;
	for (int trees = 0; trees < 2; ++trees)
	{
		tbWorldDef worldDef = tbDefaultWorldDef();
		worldDef.enableJointTrees = trees != 0;
		tbWorldId world = tbCreateWorld(&worldDef);
		tbBodyId wall = CreateBody(world, tb_staticBody, tbVec2_zero);
		tbBodyId beam = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.5f * L, 0.0f), 0.5f * L, 0.1f, 5.0f);
		tbWeldJointDef def = tbDefaultWeldJointDef();
		def.base.bodyIdA = wall;
		def.base.bodyIdB = beam;
		def.base.localFrameB.p = tbMakeVec2(-0.5f * L, 0.0f);
		tbCreateWeldJoint(world, &def);
		for (int i = 0; i < 180; ++i)
		{
			tbWorld_Step(world, DT, SUB_STEPS);
		}
		float sag = -tbBody_GetWorldPoint(beam, tbMakeVec2(0.5f * L, 0.0f)).y;
		if (trees)
		{
			cr_expect(fabsf(sag) < 1e-5f, "tree: tip sag %.4f mm", (double)(1000.0f * sag));
		}
		else
		{
			float omega = 2.0f * TB_PI * 60.0f;
			float derived = 10.0f * g / (omega * omega);
			cr_expect(sag < 1.1f * derived && sag > 0.9f * derived, "row by row: tip sag %.3f mm, derived %.3f mm",
					  (double)(1000.0f * sag), (double)(1000.0f * derived));
		}
		tbDestroyWorld(world);
	}
}

// A motor joint from a static body pulls a box onto a target frame with critically damped linear
// and angular springs (4 Hz): after t = 3 s the remaining error of a critically damped spring is
// e^(−ωt)·(1 + ωt) ≈ 1e−31 of the start, so what is left is the soft spring's sag under the load
// (no gravity here: none) and rounding: 1 mm and 0.001 rad. Then velocity control: the joint
// drives the box at the target velocity against gravity (force cap far above m·g): within 1 %.
Test(joint, motor_joint_reaches_target)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId box = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	tbMotorJointDef def = tbDefaultMotorJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = box;
	def.base.localFrameA.p = tbMakeVec2(3.0f, 2.0f);
	def.base.localFrameA.q = tbMakeRot(0.5f);
	def.linearHertz = 4.0f;
	def.linearDampingRatio = 1.0f;
	def.maxSpringForce = 1000.0f;
	def.angularHertz = 4.0f;
	def.angularDampingRatio = 1.0f;
	def.maxSpringTorque = 1000.0f;
	tbJointId joint = tbCreateMotorJoint(world, &def);
	for (int i = 0; i < 180; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}
	tbVec2 p = tbBody_GetPosition(box);
	cr_expect(fabsf(p.x - 3.0f) < 0.001f && fabsf(p.y - 2.0f) < 0.001f, "box at (%.4f, %.4f)", (double)p.x, (double)p.y);
	cr_expect(fabsf(tbBody_GetAngle(box) - 0.5f) < 0.001f, "angle %.4f", (double)tbBody_GetAngle(box));

	// Velocity control, springs off, with gravity.
	tbWorld_SetGravity(world, tbMakeVec2(0.0f, -10.0f));
	tbMotorJoint_SetMaxSpringForce(joint, 0.0f);
	tbMotorJoint_SetMaxSpringTorque(joint, 0.0f);
	tbMotorJoint_SetLinearVelocity(joint, tbMakeVec2(1.0f, 0.5f));
	tbMotorJoint_SetMaxVelocityForce(joint, 100.0f);
	tbMotorJoint_SetAngularVelocity(joint, 0.0f);
	tbMotorJoint_SetMaxVelocityTorque(joint, 100.0f);
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}
	tbVec2 v = tbBody_GetLinearVelocity(box);
	cr_expect(fabsf(v.x - 1.0f) < 0.01f && fabsf(v.y - 0.5f) < 0.005f, "velocity (%.4f, %.4f)", (double)v.x, (double)v.y);
	tbDestroyWorld(world);
}

// ---------------------------------------------------------------------------------------------
// Forces and events

// A bob hanging at rest on a distance joint: the joint holds its weight, force (0, m·g) on the
// bob. The soft row settles to its load within rounding: 0.1 %.
Test(joint, constraint_force_holds_the_weight)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId bob = CreateDiscOfMass(world, tbMakeVec2(0.0f, -1.0f), 0.1f, 3.0f);
	tbBody_EnableSleep(bob, false); // events come from awake joints only
	tbDistanceJointDef def = tbDefaultDistanceJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = bob;
	def.base.forceThreshold = 29.0f; // just below m·g = 30 N
	tbJointId joint = tbCreateDistanceJoint(world, &def);
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}
	tbVec2 force = tbJoint_GetConstraintForce(joint);
	cr_expect(fabsf(force.x) < 0.03f && fabsf(force.y - 30.0f) < 0.03f, "force (%.4f, %.4f) N", (double)force.x,
			  (double)force.y);
	cr_expect_float_eq(tbJoint_GetConstraintTorque(joint), 0.0f, 1e-6f);
	tbJointEvents events = tbWorld_GetJointEvents(world);
	cr_assert_eq(events.count, 1, "the 30 N load passes the 29 N threshold");
	cr_expect(TB_ID_EQUALS(events.jointEvents[0].jointId, joint));

	tbJoint_SetForceThreshold(joint, 31.0f);
	tbWorld_Step(world, DT, SUB_STEPS);
	cr_expect_eq(tbWorld_GetJointEvents(world).count, 0, "31 N is not reached");
	tbDestroyWorld(world);
}

// Joint events are looked for only in steps whose joints include one with a threshold
// (tbFinishJoints): a threshold set between steps on a joint made without one must be seen at the
// next step, and one lifted back to FLT_MAX must end the events. The bob's load is m·g = 30 N.
Test(joint, a_threshold_set_between_steps_reports_at_the_next_step)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId bob = CreateDiscOfMass(world, tbMakeVec2(0.0f, -1.0f), 0.1f, 3.0f);
	tbBody_EnableSleep(bob, false);
	tbDistanceJointDef def = tbDefaultDistanceJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = bob;
	tbJointId joint = tbCreateDistanceJoint(world, &def);
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
		cr_assert_eq(tbWorld_GetJointEvents(world).count, 0, "step %d: no threshold, no event", i);
	}
	tbJoint_SetForceThreshold(joint, 29.0f);
	tbWorld_Step(world, DT, SUB_STEPS);
	tbJointEvents events = tbWorld_GetJointEvents(world);
	cr_assert_eq(events.count, 1, "the 30 N load passes the 29 N threshold set before this step");
	cr_expect(TB_ID_EQUALS(events.jointEvents[0].jointId, joint));
	tbJoint_SetForceThreshold(joint, FLT_MAX);
	tbWorld_Step(world, DT, SUB_STEPS);
	cr_expect_eq(tbWorld_GetJointEvents(world).count, 0, "the threshold lifted: no event");
	tbDestroyWorld(world);
}

// ---------------------------------------------------------------------------------------------
// Bookkeeping

Test(joint, bad_input_is_refused_without_change, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbWorldId other = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId body = CreateDiscOfMass(world, tbMakeVec2(0.0f, -1.0f), 0.1f, 1.0f);
	tbBodyId stranger = CreateDiscOfMass(other, tbMakeVec2(0.0f, -1.0f), 0.1f, 1.0f);
	tbBodyId dead = CreateDiscOfMass(world, tbMakeVec2(3.0f, 0.0f), 0.1f, 1.0f);
	tbDestroyBody(dead);

	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = body;

	struct Case
	{
		const char* argument;
		tbRevoluteJointDef def;
	} cases[11];
	int n = 0;
	cases[n].argument = "same body";
	cases[n].def = def;
	cases[n++].def.base.bodyIdA = body;
	cases[n].argument = "another world";
	cases[n].def = def;
	cases[n++].def.base.bodyIdB = stranger;
	cases[n].argument = "def->base.bodyIdB";
	cases[n].def = def;
	cases[n++].def.base.bodyIdB = dead;
	cases[n].argument = "def->base.localFrameA.q";
	cases[n].def = def;
	cases[n++].def.base.localFrameA.q = (tbRot){0.5f, 0.5f};
	cases[n].argument = "def->base.localFrameB.p";
	cases[n].def = def;
	cases[n++].def.base.localFrameB.p = (tbVec2){NAN, 0.0f};
	// An anchor beyond TB_MAX_COORDINATE (1e6 m) from its body: the fuzzer's 8.9e17 m anchor made
	// NaN velocities before it was refused.
	cases[n].argument = "def->base.localFrameA.p";
	cases[n].def = def;
	cases[n++].def.base.localFrameA.p = (tbVec2){8.9e17f, -2.2f};
	cases[n].argument = "def->hertz";
	cases[n].def = def;
	cases[n++].def.hertz = -1.0f;
	cases[n].argument = "def->lowerAngle";
	cases[n].def = def;
	cases[n].def.lowerAngle = 0.5f;
	cases[n++].def.upperAngle = 0.2f;
	cases[n].argument = "def->base.constraintHertz";
	cases[n].def = def;
	cases[n++].def.base.constraintHertz = INFINITY;
	cases[n].argument = "def->base.forceThreshold";
	cases[n].def = def;
	cases[n++].def.base.forceThreshold = -1.0f;
	cases[n].argument = "tbDefaultRevoluteJointDef";
	cases[n].def = def;
	cases[n++].def.internalValue = 0;

	for (int i = 0; i < n; ++i)
	{
		int before = s_errors;
		tbJointId id = tbCreateRevoluteJoint(world, &cases[i].def);
		cr_expect(TB_IS_NULL(id), "case %s made a joint", cases[i].argument);
		ExpectError(before, "tbCreateRevoluteJoint", cases[i].argument);
	}
	cr_expect_eq(tbBody_GetJointCount(body), 0, "nothing was created");
	cr_expect_eq(tbBody_GetJointCount(ground), 0);

	// Setters refuse bad values and keep the old ones; a kind mismatch is refused.
	tbJointId joint = tbCreateRevoluteJoint(world, &def);
	cr_assert(tbJoint_IsValid(joint));
	int before = s_errors;
	cr_expect(tbRevoluteJoint_SetLimits(joint, 0.4f, 0.1f) == false);
	ExpectError(before, "tbRevoluteJoint_SetLimits", "lower");
	cr_expect_float_eq(tbRevoluteJoint_GetLowerLimit(joint), 0.0f, 0.0f);
	before = s_errors;
	cr_expect(tbRevoluteJoint_SetSpringHertz(joint, NAN) == false);
	ExpectError(before, "tbRevoluteJoint_SetSpringHertz", "hertz");
	before = s_errors;
	cr_expect(tbDistanceJoint_SetLength(joint, 2.0f) == false);
	ExpectError(before, "tbDistanceJoint_SetLength", "revolute joint");
	before = s_errors;
	cr_expect(tbJoint_SetLocalFrameA(joint, (tbTransform){{0.0f, 0.0f}, {2.0f, 0.0f}}) == false);
	ExpectError(before, "tbJoint_SetLocalFrameA", "localFrame.q");
	cr_expect_float_eq(tbJoint_GetLocalFrameA(joint).q.c, 1.0f, 0.0f);

	tbDestroyJoint(joint);
	before = s_errors;
	tbDestroyJoint(joint);
	ExpectError(before, "tbDestroyJoint", "jointId");
	before = s_errors;
	cr_expect(TB_IS_NULL(tbJoint_GetBodyA(joint)));
	ExpectError(before, "tbJoint_GetBodyA", "destroyed");
	tbDestroyWorld(other);
	tbDestroyWorld(world);
}

// A revolute joint whose anchors start 290 km apart (the fuzzer's scene: its anchor on body B lies
// 291,522 m from the body, within TB_MAX_COORDINATE, so it is accepted). The soft joint asks for the
// gap over its spring time, 7e7 m/s and 8e17 rad/s, which used to reach non-finite positions by
// step 5. In a world with joints the positions are integrated with speeds at most 16 times the
// world's limits (integrator.c, tbGuardSpeeds), so the centre of mass moves by at most
// 16·maxLinearSpeed·dt a step (the four sub-steps' h·|v| add up to it; 0.1 % is allowed for the
// float sums), and everything stays finite. Without the guard the test fails in its first steps.
Test(joint, anchors_far_apart_keep_positions_finite)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId body = CreateDiscOfMass(world, tbMakeVec2(0.0f, 6.0f), 0.1f, 0.1f);
	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = body;
	def.base.localFrameA.p = tbMakeVec2(4.0f, 0.3f);
	def.base.localFrameB.p = tbMakeVec2(291521.89f, -2.2f);
	tbJointId joint = tbCreateRevoluteJoint(world, &def);
	cr_assert(tbJoint_IsValid(joint));
	float dt = 1.0f / 60.0f;
	float maxStep = 16.0f * tbWorld_GetMaximumLinearSpeed(world) * dt;
	tbVec2 previous = tbBody_GetWorldCenter(body);
	for (int i = 0; i < 20; ++i)
	{
		tbWorld_Step(world, dt, 4);
		tbVec2 c = tbBody_GetWorldCenter(body);
		cr_assert(tbIsValidVec2(c) && tbIsValidFloat(tbBody_GetAngularVelocity(body)),
				  "step %d: centre (%g, %g), spin %g", i, c.x, c.y, tbBody_GetAngularVelocity(body));
		cr_expect(tbDistance(c, previous) <= maxStep * 1.001f, "step %d moved %g m (bound %g m)", i,
				  tbDistance(c, previous), maxStep);
		previous = c;
	}
	tbDestroyWorld(world);
}

Test(joint, destroying_a_body_makes_its_joint_ids_stale, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId a = CreateDiscOfMass(world, tbMakeVec2(0.0f, -1.0f), 0.1f, 1.0f);
	tbBodyId b = CreateDiscOfMass(world, tbMakeVec2(0.0f, -2.0f), 0.1f, 1.0f);
	tbDistanceJointDef def = tbDefaultDistanceJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = a;
	tbJointId top = tbCreateDistanceJoint(world, &def);
	def.base.bodyIdA = a;
	def.base.bodyIdB = b;
	tbJointId bottom = tbCreateDistanceJoint(world, &def);
	cr_expect_eq(tbBody_GetJointCount(a), 2);
	tbJointId listed[4];
	cr_expect_eq(tbBody_GetJoints(a, listed, 4), 2);
	for (int i = 0; i < 10; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}

	tbDestroyBody(a);
	cr_expect(tbJoint_IsValid(top) == false);
	cr_expect(tbJoint_IsValid(bottom) == false);
	cr_expect_eq(tbBody_GetJointCount(ground), 0);
	cr_expect_eq(tbBody_GetJointCount(b), 0);
	cr_expect(tbBody_IsAwake(b), "the other body is woken");

	// A new joint may reuse the slot: the old id stays stale (generation).
	def.base.bodyIdA = ground;
	def.base.bodyIdB = b;
	tbJointId fresh = tbCreateDistanceJoint(world, &def);
	cr_expect(tbJoint_IsValid(fresh));
	cr_expect(tbJoint_IsValid(top) == false && tbJoint_IsValid(bottom) == false);
	int before = s_errors;
	tbDistanceJoint_SetLength(top, 3.0f);
	ExpectError(before, "tbDistanceJoint_SetLength", "destroyed");
	cr_expect_float_eq(tbDistanceJoint_GetLength(fresh), 1.0f, 0.0f);
	for (int i = 0; i < 10; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}
	tbDestroyWorld(world);
	cr_expect(tbJoint_IsValid(fresh) == false, "destroying the world makes joint ids stale");
}

/// A chain of `count` boxes hanging from `anchor` on revolute joints, links 0.5 m apart.
static void MakeHangingChain(tbWorldId world, tbBodyId anchorBody, tbVec2 anchor, int count, tbBodyId* links)
{
	tbBodyId previous = anchorBody;
	for (int i = 0; i < count; ++i)
	{
		tbVec2 pivot = {anchor.x, anchor.y - 0.5f * (float)i};
		links[i] = CreateBox(world, tb_dynamicBody, tbMakeVec2(pivot.x, pivot.y - 0.25f), 0.05f, 0.25f, 1.0f);
		tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
		def.base.bodyIdA = previous;
		def.base.bodyIdB = links[i];
		def.base.localFrameA.p = tbBody_GetLocalPoint(previous, pivot);
		def.base.localFrameB.p = tbBody_GetLocalPoint(links[i], pivot);
		tbCreateRevoluteJoint(world, &def);
		previous = links[i];
	}
}

// Joined bodies are one island: a hanging chain falls asleep as a whole, and touching its bottom
// link wakes every link. A second chain on the same static ground is another island (a joint to a
// static body links nothing): it sleeps on.
Test(joint, joined_bodies_sleep_and_wake_together)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId left[4], right[4];
	MakeHangingChain(world, ground, tbMakeVec2(0.0f, 0.0f), 4, left);
	MakeHangingChain(world, ground, tbMakeVec2(3.0f, 0.0f), 4, right);
	int steps = 0;
	while (steps < 600 && (tbBody_IsAwake(left[0]) || tbBody_IsAwake(right[0])))
	{
		tbWorld_Step(world, DT, SUB_STEPS);
		steps += 1;
	}
	cr_assert(steps < 600, "the chains never slept");
	for (int i = 0; i < 4; ++i)
	{
		cr_expect(tbBody_IsAwake(left[i]) == false && tbBody_IsAwake(right[i]) == false, "link %d sleeps", i);
	}

	tbBody_SetLinearVelocity(left[3], tbMakeVec2(1.0f, 0.0f));
	for (int i = 0; i < 4; ++i)
	{
		cr_expect(tbBody_IsAwake(left[i]), "left link %d woke with the bottom link", i);
		cr_expect(tbBody_IsAwake(right[i]) == false, "right link %d sleeps on", i);
	}
	tbWorld_Step(world, DT, SUB_STEPS);
	cr_expect(tbBody_GetLinearVelocity(left[0]).x > 0.0f, "the push travels up the chain");
	for (int i = 0; i < 4; ++i)
	{
		cr_expect(tbBody_IsAwake(right[i]) == false);
	}
	tbDestroyWorld(world);
}

// A joint with one side awake wakes the other at the next step. Sleeping one body of an awake
// chain by hand (tbBody_SetAwake(false)) is such a case; the step looks for it only after the
// awake set changed (joint.c), and this is the change it must notice. A step later nothing changed
// and the chain stays awake with its link.
Test(joint, a_body_put_to_sleep_by_hand_is_woken_by_its_awake_partner)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId links[4];
	MakeHangingChain(world, ground, tbMakeVec2(0.0f, 0.0f), 4, links);
	tbBody_SetLinearVelocity(links[3], tbMakeVec2(2.0f, 0.0f)); // swinging: nothing rests
	tbWorld_Step(world, DT, SUB_STEPS);
	tbBody_SetAwake(links[2], false);
	cr_assert(tbBody_IsAwake(links[2]) == false);
	cr_assert(tbBody_IsAwake(links[1]) && tbBody_IsAwake(links[3]));
	tbWorld_Step(world, DT, SUB_STEPS);
	cr_expect(tbBody_IsAwake(links[2]), "the awake links woke the one put to sleep");
	tbWorld_Step(world, DT, SUB_STEPS);
	for (int i = 0; i < 4; ++i)
	{
		cr_expect(tbBody_IsAwake(links[i]), "link %d awake", i);
	}
	tbDestroyWorld(world);
}

// A joint tree (joint_tree.c) between bodies whose masses and lever arms spread over many orders
// of magnitude: a 0.1 kg capsule pinned 60 m from the centre of an 8,171 kg disc of radius 51 m
// (mass ratio 8e4, inertia ratio 5e9). Solved in single precision the tree's impulses lost to
// cancellation what its velocities gained, the warm start re-applied them, and the velocity grew
// 150-fold per sub-step to NaN in five steps (found by fuzz_scene). Falling freely, the pair must
// fall freely: v = −g·t after n steps of 1/60 s (the sub-stepped integration is exact for constant
// acceleration; the tolerance is float rounding of 60 steps).
Test(joint, tree_of_very_different_bodies_falls_freely)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbMakeVec2(0.0f, 6.0f);
	tbBodyId light = tbCreateBody(world, &bodyDef);
	bodyDef.position = tbMakeVec2(0.0f, 66.5f);
	tbBodyId heavy = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCapsule capsule = {{0.0f, -0.2f}, {0.0f, 0.2f}, 0.1f};
	tbCreateCapsuleShape(light, &shapeDef, &capsule);
	tbCircle disc = {{0.0f, 0.0f}, 51.0f};
	tbCreateCircleShape(heavy, &shapeDef, &disc);
	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	def.base.bodyIdA = light;
	def.base.bodyIdB = heavy;
	def.base.localFrameA.p = tbMakeVec2(0.0f, 0.3f);
	def.base.localFrameB.p = tbMakeVec2(0.0f, -60.2f);
	tbCreateRevoluteJoint(world, &def);
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}
	float expected = -10.0f * 60.0f * DT;
	cr_expect(fabsf(tbBody_GetLinearVelocity(light).y - expected) < 1e-3f, "light body %g m/s, free fall %g",
			  (double)tbBody_GetLinearVelocity(light).y, (double)expected);
	cr_expect(fabsf(tbBody_GetLinearVelocity(heavy).y - expected) < 1e-3f, "heavy body %g m/s, free fall %g",
			  (double)tbBody_GetLinearVelocity(heavy).y, (double)expected);
	cr_expect(fabsf(tbBody_GetLinearVelocity(light).x) < 1e-3f);
	tbDestroyWorld(world);
}

// collideConnected = false: two overlapping boxes joined by a revolute joint make no contact and
// stay where they are; true: they collide and are pushed apart. Destroying the forbidding joint
// lets the broad phase find the pair again.
Test(joint, collide_connected_filters_contacts)
{
	for (int collide = 0; collide < 2; ++collide)
	{
		tbWorldId world = CreateWorld(tbVec2_zero);
		tbBodyId a = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.0f), 0.5f, 0.5f, 1.0f);
		tbBodyId b = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.6f, 0.0f), 0.5f, 0.5f, 1.0f);
		tbWorld_Step(world, DT, SUB_STEPS); // a contact exists before the joint (and pushed them)
		cr_assert(tbWorld_GetCounters(world).touchingCount > 0);
		tbBody_SetTransform(a, tbMakeVec2(0.0f, 0.0f), tbRot_identity);
		tbBody_SetTransform(b, tbMakeVec2(0.6f, 0.0f), tbRot_identity);
		tbBody_SetLinearVelocity(a, tbVec2_zero);
		tbBody_SetLinearVelocity(b, tbVec2_zero);
		tbBody_SetAngularVelocity(a, 0.0f);
		tbBody_SetAngularVelocity(b, 0.0f);
		tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
		def.base.bodyIdA = a;
		def.base.bodyIdB = b;
		def.base.localFrameA.p = tbMakeVec2(0.3f, 0.0f);
		def.base.localFrameB.p = tbMakeVec2(-0.3f, 0.0f);
		def.base.collideConnected = collide != 0;
		tbJointId joint = tbCreateRevoluteJoint(world, &def);
		for (int i = 0; i < 30; ++i)
		{
			tbWorld_Step(world, DT, SUB_STEPS);
		}
		int touching = tbWorld_GetCounters(world).touchingCount;
		if (collide)
		{
			cr_expect(touching > 0, "collideConnected: they touch");
		}
		else
		{
			cr_expect_eq(touching, 0, "no contact between joined bodies");
			cr_expect(fabsf(tbBody_GetPosition(b).x - 0.6f) < 1e-3f, "and nothing pushed them");
			tbDestroyJoint(joint);
			tbWorld_Step(world, DT, SUB_STEPS);
			cr_expect(tbWorld_GetCounters(world).touchingCount > 0, "the pair is found again");
		}
		tbDestroyWorld(world);
	}
}

/// FNV-1a over the transforms and velocities of the given bodies.
static uint64_t HashBodies(const tbBodyId* bodies, int count)
{
	uint64_t hash = 1469598103934665603ull;
	for (int i = 0; i < count; ++i)
	{
		tbTransform xf = tbBody_GetTransform(bodies[i]);
		tbVec2 v = tbBody_GetLinearVelocity(bodies[i]);
		float values[7] = {xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y, tbBody_GetAngularVelocity(bodies[i])};
		const unsigned char* bytes = (const unsigned char*)values;
		for (size_t k = 0; k < sizeof(values); ++k)
		{
			hash = (hash ^ bytes[k]) * 1099511628211ull;
		}
	}
	return hash;
}

/// A jointed scene with every kind: a chain falling onto a wheeled cart driven by a motor, a
/// prismatic piston, a welded pair, a spring, a motor joint and a filter joint, over boxes on
/// the ground. Returns the hash after `steps` steps under the given broad phase.
static uint64_t RunJointedScene(tbBroadPhaseMethod method, int steps)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.broadPhase = method;
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyId bodies[64];
	int n = 0;
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbSegment floor = {{-20.0f, 0.0f}, {20.0f, 0.0f}};
	tbCreateSegmentShape(ground, &shapeDef, &floor);

	// Cart: a box on two motorised wheels.
	tbBodyId cart = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 1.0f), 1.0f, 0.2f, 2.0f);
	bodies[n++] = cart;
	for (int side = -1; side <= 1; side += 2)
	{
		tbBodyId wheel = CreateDiscOfMass(world, tbMakeVec2(0.7f * (float)side, 0.4f), 0.3f, 1.0f);
		bodies[n++] = wheel;
		tbWheelJointDef def = tbDefaultWheelJointDef();
		def.base.bodyIdA = cart;
		def.base.bodyIdB = wheel;
		def.base.localFrameA.p = tbMakeVec2(0.7f * (float)side, -0.6f);
		def.base.localFrameA.q = tbMakeRot(0.5f * TB_PI);
		def.hertz = 5.0f;
		def.enableMotor = true;
		def.motorSpeed = -4.0f;
		def.maxMotorTorque = 20.0f;
		def.enableLimit = true;
		def.lowerTranslation = -0.2f;
		def.upperTranslation = 0.2f;
		tbCreateWheelJoint(world, &def);
	}
	// A chain from a static anchor, swinging onto the cart.
	tbBodyId chain[8];
	MakeHangingChain(world, ground, tbMakeVec2(3.0f, 5.0f), 8, chain);
	for (int i = 0; i < 8; ++i)
	{
		bodies[n++] = chain[i];
	}
	tbBody_SetLinearVelocity(chain[7], tbMakeVec2(-5.0f, 0.0f));
	// Piston on a prismatic joint with a spring and limits.
	tbBodyId piston = CreateBox(world, tb_dynamicBody, tbMakeVec2(-4.0f, 2.0f), 0.3f, 0.3f, 1.0f);
	bodies[n++] = piston;
	tbPrismaticJointDef prismatic = tbDefaultPrismaticJointDef();
	prismatic.base.bodyIdA = ground;
	prismatic.base.bodyIdB = piston;
	prismatic.base.localFrameA.p = tbMakeVec2(-4.0f, 2.0f);
	prismatic.base.localFrameA.q = tbMakeRot(0.5f * TB_PI);
	prismatic.enableSpring = true;
	prismatic.hertz = 2.0f;
	prismatic.dampingRatio = 0.1f;
	prismatic.enableLimit = true;
	prismatic.lowerTranslation = -1.5f;
	prismatic.upperTranslation = 1.0f;
	tbCreatePrismaticJoint(world, &prismatic);
	// A welded pair with soft weld, and a spring to the ground.
	tbBodyId a = CreateBox(world, tb_dynamicBody, tbMakeVec2(-2.0f, 3.0f), 0.4f, 0.2f, 1.0f);
	tbBodyId b = CreateBox(world, tb_dynamicBody, tbMakeVec2(-1.2f, 3.0f), 0.4f, 0.2f, 1.0f);
	bodies[n++] = a;
	bodies[n++] = b;
	tbWeldJointDef weld = tbDefaultWeldJointDef();
	weld.base.bodyIdA = a;
	weld.base.bodyIdB = b;
	weld.base.localFrameA.p = tbMakeVec2(0.4f, 0.0f);
	weld.base.localFrameB.p = tbMakeVec2(-0.4f, 0.0f);
	weld.angularHertz = 3.0f;
	weld.angularDampingRatio = 0.5f;
	tbCreateWeldJoint(world, &weld);
	tbDistanceJointDef spring = tbDefaultDistanceJointDef();
	spring.base.bodyIdA = ground;
	spring.base.bodyIdB = a;
	spring.base.localFrameA.p = tbMakeVec2(-2.0f, 6.0f);
	spring.length = 2.0f;
	spring.enableSpring = true;
	spring.hertz = 1.5f;
	spring.dampingRatio = 0.2f;
	tbCreateDistanceJoint(world, &spring);
	// A box dragged by a motor joint, and a filter joint between two overlapping boxes.
	tbBodyId dragged = CreateBox(world, tb_dynamicBody, tbMakeVec2(6.0f, 1.0f), 0.3f, 0.3f, 1.0f);
	bodies[n++] = dragged;
	tbMotorJointDef motor = tbDefaultMotorJointDef();
	motor.base.bodyIdA = ground;
	motor.base.bodyIdB = dragged;
	motor.base.localFrameA.p = tbMakeVec2(4.0f, 3.0f);
	motor.linearHertz = 2.0f;
	motor.linearDampingRatio = 0.7f;
	motor.maxSpringForce = 50.0f;
	tbCreateMotorJoint(world, &motor);
	tbBodyId f1 = CreateBox(world, tb_dynamicBody, tbMakeVec2(8.0f, 0.5f), 0.5f, 0.5f, 1.0f);
	tbBodyId f2 = CreateBox(world, tb_dynamicBody, tbMakeVec2(8.5f, 0.5f), 0.5f, 0.5f, 1.0f);
	bodies[n++] = f1;
	bodies[n++] = f2;
	tbFilterJointDef filter = tbDefaultFilterJointDef();
	filter.base.bodyIdA = f1;
	filter.base.bodyIdB = f2;
	tbCreateFilterJoint(world, &filter);
	for (int i = 0; i < 6; ++i)
	{
		tbVec2 position = tbMakeVec2(-1.0f + 0.5f * (float)i, 0.25f + 0.6f * (float)(i % 2));
		bodies[n++] = CreateBox(world, tb_dynamicBody, position, 0.25f, 0.25f, 1.0f);
	}

	for (int i = 0; i < steps; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}
	for (int i = 0; i < n; ++i)
	{
		tbVec2 p = tbBody_GetPosition(bodies[i]);
		cr_assert(tbIsValidVec2(p) && fabsf(p.x) < 30.0f && p.y > -0.5f && p.y < 10.0f, "body %d at (%g, %g)", i,
				  (double)p.x, (double)p.y);
	}
	uint64_t hash = HashBodies(bodies, n);
	tbDestroyWorld(world);
	return hash;
}

// The same jointed scene twice gives the same bits, and every broad phase gives the same bits
// (joints are solved in joint-id order, independent of how contacts were found).
Test(joint, determinism_with_joints)
{
	uint64_t first = RunJointedScene(tb_broadPhaseTree, 240);
	uint64_t second = RunJointedScene(tb_broadPhaseTree, 240);
	cr_expect_eq(first, second, "same scene twice: %016llx vs %016llx", (unsigned long long)first,
				 (unsigned long long)second);
	cr_expect_eq(RunJointedScene(tb_broadPhaseSortAndSweep, 240), first);
	cr_expect_eq(RunJointedScene(tb_broadPhaseBruteForce, 240), first);
}

/// Relative stretch of a chain: the sum of its joints' anchor gaps over the rest length.
static float ChainStretch(const tbJointId* joints, int count, float restLength)
{
	float gaps = 0.0f;
	for (int i = 0; i < count; ++i)
	{
		tbVec2 a = tbBody_GetWorldPoint(tbJoint_GetBodyA(joints[i]), tbJoint_GetLocalFrameA(joints[i]).p);
		tbVec2 b = tbBody_GetWorldPoint(tbJoint_GetBodyB(joints[i]), tbJoint_GetLocalFrameB(joints[i]).p);
		gaps += tbDistance(a, b);
	}
	return gaps / restLength;
}

/// Box2D v3's "Ball & Chain" with the numbers: 30 capsule links 0.5 m long (pivot to
/// pivot), joined by revolute joints, from a static pivot, holding a ball 100 times heavier than a
/// link, released horizontally. Returns the largest stretch over `steps` steps.
static float SwingBallAndChain(int subSteps, bool trees, int steps)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.enableJointTrees = trees;
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	const int count = 30;
	const float hx = 0.25f, top = 20.0f;
	tbCapsule capsule = {{-hx, 0.0f}, {hx, 0.0f}, 0.05f};
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.density = 20.0f;
	shapeDef.filter.categoryBits = 1; // links do not collide with each other, only with the ball
	shapeDef.filter.maskBits = 2;
	tbJointId joints[31];
	tbBodyId previous = ground;
	float linkMass = 0.0f;
	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	for (int i = 0; i <= count; ++i)
	{
		tbVec2 pivot = {2.0f * hx * (float)i, top};
		tbBodyDef bodyDef = tbDefaultBodyDef();
		bodyDef.type = tb_dynamicBody;
		tbBodyId body;
		if (i < count)
		{
			bodyDef.position = tbMakeVec2(pivot.x + hx, top);
			body = tbCreateBody(world, &bodyDef);
			tbCreateCapsuleShape(body, &shapeDef, &capsule);
			linkMass = tbBody_GetMass(body);
		}
		else
		{
			const float radius = 0.5f;
			bodyDef.position = tbMakeVec2(pivot.x + radius, top);
			body = tbCreateBody(world, &bodyDef);
			tbShapeDef ballDef = shapeDef;
			ballDef.density = 100.0f * linkMass / (TB_PI * radius * radius);
			ballDef.filter.categoryBits = 2;
			ballDef.filter.maskBits = 1;
			tbCircle circle = {{0.0f, 0.0f}, radius};
			tbCreateCircleShape(body, &ballDef, &circle);
			cr_assert_float_eq(tbBody_GetMass(body), 100.0f * linkMass, 1e-3f * linkMass);
		}
		def.base.bodyIdA = previous;
		def.base.bodyIdB = body;
		def.base.localFrameA.p = tbBody_GetLocalPoint(previous, pivot);
		def.base.localFrameB.p = tbBody_GetLocalPoint(body, pivot);
		joints[i] = tbCreateRevoluteJoint(world, &def);
		previous = body;
	}
	float worst = 0.0f;
	for (int i = 0; i < steps; ++i)
	{
		tbWorld_Step(world, DT, subSteps);
		worst = fmaxf(worst, ChainStretch(joints, count + 1, 2.0f * hx * (float)count));
	}
	tbDestroyWorld(world);
	return worst;
}

// The issue asks for less than 2 % stretch at 4 sub-steps, where Box2D v3.2 stretches 9.6 %.
// Row by row this set-up peaks at 14 % here too (each light link's soft pin settles at the load
// over its own small effective mass); solved exactly over the chain (joint trees, the default)
// the pins are rigid and the peak stretch over 5 s of swinging is a few hundredths of a percent.
Test(joint, chain_holds_a_ball_100_times_heavier)
{
	float stretch = SwingBallAndChain(4, true, 300);
	cr_expect(stretch < 0.02f, "peak stretch %.3f %%", (double)(100.0f * stretch));
}

/// Largest anchor gap of a set of joints (m).
static float LargestGap(const tbJointId* joints, int count)
{
	float worst = 0.0f;
	for (int i = 0; i < count; ++i)
	{
		tbVec2 a = tbBody_GetWorldPoint(tbJoint_GetBodyA(joints[i]), tbJoint_GetLocalFrameA(joints[i]).p);
		tbVec2 b = tbBody_GetWorldPoint(tbJoint_GetBodyB(joints[i]), tbJoint_GetLocalFrameB(joints[i]).p);
		worst = fmaxf(worst, tbDistance(a, b));
	}
	return worst;
}

static tbJointId Pin(tbWorldId world, tbBodyId a, tbBodyId b, tbVec2 pivot)
{
	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	def.base.bodyIdA = a;
	def.base.bodyIdB = b;
	def.base.localFrameA.p = tbBody_GetLocalPoint(a, pivot);
	def.base.localFrameB.p = tbBody_GetLocalPoint(b, pivot);
	return tbCreateRevoluteJoint(world, &def);
}

// The shapes a joint tree meets: a bridge pinned to ground at both ends (a loop through the
// ground: its far pin stays row by row) with a heavy box wedged in it, a closed four-bar linkage
// (one joint closes the loop and stays row by row), a ragdoll-like tree with limits falling onto
// the ground among contacts, a prismatic joint between two bodies that cannot turn (its angular
// row is void: the block is singular and that tree falls back to row by row) and a pendulum on a
// moving kinematic body. After 3 s every body is finite and above the ground, every joint away
// from the bridge holds within 5 mm (a failing solve leaves centimetres), and the bridge within
// 2 cm: a 50 kg box wedged between 0.2 kg planks loads the pins beside it through contacts solved
// after the joints, and its far pin closes the loop row by row (measured 1.6 cm; row by row every
// pin of the bridge opens 6.5 cm).
Test(joint, trees_handle_bridges_loops_ragdolls_and_degenerate_blocks)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbSegment floor = {{-30.0f, 0.0f}, {30.0f, 0.0f}};
	tbCreateSegmentShape(ground, &shapeDef, &floor);
	tbJointId joints[64];
	int n = 0;
	tbBodyId bodies[64];
	int m = 0;

	// Bridge: 10 planks of 1 m hung in a V between pins 9 m apart at y = 6 (a taut bridge could not
	// sag without stretching), a 50 kg box dropped on it.
	tbBodyId previous = ground;
	float slope = -acosf(0.9f); // the V: 5 planks of 1 m span half of the 9 m
	tbVec2 pivot = {-10.0f, 6.0f};
	for (int i = 0; i < 10; ++i)
	{
		float angle = i < 5 ? slope : -slope;
		tbVec2 along = {cosf(angle), sinf(angle)};
		tbBodyDef plankDef = tbDefaultBodyDef();
		plankDef.type = tb_dynamicBody;
		plankDef.position = tbMulAdd(pivot, 0.5f, along);
		plankDef.rotation = tbMakeRot(angle);
		tbBodyId plank = tbCreateBody(world, &plankDef);
		tbShapeDef plankShape = tbDefaultShapeDef();
		plankShape.density = 2.0f;
		tbPolygon plankBox = tbMakeBox(0.5f, 0.05f);
		tbCreatePolygonShape(plank, &plankShape, &plankBox);
		bodies[m++] = plank;
		joints[n++] = Pin(world, previous, plank, pivot);
		pivot = tbAdd(pivot, along);
		previous = plank;
	}
	joints[n++] = Pin(world, previous, ground, pivot);
	bodies[m++] = CreateBox(world, tb_dynamicBody, tbMakeVec2(-5.5f, 5.0f), 0.5f, 0.5f, 50.0f);

	// Four-bar linkage: ground pivots at x = 3 and x = 5, a coupler between the cranks.
	tbBodyId crankA = CreateBox(world, tb_dynamicBody, tbMakeVec2(3.0f, 4.0f), 0.05f, 1.0f, 1.0f);
	tbBodyId crankB = CreateBox(world, tb_dynamicBody, tbMakeVec2(5.0f, 4.0f), 0.05f, 1.0f, 1.0f);
	tbBodyId coupler = CreateBox(world, tb_dynamicBody, tbMakeVec2(4.0f, 3.0f), 1.0f, 0.05f, 1.0f);
	bodies[m++] = crankA;
	bodies[m++] = crankB;
	bodies[m++] = coupler;
	joints[n++] = Pin(world, ground, crankA, tbMakeVec2(3.0f, 5.0f));
	joints[n++] = Pin(world, ground, crankB, tbMakeVec2(5.0f, 5.0f));
	joints[n++] = Pin(world, crankA, coupler, tbMakeVec2(3.0f, 3.0f));
	joints[n++] = Pin(world, crankB, coupler, tbMakeVec2(5.0f, 3.0f));
	tbBody_SetAngularVelocity(crankA, 2.0f);

	// Ragdoll-like tree: a torso with two two-segment limbs on limited hinges, dropped from 3 m.
	tbBodyId torso = CreateBox(world, tb_dynamicBody, tbMakeVec2(10.0f, 3.0f), 0.3f, 0.6f, 1.0f);
	bodies[m++] = torso;
	for (int side = -1; side <= 1; side += 2)
	{
		tbBodyId upper =
			CreateBox(world, tb_dynamicBody, tbMakeVec2(10.0f + 0.15f * (float)side, 2.1f), 0.08f, 0.3f, 1.0f);
		tbBodyId lower =
			CreateBox(world, tb_dynamicBody, tbMakeVec2(10.0f + 0.15f * (float)side, 1.5f), 0.08f, 0.3f, 1.0f);
		bodies[m++] = upper;
		bodies[m++] = lower;
		tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
		def.enableLimit = true;
		def.lowerAngle = -0.5f;
		def.upperAngle = 1.0f;
		def.base.bodyIdA = torso;
		def.base.bodyIdB = upper;
		def.base.localFrameA.p = tbMakeVec2(0.15f * (float)side, -0.6f);
		def.base.localFrameB.p = tbMakeVec2(0.0f, 0.3f);
		joints[n++] = tbCreateRevoluteJoint(world, &def);
		def.base.bodyIdA = upper;
		def.base.bodyIdB = lower;
		def.base.localFrameA.p = tbMakeVec2(0.0f, -0.3f);
		def.base.localFrameB.p = tbMakeVec2(0.0f, 0.3f);
		joints[n++] = tbCreateRevoluteJoint(world, &def);
	}
	tbBody_SetAngularVelocity(torso, 3.0f);

	// A prismatic joint between two bodies that cannot turn, the first on a pin to ground.
	tbBodyDef fixedDef = tbDefaultBodyDef();
	fixedDef.type = tb_dynamicBody;
	fixedDef.fixedRotation = true;
	fixedDef.position = tbMakeVec2(15.0f, 4.0f);
	tbBodyId slider = tbCreateBody(world, &fixedDef);
	tbPolygon box = tbMakeBox(0.2f, 0.2f);
	tbCreatePolygonShape(slider, &shapeDef, &box);
	fixedDef.position = tbMakeVec2(16.0f, 4.0f);
	tbBodyId carriage = tbCreateBody(world, &fixedDef);
	tbCreatePolygonShape(carriage, &shapeDef, &box);
	bodies[m++] = slider;
	bodies[m++] = carriage;
	joints[n++] = Pin(world, ground, slider, tbMakeVec2(15.0f, 5.0f));
	tbPrismaticJointDef prismatic = tbDefaultPrismaticJointDef();
	prismatic.base.bodyIdA = slider;
	prismatic.base.bodyIdB = carriage;
	prismatic.base.localFrameB.p = tbMakeVec2(-1.0f, 0.0f);
	tbJointId slide = tbCreatePrismaticJoint(world, &prismatic);

	// A pendulum on a kinematic body moving right at 1 m/s.
	tbBodyDef kinematicDef = tbDefaultBodyDef();
	kinematicDef.type = tb_kinematicBody;
	kinematicDef.position = tbMakeVec2(20.0f, 5.0f);
	kinematicDef.linearVelocity = tbMakeVec2(1.0f, 0.0f);
	tbBodyId cart = tbCreateBody(world, &kinematicDef);
	tbBodyId bob = CreateDiscOfMass(world, tbMakeVec2(21.0f, 5.0f), 0.1f, 1.0f);
	bodies[m++] = bob;
	joints[n++] = Pin(world, cart, bob, tbMakeVec2(20.0f, 5.0f));

	for (int i = 0; i < 180; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS);
	}
	for (int i = 0; i < m; ++i)
	{
		tbVec2 p = tbBody_GetPosition(bodies[i]);
		cr_assert(tbIsValidVec2(p) && p.y > -0.05f && p.y < 8.0f, "body %d at (%g, %g)", i, (double)p.x, (double)p.y);
	}
	const int bridgeJoints = 11;
	float bridgeGap = LargestGap(joints, bridgeJoints);
	float gap = LargestGap(joints + bridgeJoints, n - bridgeJoints);
	// Bound: measured 0.016 m with one relaxing iteration per sub-step and 0.0305 m with the
	// default four of a step with joint trees (the contacts' relax passes re-open the pins of the light planks under the
	// 250x heavier box; an open interaction between the soft step's default and joint trees).
	// 0.035 m keeps the measured value with a margin of float and order effects.
	cr_expect(bridgeGap < 0.035f, "largest bridge gap %.4f m", (double)bridgeGap);
	cr_expect(gap < 0.005f, "largest gap elsewhere %.4f m", (double)gap);
	cr_expect(tbBody_GetPosition(bodies[10]).y > 3.0f, "the bridge holds the box (y = %.3f)",
			  (double)tbBody_GetPosition(bodies[10]).y);
	// The carriage stays on its line through the slider (it cannot turn either).
	tbVec2 offset = tbSub(tbBody_GetPosition(carriage), tbBody_GetPosition(slider));
	cr_expect(fabsf(offset.y) < 0.005f, "carriage off its line by %.4f m", (double)offset.y);
	cr_expect(fabsf(tbPrismaticJoint_GetTranslation(slide) - offset.x + 1.0f) < 1e-4f);
	// The bob hangs below the cart, which has moved 3 m.
	tbVec2 cartPosition = tbBody_GetPosition(cart);
	cr_expect(fabsf(cartPosition.x - 23.0f) < 1e-3f);
	cr_expect(tbDistance(tbBody_GetPosition(bob), cartPosition) < 1.005f);
	tbDestroyWorld(world);
}

// The catalogue's jointed scenes, as drawn and timed: after 5 s every body is finite, every
// revolute pin holds within 1 cm and every wheel stays within its suspension travel (plus the
// 5 mm slop). 1 cm: a twentieth of the smallest link in them (the ragdolls' 0.2 m bones), the
// scale at which a joint visibly comes apart; the trees keep the pins far tighter except where
// contacts load light bodies (measured below 3 mm here).
Test(joint, catalogue_joint_scenes_hold_together)
{
	const char* names[] = {"pendulum_chain", "rope_bridge", "car", "ragdolls"};
	for (size_t n = 0; n < sizeof(names) / sizeof(names[0]); ++n)
	{
		Scene* scene = Catalogue_Build(names[n]);
		cr_assert_not_null(scene);
		SceneWorld sw = Scene_BuildWorld(scene, NULL);
		cr_assert_gt(sw.jointCount, 0, "%s", names[n]);
		for (int i = 0; i < 300; ++i)
		{
			tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
		}
		for (int i = 0; i < sw.bodyCount; ++i)
		{
			cr_assert(tbIsValidVec2(tbBody_GetPosition(sw.bodyIds[i])), "%s body %d", names[n], i);
		}
		float worstPin = 0.0f, worstTravel = 0.0f;
		for (int j = 0; j < sw.jointCount; ++j)
		{
			tbJointId joint = sw.jointIds[j];
			cr_assert(tbJoint_IsValid(joint), "%s joint %d", names[n], j);
			if (tbJoint_GetType(joint) == tb_revoluteJoint)
			{
				worstPin = fmaxf(worstPin, LargestGap(&joint, 1));
			}
			else if (tbJoint_GetType(joint) == tb_wheelJoint)
			{
				tbVec2 a = tbBody_GetWorldPoint(tbJoint_GetBodyA(joint), tbJoint_GetLocalFrameA(joint).p);
				tbVec2 b = tbBody_GetWorldPoint(tbJoint_GetBodyB(joint), tbJoint_GetLocalFrameB(joint).p);
				float excess = tbDistance(a, b) - tbWheelJoint_GetUpperLimit(joint);
				worstTravel = fmaxf(worstTravel, excess);
			}
		}
		cr_expect(worstPin < 0.01f, "%s: a pin opened %.4f m", names[n], (double)worstPin);
		cr_expect(worstTravel < TB_LINEAR_SLOP, "%s: a wheel left its travel by %.4f m", names[n], (double)worstTravel);
		SceneWorld_Destroy(&sw);
		Scene_Destroy(scene);
	}
}

// The catalogue's ragdoll pile comes to rest and falls asleep as a whole within 10 s. A regression
// test for rigid joint trees among contacts: with one relaxing iteration they left a jitter that
// kept 105 of the 240 bodies above the sleep speed forever (joint.c, tbJointTreeRelaxIterations).
Test(joint, ragdoll_pile_falls_asleep)
{
	Scene* scene = Catalogue_Build("ragdolls");
	SceneWorld sw = Scene_BuildWorld(scene, NULL);
	int step = 0;
	while (step < 600 && SceneWorld_AwakeCount(&sw) > 0)
	{
		tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
		step += 1;
	}
	cr_expect_eq(SceneWorld_AwakeCount(&sw), 0, "%d of 240 bodies still awake after 10 s", SceneWorld_AwakeCount(&sw));
	SceneWorld_Destroy(&sw);
	Scene_Destroy(scene);
}

// Each kind refuses a bad definition with one message naming the field, and creates nothing.
Test(joint, every_kind_refuses_a_bad_definition, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId a = CreateDiscOfMass(world, tbMakeVec2(0.0f, 0.0f), 0.1f, 1.0f);
	tbBodyId b = CreateDiscOfMass(world, tbMakeVec2(1.0f, 0.0f), 0.1f, 1.0f);
	int before = s_errors;

	tbDistanceJointDef distance = tbDefaultDistanceJointDef();
	distance.base.bodyIdA = a;
	distance.base.bodyIdB = b;
	distance.minLength = 2.0f;
	distance.maxLength = 1.0f;
	cr_expect(TB_IS_NULL(tbCreateDistanceJoint(world, &distance)));
	ExpectError(before, "tbCreateDistanceJoint", "def->minLength");

	before = s_errors;
	tbPrismaticJointDef prismatic = tbDefaultPrismaticJointDef();
	prismatic.base.bodyIdA = a;
	prismatic.base.bodyIdB = b;
	prismatic.lowerTranslation = 1.0f;
	prismatic.upperTranslation = -1.0f;
	cr_expect(TB_IS_NULL(tbCreatePrismaticJoint(world, &prismatic)));
	ExpectError(before, "tbCreatePrismaticJoint", "def->lowerTranslation");

	before = s_errors;
	tbWheelJointDef wheel = tbDefaultWheelJointDef();
	wheel.base.bodyIdA = a;
	wheel.base.bodyIdB = b;
	wheel.motorSpeed = NAN;
	cr_expect(TB_IS_NULL(tbCreateWheelJoint(world, &wheel)));
	ExpectError(before, "tbCreateWheelJoint", "def->motorSpeed");

	before = s_errors;
	tbMotorJointDef motor = tbDefaultMotorJointDef();
	motor.base.bodyIdA = a;
	motor.base.bodyIdB = b;
	motor.maxSpringForce = -1.0f;
	cr_expect(TB_IS_NULL(tbCreateMotorJoint(world, &motor)));
	ExpectError(before, "tbCreateMotorJoint", "def->maxSpringForce");

	before = s_errors;
	tbMoverJointDef mover = tbDefaultMoverJointDef();
	mover.base.bodyIdA = a;
	mover.base.bodyIdB = b;
	mover.maxVelocityForce = tbMakeVec2(1.0f, -1.0f);
	cr_expect(TB_IS_NULL(tbCreateMoverJoint(world, &mover)));
	ExpectError(before, "tbCreateMoverJoint", "def->maxVelocityForce");

	before = s_errors;
	tbPogoJointDef pogo = tbDefaultPogoJointDef();
	pogo.base.bodyIdA = a;
	pogo.base.bodyIdB = b;
	pogo.normal = tbMakeVec2(1.0f, 1.0f);
	cr_expect(TB_IS_NULL(tbCreatePogoJoint(world, &pogo)));
	ExpectError(before, "tbCreatePogoJoint", "def->normal");

	before = s_errors;
	tbWeldJointDef weld = tbDefaultWeldJointDef();
	weld.base.bodyIdA = a;
	weld.base.bodyIdB = b;
	weld.linearHertz = -3.0f;
	cr_expect(TB_IS_NULL(tbCreateWeldJoint(world, &weld)));
	ExpectError(before, "tbCreateWeldJoint", "def->linearHertz");

	before = s_errors;
	tbRevoluteJointDef revolute = tbDefaultRevoluteJointDef();
	revolute.base.bodyIdA = a;
	revolute.base.bodyIdB = b;
	revolute.enableLimit = true;
	revolute.lowerAngle = -4.0f;
	cr_expect(TB_IS_NULL(tbCreateRevoluteJoint(world, &revolute)));
	ExpectError(before, "tbCreateRevoluteJoint", "[-pi, pi]");

	before = s_errors;
	cr_expect(TB_IS_NULL(tbCreateFilterJoint(world, NULL)));
	ExpectError(before, "tbCreateFilterJoint", "def");

	// A locked world refuses: create from inside a query callback is not possible here, so check
	// the stale world instead.
	tbWorldId stale = CreateWorld(tbVec2_zero);
	tbDestroyWorld(stale);
	before = s_errors;
	tbFilterJointDef filter = tbDefaultFilterJointDef();
	filter.base.bodyIdA = a;
	filter.base.bodyIdB = b;
	cr_expect(TB_IS_NULL(tbCreateFilterJoint(stale, &filter)));
	ExpectError(before, "tbCreateFilterJoint", "worldId");

	cr_expect_eq(tbBody_GetJointCount(a), 0, "nothing was created");
	cr_expect_eq(tbBody_GetJointCount(b), 0);
	tbDestroyWorld(world);
}

// Every setter stores what its getter returns, wakes the bodies, and the common functions report
// what the definition said.
Test(joint, setters_and_getters_round_trip)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId a = CreateDiscOfMass(world, tbMakeVec2(0.0f, 0.0f), 0.1f, 1.0f);
	tbBodyId b = CreateDiscOfMass(world, tbMakeVec2(1.0f, 0.0f), 0.1f, 1.0f);
	int tag = 7;

	tbRevoluteJointDef rd = tbDefaultRevoluteJointDef();
	rd.base.bodyIdA = a;
	rd.base.bodyIdB = b;
	rd.base.userData = &tag;
	rd.base.localFrameB.p = tbMakeVec2(-1.0f, 0.0f);
	tbJointId r = tbCreateRevoluteJoint(world, &rd);
	cr_expect_eq(tbJoint_GetType(r), tb_revoluteJoint);
	cr_expect(TB_ID_EQUALS(tbJoint_GetBodyA(r), a) && TB_ID_EQUALS(tbJoint_GetBodyB(r), b));
	cr_expect(tbJoint_GetWorld(r).index1 == world.index1);
	cr_expect_eq(tbJoint_GetUserData(r), &tag);
	cr_expect_float_eq(tbJoint_GetLocalFrameB(r).p.x, -1.0f, 0.0f);
	cr_expect(tbJoint_GetCollideConnected(r) == false);
	float hertz, damping;
	tbJoint_GetConstraintTuning(r, &hertz, &damping);
	cr_expect(hertz == 60.0f && damping == 2.0f, "Box2D v3's defaults");
	cr_expect(tbJoint_GetForceThreshold(r) == FLT_MAX && tbJoint_GetTorqueThreshold(r) == FLT_MAX);

	tbBody_SetAwake(a, false);
	tbBody_SetAwake(b, false);
	tbRevoluteJoint_EnableSpring(r, true);
	cr_expect(tbBody_IsAwake(a) && tbBody_IsAwake(b), "changing a joint wakes its bodies");
	cr_expect(tbRevoluteJoint_IsSpringEnabled(r));
	cr_expect(tbRevoluteJoint_SetSpringHertz(r, 3.0f) && tbRevoluteJoint_GetSpringHertz(r) == 3.0f);
	cr_expect(tbRevoluteJoint_SetSpringDampingRatio(r, 0.4f) && tbRevoluteJoint_GetSpringDampingRatio(r) == 0.4f);
	cr_expect(tbRevoluteJoint_SetTargetAngle(r, 0.3f) && tbRevoluteJoint_GetTargetAngle(r) == 0.3f);
	tbRevoluteJoint_EnableLimit(r, true);
	cr_expect(tbRevoluteJoint_IsLimitEnabled(r));
	cr_expect(tbRevoluteJoint_SetLimits(r, -0.2f, 0.4f));
	cr_expect(tbRevoluteJoint_GetLowerLimit(r) == -0.2f && tbRevoluteJoint_GetUpperLimit(r) == 0.4f);
	tbRevoluteJoint_EnableMotor(r, true);
	cr_expect(tbRevoluteJoint_IsMotorEnabled(r));
	cr_expect(tbRevoluteJoint_SetMotorSpeed(r, 1.5f) && tbRevoluteJoint_GetMotorSpeed(r) == 1.5f);
	cr_expect(tbRevoluteJoint_SetMaxMotorTorque(r, 8.0f) && tbRevoluteJoint_GetMaxMotorTorque(r) == 8.0f);
	cr_expect(tbJoint_SetConstraintTuning(r, 30.0f, 1.0f));
	cr_expect(tbJoint_SetForceThreshold(r, 5.0f) && tbJoint_GetForceThreshold(r) == 5.0f);
	cr_expect(tbJoint_SetTorqueThreshold(r, 6.0f) && tbJoint_GetTorqueThreshold(r) == 6.0f);
	cr_expect(tbJoint_SetDrawScale(r, 2.0f) && tbJoint_GetDrawScale(r) == 2.0f);
	tbJoint_SetCollideConnected(r, true);
	cr_expect(tbJoint_GetCollideConnected(r));
	tbJoint_SetUserData(r, NULL);
	cr_expect_null(tbJoint_GetUserData(r));

	tbDistanceJointDef dd = tbDefaultDistanceJointDef();
	dd.base.bodyIdA = a;
	dd.base.bodyIdB = b;
	tbJointId d = tbCreateDistanceJoint(world, &dd);
	cr_expect(tbDistanceJoint_SetLength(d, 1.5f) && tbDistanceJoint_GetLength(d) == 1.5f);
	tbDistanceJoint_EnableSpring(d, true);
	cr_expect(tbDistanceJoint_IsSpringEnabled(d));
	cr_expect(tbDistanceJoint_SetSpringForceRange(d, -4.0f, 5.0f));
	float lower, upper;
	tbDistanceJoint_GetSpringForceRange(d, &lower, &upper);
	cr_expect(lower == -4.0f && upper == 5.0f);
	cr_expect(tbDistanceJoint_SetSpringHertz(d, 2.0f) && tbDistanceJoint_GetSpringHertz(d) == 2.0f);
	cr_expect(tbDistanceJoint_SetSpringDampingRatio(d, 0.3f) && tbDistanceJoint_GetSpringDampingRatio(d) == 0.3f);
	tbDistanceJoint_EnableLimit(d, true);
	cr_expect(tbDistanceJoint_IsLimitEnabled(d));
	cr_expect(tbDistanceJoint_SetLengthRange(d, 0.5f, 2.5f));
	cr_expect(tbDistanceJoint_GetMinLength(d) == 0.5f && tbDistanceJoint_GetMaxLength(d) == 2.5f);
	tbDistanceJoint_EnableMotor(d, true);
	cr_expect(tbDistanceJoint_IsMotorEnabled(d));
	cr_expect(tbDistanceJoint_SetMotorSpeed(d, 0.7f) && tbDistanceJoint_GetMotorSpeed(d) == 0.7f);
	cr_expect(tbDistanceJoint_SetMaxMotorForce(d, 9.0f) && tbDistanceJoint_GetMaxMotorForce(d) == 9.0f);
	cr_expect_float_eq(tbDistanceJoint_GetCurrentLength(d), 1.0f, 1e-6f);

	tbPrismaticJointDef pd = tbDefaultPrismaticJointDef();
	pd.base.bodyIdA = a;
	pd.base.bodyIdB = b;
	tbJointId p = tbCreatePrismaticJoint(world, &pd);
	tbPrismaticJoint_EnableSpring(p, true);
	cr_expect(tbPrismaticJoint_IsSpringEnabled(p));
	cr_expect(tbPrismaticJoint_SetSpringHertz(p, 2.5f) && tbPrismaticJoint_GetSpringHertz(p) == 2.5f);
	cr_expect(tbPrismaticJoint_SetSpringDampingRatio(p, 0.2f) && tbPrismaticJoint_GetSpringDampingRatio(p) == 0.2f);
	cr_expect(tbPrismaticJoint_SetTargetTranslation(p, 0.4f) && tbPrismaticJoint_GetTargetTranslation(p) == 0.4f);
	tbPrismaticJoint_EnableLimit(p, true);
	cr_expect(tbPrismaticJoint_IsLimitEnabled(p));
	cr_expect(tbPrismaticJoint_SetLimits(p, -1.0f, 2.0f));
	cr_expect(tbPrismaticJoint_GetLowerLimit(p) == -1.0f && tbPrismaticJoint_GetUpperLimit(p) == 2.0f);
	tbPrismaticJoint_EnableMotor(p, true);
	cr_expect(tbPrismaticJoint_IsMotorEnabled(p));
	cr_expect(tbPrismaticJoint_SetMotorSpeed(p, -0.5f) && tbPrismaticJoint_GetMotorSpeed(p) == -0.5f);
	cr_expect(tbPrismaticJoint_SetMaxMotorForce(p, 11.0f) && tbPrismaticJoint_GetMaxMotorForce(p) == 11.0f);
	cr_expect_float_eq(tbPrismaticJoint_GetTranslation(p), 1.0f, 1e-6f);

	tbWeldJointDef wd = tbDefaultWeldJointDef();
	wd.base.bodyIdA = a;
	wd.base.bodyIdB = b;
	tbJointId w = tbCreateWeldJoint(world, &wd);
	cr_expect(tbWeldJoint_SetLinearHertz(w, 4.0f) && tbWeldJoint_GetLinearHertz(w) == 4.0f);
	cr_expect(tbWeldJoint_SetLinearDampingRatio(w, 0.6f) && tbWeldJoint_GetLinearDampingRatio(w) == 0.6f);
	cr_expect(tbWeldJoint_SetAngularHertz(w, 5.0f) && tbWeldJoint_GetAngularHertz(w) == 5.0f);
	cr_expect(tbWeldJoint_SetAngularDampingRatio(w, 0.7f) && tbWeldJoint_GetAngularDampingRatio(w) == 0.7f);

	tbWheelJointDef hd = tbDefaultWheelJointDef();
	hd.base.bodyIdA = a;
	hd.base.bodyIdB = b;
	tbJointId h = tbCreateWheelJoint(world, &hd);
	cr_expect(tbWheelJoint_IsSpringEnabled(h) && tbWheelJoint_GetSpringHertz(h) == 1.0f, "Box2D v3's defaults");
	tbWheelJoint_EnableSpring(h, false);
	cr_expect(tbWheelJoint_IsSpringEnabled(h) == false);
	cr_expect(tbWheelJoint_SetSpringHertz(h, 6.0f) && tbWheelJoint_GetSpringHertz(h) == 6.0f);
	cr_expect(tbWheelJoint_SetSpringDampingRatio(h, 0.9f) && tbWheelJoint_GetSpringDampingRatio(h) == 0.9f);
	tbWheelJoint_EnableLimit(h, true);
	cr_expect(tbWheelJoint_IsLimitEnabled(h));
	cr_expect(tbWheelJoint_SetLimits(h, -0.1f, 0.3f));
	cr_expect(tbWheelJoint_GetLowerLimit(h) == -0.1f && tbWheelJoint_GetUpperLimit(h) == 0.3f);
	tbWheelJoint_EnableMotor(h, true);
	cr_expect(tbWheelJoint_IsMotorEnabled(h));
	cr_expect(tbWheelJoint_SetMotorSpeed(h, 3.0f) && tbWheelJoint_GetMotorSpeed(h) == 3.0f);
	cr_expect(tbWheelJoint_SetMaxMotorTorque(h, 12.0f) && tbWheelJoint_GetMaxMotorTorque(h) == 12.0f);

	tbMotorJointDef md = tbDefaultMotorJointDef();
	md.base.bodyIdA = a;
	md.base.bodyIdB = b;
	tbJointId m = tbCreateMotorJoint(world, &md);
	cr_expect(tbMotorJoint_SetLinearVelocity(m, tbMakeVec2(1.0f, 2.0f)));
	cr_expect(tbMotorJoint_GetLinearVelocity(m).x == 1.0f && tbMotorJoint_GetLinearVelocity(m).y == 2.0f);
	cr_expect(tbMotorJoint_SetAngularVelocity(m, 0.5f) && tbMotorJoint_GetAngularVelocity(m) == 0.5f);
	cr_expect(tbMotorJoint_SetMaxVelocityForce(m, 13.0f) && tbMotorJoint_GetMaxVelocityForce(m) == 13.0f);
	cr_expect(tbMotorJoint_SetMaxVelocityTorque(m, 14.0f) && tbMotorJoint_GetMaxVelocityTorque(m) == 14.0f);
	cr_expect(tbMotorJoint_SetLinearHertz(m, 1.1f) && tbMotorJoint_GetLinearHertz(m) == 1.1f);
	cr_expect(tbMotorJoint_SetLinearDampingRatio(m, 1.2f) && tbMotorJoint_GetLinearDampingRatio(m) == 1.2f);
	cr_expect(tbMotorJoint_SetAngularHertz(m, 1.3f) && tbMotorJoint_GetAngularHertz(m) == 1.3f);
	cr_expect(tbMotorJoint_SetAngularDampingRatio(m, 1.4f) && tbMotorJoint_GetAngularDampingRatio(m) == 1.4f);
	cr_expect(tbMotorJoint_SetMaxSpringForce(m, 15.0f) && tbMotorJoint_GetMaxSpringForce(m) == 15.0f);
	cr_expect(tbMotorJoint_SetMaxSpringTorque(m, 16.0f) && tbMotorJoint_GetMaxSpringTorque(m) == 16.0f);

	tbJointId listed[8];
	cr_expect_eq(tbBody_GetJoints(a, listed, 8), 6);
	cr_expect_eq(tbBody_GetJoints(a, listed, 2), 2, "capacity is respected");
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(world, DT, SUB_STEPS); // every kind at once, between the same two bodies
	}
	cr_expect(tbIsValidVec2(tbBody_GetPosition(a)) && tbIsValidVec2(tbBody_GetPosition(b)));
	tbDestroyWorld(world);
}
