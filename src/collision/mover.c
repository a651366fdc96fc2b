// Character movers: the stateless part of Box2D v3.2's kit for characters that the game moves
// itself (no forces, no solver): the planes a capsule touches, the motion those planes allow, and
// the velocity left after them. The world queries that feed them (tbWorld_CollideMover,
// tbWorld_CastMover) are in query.c.
//
// A mover step, as a game runs it: target = position + velocity·dt; collect the planes at the
// current position; δ = tbSolvePlanes(target − position, planes); sweep δ with tbWorld_CastMover
// and move by the fraction it allows; velocity = tbClipVector(velocity, planes). Sliding along
// walls, standing on slopes and stopping at corners all come out of the planes.
#include "core/core.h"
#include "distance_internal.h"

#include "tumble/collision.h"

/// The shape's rounding radius and a proxy of its core (no radius) in the given frame.
static float tbCoreProxy(const tbGeometry* shape, tbShapeProxy* proxy)
{
	*proxy = tbMakeShapeProxy(shape);
	float radius = proxy->radius;
	proxy->radius = 0.0f;
	return radius;
}

tbPlaneResult tbCollideMover(const tbCapsule* mover, const tbGeometry* shape, tbTransform transform)
{
	tbPlaneResult result = {{tbVec2_zero, 0.0f}, tbVec2_zero, false};
	if (mover == NULL || shape == NULL)
	{
		tbReportError("tbCollideMover", "mover and shape must not be NULL");
		return result;
	}
	// Distance between the cores (the mover's segment, the shape without its rounding): the mover
	// reaches the shape when it is within the two radii. The plane's normal points from the shape
	// to the mover; its offset is how far the mover must go along it to just touch.
	tbShapeProxy core;
	float shapeRadius = tbCoreProxy(shape, &core);
	tbVec2 centers[2] = {mover->center1, mover->center2};
	tbShapeProxy segment = tbMakeProxy(centers, 2, 0.0f);
	tbDistanceOutput output = tbShapeDistanceBetween(&core, transform, &segment, tbTransform_identity, false, NULL, NULL);
	float reach = mover->radius + shapeRadius;
	// Cores that overlap have no normal: the mover is too deep inside to be pushed out sensibly.
	if (output.distance > reach || output.distance <= 0.0f)
	{
		return result;
	}
	result.plane.normal = output.normal;
	result.plane.offset = reach - output.distance;
	result.point = tbMulAdd(output.pointA, shapeRadius, output.normal);
	result.hit = true;
	return result;
}

/// Separation of a plane after the mover moves by delta (negative: inside).
static float tbPlaneGap(tbPlane plane, tbVec2 delta)
{
	return tbDot(plane.normal, delta) - plane.offset;
}

// Each plane asks for dot(n, δ) ≥ offset − slop (a slop's overlap is allowed, so a mover resting
// on the ground keeps touching it and does not jitter in and out). A plane only pushes (push ≥ 0)
// and at most pushLimit in total. The pushes are found by projected Gauss–Seidel: each plane in turn
// corrects δ along its normal by what it still lacks, clamped in its accumulated push; corners
// (two planes at an angle) converge in a few sweeps, a sweep that moves less than the slop ends it.
tbPlaneSolverResult tbSolvePlanes(tbVec2 targetDelta, tbCollisionPlane* planes, int count)
{
	tbPlaneSolverResult result = {targetDelta, 0};
	if (count > 0 && planes == NULL)
	{
		tbReportError("tbSolvePlanes", "planes is NULL with count %d", count);
		return result;
	}
	for (int i = 0; i < count; ++i)
	{
		planes[i].push = 0.0f;
	}
	tbVec2 delta = targetDelta;
	int sweep = 0;
	for (; sweep < 20; ++sweep)
	{
		float moved = 0.0f;
		for (int i = 0; i < count; ++i)
		{
			tbCollisionPlane* p = planes + i;
			float lacking = -(tbPlaneGap(p->plane, delta) + TB_LINEAR_SLOP);
			float accumulated = tbClampFloat(p->push + lacking, 0.0f, p->pushLimit);
			float push = accumulated - p->push;
			p->push = accumulated;
			delta = tbMulAdd(delta, push, p->plane.normal);
			moved += tbAbsFloat(push);
		}
		if (moved < TB_LINEAR_SLOP)
		{
			break;
		}
	}
	result.delta = delta;
	result.iterationCount = sweep;
	return result;
}

tbVec2 tbClipVector(tbVec2 vector, const tbCollisionPlane* planes, int count)
{
	if (count > 0 && planes == NULL)
	{
		tbReportError("tbClipVector", "planes is NULL with count %d", count);
		return vector;
	}
	tbVec2 v = vector;
	for (int i = 0; i < count; ++i)
	{
		const tbCollisionPlane* p = planes + i;
		if (p->push > 0.0f && p->clipVelocity)
		{
			float into = tbMinFloat(tbDot(v, p->plane.normal), 0.0f);
			v = tbMulSub(v, into, p->plane.normal);
		}
	}
	return v;
}
