// Scene model: construction, conversion to a world, and whole-world measures for summaries.
#include "scene.h"
#include "task_system.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

// Growth for the body and shape arrays: double, starting at 8. Out of memory is fatal here:
// the samples have no way to continue without the scene.
static void* GrowArray(void* array, int* capacity, int needed, size_t elementSize)
{
	if (needed <= *capacity)
	{
		return array;
	}
	int newCapacity = *capacity < 8 ? 8 : *capacity;
	while (newCapacity < needed)
	{
		newCapacity *= 2;
	}
	void* grown = realloc(array, (size_t)newCapacity * elementSize);
	if (grown == NULL)
	{
		fprintf(stderr, "scene: out of memory\n");
		abort();
	}
	*capacity = newCapacity;
	return grown;
}

Scene* Scene_Create(void)
{
	Scene* scene = calloc(1, sizeof(Scene));
	if (scene == NULL)
	{
		return NULL;
	}
	scene->gravity = (tbVec2){0.0f, -10.0f};
	scene->timeStep = 1.0f / 60.0f;
	scene->subSteps = 4;
	scene->steps = 600;
	scene->enableSleep = true;
	return scene;
}

void Scene_Destroy(Scene* scene)
{
	if (scene == NULL)
	{
		return;
	}
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		free(scene->bodies[i].shapes);
	}
	free(scene->bodies);
	free(scene->joints);
	for (int i = 0; i < scene->chainCount; ++i)
	{
		free(scene->chains[i].points);
	}
	free(scene->chains);
	for (int i = 0; i < scene->templateCount; ++i)
	{
		Scene_Destroy(scene->templates[i].parts);
	}
	free(scene->templates);
	free(scene->spawners);
	free(scene);
}

int Scene_AddBody(Scene* scene, tbBodyType type, tbVec2 position, float angle)
{
	scene->bodies = GrowArray(scene->bodies, &scene->bodyCapacity, scene->bodyCount + 1, sizeof(SceneBody));
	SceneBody* body = scene->bodies + scene->bodyCount;
	memset(body, 0, sizeof(SceneBody));
	body->type = type;
	body->position = position;
	body->angle = angle;
	body->gravityScale = 1.0f;
	body->isAwake = true;
	body->sleepThreshold = TB_LINEAR_SLEEP_TOLERANCE;
	return scene->bodyCount++;
}

SceneShape Scene_DefaultShape(void)
{
	SceneShape shape;
	memset(&shape, 0, sizeof(shape));
	shape.geometry.type = tb_circleShape;
	shape.geometry.circle.radius = 0.5f;
	shape.density = 1.0f;
	shape.friction = 0.6f;
	shape.categoryBits = TB_DEFAULT_CATEGORY_BITS;
	shape.maskBits = TB_DEFAULT_MASK_BITS;
	return shape;
}

int Scene_AddShape(Scene* scene, int bodyIndex, const SceneShape* shape)
{
	SceneBody* body = scene->bodies + bodyIndex;
	body->shapes = GrowArray(body->shapes, &body->shapeCapacity, body->shapeCount + 1, sizeof(SceneShape));
	body->shapes[body->shapeCount] = *shape;
	return body->shapeCount++;
}

int Scene_AddGeometry(Scene* scene, int bodyIndex, const tbGeometry* geometry, float density, float friction)
{
	SceneShape shape = Scene_DefaultShape();
	shape.geometry = *geometry;
	shape.density = density;
	shape.friction = friction;
	return Scene_AddShape(scene, bodyIndex, &shape);
}

// Zeroed geometry so that unused union bytes never carry garbage (exports and hashes stay stable).
static tbGeometry EmptyGeometry(tbShapeType type)
{
	tbGeometry geometry;
	memset(&geometry, 0, sizeof(geometry));
	geometry.type = type;
	return geometry;
}

tbGeometry Scene_MakeBoxGeometry(float halfWidth, float halfHeight, tbVec2 center, float angle)
{
	tbGeometry geometry = EmptyGeometry(tb_polygonShape);
	if (center.x == 0.0f && center.y == 0.0f && angle == 0.0f)
	{
		geometry.polygon = tbMakeBox(halfWidth, halfHeight);
	}
	else
	{
		geometry.polygon = tbMakeOffsetBox(halfWidth, halfHeight, center, tbMakeRot(angle));
	}
	return geometry;
}

tbGeometry Scene_MakeCircleGeometry(tbVec2 center, float radius)
{
	tbGeometry geometry = EmptyGeometry(tb_circleShape);
	geometry.circle.center = center;
	geometry.circle.radius = radius;
	return geometry;
}

tbGeometry Scene_MakeCapsuleGeometry(tbVec2 center1, tbVec2 center2, float radius)
{
	tbGeometry geometry = EmptyGeometry(tb_capsuleShape);
	geometry.capsule.center1 = center1;
	geometry.capsule.center2 = center2;
	geometry.capsule.radius = radius;
	return geometry;
}

tbGeometry Scene_MakeSegmentGeometry(tbVec2 point1, tbVec2 point2)
{
	tbGeometry geometry = EmptyGeometry(tb_segmentShape);
	geometry.segment.point1 = point1;
	geometry.segment.point2 = point2;
	return geometry;
}

