// Internal: routines on axis-aligned boxes that are not part of the public maths (aabb.c).
#pragma once

#include "tumble/collision.h"

/// First crossing of the segment p1 → p2 into box a (the segment's radius is not handled).
/// A segment that starts inside the box, misses it or ends before it is no hit.
tbCastOutput tbAABB_RayCast(tbAABB a, tbVec2 p1, tbVec2 p2);
