// The WebAssembly module's exports: the C API flattened to numbers, for tumble.js.
//
// A WebAssembly export takes and returns numbers only, so each function here unpacks its numbers
// into the library's structures and calls the library. Handles cross as the library's stored
// forms (tbStoreWorldId: 32 bits; tbStoreBodyId and the other ids: 64 bits, a BigInt in
// JavaScript). Arrays go both ways through one scratch buffer (Web_Scratch): vertices in, query
// results and events out. Debug drawing fills a stream of floats (Web_World_Draw) that JavaScript
// reads in one go after the call, instead of crossing into JavaScript once per primitive.
//
// The scene catalogue (catalogue.c, scene.c) is exported too: Web_LoadScene builds a catalogue
// scene as the `tumble` program does, with the same overrides, so that a scene stepped here gives
// the same state hash as the native program.
#include "catalogue.h"

#include <stdlib.h>
#include <string.h>

#define WEB_EXPORT(name) __attribute__((export_name(#name))) name

/// Scratch buffer shared with JavaScript: 64 KiB, 8-byte aligned so that it can be read as
/// 64-bit ids. Every function that uses it says what it holds on return.
#define WEB_SCRATCH_BYTES 65536
static _Alignas(8) unsigned char s_scratch[WEB_SCRATCH_BYTES];

void* WEB_EXPORT(Web_Scratch)(void);
void* Web_Scratch(void)
{
	return s_scratch;
}

int WEB_EXPORT(Web_ScratchBytes)(void);
int Web_ScratchBytes(void)
{
	return WEB_SCRATCH_BYTES;
}

// The engine's live byte count (every world, body and contact): back to its baseline when every
// world is destroyed.
double WEB_EXPORT(Web_GetByteCount)(void);
double Web_GetByteCount(void)
{
	return (double)tbGetByteCount();
}

// ---------------------------------------------------------------------------------------------
// World

/// Methods are given as the enums' values, −1 for the library's default.
uint32_t WEB_EXPORT(Web_CreateWorld)(float gravityX, float gravityY, int enableSleep, int broadPhase, int narrowPhase,
									 int continuous, int solver);
uint32_t Web_CreateWorld(float gravityX, float gravityY, int enableSleep, int broadPhase, int narrowPhase,
						 int continuous, int solver)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = (tbVec2){gravityX, gravityY};
	def.enableSleep = enableSleep != 0;
	def.broadPhase = broadPhase >= 0 ? (tbBroadPhaseMethod)broadPhase : def.broadPhase;
	def.narrowPhase = narrowPhase >= 0 ? (tbNarrowPhaseMethod)narrowPhase : def.narrowPhase;
	def.continuous = continuous >= 0 ? (tbContinuousMethod)continuous : def.continuous;
	def.solver = solver >= 0 ? (tbSolverMethod)solver : def.solver;
	return tbStoreWorldId(tbCreateWorld(&def));
}

void WEB_EXPORT(Web_DestroyWorld)(uint32_t world);
void Web_DestroyWorld(uint32_t world)
{
	tbDestroyWorld(tbLoadWorldId(world));
}

int WEB_EXPORT(Web_World_IsValid)(uint32_t world);
int Web_World_IsValid(uint32_t world)
{
	return tbWorld_IsValid(tbLoadWorldId(world));
}

int WEB_EXPORT(Web_World_Step)(uint32_t world, float timeStep, int subSteps);
int Web_World_Step(uint32_t world, float timeStep, int subSteps)
{
	return tbWorld_Step(tbLoadWorldId(world), timeStep, subSteps);
}

uint64_t WEB_EXPORT(Web_World_GetStateHash)(uint32_t world);
uint64_t Web_World_GetStateHash(uint32_t world)
{
	return tbWorld_GetStateHash(tbLoadWorldId(world));
}

/// The last step's time in milliseconds (tbProfile::step).
float WEB_EXPORT(Web_World_GetStepTime)(uint32_t world);
float Web_World_GetStepTime(uint32_t world)
{
	return tbWorld_GetProfile(tbLoadWorldId(world)).step;
}

/// Scratch on return: int32 bodyCount, shapeCount, contactCount, touchingCount, jointCount.
void WEB_EXPORT(Web_World_GetCounters)(uint32_t world);
void Web_World_GetCounters(uint32_t world)
{
	tbCounters c = tbWorld_GetCounters(tbLoadWorldId(world));
	int32_t values[5] = {c.bodyCount, c.shapeCount, c.contactCount, c.touchingCount, c.jointCount};
	memcpy(s_scratch, values, sizeof(values));
}

// ---------------------------------------------------------------------------------------------
// Bodies

uint64_t WEB_EXPORT(Web_CreateBody)(uint32_t world, int type, float x, float y, float angle, float vx, float vy,
									float angularVelocity, float linearDamping, float angularDamping, float gravityScale,
									int isBullet, int fixedRotation);
