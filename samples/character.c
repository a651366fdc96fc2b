// A platformer character on the mover kit (character.h). The frame, as Box2D v3.2's mover sample
// runs it: gravity and input set the velocity, the planes around the character give the motion
// toward target = position + v·dt (a few rounds: the planes change as it moves), and the velocity
// loses what pointed into the planes, so it slides along walls and stops on slopes it stands on.
// Static shapes are rigid planes; dynamic ones are soft (they push back at most a few centimetres
// a frame and leave the velocity alone): the kinematic body shoves them aside instead.
#include "character.h"

#include <float.h>
#include <string.h>

#define CHARACTER_MAX_PLANES 16
#define CHARACTER_ROUNDS 5
#define CHARACTER_SOFT_PUSH 0.02f ///< m, what a dynamic shape may push the character per frame
#define CHARACTER_WALKABLE 0.7071f ///< cos 45°: steeper planes are walls

typedef struct CharacterPlanes
{
	tbWorldId world;
	tbCollisionPlane planes[CHARACTER_MAX_PLANES];
	int count;
	bool onGround;
} CharacterPlanes;

static bool CollectPlane(tbShapeId shapeId, const tbPlaneResult* result, void* context)
{
	CharacterPlanes* p = context;
	if (p->count == CHARACTER_MAX_PLANES)
	{
		return false;
	}
	bool rigid = tbBody_GetType(tbShape_GetBody(shapeId)) != tb_dynamicBody;
	tbCollisionPlane* plane = p->planes + p->count++;
	plane->plane = result->plane;
	plane->pushLimit = rigid ? FLT_MAX : CHARACTER_SOFT_PUSH;
	plane->push = 0.0f;
	plane->clipVelocity = rigid;
	p->onGround = p->onGround || (rigid && result->plane.normal.y >= CHARACTER_WALKABLE);
	return true;
}

static tbQueryFilter CharacterFilter(void)
{
	tbQueryFilter filter = tbDefaultQueryFilter();
	filter.maskBits &= ~CHARACTER_CATEGORY;
	return filter;
}

Character Character_Create(tbWorldId world, tbVec2 feet, float radius, float height)
{
	Character c = {0};
	c.capsule = (tbCapsule){{0.0f, radius}, {0.0f, height - radius}, radius};
	c.position = feet;
	c.gravity = 20.0f;
	c.jumpSpeed = 9.0f;
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_kinematicBody;
	bodyDef.position = feet;
	bodyDef.name = "character";
	c.body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.filter.categoryBits = CHARACTER_CATEGORY;
	tbCreateCapsuleShape(c.body, &shapeDef, &c.capsule);
	return c;
}

void Character_Step(Character* c, tbWorldId world, float moveSpeed, bool jump, float dt)
{
	c->velocity.x = moveSpeed;
	c->velocity.y = c->onGround && jump ? c->jumpSpeed : c->velocity.y - c->gravity * dt;
	tbQueryFilter filter = CharacterFilter();
	tbVec2 target = tbMulAdd(c->position, dt, c->velocity);
	CharacterPlanes planes;
	memset(&planes, 0, sizeof(planes));
	planes.world = world;
	for (int round = 0; round < CHARACTER_ROUNDS; ++round)
	{
		planes.count = 0;
		planes.onGround = false;
		tbWorld_CollideMover(world, c->position, &c->capsule, filter, CollectPlane, &planes);
		tbPlaneSolverResult solved = tbSolvePlanes(tbSub(target, c->position), planes.planes, planes.count);
		float fraction = tbWorld_CastMover(world, c->position, &c->capsule, solved.delta, filter);
		tbVec2 step = tbMulSV(fraction, solved.delta);
		c->position = tbAdd(c->position, step);
		if (tbLengthSquared(step) < TB_LINEAR_SLOP * TB_LINEAR_SLOP)
		{
			break;
		}
	}
	c->velocity = tbClipVector(c->velocity, planes.planes, planes.count);
	c->onGround = planes.onGround;
	c->planeCount = planes.count;
	tbTransform pose = {c->position, tbRot_identity};
	tbBody_SetTargetTransform(c->body, pose, dt, true);
}
