// The solve stage: gather the awake bodies into dense arrays, build contact constraints, run the
// sub-step loop of the chosen method, apply restitution and write the results back.
//
// One step of length Δt is cut into n sub-steps of h = Δt/n. Each sub-step:
//   1. integrate velocities (semi-implicit Euler): v ← (v + h·(gravityScale·g + F/m))/(1 + h·c_lin),
//      ω ← (ω + h·τ/I)/(1 + h·c_ang); kinematic bodies keep their velocity;
//   2. warm start: re-apply the accumulated joint and contact impulses;
//   3. the method's sub-step (solver_soft.c, solver_baumgarte.c, solver_ngs.c): velocity
//      iterations, position integration (Δp += h·v, Δq ← integrate(Δq, h·ω)), and its own
//      relaxing or position-correction passes; each velocity pass solves the joints (joint.c)
//      before the contacts.
// After the loop: restitution, store impulses for the next step's warm start, scatter.
// Sub-stepping with one solve per sub-step beats more iterations per step (Catto, Solver2D 2024):
// each sub-step sees the position error that the previous one left.
//
// Speed clamps: |v| ≤ maximumLinearSpeed, and |ω|·Δt ≤ TB_MAX_ROTATION (per step, not per
// sub-step) so that the rotation bound that continuous collision relies on holds for the step.
// They apply to the velocities the step starts from (the approach speeds that contacts and
// restitution see) and after each velocity integration.
#include "joints/joint.h"
#include "solver.h"
#include "solver_workers.h"
#include "world/continuous.h"
#include "core/task.h"

#include "tumble/constants.h"

#include <stdatomic.h>
#include <string.h>

/// Bodies per task range when the step runs on workers (a range must pay for its hand-over).
#define TB_BODIES_PER_TASK 256

// The per-step arrays, from the step arena (arena.h), carved in 32-byte aligned pieces.
static void tbAllocateStep(tbStepContext* context, int bodyCount, int constraintCount)
{
	int bodyBytes = (int)sizeof(tbSolverBody) * (bodyCount + 1);
	int motionBytes = (((int)sizeof(tbSolverMotion) * bodyCount + 31) / 32) * 32;
	int massBytes = (((int)sizeof(tbSolverMass) * (bodyCount + 1) + 31) / 32) * 32;
	int constraintBytes = (int)sizeof(tbContactConstraint) * constraintCount;
	char* p = tbArenaAlloc(&context->world->stepArena, bodyBytes + motionBytes + massBytes + constraintBytes);
	context->bodies = (tbSolverBody*)p;
	context->motions = (tbSolverMotion*)(p + bodyBytes);
	context->masses = (tbSolverMass*)(p + bodyBytes + motionBytes);
	context->constraints = (tbContactConstraint*)(p + bodyBytes + motionBytes + massBytes);
	context->bodyCount = bodyCount;
	context->constraintCount = constraintCount;
	context->linearLocks = NULL;
	if (context->world->linearLockCount > 0)
	{
		context->linearLocks = tbArenaAlloc(&context->world->stepArena, bodyCount + 1);
	}
	context->fastRotation = NULL;
	if (context->world->fastRotationCount > 0)
	{
		context->fastRotation = tbArenaAlloc(&context->world->stepArena, bodyCount + 1);
	}
}


