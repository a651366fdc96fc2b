// Internal: recordings (recording.c writes them, replay.c reads them, recording_args.c encodes the
// calls' arguments). The format is described in recording.c.
#pragma once

#include "tumble/tumble.h"

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

struct tbWorld;

#define TB_RECORDING_MAGIC 0x43524254u // "TBRC" as bytes
/// Any change to the header, the framing, the op list (recording_ops.h) or an argument's encoding
/// is a new version: a reader refuses every version but its own rather than misread one.
#define TB_RECORDING_VERSION 1u
#define TB_RECORDING_HEADER_SIZE 32
/// A record's frame: its opcode (1 byte) and its payload's size (4 bytes).
#define TB_RECORD_FRAME_SIZE 5

/// The records that are not API calls. API calls take the opcodes 1 to 255 - 3 in the order of
/// recording_ops.h.
enum
{
	tb_recQuery = 252, ///< a spatial query and its results (recording_queries.c), for the player to show
	tb_recStep = 253,  ///< dt, sub-steps, then the state hash the step ended on
	tb_recStop = 254, ///< the union of the world's bounds over the recorded steps
};

/// The API calls that are recorded, numbered from 1 in the order of recording_ops.h.
enum
{
	tb_recNone = 0,
#define TB_REC_OP(code, Name, kinds, ret, call) tb_rec##Name = code,
#include "recording_ops.h"
#undef TB_REC_OP
};

/// A recording buffer: a sealed recording at every moment (the header's size, step count and
/// checksum are rewritten after each record), so tbRecording_GetData never needs to finish it.
struct tbRecording
{
	uint8_t* data;
	int size;
	int capacity;
	tbWorldId world;	  ///< the world recording into it, or null
	int stepCount;		  ///< tb_recStep records
	uint64_t payloadHash; ///< checksum state over the payload up to hashedSize
	int hashedSize;		  ///< bytes the payload hash covers: all but the last record, which an error may take back
	tbAABB bounds;		  ///< union of the world's bounds after each recorded step
	bool haveBounds;
	atomic_flag queryLock; ///< queries may run on several threads at once: one writes at a time
};

/// Record an API call at its entry (before any check): the call's opcode, then a pointer to each
/// argument (pointer arguments as they are), in an array so that each converts to a const void*.
/// A call that reports an error through tbReportError under its own name takes its record back
/// (recording.c), so a recording holds only the calls that were accepted, which replay the same way.
#define TB_RECORD(Name, ...) tbRecordCall(tb_rec##Name, (const void* const[]){__VA_ARGS__})
void tbRecordCall(int op, const void* const* args);

/// After a step of a recording world: the step's record with the hash it ended on.
void tbRecordStep(struct tbWorld* world, float timeStep, int subStepCount);

/// Append a whole record (a query's, whose payload was built aside while the query ran).
void tbRecordingAppend(tbRecording* recording, int op, const uint8_t* payload, int size);

/// A world that is destroyed while recording stops first.
void tbRecordingDetach(struct tbWorld* world);

/// Checksum of a recording's bytes (at least the header), as its header holds it.
uint64_t tbRecordingChecksum(const uint8_t* data, int size);

/// Write the checksum of a recording of size bytes into its header (for tests and fuzzing, which
/// change bytes behind the checksum to reach the checks that come after it).
void tbRecordingSeal(uint8_t* data, int size);

/// The checks of a recording's bytes (header, version, precision, size, length units, checksum,
/// snapshot size); false after reporting the first problem to `function`.
bool tbCheckRecordingBytes(const char* function, const uint8_t* data, int size);

/// The API name and argument kinds of an opcode (NULL for an unknown one). Kinds: recording_args.c.
const char* tbRecordingOpName(int op);
const char* tbRecordingOpKinds(int op);

// Arguments (recording_args.c) ---------------------------------------------------------------


/// A growable byte array the encoder appends to.
typedef struct tbRecBytes
{
	uint8_t* data;
	int size;
	int capacity;
} tbRecBytes;

