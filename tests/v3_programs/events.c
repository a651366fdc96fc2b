// Contact events as a game sees them under Box2D v3.2's rules: a crate and a capsule that ask for
// contact events land on a ground that does not (either shape asking is enough), a ball that does
// not ask lands unreported, the crate asks for hit events too; the crate is destroyed while it
// rests (its end event comes with the next step's events) and the capsule stops asking.
#include "program.h"

static b2ShapeId AddBody(b2WorldId world, b2BodyType type, b2Pos position, const char* name, bool contactEvents,
						 bool hitEvents, int kind, b2BodyId* bodyOut)
{
	b2BodyDef bodyDef = b2DefaultBodyDef();
	bodyDef.type = type;
	bodyDef.position = position;
	b2BodyId body = b2CreateBody(world, &bodyDef);
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	shapeDef.enableContactEvents = contactEvents;
	shapeDef.enableHitEvents = hitEvents;
	b2ShapeId shape;
	if (kind == 0)
	{
		b2Polygon box = type == b2_staticBody ? b2MakeBox(20.0f, 0.5f) : b2MakeBox(0.5f, 0.5f);
		shape = b2CreatePolygonShape(body, &shapeDef, &box);
	}
	else if (kind == 1)
	{
		b2Circle circle = {{0.0f, 0.0f}, 0.5f};
		shape = b2CreateCircleShape(body, &shapeDef, &circle);
	}
	else
	{
		b2Capsule capsule = {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f};
		shape = b2CreateCapsuleShape(body, &shapeDef, &capsule);
	}
	NameShape(shape, name);
	*bodyOut = body;
	return shape;
}

int main(void)
{
	b2WorldDef worldDef = b2DefaultWorldDef();
	b2WorldId world = b2CreateWorld(&worldDef);
	b2BodyId ground, crate, ball, capsule;
	AddBody(world, b2_staticBody, (b2Pos){0.0f, 0.0f}, "ground", false, false, 0, &ground);
	AddBody(world, b2_dynamicBody, (b2Pos){-4.0f, 4.0f}, "crate", true, true, 0, &crate);
	AddBody(world, b2_dynamicBody, (b2Pos){0.0f, 6.0f}, "ball", false, false, 1, &ball);
	b2ShapeId capsuleShape = AddBody(world, b2_dynamicBody, (b2Pos){4.0f, 3.0f}, "capsule", true, false, 2, &capsule);

	for (int step = 1; step <= 240; ++step)
	{
		if (step == 120)
		{
			b2DestroyBody(crate);
		}
		if (step == 150)
		{
			b2Shape_EnableContactEvents(capsuleShape, false);
			b2Body_ApplyLinearImpulseToCenter(capsule, (b2Vec2){0.0f, 6.0f}, true);
		}
		b2World_Step(world, 1.0f / 60.0f, 4);
		b2ContactEvents events = b2World_GetContactEvents(world);
		for (int i = 0; i < events.beginCount; ++i)
		{
			PrintPair(step, "begin", events.beginEvents[i].shapeIdA, events.beginEvents[i].shapeIdB);
		}
		for (int i = 0; i < events.endCount; ++i)
		{
			PrintPair(step, "end", events.endEvents[i].shapeIdA, events.endEvents[i].shapeIdB);
		}
		for (int i = 0; i < events.hitCount; ++i)
		{
			PrintPair(step, "hit", events.hitEvents[i].shapeIdA, events.hitEvents[i].shapeIdB);
			printf("  approaching at about %.0f m/s\n", (double)events.hitEvents[i].approachSpeed);
		}
	}
	b2Pos p = b2Body_GetPosition(ball);
	printf("ball rests at y = %.2f\n", (double)p.y);
	b2DestroyWorld(world);
	return 0;
}
