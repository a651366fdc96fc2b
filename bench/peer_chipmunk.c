// Chipmunk 7 adapter for tumble-bench (see peers.h): builds a Scene as a cpSpace.
#include "peers.h"

#include <chipmunk/chipmunk_private.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

struct PeerWorld
{
	cpSpace* space;
	cpBody** bodies; // scene body index -> body
	int bodyCount;
	int* driven; // scene indices of the bodies with a SceneDrive
	int drivenCount;
	int stepIndex;
	const Scene* scene;
	float timeStep;
};

static cpVect ToCp(tbVec2 v)
{
	return cpv(v.x, v.y);
}

static cpShape* MakeShape(cpBody* body, const tbGeometry* g)
{
	switch (g->type)
	{
		case tb_circleShape:
			return cpCircleShapeNew(body, g->circle.radius, ToCp(g->circle.center));
		case tb_capsuleShape:
			return cpSegmentShapeNew(body, ToCp(g->capsule.center1), ToCp(g->capsule.center2), g->capsule.radius);
		case tb_segmentShape:
			return cpSegmentShapeNew(body, ToCp(g->segment.point1), ToCp(g->segment.point2), 0.0);
		case tb_polygonShape:
		{
			cpVect points[TB_MAX_POLYGON_VERTICES];
			for (int i = 0; i < g->polygon.count; ++i)
			{
				points[i] = ToCp(g->polygon.vertices[i]);
			}
			return cpPolyShapeNew(body, g->polygon.count, points, cpTransformIdentity, g->polygon.radius);
		}
		default:
			return NULL;
	}
}

static int CompareFloats(const void* a, const void* b)
{
	float x = *(const float*)a, y = *(const float*)b;
	return (x > y) - (x < y);
}

// Spatial-hash cell: the median extent of the dynamic shapes (Chipmunk's advice: about the
// size of the typical shape).
static float HashCellSize(const Scene* scene)
{
	int count = Scene_ShapeCount(scene), n = 0;
	float* sizes = malloc(sizeof(float) * (size_t)(count > 0 ? count : 1));
	tbTransform identity = {{0.0f, 0.0f}, {1.0f, 0.0f}};
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		for (int s = 0; s < scene->bodies[i].shapeCount && scene->bodies[i].type == tb_dynamicBody; ++s)
		{
			tbAABB box = tbComputeShapeAABB(&scene->bodies[i].shapes[s].geometry, identity);
			float w = box.upperBound.x - box.lowerBound.x, h = box.upperBound.y - box.lowerBound.y;
			sizes[n++] = w > h ? w : h;
		}
	}
	float size = 1.0f;
	if (n > 0)
	{
		qsort(sizes, (size_t)n, sizeof(float), CompareFloats);
		size = sizes[n / 2];
	}
	free(sizes);
	return size;
}

static cpBody* MakeBody(cpSpace* space, const SceneBody* sb)
{
	cpBody* body;
	switch (sb->type)
	{
		case tb_dynamicBody:
			body = cpBodyNew(0.0, 0.0); // mass and inertia accumulate from the shapes' densities
			break;
		case tb_kinematicBody:
			body = cpBodyNewKinematic();
			break;
		default:
			body = cpBodyNewStatic();
			break;
	}
	cpSpaceAddBody(space, body);
	for (int s = 0; s < sb->shapeCount; ++s)
	{
		const SceneShape* shape = sb->shapes + s;
		cpShape* cs = MakeShape(body, &shape->geometry);
		if (cs == NULL)
		{
			continue;
		}
		if (sb->type == tb_dynamicBody)
		{
			cpShapeSetDensity(cs, shape->density);
		}
		cpShapeSetFriction(cs, sqrtf(shape->friction));
		cpShapeSetElasticity(cs, sqrtf(shape->restitution));
		cpShapeSetSensor(cs, shape->isSensor);
		// A negative group never collides with itself: Chipmunk's group does the same. Categories
		// and masks map to Chipmunk's bitmasks (their low 32 bits).
		cpGroup group = shape->groupIndex < 0 ? (cpGroup)(uintptr_t)(-shape->groupIndex) : CP_NO_GROUP;
		cpShapeSetFilter(cs, cpShapeFilterNew(group, (cpBitmask)shape->categoryBits, (cpBitmask)shape->maskBits));
		cpSpaceAddShape(space, cs);
	}
	cpBodySetAngle(body, sb->angle);
	cpBodySetPosition(body, ToCp(sb->position));
	if (sb->type != tb_staticBody)
	{
		cpBodySetVelocity(body, ToCp(sb->linearVelocity));
		cpBodySetAngularVelocity(body, sb->angularVelocity);
	}
	return body;
}

