// Fuzz harness for snapshot images (tbWorld_Restore, tbCreateWorldFromSnapshot): bytes become
// either an image as they are, or a valid image of a small world (every joint kind, a chain,
// sleeping and touching bodies; tree, spatial-hash or sort-and-sweep broad phase) with bytes
// overwritten, inserted or cut, then resealed so that the checksum passes and the checks inside
// the image are what is exercised. The image is restored into a live world and made into a new one.
// Checks: no abort or sanitizer report; a refused image leaves the live world as it was (same
// state hash, same image) and stepping it gives the hash the untouched world gives; an accepted
// image gives a world that steps, snapshots and restores from its own snapshot; no bytes are left
// once the worlds are destroyed.
#include "fuzz_input.h"

#include "world/snapshot.h"

#include "tumble/tumble.h"

#include <stdio.h>
#include <stdlib.h>

#define BASE_COUNT 3
#define STEP (1.0f / 60.0f)

typedef struct Base
{
	uint8_t* image;
	int size;
	uint64_t hash;	   ///< the world's state hash at the image
	uint64_t nextHash; ///< and one step later
} Base;

static Base s_bases[BASE_COUNT];
static tbWorldId s_live;
static int64_t s_baseline; ///< bytes allocated with the live world holding the first base image
static bool s_trace = false;
static char s_lastError[512];

static void Quiet(const char* message, void* context)
{
	(void)context;
	snprintf(s_lastError, sizeof(s_lastError), "%s", message);
	if (s_trace)
	{
		fprintf(stderr, "  refused: %s\n", message);
	}
}

static void Check(bool condition, const char* what)
{
	if (condition == false)
	{
		fprintf(stderr, "fuzz_snapshot: %s\n", what);
		abort();
	}
}

static tbBodyId Body(tbWorldId world, tbBodyType type, float x, float y, bool awake)
{
	tbBodyDef def = tbDefaultBodyDef();
	def.type = type;
	def.position = tbMakeVec2(x, y);
	def.isAwake = awake;
	return tbCreateBody(world, &def);
}

