// The replay player (Box2D v3.2's tbRecPlayer_*): a recording played step by step in a world of
// its own (replay.c), for viewers and tools, with seeking both ways.
//
// Seeking forward plays on. Seeking backward restores a keyframe, a snapshot the player took while
// playing forward, at or before the target and plays on from there; without one it restores the
// recording's own snapshot. A keyframe holds what playing on from it needs: the world's image, the
// record offset of the next step, the body list and the divergence seen so far. Keyframes are taken
// every `interval` frames; when their bytes pass the budget the interval doubles and the keyframes
// off the new spacing go, so the memory stays under the budget and the spacing stays regular
// (a backward seek replays at most one interval).
//
// The spatial queries recorded before a frame's step are kept with the frame (replay.c) for the
// accessors and the drawing below; they are not run again, as they change nothing.
#include "replay.h"

#include "core/core.h"

#include <string.h>

#define TB_KEYFRAME_BUDGET ((size_t)32 * 1024 * 1024)
#define TB_KEYFRAME_INTERVAL 30

typedef struct tbKeyframe
{
	int frame;
	int cursor;
	int divergeFrame;
	uint8_t* image;
	int imageSize;
	tbBodyId* bodies;
	int bodyCount;
} tbKeyframe;

struct tbRecPlayer
{
	uint8_t* data; ///< the player's copy of the recording
	int size;
	int workerCount;
	tbReplay replay;
	tbKeyframe* keyframes; ///< in increasing frame order
	int keyframeCount, keyframeCapacity;
	size_t keyframeBudget;
	size_t keyframeBytes;
	int keyframeMinInterval;
	int keyframeInterval;
};

static size_t tbKeyframeBytes(const tbKeyframe* k)
{
	return (size_t)k->imageSize + (size_t)k->bodyCount * sizeof(tbBodyId);
}

static void tbFreeKeyframe(tbRecPlayer* player, tbKeyframe* k)
{
	player->keyframeBytes -= tbKeyframeBytes(k);
	tbFree(k->image, k->imageSize);
	tbFree(k->bodies, k->bodyCount * (int)sizeof(tbBodyId));
}

static void tbClearKeyframes(tbRecPlayer* player)
{
	for (int i = 0; i < player->keyframeCount; ++i)
	{
		tbFreeKeyframe(player, player->keyframes + i);
	}
	player->keyframeCount = 0;
	player->keyframeInterval = player->keyframeMinInterval;
}

/// Over budget: double the spacing and drop the keyframes off it, until under budget again.
static void tbThinKeyframes(tbRecPlayer* player)
{
	while (player->keyframeBytes > player->keyframeBudget && player->keyframeCount > 0)
	{
		player->keyframeInterval *= 2;
		int kept = 0;
		for (int i = 0; i < player->keyframeCount; ++i)
		{
			tbKeyframe* k = player->keyframes + i;
			if (k->frame % player->keyframeInterval == 0)
			{
				player->keyframes[kept++] = *k;
			}
			else
			{
				tbFreeKeyframe(player, k);
			}
		}
		player->keyframeCount = kept;
	}
}

/// After a forward step onto the spacing, a keyframe (unless one exists for this frame or later).
static void tbTakeKeyframe(tbRecPlayer* player)
{
	const tbReplay* r = &player->replay;
	bool due = r->frame > 0 && r->frame % player->keyframeInterval == 0;
	if (due == false || (player->keyframeCount > 0 && player->keyframes[player->keyframeCount - 1].frame >= r->frame))
	{
		return;
	}
	int size = tbWorld_Snapshot(r->world, NULL, 0);
	if (size <= 0)
	{
		return;
	}
	if (player->keyframeCount == player->keyframeCapacity)
	{
		int capacity = player->keyframeCapacity > 0 ? 2 * player->keyframeCapacity : 16;
		player->keyframes = tbGrowAlloc(player->keyframes, player->keyframeCapacity * (int)sizeof(tbKeyframe),
										capacity * (int)sizeof(tbKeyframe));
		player->keyframeCapacity = capacity;
	}
	tbKeyframe* k = player->keyframes + player->keyframeCount++;
	*k = (tbKeyframe){r->frame, r->cursor, r->divergeFrame, tbAlloc(size), size, NULL, r->bodyCount};
	tbWorld_Snapshot(r->world, k->image, size);
	if (r->bodyCount > 0)
	{
		k->bodies = tbAlloc(r->bodyCount * (int)sizeof(tbBodyId));
		memcpy(k->bodies, r->bodies, (size_t)r->bodyCount * sizeof(tbBodyId));
	}
	player->keyframeBytes += tbKeyframeBytes(k);
	tbThinKeyframes(player);
}

