// Sensor events as a game sees them under Box2D v3.2's rules: a trigger zone on the ground; a
// kinematic cart crossing it; a ball falling through it; a ball that does not ask for sensor
// events falling through unseen; a kinematic lift parked inside and destroyed there; a second
// sensor carried through the zone (two sensors see each other). Each event is printed in the step
// it is reported, with the number of visitors the zone lists.
#include "program.h"

static b2BodyId AddBody(b2WorldId world, b2BodyType type, b2Pos position, b2Vec2 velocity)
{
	b2BodyDef bodyDef = b2DefaultBodyDef();
	bodyDef.type = type;
	bodyDef.position = position;
	bodyDef.linearVelocity = velocity;
	bodyDef.gravityScale = type == b2_dynamicBody ? 1.0f : 0.0f;
	return b2CreateBody(world, &bodyDef);
}

static b2ShapeId AddBall(b2BodyId body, bool sensorEvents, const char* name)
{
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	shapeDef.enableSensorEvents = sensorEvents;
	b2Circle circle = {{0.0f, 0.0f}, 0.5f};
	b2ShapeId shape = b2CreateCircleShape(body, &shapeDef, &circle);
	NameShape(shape, name);
	return shape;
}

int main(void)
{
	b2WorldDef worldDef = b2DefaultWorldDef();
	b2WorldId world = b2CreateWorld(&worldDef);
	b2BodyId ground = AddBody(world, b2_staticBody, (b2Pos){0.0f, 0.0f}, (b2Vec2){0.0f, 0.0f});
	AddBox(ground, 20.0f, 0.5f, false, false, "ground");
	b2BodyId zoneBody = AddBody(world, b2_staticBody, (b2Pos){0.0f, 5.0f}, (b2Vec2){0.0f, 0.0f});
	b2ShapeId zone = AddBox(zoneBody, 2.0f, 1.5f, true, true, "zone");

	b2BodyId cart = AddBody(world, b2_kinematicBody, (b2Pos){-8.0f, 5.0f}, (b2Vec2){3.0f, 0.0f});
	AddBox(cart, 0.5f, 0.25f, false, true, "cart");
	b2BodyId ball = AddBody(world, b2_dynamicBody, (b2Pos){0.5f, 8.5f}, (b2Vec2){0.0f, 0.0f});
	AddBall(ball, true, "ball");
	b2BodyId ghost = AddBody(world, b2_dynamicBody, (b2Pos){-1.0f, 9.0f}, (b2Vec2){0.0f, 0.0f});
	AddBall(ghost, false, "ghost");
	b2BodyId lift = AddBody(world, b2_kinematicBody, (b2Pos){1.5f, 5.5f}, (b2Vec2){0.0f, 0.0f});
	AddBox(lift, 0.25f, 0.25f, false, true, "lift");
	b2BodyId probe = AddBody(world, b2_kinematicBody, (b2Pos){0.0f, 12.0f}, (b2Vec2){0.0f, -2.0f});
	AddBox(probe, 0.25f, 0.25f, true, true, "probe");

	b2ShapeId visitors[8];
	for (int step = 1; step <= 360; ++step)
	{
		if (step == 90)
		{
			b2DestroyBody(lift);
		}
		b2World_Step(world, 1.0f / 60.0f, 4);
		if (PrintSensorEvents(step, world) > 0)
		{
			int count = b2Shape_GetSensorData(zone, visitors, 8);
			printf("  the zone lists %d\n", count);
		}
	}
	b2DestroyWorld(world);
	return 0;
}