tbGeometry Scene_MakePolygonGeometry(const tbVec2* points, int count, float radius)
{
	tbGeometry geometry = EmptyGeometry(tb_polygonShape);
	tbHull hull = tbComputeHull(points, count);
	if (hull.count > 0)
	{
		geometry.polygon = tbMakePolygon(&hull, radius);
	}
	return geometry;
}

void Scene_DefaultJointDef(tbJointType type, SceneJoint* joint)
{
	memset(&joint->def, 0, sizeof(joint->def));
	switch (type)
	{
		case tb_distanceJoint:
			joint->def.distance = tbDefaultDistanceJointDef();
			break;
		case tb_filterJoint:
			joint->def.filter = tbDefaultFilterJointDef();
			break;
		case tb_motorJoint:
			joint->def.motor = tbDefaultMotorJointDef();
			break;
		case tb_moverJoint:
			joint->def.mover = tbDefaultMoverJointDef();
			break;
		case tb_pogoJoint:
			joint->def.pogo = tbDefaultPogoJointDef();
			break;
		case tb_prismaticJoint:
			joint->def.prismatic = tbDefaultPrismaticJointDef();
			break;
		case tb_weldJoint:
			joint->def.weld = tbDefaultWeldJointDef();
			break;
		case tb_wheelJoint:
			joint->def.wheel = tbDefaultWheelJointDef();
			break;
		case tb_revoluteJoint:
		default:
			joint->def.revolute = tbDefaultRevoluteJointDef();
			break;
	}
}

SceneChain* Scene_AddChain(Scene* scene, int bodyIndex, const tbVec2* points, int count, bool isLoop)
{
	scene->chains = GrowArray(scene->chains, &scene->chainCapacity, scene->chainCount + 1, sizeof(SceneChain));
	SceneChain* chain = scene->chains + scene->chainCount++;
	memset(chain, 0, sizeof(*chain));
	chain->body = bodyIndex;
	chain->points = malloc(sizeof(tbVec2) * (size_t)(count > 0 ? count : 1));
	if (chain->points != NULL && count > 0)
	{
		memcpy(chain->points, points, sizeof(tbVec2) * (size_t)count);
	}
	chain->count = chain->points != NULL ? count : 0;
	chain->isLoop = isLoop;
	chain->friction = 0.6f;
	return chain;
}

static tbChainId CreateSceneChain(tbWorldId worldId, const tbBodyId* bodyIds, int bodyCount, const SceneChain* chain)
{
	(void)worldId;
	if (chain->body < 0 || chain->body >= bodyCount || TB_IS_NULL(bodyIds[chain->body]))
	{
		return TB_NULL_CHAIN_ID;
	}
	tbSurfaceMaterial material = tbDefaultSurfaceMaterial();
	material.friction = chain->friction;
	material.restitution = chain->restitution;
	tbChainDef def = tbDefaultChainDef();
	def.points = chain->points;
	def.count = chain->count;
	def.isLoop = chain->isLoop;
	def.materials = &material;
	def.materialCount = 1;
	return tbCreateChain(bodyIds[chain->body], &def);
}

SceneJoint* Scene_AddJoint(Scene* scene, tbJointType type, int bodyA, int bodyB)
{
	scene->joints = GrowArray(scene->joints, &scene->jointCapacity, scene->jointCount + 1, sizeof(SceneJoint));
	SceneJoint* joint = scene->joints + scene->jointCount++;
	memset(joint, 0, sizeof(*joint));
	joint->type = type;
	joint->bodyA = bodyA;
	joint->bodyB = bodyB;
	Scene_DefaultJointDef(type, joint);
	return joint;
}

static tbVec2 LocalPoint(const SceneBody* body, tbVec2 worldPoint)
{
	tbTransform xf = {body->position, tbMakeRot(body->angle)};
	return tbInvTransformPoint(xf, worldPoint);
}

void Scene_SetJointAnchor(const Scene* scene, SceneJoint* joint, tbVec2 worldPoint)
{
	joint->def.base.localFrameA.p = LocalPoint(scene->bodies + joint->bodyA, worldPoint);
	joint->def.base.localFrameB.p = LocalPoint(scene->bodies + joint->bodyB, worldPoint);
}

int Scene_AddTemplate(Scene* scene, const char* name)
{
	scene->templates =
		GrowArray(scene->templates, &scene->templateCapacity, scene->templateCount + 1, sizeof(SceneTemplate));
	SceneTemplate* entry = scene->templates + scene->templateCount;
	memset(entry, 0, sizeof(*entry));
	snprintf(entry->name, sizeof(entry->name), "%s", name != NULL ? name : "");
	entry->parts = Scene_Create();
	if (entry->parts == NULL)
	{
		fprintf(stderr, "scene: out of memory\n");
		abort();
	}
	return scene->templateCount++;
}

int Scene_FindTemplate(const Scene* scene, const char* name)
{
	for (int i = 0; name != NULL && i < scene->templateCount; ++i)
	{
		if (strcmp(scene->templates[i].name, name) == 0)
		{
			return i;
		}
	}
	return -1;
}

SceneSpawner* Scene_AddSpawner(Scene* scene, int templateIndex, int interval, tbVec2 origin)
{
	scene->spawners =
		GrowArray(scene->spawners, &scene->spawnerCapacity, scene->spawnerCount + 1, sizeof(SceneSpawner));
	SceneSpawner* spawner = scene->spawners + scene->spawnerCount++;
	memset(spawner, 0, sizeof(*spawner));
	spawner->templateIndex = templateIndex;
	spawner->interval = interval;
	spawner->slotCount = 1;
	spawner->origin = origin;
	return spawner;
}