uint64_t Web_CreateBody(uint32_t world, int type, float x, float y, float angle, float vx, float vy,
						float angularVelocity, float linearDamping, float angularDamping, float gravityScale,
						int isBullet, int fixedRotation)
{
	tbBodyDef def = tbDefaultBodyDef();
	def.type = (tbBodyType)type;
	def.position = (tbPos){x, y};
	def.rotation = tbMakeRot(angle);
	def.linearVelocity = (tbVec2){vx, vy};
	def.angularVelocity = angularVelocity;
	def.linearDamping = linearDamping;
	def.angularDamping = angularDamping;
	def.gravityScale = gravityScale;
	def.isBullet = isBullet != 0;
	def.fixedRotation = fixedRotation != 0;
	return tbStoreBodyId(tbCreateBody(tbLoadWorldId(world), &def));
}

void WEB_EXPORT(Web_DestroyBody)(uint64_t body);
void Web_DestroyBody(uint64_t body)
{
	tbDestroyBody(tbLoadBodyId(body));
}

int WEB_EXPORT(Web_Body_IsValid)(uint64_t body);
int Web_Body_IsValid(uint64_t body)
{
	return tbBody_IsValid(tbLoadBodyId(body));
}

int WEB_EXPORT(Web_Body_GetType)(uint64_t body);
int Web_Body_GetType(uint64_t body)
{
	return (int)tbBody_GetType(tbLoadBodyId(body));
}

/// Scratch on return: float x, y, angle, vx, vy, angularVelocity, mass, centreX, centreY,
/// rotational inertia (about the centre of mass).
void WEB_EXPORT(Web_Body_GetState)(uint64_t body);
void Web_Body_GetState(uint64_t body)
{
	tbBodyId id = tbLoadBodyId(body);
	tbPos p = tbBody_GetPosition(id);
	tbVec2 v = tbBody_GetLinearVelocity(id);
	tbPos c = tbBody_GetWorldCenter(id);
	float values[10] = {p.x, p.y, tbBody_GetAngle(id), v.x, v.y, tbBody_GetAngularVelocity(id),
						tbBody_GetMass(id), c.x, c.y, tbBody_GetRotationalInertia(id)};
	memcpy(s_scratch, values, sizeof(values));
}

int WEB_EXPORT(Web_Body_SetTransform)(uint64_t body, float x, float y, float angle);
int Web_Body_SetTransform(uint64_t body, float x, float y, float angle)
{
	return tbBody_SetTransform(tbLoadBodyId(body), (tbPos){x, y}, tbMakeRot(angle));
}

int WEB_EXPORT(Web_Body_SetVelocity)(uint64_t body, float vx, float vy, float angularVelocity);
int Web_Body_SetVelocity(uint64_t body, float vx, float vy, float angularVelocity)
{
	tbBodyId id = tbLoadBodyId(body);
	return tbBody_SetLinearVelocity(id, (tbVec2){vx, vy}) && tbBody_SetAngularVelocity(id, angularVelocity);
}

int WEB_EXPORT(Web_Body_ApplyLinearImpulse)(uint64_t body, float ix, float iy, float x, float y, int wake);
int Web_Body_ApplyLinearImpulse(uint64_t body, float ix, float iy, float x, float y, int wake)
{
	return tbBody_ApplyLinearImpulse(tbLoadBodyId(body), (tbVec2){ix, iy}, (tbPos){x, y}, wake != 0);
}

int WEB_EXPORT(Web_Body_ApplyForceToCenter)(uint64_t body, float fx, float fy, int wake);
int Web_Body_ApplyForceToCenter(uint64_t body, float fx, float fy, int wake)
{
	return tbBody_ApplyForceToCenter(tbLoadBodyId(body), (tbVec2){fx, fy}, wake != 0);
}

void WEB_EXPORT(Web_Body_SetAwake)(uint64_t body, int awake);
void Web_Body_SetAwake(uint64_t body, int awake)
{
	tbBody_SetAwake(tbLoadBodyId(body), awake != 0);
}

// ---------------------------------------------------------------------------------------------
// Shapes: one function per geometry, the material in the same order in each.

static tbShapeDef MakeShapeDef(float density, float friction, float restitution, int flags)
{
	tbShapeDef def = tbDefaultShapeDef();
	def.density = density;
	def.material.friction = friction;
	def.material.restitution = restitution;
	def.isSensor = (flags & 1) != 0;
	def.enableContactEvents = (flags & 2) != 0;
	def.enableHitEvents = (flags & 4) != 0;
	def.enableSensorEvents = (flags & 8) != 0;
	return def;
}

/// flags: 1 sensor, 2 contact events, 4 hit events, 8 sensor events.
uint64_t WEB_EXPORT(Web_CreateCircleShape)(uint64_t body, float cx, float cy, float radius, float density,
										   float friction, float restitution, int flags);
uint64_t Web_CreateCircleShape(uint64_t body, float cx, float cy, float radius, float density, float friction,
							   float restitution, int flags)
{
	tbShapeDef def = MakeShapeDef(density, friction, restitution, flags);
	tbCircle circle = {{cx, cy}, radius};
	return tbStoreShapeId(tbCreateCircleShape(tbLoadBodyId(body), &def, &circle));
}

uint64_t WEB_EXPORT(Web_CreateCapsuleShape)(uint64_t body, float x1, float y1, float x2, float y2, float radius,
											float density, float friction, float restitution, int flags);