/// Solver bodies [start, end) from the awake bodies (a task: each body writes its own).
static void tbGatherBodiesTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	tbStepContext* context = taskContext;
	tbWorld* world = context->world;
	tbVec2 gravity = world->def.gravity;
	float h = context->h;
	for (int i = start; i < end; ++i)
	{
		// The awake list is in waking order, not memory order: ask for the body a few ahead (its
		// three lines: pose and velocity, mass and forces, damping and flags are all read here).
		if (i + TB_PREFETCH_AHEAD < end)
		{
			tbPrefetch(world->bodies + world->awakeBodies[i + TB_PREFETCH_AHEAD], (int)sizeof(tbBody));
		}
		tbBody* body = world->bodies + world->awakeBodies[i];
		body->center0 = body->center;
		body->rotation0 = body->transform.q;

		tbSolverBody* sb = context->bodies + i;
		sb->linearVelocity = body->linearVelocity;
		sb->angularVelocity = body->fixedRotation ? 0.0f : body->angularVelocity;
		if (context->fastRotation != NULL)
		{
			context->fastRotation[i] = body->allowFastRotation ? 1 : 0; // read by tbClampSpeeds below
		}
		tbClampSpeeds(context, sb, i); // a body set to 3e38 m/s approaches its contacts at the clamped speed
		sb->padding = 0.0f;
		sb->deltaPosition = tbVec2_zero;
		sb->deltaRotation = tbRot_identity;

		if (context->linearLocks != NULL)
		{
			context->linearLocks[i] = (uint8_t)((body->lockLinearX ? 1 : 0) | (body->lockLinearY ? 2 : 0));
		}

		tbSolverMass* mass = context->masses + i;
		bool dynamic = body->type == tb_dynamicBody;
		mass->invMass = dynamic ? body->invMass : 0.0f;
		mass->invI = dynamic && !body->fixedRotation ? body->invInertia : 0.0f;
		mass->gravityScale = body->gravityScale;
		mass->padding = 0.0f;

		tbSolverMotion* m = context->motions + i;
		if (dynamic)
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
			m->linearDelta = tbVec2_zero;
			m->angularDelta = 0.0f;
			m->linearDamping = 1.0f;
			m->angularDamping = 1.0f;
		}
	}
}

static void tbGatherBodies(tbStepContext* context)
{
	tbParallelFor(&context->world->def, tbGatherBodiesTask, context->bodyCount, TB_BODIES_PER_TASK, context);
	// The stand-in for static and non-awake bodies: at rest, never moves.
	tbSolverBody* fixed = context->bodies + context->bodyCount;
	memset(fixed, 0, sizeof(*fixed));
	fixed->deltaRotation = tbRot_identity;
	memset(context->masses + context->bodyCount, 0, sizeof(tbSolverMass));
}


typedef struct tbScatterTaskContext
{
	tbStepContext* context;
	bool markFast;		  ///< continuous collision is on: mark the fast bodies (tbMarkFastBody)
	atomic_int fastCount; ///< bodies marked fast (an integer sum, in any order)
} tbScatterTaskContext;

/// The solved state back into bodies [start, end) (a task), each body then marked fast or not for
/// the continuous stage while it is in cache.
static void tbScatterBodiesTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	tbScatterTaskContext* task = taskContext;
	tbStepContext* context = task->context;
	tbWorld* world = context->world;
	int fastCount = 0;
	for (int i = start; i < end; ++i)
	{
		if (i + TB_PREFETCH_AHEAD < end)
		{
			tbPrefetch(world->bodies + world->awakeBodies[i + TB_PREFETCH_AHEAD], (int)sizeof(tbBody));
		}
		tbBody* body = world->bodies + world->awakeBodies[i];
		tbSolverBody* sb = context->bodies + i;
		if (context->linearLocks != NULL && context->linearLocks[i] != 0)
		{
			tbApplyLinearLocks(context->linearLocks[i], &sb->linearVelocity); // what the relax passes left
			tbApplyLinearLocks(context->linearLocks[i], &sb->deltaPosition);  // NGS position corrections
		}
		body->linearVelocity = sb->linearVelocity;
		body->angularVelocity = sb->angularVelocity;
		body->center = tbOffsetPos(body->center0, sb->deltaPosition);
		tbRot q = tbNormalizeRot(tbMulRot(sb->deltaRotation, body->rotation0));
		body->transform.q = q;
		body->transform.p = tbOffsetPos(body->center, tbNeg(tbRotateVector(q, body->localCenter)));
		body->force = tbVec2_zero;
		body->torque = 0.0f;
		if (task->markFast)
		{
			fastCount += tbMarkFastBody(world, body) ? 1 : 0; // continuous.c
		}
	}
	atomic_fetch_add_explicit(&task->fastCount, fastCount, memory_order_relaxed);
}

