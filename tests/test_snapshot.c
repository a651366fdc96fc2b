// Snapshots (tbWorld_Snapshot, tbWorld_Restore, tbCreateWorldFromSnapshot): a world restored from
// an image steps on bit for bit as the world it was taken from (state hash and the next image, byte
// for byte), in place, in a new world and on workers; ids keep Box2D v3.2's rules; a damaged image
// is refused and leaves the world as it was.
#include <criterion/criterion.h>

#include "error_recorder.h"
#include "snapshot_scene.h"
#include "task_system.h"
#include "test_helpers.h"
#include "world/snapshot.h"

#include "tumble/tumble.h"

#include <stdlib.h>
#include <string.h>

#define SNAP_STEP (1.0f / 60.0f)
#define SNAP_SUBSTEPS 4
#define SNAP_AT 300
#define SNAP_RUN 100

static void Run(tbWorldId world, int steps)
{
	for (int i = 0; i < steps; ++i)
	{
		cr_assert(tbWorld_Step(world, SNAP_STEP, SNAP_SUBSTEPS));
	}
}

typedef struct Image
{
	uint8_t* bytes;
	int size;
} Image;

static Image TakeSnapshot(tbWorldId world)
{
	Image image;
	image.size = tbWorld_Snapshot(world, NULL, 0);
	cr_assert_gt(image.size, TB_SNAPSHOT_HEADER_SIZE);
	image.bytes = malloc((size_t)image.size);
	cr_assert_eq(tbWorld_Snapshot(world, image.bytes, image.size), image.size);
	return image;
}

static bool SameImage(Image a, Image b)
{
	return a.size == b.size && memcmp(a.bytes, b.bytes, (size_t)a.size) == 0;
}

/// Every body's transform, velocities and awake flag: what the game sees of the state.
typedef struct BodyState
{
	tbTransform transform;
	tbVec2 linearVelocity;
	float angularVelocity;
	bool awake;
} BodyState;

static void ReadBodies(const tbBodyId* ids, BodyState* out)
{
	for (int i = 0; i < SNAP_SCENE_BODIES; ++i)
	{
		memset(out + i, 0, sizeof(BodyState));
		out[i].transform = tbBody_GetTransform(ids[i]);
		out[i].linearVelocity = tbBody_GetLinearVelocity(ids[i]);
		out[i].angularVelocity = tbBody_GetAngularVelocity(ids[i]);
		out[i].awake = tbBody_IsAwake(ids[i]);
	}
}

/// The scene's world (on `tasks` when not NULL), stepped to SNAP_AT.
static tbWorldId BuildScene(TaskSystem* tasks, tbBodyId* ids)
{
	tbWorldDef def = tbDefaultWorldDef();
	if (tasks != NULL)
	{
		def.workerCount = TaskSystem_WorkerCount(tasks);
		def.enqueueTask = TaskSystem_Enqueue;
		def.finishTask = TaskSystem_Finish;
		def.userTaskContext = tasks;
	}
	tbWorldId world = tbCreateWorld(&def);
	cr_assert_eq(SnapScene_Build(world, ids), SNAP_SCENE_BODIES);
	Run(world, SNAP_AT);
	return world;
}

/// Snapshot at SNAP_AT, run SNAP_RUN (the reference), restore in place, run SNAP_RUN again: the
/// same hash, the same bodies and the same image. Returns the reference hash.
static uint64_t CheckInPlace(tbWorldId world, const tbBodyId* ids)
{
	Image start = TakeSnapshot(world);
	uint64_t startHash = tbWorld_GetStateHash(world);
	Run(world, SNAP_RUN);
	uint64_t hash = tbWorld_GetStateHash(world);
	Image end = TakeSnapshot(world);
	BodyState* reference = malloc(sizeof(BodyState) * SNAP_SCENE_BODIES);
	BodyState* replay = malloc(sizeof(BodyState) * SNAP_SCENE_BODIES);
	ReadBodies(ids, reference);
	cr_assert_neq(hash, startHash, "the scene must move");

	cr_assert(tbWorld_Restore(world, start.bytes, start.size));
	cr_assert_eq(tbWorld_GetStateHash(world), startHash);
	Image again = TakeSnapshot(world);
	cr_assert(SameImage(start, again), "a restored world's image is the image it was restored from");
	Run(world, SNAP_RUN);
	cr_assert_eq(tbWorld_GetStateHash(world), hash);
	ReadBodies(ids, replay);
	cr_assert_eq(memcmp(reference, replay, sizeof(BodyState) * SNAP_SCENE_BODIES), 0, "bodies differ after the replay");
	Image replayEnd = TakeSnapshot(world);
	cr_assert(SameImage(end, replayEnd), "the replay's image differs from the reference's (%d and %d bytes)", end.size,
			  replayEnd.size);
	free(reference);
	free(replay);
	free(start.bytes);
	free(end.bytes);
	free(again.bytes);
	free(replayEnd.bytes);
	return hash;
}

