// Reference task system (see task_system.h). Threads wait for a task by spinning briefly on its
// generation counter (a step issues its tasks microseconds apart), then sleep on a condition
// variable. The ranges are cut into one share per worker, each with an atomic counter: worker w
// claims from share w first, then from the others', so a range is run exactly once, by whichever
// thread gets to it first; completions are counted to know when the task is done.
//
// The one task record is reused, so a thread late from the last task must not read it while the
// next is written. The generation works as a sequence lock: odd while the caller writes a task,
// even once it is published. A thread announces itself (busy) before it reads a published task and
// checks that the generation did not move meanwhile; the caller makes the generation odd, then
// waits until no thread is busy, before it writes.
#include "task_system.h"

#include <pthread.h>
#include <sched.h>
#include <stdalign.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#define TASK_SPIN_ROUNDS 4000

/// The ranges of one worker's share: the next to claim, on a line of its own (every claim writes it).
typedef struct Share
{
	alignas(64) atomic_int next;
	int end;
} Share;

typedef struct Task
{
	tbTaskCallback* callback;
	void* context;
	int itemCount;
	int rangeSize;
	int rangeCount;
	int shareCount;
	Share shares[TB_MAX_WORKERS];
	alignas(64) atomic_int doneRanges;
} Task;

typedef struct Thread
{
	TaskSystem* system;
	pthread_t handle;
	uint32_t workerIndex;
} Thread;

struct TaskSystem
{
	int workerCount;
	Thread threads[TB_MAX_WORKERS];
	int threadCount;
	Task task;
	atomic_uint generation; ///< odd while a task is written, even when published
	atomic_int busy;		///< threads reading or running the published task
	atomic_bool quit;
	pthread_mutex_t lock;
	pthread_cond_t wake;
};

/// A hint to the processor that this is a spin-wait (frees the core's resources for the others).
static inline void Pause(void)
{
#if defined(__x86_64__) || defined(__i386__)
	__builtin_ia32_pause();
#endif
}

/// Claim and run ranges of the current task until none is left. The ranges are cut into one
/// contiguous share per worker; worker w starts on share w, then helps with the others in turn. Loop
/// after loop over the same items (bodies, contacts in id order) a worker so takes the same items,
/// and finds them and what the step's other stages wrote for them in its own cache; the library's
/// sub-step stages start worker w at w/n of each stage likewise (solver_workers.c).
static void RunRanges(Task* task, uint32_t workerIndex)
{
	for (int k = 0; k < task->shareCount; ++k)
	{
		Share* share = task->shares + ((int)workerIndex + k) % task->shareCount;
		for (;;)
		{
			int range = atomic_fetch_add_explicit(&share->next, 1, memory_order_acq_rel);
			if (range >= share->end)
			{
				break;
			}
			int start = range * task->rangeSize;
			int end = start + task->rangeSize < task->itemCount ? start + task->rangeSize : task->itemCount;
			task->callback(start, end, workerIndex, task->context);
			atomic_fetch_add_explicit(&task->doneRanges, 1, memory_order_acq_rel);
		}
	}
}

static unsigned WaitForTask(TaskSystem* system, unsigned seen)
{
	for (int i = 0; i < TASK_SPIN_ROUNDS; ++i)
	{
		unsigned now = atomic_load_explicit(&system->generation, memory_order_acquire);
		if (now != seen || atomic_load_explicit(&system->quit, memory_order_acquire))
		{
			return now;
		}
		Pause();
	}
	pthread_mutex_lock(&system->lock);
	unsigned now = atomic_load_explicit(&system->generation, memory_order_acquire);
	while (now == seen && atomic_load_explicit(&system->quit, memory_order_acquire) == false)
	{
		pthread_cond_wait(&system->wake, &system->lock);
		now = atomic_load_explicit(&system->generation, memory_order_acquire);
	}
	pthread_mutex_unlock(&system->lock);
	return now;
}

static void* ThreadMain(void* argument)
{
	Thread* thread = argument;
	TaskSystem* system = thread->system;
	unsigned seen = atomic_load_explicit(&system->generation, memory_order_acquire);
	for (;;)
	{
		seen = WaitForTask(system, seen);
		if (atomic_load_explicit(&system->quit, memory_order_acquire))
		{
			return NULL;
		}
		if (seen & 1u)
		{
			continue; // being written: wait for it to be published
		}
		atomic_fetch_add_explicit(&system->busy, 1, memory_order_seq_cst);
		if (atomic_load_explicit(&system->generation, memory_order_seq_cst) == seen)
		{
			RunRanges(&system->task, thread->workerIndex);
		}
		atomic_fetch_sub_explicit(&system->busy, 1, memory_order_release);
	}
}

