// Fuzz harness for the whole API as a program uses it: bytes become a sequence of calls on up to
// three worlds that holds every kind of object and every kind of callback. Bodies of each type
// (created, retyped, disabled and enabled, driven by target transforms, forces and impulses);
// every shape kind, sensors among them, and concave bodies from tbDecomposePolygon; chains, open
// and looped, with one material or one per segment; every joint kind with its setters (a motor
// joint whose frame is moved between steps is the mouse drag); explosions; queries of every kind
// whose callbacks change the world as far as a query allows and try what it must refuse; pre-solve,
// pre-continuous, custom filter, friction and restitution callbacks that edit manifolds with
// hostile values and try calls the locked world must refuse; worker counts 1 to 4 through a task
// system in this file that runs each task's ranges one after another (deterministic, so a finding
// replays) with varied split, order and worker indices, and changes of the count between steps.
// Numbers are mostly ordinary (a scene whose bodies touch, sleep and pull on their joints), with
// a hostile value (fuzz_input.h) now and then.
//
// Checks: no abort and no sanitizer report; every call a locked world or a running query must
// refuse returns its refusal, reports one error at least and changes nothing; ids of destroyed
// objects (bodies, shapes, joints, chains, worlds) stay invalid, also after a slot was reused
// tens of thousands of times; ids of live objects stay valid; after every step every live body's
// position and velocity are finite and every enabled body is within TB_MAX_POSITION, and the
// broad phase's bounds are finite; events, debug drawing and callback arguments carry finite
// numbers and ids of the right kind; once every world is destroyed, tbGetByteCount() is back where
// it started.
#include "fuzz_input.h"

#include "tumble/tumble.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WORLD_SLOTS 3
#define MAX_LIVE 40
#define MAX_DEAD 64
#define MAX_STEPS 120
#define MAX_CHAIN_POINTS 24
#define MAX_PENDING 4

// FUZZ_TRACE=1 prints each operation and each refusal's message (replay: ./fuzz_api CRASH_FILE).
static bool s_trace = false;
#define TRACE(...) (s_trace ? (void)fprintf(stderr, __VA_ARGS__) : (void)0)

// ---------------------------------------------------------------------------------------------
// Decoding. Mostly ordinary values in a range; one byte value in 32 asks for a hostile float
// instead. Each value is read in its own statement, so the bytes decode in the same order with
// any compiler (C leaves the order of a call's arguments unspecified).

static float Num(FuzzInput* in, float lo, float hi)
{
	uint8_t b = FuzzByte(in);
	if (b >= 248)
	{
		return FuzzFloat(in);
	}
	return lo + (hi - lo) * (float)b / 247.0f;
}

static tbVec2 Vec(FuzzInput* in, float lo, float hi)
{
	float x = Num(in, lo, hi);
	float y = Num(in, lo, hi);
	return tbMakeVec2(x, y);
}

static tbRot Rot(FuzzInput* in)
{
	return tbMakeRot(Num(in, -3.5f, 3.5f));
}

static bool Flag(FuzzInput* in)
{
	return (FuzzByte(in) & 1u) != 0;
}

static tbTransform Frame(FuzzInput* in)
{
	tbTransform t;
	t.p = Vec(in, -2.0f, 2.0f);
	t.q = Rot(in);
	return t;
}

// ---------------------------------------------------------------------------------------------
// The objects the harness knows about. Body, shape, joint and chain ids share one layout, so one
// record type keeps them; each live object remembers what it dies with.

typedef struct Handle
{
	int32_t index1;
	uint16_t world0;
	uint16_t generation;
} Handle;

_Static_assert(sizeof(Handle) == sizeof(tbBodyId) && sizeof(Handle) == sizeof(tbShapeId) &&
				   sizeof(Handle) == sizeof(tbJointId) && sizeof(Handle) == sizeof(tbChainId),
			   "ids share a layout");

static tbBodyId AsBody(Handle h)
{
	tbBodyId id = {h.index1, h.world0, h.generation};
	return id;
}
static tbShapeId AsShape(Handle h)
{
	tbShapeId id = {h.index1, h.world0, h.generation};
	return id;
}
static tbJointId AsJoint(Handle h)
{
	tbJointId id = {h.index1, h.world0, h.generation};
	return id;
}
static tbChainId AsChain(Handle h)
{
	tbChainId id = {h.index1, h.world0, h.generation};
	return id;
}
#define HANDLE(id) ((Handle){(id).index1, (id).world0, (id).generation})

static bool SameHandle(Handle a, Handle b)
{
	return a.index1 == b.index1 && a.world0 == b.world0 && a.generation == b.generation;
}

typedef enum Kind
{
	kindBody,
	kindShape,
	kindJoint,
	kindChain,
	kindCount
} Kind;

static const char* const s_kindNames[kindCount] = {"body", "shape", "joint", "chain"};

typedef struct Record
{
	Handle id;
	int slot;	  ///< world slot
	Handle owner; ///< shape, chain: its body; joint: body A
	Handle other; ///< joint: body B; shape: its chain (index1 0 when none)
	int type;	  ///< joint kind
} Record;

typedef struct List
{
	Record live[MAX_LIVE];
	int liveCount;
	Handle dead[MAX_DEAD];
	int deadCount;
} List;

/// The harness's own task system (Box2D v3.2's interface: a task is one callback): tasks run on the
/// calling thread, inside enqueueTask or later in finishTask, and in one mode every pending task
/// runs at the first finish, the last enqueued first. The library must give 1 worker's results
/// whatever the order.
typedef struct PendingTask
{
	tbTaskCallback* task;
	void* context;
	uint8_t state; ///< 0 free, 1 enqueued, 2 run (until finishTask frees it)
} PendingTask;

typedef struct Tasks
{
	int workerCount; ///< what tbWorld_GetWorkerCount says
	uint8_t mode;	 ///< bit 0: defer to finishTask; 1: run every pending task at the first finish, last first
	int tasksRun;
	PendingTask pending[MAX_PENDING];
} Tasks;

/// What a world's callbacks do, chosen by the input when they are registered.
typedef struct Script
{
	uint8_t mode;
	float value;
	uint32_t calls;
} Script;

typedef struct WorldSlot
{
	tbWorldId id;
	Tasks tasks;
	Script preSolve;
	Script filter;
	bool hasTasks;
	bool retiredBodySlot; ///< a churn retired a body slot (see DestroyWorld)
} WorldSlot;

typedef struct Harness
{
	WorldSlot worlds[WORLD_SLOTS];
	tbWorldId deadWorlds[8];
	int deadWorldCount;
	List lists[kindCount];
	tbContactId contacts[16];
	int contactCount;
	int steps;
	int queryDepth;
	FuzzInput* in;
} Harness;

static Harness* s_h = NULL; // the friction and restitution callbacks take no context
static Script s_mix;

static void OnError(const char* message, void* context)
{
	(void)context;
	TRACE("  refused: %s\n", message);
}

static void AddLive(List* list, Record r)
{
	if (list->liveCount < MAX_LIVE)
	{
		list->live[list->liveCount++] = r;
	}
}

static void AddDead(List* list, Handle id)
{
	if (list->deadCount < MAX_DEAD)
	{
		list->dead[list->deadCount++] = id;
	}
	else
	{
		list->dead[id.generation % MAX_DEAD] = id; // keep a spread of old and new ones
	}
}

static bool IsValid(Kind kind, Handle id)
{
	switch (kind)
	{
		case kindBody:
			return tbBody_IsValid(AsBody(id));
		case kindShape:
			return tbShape_IsValid(AsShape(id));
		case kindJoint:
			return tbJoint_IsValid(AsJoint(id));
		default:
			return tbChain_IsValid(AsChain(id));
	}
}

/// Move the live records of `kind` for which `dies` holds to the dead list.
static void Bury(Harness* h, Kind kind, bool (*dies)(const Record*, const void*), const void* cause)
{
	List* list = h->lists + kind;
	for (int i = list->liveCount - 1; i >= 0; --i)
	{
		if (dies(list->live + i, cause))
		{
			AddDead(list, list->live[i].id);
			list->live[i] = list->live[--list->liveCount];
		}
	}
}

static bool InSlot(const Record* r, const void* cause)
{
	return r->slot == *(const int*)cause;
}

/// Shapes and chains: on this body.
static bool OnBody(const Record* r, const void* cause)
{
	return SameHandle(r->owner, *(const Handle*)cause);
}

/// Joints: body A or body B is this one.
static bool Joins(const Record* r, const void* cause)
{
	Handle body = *(const Handle*)cause;
	return SameHandle(r->owner, body) || SameHandle(r->other, body);
}

static bool IsThis(const Record* r, const void* cause)
{
	return SameHandle(r->id, *(const Handle*)cause);
}

/// Segments of a destroyed chain: shapes whose `other` is the chain.
static bool InChain(const Record* r, const void* cause)
{
	return r->other.index1 != 0 && SameHandle(r->other, *(const Handle*)cause);
}

/// A body's death takes its shapes, joints and chains (and the chains' segments) along.
static void BuryBody(Harness* h, Handle body)
{
	Bury(h, kindBody, IsThis, &body);
	Bury(h, kindShape, OnBody, &body);
	Bury(h, kindJoint, Joins, &body);
	Bury(h, kindChain, OnBody, &body);
}

static void BuryWorld(Harness* h, int slot)
{
	for (int k = 0; k < kindCount; ++k)
	{
		Bury(h, (Kind)k, InSlot, &slot);
	}
	h->deadWorlds[h->deadWorldCount++ % 8] = h->worlds[slot].id;
	h->worlds[slot].id = TB_NULL_WORLD_ID;
	h->contactCount = 0;
}

/// The slot of the world an id belongs to (an id picked from another world's objects makes its
/// object there).
static int SlotOf(const Harness* h, uint16_t world0)
{
	for (int s = 0; s < WORLD_SLOTS; ++s)
	{
		if (TB_IS_NON_NULL(h->worlds[s].id) && h->worlds[s].id.index1 - 1 == world0)
		{
			return s;
		}
	}
	FUZZ_CHECK(false, "an object was made in world %d, which the harness does not hold", world0);
	return 0;
}

/// A live record of `kind` in `slot`, or NULL.
static Record* PickLive(Harness* h, Kind kind, int slot, FuzzInput* in)
{
	List* list = h->lists + kind;
	int start = FuzzInt(in, 256);
	for (int k = 0; k < list->liveCount; ++k)
	{
		Record* r = list->live + (start + k) % list->liveCount;
		if (r->slot == slot)
		{
			return r;
		}
	}
	return NULL;
}

/// An id to call with: mostly a live one of the slot's world, sometimes a dead one, a live one of
/// another world, or made up.
static Handle PickId(Harness* h, Kind kind, int slot, FuzzInput* in)
{
	List* list = h->lists + kind;
	int choice = FuzzInt(in, 16);
	if (choice == 0 && list->deadCount > 0)
	{
		return list->dead[FuzzInt(in, list->deadCount)];
	}
	if (choice == 1)
	{
		int index = FuzzInt(in, 10) - 1;
		int world = FuzzInt(in, 4);
		int generation = FuzzInt(in, 4);
		Handle made = {index, (uint16_t)world, (uint16_t)generation};
		return made;
	}
	if (choice == 2 && list->liveCount > 0)
	{
		return list->live[FuzzInt(in, list->liveCount)].id;
	}
	Record* r = PickLive(h, kind, slot, in);
	return r != NULL ? r->id : (Handle){0, 0, 0};
}

// ---------------------------------------------------------------------------------------------
// The task system.

static void RunPending(Tasks* t, PendingTask* p)
{
	p->state = 2;
	p->task(p->context);
	t->tasksRun += 1;
}

static void* EnqueueTask(tbTaskCallback* task, void* taskContext, void* userContext)
{
	Tasks* t = userContext;
	FUZZ_CHECK(task != NULL, "enqueueTask without a task");
	if ((t->mode & 1u) != 0)
	{
		for (int i = 0; i < MAX_PENDING; ++i)
		{
			if (t->pending[i].state == 0)
			{
				t->pending[i] = (PendingTask){task, taskContext, 1};
				return t->pending + i;
			}
		}
	}
	task(taskContext);
	t->tasksRun += 1;
	return NULL;
}

static void FinishTask(void* userTask, void* userContext)
{
	Tasks* t = userContext;
	PendingTask* p = userTask;
	FUZZ_CHECK(p >= t->pending && p < t->pending + MAX_PENDING && p->state != 0,
			   "finishTask with a handle not given out");
	if ((t->mode & 2u) != 0)
	{
		for (int i = MAX_PENDING - 1; i >= 0; --i)
		{
			if (t->pending[i].state == 1)
			{
				RunPending(t, t->pending + i);
			}
		}
	}
	else if (p->state == 1)
	{
		RunPending(t, p);
	}
	p->state = 0;
}

