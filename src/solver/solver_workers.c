// The soft step's sub-steps spread over the game's workers (tbWorldDef::workerCount > 1).
//
// The sub-steps are a fixed sequence of stages: integrate velocities, warm start, solve, integrate
// positions, relax, each contact stage once per graph colour (constraint_graph.c). Within a stage
// the units are independent: bodies, or blocks of one colour, which share no moving body. So a
// stage's units may run on any worker in any order and the result is bit-identical to the serial
// loop; between stages everyone waits (a colour reads what the previous one wrote).
//
// Synchronisation (C11 atomics, no locks): every stage has its own counters, the units claimed
// in each worker's share (tbWorkOnStage) and the units done. One participant, the orchestrator, opens the stages one after another
// and waits for each to be done before opening the next; every participant (the orchestrator too)
// claims units of the open stage until none is left. The orchestrator is whoever arrives first,
// the caller or one of the tasks it enqueued (compare-and-swap), and it can finish every stage on
// its own: helpers only speed it up. So a task system that runs the tasks late, on fewer threads,
// or inline inside enqueueTask still finishes (a helper that arrives after the last stage leaves).
// Joints have colours of their own (constraint_graph.c): a joint pass is a stage per joint colour,
// before the contact colours. The joint trees' exact solve, the joints and the contacts that found
// no colour are one-unit stages: whoever claims them runs them alone, in order with the rest. Idea from Box2D v3's solver stages (Catto 2024, "Solver2D"
// and the v3 solver notes); written here for Tumble's stage list.
//
// Island partitions. When the colouring has cut the awake bodies into one run per worker that no
// contact links (constraint_graph.c: separate piles), each worker takes its run through the whole
// stage list alone (tbRunPartition): no claims and no barrier per stage, and no body's state moves
// between the workers' caches. Results are the same bit for bit. A step has a stage per colour
// and pass in every sub-step, each ending at a barrier where the workers wait for the slowest;
// with separate piles (many_pyramids) partitions take that waiting out of the step.
#include "solver_workers.h"

#include "contact_solver.h"
#include "integrator.h"
#include "joints/joint.h"
#include "solver_methods.h"
#include "core/task.h"
#include "world/world.h"

#include <stdalign.h>
#include <stdatomic.h>

/// Bodies per unit of the integration stages, blocks (of TB_SIMD_WIDTH contacts) per unit of a
/// colour, joints per unit of a joint colour.
#define TB_BODIES_PER_UNIT 64
#define TB_BLOCKS_PER_UNIT 4
#define TB_JOINTS_PER_UNIT 16
#define TB_UNITS_PER_WORKER 4

typedef enum tbStageKind
{
	tb_stageIntegrateVelocities,
	tb_stageIntegratePositions,
	tb_stageWarmStartMechanisms,
	tb_stageWarmStartJoints,
	tb_stageBeginJointPass,
	tb_stageSolveMechanisms,
	tb_stageSolveJoints,
	tb_stageSolveJointTrees,
	tb_stageWarmStartColor,
	tb_stageSolveColor,
	tb_stageWarmStartOverflow,
	tb_stageSolveOverflow,
} tbStageKind;

typedef struct tbStage
{
	uint8_t kind;	///< tbStageKind
	uint8_t policy; ///< tbBiasPolicy of a solve stage
	bool useBias;	///< joint stages: the biased pass
	int color;		///< a contact colour stage's colour (−1 for the others)
	int start;		///< first block of a colour stage
	int count;		///< bodies or blocks
	int unitSize;
	int unitCount;
	int index;		///< in the program's stage list (its column of the share counters)
	alignas(64) atomic_int doneUnits; ///< on a line of its own: every worker counts here
} tbStage;

typedef struct tbStageProgram
{
	tbStepContext* context;
	int workerCount;
	tbStage* stages;
	int stageCount;
	/// Per worker share and stage, the units of the share claimed so far: row w (worker w's, on
	/// lines of its own) holds a counter per stage, so a worker claims its own units with an
	/// uncontended increment and touches another's row only to help with what is left.
	atomic_int* shareClaims;
	int shareStride; ///< counters per row: the stage count rounded up to a whole line
	atomic_int openStage; ///< stages [0, openStage] may be worked on; stageCount: all done
	atomic_int orchestrator; ///< 0 until a participant takes the role
} tbStageProgram;

