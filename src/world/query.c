// World queries: AABB overlap, point, shape overlap, ray casts and shape casts. All go through
// the broad phase and respect the query filter (category of the query against the shape's mask
// and the shape's category against the query's mask).
#include "recording.h"
#include "world.h"

#include "collision/distance_internal.h"

#include <string.h>

static bool tbQueryFilterAccepts(tbQueryFilter filter, const tbShape* shape)
{
	return (shape->filter.categoryBits & filter.maskBits) != 0 && (shape->filter.maskBits & filter.categoryBits) != 0;
}

typedef struct tbQueryContext
{
	tbWorld* world;
	tbQueryFilter filter;
	tbOverlapResultFcn* fcn;
	void* userContext;
	// point and shape queries; ray casts
	tbPos point; ///< the point of a point query, the origin of a ray
	tbPos base;	 ///< shape queries and casts: the origin their shape is measured from
	tbShapeProxy proxy; ///< shape queries and casts: the query shape, its points measured from base
	// casts
	tbCastResultFcn* castFcn;
	tbVec2 translation;
	float maxFraction;
	tbQueryLog* log; ///< the query's record while the world records, else NULL
} tbQueryContext;

static bool tbAABBQueryCallback(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbQueryContext* q = context;
	const tbShape* shape = q->world->shapes + shapeIndex;
	if (tbQueryFilterAccepts(q->filter, shape) == false)
	{
		return true;
	}
	tbShapeId id = tbMakeShapeId(q->world, shapeIndex);
	tbQueryLogHit(q->log, id, q->point, tbVec2_zero, 0.0f);
	return q->fcn(id, q->userContext);
}

/// While a query calls back, a callback that created or destroyed a body or shape, moved one
/// (SetTransform, SetType) or changed a filter would free or move the broad-phase nodes the query
/// is walking: such calls are refused with an error (tbStructureLocked); collect ids in the callback
/// and make those changes after the query. Velocities, impulses, materials and awake state may be
/// changed inside (an explosion applies its impulses from the callback). Queries nest.
static void tbEnterQuery(tbWorld* world)
{
	world->queryDepth += 1;
}

static void tbLeaveQuery(tbWorld* world)
{
	world->queryDepth -= 1;
}

static bool tbCheckQueryWorld(tbWorld* world, const char* f, bool hasFcn)
{
	if (world != NULL && hasFcn == false)
	{
		tbReportError(f, "fcn is NULL; pass a result callback");
	}
	return world != NULL && hasFcn;
}

// A query shape (tbShapeProxy, measured from the query's origin): 1 to TB_MAX_POLYGON_VERTICES
// points within TB_MAX_COORDINATE of the origin (the collision layer's answers are defined there)
// and a radius in [0, TB_MAX_COORDINATE]; and the origin itself a valid position.
static bool tbCheckQueryShape(const char* f, tbPos origin, const tbShapeProxy* proxy)
{
	if (tbCheckPosition(f, "origin", origin) == false || tbCheckPointer(f, "proxy", proxy) == false)
	{
		return false;
	}
	if (proxy->count < 1 || proxy->count > TB_MAX_POLYGON_VERTICES)
	{
		tbReportError(f, "proxy->count is %d; a proxy has 1 to %d points (make it with tbMakeProxy)", proxy->count,
					  TB_MAX_POLYGON_VERTICES);
		return false;
	}
	return tbCheckPoints(f, "proxy->points", proxy->points, proxy->count) &&
		   tbCheckLength(f, "proxy->radius", proxy->radius, false);
}

/// The proxy's box, grown by its radius and placed at the origin.
static tbAABB tbProxyBox(tbPos origin, const tbShapeProxy* proxy)
{
	return tbOffsetAABB(tbMakeAABB(proxy->points, proxy->count, proxy->radius), origin);
}