/// A small world with one of everything a snapshot holds.
static tbWorldId BuildWorld(tbBroadPhaseMethod method)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.broadPhase = method;
	tbWorldId world = tbCreateWorld(&def);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbBodyId ground = Body(world, tb_staticBody, 0.0f, 0.0f, true);
	tbVec2 points[6] = {{12.0f, 6.0f}, {10.0f, 4.0f}, {5.0f, 0.0f}, {-5.0f, 0.0f}, {-10.0f, 4.0f}, {-12.0f, 6.0f}};
	tbSurfaceMaterial material = tbDefaultSurfaceMaterial();
	tbChainDef chainDef = tbDefaultChainDef();
	chainDef.points = points;
	chainDef.count = 6;
	chainDef.materials = &material;
	chainDef.materialCount = 1;
	tbCreateChain(ground, &chainDef);
	tbSegment shelf = {{-4.0f, 3.0f}, {-2.0f, 3.0f}};
	tbCreateSegmentShape(ground, &shapeDef, &shelf);
	tbPolygon box = tbMakeBox(0.4f, 0.4f);
	tbBodyId bodies[12];
	for (int i = 0; i < 6; ++i)
	{
		bodies[i] = Body(world, tb_dynamicBody, 1.0f + 0.1f * (float)i, 0.4f + 0.8f * (float)i, true);
		tbCreatePolygonShape(bodies[i], &shapeDef, &box);
	}
	tbBodyId sleeper = Body(world, tb_dynamicBody, -3.0f, 3.4f, false);
	tbCreatePolygonShape(sleeper, &shapeDef, &box);
	tbCircle circle = {{0.0f, 0.0f}, 0.3f};
	tbCapsule capsule = {{-0.3f, 0.0f}, {0.3f, 0.0f}, 0.15f};
	tbPolygon rounded = tbMakeRoundedBox(0.3f, 0.2f, 0.05f);
	for (int i = 6; i < 12; ++i)
	{
		bodies[i] = Body(world, tb_dynamicBody, -2.0f + 0.7f * (float)(i - 6), 5.0f, true);
		if (i % 3 == 0)
		{
			tbCreateCircleShape(bodies[i], &shapeDef, &circle);
		}
		else if (i % 3 == 1)
		{
			tbCreateCapsuleShape(bodies[i], &shapeDef, &capsule);
		}
		else
		{
			tbCreatePolygonShape(bodies[i], &shapeDef, &rounded);
		}
	}
	tbDistanceJointDef distance = tbDefaultDistanceJointDef();
	distance.base.bodyIdA = bodies[6];
	distance.base.bodyIdB = bodies[7];
	distance.enableSpring = true;
	distance.hertz = 3.0f;
	tbCreateDistanceJoint(world, &distance);
	tbRevoluteJointDef revolute = tbDefaultRevoluteJointDef();
	revolute.base.bodyIdA = bodies[7];
	revolute.base.bodyIdB = bodies[8];
	revolute.enableLimit = true;
	revolute.lowerAngle = -0.5f;
	revolute.upperAngle = 0.5f;
	tbCreateRevoluteJoint(world, &revolute);
	tbPrismaticJointDef prismatic = tbDefaultPrismaticJointDef();
	prismatic.base.bodyIdA = ground;
	prismatic.base.bodyIdB = bodies[9];
	prismatic.base.localFrameA.p = tbMakeVec2(-0.1f, 5.0f);
	prismatic.enableMotor = true;
	prismatic.maxMotorForce = 50.0f;
	prismatic.motorSpeed = 0.5f;
	tbCreatePrismaticJoint(world, &prismatic);
	tbWheelJointDef wheel = tbDefaultWheelJointDef();
	wheel.base.bodyIdA = bodies[9];
	wheel.base.bodyIdB = bodies[10];
	tbCreateWheelJoint(world, &wheel);
	tbWeldJointDef weld = tbDefaultWeldJointDef();
	weld.base.bodyIdA = bodies[10];
	weld.base.bodyIdB = bodies[11];
	weld.linearHertz = 4.0f;
	tbCreateWeldJoint(world, &weld);
	tbMotorJointDef motor = tbDefaultMotorJointDef();
	motor.base.bodyIdA = ground;
	motor.base.bodyIdB = bodies[5];
	motor.linearHertz = 2.0f;
	motor.maxSpringForce = 10.0f;
	tbCreateMotorJoint(world, &motor);
	tbMoverJointDef mover = tbDefaultMoverJointDef();
	mover.base.bodyIdA = ground;
	mover.base.bodyIdB = bodies[4];
	mover.maxVelocityForce = tbMakeVec2(5.0f, 0.0f);
	tbCreateMoverJoint(world, &mover);
	tbPogoJointDef pogo = tbDefaultPogoJointDef();
	pogo.base.bodyIdA = ground;
	pogo.base.bodyIdB = bodies[3];
	pogo.hertz = 2.0f;
	pogo.restLength = 1.0f;
	pogo.maxCompressionForce = 20.0f;
	tbCreatePogoJoint(world, &pogo);
	tbFilterJointDef filter = tbDefaultFilterJointDef();
	filter.base.bodyIdA = bodies[0];
	filter.base.bodyIdB = bodies[1];
	tbCreateFilterJoint(world, &filter);
	tbBodyDef paddleDef = tbDefaultBodyDef();
	paddleDef.type = tb_kinematicBody;
	paddleDef.position = tbMakeVec2(6.0f, 2.0f);
	paddleDef.angularVelocity = 1.0f;
	tbBodyId paddle = tbCreateBody(world, &paddleDef);
	tbPolygon bar = tbMakeBox(1.5f, 0.1f);
	tbCreatePolygonShape(paddle, &shapeDef, &bar);
	tbBodyDef bulletDef = tbDefaultBodyDef();
	bulletDef.type = tb_dynamicBody;
	bulletDef.position = tbMakeVec2(-8.0f, 6.0f);
	bulletDef.linearVelocity = tbMakeVec2(40.0f, 0.0f);
	bulletDef.isBullet = true;
	tbBodyId bullet = tbCreateBody(world, &bulletDef);
	tbCreateCircleShape(bullet, &shapeDef, &circle);
	tbDestroyBody(bodies[2]); // free ids on the pools' free lists
	for (int i = 0; i < 40; ++i)
	{
		tbWorld_Step(world, STEP, 4);
	}
	return world;
}