Test(snapshot, scene_has_everything_to_restore)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	tbCounters counters = tbWorld_GetCounters(world);
	int asleep = 0;
	for (int i = 0; i < SNAP_SCENE_BODIES; ++i)
	{
		asleep += tbBody_GetType(ids[i]) != tb_staticBody && tbBody_IsAwake(ids[i]) == false ? 1 : 0;
	}
	// What the step-300 snapshot of the other tests holds: 200 bodies, some asleep (the shelf's
	// stack at least), hundreds of contacts, touching ones among them, and the scene's joints.
	cr_assert_eq(counters.bodyCount, SNAP_SCENE_BODIES);
	cr_assert_geq(asleep, SNAP_SCENE_ASLEEP_COUNT);
	cr_assert_gt(counters.contactCount, 300);
	cr_assert_gt(counters.touchingCount, 100);
	int jointEnds = 0;
	for (int i = 0; i < SNAP_SCENE_BODIES; ++i)
	{
		jointEnds += tbBody_GetJointCount(ids[i]);
	}
	// 15 revolute, 2 wheel, distance, weld, prismatic, motor, pogo and filter joints, two ends each.
	cr_assert_eq(jointEnds, 2 * (15 + 2 + 6));
	tbDestroyWorld(world);
}

Test(snapshot, in_place_restore_steps_on_bit_identically)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	CheckInPlace(world, ids);
	tbDestroyWorld(world);
}

Test(snapshot, new_world_steps_on_bit_identically)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	Image start = TakeSnapshot(world);
	Run(world, SNAP_RUN);
	uint64_t hash = tbWorld_GetStateHash(world);
	Image end = TakeSnapshot(world);
	for (int workers = 0; workers <= 4; workers += 2)
	{
		tbWorldId copy = tbCreateWorldFromSnapshot(start.bytes, start.size, workers);
		cr_assert(tbWorld_IsValid(copy));
		cr_assert_neq(copy.index1, world.index1, "a new world takes a new slot");
		cr_assert_eq(tbWorld_GetWorkerCount(copy), workers > 0 ? workers : 1);
		Run(copy, SNAP_RUN);
		cr_assert_eq(tbWorld_GetStateHash(copy), hash, "a new world on %d workers", workers);
		Image copyEnd = TakeSnapshot(copy);
		cr_assert(SameImage(end, copyEnd));
		free(copyEnd.bytes);
		// Ids of the original world do not name the new world's bodies.
		cr_assert(tbBody_IsValid(ids[10]));
		cr_assert_eq(tbBody_GetWorld(ids[10]).index1, world.index1);
		tbDestroyWorld(copy);
	}
	free(start.bytes);
	free(end.bytes);
	tbDestroyWorld(world);
}