/// The record of a query while the world records (recording_queries.c), else NULL: its kind and
/// inputs as tbRecPlayer_GetFrameQuery tells them (the box relative to the origin).
static tbQueryLog* tbLogQuery(tbQueryLog* log, const tbWorld* world, tbRecQueryType type, tbQueryFilter filter,
							  tbPos origin, tbAABB box, tbVec2 translation)
{
	tbRecQueryInfo info;
	memset(&info, 0, sizeof(info));
	info.type = type;
	info.filter = filter;
	info.aabb = box;
	info.origin = origin;
	info.translation = translation;
	return tbQueryLogBegin(log, world, &info);
}

static tbAABB tbCapsuleBox(const tbCapsule* c)
{
	tbVec2 r = {c->radius, c->radius};
	return (tbAABB){tbSub(tbMin(c->center1, c->center2), r), tbAdd(tbMax(c->center1, c->center2), r)};
}

static tbQueryContext tbMakeQueryContext(tbWorld* world, tbQueryFilter filter, void* userContext)
{
	tbQueryContext q;
	memset(&q, 0, sizeof(q));
	q.world = world;
	q.filter = filter;
	q.userContext = userContext;
	q.maxFraction = 1.0f;
	return q;
}

tbTreeStats tbWorld_OverlapAABB(tbWorldId worldId, tbPos origin, tbAABB aabb, tbQueryFilter filter, tbOverlapResultFcn* fcn,
						 void* context)
{
	const char* f = "tbWorld_OverlapAABB";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (tbCheckQueryWorld(world, f, fcn != NULL) == false || tbCheckPosition(f, "origin", origin) == false)
	{
		return (tbTreeStats){0, 0};
	}
	if (tbIsValidAABB(aabb) == false)
	{
		tbReportError(f, "aabb is not finite or has lowerBound > upperBound; pass a valid box");
		return (tbTreeStats){0, 0};
	}
	tbQueryContext q = tbMakeQueryContext(world, filter, context);
	q.fcn = fcn;
	q.point = origin; // what the record gives as each result's point
	tbQueryLog log;
	q.log = tbLogQuery(&log, world, tb_recQueryOverlapAABB, filter, origin, aabb, tbVec2_zero);
	tbEnterQuery(world);
	tbTreeStats stats = tbBroadPhase_Query(&world->broadPhase, tbOffsetAABB(aabb, origin), filter.maskBits, tbAABBQueryCallback, &q);
	tbLeaveQuery(world);
	tbQueryLogEnd(q.log);
	return stats;
}

static bool tbPointQueryCallback(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbQueryContext* q = context;
	const tbShape* shape = q->world->shapes + shapeIndex;
	if (tbQueryFilterAccepts(q->filter, shape) == false)
	{
		return true;
	}
	tbVec2 local = tbInvTransformWorldPoint(q->world->bodies[shape->bodyId].transform, q->point);
	if (tbPointInShape(&shape->geometry, local) == false)
	{
		return true;
	}
	tbShapeId id = tbMakeShapeId(q->world, shapeIndex);
	tbQueryLogHit(q->log, id, q->point, tbVec2_zero, 0.0f);
	return q->fcn(id, q->userContext);
}

bool tbWorld_OverlapPoint(tbWorldId worldId, tbPos point, tbQueryFilter filter, tbOverlapResultFcn* fcn, void* context)
{
	const char* f = "tbWorld_OverlapPoint";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (tbCheckQueryWorld(world, f, fcn != NULL) == false || tbCheckFinitePosition(f, "point", point) == false)
	{
		return false;
	}
	tbQueryContext q = tbMakeQueryContext(world, filter, context);
	q.fcn = fcn;
	q.point = point;
	tbAABB box = tbOffsetAABB((tbAABB){tbVec2_zero, tbVec2_zero}, point); // contains the point
	tbQueryLog log; // recorded as the overlap of an empty box at the point (Box2D v3.2 has no point query)
	q.log = tbLogQuery(&log, world, tb_recQueryOverlapAABB, filter, point, (tbAABB){tbVec2_zero, tbVec2_zero},
					   tbVec2_zero);
	tbEnterQuery(world);
	tbBroadPhase_Query(&world->broadPhase, box, filter.maskBits, tbPointQueryCallback, &q);
	tbLeaveQuery(world);
	tbQueryLogEnd(q.log);
	return true;
}

