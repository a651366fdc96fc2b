// The continuous stage: time of impact for bodies fast enough to tunnel.
//
// After the solve, a dynamic body whose motion in the step exceeds what speculative contacts cover,
// max(TB_SPECULATIVE_REACH, safetyFactor × its thickness) (minExtent: the smallest distance
// from its centre of mass to its surface; the body's safety factor, Box2D v3.2's, is
// TB_CONTINUOUS_FRACTION = 0.5 unless the game set another), or any bullet, is swept from its start transform (center0, rotation0) to its end transform against
// static shapes (bullets also against non-bullet dynamic bodies, which are swept along their own
// motion). The body is moved back to the earliest time of impact; its velocity is kept, and the
// contact that the next step finds stops it (Box2D's approach: no energy is invented, some time
// is lost). A scene without fast bodies does no work here beyond one comparison per awake body.
//
// Sensors: a fast shape that enables sensor events also notes the sensors (enabling them too) its
// sweep reaches before the impact that stops it, up to TB_MAX_SWEPT_SENSORS a shape; each such
// sensor counts the shape as a visitor for this step (Box2D v3.2's rule), so a bullet that crosses
// a trigger between two steps still begins and ends touching it (tbSensorStage).
//
// Methods: tb_continuousDefault uses the closed-form quadratic for circle pairs whose motion is
// linear and conservative advancement otherwise; tb_continuousConservative uses conservative
// advancement for every pair; tb_continuousOff skips the stage.
#include "continuous.h"

#include "world.h"

#include "core/sort.h"
#include "core/task.h"

#include <math.h>
#include <string.h>

/// Time-of-impact counters of one worker (summed into the world's after the stage).
typedef struct tbToiCounters
{
	int calls;
	int iterationsMax;
	int failures;
} tbToiCounters;

/// Sensors noted for one fast body at most: Box2D v3.2's bound.
#define TB_MAX_SWEPT_SENSORS 8

/// A sensor reached by a fast shape's sweep, and when.
typedef struct tbSweptSensor
{
	int sensor;
	int visitor;
	float fraction;
} tbSweptSensor;

typedef struct tbContinuousContext
{
	tbWorld* world;
	tbToiCounters* counters;
	tbBody* fastBody;
	int fastBodyId;
	tbPos base; ///< the frame's origin of every sweep and result (tbSweepBase)
	tbSweep sweep;
	tbTransform sweepEnd;			  ///< the sweep at 1 (tbGetSweepTransform), made once
	tbTransform sweepStart;			  ///< and at 0, made for the first candidate that asks (tbSweepStart)
	bool sweepStartMade;
	const tbShape* fastShape;
	tbShapeProxy fastProxy;
	bool fastProxyMade; ///< fastProxy holds fastShape's proxy (tbFastProxy)
	float fraction; ///< earliest time of impact so far
	bool coreHit;	///< the earliest impact came from the core sweep
	tbVec2 normal;	///< its normal, from the other shape to the fast body
	tbVec2 otherVelocity;
	tbSweptSensor* sensors; ///< TB_MAX_SWEPT_SENSORS slots
	int sensorCount;
} tbContinuousContext;

/// The origin the sweeps of one fast body are measured from. Sweeps and times of impact are float
/// arithmetic; in the large-world build the fast body's start centre is the origin, so the
/// positions they see are within a step's travel of it, and results are moved back by it. In the
/// float build positions are floats already and the origin is the world's (no extra rounding).
static tbPos tbSweepBase(const tbBody* fastBody)
{
#if defined(TUMBLE_DOUBLE_PRECISION)
	return fastBody->center0;
#else
	(void)fastBody;
	return tbPos_zero;
#endif
}

static tbSweep tbMakeBodySweep(const tbBody* body, tbPos base)
{
	tbSweep sweep;
	sweep.localCenter = body->localCenter;
	sweep.c1 = tbSubPos(body->center0, base);
	sweep.c2 = tbSubPos(body->center, base);
	sweep.q1 = body->rotation0;
	sweep.q2 = body->transform.q;
	return sweep;
}

