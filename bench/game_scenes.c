// Game-scale scenes (see game_scenes.h), written once against the Box2D v3.2 API through prefix
// macros and compiled twice: with GAME_TUMBLE against Tumble (tb*), with GAME_BOX2D3 against
// Box2D v3.2 (b2*). Every call, type and constant below goes through P() (functions and types:
// P(CreateWorld), P(BodyDef)), K() (enumerators: K(dynamicBody)) or C() (macros: C(IS_NULL)), so
// that a scene that compiles here for both engines is a port by renaming: every line is written once,
// the allocator hook included.
//
// Both engines get the same work: the same bodies in the same order, the same frame (1/60 s,
// 4 sub-steps), the same sleep settings (on, each body's default threshold), the same material
// values set explicitly (defaults are not trusted to agree), and the same scripted input, which
// depends only on the frame number, never on the engine's state (a pinball drain, read from the
// ball, only relaunches the ball: both engines do the same thing when it happens).
#include "game_scenes.h"

#if defined(GAME_TUMBLE)
#include "tumble/tumble.h"
#define P(name) tb##name
#define K(name) tb_##name
#define C(name) TB_##name
#define GAME_ENGINE gameEngineTumble
#define GAME_ENGINE_NAME "tumble"
#elif defined(GAME_BOX2D3)
#include "box2d/box2d.h"
#define P(name) b2##name
#define K(name) b2_##name
#define C(name) B2_##name
#define GAME_ENGINE gameEngineBox2D3
#define GAME_ENGINE_NAME "box2d-3.2"
#else
#error "compile with GAME_TUMBLE or GAME_BOX2D3"
#endif

#include <float.h>
#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#define GAME_DT (1.0f / 60.0f)
#define GAME_SUBSTEPS 4
#define GAME_PI 3.14159265f

typedef P(Vec2) Vec2;
typedef P(BodyId) BodyId;
typedef P(WorldId) WorldId;

// The reference task system (samples/task_system.c), declared here with this engine's callback
// type: Tumble's tbTaskCallback and v3.2's b2TaskCallback are the same function type, void(void*),
// so one pool serves both engines as it is.
void* TaskSystem_Enqueue(P(TaskCallback) * task, void* taskContext, void* userContext);
void TaskSystem_Finish(void* userTask, void* userContext);

static Vec2 V(float x, float y)
{
	Vec2 v = {x, y};
	return v;
}

static P(Rot) Rot(float angle)
{
	P(Rot) q = {cosf(angle), sinf(angle)}; // exact, so both engines start from the same rotations
	return q;
}

// A small generator of our own, so both engines get the same numbers.
typedef struct Rng
{
	uint32_t state;
} Rng;

static float RandomRange(Rng* rng, float lo, float hi)
{
	rng->state ^= rng->state << 13;
	rng->state ^= rng->state >> 17;
	rng->state ^= rng->state << 5;
	return lo + (hi - lo) * (float)(rng->state >> 8) / 16777216.0f;
}

// ---------------------------------------------------------------------------------------------
// The game: one or many worlds, every body made (for the end-state check), and what each scene drives

#define GAME_MAX_JOINTS 8

typedef struct Mover
{
	BodyId body;	   // kinematic capsule that follows the mover, so it shoves crates
	P(Capsule) capsule; // relative to the feet point
	Vec2 position;	   // feet point
	Vec2 velocity;
	bool onGround;
	int planeCount;
} Mover;

struct Game
{
	int scene;
	int param;
	WorldId world;
	WorldId* worlds; // the many-worlds scene: the live batch
	int worldCount;
	BodyId* bodies;
	int bodyCount, bodyCapacity;
	int jointCount;
	int stepIndex;
	int64_t events;
	BodyId tracked;
	bool hasTracked;
	P(JointId) joints[GAME_MAX_JOINTS];
	BodyId platform;
	Mover mover;
	BodyId ground;
	void* taskSystem;
	float rollingResistance; // of the round mixed bodies
	int workers;			 // the many-worlds scene: each world's worker count
	GameStats batchStats; // the many-worlds scene: batches already destroyed
};

static BodyId AddBody(Game* g, WorldId world, const P(BodyDef) * def)
{
	BodyId id = P(CreateBody)(world, def);
	if (g->bodyCount == g->bodyCapacity)
	{
		g->bodyCapacity = g->bodyCapacity ? 2 * g->bodyCapacity : 64;
		g->bodies = realloc(g->bodies, (size_t)g->bodyCapacity * sizeof(BodyId));
	}
	g->bodies[g->bodyCount++] = id;
	return id;
}

static P(WorldDef) GameWorldDef(void)
{
	P(WorldDef) def = P(DefaultWorldDef)();
	def.gravity = V(0.0f, -10.0f);
	def.enableSleep = true;
	// The defaults differ here (v3.2: 400 m/s, Tumble: 4000 m/s); no scene comes near either.
	def.maximumLinearSpeed = 400.0f;
	return def;
}

static P(ShapeDef) GameShapeDef(float density, float friction)
{
	P(ShapeDef) def = P(DefaultShapeDef)();
	def.density = density;
	def.material.friction = friction;
	def.material.restitution = 0.0f;
	def.material.rollingResistance = 0.0f;
	def.enableContactEvents = false;
	def.enableHitEvents = false;
	def.enableSensorEvents = false;
	return def;
}

static P(BodyDef) GameBodyDef(P(BodyType) type, Vec2 position, float angle)
{
	P(BodyDef) def = P(DefaultBodyDef)();
	def.type = type;
	def.position = position;
	def.rotation = Rot(angle);
	def.sleepThreshold = 0.05f;
	def.enableSleep = true;
	return def;
}

static Game* NewGame(int scene, const GameOptions* options)
{
	Game* g = calloc(1, sizeof(Game));
	g->scene = scene;
	g->param = options->param;
	g->taskSystem = options->taskSystem;
	g->rollingResistance = 0.1f;
	return g;
}

static WorldId NewWorld(Game* g, Vec2 gravity)
{
	P(WorldDef) def = GameWorldDef();
	def.gravity = gravity;
	g->world = P(CreateWorld)(&def);
	return g->world;
}

static void StepWorld(Game* g)
{
	P(World_Step)(g->world, GAME_DT, GAME_SUBSTEPS);
	g->stepIndex += 1;
}

static int TouchingContacts(BodyId body)
{
	enum
	{
		localCapacity = 64
	};
	P(ContactData) local[localCapacity];
	int capacity = P(Body_GetContactCapacity)(body);
	P(ContactData)* data = capacity <= localCapacity ? local : malloc((size_t)capacity * sizeof(P(ContactData)));
	int count = P(Body_GetContactData)(body, data, capacity);
	int touching = 0;
	for (int i = 0; i < count; ++i)
	{
		touching += data[i].manifold.pointCount > 0;
	}
	if (data != local)
	{
		free(data);
	}
	return touching;
}