static bool tbShapeQueryCallback(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbQueryContext* q = context;
	const tbShape* shape = q->world->shapes + shapeIndex;
	if (tbQueryFilterAccepts(q->filter, shape) == false)
	{
		return true;
	}
	tbDistanceInput input;
	input.proxyA = tbMakeShapeProxy(&shape->geometry);
	input.proxyB = q->proxy;
	tbWorldTransform frame = {q->base, tbRot_identity};
	input.transform = tbInvMulWorldTransforms(q->world->bodies[shape->bodyId].transform, frame);
	input.useRadii = true;
	tbDistanceOutput output = tbShapeDistance(&input, NULL, NULL, 0);
	if (output.distance > 0.0f)
	{
		return true;
	}
	tbShapeId id = tbMakeShapeId(q->world, shapeIndex);
	tbQueryLogHit(q->log, id, q->base, tbVec2_zero, 0.0f);
	return q->fcn(id, q->userContext);
}

tbTreeStats tbWorld_OverlapShape(tbWorldId worldId, tbPos origin, const tbShapeProxy* proxy, tbQueryFilter filter,
						  tbOverlapResultFcn* fcn, void* context)
{
	const char* f = "tbWorld_OverlapShape";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (tbCheckQueryWorld(world, f, fcn != NULL) == false || tbCheckQueryShape(f, origin, proxy) == false)
	{
		return (tbTreeStats){0, 0};
	}
	tbQueryContext q = tbMakeQueryContext(world, filter, context);
	q.fcn = fcn;
	q.proxy = *proxy;
	q.base = origin;
	tbQueryLog log;
	tbAABB box = tbMakeAABB(proxy->points, proxy->count, proxy->radius);
	q.log = tbLogQuery(&log, world, tb_recQueryOverlapShape, filter, origin, box, tbVec2_zero);
	tbEnterQuery(world);
	tbTreeStats stats = tbBroadPhase_Query(&world->broadPhase, tbProxyBox(origin, proxy), filter.maskBits, tbShapeQueryCallback, &q);
	tbLeaveQuery(world);
	tbQueryLogEnd(q.log);
	return stats;
}

static float tbRayCastCallback(const tbRayCastInput* input, int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbQueryContext* q = context;
	const tbShape* shape = q->world->shapes + shapeIndex;
	if (tbQueryFilterAccepts(q->filter, shape) == false)
	{
		return input->maxFraction;
	}
	tbWorldTransform xf = q->world->bodies[shape->bodyId].transform;
	tbRayCastInput local = *input;
	local.origin = tbInvTransformWorldPoint(xf, q->point);
	local.translation = tbInvRotateVector(xf.q, input->translation);
	tbCastOutput output = tbRayCastShape(&shape->geometry, &local);
	if (output.hit == false)
	{
		return input->maxFraction;
	}
	tbPos point = tbTransformWorldPoint(xf, output.point);
	tbVec2 normal = tbRotateVector(xf.q, output.normal);
	tbShapeId id = tbMakeShapeId(q->world, shapeIndex);
	tbQueryLogHit(q->log, id, point, normal, output.fraction);
	float result = q->castFcn(id, point, normal, output.fraction, q->userContext);
	// −1 ignores this shape: keep the current clip.
	return result < 0.0f ? input->maxFraction : result;
}

// The collision layer answers for shapes and placements within TB_MAX_COORDINATE: a ray origin
// beyond it is refused. A translation may have any finite length.
static bool tbCheckWorldRay(const char* f, tbPos origin, tbVec2 translation)
{
	return tbCheckPosition(f, "origin", origin) && tbCheckVec2(f, "translation", translation);
}

