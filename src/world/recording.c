// Recordings (Box2D v3.2's recording group): a world's session as the state it started from and
// the calls and steps that followed, which replay.c plays again bit for bit.
//
// What is recorded: at tbWorld_StartRecording, a snapshot of the world (tbWorld_Snapshot: every
// state the next steps read); then, in the order they are made, the calls that change the world
// (recording_ops.h: creations, destructions, setters, forces, impulses, explosions, wind, world
// settings) and each step with the state hash it ended on (tbWorld_GetStateHash), which replay
// compares to find the first step that differs; spatial queries too, with their results, for a
// viewer to show (recording_queries.c). Host wiring (callbacks, user data, the task
// system) is not state and is not recorded, as in snapshots. A call is recorded at its entry,
// before it checks anything, and taken back when it reports an error under its own name: the
// error hook sees every refusal (core's error observer), so the record never holds a refused call
// and each call site needs one line, not one at each of its returns.
//
// Format (little-endian). A 32-byte header: "TBRC", version (2 bytes), precision (1: the build's
// tbPos in doubles), header size, total size (4), length units per metre (float), checksum (8), the
// snapshot's size (4) and the steps recorded (4). Then the snapshot image (its own header and
// checksum), then records: an opcode (1 byte), the payload's size (4), the payload. An API call's
// payload is its arguments in the order of its prototype (recording_args.c); a step's is dt,
// sub-steps and the hash; a query's is described in recording_queries.c; the stop record's is the
// union of the world's bounds over the steps. The
// checksum is 64-bit FNV-1a (Fowler, Noll, Vo) over the snapshot and records, then over the
// header's other bytes, so one changed byte anywhere always fails it. The buffer is a sealed
// recording after every record: the payload hash is kept up to the last record, the only one a
// refusal can take back, and the header is rewritten from it.
#include "recording.h"

#include "replay.h"
#include "world.h"

#include "core/core.h"

#include <stdio.h>
#include <string.h>

#if defined(TUMBLE_DOUBLE_PRECISION)
#define TB_RECORDING_PRECISION 1u
#else
#define TB_RECORDING_PRECISION 0u
#endif

#define TB_FNV_OFFSET 14695981039346656037ull
#define TB_FNV_PRIME 1099511628211ull

typedef struct tbRecOp
{
	const char* function;
	const char* kinds;
} tbRecOp;

/// By opcode; a gap in the numbering is an opcode no record may hold.
static const tbRecOp s_ops[] = {
	[0] = {NULL, NULL},
#define TB_REC_OP(code, Name, kinds, ret, call) [code] = {"tb" #Name, kinds},
#include "recording_ops.h"
#undef TB_REC_OP
};

#define TB_REC_OP_COUNT ((int)(sizeof(s_ops) / sizeof(s_ops[0])))
_Static_assert(TB_REC_OP_COUNT <= tb_recStep, "API opcodes stay below those of steps and stops");

/// Recordings attached to a world: while none is, a recorded call costs one test.
static _Atomic int s_recordingCount = 0;

/// The last call recorded on this thread, which an error under its name takes back.
static _Thread_local struct
{
	tbRecording* recording;
	int start;
	int op;
} s_pending;

const char* tbRecordingOpName(int op)
{
	// "tb" and the name in recording_ops.h: the API name without its underscore ("tbBodySetType"
	// for tbBody_SetType), which tbSameCall allows for.
	return op > 0 && op < TB_REC_OP_COUNT ? s_ops[op].function : NULL;
}

const char* tbRecordingOpKinds(int op)
{
	return op > 0 && op < TB_REC_OP_COUNT ? s_ops[op].kinds : NULL;
}

// --------------------------------------------------------------------------------------------
// Checksum and header

static uint64_t tbFnv(uint64_t h, const uint8_t* bytes, int count)
{
	for (int i = 0; i < count; ++i)
	{
		h = (h ^ bytes[i]) * TB_FNV_PRIME;
	}
	return h;
}

/// The checksum from the payload's hash and the header's bytes other than the checksum's own.
static uint64_t tbFinishChecksum(uint64_t payloadHash, const uint8_t* header)
{
	uint64_t h = tbFnv(payloadHash, header, 16);
	return tbFnv(h, header + 24, TB_RECORDING_HEADER_SIZE - 24);
}

static void tbStoreU32(uint8_t* p, uint32_t v)
{
	for (int k = 0; k < 4; ++k)
	{
		p[k] = (uint8_t)(v >> (8 * k));
	}
}

