// Tasks: the step hands ranges of independent items (contacts to collide, bodies to integrate,
// blocks of one graph colour) to the game's task system. Results never depend on how the items
// are split or which worker runs them: every item writes only its own data, and whatever is
// appended or summed is done afterwards on the caller in item order.
#include "task.h"

#include "world.h"

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

int tbWorkerCount(const tbWorld* world)
{
	return world->def.enqueueTask != NULL ? world->def.workerCount : 1;
}

void tbParallelFor(tbWorld* world, tbTaskCallback* task, int itemCount, int minRange, void* context)
{
	if (itemCount <= 0)
	{
		return;
	}
	int workers = tbWorkerCount(world);
	if (workers <= 1 || itemCount <= minRange)
	{
		task(0, itemCount, 0, context);
		return;
	}
	void* handle = world->def.enqueueTask(task, itemCount, minRange, context, world->def.userTaskContext);
	if (handle != NULL)
	{
		world->def.finishTask(handle, world->def.userTaskContext);
	}
}

void tbParallelForAlongside(tbWorld* world, tbTaskCallback* task, int itemCount, int minRange, void* context,
							void (*alongside)(void*), void* alongsideContext)
{
	int workers = tbWorkerCount(world);
	if (workers <= 1 || itemCount <= minRange)
	{
		alongside(alongsideContext);
		tbParallelFor(world, task, itemCount, minRange, context);
		return;
	}
	void* handle = world->def.enqueueTask(task, itemCount, minRange, context, world->def.userTaskContext);
	alongside(alongsideContext);
	if (handle != NULL)
	{
		world->def.finishTask(handle, world->def.userTaskContext);
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
