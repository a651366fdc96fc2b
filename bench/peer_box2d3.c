// Box2D v3 adapter for tumble-bench (see peers.h): builds a Scene as a b2World with bodies and shapes.
// Compiled in its own target (bench/peers.cmake) so that this file alone sees v3's box2d/box2d.h,
// which shares its path with Box2D 2.4's header.
#include "peers.h"

#include <box2d/box2d.h>
#include <box2d/constants.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

// The living instances of one spawner (see SpawnedInstances in scene.h): a ring of `capacity`
// instances of `bodiesPer` bodies. Their joints are found from the bodies when they go.
typedef struct PeerSpawned
{
	b2BodyId* bodies; // capacity × bodiesPer
	int bodiesPer;
	int capacity;
	int built; // instances built so far
} PeerSpawned;

struct PeerWorld
{
	b2WorldId world;
	b2BodyId* bodies; // scene body index -> body
	const b2BodyId* jointBodies; // what the next joint's body indices refer to: bodies, or a spawned instance's
	PeerSpawned* spawned; // one per scene spawner
	int spawnerCount;
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
	def.filter.groupIndex = shape->groupIndex;
	def.filter.categoryBits = shape->categoryBits;
	def.filter.maskBits = shape->maskBits;
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

static b2BodyId MakeBody(b2WorldId world, const SceneBody* sb, tbVec2 offset)
{
	b2BodyDef def = b2DefaultBodyDef();
	def.type = ToB2Type(sb->type);
	def.position = (b2Vec2){sb->position.x + offset.x, sb->position.y + offset.y};
	def.sleepThreshold = sb->sleepThreshold;
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

static b2Transform ToB2Transform(tbTransform t)
{
	return (b2Transform){ToB2(t.p), {t.q.c, t.q.s}};
}

// v3.2's joint definitions have the very fields of Tumble's (the same grammar), so each kind's
// definition is copied field by field: the same constraint, only the solver differs.
static b2JointDef ToB2JointBase(const PeerWorld* peer, const SceneJoint* sj)
{
	const tbJointDef* d = &sj->def.base;
	b2JointDef base = {0};
	base.bodyIdA = peer->jointBodies[sj->bodyA];
	base.bodyIdB = peer->jointBodies[sj->bodyB];
	base.localFrameA = ToB2Transform(d->localFrameA);
	base.localFrameB = ToB2Transform(d->localFrameB);
	base.forceThreshold = d->forceThreshold;
	base.torqueThreshold = d->torqueThreshold;
	base.constraintHertz = d->constraintHertz;
	base.constraintDampingRatio = d->constraintDampingRatio;
	base.drawScale = d->drawScale;
	base.collideConnected = d->collideConnected;
	return base;
}

static void AddRevolute(PeerWorld* peer, const SceneJoint* sj)
{
	const tbRevoluteJointDef* s = &sj->def.revolute;
	b2RevoluteJointDef d = b2DefaultRevoluteJointDef();
	d.base = ToB2JointBase(peer, sj);
	d.targetAngle = s->targetAngle;
	d.enableSpring = s->enableSpring;
	d.hertz = s->hertz;
	d.dampingRatio = s->dampingRatio;
	d.enableLimit = s->enableLimit;
	d.lowerAngle = s->lowerAngle;
	d.upperAngle = s->upperAngle;
	d.enableMotor = s->enableMotor;
	d.maxMotorTorque = s->maxMotorTorque;
	d.motorSpeed = s->motorSpeed;
	b2CreateRevoluteJoint(peer->world, &d);
}

static void AddPrismatic(PeerWorld* peer, const SceneJoint* sj)
{
	const tbPrismaticJointDef* s = &sj->def.prismatic;
	b2PrismaticJointDef d = b2DefaultPrismaticJointDef();
	d.base = ToB2JointBase(peer, sj);
	d.enableSpring = s->enableSpring;
	d.hertz = s->hertz;
	d.dampingRatio = s->dampingRatio;
	d.targetTranslation = s->targetTranslation;
	d.enableLimit = s->enableLimit;
	d.lowerTranslation = s->lowerTranslation;
	d.upperTranslation = s->upperTranslation;
	d.enableMotor = s->enableMotor;
	d.maxMotorForce = s->maxMotorForce;
	d.motorSpeed = s->motorSpeed;
	b2CreatePrismaticJoint(peer->world, &d);
}

static void AddDistance(PeerWorld* peer, const SceneJoint* sj)
{
	const tbDistanceJointDef* s = &sj->def.distance;
	b2DistanceJointDef d = b2DefaultDistanceJointDef();
	d.base = ToB2JointBase(peer, sj);
	d.length = s->length;
	d.enableSpring = s->enableSpring;
	d.lowerSpringForce = s->lowerSpringForce;
	d.upperSpringForce = s->upperSpringForce;
	d.hertz = s->hertz;
	d.dampingRatio = s->dampingRatio;
	d.enableLimit = s->enableLimit;
	d.minLength = s->minLength;
	d.maxLength = s->maxLength;
	d.enableMotor = s->enableMotor;
	d.maxMotorForce = s->maxMotorForce;
	d.motorSpeed = s->motorSpeed;
	b2CreateDistanceJoint(peer->world, &d);
}

static void AddOtherJoint(PeerWorld* peer, const SceneJoint* sj)
{
	switch (sj->type)
	{
		case tb_weldJoint:
		{
			b2WeldJointDef d = b2DefaultWeldJointDef();
			d.base = ToB2JointBase(peer, sj);
			d.linearHertz = sj->def.weld.linearHertz;
			d.angularHertz = sj->def.weld.angularHertz;
			d.linearDampingRatio = sj->def.weld.linearDampingRatio;
			d.angularDampingRatio = sj->def.weld.angularDampingRatio;
			b2CreateWeldJoint(peer->world, &d);
			break;
		}
		case tb_wheelJoint:
		{
			const tbWheelJointDef* s = &sj->def.wheel;
			b2WheelJointDef d = b2DefaultWheelJointDef();
			d.base = ToB2JointBase(peer, sj);
			d.enableSpring = s->enableSpring;
			d.hertz = s->hertz;
			d.dampingRatio = s->dampingRatio;
			d.enableLimit = s->enableLimit;
			d.lowerTranslation = s->lowerTranslation;
			d.upperTranslation = s->upperTranslation;
			d.enableMotor = s->enableMotor;
			d.maxMotorTorque = s->maxMotorTorque;
			d.motorSpeed = s->motorSpeed;
			b2CreateWheelJoint(peer->world, &d);
			break;
		}
		case tb_motorJoint:
		{
			const tbMotorJointDef* s = &sj->def.motor;
			b2MotorJointDef d = b2DefaultMotorJointDef();
			d.base = ToB2JointBase(peer, sj);
			d.linearVelocity = ToB2(s->linearVelocity);
			d.maxVelocityForce = s->maxVelocityForce;
			d.angularVelocity = s->angularVelocity;
			d.maxVelocityTorque = s->maxVelocityTorque;
			d.linearHertz = s->linearHertz;
			d.linearDampingRatio = s->linearDampingRatio;
			d.maxSpringForce = s->maxSpringForce;
			d.angularHertz = s->angularHertz;
			d.angularDampingRatio = s->angularDampingRatio;
			d.maxSpringTorque = s->maxSpringTorque;
			b2CreateMotorJoint(peer->world, &d);
			break;
		}
		case tb_moverJoint:
		{
			b2MoverJointDef d = b2DefaultMoverJointDef();
			d.base = ToB2JointBase(peer, sj);
			d.linearVelocity = ToB2(sj->def.mover.linearVelocity);
			d.maxVelocityForce = ToB2(sj->def.mover.maxVelocityForce);
			b2CreateMoverJoint(peer->world, &d);
			break;
		}
		case tb_pogoJoint:
		{
			const tbPogoJointDef* s = &sj->def.pogo;
			b2PogoJointDef d = b2DefaultPogoJointDef();
			d.base = ToB2JointBase(peer, sj);
			d.normal = ToB2(s->normal);
			d.hertz = s->hertz;
			d.dampingRatio = s->dampingRatio;
			d.restLength = s->restLength;
			d.maxTensionForce = s->maxTensionForce;
			d.maxCompressionForce = s->maxCompressionForce;
			d.impulse = s->impulse;
			d.velocity = s->velocity;
			b2CreatePogoJoint(peer->world, &d);
			break;
		}
		case tb_filterJoint:
		{
			b2FilterJointDef d = b2DefaultFilterJointDef();
			d.base = ToB2JointBase(peer, sj);
			b2CreateFilterJoint(peer->world, &d);
			break;
		}
		default:
			// Every kind is mapped above: a kind added to Tumble without a mapping here says so
			// instead of running a different scene.
			fprintf(stderr, "box2d-3: joint kind %d has no mapping in this peer; the joint is left out\n", (int)sj->type);
			break;
	}
}

static void AddJoint(PeerWorld* peer, const SceneJoint* sj)
{
	switch (sj->type)
	{
		case tb_revoluteJoint:
			AddRevolute(peer, sj);
			break;
		case tb_prismaticJoint:
			AddPrismatic(peer, sj);
			break;
		case tb_distanceJoint:
			AddDistance(peer, sj);
			break;
		default:
			AddOtherJoint(peer, sj);
			break;
	}
}

// ---------------------------------------------------------------------------------------------
// Spawn schedule (SceneSpawner), as SceneWorld_Step runs it for Tumble: before a step, spawner by
// spawner, destroy the instance whose lifetime ends and the oldest when the ring is full (its
// joints, then its bodies, as v3's rain destroys a human), then build the new one.

static bool AllocateSpawned(PeerWorld* peer, const Scene* scene)
{
	peer->spawnerCount = scene->spawnerCount;
	peer->spawned = calloc((size_t)(scene->spawnerCount > 0 ? scene->spawnerCount : 1), sizeof(PeerSpawned));
	if (peer->spawned == NULL)
	{
		return false;
	}
	for (int i = 0; i < scene->spawnerCount; ++i)
	{
		const SceneSpawner* spawner = scene->spawners + i;
		PeerSpawned* ring = peer->spawned + i;
		ring->capacity = SceneSpawner_Capacity(spawner);
		ring->bodiesPer = scene->templates[spawner->templateIndex].parts->bodyCount;
		ring->bodies = calloc((size_t)(ring->capacity * (ring->bodiesPer > 0 ? ring->bodiesPer : 1)), sizeof(b2BodyId));
		if (ring->bodies == NULL)
		{
			return false;
		}
	}
	return true;
}

// A body with more than 16 joints loses the rest with itself (b2DestroyBody destroys them).
static void DestroyInstance(const b2BodyId* bodies, int count)
{
	for (int b = 0; b < count; ++b)
	{
		b2JointId joints[16];
		int jointCount = b2Body_IsValid(bodies[b]) ? b2Body_GetJoints(bodies[b], joints, 16) : 0;
		for (int j = 0; j < jointCount; ++j)
		{
			b2DestroyJoint(joints[j]);
		}
	}
	for (int b = 0; b < count; ++b)
	{
		if (b2Body_IsValid(bodies[b]))
		{
			b2DestroyBody(bodies[b]);
		}
	}
}

static void RunSpawners(PeerWorld* peer)
{
	const Scene* scene = peer->scene;
	for (int i = 0; i < peer->spawnerCount; ++i)
	{
		const SceneSpawner* spawner = scene->spawners + i;
		PeerSpawned* ring = peer->spawned + i;
		int expired = SceneSpawner_ExpiryAt(spawner, peer->stepIndex);
		if (expired >= 0 && expired < ring->built && expired >= ring->built - ring->capacity)
		{
			DestroyInstance(ring->bodies + (expired % ring->capacity) * ring->bodiesPer, ring->bodiesPer);
		}
		int instance = SceneSpawner_InstanceAt(spawner, peer->stepIndex);
		if (instance < 0)
		{
			continue;
		}
		b2BodyId* bodies = ring->bodies + (instance % ring->capacity) * ring->bodiesPer;
		if (instance >= ring->capacity)
		{
			DestroyInstance(bodies, ring->bodiesPer);
		}
		const Scene* parts = scene->templates[spawner->templateIndex].parts;
		tbVec2 offset = SceneSpawner_Offset(spawner, instance);
		for (int b = 0; b < ring->bodiesPer; ++b)
		{
			bodies[b] = MakeBody(peer->world, parts->bodies + b, offset);
		}
		peer->jointBodies = bodies;
		for (int j = 0; j < parts->jointCount; ++j)
		{
			AddJoint(peer, parts->joints + j);
		}
		ring->built = instance + 1;
	}
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
		peer->bodies[i] = MakeBody(peer->world, scene->bodies + i, tbVec2_zero);
		if (scene->bodies[i].drive.enabled)
		{
			peer->driven[peer->drivenCount++] = i;
		}
	}
	peer->jointBodies = peer->bodies;
	for (int j = 0; j < scene->jointCount; ++j)
	{
		AddJoint(peer, scene->joints + j);
	}
	if (AllocateSpawned(peer, scene) == false)
	{
		PeerBox2D3_Destroy(peer);
		return NULL;
	}
	return peer;
}

void PeerBox2D3_Step(PeerWorld* peer)
{
	const Scene* scene = peer->scene;
	RunSpawners(peer);
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
	for (int s = 0; s < peer->spawnerCount; ++s)
	{
		const PeerSpawned* ring = peer->spawned + s;
		for (int i = 0; i < ring->capacity * ring->bodiesPer; ++i)
		{
			b2BodyId body = ring->bodies[i];
			result.awakeBodyCount += b2Body_IsValid(body) && b2Body_IsAwake(body) ? 1 : 0;
		}
	}
	return result;
}

void PeerBox2D3_SetSubSteps(PeerWorld* peer, int subSteps)
{
	peer->subSteps = subSteps > 0 ? subSteps : peer->scene->subSteps;
}

StageProfile PeerBox2D3_GetProfile(PeerWorld* peer)
{
	b2Profile p = b2World_GetProfile(peer->world);
	StageProfile result;
	result.pairs = p.pairs;
	result.collide = p.collide;
	result.setup = p.solverSetup;
	result.solve = p.constraints;
	result.finalize = p.transforms + p.refit;
	result.continuous = p.bullets;
	result.events = p.hitEvents + p.jointEvents + p.sensorHits + p.sensors;
	result.sleep = p.splitIslands + p.sleepIslands;
	result.step = p.step;
	result.solverSetup = NAN;
	result.prepareConstraints = p.prepareConstraints;
	result.integrateVelocities = p.integrateVelocities;
	result.warmStart = p.warmStart;
	result.solveImpulses = p.solveImpulses;
	result.integratePositions = p.integratePositions;
	result.relaxImpulses = p.relaxImpulses;
	result.applyRestitution = p.applyRestitution;
	result.storeImpulses = p.storeImpulses;
	result.scatterBodies = NAN;
	return result;
}

void PeerBox2D3_Destroy(PeerWorld* peer)
{
	b2DestroyWorld(peer->world);
	free(peer->bodies);
	free(peer->driven);
	for (int i = 0; i < peer->spawnerCount; ++i)
	{
		free(peer->spawned[i].bodies);
	}
	free(peer->spawned);
	free(peer);
}

// ---------------------------------------------------------------------------------------------
// The collision layer alone (see peers.h). Inputs are converted once; the passes call v3's public
// functions the way its world does, so what a pass costs is v3's routine and a loop around it.

static b2Transform ToB2TransformPose(tbTransform t)
{
	return (b2Transform){ToB2(t.p), {t.q.c, t.q.s}};
}

struct PeerPolygonPairs
{
	b2Polygon* a;
	b2Polygon* b;
	b2Transform* xfA;
	b2Transform* xfB;
	int count;
};

PeerPolygonPairs* PeerBox2D3_CreatePolygonPairs(const tbPolygon* a, const tbTransform* xfA, const tbPolygon* b,
												const tbTransform* xfB, int count)
{
	PeerPolygonPairs* pairs = calloc(1, sizeof(PeerPolygonPairs));
	pairs->a = malloc(sizeof(b2Polygon) * (size_t)count);
	pairs->b = malloc(sizeof(b2Polygon) * (size_t)count);
	pairs->xfA = malloc(sizeof(b2Transform) * (size_t)count);
	pairs->xfB = malloc(sizeof(b2Transform) * (size_t)count);
	pairs->count = count;
	for (int i = 0; i < count; ++i)
	{
		pairs->a[i] = ToB2Polygon(a + i);
		pairs->b[i] = ToB2Polygon(b + i);
		pairs->xfA[i] = ToB2TransformPose(xfA[i]);
		pairs->xfB[i] = ToB2TransformPose(xfB[i]);
	}
	return pairs;
}

PeerManifold PeerBox2D3_CollidePolygonPair(const PeerPolygonPairs* pairs, int i)
{
	b2Transform xf = b2InvMulTransforms(pairs->xfA[i], pairs->xfB[i]);
	b2LocalManifold m = b2CollidePolygons(pairs->a + i, pairs->b + i, xf);
	b2Vec2 n = b2RotateVector(pairs->xfA[i].q, m.normal);
	PeerManifold result = {{n.x, n.y}, 0.0f, m.pointCount};
	for (int k = 0; k < m.pointCount; ++k)
	{
		result.depth = fmaxf(result.depth, -m.points[k].separation);
	}
	return result;
}

float PeerBox2D3_CollidePolygonPass(const PeerPolygonPairs* pairs)
{
	float sum = 0.0f;
	for (int i = 0; i < pairs->count; ++i)
	{
		b2Transform xf = b2InvMulTransforms(pairs->xfA[i], pairs->xfB[i]);
		b2LocalManifold m = b2CollidePolygons(pairs->a + i, pairs->b + i, xf);
		sum += b2RotateVector(pairs->xfA[i].q, m.normal).x;
	}
	return sum;
}

void PeerBox2D3_DestroyPolygonPairs(PeerPolygonPairs* pairs)
{
	if (pairs != NULL)
	{
		free(pairs->a);
		free(pairs->b);
		free(pairs->xfA);
		free(pairs->xfB);
		free(pairs);
	}
}

struct PeerTOICases
{
	b2TOIInput* inputs;
	int count;
};

static b2ShapeProxy ToB2Proxy(const tbShapeProxy* proxy)
{
	b2Vec2 points[B2_MAX_POLYGON_VERTICES];
	int count = proxy->count < B2_MAX_POLYGON_VERTICES ? proxy->count : B2_MAX_POLYGON_VERTICES;
	for (int i = 0; i < count; ++i)
	{
		points[i] = ToB2(proxy->points[i]);
	}
	return b2MakeProxy(points, count, proxy->radius);
}

static b2Sweep ToB2Sweep(const tbSweep* s)
{
	return (b2Sweep){ToB2(s->localCenter), ToB2(s->c1), ToB2(s->c2), {s->q1.c, s->q1.s}, {s->q2.c, s->q2.s}};
}

PeerTOICases* PeerBox2D3_CreateTOICases(const tbShapeProxy* a, const tbSweep* sweepA, const tbShapeProxy* b,
										const tbSweep* sweepB, int count)
{
	PeerTOICases* cases = calloc(1, sizeof(PeerTOICases));
	cases->inputs = malloc(sizeof(b2TOIInput) * (size_t)count);
	cases->count = count;
	for (int i = 0; i < count; ++i)
	{
		cases->inputs[i] = (b2TOIInput){ToB2Proxy(a + i), ToB2Proxy(b + i), ToB2Sweep(sweepA + i), ToB2Sweep(sweepB + i), 1.0f};
	}
	return cases;
}

float PeerBox2D3_TimeOfImpactPass(const PeerTOICases* cases, float* fractions, bool* hits)
{
	float sum = 0.0f;
	for (int i = 0; i < cases->count; ++i)
	{
		b2TOIOutput out = b2TimeOfImpact(cases->inputs + i);
		sum += out.fraction;
		if (fractions != NULL)
		{
			fractions[i] = out.fraction;
		}
		if (hits != NULL)
		{
			hits[i] = out.state == b2_toiStateHit;
		}
	}
	return sum;
}

float PeerBox2D3_TOITargetSeparation(float radiusA, float radiusB)
{
	float total = radiusA + radiusB;
	return fmaxf(B2_LINEAR_SLOP, total - B2_LINEAR_SLOP) - total;
}

void PeerBox2D3_DestroyTOICases(PeerTOICases* cases)
{
	if (cases != NULL)
	{
		free(cases->inputs);
		free(cases);
	}
}

typedef struct PeerPair
{
	int a, b;
} PeerPair;

struct PeerTree
{
	b2DynamicTree tree;
	unsigned char* moved; // by proxy id: moved since the last pair update
	int* moveList;		  // the moved proxies' ids, in the order they moved
	int moveCount;
	int capacity;
	PeerPair* pairs;
	int pairCount;
	int pairCapacity;
	int queryProxy; // the proxy whose box is being queried
};

PeerTree* PeerBox2D3_CreateTree(int proxyCapacity)
{
	PeerTree* tree = calloc(1, sizeof(PeerTree));
	tree->tree = b2DynamicTree_Create(proxyCapacity);
	tree->capacity = proxyCapacity > 16 ? proxyCapacity : 16;
	tree->moved = calloc((size_t)tree->capacity, 1);
	tree->moveList = malloc(sizeof(int) * (size_t)tree->capacity);
	tree->pairCapacity = 4 * tree->capacity;
	tree->pairs = malloc(sizeof(PeerPair) * (size_t)tree->pairCapacity);
	return tree;
}

static void BufferMove(PeerTree* tree, int proxyId)
{
	if (proxyId >= tree->capacity)
	{
		int capacity = 2 * proxyId;
		tree->moved = realloc(tree->moved, (size_t)capacity);
		memset(tree->moved + tree->capacity, 0, (size_t)(capacity - tree->capacity));
		tree->moveList = realloc(tree->moveList, sizeof(int) * (size_t)capacity);
		tree->capacity = capacity;
	}
	if (tree->moved[proxyId] == 0)
	{
		tree->moved[proxyId] = 1;
		tree->moveList[tree->moveCount++] = proxyId;
	}
}

int PeerBox2D3_TreeCreateProxy(PeerTree* tree, tbAABB fatAABB)
{
	b2AABB box = {ToB2(fatAABB.lowerBound), ToB2(fatAABB.upperBound)};
	int proxyId = b2DynamicTree_CreateProxy(&tree->tree, box, B2_DEFAULT_CATEGORY_BITS, 0);
	BufferMove(tree, proxyId);
	return proxyId;
}

void PeerBox2D3_TreeMoveProxy(PeerTree* tree, int proxyId, tbAABB fatAABB)
{
	b2AABB box = {ToB2(fatAABB.lowerBound), ToB2(fatAABB.upperBound)};
	b2DynamicTree_EnlargeProxy(&tree->tree, proxyId, box);
	BufferMove(tree, proxyId);
}

static bool PairQuery(int proxyId, uint64_t userData, void* context)
{
	(void)userData;
	PeerTree* tree = context;
	int queryProxy = tree->queryProxy;
	// Not with itself, and a pair of two moved proxies only from the higher id (v3's rule).
	if (proxyId == queryProxy || (proxyId < queryProxy && tree->moved[proxyId]))
	{
		return true;
	}
	if (tree->pairCount == tree->pairCapacity)
	{
		tree->pairCapacity *= 2;
		tree->pairs = realloc(tree->pairs, sizeof(PeerPair) * (size_t)tree->pairCapacity);
	}
	tree->pairs[tree->pairCount++] = (PeerPair){proxyId < queryProxy ? proxyId : queryProxy,
												proxyId < queryProxy ? queryProxy : proxyId};
	return true;
}

int PeerBox2D3_TreeUpdatePairs(PeerTree* tree)
{
	tree->pairCount = 0;
	for (int i = 0; i < tree->moveCount; ++i)
	{
		tree->queryProxy = tree->moveList[i];
		b2AABB box = b2DynamicTree_GetAABB(&tree->tree, tree->queryProxy);
		b2DynamicTree_Query(&tree->tree, box, B2_DEFAULT_MASK_BITS, PairQuery, tree);
	}
	if (tree->moveCount > 0)
	{
		b2DynamicTree_Rebuild(&tree->tree, false);
	}
	for (int i = 0; i < tree->moveCount; ++i)
	{
		tree->moved[tree->moveList[i]] = 0;
	}
	tree->moveCount = 0;
	return tree->pairCount;
}

void PeerBox2D3_DestroyTree(PeerTree* tree)
{
	if (tree != NULL)
	{
		b2DynamicTree_Destroy(&tree->tree);
		free(tree->moved);
		free(tree->moveList);
		free(tree->pairs);
		free(tree);
	}
}