void tbRecPutBytes(tbRecBytes* out, const void* bytes, int count);
void tbRecPutU32(tbRecBytes* out, uint32_t value);
void tbRecPutU64(tbRecBytes* out, uint64_t value);
void tbRecPutFloat(tbRecBytes* out, float value);

/// Append an argument of kind `kind` that `value` points to.
void tbRecPutArg(tbRecBytes* out, char kind, const void* value);

/// A decoded argument, any kind. Ids are the recorded ones (index only); replay.c maps them.
typedef struct tbRecArg
{
	bool present; ///< false: a NULL pointer argument
	union
	{
		tbWorldId world;
		tbBodyId body;
		tbShapeId shape;
		tbChainId chain;
		tbJointId joint;
		float f;
		bool b;
		int i;
		uint64_t u;
		tbVec2 v;
		tbRot r;
		tbPos p;
		tbTransform x;
		tbWorldTransform X;
		tbMassData mass;
		tbMotionLocks locks;
		tbFilter filter;
		const char* name;
		tbBodyDef bodyDef;
		tbShapeDef shapeDef;
		tbCircle circle;
		tbCapsule capsule;
		tbPolygon polygon;
		tbSegment segment;
		tbChainSegment chainSegment;
		tbGeometry geometry;
		tbChainDef chainDef;
		tbSurfaceMaterial material;
		tbExplosionDef explosion;
		tbDistanceJointDef distance;
		tbFilterJointDef filterJoint;
		tbMotorJointDef motor;
		tbMoverJointDef mover;
		tbPogoJointDef pogo;
		tbPrismaticJointDef prismatic;
		tbRevoluteJointDef revolute;
		tbWeldJointDef weld;
		tbWheelJointDef wheel;
	};
} tbRecArg;

/// Reads a record's payload. Chain points and materials are decoded into `scratch` (freed by
/// tbRecArgsFree); names point into the payload, which must outlive the call.
typedef struct tbRecArgReader
{
	const uint8_t* data;
	int size;
	int offset;
	bool failed;
	void* scratch[2];
	int scratchBytes[2];
} tbRecArgReader;

/// Decode an argument of kind `kind`; false (reader failed) when the payload ends early or holds
/// a value no encoder writes.
bool tbRecGetArg(tbRecArgReader* r, char kind, tbRecArg* out);
bool tbRecGetU32(tbRecArgReader* r, uint32_t* value);
bool tbRecGetU64(tbRecArgReader* r, uint64_t* value);
bool tbRecGetFloat(tbRecArgReader* r, float* value);
void tbRecArgsFree(tbRecArgReader* r);

/// The id fields of an argument of kind `kind` (a joint definition's bodies), for replay.c to map.
/// Fills ids with pointers to them and returns how many (at most 2).
int tbRecArgBodyIds(char kind, tbRecArg* arg, tbBodyId* ids[2]);

// Queries (recording_queries.c) ----------------------------------------------------------------

/// A spatial query being recorded: begun by the query, told each result its callback reports,
/// written as one record when the query ends. Queries change nothing, so replay does not run them
/// again: the player shows them, frame by frame.
typedef struct tbQueryLog
{
	struct tbRecording* recording;
	tbRecQueryInfo info;
	tbRecBytes hits;
	int hitCount;
} tbQueryLog;

/// The log of a query of the world (info: its kind and inputs, ids as the world's), or NULL when
/// the world is not recording (or is stepping). Every function below takes a NULL log.
tbQueryLog* tbQueryLogBegin(tbQueryLog* log, const struct tbWorld* world, const tbRecQueryInfo* info);
void tbQueryLogHit(tbQueryLog* log, tbShapeId shape, tbPos point, tbVec2 normal, float fraction);
void tbQueryLogEnd(tbQueryLog* log);

/// Decode a query record's payload into info and up to hitCapacity hits (ids as recorded: index
/// only); false when it does not decode or holds more hits. A payload of n bytes holds fewer than
/// n / TB_QUERY_HIT_MIN_BYTES hits.
#define TB_QUERY_HIT_MIN_BYTES 20
bool tbQueryLogRead(const uint8_t* payload, int size, tbRecQueryInfo* info, tbRecQueryHit* hits, int hitCapacity);