// ---------------------------------------------------------------------------------------------
// Calls that must be refused. `inStep`: the world is stepping (a pre-solve, pre-continuous or
// custom filter callback): every change is refused. Otherwise a query callback runs: changes to
// what the broad phase holds are refused.

#define EXPECT_REFUSED(call, refused, what)                                                                          \
	do                                                                                                                \
	{                                                                                                                 \
		int errorsBefore = tbGetErrorCount();                                                                         \
		call;                                                                                                         \
		FUZZ_CHECK((refused) && tbGetErrorCount() > errorsBefore, "%s was not refused %s", what,                     \
				   inStep ? "during the step" : "inside a query callback");                                         \
	} while (0)

static void TryForbidden(int which, tbWorldId world, tbShapeId shape, bool inStep)
{
	tbBodyId body = tbShape_GetBody(shape);
	if (tbBody_IsValid(body) == false)
	{
		return;
	}
	TRACE("  forbidden call %d %s\n", which, inStep ? "in the step" : "in a query");
	switch (which % (inStep ? 20 : 16))
	{
		case 0:
		{
			tbBodyDef def = tbDefaultBodyDef();
			tbBodyId made = TB_NULL_BODY_ID;
			EXPECT_REFUSED(made = tbCreateBody(world, &def), TB_IS_NULL(made), "tbCreateBody");
			break;
		}
		case 1:
			EXPECT_REFUSED(tbDestroyBody(body), tbBody_IsValid(body), "tbDestroyBody");
			break;
		case 2:
		{
			bool moved = true;
			EXPECT_REFUSED(moved = tbBody_SetTransform(body, tbPos_zero, tbRot_identity), moved == false,
						   "tbBody_SetTransform");
			break;
		}
		case 3:
		{
			tbBodyType type = tbBody_GetType(body);
			bool changed = true;
			EXPECT_REFUSED(changed = tbBody_SetType(body, (tbBodyType)((type + 1) % tb_bodyTypeCount)),
						   changed == false && tbBody_GetType(body) == type, "tbBody_SetType");
			break;
		}
		case 4:
		{
			bool changed = true;
			EXPECT_REFUSED(changed = tbShape_SetFilter(shape, tbDefaultFilter()), changed == false,
						   "tbShape_SetFilter");
			break;
		}
		case 5:
		{
			tbShapeDef def = tbDefaultShapeDef();
			tbCircle circle = {{0.0f, 0.0f}, 0.5f};
			tbShapeId made = TB_NULL_SHAPE_ID;
			EXPECT_REFUSED(made = tbCreateCircleShape(body, &def, &circle), TB_IS_NULL(made), "tbCreateCircleShape");
			break;
		}
		case 6:
			EXPECT_REFUSED(tbDestroyShape(shape, true), tbShape_IsValid(shape), "tbDestroyShape");
			break;
		case 7:
		{
			bool changed = true;
			EXPECT_REFUSED(changed = tbWorld_SetGravity(world, tbMakeVec2(0.0f, -5.0f)), changed == false,
						   "tbWorld_SetGravity");
			break;
		}
		case 8:
		{
			bool stepped = true;
			EXPECT_REFUSED(stepped = tbWorld_Step(world, 1.0f / 60.0f, 1), stepped == false, "tbWorld_Step");
			break;
		}
		case 9:
			EXPECT_REFUSED(tbDestroyWorld(world), tbWorld_IsValid(world), "tbDestroyWorld");
			break;
		case 10:
			if (tbBody_IsEnabled(body))
			{
				EXPECT_REFUSED(tbBody_Disable(body), tbBody_IsEnabled(body), "tbBody_Disable");
			}
			break;
		case 11:
		{
			static const tbVec2 points[4] = {{3.0f, 0.0f}, {1.0f, 0.0f}, {-1.0f, 0.0f}, {-3.0f, 0.0f}};
			tbChainDef def = tbDefaultChainDef();
			def.points = points;
			def.count = 4;
			tbChainId made = TB_NULL_CHAIN_ID;
			EXPECT_REFUSED(made = tbCreateChain(body, &def), TB_IS_NULL(made), "tbCreateChain");
			break;
		}
		case 12:
		{
			tbWeldJointDef def = tbDefaultWeldJointDef();
			def.base.bodyIdA = body;
			def.base.bodyIdB = body;
			tbJointId made = TB_NULL_JOINT_ID;
			EXPECT_REFUSED(made = tbCreateWeldJoint(world, &def), TB_IS_NULL(made), "tbCreateWeldJoint");
			break;
		}
		case 13:
		{
			tbCircle circle = {{0.0f, 0.0f}, 0.25f};
			bool changed = true;
			EXPECT_REFUSED(changed = tbShape_SetCircle(shape, &circle), changed == false, "tbShape_SetCircle");
			break;
		}
		case 14:
			EXPECT_REFUSED(tbWorld_RebuildStaticTree(world), true, "tbWorld_RebuildStaticTree");
			break;
		case 15:
		{
			int before = tbWorld_GetWorkerCount(world);
			EXPECT_REFUSED(tbWorld_SetWorkerCount(world, before % 4 + 1), tbWorld_GetWorkerCount(world) == before,
						   "tbWorld_SetWorkerCount");
			break;
		}
		// Allowed in a query callback, refused during the step:
		case 16:
		{
			bool changed = true;
			EXPECT_REFUSED(changed = tbBody_SetLinearVelocity(body, tbMakeVec2(1.0f, 0.0f)), changed == false,
						   "tbBody_SetLinearVelocity");
			break;
		}
		case 17:
		{
			bool changed = true;
			EXPECT_REFUSED(changed = tbShape_SetFriction(shape, 0.3f), changed == false, "tbShape_SetFriction");
			break;
		}
		case 18:
		{
			tbExplosionDef def = tbDefaultExplosionDef();
			def.radius = 1.0f;
			def.impulsePerLength = 1.0f;
			EXPECT_REFUSED(tbWorld_Explode(world, &def), true, "tbWorld_Explode");
			break;
		}
		default:
		{
			tbAABB bounds = {{1.0f, 1.0f}, {1.0f, 1.0f}};
			EXPECT_REFUSED(bounds = tbWorld_GetBounds(world),
						   bounds.lowerBound.x == 0.0f && bounds.upperBound.x == 0.0f,
						   "tbWorld_GetBounds");
			break;
		}
	}
}

/// Reads any callback may make (serial tasks: nothing runs alongside).
static void ReadShape(tbShapeId shape)
{
	FUZZ_CHECK(tbShape_IsValid(shape), "a callback got a stale shape id");
	tbBodyId body = tbShape_GetBody(shape);
	FUZZ_CHECK(tbBody_IsValid(body), "a callback's shape has no valid body");
	tbPos p = tbBody_GetPosition(body);
	tbVec2 v = tbBody_GetLinearVelocity(body);
	FUZZ_CHECK(FuzzIsFinite2((float)p.x, (float)p.y) && FuzzIsFinite2(v.x, v.y),
			   "a callback's body at (%g, %g) v (%g, %g)", (double)p.x, (double)p.y, (double)v.x, (double)v.y);
	(void)tbShape_GetAABB(shape);
	(void)tbShape_GetFilter(shape);
	(void)tbShape_GetType(shape);
}

// ---------------------------------------------------------------------------------------------
// Step callbacks.

static bool CustomFilter(tbShapeId shapeIdA, tbShapeId shapeIdB, void* context)
{
	WorldSlot* w = context;
	Script* s = &w->filter;
	s->calls += 1;
	FUZZ_CHECK(tbShape_IsValid(shapeIdA) && tbShape_IsValid(shapeIdB), "custom filter got a stale shape id");
	if ((s->mode & 0x10u) != 0 && s->calls % 5u == 0u)
	{
		TryForbidden((int)(s->calls / 5u + s->mode), w->id, shapeIdA, true);
	}
	if ((s->mode & 0x20u) != 0)
	{
		ReadShape(shapeIdB);
	}
	switch (s->mode & 3u)
	{
		case 0:
			return true;
		case 1:
			return false;
		case 2:
			return (s->calls & 1u) != 0;
		default:
			return (shapeIdA.index1 + shapeIdB.index1) % 3 != 0;
	}
}

static void PreSolve(tbShapeId shapeIdA, tbShapeId shapeIdB, tbManifold* manifold, void* context)
{
	WorldSlot* w = context;
	Script* s = &w->preSolve;
	s->calls += 1;
	FUZZ_CHECK(tbShape_IsValid(shapeIdA) && tbShape_IsValid(shapeIdB), "pre-solve got a stale shape id");
	FUZZ_CHECK(tbShape_IsSensor(shapeIdA) == false && tbShape_IsSensor(shapeIdB) == false,
			   "pre-solve called for a sensor's pair");
	FUZZ_CHECK(tbBody_GetType(tbShape_GetBody(shapeIdA)) == tb_dynamicBody ||
				   tbBody_GetType(tbShape_GetBody(shapeIdB)) == tb_dynamicBody,
			   "pre-solve called for a pair without a dynamic body");
	FUZZ_CHECK(manifold->pointCount >= 0 && manifold->pointCount <= 2 &&
				   FuzzIsFinite2(manifold->normal.x, manifold->normal.y),
			   "pre-solve got %d points, normal (%g, %g)", manifold->pointCount, (double)manifold->normal.x,
			   (double)manifold->normal.y);
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		const tbManifoldPoint* mp = manifold->points + i;
		FUZZ_CHECK(FuzzIsFinite2(mp->point.x, mp->point.y) && isfinite(mp->separation),
				   "pre-solve point %d at (%g, %g) separation %g", i, (double)mp->point.x, (double)mp->point.y,
				   (double)mp->separation);
	}
	uint32_t action = (s->mode + s->calls) % 12u;
	TRACE("  pre-solve shapes %d, %d: %d points, action %u, value %g\n", shapeIdA.index1, shapeIdB.index1,
		  manifold->pointCount, action, (double)s->value);
	switch (action)
	{
		case 0:
			manifold->pointCount = 0; // a one-way platform's answer
			break;
		case 1:
			if (manifold->pointCount > 0)
			{
				manifold->pointCount -= 1;
			}
			break;
		case 2:
			if (manifold->pointCount > 0)
			{
				manifold->points[0].separation = s->value; // huge, negative, NaN: refused or clamped
			}
			break;
		case 3:
			manifold->normal = tbMakeVec2(s->value, -s->value);
			break;
		case 4:
			manifold->pointCount = 2 + (int)(s->calls % 3u); // adding points is refused (clamped)
			break;
		case 5:
			for (int i = 0; i < manifold->pointCount; ++i)
			{
				manifold->points[i].normalImpulse = s->value;
				manifold->points[i].anchorA = tbMakeVec2(s->value, 0.0f);
			}
			break;
		case 6:
			TryForbidden((int)(s->calls + s->mode), w->id, shapeIdA, true);
			break;
		case 7:
			ReadShape(shapeIdA);
			ReadShape(shapeIdB);
			break;
		case 8:
			manifold->rollingImpulse = s->value;
			if (manifold->pointCount > 0)
			{
				manifold->points[0].separation = -0.5f; // deep, but what two shapes can overlap
			}
			break;
		default:
			break;
	}
}

static bool PreContinuous(tbShapeId shapeIdA, tbShapeId shapeIdB, tbPos point, tbVec2 normal, void* context)
{
	WorldSlot* w = context;
	Script* s = &w->preSolve;
	s->calls += 1;
	FUZZ_CHECK(tbShape_IsValid(shapeIdA) && tbShape_IsValid(shapeIdB), "pre-continuous got a stale shape id");
	FUZZ_CHECK(FuzzIsFinite2((float)point.x, (float)point.y) && FuzzIsFinite2(normal.x, normal.y),
			   "pre-continuous point (%g, %g) normal (%g, %g)", (double)point.x, (double)point.y, (double)normal.x,
			   (double)normal.y);
	if ((s->mode & 0x40u) != 0 && s->calls % 3u == 0u)
	{
		TryForbidden((int)(s->calls + 7u), w->id, shapeIdB, true);
	}
	return (s->mode & 0x80u) != 0 ? (s->calls & 1u) != 0 : true;
}

static float MixFriction(float frictionA, uint64_t userMaterialIdA, float frictionB, uint64_t userMaterialIdB)
{
	(void)userMaterialIdA;
	(void)userMaterialIdB;
	s_mix.calls += 1;
	switch (s_mix.mode & 3u)
	{
		case 0:
			return frictionA < frictionB ? frictionA : frictionB;
		case 1:
			return s_mix.value; // NaN or negative: reported, the default used
		case 2:
			return INFINITY; // never slides
		default:
			return (float)(s_mix.calls % 4u) * 0.5f;
	}
}

static float MixRestitution(float restitutionA, uint64_t userMaterialIdA, float restitutionB, uint64_t userMaterialIdB)
{
	(void)userMaterialIdA;
	(void)userMaterialIdB;
	switch ((s_mix.mode >> 2) & 3u)
	{
		case 0:
			return restitutionA + restitutionB;
		case 1:
			return s_mix.value;
		case 2:
			return 1.5f;
		default:
			return 0.0f;
	}
}

