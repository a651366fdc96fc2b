// Internal: the continuous stage of the step: time of impact for bodies fast enough to tunnel
// (continuous.c).
#pragma once

#include <stdbool.h>

typedef struct tbWorld tbWorld;
typedef struct tbBody tbBody;

/// Sets and returns body->isFast: the body moved further this step than its speculative contacts
/// cover (or is a bullet), so the continuous stage sweeps it.
bool tbMarkFastBody(const tbWorld* world, tbBody* body);
/// Sweep the fast bodies and move each back to its earliest time of impact.
void tbContinuousStage(tbWorld* world);