int SceneSpawner_InstanceAt(const SceneSpawner* spawner, int step)
{
	if (step < spawner->firstStep || spawner->interval < 1 || (step - spawner->firstStep) % spawner->interval != 0)
	{
		return -1;
	}
	int instance = (step - spawner->firstStep) / spawner->interval;
	return spawner->count > 0 && instance >= spawner->count ? -1 : instance;
}

int SceneSpawner_ExpiryAt(const SceneSpawner* spawner, int step)
{
	return spawner->lifetime > 0 ? SceneSpawner_InstanceAt(spawner, step - spawner->lifetime) : -1;
}

int SceneSpawner_Capacity(const SceneSpawner* spawner)
{
	int capacity = spawner->keep > 0 ? spawner->keep : INT_MAX;
	capacity = spawner->count > 0 && spawner->count < capacity ? spawner->count : capacity;
	if (spawner->lifetime > 0 && spawner->interval > 0)
	{
		int byLifetime = (spawner->lifetime - 1) / spawner->interval + 1;
		capacity = byLifetime < capacity ? byLifetime : capacity;
	}
	return capacity == INT_MAX ? 1 : capacity;
}

tbVec2 SceneSpawner_Offset(const SceneSpawner* spawner, int instance)
{
	int slot = spawner->slotCount > 1 ? instance % spawner->slotCount : 0;
	return tbAdd(spawner->origin, tbMulSV((float)slot, spawner->slotStep));
}

// Instances a spawner has built before step `steps` (that is, in steps 0 … steps − 1).
static int InstancesBuiltBefore(const SceneSpawner* spawner, int steps)
{
	if (steps <= spawner->firstStep || spawner->interval < 1)
	{
		return 0;
	}
	int built = (steps - 1 - spawner->firstStep) / spawner->interval + 1;
	return spawner->count > 0 && built > spawner->count ? spawner->count : built;
}

void Scene_LiveCounts(const Scene* scene, int steps, int* bodyCount, int* jointCount)
{
	*bodyCount = scene->bodyCount;
	*jointCount = scene->jointCount;
	for (int i = 0; i < scene->spawnerCount; ++i)
	{
		const SceneSpawner* spawner = scene->spawners + i;
		int built = InstancesBuiltBefore(spawner, steps);
		int oldest = spawner->keep > 0 && built > spawner->keep ? built - spawner->keep : 0;
		if (spawner->lifetime > 0 && spawner->interval > 0)
		{
			// alive: built before step s ≥ steps − lifetime (destroyed before s + lifetime ≥ steps)
			int first = steps - spawner->lifetime - spawner->firstStep;
			int byLifetime = first > 0 ? (first - 1) / spawner->interval + 1 : 0;
			oldest = byLifetime > oldest ? byLifetime : oldest;
		}
		int live = built > oldest ? built - oldest : 0;
		const Scene* parts = scene->templates[spawner->templateIndex].parts;
		*bodyCount += live * parts->bodyCount;
		*jointCount += live * parts->jointCount;
	}
}

int Scene_ShapeCount(const Scene* scene)
{
	int count = 0;
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		count += scene->bodies[i].shapeCount;
	}
	return count;
}

bool Scene_DriveTarget(const Scene* scene, int bodyIndex, int step, tbTransform* target)
{
	const SceneBody* body = scene->bodies + bodyIndex;
	if (body->drive.enabled == false)
	{
		return false;
	}
	// tbComputeCosSin, not libm's sinf: the same path on every platform (docs/web.md)
	float phase = tbComputeCosSin(body->drive.angularFrequency * scene->timeStep * (float)step).sine;
	target->p = tbMulAdd(body->position, phase, body->drive.amplitude);
	target->q = tbMakeRot(body->angle);
	return true;
}

void Scene_TargetVelocity(tbTransform current, tbVec2 localCenter, tbTransform target, float timeStep,
						  tbVec2* linearVelocity, float* angularVelocity)
{
	tbVec2 center = tbTransformPoint(current, localCenter);
	tbVec2 targetCenter = tbTransformPoint(target, localCenter);
	*linearVelocity = tbMulSV(1.0f / timeStep, tbSub(targetCenter, center));
	*angularVelocity = tbRelativeAngle(current.q, target.q) / timeStep;
}

// ---------------------------------------------------------------------------------------------
// Building a world

static void ApplyMethods(tbWorldDef* def, const SceneMethods* methods)
{
	if (methods->hasBroadPhase)
	{
		def->broadPhase = methods->broadPhase;
	}
	if (methods->hasNarrowPhase)
	{
		def->narrowPhase = methods->narrowPhase;
	}
	if (methods->hasContinuous)
	{
		def->continuous = methods->continuous;
	}
	if (methods->hasSolver)
	{
		def->solver = methods->solver;
	}
}

