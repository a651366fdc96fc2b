// A small reference task system for tbWorldDef's enqueueTask/finishTask (Box2D v3.2's interface):
// a pool of workerCount − 1 threads (POSIX threads) and a queue of callbacks; the calling thread
// runs waiting tasks while it finishes one. The library itself creates no threads; a game passes
// its own task system instead (any that runs a callback once per enqueue).
//
//   TaskSystem* tasks = TaskSystem_Create(4);
//   def.workerCount = TaskSystem_WorkerCount(tasks);
//   def.enqueueTask = TaskSystem_Enqueue;
//   def.finishTask = TaskSystem_Finish;
//   def.userTaskContext = tasks;
#pragma once

#include "tumble/tumble.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct TaskSystem TaskSystem;

/// A pool of workerCount − 1 threads (workerCount 1 to TB_MAX_WORKERS); NULL if threads cannot start.
TaskSystem* TaskSystem_Create(int workerCount);
void TaskSystem_Destroy(TaskSystem* system);
int TaskSystem_WorkerCount(const TaskSystem* system);

/// tbEnqueueTaskCallback: queues task(taskContext) for the pool's threads; runs it at once and
/// returns NULL when the pool has no thread or no free slot.
void* TaskSystem_Enqueue(tbTaskCallback* task, void* taskContext, void* userContext);
/// tbFinishTaskCallback: runs waiting tasks until this one has run, then frees its slot.
void TaskSystem_Finish(void* userTask, void* userContext);

#ifdef __cplusplus
}
#endif