/// The body is fast (tbMarkFastBody), for the bodies the quick bound of continuous.h left open.
static bool tbIsFast(const tbBody* body)
{
	// Largest displacement of any point of the body: translation of the centre plus the arc of
	// the farthest point.
	float translation = tbLength(tbSubPos(body->center, body->center0));
	float reach = tbSpeculativeReach(body);
	// Moving beyond its reach is fast whatever the turn: no angle needed (in a scene of flying
	// debris, smash, most fast bodies fly straight).
	if (body->isBullet == false && translation > reach)
	{
		return true;
	}
	float rotation = tbAbsFloat(tbRelativeAngle(body->rotation0, body->transform.q));
	// Speculative contacts cover a closing distance of up to the body's reach per step (contact.c,
	// shape.c); only motion beyond that can tunnel.
	return body->isBullet || translation + rotation * body->maxExtent > reach;
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

static const tbShapeProxy* tbFastProxy(tbContinuousContext* c)
{
	if (c->fastProxyMade == false)
	{
		c->fastProxy = tbMakeShapeProxy(&c->fastShape->geometry);
		c->fastProxyMade = true;
	}
	return &c->fastProxy;
}

static tbTOIOutput tbComputeTOI(tbContinuousContext* c, const tbShape* other, const tbSweep* otherSweep)
{
	tbWorld* world = c->world;
	bool quadratic = world->def.continuous == tb_continuousDefault && tbIsLinearCircle(c->fastShape, &c->sweep) &&
					 tbIsLinearCircle(other, otherSweep);
	c->counters->calls += 1;
	if (quadratic)
	{
		return tbTimeOfImpactCircles(&other->geometry.circle, otherSweep, &c->fastShape->geometry.circle, &c->sweep,
									 c->fraction, TB_TOI_TARGET_SEPARATION);
	}
	tbTOIInput input;
	input.proxyA = tbMakeShapeProxy(&other->geometry);
	input.proxyB = *tbFastProxy(c);
	input.sweepA = *otherSweep;
	input.sweepB = c->sweep;
	input.maxFraction = c->fraction;
	tbTOIOutput output = tbTimeOfImpact(&input); // to TB_TOI_TARGET_SEPARATION
	c->counters->iterationsMax = tbMaxInt(c->counters->iterationsMax, output.iterations);
	c->counters->failures += output.state == tb_toiStateFailed ? 1 : 0;
	return output;
}

/// The shapes already touch at the start of the sweep (the body was stopped there last step), so
/// the full shape cannot be advanced. The contact handles the touching features, but a fast body
/// that turns can still carry its centre through the other shape. Sweep the body's core instead:
/// a circle of half its thickness around the centre of mass, which lies inside the body. The core
/// never crosses a surface, so the body cannot pass through, though it may end partly embedded
/// (by at most its extent), which the solver then resolves. The core may itself start near the
/// surface (it was stopped there last step): its target is then half its current gap, so it can
/// still be stopped short of the surface; a core already on the surface is left to the solver.
static tbTransform tbSweepStart(tbContinuousContext* c);

static tbTOIOutput tbComputeCoreTOI(tbContinuousContext* c, const tbShape* other, const tbSweep* otherSweep)
{
	tbTOIInput input;
	input.proxyA = tbMakeShapeProxy(&other->geometry);
	input.proxyB = tbMakeProxy(&c->sweep.localCenter, 1, 0.5f * c->fastBody->minExtent);
	input.sweepA = *otherSweep;
	input.sweepB = c->sweep;
	input.maxFraction = c->fraction;
	tbDistanceInput start;
	start.proxyA = input.proxyA;
	start.proxyB = input.proxyB;
	start.transform = tbInvMulTransforms(tbGetSweepTransform(otherSweep, 0.0f), tbSweepStart(c));
	start.useRadii = true;
	float gap = tbShapeDistance(&start, NULL, NULL, 0).distance;
	tbTOIOutput output = {tb_toiStateOverlapped, 0.0f, 0, {0.0f, 0.0f}, {0.0f, 0.0f}};
	if (gap < 1e-5f)
	{
		return output;
	}
	c->counters->calls += 1;
	output = tbTimeOfImpactToTarget(&input, tbMinFloat(TB_TOI_TARGET_SEPARATION, 0.5f * gap));
	c->counters->iterationsMax = tbMaxInt(c->counters->iterationsMax, output.iterations);
	c->counters->failures += output.state == tb_toiStateFailed ? 1 : 0;
	return output;
}

/// The user's pre-continuous callback, asked when either shape enables pre-solve events.
static bool tbAllowedByPreContinuous(tbWorld* world, const tbShape* other, const tbShape* fastShape,
									 const tbTOIOutput* output, tbPos base)
{
	if (world->preContinuousFcn == NULL || (other->enablePreSolveEvents == false && fastShape->enablePreSolveEvents == false))
	{
		return true;
	}
	return world->preContinuousFcn(tbMakeShapeId(world, (int)(other - world->shapes)),
								   tbMakeShapeId(world, (int)(fastShape - world->shapes)), tbOffsetPos(base, output->point),
								   output->normal, world->preSolveContext);
}

/// A point inside a shape (its centroid), in its body's frame.
static tbVec2 tbShapeCentroid(const tbGeometry* g)
{
	switch (g->type)
	{
		case tb_circleShape:
			return g->circle.center;
		case tb_capsuleShape:
			return tbLerp(g->capsule.center1, g->capsule.center2, 0.5f);
		case tb_polygonShape:
			return g->polygon.centroid;
		default:
			return tbLerp(g->segment.point1, g->segment.point2, 0.5f);
	}
}

/// Chain segments need no sweep in two cases. They are one-sided: a fast shape whose centroid
/// starts behind one (on its solid side) passes through, as the narrow phase lets it. And a shape
/// sliding fast along a chain (a ball round a loop, a character down a slope) approaches the
/// segments ahead by less than its core while staying clear of them: the speculative contacts
/// hold it, and a sweep would stop it at each segment it comes within TB_TOI_TARGET_SEPARATION of.
/// So the sweep runs only when the centroid closes on the segment's line by at least the core
/// radius (half the body's thickness, tbComputeCoreTOI's) or ends within it.
/// The sweep at 0, made once, for the first candidate that needs it (most fast bodies meet none:
/// their swept boxes come from the shapes' boxes and the sweep's end).
static tbTransform tbSweepStart(tbContinuousContext* c)
{
	if (c->sweepStartMade == false)
	{
		c->sweepStart = tbGetSweepTransform(&c->sweep, 0.0f);
		c->sweepStartMade = true;
	}
	return c->sweepStart;
}

static bool tbSkipChainSweep(tbContinuousContext* c, const tbShape* other, const tbBody* otherBody)
{
	if (other->geometry.type != tb_chainSegmentShape)
	{
		return false;
	}
	const tbSegment* segment = &other->geometry.chainSegment.segment;
	tbVec2 e = tbNormalize(tbSub(segment->point2, segment->point1));
	tbVec2 centroid = tbShapeCentroid(&c->fastShape->geometry);
	tbTransform xfOther = tbToRelativeTransform(otherBody->transform, c->base);
	tbVec2 c1 = tbInvTransformPoint(xfOther, tbTransformPoint(tbSweepStart(c), centroid));
	tbVec2 c2 = tbInvTransformPoint(xfOther, tbTransformPoint(c->sweepEnd, centroid));
	float separation1 = tbCross(tbSub(c1, segment->point1), e); // > 0 in front (right of the direction)
	float separation2 = tbCross(tbSub(c2, segment->point1), e);
	float core = 0.5f * c->fastBody->minExtent;
	return separation1 < 0.0f || (separation1 - separation2 < core && separation2 > core);
}

/// Time of impact of the fast shape against one candidate shape; an earlier impact narrows the sweep
/// (c->fraction) for the candidates after it.
static void tbSweepCandidate(tbContinuousContext* c, int shapeIndex)
{
	tbWorld* world = c->world;
	const tbShape* other = world->shapes + shapeIndex;
	const tbBody* otherBody = world->bodies + other->bodyId;
	bool sensor = other->isSensor;
	if (other->bodyId == c->fastBodyId || tbShouldShapesCollide(c->fastShape->filter, other->filter) == false ||
		(sensor && (other->enableSensorEvents == false || c->fastShape->enableSensorEvents == false ||
					c->sensorCount == TB_MAX_SWEPT_SENSORS)))
	{
		return;
	}
	// Non-bullets stop only at static shapes; bullets also at dynamic and kinematic bodies (a
	// moving kinematic wall, a door or a lift, is swept along its own motion), not at other bullets.
	bool againstMoving = otherBody->type != tb_staticBody;
	if (againstMoving && (c->fastBody->isBullet == false || otherBody->isBullet))
	{
		return;
	}
	if ((other->enableCustomFiltering || c->fastShape->enableCustomFiltering) && world->customFilterFcn != NULL &&
		world->customFilterFcn(tbMakeShapeId(world, shapeIndex), tbMakeShapeId(world, (int)(c->fastShape - world->shapes)),
							   world->customFilterContext) == false)
	{
		return; // the custom filter keeps them apart: no contact, no sweep either
	}
	if (sensor == false && tbSkipChainSweep(c, other, otherBody))
	{
		return;
	}
	tbSweep otherSweep = tbMakeBodySweep(otherBody, c->base);
	if (otherBody->awakeIndex == TB_NULL_INDEX)
	{
		otherSweep.c1 = otherSweep.c2;
		otherSweep.q1 = otherSweep.q2;
	}
	tbTOIOutput output = tbComputeTOI(c, other, &otherSweep);
	if (sensor)
	{
		// Kept if reached before the impact found so far; the body's final impact filters again.
		if (output.state == tb_toiStateOverlapped || (output.state == tb_toiStateHit && output.fraction < c->fraction))
		{
			float fraction = output.state == tb_toiStateOverlapped ? 0.0f : output.fraction;
			c->sensors[c->sensorCount++] = (tbSweptSensor){shapeIndex, (int)(c->fastShape - world->shapes), fraction};
		}
		return;
	}
	bool core = false;
	if (output.state == tb_toiStateOverlapped || (output.state == tb_toiStateHit && output.fraction == 0.0f))
	{
		output = tbComputeCoreTOI(c, other, &otherSweep);
		core = true;
	}
	// A hit strictly inside the sweep moves the body back, unless the pre-continuous callback
	// lets the body pass (a one-way platform).
	if (output.state == tb_toiStateHit && output.fraction > 0.0f && output.fraction < c->fraction &&
		tbAllowedByPreContinuous(world, other, c->fastShape, &output, c->base))
	{
		c->fraction = output.fraction;
		c->coreHit = core;
		c->normal = output.normal;
		c->otherVelocity = otherBody->awakeIndex != TB_NULL_INDEX ? otherBody->linearVelocity : tbVec2_zero;
	}
}

/// The candidates of one fast shape's sweep. The broad-phase methods report them each in an order of
/// its own, and each candidate's time of impact is sought only up to the earliest found before it,
/// which decides between near-equal impacts: visited in the order reported, the sweep's outcome
/// would depend on the broad-phase method (and on when `auto` switches). Gathered first, then
/// visited in shape order, it does not.
#define TB_LOCAL_CANDIDATES 64

typedef struct tbCandidates
{
	int* ids;
	int count;
	int capacity;
	int local[TB_LOCAL_CANDIDATES];
} tbCandidates;

static bool tbGatherCandidate(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbCandidates* list = context;
	if (list->count == list->capacity)
	{
		int capacity = 2 * list->capacity;
		int* ids = tbAlloc(capacity * (int)sizeof(int));
		memcpy(ids, list->ids, (size_t)list->count * sizeof(int));
		if (list->ids != list->local)
		{
			tbFree(list->ids, list->capacity * (int)sizeof(int));
		}
		list->ids = ids;
		list->capacity = capacity;
	}
	list->ids[list->count++] = shapeIndex;
	return true;
}

/// The gathered candidates in ascending shape order, each once: insertion sort for the few a sweep
/// usually meets, the radix sort beyond.
static void tbSortCandidates(tbCandidates* list)
{
	int* ids = list->ids;
	if (list->count <= TB_LOCAL_CANDIDATES)
	{
		for (int i = 1; i < list->count; ++i)
		{
			int id = ids[i], j = i;
			for (; j > 0 && ids[j - 1] > id; --j)
			{
				ids[j] = ids[j - 1];
			}
			ids[j] = id;
		}
	}
	else
	{
		int* scratch = tbAlloc(list->count * (int)sizeof(int));
		tbSortIndices(ids, list->count, scratch);
		tbFree(scratch, list->count * (int)sizeof(int));
	}
	int kept = 0;
	for (int i = 0; i < list->count; ++i)
	{
		if (kept == 0 || ids[kept - 1] != ids[i])
		{
			ids[kept++] = ids[i];
		}
	}
	list->count = kept;
}

/// The world box of the shape over the sweep's two ends xf1 and xf2 (measured from base).
/// The box of a shape over its sweep's ends. The start is where the body began the step, where the
/// last finalize (or a teleport since: tbBody_SetTransform refreshes the boxes) left the shape's
/// tight box: only the end is computed.
static tbAABB tbSweptShapeBox(const tbShape* shape, tbTransform xf2, tbPos base)
{
	tbWorldTransform end = {tbOffsetPos(base, xf2.p), xf2.q};
	return tbAABB_Union(shape->aabb, tbComputeShapeAABB(&shape->geometry, end));
}

/// The core hit while the body was already touching: the contact points the solver saw did not
/// cover the part that is closing (it was beyond the speculative distance), so without help the
/// body would be pinned here step after step with its velocity intact. Stop the core's approach
/// along the normal, a perfectly inelastic impact of the centre of mass: energy is removed, never
/// added (restitution is not applied on this rare path).
static void tbStopCoreApproach(tbBody* body, tbVec2 normal, tbVec2 otherVelocity)
{
	float vn = tbDot(tbSub(body->linearVelocity, otherVelocity), normal);
	if (vn < 0.0f)
	{
		body->linearVelocity = tbMulSub(body->linearVelocity, vn, normal);
	}
}

/// Sweep one fast body and move it back to its earliest impact. Returns how many sensors it reached
/// before that impact, written to `sensors` (TB_MAX_SWEPT_SENSORS slots), in the order found.
static int tbSolveFastBody(tbWorld* world, int bodyId, tbToiCounters* counters, tbSweptSensor* sensors)
{
	tbBody* body = world->bodies + bodyId;
	tbContinuousContext c;
	c.sensors = sensors;
	c.sensorCount = 0;
	c.world = world;
	c.counters = counters;
	c.fastBody = body;
	c.fastBodyId = bodyId;
	c.base = tbSweepBase(body);
	c.sweep = tbMakeBodySweep(body, c.base);
	// Each shape's box and each chain candidate ask for the sweep's end: computed once here.
	c.sweepEnd = tbGetSweepTransform(&c.sweep, 1.0f);
	c.sweepStartMade = false;
	c.fraction = 1.0f;
	c.coreHit = false;
	// Rotation can carry points outside both end boxes by at most the arc's sagitta,
	// maxExtent·(1 − cos(Δθ/2)) (shape.c), for a turn of at most half a turn. From cos Δθ = q1·q2
	// and cos(Δθ/2) = √((1 + cos Δθ)/2): 1 − cos(Δθ/2) = (1 − cos Δθ)/(2·(1 + cos(Δθ/2))), with no
	// angle computed (no atan2 per fast body, of which a scene of flying debris has thousands).
	float cosTurn = tbClampFloat(c.sweep.q1.c * c.sweep.q2.c + c.sweep.q1.s * c.sweep.q2.s, -1.0f, 1.0f);
	float cosHalf = sqrtf(0.5f * (1.0f + cosTurn));
	float pad = body->maxExtent * (1.0f - cosTurn) / (2.0f * (1.0f + cosHalf));
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		const tbShape* shape = world->shapes + id;
		if (shape->isSensor)
		{
			continue;
		}
		c.fastShape = shape;
		c.fastProxyMade = false; // made for the first candidate (most fast bodies meet none)
		tbAABB box = tbAABB_Fatten(tbSweptShapeBox(shape, c.sweepEnd, c.base), pad + TB_LINEAR_SLOP);
		tbCandidates candidates;
		candidates.ids = candidates.local;
		candidates.count = 0;
		candidates.capacity = TB_LOCAL_CANDIDATES;
		if (body->isBullet)
		{
			tbBroadPhase_Query(&world->broadPhase, box, shape->filter.maskBits, tbGatherCandidate, &candidates);
		}
		else
		{
			// A non-bullet stops only at static shapes: the movable proxies (the whole moving
			// pile, in a scene like the spinner) need not be visited at all.
			tbBroadPhase_QueryStatic(&world->broadPhase, box, shape->filter.maskBits, tbGatherCandidate, &candidates);
		}
		tbSortCandidates(&candidates);
		for (int k = 0; k < candidates.count; ++k)
		{
			tbSweepCandidate(&c, candidates.ids[k]);
		}
		if (candidates.ids != candidates.local)
		{
			tbFree(candidates.ids, candidates.capacity * (int)sizeof(int));
		}
	}
	if (c.fraction < 1.0f)
	{
		tbTransform xf = tbGetSweepTransform(&c.sweep, c.fraction);
		body->transform.p = tbOffsetPos(c.base, xf.p);
		body->transform.q = xf.q;
		body->center = tbTransformWorldPoint(body->transform, body->localCenter);
		if (c.coreHit)
		{
			tbStopCoreApproach(body, c.normal, c.otherVelocity);
		}
	}
	int kept = 0;
	for (int i = 0; i < c.sensorCount; ++i)
	{
		if (sensors[i].fraction < c.fraction)
		{
			sensors[kept++] = sensors[i];
		}
	}
	return kept;
}