tbWorldDef Scene_MakeWorldDef(const Scene* scene, const SceneOverrides* overrides)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = scene->gravity;
	def.enableSleep = scene->enableSleep;
	ApplyMethods(&def, &scene->methods);
	if (overrides != NULL)
	{
		ApplyMethods(&def, &overrides->methods);
		if (overrides->velocityIterations > 0)
		{
			def.velocityIterations = overrides->velocityIterations;
		}
		if (overrides->relaxIterations > 0)
		{
			def.relaxIterations = overrides->relaxIterations;
		}
		if (overrides->finalRelaxGiven)
		{
			def.finalRelaxIterations = overrides->finalRelaxIterations;
		}
		if (overrides->settledHertzRatio > 0.0f)
		{
			def.settledHertzRatio = overrides->settledHertzRatio;
		}
		if (overrides->scalarSolver)
		{
			def.enableWideSolver = false;
		}
		if (overrides->noRecycle)
		{
			def.enableManifoldRecycling = false;
		}
		if (overrides->pointFriction)
		{
			def.enableCentralFriction = false;
		}
		if (overrides->impactPropagation)
		{
			def.enableImpactPropagation = true;
		}
		if (overrides->tasks != NULL)
		{
			def.workerCount = TaskSystem_WorkerCount(overrides->tasks);
			def.enqueueTask = TaskSystem_Enqueue;
			def.finishTask = TaskSystem_Finish;
			def.userTaskContext = overrides->tasks;
		}
		else if (overrides->enqueueTask != NULL)
		{
			def.workerCount = overrides->workerCount;
			def.enqueueTask = overrides->enqueueTask;
			def.finishTask = overrides->finishTask;
			def.userTaskContext = overrides->userTaskContext;
		}
	}
	return def;
}

// Create the body and its shapes. *refusedShape is the index of the first shape the library
// refused, or stays as it was when every shape was created.
static tbBodyId CreateSceneBody(tbWorldId worldId, const SceneBody* body, tbVec2 offset, const char* name,
							   int* refusedShape)
{
	tbBodyDef def = tbDefaultBodyDef();
	def.type = body->type;
	def.position = tbAdd(body->position, offset);
	def.rotation = tbMakeRot(body->angle);
	def.linearVelocity = body->linearVelocity;
	def.angularVelocity = body->angularVelocity;
	def.linearDamping = body->linearDamping;
	def.angularDamping = body->angularDamping;
	def.gravityScale = body->gravityScale;
	def.isBullet = body->bullet;
	def.fixedRotation = body->fixedRotation;
	def.isAwake = body->isAwake;
	def.sleepThreshold = body->sleepThreshold;
	def.name = name[0] != '\0' ? name : NULL;
	tbBodyId bodyId = tbCreateBody(worldId, &def);
	if (TB_IS_NULL(bodyId))
	{
		return bodyId;
	}
	for (int i = 0; i < body->shapeCount; ++i)
	{
		const SceneShape* shape = body->shapes + i;
		tbShapeDef shapeDef = tbDefaultShapeDef();
		shapeDef.density = shape->density;
		shapeDef.material.friction = shape->friction;
		shapeDef.material.restitution = shape->restitution;
		shapeDef.isSensor = shape->isSensor;
		shapeDef.enableHitEvents = shape->enableHitEvents;
		shapeDef.filter.groupIndex = shape->groupIndex;
		shapeDef.filter.categoryBits = shape->categoryBits;
		shapeDef.filter.maskBits = shape->maskBits;
		if (TB_IS_NULL(tbCreateShape(bodyId, &shapeDef, &shape->geometry)) && *refusedShape < 0)
		{
			*refusedShape = i;
		}
	}
	return bodyId;
}

bool Scene_FindRefusedItem(const Scene* scene, char* item, int itemSize)
{
	tbWorldDef def = Scene_MakeWorldDef(scene, NULL);
	tbWorldId worldId = tbCreateWorld(&def);
	bool refused = TB_IS_NULL(worldId);
	snprintf(item, (size_t)itemSize, "scene");
	tbBodyId* bodyIds = calloc((size_t)(scene->bodyCount > 0 ? scene->bodyCount : 1), sizeof(tbBodyId));
	refused = refused || bodyIds == NULL;
	for (int i = 0; i < scene->bodyCount && refused == false; ++i)
	{
		int shapeIndex = -1;
		tbBodyId bodyId = CreateSceneBody(worldId, scene->bodies + i, tbVec2_zero, "", &shapeIndex);
		bodyIds[i] = bodyId;
		refused = TB_IS_NULL(bodyId) || shapeIndex >= 0;
		if (TB_IS_NULL(bodyId))
		{
			snprintf(item, (size_t)itemSize, "bodies[%d]", i);
		}
		else if (shapeIndex >= 0)
		{
			snprintf(item, (size_t)itemSize, "bodies[%d].shapes[%d]", i, shapeIndex);
		}
	}
	for (int i = 0; i < scene->chainCount && refused == false; ++i)
	{
		refused = TB_IS_NULL(CreateSceneChain(worldId, bodyIds, scene->bodyCount, scene->chains + i));
		if (refused)
		{
			snprintf(item, (size_t)itemSize, "chains[%d]", i);
		}
	}
	free(bodyIds);
	if (TB_IS_NON_NULL(worldId))
	{
		tbDestroyWorld(worldId);
	}
	return refused;
}

