// Reference task system (see task_system.h): a pool of threads and a queue of callbacks. The
// library cuts its loops into ranges and hands each worker one task whose context says which
// worker it is, so the system only runs callbacks, once each, in any order.
//
// Enqueue puts a task in the next free slot of a ring and wakes the threads; a thread takes the
// oldest waiting task. Finish waits for one task: while it has not been taken, the caller takes
// waiting tasks itself (so a step never waits on threads that are busy elsewhere), then it spins
// until the task is done. Threads spin a while for the next task (a step enqueues its loops
// microseconds apart) before they sleep on a condition variable.
#include "task_system.h"

#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#define TASK_SPIN_ROUNDS 4000
#define TASK_SLOTS 256

typedef struct Slot
{
	tbTaskCallback* callback;
	void* context;
	atomic_int state; ///< a SlotState
} Slot;

enum SlotState
{
	slotFree,
	slotWaiting, ///< enqueued, not yet taken
	slotRunning,
	slotDone, ///< run; freed by TaskSystem_Finish
};

struct TaskSystem
{
	int workerCount;
	pthread_t threads[TB_MAX_WORKERS];
	int threadCount;
	Slot slots[TASK_SLOTS];
	int head; ///< next slot to enqueue into (the caller's; under lock)
	int tail; ///< oldest slot that may be waiting (under lock)
	atomic_int waiting;	 ///< tasks enqueued and not yet taken
	atomic_int sleeping; ///< threads asleep on the condition variable (the rest spin)
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

/// Take the oldest waiting task, or NULL when none waits.
static Slot* TakeTask(TaskSystem* system)
{
	Slot* taken = NULL;
	pthread_mutex_lock(&system->lock);
	while (system->tail != system->head)
	{
		Slot* slot = system->slots + system->tail;
		system->tail = (system->tail + 1) % TASK_SLOTS;
		int expected = slotWaiting;
		if (atomic_compare_exchange_strong(&slot->state, &expected, slotRunning))
		{
			atomic_fetch_sub(&system->waiting, 1);
			taken = slot;
			break;
		}
	}
	pthread_mutex_unlock(&system->lock);
	return taken;
}

static void RunTask(Slot* slot)
{
	slot->callback(slot->context);
	atomic_store_explicit(&slot->state, slotDone, memory_order_release);
}

/// Wait until a task waits or the system quits: spin first, then sleep.
static void WaitForWork(TaskSystem* system)
{
	for (int i = 0; i < TASK_SPIN_ROUNDS; ++i)
	{
		if (atomic_load(&system->waiting) > 0 || atomic_load(&system->quit))
		{
			return;
		}
		Pause();
	}
	pthread_mutex_lock(&system->lock);
	atomic_fetch_add(&system->sleeping, 1);
	while (atomic_load(&system->waiting) == 0 && atomic_load(&system->quit) == false)
	{
		pthread_cond_wait(&system->wake, &system->lock);
	}
	atomic_fetch_sub(&system->sleeping, 1);
	pthread_mutex_unlock(&system->lock);
}

static void* ThreadMain(void* argument)
{
	TaskSystem* system = argument;
	for (;;)
	{
		WaitForWork(system);
		if (atomic_load(&system->quit))
		{
			return NULL;
		}
		Slot* slot = TakeTask(system);
		if (slot != NULL)
		{
			RunTask(slot);
		}
	}
}

TaskSystem* TaskSystem_Create(int workerCount)
{
	if (workerCount < 1 || workerCount > TB_MAX_WORKERS)
	{
		return NULL;
	}
	TaskSystem* system = calloc(1, sizeof(TaskSystem));
	if (system == NULL)
	{
		return NULL;
	}
	system->workerCount = workerCount;
	for (int i = 0; i < TASK_SLOTS; ++i)
	{
		atomic_init(&system->slots[i].state, slotFree);
	}
	atomic_init(&system->waiting, 0);
	atomic_init(&system->sleeping, 0);
	atomic_init(&system->quit, false);
	pthread_mutex_init(&system->lock, NULL);
	pthread_cond_init(&system->wake, NULL);
	for (int i = 0; i < workerCount - 1; ++i)
	{
		if (pthread_create(system->threads + i, NULL, ThreadMain, system) != 0)
		{
			break;
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
	atomic_store(&system->quit, true);
	pthread_cond_broadcast(&system->wake);
	pthread_mutex_unlock(&system->lock);
	for (int i = 0; i < system->threadCount; ++i)
	{
		pthread_join(system->threads[i], NULL);
	}
	pthread_mutex_destroy(&system->lock);
	pthread_cond_destroy(&system->wake);
	free(system);
}

int TaskSystem_WorkerCount(const TaskSystem* system)
{
	return system != NULL ? system->workerCount : 1;
}

void* TaskSystem_Enqueue(tbTaskCallback* callback, void* taskContext, void* userContext)
{
	TaskSystem* system = userContext;
	pthread_mutex_lock(&system->lock);
	Slot* slot = system->slots + system->head;
	bool room = system->threadCount > 0 && atomic_load(&slot->state) == slotFree;
	if (room)
	{
		slot->callback = callback;
		slot->context = taskContext;
		atomic_store(&slot->state, slotWaiting);
		system->head = (system->head + 1) % TASK_SLOTS;
		atomic_fetch_add(&system->waiting, 1);
		if (atomic_load(&system->sleeping) > 0)
		{
			pthread_cond_signal(&system->wake); // spinning threads see `waiting` without it
		}
	}
	pthread_mutex_unlock(&system->lock);
	if (room == false)
	{
		callback(taskContext); // no thread, or every slot in use: run it here
		return NULL;
	}
	return slot;
}

void TaskSystem_Finish(void* userTask, void* userContext)
{
	TaskSystem* system = userContext;
	Slot* slot = userTask;
	int rounds = 0;
	while (atomic_load_explicit(&slot->state, memory_order_acquire) != slotDone)
	{
		Slot* other = atomic_load(&system->waiting) > 0 ? TakeTask(system) : NULL;
		if (other != NULL)
		{
			RunTask(other); // perhaps this very task: nobody had taken it yet
			continue;
		}
		if (++rounds < TASK_SPIN_ROUNDS)
		{
			Pause();
		}
		else
		{
			sched_yield();
		}
	}
	atomic_store_explicit(&slot->state, slotFree, memory_order_release);
}