// The end state of the live world(s); every contact is listed on both of its bodies.
static GameStats ReadStats(Game* g)
{
	GameStats s = g->batchStats;
	s.fastest = 0.0f;
	s.fastestBody = -1;
	int touchingEnds = 0;
	for (int i = 0; i < g->bodyCount; ++i)
	{
		if (P(Body_IsValid)(g->bodies[i]))
		{
			s.bodies += 1;
			touchingEnds += TouchingContacts(g->bodies[i]);
			if (P(Body_IsAwake)(g->bodies[i]))
			{
				Vec2 v = P(Body_GetLinearVelocity)(g->bodies[i]);
				float speed = sqrtf(v.x * v.x + v.y * v.y) + fabsf(P(Body_GetAngularVelocity)(g->bodies[i]));
				if (speed > s.fastest)
				{
					s.fastest = speed;
					s.fastestBody = i;
				}
			}
		}
	}
	s.touching += touchingEnds / 2;
	if (g->worlds != NULL)
	{
		for (int w = 0; w < g->worldCount; ++w)
		{
			s.awake += P(World_GetAwakeBodyCount)(g->worlds[w]);
		}
	}
	else
	{
		s.awake += P(World_GetAwakeBodyCount)(g->world);
		P(Counters) counters = P(World_GetCounters)(g->world);
		s.contacts = counters.awakeContactCount;
		s.recycled = counters.recycledContactCount;
	}
	s.joints += g->jointCount;
	s.events = g->events;
	if (g->hasTracked && P(Body_IsValid)(g->tracked))
	{
		P(Pos) p = P(Body_GetPosition)(g->tracked);
		s.x = (double)p.x;
		s.y = (double)p.y;
	}
	else
	{
		s.x = s.y = NAN;
	}
	return s;
}

static void FreeGame(Game* g)
{
	if (g->worlds != NULL)
	{
		for (int w = 0; w < g->worldCount; ++w)
		{
			P(DestroyWorld)(g->worlds[w]);
		}
		free(g->worlds);
	}
	else if (C(IS_NON_NULL)(g->world))
	{
		P(DestroyWorld)(g->world);
	}
	free(g->bodies);
	free(g);
}

// Step until no body is awake, then 30 frames more: an engine may finish work of its own in the
// first frames after the last island sleeps (broad-phase upkeep), which is not the asleep state
// being timed.
static int Settle(Game* g, int maxSteps)
{
	for (int i = 0; i < maxSteps && P(World_GetAwakeBodyCount)(g->world) > 0; ++i)
	{
		StepWorld(g);
	}
	for (int i = 0; i < 30; ++i)
	{
		StepWorld(g);
	}
	return P(World_GetAwakeBodyCount)(g->world);
}

static void StaticBox(Game* g, BodyId body, float hx, float hy, Vec2 center, float angle)
{
	(void)g;
	P(ShapeDef) sd = GameShapeDef(0.0f, 0.6f);
	P(Polygon) box = P(MakeOffsetBox)(hx, hy, center, Rot(angle));
	P(CreatePolygonShape)(body, &sd, &box);
}

// One of three kinds by index: a box, a circle, a capsule, each about a metre across. Round shapes
// get a little rolling resistance (the game's setting), so that piles come to rest.
static BodyId AddMixedBody(Game* g, WorldId world, Vec2 position, float angle, int kind)
{
	P(BodyDef) bd = GameBodyDef(K(dynamicBody), position, angle);
	BodyId body = AddBody(g, world, &bd);
	P(ShapeDef) sd = GameShapeDef(1.0f, 0.6f);
	switch (kind % 3)
	{
		case 0:
		{
			P(Polygon) box = P(MakeBox)(0.4f, 0.4f);
			P(CreatePolygonShape)(body, &sd, &box);
			break;
		}
		case 1:
		{
			sd.material.rollingResistance = g->rollingResistance;
			P(Circle) circle = {V(0.0f, 0.0f), 0.45f};
			P(CreateCircleShape)(body, &sd, &circle);
			break;
		}
		default:
		{
			sd.material.rollingResistance = g->rollingResistance;
			P(Capsule) capsule = {V(-0.35f, 0.0f), V(0.35f, 0.0f), 0.25f};
			P(CreateCapsuleShape)(body, &sd, &capsule);
			break;
		}
	}
	return body;
}

// ---------------------------------------------------------------------------------------------
// Empty world: the fixed cost of one step

static Game* CreateEmpty(const GameOptions* options)
{
	Game* g = NewGame(0, options);
	NewWorld(g, V(0.0f, -10.0f));
	return g;
}

// ---------------------------------------------------------------------------------------------
// Falling bodies: `param` mixed bodies in a grid above a ground between two walls, falling and
// landing during the timed frames. The box is as wide as the count needs for a pile a few bodies deep.

static void BuildFallingBox(Game* g, WorldId world, int count, uint32_t seed)
{
	float width = fmaxf(12.0f, (float)count / 8.0f); // about eight rows falling, a pile about six deep
	P(BodyDef) gd = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
	BodyId ground = AddBody(g, world, &gd);
	g->ground = ground;
	StaticBox(g, ground, 0.5f * width + 1.0f, 0.5f, V(0.0f, -0.5f), 0.0f);
	const float wallHeight = 20.0f;
	StaticBox(g, ground, 0.5f, 0.5f * wallHeight, V(-0.5f * width - 0.5f, 0.5f * wallHeight), 0.0f);
	StaticBox(g, ground, 0.5f, 0.5f * wallHeight, V(0.5f * width + 0.5f, 0.5f * wallHeight), 0.0f);

	const float spacing = 1.25f;
	int columns = (int)(width / spacing) - 1;
	if (columns < 1)
	{
		columns = 1;
	}
	Rng rng = {seed};
	for (int i = 0; i < count; ++i)
	{
		int column = i % columns, row = i / columns;
		float x = -0.5f * width + spacing * (float)(column + 1) + RandomRange(&rng, -0.1f, 0.1f);
		float y = 3.0f + spacing * (float)row;
		AddMixedBody(g, world, V(x, y), RandomRange(&rng, -GAME_PI, GAME_PI), i);
	}
}

static Game* CreateFalling(const GameOptions* options)
{
	Game* g = NewGame(1, options);
	WorldId world = NewWorld(g, V(0.0f, -10.0f));
	BuildFallingBox(g, world, options->param, 12345u);
	return g;
}

// The same without rolling resistance: the round bodies keep rolling, but the cost of the rolling
// resistance rows is left out of the comparison.
static Game* CreateFallingNoRolling(const GameOptions* options)
{
	Game* g = NewGame(1, options);
	g->rollingResistance = 0.0f;
	WorldId world = NewWorld(g, V(0.0f, -10.0f));
	BuildFallingBox(g, world, options->param, 12345u);
	return g;
}

// ---------------------------------------------------------------------------------------------
// A level at rest: `param` boxes in walls on five static ledges, settled until every body sleeps
// (untimed), then timed asleep.