// A revolute joint as Chipmunk builds one: a pivot at the two anchors (body-local, from the body
// origin), a rotary limit on θB − θA shifted by the frames' angles (Tumble's angle is
// (θB + φB) − (θA + φA)), and a simple motor whose rate is −motorSpeed (Chipmunk drives ωB − ωA
// to −rate) with its torque capped by maxForce. Other kinds, and revolute springs, are not mapped:
// such a scene is not run (false).
static bool AddJoint(PeerWorld* peer, const SceneJoint* sj)
{
	if (sj->type != tb_revoluteJoint || sj->def.revolute.enableSpring)
	{
		return false;
	}
	const tbRevoluteJointDef* s = &sj->def.revolute;
	cpBody* a = peer->bodies[sj->bodyA];
	cpBody* b = peer->bodies[sj->bodyB];
	if (cpBodyGetType(a) != CP_BODY_TYPE_DYNAMIC && cpBodyGetType(b) != CP_BODY_TYPE_DYNAMIC)
	{
		return true; // between two bodies that never move (joint_grid's top row): nothing to solve
	}
	tbTransform fA = s->base.localFrameA, fB = s->base.localFrameB;
	cpConstraint* pivot = cpPivotJointNew2(a, b, ToCp(fA.p), ToCp(fB.p));
	cpSpaceAddConstraint(peer->space, pivot);
	float offset = atan2f(fB.q.s, fB.q.c) - atan2f(fA.q.s, fA.q.c);
	if (s->enableLimit)
	{
		cpSpaceAddConstraint(peer->space, cpRotaryLimitJointNew(a, b, s->lowerAngle - offset, s->upperAngle - offset));
	}
	if (s->enableMotor)
	{
		cpConstraint* motor = cpSimpleMotorNew(a, b, -s->motorSpeed);
		cpConstraintSetMaxForce(motor, s->maxMotorTorque);
		cpSpaceAddConstraint(peer->space, motor);
	}
	if (s->base.collideConnected == false)
	{
		cpConstraintSetCollideBodies(pivot, cpFalse);
	}
	return true;
}

PeerWorld* PeerChipmunk_Create(const Scene* scene, bool useTree)
{
	// (a cpDampedRotarySpring would need its stiffness and damping from the bodies' inertia)
	if (Peer_RefuseSpawnSchedule(scene, "chipmunk-7", "which this adapter does not map to Chipmunk"))
	{
		return NULL;
	}
	PeerWorld* peer = calloc(1, sizeof(PeerWorld));
	peer->space = cpSpaceNew();
	peer->timeStep = scene->timeStep;
	cpSpaceSetIterations(peer->space, 10);
	cpSpaceSetGravity(peer->space, ToCp(scene->gravity));
	cpSpaceSetCollisionSlop(peer->space, 0.01);
	if (scene->enableSleep)
	{
		cpSpaceSetSleepTimeThreshold(peer->space, 0.5);
	}
	if (!useTree)
	{
		int count = 10 * Scene_ShapeCount(scene);
		cpSpaceUseSpatialHash(peer->space, HashCellSize(scene), count > 1000 ? count : 1000);
	}
	peer->bodyCount = scene->bodyCount;
	peer->bodies = calloc((size_t)(scene->bodyCount > 0 ? scene->bodyCount : 1), sizeof(cpBody*));
	peer->driven = calloc((size_t)(scene->bodyCount > 0 ? scene->bodyCount : 1), sizeof(int));
	peer->scene = scene;
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		peer->bodies[i] = MakeBody(peer->space, scene->bodies + i);
		if (scene->bodies[i].drive.enabled)
		{
			peer->driven[peer->drivenCount++] = i;
		}
	}
	for (int j = 0; j < scene->jointCount; ++j)
	{
		if (AddJoint(peer, scene->joints + j) == false)
		{
			fprintf(stderr, "chipmunk-7: joint %d (%s) is not mapped to Chipmunk; scene not run\n", j,
					Scene_JointTypeName(scene->joints[j].type));
			PeerChipmunk_Destroy(peer);
			return NULL;
		}
	}
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		if (scene->enableSleep && !scene->bodies[i].isAwake && scene->bodies[i].type == tb_dynamicBody)
		{
			cpBodySleep(peer->bodies[i]);
		}
	}
	return peer;
}