static tbJointId CreateSceneJoint(tbWorldId worldId, const tbBodyId* bodyIds, int bodyCount, const SceneJoint* joint)
{
	if (joint->bodyA < 0 || joint->bodyA >= bodyCount || joint->bodyB < 0 || joint->bodyB >= bodyCount)
	{
		return TB_NULL_JOINT_ID;
	}
	SceneJoint copy = *joint;
	copy.def.base.bodyIdA = bodyIds[joint->bodyA];
	copy.def.base.bodyIdB = bodyIds[joint->bodyB];
	switch (joint->type)
	{
		case tb_distanceJoint:
			return tbCreateDistanceJoint(worldId, &copy.def.distance);
		case tb_filterJoint:
			return tbCreateFilterJoint(worldId, &copy.def.filter);
		case tb_motorJoint:
			return tbCreateMotorJoint(worldId, &copy.def.motor);
		case tb_moverJoint:
			return tbCreateMoverJoint(worldId, &copy.def.mover);
		case tb_pogoJoint:
			return tbCreatePogoJoint(worldId, &copy.def.pogo);
		case tb_prismaticJoint:
			return tbCreatePrismaticJoint(worldId, &copy.def.prismatic);
		case tb_revoluteJoint:
			return tbCreateRevoluteJoint(worldId, &copy.def.revolute);
		case tb_weldJoint:
			return tbCreateWeldJoint(worldId, &copy.def.weld);
		case tb_wheelJoint:
			return tbCreateWheelJoint(worldId, &copy.def.wheel);
		default:
			return TB_NULL_JOINT_ID;
	}
}

// ---------------------------------------------------------------------------------------------
// Spawned instances

// One ring per spawner, as large as the instances that can live at once.
static bool AllocateSpawned(SceneWorld* world, const Scene* scene)
{
	if (scene->spawnerCount == 0)
	{
		return true;
	}
	world->spawned = calloc((size_t)scene->spawnerCount, sizeof(SpawnedInstances));
	if (world->spawned == NULL)
	{
		return false;
	}
	world->spawnerCount = scene->spawnerCount;
	for (int i = 0; i < scene->spawnerCount; ++i)
	{
		const SceneSpawner* spawner = scene->spawners + i;
		const Scene* parts = scene->templates[spawner->templateIndex].parts;
		SpawnedInstances* ring = world->spawned + i;
		ring->schedule = *spawner;
		ring->capacity = SceneSpawner_Capacity(spawner);
		ring->bodiesPer = parts->bodyCount;
		ring->jointsPer = parts->jointCount;
		size_t bodySlots = (size_t)(ring->capacity * (ring->bodiesPer > 0 ? ring->bodiesPer : 1));
		size_t jointSlots = (size_t)(ring->capacity * (ring->jointsPer > 0 ? ring->jointsPer : 1));
		ring->bodyIds = calloc(bodySlots, sizeof(tbBodyId));
		ring->jointIds = calloc(jointSlots, sizeof(tbJointId));
		if (ring->bodyIds == NULL || ring->jointIds == NULL)
		{
			return false;
		}
	}
	return true;
}

// Joints first, then bodies, as Box2D v3's rain destroys a human.
static void DestroyInstance(SpawnedInstances* ring, int slot)
{
	tbJointId* joints = ring->jointIds + slot * ring->jointsPer;
	for (int i = 0; i < ring->jointsPer; ++i)
	{
		if (tbJoint_IsValid(joints[i]))
		{
			tbDestroyJoint(joints[i]);
		}
	}
	tbBodyId* bodies = ring->bodyIds + slot * ring->bodiesPer;
	for (int i = 0; i < ring->bodiesPer; ++i)
	{
		if (tbBody_IsValid(bodies[i]))
		{
			tbDestroyBody(bodies[i]);
		}
	}
}

// The template's bodies (moved by offset) and joints into the ring's slot. Spawned bodies have
// no name (the library does not copy names) and no drive.
static void BuildInstance(tbWorldId worldId, const Scene* parts, tbVec2 offset, SpawnedInstances* ring, int slot)
{
	tbBodyId* bodies = ring->bodyIds + slot * ring->bodiesPer;
	for (int i = 0; i < ring->bodiesPer; ++i)
	{
		int refusedShape = -1;
		bodies[i] = CreateSceneBody(worldId, parts->bodies + i, offset, "", &refusedShape);
	}
	tbJointId* joints = ring->jointIds + slot * ring->jointsPer;
	for (int i = 0; i < ring->jointsPer; ++i)
	{
		joints[i] = CreateSceneJoint(worldId, bodies, ring->bodiesPer, parts->joints + i);
	}
}

// The spawns of the coming step, spawner by spawner: destroy the instance whose lifetime ends,
// then the oldest when the ring is full (a no-op when it is already gone), then build.
static void RunSpawners(SceneWorld* world, const Scene* scene)
{
	for (int i = 0; i < world->spawnerCount; ++i)
	{
		const SceneSpawner* spawner = scene->spawners + i;
		SpawnedInstances* ring = world->spawned + i;
		int expired = SceneSpawner_ExpiryAt(spawner, world->stepIndex);
		if (expired >= 0 && expired < ring->built && expired >= ring->built - ring->capacity)
		{
			DestroyInstance(ring, expired % ring->capacity);
		}
		int instance = SceneSpawner_InstanceAt(spawner, world->stepIndex);
		if (instance < 0)
		{
			continue;
		}
		int slot = instance % ring->capacity;
		if (instance >= ring->capacity)
		{
			DestroyInstance(ring, slot);
		}
		const Scene* parts = scene->templates[spawner->templateIndex].parts;
		BuildInstance(world->worldId, parts, SceneSpawner_Offset(spawner, instance), ring, slot);
		ring->built = instance + 1;
	}
}

