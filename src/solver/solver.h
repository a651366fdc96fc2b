// Internal: every piece of the solve stage in one include, for the stage driver (solver.c) and
// the tests. The pieces themselves include only what they use (solver_types.h and the headers
// of the pieces they call), never this header.
#pragma once

#include "constraint_graph.h"
#include "contact_solver.h"
#include "integrator.h"
#include "solver_methods.h"
#include "solver_types.h"

/// The solve stage of the step: integrate and solve the awake bodies, contacts and joints.
void tbSolveStage(tbWorld* world, float timeStep, int subStepCount);