static Game* CreateLevelAsleep(const GameOptions* options)
{
	Game* g = NewGame(2, options);
	WorldId world = NewWorld(g, V(0.0f, -10.0f));
	P(BodyDef) gd = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
	BodyId ground = AddBody(g, world, &gd);
	g->ground = ground;
	const int ledges = 5;
	StaticBox(g, ground, 80.0f, 0.5f, V(0.0f, -0.5f), 0.0f);
	int perLedge = (options->param + ledges - 1) / ledges;
	int made = 0;
	for (int l = 0; l < ledges; ++l)
	{
		float lx = -60.0f + 30.0f * (float)l, ly = 2.0f * (float)l;
		if (l > 0)
		{
			StaticBox(g, ground, 8.0f, 0.25f, V(lx, ly - 0.25f), 0.0f);
		}
		for (int i = 0; i < perLedge && made < options->param; ++i, ++made)
		{
			int column = i % 10, row = i / 10;
			P(BodyDef) bd = GameBodyDef(K(dynamicBody), V(lx - 5.0f + 1.0f * (float)column + 0.5f * (float)(row % 2),
															 ly + 0.5f + 1.0f * (float)row),
										0.0f);
			BodyId body = AddBody(g, world, &bd);
			P(ShapeDef) sd = GameShapeDef(1.0f, 0.6f);
			P(Polygon) box = P(MakeBox)(0.45f, 0.5f); // a clear gap between neighbours, resting on the row below
			P(CreatePolygonShape)(body, &sd, &box);
		}
	}
	Settle(g, 4 * GAME_SETTLE_STEPS);
	return g;
}

// ---------------------------------------------------------------------------------------------
// Pinball: a table outlined by a chain loop, two motorised flippers on revolute joints with limits,
// a bullet ball and five bumpers that report begin-touch events (read every frame). The flippers
// flip on a fixed schedule; a ball that drains is put back on the launch spot with the same kick.

static const Vec2 pinballLaunch = {3.6f, 3.5f};
static const Vec2 pinballKick = {-1.0f, 15.0f};

static P(JointId) AddFlipper(Game* g, BodyId table, Vec2 pivot, float direction)
{
	P(BodyDef) bd = GameBodyDef(K(dynamicBody), pivot, 0.0f);
	bd.isBullet = false;
	BodyId flipper = AddBody(g, g->world, &bd);
	P(ShapeDef) sd = GameShapeDef(4.0f, 0.4f);
	P(Capsule) capsule = {V(0.0f, 0.0f), V(direction * 1.25f, 0.0f), 0.13f};
	P(CreateCapsuleShape)(flipper, &sd, &capsule);
	P(RevoluteJointDef) jd = P(DefaultRevoluteJointDef)();
	jd.base.bodyIdA = table;
	jd.base.bodyIdB = flipper;
	jd.base.localFrameA.p = pivot;
	jd.base.localFrameA.q = Rot(0.0f);
	jd.base.localFrameB.p = V(0.0f, 0.0f);
	jd.base.localFrameB.q = Rot(0.0f);
	jd.enableLimit = true;
	jd.lowerAngle = -0.5f;
	jd.upperAngle = 0.5f;
	jd.enableMotor = true;
	jd.maxMotorTorque = 400.0f;
	jd.motorSpeed = -direction * 12.0f; // rest: down
	g->jointCount += 1;
	return P(CreateRevoluteJoint)(g->world, &jd);
}

static Game* CreatePinball(const GameOptions* options)
{
	Game* g = NewGame(3, options);
	WorldId world = NewWorld(g, V(0.0f, -6.0f)); // a tilted table: a part of gravity along it
	P(BodyDef) td = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
	BodyId table = AddBody(g, world, &td);
	g->ground = table;
	// Clockwise, so the chain is solid outside and the ball plays inside; a pit below the flippers.
	static const Vec2 outline[] = {{-4.0f, 12.0f}, {-3.0f, 13.5f}, {-1.5f, 14.0f}, {1.5f, 14.0f}, {3.0f, 13.5f},
								   {4.0f, 12.0f},  {4.0f, 3.0f},   {1.6f, 1.5f},   {1.6f, -1.0f}, {-1.6f, -1.0f},
								   {-1.6f, 1.5f},  {-4.0f, 3.0f}};
	P(SurfaceMaterial) wall = P(DefaultSurfaceMaterial)();
	wall.friction = 0.3f;
	wall.restitution = 0.3f;
	P(ChainDef) cd = P(DefaultChainDef)();
	cd.points = outline;
	cd.count = (int)(sizeof(outline) / sizeof(outline[0]));
	cd.materials = &wall;
	cd.materialCount = 1;
	cd.isLoop = true;
	P(CreateChain)(table, &cd);

	static const Vec2 bumpers[] = {{-1.4f, 9.0f}, {1.4f, 9.0f}, {0.0f, 10.8f}, {-2.2f, 6.5f}, {2.0f, 6.5f}};
	for (int i = 0; i < 5; ++i)
	{
		P(ShapeDef) sd = GameShapeDef(0.0f, 0.2f);
		sd.material.restitution = 1.2f;
		sd.enableContactEvents = true;
		P(Circle) circle = {bumpers[i], 0.5f};
		P(CreateCircleShape)(table, &sd, &circle);
	}
	// Pivots just below the ends of the inlanes, so that a ball rolling down an inlane rolls onto
	// the flipper's top instead of wedging between the flipper's round end and the wall.
	g->joints[0] = AddFlipper(g, table, V(-1.6f, 1.37f), 1.0f);
	g->joints[1] = AddFlipper(g, table, V(1.6f, 1.37f), -1.0f);

	P(BodyDef) bd = GameBodyDef(K(dynamicBody), pinballLaunch, 0.0f);
	bd.isBullet = true;
	bd.linearVelocity = pinballKick;
	BodyId ball = AddBody(g, world, &bd);
	P(ShapeDef) sd = GameShapeDef(8.0f, 0.2f);
	P(Circle) circle = {V(0.0f, 0.0f), 0.2f};
	P(CreateCircleShape)(ball, &sd, &circle);
	g->tracked = ball;
	g->hasTracked = true;
	return g;
}

static void StepPinball(Game* g)
{
	bool flip = g->stepIndex % 50 < 12; // both flippers up for a fifth of a second in every 50 frames
	P(RevoluteJoint_SetMotorSpeed)(g->joints[0], flip ? 14.0f : -12.0f);
	P(RevoluteJoint_SetMotorSpeed)(g->joints[1], flip ? -14.0f : 12.0f);
	P(Pos) p = P(Body_GetPosition)(g->tracked);
	if (p.y < -0.5f)
	{
		P(Body_SetTransform)(g->tracked, pinballLaunch, Rot(0.0f));
		P(Body_SetLinearVelocity)(g->tracked, pinballKick);
		P(Body_SetAngularVelocity)(g->tracked, 0.0f);
	}
	StepWorld(g);
	P(ContactEvents) events = P(World_GetContactEvents)(g->world);
	for (int i = 0; i < events.beginCount; ++i)
	{
		g->events += P(Shape_IsValid)(events.beginEvents[i].shapeIdA) ? 1 : 0;
	}
}

// ---------------------------------------------------------------------------------------------
// Slingshot: a 30-piece tower (ten floors of two posts and a plank) and projectiles shot at it by
// a spring (a distance joint) that lets go as the projectile passes the fork; a new projectile
// every 150 frames. Hit events on the tower and the projectiles, read every frame.

static const Vec2 slingFork = {0.0f, 3.0f};