const tbBodyId* SceneWorld_InstanceBodies(const SceneWorld* world, int spawner, int instance)
{
	if (spawner < 0 || spawner >= world->spawnerCount)
	{
		return NULL;
	}
	const SpawnedInstances* ring = world->spawned + spawner;
	if (instance < 0 || instance >= ring->built || instance < ring->built - ring->capacity)
	{
		return NULL;
	}
	const SceneSpawner* schedule = &ring->schedule;
	int builtBefore = schedule->firstStep + instance * schedule->interval;
	if (schedule->lifetime > 0 && builtBefore + schedule->lifetime < world->stepIndex)
	{
		return NULL; // destroyed before step builtBefore + lifetime, which has been taken
	}
	return ring->bodyIds + (instance % ring->capacity) * ring->bodiesPer;
}

int SceneWorld_CollectBodies(const SceneWorld* world, tbBodyId* out, int capacity)
{
	int count = 0;
	for (int i = 0; i < world->bodyCount && count < capacity; ++i)
	{
		out[count++] = world->bodyIds[i];
	}
	for (int s = 0; s < world->spawnerCount; ++s)
	{
		const SpawnedInstances* ring = world->spawned + s;
		for (int i = 0; i < ring->capacity * ring->bodiesPer && count < capacity; ++i)
		{
			if (tbBody_IsValid(ring->bodyIds[i]))
			{
				out[count++] = ring->bodyIds[i];
			}
		}
	}
	return count;
}

int SceneWorld_BodyCapacity(const SceneWorld* world)
{
	int capacity = world->bodyCount;
	for (int s = 0; s < world->spawnerCount; ++s)
	{
		capacity += world->spawned[s].capacity * world->spawned[s].bodiesPer;
	}
	return capacity > 0 ? capacity : 1;
}

SceneWorld Scene_BuildWorldWithDef(const Scene* scene, const tbWorldDef* def)
{
	SceneWorld world;
	memset(&world, 0, sizeof(world));
	world.worldId = tbCreateWorld(def);
	if (TB_IS_NULL(world.worldId))
	{
		return world;
	}
	int count = scene->bodyCount;
	world.bodyIds = calloc((size_t)(count > 0 ? count : 1), sizeof(tbBodyId));
	world.names = calloc((size_t)(count > 0 ? count : 1), sizeof(*world.names));
	world.drivenBodies = calloc((size_t)(count > 0 ? count : 1), sizeof(int));
	if (world.bodyIds == NULL || world.names == NULL || world.drivenBodies == NULL)
	{
		SceneWorld_Destroy(&world);
		return world;
	}
	world.bodyCount = count;
	for (int i = 0; i < count; ++i)
	{
		memcpy(world.names[i], scene->bodies[i].name, SCENE_NAME_SIZE);
		world.names[i][SCENE_NAME_SIZE - 1] = '\0';
		int refusedShape = -1; // scene files are checked when loaded (Scene_FindRefusedItem)
		world.bodyIds[i] =
			CreateSceneBody(world.worldId, scene->bodies + i, tbVec2_zero, world.names[i], &refusedShape);
		if (scene->bodies[i].drive.enabled)
		{
			world.drivenBodies[world.drivenCount++] = i;
		}
	}
	world.jointIds = calloc((size_t)(scene->jointCount > 0 ? scene->jointCount : 1), sizeof(tbJointId));
	if (world.jointIds == NULL)
	{
		SceneWorld_Destroy(&world);
		return world;
	}
	world.jointCount = scene->jointCount;
	for (int i = 0; i < scene->jointCount; ++i)
	{
		world.jointIds[i] = CreateSceneJoint(world.worldId, world.bodyIds, world.bodyCount, scene->joints + i);
	}
	for (int i = 0; i < scene->chainCount; ++i)
	{
		CreateSceneChain(world.worldId, world.bodyIds, world.bodyCount, scene->chains + i);
	}
	if (AllocateSpawned(&world, scene) == false)
	{
		SceneWorld_Destroy(&world);
	}
	return world;
}

SceneWorld Scene_BuildWorld(const Scene* scene, const SceneOverrides* overrides)
{
	tbWorldDef def = Scene_MakeWorldDef(scene, overrides);
	return Scene_BuildWorldWithDef(scene, &def);
}

bool SceneWorld_Step(SceneWorld* world, const Scene* scene, int subSteps)
{
	RunSpawners(world, scene);
	for (int i = 0; i < world->drivenCount; ++i)
	{
		int index = world->drivenBodies[i];
		tbTransform target;
		if (Scene_DriveTarget(scene, index, world->stepIndex, &target))
		{
			tbBody_SetTargetTransform(world->bodyIds[index], target, scene->timeStep, true);
		}
	}
	world->stepIndex += 1;
	return tbWorld_Step(world->worldId, scene->timeStep, subSteps);
}

void SceneWorld_Destroy(SceneWorld* world)
{
	if (TB_IS_NON_NULL(world->worldId))
	{
		tbDestroyWorld(world->worldId);
	}
	free(world->bodyIds);
	free(world->jointIds);
	free(world->names);
	free(world->drivenBodies);
	for (int i = 0; i < world->spawnerCount; ++i)
	{
		free(world->spawned[i].bodyIds);
		free(world->spawned[i].jointIds);
	}
	free(world->spawned);
	memset(world, 0, sizeof(*world));
}

// ---------------------------------------------------------------------------------------------
// Measures

