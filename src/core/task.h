// Internal: running parts of the step on the game's task system, as the world definition
// describes it (tbWorldDef::enqueueTask, finishTask, userTaskContext, workerCount).
#pragma once

#include "tumble/types.h"

/// Workers the step may use: def->workerCount when the task callbacks are set, else 1.
int tbWorkerCount(const tbWorldDef* def);

/// Per-worker slots a task run by tbParallelFor may be handed: workerIndex is below this. The
/// game's worker indices [0, workerCount), and as many spares for a task system that breaks the
/// callback's contract (an index at or beyond workerCount: tbParallelFor reports it and lends the
/// range a spare slot), so per-worker buffers of this many entries are never overrun.
int tbWorkerSlotCount(const tbWorldDef* def);

/// Run task over items [0, itemCount) on the workers def describes, ranges of at least minRange items,
/// and return when every item has run. Without task callbacks (or with one worker, or too few
/// items to split) it runs on the caller as task(0, itemCount, 0, context). The task sees a worker
/// index below tbWorkerSlotCount, never shared by two ranges running at once.
void tbParallelFor(const tbWorldDef* def, tbTaskCallback* task, int itemCount, int minRange, void* context);

/// tbParallelFor, with `alongside(alongsideContext)` run on the caller while the workers start on
/// the items (between enqueueing the task and finishing it), for serial work that shares no data
/// with the task. Without workers it runs first, then the task.
void tbParallelForAlongside(const tbWorldDef* def, tbTaskCallback* task, int itemCount, int minRange, void* context,
							void (*alongside)(void*), void* alongsideContext);

/// One round of a spin-wait: a pause hint to the processor, and after many rounds a yield of the
/// thread, so that waiting workers on an oversubscribed machine let the others run.
void tbSpinPause(int* rounds);