static void LoadSling(Game* g)
{
	P(BodyDef) bd = GameBodyDef(K(dynamicBody), V(-3.0f, 1.2f), 0.0f);
	bd.isBullet = false;
	BodyId projectile = AddBody(g, g->world, &bd);
	P(ShapeDef) sd = GameShapeDef(4.0f, 0.5f);
	sd.enableHitEvents = true;
	P(Circle) circle = {V(0.0f, 0.0f), 0.3f};
	P(CreateCircleShape)(projectile, &sd, &circle);
	P(DistanceJointDef) jd = P(DefaultDistanceJointDef)();
	jd.base.bodyIdA = g->ground;
	jd.base.bodyIdB = projectile;
	jd.base.localFrameA.p = slingFork;
	jd.base.localFrameA.q = Rot(0.0f);
	jd.base.localFrameB.p = V(0.0f, 0.0f);
	jd.base.localFrameB.q = Rot(0.0f);
	jd.length = 0.1f;
	jd.enableSpring = true;
	jd.hertz = 0.9f;
	jd.dampingRatio = 0.0f;
	g->joints[0] = P(CreateDistanceJoint)(g->world, &jd);
	g->jointCount += 1;
	g->tracked = projectile;
	g->hasTracked = true;
}

static Game* CreateSlingshot(const GameOptions* options)
{
	Game* g = NewGame(4, options);
	WorldId world = NewWorld(g, V(0.0f, -10.0f));
	P(BodyDef) gd = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
	g->ground = AddBody(g, world, &gd);
	StaticBox(g, g->ground, 60.0f, 0.5f, V(20.0f, -0.5f), 0.0f);
	const float postHalfWidth = 0.15f, postHalfHeight = 0.6f, plankHalfWidth = 1.2f, plankHalfHeight = 0.15f;
	const float towerX = 18.0f;
	for (int floor = 0; floor < 10; ++floor)
	{
		float base = (float)floor * 2.0f * (postHalfHeight + plankHalfHeight);
		for (int side = -1; side <= 1; side += 2)
		{
			P(BodyDef) pd = GameBodyDef(K(dynamicBody), V(towerX + (float)side * 0.9f, base + postHalfHeight), 0.0f);
			BodyId post = AddBody(g, world, &pd);
			P(ShapeDef) sd = GameShapeDef(0.5f, 0.6f);
			sd.enableHitEvents = true;
			P(Polygon) box = P(MakeBox)(postHalfWidth, postHalfHeight);
			P(CreatePolygonShape)(post, &sd, &box);
		}
		P(BodyDef) kd = GameBodyDef(K(dynamicBody), V(towerX, base + 2.0f * postHalfHeight + plankHalfHeight), 0.0f);
		BodyId plank = AddBody(g, world, &kd);
		P(ShapeDef) sd = GameShapeDef(0.5f, 0.6f);
		sd.enableHitEvents = true;
		P(Polygon) box = P(MakeBox)(plankHalfWidth, plankHalfHeight);
		P(CreatePolygonShape)(plank, &sd, &box);
	}
	LoadSling(g);
	return g;
}

static void StepSlingshot(Game* g)
{
	if (g->stepIndex > 0 && g->stepIndex % 150 == 0)
	{
		LoadSling(g);
	}
	if (C(IS_NON_NULL)(g->joints[0]) && P(Body_GetPosition)(g->tracked).x > slingFork.x)
	{
		P(DestroyJoint)(g->joints[0]);
		g->joints[0] = (P(JointId)){0};
		g->jointCount -= 1;
	}
	StepWorld(g);
	P(ContactEvents) events = P(World_GetContactEvents)(g->world);
	g->events += events.hitCount;
}

// ---------------------------------------------------------------------------------------------
// Platformer: a character on the mover kit (World_CollideMover, SolvePlanes, World_CastMover,
// ClipVector), as Box2D v3.2's mover sample runs one, over a chain ground with ledges, crates it
// its body shoves aside (its capsule is also a kinematic body driven to its pose; its queries leave
// the crates out) and a kinematic platform
// that moves back and forth. Input: run right, then left, jumping every 45 frames.

#define MOVER_CATEGORY 0x8000u
#define CRATE_CATEGORY 0x4000u
#define MOVER_MAX_PLANES 16

typedef struct MoverPlanes
{
	P(CollisionPlane) planes[MOVER_MAX_PLANES];
	int count;
	bool onGround;
} MoverPlanes;

static bool CollectPlane(P(ShapeId) shapeId, const P(PlaneResult) * result, void* context)
{
	MoverPlanes* p = context;
	if (p->count == MOVER_MAX_PLANES || result->hit == false)
	{
		return p->count < MOVER_MAX_PLANES;
	}
	bool rigid = P(Body_GetType)(P(Shape_GetBody)(shapeId)) != K(dynamicBody);
	P(CollisionPlane)* plane = p->planes + p->count++;
	plane->plane = result->plane;
	plane->pushLimit = rigid ? FLT_MAX : 0.02f; // a crate pushes back a little; the body shoves it
	plane->push = 0.0f;
	plane->clipVelocity = rigid;
	p->onGround = p->onGround || (rigid && result->plane.normal.y > 0.7f);
	return true;
}

static void MoverUpdate(Game* g, float moveSpeed, bool jump)
{
	Mover* m = &g->mover;
	m->velocity.x = moveSpeed;
	m->velocity.y = m->onGround && jump ? 9.0f : m->velocity.y - 20.0f * GAME_DT;
	P(QueryFilter) filter = P(DefaultQueryFilter)();
	// The mover sees the static level and the platform, not the crates, which its body shoves
	// aside: its path is then the same on both engines whatever the crates do.
	filter.maskBits &= ~(uint64_t)(MOVER_CATEGORY | CRATE_CATEGORY);
	Vec2 target = P(MulAdd)(m->position, GAME_DT, m->velocity);
	MoverPlanes planes;
	memset(&planes, 0, sizeof(planes));
	for (int round = 0; round < 5; ++round)
	{
		planes.count = 0;
		planes.onGround = false;
		P(World_CollideMover)(g->world, m->position, &m->capsule, filter, CollectPlane, &planes);
		P(PlaneSolverResult) solved = P(SolvePlanes)(P(Sub)(target, m->position), planes.planes, planes.count);
		float fraction = P(World_CastMover)(g->world, m->position, &m->capsule, solved.delta, filter);
		Vec2 delta = P(MulSV)(fraction, solved.delta);
		m->position = P(Add)(m->position, delta);
		if (P(LengthSquared)(delta) < 0.01f * 0.01f)
		{
			break;
		}
	}
	m->velocity = P(ClipVector)(m->velocity, planes.planes, planes.count);
	m->onGround = planes.onGround;
	m->planeCount = planes.count;
	P(WorldTransform) pose = {m->position, Rot(0.0f)};
	P(Body_SetTargetTransform)(m->body, pose, GAME_DT, true);
}

