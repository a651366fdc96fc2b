// Rollback as a networked game does it with Box2D v3.2's snapshots: a pile with contact events is
// snapshotted at step 60 and run to step 120; restored in place and run again it must give the
// same state and the same events, with the ids held from before still valid; a new world made from
// the image and run the same 60 steps must reach the same state too.
#include "program.h"

#include <stdlib.h>

#define BODY_COUNT 24

typedef struct Run
{
	uint64_t stateHash;
	uint64_t eventHash;
	int beginCount;
} Run;

static void MixEvent(Run* run, b2ShapeId a, b2ShapeId b)
{
	uint32_t words[2] = {(uint32_t)a.index1, (uint32_t)b.index1};
	const unsigned char* bytes = (const unsigned char*)words;
	for (size_t k = 0; k < sizeof(words); ++k)
	{
		run->eventHash = (run->eventHash ^ bytes[k]) * 1099511628211ull;
	}
}

static Run RunSteps(b2WorldId world, const b2BodyId* bodies, int steps)
{
	Run run = {0, 14695981039346656037ull, 0};
	for (int i = 0; i < steps; ++i)
	{
		b2World_Step(world, 1.0f / 60.0f, 4);
		b2ContactEvents events = b2World_GetContactEvents(world);
		for (int k = 0; k < events.beginCount; ++k)
		{
			MixEvent(&run, events.beginEvents[k].shapeIdA, events.beginEvents[k].shapeIdB);
		}
		run.beginCount += events.beginCount;
	}
	run.stateHash = HashBodies(bodies, BODY_COUNT);
	return run;
}

typedef struct Found
{
	b2ShapeId shapes[BODY_COUNT];
	int count;
} Found;

static bool CollectDynamic(b2ShapeId shapeId, void* context)
{
	Found* found = context;
	if (b2Body_GetType(b2Shape_GetBody(shapeId)) == b2_dynamicBody && found->count < BODY_COUNT)
	{
		found->shapes[found->count++] = shapeId;
	}
	return true;
}

static int CompareShapes(const void* a, const void* b)
{
	const b2ShapeId* x = a;
	const b2ShapeId* y = b;
	return (x->index1 > y->index1) - (x->index1 < y->index1);
}

/// A world's dynamic bodies in the order of their shapes' slots (one shape a body here): the ids
/// held from another world do not name a world made from a snapshot, a query finds its bodies.
static int FindBodies(b2WorldId world, b2BodyId* bodies)
{
	Found found;
	found.count = 0;
	b2AABB everywhere = {{-100.0f, -100.0f}, {100.0f, 100.0f}};
	b2World_OverlapAABB(world, (b2Pos){0.0f, 0.0f}, everywhere, b2DefaultQueryFilter(), CollectDynamic, &found);
	qsort(found.shapes, (size_t)found.count, sizeof(b2ShapeId), CompareShapes);
	for (int i = 0; i < found.count; ++i)
	{
		bodies[i] = b2Shape_GetBody(found.shapes[i]);
	}
	return found.count;
}

int main(void)
{
	b2WorldDef worldDef = b2DefaultWorldDef();
	b2WorldId world = b2CreateWorld(&worldDef);
	b2BodyDef groundDef = b2DefaultBodyDef();
	b2BodyId ground = b2CreateBody(world, &groundDef);
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	shapeDef.enableContactEvents = true;
	b2Polygon floor = b2MakeBox(20.0f, 0.5f);
	b2CreatePolygonShape(ground, &shapeDef, &floor);
	b2BodyId bodies[BODY_COUNT];
	for (int i = 0; i < BODY_COUNT; ++i)
	{
		b2BodyDef bodyDef = b2DefaultBodyDef();
		bodyDef.type = b2_dynamicBody;
		bodyDef.position = (b2Pos){-3.0f + 0.7f * (float)(i % 8) + 0.1f * (float)(i / 8), 2.0f + 1.2f * (float)(i / 8)};
		bodyDef.rotation = b2MakeRot(0.3f * (float)i);
		bodies[i] = b2CreateBody(world, &bodyDef);
		if (i % 3 == 0)
		{
			b2Circle circle = {{0.0f, 0.0f}, 0.3f};
			b2CreateCircleShape(bodies[i], &shapeDef, &circle);
		}
		else
		{
			b2Polygon box = b2MakeBox(0.3f, 0.2f);
			b2CreatePolygonShape(bodies[i], &shapeDef, &box);
		}
	}
	RunSteps(world, bodies, 60);

	int size = b2World_Snapshot(world, NULL, 0);
	uint8_t* image = malloc((size_t)size);
	int written = b2World_Snapshot(world, image, size);
	printf("the snapshot is written whole: %s\n", written == size && size > 0 ? "yes" : "no");

	Run first = RunSteps(world, bodies, 60);
	printf("bodies begin to touch in steps 61 to 120: %s\n", first.beginCount > 0 ? "yes" : "no");

	bool restored = b2World_Restore(world, image, size);
	printf("restored in place: %s\n", restored ? "yes" : "no");
	printf("held ids valid after the restore: %s\n",
		   b2Body_IsValid(bodies[0]) && b2Body_IsValid(bodies[BODY_COUNT - 1]) ? "yes" : "no");
	Run again = RunSteps(world, bodies, 60);
	printf("in place, the same state and events: %s\n",
		   again.stateHash == first.stateHash && again.eventHash == first.eventHash ? "yes" : "no");

	b2WorldId copy = b2CreateWorldFromSnapshot(image, size, 0);
	printf("a new world from the image: %s\n", b2World_IsValid(copy) ? "yes" : "no");
	b2BodyId copied[BODY_COUNT], origin[BODY_COUNT];
	int copiedCount = FindBodies(copy, copied);
	int originCount = FindBodies(world, origin);
	printf("the new world holds every body: %s\n", copiedCount == BODY_COUNT && originCount == BODY_COUNT ? "yes" : "no");
	if (copiedCount == BODY_COUNT && originCount == BODY_COUNT)
	{
		Run fresh = RunSteps(copy, copied, 60);
		printf("the new world, the same state and events: %s\n",
			   fresh.stateHash == HashBodies(origin, BODY_COUNT) && fresh.eventHash == first.eventHash ? "yes" : "no");
	}
	b2DestroyWorld(copy);
	b2DestroyWorld(world);
	free(image);
	return 0;
}
