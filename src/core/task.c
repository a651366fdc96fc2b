// Tasks: the step hands ranges of independent items (contacts to collide, bodies to integrate,
// blocks of one graph colour) to the game's task system. Results never depend on how the items
// are split or which worker runs them: every item writes only its own data, and whatever is
// appended or summed is done afterwards on the caller in item order.
#include "task.h"

#include "core.h"

#include <stdatomic.h>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define TB_PAUSE() _mm_pause()
#else
#define TB_PAUSE() ((void)0)
#endif

#if !defined(__STDC_NO_THREADS__)
#include <threads.h>
#define TB_YIELD() thrd_yield()
#else
#define TB_YIELD() ((void)0)
#endif

/// Spin rounds before a waiting worker starts yielding its time slice.
#define TB_SPINS_BEFORE_YIELD 2000

int tbWorkerCount(const tbWorldDef* def)
{
	return def->enqueueTask != NULL ? def->workerCount : 1;
}

int tbWorkerSlotCount(const tbWorldDef* def)
{
	return 2 * tbWorkerCount(def);
}

// The task callback's contract (types.h) gives every range a worker index in [0, workerCount), and
// the step's per-worker buffers are indexed by it. A task system that hands out a larger one (a
// pool of more threads than tbWorld_SetWorkerCount allows) would write past them, so the library's
// tasks run through this guard: a valid index passes straight on; a range with an invalid one
// borrows a spare slot [workerCount, 2·workerCount) for its duration (a bit mask, claimed by
// compare-and-swap; with every spare lent out it waits for one), and the caller reports the broken
// contract once the task is done. Sums and pair lists do not depend on which slot a range used.
typedef struct tbTaskGuard
{
	tbTaskCallback* task;
	void* context;
	uint32_t workers;
	atomic_uint_fast64_t spares; ///< bit s: spare slot workers + s is free
	atomic_uint badIndex;		 ///< the first invalid index seen + 1, or 0
} tbTaskGuard;

static void tbGuardedTask(int startIndex, int endIndex, uint32_t workerIndex, void* context)
{
	tbTaskGuard* guard = context;
	if (workerIndex < guard->workers)
	{
		guard->task(startIndex, endIndex, workerIndex, guard->context);
		return;
	}
	unsigned int none = 0u;
	atomic_compare_exchange_strong(&guard->badIndex, &none, workerIndex + 1u);
	int rounds = 0;
	uint_fast64_t free = atomic_load(&guard->spares);
	for (;;)
	{
		if (free == 0u)
		{
			tbSpinPause(&rounds);
			free = atomic_load(&guard->spares);
		}
		else if (atomic_compare_exchange_weak(&guard->spares, &free, free & (free - 1u)))
		{
			break;
		}
	}
	int spare = tbLowestSetBit(free);
	guard->task(startIndex, endIndex, guard->workers + (uint32_t)spare, guard->context);
	atomic_fetch_or(&guard->spares, (uint_fast64_t)1u << spare);
}

static void tbInitTaskGuard(tbTaskGuard* guard, tbTaskCallback* task, void* context, int workers)
{
	guard->task = task;
	guard->context = context;
	guard->workers = (uint32_t)workers;
	atomic_init(&guard->spares, workers >= 64 ? ~(uint_fast64_t)0u : ((uint_fast64_t)1u << workers) - 1u);
	atomic_init(&guard->badIndex, 0u);
}

static void tbFinishGuardedTask(const tbWorldDef* def, void* handle, tbTaskGuard* guard)
{
	if (handle != NULL)
	{
		def->finishTask(handle, def->userTaskContext);
	}
	unsigned int bad = atomic_load(&guard->badIndex);
	if (bad != 0u)
	{
		tbReportError("tbWorld_Step",
					  "the task system gave worker index %u, outside [0, workerCount = %u): the range ran in a spare "
					  "slot; give indices below tbWorldDef::workerCount (tbWorld_SetWorkerCount)",
					  bad - 1u, guard->workers);
	}
}

void tbParallelFor(const tbWorldDef* def, tbTaskCallback* task, int itemCount, int minRange, void* context)
{
	if (itemCount <= 0)
	{
		return;
	}
	int workers = tbWorkerCount(def);
	if (workers <= 1 || itemCount <= minRange)
	{
		task(0, itemCount, 0, context);
		return;
	}
	tbTaskGuard guard;
	tbInitTaskGuard(&guard, task, context, workers);
	void* handle = def->enqueueTask(tbGuardedTask, itemCount, minRange, &guard, def->userTaskContext);
	tbFinishGuardedTask(def, handle, &guard);
}

void tbParallelForAlongside(const tbWorldDef* def, tbTaskCallback* task, int itemCount, int minRange, void* context,
							void (*alongside)(void*), void* alongsideContext)
{
	int workers = tbWorkerCount(def);
	if (workers <= 1 || itemCount <= minRange)
	{
		alongside(alongsideContext);
		tbParallelFor(def, task, itemCount, minRange, context);
		return;
	}
	tbTaskGuard guard;
	tbInitTaskGuard(&guard, task, context, workers);
	void* handle = def->enqueueTask(tbGuardedTask, itemCount, minRange, &guard, def->userTaskContext);
	alongside(alongsideContext);
	tbFinishGuardedTask(def, handle, &guard);
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