static void tbAddStage(tbStageProgram* p, tbStageKind kind, int start, int count, int unitSize, tbBiasPolicy policy,
					   bool useBias)
{
	if (count <= 0)
	{
		return;
	}
	// Units of at least unitSize, about TB_UNITS_PER_WORKER per worker: enough to even out uneven
	// units, few enough that claiming costs little.
	unitSize = tbMaxInt(unitSize, count / (TB_UNITS_PER_WORKER * p->workerCount));
	tbStage* s = p->stages + p->stageCount++;
	s->kind = (uint8_t)kind;
	s->policy = (uint8_t)policy;
	s->useBias = useBias;
	s->color = -1;
	s->start = start;
	s->count = count;
	s->unitSize = unitSize;
	s->unitCount = (count + unitSize - 1) / unitSize;
	s->index = p->stageCount - 1;
	atomic_init(&s->doneUnits, 0);
}

/// One contact pass: each colour's blocks, then the overflow.
static void tbAddContactPass(tbStageProgram* p, bool warmStart, tbBiasPolicy policy)
{
	const tbStepContext* context = p->context;
	for (int color = 0; color < context->colorCount; ++color)
	{
		int start = context->colorBlockStart[color];
		int count = context->colorBlockStart[color + 1] - start;
		tbAddStage(p, warmStart ? tb_stageWarmStartColor : tb_stageSolveColor, start, count, TB_BLOCKS_PER_UNIT, policy,
				   false);
		if (count > 0)
		{
			p->stages[p->stageCount - 1].color = color;
		}
	}
	tbAddStage(p, warmStart ? tb_stageWarmStartOverflow : tb_stageSolveOverflow, 0, context->overflowCount > 0 ? 1 : 0,
			   1, policy, false);
}

/// One joint pass: the small mechanisms (units of whole mechanisms) and each joint colour (the last
/// group may be the joints without one, one unit).
static void tbAddJointColors(tbStageProgram* p, tbStageKind kind, bool useBias)
{
	const tbStepContext* context = p->context;
	tbAddStage(p, kind == tb_stageWarmStartJoints ? tb_stageWarmStartMechanisms : tb_stageSolveMechanisms, 0,
			   context->jointUnitCount, 1, tb_biasSoft, useBias);
	for (int k = 0; k < context->jointColorCount; ++k)
	{
		int start = context->jointColorStart[k];
		int count = context->jointColorStart[k + 1] - start;
		bool overflow = k == context->jointColorCount - 1 && context->jointOverflow;
		tbAddStage(p, kind, start, count, overflow ? count : TB_JOINTS_PER_UNIT, tb_biasSoft, useBias);
	}
}

/// tbSolveJoints as stages: the trees' marking and factoring, the rows colour by colour, and in a
/// biased pass with trees the trees' exact solve and the rows once more.
static void tbAddJointPass(tbStageProgram* p, bool useBias)
{
	bool trees = p->context->world->cache.jointTreeCount > 0;
	tbAddStage(p, tb_stageBeginJointPass, 0, trees ? 1 : 0, 1, tb_biasSoft, useBias);
	tbAddJointColors(p, tb_stageSolveJoints, useBias);
	if (useBias && trees)
	{
		tbAddStage(p, tb_stageSolveJointTrees, 0, 1, 1, tb_biasSoft, useBias);
		tbAddJointColors(p, tb_stageSolveJoints, useBias);
	}
}