/// Back to a keyframe: the world, the record offset, the body list and the divergence of then.
static void tbRestoreKeyframe(tbRecPlayer* player, const tbKeyframe* k)
{
	tbReplay* r = &player->replay;
	if (tbWorld_Restore(r->world, k->image, k->imageSize) == false)
	{
		r->failed = true; // the game destroyed the replay world (reported)
		return;
	}
	r->frame = k->frame;
	r->cursor = k->cursor;
	r->divergeFrame = k->divergeFrame;
	r->failed = false;
	r->queryCount = 0; // the queries before a keyframe's step are not kept with it
	r->hitCount = 0;
	r->queriesStale = false;
	tbReplayReserveBodies(r, k->bodyCount);
	if (k->bodyCount > 0)
	{
		memcpy(r->bodies, k->bodies, (size_t)k->bodyCount * sizeof(tbBodyId));
	}
	r->bodyCount = k->bodyCount;
}

static bool tbCheckPlayer(const tbRecPlayer* player, const char* function)
{
	return tbCheckPointer(function, "player", player);
}

// --------------------------------------------------------------------------------------------
// The API

tbRecPlayer* tbRecPlayer_Create(const void* data, int size, int workerCount)
{
	const char* f = "tbRecPlayer_Create";
	if (tbCheckPointer(f, "data", data) == false)
	{
		return NULL;
	}
	if (size < 0 || workerCount < 0 || workerCount > TB_MAX_WORKERS)
	{
		tbReportError(f, "%s is %d; pass %s", size < 0 ? "size" : "workerCount", size < 0 ? size : workerCount,
					  size < 0 ? "the recording's size in bytes" : "0 to TB_MAX_WORKERS");
		return NULL;
	}
	tbRecPlayer* player = tbAlloc((int)sizeof(tbRecPlayer));
	memset(player, 0, sizeof(*player));
	player->data = size > 0 ? tbAlloc(size) : NULL;
	if (size > 0)
	{
		memcpy(player->data, data, (size_t)size);
	}
	player->size = size;
	player->workerCount = workerCount > 0 ? workerCount : 1;
	player->keyframeBudget = TB_KEYFRAME_BUDGET;
	player->keyframeMinInterval = TB_KEYFRAME_INTERVAL;
	player->keyframeInterval = TB_KEYFRAME_INTERVAL;
	if (tbReplayOpen(&player->replay, f, player->data, size, workerCount) == false)
	{
		tbFree(player->data, size);
		tbFree(player, (int)sizeof(tbRecPlayer));
		return NULL;
	}
	return player;
}

void tbRecPlayer_Destroy(tbRecPlayer* player)
{
	if (player == NULL)
	{
		return;
	}
	tbClearKeyframes(player);
	tbFree(player->keyframes, player->keyframeCapacity * (int)sizeof(tbKeyframe));
	tbReplayClose(&player->replay);
	tbFree(player->data, player->size);
	tbFree(player, (int)sizeof(tbRecPlayer));
}

bool tbRecPlayer_StepFrame(tbRecPlayer* player)
{
	if (tbCheckPlayer(player, "tbRecPlayer_StepFrame") == false ||
		tbReplayStep(&player->replay, "tbRecPlayer_StepFrame") == false)
	{
		return false;
	}
	tbTakeKeyframe(player);
	return true;
}

tbWorldId tbRecPlayer_GetWorldId(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetWorldId") ? player->replay.world : TB_NULL_WORLD_ID;
}

