// Spatial queries in a recording (recording.h): what a query asked and what its callback was
// told, one record a query, so that a replay viewer can show them frame by frame (Box2D v3.2's
// tbRecPlayer_GetFrameQuery). Queries change nothing and replay does not run them again.
//
// Payload (little-endian): the kind (4 bytes), the filter's category and mask bits (8 each), the
// box (4 floats, relative to the origin), the origin (a world position), the translation (2
// floats), the shape of a shape's own test (its index, 0 for none), the number of results, then
// each result: its shape's index, the point (a world position), the normal (2 floats), the
// fraction. The results are gathered aside while the query runs (its callbacks may start other
// queries, and queries may run on several threads) and written at its end under the recording's
// lock.
#include "recording.h"

#include "world.h"

#include "core/core.h"

#include <string.h>

tbQueryLog* tbQueryLogBegin(tbQueryLog* log, const tbWorld* world, const tbRecQueryInfo* info)
{
	if (world == NULL || world->recording == NULL || world->locked)
	{
		return NULL;
	}
	memset(log, 0, sizeof(*log));
	log->recording = world->recording;
	log->info = *info;
	return log;
}

static void tbPutPosition(tbRecBytes* out, tbPos p)
{
	tbRecPutArg(out, 'p', &p);
}

void tbQueryLogHit(tbQueryLog* log, tbShapeId shape, tbPos point, tbVec2 normal, float fraction)
{
	if (log == NULL)
	{
		return;
	}
	tbRecPutU32(&log->hits, (uint32_t)shape.index1);
	tbPutPosition(&log->hits, point);
	tbRecPutFloat(&log->hits, normal.x);
	tbRecPutFloat(&log->hits, normal.y);
	tbRecPutFloat(&log->hits, fraction);
	log->hitCount += 1;
}

static void tbPutInfo(tbRecBytes* out, const tbRecQueryInfo* info, int hitCount)
{
	tbRecPutU32(out, (uint32_t)info->type);
	tbRecPutU64(out, info->filter.categoryBits);
	tbRecPutU64(out, info->filter.maskBits);
	const float box[4] = {info->aabb.lowerBound.x, info->aabb.lowerBound.y, info->aabb.upperBound.x,
						  info->aabb.upperBound.y};
	for (int k = 0; k < 4; ++k)
	{
		tbRecPutFloat(out, box[k]);
	}
	tbPutPosition(out, info->origin);
	tbRecPutFloat(out, info->translation.x);
	tbRecPutFloat(out, info->translation.y);
	tbRecPutU32(out, (uint32_t)info->shape.index1);
	tbRecPutU32(out, (uint32_t)hitCount);
}

void tbQueryLogEnd(tbQueryLog* log)
{
	if (log == NULL)
	{
		return;
	}
	tbRecBytes payload = {NULL, 0, 0};
	tbPutInfo(&payload, &log->info, log->hitCount);
	if (log->hits.size > 0)
	{
		tbRecPutBytes(&payload, log->hits.data, log->hits.size);
	}
	tbRecording* rec = log->recording;
	while (atomic_flag_test_and_set_explicit(&rec->queryLock, memory_order_acquire))
	{
	}
	tbRecordingAppend(rec, tb_recQuery, payload.data, payload.size);
	atomic_flag_clear_explicit(&rec->queryLock, memory_order_release);
	tbFree(payload.data, payload.capacity);
	tbFree(log->hits.data, log->hits.capacity);
	memset(log, 0, sizeof(*log));
}

static bool tbReadPosition(tbRecArgReader* r, tbPos* p)
{
	tbRecArg arg;
	bool ok = tbRecGetArg(r, 'p', &arg);
	*p = arg.p;
	return ok;
}

static bool tbReadInfo(tbRecArgReader* r, tbRecQueryInfo* info, uint32_t* hitCount)
{
	uint32_t type = 0, shape = 0;
	float box[4] = {0.0f, 0.0f, 0.0f, 0.0f};
	tbRecGetU32(r, &type);
	tbRecGetU64(r, &info->filter.categoryBits);
	tbRecGetU64(r, &info->filter.maskBits);
	for (int k = 0; k < 4; ++k)
	{
		tbRecGetFloat(r, box + k);
	}
	info->aabb = (tbAABB){{box[0], box[1]}, {box[2], box[3]}};
	tbReadPosition(r, &info->origin);
	tbRecGetFloat(r, &info->translation.x);
	tbRecGetFloat(r, &info->translation.y);
	tbRecGetU32(r, &shape);
	tbRecGetU32(r, hitCount);
	info->type = (tbRecQueryType)type;
	info->shape.index1 = (int32_t)shape;
	info->hitCount = (int)*hitCount;
	return r->failed == false && type <= (uint32_t)tb_recQueryShapeRayCast && shape <= (uint32_t)INT32_MAX;
}

bool tbQueryLogRead(const uint8_t* payload, int size, tbRecQueryInfo* info, tbRecQueryHit* hits, int hitCapacity)
{
	tbRecArgReader r = {payload, size, 0, false, {NULL, NULL}, {0, 0}};
	uint32_t hitCount = 0;
	memset(info, 0, sizeof(*info));
	if (tbReadInfo(&r, info, &hitCount) == false || hitCount > (uint32_t)hitCapacity)
	{
		return false;
	}
	bool badShape = false;
	for (uint32_t i = 0; i < hitCount; ++i)
	{
		uint32_t shape = 0;
		memset(hits + i, 0, sizeof(hits[i]));
		tbRecGetU32(&r, &shape);
		badShape = badShape || shape > (uint32_t)INT32_MAX;
		hits[i].shape.index1 = (int32_t)shape;
		tbReadPosition(&r, &hits[i].point);
		tbRecGetFloat(&r, &hits[i].normal.x);
		tbRecGetFloat(&r, &hits[i].normal.y);
		tbRecGetFloat(&r, &hits[i].fraction);
	}
	return r.failed == false && r.offset == size && badShape == false;
}