/// tbWorld_CastRay, recorded as a query of kind `type` (a ray or the closest hit of one).
static tbTreeStats tbCastRay(tbWorldId worldId, tbPos origin, tbVec2 translation, tbQueryFilter filter,
							 tbCastResultFcn* fcn, void* context, tbRecQueryType type)
{
	const char* f = "tbWorld_CastRay";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (tbCheckQueryWorld(world, f, fcn != NULL) == false || tbCheckWorldRay(f, origin, translation) == false)
	{
		return (tbTreeStats){0, 0};
	}
	tbQueryContext q = tbMakeQueryContext(world, filter, context);
	q.castFcn = fcn;
	q.point = origin; // each shape is hit from the exact origin; the broad phase walks a float one
	tbRayCastInput input = {tbToVec2(origin), translation, 1.0f};
	tbQueryLog log;
	q.log = tbLogQuery(&log, world, type, filter, origin, (tbAABB){tbVec2_zero, tbVec2_zero}, translation);
	tbEnterQuery(world);
	tbTreeStats stats = tbBroadPhase_RayCast(&world->broadPhase, &input, filter.maskBits, tbRayCastCallback, &q);
	tbLeaveQuery(world);
	tbQueryLogEnd(q.log);
	return stats;
}

tbTreeStats tbWorld_CastRay(tbWorldId worldId, tbPos origin, tbVec2 translation, tbQueryFilter filter,
							tbCastResultFcn* fcn, void* context)
{
	return tbCastRay(worldId, origin, translation, filter, fcn, context, tb_recQueryCastRay);
}

static float tbClosestCallback(tbShapeId shapeId, tbPos point, tbVec2 normal, float fraction, void* context)
{
	tbRayResult* result = context;
	result->shapeId = shapeId;
	result->point = point;
	result->normal = normal;
	result->fraction = fraction;
	result->hit = true;
	return fraction;
}

tbRayResult tbWorld_CastRayClosest(tbWorldId worldId, tbPos origin, tbVec2 translation, tbQueryFilter filter)
{
	tbRayResult result;
	memset(&result, 0, sizeof(result));
	tbTreeStats stats =
		tbCastRay(worldId, origin, translation, filter, tbClosestCallback, &result, tb_recQueryCastRayClosest);
	result.nodeVisits = stats.nodeVisits;
	result.leafVisits = stats.leafVisits;
	return result;
}

/// Shape cast candidate: cast against one shape, report, and clip later casts by the result.
static bool tbShapeCastCallback(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbQueryContext* q = context;
	const tbShape* shape = q->world->shapes + shapeIndex;
	if (tbQueryFilterAccepts(q->filter, shape) == false)
	{
		return true;
	}
	tbShapeProxy proxyA = tbMakeShapeProxy(&shape->geometry);
	tbTransform xfA = tbToRelativeTransform(q->world->bodies[shape->bodyId].transform, q->base);
	tbCastOutput output =
		tbShapeCastBetween(&proxyA, xfA, &q->proxy, tbTransform_identity, q->translation, q->maxFraction, false);
	if (output.hit == false)
	{
		return true;
	}
	tbShapeId id = tbMakeShapeId(q->world, shapeIndex);
	tbPos point = tbOffsetPos(q->base, output.point);
	tbQueryLogHit(q->log, id, point, output.normal, output.fraction);
	float result = q->castFcn(id, point, output.normal, output.fraction, q->userContext);
	if (result == 0.0f)
	{
		return false;
	}
	if (result > 0.0f && result < q->maxFraction)
	{
		q->maxFraction = result;
	}
	return true;
}