uint64_t Web_CreateCapsuleShape(uint64_t body, float x1, float y1, float x2, float y2, float radius, float density,
								float friction, float restitution, int flags)
{
	tbShapeDef def = MakeShapeDef(density, friction, restitution, flags);
	tbCapsule capsule = {{x1, y1}, {x2, y2}, radius};
	return tbStoreShapeId(tbCreateCapsuleShape(tbLoadBodyId(body), &def, &capsule));
}

uint64_t WEB_EXPORT(Web_CreateSegmentShape)(uint64_t body, float x1, float y1, float x2, float y2, float density,
											float friction, float restitution, int flags);
uint64_t Web_CreateSegmentShape(uint64_t body, float x1, float y1, float x2, float y2, float density, float friction,
								float restitution, int flags)
{
	tbShapeDef def = MakeShapeDef(density, friction, restitution, flags);
	tbSegment segment = {{x1, y1}, {x2, y2}};
	return tbStoreShapeId(tbCreateSegmentShape(tbLoadBodyId(body), &def, &segment));
}

uint64_t WEB_EXPORT(Web_CreateBoxShape)(uint64_t body, float halfWidth, float halfHeight, float cx, float cy,
										float angle, float density, float friction, float restitution, int flags);
uint64_t Web_CreateBoxShape(uint64_t body, float halfWidth, float halfHeight, float cx, float cy, float angle,
							float density, float friction, float restitution, int flags)
{
	tbShapeDef def = MakeShapeDef(density, friction, restitution, flags);
	tbPolygon box = tbMakeOffsetBox(halfWidth, halfHeight, (tbVec2){cx, cy}, tbMakeRot(angle));
	return tbStoreShapeId(tbCreatePolygonShape(tbLoadBodyId(body), &def, &box));
}

/// The convex hull of `count` points (float x, y pairs in the scratch buffer) rounded by radius;
/// a null id when the points have no hull (tbComputeHull: 3 to TB_MAX_POLYGON_VERTICES points, not
/// all on a line).
uint64_t WEB_EXPORT(Web_CreatePolygonShape)(uint64_t body, int count, float radius, float density, float friction,
											float restitution, int flags);
uint64_t Web_CreatePolygonShape(uint64_t body, int count, float radius, float density, float friction,
								float restitution, int flags)
{
	tbVec2 points[TB_MAX_POLYGON_VERTICES];
	if (count < 3 || count > TB_MAX_POLYGON_VERTICES)
	{
		return tbStoreShapeId(tb_nullShapeId);
	}
	memcpy(points, s_scratch, sizeof(tbVec2) * (size_t)count);
	tbHull hull = tbComputeHull(points, count);
	if (hull.count == 0)
	{
		return tbStoreShapeId(tb_nullShapeId);
	}
	tbShapeDef def = MakeShapeDef(density, friction, restitution, flags);
	tbPolygon polygon = tbMakePolygon(&hull, radius);
	return tbStoreShapeId(tbCreatePolygonShape(tbLoadBodyId(body), &def, &polygon));
}

void WEB_EXPORT(Web_DestroyShape)(uint64_t shape);
void Web_DestroyShape(uint64_t shape)
{
	tbDestroyShape(tbLoadShapeId(shape), true);
}

uint64_t WEB_EXPORT(Web_Shape_GetBody)(uint64_t shape);
uint64_t Web_Shape_GetBody(uint64_t shape)
{
	return tbStoreBodyId(tbShape_GetBody(tbLoadShapeId(shape)));
}

// ---------------------------------------------------------------------------------------------
// Joints: both frames' origins at one world point (anchorX, anchorY), as Box2D v3's samples place
// them, unless the kind says otherwise.

static tbJointDef MakeJointBase(uint64_t bodyA, uint64_t bodyB, tbPos anchorA, tbPos anchorB, int collideConnected)
{
	tbJointDef base = tbDefaultDistanceJointDef().base;
	base.bodyIdA = tbLoadBodyId(bodyA);
	base.bodyIdB = tbLoadBodyId(bodyB);
	base.localFrameA.p = tbBody_GetLocalPoint(base.bodyIdA, anchorA);
	base.localFrameB.p = tbBody_GetLocalPoint(base.bodyIdB, anchorB);
	base.collideConnected = collideConnected != 0;
	return base;
}

/// A distance joint between a world point on each body; its length is their distance now.
uint64_t WEB_EXPORT(Web_CreateDistanceJoint)(uint32_t world, uint64_t bodyA, uint64_t bodyB, float ax, float ay,
											 float bx, float by, int enableSpring, float hertz, float dampingRatio,
											 int collideConnected);
uint64_t Web_CreateDistanceJoint(uint32_t world, uint64_t bodyA, uint64_t bodyB, float ax, float ay, float bx, float by,
								 int enableSpring, float hertz, float dampingRatio, int collideConnected)
{
	tbDistanceJointDef def = tbDefaultDistanceJointDef();
	def.base = MakeJointBase(bodyA, bodyB, (tbPos){ax, ay}, (tbPos){bx, by}, collideConnected);
	def.length = tbLength(tbSub((tbVec2){bx, by}, (tbVec2){ax, ay}));
	def.enableSpring = enableSpring != 0;
	def.hertz = hertz;
	def.dampingRatio = dampingRatio;
	return tbStoreJointId(tbCreateDistanceJoint(tbLoadWorldId(world), &def));
}

