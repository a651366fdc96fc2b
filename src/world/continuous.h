// Internal: the continuous stage of the step: time of impact for bodies fast enough to tunnel
// (continuous.c).
#pragma once

#include "body.h"

#include <math.h>
#include <stdbool.h>

typedef struct tbWorld tbWorld;

/// tbMarkFastBody for the bodies its quick bound does not settle (continuous.c).
bool tbMarkFastBodyExactly(const tbWorld* world, tbBody* body);

/// Sets and returns body->isFast: the body moved further this step than its speculative contacts
/// cover (or is a bullet), so the continuous stage sweeps it. Inline, for the scatter's walk over
/// every awake body: most bodies turn little, and for a turn θ with cos θ ≥ 0,
/// |θ| = asin|sin θ| ≤ (π/2)·|sin θ| < 1.6·|sin θ|, so a body whose translation plus that bound on
/// its farthest point's arc stays within its reach is not fast, without the angle.
static inline bool tbMarkFastBody(const tbWorld* world, tbBody* body)
{
	float translation = tbLength(tbSubPos(body->center, body->center0));
	tbRot turn = tbInvMulRot(body->rotation0, body->transform.q);
	// fabsf rather than tbAbsFloat's comparison, a branch on the turn's sign (see tbSpeculativeMargin).
	if (body->isBullet == false && turn.c >= 0.0f &&
		translation + 1.6f * fabsf(turn.s) * body->maxExtent <= tbSpeculativeReach(body))
	{
		body->isFast = false;
		return false;
	}
	return tbMarkFastBodyExactly(world, body);
}
/// Sweep the fast bodies and move each back to its earliest time of impact.
void tbContinuousStage(tbWorld* world);
