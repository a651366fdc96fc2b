// The solve stage: gather the awake bodies into dense arrays, build contact constraints, run the
// sub-step loop of the chosen method, apply restitution and write the results back.
//
// One step of length Δt is cut into n sub-steps of h = Δt/n. Each sub-step:
//   1. integrate velocities (semi-implicit Euler): v ← (v + h·(gravityScale·g + F/m))/(1 + h·c_lin),
//      ω ← (ω + h·τ/I)/(1 + h·c_ang); kinematic bodies keep their velocity;
//   2. warm start: re-apply the accumulated contact impulses;
//   3. the method's sub-step (solver_soft.c, solver_baumgarte.c, solver_ngs.c): velocity
//      iterations, position integration (Δp += h·v, Δq ← integrate(Δq, h·ω)), and its own
//      relaxing or position-correction passes.
// After the loop: restitution, store impulses for the next step's warm start, scatter.
// Sub-stepping with one solve per sub-step beats more iterations per step (Catto, Solver2D 2024):
// each sub-step sees the position error that the previous one left.
//
// Speed clamps: |v| ≤ maximumLinearSpeed, and |ω|·Δt ≤ TB_MAX_ROTATION (per step, not per
// sub-step) so that the rotation bound that continuous collision relies on holds for the step.
// They apply to the velocities the step starts from (the approach speeds that contacts and
// restitution see) and after each velocity integration.
#include "solver.h"

#include "tumble/constants.h"

#include <string.h>

// The per-step arrays, from the step arena (arena.h), carved in 32-byte aligned pieces.
static void tbAllocateStep(tbStepContext* context, int bodyCount, int constraintCount)
{
	int bodyBytes = (int)sizeof(tbSolverBody) * (bodyCount + 1);
	int motionBytes = (((int)sizeof(tbSolverMotion) * bodyCount + 31) / 32) * 32;
	int constraintBytes = (int)sizeof(tbContactConstraint) * constraintCount;
	char* p = tbArenaAlloc(&context->world->stepArena, bodyBytes + motionBytes + constraintBytes);
	context->bodies = (tbSolverBody*)p;
	context->motions = (tbSolverMotion*)(p + bodyBytes);
	context->constraints = (tbContactConstraint*)(p + bodyBytes + motionBytes);
	context->bodyCount = bodyCount;
	context->constraintCount = constraintCount;
}

static void tbGatherBodies(tbStepContext* context)
{
	tbWorld* world = context->world;
	tbVec2 gravity = world->def.gravity;
	float h = context->h;
	for (int i = 0; i < context->bodyCount; ++i)
	{
		tbBody* body = world->bodies + world->awakeBodies[i];
		body->solverIndex = i;
		body->center0 = body->center;
		body->rotation0 = body->transform.q;

		tbSolverBody* sb = context->bodies + i;
		sb->linearVelocity = body->linearVelocity;
		sb->angularVelocity = body->fixedRotation ? 0.0f : body->angularVelocity;
		tbClampSpeeds(context, sb); // a body set to 3e38 m/s approaches its contacts at the clamped speed
		sb->padding = 0.0f;
		sb->deltaPosition = tb_vec2_zero;
		sb->deltaRotation = tb_rot_identity;

		tbSolverMotion* m = context->motions + i;
		if (body->type == tb_dynamicBody)
		{
			tbVec2 acceleration = tbMulAdd(tbMulSV(body->gravityScale, gravity), body->invMass, body->force);
			float invInertia = body->fixedRotation ? 0.0f : body->invInertia;
			m->linearDelta = tbMulSV(h, acceleration);
			m->angularDelta = h * invInertia * body->torque;
			m->linearDamping = 1.0f / (1.0f + h * body->linearDamping);
			m->angularDamping = 1.0f / (1.0f + h * body->angularDamping);
		}
		else
		{
			m->linearDelta = tb_vec2_zero;
			m->angularDelta = 0.0f;
			m->linearDamping = 1.0f;
			m->angularDamping = 1.0f;
		}
	}

	// The stand-in for static and non-awake bodies: at rest, never moves.
	tbSolverBody* fixed = context->bodies + context->bodyCount;
	memset(fixed, 0, sizeof(*fixed));
	fixed->deltaRotation = tb_rot_identity;
}

// The speed clamp when |v|² is not a finite float: a speed above ~1.8e19 m/s (a velocity of
// 1e20 set by the user, gravity 3e38 m/s²) squares to infinity, and the plain clamp's factor
// max/|v| would be 0, stopping the body. Scale v by its largest component first, so the length
// is computed without overflow; an infinite component (the sum overflowed) gives the direction
// alone, and a NaN component (∞ − ∞) has no direction and counts as 0.
static tbVec2 tbClampHugeSpeed(tbVec2 v, float maxSpeed)
{
	float x = v.x == v.x ? v.x : 0.0f;
	float y = v.y == v.y ? v.y : 0.0f;
	bool infinite = isinf(x) || isinf(y);
	if (infinite)
	{
		x = isinf(x) ? copysignf(1.0f, x) : 0.0f;
		y = isinf(y) ? copysignf(1.0f, y) : 0.0f;
	}
	float scale = tbMaxFloat(tbAbsFloat(x), tbAbsFloat(y));
	if (scale == 0.0f)
	{
		return tb_vec2_zero;
	}
	tbVec2 scaled = tbMakeVec2(x / scale, y / scale); // largest component ±1: |scaled| in [1, √2]
	float length = tbLength(scaled);
	float speed = infinite ? maxSpeed : tbMinFloat(maxSpeed, scale * length);
	return tbMulSV(speed / length, scaled);
}