// ---------------------------------------------------------------------------------------------
// Query callbacks: change what a query allows, try what it refuses, query again inside.

typedef struct QueryContext
{
	Harness* h;
	int slot;
	uint8_t mode;
	int results;
} QueryContext;

static void NestedQuery(QueryContext* q);

static void OnQueryResult(QueryContext* q, tbShapeId shape)
{
	q->results += 1;
	ReadShape(shape);
	tbBodyId body = tbShape_GetBody(shape);
	tbWorldId world = q->h->worlds[q->slot].id;
	switch ((q->mode + q->results) % 10)
	{
		case 0:
			(void)tbBody_SetLinearVelocity(body, tbMakeVec2(0.5f, 2.0f));
			break;
		case 1:
			(void)tbBody_ApplyLinearImpulseToCenter(body, tbMakeVec2(0.0f, 1.0f), true);
			break;
		case 2:
			tbBody_SetAwake(body, (q->results & 1) != 0);
			break;
		case 3:
			(void)tbShape_SetFriction(shape, 0.1f * (float)(q->results % 8));
			(void)tbShape_SetRestitution(shape, 0.25f);
			break;
		case 4:
		{
			tbExplosionDef def = tbDefaultExplosionDef();
			def.position = tbBody_GetPosition(body);
			def.radius = 0.5f;
			def.falloff = 1.0f;
			def.impulsePerLength = 2.0f;
			tbWorld_Explode(world, &def); // allowed inside a query (it is one itself)
			break;
		}
		case 5:
			NestedQuery(q);
			break;
		case 6:
			(void)tbShape_ApplyWind(shape, tbMakeVec2(5.0f, 0.0f), 1.0f, 0.5f, true);
			break;
		default:
			TryForbidden(q->mode + q->results, world, shape, false);
			break;
	}
}

static bool OverlapResult(tbShapeId shapeId, void* context)
{
	QueryContext* q = context;
	OnQueryResult(q, shapeId);
	return (q->mode & 0x40u) == 0 || q->results < 3;
}

static float CastResult(tbShapeId shapeId, tbPos point, tbVec2 normal, float fraction, void* context)
{
	QueryContext* q = context;
	FUZZ_CHECK(FuzzIsFinite2((float)point.x, (float)point.y) && FuzzIsFinite2(normal.x, normal.y) &&
				   fraction >= 0.0f && fraction <= 1.0f,
			   "cast result: point (%g, %g) normal (%g, %g) fraction %g", (double)point.x, (double)point.y,
			   (double)normal.x, (double)normal.y, (double)fraction);
	OnQueryResult(q, shapeId);
	switch ((q->mode >> 4) & 3u)
	{
		case 0:
			return fraction;
		case 1:
			return 1.0f;
		case 2:
			return q->results % 2 == 0 ? -1.0f : fraction;
		default:
			return 0.0f;
	}
}

static bool PlaneResult(tbShapeId shapeId, const tbPlaneResult* plane, void* context)
{
	QueryContext* q = context;
	FUZZ_CHECK(FuzzIsFinite2(plane->plane.normal.x, plane->plane.normal.y) && isfinite(plane->plane.offset),
			   "mover plane normal (%g, %g) offset %g", (double)plane->plane.normal.x, (double)plane->plane.normal.y,
			   (double)plane->plane.offset);
	OnQueryResult(q, shapeId);
	return true;
}

static void NestedQuery(QueryContext* q)
{
	if (q->h->queryDepth >= 3)
	{
		return;
	}
	q->h->queryDepth += 1;
	QueryContext inner = {q->h, q->slot, (uint8_t)(q->mode * 7u + 3u), 0};
	tbAABB box = {{-5.0f, -5.0f}, {5.0f, 5.0f}};
	tbWorld_OverlapAABB(q->h->worlds[q->slot].id, tbPos_zero, box, tbDefaultQueryFilter(), OverlapResult, &inner);
	q->h->queryDepth -= 1;
}

// ---------------------------------------------------------------------------------------------
// Worlds.

static void CreateWorld(Harness* h, int slot, FuzzInput* in)
{
	WorldSlot* w = h->worlds + slot;
	tbWorldDef def = tbDefaultWorldDef();
	if (Flag(in))
	{
		def.gravity = Vec(in, -20.0f, 20.0f);
	}
	def.broadPhase = (tbBroadPhaseMethod)FuzzInt(in, tb_broadPhaseMethodCount);
	def.narrowPhase = (tbNarrowPhaseMethod)FuzzInt(in, 3);
	def.continuous = (tbContinuousMethod)FuzzInt(in, tb_continuousMethodCount);
	def.solver = (tbSolverMethod)FuzzInt(in, tb_solverMethodCount);
	uint8_t flags = FuzzByte(in);
	def.enableWideSolver = (flags & 1u) == 0;
	def.enableJointTrees = (flags & 2u) == 0;
	def.enableCentralFriction = (flags & 4u) == 0;
	def.enableManifoldRecycling = (flags & 8u) == 0;
	def.enableImpactPropagation = (flags & 16u) != 0;
	def.enableSleep = (flags & 32u) == 0;
	def.enableWarmStarting = (flags & 64u) == 0;
	def.contactHertzFollowsSubStep = (flags & 128u) != 0;
	if (FuzzInt(in, 4) == 0)
	{
		def.capacity.dynamicBodyCount = FuzzInt(in, 16);
		def.capacity.dynamicShapeCount = FuzzInt(in, 16);
		def.capacity.contactCount = FuzzInt(in, 32);
		def.capacity.staticShapeCount = FuzzInt(in, 8);
		def.capacity.staticBodyCount = FuzzInt(in, 8);
	}
	int workers = FuzzInt(in, 5);
	memset(&w->tasks, 0, sizeof(w->tasks));
	w->hasTasks = workers > 0;
	if (w->hasTasks)
	{
		def.workerCount = workers;
		def.enqueueTask = EnqueueTask;
		def.finishTask = FinishTask;
		def.userTaskContext = &w->tasks;
		w->tasks.mode = FuzzByte(in);
	}
	if (FuzzInt(in, 4) == 0)
	{
		s_mix.mode = FuzzByte(in);
		s_mix.value = FuzzFloat(in);
		def.frictionCallback = MixFriction;
		def.restitutionCallback = MixRestitution;
	}
	w->id = tbCreateWorld(&def);
	TRACE("create world in slot %d: broad %d narrow %d continuous %d solver %d flags %02x workers %d mode %02x -> %d\n",
		  slot, (int)def.broadPhase, (int)def.narrowPhase, (int)def.continuous, (int)def.solver, flags, workers,
		  w->tasks.mode, w->id.index1);
	if (TB_IS_NULL(w->id))
	{
		return; // a hostile gravity or capacity: refused, the slot stays empty
	}
	w->tasks.workerCount = tbWorld_GetWorkerCount(w->id);
	memset(&w->preSolve, 0, sizeof(w->preSolve));
	memset(&w->filter, 0, sizeof(w->filter));
}

static bool InWorld0(const Handle* id, uint16_t world0)
{
	return id->world0 == world0;
}

static void DestroyWorld(Harness* h, int slot)
{
	TRACE("destroy world in slot %d\n", slot);
	tbWorldId world = h->worlds[slot].id;
	tbDestroyWorld(world);
	FUZZ_CHECK(tbWorld_IsValid(world) == false, "a destroyed world's id is valid");
	BuryWorld(h, slot);
	if (h->worlds[slot].retiredBodySlot)
	{
		// The case docs/limits.md leaves open: a new world in this world's slot starts its body
		// generations where this world's first bodies were, so their ids may match again. They
		// are not checked from here on.
		List* bodies = h->lists + kindBody;
		for (int i = bodies->deadCount - 1; i >= 0; --i)
		{
			if (InWorld0(bodies->dead + i, (uint16_t)(world.index1 - 1)))
			{
				bodies->dead[i] = bodies->dead[--bodies->deadCount];
			}
		}
		h->worlds[slot].retiredBodySlot = false;
	}
}

static void WorldSettings(Harness* h, int slot, FuzzInput* in)
{
	WorldSlot* w = h->worlds + slot;
	tbWorldId world = w->id;
	int kind = FuzzInt(in, 20);
	TRACE("world setting %d\n", kind);
	switch (kind)
	{
		case 0:
			tbWorld_SetGravity(world, Vec(in, -30.0f, 30.0f));
			break;
		case 1:
			tbWorld_EnableSleeping(world, Flag(in));
			break;
		case 2:
		{
			float hertz = Num(in, 0.0f, 120.0f);
			float damping = Num(in, 0.0f, 20.0f);
			float push = Num(in, 0.0f, 10.0f);
			tbWorld_SetContactTuning(world, hertz, damping, push);
			break;
		}
		case 3:
			tbWorld_SetRestitutionThreshold(world, Num(in, 0.0f, 5.0f));
			tbWorld_SetHitEventThreshold(world, Num(in, 0.0f, 5.0f));
			break;
		case 4:
			tbWorld_EnableWarmStarting(world, Flag(in));
			break;
		case 5:
			tbWorld_EnableContinuous(world, Flag(in));
			break;
		case 6:
			tbWorld_SetMaximumLinearSpeed(world, Num(in, 0.0f, 1000.0f));
			break;
		case 7:
			tbWorld_SetBroadPhaseMethod(world, (tbBroadPhaseMethod)FuzzInt(in, tb_broadPhaseMethodCount + 1));
			break;
		case 8:
			tbWorld_SetNarrowPhaseMethod(world, (tbNarrowPhaseMethod)FuzzInt(in, 4));
			tbWorld_SetContinuousMethod(world, (tbContinuousMethod)FuzzInt(in, tb_continuousMethodCount + 1));
			break;
		case 9:
		{
			tbSolverMethod method = (tbSolverMethod)FuzzInt(in, tb_solverMethodCount + 1);
			int velocity = FuzzInt(in, 12) - 1;
			int position = FuzzInt(in, 6) - 1;
			tbWorld_SetSolverMethod(world, method, velocity, position);
			break;
		}
		case 10:
			tbWorld_EnableManifoldRecycling(world, Flag(in));
			tbWorld_EnableCentralFriction(world, Flag(in));
			break;
		case 11:
			tbWorld_SetContactRecycleDistance(world, Num(in, 0.0f, 0.2f));
			tbWorld_EnableSpeculative(world, Flag(in));
			break;
		case 12:
		case 13:
		{
			// 0 and 9 are clamped to 1..TB_MAX_WORKERS; the task system follows what the world says.
			static const int counts[] = {1, 2, 3, 4, 0, 9};
			int count = counts[FuzzInt(in, 6)];
			tbWorld_SetWorkerCount(world, count);
			w->tasks.workerCount = tbWorld_GetWorkerCount(world);
			w->tasks.mode = FuzzByte(in);
			TRACE("  workers %d -> %d, mode %02x\n", count, w->tasks.workerCount, w->tasks.mode);
			break;
		}
		case 14:
			w->filter.mode = FuzzByte(in);
			tbWorld_SetCustomFilterCallback(world, (w->filter.mode & 0xC0u) == 0xC0u ? NULL : CustomFilter, w);
			break;
		case 15:
		case 16:
		{
			w->preSolve.mode = FuzzByte(in);
			float value = FuzzFloat(in);
			w->preSolve.value = value;
			bool off = (w->preSolve.mode & 0x0Fu) == 0x0Fu;
			tbWorld_SetPreSolveCallback(world, off ? NULL : PreSolve, Flag(in) ? PreContinuous : NULL, w);
			break;
		}
		case 17:
			tbWorld_SetFrictionCallback(world, Flag(in) ? MixFriction : NULL);
			tbWorld_SetRestitutionCallback(world, Flag(in) ? MixRestitution : NULL);
			s_mix.mode = FuzzByte(in);
			s_mix.value = FuzzFloat(in);
			break;
		case 18:
			tbWorld_RebuildStaticTree(world);
			(void)tbWorld_GetBounds(world);
			(void)tbWorld_GetMaxCapacity(world);
			break;
		default:
		{
			tbExplosionDef def = tbDefaultExplosionDef();
			def.position = tbToPos(Vec(in, -10.0f, 10.0f));
			def.radius = Num(in, 0.0f, 5.0f);
			def.falloff = Num(in, 0.0f, 5.0f);
			def.impulsePerLength = Num(in, -20.0f, 50.0f);
			def.maskBits = FuzzInt(in, 4) == 0 ? (uint64_t)FuzzByte(in) : def.maskBits;
			TRACE("  explode at (%g, %g) radius %g falloff %g impulse %g\n", (double)def.position.x,
				  (double)def.position.y, (double)def.radius, (double)def.falloff, (double)def.impulsePerLength);
			tbWorld_Explode(world, &def);
			break;
		}
	}
}