void tbRecPlayer_Restart(tbRecPlayer* player)
{
	if (tbCheckPlayer(player, "tbRecPlayer_Restart"))
	{
		tbReplayRestart(&player->replay);
	}
}

void tbRecPlayer_SeekFrame(tbRecPlayer* player, int targetFrame)
{
	if (tbCheckPlayer(player, "tbRecPlayer_SeekFrame") == false)
	{
		return;
	}
	tbReplay* r = &player->replay;
	int target = targetFrame < 0 ? 0 : targetFrame > r->info.frameCount ? r->info.frameCount : targetFrame;
	if (target < r->frame)
	{
		const tbKeyframe* best = NULL;
		for (int i = 0; i < player->keyframeCount && player->keyframes[i].frame <= target; ++i)
		{
			best = player->keyframes + i;
		}
		if (best != NULL)
		{
			tbRestoreKeyframe(player, best);
		}
		else
		{
			tbReplayRestart(r);
		}
	}
	while (r->frame < target && tbRecPlayer_StepFrame(player))
	{
	}
}

int tbRecPlayer_GetFrame(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetFrame") ? player->replay.frame : 0;
}

tbRecPlayerInfo tbRecPlayer_GetInfo(const tbRecPlayer* player)
{
	tbRecPlayerInfo info;
	memset(&info, 0, sizeof(info));
	if (tbCheckPlayer(player, "tbRecPlayer_GetInfo"))
	{
		const tbReplayInfo* r = &player->replay.info;
		uint32_t unitBits = (uint32_t)player->data[12] | (uint32_t)player->data[13] << 8 |
							(uint32_t)player->data[14] << 16 | (uint32_t)player->data[15] << 24;
		info.frameCount = r->frameCount;
		info.workerCount = player->workerCount;
		info.timeStep = r->timeStep;
		info.subStepCount = r->subStepCount;
		memcpy(&info.lengthScale, &unitBits, sizeof(float));
		info.bounds = r->bounds;
	}
	return info;
}

bool tbRecPlayer_IsAtEnd(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_IsAtEnd") &&
		   (player->replay.failed || player->replay.frame >= player->replay.info.frameCount);
}

bool tbRecPlayer_HasDiverged(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_HasDiverged") && player->replay.divergeFrame >= 0;
}

int tbRecPlayer_GetDivergeFrame(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetDivergeFrame") ? player->replay.divergeFrame : -1;
}

void tbRecPlayer_SetKeyframePolicy(tbRecPlayer* player, size_t budgetBytes, int minIntervalFrames)
{
	if (tbCheckPlayer(player, "tbRecPlayer_SetKeyframePolicy") == false)
	{
		return;
	}
	player->keyframeBudget = budgetBytes > 0 ? budgetBytes : player->keyframeBudget;
	player->keyframeMinInterval = minIntervalFrames > 0 ? minIntervalFrames : player->keyframeMinInterval;
	tbClearKeyframes(player);
}

size_t tbRecPlayer_GetKeyframeBudget(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetKeyframeBudget") ? player->keyframeBudget : 0;
}

int tbRecPlayer_GetKeyframeMinInterval(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetKeyframeMinInterval") ? player->keyframeMinInterval : 0;
}

int tbRecPlayer_GetKeyframeInterval(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetKeyframeInterval") ? player->keyframeInterval : 0;
}

size_t tbRecPlayer_GetKeyframeBytes(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetKeyframeBytes") ? player->keyframeBytes : 0;
}