float SceneWorld_KineticEnergy(const SceneWorld* world)
{
	double energy = 0.0;
	tbBodyId* ids = malloc(sizeof(tbBodyId) * (size_t)SceneWorld_BodyCapacity(world));
	int count = ids != NULL ? SceneWorld_CollectBodies(world, ids, SceneWorld_BodyCapacity(world)) : 0;
	for (int i = 0; i < count; ++i)
	{
		tbBodyId id = ids[i];
		if (tbBody_IsValid(id) == false || tbBody_GetType(id) != tb_dynamicBody)
		{
			continue;
		}
		tbVec2 v = tbBody_GetLinearVelocity(id);
		float w = tbBody_GetAngularVelocity(id);
		energy += 0.5 * tbBody_GetMass(id) * tbDot(v, v);
		energy += 0.5 * tbBody_GetRotationalInertia(id) * w * w;
	}
	free(ids);
	return (float)energy;
}

int SceneWorld_AwakeCount(const SceneWorld* world)
{
	int count = 0;
	tbBodyId* ids = malloc(sizeof(tbBodyId) * (size_t)SceneWorld_BodyCapacity(world));
	int bodyCount = ids != NULL ? SceneWorld_CollectBodies(world, ids, SceneWorld_BodyCapacity(world)) : 0;
	for (int i = 0; i < bodyCount; ++i)
	{
		tbBodyId id = ids[i];
		if (tbBody_IsValid(id) && tbBody_GetType(id) != tb_staticBody && tbBody_IsAwake(id))
		{
			count += 1;
		}
	}
	free(ids);
	return count;
}

typedef struct PenetrationQuery
{
	tbShapeId shapeId;
	tbBodyId bodyId;
	tbGeometry geometry;
	tbTransform transform;
	float deepest; ///< most negative separation seen (m)
} PenetrationQuery;

// Bodies joined by a joint that forbids their collision overlap on purpose (a ragdoll's limbs).
static bool JoinedWithoutCollision(tbBodyId a, tbBodyId b)
{
	tbJointId joints[32];
	int count = tbBody_GetJoints(a, joints, 32);
	for (int i = 0; i < count; ++i)
	{
		tbBodyId other = tbJoint_GetBodyA(joints[i]);
		if (other.index1 == a.index1)
		{
			other = tbJoint_GetBodyB(joints[i]);
		}
		if (other.index1 == b.index1 && tbJoint_GetCollideConnected(joints[i]) == false)
		{
			return true;
		}
	}
	return false;
}

// Whether two shapes' filters let them collide, by the library's rule (tbFilter): a shared
// non-zero group decides (negative: never), otherwise each category must be in the other's mask.
bool Scene_FiltersCollide(int groupA, uint64_t categoryA, uint64_t maskA, int groupB, uint64_t categoryB,
						  uint64_t maskB)
{
	if (groupA == groupB && groupA != 0)
	{
		return groupA > 0;
	}
	return (categoryA & maskB) != 0 && (categoryB & maskA) != 0;
}

static bool ShapesCollide(tbShapeId a, tbShapeId b)
{
	tbFilter fa = tbShape_GetFilter(a), fb = tbShape_GetFilter(b);
	return Scene_FiltersCollide(fa.groupIndex, fa.categoryBits, fa.maskBits, fb.groupIndex, fb.categoryBits,
								fb.maskBits);
}

// Collide the query shape with one found shape. Each pair is visited from its lower shape id
// when both are non-static, so no pair is measured twice. Pairs the engine is told not to collide
// (filters, joints without collideConnected) overlap on purpose: a ragdoll's own bones.
static bool PenetrationCallback(tbShapeId shapeId, void* context)
{
	PenetrationQuery* query = context;
	tbBodyId bodyId = tbShape_GetBody(shapeId);
	if (bodyId.index1 == query->bodyId.index1 || tbShape_IsSensor(shapeId) ||
		ShapesCollide(query->shapeId, shapeId) == false || JoinedWithoutCollision(query->bodyId, bodyId))
	{
		return true;
	}
	if (tbBody_GetType(bodyId) != tb_staticBody && shapeId.index1 < query->shapeId.index1)
	{
		return true;
	}
	tbGeometry other = tbShape_GetGeometry(shapeId);
	tbTransform otherTransform = tbBody_GetTransform(bodyId);
	tbManifold manifold;
	if (query->geometry.type <= other.type)
	{
		manifold = tbCollideShapes(&query->geometry, query->transform, &other, otherTransform, tb_narrowPhaseAuto);
	}
	else
	{
		manifold = tbCollideShapes(&other, otherTransform, &query->geometry, query->transform, tb_narrowPhaseAuto);
	}
	for (int i = 0; i < manifold.pointCount; ++i)
	{
		query->deepest = tbMinFloat(query->deepest, manifold.points[i].separation);
	}
	return true;
}

static void MeasureBodyPenetration(tbWorldId worldId, tbBodyId bodyId, PenetrationQuery* query)
{
	tbShapeId shapes[64];
	int count = tbBody_GetShapes(bodyId, shapes, 64);
	query->bodyId = bodyId;
	query->transform = tbBody_GetTransform(bodyId);
	for (int i = 0; i < count; ++i)
	{
		if (tbShape_IsSensor(shapes[i]))
		{
			continue;
		}
		query->shapeId = shapes[i];
		query->geometry = tbShape_GetGeometry(shapes[i]);
		tbWorld_OverlapAABB(worldId, tbPos_zero, tbShape_GetAABB(shapes[i]), tbDefaultQueryFilter(), PenetrationCallback,
							query);
	}
}

