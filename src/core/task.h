// Internal: running parts of the step on the game's task system, as the world definition
// describes it (tbWorldDef::enqueueTask, finishTask, userTaskContext, workerCount). The game's
// system only runs callbacks (Box2D v3.2's interface); the splitting of a loop into ranges and the
// worker indices are the library's, here.
#pragma once

#include "tumble/types.h"

/// A part of a loop: items [startIndex, endIndex) run by worker `workerIndex` (below the worker
/// count; no two ranges running at the same time share one).
typedef void tbRangeTask(int startIndex, int endIndex, uint32_t workerIndex, void* context);

/// Workers the step may use: def->workerCount when the task callbacks are set, else 1.
int tbWorkerCount(const tbWorldDef* def);

/// Per-worker slots a range task may be handed: workerIndex is below this (the worker count).
int tbWorkerSlotCount(const tbWorldDef* def);

/// Run task over items [0, itemCount) on the workers def describes, ranges of at least minRange
/// items, and return when every item has run. Without task callbacks (or with one worker, or too
/// few items to split) it runs on the caller as task(0, itemCount, 0, context).
void tbParallelFor(const tbWorldDef* def, tbRangeTask* task, int itemCount, int minRange, void* context);

/// tbParallelFor, with `alongside(alongsideContext)` run on the caller while the workers start on
/// the items (between enqueueing the tasks and joining them), for serial work that shares no data
/// with the task. Without workers it runs first, then the task.
void tbParallelForAlongside(const tbWorldDef* def, tbRangeTask* task, int itemCount, int minRange, void* context,
							void (*alongside)(void*), void* alongsideContext);

/// Run `task(contexts + i·contextSize)` for i in [0, count): i = 0 on the caller, the others as
/// tasks of the game's system, and return when all have run. For work whose parts are the workers'
/// own (the solver's partitions and stage helpers): each part's context says which worker it is.
/// Every part must be able to finish without another one running at the same time.
void tbRunOnWorkers(const tbWorldDef* def, tbTaskCallback* task, void* contexts, int contextSize, int count);

/// One round of a spin-wait: a pause hint to the processor, and after many rounds a yield of the
/// thread, so that waiting workers on an oversubscribed machine let the others run.
void tbSpinPause(int* rounds);

/// Count the tasks this thread hands to the game's task system into *counter from now on (NULL:
/// stop counting). The world sets it for the thread that steps (tbCounters::taskCount); a thread
/// local, so worlds stepping on different threads count apart.
void tbCountTasksInto(int* counter);