static Game* CreatePlatformer(const GameOptions* options)
{
	Game* g = NewGame(5, options);
	WorldId world = NewWorld(g, V(0.0f, -10.0f));
	P(BodyDef) gd = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
	g->ground = AddBody(g, world, &gd);
	// Right to left, so the chain is solid below; its first and last points are ghosts.
	static const Vec2 ground[] = {{62.0f, 0.0f}, {60.0f, 0.0f}, {40.0f, 0.0f},	{36.0f, 2.0f},	{30.0f, 2.0f},
								  {26.0f, 0.0f}, {10.0f, 0.0f}, {8.0f, 1.0f},	{4.0f, 1.0f},	{2.0f, 0.0f},
								  {-20.0f, 0.0f}, {-20.0f, 8.0f}, {-22.0f, 8.0f}};
	P(SurfaceMaterial) material = P(DefaultSurfaceMaterial)();
	material.friction = 0.6f;
	P(ChainDef) cd = P(DefaultChainDef)();
	cd.points = ground;
	cd.count = (int)(sizeof(ground) / sizeof(ground[0]));
	cd.materials = &material;
	cd.materialCount = 1;
	P(CreateChain)(g->ground, &cd);
	StaticBox(g, g->ground, 0.5f, 6.0f, V(60.5f, 6.0f), 0.0f); // the right wall
	StaticBox(g, g->ground, 2.0f, 0.2f, V(16.0f, 3.0f), 0.0f); // ledges
	StaticBox(g, g->ground, 2.0f, 0.2f, V(46.0f, 3.5f), 0.0f);

	for (int i = 0; i < 24; ++i) // crates in piles of three
	{
		float x = -12.0f + 3.0f * (float)(i / 3) + (i / 3 >= 4 ? 16.0f : 0.0f);
		float y = 0.4f + 0.8f * (float)(i % 3) + (x > 26.0f && x < 40.0f ? 2.0f : 0.0f);
		P(BodyDef) bd = GameBodyDef(K(dynamicBody), V(x, y), 0.0f);
		BodyId crate = AddBody(g, world, &bd);
		P(ShapeDef) sd = GameShapeDef(0.5f, 0.6f);
		sd.filter.categoryBits = CRATE_CATEGORY;
		P(Polygon) box = P(MakeBox)(0.4f, 0.4f);
		P(CreatePolygonShape)(crate, &sd, &box);
	}

	P(BodyDef) pd = GameBodyDef(K(kinematicBody), V(20.0f, 4.5f), 0.0f);
	g->platform = AddBody(g, world, &pd);
	StaticBox(g, g->platform, 1.5f, 0.2f, V(0.0f, 0.0f), 0.0f);

	Mover* m = &g->mover;
	m->capsule = (P(Capsule)){V(0.0f, 0.3f), V(0.0f, 1.5f), 0.3f};
	m->position = V(-15.0f, 0.05f);
	P(BodyDef) md = GameBodyDef(K(kinematicBody), m->position, 0.0f);
	m->body = AddBody(g, world, &md);
	P(ShapeDef) sd = GameShapeDef(1.0f, 0.6f);
	sd.filter.categoryBits = MOVER_CATEGORY;
	P(CreateCapsuleShape)(m->body, &sd, &m->capsule);
	g->tracked = m->body;
	g->hasTracked = true;
	return g;
}

static void StepPlatformer(Game* g)
{
	int t = g->stepIndex;
	float phase = (float)t * GAME_DT;
	P(WorldTransform) platform = {V(20.0f + 6.0f * sinf(0.8f * (phase + GAME_DT)), 4.5f), Rot(0.0f)};
	P(Body_SetTargetTransform)(g->platform, platform, GAME_DT, true);
	float speed = (t / 300) % 2 == 0 ? 6.0f : -6.0f;
	MoverUpdate(g, speed, t % 45 == 0);
	StepWorld(g);
	g->events += g->mover.planeCount;
}

// ---------------------------------------------------------------------------------------------
// Ragdolls: `param` ragdolls of eleven capsules (head, torso in two, upper and lower arms and legs)
// joined by revolute joints with limits, dropped into a pit from a few heights so they pile up.

typedef struct Limb
{
	Vec2 center1, center2; // the capsule in the body frame
	float radius;
	Vec2 position;	// body origin relative to the ragdoll's hip
	int parent;		// -1 for the root
	Vec2 pivot;		// joint anchor relative to the hip
	float lower, upper;
} Limb;

static const Limb ragdollLimbs[] = {
	{{0.0f, -0.15f}, {0.0f, 0.15f}, 0.14f, {0.0f, 0.25f}, -1, {0.0f, 0.0f}, 0.0f, 0.0f},				  // lower torso
	{{0.0f, -0.15f}, {0.0f, 0.15f}, 0.16f, {0.0f, 0.65f}, 0, {0.0f, 0.45f}, -0.25f * GAME_PI, 0.0f}, // upper torso
	{{0.0f, -0.05f}, {0.0f, 0.05f}, 0.12f, {0.0f, 1.05f}, 1, {0.0f, 0.9f}, -0.3f * GAME_PI, 0.1f * GAME_PI}, // head
	{{0.0f, -0.17f}, {0.0f, 0.17f}, 0.07f, {0.0f, 0.6f}, 1, {0.0f, 0.8f}, -0.9f * GAME_PI, 0.9f * GAME_PI}, // upper arm L
	{{0.0f, -0.17f}, {0.0f, 0.17f}, 0.06f, {0.0f, 0.25f}, 3, {0.0f, 0.42f}, -0.8f * GAME_PI, 0.0f},		 // lower arm L
	{{0.0f, -0.17f}, {0.0f, 0.17f}, 0.07f, {0.0f, 0.6f}, 1, {0.0f, 0.8f}, -0.9f * GAME_PI, 0.9f * GAME_PI}, // upper arm R
	{{0.0f, -0.17f}, {0.0f, 0.17f}, 0.06f, {0.0f, 0.25f}, 5, {0.0f, 0.42f}, 0.0f, 0.8f * GAME_PI},		 // lower arm R
	{{0.0f, -0.2f}, {0.0f, 0.2f}, 0.09f, {0.0f, -0.25f}, 0, {0.0f, 0.0f}, -0.2f * GAME_PI, 0.6f * GAME_PI}, // upper leg L
	{{0.0f, -0.2f}, {0.0f, 0.2f}, 0.08f, {0.0f, -0.75f}, 7, {0.0f, -0.5f}, -0.6f * GAME_PI, 0.0f},		 // lower leg L
	{{0.0f, -0.2f}, {0.0f, 0.2f}, 0.09f, {0.0f, -0.25f}, 0, {0.0f, 0.0f}, -0.2f * GAME_PI, 0.6f * GAME_PI}, // upper leg R
	{{0.0f, -0.2f}, {0.0f, 0.2f}, 0.08f, {0.0f, -0.75f}, 9, {0.0f, -0.5f}, -0.6f * GAME_PI, 0.0f},		 // lower leg R
};
#define RAGDOLL_LIMBS ((int)(sizeof(ragdollLimbs) / sizeof(ragdollLimbs[0])))