// ---------------------------------------------------------------------------------------------
// Bodies.

static void CreateBody(Harness* h, int slot, FuzzInput* in)
{
	if (h->lists[kindBody].liveCount >= MAX_LIVE)
	{
		return;
	}
	tbBodyDef def = tbDefaultBodyDef();
	def.type = (tbBodyType)FuzzInt(in, 3);
	def.position = tbToPos(Vec(in, -10.0f, 10.0f));
	def.rotation = Rot(in);
	uint8_t flags = FuzzByte(in);
	if (flags & 1u)
	{
		def.linearVelocity = Vec(in, -20.0f, 20.0f);
		def.angularVelocity = Num(in, -10.0f, 10.0f);
	}
	if (flags & 2u)
	{
		def.linearDamping = Num(in, 0.0f, 2.0f);
		def.angularDamping = Num(in, 0.0f, 2.0f);
		def.gravityScale = Num(in, -2.0f, 3.0f);
	}
	if (flags & 4u)
	{
		def.sleepThreshold = Num(in, 0.0f, 1.0f);
		def.safetyFactor = Num(in, 0.0f, 1.0f);
	}
	def.isBullet = (flags & 8u) != 0;
	def.fixedRotation = (flags & 16u) != 0;
	def.motionLocks.linearX = (flags & 0x60u) == 0x20u;
	def.motionLocks.linearY = (flags & 0x60u) == 0x40u;
	def.isAwake = (flags & 0x80u) == 0;
	def.enableSleep = FuzzInt(in, 8) != 0;
	def.enableContactRecycling = FuzzInt(in, 8) != 0;
	def.name = "fuzz body";
	tbBodyId body = tbCreateBody(h->worlds[slot].id, &def);
	TRACE("create body type %d at (%g, %g) flags %02x -> %d\n", (int)def.type, (double)def.position.x,
		  (double)def.position.y, flags, body.index1);
	if (TB_IS_NON_NULL(body))
	{
		AddLive(h->lists + kindBody, (Record){HANDLE(body), slot, {0, 0, 0}, {0, 0, 0}, 0});
	}
}

static void DestroyBody(Harness* h, int slot, FuzzInput* in)
{
	Record* r = PickLive(h, kindBody, slot, in);
	if (r == NULL)
	{
		return;
	}
	Handle body = r->id;
	TRACE("destroy body %d\n", body.index1);
	tbDestroyBody(AsBody(body));
	BuryBody(h, body);
}

static void ModifyBody(Harness* h, int slot, FuzzInput* in)
{
	tbBodyId body = AsBody(PickId(h, kindBody, slot, in));
	int kind = FuzzInt(in, 28);
	TRACE("modify body %d: %d\n", body.index1, kind);
	switch (kind)
	{
		case 0:
			tbBody_SetLinearVelocity(body, Vec(in, -30.0f, 30.0f));
			break;
		case 1:
			tbBody_SetAngularVelocity(body, Num(in, -20.0f, 20.0f));
			break;
		case 2:
		{
			tbVec2 p = Vec(in, -10.0f, 10.0f);
			tbBody_SetTransform(body, tbToPos(p), Rot(in));
			break;
		}
		case 3:
		case 4:
		{
			tbTransform t = Frame(in);
			tbWorldTransform target = {tbToPos(tbMulAdd(tbToVec2(tbBody_GetPosition(body)), 2.0f, t.p)), t.q};
			float dt = FuzzInt(in, 8) == 0 ? Num(in, -1.0f, 1.0f) : 1.0f / 60.0f;
			tbBody_SetTargetTransform(body, target, dt, Flag(in));
			break;
		}
		case 5:
		{
			tbVec2 force = Vec(in, -100.0f, 100.0f);
			tbVec2 point = Vec(in, -10.0f, 10.0f);
			tbBody_ApplyForce(body, force, tbToPos(point), Flag(in));
			break;
		}
		case 6:
			tbBody_ApplyForceToCenter(body, Vec(in, -100.0f, 100.0f), Flag(in));
			tbBody_ApplyTorque(body, Num(in, -50.0f, 50.0f), Flag(in));
			break;
		case 7:
		{
			tbVec2 impulse = Vec(in, -10.0f, 10.0f);
			tbVec2 point = Vec(in, -10.0f, 10.0f);
			tbBody_ApplyLinearImpulse(body, impulse, tbToPos(point), Flag(in));
			break;
		}
		case 8:
			tbBody_ApplyLinearImpulseToCenter(body, Vec(in, -10.0f, 10.0f), Flag(in));
			tbBody_ApplyAngularImpulse(body, Num(in, -5.0f, 5.0f), Flag(in));
			break;
		case 9:
		case 10:
			tbBody_SetType(body, (tbBodyType)FuzzInt(in, 4));
			break;
		case 11:
			if (tbBody_IsEnabled(body))
			{
				tbBody_Disable(body);
			}
			else
			{
				tbBody_Enable(body);
			}
			break;
		case 12:
			tbBody_SetAwake(body, Flag(in));
			break;
		case 13:
		{
			tbMassData mass;
			mass.mass = Num(in, 0.0f, 10.0f);
			mass.center = Vec(in, -1.0f, 1.0f);
			mass.rotationalInertia = Num(in, 0.0f, 10.0f);
			tbBody_SetMassData(body, mass);
			break;
		}
		case 14:
			tbBody_ApplyMassFromShapes(body);
			break;
		case 15:
			tbBody_SetLinearDamping(body, Num(in, 0.0f, 5.0f));
			tbBody_SetAngularDamping(body, Num(in, 0.0f, 5.0f));
			break;
		case 16:
			tbBody_SetGravityScale(body, Num(in, -3.0f, 3.0f));
			break;
		case 17:
			tbBody_SetSleepThreshold(body, Num(in, 0.0f, 2.0f));
			tbBody_EnableSleep(body, Flag(in));
			break;
		case 18:
			tbBody_SetSafetyFactor(body, Num(in, 0.0f, 1.0f));
			tbBody_SetBullet(body, Flag(in));
			break;
		case 19:
			tbBody_SetFixedRotation(body, Flag(in));
			break;
		case 20:
		{
			uint8_t bits = FuzzByte(in);
			tbMotionLocks locks = {(bits & 1u) != 0, (bits & 2u) != 0, (bits & 4u) != 0};
			tbBody_SetMotionLocks(body, locks);
			break;
		}
		case 21:
			tbBody_EnableContactEvents(body, Flag(in));
			tbBody_EnableHitEvents(body, Flag(in));
			break;
		case 22:
			tbBody_WakeTouching(body);
			tbBody_ClearForces(body);
			break;
		case 23:
			tbBody_EnableContactRecycling(body, Flag(in));
			break;
		default:
		{
			// Reads: every getter on a live, stale or made-up id.
			tbPos p = tbBody_GetPosition(body);
			tbVec2 v = tbBody_GetLinearVelocity(body);
			FUZZ_CHECK(FuzzIsFinite2((float)p.x, (float)p.y) && FuzzIsFinite2(v.x, v.y), "body %d at (%g, %g)",
					   body.index1, (double)p.x, (double)p.y);
			(void)tbBody_GetAngle(body);
			(void)tbBody_GetMassData(body);
			(void)tbBody_GetWorldCenter(body);
			(void)tbBody_GetLocalPoint(body, tbPos_zero);
			(void)tbBody_GetWorldPointVelocity(body, tbPos_zero);
			(void)tbBody_ComputeAABB(body);
			(void)tbBody_GetMotionLocks(body);
			tbShapeId shapes[8];
			int count = tbBody_GetShapes(body, shapes, 8);
			FUZZ_CHECK(count >= 0 && count <= 8, "tbBody_GetShapes wrote %d", count);
			for (int i = 0; i < count; ++i)
			{
				FUZZ_CHECK(TB_ID_EQUALS(tbShape_GetBody(shapes[i]), body), "shape %d of body %d names another body",
						   i, body.index1);
			}
			tbJointId joints[8];
			count = tbBody_GetJoints(body, joints, 8);
			FUZZ_CHECK(count >= 0 && count <= 8 && count <= tbBody_GetJointCount(body), "tbBody_GetJoints wrote %d",
					   count);
			tbContactData data[8];
			int capacity = tbBody_GetContactCapacity(body);
			count = tbBody_GetContactData(body, data, 8);
			FUZZ_CHECK(count >= 0 && count <= 8 && count <= capacity, "tbBody_GetContactData wrote %d (capacity %d)",
					   count, capacity);
			for (int i = 0; i < count; ++i)
			{
				FUZZ_CHECK(data[i].manifold.pointCount >= 0 && data[i].manifold.pointCount <= 2,
						   "contact data with %d points", data[i].manifold.pointCount);
				if (h->contactCount < 16)
				{
					h->contacts[h->contactCount++] = data[i].contactId;
				}
			}
			break;
		}
	}
}

/// Tens of thousands of creations and destructions in one slot: the generation wraps unless the
/// slot is retired, and an old id must never match a new body.
static void Churn(Harness* h, int slot, FuzzInput* in)
{
	int cycles = 1 << (FuzzInt(in, 17));
	tbWorldId world = h->worlds[slot].id;
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	Handle first = {0, 0, 0};
	TRACE("churn %d bodies\n", cycles);
	for (int i = 0; i < cycles; ++i)
	{
		tbBodyId body = tbCreateBody(world, &def);
		FUZZ_CHECK(TB_IS_NON_NULL(body), "churn: body %d refused", i);
		if (i == 0)
		{
			first = HANDLE(body);
		}
		tbDestroyBody(body);
		FUZZ_CHECK(tbBody_IsValid(body) == false, "churn: body %d valid after its destruction", i);
		FUZZ_CHECK(i == 0 || tbBody_IsValid(AsBody(first)) == false, "churn: the first id matches again after %d", i);
		if (i == cycles - 1)
		{
			AddDead(h->lists + kindBody, HANDLE(body));
		}
	}
	AddDead(h->lists + kindBody, first);
	if (cycles >= 65535)
	{
		h->worlds[slot].retiredBodySlot = true;
	}
}

// ---------------------------------------------------------------------------------------------
// Shapes.

static tbSurfaceMaterial Material(FuzzInput* in)
{
	tbSurfaceMaterial m = tbDefaultSurfaceMaterial();
	uint8_t which = FuzzByte(in);
	if (which & 1u)
	{
		m.friction = Num(in, 0.0f, 2.0f);
	}
	if (which & 2u)
	{
		m.restitution = Num(in, 0.0f, 1.2f);
	}
	if (which & 4u)
	{
		m.rollingResistance = Num(in, 0.0f, 1.0f);
	}
	if (which & 8u)
	{
		m.tangentSpeed = Num(in, -5.0f, 5.0f);
	}
	m.userMaterialId = which >> 4;
	return m;
}

static tbFilter Filter(FuzzInput* in)
{
	tbFilter f = tbDefaultFilter();
	uint8_t which = FuzzByte(in);
	if (which & 1u)
	{
		f.categoryBits = (uint64_t)1u << FuzzInt(in, 64);
	}
	if (which & 2u)
	{
		f.maskBits = ~((uint64_t)FuzzByte(in));
	}
	if (which & 4u)
	{
		f.groupIndex = FuzzInt(in, 5) - 2;
	}
	return f;
}

static tbGeometry Geometry(FuzzInput* in)
{
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	int kind = FuzzInt(in, 7);
	switch (kind)
	{
		case 0:
			g.type = tb_circleShape;
			g.circle.center = Vec(in, -1.0f, 1.0f);
			g.circle.radius = Num(in, 0.02f, 1.5f);
			break;
		case 1:
			g.type = tb_capsuleShape;
			g.capsule.center1 = Vec(in, -1.0f, 1.0f);
			g.capsule.center2 = Vec(in, -1.0f, 1.0f);
			g.capsule.radius = Num(in, 0.02f, 1.0f);
			break;
		case 2:
			g.type = tb_segmentShape;
			g.segment.point1 = Vec(in, -5.0f, 5.0f);
			g.segment.point2 = Vec(in, -5.0f, 5.0f);
			break;
		case 3:
		{
			float hx = Num(in, 0.02f, 3.0f);
			float hy = Num(in, 0.02f, 3.0f);
			tbVec2 center = Vec(in, -1.0f, 1.0f);
			tbRot q = Rot(in);
			g.type = tb_polygonShape;
			g.polygon = tbMakeOffsetBox(hx, hy, center, q);
			break;
		}
		case 4:
		{
			float hx = Num(in, 0.02f, 2.0f);
			float hy = Num(in, 0.02f, 2.0f);
			float radius = Num(in, 0.0f, 0.5f);
			g.type = tb_polygonShape;
			g.polygon = tbMakeRoundedBox(hx, hy, radius);
			break;
		}
		case 5:
		{
			tbVec2 points[TB_MAX_POLYGON_VERTICES];
			int count = 3 + FuzzInt(in, TB_MAX_POLYGON_VERTICES - 2);
			for (int i = 0; i < count; ++i)
			{
				points[i] = Vec(in, -1.5f, 1.5f);
			}
			tbHull hull = tbComputeHull(points, count);
			g.type = tb_polygonShape;
			g.polygon = tbMakePolygon(&hull, FuzzInt(in, 4) == 0 ? Num(in, 0.0f, 0.3f) : 0.0f);
			break;
		}
		default:
			g.type = tb_chainSegmentShape;
			g.chainSegment.ghost1 = Vec(in, -6.0f, 6.0f);
			g.chainSegment.segment.point1 = Vec(in, -4.0f, 4.0f);
			g.chainSegment.segment.point2 = Vec(in, -4.0f, 4.0f);
			g.chainSegment.ghost2 = Vec(in, -6.0f, 6.0f);
			g.chainSegment.chainId = -1;
			break;
	}
	return g;
}