Test(snapshot, two_and_four_workers_restore_bit_identically)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId serial = BuildScene(NULL, ids);
	uint64_t serialHash = CheckInPlace(serial, ids);
	tbDestroyWorld(serial);
	for (int workers = 2; workers <= 4; workers += 2)
	{
		TaskSystem* tasks = TaskSystem_Create(workers);
		cr_assert_not_null(tasks);
		tbWorldId world = BuildScene(tasks, ids);
		Image start = TakeSnapshot(world);
		cr_assert_eq(CheckInPlace(world, ids), serialHash, "%d workers: the same trajectory as one", workers);

		// The image restored into another world that runs on the same workers.
		tbWorldDef def = tbDefaultWorldDef();
		def.workerCount = workers;
		def.enqueueTask = TaskSystem_Enqueue;
		def.finishTask = TaskSystem_Finish;
		def.userTaskContext = tasks;
		tbWorldId other = tbCreateWorld(&def);
		cr_assert(tbWorld_Restore(other, start.bytes, start.size));
		Run(other, SNAP_RUN);
		cr_assert_eq(tbWorld_GetStateHash(other), serialHash);
		tbDestroyWorld(other);
		free(start.bytes);
		tbDestroyWorld(world);
		TaskSystem_Destroy(tasks);
	}
}

Test(snapshot, held_ids_stay_valid_and_later_ids_do_not)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	tbShapeId shapes[16];
	cr_assert_eq(tbBody_GetShapes(ids[0], shapes, 16), 9); // the chain's 7 segments, the conveyor, the sensor
	tbJointId joints[4];
	int bridgeJoints = tbBody_GetJoints(ids[1], joints, 4);
	cr_assert_eq(bridgeJoints, 1);
	Image start = TakeSnapshot(world);

	// Objects made after the snapshot: a body with a shape, a joint, a chain.
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){0.0f, 30.0f};
	tbBodyId later = tbCreateBody(world, &bodyDef);
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbShapeId laterShape = tbCreatePolygonShape(later, &shapeDef, &box);
	tbWeldJointDef weld = tbDefaultWeldJointDef();
	weld.base.bodyIdA = later;
	weld.base.bodyIdB = ids[100];
	tbJointId laterJoint = tbCreateWeldJoint(world, &weld);
	tbVec2 points[4] = {{5.0f, 40.0f}, {4.0f, 40.0f}, {3.0f, 40.0f}, {2.0f, 40.0f}};
	tbChainDef chainDef = tbDefaultChainDef();
	chainDef.points = points;
	chainDef.count = 4;
	tbSurfaceMaterial material = tbDefaultSurfaceMaterial();
	chainDef.materials = &material;
	chainDef.materialCount = 1;
	tbChainId laterChain = tbCreateChain(ids[0], &chainDef);
	// And one destroyed after it.
	tbDestroyBody(ids[150]);
	cr_assert(tbBody_IsValid(later) && tbShape_IsValid(laterShape) && tbJoint_IsValid(laterJoint) &&
			  tbChain_IsValid(laterChain));
	cr_assert_not(tbBody_IsValid(ids[150]));

	cr_assert(tbWorld_Restore(world, start.bytes, start.size));
	for (int i = 0; i < SNAP_SCENE_BODIES; ++i)
	{
		cr_assert(tbBody_IsValid(ids[i]), "body %d held from the snapshot's instant", i);
	}
	cr_assert(tbShape_IsValid(shapes[0]) && tbShape_IsValid(shapes[3]));
	cr_assert(tbJoint_IsValid(joints[0]));
	cr_assert_eq(tbJoint_GetBodyA(joints[0]).index1, ids[1].index1);
	cr_assert_not(tbBody_IsValid(later), "an id made after the snapshot does not alias");
	cr_assert_not(tbShape_IsValid(laterShape));
	cr_assert_not(tbJoint_IsValid(laterJoint));
	cr_assert_not(tbChain_IsValid(laterChain));
	cr_assert_eq(tbWorld_GetCounters(world).bodyCount, SNAP_SCENE_BODIES);
	free(start.bytes);
	tbDestroyWorld(world);
}

