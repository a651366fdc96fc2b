// Internal: the two island stages of the step (island.c).
#pragma once

typedef struct tbWorld tbWorld;

/// Before the solve: wake what touches the awake set and gather the touching contacts the solver
/// will see, in memory order and in solve order.
void tbIslandStage(tbWorld* world);
/// After the solve: islands of awake bodies that stayed slow for TB_TIME_TO_SLEEP fall asleep.
void tbSleepStage(tbWorld* world, float timeStep);
