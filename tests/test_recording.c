// Recording and replay (Box2D v3.2's recording and replay groups): a 600-step session with
// creations, destructions and setter calls recorded, saved, loaded and replayed with the original's
// state hash at every step; refused recordings (flipped byte, truncated, other version) and bad
// calls; a changed input found at its step; the player's seeks; two workers; memory back to zero.
#include <criterion/criterion.h>

#include "error_recorder.h"
#include "world/recording.h"

#include "tumble/tumble.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REC_STEPS 600
#define REC_DT (1.0f / 60.0f)
#define REC_SUBSTEPS 4
#define REC_CHANGED_STEP 300

// ---------------------------------------------------------------------------------------------
// Two workers: each task on a thread of its own, joined by finishTask (the test's own task system:
// the samples' one is not built in every configuration this file runs in).

typedef struct Task
{
	pthread_t thread;
	tbTaskCallback* task;
	void* context;
} Task;

static void* RunTask(void* argument)
{
	Task* t = argument;
	t->task(t->context);
	return NULL;
}

static void* EnqueueTask(tbTaskCallback* task, void* taskContext, void* userContext)
{
	(void)userContext;
	Task* t = malloc(sizeof(Task));
	t->task = task;
	t->context = taskContext;
	if (pthread_create(&t->thread, NULL, RunTask, t) != 0)
	{
		task(taskContext);
		free(t);
		return NULL;
	}
	return t;
}

static void FinishTask(void* userTask, void* userContext)
{
	(void)userContext;
	Task* t = userTask;
	pthread_join(t->thread, NULL);
	free(t);
}

static tbWorldId MakeWorld(int workerCount)
{
	tbWorldDef def = tbDefaultWorldDef();
	if (workerCount > 1)
	{
		def.workerCount = workerCount;
		def.enqueueTask = EnqueueTask;
		def.finishTask = FinishTask;
	}
	return tbCreateWorld(&def);
}

// ---------------------------------------------------------------------------------------------
// The session: a ground, a few joined bodies, and every step some calls from a fixed script.

typedef struct Session
{
	tbWorldId world;
	tbBodyId ground, kinematic, crate, wheel, arm;
	tbJointId revolute, distance, prismatic, wheelJoint, weld, motor;
	tbShapeId extraShape;
	tbChainId chain;
	tbBodyId spawned[64];
	int spawnedCount, destroyedCount;
	int refusedCalls; ///< calls the script made that were refused (not recorded)
	tbRayResult ray;  ///< the last ray of Look
	int overlaps;	  ///< shapes the last overlap of Look found
} Session;

static tbBodyId Body(tbWorldId world, tbBodyType type, float x, float y)
{
	tbBodyDef def = tbDefaultBodyDef();
	def.type = type;
	def.position = (tbPos){x, y};
	def.name = "recorded";
	return tbCreateBody(world, &def);
}

static void BuildGround(Session* s)
{
	tbShapeDef shapeDef = tbDefaultShapeDef();
	s->ground = Body(s->world, tb_staticBody, 0.0f, 0.0f);
	tbSegment floor = {{-40.0f, 0.0f}, {40.0f, 0.0f}};
	tbCreateSegmentShape(s->ground, &shapeDef, &floor);
	tbPolygon wall = tbMakeOffsetBox(0.5f, 5.0f, (tbVec2){-20.0f, 5.0f}, tbMakeRot(0.0f));
	tbCreatePolygonShape(s->ground, &shapeDef, &wall);
	s->kinematic = Body(s->world, tb_kinematicBody, 10.0f, 3.0f);
	tbPolygon paddle = tbMakeBox(2.0f, 0.2f);
	tbCreatePolygonShape(s->kinematic, &shapeDef, &paddle);
}

static void BuildJoints(Session* s)
{
	tbShapeDef shapeDef = tbDefaultShapeDef();
	s->crate = Body(s->world, tb_dynamicBody, -5.0f, 4.0f);
	tbPolygon box = tbMakeRoundedBox(0.5f, 0.5f, 0.05f);
	tbCreatePolygonShape(s->crate, &shapeDef, &box);
	tbCircle lump = {{0.5f, 0.5f}, 0.3f};
	s->extraShape = tbCreateCircleShape(s->crate, &shapeDef, &lump);
	s->wheel = Body(s->world, tb_dynamicBody, -3.0f, 2.0f);
	tbCircle tyre = {{0.0f, 0.0f}, 0.5f};
	tbCreateCircleShape(s->wheel, &shapeDef, &tyre);
	s->arm = Body(s->world, tb_dynamicBody, 3.0f, 6.0f);
	tbCapsule rod = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.2f};
	tbCreateCapsuleShape(s->arm, &shapeDef, &rod);

	tbRevoluteJointDef revolute = tbDefaultRevoluteJointDef();
	revolute.base.bodyIdA = s->ground;
	revolute.base.bodyIdB = s->arm;
	revolute.base.localFrameA.p = (tbVec2){3.0f, 6.0f};
	revolute.base.localFrameB.p = (tbVec2){-1.0f, 0.0f};
	s->revolute = tbCreateRevoluteJoint(s->world, &revolute);
	tbDistanceJointDef distance = tbDefaultDistanceJointDef();
	distance.base.bodyIdA = s->crate;
	distance.base.bodyIdB = s->wheel;
	distance.length = 2.0f;
	distance.enableSpring = true;
	distance.hertz = 2.0f;
	s->distance = tbCreateDistanceJoint(s->world, &distance);
	tbPrismaticJointDef prismatic = tbDefaultPrismaticJointDef();
	prismatic.base.bodyIdA = s->ground;
	prismatic.base.bodyIdB = s->crate;
	prismatic.base.localFrameA.p = (tbVec2){-5.0f, 4.0f};
	s->prismatic = tbCreatePrismaticJoint(s->world, &prismatic);
	tbWheelJointDef wheel = tbDefaultWheelJointDef();
	wheel.base.bodyIdA = s->crate;
	wheel.base.bodyIdB = s->wheel;
	wheel.base.localFrameA.p = (tbVec2){2.0f, -2.0f};
	s->wheelJoint = tbCreateWheelJoint(s->world, &wheel);
	tbWeldJointDef weld = tbDefaultWeldJointDef();
	weld.base.bodyIdA = s->arm;
	weld.base.bodyIdB = s->crate;
	weld.linearHertz = 3.0f;
	s->weld = tbCreateWeldJoint(s->world, &weld);
	tbMotorJointDef motor = tbDefaultMotorJointDef();
	motor.base.bodyIdA = s->ground;
	motor.base.bodyIdB = s->wheel;
	motor.maxVelocityForce = 10.0f;
	s->motor = tbCreateMotorJoint(s->world, &motor);
}