Test(snapshot, next_created_body_gets_the_uninterrupted_runs_id)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	// Free ids on the pools' free lists first (two bridge planks, their shapes and joints), so that
	// the next ids come from them.
	tbDestroyBody(ids[60]);
	tbDestroyBody(ids[61]);
	Image start = TakeSnapshot(world);

	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	def.position = (tbVec2){1.0f, 25.0f};
	tbPolygon box = tbMakeBox(0.3f, 0.3f);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	Run(world, SNAP_RUN);
	tbBodyId first = tbCreateBody(world, &def);
	tbShapeId firstShape = tbCreatePolygonShape(first, &shapeDef, &box);
	tbBodyId second = tbCreateBody(world, &def);
	Run(world, 10);
	uint64_t hash = tbWorld_GetStateHash(world);

	cr_assert(tbWorld_Restore(world, start.bytes, start.size));
	Run(world, SNAP_RUN);
	tbBodyId replayFirst = tbCreateBody(world, &def);
	tbShapeId replayShape = tbCreatePolygonShape(replayFirst, &shapeDef, &box);
	tbBodyId replaySecond = tbCreateBody(world, &def);
	cr_assert_eq(memcmp(&first, &replayFirst, sizeof(tbBodyId)), 0, "the same body id (slot and generation)");
	cr_assert_eq(memcmp(&firstShape, &replayShape, sizeof(tbShapeId)), 0);
	cr_assert_eq(memcmp(&second, &replaySecond, sizeof(tbBodyId)), 0);
	cr_assert_eq(first.index1, ids[61].index1, "the last freed id is handed out first");
	Run(world, 10);
	cr_assert_eq(tbWorld_GetStateHash(world), hash);
	free(start.bytes);
	tbDestroyWorld(world);
}

static bool s_filterCalled;

static bool CountingFilter(tbShapeId a, tbShapeId b, void* context)
{
	(void)a;
	(void)b;
	(void)context;
	s_filterCalled = true;
	return true;
}

Test(snapshot, host_wiring_and_user_data_follow_box2d_v32)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	int worldData = 1, bodyData = 2;
	tbWorld_SetUserData(world, &worldData);
	tbWorld_SetCustomFilterCallback(world, CountingFilter, NULL);
	tbBody_SetUserData(ids[50], &bodyData);
	char name[16] = "crate";
	tbBody_SetName(ids[50], name);
	Image start = TakeSnapshot(world);
	strcpy(name, "changed");

	cr_assert(tbWorld_Restore(world, start.bytes, start.size));
	cr_assert_eq(tbWorld_GetUserData(world), &worldData, "in place: the world's user data stays");
	cr_assert_null(tbBody_GetUserData(ids[50]), "object user data is not state: NULL, as in Box2D v3.2");
	cr_assert_str_eq(tbBody_GetName(ids[50]), "crate", "names are state: the world keeps a copy");
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = tbBody_GetPosition(ids[100]);
	tbBodyId probe = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.enableCustomFiltering = true;
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbCreateCircleShape(probe, &shapeDef, &circle);
	s_filterCalled = false;
	Run(world, 1);
	cr_assert(s_filterCalled, "in place: the custom filter stays");

	tbWorldId copy = tbCreateWorldFromSnapshot(start.bytes, start.size, 1);
	cr_assert_null(tbWorld_GetUserData(copy), "a new world's wiring is the defaults");
	cr_assert_eq(tbWorld_GetDef(copy).workerCount, 1);
	cr_assert_null(tbWorld_GetDef(copy).enqueueTask);
	free(start.bytes);
	tbDestroyWorld(copy);
	tbDestroyWorld(world);
}