/// The stage list of the soft step's sub-steps (tbSolveStage's loop with tbSoftSubStep inlined).
static void tbBuildSoftProgram(tbStageProgram* p)
{
	tbStepContext* context = p->context;
	for (int i = 0; i < context->subStepCount; ++i)
	{
		int relaxIterations = tbSoftRelaxIterations(context, i);
		tbAddStage(p, tb_stageIntegrateVelocities, 0, context->bodyCount, TB_BODIES_PER_UNIT, tb_biasSoft, false);
		tbAddJointColors(p, tb_stageWarmStartJoints, false);
		tbAddContactPass(p, true, tb_biasSoft);
		tbAddJointPass(p, true);
		tbAddContactPass(p, false, tb_biasSoft);
		tbAddStage(p, tb_stageIntegratePositions, 0, context->bodyCount, TB_BODIES_PER_UNIT, tb_biasSoft, false);
		for (int k = 0; k < relaxIterations; ++k)
		{
			if (tbRelaxJointsInIteration(context, k))
			{
				tbAddJointPass(p, false);
			}
			tbAddContactPass(p, false, k == 0 ? tb_biasRelax : tb_biasRelaxRepeat);
		}
	}
}

/// Stage s's items [begin, end): bodies, blocks or joints.
static void tbRunRange(tbStepContext* context, const tbStage* s, int begin, int end)
{
	switch ((tbStageKind)s->kind)
	{
		case tb_stageIntegrateVelocities:
			tbIntegrateVelocitiesRange(context, begin, end);
			break;
		case tb_stageIntegratePositions:
			tbIntegratePositionsRange(context, begin, end);
			break;
		case tb_stageWarmStartMechanisms:
			tbWarmStartJointRange(context, context->jointUnitStart[begin], context->jointUnitStart[end]);
			break;
		case tb_stageWarmStartJoints:
			tbWarmStartJointRange(context, begin, end);
			break;
		case tb_stageSolveMechanisms:
			tbSolveJointRowRange(context, context->jointUnitStart[begin], context->jointUnitStart[end], s->useBias);
			break;
		case tb_stageBeginJointPass:
			// The program's one biased pass per sub-step factors the trees for the new positions.
			context->world->cache.jointTreesStale = context->world->cache.jointTreesStale || s->useBias;
			tbBeginJointPass(context, s->useBias);
			break;
		case tb_stageSolveJoints:
			tbSolveJointRowRange(context, begin, end, s->useBias);
			break;
		case tb_stageSolveJointTrees:
			tbSolveJointTrees(context);
			break;
		case tb_stageWarmStartColor:
			tbWarmStartWideRange(context, begin, end, true);
			break;
		case tb_stageSolveColor:
			tbSolveWideRange(context, (tbBiasPolicy)s->policy, begin, end, true);
			break;
		case tb_stageWarmStartOverflow:
			tbWarmStartOverflow(context);
			break;
		case tb_stageSolveOverflow:
		default:
			tbSolveOverflow(context, (tbBiasPolicy)s->policy);
			break;
	}
}

static void tbRunUnit(tbStepContext* context, const tbStage* s, int unit)
{
	int begin = s->start + unit * s->unitSize;
	tbRunRange(context, s, begin, tbMinInt(s->start + s->count, begin + s->unitSize));
}

/// Run every unit of stage s nobody has claimed. The units are cut into one contiguous share per
/// participant; participant `slot` claims from its own share first (so in a stage after stage it
/// finds the same blocks and bodies it had before in its cache), then helps with the others' in
/// turn. The units done are counted once, at the end.
static void tbWorkOnStage(tbStageProgram* p, tbStage* s, int slot)
{
	int shares = p->workerCount;
	int done = 0;
	for (int j = 0; j < shares; ++j)
	{
		int share = slot + j < shares ? slot + j : slot + j - shares;
		int first = (int)((int64_t)share * s->unitCount / shares);
		int end = (int)((int64_t)(share + 1) * s->unitCount / shares);
		atomic_int* claimed = p->shareClaims + share * p->shareStride + s->index;
		for (;;)
		{
			int unit = first + atomic_fetch_add_explicit(claimed, 1, memory_order_relaxed);
			if (unit >= end)
			{
				break;
			}
			tbRunUnit(p->context, s, unit);
			done += 1;
		}
	}
	if (done > 0)
	{
		atomic_fetch_add_explicit(&s->doneUnits, done, memory_order_release);
	}
}

