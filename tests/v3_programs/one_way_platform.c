// A one-way platform made with the pre-solve callback, as Box2D v3.2's samples make it: a ball
// thrown up from below passes through the platform, falls back onto it and rests there. (It
// crosses at about 6 m/s, 0.11 m a step: less than half its radius, so no continuous collision
// is involved, where the engines differ without a pre-continuous callback.) The
// callback keeps a contact only when the normal points up out of the platform into the ball and
// the ball is not deep inside it. Printed: when the ball is first above the platform, its
// begin-touch events, and where it rests.
#include "program.h"

typedef struct Level
{
	b2ShapeId platform;
	b2ShapeId ball;
} Level;

static void PreSolve(b2ShapeId shapeIdA, b2ShapeId shapeIdB, b2Manifold* manifold, void* context)
{
	Level* level = context;
	float sign;
	if (B2_ID_EQUALS(shapeIdA, level->platform))
	{
		sign = 1.0f; // the normal points from A to B: from the platform to the ball
	}
	else if (B2_ID_EQUALS(shapeIdB, level->platform))
	{
		sign = -1.0f;
	}
	else
	{
		return;
	}
	if (sign * manifold->normal.y < 0.7f)
	{
		manifold->pointCount = 0; // from below or the side: pass through
		return;
	}
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		if (manifold->points[i].separation < -0.1f)
		{
			manifold->pointCount = 0; // still crossing from below
			return;
		}
	}
}

int main(void)
{
	b2WorldDef worldDef = b2DefaultWorldDef();
	b2WorldId world = b2CreateWorld(&worldDef);
	Level level;

	b2BodyDef groundDef = b2DefaultBodyDef();
	b2BodyId ground = b2CreateBody(world, &groundDef);
	b2ShapeDef groundShape = b2DefaultShapeDef();
	b2Segment floor = {{-20.0f, 0.0f}, {20.0f, 0.0f}};
	NameShape(b2CreateSegmentShape(ground, &groundShape, &floor), "floor");

	b2BodyDef platformDef = b2DefaultBodyDef();
	platformDef.position = (b2Pos){0.0f, 3.0f};
	b2BodyId platformBody = b2CreateBody(world, &platformDef);
	b2ShapeDef platformShape = b2DefaultShapeDef();
	platformShape.enablePreSolveEvents = true;
	b2Polygon slab = b2MakeBox(3.0f, 0.25f);
	level.platform = b2CreatePolygonShape(platformBody, &platformShape, &slab);
	NameShape(level.platform, "platform");

	b2BodyDef ballDef = b2DefaultBodyDef();
	ballDef.type = b2_dynamicBody;
	ballDef.position = (b2Pos){0.0f, 0.5f};
	ballDef.linearVelocity = (b2Vec2){0.0f, 9.0f};
	b2BodyId ball = b2CreateBody(world, &ballDef);
	b2ShapeDef ballShape = b2DefaultShapeDef();
	ballShape.enableContactEvents = true;
	ballShape.enablePreSolveEvents = true;
	b2Circle circle = {{0.0f, 0.0f}, 0.25f};
	level.ball = b2CreateCircleShape(ball, &ballShape, &circle);
	NameShape(level.ball, "ball");

	b2World_SetPreSolveCallback(world, PreSolve, NULL, &level);

	bool above = false;
	for (int step = 1; step <= 240; ++step)
	{
		b2World_Step(world, 1.0f / 60.0f, 4);
		b2Pos p = b2Body_GetPosition(ball);
		if (above == false && p.y - 0.25f > 3.25f)
		{
			above = true;
			printf("step %d: the ball is above the platform\n", step);
		}
		b2ContactEvents events = b2World_GetContactEvents(world);
		for (int i = 0; i < events.beginCount; ++i)
		{
			PrintPair(step, "begin", events.beginEvents[i].shapeIdA, events.beginEvents[i].shapeIdB);
		}
		for (int i = 0; i < events.endCount; ++i)
		{
			PrintPair(step, "end", events.endEvents[i].shapeIdA, events.endEvents[i].shapeIdB);
		}
	}
	b2Pos p = b2Body_GetPosition(ball);
	printf("the ball rests at y = %.2f, %s\n", (double)p.y, b2Body_IsAwake(ball) ? "awake" : "asleep");
	b2DestroyWorld(world);
	return 0;
}