Test(snapshot, size_query_and_refused_calls, .init = SetupErrors, .fini = TeardownErrors)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	int size = tbWorld_Snapshot(world, NULL, 0);
	// The same scene in Box2D v3.2 (tests/snapshot_scene.h renamed) makes a 283,767-byte image;
	// Tumble's must stay below a quarter of it (each recyclable contact adds its recycling base).
	cr_assert_gt(size, 30000);
	cr_assert_lt(size, 283767 / 4, "%d bytes: %d a body", size, size / SNAP_SCENE_BODIES);
	uint8_t* buffer = malloc((size_t)size + 16);
	memset(buffer, 0xAB, (size_t)size + 16);
	// Too small: the size, nothing written.
	cr_assert_eq(tbWorld_Snapshot(world, buffer, size - 1), size);
	for (int i = 0; i < size + 16; ++i)
	{
		cr_assert_eq(buffer[i], 0xAB);
	}
	cr_assert_eq(tbWorld_Snapshot(world, buffer, size + 16), size);
	cr_assert_eq(buffer[size], 0xAB, "nothing past the image");
	cr_assert_eq(memcmp(buffer, "TBSN", 4), 0);
	cr_assert_eq(s_errors, 0);

	int before = s_errors;
	cr_assert_eq(tbWorld_Snapshot(world, NULL, 100), 0);
	ExpectError(before, "tbWorld_Snapshot", "NULL");
	before = s_errors;
	cr_assert_eq(tbWorld_Snapshot(world, buffer, -1), 0);
	ExpectError(before, "tbWorld_Snapshot", "capacity");
	before = s_errors;
	cr_assert_not(tbWorld_Restore(world, NULL, size));
	ExpectError(before, "tbWorld_Restore", "NULL");
	before = s_errors;
	cr_assert_not(tbWorld_Restore(world, buffer, -5));
	ExpectError(before, "tbWorld_Restore", "size");
	before = s_errors;
	cr_assert_eq(tbCreateWorldFromSnapshot(buffer, size, -1).index1, 0);
	ExpectError(before, "tbCreateWorldFromSnapshot", "workerCount");
	before = s_errors;
	cr_assert_eq(tbCreateWorldFromSnapshot(buffer, size, TB_MAX_WORKERS + 1).index1, 0);
	ExpectError(before, "tbCreateWorldFromSnapshot", "workerCount");

	tbWorldId dead = tbCreateWorldFromSnapshot(buffer, size, 1);
	cr_assert(tbWorld_IsValid(dead));
	tbDestroyWorld(dead);
	before = s_errors;
	cr_assert_eq(tbWorld_Snapshot(dead, NULL, 0), 0);
	ExpectError(before, "tbWorld_Snapshot", "destroyed");
	before = s_errors;
	cr_assert_not(tbWorld_Restore(dead, buffer, size));
	ExpectError(before, "tbWorld_Restore", "destroyed");
	free(buffer);
	tbDestroyWorld(world);
}

typedef struct LockedProbe
{
	tbWorldId world;
	const uint8_t* image;
	int size;
	int snapshotResult;
	bool restoreResult;
	bool called;
} LockedProbe;

static void ProbeFromPreSolve(tbShapeId a, tbShapeId b, tbManifold* manifold, void* context)
{
	(void)a;
	(void)b;
	(void)manifold;
	LockedProbe* probe = context;
	if (probe->called)
	{
		return;
	}
	probe->called = true;
	probe->snapshotResult = tbWorld_Snapshot(probe->world, NULL, 0);
	probe->restoreResult = tbWorld_Restore(probe->world, probe->image, probe->size);
}

Test(snapshot, locked_world_is_refused, .init = SetupErrors, .fini = TeardownErrors)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	Image start = TakeSnapshot(world);
	LockedProbe probe = {world, start.bytes, start.size, -1, true, false};
	tbWorld_SetPreSolveCallback(world, ProbeFromPreSolve, NULL, &probe);
	tbShapeId shapes[1];
	tbBody_GetShapes(ids[SNAP_SCENE_BODIES - 3], shapes, 1);
	tbShape_EnablePreSolveEvents(shapes[0], true);
	// Contacts take the flag when they are made (Box2D v3.2's rule): remake the body's contacts.
	tbBody_Disable(ids[SNAP_SCENE_BODIES - 3]);
	tbBody_Enable(ids[SNAP_SCENE_BODIES - 3]);
	tbBody_SetAwake(ids[SNAP_SCENE_BODIES - 3], true);
	int before = s_errors;
	for (int i = 0; i < 60 && probe.called == false; ++i)
	{
		tbWorld_Step(world, SNAP_STEP, SNAP_SUBSTEPS);
	}
	cr_assert(probe.called, "the probe body must touch something");
	cr_assert_eq(probe.snapshotResult, 0, "mid-step: 0, as in Box2D v3.2");
	cr_assert_not(probe.restoreResult);
	cr_assert_eq(s_errors, before + 2);
	cr_assert(strstr(s_lastError, "tbWorld_Restore") != NULL && strstr(s_lastError, "locked") != NULL);
	free(start.bytes);
	tbDestroyWorld(world);
}