static void tbStoreU64(uint8_t* p, uint64_t v)
{
	tbStoreU32(p, (uint32_t)v);
	tbStoreU32(p + 4, (uint32_t)(v >> 32));
}

uint64_t tbRecordingChecksum(const uint8_t* data, int size)
{
	uint64_t h = tbFnv(TB_FNV_OFFSET, data + TB_RECORDING_HEADER_SIZE, size - TB_RECORDING_HEADER_SIZE);
	return tbFinishChecksum(h, data);
}

void tbRecordingSeal(uint8_t* data, int size)
{
	if (data != NULL && size >= TB_RECORDING_HEADER_SIZE)
	{
		tbStoreU64(data + 16, tbRecordingChecksum(data, size));
	}
}

/// Rewrite the header's size, step count and checksum for the bytes the buffer holds now.
static void tbReseal(tbRecording* rec)
{
	tbStoreU32(rec->data + 8, (uint32_t)rec->size);
	tbStoreU32(rec->data + 28, (uint32_t)rec->stepCount);
	uint64_t h = tbFnv(rec->payloadHash, rec->data + rec->hashedSize, rec->size - rec->hashedSize);
	tbStoreU64(rec->data + 16, tbFinishChecksum(h, rec->data));
}

/// The record that could still be taken back is final: fold it into the payload hash.
static void tbCommitPending(tbRecording* rec)
{
	rec->payloadHash = tbFnv(rec->payloadHash, rec->data + rec->hashedSize, rec->size - rec->hashedSize);
	rec->hashedSize = rec->size;
	if (s_pending.recording == rec)
	{
		s_pending.recording = NULL;
	}
}