float SceneWorld_LargestPenetration(const SceneWorld* world)
{
	PenetrationQuery query;
	memset(&query, 0, sizeof(query));
	query.deepest = 0.0f;
	tbBodyId* ids = malloc(sizeof(tbBodyId) * (size_t)SceneWorld_BodyCapacity(world));
	int count = ids != NULL ? SceneWorld_CollectBodies(world, ids, SceneWorld_BodyCapacity(world)) : 0;
	for (int i = 0; i < count; ++i)
	{
		tbBodyId id = ids[i];
		if (tbBody_IsValid(id) && tbBody_GetType(id) != tb_staticBody)
		{
			MeasureBodyPenetration(world->worldId, id, &query);
		}
	}
	free(ids);
	return -query.deepest;
}

// ---------------------------------------------------------------------------------------------
// Names

typedef struct NamedValue
{
	const char* name;
	int value;
} NamedValue;

static const NamedValue s_broadPhaseNames[] = {
	{"tree", tb_broadPhaseTree}, {"sap", tb_broadPhaseSortAndSweep}, {"brute", tb_broadPhaseBruteForce},
	{"hash", tb_broadPhaseSpatialHash},
	{"auto", tb_broadPhaseAuto}, {NULL, 0}};
static const NamedValue s_narrowPhaseNames[] = {
	{"sat", tb_narrowPhaseSAT}, {"gjk", tb_narrowPhaseGJK}, {"auto", tb_narrowPhaseAuto}, {NULL, 0}};
static const NamedValue s_continuousNames[] = {
	{"off", tb_continuousOff}, {"quadratic", tb_continuousDefault}, {"ca", tb_continuousConservative}, {NULL, 0}};
static const NamedValue s_solverNames[] = {
	{"baumgarte", tb_solverBaumgarte}, {"ngs", tb_solverNGS}, {"soft", tb_solverSoft}, {NULL, 0}};
static const NamedValue s_bodyTypeNames[] = {
	{"static", tb_staticBody}, {"kinematic", tb_kinematicBody}, {"dynamic", tb_dynamicBody}, {NULL, 0}};
static const NamedValue s_jointTypeNames[] = {
	{"distance", tb_distanceJoint}, {"filter", tb_filterJoint}, {"motor", tb_motorJoint}, {"mover", tb_moverJoint},
	{"pogo", tb_pogoJoint},
	{"prismatic", tb_prismaticJoint}, {"revolute", tb_revoluteJoint}, {"weld", tb_weldJoint},
	{"wheel", tb_wheelJoint}, {NULL, 0}};

static const char* NameOf(const NamedValue* table, int value)
{
	for (int i = 0; table[i].name != NULL; ++i)
	{
		if (table[i].value == value)
		{
			return table[i].name;
		}
	}
	return NULL;
}

static bool ValueOf(const NamedValue* table, const char* name, int* value)
{
	for (int i = 0; name != NULL && table[i].name != NULL; ++i)
	{
		if (strcmp(table[i].name, name) == 0)
		{
			*value = table[i].value;
			return true;
		}
	}
	return false;
}

const char* Scene_BroadPhaseName(tbBroadPhaseMethod method)
{
	return NameOf(s_broadPhaseNames, (int)method);
}

const char* Scene_NarrowPhaseName(tbNarrowPhaseMethod method)
{
	return NameOf(s_narrowPhaseNames, (int)method);
}

const char* Scene_ContinuousName(tbContinuousMethod method)
{
	return NameOf(s_continuousNames, (int)method);
}

const char* Scene_SolverName(tbSolverMethod method)
{
	return NameOf(s_solverNames, (int)method);
}

const char* Scene_BodyTypeName(tbBodyType type)
{
	return NameOf(s_bodyTypeNames, (int)type);
}

bool Scene_ParseBroadPhase(const char* text, tbBroadPhaseMethod* method)
{
	int value = 0;
	bool found = ValueOf(s_broadPhaseNames, text, &value);
	*method = found ? (tbBroadPhaseMethod)value : *method;
	return found;
}

bool Scene_ParseNarrowPhase(const char* text, tbNarrowPhaseMethod* method)
{
	int value = 0;
	bool found = ValueOf(s_narrowPhaseNames, text, &value);
	*method = found ? (tbNarrowPhaseMethod)value : *method;
	return found;
}

bool Scene_ParseContinuous(const char* text, tbContinuousMethod* method)
{
	int value = 0;
	bool found = ValueOf(s_continuousNames, text, &value);
	*method = found ? (tbContinuousMethod)value : *method;
	return found;
}

bool Scene_ParseSolver(const char* text, tbSolverMethod* method)
{
	int value = 0;
	bool found = ValueOf(s_solverNames, text, &value);
	*method = found ? (tbSolverMethod)value : *method;
	return found;
}

bool Scene_ParseBodyType(const char* text, tbBodyType* type)
{
	int value = 0;
	bool found = ValueOf(s_bodyTypeNames, text, &value);
	*type = found ? (tbBodyType)value : *type;
	return found;
}

const char* Scene_JointTypeName(tbJointType type)
{
	return NameOf(s_jointTypeNames, (int)type);
}

bool Scene_ParseJointType(const char* text, tbJointType* type)
{
	int value;
	if (ValueOf(s_jointTypeNames, text, &value) == false)
	{
		return false;
	}
	*type = (tbJointType)value;
	return true;
}