static void RememberShape(Harness* h, tbShapeId shape)
{
	if (TB_IS_NON_NULL(shape))
	{
		Handle body = HANDLE(tbShape_GetBody(shape));
		AddLive(h->lists + kindShape, (Record){HANDLE(shape), SlotOf(h, shape.world0), body, {0, 0, 0}, 0});
	}
}

static tbShapeDef ShapeDef(FuzzInput* in)
{
	tbShapeDef def = tbDefaultShapeDef();
	uint8_t flags = FuzzByte(in);
	def.isSensor = (flags & 3u) == 3u;
	def.enableSensorEvents = (flags & 4u) == 0;
	def.enableContactEvents = (flags & 8u) == 0;
	def.enableHitEvents = (flags & 16u) != 0;
	def.enableCustomFiltering = (flags & 32u) != 0;
	def.enablePreSolveEvents = (flags & 64u) != 0;
	def.updateBodyMass = FuzzInt(in, 8) != 0;
	if (flags & 128u)
	{
		def.density = Num(in, 0.0f, 10.0f);
		def.material = Material(in);
		def.filter = Filter(in);
	}
	return def;
}

static void CreateShape(Harness* h, int slot, FuzzInput* in)
{
	if (h->lists[kindShape].liveCount >= MAX_LIVE)
	{
		return;
	}
	tbShapeDef def = ShapeDef(in);
	tbGeometry g = Geometry(in);
	tbBodyId body = AsBody(PickId(h, kindBody, slot, in));
	tbShapeId shape;
	switch (g.type)
	{
		case tb_circleShape:
			shape = tbCreateCircleShape(body, &def, &g.circle);
			break;
		case tb_capsuleShape:
			shape = tbCreateCapsuleShape(body, &def, &g.capsule);
			break;
		case tb_segmentShape:
			shape = tbCreateSegmentShape(body, &def, &g.segment);
			break;
		case tb_chainSegmentShape:
			shape = tbCreateChainSegmentShape(body, &def, &g.chainSegment);
			break;
		default:
			shape = FuzzInt(in, 2) ? tbCreatePolygonShape(body, &def, &g.polygon) : tbCreateShape(body, &def, &g);
			break;
	}
	TRACE("create shape type %d sensor %d on body %d -> %d\n", (int)g.type, (int)def.isSensor, body.index1,
		  shape.index1);
	RememberShape(h, shape);
}

/// A concave body: a star or zigzag outline cut by tbDecomposePolygon, each piece a shape.
static void CreateConcave(Harness* h, int slot, FuzzInput* in)
{
	tbVec2 points[16];
	int count = 3 + FuzzInt(in, 14);
	float inner = Num(in, 0.1f, 1.0f);
	float outer = Num(in, 0.2f, 3.0f);
	for (int i = 0; i < count; ++i)
	{
		float angle = 6.2831853f * (float)i / (float)count;
		float r = (i & 1) ? inner : outer;
		points[i] = tbMakeVec2(r * cosf(angle), r * sinf(angle));
	}
	tbPolygon pieces[16];
	int n = tbDecomposePolygon(points, count, pieces, 16);
	TRACE("concave outline of %d points -> %d pieces\n", count, n);
	tbBodyId body = AsBody(PickId(h, kindBody, slot, in));
	tbShapeDef def = ShapeDef(in);
	for (int i = 0; i < n && h->lists[kindShape].liveCount < MAX_LIVE; ++i)
	{
		FUZZ_CHECK(pieces[i].count >= 3 && pieces[i].count <= TB_MAX_POLYGON_VERTICES, "piece %d has %d vertices", i,
				   pieces[i].count);
		RememberShape(h, tbCreatePolygonShape(body, &def, pieces + i));
	}
}

static void DestroyShape(Harness* h, int slot, FuzzInput* in)
{
	Record* r = PickLive(h, kindShape, slot, in);
	if (r == NULL)
	{
		return;
	}
	Handle shape = r->id;
	bool chainSegment = r->other.index1 != 0;
	TRACE("destroy shape %d%s\n", shape.index1, chainSegment ? " (a chain's: refused)" : "");
	tbDestroyShape(AsShape(shape), Flag(in));
	if (chainSegment)
	{
		FUZZ_CHECK(tbShape_IsValid(AsShape(shape)), "a chain's segment was destroyed on its own");
	}
	else
	{
		Bury(h, kindShape, IsThis, &shape);
	}
}

static void ModifyShape(Harness* h, int slot, FuzzInput* in)
{
	tbShapeId shape = AsShape(PickId(h, kindShape, slot, in));
	int kind = FuzzInt(in, 20);
	TRACE("modify shape %d: %d\n", shape.index1, kind);
	switch (kind)
	{
		case 0:
			tbShape_SetDensity(shape, Num(in, 0.0f, 10.0f), Flag(in));
			break;
		case 1:
			tbShape_SetFriction(shape, Num(in, 0.0f, 2.0f));
			tbShape_SetRestitution(shape, Num(in, 0.0f, 1.0f));
			break;
		case 2:
		{
			tbSurfaceMaterial m = Material(in);
			tbShape_SetSurfaceMaterial(shape, &m);
			tbShape_SetUserMaterial(shape, FuzzByte(in));
			break;
		}
		case 3:
			tbShape_SetFilter(shape, Filter(in));
			break;
		case 4:
		case 5:
		{
			tbGeometry g = Geometry(in);
			switch (g.type)
			{
				case tb_circleShape:
					tbShape_SetCircle(shape, &g.circle);
					break;
				case tb_capsuleShape:
					tbShape_SetCapsule(shape, &g.capsule);
					break;
				case tb_segmentShape:
					tbShape_SetSegment(shape, &g.segment);
					break;
				case tb_chainSegmentShape:
					tbShape_SetChainSegment(shape, &g.chainSegment);
					break;
				default:
					tbShape_SetPolygon(shape, &g.polygon);
					break;
			}
			break;
		}
		case 6:
			tbShape_EnableContactEvents(shape, Flag(in));
			tbShape_EnableHitEvents(shape, Flag(in));
			break;
		case 7:
			tbShape_EnableSensorEvents(shape, Flag(in));
			tbShape_EnablePreSolveEvents(shape, Flag(in));
			break;
		case 8:
		{
			tbVec2 wind = Vec(in, -30.0f, 30.0f);
			float drag = Num(in, 0.0f, 1.0f);
			float lift = Num(in, -1.0f, 1.0f);
			tbShape_ApplyWind(shape, wind, drag, lift, Flag(in));
			break;
		}
		case 9:
		{
			tbShapeId visitors[8];
			int capacity = tbShape_GetSensorCapacity(shape);
			int count = tbShape_GetSensorData(shape, visitors, 8);
			FUZZ_CHECK(count >= 0 && count <= 8 && count <= capacity, "tbShape_GetSensorData wrote %d (capacity %d)",
					   count, capacity);
			for (int i = 0; i < count; ++i)
			{
				// Another sensor may visit (Box2D v3.2: overlapping sensors see each other), not the sensor itself.
				FUZZ_CHECK(tbShape_IsValid(visitors[i]) && TB_ID_EQUALS(visitors[i], shape) == false,
						   "visitor %d of shape %d is stale or the shape itself", i, shape.index1);
			}
			break;
		}
		case 10:
		{
			tbContactData data[8];
			int capacity = tbShape_GetContactCapacity(shape);
			int count = tbShape_GetContactData(shape, data, 8);
			FUZZ_CHECK(count >= 0 && count <= 8 && count <= capacity, "tbShape_GetContactData wrote %d (capacity %d)",
					   count, capacity);
			for (int i = 0; i < count; ++i)
			{
				FUZZ_CHECK(TB_ID_EQUALS(data[i].shapeIdA, shape) || TB_ID_EQUALS(data[i].shapeIdB, shape),
						   "a shape's contact names neither side as the shape");
			}
			break;
		}
		case 11:
		{
			tbVec2 origin = Vec(in, -10.0f, 10.0f);
			tbWorldCastOutput out = tbShape_RayCast(shape, tbToPos(origin), Vec(in, -20.0f, 20.0f));
			FUZZ_CHECK(out.hit == false || (FuzzIsFinite2((float)out.point.x, (float)out.point.y) &&
											 FuzzIsFinite2(out.normal.x, out.normal.y) && isfinite(out.fraction)),
					   "tbShape_RayCast hit with non-finite numbers");
			(void)tbShape_TestPoint(shape, tbToPos(origin));
			tbPos closest = tbShape_GetClosestPoint(shape, tbToPos(origin));
			(void)closest;
			break;
		}
		default:
		{
			tbGeometry g = tbShape_GetGeometry(shape);
			(void)g;
			(void)tbShape_ComputeMassData(shape);
			(void)tbShape_GetAABB(shape);
			(void)tbShape_GetSurfaceMaterial(shape);
			(void)tbShape_GetParentChain(shape);
			(void)tbShape_GetChainSegment(shape);
			(void)tbShape_GetPolygon(shape);
			break;
		}
	}
}

// ---------------------------------------------------------------------------------------------
// Chains.

static int ChainPoints(FuzzInput* in, tbVec2* points)
{
	int count = 4 + FuzzInt(in, MAX_CHAIN_POINTS - 3);
	tbVec2 offset = Vec(in, -8.0f, 8.0f);
	int style = FuzzInt(in, 5);
	float scale = Num(in, 0.05f, 3.0f);
	tbVec2 walk = offset;
	for (int i = 0; i < count; ++i)
	{
		switch (style)
		{
			case 0: // ground, right to left (solid below), with bumps
				points[i] = tbMakeVec2(offset.x + scale * (float)(count - 1 - i), offset.y + Num(in, -0.5f, 0.5f));
				break;
			case 1: // a ring, counter-clockwise or not
			{
				float angle = 6.2831853f * (float)i / (float)count;
				float r = scale * (4.0f + Num(in, -1.0f, 1.0f));
				points[i] = tbMakeVec2(offset.x + r * cosf(angle), offset.y + r * sinf(angle));
				break;
			}
			case 2: // a random walk (may cross itself)
				walk = tbMulAdd(walk, scale, Vec(in, -1.0f, 1.0f));
				points[i] = walk;
				break;
			case 3: // near-duplicate neighbours
				points[i] = tbMakeVec2(offset.x - scale * (float)(i / 2) - 0.004f * (float)(i & 1), offset.y);
				break;
			default:
				points[i] = Vec(in, -10.0f, 10.0f);
				break;
		}
	}
	return count;
}

static void CreateChain(Harness* h, int slot, FuzzInput* in)
{
	if (h->lists[kindChain].liveCount >= MAX_LIVE)
	{
		return;
	}
	tbVec2 points[MAX_CHAIN_POINTS];
	tbSurfaceMaterial materials[MAX_CHAIN_POINTS];
	tbChainDef def = tbDefaultChainDef();
	def.count = ChainPoints(in, points);
	def.points = points;
	def.isLoop = Flag(in);
	int segments = def.isLoop ? def.count : def.count - 3;
	int materialChoice = FuzzInt(in, 4);
	def.materialCount = materialChoice == 0 ? segments : materialChoice == 3 ? FuzzInt(in, MAX_CHAIN_POINTS) : 1;
	for (int i = 0; i < def.materialCount; ++i)
	{
		materials[i] = Material(in);
	}
	def.materials = materials;
	if (Flag(in))
	{
		def.filter = Filter(in);
	}
	def.enableSensorEvents = Flag(in);
	tbBodyId body = AsBody(PickId(h, kindBody, slot, in));
	tbChainId chain = tbCreateChain(body, &def);
	TRACE("create chain of %d points loop %d materials %d on body %d -> %d\n", def.count, (int)def.isLoop,
		  def.materialCount, body.index1, chain.index1);
	if (TB_IS_NULL(chain))
	{
		return;
	}
	Handle owner = HANDLE(tbChain_GetBody(chain));
	slot = SlotOf(h, chain.world0);
	AddLive(h->lists + kindChain, (Record){HANDLE(chain), slot, owner, {0, 0, 0}, 0});
	tbShapeId segmentIds[MAX_CHAIN_POINTS];
	int count = tbChain_GetSegments(chain, segmentIds, MAX_CHAIN_POINTS);
	FUZZ_CHECK(count == segments && count == tbChain_GetSegmentCount(chain), "a chain of %d points%s has %d segments",
			   def.count, def.isLoop ? " (loop)" : "", count);
	for (int i = 0; i < count && h->lists[kindShape].liveCount < MAX_LIVE; ++i)
	{
		FUZZ_CHECK(TB_ID_EQUALS(tbShape_GetParentChain(segmentIds[i]), chain), "segment %d names another chain", i);
		AddLive(h->lists + kindShape, (Record){HANDLE(segmentIds[i]), slot, owner, HANDLE(chain), 0});
	}
}

