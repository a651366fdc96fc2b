// Internal: playing a recording (replay.c) for the player (rec_player.c) and tbValidateReplay.
#pragma once

#include "tumble/tumble.h"

#include <stdbool.h>
#include <stdint.h>

/// What a recording holds, from one walk over its records when it is opened.
typedef struct tbReplayInfo
{
	int frameCount;
	float timeStep;
	int subStepCount;
	tbAABB bounds;
	int recordsStart; ///< the first record's offset (after the snapshot)
} tbReplayInfo;

/// A recorded query of the frame being shown, and where its results start in the hit list.
typedef struct tbReplayQuery
{
	tbRecQueryInfo info;
	int firstHit;
} tbReplayQuery;

/// A recording being played into its world. The bytes belong to the caller and must outlive it.
typedef struct tbReplay
{
	const uint8_t* data;
	int size;
	tbReplayInfo info;
	tbWorldId world;
	int cursor;		  ///< the next record's offset
	int frame;		  ///< steps replayed
	int divergeFrame; ///< the first step whose hash differed, or -1
	bool failed;	  ///< a record could not be played (reported): nothing more plays
	/// Bodies in creation order (the snapshot's in id order first); destroyed ones null.
	tbBodyId* bodies;
	int bodyCount, bodyCapacity;
	/// The queries recorded before the step replayed last (before the first step until then), with
	/// their results, ids mapped to the replay world. Stale once the step is taken: the next frame's
	/// replace them.
	tbReplayQuery* queries;
	int queryCount, queryCapacity;
	tbRecQueryHit* hits;
	int hitCount, hitCapacity;
	bool queriesStale;
} tbReplay;

/// Check a recording's bytes (recording.c's checks) and walk its records' frames, filling info;
/// false after reporting the first problem to `function`.
bool tbReplayCheck(const char* function, const uint8_t* data, int size, tbReplayInfo* info);

/// Check the bytes and walk their records (reporting the first problem to `function`), then make
/// the replay world from the snapshot and play the calls made before the first step. False when
/// refused; the replay then holds nothing.
bool tbReplayOpen(tbReplay* replay, const char* function, const uint8_t* data, int size, int workerCount);

/// Play the calls up to the next step and take it. False at the end or after a record that could
/// not be played (reported to `function`).
bool tbReplayStep(tbReplay* replay, const char* function);

/// Back to the snapshot the recording starts from, in the same world, and the calls before the
/// first step played again.
void tbReplayRestart(tbReplay* replay);

/// Free the world and the body list.
void tbReplayClose(tbReplay* replay);

/// The body list grown to hold count ids.
void tbReplayReserveBodies(tbReplay* replay, int count);
