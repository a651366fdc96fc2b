// Replay (Box2D v3.2's tbValidateReplay and the engine of its replay player): a recording's
// snapshot restored into a world of its own, then its records played in order: each API call made
// again with the same arguments, each step taken again and its state hash compared with the one
// recorded. Bit-identical replay follows from what recording.c records: the whole state the steps
// read at the start, and every call that changed it since, in order.
//
// Ids: a recording names objects by index. The replay world numbers its objects as the recorded one
// did (the snapshot holds the id pools and their free lists, and creations come in the same order),
// so an index names the same object; the generation is the replay world's own (each world slot
// starts its generations past those of the worlds it held before). A recorded call naming an index
// that holds nothing in the replay is a replay that has gone wrong: it stops there, reported.
//
// Nothing in the bytes is trusted. Opening checks the header and checksum (recording.c), then walks
// every record's frame: a known opcode and a payload inside the bytes. Playing a record checks that
// its arguments fill its payload exactly; the calls then check their arguments as they check a
// game's.
#include "replay.h"

#include "body.h"
#include "chain.h"
#include "recording.h"
#include "shape.h"
#include "world.h"

#include "core/core.h"
#include "joints/joint.h"

#include <string.h>

#define TB_REC_MAX_ARGS 6

static uint32_t tbLoadU32(const uint8_t* p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static float tbLoadFloat(const uint8_t* p)
{
	uint32_t bits = tbLoadU32(p);
	float value;
	memcpy(&value, &bits, sizeof(value));
	return value;
}

/// The fixed payload size of the records that are not calls, or -1 for a call (any size).
static int tbFixedPayload(int op)
{
	return op == tb_recStep ? 16 : op == tb_recStop ? 16 : -1;
}

/// Walk the records' frames: fills the info, false after reporting the first bad frame.
static bool tbScanRecords(const char* f, const uint8_t* data, int size, tbReplayInfo* info)
{
	int offset = info->recordsStart;
	while (offset < size)
	{
		if (size - offset < TB_RECORD_FRAME_SIZE)
		{
			tbReportError(f, "the record at byte %d is cut short (truncated recording)", offset);
			return false;
		}
		int op = data[offset];
		uint32_t payload = tbLoadU32(data + offset + 1);
		int fixed = tbFixedPayload(op);
		bool known = fixed >= 0 || op == tb_recQuery || tbRecordingOpName(op) != NULL;
		if (known == false || payload > (uint32_t)(size - offset - TB_RECORD_FRAME_SIZE) ||
			(fixed >= 0 && payload != (uint32_t)fixed))
		{
			tbReportError(f, "the record at byte %d (opcode %d) is %s", offset, op,
						  known ? "longer than the bytes left or the wrong size" : "of no kind this version knows");
			return false;
		}
		const uint8_t* p = data + offset + TB_RECORD_FRAME_SIZE;
		if (op == tb_recStep && info->frameCount++ == 0)
		{
			info->timeStep = tbLoadFloat(p);
			info->subStepCount = (int)tbLoadU32(p + 4);
		}
		else if (op == tb_recStop)
		{
			info->bounds = (tbAABB){{tbLoadFloat(p), tbLoadFloat(p + 4)}, {tbLoadFloat(p + 8), tbLoadFloat(p + 12)}};
		}
		offset += TB_RECORD_FRAME_SIZE + (int)payload;
	}
	return true;
}

static bool tbPlayCalls(tbReplay* replay, const char* f);
static bool tbReplayWorldLives(tbReplay* replay, const char* f);

void tbReplayReserveBodies(tbReplay* replay, int count)
{
	if (count > replay->bodyCapacity)
	{
		int capacity = replay->bodyCapacity > 0 ? 2 * replay->bodyCapacity : 64;
		capacity = capacity > count ? capacity : count;
		replay->bodies = tbGrowAlloc(replay->bodies, replay->bodyCapacity * (int)sizeof(tbBodyId),
									 capacity * (int)sizeof(tbBodyId));
		replay->bodyCapacity = capacity;
	}
}

/// The body list of the snapshot: its live bodies in id order.
static void tbListSnapshotBodies(tbReplay* replay)
{
	tbWorld* world = tbGetWorldFromIndex(replay->world.index1 - 1);
	replay->bodyCount = 0;
	for (int id = 0; id < world->bodyPool.highWater; ++id)
	{
		if (world->bodies[id].inUse)
		{
			tbReplayReserveBodies(replay, replay->bodyCount + 1);
			replay->bodies[replay->bodyCount++] = tbMakeBodyId(world, id);
		}
	}
}

bool tbReplayCheck(const char* f, const uint8_t* data, int size, tbReplayInfo* info)
{
	memset(info, 0, sizeof(*info));
	if (tbCheckRecordingBytes(f, data, size) == false)
	{
		return false;
	}
	info->recordsStart = TB_RECORDING_HEADER_SIZE + (int)tbLoadU32(data + 24);
	return tbScanRecords(f, data, size, info);
}

bool tbReplayOpen(tbReplay* replay, const char* f, const uint8_t* data, int size, int workerCount)
{
	memset(replay, 0, sizeof(*replay));
	if (tbReplayCheck(f, data, size, &replay->info) == false)
	{
		return false;
	}
	int snapshotSize = (int)tbLoadU32(data + 24);
	replay->world = tbCreateWorldFromSnapshot(data + TB_RECORDING_HEADER_SIZE, snapshotSize, workerCount);
	if (tbWorld_IsValid(replay->world) == false)
	{
		tbReportError(f, "the recording's snapshot was refused (reported above)");
		return false;
	}
	replay->data = data;
	replay->size = size;
	replay->cursor = replay->info.recordsStart;
	replay->divergeFrame = -1;
	tbListSnapshotBodies(replay);
	tbPlayCalls(replay, f); // up to the first step, as Box2D v3.2's player opens
	return true;
}

void tbReplayRestart(tbReplay* replay)
{
	if (tbWorld_IsValid(replay->world) == false)
	{
		tbReplayWorldLives(replay, "tbRecPlayer_Restart");
		return;
	}
	int snapshotSize = (int)tbLoadU32(replay->data + 24);
	tbWorld_Restore(replay->world, replay->data + TB_RECORDING_HEADER_SIZE, snapshotSize);
	replay->cursor = replay->info.recordsStart;
	replay->frame = 0;
	replay->divergeFrame = -1;
	replay->failed = false;
	replay->queryCount = 0;
	replay->hitCount = 0;
	replay->queriesStale = false;
	tbListSnapshotBodies(replay);
	tbPlayCalls(replay, "tbRecPlayer_Restart");
}

void tbReplayClose(tbReplay* replay)
{
	if (tbWorld_IsValid(replay->world))
	{
		tbDestroyWorld(replay->world);
	}
	tbFree(replay->bodies, replay->bodyCapacity * (int)sizeof(tbBodyId));
	tbFree(replay->queries, replay->queryCapacity * (int)sizeof(tbReplayQuery));
	tbFree(replay->hits, replay->hitCapacity * (int)sizeof(tbRecQueryHit));
	memset(replay, 0, sizeof(*replay));
}

// --------------------------------------------------------------------------------------------
// Ids

/// The generation of slot `index` of a kind of object in the replay world, or -1 when it holds none.
static int tbSlotGeneration(const tbWorld* world, char kind, int index)
{
	switch (kind)
	{
		case 'b':
			return index < world->bodyPool.highWater && world->bodies[index].inUse ? world->bodies[index].generation
																					: -1;
		case 's':
			return index < world->shapePool.highWater && world->shapes[index].inUse ? world->shapes[index].generation
																					 : -1;
		case 'c':
			return index < world->chainPool.highWater && world->chains[index].inUse ? world->chains[index].generation
																					 : -1;
		default:
			return index < world->jointPool.highWater && world->joints[index].inUse ? world->joints[index].generation
																					 : -1;
	}
}

/// A recorded id (index only) as the replay world's id of that slot; false when the slot is empty.
static bool tbMapId(const tbWorld* world, char kind, tbBodyId* id)
{
	if (id->index1 == 0)
	{
		return true; // a null id stays null (the call refuses it as it did when recorded)
	}
	int generation = id->index1 > 0 ? tbSlotGeneration(world, kind, id->index1 - 1) : -1;
	if (generation < 0)
	{
		return false;
	}
	id->world0 = world->worldId;
	id->generation = (uint16_t)generation;
	return true;
}

/// Every id of an argument mapped; false (and the unmapped index in *missing) when one names nothing.
static bool tbMapArg(const tbWorld* world, char kind, tbRecArg* arg, int* missing)
{
	tbBodyId* ids[2] = {&arg->body, NULL};
	char kinds[2] = {kind, 'b'};
	int count = strchr("bscj", kind) != NULL && kind != 0 ? 1 : 0;
	if (count == 0)
	{
		count = tbRecArgBodyIds(kind, arg, ids);
		kinds[0] = 'b';
	}
	for (int k = 0; k < count; ++k)
	{
		if (tbMapId(world, kinds[k], ids[k]) == false)
		{
			*missing = ids[k]->index1 - 1;
			return false;
		}
	}
	return true;
}

// --------------------------------------------------------------------------------------------
// Playing

static void tbNoteBody(tbReplay* replay, tbBodyId id)
{
	tbReplayReserveBodies(replay, replay->bodyCount + 1);
	replay->bodies[replay->bodyCount++] = id;
}

static void tbForgetBody(tbReplay* replay, tbBodyId id)
{
	for (int i = 0; i < replay->bodyCount; ++i)
	{
		if (memcmp(replay->bodies + i, &id, sizeof(id)) == 0)
		{
			replay->bodies[i] = tb_nullBodyId;
		}
	}
}

#define TB_PLAY_NONE(call) (void)(call)
#define TB_PLAY_BODY(call) tbNoteBody(replay, call)
#define TB_PLAY_SHAPE(call) (void)(call)
#define TB_PLAY_CHAIN(call) (void)(call)
#define TB_PLAY_JOINT(call) (void)(call)
#define TB_REC_POINTER(arg, member) ((arg).present ? &(arg).member : NULL)

/// Make the recorded call `op` with its decoded, mapped arguments.
static void tbMakeCall(tbReplay* replay, int op, tbRecArg* a)
{
	tbWorldId world = replay->world;
	if (op == tb_recDestroyBody)
	{
		tbForgetBody(replay, a[0].body);
	}
	switch (op)
	{
#define TB_REC_OP(code, Name, kinds, ret, call)                                                                       \
	case code:                                                                                                        \
		TB_PLAY_##ret(call);                                                                                          \
		break;
#include "recording_ops.h"
#undef TB_REC_OP
		default:
			break;
	}
}

/// Decode and make one recorded call; false after reporting a payload that does not decode or an
/// id that names nothing in the replay.
static bool tbPlayCall(tbReplay* replay, const char* f, int op, const uint8_t* payload, int size)
{
	const char* kinds = tbRecordingOpKinds(op);
	const tbWorld* world = tbGetWorldFromIndex(replay->world.index1 - 1);
	tbRecArg a[TB_REC_MAX_ARGS];
	tbRecArgReader in = {payload, size, 0, false, {NULL, NULL}, {0, 0}};
	int count = (int)strlen(kinds), missing = -1;
	bool mapped = true;
	for (int k = 0; k < count && k < TB_REC_MAX_ARGS; ++k)
	{
		tbRecGetArg(&in, kinds[k], a + k);
		mapped = mapped && (in.failed || tbMapArg(world, kinds[k], a + k, &missing));
	}
	bool ok = in.failed == false && in.offset == size && mapped;
	if (in.failed || in.offset != size)
	{
		tbReportError(f, "the %s record before step %d does not decode (corrupt recording)", tbRecordingOpName(op),
					  replay->frame + 1);
	}
	else if (mapped == false)
	{
		tbReportError(f, "the %s record before step %d names object %d, which does not exist in the replay",
					  tbRecordingOpName(op), replay->frame + 1, missing);
	}
	else
	{
		tbMakeCall(replay, op, a);
	}
	tbRecArgsFree(&in);
	return ok;
}

/// Take the recorded step and compare the hash it ends on with the recorded one.
static void tbPlayStep(tbReplay* replay, const uint8_t* payload)
{
	float timeStep = tbLoadFloat(payload);
	int subStepCount = (int)tbLoadU32(payload + 4);
	uint64_t recorded = (uint64_t)tbLoadU32(payload + 8) | (uint64_t)tbLoadU32(payload + 12) << 32;
	tbWorld_Step(replay->world, timeStep, subStepCount);
	replay->frame += 1;
	if (replay->divergeFrame < 0 && tbWorld_GetStateHash(replay->world) != recorded)
	{
		replay->divergeFrame = replay->frame;
	}
}

/// The query list grown to hold queryCount queries and hitCount hits.
static void tbReserveQueries(tbReplay* replay, int queryCount, int hitCount)
{
	if (queryCount > replay->queryCapacity)
	{
		int capacity = queryCount > 2 * replay->queryCapacity ? queryCount : 2 * replay->queryCapacity;
		replay->queries = tbGrowAlloc(replay->queries, replay->queryCapacity * (int)sizeof(tbReplayQuery),
									  capacity * (int)sizeof(tbReplayQuery));
		replay->queryCapacity = capacity;
	}
	if (hitCount > replay->hitCapacity)
	{
		int capacity = hitCount > 2 * replay->hitCapacity ? hitCount : 2 * replay->hitCapacity;
		replay->hits = tbGrowAlloc(replay->hits, replay->hitCapacity * (int)sizeof(tbRecQueryHit),
								   capacity * (int)sizeof(tbRecQueryHit));
		replay->hitCapacity = capacity;
	}
}

/// A recorded shape id as the replay world's, or null when its slot holds nothing now.
static tbShapeId tbMapShape(const tbWorld* world, tbShapeId id)
{
	tbBodyId asBody = {id.index1, 0, 0};
	if (tbMapId(world, 's', &asBody) == false)
	{
		return TB_NULL_SHAPE_ID;
	}
	return (tbShapeId){asBody.index1, asBody.world0, asBody.generation};
}

/// Keep a query record for the frame; false after reporting one that does not decode.
static bool tbKeepQuery(tbReplay* replay, const char* f, const uint8_t* payload, int size)
{
	int room = size / TB_QUERY_HIT_MIN_BYTES + 1;
	tbReserveQueries(replay, replay->queryCount + 1, replay->hitCount + room);
	tbReplayQuery* q = replay->queries + replay->queryCount;
	tbRecQueryHit* hits = replay->hits + replay->hitCount;
	if (tbQueryLogRead(payload, size, &q->info, hits, room) == false)
	{
		tbReportError(f, "the query record before step %d does not decode (corrupt recording)", replay->frame + 1);
		return false;
	}
	const tbWorld* world = tbGetWorldFromIndex(replay->world.index1 - 1);
	q->info.shape = tbMapShape(world, q->info.shape);
	for (int i = 0; i < q->info.hitCount; ++i)
	{
		hits[i].shape = tbMapShape(world, hits[i].shape);
	}
	q->firstHit = replay->hitCount;
	replay->queryCount += 1;
	replay->hitCount += q->info.hitCount;
	return true;
}

/// Play the calls up to the next step record (or the end); false after one could not be played.
static bool tbPlayCalls(tbReplay* replay, const char* f)
{
	while (replay->failed == false && replay->cursor < replay->size && replay->data[replay->cursor] != tb_recStep)
	{
		const uint8_t* record = replay->data + replay->cursor;
		int op = record[0];
		int payloadSize = (int)tbLoadU32(record + 1); // in range: tbScanRecords checked every frame
		replay->cursor += TB_RECORD_FRAME_SIZE + payloadSize;
		const uint8_t* payload = record + TB_RECORD_FRAME_SIZE;
		bool ok = op == tb_recStop ? true
			: op == tb_recQuery	   ? tbKeepQuery(replay, f, payload, payloadSize)
								   : tbPlayCall(replay, f, op, payload, payloadSize);
		replay->failed = ok == false;
	}
	return replay->failed == false;
}

/// The replay world is the player's: a game that destroyed it stops the replay, reported.
static bool tbReplayWorldLives(tbReplay* replay, const char* f)
{
	if (replay->failed == false && tbWorld_IsValid(replay->world) == false)
	{
		tbReportError(f, "the replay world was destroyed; destroy the player instead");
		replay->failed = true;
	}
	return replay->failed == false;
}

bool tbReplayStep(tbReplay* replay, const char* f)
{
	if (tbReplayWorldLives(replay, f) == false)
	{
		return false;
	}
	if (replay->queriesStale)
	{
		replay->queryCount = 0;
		replay->hitCount = 0;
		replay->queriesStale = false;
	}
	if (tbPlayCalls(replay, f) == false || replay->cursor >= replay->size)
	{
		return false;
	}
	const uint8_t* record = replay->data + replay->cursor;
	replay->cursor += TB_RECORD_FRAME_SIZE + (int)tbLoadU32(record + 1);
	tbPlayStep(replay, record + TB_RECORD_FRAME_SIZE);
	replay->queriesStale = true;
	return true;
}

bool tbValidateReplay(const void* data, int size, int workerCount)
{
	const char* f = "tbValidateReplay";
	if (workerCount < 0 || workerCount > TB_MAX_WORKERS)
	{
		tbReportError(f, "workerCount is %d; pass 0 to %d", workerCount, TB_MAX_WORKERS);
		return false;
	}
	tbReplay replay;
	if (tbReplayOpen(&replay, f, data, size, workerCount) == false)
	{
		return false;
	}
	while (tbReplayStep(&replay, f))
	{
	}
	bool ok = replay.failed == false && replay.divergeFrame < 0 && replay.frame == replay.info.frameCount;
	if (replay.failed == false && replay.divergeFrame >= 0)
	{
		tbReportError(f, "the replay diverged at step %d of %d: its state hash differs from the recorded one",
					  replay.divergeFrame, replay.info.frameCount);
	}
	tbReplayClose(&replay);
	return ok;
}