static void AddRagdoll(Game* g, Vec2 hip, float angle, int group)
{
	BodyId limbs[RAGDOLL_LIMBS];
	P(Rot) q = Rot(angle);
	for (int i = 0; i < RAGDOLL_LIMBS; ++i)
	{
		const Limb* l = ragdollLimbs + i;
		P(BodyDef) bd = GameBodyDef(K(dynamicBody), P(Add)(hip, P(RotateVector)(q, l->position)), angle);
		limbs[i] = AddBody(g, g->world, &bd);
		P(ShapeDef) sd = GameShapeDef(1.0f, 0.6f);
		sd.filter.groupIndex = -group; // a ragdoll's limbs do not collide with each other
		P(Capsule) capsule = {l->center1, l->center2, l->radius};
		P(CreateCapsuleShape)(limbs[i], &sd, &capsule);
	}
	for (int i = 1; i < RAGDOLL_LIMBS; ++i)
	{
		const Limb* l = ragdollLimbs + i;
		const Limb* parent = ragdollLimbs + l->parent;
		P(RevoluteJointDef) jd = P(DefaultRevoluteJointDef)();
		jd.base.bodyIdA = limbs[l->parent];
		jd.base.bodyIdB = limbs[i];
		jd.base.localFrameA.p = P(Sub)(l->pivot, parent->position);
		jd.base.localFrameA.q = Rot(0.0f);
		jd.base.localFrameB.p = P(Sub)(l->pivot, l->position);
		jd.base.localFrameB.q = Rot(0.0f);
		jd.enableLimit = true;
		jd.lowerAngle = l->lower;
		jd.upperAngle = l->upper;
		jd.enableMotor = true; // a little joint friction, as v3's ragdoll sample has
		jd.maxMotorTorque = 0.5f;
		jd.motorSpeed = 0.0f;
		P(CreateRevoluteJoint)(g->world, &jd);
		g->jointCount += 1;
	}
}

static Game* CreateRagdolls(const GameOptions* options)
{
	Game* g = NewGame(6, options);
	WorldId world = NewWorld(g, V(0.0f, -10.0f));
	P(BodyDef) gd = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
	g->ground = AddBody(g, world, &gd);
	StaticBox(g, g->ground, 6.0f, 0.5f, V(0.0f, -0.5f), 0.0f);
	StaticBox(g, g->ground, 0.5f, 8.0f, V(-6.5f, 8.0f), 0.0f);
	StaticBox(g, g->ground, 0.5f, 8.0f, V(6.5f, 8.0f), 0.0f);
	Rng rng = {777u};
	for (int i = 0; i < options->param; ++i)
	{
		float x = -3.5f + 3.5f * (float)(i % 3) + RandomRange(&rng, -0.3f, 0.3f);
		float y = 3.0f + 2.6f * (float)(i / 3);
		AddRagdoll(g, V(x, y), RandomRange(&rng, -0.5f * GAME_PI, 0.5f * GAME_PI), i + 1);
	}
	return g;
}

// ---------------------------------------------------------------------------------------------
// Car: a chassis on two wheels (wheel joints with springs, limits and motors) driving over a
// chain of rolling hills, with a few crates on the way.

static float TerrainHeight(float x)
{
	return x > 10.0f ? 1.2f * sinf(0.11f * x) + 0.5f * sinf(0.37f * x) - 1.2f * sinf(1.1f) - 0.5f * sinf(3.7f) : 0.0f;
}

static Game* CreateCar(const GameOptions* options)
{
	Game* g = NewGame(7, options);
	WorldId world = NewWorld(g, V(0.0f, -10.0f));
	P(BodyDef) gd = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
	g->ground = AddBody(g, world, &gd);
	enum
	{
		terrainPoints = 403
	};
	static Vec2 terrain[terrainPoints];
	for (int i = 0; i < terrainPoints; ++i) // right to left: solid below
	{
		float x = 390.0f - 1.0f * (float)i;
		terrain[i] = V(x, TerrainHeight(x));
	}
	P(SurfaceMaterial) material = P(DefaultSurfaceMaterial)();
	material.friction = 0.9f;
	P(ChainDef) cd = P(DefaultChainDef)();
	cd.points = terrain;
	cd.count = terrainPoints;
	cd.materials = &material;
	cd.materialCount = 1;
	P(CreateChain)(g->ground, &cd);

	P(BodyDef) bd = GameBodyDef(K(dynamicBody), V(0.0f, 1.2f), 0.0f);
	BodyId chassis = AddBody(g, world, &bd);
	P(ShapeDef) sd = GameShapeDef(2.0f, 0.6f);
	P(Polygon) body = P(MakeBox)(1.4f, 0.3f);
	P(CreatePolygonShape)(chassis, &sd, &body);
	P(Polygon) cabin = P(MakeOffsetBox)(0.6f, 0.25f, V(-0.2f, 0.5f), Rot(0.0f));
	P(CreatePolygonShape)(chassis, &sd, &cabin);
	for (int w = 0; w < 2; ++w)
	{
		Vec2 offset = V(w == 0 ? -1.0f : 1.0f, -0.45f);
		P(BodyDef) wd = GameBodyDef(K(dynamicBody), P(Add)(V(0.0f, 1.2f), offset), 0.0f);
		BodyId wheel = AddBody(g, world, &wd);
		P(ShapeDef) ws = GameShapeDef(2.0f, 0.9f);
		ws.material.rollingResistance = 0.0f;
		P(Circle) circle = {V(0.0f, 0.0f), 0.4f};
		P(CreateCircleShape)(wheel, &ws, &circle);
		P(WheelJointDef) jd = P(DefaultWheelJointDef)();
		jd.base.bodyIdA = chassis;
		jd.base.bodyIdB = wheel;
		jd.base.localFrameA.p = offset;
		jd.base.localFrameA.q = Rot(0.5f * GAME_PI); // the frame's x-axis, the suspension, points up
		jd.base.localFrameB.p = V(0.0f, 0.0f);
		jd.base.localFrameB.q = Rot(0.5f * GAME_PI);
		jd.enableSpring = true;
		jd.hertz = 5.0f;
		jd.dampingRatio = 0.7f;
		jd.enableLimit = true;
		jd.lowerTranslation = -0.25f;
		jd.upperTranslation = 0.25f;
		jd.enableMotor = true;
		jd.maxMotorTorque = 10.0f;
		jd.motorSpeed = -18.0f; // clockwise: forward, to the right
		g->joints[w] = P(CreateWheelJoint)(world, &jd);
		g->jointCount += 1;
	}
	for (int i = 0; i < 12; ++i)
	{
		float x = 30.0f + 25.0f * (float)i;
		float y = TerrainHeight(x) + 1.0f;
		P(BodyDef) cb = GameBodyDef(K(dynamicBody), V(x, y), 0.0f);
		BodyId crate = AddBody(g, world, &cb);
		P(ShapeDef) cs = GameShapeDef(0.3f, 0.6f);
		P(Polygon) box = P(MakeBox)(0.3f, 0.3f);
		P(CreatePolygonShape)(crate, &cs, &box);
	}
	g->tracked = chassis;
	g->hasTracked = true;
	return g;
}

// ---------------------------------------------------------------------------------------------
// Many worlds: `param` worlds of 20 bodies (a small mixed pile falling on a ground), each stepped in
// turn. Both engines allow 128 worlds at once (TB_MAX_WORLDS, B2_MAX_WORLDS), so the worlds live in
// batches of 125: a batch is made (untimed), each of its worlds stepped `steps` frames one world
// after another, its end state added up and the batch destroyed. µs per step is the time of one
// frame of every world. With workers, each world steps on 2 workers through the task system.

#define WORLD_BATCH 125