/// A new body every 20 steps, shapes of each kind in turn; the oldest goes every 50 steps from 100.
static void SpawnAndDestroy(Session* s, int i)
{
	tbShapeDef shapeDef = tbDefaultShapeDef();
	if (i % 20 == 5 && s->spawnedCount < 64)
	{
		tbBodyId id = Body(s->world, tb_dynamicBody, -10.0f + 0.7f * (float)(s->spawnedCount % 20), 8.0f);
		int kind = s->spawnedCount % 4;
		if (kind == 0)
		{
			tbCircle c = {{0.0f, 0.0f}, 0.4f};
			tbCreateCircleShape(id, &shapeDef, &c);
		}
		else if (kind == 1)
		{
			tbPolygon p = tbMakeBox(0.3f, 0.4f);
			tbCreatePolygonShape(id, &shapeDef, &p);
		}
		else if (kind == 2)
		{
			tbCapsule c = {{0.0f, -0.3f}, {0.0f, 0.3f}, 0.25f};
			tbCreateCapsuleShape(id, &shapeDef, &c);
		}
		else
		{
			tbGeometry g = {.type = tb_circleShape, .circle = {{0.1f, 0.0f}, 0.35f}};
			tbCreateShape(id, &shapeDef, &g);
		}
		s->spawned[s->spawnedCount++] = id;
	}
	if (i >= 100 && i % 50 == 0 && s->destroyedCount < s->spawnedCount)
	{
		tbDestroyBody(s->spawned[s->destroyedCount++]);
	}
}

/// Velocities, impulses, forces and transforms.
static void Push(Session* s, int i)
{
	if (i % 7 == 0)
	{
		tbBody_SetLinearVelocity(s->wheel, (tbVec2){0.5f * (float)(i % 5) - 1.0f, 0.2f});
	}
	if (i % 11 == 0)
	{
		tbBody_SetAngularVelocity(s->arm, 0.1f * (float)(i % 3));
	}
	if (i % 13 == 0)
	{
		tbBody_ApplyLinearImpulse(s->crate, (tbVec2){0.3f, 1.0f}, tbBody_GetPosition(s->crate), true);
	}
	if (i % 17 == 0)
	{
		tbBody_ApplyForceToCenter(s->wheel, (tbVec2){5.0f, 0.0f}, true);
		tbBody_ApplyTorque(s->arm, 2.0f, true);
	}
	if (i % 30 == 15)
	{
		tbBody_SetTransform(s->kinematic, (tbPos){10.0f + 0.01f * (float)i, 3.0f}, tbMakeRot(0.002f * (float)i));
		tbBody_SetLinearVelocity(s->kinematic, (tbVec2){0.0f, 0.1f * (float)((i / 30) % 3) - 0.1f});
	}
	if (i == REC_CHANGED_STEP - 1)
	{
		tbBody_SetLinearVelocity(s->crate, (tbVec2){2.0f, 3.0f}); // the input test_changed_input alters
	}
}

/// Setters of joints, shapes, bodies and the world at fixed steps.
static void Tune(Session* s, int i)
{
	switch (i)
	{
		case 40:
			tbRevoluteJoint_EnableMotor(s->revolute, true);
			tbRevoluteJoint_SetMotorSpeed(s->revolute, 1.5f);
			tbRevoluteJoint_SetMaxMotorTorque(s->revolute, 50.0f);
			break;
		case 80:
			tbDistanceJoint_SetLength(s->distance, 2.5f);
			tbPrismaticJoint_EnableLimit(s->prismatic, true);
			tbPrismaticJoint_SetLimits(s->prismatic, -2.0f, 2.0f);
			tbWheelJoint_SetSpringHertz(s->wheelJoint, 3.0f);
			tbMotorJoint_SetLinearVelocity(s->motor, (tbVec2){0.5f, 0.0f});
			break;
		case 120:
			tbShape_SetFriction(s->extraShape, 0.2f);
			tbShape_SetRestitution(s->extraShape, 0.5f);
			tbShape_SetDensity(s->extraShape, 2.0f, true);
			tbBody_SetLinearDamping(s->wheel, 0.1f);
			tbBody_SetAngularDamping(s->arm, 0.2f);
			break;
		case 150:
			tbDestroyJoint(s->weld);
			break;
		case 160:
			tbDestroyShape(s->extraShape, true);
			break;
		case 200:
		{
			tbExplosionDef blast = tbDefaultExplosionDef();
			blast.position = (tbPos){-4.0f, 1.0f};
			blast.radius = 3.0f;
			blast.impulsePerLength = 2.0f;
			tbWorld_Explode(s->world, &blast);
			break;
		}
		case 250:
			tbWorld_SetGravity(s->world, (tbVec2){0.5f, -9.0f});
			break;
		case 270:
			tbBody_SetType(s->arm, tb_kinematicBody);
			break;
		case 330:
			tbBody_SetType(s->arm, tb_dynamicBody);
			tbJoint_SetCollideConnected(s->revolute, true);
			break;
		default:
			break;
	}
}

