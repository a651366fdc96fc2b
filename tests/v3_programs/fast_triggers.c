// Trigger zones crossed between two steps, under Box2D v3.2's rules: a bullet and a fast crate
// fired through thin gates (a gate 0.1 m wide against 5 m of travel a step), so that no step ends
// with a visitor inside a gate. Each gate must still report the visitor: it begins touching in the
// step it is crossed and ends in the next. A bullet also sees a moving gate; a fast body that is
// not a bullet sees only gates on static bodies; a shape without sensor events is never seen; a gate
// behind the wall that stops the bullet is never reached. Each event is printed in the step it is
// reported, with the number of visitors the first gate lists.
#include "program.h"

static b2BodyId AddBody(b2WorldId world, b2BodyType type, b2Pos position, b2Vec2 velocity, bool bullet)
{
	b2BodyDef bodyDef = b2DefaultBodyDef();
	bodyDef.type = type;
	bodyDef.position = position;
	bodyDef.linearVelocity = velocity;
	bodyDef.gravityScale = 0.0f;
	bodyDef.isBullet = bullet;
	return b2CreateBody(world, &bodyDef);
}

static b2ShapeId AddBall(b2BodyId body, float radius, bool sensorEvents, const char* name)
{
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	shapeDef.enableSensorEvents = sensorEvents;
	b2Circle circle = {{0.0f, 0.0f}, radius};
	b2ShapeId shape = b2CreateCircleShape(body, &shapeDef, &circle);
	NameShape(shape, name);
	return shape;
}

static void PrintEvents(int step, b2WorldId world, b2ShapeId gate)
{
	if (PrintSensorEvents(step, world) > 0)
	{
		b2ShapeId visitors[8];
		printf("  gate lists %d\n", b2Shape_GetSensorData(gate, visitors, 8));
	}
}

int main(void)
{
	b2WorldDef worldDef = b2DefaultWorldDef();
	b2WorldId world = b2CreateWorld(&worldDef);
	b2Vec2 still = {0.0f, 0.0f};

	// Two static gates spanning every lane, a wall in the bullet's lane and a gate behind it.
	b2BodyId gateBody = AddBody(world, b2_staticBody, (b2Pos){10.0f, 5.0f}, still, false);
	b2ShapeId gate = AddBox(gateBody, 0.05f, 6.0f, true, true, "gate");
	b2BodyId gate2Body = AddBody(world, b2_staticBody, (b2Pos){22.0f, 5.0f}, still, false);
	AddBox(gate2Body, 0.05f, 6.0f, true, true, "gate2");
	b2BodyId wallBody = AddBody(world, b2_staticBody, (b2Pos){40.0f, 2.0f}, still, false);
	AddBox(wallBody, 0.5f, 1.0f, false, false, "wall");
	b2BodyId hiddenBody = AddBody(world, b2_staticBody, (b2Pos){45.0f, 2.0f}, still, false);
	AddBox(hiddenBody, 0.05f, 1.0f, true, true, "hidden");
	// A kinematic gate drifting across the lanes: only the bullet sweeps against moving bodies.
	b2BodyId droneBody = AddBody(world, b2_kinematicBody, (b2Pos){31.0f, 5.0f}, (b2Vec2){0.0f, 0.1f}, false);
	AddBox(droneBody, 0.05f, 6.0f, true, true, "drone");

	// Lane y = 2: a bullet at 300 m/s, never inside a gate at the end of a step; lane y = 6: a crate
	// at 300 m/s that is not a bullet, which ends step 2 inside the first gate and leaves it; lane
	// y = 9: a ball at 300 m/s without sensor events.
	b2BodyId bullet = AddBody(world, b2_dynamicBody, (b2Pos){0.7f, 2.0f}, (b2Vec2){300.0f, 0.0f}, true);
	AddBall(bullet, 0.1f, true, "bullet");
	b2BodyId crate = AddBody(world, b2_dynamicBody, (b2Pos){0.0f, 6.0f}, (b2Vec2){300.0f, 0.0f}, false);
	AddBox(crate, 0.1f, 0.1f, false, true, "crate");
	b2BodyId ghost = AddBody(world, b2_dynamicBody, (b2Pos){0.0f, 9.0f}, (b2Vec2){300.0f, 0.0f}, false);
	AddBall(ghost, 0.1f, false, "ghost");

	for (int step = 1; step <= 30; ++step)
	{
		b2World_Step(world, 1.0f / 60.0f, 4);
		PrintEvents(step, world, gate);
	}
	b2DestroyWorld(world);
	return 0;
}