/// A world that refused an image is unchanged: its hash and image are those before the refusal.
static void ExpectUnchanged(tbWorldId world, Image state, uint64_t hash)
{
	cr_assert_eq(tbWorld_GetStateHash(world), hash);
	Image now = TakeSnapshot(world);
	cr_assert(SameImage(now, state), "a refused image changed the world");
	free(now.bytes);
}

Test(snapshot, damaged_images_are_refused_and_the_world_steps_on, .init = SetupErrors, .fini = TeardownErrors)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	Image start = TakeSnapshot(world);
	uint64_t startHash = tbWorld_GetStateHash(world);
	Run(world, SNAP_RUN);
	uint64_t reference = tbWorld_GetStateHash(world);
	cr_assert(tbWorld_Restore(world, start.bytes, start.size));

	uint8_t* damaged = malloc((size_t)start.size);
	int refusals = 0;
	// Truncated at every length up to the header and beyond, then at many lengths through the body.
	for (int length = 0; length < start.size; length += length < 64 ? 1 : 97)
	{
		int before = s_errors;
		cr_assert_not(tbWorld_Restore(world, start.bytes, length), "truncated at %d", length);
		cr_assert_eq(s_errors, before + 1, "one error per refusal");
		cr_assert(strstr(s_lastError, "tbWorld_Restore") != NULL && strstr(s_lastError, "unchanged") != NULL);
		refusals += 1;
	}
	cr_assert(strstr(s_lastError, "truncated") != NULL, "%s", s_lastError);
	// A byte flipped anywhere: the checksum catches it (the header's own fields name their problem).
	for (int offset = 0; offset < start.size; offset += offset < 64 ? 1 : 61)
	{
		memcpy(damaged, start.bytes, (size_t)start.size);
		damaged[offset] ^= (uint8_t)(1u << (offset % 8));
		int before = s_errors;
		cr_assert_not(tbWorld_Restore(world, damaged, start.size), "flipped byte %d", offset);
		cr_assert_eq(s_errors, before + 1);
		refusals += 1;
	}
	cr_assert(strstr(s_lastError, "checksum") != NULL, "%s", s_lastError);
	ExpectUnchanged(world, start, startHash);
	cr_assert_gt(refusals, 1000);

	// Header fields, resealed so that the field itself is what is refused.
	struct
	{
		int offset;
		uint8_t value;
		const char* message;
	} header[] = {{0, 'X', "TBSN"}, {4, 9, "version"}, {6, 1, "double-precision"}, {8, 0, "truncated or padded"},
				  {15, 0x41, "length units"}};
	for (int i = 0; i < 5; ++i)
	{
		memcpy(damaged, start.bytes, (size_t)start.size);
		damaged[header[i].offset] = header[i].value;
		tbSnapshotSeal(damaged, start.size);
		int before = s_errors;
		cr_assert_not(tbWorld_Restore(world, damaged, start.size));
		cr_assert_eq(s_errors, before + 1);
		cr_assert(strstr(s_lastError, header[i].message) != NULL, "%s", s_lastError);
	}
	// The same with a new world: none is made.
	cr_assert_eq(tbCreateWorldFromSnapshot(start.bytes, start.size - 1, 1).index1, 0);
	ExpectUnchanged(world, start, startHash);
	Run(world, SNAP_RUN);
	cr_assert_eq(tbWorld_GetStateHash(world), reference, "after the refusals the world steps on as before");
	free(damaged);
	free(start.bytes);
	tbDestroyWorld(world);
}