uint64_t WEB_EXPORT(Web_CreateRevoluteJoint)(uint32_t world, uint64_t bodyA, uint64_t bodyB, float x, float y,
											 int enableLimit, float lowerAngle, float upperAngle, int enableMotor,
											 float motorSpeed, float maxMotorTorque, int collideConnected);
uint64_t Web_CreateRevoluteJoint(uint32_t world, uint64_t bodyA, uint64_t bodyB, float x, float y, int enableLimit,
								 float lowerAngle, float upperAngle, int enableMotor, float motorSpeed, float maxMotorTorque,
								 int collideConnected)
{
	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	def.base = MakeJointBase(bodyA, bodyB, (tbPos){x, y}, (tbPos){x, y}, collideConnected);
	def.enableLimit = enableLimit != 0;
	def.lowerAngle = lowerAngle;
	def.upperAngle = upperAngle;
	def.enableMotor = enableMotor != 0;
	def.motorSpeed = motorSpeed;
	def.maxMotorTorque = maxMotorTorque;
	return tbStoreJointId(tbCreateRevoluteJoint(tbLoadWorldId(world), &def));
}

/// Weld: rigid with both hertz 0, else through linear and angular springs.
uint64_t WEB_EXPORT(Web_CreateWeldJoint)(uint32_t world, uint64_t bodyA, uint64_t bodyB, float x, float y,
										 float linearHertz, float angularHertz, float dampingRatio, int collideConnected);
uint64_t Web_CreateWeldJoint(uint32_t world, uint64_t bodyA, uint64_t bodyB, float x, float y, float linearHertz,
							 float angularHertz, float dampingRatio, int collideConnected)
{
	tbWeldJointDef def = tbDefaultWeldJointDef();
	def.base = MakeJointBase(bodyA, bodyB, (tbPos){x, y}, (tbPos){x, y}, collideConnected);
	tbBodyId idA = def.base.bodyIdA, idB = def.base.bodyIdB;
	def.base.localFrameA.q = tbInvMulRot(tbBody_GetRotation(idA), tbBody_GetRotation(idB)); // held as it is now
	def.linearHertz = linearHertz;
	def.angularHertz = angularHertz;
	def.linearDampingRatio = dampingRatio;
	def.angularDampingRatio = dampingRatio;
	return tbStoreJointId(tbCreateWeldJoint(tbLoadWorldId(world), &def));
}

/// Prismatic: body B slides along the world axis (axisX, axisY) through the anchor.
uint64_t WEB_EXPORT(Web_CreatePrismaticJoint)(uint32_t world, uint64_t bodyA, uint64_t bodyB, float x, float y,
											  float axisX, float axisY, int enableLimit, float lower, float upper,
											  int enableMotor, float motorSpeed, float maxMotorForce,
											  int collideConnected);
uint64_t Web_CreatePrismaticJoint(uint32_t world, uint64_t bodyA, uint64_t bodyB, float x, float y, float axisX,
								  float axisY, int enableLimit, float lower, float upper, int enableMotor, float motorSpeed,
								  float maxMotorForce, int collideConnected)
{
	tbPrismaticJointDef def = tbDefaultPrismaticJointDef();
	def.base = MakeJointBase(bodyA, bodyB, (tbPos){x, y}, (tbPos){x, y}, collideConnected);
	tbRot axis = tbMakeRotFromUnitVector(tbNormalize((tbVec2){axisX, axisY}));
	def.base.localFrameA.q = tbInvMulRot(tbBody_GetRotation(def.base.bodyIdA), axis);
	def.base.localFrameB.q = tbInvMulRot(tbBody_GetRotation(def.base.bodyIdB), axis);
	def.enableLimit = enableLimit != 0;
	def.lowerTranslation = lower;
	def.upperTranslation = upper;
	def.enableMotor = enableMotor != 0;
	def.motorSpeed = motorSpeed;
	def.maxMotorForce = maxMotorForce;
	return tbStoreJointId(tbCreatePrismaticJoint(tbLoadWorldId(world), &def));
}

/// Motor joint whose linear spring pulls a world point of body B (x, y) onto frame A's origin,
/// also at (x, y) to start with: move frame A (Web_Joint_SetTargetA) and body B follows. The
/// mouse drag of Box2D v3.2's samples, with body A a static body.
uint64_t WEB_EXPORT(Web_CreateMotorJoint)(uint32_t world, uint64_t bodyA, uint64_t bodyB, float x, float y,
										  float linearHertz, float linearDampingRatio, float maxSpringForce,
										  float maxVelocityTorque);