static void ChainOp(Harness* h, int slot, FuzzInput* in)
{
	Record* r = PickLive(h, kindChain, slot, in);
	tbChainId chain = r != NULL && FuzzInt(in, 8) != 0 ? AsChain(r->id) : AsChain(PickId(h, kindChain, slot, in));
	int kind = FuzzInt(in, 4);
	TRACE("chain %d: %d\n", chain.index1, kind);
	if (kind == 0)
	{
		// Any id may name a chain the harness holds (a live one of another world, a made-up one
		// that matches): bury what it names, if anything.
		Handle id = HANDLE(chain);
		tbDestroyChain(chain);
		FUZZ_CHECK(tbChain_IsValid(chain) == false, "a destroyed chain's id is valid");
		Bury(h, kindShape, InChain, &id);
		Bury(h, kindChain, IsThis, &id);
	}
	else if (kind == 1)
	{
		tbSurfaceMaterial m = Material(in);
		int count = tbChain_GetSurfaceMaterialCount(chain);
		tbChain_SetSurfaceMaterial(chain, &m, FuzzInt(in, count + 2) - 1);
	}
	else
	{
		(void)tbChain_GetWorld(chain);
		(void)tbChain_GetSurfaceMaterial(chain, FuzzInt(in, 3));
		tbShapeId segments[4];
		int count = tbChain_GetSegments(chain, segments, 4);
		FUZZ_CHECK(count >= 0 && count <= 4, "tbChain_GetSegments wrote %d", count);
	}
}

// ---------------------------------------------------------------------------------------------
// Joints.

static void JointBase(Harness* h, int slot, FuzzInput* in, tbJointDef* base)
{
	base->bodyIdA = AsBody(PickId(h, kindBody, slot, in));
	base->bodyIdB = AsBody(PickId(h, kindBody, slot, in));
	base->localFrameA = Frame(in);
	base->localFrameB = Frame(in);
	uint8_t flags = FuzzByte(in);
	base->collideConnected = (flags & 1u) != 0;
	if (flags & 2u)
	{
		base->forceThreshold = Num(in, 0.0f, 100.0f);
		base->torqueThreshold = Num(in, 0.0f, 100.0f);
	}
	if (flags & 4u)
	{
		base->constraintHertz = Num(in, 0.0f, 240.0f);
		base->constraintDampingRatio = Num(in, 0.0f, 10.0f);
	}
	if (flags & 8u)
	{
		base->drawScale = Num(in, 0.0f, 2.0f);
	}
}

static void CreateJoint(Harness* h, int slot, FuzzInput* in)
{
	if (h->lists[kindJoint].liveCount >= MAX_LIVE)
	{
		return;
	}
	tbWorldId world = h->worlds[slot].id;
	tbJointType type = (tbJointType)FuzzInt(in, tb_jointTypeCount);
	tbJointId joint = TB_NULL_JOINT_ID;
	switch (type)
	{
		case tb_distanceJoint:
		{
			tbDistanceJointDef def = tbDefaultDistanceJointDef();
			JointBase(h, slot, in, &def.base);
			def.length = Num(in, 0.0f, 5.0f);
			uint8_t flags = FuzzByte(in);
			def.enableSpring = (flags & 1u) != 0;
			def.enableLimit = (flags & 2u) != 0;
			def.enableMotor = (flags & 4u) != 0;
			def.hertz = Num(in, 0.0f, 10.0f);
			def.dampingRatio = Num(in, 0.0f, 2.0f);
			def.minLength = Num(in, 0.0f, 2.0f);
			def.maxLength = Num(in, 0.0f, 6.0f);
			def.maxMotorForce = Num(in, 0.0f, 100.0f);
			def.motorSpeed = Num(in, -5.0f, 5.0f);
			if (flags & 8u)
			{
				def.lowerSpringForce = Num(in, -100.0f, 0.0f);
				def.upperSpringForce = Num(in, 0.0f, 100.0f);
			}
			joint = tbCreateDistanceJoint(world, &def);
			break;
		}
		case tb_filterJoint:
		{
			tbFilterJointDef def = tbDefaultFilterJointDef();
			JointBase(h, slot, in, &def.base);
			joint = tbCreateFilterJoint(world, &def);
			break;
		}
		case tb_motorJoint:
		{
			tbMotorJointDef def = tbDefaultMotorJointDef();
			JointBase(h, slot, in, &def.base);
			def.linearVelocity = Vec(in, -5.0f, 5.0f);
			def.maxVelocityForce = Num(in, 0.0f, 500.0f);
			def.angularVelocity = Num(in, -5.0f, 5.0f);
			def.maxVelocityTorque = Num(in, 0.0f, 500.0f);
			def.linearHertz = Num(in, 0.0f, 10.0f);
			def.linearDampingRatio = Num(in, 0.0f, 2.0f);
			def.maxSpringForce = Num(in, 0.0f, 1000.0f);
			def.angularHertz = Num(in, 0.0f, 10.0f);
			def.angularDampingRatio = Num(in, 0.0f, 2.0f);
			def.maxSpringTorque = Num(in, 0.0f, 1000.0f);
			joint = tbCreateMotorJoint(world, &def);
			break;
		}
		case tb_moverJoint:
		{
			tbMoverJointDef def = tbDefaultMoverJointDef();
			JointBase(h, slot, in, &def.base);
			def.linearVelocity = Vec(in, -5.0f, 5.0f);
			def.maxVelocityForce = Vec(in, 0.0f, 500.0f);
			joint = tbCreateMoverJoint(world, &def);
			break;
		}
		case tb_pogoJoint:
		{
			tbPogoJointDef def = tbDefaultPogoJointDef();
			JointBase(h, slot, in, &def.base);
			if (Flag(in))
			{
				def.normal = tbNormalize(Vec(in, -1.0f, 1.0f));
			}
			def.hertz = Num(in, 0.0f, 10.0f);
			def.dampingRatio = Num(in, 0.0f, 2.0f);
			def.restLength = Num(in, 0.0f, 2.0f);
			def.maxTensionForce = Num(in, 0.0f, 500.0f);
			def.maxCompressionForce = Num(in, 0.0f, 500.0f);
			def.impulse = Num(in, -1.0f, 1.0f);
			def.velocity = Num(in, -1.0f, 1.0f);
			joint = tbCreatePogoJoint(world, &def);
			break;
		}
		case tb_prismaticJoint:
		{
			tbPrismaticJointDef def = tbDefaultPrismaticJointDef();
			JointBase(h, slot, in, &def.base);
			uint8_t flags = FuzzByte(in);
			def.enableSpring = (flags & 1u) != 0;
			def.enableLimit = (flags & 2u) != 0;
			def.enableMotor = (flags & 4u) != 0;
			def.hertz = Num(in, 0.0f, 10.0f);
			def.dampingRatio = Num(in, 0.0f, 2.0f);
			def.targetTranslation = Num(in, -2.0f, 2.0f);
			def.lowerTranslation = Num(in, -3.0f, 0.5f);
			def.upperTranslation = Num(in, -0.5f, 3.0f);
			def.maxMotorForce = Num(in, 0.0f, 200.0f);
			def.motorSpeed = Num(in, -5.0f, 5.0f);
			joint = tbCreatePrismaticJoint(world, &def);
			break;
		}
		case tb_revoluteJoint:
		{
			tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
			JointBase(h, slot, in, &def.base);
			uint8_t flags = FuzzByte(in);
			def.enableSpring = (flags & 1u) != 0;
			def.enableLimit = (flags & 2u) != 0;
			def.enableMotor = (flags & 4u) != 0;
			def.targetAngle = Num(in, -3.0f, 3.0f);
			def.hertz = Num(in, 0.0f, 10.0f);
			def.dampingRatio = Num(in, 0.0f, 2.0f);
			def.lowerAngle = Num(in, -3.3f, 0.5f);
			def.upperAngle = Num(in, -0.5f, 3.3f);
			def.maxMotorTorque = Num(in, 0.0f, 200.0f);
			def.motorSpeed = Num(in, -5.0f, 5.0f);
			joint = tbCreateRevoluteJoint(world, &def);
			break;
		}
		case tb_weldJoint:
		{
			tbWeldJointDef def = tbDefaultWeldJointDef();
			JointBase(h, slot, in, &def.base);
			def.linearHertz = Num(in, 0.0f, 10.0f);
			def.angularHertz = Num(in, 0.0f, 10.0f);
			def.linearDampingRatio = Num(in, 0.0f, 2.0f);
			def.angularDampingRatio = Num(in, 0.0f, 2.0f);
			joint = tbCreateWeldJoint(world, &def);
			break;
		}
		default:
		{
			tbWheelJointDef def = tbDefaultWheelJointDef();
			JointBase(h, slot, in, &def.base);
			uint8_t flags = FuzzByte(in);
			def.enableSpring = (flags & 1u) == 0;
			def.enableLimit = (flags & 2u) != 0;
			def.enableMotor = (flags & 4u) != 0;
			def.hertz = Num(in, 0.0f, 10.0f);
			def.dampingRatio = Num(in, 0.0f, 2.0f);
			def.lowerTranslation = Num(in, -3.0f, 0.5f);
			def.upperTranslation = Num(in, -0.5f, 3.0f);
			def.maxMotorTorque = Num(in, 0.0f, 200.0f);
			def.motorSpeed = Num(in, -10.0f, 10.0f);
			joint = tbCreateWheelJoint(world, &def);
			break;
		}
	}
	TRACE("create joint type %d -> %d\n", (int)type, joint.index1);
	if (TB_IS_NON_NULL(joint))
	{
		FUZZ_CHECK(tbJoint_GetType(joint) == type, "joint of type %d reports type %d", (int)type,
				   (int)tbJoint_GetType(joint));
		Handle a = HANDLE(tbJoint_GetBodyA(joint));
		Handle b = HANDLE(tbJoint_GetBodyB(joint));
		AddLive(h->lists + kindJoint, (Record){HANDLE(joint), SlotOf(h, joint.world0), a, b, (int)type});
	}
}