// The speed clamps of the top of the file, on a solver body's velocity.
void tbClampSpeeds(const tbStepContext* context, tbSolverBody* sb)
{
	float maxLinearSpeed = context->maxLinearSpeed;
	float maxAngularSpeed = context->maxAngularSpeed;
	tbVec2 v = sb->linearVelocity;
	float w = sb->angularVelocity;
	float speedSquared = tbDot(v, v);
	if (tbIsValidFloat(speedSquared) == false)
	{
		v = tbClampHugeSpeed(v, maxLinearSpeed);
	}
	else if (speedSquared > maxLinearSpeed * maxLinearSpeed)
	{
		v = tbMulSV(maxLinearSpeed / sqrtf(speedSquared), v);
	}
	w = w == w ? tbClampFloat(w, -maxAngularSpeed, maxAngularSpeed) : 0.0f; // NaN (0 · ∞ torque): no direction
	sb->linearVelocity = v;
	sb->angularVelocity = w;
}

void tbIntegrateVelocities(tbStepContext* context)
{
	for (int i = 0; i < context->bodyCount; ++i)
	{
		tbSolverBody* sb = context->bodies + i;
		const tbSolverMotion* m = context->motions + i;
		sb->linearVelocity = tbMulSV(m->linearDamping, tbAdd(sb->linearVelocity, m->linearDelta));
		sb->angularVelocity = m->angularDamping * (sb->angularVelocity + m->angularDelta);
		tbClampSpeeds(context, sb);
	}
}

void tbIntegratePositions(tbStepContext* context)
{
	float h = context->h;
	for (int i = 0; i < context->bodyCount; ++i)
	{
		tbSolverBody* sb = context->bodies + i;
		sb->deltaPosition = tbMulAdd(sb->deltaPosition, h, sb->linearVelocity);
		sb->deltaRotation = tbIntegrateRotation(sb->deltaRotation, h * sb->angularVelocity);
	}
}

static void tbScatterBodies(tbStepContext* context)
{
	tbWorld* world = context->world;
	for (int i = 0; i < context->bodyCount; ++i)
	{
		tbBody* body = world->bodies + world->awakeBodies[i];
		const tbSolverBody* sb = context->bodies + i;
		body->linearVelocity = sb->linearVelocity;
		body->angularVelocity = sb->angularVelocity;
		body->center = tbAdd(body->center0, sb->deltaPosition);
		tbRot q = tbNormalizeRot(tbMulRot(sb->deltaRotation, body->rotation0));
		body->transform.q = q;
		body->transform.p = tbSub(body->center, tbRotateVector(q, body->localCenter));
		body->force = tb_vec2_zero;
		body->torque = 0.0f;
	}
}

static void tbPrepareMethod(tbStepContext* context)
{
	switch (context->world->def.solver)
	{
		case tb_solverBaumgarte:
			tbBaumgartePrepare(context);
			break;
		case tb_solverNGS:
			tbNGSPrepare(context);
			break;
		case tb_solverSoft:
		default:
			tbSoftPrepare(context);
			break;
	}
}

static void tbMethodSubStep(tbStepContext* context)
{
	switch (context->world->def.solver)
	{
		case tb_solverBaumgarte:
			tbBaumgarteSubStep(context);
			break;
		case tb_solverNGS:
			tbNGSSubStep(context);
			break;
		case tb_solverSoft:
		default:
			tbSoftSubStep(context);
			break;
	}
}

void tbSolveStage(tbWorld* world, float timeStep, int subStepCount)
{
	if (timeStep <= 0.0f)
	{
		return; // a zero step moves nothing (the world may step with 0 to refresh contacts)
	}
	subStepCount = tbMaxInt(subStepCount, 1);

	tbStepContext context;
	memset(&context, 0, sizeof(context));
	context.world = world;
	context.timeStep = timeStep;
	context.subStepCount = subStepCount;
	context.h = timeStep / (float)subStepCount;
	context.inv_h = 1.0f / context.h;
	context.maxContactPushSpeed = world->def.maxContactPushSpeed;
	context.maxLinearSpeed = world->def.maximumLinearSpeed;
	context.maxAngularSpeed = TB_MAX_ROTATION / timeStep;
	context.enableWarmStarting = world->def.enableWarmStarting;

	tbAllocateStep(&context, world->awakeBodyCount, world->solverContactCount);
	tbGatherBodies(&context);
	tbPrepareMethod(&context);
	tbPrepareContacts(&context);
	if (world->def.solver == tb_solverSoft)
	{
		tbSoftPrepareContacts(&context);
	}
	if (world->def.enableWideSolver && world->def.solver != tb_solverNGS && context.constraintCount > 0)
	{
		tbColorConstraints(&context); // NGS has its own solver loops (solver_ngs.c): scalar only
	}

	for (int i = 0; i < subStepCount; ++i)
	{
		tbIntegrateVelocities(&context);
		tbWarmStartContacts(&context);
		tbMethodSubStep(&context);
	}

	tbApplyRestitution(&context);
	tbStoreImpulses(&context);
	if (context.wideConstraints != NULL)
	{
		tbReleaseColors(&context);
	}
	tbScatterBodies(&context);
}