Test(snapshot, resealed_damage_is_checked_inside, .init = SetupErrors, .fini = TeardownErrors)
{
	tbBodyId ids[SNAP_SCENE_BODIES];
	tbWorldId world = BuildScene(NULL, ids);
	Image start = TakeSnapshot(world);
	uint64_t startHash = tbWorld_GetStateHash(world);
	uint8_t* damaged = malloc((size_t)start.size);
	int refused = 0, accepted = 0, outOfRange = 0;
	uint32_t seed = 12345u;
	// Damage past the header with a valid checksum: the checks inside the image must catch what
	// would break the world; what they accept must step (and is undone by restoring the original).
	for (int trial = 0; trial < 600; ++trial)
	{
		memcpy(damaged, start.bytes, (size_t)start.size);
		seed = seed * 1664525u + 1013904223u;
		int offset = TB_SNAPSHOT_HEADER_SIZE + (int)((seed >> 8) % (uint32_t)(start.size - TB_SNAPSHOT_HEADER_SIZE));
		seed = seed * 1664525u + 1013904223u;
		damaged[offset] = (uint8_t)(seed >> 24);
		if (trial % 3 == 0)
		{
			damaged[offset] = 0xFF;
		}
		tbSnapshotSeal(damaged, start.size);
		int before = s_errors;
		if (tbWorld_Restore(world, damaged, start.size))
		{
			accepted += 1;
			tbWorld_Step(world, SNAP_STEP, SNAP_SUBSTEPS);
			s_errors = before; // a strange but valid world may report what it does
			cr_assert(tbWorld_Restore(world, start.bytes, start.size));
		}
		else
		{
			refused += 1;
			cr_assert_eq(s_errors, before + 1);
			outOfRange += strstr(s_lastError, "out of range") != NULL ? 1 : 0;
			cr_assert_eq(tbWorld_GetStateHash(world), startHash);
		}
	}
	ExpectUnchanged(world, start, startHash);
	cr_log_info("resealed damage: %d refused, %d accepted", refused, accepted);
	cr_assert_gt(refused, 100, "refused %d accepted %d", refused, accepted);
	cr_assert_gt(outOfRange, 0);
	free(damaged);
	free(start.bytes);
	tbDestroyWorld(world);
}

Test(snapshot, empty_world_and_every_broad_phase)
{
	tbWorldDef def = tbDefaultWorldDef();
	tbWorldId empty = tbCreateWorld(&def);
	Image image = TakeSnapshot(empty);
	cr_assert_lt(image.size, 200);
	tbWorldId copy = tbCreateWorldFromSnapshot(image.bytes, image.size, 1);
	cr_assert(tbWorld_IsValid(copy));
	cr_assert_eq(tbWorld_GetCounters(copy).bodyCount, 0);
	free(image.bytes);
	tbDestroyWorld(copy);
	tbDestroyWorld(empty);
	tbBroadPhaseMethod methods[4] = {tb_broadPhaseTree, tb_broadPhaseSortAndSweep, tb_broadPhaseBruteForce,
									 tb_broadPhaseSpatialHash};
	uint64_t hashes[4];
	for (int m = 0; m < 4; ++m)
	{
		def = tbDefaultWorldDef();
		def.broadPhase = methods[m];
		tbWorldId world = tbCreateWorld(&def);
		tbBodyId ids[SNAP_SCENE_BODIES];
		SnapScene_Build(world, ids);
		Run(world, 120);
		hashes[m] = CheckInPlace(world, ids);
		cr_assert_eq(tbWorld_GetDef(world).broadPhase, methods[m]);
		tbDestroyWorld(world);
	}
	cr_assert(hashes[1] == hashes[0] && hashes[2] == hashes[0] && hashes[3] == hashes[0]);
}