static void TuneLater(Session* s, int i)
{
	if (i == 350)
	{
		tbVec2 points[5] = {{30.0f, 5.0f}, {25.0f, 0.5f}, {20.0f, 0.2f}, {15.0f, 0.5f}, {12.0f, 4.0f}};
		tbChainDef def = tbDefaultChainDef();
		def.points = points;
		def.count = 5;
		s->chain = tbCreateChain(s->ground, &def);
	}
	else if (i == 420)
	{
		tbDestroyChain(s->chain);
		tbMassData mass = {2.0f, {0.1f, 0.0f}, 0.5f};
		tbBody_SetMassData(s->wheel, mass);
	}
	else if (i == 470)
	{
		tbBody_SetMotionLocks(s->arm, (tbMotionLocks){false, false, true});
		tbBody_SetBullet(s->wheel, true);
		tbFilter filter = tbDefaultFilter();
		filter.groupIndex = -1;
		tbShapeId shapes[4];
		int count = tbBody_GetShapes(s->crate, shapes, 4);
		cr_assert_gt(count, 0);
		tbShape_SetFilter(shapes[0], filter);
		tbPolygon bigger = tbMakeBox(0.6f, 0.6f);
		tbShape_SetPolygon(shapes[0], &bigger);
	}
	else if (i == 520)
	{
		tbBody_SetAwake(s->crate, true);
		tbWorld_EnableSleeping(s->world, false);
	}
}

static bool CountOverlap(tbShapeId shapeId, void* context)
{
	(void)shapeId;
	*(int*)context += 1;
	return true;
}

/// Queries every 10 steps (recorded for the player, changing nothing).
static void Look(Session* s, int i)
{
	if (i % 10 != 3)
	{
		return;
	}
	tbPos above = tbBody_GetPosition(s->crate);
	above.y += 5.0f;
	s->ray = tbWorld_CastRayClosest(s->world, above, (tbVec2){0.0f, -20.0f}, tbDefaultQueryFilter());
	tbAABB box = {{-3.0f, -3.0f}, {3.0f, 3.0f}};
	s->overlaps = 0;
	tbPos centre = tbBody_GetPosition(s->crate);
	tbWorld_OverlapAABB(s->world, centre, box, tbDefaultQueryFilter(), CountOverlap, &s->overlaps);
	tbShapeId shapes[2];
	if (tbBody_GetShapes(s->wheel, shapes, 2) > 0)
	{
		tbShape_TestPoint(shapes[0], tbBody_GetPosition(s->wheel));
	}
}

/// Calls the API refuses: nothing of them may reach the recording.
static void Refused(Session* s, int i)
{
	if (i == 60 || i == 260)
	{
		float nan = strtof("nan", NULL);
		tbBody_SetLinearVelocity(s->wheel, (tbVec2){nan, 0.0f});
		tbShape_SetFriction(s->extraShape, -1.0f);
		tbCircle bad = {{0.0f, 0.0f}, -1.0f};
		tbShapeDef shapeDef = tbDefaultShapeDef();
		tbCreateCircleShape(s->crate, &shapeDef, &bad);
		s->refusedCalls += 3; // at 260 the shape is gone: SetFriction is refused for its stale id
	}
}

/// Run the session's script for `steps` steps, writing the state hash after each into hashes.
static void RunSession(Session* s, int steps, uint64_t* hashes)
{
	for (int i = 0; i < steps; ++i)
	{
		SpawnAndDestroy(s, i);
		Push(s, i);
		Tune(s, i);
		TuneLater(s, i);
		Refused(s, i);
		Look(s, i);
		cr_assert(tbWorld_Step(s->world, REC_DT, REC_SUBSTEPS));
		hashes[i] = tbWorld_GetStateHash(s->world);
	}
}

/// The last ray and overlap count of the last session recorded (Look, at i = 593).
static tbRayResult s_lastRay;
static int s_lastOverlaps;

/// A world, a recording of a session of REC_STEPS steps in it, and the hash after each step.
static tbRecording* RecordSession(int workerCount, uint64_t* hashes)
{
	Session s;
	memset(&s, 0, sizeof(s));
	s.world = MakeWorld(workerCount);
	BuildGround(&s);
	tbRecording* recording = tbCreateRecording(0);
	tbWorld_StartRecording(s.world, recording);
	cr_assert_gt(tbRecording_GetSize(recording), TB_RECORDING_HEADER_SIZE);
	BuildJoints(&s);
	int errors = s_errors;
	RunSession(&s, REC_STEPS, hashes);
	cr_assert_eq(s_errors - errors, s.refusedCalls, "the script's refused calls: %d errors", s_errors - errors);
	s_lastRay = s.ray;
	s_lastOverlaps = s.overlaps;
	tbWorld_StopRecording(s.world);
	tbDestroyWorld(s.world);
	return recording;
}

static uint64_t s_hashes[REC_STEPS];