static uint32_t tbLoadU32(const uint8_t* p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint64_t tbLoadU64(const uint8_t* p)
{
	return (uint64_t)tbLoadU32(p) | (uint64_t)tbLoadU32(p + 4) << 32;
}

/// The header's checks but the checksum; a message for the first that fails, or NULL.
static const char* tbHeaderProblem(const uint8_t* data, int size, char* message, size_t capacity)
{
	uint32_t version = (uint32_t)data[4] | (uint32_t)data[5] << 8;
	float units;
	uint32_t unitBits = tbLoadU32(data + 12);
	memcpy(&units, &unitBits, sizeof(units));
	if (tbLoadU32(data) != TB_RECORDING_MAGIC)
	{
		snprintf(message, capacity, "the bytes are not a Tumble recording (no \"TBRC\" at the start)");
	}
	else if (version != TB_RECORDING_VERSION || data[7] != TB_RECORDING_HEADER_SIZE)
	{
		snprintf(message, capacity, "the recording has format version %u; this build reads version %u only", version,
				 TB_RECORDING_VERSION);
	}
	else if (data[6] != TB_RECORDING_PRECISION)
	{
		const char* made = data[6] != 0 ? "double-precision" : "float";
		const char* here = TB_RECORDING_PRECISION != 0 ? "double-precision" : "float";
		snprintf(message, capacity, "the recording was made by a %s build; this one is %s", made, here);
	}
	else if (tbLoadU32(data + 8) != (uint32_t)size)
	{
		snprintf(message, capacity, "the recording's header says %u bytes but %d were given (truncated or extended)",
				 tbLoadU32(data + 8), size);
	}
	else if (units != tbGetLengthUnitsPerMeter())
	{
		snprintf(message, capacity, "the recording was made at %g length units per metre, the program uses %g",
				 (double)units, (double)tbGetLengthUnitsPerMeter());
	}
	else
	{
		return NULL;
	}
	return message;
}

bool tbCheckRecordingBytes(const char* f, const uint8_t* data, int size)
{
	char message[256];
	if (data == NULL || size < TB_RECORDING_HEADER_SIZE)
	{
		tbReportError(f, "the recording is %d bytes, shorter than its %d-byte header (truncated or not a recording)",
					  data == NULL ? 0 : size, TB_RECORDING_HEADER_SIZE);
		return false;
	}
	if (tbHeaderProblem(data, size, message, sizeof(message)) != NULL)
	{
		tbReportError(f, "%s", message);
		return false;
	}
	if (tbLoadU64(data + 16) != tbRecordingChecksum(data, size))
	{
		tbReportError(f, "the recording's checksum does not match its bytes (corrupt: changed after it was written)");
		return false;
	}
	uint32_t snapshotSize = tbLoadU32(data + 24);
	if (snapshotSize < 32u || snapshotSize > (uint32_t)(size - TB_RECORDING_HEADER_SIZE))
	{
		tbReportError(f, "the recording's snapshot is %u bytes, beyond the %d bytes after the header", snapshotSize,
					  size - TB_RECORDING_HEADER_SIZE);
		return false;
	}
	return true;
}

// --------------------------------------------------------------------------------------------
// Records

/// Open a record: its opcode and a size filled in by tbEndRecord. Returns the record's start.
static int tbBeginRecord(tbRecording* rec, tbRecBytes* out, int op)
{
	tbCommitPending(rec);
	*out = (tbRecBytes){rec->data, rec->size, rec->capacity};
	uint8_t frame[TB_RECORD_FRAME_SIZE] = {(uint8_t)op, 0, 0, 0, 0};
	tbRecPutBytes(out, frame, TB_RECORD_FRAME_SIZE);
	return rec->size;
}

static void tbEndRecord(tbRecording* rec, tbRecBytes* out, int start)
{
	tbStoreU32(out->data + start + 1, (uint32_t)(out->size - start - TB_RECORD_FRAME_SIZE));
	rec->data = out->data;
	rec->size = out->size;
	rec->capacity = out->capacity;
	tbReseal(rec);
}

void tbRecordingAppend(tbRecording* rec, int op, const uint8_t* payload, int size)
{
	tbRecBytes out;
	int start = tbBeginRecord(rec, &out, op);
	tbRecPutBytes(&out, payload, size);
	tbEndRecord(rec, &out, start);
}

/// The world an argument of kind `kind` names (a world id or an object's id), or NULL.
static tbWorld* tbWorldOfArg(char kind, const void* value)
{
	int index = -1;
	if (kind == 'W')
	{
		tbWorldId id = *(const tbWorldId*)value;
		index = id.index1 - 1;
		tbWorld* world = index >= 0 && index < TB_MAX_WORLDS ? tbGetWorldFromIndex(index) : NULL;
		return world != NULL && world->generation == id.generation ? world : NULL;
	}
	index = ((const tbBodyId*)value)->world0; // every object id has the same layout
	return index < TB_MAX_WORLDS ? tbGetWorldFromIndex(index) : NULL;
}

void tbRecordCall(int op, const void* const* args)
{
	s_pending.recording = NULL;
	if (s_recordingCount == 0)
	{
		return;
	}
	const char* kinds = tbRecordingOpKinds(op);
	tbWorld* world = tbWorldOfArg(kinds[0], args[0]);
	if (world == NULL || world->recording == NULL || world->locked)
	{
		return; // a stale id or a call from inside the step: refused, nothing to record
	}
	tbRecording* rec = world->recording;
	tbRecBytes out;
	int start = tbBeginRecord(rec, &out, op);
	for (int k = 0; kinds[k] != 0; ++k)
	{
		tbRecPutArg(&out, kinds[k], args[k]);
	}
	tbEndRecord(rec, &out, start);
	s_pending.recording = rec;
	s_pending.start = start;
	s_pending.op = op;
}

/// Does the API name `function` (with its underscore, "tbBody_SetType") match the recorded call?
static bool tbSameCall(const char* function, const char* recorded)
{
	for (; *function != 0; ++function)
	{
		if (*function == '_')
		{
			continue;
		}
		if (*function != *recorded)
		{
			return false;
		}
		++recorded;
	}
	return *recorded == 0;
}

/// Core's error observer: a call refused under its own name leaves no record.
static void tbRecordingTakeBack(const char* function)
{
	tbRecording* rec = s_pending.recording;
	if (rec == NULL || function == NULL || tbSameCall(function, tbRecordingOpName(s_pending.op)) == false)
	{
		return;
	}
	rec->size = s_pending.start;
	s_pending.recording = NULL;
	tbReseal(rec);
}

void tbRecordStep(tbWorld* world, float timeStep, int subStepCount)
{
	tbRecording* rec = world->recording;
	tbRecBytes out;
	int start = tbBeginRecord(rec, &out, tb_recStep);
	tbRecPutFloat(&out, timeStep);
	tbRecPutU32(&out, (uint32_t)subStepCount);
	tbRecPutU64(&out, tbWorld_GetStateHash((tbWorldId){(uint16_t)(world->worldId + 1), world->generation}));
	rec->stepCount += 1;
	tbEndRecord(rec, &out, start);
	tbAABB bounds = tbWorld_GetBounds((tbWorldId){(uint16_t)(world->worldId + 1), world->generation});
	rec->bounds = rec->haveBounds ? tbAABB_Union(rec->bounds, bounds) : bounds;
	rec->haveBounds = true;
}

/// The stop record and the world let go of the recording.
static void tbStop(tbWorld* world)
{
	tbRecording* rec = world->recording;
	tbRecBytes out;
	int start = tbBeginRecord(rec, &out, tb_recStop);
	const float* box = &rec->bounds.lowerBound.x;
	for (int k = 0; k < 4; ++k)
	{
		tbRecPutFloat(&out, box[k]);
	}
	tbEndRecord(rec, &out, start);
	tbCommitPending(rec);
	rec->world = TB_NULL_WORLD_ID;
	world->recording = NULL;
	s_recordingCount -= 1;
}

void tbRecordingDetach(tbWorld* world)
{
	if (world->recording != NULL)
	{
		tbStop(world);
	}
}

// --------------------------------------------------------------------------------------------
// The API

tbRecording* tbCreateRecording(int byteCapacity)
{
	if (byteCapacity < 0)
	{
		tbReportError("tbCreateRecording", "byteCapacity is %d; pass 0 or the bytes to reserve", byteCapacity);
		return NULL;
	}
	tbRecording* rec = tbAlloc((int)sizeof(tbRecording));
	memset(rec, 0, sizeof(*rec));
	if (byteCapacity > 0)
	{
		rec->data = tbAlloc(byteCapacity);
		rec->capacity = byteCapacity;
	}
	return rec;
}

void tbDestroyRecording(tbRecording* recording)
{
	if (recording == NULL)
	{
		return;
	}
	if (tbWorld_IsValid(recording->world))
	{
		tbRecordingDetach(tbGetWorldFromIndex(recording->world.index1 - 1));
	}
	if (s_pending.recording == recording)
	{
		s_pending.recording = NULL;
	}
	tbFree(recording->data, recording->capacity);
	tbFree(recording, (int)sizeof(tbRecording));
}

const uint8_t* tbRecording_GetData(const tbRecording* recording)
{
	if (tbCheckPointer("tbRecording_GetData", "recording", recording) == false)
	{
		return NULL;
	}
	return recording->data;
}

int tbRecording_GetSize(const tbRecording* recording)
{
	if (tbCheckPointer("tbRecording_GetSize", "recording", recording) == false)
	{
		return 0;
	}
	return recording->size;
}

/// The checks of tbWorld_StartRecording; the world, or NULL after reporting why.
static tbWorld* tbCheckStart(tbWorldId worldId, const tbRecording* recording)
{
	const char* f = "tbWorld_StartRecording";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL || tbCheckPointer(f, "recording", recording) == false)
	{
		return NULL;
	}
	if (world->recording != NULL)
	{
		tbReportError(f, "the world is already recording; stop it first (tbWorld_StopRecording)");
		return NULL;
	}
	if (recording->world.index1 != 0 || recording->size != 0)
	{
		tbReportError(f, "the recording %s; record into a new one from tbCreateRecording",
					  recording->world.index1 != 0 ? "is in use by another world" : "already holds a session");
		return NULL;
	}
	if (tbStructureLocked(world, f, "start recording"))
	{
		return NULL;
	}
	return world;
}