uint64_t Web_CreateMotorJoint(uint32_t world, uint64_t bodyA, uint64_t bodyB, float x, float y, float linearHertz,
							  float linearDampingRatio, float maxSpringForce, float maxVelocityTorque)
{
	tbMotorJointDef def = tbDefaultMotorJointDef();
	def.base = MakeJointBase(bodyA, bodyB, (tbPos){x, y}, (tbPos){x, y}, 0);
	def.linearHertz = linearHertz;
	def.linearDampingRatio = linearDampingRatio;
	def.maxSpringForce = maxSpringForce;
	def.maxVelocityTorque = maxVelocityTorque; // with angular velocity 0: resists spinning
	return tbStoreJointId(tbCreateMotorJoint(tbLoadWorldId(world), &def));
}

/// Moves frame A's origin to a world point and wakes body B.
int WEB_EXPORT(Web_Joint_SetTargetA)(uint64_t joint, float x, float y);
int Web_Joint_SetTargetA(uint64_t joint, float x, float y)
{
	tbJointId id = tbLoadJointId(joint);
	tbBodyId bodyA = tbJoint_GetBodyA(id);
	tbTransform frame = {tbBody_GetLocalPoint(bodyA, (tbPos){x, y}), tbRot_identity};
	bool done = tbJoint_SetLocalFrameA(id, frame);
	tbBody_SetAwake(tbJoint_GetBodyB(id), true);
	return done;
}

void WEB_EXPORT(Web_DestroyJoint)(uint64_t joint);
void Web_DestroyJoint(uint64_t joint)
{
	tbDestroyJoint(tbLoadJointId(joint));
}

int WEB_EXPORT(Web_Joint_IsValid)(uint64_t joint);
int Web_Joint_IsValid(uint64_t joint)
{
	return tbJoint_IsValid(tbLoadJointId(joint));
}

// ---------------------------------------------------------------------------------------------
// Queries

typedef struct PointQuery
{
	tbPos point;
	tbBodyId body;
	bool dynamicOnly;
} PointQuery;

static bool TakeBodyAtPoint(tbShapeId shapeId, void* context)
{
	PointQuery* query = context;
	tbBodyId body = tbShape_GetBody(shapeId);
	bool wrongType = query->dynamicOnly && tbBody_GetType(body) != tb_dynamicBody;
	if (wrongType || tbShape_TestPoint(shapeId, query->point) == false)
	{
		return true; // go on
	}
	query->body = body;
	return false;
}

/// The first body (a dynamic one when dynamicOnly) with a shape holding the point; null if none.
uint64_t WEB_EXPORT(Web_World_BodyAtPoint)(uint32_t world, float x, float y, int dynamicOnly);
uint64_t Web_World_BodyAtPoint(uint32_t world, float x, float y, int dynamicOnly)
{
	PointQuery query = {{x, y}, tb_nullBodyId, dynamicOnly != 0};
	tbAABB box = {{x - 0.001f, y - 0.001f}, {x + 0.001f, y + 0.001f}};
	tbWorld_OverlapAABB(tbLoadWorldId(world), tbPos_zero, box, tbDefaultQueryFilter(), TakeBodyAtPoint, &query);
	return tbStoreBodyId(query.body);
}

typedef struct ShapeList
{
	uint64_t* ids;
	int count;
	int capacity;
} ShapeList;

static bool CollectShape(tbShapeId shapeId, void* context)
{
	ShapeList* list = context;
	if (list->count == list->capacity)
	{
		return false;
	}
	list->ids[list->count++] = tbStoreShapeId(shapeId);
	return true;
}

/// Shapes whose fat boxes overlap the box: their ids (uint64) in the scratch buffer, the count
/// returned (at most what the buffer holds).
int WEB_EXPORT(Web_World_OverlapAABB)(uint32_t world, float lowerX, float lowerY, float upperX, float upperY);
int Web_World_OverlapAABB(uint32_t world, float lowerX, float lowerY, float upperX, float upperY)
{
	ShapeList list = {(uint64_t*)(void*)s_scratch, 0, WEB_SCRATCH_BYTES / (int)sizeof(uint64_t)};
	tbAABB box = {{lowerX, lowerY}, {upperX, upperY}};
	tbWorld_OverlapAABB(tbLoadWorldId(world), tbPos_zero, box, tbDefaultQueryFilter(), CollectShape, &list);
	return list.count;
}

/// The closest shape along the ray: true on a hit, with the scratch buffer holding uint64 shape
/// id, then float point x, y, normal x, y, fraction.
int WEB_EXPORT(Web_World_CastRayClosest)(uint32_t world, float x, float y, float dx, float dy);
int Web_World_CastRayClosest(uint32_t world, float x, float y, float dx, float dy)
{
	tbRayResult r = tbWorld_CastRayClosest(tbLoadWorldId(world), (tbPos){x, y}, (tbVec2){dx, dy}, tbDefaultQueryFilter());
	if (r.hit == false)
	{
		return 0;
	}
	uint64_t shape = tbStoreShapeId(r.shapeId);
	float values[5] = {r.point.x, r.point.y, r.normal.x, r.normal.y, r.fraction};
	memcpy(s_scratch, &shape, sizeof(shape));
	memcpy(s_scratch + sizeof(shape), values, sizeof(values));
	return 1;
}

// ---------------------------------------------------------------------------------------------
// Events of the last step