// Chipmunk has no target-transform call: the velocity that reaches the target, from the body's pose.
static void DriveBody(PeerWorld* peer, int index)
{
	tbTransform target;
	Scene_DriveTarget(peer->scene, index, peer->stepIndex, &target);
	cpBody* body = peer->bodies[index];
	cpVect p = cpBodyGetPosition(body), cog = cpBodyGetCenterOfGravity(body);
	double angle = cpBodyGetAngle(body);
	tbTransform current = {{(float)p.x, (float)p.y}, {(float)cos(angle), (float)sin(angle)}};
	tbVec2 v, localCenter = {(float)cog.x, (float)cog.y};
	float w;
	Scene_TargetVelocity(current, localCenter, target, peer->timeStep, &v, &w);
	cpBodySetVelocity(body, ToCp(v));
	cpBodySetAngularVelocity(body, w);
}

void PeerChipmunk_Step(PeerWorld* peer)
{
	for (int i = 0; i < peer->drivenCount; ++i)
	{
		DriveBody(peer, peer->driven[i]);
	}
	peer->stepIndex += 1;
	cpSpaceStep(peer->space, peer->timeStep);
}

PeerBody PeerChipmunk_GetBody(PeerWorld* peer, int bodyIndex)
{
	cpBody* body = peer->bodies[bodyIndex];
	cpVect p = cpBodyGetPosition(body), v = cpBodyGetVelocity(body);
	double angle = cpBodyGetAngle(body);
	PeerBody result = {{(float)p.x, (float)p.y}, {(float)cos(angle), (float)sin(angle)}, {(float)v.x, (float)v.y},
					   (float)cpBodyGetAngularVelocity(body)};
	return result;
}

PeerCounters PeerChipmunk_GetCounters(PeerWorld* peer)
{
	PeerCounters counters = {peer->bodyCount, peer->space->arbiters->num, 0};
	for (int i = 0; i < peer->bodyCount; ++i)
	{
		cpBody* body = peer->bodies[i];
		counters.awakeBodyCount += cpBodyGetType(body) != CP_BODY_TYPE_STATIC && !cpBodyIsSleeping(body) ? 1 : 0;
	}
	return counters;
}

static void FreeShape(cpBody* body, cpShape* shape, void* data)
{
	(void)body;
	cpSpaceRemoveShape((cpSpace*)data, shape);
	cpShapeFree(shape);
}

void PeerChipmunk_Destroy(PeerWorld* peer)
{
	for (int i = 0; i < peer->bodyCount; ++i)
	{
		cpBodyEachShape(peer->bodies[i], FreeShape, peer->space);
		cpSpaceRemoveBody(peer->space, peer->bodies[i]);
		cpBodyFree(peer->bodies[i]);
	}
	cpSpaceFree(peer->space);
	free(peer->bodies);
	free(peer->driven);
	free(peer);
}