static void tbWriteHeader(uint8_t* header, int snapshotSize)
{
	memset(header, 0, TB_RECORDING_HEADER_SIZE);
	tbStoreU32(header, TB_RECORDING_MAGIC);
	header[4] = (uint8_t)TB_RECORDING_VERSION;
	header[5] = (uint8_t)(TB_RECORDING_VERSION >> 8);
	header[6] = (uint8_t)TB_RECORDING_PRECISION;
	header[7] = (uint8_t)TB_RECORDING_HEADER_SIZE;
	float units = tbGetLengthUnitsPerMeter();
	uint32_t unitBits;
	memcpy(&unitBits, &units, sizeof(unitBits));
	tbStoreU32(header + 12, unitBits);
	tbStoreU32(header + 24, (uint32_t)snapshotSize);
}

void tbWorld_StartRecording(tbWorldId worldId, tbRecording* recording)
{
	tbWorld* world = tbCheckStart(worldId, recording);
	if (world == NULL)
	{
		return;
	}
	int snapshotSize = tbWorld_Snapshot(worldId, NULL, 0);
	if (snapshotSize <= 0 || snapshotSize > INT32_MAX - TB_RECORDING_HEADER_SIZE)
	{
		return; // tbWorld_Snapshot reported why
	}
	int size = TB_RECORDING_HEADER_SIZE + snapshotSize;
	if (size > recording->capacity)
	{
		recording->data = tbGrowAlloc(recording->data, recording->capacity, size);
		recording->capacity = size;
	}
	tbWorld_Snapshot(worldId, recording->data + TB_RECORDING_HEADER_SIZE, snapshotSize);
	tbWriteHeader(recording->data, snapshotSize);
	recording->size = size;
	recording->payloadHash = tbFnv(TB_FNV_OFFSET, recording->data + TB_RECORDING_HEADER_SIZE, snapshotSize);
	recording->hashedSize = size;
	recording->stepCount = 0;
	recording->haveBounds = false;
	recording->bounds = (tbAABB){{0.0f, 0.0f}, {0.0f, 0.0f}};
	tbReseal(recording);
	recording->world = worldId;
	world->recording = recording;
	tbSetErrorObserver(tbRecordingTakeBack);
	s_recordingCount += 1;
}