static uint8_t* Snapshot(tbWorldId world, int* size)
{
	*size = tbWorld_Snapshot(world, NULL, 0);
	Check(*size > 0, "a live world's snapshot size is 0");
	uint8_t* image = malloc((size_t)*size);
	Check(tbWorld_Snapshot(world, image, *size) == *size, "tbWorld_Snapshot wrote another size");
	return image;
}

static void Setup(void)
{
	s_trace = getenv("FUZZ_TRACE") != NULL;
	tbSetErrorCallback(Quiet, NULL);
	tbBroadPhaseMethod methods[BASE_COUNT] = {tb_broadPhaseTree, tb_broadPhaseSpatialHash, tb_broadPhaseSortAndSweep};
	for (int i = 0; i < BASE_COUNT; ++i)
	{
		tbWorldId world = BuildWorld(methods[i]);
		Base* base = s_bases + i;
		base->image = Snapshot(world, &base->size);
		base->hash = tbWorld_GetStateHash(world);
		tbWorld_Step(world, STEP, 4);
		base->nextHash = tbWorld_GetStateHash(world);
		tbDestroyWorld(world);
	}
	if (s_trace && getenv("FUZZ_BASE") != NULL)
	{
		FILE* file = fopen(getenv("FUZZ_BASE"), "wb"); // the first base image, to compare a finding with
		if (file != NULL)
		{
			fwrite(s_bases[0].image, 1, (size_t)s_bases[0].size, file);
			fclose(file);
		}
	}
	s_live = tbCreateWorldFromSnapshot(s_bases[0].image, s_bases[0].size, 1);
	Check(tbWorld_IsValid(s_live), "the live world");
	s_baseline = tbGetByteCount();
}

static bool SameImage(const uint8_t* a, int sizeA, const uint8_t* b, int sizeB)
{
	return sizeA == sizeB && memcmp(a, b, (size_t)sizeA) == 0;
}

