// Tasks: the step hands loops over independent items (contacts to collide, bodies to integrate,
// blocks of one graph colour) to the game's task system. Results never depend on how the items
// are split or which worker runs them: every item writes only its own data, and whatever is
// appended or summed is done afterwards on the caller in item order.
//
// The game's system only runs callbacks (Box2D v3.2's interface: task(taskContext), once per
// enqueue). A loop is cut here into ranges, and the ranges into one contiguous share per worker;
// worker w claims ranges from share w first, then from the others' in turn. Loop after loop over
// the same items (bodies, contacts in id order) a worker so takes the same items and finds them,
// and what the step's other stages wrote for them, in its own cache; the solver's stages start
// worker w at w/n of each stage likewise (solver_workers.c). The caller is worker 0 and enqueues
// one task for each other worker. Since every worker claims from every share once its own is
// done, the caller alone finishes the loop when the system runs none of the tasks before it is
// asked to finish them (fewer threads, tasks run in order, or run inline by enqueue).
#include "task.h"

#include "core.h"

#include <stdalign.h>
#include <stdatomic.h>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define TB_PAUSE() _mm_pause()
#else
#define TB_PAUSE() ((void)0)
#endif

// wasi-libc declares <threads.h> but defines thrd_yield only in its threaded build (atomics on): a
// single-threaded WebAssembly module has no other thread to yield to.
#if !defined(__STDC_NO_THREADS__) && (!defined(__wasm__) || defined(__wasm_atomics__))
#include <threads.h>
#define TB_YIELD() thrd_yield()
#else
#define TB_YIELD() ((void)0)
#endif

/// Spin rounds before a waiting worker starts yielding its time slice.
#define TB_SPINS_BEFORE_YIELD 2000

/// Ranges a loop is cut into per worker: uneven items even out as workers that finish early take
/// ranges from the others' shares.
#define TB_RANGES_PER_WORKER 4

/// One worker's share of a loop's ranges: the next to claim, on a cache line of its own (every
/// claim writes it).
typedef struct tbShare
{
	alignas(64) atomic_int next;
	int end;
} tbShare;

typedef struct tbLoop
{
	tbRangeTask* task;
	void* context;
	int itemCount;
	int rangeSize;
	int shareCount;
	tbShare shares[TB_MAX_WORKERS];
} tbLoop;

/// The context of one worker's task: the loop and the worker's index.
typedef struct tbLoopWorker
{
	tbLoop* loop;
	uint32_t workerIndex;
} tbLoopWorker;

int tbWorkerCount(const tbWorldDef* def)
{
	return def->enqueueTask != NULL && def->finishTask != NULL ? def->workerCount : 1;
}

int tbWorkerSlotCount(const tbWorldDef* def)
{
	return tbWorkerCount(def);
}

/// Claim and run ranges until none is left: the worker's own share, then the others' in turn.
static void tbRunShares(tbLoop* loop, uint32_t workerIndex)
{
	for (int k = 0; k < loop->shareCount; ++k)
	{
		tbShare* share = loop->shares + ((int)workerIndex + k) % loop->shareCount;
		for (;;)
		{
			int range = atomic_fetch_add_explicit(&share->next, 1, memory_order_relaxed);
			if (range >= share->end)
			{
				break;
			}
			int start = range * loop->rangeSize;
			int end = tbMinInt(start + loop->rangeSize, loop->itemCount);
			loop->task(start, end, workerIndex, loop->context);
		}
	}
}

static void tbLoopTask(void* taskContext)
{
	tbLoopWorker* worker = taskContext;
	tbRunShares(worker->loop, worker->workerIndex);
}