static void ModifyJoint(Harness* h, int slot, FuzzInput* in)
{
	Record* r = PickLive(h, kindJoint, slot, in);
	tbJointId joint;
	int type;
	if (r != NULL && FuzzInt(in, 8) != 0)
	{
		joint = AsJoint(r->id);
		type = FuzzInt(in, 8) != 0 ? r->type : FuzzInt(in, tb_jointTypeCount); // another kind's setter: refused
	}
	else
	{
		joint = AsJoint(PickId(h, kindJoint, slot, in));
		type = FuzzInt(in, tb_jointTypeCount);
	}
	int kind = FuzzInt(in, 12);
	TRACE("modify joint %d (as type %d): %d\n", joint.index1, type, kind);
	// The setters every kind shares, then the kind's own.
	switch (kind)
	{
		case 0:
			tbJoint_SetLocalFrameA(joint, Frame(in)); // a motor joint dragged by its frame: the mouse joint
			break;
		case 1:
			tbJoint_SetLocalFrameB(joint, Frame(in));
			break;
		case 2:
			tbJoint_SetCollideConnected(joint, Flag(in));
			break;
		case 3:
		{
			float hertz = Num(in, 0.0f, 240.0f);
			tbJoint_SetConstraintTuning(joint, hertz, Num(in, 0.0f, 10.0f));
			break;
		}
		case 4:
			tbJoint_SetForceThreshold(joint, Num(in, 0.0f, 100.0f));
			tbJoint_SetTorqueThreshold(joint, Num(in, 0.0f, 100.0f));
			break;
		case 5:
		{
			tbJoint_WakeBodies(joint);
			tbVec2 force = tbJoint_GetConstraintForce(joint);
			float torque = tbJoint_GetConstraintTorque(joint);
			(void)force;
			(void)torque;
			(void)tbJoint_GetLinearSeparation(joint);
			(void)tbJoint_GetAngularSeparation(joint);
			(void)tbJoint_GetLocalFrameA(joint);
			break;
		}
		default:
		{
			float a = Num(in, -5.0f, 5.0f);
			float b = Num(in, -5.0f, 5.0f);
			bool on = Flag(in);
			int which = FuzzInt(in, 4);
			switch (type)
			{
				case tb_distanceJoint:
					if (which == 0)
					{
						tbDistanceJoint_SetLength(joint, a);
						tbDistanceJoint_EnableSpring(joint, on);
						tbDistanceJoint_SetSpringHertz(joint, b);
					}
					else if (which == 1)
					{
						tbDistanceJoint_EnableLimit(joint, on);
						tbDistanceJoint_SetLengthRange(joint, a, b);
						tbDistanceJoint_SetSpringForceRange(joint, -fabsf(a) * 10.0f, b * 10.0f);
					}
					else
					{
						tbDistanceJoint_EnableMotor(joint, on);
						tbDistanceJoint_SetMotorSpeed(joint, a);
						tbDistanceJoint_SetMaxMotorForce(joint, b * 20.0f);
						tbDistanceJoint_SetSpringDampingRatio(joint, b);
						(void)tbDistanceJoint_GetCurrentLength(joint);
						(void)tbDistanceJoint_GetMotorForce(joint);
					}
					break;
				case tb_motorJoint:
					if (which == 0)
					{
						tbMotorJoint_SetLinearVelocity(joint, tbMakeVec2(a, b));
						tbMotorJoint_SetAngularVelocity(joint, b);
					}
					else if (which == 1)
					{
						tbMotorJoint_SetMaxVelocityForce(joint, a * 100.0f);
						tbMotorJoint_SetMaxVelocityTorque(joint, b * 100.0f);
					}
					else
					{
						tbMotorJoint_SetLinearHertz(joint, a);
						tbMotorJoint_SetLinearDampingRatio(joint, b);
						tbMotorJoint_SetAngularHertz(joint, b);
						tbMotorJoint_SetAngularDampingRatio(joint, a);
						tbMotorJoint_SetMaxSpringForce(joint, a * 100.0f);
						tbMotorJoint_SetMaxSpringTorque(joint, b * 100.0f);
					}
					break;
				case tb_moverJoint:
					tbMoverJoint_SetLinearVelocity(joint, tbMakeVec2(a, b));
					tbMoverJoint_SetMaxVelocityForce(joint, tbMakeVec2(a * 50.0f, b * 50.0f));
					(void)tbMoverJoint_GetLinearVelocity(joint);
					break;
				case tb_pogoJoint:
					tbPogoJoint_SetRestLength(joint, a);
					tbPogoJoint_SetSpringHertz(joint, b);
					tbPogoJoint_SetSpringDampingRatio(joint, a);
					(void)tbPogoJoint_GetLength(joint);
					(void)tbPogoJoint_GetVelocity(joint);
					(void)tbPogoJoint_GetImpulse(joint);
					break;
				case tb_prismaticJoint:
					if (which == 0)
					{
						tbPrismaticJoint_EnableSpring(joint, on);
						tbPrismaticJoint_SetSpringHertz(joint, a);
						tbPrismaticJoint_SetSpringDampingRatio(joint, b);
						tbPrismaticJoint_SetTargetTranslation(joint, a);
					}
					else if (which == 1)
					{
						tbPrismaticJoint_EnableLimit(joint, on);
						tbPrismaticJoint_SetLimits(joint, a, b);
					}
					else
					{
						tbPrismaticJoint_EnableMotor(joint, on);
						tbPrismaticJoint_SetMotorSpeed(joint, a);
						tbPrismaticJoint_SetMaxMotorForce(joint, b * 50.0f);
						(void)tbPrismaticJoint_GetTranslation(joint);
						(void)tbPrismaticJoint_GetSpeed(joint);
						(void)tbPrismaticJoint_GetMotorForce(joint);
					}
					break;
				case tb_revoluteJoint:
					if (which == 0)
					{
						tbRevoluteJoint_EnableSpring(joint, on);
						tbRevoluteJoint_SetSpringHertz(joint, a);
						tbRevoluteJoint_SetSpringDampingRatio(joint, b);
						tbRevoluteJoint_SetTargetAngle(joint, a);
					}
					else if (which == 1)
					{
						tbRevoluteJoint_EnableLimit(joint, on);
						tbRevoluteJoint_SetLimits(joint, a, b);
					}
					else
					{
						tbRevoluteJoint_EnableMotor(joint, on);
						tbRevoluteJoint_SetMotorSpeed(joint, a);
						tbRevoluteJoint_SetMaxMotorTorque(joint, b * 50.0f);
						(void)tbRevoluteJoint_GetAngle(joint);
						(void)tbRevoluteJoint_GetMotorTorque(joint);
					}
					break;
				case tb_weldJoint:
					tbWeldJoint_SetLinearHertz(joint, a);
					tbWeldJoint_SetLinearDampingRatio(joint, b);
					tbWeldJoint_SetAngularHertz(joint, b);
					tbWeldJoint_SetAngularDampingRatio(joint, a);
					break;
				case tb_wheelJoint:
					if (which == 0)
					{
						tbWheelJoint_EnableSpring(joint, on);
						tbWheelJoint_SetSpringHertz(joint, a);
						tbWheelJoint_SetSpringDampingRatio(joint, b);
					}
					else if (which == 1)
					{
						tbWheelJoint_EnableLimit(joint, on);
						tbWheelJoint_SetLimits(joint, a, b);
					}
					else
					{
						tbWheelJoint_EnableMotor(joint, on);
						tbWheelJoint_SetMotorSpeed(joint, a);
						tbWheelJoint_SetMaxMotorTorque(joint, b * 50.0f);
						(void)tbWheelJoint_GetMotorTorque(joint);
					}
					break;
				default: // the filter joint has no setters of its own
					break;
			}
			break;
		}
	}
}

static void DestroyJoint(Harness* h, int slot, FuzzInput* in)
{
	Record* r = PickLive(h, kindJoint, slot, in);
	if (r == NULL)
	{
		return;
	}
	Handle joint = r->id;
	TRACE("destroy joint %d\n", joint.index1);
	tbDestroyJoint(AsJoint(joint));
	Bury(h, kindJoint, IsThis, &joint);
}

// ---------------------------------------------------------------------------------------------
// Queries.

static void Query(Harness* h, int slot, FuzzInput* in)
{
	tbWorldId world = h->worlds[slot].id;
	QueryContext q = {h, slot, FuzzByte(in), 0};
	tbQueryFilter filter = tbDefaultQueryFilter();
	if (FuzzInt(in, 4) == 0)
	{
		filter.maskBits = (uint64_t)FuzzByte(in) << FuzzInt(in, 56);
	}
	tbVec2 a = Vec(in, -12.0f, 12.0f);
	tbVec2 b = Vec(in, -12.0f, 12.0f);
	int kind = FuzzInt(in, 8);
	TRACE("query %d mode %02x from (%g, %g) to (%g, %g)\n", kind, q.mode, (double)a.x, (double)a.y, (double)b.x,
		  (double)b.y);
	switch (kind)
	{
		case 0:
		{
			tbAABB box = {tbMin(a, b), tbMax(a, b)};
			tbWorld_OverlapAABB(world, tbPos_zero, box, filter, OverlapResult, &q);
			break;
		}
		case 1:
			tbWorld_OverlapPoint(world, tbToPos(a), filter, OverlapResult, &q);
			break;
		case 2:
		case 3:
		{
			tbGeometry g = Geometry(in);
			if (g.type == tb_chainSegmentShape)
			{
				g.type = tb_segmentShape; // a proxy of its segment
			}
			tbShapeProxy proxy = tbMakeShapeProxy(&g);
			if (kind == 2)
			{
				tbWorld_OverlapShape(world, tbToPos(a), &proxy, filter, OverlapResult, &q);
			}
			else
			{
				tbWorld_CastShape(world, tbToPos(a), &proxy, tbSub(b, a), filter, CastResult, &q);
			}
			break;
		}
		case 4:
			tbWorld_CastRay(world, tbToPos(a), tbSub(b, a), filter, CastResult, &q);
			break;
		case 5:
		{
			tbRayResult result = tbWorld_CastRayClosest(world, tbToPos(a), tbSub(b, a), filter);
			FUZZ_CHECK(result.hit == false || (tbShape_IsValid(result.shapeId) && result.fraction >= 0.0f &&
												result.fraction <= 1.0f &&
												FuzzIsFinite2((float)result.point.x, (float)result.point.y)),
					   "closest ray hit: fraction %g", (double)result.fraction);
			break;
		}
		case 6:
		{
			tbCapsule mover = {{0.0f, -0.5f}, {0.0f, 0.5f}, Num(in, 0.05f, 1.0f)};
			float fraction = tbWorld_CastMover(world, tbToPos(a), &mover, tbSub(b, a), filter);
			FUZZ_CHECK(fraction >= 0.0f && fraction <= 1.0f, "tbWorld_CastMover returned %g", (double)fraction);
			break;
		}
		default:
		{
			tbCapsule mover = {{0.0f, -0.5f}, {0.0f, 0.5f}, Num(in, 0.05f, 1.0f)};
			tbWorld_CollideMover(world, tbToPos(a), &mover, filter, PlaneResult, &q);
			break;
		}
	}
}

// ---------------------------------------------------------------------------------------------
// Stepping and what must hold after it.

static void CheckIds(Harness* h)
{
	for (int k = 0; k < kindCount; ++k)
	{
		const List* list = h->lists + k;
		for (int i = 0; i < list->deadCount; ++i)
		{
			FUZZ_CHECK(IsValid((Kind)k, list->dead[i]) == false,
					   "the id of a destroyed %s (index %d, generation %d) is valid", s_kindNames[k],
					   list->dead[i].index1, list->dead[i].generation);
		}
		for (int i = 0; i < list->liveCount; ++i)
		{
			FUZZ_CHECK(IsValid((Kind)k, list->live[i].id), "a live %s (index %d) became invalid", s_kindNames[k],
					   list->live[i].id.index1);
		}
	}
	for (int i = 0; i < h->deadWorldCount && i < 8; ++i)
	{
		FUZZ_CHECK(tbWorld_IsValid(h->deadWorlds[i]) == false, "a destroyed world's id is valid");
	}
}

static void CheckBodies(Harness* h, int slot)
{
	const List* bodies = h->lists + kindBody;
	for (int i = 0; i < bodies->liveCount; ++i)
	{
		if (bodies->live[i].slot != slot)
		{
			continue;
		}
		tbBodyId body = AsBody(bodies->live[i].id);
		tbPos p = tbBody_GetPosition(body);
		tbVec2 v = tbBody_GetLinearVelocity(body);
		float w = tbBody_GetAngularVelocity(body);
		FUZZ_CHECK(isfinite(p.x) && isfinite(p.y) && FuzzIsFinite2(v.x, v.y) && isfinite(w),
				   "body %d at (%g, %g) v (%g, %g) w %g", body.index1, (double)p.x, (double)p.y, (double)v.x,
				   (double)v.y, (double)w);
		FUZZ_CHECK(tbBody_IsEnabled(body) == false || (fabs((double)p.x) <= TB_MAX_POSITION &&
													   fabs((double)p.y) <= TB_MAX_POSITION),
				   "enabled body %d at (%g, %g), beyond TB_MAX_POSITION", body.index1, (double)p.x, (double)p.y);
	}
}