/// Play a recording with the player and compare every step's hash with `hashes`.
static void ReplayMatches(const uint8_t* data, int size, int workerCount, const uint64_t* hashes)
{
	tbRecPlayer* player = tbRecPlayer_Create(data, size, workerCount);
	cr_assert_not_null(player);
	tbRecPlayerInfo info = tbRecPlayer_GetInfo(player);
	cr_assert_eq(info.frameCount, REC_STEPS);
	cr_assert_eq(info.subStepCount, REC_SUBSTEPS);
	cr_assert_eq(info.timeStep, REC_DT);
	cr_assert_eq(info.lengthScale, 1.0f);
	cr_assert_lt(info.bounds.lowerBound.x, info.bounds.upperBound.x);
	tbWorldId world = tbRecPlayer_GetWorldId(player);
	int frames = 0;
	while (tbRecPlayer_StepFrame(player))
	{
		cr_assert_eq(tbWorld_GetStateHash(world), hashes[frames], "step %d: the replay differs", frames + 1);
		frames += 1;
		cr_assert_eq(tbRecPlayer_GetFrame(player), frames);
	}
	cr_assert_eq(frames, REC_STEPS);
	cr_assert(tbRecPlayer_IsAtEnd(player));
	cr_assert_not(tbRecPlayer_HasDiverged(player));
	cr_assert_eq(tbRecPlayer_GetDivergeFrame(player), -1);
	tbRecPlayer_Destroy(player);
}

Test(recording, session_saved_loaded_and_replayed_bit_identically, .init = SetupErrors, .fini = TeardownErrors)
{
	tbRecording* recording = RecordSession(1, s_hashes);
	const char* path = "test_recording_session.tbrec";
	cr_assert(tbSaveRecordingToFile(recording, path));
	tbRecording* loaded = tbLoadRecordingFromFile(path);
	cr_assert_not_null(loaded);
	cr_assert_eq(tbRecording_GetSize(loaded), tbRecording_GetSize(recording));
	cr_assert_eq(memcmp(tbRecording_GetData(loaded), tbRecording_GetData(recording),
						(size_t)tbRecording_GetSize(recording)),
				 0);
	int errors = s_errors;
	ReplayMatches(tbRecording_GetData(loaded), tbRecording_GetSize(loaded), 0, s_hashes);
	cr_assert(tbValidateReplay(tbRecording_GetData(loaded), tbRecording_GetSize(loaded), 0));
	cr_assert_eq(s_errors, errors, "a faithful replay reports nothing: %s", s_lastError);
	remove(path);

	// The same calls record the same bytes.
	uint64_t again[REC_STEPS];
	tbRecording* second = RecordSession(1, again);
	cr_assert_eq(memcmp(again, s_hashes, sizeof(again)), 0);
	cr_assert_eq(tbRecording_GetSize(second), tbRecording_GetSize(recording));
	cr_assert_eq(memcmp(tbRecording_GetData(second), tbRecording_GetData(recording),
						(size_t)tbRecording_GetSize(recording)),
				 0);
	tbDestroyRecording(second);
	tbDestroyRecording(loaded);
	tbDestroyRecording(recording);
	cr_assert_eq(tbGetByteCount(), 0);
}

Test(recording, two_workers_record_and_replay_the_serial_trajectory, .init = SetupErrors, .fini = TeardownErrors)
{
	tbRecording* serial = RecordSession(1, s_hashes);
	uint64_t hashes[REC_STEPS];
	tbRecording* parallel = RecordSession(2, hashes);
	cr_assert_eq(memcmp(hashes, s_hashes, sizeof(hashes)), 0, "two workers: the serial trajectory");
	const uint8_t* data = tbRecording_GetData(parallel);
	int size = tbRecording_GetSize(parallel);
	cr_assert(tbValidateReplay(data, size, 2));
	cr_assert(tbValidateReplay(data, size, 0));
	ReplayMatches(data, size, 2, s_hashes);
	tbDestroyRecording(parallel);
	tbDestroyRecording(serial);
	cr_assert_eq(tbGetByteCount(), 0);
}

// ---------------------------------------------------------------------------------------------
// Refusals

/// A copy of a recording's bytes.
static uint8_t* CopyBytes(const tbRecording* recording, int* size)
{
	*size = tbRecording_GetSize(recording);
	uint8_t* bytes = malloc((size_t)*size);
	memcpy(bytes, tbRecording_GetData(recording), (size_t)*size);
	return bytes;
}

/// Refused by validation, the player and loading from a file, each with a message holding `what`.
static void ExpectRefused(const uint8_t* bytes, int size, const char* what)
{
	int before = s_errors;
	cr_assert_not(tbValidateReplay(bytes, size, 0));
	ExpectError(before, "tbValidateReplay", what);
	before = s_errors;
	cr_assert_null(tbRecPlayer_Create(bytes, size, 0));
	ExpectError(before, "tbRecPlayer_Create", what);
	const char* path = "test_recording_refused.tbrec";
	FILE* file = fopen(path, "wb");
	cr_assert_not_null(file);
	cr_assert_eq(fwrite(bytes, 1, (size_t)size, file), (size_t)size);
	fclose(file);
	before = s_errors;
	cr_assert_null(tbLoadRecordingFromFile(path));
	ExpectError(before, "tbLoadRecordingFromFile", what);
	remove(path);
}