/// The image to try: the input as it is, or a base image with the input's edits, resealed.
static uint8_t* MakeImage(FuzzInput* in, int* sizeOut, const Base** baseOut)
{
	int mode = FuzzInt(in, 4);
	const Base* base = s_bases + FuzzInt(in, BASE_COUNT);
	*baseOut = base;
	if (mode == 0)
	{
		int size = (int)(in->size - in->offset);
		uint8_t* image = malloc((size_t)size + 1);
		memcpy(image, in->data + in->offset, (size_t)size);
		if (size >= TB_SNAPSHOT_HEADER_SIZE && FuzzInt(in, 2) == 0)
		{
			tbSnapshotSeal(image, size); // raw bytes with a valid checksum: reach the header's fields
		}
		*sizeOut = size;
		return image;
	}
	int size = base->size;
	int capacity = size + 64;
	uint8_t* image = malloc((size_t)capacity);
	memcpy(image, base->image, (size_t)size);
	int edits = 1 + FuzzInt(in, 8);
	for (int e = 0; e < edits && in->offset < in->size; ++e)
	{
		int kind = FuzzInt(in, 8);
		int high = FuzzByte(in), low = FuzzByte(in);
		// Most edits land past the header, where the checks inside the image are.
		int offset = TB_SNAPSHOT_HEADER_SIZE + (int)(((unsigned)high << 8 | (unsigned)low) % (unsigned)(size - TB_SNAPSHOT_HEADER_SIZE));
		uint8_t value = FuzzByte(in);
		if (kind < 5)
		{
			image[offset] = value; // overwrite
		}
		else if (kind == 5)
		{
			image[offset] ^= (uint8_t)(1u << (value & 7u)); // one bit
		}
		else if (kind == 6 && size < capacity)
		{
			memmove(image + offset + 1, image + offset, (size_t)(size - offset)); // insert a byte
			image[offset] = value;
			size += 1;
		}
		else if (size > TB_SNAPSHOT_HEADER_SIZE + 1)
		{
			memmove(image + offset, image + offset + 1, (size_t)(size - offset - 1)); // cut a byte
			size -= 1;
		}
	}
	if (mode != 3)
	{
		// The header's size field follows the image unless the input says not to.
		image[8] = (uint8_t)size;
		image[9] = (uint8_t)(size >> 8);
		image[10] = (uint8_t)(size >> 16);
		image[11] = (uint8_t)(size >> 24);
		tbSnapshotSeal(image, size);
	}
	*sizeOut = size;
	return image;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static bool ready = false;
	if (ready == false)
	{
		Setup();
		ready = true;
	}
	FuzzInput in = {data, size, 0};
	const Base* base;
	int imageSize;
	uint8_t* image = MakeImage(&in, &imageSize, &base);
	if (s_trace && getenv("FUZZ_IMAGE") != NULL)
	{
		FILE* file = fopen(getenv("FUZZ_IMAGE"), "wb"); // the image tried, to replay outside the fuzzer
		if (file != NULL)
		{
			fwrite(image, 1, (size_t)imageSize, file);
			fclose(file);
		}
	}

	// In place: the live world holds `base`.
	Check(tbWorld_Restore(s_live, base->image, base->size), "a valid image was refused");
	if (tbWorld_Restore(s_live, image, imageSize))
	{
		for (int i = 0; i < 3; ++i)
		{
			tbWorld_Step(s_live, STEP, 4);
		}
		int againSize;
		uint8_t* again = Snapshot(s_live, &againSize);
		// A crafted image may hold values no step could have made (impulses of 1e38 on a 1 kg body)
		// and the world may then overflow; its snapshot is then refused for what went non-finite.
		// Any other refusal of a world's own snapshot is a bug.
		if (tbWorld_Restore(s_live, again, againSize))
		{
			int thirdSize;
			uint8_t* third = Snapshot(s_live, &thirdSize);
			Check(SameImage(again, againSize, third, thirdSize), "a restored world's image differs from its source");
			free(third);
		}
		else
		{
			Check(strstr(s_lastError, "not finite") != NULL, "a world's own snapshot was refused");
		}
		free(again);
	}
	else
	{
		Check(tbWorld_GetStateHash(s_live) == base->hash, "a refused image changed the world's state");
		int nowSize;
		uint8_t* now = Snapshot(s_live, &nowSize);
		Check(SameImage(now, nowSize, base->image, base->size), "a refused image changed the world");
		free(now);
		tbWorld_Step(s_live, STEP, 4);
		Check(tbWorld_GetStateHash(s_live) == base->nextHash, "after a refusal the world steps differently");
	}

	// A new world.
	tbWorldId world = tbCreateWorldFromSnapshot(image, imageSize, 1 + FuzzInt(&in, 4));
	if (tbWorld_IsValid(world))
	{
		tbWorld_Step(world, STEP, 4);
		tbDestroyWorld(world);
	}
	free(image);
	// The live world is reset by the next input; what else was made is gone.
	Check(tbWorld_Restore(s_live, s_bases[0].image, s_bases[0].size), "a valid image was refused");
	Check(tbGetByteCount() == s_baseline, "bytes left over: a restore or a refusal leaks");
	return 0;
}
