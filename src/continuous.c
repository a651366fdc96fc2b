// The continuous stage: time of impact for bodies fast enough to tunnel.
//
// After the solve, a dynamic body whose motion in the step exceeds TB_CONTINUOUS_FRACTION of its
// thickness (minExtent: the smallest distance from its centre of mass to its surface), or any
// bullet, is swept from its start transform (center0, rotation0) to its end transform against
// static shapes (bullets also against non-bullet dynamic bodies, which are swept along their own
// motion). The body is moved back to the earliest time of impact; its velocity is kept, and the
// contact that the next step finds stops it (Box2D's approach: no energy is invented, some time
// is lost). A scene without fast bodies does no work here beyond one comparison per awake body.
//
// Methods: tb_continuousDefault uses the closed-form quadratic for circle pairs whose motion is
// linear and conservative advancement otherwise; tb_continuousConservative uses conservative
// advancement for every pair; tb_continuousOff skips the stage.
#include "world.h"

typedef struct tbContinuousContext
{
	tbWorld* world;
	tbBody* fastBody;
	int fastBodyId;
	tbSweep sweep;
	const tbShape* fastShape;
	tbShapeProxy fastProxy;
	float fraction; ///< earliest time of impact so far
} tbContinuousContext;

static tbSweep tbMakeBodySweep(const tbBody* body)
{
	tbSweep sweep;
	sweep.localCenter = body->localCenter;
	sweep.c1 = body->center0;
	sweep.c2 = body->center;
	sweep.q1 = body->rotation0;
	sweep.q2 = body->transform.q;
	return sweep;
}

static bool tbIsFast(const tbWorld* world, const tbBody* body, float* motion)
{
	// Largest displacement of any point of the body: translation of the centre plus the arc of
	// the farthest point.
	float translation = tbDistance(body->center, body->center0);
	float rotation = tbAbsFloat(tbRelativeAngle(body->rotation0, body->transform.q));
	*motion = translation + rotation * body->maxExtent;
	(void)world;
	return body->isBullet || *motion > TB_CONTINUOUS_FRACTION * body->minExtent;
}

/// A circle whose motion over the sweep is linear: centred on the centre of mass, or no rotation.
static bool tbIsLinearCircle(const tbShape* shape, const tbSweep* sweep)
{
	if (shape->geometry.type != tb_circleShape)
	{
		return false;
	}
	bool centred = tbDistanceSquared(shape->geometry.circle.center, sweep->localCenter) < 1e-12f;
	bool noRotation = sweep->q1.c == sweep->q2.c && sweep->q1.s == sweep->q2.s;
	return centred || noRotation;
}

static tbTOIOutput tbComputeTOI(tbContinuousContext* c, const tbShape* other, const tbSweep* otherSweep)
{
	tbWorld* world = c->world;
	bool quadratic = world->def.continuous == tb_continuousDefault && tbIsLinearCircle(c->fastShape, &c->sweep) &&
					 tbIsLinearCircle(other, otherSweep);
	world->counters.toiCalls += 1;
	if (quadratic)
	{
		return tbTimeOfImpactCircles(&other->geometry.circle, otherSweep, &c->fastShape->geometry.circle, &c->sweep,
									 c->fraction, TB_TOI_TARGET_SEPARATION);
	}
	tbTOIInput input;
	input.proxyA = tbMakeShapeProxy(&other->geometry);
	input.proxyB = c->fastProxy;
	input.sweepA = *otherSweep;
	input.sweepB = c->sweep;
	input.maxFraction = c->fraction;
	input.targetSeparation = TB_TOI_TARGET_SEPARATION;
	tbTOIOutput output = tbTimeOfImpact(&input);
	world->counters.toiIterationsMax = tbMaxInt(world->counters.toiIterationsMax, output.iterations);
	world->counters.toiFailures += output.state == tb_toiStateFailed ? 1 : 0;
	return output;
}

/// Broad-phase callback: time of impact of the fast shape against one candidate shape.
static bool tbContinuousQueryCallback(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbContinuousContext* c = context;
	tbWorld* world = c->world;
	const tbShape* other = world->shapes + shapeIndex;
	const tbBody* otherBody = world->bodies + other->bodyId;
	if (other->bodyId == c->fastBodyId || other->isSensor ||
		tbShouldShapesCollide(c->fastShape->filter, other->filter) == false)
	{
		return true;
	}
	bool againstDynamic = otherBody->type != tb_staticBody;
	if (againstDynamic && (c->fastBody->isBullet == false || otherBody->isBullet || otherBody->type != tb_dynamicBody))
	{
		return true;
	}
	tbSweep otherSweep = tbMakeBodySweep(otherBody);
	if (otherBody->awakeIndex == TB_NULL_INDEX)
	{
		otherSweep.c1 = otherSweep.c2;
		otherSweep.q1 = otherSweep.q2;
	}
	tbTOIOutput output = tbComputeTOI(c, other, &otherSweep);
	// A hit strictly inside the sweep moves the body back. Overlap at t = 0 means the shapes were
	// already touching: the solver's contact handles that case.
	if (output.state == tb_toiStateHit && output.fraction > 0.0f && output.fraction < c->fraction)
	{
		c->fraction = output.fraction;
	}
	return true;
}

static tbAABB tbSweptShapeBox(const tbShape* shape, const tbSweep* sweep)
{
	tbTransform xf1 = tbGetSweepTransform(sweep, 0.0f);
	tbTransform xf2 = tbGetSweepTransform(sweep, 1.0f);
	return tbAABB_Union(tbComputeShapeAABB(&shape->geometry, xf1), tbComputeShapeAABB(&shape->geometry, xf2));
}

static void tbSolveFastBody(tbWorld* world, int bodyId)
{
	tbBody* body = world->bodies + bodyId;
	tbContinuousContext c;
	c.world = world;
	c.fastBody = body;
	c.fastBodyId = bodyId;
	c.sweep = tbMakeBodySweep(body);
	c.fraction = 1.0f;
	// Rotation can carry points outside both end boxes by at most the arc's sagitta,
	// maxExtent·(1 − cos(Δθ/2)) ≤ maxExtent·Δθ²/8 (capped at maxExtent).
	float dTheta = tbAbsFloat(tbRelativeAngle(c.sweep.q1, c.sweep.q2));
	float pad = body->maxExtent * tbMinFloat(1.0f, dTheta * dTheta * 0.125f);
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		const tbShape* shape = world->shapes + id;
		if (shape->isSensor)
		{
			continue;
		}
		c.fastShape = shape;
		c.fastProxy = tbMakeShapeProxy(&shape->geometry);
		tbAABB box = tbAABB_Fatten(tbSweptShapeBox(shape, &c.sweep), pad + TB_LINEAR_SLOP);
		tbBroadPhase_Query(&world->broadPhase, box, shape->filter.maskBits, tbContinuousQueryCallback, &c);
	}
	if (c.fraction < 1.0f)
	{
		tbTransform xf = tbGetSweepTransform(&c.sweep, c.fraction);
		body->transform = xf;
		body->center = tbTransformPoint(xf, body->localCenter);
	}
}

void tbContinuousStage(tbWorld* world)
{
	if (world->def.continuous == tb_continuousOff)
	{
		return;
	}
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		int bodyId = world->awakeBodies[i];
		tbBody* body = world->bodies + bodyId;
		float motion;
		body->isFast = false;
		if (body->type != tb_dynamicBody || tbIsFast(world, body, &motion) == false)
		{
			continue;
		}
		body->isFast = true;
		world->counters.fastBodies += 1;
		tbSolveFastBody(world, bodyId);
	}
}