tbTreeStats tbWorld_CastShape(tbWorldId worldId, tbPos origin, const tbShapeProxy* proxy, tbVec2 translation,
					   tbQueryFilter filter, tbCastResultFcn* fcn, void* context)
{
	const char* f = "tbWorld_CastShape";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (tbCheckQueryWorld(world, f, fcn != NULL) == false || tbCheckQueryShape(f, origin, proxy) == false ||
		tbCheckVec2(f, "translation", translation) == false)
	{
		return (tbTreeStats){0, 0};
	}
	tbQueryContext q = tbMakeQueryContext(world, filter, context);
	q.castFcn = fcn;
	q.proxy = *proxy;
	q.base = origin;
	q.translation = translation;
	q.maxFraction = 1.0f;
	// Candidates: shapes whose boxes overlap the shape's box swept over the translation.
	tbAABB box = tbProxyBox(origin, proxy);
	tbAABB moved = {tbAdd(box.lowerBound, translation), tbAdd(box.upperBound, translation)};
	tbQueryLog log;
	tbAABB shapeBox = tbMakeAABB(proxy->points, proxy->count, proxy->radius);
	q.log = tbLogQuery(&log, world, tb_recQueryCastShape, filter, origin, shapeBox, translation);
	tbEnterQuery(world);
	tbTreeStats stats = tbBroadPhase_Query(&world->broadPhase, tbAABB_Union(box, moved), filter.maskBits, tbShapeCastCallback, &q);
	tbLeaveQuery(world);
	tbQueryLogEnd(q.log);
	return stats;
}

// --- Character movers (mover.c has the planes and their solver) ------------------------------

/// A mover's capsule: finite, radius above twice the linear slop (the plane solver's tolerance).
static bool tbCheckMover(const char* f, tbPos origin, const tbCapsule* mover)
{
	if (tbCheckPointer(f, "mover", mover) == false || tbCheckPosition(f, "origin", origin) == false ||
		tbCheckVec2(f, "mover->center1", mover->center1) == false ||
		tbCheckVec2(f, "mover->center2", mover->center2) == false)
	{
		return false;
	}
	if (tbIsValidFloat(mover->radius) == false || mover->radius <= 2.0f * TB_LINEAR_SLOP)
	{
		tbReportError(f, "mover->radius is %g; it must be finite and > %g m (twice the linear slop)",
					  (double)mover->radius, (double)(2.0f * TB_LINEAR_SLOP));
		return false;
	}
	return true;
}

/// The capsule's box, relative to the origin, placed in the world.
static tbAABB tbMoverBox(tbPos origin, const tbCapsule* mover)
{
	tbVec2 r = {mover->radius, mover->radius};
	tbAABB box = {tbSub(tbMin(mover->center1, mover->center2), r), tbAdd(tbMax(mover->center1, mover->center2), r)};
	return tbOffsetAABB(box, origin);
}

/// A shape's body transform relative to the query origin.
static tbTransform tbRelativeTransform(const tbWorld* world, const tbShape* shape, tbPos origin)
{
	return tbToRelativeTransform(world->bodies[shape->bodyId].transform, origin);
}

typedef struct tbMoverQuery
{
	tbQueryContext q;
	tbPos origin;
	const tbCapsule* mover;
	tbPlaneResultFcn* planeFcn;
	float fraction;
} tbMoverQuery;

static bool tbMoverPlaneCallback(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbMoverQuery* m = context;
	const tbShape* shape = m->q.world->shapes + shapeIndex;
	if (tbQueryFilterAccepts(m->q.filter, shape) == false || shape->isSensor)
	{
		return true;
	}
	tbPlaneResult result = tbCollideMover(m->mover, &shape->geometry, tbRelativeTransform(m->q.world, shape, m->origin));
	if (result.hit == false)
	{
		return true;
	}
	tbShapeId id = tbMakeShapeId(m->q.world, shapeIndex);
	tbQueryLogHit(m->q.log, id, tbOffsetPos(m->origin, result.point), result.plane.normal, 0.0f);
	return m->planeFcn(id, &result, m->q.userContext);
}

