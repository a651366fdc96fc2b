// The task system (task_system.h) where the platform has no threads, as in the WebAssembly build
// (WASI without its threads proposal): no pool can start, so TaskSystem_Create answers NULL as its
// contract says for threads that cannot start, and a task given to Enqueue runs at once on the
// caller, as task_system.c runs it when its pool has no thread.
#include "task_system.h"

#include <stddef.h>

TaskSystem* TaskSystem_Create(int workerCount)
{
	(void)workerCount;
	return NULL;
}

void TaskSystem_Destroy(TaskSystem* system)
{
	(void)system;
}

int TaskSystem_WorkerCount(const TaskSystem* system)
{
	(void)system;
	return 1;
}

void* TaskSystem_Enqueue(tbTaskCallback* callback, void* taskContext, void* userContext)
{
	(void)userContext;
	callback(taskContext);
	return NULL;
}

void TaskSystem_Finish(void* userTask, void* userContext)
{
	(void)userTask; // always NULL: Enqueue ran the task
	(void)userContext;
}