typedef struct tbContinuousTaskContext
{
	tbWorld* world;
	const int* bodies;
	tbSweptSensor* sensors; ///< TB_MAX_SWEPT_SENSORS slots per entry of `bodies`
	int* sensorCounts;		///< per entry of `bodies`
	tbToiCounters counters[TB_MAX_WORKERS]; ///< per worker slot (tbWorkerSlotCount, task.h)
} tbContinuousTaskContext;

static void tbContinuousTask(int start, int end, uint32_t workerIndex, void* context)
{
	tbContinuousTaskContext* task = context;
	for (int i = start; i < end; ++i)
	{
		task->sensorCounts[i] = tbSolveFastBody(task->world, task->bodies[i], task->counters + workerIndex,
												task->sensors + TB_MAX_SWEPT_SENSORS * i);
	}
}

/// The sensors the fast bodies reached, in the order the bodies were listed (the same on any
/// number of workers), each marked on its pair's contact for the sensor stage (tbMarkSensorHit).
static void tbNoteSweptSensors(tbWorld* world, const tbSweptSensor* sensors, const int* counts, int total)
{
	int hitCount = 0;
	for (int i = 0; i < total; ++i)
	{
		hitCount += counts[i];
	}
	if (hitCount == 0)
	{
		return;
	}
	uint64_t ticks = tbGetTicks();
	int* contacts = tbArenaAlloc(&world->stepArena, hitCount * (int)sizeof(int));
	int contactCount = 0;
	for (int i = 0; i < total; ++i)
	{
		for (int k = 0; k < counts[i]; ++k)
		{
			const tbSweptSensor* hit = sensors + TB_MAX_SWEPT_SENSORS * i + k;
			int contactId = tbMarkSensorHit(world, hit->sensor, hit->visitor);
			if (contactId != TB_NULL_INDEX)
			{
				contacts[contactCount++] = contactId;
			}
		}
	}
	world->cache.sensorHitContacts = contacts;
	world->cache.sensorHitCount = contactCount;
	world->profile.sensorHits = tbGetMilliseconds(ticks);
}