/// The part of the step's profile a stage's time goes to (tbProfile).
static float* tbStageProfilePart(tbProfile* profile, const tbStage* s)
{
	switch ((tbStageKind)s->kind)
	{
		case tb_stageIntegrateVelocities:
			return &profile->integrateVelocities;
		case tb_stageIntegratePositions:
			return &profile->integratePositions;
		case tb_stageWarmStartMechanisms:
		case tb_stageWarmStartJoints:
		case tb_stageWarmStartColor:
		case tb_stageWarmStartOverflow:
			return &profile->warmStart;
		case tb_stageSolveColor:
		case tb_stageSolveOverflow:
			return s->policy == tb_biasSoft ? &profile->solveImpulses : &profile->relaxImpulses;
		default: // the joint passes
			return s->useBias ? &profile->solveImpulses : &profile->relaxImpulses;
	}
}

/// Opens the stages one after another; the time of each, from opening to done, goes to its part
/// of the profile (only the orchestrator writes it, and the caller reads it after the program).
static void tbOrchestrate(tbStageProgram* p, int slot)
{
	tbProfile* profile = &p->context->world->profile;
	for (int k = 0; k < p->stageCount; ++k)
	{
		tbStage* s = p->stages + k;
		atomic_store_explicit(&p->openStage, k, memory_order_release);
		tbWorkOnStage(p, s, slot);
		int rounds = 0;
		while (atomic_load_explicit(&s->doneUnits, memory_order_acquire) < s->unitCount)
		{
			tbSpinPause(&rounds); // the last units of the stage are running on other workers
		}
		tbProfileLap(tbStageProfilePart(profile, s), &p->context->lapTicks);
	}
	atomic_store_explicit(&p->openStage, p->stageCount, memory_order_release);
}

static void tbHelp(tbStageProgram* p, int slot)
{
	for (int k = 0; k < p->stageCount; ++k)
	{
		int open = atomic_load_explicit(&p->openStage, memory_order_acquire);
		int rounds = 0;
		while (open < k)
		{
			tbSpinPause(&rounds);
			open = atomic_load_explicit(&p->openStage, memory_order_acquire);
		}
		if (open >= p->stageCount)
		{
			return;
		}
		tbWorkOnStage(p, p->stages + k, slot);
	}
}

/// `workerIndex`: the task system's for the thread (the caller's is 0). Worker w takes slot w, so it
/// starts each stage where it started the loops before (tbWorkOnStage), as a task system that hands
/// worker w the w-th share of a loop's items does (samples/task_system.c).
static void tbParticipate(tbStageProgram* p, uint32_t workerIndex)
{
	int slot = (int)(workerIndex % (uint32_t)p->workerCount);
	int expected = 0;
	if (atomic_compare_exchange_strong_explicit(&p->orchestrator, &expected, 1, memory_order_acq_rel,
												memory_order_acquire))
	{
		tbOrchestrate(p, slot);
	}
	else
	{
		tbHelp(p, slot);
	}
}

/// Every stage of the program on partition `partition`'s bodies and blocks alone (constraint_graph.c):
/// nothing it reads or writes is another partition's, so it waits for no one. Partition 0 runs on
/// the caller, which laps the stages' times.
static void tbRunPartition(tbStageProgram* p, int partition)
{
	tbStepContext* context = p->context;
	tbProfile* profile = &context->world->profile;
	int firstBody = context->partitionBodyStart[partition];
	int endBody = context->partitionBodyStart[partition + 1];
	for (int k = 0; k < p->stageCount; ++k)
	{
		const tbStage* s = p->stages + k;
		if (s->kind == tb_stageIntegrateVelocities || s->kind == tb_stageIntegratePositions)
		{
			tbRunRange(context, s, firstBody, endBody);
		}
		else if (s->color >= 0) // the program holds no other stage with partitions (tbSolveSubStepsOnWorkers)
		{
			const int* blockStart = context->partitionBlockStart[s->color];
			tbRunRange(context, s, blockStart[partition], blockStart[partition + 1]);
		}
		if (partition == 0)
		{
			tbProfileLap(tbStageProfilePart(profile, s), &context->lapTicks);
		}
	}
}

/// One worker's part of the program: a partition, or a share of the stages (tbParticipate).
typedef struct tbProgramPart
{
	tbStageProgram* program;
	int index; ///< the partition, or the worker index
} tbProgramPart;