static void tbScatterBodies(tbStepContext* context)
{
	tbWorld* world = context->world;
	tbScatterTaskContext task;
	task.context = context;
	task.markFast = world->def.continuous != tb_continuousOff;
	atomic_init(&task.fastCount, 0);
	tbParallelFor(&world->def, tbScatterBodiesTask, context->bodyCount, TB_BODIES_PER_TASK, &task);
	if (task.markFast)
	{
		world->cache.fastMarkedStep = world->stepIndex;
		world->cache.fastMarkedCount = atomic_load_explicit(&task.fastCount, memory_order_relaxed);
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

/// A step with nothing to solve (a zero time step, or nothing awake): no body moves, no joint is
/// solved and none reports an event. The joints keep the last solve's impulses and 1/h, whose
/// product is the force they report.
static void tbSkipSolve(tbWorld* world)
{
	world->cache.solverJointCount = 0;
	world->cache.jointTreeCount = 0;
	world->cache.jointTreeNodeCount = 0;
	world->events.jointEventCount = 0;
}

void tbSolveStage(tbWorld* world, float timeStep, int subStepCount)
{
	if (timeStep <= 0.0f || world->awakeBodyCount == 0)
	{
		tbSkipSolve(world); // a zero step moves nothing (the world may step with 0 to refresh contacts)
		return;
	}
	subStepCount = tbMaxInt(subStepCount, 1);

	tbStepContext context;
	memset(&context, 0, sizeof(context));
	context.world = world;
	context.timeStep = timeStep;
	context.subStepCount = subStepCount;
	context.h = timeStep / (float)subStepCount;
	context.inv_h = 1.0f / context.h;
	context.contactSpeed = world->def.contactSpeed;
	context.maxLinearSpeed = world->def.maximumLinearSpeed;
	context.maxAngularSpeed = TB_MAX_ROTATION / timeStep;
	context.enableWarmStarting = world->def.enableWarmStarting;
	context.centralFriction = world->def.enableCentralFriction && world->def.solver != tb_solverNGS;
	context.lapTicks = tbGetTicks();
	tbProfile* profile = &world->profile; // the solve stage's parts (tbProfileLap)

	tbAllocateStep(&context, world->awakeBodyCount, world->cache.solverContactCount);
	tbGatherBodies(&context);
	tbPrepareMethod(&context);
	if (world->def.enableWideSolver && world->def.solver != tb_solverNGS && context.constraintCount > 0)
	{
		tbKeyContacts(&context);	  // contact_solver.c: the bodies each contact moves
		tbColorConstraints(&context); // NGS has its own solver loops (solver_ngs.c): scalar only
	}
	tbProfileLap(&profile->solverSetup, &context.lapTicks);
	tbPrepareContacts(&context); // coloured contacts straight into their wide lanes
	tbPropagateImpacts(&context);
	tbPrepareJoints(&context); // joint.c
	tbColorJoints(&context);   // constraint_graph.c: the joints' solve order, mechanism by mechanism or by colour
	tbBuildJointTrees(&context); // joint_tree.c: exact solves of the mechanisms that are mostly trees
	tbProfileLap(&profile->prepareConstraints, &context.lapTicks);

	if (tbSolveSubStepsOnWorkers(&context) == false) // solver_workers.c laps its own stages
	{
		for (int i = 0; i < subStepCount; ++i)
		{
			context.subStepIndex = i;
			tbIntegrateVelocities(&context);
			tbProfileLap(&profile->integrateVelocities, &context.lapTicks);
			tbWarmStartJoints(&context);
			tbWarmStartContacts(&context);
			tbProfileLap(&profile->warmStart, &context.lapTicks);
			tbMethodSubStep(&context); // the soft step laps its passes (solver_soft.c)
			tbProfileLap(&profile->solveImpulses, &context.lapTicks);
		}
	}

	tbApplyRestitution(&context);
	tbProfileLap(&profile->applyRestitution, &context.lapTicks);
	tbStoreImpulses(&context);
	uint64_t jointTicks = tbGetTicks();
	tbFinishJoints(&context); // joint events; joints keep their own impulses
	profile->jointEvents = tbGetMilliseconds(jointTicks); // a part of storeImpulses
	if (context.wideConstraints != NULL)
	{
		tbReleaseColors(&context);
	}
	tbProfileLap(&profile->storeImpulses, &context.lapTicks);
	tbScatterBodies(&context);
	tbProfileLap(&profile->scatterBodies, &context.lapTicks);
}
