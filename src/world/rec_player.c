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
// Spatial queries change nothing and are not recorded (recording.c), so a frame has no queries to
// show: the query accessors answer for an empty list.
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
	tbWorld_Restore(r->world, k->image, k->imageSize);
	r->frame = k->frame;
	r->cursor = k->cursor;
	r->divergeFrame = k->divergeFrame;
	r->failed = false;
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

void tbRecPlayer_DrawFrameQueries(tbRecPlayer* player, tbDebugDraw* draw, int queryIndex)
{
	(void)queryIndex; // no frame holds queries: nothing to draw
	if (tbCheckPlayer(player, "tbRecPlayer_DrawFrameQueries"))
	{
		tbCheckPointer("tbRecPlayer_DrawFrameQueries", "draw", draw);
	}
}

int tbRecPlayer_GetFrameQueryCount(const tbRecPlayer* player)
{
	tbCheckPlayer(player, "tbRecPlayer_GetFrameQueryCount");
	return 0;
}

tbRecQueryInfo tbRecPlayer_GetFrameQuery(const tbRecPlayer* player, int index)
{
	tbRecQueryInfo info;
	memset(&info, 0, sizeof(info));
	if (tbCheckPlayer(player, "tbRecPlayer_GetFrameQuery"))
	{
		tbReportError("tbRecPlayer_GetFrameQuery", "index is %d; the frame has no queries (count 0)", index);
	}
	return info;
}

tbRecQueryHit tbRecPlayer_GetFrameQueryHit(const tbRecPlayer* player, int queryIndex, int hitIndex)
{
	tbRecQueryHit hit;
	memset(&hit, 0, sizeof(hit));
	if (tbCheckPlayer(player, "tbRecPlayer_GetFrameQueryHit"))
	{
		tbReportError("tbRecPlayer_GetFrameQueryHit", "queryIndex is %d (hitIndex %d); the frame has no queries",
					  queryIndex, hitIndex);
	}
	return hit;
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