bool tbMarkFastBodyExactly(const tbWorld* world, tbBody* body)
{
	(void)world;
	body->isFast = body->type == tb_dynamicBody && tbIsFast(body);
	return body->isFast;
}

/// isFast of awake bodies [start, end) (each writes its own body).
static void tbMarkFastTask(int start, int end, uint32_t workerIndex, void* context)
{
	(void)workerIndex;
	tbWorld* world = context;
	for (int i = start; i < end; ++i)
	{
		tbMarkFastBody(world, world->bodies + world->awakeBodies[i]);
	}
}

/// Fast bodies that are not bullets stop only at static shapes, which do not move: each depends on
/// nothing the others change, so they run on the workers. Bullets also stop at moving bodies (at
/// their positions after the others were stopped) and run after, one at a time in body order.
void tbContinuousStage(tbWorld* world)
{
	if (world->def.continuous == tb_continuousOff)
	{
		return;
	}
	// The solve's scatter marks the bodies it moves (tbMarkFastBody, while each body is in cache, as
	// Box2D v3 does in its finalize): a step in which none is fast walks nothing here, where it would
	// walk every awake body (a settled pile pays nothing). A step without a solve (time step 0) marks
	// here.
	bool marked = world->cache.fastMarkedStep == world->stepIndex;
	if (marked && world->cache.fastMarkedCount == 0)
	{
		return;
	}
	int bytes = world->awakeBodyCount * (int)sizeof(int);
	int* fast = tbArenaAlloc(&world->stepArena, bytes > 0 ? bytes : (int)sizeof(int));
	int fastCount = 0, bulletCount = 0;
	bool onWorkers = tbWorkerCount(&world->def) > 1;
	if (onWorkers && marked == false)
	{
		tbParallelFor(&world->def, tbMarkFastTask, world->awakeBodyCount, 512, world); // then listed below
	}
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		int bodyId = world->awakeBodies[i];
		tbBody* body = world->bodies + bodyId;
		if (onWorkers == false && marked == false)
		{
			tbMarkFastBody(world, body);
		}
		if (body->isFast && body->isBullet)
		{
			fast[world->awakeBodyCount - 1 - bulletCount++] = bodyId; // bullets from the back, reversed
		}
		else if (body->isFast)
		{
			fast[fastCount++] = bodyId;
		}
	}
	world->counters.fastBodies += fastCount + bulletCount;
	if (world->staticProxyCount == 0)
	{
		fastCount = 0; // non-bullets stop only at static shapes, and there are none (smash)
	}
	tbContinuousTaskContext* task = tbArenaAlloc(&world->stepArena, (int)sizeof(tbContinuousTaskContext));
	memset(task, 0, sizeof(*task));
	task->world = world;
	task->bodies = fast;
	// Swept sensors: the non-bullets' slots first, then the bullets', in the order they are solved.
	int total = fastCount + bulletCount;
	task->sensorCounts = tbArenaAlloc(&world->stepArena, tbMaxInt(total, 1) * (int)sizeof(int));
	task->sensors = tbArenaAlloc(&world->stepArena, tbMaxInt(total, 1) * TB_MAX_SWEPT_SENSORS * (int)sizeof(tbSweptSensor));
	tbParallelFor(&world->def, tbContinuousTask, fastCount, 16, task);
	if (bulletCount > 0)
	{
		uint64_t bulletTicks = tbGetTicks();
		for (int i = 0; i < bulletCount; ++i)
		{
			int slot = fastCount + i;
			task->sensorCounts[slot] = tbSolveFastBody(world, fast[world->awakeBodyCount - 1 - i], task->counters,
													   task->sensors + TB_MAX_SWEPT_SENSORS * slot);
		}
		world->profile.bullets = tbGetMilliseconds(bulletTicks); // a part of the continuous stage
	}
	tbNoteSweptSensors(world, task->sensors, task->sensorCounts, total);
	for (int w = 0; w < tbWorkerSlotCount(&world->def); ++w)
	{
		world->counters.toiCalls += task->counters[w].calls;
		world->counters.toiIterationsMax = tbMaxInt(world->counters.toiIterationsMax, task->counters[w].iterationsMax);
		world->counters.toiFailures += task->counters[w].failures;
	}
}