static void CheckEvents(Harness* h, int slot)
{
	tbWorldId world = h->worlds[slot].id;
	tbContactEvents contacts = tbWorld_GetContactEvents(world);
	FUZZ_CHECK(contacts.beginCount >= 0 && contacts.endCount >= 0 && contacts.hitCount >= 0, "negative event counts");
	for (int i = 0; i < contacts.beginCount; ++i)
	{
		const tbContactBeginTouchEvent* e = contacts.beginEvents + i;
		FUZZ_CHECK(tbShape_IsValid(e->shapeIdA) && tbShape_IsValid(e->shapeIdB), "begin event %d with a stale shape",
				   i);
		FUZZ_CHECK(tbShape_IsSensor(e->shapeIdA) == false && tbShape_IsSensor(e->shapeIdB) == false,
				   "begin event %d for a sensor", i);
		if (tbContact_IsValid(e->contactId))
		{
			tbContactData data = tbContact_GetData(e->contactId);
			FUZZ_CHECK(TB_ID_EQUALS(data.shapeIdA, e->shapeIdA) && TB_ID_EQUALS(data.shapeIdB, e->shapeIdB),
					   "begin event %d's contact names other shapes", i);
			FUZZ_CHECK(data.manifold.pointCount >= 0 && data.manifold.pointCount <= 2 &&
						   FuzzIsFinite2(data.manifold.normal.x, data.manifold.normal.y),
					   "begin event %d's contact: %d points", i, data.manifold.pointCount);
			if (h->contactCount < 16)
			{
				h->contacts[h->contactCount++] = e->contactId;
			}
		}
	}
	for (int i = 0; i < contacts.endCount; ++i)
	{
		(void)tbShape_GetBody(contacts.endEvents[i].shapeIdA); // may be stale (a destroyed shape's)
	}
	for (int i = 0; i < contacts.hitCount; ++i)
	{
		const tbContactHitEvent* e = contacts.hitEvents + i;
		FUZZ_CHECK(FuzzIsFinite2((float)e->point.x, (float)e->point.y) && FuzzIsFinite2(e->normal.x, e->normal.y) &&
					   isfinite(e->approachSpeed) && e->approachSpeed >= 0.0f,
				   "hit event %d: point (%g, %g) normal (%g, %g) speed %g", i, (double)e->point.x, (double)e->point.y,
				   (double)e->normal.x, (double)e->normal.y, (double)e->approachSpeed);
	}
	tbSensorEvents sensors = tbWorld_GetSensorEvents(world);
	FUZZ_CHECK(sensors.beginCount >= 0 && sensors.endCount >= 0, "negative sensor event counts");
	for (int i = 0; i < sensors.beginCount; ++i)
	{
		const tbSensorBeginTouchEvent* e = sensors.beginEvents + i;
		FUZZ_CHECK(tbShape_IsValid(e->sensorShapeId) && tbShape_IsSensor(e->sensorShapeId),
				   "sensor begin event %d: its sensor is not a live sensor", i);
		FUZZ_CHECK(tbShape_IsValid(e->visitorShapeId) && TB_ID_EQUALS(e->visitorShapeId, e->sensorShapeId) == false,
				   "sensor begin event %d: the visitor is stale or the sensor itself", i);
	}
	for (int i = 0; i < sensors.endCount; ++i)
	{
		(void)tbShape_IsSensor(sensors.endEvents[i].sensorShapeId);
	}
	tbBodyEvents moves = tbWorld_GetBodyEvents(world);
	for (int i = 0; i < moves.moveCount; ++i)
	{
		const tbBodyMoveEvent* e = moves.moveEvents + i;
		FUZZ_CHECK(isfinite(e->transform.p.x) && isfinite(e->transform.p.y) &&
					   FuzzIsFinite2(e->transform.q.c, e->transform.q.s),
				   "move event %d: (%g, %g)", i, (double)e->transform.p.x, (double)e->transform.p.y);
		FUZZ_CHECK(tbBody_IsValid(e->bodyId), "move event %d names a stale body", i);
	}
	tbJointEvents joints = tbWorld_GetJointEvents(world);
	for (int i = 0; i < joints.count; ++i)
	{
		FUZZ_CHECK(tbJoint_IsValid(joints.jointEvents[i].jointId), "joint event %d names a stale joint", i);
	}
	for (int i = 0; i < h->contactCount; ++i)
	{
		if (tbContact_IsValid(h->contacts[i]))
		{
			tbContactData data = tbContact_GetData(h->contacts[i]);
			FUZZ_CHECK(tbShape_IsValid(data.shapeIdA) && tbShape_IsValid(data.shapeIdB),
					   "a live contact has a stale shape");
		}
	}
	tbAABB bounds = tbWorld_GetBounds(world);
	FUZZ_CHECK(isfinite(bounds.lowerBound.x) && isfinite(bounds.lowerBound.y) && isfinite(bounds.upperBound.x) &&
				   isfinite(bounds.upperBound.y),
			   "broad-phase bounds (%g, %g)-(%g, %g)", (double)bounds.lowerBound.x, (double)bounds.lowerBound.y,
			   (double)bounds.upperBound.x, (double)bounds.upperBound.y);
	(void)tbWorld_GetCounters(world);
	(void)tbWorld_GetProfile(world);
	(void)tbWorld_GetStateHash(world);
	(void)tbWorld_GetAwakeBodyCount(world);
}

static void Step(Harness* h, int slot, FuzzInput* in)
{
	if (h->steps >= MAX_STEPS)
	{
		return;
	}
	tbWorldId world = h->worlds[slot].id;
	int choice = FuzzInt(in, 16);
	float dt = choice < 12 ? 1.0f / 60.0f : choice < 15 ? Num(in, 0.0f, 0.1f) : FuzzFloat(in);
	int subSteps = 1 + FuzzInt(in, 6);
	int repeat = 1 + FuzzInt(in, 4) * FuzzInt(in, 4); // runs of steps: bodies settle and fall asleep
	for (int i = 0; i < repeat && h->steps < MAX_STEPS; ++i)
	{
		bool stepped = tbWorld_Step(world, dt, subSteps);
		TRACE("step dt %g, %d sub-steps, %d workers: %s\n", (double)dt, subSteps, h->worlds[slot].tasks.workerCount,
			  stepped ? "stepped" : "refused");
		h->steps += 1;
		CheckBodies(h, slot);
		if (stepped)
		{
			CheckEvents(h, slot);
		}
	}
	h->contactCount = 0;
	CheckIds(h);
	for (int k = 0; k < MAX_PENDING; ++k)
	{
		FUZZ_CHECK(h->worlds[slot].tasks.pending[k].state == 0, "a task was enqueued and never finished");
	}
}

// Debug drawing: every number the library hands out must be finite.
static void CheckVertices(const tbVec2* vertices, int vertexCount)
{
	FUZZ_CHECK(vertexCount >= 1 && vertexCount <= TB_MAX_POLYGON_VERTICES, "drawn polygon of %d vertices", vertexCount);
	for (int i = 0; i < vertexCount; ++i)
	{
		FUZZ_CHECK(FuzzIsFinite2(vertices[i].x, vertices[i].y), "drawn vertex (%g, %g)", (double)vertices[i].x,
				   (double)vertices[i].y);
	}
}

static void DrawCircle(tbPos center, float radius, tbHexColor color, void* context)
{
	(void)color;
	(void)context;
	FUZZ_CHECK(FuzzIsFinite2(center.x, center.y) && isfinite(radius), "drawn circle at (%g, %g) r %g",
			   (double)center.x, (double)center.y, (double)radius);
}

static void DrawTransform(tbWorldTransform transform, void* context)
{
	DrawCircle(transform.p, 0.0f, tb_colorBlack, context);
	FUZZ_CHECK(FuzzIsFinite2(transform.q.c, transform.q.s), "drawn rotation (%g, %g)", (double)transform.q.c,
			   (double)transform.q.s);
}

static void DrawPolygon(tbWorldTransform transform, const tbVec2* vertices, int vertexCount, tbHexColor color,
						void* context)
{
	(void)color;
	DrawTransform(transform, context);
	CheckVertices(vertices, vertexCount);
}

static void DrawSolidPolygon(tbWorldTransform transform, const tbVec2* vertices, int vertexCount, float radius,
							 tbHexColor color, void* context)
{
	FUZZ_CHECK(isfinite(radius), "drawn polygon of radius %g", (double)radius);
	DrawPolygon(transform, vertices, vertexCount, color, context);
}

static void DrawSolidCircle(tbWorldTransform transform, tbVec2 center, float radius, tbHexColor color, void* context)
{
	DrawTransform(transform, context);
	DrawCircle(tbToPos(center), radius, color, context);
}

static void DrawSolidCapsule(tbPos p1, tbPos p2, float radius, tbHexColor color, void* context)
{
	DrawCircle(p1, radius, color, context);
	DrawCircle(p2, radius, color, context);
}

static void DrawLine(tbPos p1, tbPos p2, tbHexColor color, void* context)
{
	DrawCircle(p1, 0.0f, color, context);
	DrawCircle(p2, 0.0f, color, context);
}

static void DrawPoint(tbPos p, float size, tbHexColor color, void* context)
{
	DrawCircle(p, size, color, context);
}

static void DrawString(tbPos p, const char* text, tbHexColor color, void* context)
{
	FUZZ_CHECK(text != NULL && strlen(text) < 256, "drawn text");
	DrawCircle(p, 0.0f, color, context);
}

static void DrawBounds(tbAABB box, tbHexColor color, void* context)
{
	DrawCircle(tbToPos(box.lowerBound), 0.0f, color, context);
	DrawCircle(tbToPos(box.upperBound), 0.0f, color, context);
}

static void Draw(Harness* h, int slot, FuzzInput* in)
{
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
	uint8_t flags = FuzzByte(in);
	draw.drawShapes = true;
	draw.drawBounds = (flags & 1u) != 0;
	draw.drawTree = (flags & 2u) != 0;
	draw.drawContacts = (flags & 4u) != 0;
	draw.drawGraphColors = (flags & 4u) != 0 && (flags & 64u) != 0;
	draw.drawContactNormals = (flags & 8u) != 0;
	draw.drawContactForces = (flags & 8u) != 0 && (flags & 64u) != 0;
	draw.drawFrictionForces = (flags & 8u) != 0 && (flags & 128u) != 0;
	draw.drawContactFeatures = (flags & 4u) != 0 && (flags & 128u) != 0;
	draw.drawJoints = (flags & 16u) == 0;
	draw.drawJointExtras = (flags & 16u) == 0 && (flags & 64u) != 0;
	draw.drawMass = (flags & 64u) != 0;
	draw.drawBodyNames = (flags & 64u) != 0;
	draw.drawIslands = (flags & 128u) != 0;
	draw.drawChainNormals = (flags & 128u) != 0;
	draw.drawAnchorA = (flags & 128u) != 0;
	if ((flags & 32u) != 0)
	{
		draw.drawingBounds = (tbAABB){{-5.0f, -5.0f}, {5.0f, 5.0f}};
	}
	TRACE("draw %02x in slot %d\n", flags, slot);
	tbWorld_Draw(h->worlds[slot].id, &draw);
}

// ---------------------------------------------------------------------------------------------

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	s_trace = getenv("FUZZ_TRACE") != NULL;
	tbSetErrorCallback(OnError, NULL);
	int64_t startBytes = tbGetByteCount();
	FuzzInput in = {data, size, 0};
	static Harness harness; // large: static, cleared for each input
	memset(&harness, 0, sizeof(harness));
	Harness* h = &harness;
	h->in = &in;
	s_h = h;
	memset(&s_mix, 0, sizeof(s_mix));
	// Length units are global and only change while no world exists: now and then a scaled run.
	static const float units[] = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 100.0f, 32.0f, 0.1f};
	float unit = units[FuzzInt(&in, 8)];
	if (unit != 1.0f)
	{
		FUZZ_CHECK(tbSetLengthUnitsPerMeter(unit), "length units %g refused with no world", (double)unit);
	}
	CreateWorld(h, 0, &in);
	while (in.offset < in.size)
	{
		int slot = FuzzInt(&in, WORLD_SLOTS);
		int op = FuzzInt(&in, 32);
		if (tbWorld_IsValid(h->worlds[slot].id) == false)
		{
			if (op < 4)
			{
				CreateWorld(h, slot, &in);
			}
			continue;
		}
		TRACE("[slot %d, op %d]\n", slot, op);
		switch (op)
		{
			case 0:
				if (FuzzInt(&in, 4) == 0)
				{
					DestroyWorld(h, slot);
					CheckIds(h);
				}
				break;
			case 1:
			case 2:
			case 3:
				CreateBody(h, slot, &in);
				break;
			case 4:
			case 5:
			case 6:
				CreateShape(h, slot, &in);
				break;
			case 7:
				CreateConcave(h, slot, &in);
				break;
			case 8:
				CreateChain(h, slot, &in);
				break;
			case 9:
			case 10:
			case 11:
				CreateJoint(h, slot, &in);
				break;
			case 12:
				DestroyBody(h, slot, &in);
				break;
			case 13:
				DestroyShape(h, slot, &in);
				break;
			case 14:
				DestroyJoint(h, slot, &in);
				break;
			case 15:
				ChainOp(h, slot, &in);
				break;
			case 16:
			case 17:
			case 18:
				ModifyBody(h, slot, &in);
				break;
			case 19:
				ModifyShape(h, slot, &in);
				break;
			case 20:
			case 21:
				ModifyJoint(h, slot, &in);
				break;
			case 22:
			case 23:
				WorldSettings(h, slot, &in);
				break;
			case 24:
			case 25:
				Query(h, slot, &in);
				break;
			case 26:
				Draw(h, slot, &in);
				break;
			case 27:
				if (FuzzInt(&in, 8) == 0)
				{
					Churn(h, slot, &in);
					CheckIds(h);
				}
				break;
			default:
				Step(h, slot, &in);
				break;
		}
	}
	for (int i = 0; i < WORLD_SLOTS; ++i)
	{
		if (tbWorld_IsValid(h->worlds[i].id))
		{
			DestroyWorld(h, i);
		}
	}
	CheckIds(h);
	FUZZ_CHECK(tbGetByteCount() == startBytes, "%lld bytes left after destroying every world (%lld at the start)",
			   (long long)tbGetByteCount(), (long long)startBytes);
	if (unit != 1.0f)
	{
		tbSetLengthUnitsPerMeter(1.0f);
	}
	s_h = NULL;
	return 0;
}