void tbWorld_StopRecording(tbWorldId worldId)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_StopRecording");
	if (world == NULL)
	{
		return;
	}
	if (world->recording == NULL)
	{
		tbReportError("tbWorld_StopRecording", "the world is not recording");
		return;
	}
	tbStop(world);
}

bool tbSaveRecordingToFile(const tbRecording* recording, const char* path)
{
	const char* f = "tbSaveRecordingToFile";
	if (tbCheckPointer(f, "recording", recording) == false || tbCheckPointer(f, "path", path) == false)
	{
		return false;
	}
	if (recording->size == 0)
	{
		tbReportError(f, "the recording is empty; start one with tbWorld_StartRecording");
		return false;
	}
	FILE* file = fopen(path, "wb");
	if (file == NULL)
	{
		tbReportError(f, "cannot open '%s' for writing", path);
		return false;
	}
	size_t written = fwrite(recording->data, 1, (size_t)recording->size, file);
	bool closed = fclose(file) == 0;
	if (written != (size_t)recording->size || closed == false)
	{
		tbReportError(f, "writing '%s' failed after %zu of %d bytes", path, written, recording->size);
		return false;
	}
	return true;
}

/// The whole of a file in a new buffer (NULL when empty) of *size bytes; false after reporting why.
static bool tbReadFile(const char* f, const char* path, uint8_t** data, int* size)
{
	*data = NULL;
	*size = 0;
	FILE* file = fopen(path, "rb");
	if (file == NULL)
	{
		tbReportError(f, "cannot open '%s' for reading", path);
		return false;
	}
	long length = fseek(file, 0, SEEK_END) == 0 ? ftell(file) : -1;
	if (length < 0 || length > INT32_MAX || fseek(file, 0, SEEK_SET) != 0)
	{
		fclose(file);
		tbReportError(f, "cannot read the size of '%s' (or it is beyond what an int counts)", path);
		return false;
	}
	*data = length > 0 ? tbAlloc((int)length) : NULL;
	size_t read = length > 0 ? fread(*data, 1, (size_t)length, file) : 0;
	fclose(file);
	if (read != (size_t)length)
	{
		tbFree(*data, (int)length);
		*data = NULL;
		tbReportError(f, "reading '%s' failed after %zu of %ld bytes", path, read, length);
		return false;
	}
	*size = (int)length;
	return true;
}

tbRecording* tbLoadRecordingFromFile(const char* path)
{
	const char* f = "tbLoadRecordingFromFile";
	uint8_t* data = NULL;
	int size = 0;
	if (tbCheckPointer(f, "path", path) == false || tbReadFile(f, path, &data, &size) == false)
	{
		return NULL;
	}
	tbReplayInfo info;
	if (tbReplayCheck(f, data, size, &info) == false)
	{
		tbFree(data, size);
		return NULL;
	}
	tbRecording* rec = tbAlloc((int)sizeof(tbRecording));
	memset(rec, 0, sizeof(*rec));
	rec->data = data;
	rec->size = size;
	rec->capacity = size;
	rec->hashedSize = size;
	rec->payloadHash = tbFnv(TB_FNV_OFFSET, data + TB_RECORDING_HEADER_SIZE, size - TB_RECORDING_HEADER_SIZE);
	rec->stepCount = (int)tbLoadU32(data + 28);
	return rec;
}