Test(recording, corrupt_truncated_and_foreign_recordings_are_refused, .init = SetupErrors, .fini = TeardownErrors)
{
	tbRecording* recording = RecordSession(1, s_hashes);
	int size;
	uint8_t* bytes = CopyBytes(recording, &size);

	// A flipped byte anywhere: in the snapshot, in a record, in the header.
	int offsets[4] = {TB_RECORDING_HEADER_SIZE + 40, size / 2, size - 3, 13};
	for (int k = 0; k < 4; ++k)
	{
		bytes[offsets[k]] ^= 0x10;
		ExpectRefused(bytes, size, offsets[k] == 13 ? "length units" : "checksum");
		bytes[offsets[k]] ^= 0x10;
	}
	ExpectRefused(bytes, size - 1, "truncated");
	ExpectRefused(bytes, 20, "truncated");
	ExpectRefused(bytes, 0, "truncated");

	// Another version, sealed: refused for its version, not its checksum.
	bytes[4] = 2;
	tbRecordingSeal(bytes, size);
	ExpectRefused(bytes, size, "version");
	bytes[4] = 1;
	bytes[0] = 'X';
	tbRecordingSeal(bytes, size);
	ExpectRefused(bytes, size, "not a Tumble recording");
	bytes[0] = 'T';

	// A record with an unknown opcode, sealed: found when the records are walked.
	int snapshotSize = bytes[24] | bytes[25] << 8 | bytes[26] << 16 | bytes[27] << 24;
	int first = TB_RECORDING_HEADER_SIZE + snapshotSize;
	uint8_t op = bytes[first];
	bytes[first] = 200;
	tbRecordingSeal(bytes, size);
	ExpectRefused(bytes, size, "opcode 200");
	bytes[first] = op;
	tbRecordingSeal(bytes, size);
	cr_assert(tbValidateReplay(bytes, size, 0));

	// NULL and negative arguments.
	int before = s_errors;
	cr_assert_not(tbValidateReplay(NULL, 100, 0));
	ExpectError(before, "tbValidateReplay", "shorter");
	before = s_errors;
	cr_assert_null(tbRecPlayer_Create(bytes, -1, 0));
	ExpectError(before, "tbRecPlayer_Create", "size");
	before = s_errors;
	cr_assert_null(tbRecPlayer_Create(bytes, size, -3));
	ExpectError(before, "tbRecPlayer_Create", "workerCount");
	before = s_errors;
	cr_assert_not(tbValidateReplay(bytes, size, TB_MAX_WORKERS + 1));
	ExpectError(before, "tbValidateReplay", "workerCount");
	before = s_errors;
	cr_assert_null(tbLoadRecordingFromFile("no/such/dir/recording.tbrec"));
	ExpectError(before, "tbLoadRecordingFromFile", "cannot open");
	before = s_errors;
	cr_assert_not(tbSaveRecordingToFile(recording, "no/such/dir/recording.tbrec"));
	ExpectError(before, "tbSaveRecordingToFile", "cannot open");
	free(bytes);
	tbDestroyRecording(recording);
	cr_assert_eq(tbGetByteCount(), 0);
}

typedef struct QueryStart
{
	tbWorldId world;
	tbRecording* recording;
} QueryStart;

static bool StartFromQuery(tbShapeId shapeId, void* context)
{
	(void)shapeId;
	QueryStart* q = context;
	tbWorld_StartRecording(q->world, q->recording);
	return false;
}