/// Contact begin-touch events (kind 0), end-touch events (1) or hit events (2): per event the
/// uint64 ids of shape A and shape B, then for hits float point x, y, normal x, y, approach
/// speed (24 bytes more). Returns the count that fits in the scratch buffer.
int WEB_EXPORT(Web_World_GetContactEvents)(uint32_t world, int kind);
int Web_World_GetContactEvents(uint32_t world, int kind)
{
	tbContactEvents events = tbWorld_GetContactEvents(tbLoadWorldId(world));
	int stride = kind == 2 ? 40 : 16;
	int count = kind == 0 ? events.beginCount : kind == 1 ? events.endCount : events.hitCount;
	count = count < WEB_SCRATCH_BYTES / stride ? count : WEB_SCRATCH_BYTES / stride;
	for (int i = 0; i < count; ++i)
	{
		unsigned char* out = s_scratch + i * stride;
		tbShapeId a = kind == 0 ? events.beginEvents[i].shapeIdA
					  : kind == 1 ? events.endEvents[i].shapeIdA
								  : events.hitEvents[i].shapeIdA;
		tbShapeId b = kind == 0 ? events.beginEvents[i].shapeIdB
					  : kind == 1 ? events.endEvents[i].shapeIdB
								  : events.hitEvents[i].shapeIdB;
		uint64_t ids[2] = {tbStoreShapeId(a), tbStoreShapeId(b)};
		memcpy(out, ids, sizeof(ids));
		if (kind == 2)
		{
			const tbContactHitEvent* hit = events.hitEvents + i;
			float values[5] = {hit->point.x, hit->point.y, hit->normal.x, hit->normal.y, hit->approachSpeed};
			memcpy(out + sizeof(ids), values, sizeof(values));
		}
	}
	return count;
}

// ---------------------------------------------------------------------------------------------
// Debug draw stream
//
// Each primitive is an opcode, then its colour (0xRRGGBB, exact in a float), then its numbers, in
// world coordinates (polygons already transformed):
//   1 polygon        color n x0 y0 … x(n−1) y(n−1)
//   2 solid polygon  color n radius x0 y0 …
//   3 circle         color x y radius
//   4 solid circle   color x y radius axisX axisY   (axis: the body's turn)
//   5 solid capsule  color x1 y1 x2 y2 radius
//   6 line           color x1 y1 x2 y2
//   7 transform      x y cos sin                    (no colour)
//   8 point          color x y size                 (size in pixels)
//   9 string         color x y length characters…   (one byte a float)
//  10 bounds         color lowerX lowerY upperX upperY

typedef struct DrawStream
{
	float* data;
	int count;
	int capacity;
	bool failed; ///< out of memory: the frame is cut short
} DrawStream;

static DrawStream s_stream;

static float* Reserve(int count)
{
	if (s_stream.count + count > s_stream.capacity)
	{
		int capacity = s_stream.capacity > 0 ? s_stream.capacity : 4096;
		while (capacity < s_stream.count + count)
		{
			capacity *= 2;
		}
		float* data = realloc(s_stream.data, sizeof(float) * (size_t)capacity);
		if (data == NULL)
		{
			s_stream.failed = true;
			return NULL;
		}
		s_stream.data = data;
		s_stream.capacity = capacity;
	}
	float* out = s_stream.data + s_stream.count;
	s_stream.count += count;
	return out;
}

static void PushPolygon(float op, tbWorldTransform xf, const tbVec2* vertices, int count, float radius,
						tbHexColor color)
{
	int extra = op == 2.0f ? 1 : 0;
	float* out = Reserve(3 + extra + 2 * count);
	if (out == NULL)
	{
		return;
	}
	out[0] = op;
	out[1] = (float)color;
	out[2] = (float)count;
	out[3] = radius; // overwritten by the first vertex for an outline
	float* v = out + 3 + extra;
	for (int i = 0; i < count; ++i)
	{
		tbPos p = tbTransformWorldPoint(xf, vertices[i]);
		v[2 * i] = (float)p.x;
		v[2 * i + 1] = (float)p.y;
	}
}

static void DrawPolygon(tbWorldTransform xf, const tbVec2* vertices, int count, tbHexColor color, void* context)
{
	(void)context;
	PushPolygon(1.0f, xf, vertices, count, 0.0f, color);
}

static void DrawSolidPolygon(tbWorldTransform xf, const tbVec2* vertices, int count, float radius, tbHexColor color,
							 void* context)
{
	(void)context;
	PushPolygon(2.0f, xf, vertices, count, radius, color);
}

static void Push(const float* values, int count)
{
	float* out = Reserve(count);
	if (out != NULL)
	{
		memcpy(out, values, sizeof(float) * (size_t)count);
	}
}

static void DrawCircle(tbPos center, float radius, tbHexColor color, void* context)
{
	(void)context;
	Push((float[]){3.0f, (float)color, (float)center.x, (float)center.y, radius}, 5);
}

static void DrawSolidCircle(tbWorldTransform xf, tbVec2 center, float radius, tbHexColor color, void* context)
{
	(void)context;
	tbPos c = tbTransformWorldPoint(xf, center);
	Push((float[]){4.0f, (float)color, (float)c.x, (float)c.y, radius, xf.q.c, xf.q.s}, 7);
}

