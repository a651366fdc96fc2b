// Box2D v3 adapter for tumble-bench (see peers.h): builds a Scene as a b2World with bodies and shapes.
// Compiled in its own target (bench/peers.cmake) so that this file alone sees v3's box2d/box2d.h,
// which shares its path with Box2D 2.4's header.
#include "peers.h"

#include <box2d/box2d.h>

#include <math.h>
#include <stdlib.h>

struct PeerWorld
{
	b2WorldId world;
	b2BodyId* bodies; // scene body index -> body
	int bodyCount;
	int* driven; // scene indices of the bodies with a SceneDrive
	int drivenCount;
	int stepIndex;
	int subSteps;
	const Scene* scene;
};

static b2Vec2 ToB2(tbVec2 v)
{
	return (b2Vec2){v.x, v.y};
}

// The scene's polygon as v3 stores one: the same vertices, normals, centroid and radius (both keep
// counter-clockwise hulls with unit outward normals), so thin boxes that a hull would weld survive.
static b2Polygon ToB2Polygon(const tbPolygon* polygon)
{
	b2Polygon result = {0};
	result.count = polygon->count < B2_MAX_POLYGON_VERTICES ? polygon->count : B2_MAX_POLYGON_VERTICES;
	for (int i = 0; i < result.count; ++i)
	{
		result.vertices[i] = ToB2(polygon->vertices[i]);
		result.normals[i] = ToB2(polygon->normals[i]);
	}
	result.centroid = ToB2(polygon->centroid);
	result.radius = polygon->radius;
	return result;
}

static void AddShape(b2BodyId body, const SceneShape* shape)
{
	b2ShapeDef def = b2DefaultShapeDef();
	def.density = shape->density;
	def.material.friction = shape->friction;
	def.material.restitution = shape->restitution;
	def.isSensor = shape->isSensor;
	def.enableHitEvents = shape->enableHitEvents;
	const tbGeometry* g = &shape->geometry;
	switch (g->type)
	{
		case tb_circleShape:
		{
			b2Circle circle = {ToB2(g->circle.center), g->circle.radius};
			b2CreateCircleShape(body, &def, &circle);
			break;
		}
		case tb_capsuleShape:
		{
			b2Capsule capsule = {ToB2(g->capsule.center1), ToB2(g->capsule.center2), g->capsule.radius};
			b2CreateCapsuleShape(body, &def, &capsule);
			break;
		}
		case tb_segmentShape:
		{
			b2Segment segment = {ToB2(g->segment.point1), ToB2(g->segment.point2)};
			b2CreateSegmentShape(body, &def, &segment);
			break;
		}
		case tb_polygonShape:
		{
			b2Polygon polygon = ToB2Polygon(&g->polygon);
			b2CreatePolygonShape(body, &def, &polygon);
			break;
		}
		default:
			break;
	}
}

static b2BodyType ToB2Type(tbBodyType type)
{
	switch (type)
	{
		case tb_dynamicBody:
			return b2_dynamicBody;
		case tb_kinematicBody:
			return b2_kinematicBody;
		default:
			return b2_staticBody;
	}
}

static b2BodyId MakeBody(b2WorldId world, const SceneBody* sb)
{
	b2BodyDef def = b2DefaultBodyDef();
	def.type = ToB2Type(sb->type);
	def.position = ToB2(sb->position);
	def.rotation = (b2Rot){cosf(sb->angle), sinf(sb->angle)}; // b2MakeRot approximates (~1e-3 rad)
	def.linearDamping = sb->linearDamping;
	def.angularDamping = sb->angularDamping;
	def.gravityScale = sb->gravityScale;
	def.isBullet = sb->bullet;
	def.isAwake = sb->isAwake;
	b2BodyId body = b2CreateBody(world, &def);
	for (int s = 0; s < sb->shapeCount; ++s)
	{
		AddShape(body, sb->shapes + s);
	}
	// v3's body definition takes the origin's velocity; the scene's (as b2Body_SetLinearVelocity's)
	// is the centre of mass's: set once the shapes have placed the centre.
	if (sb->linearVelocity.x != 0.0f || sb->linearVelocity.y != 0.0f)
	{
		b2Body_SetLinearVelocity(body, ToB2(sb->linearVelocity));
	}
	if (sb->angularVelocity != 0.0f)
	{
		b2Body_SetAngularVelocity(body, sb->angularVelocity);
	}
	return body;
}

static int s_workerCount = 1;

void PeerBox2D3_SetWorkerCount(int workerCount)
{
	s_workerCount = workerCount;
}

PeerWorld* PeerBox2D3_Create(const Scene* scene)
{
	PeerWorld* peer = calloc(1, sizeof(PeerWorld));
	b2WorldDef def = b2DefaultWorldDef(); // one worker, no task system: single-threaded
	def.workerCount = s_workerCount;	  // unless --workers: then v3's own scheduler
	def.gravity = ToB2(scene->gravity);
	def.enableSleep = scene->enableSleep;
	peer->world = b2CreateWorld(&def);
	peer->scene = scene;
	peer->subSteps = scene->subSteps;
	peer->bodyCount = scene->bodyCount;
	size_t slots = (size_t)(scene->bodyCount > 0 ? scene->bodyCount : 1);
	peer->bodies = calloc(slots, sizeof(b2BodyId));
	peer->driven = calloc(slots, sizeof(int));
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		peer->bodies[i] = MakeBody(peer->world, scene->bodies + i);
		if (scene->bodies[i].drive.enabled)
		{
			peer->driven[peer->drivenCount++] = i;
		}
	}
	return peer;
}

void PeerBox2D3_Step(PeerWorld* peer)
{
	const Scene* scene = peer->scene;
	for (int i = 0; i < peer->drivenCount; ++i)
	{
		tbTransform target;
		Scene_DriveTarget(scene, peer->driven[i], peer->stepIndex, &target);
		b2Transform b2Target = {ToB2(target.p), {target.q.c, target.q.s}};
		b2Body_SetTargetTransform(peer->bodies[peer->driven[i]], b2Target, scene->timeStep, true);
	}
	peer->stepIndex += 1;
	b2World_Step(peer->world, scene->timeStep, peer->subSteps);
}

PeerBody PeerBox2D3_GetBody(PeerWorld* peer, int bodyIndex)
{
	b2BodyId body = peer->bodies[bodyIndex];
	b2Vec2 p = b2Body_GetPosition(body), v = b2Body_GetLinearVelocity(body);
	b2Rot q = b2Body_GetRotation(body);
	PeerBody result = {{p.x, p.y}, {q.c, q.s}, {v.x, v.y}, b2Body_GetAngularVelocity(body)};
	return result;
}

PeerCounters PeerBox2D3_GetCounters(PeerWorld* peer)
{
	b2Counters counters = b2World_GetCounters(peer->world);
	PeerCounters result = {counters.bodyCount, counters.contactCount, 0};
	for (int i = 0; i < peer->bodyCount; ++i)
	{
		b2BodyId body = peer->bodies[i];
		result.awakeBodyCount += b2Body_GetType(body) != b2_staticBody && b2Body_IsAwake(body) ? 1 : 0;
	}
	return result;
}

void PeerBox2D3_Destroy(PeerWorld* peer)
{
	b2DestroyWorld(peer->world);
	free(peer->bodies);
	free(peer->driven);
	free(peer);
}