Test(recording, bad_calls_are_refused_and_change_nothing, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = MakeWorld(1);
	tbBodyId body = Body(world, tb_dynamicBody, 0.0f, 1.0f);
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCreateCircleShape(body, &shapeDef, &circle);
	tbRecording* recording = tbCreateRecording(1024);
	int before = s_errors;
	cr_assert_null(tbCreateRecording(-1));
	ExpectError(before, "tbCreateRecording", "byteCapacity");
	before = s_errors;
	tbWorld_StartRecording(world, NULL);
	ExpectError(before, "tbWorld_StartRecording", "recording");
	before = s_errors;
	tbWorld_StartRecording(TB_NULL_WORLD_ID, recording);
	cr_assert_eq(s_errors, before + 1);
	cr_assert_eq(tbRecording_GetSize(recording), 0);

	// A locked world: from inside a query callback.
	QueryStart q = {world, recording};
	tbAABB box = {{-1.0f, 0.0f}, {1.0f, 2.0f}};
	before = s_errors;
	tbWorld_OverlapAABB(world, (tbPos){0.0f, 0.0f}, box, tbDefaultQueryFilter(), StartFromQuery, &q);
	ExpectError(before, "tbWorld_StartRecording", "start recording");
	cr_assert_eq(tbRecording_GetSize(recording), 0);

	// Recording; a second start, a second world on the same buffer, a restore: refused.
	tbWorld_StartRecording(world, recording);
	int size = tbRecording_GetSize(recording);
	cr_assert_gt(size, TB_RECORDING_HEADER_SIZE);
	before = s_errors;
	tbWorld_StartRecording(world, recording);
	ExpectError(before, "tbWorld_StartRecording", "already recording");
	tbWorldId other = MakeWorld(1);
	before = s_errors;
	tbWorld_StartRecording(other, recording);
	ExpectError(before, "tbWorld_StartRecording", "in use");
	uint8_t image[4096];
	int imageSize = tbWorld_Snapshot(world, image, (int)sizeof(image));
	cr_assert_gt(imageSize, 0);
	before = s_errors;
	cr_assert_not(tbWorld_Restore(world, image, imageSize));
	ExpectError(before, "tbWorld_Restore", "recording");

	// Refused calls leave no record: stale ids, bad values.
	tbBodyId gone = Body(world, tb_dynamicBody, 5.0f, 5.0f);
	tbDestroyBody(gone);
	size = tbRecording_GetSize(recording);
	before = s_errors;
	tbBody_SetLinearVelocity(gone, (tbVec2){1.0f, 0.0f});
	tbBody_SetAngularDamping(body, -1.0f);
	tbCreateCircleShape(body, NULL, &circle);
	tbDestroyBody(gone);
	cr_assert_eq(s_errors, before + 4);
	cr_assert_eq(tbRecording_GetSize(recording), size, "refused calls are not recorded");
	// An accepted call is, and a refused one after it takes back only itself.
	tbBody_SetLinearVelocity(body, (tbVec2){1.0f, 0.0f});
	int withCall = tbRecording_GetSize(recording);
	cr_assert_gt(withCall, size);
	tbBody_GetLinearVelocity(gone); // another function's error takes nothing back
	cr_assert_eq(tbRecording_GetSize(recording), withCall);
	cr_assert(tbWorld_Step(world, REC_DT, REC_SUBSTEPS));
	tbWorld_StopRecording(world);
	before = s_errors;
	tbWorld_StopRecording(world);
	ExpectError(before, "tbWorld_StopRecording", "not recording");
	cr_assert(tbValidateReplay(tbRecording_GetData(recording), tbRecording_GetSize(recording), 0));

	// A used buffer is not reused; NULL is refused by the accessors.
	before = s_errors;
	tbWorld_StartRecording(world, recording);
	ExpectError(before, "tbWorld_StartRecording", "already holds");
	before = s_errors;
	cr_assert_null(tbRecording_GetData(NULL));
	cr_assert_eq(tbRecording_GetSize(NULL), 0);
	cr_assert_not(tbSaveRecordingToFile(NULL, "x"));
	cr_assert_null(tbLoadRecordingFromFile(NULL));
	cr_assert_eq(s_errors, before + 4);
	before = s_errors;
	cr_assert_eq(tbRecPlayer_GetFrame(NULL), 0);
	cr_assert_not(tbRecPlayer_StepFrame(NULL));
	cr_assert_eq(s_errors, before + 2);
	tbRecPlayer_Destroy(NULL);
	tbDestroyRecording(NULL);

	// A player whose world the game destroyed stops, reported.
	tbRecPlayer* player = tbRecPlayer_Create(tbRecording_GetData(recording), tbRecording_GetSize(recording), 0);
	cr_assert_not_null(player);
	tbDestroyWorld(tbRecPlayer_GetWorldId(player));
	before = s_errors;
	cr_assert_not(tbRecPlayer_StepFrame(player));
	ExpectError(before, "tbRecPlayer_StepFrame", "destroyed");
	cr_assert(tbRecPlayer_IsAtEnd(player));
	tbRecPlayer_Restart(player);
	tbRecPlayer_SeekFrame(player, 1);
	tbRecPlayer_Destroy(player);

	// A world destroyed while recording stops first; the recording stays whole.
	tbRecording* live = tbCreateRecording(0);
	tbWorld_StartRecording(other, live);
	tbDestroyWorld(other);
	cr_assert(tbValidateReplay(tbRecording_GetData(live), tbRecording_GetSize(live), 0));
	// A recording destroyed while its world records: the world stops recording.
	tbRecording* dropped = tbCreateRecording(0);
	tbWorld_StartRecording(world, dropped);
	tbDestroyRecording(dropped);
	tbBody_SetLinearVelocity(body, (tbVec2){0.0f, 1.0f});
	cr_assert(tbWorld_Step(world, REC_DT, REC_SUBSTEPS));
	tbDestroyRecording(live);
	tbDestroyRecording(recording);
	tbDestroyWorld(world);
	cr_assert_eq(tbGetByteCount(), 0);
}

// ---------------------------------------------------------------------------------------------
// Divergence