static void tbPartitionTask(void* taskContext)
{
	tbProgramPart* part = taskContext;
	tbRunPartition(part->program, part->index);
}

/// The partitions' programs side by side: the caller runs partition 0 and the workers the others.
static void tbRunPartitions(tbStageProgram* p)
{
	tbWorld* world = p->context->world;
	tbProgramPart parts[TB_MAX_WORKERS];
	int count = p->context->partitionCount;
	for (int i = 0; i < count; ++i)
	{
		parts[i] = (tbProgramPart){p, i};
	}
	tbRunOnWorkers(&world->def, tbPartitionTask, parts, (int)sizeof(tbProgramPart), count);
	// The wait for the last partition goes to the last stage's part of the profile.
	tbProfileLap(tbStageProfilePart(&world->profile, p->stages + p->stageCount - 1), &p->context->lapTicks);
}

static void tbHelperTask(void* taskContext)
{
	tbProgramPart* part = taskContext;
	tbParticipate(part->program, (uint32_t)part->index);
}

bool tbSolveSubStepsOnWorkers(tbStepContext* context)
{
	tbWorld* world = context->world;
	int workers = tbWorkerCount(&world->def);
	bool contactsColored = context->wideConstraints != NULL || context->constraintCount == 0;
	if (workers <= 1 || world->def.solver != tb_solverSoft || contactsColored == false ||
		context->enableWarmStarting == false)
	{
		return false; // the serial loop (warm starting off zeroes impulses there)
	}
	// A world this small solves faster on the caller than with the stages shared: each stage's
	// hand-over between threads costs more than its work (many small worlds on a server's workers).
	// The two loops give the same results, so the choice does not show.
	if (context->bodyCount < TB_BODIES_PER_UNIT && context->constraintCount + world->cache.solverJointCount < 2 * TB_BODIES_PER_UNIT)
	{
		return false;
	}
	// Stages per sub-step: 2 integrations; per pass (warm start, solve, relaxes) one per contact
	// colour and the overflow, and for the joints the trees' 2 stages and twice their colours.
	int relaxPasses = 0;
	for (int i = 0; i < context->subStepCount; ++i)
	{
		relaxPasses += tbSoftRelaxIterations(context, i);
	}
	int passStages = 1 + context->colorCount + 2 + 2 * (1 + context->jointColorCount);
	int capacity = context->subStepCount * (2 + 2 * passStages) + relaxPasses * passStages;
	tbStageProgram program;
	program.context = context;
	program.workerCount = workers;
	program.stageCount = 0;
	program.stages = tbArenaAlloc(&world->stepArena, capacity * (int)sizeof(tbStage) + 64);
	program.stages = (tbStage*)(((uintptr_t)program.stages + 63) & ~(uintptr_t)63); // the alignment above
	atomic_init(&program.openStage, -1);
	atomic_init(&program.orchestrator, 0);
	tbBuildSoftProgram(&program);
	// Partitions (constraint_graph.c) hold only contact colours and bodies: no joint stage, no
	// overflow.
	bool jointStages = context->jointUnitCount > 0 || context->jointColorCount > 0 || world->cache.jointTreeCount > 0;
	if (context->partitionCount == workers && jointStages == false && context->overflowCount == 0)
	{
		tbRunPartitions(&program);
		return true;
	}
	int lineInts = 64 / (int)sizeof(atomic_int);
	program.shareStride = (program.stageCount + lineInts - 1) / lineInts * lineInts;
	int counters = workers * program.shareStride;
	char* claimBytes = tbArenaAlloc(&world->stepArena, counters * (int)sizeof(atomic_int) + 64);
	program.shareClaims = (atomic_int*)(((uintptr_t)claimBytes + 63) & ~(uintptr_t)63); // rows on lines of their own
	for (int i = 0; i < counters; ++i)
	{
		atomic_init(program.shareClaims + i, 0);
	}
	tbProgramPart parts[TB_MAX_WORKERS];
	for (int w = 0; w < workers; ++w)
	{
		parts[w] = (tbProgramPart){&program, w};
	}
	tbRunOnWorkers(&world->def, tbHelperTask, parts, (int)sizeof(tbProgramPart), workers);
	return true; // the stages go with the step arena
}