/// A query: its box (overlaps, casts, movers), its ray or sweep, and a point and normal a result,
/// through Box2D v3.2's debug-draw callbacks (bounds, line, point).
static void tbDrawQuery(tbDebugDraw* draw, const tbReplay* r, const tbReplayQuery* q)
{
	const tbRecQueryInfo* info = &q->info;
	bool ray = info->type == tb_recQueryCastRay || info->type == tb_recQueryCastRayClosest ||
			   info->type == tb_recQueryShapeRayCast;
	bool point = info->type == tb_recQueryShapeTestPoint;
	if (ray == false && point == false && draw->DrawBoundsFcn != NULL)
	{
		draw->DrawBoundsFcn(tbOffsetAABB(info->aabb, info->origin), tb_colorYellow, draw->context);
	}
	if (point && draw->DrawPointFcn != NULL)
	{
		draw->DrawPointFcn(info->origin, 6.0f, tb_colorYellow, draw->context);
	}
	if ((info->translation.x != 0.0f || info->translation.y != 0.0f) && draw->DrawLineFcn != NULL)
	{
		draw->DrawLineFcn(info->origin, tbOffsetPos(info->origin, info->translation), tb_colorYellow, draw->context);
	}
	for (int i = 0; i < info->hitCount; ++i)
	{
		const tbRecQueryHit* hit = r->hits + q->firstHit + i;
		if (draw->DrawPointFcn != NULL)
		{
			draw->DrawPointFcn(hit->point, 5.0f, tb_colorOrangeRed, draw->context);
		}
		if ((hit->normal.x != 0.0f || hit->normal.y != 0.0f) && draw->DrawLineFcn != NULL)
		{
			draw->DrawLineFcn(hit->point, tbOffsetPos(hit->point, tbMulSV(0.5f, hit->normal)), tb_colorOrangeRed,
							  draw->context);
		}
	}
}

void tbRecPlayer_DrawFrameQueries(tbRecPlayer* player, tbDebugDraw* draw, int queryIndex)
{
	const char* f = "tbRecPlayer_DrawFrameQueries";
	if (tbCheckPlayer(player, f) == false || tbCheckPointer(f, "draw", draw) == false)
	{
		return;
	}
	const tbReplay* r = &player->replay;
	if (queryIndex < -1 || queryIndex >= r->queryCount)
	{
		tbReportError(f, "queryIndex is %d; pass -1 (all) or 0 to %d, the frame's queries", queryIndex,
					  r->queryCount - 1);
		return;
	}
	int first = queryIndex >= 0 ? queryIndex : 0;
	int last = queryIndex >= 0 ? queryIndex + 1 : r->queryCount;
	for (int i = first; i < last; ++i)
	{
		tbDrawQuery(draw, r, r->queries + i);
	}
}

int tbRecPlayer_GetFrameQueryCount(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetFrameQueryCount") ? player->replay.queryCount : 0;
}

tbRecQueryInfo tbRecPlayer_GetFrameQuery(const tbRecPlayer* player, int index)
{
	const char* f = "tbRecPlayer_GetFrameQuery";
	tbRecQueryInfo info;
	memset(&info, 0, sizeof(info));
	if (tbCheckPlayer(player, f) == false)
	{
		return info;
	}
	if (index < 0 || index >= player->replay.queryCount)
	{
		tbReportError(f, "index is %d; the frame has %d queries", index, player->replay.queryCount);
		return info;
	}
	return player->replay.queries[index].info;
}

tbRecQueryHit tbRecPlayer_GetFrameQueryHit(const tbRecPlayer* player, int queryIndex, int hitIndex)
{
	const char* f = "tbRecPlayer_GetFrameQueryHit";
	tbRecQueryHit hit;
	memset(&hit, 0, sizeof(hit));
	if (tbCheckPlayer(player, f) == false)
	{
		return hit;
	}
	const tbReplay* r = &player->replay;
	if (queryIndex < 0 || queryIndex >= r->queryCount || hitIndex < 0 ||
		hitIndex >= r->queries[queryIndex].info.hitCount)
	{
		tbReportError(f, "queryIndex %d, hitIndex %d: the frame has %d queries (and each its hitCount results)",
					  queryIndex, hitIndex, r->queryCount);
		return hit;
	}
	return r->hits[r->queries[queryIndex].firstHit + hitIndex];
}

int tbRecPlayer_GetBodyCount(const tbRecPlayer* player)
{
	return tbCheckPlayer(player, "tbRecPlayer_GetBodyCount") ? player->replay.bodyCount : 0;
}

tbBodyId tbRecPlayer_GetBodyId(const tbRecPlayer* player, int index)
{
	if (tbCheckPlayer(player, "tbRecPlayer_GetBodyId") == false || index < 0 || index >= player->replay.bodyCount)
	{
		return TB_NULL_BODY_ID;
	}
	return player->replay.bodies[index];
}