static void DrawSolidCapsule(tbPos p1, tbPos p2, float radius, tbHexColor color, void* context)
{
	(void)context;
	Push((float[]){5.0f, (float)color, (float)p1.x, (float)p1.y, (float)p2.x, (float)p2.y, radius}, 7);
}

static void DrawLine(tbPos p1, tbPos p2, tbHexColor color, void* context)
{
	(void)context;
	Push((float[]){6.0f, (float)color, (float)p1.x, (float)p1.y, (float)p2.x, (float)p2.y}, 6);
}

static void DrawTransform(tbWorldTransform xf, void* context)
{
	(void)context;
	Push((float[]){7.0f, (float)xf.p.x, (float)xf.p.y, xf.q.c, xf.q.s}, 5);
}

static void DrawPoint(tbPos p, float size, tbHexColor color, void* context)
{
	(void)context;
	Push((float[]){8.0f, (float)color, (float)p.x, (float)p.y, size}, 5);
}

static void DrawString(tbPos p, const char* text, tbHexColor color, void* context)
{
	(void)context;
	int length = (int)strlen(text);
	float* out = Reserve(5 + length);
	if (out == NULL)
	{
		return;
	}
	out[0] = 9.0f;
	out[1] = (float)color;
	out[2] = (float)p.x;
	out[3] = (float)p.y;
	out[4] = (float)length;
	for (int i = 0; i < length; ++i)
	{
		out[5 + i] = (float)(unsigned char)text[i];
	}
}

static void DrawBounds(tbAABB box, tbHexColor color, void* context)
{
	(void)context;
	Push((float[]){10.0f, (float)color, box.lowerBound.x, box.lowerBound.y, box.upperBound.x, box.upperBound.y}, 6);
}

/// Flags of Web_World_Draw: which parts of tbDebugDraw to turn on.
enum
{
	web_drawShapes = 1,
	web_drawJoints = 2,
	web_drawContacts = 4,
	web_drawContactNormals = 8,
	web_drawBounds = 16,
	web_drawMass = 32,
	web_drawJointExtras = 64,
	web_drawContactForces = 128,
	web_drawFrictionForces = 256,
	web_drawIslands = 512,
	web_drawGraphColors = 1024,
};

/// Draws the world into the stream (only what overlaps the view box); returns the count of floats,
/// read at Web_DrawStream. −1 when memory ran out (the stream holds the part drawn before).
int WEB_EXPORT(Web_World_Draw)(uint32_t world, int flags, float lowerX, float lowerY, float upperX, float upperY);
int Web_World_Draw(uint32_t world, int flags, float lowerX, float lowerY, float upperX, float upperY)
{
	s_stream.count = 0;
	s_stream.failed = false;
	tbDebugDraw draw = tbDefaultDebugDraw();
	draw.DrawPolygonFcn = DrawPolygon;
	draw.DrawSolidPolygonFcn = DrawSolidPolygon;
	draw.DrawCircleFcn = DrawCircle;
	draw.DrawSolidCircleFcn = DrawSolidCircle;
	draw.DrawSolidCapsuleFcn = DrawSolidCapsule;
	draw.DrawLineFcn = DrawLine;
	draw.DrawTransformFcn = DrawTransform;
	draw.DrawPointFcn = DrawPoint;
	draw.DrawStringFcn = DrawString;
	draw.DrawBoundsFcn = DrawBounds;
	draw.drawingBounds = (tbAABB){{lowerX, lowerY}, {upperX, upperY}};
	draw.drawShapes = (flags & web_drawShapes) != 0;
	draw.drawJoints = (flags & web_drawJoints) != 0;
	draw.drawJointExtras = (flags & web_drawJointExtras) != 0;
	draw.drawContacts = (flags & web_drawContacts) != 0;
	draw.drawContactNormals = (flags & web_drawContactNormals) != 0;
	draw.drawContactForces = (flags & web_drawContactForces) != 0;
	draw.drawFrictionForces = (flags & web_drawFrictionForces) != 0;
	draw.drawBounds = (flags & web_drawBounds) != 0;
	draw.drawMass = (flags & web_drawMass) != 0;
	draw.drawIslands = (flags & web_drawIslands) != 0;
	draw.drawGraphColors = (flags & web_drawGraphColors) != 0;
	tbWorld_Draw(tbLoadWorldId(world), &draw);
	return s_stream.failed ? -1 : s_stream.count;
}

const float* WEB_EXPORT(Web_DrawStream)(void);
const float* Web_DrawStream(void)
{
	return s_stream.data;
}

// ---------------------------------------------------------------------------------------------
// The scene catalogue

int WEB_EXPORT(Web_SceneCount)(void);
int Web_SceneCount(void)
{
	return Catalogue_Count();
}

const char* WEB_EXPORT(Web_SceneName)(int index);
const char* Web_SceneName(int index)
{
	return Catalogue_Name(index);
}

const char* WEB_EXPORT(Web_SceneDescription)(int index);
const char* Web_SceneDescription(int index)
{
	return Catalogue_Description(index);
}

/// A catalogue scene and the world built from it.
typedef struct WebScene
{
	Scene* scene;
	SceneWorld world;
	int subSteps;
} WebScene;

