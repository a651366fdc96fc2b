// A small reference task system for tbWorldDef's enqueueTask/finishTask: a fixed pool of
// workerCount − 1 threads (POSIX threads) plus the calling thread. The library itself creates no
// threads; a game passes its own task system instead. One task runs at a time per system.
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

/// tbEnqueueTaskCallback: splits the items into ranges the pool's threads start on at once; the
/// caller joins in TaskSystem_Finish (as worker 0).
void* TaskSystem_Enqueue(tbTaskCallback* task, int itemCount, int minRange, void* taskContext, void* userContext);
/// tbFinishTaskCallback: runs ranges no thread has taken yet, then waits for the rest.
void TaskSystem_Finish(void* userTask, void* userContext);

#ifdef __cplusplus
}
#endif