bool tbWorld_CollideMover(tbWorldId worldId, tbPos origin, const tbCapsule* mover, tbQueryFilter filter,
						  tbPlaneResultFcn* fcn, void* context)
{
	const char* f = "tbWorld_CollideMover";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (tbCheckQueryWorld(world, f, fcn != NULL) == false || tbCheckMover(f, origin, mover) == false)
	{
		return false;
	}
	tbMoverQuery m;
	memset(&m, 0, sizeof(m));
	m.q = tbMakeQueryContext(world, filter, context);
	m.origin = origin;
	m.mover = mover;
	m.planeFcn = fcn;
	tbQueryLog log;
	m.q.log = tbLogQuery(&log, world, tb_recQueryCollideMover, filter, origin, tbCapsuleBox(mover), tbVec2_zero);
	tbEnterQuery(world);
	tbBroadPhase_Query(&world->broadPhase, tbMoverBox(origin, mover), filter.maskBits, tbMoverPlaneCallback, &m);
	tbLeaveQuery(world);
	tbQueryLogEnd(m.q.log);
	return true;
}

static bool tbMoverCastCallback(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbMoverQuery* m = context;
	const tbShape* shape = m->q.world->shapes + shapeIndex;
	if (tbQueryFilterAccepts(m->q.filter, shape) == false || shape->isSensor)
	{
		return true;
	}
	tbShapeProxy proxyA = tbMakeShapeProxy(&shape->geometry);
	tbVec2 centers[2] = {m->mover->center1, m->mover->center2};
	tbShapeProxy proxyB = tbMakeProxy(centers, 2, m->mover->radius);
	// canEncroach: the plane solver keeps the slop; the sweep may use it
	tbCastOutput output = tbShapeCastBetween(&proxyA, tbRelativeTransform(m->q.world, shape, m->origin), &proxyB,
											 tbTransform_identity, m->q.translation, m->fraction, true);
	// Shapes the mover starts in (fraction 0) are left to the planes: ignoring them lets a mover
	// pressed into a wall move away from it.
	if (output.hit && output.fraction > 0.0f && output.fraction < m->fraction)
	{
		m->fraction = output.fraction;
	}
	return true;
}

float tbWorld_CastMover(tbWorldId worldId, tbPos origin, const tbCapsule* mover, tbVec2 translation,
						tbQueryFilter filter)
{
	const char* f = "tbWorld_CastMover";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL || tbCheckMover(f, origin, mover) == false || tbCheckVec2(f, "translation", translation) == false)
	{
		return 0.0f;
	}
	tbMoverQuery m;
	memset(&m, 0, sizeof(m));
	m.q = tbMakeQueryContext(world, filter, NULL);
	m.q.translation = translation;
	m.origin = origin;
	m.mover = mover;
	m.fraction = 1.0f;
	tbAABB box = tbMoverBox(origin, mover);
	tbAABB moved = {tbAdd(box.lowerBound, translation), tbAdd(box.upperBound, translation)};
	tbQueryLog log;
	tbAABB moverBox = tbCapsuleBox(mover);
	tbQueryLog* record = tbLogQuery(&log, world, tb_recQueryCastMover, filter, origin, moverBox, translation);
	tbEnterQuery(world);
	tbBroadPhase_Query(&world->broadPhase, tbAABB_Union(box, moved), filter.maskBits, tbMoverCastCallback, &m);
	tbLeaveQuery(world);
	if (m.fraction < 1.0f)
	{
		// No callback: the one result is where the sweep stops (its shape is not kept).
		tbQueryLogHit(record, TB_NULL_SHAPE_ID, tbOffsetPos(origin, tbMulSV(m.fraction, translation)), tbVec2_zero,
					  m.fraction);
	}
	tbQueryLogEnd(record);
	return m.fraction;
}