static void tbInitLoop(tbLoop* loop, tbRangeTask* task, void* context, int itemCount, int minRange, int workers)
{
	int rangeSize = tbMaxInt((itemCount + TB_RANGES_PER_WORKER * workers - 1) / (TB_RANGES_PER_WORKER * workers),
							 tbMaxInt(minRange, 1));
	int rangeCount = (itemCount + rangeSize - 1) / rangeSize;
	loop->task = task;
	loop->context = context;
	loop->itemCount = itemCount;
	loop->rangeSize = rangeSize;
	loop->shareCount = tbMinInt(workers, rangeCount);
	for (int w = 0; w < loop->shareCount; ++w)
	{
		atomic_init(&loop->shares[w].next, w * rangeCount / loop->shareCount);
		loop->shares[w].end = (w + 1) * rangeCount / loop->shareCount;
	}
}

static _Thread_local int* s_taskCounter = NULL;

void tbCountTasksInto(int* counter)
{
	s_taskCounter = counter;
}

/// The game's enqueue, counted for tbCounters::taskCount.
static void* tbEnqueue(const tbWorldDef* def, tbTaskCallback* task, void* taskContext)
{
	if (s_taskCounter != NULL)
	{
		*s_taskCounter += 1;
	}
	return def->enqueueTask(task, taskContext, def->userTaskContext);
}

/// Enqueue a task for each worker but the caller's (handles[w], NULL when it ran inline).
static void tbStartHelpers(const tbWorldDef* def, tbLoop* loop, tbLoopWorker* workers, void** handles)
{
	for (int w = 1; w < loop->shareCount; ++w)
	{
		workers[w] = (tbLoopWorker){loop, (uint32_t)w};
		handles[w] = tbEnqueue(def, tbLoopTask, workers + w);
	}
}

static void tbJoinHelpers(const tbWorldDef* def, const tbLoop* loop, void** handles)
{
	for (int w = 1; w < loop->shareCount; ++w)
	{
		if (handles[w] != NULL)
		{
			def->finishTask(handles[w], def->userTaskContext);
		}
	}
}

void tbParallelFor(const tbWorldDef* def, tbRangeTask* task, int itemCount, int minRange, void* context)
{
	tbParallelForAlongside(def, task, itemCount, minRange, context, NULL, NULL);
}

void tbParallelForAlongside(const tbWorldDef* def, tbRangeTask* task, int itemCount, int minRange, void* context,
							void (*alongside)(void*), void* alongsideContext)
{
	int workers = tbWorkerCount(def);
	if (workers <= 1 || itemCount <= minRange)
	{
		if (alongside != NULL)
		{
			alongside(alongsideContext);
		}
		if (itemCount > 0)
		{
			task(0, itemCount, 0, context);
		}
		return;
	}
	tbLoop loop;
	tbInitLoop(&loop, task, context, itemCount, minRange, workers);
	tbLoopWorker helpers[TB_MAX_WORKERS];
	void* handles[TB_MAX_WORKERS];
	tbStartHelpers(def, &loop, helpers, handles);
	if (alongside != NULL)
	{
		alongside(alongsideContext);
	}
	tbRunShares(&loop, 0);
	tbJoinHelpers(def, &loop, handles);
}

void tbRunOnWorkers(const tbWorldDef* def, tbTaskCallback* task, void* contexts, int contextSize, int count)
{
	void* handles[TB_MAX_WORKERS];
	bool onWorkers = tbWorkerCount(def) > 1;
	for (int i = 1; i < count; ++i)
	{
		void* part = (char*)contexts + (size_t)i * (size_t)contextSize;
		handles[i] = onWorkers ? tbEnqueue(def, task, part) : NULL;
		if (onWorkers == false)
		{
			task(part); // no task system: the caller runs the parts one after another (they wait on no one)
		}
	}
	task(contexts);
	for (int i = 1; i < count; ++i)
	{
		if (handles[i] != NULL)
		{
			def->finishTask(handles[i], def->userTaskContext);
		}
	}
}

void tbSpinPause(int* rounds)
{
	*rounds += 1;
	if (*rounds < TB_SPINS_BEFORE_YIELD)
	{
		TB_PAUSE();
	}
	else
	{
		TB_YIELD();
	}
}