static void MakeBatch(Game* g, int count, int first, int workers)
{
	g->worldCount = count;
	for (int w = 0; w < count; ++w)
	{
		P(WorldDef) def = GameWorldDef();
		if (workers > 1)
		{
			def.workerCount = workers;
			def.enqueueTask = TaskSystem_Enqueue;
			def.finishTask = TaskSystem_Finish;
			def.userTaskContext = g->taskSystem;
		}
		g->worlds[w] = P(CreateWorld)(&def);
		P(BodyDef) gd = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
		BodyId ground = AddBody(g, g->worlds[w], &gd);
		StaticBox(g, ground, 6.0f, 0.5f, V(0.0f, -0.5f), 0.0f);
		Rng rng = {1000u + (uint32_t)(first + w)};
		for (int i = 0; i < 19; ++i)
		{
			AddMixedBody(g, g->worlds[w], V(-4.0f + 2.0f * (float)(i % 5) + RandomRange(&rng, -0.2f, 0.2f), 1.0f + 1.3f * (float)(i / 5)),
						 RandomRange(&rng, -GAME_PI, GAME_PI), i);
		}
	}
}

static void EndBatch(Game* g)
{
	g->world = (WorldId){0};
	GameStats s = ReadStats(g);
	s.events = 0;
	s.x = s.y = 0.0;
	g->batchStats = s;
	for (int w = 0; w < g->worldCount; ++w)
	{
		P(DestroyWorld)(g->worlds[w]);
	}
	g->worldCount = 0;
	g->bodyCount = 0;
}

static Game* CreateWorlds(const GameOptions* options, int workers)
{
	Game* g = NewGame(8, options);
	g->worlds = calloc(WORLD_BATCH, sizeof(WorldId));
	g->workers = workers;
	return g;
}

static Game* CreateWorlds1(const GameOptions* options)
{
	return CreateWorlds(options, 1);
}

static Game* CreateWorlds2(const GameOptions* options)
{
	return CreateWorlds(options, 2);
}

static void StepWorlds(Game* g)
{
	for (int w = 0; w < g->worldCount; ++w)
	{
		P(World_Step)(g->worlds[w], GAME_DT, GAME_SUBSTEPS);
	}
}

static double RunWorlds(Game* g, int steps)
{
	int workers = g->workers;
	double seconds = 0.0;
	for (int first = 0; first < g->param; first += WORLD_BATCH)
	{
		int count = g->param - first < WORLD_BATCH ? g->param - first : WORLD_BATCH;
		MakeBatch(g, count, first, workers);
		double start = GameClockSeconds();
		for (int s = 0; s < steps; ++s)
		{
			StepWorlds(g);
		}
		seconds += GameClockSeconds() - start;
		EndBatch(g);
	}
	return seconds;
}

static GameStats WorldsStats(Game* g)
{
	GameStats s = g->batchStats;
	s.fastest = 0.0f;
	s.fastestBody = -1;
	s.x = s.y = NAN;
	return s;
}

// ---------------------------------------------------------------------------------------------
// Generic parts and the tables

static void StepPlain(Game* g)
{
	StepWorld(g);
}

static GameStats StatsPlain(Game* g)
{
	return ReadStats(g);
}

static void DestroyPlain(Game* g)
{
	FreeGame(g);
}

static void DestroyWorlds(Game* g)
{
	g->worldCount = 0; // every batch is gone already
	FreeGame(g);
}

static const GameScene scenes[] = {
	{"empty", 0, 2000, 0.0, false, CreateEmpty, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"falling_1", 1, 240, 0.0, false, CreateFalling, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"falling_10", 10, 240, 0.0, false, CreateFalling, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"falling_100", 100, 240, 0.0, false, CreateFalling, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"falling_1000", 1000, 240, 0.0, false, CreateFalling, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"falling_1000_no_rolling_resistance", 1000, 240, 0.0, false, CreateFallingNoRolling, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"level_asleep_500", 500, 240, 0.0, false, CreateLevelAsleep, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"pinball", 0, 1200, 0.0, false, CreatePinball, StepPinball, NULL, StatsPlain, DestroyPlain},
	{"slingshot", 0, 600, 0.0, false, CreateSlingshot, StepSlingshot, NULL, StatsPlain, DestroyPlain},
	{"platformer", 0, 1200, 0.1, false, CreatePlatformer, StepPlatformer, NULL, StatsPlain, DestroyPlain},
	{"ragdolls", 12, 480, 0.0, false, CreateRagdolls, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"car", 0, 900, 3.0, false, CreateCar, StepPlain, NULL, StatsPlain, DestroyPlain},
	{"worlds_1000", 1000, 60, 0.0, false, CreateWorlds1, StepWorlds, RunWorlds, WorldsStats, DestroyWorlds},
	{"worlds_1000_2workers", 1000, 60, 0.0, true, CreateWorlds2, StepWorlds, RunWorlds, WorldsStats, DestroyWorlds},
};

static const GameScene sweepScene = {"sweep", 1, 120, 0.0, false, CreateFalling, StepPlain, NULL, StatsPlain, DestroyPlain};

// ---------------------------------------------------------------------------------------------
// Memory: the allocator hook counts live bytes. Each block carries its size in a 64-byte header,
// so the count does not depend on the size the free hook is told; both engines take the same pair
// of hooks (v3.2's signatures: void* (size_t size, int alignment), void (void* memory, size_t size)).

static atomic_llong liveBytes;
static atomic_llong peakBytes; ///< the most liveBytes has been since the last reset

static void* CountingAlloc(size_t size, int alignment)
{
	(void)alignment; // at most 64, which the header keeps
	unsigned char* block = aligned_alloc(64, (size + 64 + 63) & ~(size_t)63);
	if (block == NULL)
	{
		return NULL;
	}
	*(size_t*)block = size;
	long long live = atomic_fetch_add(&liveBytes, (long long)size) + (long long)size;
	long long peak = atomic_load(&peakBytes);
	while (live > peak && atomic_compare_exchange_weak(&peakBytes, &peak, live) == false)
	{
		// another thread raised the peak meanwhile: peak holds its value, compare again
	}
	return block + 64;
}

static void CountingFree(void* memory)
{
	if (memory == NULL)
	{
		return;
	}
	unsigned char* block = (unsigned char*)memory - 64;
	atomic_fetch_sub(&liveBytes, (long long)*(size_t*)block);
	free(block);
}

static void* EngineAlloc(size_t size, int alignment)
{
	return CountingAlloc(size, alignment);
}

static void EngineFree(void* memory, size_t size)
{
	(void)size; // the block's header holds it too
	CountingFree(memory);
}

static void InstallAllocator(void)
{
	P(SetAllocator)(EngineAlloc, EngineFree);
}

static int64_t LiveBytes(void)
{
	return (int64_t)atomic_load(&liveBytes);
}

// Peak memory of two of Box2D v3's benchmark scenes, set up here as v3's benchmark describes
// them, while each is built and stepped 60 frames with sleep off: the allocator's high-water mark
// above what was live before, so the figure is the engine's own (a benchmark program that also
// holds a scene description would add that to its resident set).

