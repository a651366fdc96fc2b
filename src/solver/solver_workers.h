// Internal: the soft step's sub-steps on the game's workers (solver_workers.c).
#pragma once

#include "solver_types.h"

/// Run every sub-step of the soft step (integrate, warm start, solve, relax) on the world's workers,
/// bit-identical to the serial loop in tbSolveStage. Returns false, having done nothing, when the
/// world has one worker or the step is not the wide soft step (the serial loop runs then).
bool tbSolveSubStepsOnWorkers(tbStepContext* context);