TaskSystem* TaskSystem_Create(int workerCount)
{
	if (workerCount < 1 || workerCount > TB_MAX_WORKERS)
	{
		return NULL;
	}
	size_t bytes = (sizeof(TaskSystem) + 63) / 64 * 64; // aligned_alloc: a multiple of the alignment,
	TaskSystem* system = aligned_alloc(64, bytes);		  // which the shares' lines need (alignas)
	if (system == NULL)
	{
		return NULL;
	}
	memset(system, 0, bytes);
	system->workerCount = workerCount;
	atomic_init(&system->generation, 0u);
	atomic_init(&system->busy, 0);
	atomic_init(&system->quit, false);
	for (int w = 0; w < TB_MAX_WORKERS; ++w)
	{
		atomic_init(&system->task.shares[w].next, 0);
	}
	atomic_init(&system->task.doneRanges, 0);
	pthread_mutex_init(&system->lock, NULL);
	pthread_cond_init(&system->wake, NULL);
	for (int i = 0; i < workerCount - 1; ++i)
	{
		Thread* thread = system->threads + i;
		thread->system = system;
		thread->workerIndex = (uint32_t)(i + 1);
		if (pthread_create(&thread->handle, NULL, ThreadMain, thread) != 0)
		{
			TaskSystem_Destroy(system);
			return NULL;
		}
		system->threadCount += 1;
	}
	return system;
}

void TaskSystem_Destroy(TaskSystem* system)
{
	if (system == NULL)
	{
		return;
	}
	pthread_mutex_lock(&system->lock);
	atomic_store_explicit(&system->quit, true, memory_order_release);
	pthread_cond_broadcast(&system->wake);
	pthread_mutex_unlock(&system->lock);
	for (int i = 0; i < system->threadCount; ++i)
	{
		pthread_join(system->threads[i].handle, NULL);
	}
	pthread_cond_destroy(&system->wake);
	pthread_mutex_destroy(&system->lock);
	free(system);
}

int TaskSystem_WorkerCount(const TaskSystem* system)
{
	return system->workerCount;
}

void* TaskSystem_Enqueue(tbTaskCallback* callback, int itemCount, int minRange, void* taskContext, void* userContext)
{
	TaskSystem* system = userContext;
	if (system->threadCount == 0 || itemCount <= 0)
	{
		if (itemCount > 0)
		{
			callback(0, itemCount, 0, taskContext);
		}
		return NULL;
	}
	// Four ranges per worker (at least minRange items each): uneven items even out as workers that
	// finish early take more ranges.
	int workers = 4 * system->workerCount;
	int rangeSize = (itemCount + workers - 1) / workers;
	rangeSize = rangeSize < minRange ? minRange : rangeSize;
	Task* task = &system->task;
	atomic_fetch_add_explicit(&system->generation, 1u, memory_order_seq_cst); // odd: writing
	while (atomic_load_explicit(&system->busy, memory_order_seq_cst) != 0)
	{
		Pause(); // a thread is leaving the last task
	}
	task->callback = callback;
	task->context = taskContext;
	task->itemCount = itemCount;
	task->rangeSize = rangeSize;
	task->rangeCount = (itemCount + rangeSize - 1) / rangeSize;
	task->shareCount = system->workerCount;
	for (int w = 0; w < task->shareCount; ++w)
	{
		atomic_store_explicit(&task->shares[w].next, w * task->rangeCount / task->shareCount, memory_order_relaxed);
		task->shares[w].end = (w + 1) * task->rangeCount / task->shareCount;
	}
	atomic_store_explicit(&task->doneRanges, 0, memory_order_relaxed);
	pthread_mutex_lock(&system->lock);
	atomic_fetch_add_explicit(&system->generation, 1u, memory_order_release); // even: published
	pthread_cond_broadcast(&system->wake);
	pthread_mutex_unlock(&system->lock);
	return task;
}

void TaskSystem_Finish(void* userTask, void* userContext)
{
	(void)userContext;
	Task* task = userTask;
	RunRanges(task, 0);
	while (atomic_load_explicit(&task->doneRanges, memory_order_acquire) < task->rangeCount)
	{
		sched_yield(); // the last ranges are running on other threads
	}
}