/// A 100 × 100 grid of circles (radius 0.4, 1 m apart) joined to the neighbour above and to the
/// left by revolute joints, hung from seven static circles in the middle of the top row.
static void BuildJointGrid(WorldId world)
{
	const int n = 100;
	BodyId* bodies = malloc((size_t)(n * n) * sizeof(BodyId));
	P(ShapeDef) sd = GameShapeDef(1.0f, 0.6f);
	sd.filter.categoryBits = 2;
	sd.filter.maskBits = ~(uint64_t)2;
	P(Circle) circle = {V(0.0f, 0.0f), 0.4f};
	for (int column = 0; column < n; ++column)
	{
		for (int row = 0; row < n; ++row)
		{
			bool anchor = row == 0 && column >= n / 2 - 3 && column <= n / 2 + 3;
			P(BodyDef) bd = GameBodyDef(anchor ? K(staticBody) : K(dynamicBody), V((float)column, -(float)row), 0.0f);
			BodyId body = P(CreateBody)(world, &bd);
			P(CreateCircleShape)(body, &sd, &circle);
			P(RevoluteJointDef) jd = P(DefaultRevoluteJointDef)();
			if (row > 0)
			{
				jd.base.bodyIdA = bodies[column * n + row - 1];
				jd.base.bodyIdB = body;
				jd.base.localFrameA.p = V(0.0f, -0.5f);
				jd.base.localFrameB.p = V(0.0f, 0.5f);
				P(CreateRevoluteJoint)(world, &jd);
			}
			if (column > 0)
			{
				jd.base.bodyIdA = bodies[(column - 1) * n + row];
				jd.base.bodyIdB = body;
				jd.base.localFrameA.p = V(0.5f, 0.0f);
				jd.base.localFrameB.p = V(-0.5f, 0.0f);
				P(CreateRevoluteJoint)(world, &jd);
			}
			bodies[column * n + row] = body;
		}
	}
	free(bodies);
}

/// 20 rows of 20 pyramids, each of 55 unit boxes (a base of 10), on 20 floors one above another.
static void BuildManyPyramids(WorldId world)
{
	const int base = 10, rows = 20, columns = 20;
	const float floorGap = (float)(base + 1), floorWidth = (float)(columns * (base + 1));
	P(BodyDef) gd = GameBodyDef(K(staticBody), V(0.0f, 0.0f), 0.0f);
	BodyId ground = P(CreateBody)(world, &gd);
	P(ShapeDef) sd = GameShapeDef(1.0f, 0.6f);
	P(Polygon) box = P(MakeBox)(0.5f, 0.5f);
	for (int r = 0; r < rows; ++r)
	{
		float y = floorGap * (float)r;
		P(Segment) floor = {V(-0.5f * floorWidth, y), V(0.5f * floorWidth, y)};
		P(CreateSegmentShape)(ground, &sd, &floor);
		for (int c = 0; c < columns; ++c)
		{
			float left = -0.5f * floorWidth + (float)(c * (base + 1)) + 1.0f;
			for (int level = 0; level < base; ++level)
			{
				for (int i = 0; i < base - level; ++i)
				{
					Vec2 p = V(left + 0.5f * (float)level + (float)i, y + 0.5f + (float)level);
					P(BodyDef) bd = GameBodyDef(K(dynamicBody), p, 0.0f);
					BodyId body = P(CreateBody)(world, &bd);
					P(CreatePolygonShape)(body, &sd, &box);
				}
			}
		}
	}
}

static int64_t ScenePeakBytes(void (*build)(WorldId world))
{
	P(WorldDef) def = GameWorldDef();
	def.enableSleep = false;
	int64_t before = LiveBytes();
	atomic_store(&peakBytes, (long long)before);
	WorldId world = P(CreateWorld)(&def);
	build(world);
	for (int i = 0; i < 60; ++i)
	{
		P(World_Step)(world, GAME_DT, GAME_SUBSTEPS);
	}
	P(DestroyWorld)(world);
	return (int64_t)atomic_load(&peakBytes) - before;
}

static void MeasureScenePeaks(GameMemory* m)
{
	m->jointGridPeak = ScenePeakBytes(BuildJointGrid);
	m->manyPyramidsPeak = ScenePeakBytes(BuildManyPyramids);
}

// Bodies, shapes and joints: made far apart (no contacts), counted before and after each kind.
// Contacts: a row of circles overlapping their neighbours against the same row spread apart,
// both stepped once (the step's scratch for the contacts counts with them).
static GameMemory MeasureMemory(int count)
{
	GameMemory m = {0};
	m.count = count;
	P(WorldDef) def = GameWorldDef();
	def.gravity = V(0.0f, 0.0f);
	WorldId world = P(CreateWorld)(&def);
	int64_t b0 = LiveBytes();
	BodyId* bodies = malloc((size_t)count * sizeof(BodyId));
	for (int i = 0; i < count; ++i)
	{
		P(BodyDef) bd = GameBodyDef(K(dynamicBody), V(3.0f * (float)(i % 100), 3.0f * (float)(i / 100)), 0.0f);
		bodies[i] = P(CreateBody)(world, &bd);
	}
	int64_t b1 = LiveBytes();
	for (int i = 0; i < count; ++i)
	{
		P(ShapeDef) sd = GameShapeDef(1.0f, 0.6f);
		P(Circle) circle = {V(0.0f, 0.0f), 0.5f};
		P(CreateCircleShape)(bodies[i], &sd, &circle);
	}
	int64_t b2 = LiveBytes();
	for (int i = 1; i < count; ++i)
	{
		P(RevoluteJointDef) jd = P(DefaultRevoluteJointDef)();
		jd.base.bodyIdA = bodies[i - 1];
		jd.base.bodyIdB = bodies[i];
		jd.base.localFrameA.q = Rot(0.0f);
		jd.base.localFrameB.q = Rot(0.0f);
		P(CreateRevoluteJoint)(world, &jd);
	}
	int64_t b3 = LiveBytes();
	P(DestroyWorld)(world);
	m.body = (double)(b1 - b0) / count;
	m.shape = (double)(b2 - b1) / count;
	m.joint = (double)(b3 - b2) / (count - 1);

	int64_t grown[2];
	int touching = 0;
	for (int pass = 0; pass < 2; ++pass)
	{
		world = P(CreateWorld)(&def);
		float spacing = pass == 0 ? 3.0f : 0.9f;
		for (int i = 0; i < count; ++i)
		{
			P(BodyDef) bd = GameBodyDef(K(dynamicBody), V(spacing * (float)(i % 100), 5.0f * (float)(i / 100)), 0.0f);
			bodies[i] = P(CreateBody)(world, &bd);
			P(ShapeDef) sd = GameShapeDef(1.0f, 0.6f);
			P(Circle) circle = {V(0.0f, 0.0f), 0.5f};
			P(CreateCircleShape)(bodies[i], &sd, &circle);
		}
		P(World_Step)(world, GAME_DT, GAME_SUBSTEPS);
		grown[pass] = LiveBytes();
		if (pass == 1)
		{
			for (int i = 0; i < count; ++i)
			{
				touching += TouchingContacts(bodies[i]);
			}
			touching /= 2;
		}
		P(DestroyWorld)(world);
	}
	free(bodies);
	m.contacts = touching;
	m.contact = touching > 0 ? (double)(grown[1] - grown[0]) / touching : NAN;
	MeasureScenePeaks(&m);
	return m;
}

const GameEngine GAME_ENGINE = {
	GAME_ENGINE_NAME, scenes, (int)(sizeof(scenes) / sizeof(scenes[0])), &sweepScene, Settle, InstallAllocator, LiveBytes,
	MeasureMemory,
};