Test(snapshot, ids_made_after_a_snapshot_stay_stale_in_the_next_world_of_the_slot)
{
	tbWorldDef def = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&def);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId first = tbCreateBody(world, &bodyDef);
	tbBodyId anchor = tbCreateBody(world, &bodyDef);
	bodyDef.type = tb_dynamicBody;
	tbBodyId swing = tbCreateBody(world, &bodyDef);
	tbRevoluteJointDef jointDef = tbDefaultRevoluteJointDef();
	jointDef.base.bodyIdA = anchor;
	jointDef.base.bodyIdB = swing;
	tbJointId firstJoint = tbCreateRevoluteJoint(world, &jointDef);
	Image start = TakeSnapshot(world);
	// After the snapshot: the body's slot serves another body, the joint's another joint, each
	// under the next generation.
	tbDestroyBody(first);
	bodyDef.type = tb_staticBody;
	tbBodyId later = tbCreateBody(world, &bodyDef);
	cr_assert_eq(later.index1, first.index1);
	cr_assert_neq(later.generation, first.generation);
	tbDestroyJoint(firstJoint);
	tbJointId laterJoint = tbCreateRevoluteJoint(world, &jointDef);
	cr_assert_eq(laterJoint.index1, firstJoint.index1);
	cr_assert(tbWorld_Restore(world, start.bytes, start.size));
	cr_assert(tbBody_IsValid(first) && tbJoint_IsValid(firstJoint));
	cr_assert_not(tbBody_IsValid(later));
	cr_assert_not(tbJoint_IsValid(laterJoint));
	tbDestroyWorld(world);

	// A new world in the same world slot starts past every generation the old one handed out,
	// rolled back or not: `later` names none of its bodies.
	tbWorldId next = tbCreateWorld(&def);
	cr_assert_eq(next.index1, world.index1);
	tbBodyId fresh = tbCreateBody(next, &bodyDef);
	tbBodyId other = tbCreateBody(next, &bodyDef);
	bodyDef.type = tb_dynamicBody;
	jointDef.base.bodyIdA = other;
	jointDef.base.bodyIdB = tbCreateBody(next, &bodyDef);
	tbJointId freshJoint = tbCreateRevoluteJoint(next, &jointDef);
	cr_assert_eq(fresh.index1, later.index1);
	cr_assert_eq(freshJoint.index1, laterJoint.index1);
	cr_assert_not(tbBody_IsValid(later));
	cr_assert_not(tbBody_IsValid(first));
	cr_assert_not(tbJoint_IsValid(laterJoint));
	cr_assert(tbBody_IsValid(fresh) && tbJoint_IsValid(freshJoint));
	free(start.bytes);
	tbDestroyWorld(next);
}

// A body whose shape was destroyed without a mass update keeps its larger extents, which the image
// stores as they are; the reach of its shapes' cores, which the speculative margin reads, is always
// that of the shapes left, so the image leaves it out and the restore recomputes it. A spinning
// box with a ball at 0.3 m and another 2 m out loses the far ball without a mass update and tumbles
// onto boxes: the world restored from its image steps on to the same state hash and image.
Test(snapshot, a_shape_removed_without_a_mass_update_restores_bit_identically)
{
	tbWorldId world = CreateWorld(tbDefaultWorldDef().gravity);
	CreateGround(world, (tbVec2){0.0f, -0.5f}, 20.0f, 0.5f, NULL);
	for (int i = 0; i < 6; ++i)
	{
		CreateBox(world, tb_dynamicBody, (tbVec2){-2.5f + (float)i, 0.5f}, 0.45f, 0.45f, 1.0f);
	}
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = (tbVec2){0.0f, 3.0f};
	bodyDef.angularVelocity = 6.0f;
	tbBodyId body = CreateBoxFromDef(world, &bodyDef, 0.5f, 0.5f, NULL);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle nearBall = {{0.3f, 0.0f}, 0.4f};
	tbCreateCircleShape(body, &shapeDef, &nearBall);
	tbCircle farBall = {{2.0f, 0.0f}, 0.3f};
	tbShapeId far = tbCreateCircleShape(body, &shapeDef, &farBall);
	Run(world, 5);
	tbDestroyShape(far, false);
	Run(world, 5);
	Image start = TakeSnapshot(world);
	Run(world, 120);
	uint64_t hash = tbWorld_GetStateHash(world);
	Image end = TakeSnapshot(world);
	tbWorldId copy = tbCreateWorldFromSnapshot(start.bytes, start.size, 0);
	cr_assert(tbWorld_IsValid(copy));
	Run(copy, 120);
	cr_assert_eq(tbWorld_GetStateHash(copy), hash, "the restored world stepped to another state");
	Image copyEnd = TakeSnapshot(copy);
	cr_assert(SameImage(end, copyEnd), "the restored world's image differs (%d and %d bytes)", end.size, copyEnd.size);
	free(start.bytes);
	free(end.bytes);
	free(copyEnd.bytes);
	tbDestroyWorld(copy);
	tbDestroyWorld(world);
}