/// Builds catalogue scene `index` with the method overrides (enum values, −1: the scene's own) and
/// sub-steps (≤ 0: the scene's own), as `tumble run` does with the same options. NULL on failure.
WebScene* WEB_EXPORT(Web_LoadScene)(int index, int broadPhase, int narrowPhase, int continuous, int solver,
									int subSteps);
WebScene* Web_LoadScene(int index, int broadPhase, int narrowPhase, int continuous, int solver, int subSteps)
{
	const char* name = Catalogue_Name(index);
	Scene* scene = name != NULL ? Catalogue_Build(name) : NULL;
	WebScene* web = scene != NULL ? calloc(1, sizeof(WebScene)) : NULL;
	if (web == NULL)
	{
		Scene_Destroy(scene);
		return NULL;
	}
	SceneOverrides overrides;
	memset(&overrides, 0, sizeof(overrides));
	SceneMethods* m = &overrides.methods;
	m->hasBroadPhase = broadPhase >= 0, m->broadPhase = (tbBroadPhaseMethod)broadPhase;
	m->hasNarrowPhase = narrowPhase >= 0, m->narrowPhase = (tbNarrowPhaseMethod)narrowPhase;
	m->hasContinuous = continuous >= 0, m->continuous = (tbContinuousMethod)continuous;
	m->hasSolver = solver >= 0, m->solver = (tbSolverMethod)solver;
	overrides.subSteps = subSteps > 0 ? subSteps : 0;
	web->scene = scene;
	web->subSteps = subSteps > 0 ? subSteps : scene->subSteps;
	web->world = Scene_BuildWorld(scene, &overrides);
	if (TB_IS_NULL(web->world.worldId))
	{
		Scene_Destroy(scene);
		free(web);
		return NULL;
	}
	return web;
}

void WEB_EXPORT(Web_Scene_Destroy)(WebScene* web);
void Web_Scene_Destroy(WebScene* web)
{
	if (web != NULL)
	{
		SceneWorld_Destroy(&web->world);
		Scene_Destroy(web->scene);
		free(web);
	}
}

uint32_t WEB_EXPORT(Web_Scene_GetWorld)(const WebScene* web);
uint32_t Web_Scene_GetWorld(const WebScene* web)
{
	return tbStoreWorldId(web->world.worldId);
}

/// One step of the scene (spawners, driven bodies, then the world), as `tumble run` steps.
int WEB_EXPORT(Web_Scene_Step)(WebScene* web);
int Web_Scene_Step(WebScene* web)
{
	return SceneWorld_Step(&web->world, web->scene, web->subSteps);
}

/// Scratch on return: float time step, then int32 sub-steps, suggested steps, steps taken.
void WEB_EXPORT(Web_Scene_GetSettings)(const WebScene* web);
void Web_Scene_GetSettings(const WebScene* web)
{
	int32_t values[3] = {web->subSteps, web->scene->steps, web->world.stepIndex};
	memcpy(s_scratch, &web->scene->timeStep, sizeof(float));
	memcpy(s_scratch + sizeof(float), values, sizeof(values));
}

/// What `tumble run` prints after its run. Scratch on return: float largest penetration (m),
/// kinetic energy (J), then int32 awake bodies.
void WEB_EXPORT(Web_Scene_GetReadouts)(const WebScene* web);
void Web_Scene_GetReadouts(const WebScene* web)
{
	float values[2] = {SceneWorld_LargestPenetration(&web->world), SceneWorld_KineticEnergy(&web->world)};
	int32_t awake = SceneWorld_AwakeCount(&web->world);
	memcpy(s_scratch, values, sizeof(values));
	memcpy(s_scratch + sizeof(values), &awake, sizeof(awake));
}

static bool UnionBodyBoxes(const WebScene* web, bool moving, tbAABB* box)
{
	int capacity = SceneWorld_BodyCapacity(&web->world);
	tbBodyId* ids = malloc(sizeof(tbBodyId) * (size_t)capacity);
	int count = ids != NULL ? SceneWorld_CollectBodies(&web->world, ids, capacity) : 0;
	bool found = false;
	for (int i = 0; i < count; ++i)
	{
		if (tbBody_GetShapeCount(ids[i]) == 0 || (tbBody_GetType(ids[i]) != tb_staticBody) != moving)
		{
			continue;
		}
		tbAABB b = tbBody_ComputeAABB(ids[i]);
		*box = found ? tbAABB_Union(*box, b) : b;
		found = true;
	}
	free(ids);
	return found;
}

/// The box that frames the scene: its moving bodies (the ground is often far wider than the
/// action), or its static ones when nothing moves. Scratch on return: float lowerX, lowerY,
/// upperX, upperY.
void WEB_EXPORT(Web_Scene_GetBounds)(const WebScene* web);
void Web_Scene_GetBounds(const WebScene* web)
{
	tbAABB box = {{-10.0f, -10.0f}, {10.0f, 10.0f}};
	if (UnionBodyBoxes(web, true, &box) == false)
	{
		UnionBodyBoxes(web, false, &box);
	}
	memcpy(s_scratch, &box, sizeof(box));
}