static uint32_t Load32(const uint8_t* p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/// The offset of the first record of opcode `op` after `steps` step records, or -1.
static int FindRecord(const uint8_t* bytes, int size, int steps, int op)
{
	int offset = TB_RECORDING_HEADER_SIZE + (int)Load32(bytes + 24);
	int seen = 0;
	while (offset < size)
	{
		if (bytes[offset] == op && seen == steps)
		{
			return offset;
		}
		seen += bytes[offset] == tb_recStep ? 1 : 0;
		offset += TB_RECORD_FRAME_SIZE + (int)Load32(bytes + offset + 1);
	}
	return -1;
}

Test(recording, a_changed_input_is_found_at_its_step, .init = SetupErrors, .fini = TeardownErrors)
{
	tbRecording* recording = RecordSession(1, s_hashes);
	int size;
	uint8_t* bytes = CopyBytes(recording, &size);
	int at = FindRecord(bytes, size, REC_CHANGED_STEP - 1, tb_recBodySetLinearVelocity);
	cr_assert_geq(at, 0);
	int last = at;
	for (int next = at; next >= 0 && bytes[next] != tb_recStep;)
	{
		last = bytes[next] == tb_recBodySetLinearVelocity ? next : last;
		next += TB_RECORD_FRAME_SIZE + (int)Load32(bytes + next + 1);
	}
	// The crate's velocity (2, 3) of the script's last call before step 300 becomes (2.5, 3).
	uint8_t* vx = bytes + last + TB_RECORD_FRAME_SIZE + 4;
	float value;
	memcpy(&value, vx, 4);
	cr_assert_eq(value, 2.0f);
	value = 2.5f;
	memcpy(vx, &value, 4);
	tbRecordingSeal(bytes, size);

	int before = s_errors;
	cr_assert_not(tbValidateReplay(bytes, size, 0));
	ExpectError(before, "tbValidateReplay", "diverged at step 300 of 600");
	tbRecPlayer* player = tbRecPlayer_Create(bytes, size, 0);
	cr_assert_not_null(player);
	tbRecPlayer_SeekFrame(player, REC_CHANGED_STEP - 1);
	cr_assert_not(tbRecPlayer_HasDiverged(player));
	cr_assert_eq(tbWorld_GetStateHash(tbRecPlayer_GetWorldId(player)), s_hashes[REC_CHANGED_STEP - 2]);
	cr_assert(tbRecPlayer_StepFrame(player));
	cr_assert(tbRecPlayer_HasDiverged(player));
	cr_assert_eq(tbRecPlayer_GetDivergeFrame(player), REC_CHANGED_STEP);
	tbRecPlayer_Destroy(player);

	// The same with the bytes intact and a call of the game's between the player's steps.
	player = tbRecPlayer_Create(tbRecording_GetData(recording), tbRecording_GetSize(recording), 0);
	tbRecPlayer_SeekFrame(player, REC_CHANGED_STEP - 1);
	tbBodyId crate = tbRecPlayer_GetBodyId(player, 2); // after the ground and the paddle
	cr_assert(tbBody_IsValid(crate));
	tbBody_ApplyAngularImpulse(crate, 0.5f, true);
	tbRecPlayer_SeekFrame(player, REC_STEPS);
	cr_assert_eq(tbRecPlayer_GetDivergeFrame(player), REC_CHANGED_STEP);
	cr_assert(tbRecPlayer_IsAtEnd(player));
	tbRecPlayer_Destroy(player);
	free(bytes);
	tbDestroyRecording(recording);
	cr_assert_eq(tbGetByteCount(), 0);
}

// ---------------------------------------------------------------------------------------------
// The player

static void CountSegment(tbPos p1, tbPos p2, tbHexColor color, void* context)
{
	(void)p1;
	(void)p2;
	(void)color;
	*(int*)context += 1;
}

Test(recording, player_seeks_both_ways_on_the_recorded_trajectory, .init = SetupErrors, .fini = TeardownErrors)
{
	tbRecording* recording = RecordSession(1, s_hashes);
	tbRecPlayer* player = tbRecPlayer_Create(tbRecording_GetData(recording), tbRecording_GetSize(recording), 0);
	// The buffer may go once the player has its copy.
	tbDestroyRecording(recording);
	tbWorldId world = tbRecPlayer_GetWorldId(player);
	cr_assert_eq(tbRecPlayer_GetKeyframeMinInterval(player), 30);
	cr_assert_gt(tbRecPlayer_GetKeyframeBudget(player), 0);
	tbRecPlayer_SetKeyframePolicy(player, 0, 10);
	cr_assert_eq(tbRecPlayer_GetKeyframeMinInterval(player), 10);
	cr_assert_eq(tbRecPlayer_GetKeyframeInterval(player), 10);
	cr_assert_eq(tbRecPlayer_GetKeyframeBytes(player), 0);

	// The bodies of the snapshot (ground, paddle), then those created before the first step.
	cr_assert_eq(tbRecPlayer_GetFrame(player), 0);
	cr_assert_eq(tbRecPlayer_GetBodyCount(player), 5);
	cr_assert(tbBody_IsValid(tbRecPlayer_GetBodyId(player, 0)));
	cr_assert(tbBody_IsValid(tbRecPlayer_GetBodyId(player, 4)));
	cr_assert(TB_IS_NULL(tbRecPlayer_GetBodyId(player, 5)));

	int targets[8] = {500, 120, 121, 599, 0, 600, 333, 45};
	for (int k = 0; k < 8; ++k)
	{
		tbRecPlayer_SeekFrame(player, targets[k]);
		cr_assert_eq(tbRecPlayer_GetFrame(player), targets[k]);
		cr_assert_eq(tbRecPlayer_GetWorldId(player).index1, world.index1, "seeks keep the world");
		if (targets[k] > 0)
		{
			cr_assert_eq(tbWorld_GetStateHash(world), s_hashes[targets[k] - 1], "seek to %d", targets[k]);
		}
		cr_assert_not(tbRecPlayer_HasDiverged(player));
	}
	cr_assert_gt(tbRecPlayer_GetKeyframeBytes(player), 0);

	// Bodies: 3 joined bodies and 30 spawned (each 20 steps), the first 10 destroyed by step 600.
	tbRecPlayer_SeekFrame(player, 600);
	cr_assert_eq(tbRecPlayer_GetBodyCount(player), 2 + 3 + 30);
	int destroyed = 0;
	for (int i = 0; i < tbRecPlayer_GetBodyCount(player); ++i)
	{
		destroyed += TB_IS_NULL(tbRecPlayer_GetBodyId(player, i)) ? 1 : 0;
	}
	cr_assert_eq(destroyed, 10);
	cr_assert(TB_IS_NULL(tbRecPlayer_GetBodyId(player, 1000)));

	// A tight budget: the spacing doubles to stay under it.
	tbRecPlayer_SetKeyframePolicy(player, 50000, 10);
	tbRecPlayer_Restart(player);
	cr_assert_eq(tbRecPlayer_GetFrame(player), 0);
	tbRecPlayer_SeekFrame(player, 600);
	cr_assert_leq(tbRecPlayer_GetKeyframeBytes(player), 50000);
	cr_assert_gt(tbRecPlayer_GetKeyframeInterval(player), 10);
	tbRecPlayer_SeekFrame(player, 77);
	cr_assert_eq(tbWorld_GetStateHash(world), s_hashes[76]);
	cr_assert(tbRecPlayer_StepFrame(player));

	// The queries of a frame: those made before its step, with what their callbacks were told.
	tbRecPlayer_Restart(player);
	tbRecPlayer_SeekFrame(player, 594); // its queries came at i = 593, before the step to 594
	cr_assert_eq(tbRecPlayer_GetFrameQueryCount(player), 3);
	tbRecQueryInfo ray = tbRecPlayer_GetFrameQuery(player, 0);
	cr_assert_eq(ray.type, tb_recQueryCastRayClosest);
	cr_assert_eq(ray.translation.y, -20.0f);
	cr_assert_geq(ray.hitCount, 1);
	tbRecQueryHit hit = tbRecPlayer_GetFrameQueryHit(player, 0, ray.hitCount - 1);
	cr_assert(tbShape_IsValid(hit.shape));
	cr_assert_eq(hit.shape.index1, s_lastRay.shapeId.index1, "the closest hit is the ray's last result");
	cr_assert_eq(hit.fraction, s_lastRay.fraction);
	cr_assert_eq(hit.point.y, s_lastRay.point.y);
	tbRecQueryInfo overlap = tbRecPlayer_GetFrameQuery(player, 1);
	cr_assert_eq(overlap.type, tb_recQueryOverlapAABB);
	cr_assert_eq(overlap.hitCount, s_lastOverlaps);
	cr_assert_eq(overlap.aabb.upperBound.x, 3.0f);
	tbRecQueryInfo test = tbRecPlayer_GetFrameQuery(player, 2);
	cr_assert_eq(test.type, tb_recQueryShapeTestPoint);
	cr_assert(tbShape_IsValid(test.shape));
	cr_assert_eq(test.hitCount, 1, "the wheel's centre is inside the wheel");
	int segments = 0;
	tbDebugDraw draw = tbDefaultDebugDraw();
	draw.DrawLineFcn = CountSegment;
	draw.context = &segments;
	tbRecPlayer_DrawFrameQueries(player, &draw, -1);
	cr_assert_geq(segments, 2, "the ray and a hit's normal");
	tbRecPlayer_DrawFrameQueries(player, &draw, 2);
	cr_assert(tbRecPlayer_StepFrame(player));
	cr_assert_eq(tbRecPlayer_GetFrameQueryCount(player), 0, "no queries before the step to 595");
	int before = s_errors;
	tbRecPlayer_GetFrameQuery(player, 0);
	tbRecPlayer_GetFrameQueryHit(player, 0, 0);
	tbRecPlayer_DrawFrameQueries(player, &draw, 0);
	cr_assert_eq(s_errors, before + 3);
	tbRecPlayer_Destroy(player);
	cr_assert_eq(tbGetByteCount(), 0);
}

// ---------------------------------------------------------------------------------------------
// Crafted bytes

/// Records of a short session changed at random and sealed again, so that they pass the checksum
/// and reach the records' checks and the API's: refused or replayed, never a crash (the sanitizers
/// watch the reads) and never a leak.
Test(recording, sealed_random_damage_is_refused_or_replayed_never_a_crash, .init = SetupErrors,
	 .fini = TeardownErrors)
{
	Session s;
	memset(&s, 0, sizeof(s));
	s.world = MakeWorld(1);
	BuildGround(&s);
	tbRecording* recording = tbCreateRecording(0);
	tbWorld_StartRecording(s.world, recording);
	BuildJoints(&s);
	uint64_t hashes[120];
	RunSession(&s, 120, hashes);
	tbWorld_StopRecording(s.world);
	tbDestroyWorld(s.world);
	int size;
	uint8_t* original = CopyBytes(recording, &size);
	int recordsStart = TB_RECORDING_HEADER_SIZE + (int)Load32(original + 24);
	uint8_t* bytes = malloc((size_t)size);
	uint32_t seed = 12345u;
	int refused = 0, diverged = 0;
	for (int trial = 0; trial < 300; ++trial)
	{
		memcpy(bytes, original, (size_t)size);
		int length = size;
		seed = seed * 1664525u + 1013904223u;
		if (trial % 5 == 4)
		{
			length = recordsStart + (int)(seed % (uint32_t)(size - recordsStart)); // cut anywhere
			bytes[8] = (uint8_t)length;
			bytes[9] = (uint8_t)(length >> 8);
			bytes[10] = (uint8_t)(length >> 16);
			bytes[11] = (uint8_t)(length >> 24);
		}
		for (int flip = 0; flip < 1 + trial % 3 && trial % 5 != 4; ++flip)
		{
			seed = seed * 1664525u + 1013904223u;
			bytes[recordsStart + (int)((seed >> 8) % (uint32_t)(size - recordsStart))] ^= (uint8_t)(1u << (seed % 8u));
		}
		tbRecordingSeal(bytes, length);
		int before = s_errors;
		bool same = tbValidateReplay(bytes, length, 0);
		refused += same == false && strstr(s_lastError, "diverged") == NULL ? 1 : 0;
		diverged += same == false && strstr(s_lastError, "diverged") != NULL ? 1 : 0;
		cr_assert(same || s_errors > before, "a replay that fails says why");
	}
	cr_assert_gt(refused + diverged, 150, "most damage is found: %d refused, %d diverged", refused, diverged);
	free(bytes);
	free(original);
	tbDestroyRecording(recording);
	cr_assert_eq(tbGetByteCount(), 0);
}
