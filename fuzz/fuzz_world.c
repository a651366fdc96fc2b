// Fuzz harness for API call sequences on worlds: bytes become a sequence of calls (create and
// destroy worlds, bodies and shapes; set velocities, transforms, forces, gravity, types; step;
// query, ray and shape casts) with hostile floats and with ids that are random, live or stale
// (kept after their body, shape or world was destroyed). Checks: no abort or sanitizer report,
// stale ids refused (IsValid false), every position finite after every step, no bytes left after
// the worlds are destroyed.
#include "fuzz_input.h"

#include "tumble/tumble.h"

#include <stdio.h>
#include <stdlib.h>

#define MAX_IDS 64

typedef struct Ids
{
	tbWorldId worlds[4];
	tbBodyId bodies[MAX_IDS];
	int bodyCount;
	tbBodyId deadBodies[MAX_IDS];
	int deadBodyCount;
	tbShapeId shapes[MAX_IDS];
	int shapeCount;
	tbShapeId deadShapes[MAX_IDS];
	int deadShapeCount;
} Ids;

// FUZZ_TRACE=1 in the environment prints every call's kind and every refusal's message: what a
// finding needs to be read as a call sequence (./fuzz_world CRASH_FILE replays one input).
static bool s_trace = false;
#define TRACE(...) (s_trace ? (void)fprintf(stderr, __VA_ARGS__) : (void)0)

static void Quiet(const char* message, void* context)
{
	(void)context;
	TRACE("  refused: %s\n", message);
}

static tbVec2 FuzzVec2(FuzzInput* in)
{
	float x = FuzzFloat(in);
	return tbMakeVec2(x, FuzzFloat(in));
}

static tbBodyId PickBody(FuzzInput* in, const Ids* ids)
{
	int choice = FuzzInt(in, 4);
	if (choice == 0 && ids->deadBodyCount > 0)
	{
		return ids->deadBodies[FuzzInt(in, ids->deadBodyCount)];
	}
	if (choice == 1)
	{
		int index = FuzzInt(in, 8) - 1; // one statement each: a fixed decoding order (see FuzzGeometry)
		int world = FuzzInt(in, 4);
		int generation = FuzzInt(in, 4);
		tbBodyId random = {index, (uint16_t)world, (uint16_t)generation};
		return random;
	}
	return ids->bodyCount > 0 ? ids->bodies[FuzzInt(in, ids->bodyCount)] : TB_NULL_BODY_ID;
}

static void Remember(tbBodyId* list, int* count, tbBodyId id)
{
	if (*count < MAX_IDS)
	{
		list[(*count)++] = id;
	}
	else
	{
		list[MAX_IDS - 1] = id;
	}
}

static void RememberShape(tbShapeId* list, int* count, tbShapeId id)
{
	if (*count < MAX_IDS)
	{
		list[(*count)++] = id;
	}
	else
	{
		list[MAX_IDS - 1] = id;
	}
}

static tbGeometry FuzzGeometry(FuzzInput* in)
{
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	switch (FuzzInt(in, 4))
	{
		case 0:
			g.type = tb_circleShape;
			g.circle.center = FuzzVec2(in);
			g.circle.radius = FuzzFloat(in);
			break;
		case 1:
			g.type = tb_capsuleShape;
			g.capsule.center1 = FuzzVec2(in);
			g.capsule.center2 = FuzzVec2(in);
			g.capsule.radius = FuzzFloat(in);
			break;
		case 2:
			g.type = tb_segmentShape;
			g.segment.point1 = FuzzVec2(in);
			g.segment.point2 = FuzzVec2(in);
			break;
		default:
		{
			// Each value in its own statement: the bytes decode in this order with any compiler (C
			// leaves the order of a call's arguments unspecified; clang goes left to right).
			float hx = FuzzFloat(in);
			float hy = FuzzFloat(in);
			tbVec2 center = FuzzVec2(in);
			float angle = FuzzFloat(in);
			g.type = tb_polygonShape;
			g.polygon = tbMakeOffsetBox(hx, hy, center, tbMakeRot(angle));
			break;
		}
	}
	return g;
}

static void CreateBody(FuzzInput* in, Ids* ids, tbWorldId world)
{
	tbBodyDef def = tbDefaultBodyDef();
	def.type = (tbBodyType)FuzzInt(in, 3);
	def.position = FuzzVec2(in);
	def.linearVelocity = FuzzVec2(in);
	def.angularVelocity = FuzzFloat(in);
	def.gravityScale = FuzzInt(in, 2) ? FuzzFloat(in) : 1.0f;
	def.isBullet = FuzzInt(in, 4) == 0;
	tbBodyId body = tbCreateBody(world, &def);
	TRACE("create body type %d at (%g, %g) v (%g, %g) w %g gravityScale %g bullet %d -> %d\n", (int)def.type,
		  (double)def.position.x, (double)def.position.y, (double)def.linearVelocity.x, (double)def.linearVelocity.y,
		  (double)def.angularVelocity, (double)def.gravityScale, (int)def.isBullet, body.index1);
	if (TB_IS_NON_NULL(body))
	{
		Remember(ids->bodies, &ids->bodyCount, body);
	}
}

static void CreateShape(FuzzInput* in, Ids* ids)
{
	tbShapeDef def = tbDefaultShapeDef();
	def.density = FuzzInt(in, 2) ? FuzzFloat(in) : 1.0f;
	def.material.friction = FuzzInt(in, 2) ? FuzzFloat(in) : 0.6f;
	def.material.restitution = FuzzInt(in, 4) == 0 ? FuzzFloat(in) : 0.0f;
	tbGeometry g = FuzzGeometry(in);
	tbBodyId body = PickBody(in, ids);
	tbShapeId shape = tbCreateShape(body, &def, &g);
	TRACE("create shape type %d density %g friction %g restitution %g on body %d -> %d\n", (int)g.type,
		  (double)def.density, (double)def.material.friction, (double)def.material.restitution, body.index1,
		  shape.index1);
	if (g.type == tb_circleShape)
	{
		TRACE("  circle (%g, %g) r %g\n", (double)g.circle.center.x, (double)g.circle.center.y,
			  (double)g.circle.radius);
	}
	else if (g.type == tb_capsuleShape)
	{
		TRACE("  capsule (%g, %g) (%g, %g) r %g\n", (double)g.capsule.center1.x, (double)g.capsule.center1.y,
			  (double)g.capsule.center2.x, (double)g.capsule.center2.y, (double)g.capsule.radius);
	}
	else if (g.type == tb_segmentShape)
	{
		TRACE("  segment (%g, %g) (%g, %g)\n", (double)g.segment.point1.x, (double)g.segment.point1.y,
			  (double)g.segment.point2.x, (double)g.segment.point2.y);
	}
	else
	{
		TRACE("  polygon of %d vertices, first (%g, %g), radius %g\n", g.polygon.count,
			  (double)g.polygon.vertices[0].x, (double)g.polygon.vertices[0].y, (double)g.polygon.radius);
	}
	if (TB_IS_NON_NULL(shape))
	{
		RememberShape(ids->shapes, &ids->shapeCount, shape);
	}
}

static void DestroyBody(FuzzInput* in, Ids* ids)
{
	if (ids->bodyCount == 0)
	{
		return;
	}
	int k = FuzzInt(in, ids->bodyCount);
	tbBodyId body = ids->bodies[k];
	tbDestroyBody(body);
	ids->bodies[k] = ids->bodies[--ids->bodyCount];
	Remember(ids->deadBodies, &ids->deadBodyCount, body);
}

static void DestroyShape(FuzzInput* in, Ids* ids)
{
	if (ids->shapeCount == 0)
	{
		return;
	}
	int k = FuzzInt(in, ids->shapeCount);
	tbShapeId shape = ids->shapes[k];
	tbDestroyShape(shape, true);
	ids->shapes[k] = ids->shapes[--ids->shapeCount];
	RememberShape(ids->deadShapes, &ids->deadShapeCount, shape);
}

static void Modify(FuzzInput* in, Ids* ids)
{
	tbBodyId body = PickBody(in, ids);
	int kind = FuzzInt(in, 8);
	TRACE("modify body %d: kind %d\n", body.index1, kind);
	switch (kind)
	{
		case 0:
		{
			tbVec2 v = FuzzVec2(in);
			TRACE("  linear velocity (%g, %g)\n", (double)v.x, (double)v.y);
			tbBody_SetLinearVelocity(body, v);
			break;
		}
		case 1:
		{
			float w = FuzzFloat(in);
			TRACE("  angular velocity %g\n", (double)w);
			tbBody_SetAngularVelocity(body, w);
			break;
		}
		case 2:
		{
			tbVec2 p = FuzzVec2(in);
			float angle = FuzzFloat(in);
			TRACE("  transform (%g, %g) angle %g\n", (double)p.x, (double)p.y, (double)angle);
			tbBody_SetTransform(body, p, tbMakeRot(angle));
			break;
		}
		case 3:
		{
			tbVec2 force = FuzzVec2(in);
			TRACE("  force (%g, %g)\n", (double)force.x, (double)force.y);
			tbBody_ApplyForceToCenter(body, force, true);
			break;
		}
		case 4:
		{
			tbVec2 impulse = FuzzVec2(in);
			tbVec2 point = FuzzVec2(in);
			TRACE("  impulse (%g, %g) at (%g, %g)\n", (double)impulse.x, (double)impulse.y, (double)point.x,
				  (double)point.y);
			tbBody_ApplyLinearImpulse(body, impulse, point, true);
			break;
		}
		case 5:
			tbBody_ApplyTorque(body, FuzzFloat(in), true);
			break;
		case 6:
			tbBody_SetType(body, (tbBodyType)FuzzInt(in, 4));
			break;
		default:
			if (ids->shapeCount > 0)
			{
				tbShapeId shape = ids->shapes[FuzzInt(in, ids->shapeCount)];
				float density = FuzzFloat(in);
				TRACE("  density of shape %d: %g\n", shape.index1, (double)density);
				tbShape_SetDensity(shape, density, true);
			}
			break;
	}
}

static bool CountOverlap(tbShapeId shapeId, void* context)
{
	(void)shapeId;
	*(int*)context += 1;
	return true;
}

static float ClipCast(tbShapeId shapeId, tbPos point, tbVec2 normal, float fraction, void* context)
{
	(void)context;
	FUZZ_CHECK(FuzzIsFinite2(point.x, point.y) && FuzzIsFinite2(normal.x, normal.y) && isfinite(fraction),
			   "cast result: shape %d point (%g, %g) normal (%g, %g) fraction %g", shapeId.index1, (double)point.x,
			   (double)point.y, (double)normal.x, (double)normal.y, (double)fraction);
	return fraction;
}

static void Query(FuzzInput* in, tbWorldId world)
{
	tbVec2 a = FuzzVec2(in), b = FuzzVec2(in);
	tbAABB box = {tbMin(a, b), tbMax(a, b)};
	int found = 0;
	tbWorld_OverlapAABB(world, tbPos_zero, box, tbDefaultQueryFilter(), CountOverlap, &found);
	tbWorld_CastRay(world, a, tbSub(b, a), tbDefaultQueryFilter(), ClipCast, NULL);
	tbGeometry g = FuzzGeometry(in);
	tbShapeProxy proxy = tbMakeShapeProxy(&g);
	tbWorld_CastShape(world, a, &proxy, FuzzVec2(in), tbDefaultQueryFilter(), ClipCast, NULL);
	tbWorld_OverlapShape(world, a, &proxy, tbDefaultQueryFilter(), CountOverlap, &found);
}

static void CheckStep(const Ids* ids)
{
	for (int i = 0; i < ids->bodyCount; ++i)
	{
		if (tbBody_IsValid(ids->bodies[i]))
		{
			tbVec2 p = tbBody_GetPosition(ids->bodies[i]);
			tbVec2 v = tbBody_GetLinearVelocity(ids->bodies[i]);
			FUZZ_CHECK(FuzzIsFinite2(p.x, p.y) && FuzzIsFinite2(v.x, v.y), "body %d at (%g, %g) v (%g, %g)", i,
					   (double)p.x, (double)p.y, (double)v.x, (double)v.y);
		}
	}
	for (int i = 0; i < ids->deadBodyCount; ++i)
	{
		FUZZ_CHECK(tbBody_IsValid(ids->deadBodies[i]) == false, "stale body id %d accepted", i);
	}
	for (int i = 0; i < ids->deadShapeCount; ++i)
	{
		FUZZ_CHECK(tbShape_IsValid(ids->deadShapes[i]) == false, "stale shape id %d accepted", i);
	}
}

// A world's bodies and shapes die with it: their ids join the stale lists.
static void DestroyWorld(Ids* ids, int slot)
{
	tbWorldId world = ids->worlds[slot];
	for (int i = ids->bodyCount - 1; i >= 0; --i)
	{
		if (ids->bodies[i].world0 == world.index1 - 1)
		{
			Remember(ids->deadBodies, &ids->deadBodyCount, ids->bodies[i]);
			ids->bodies[i] = ids->bodies[--ids->bodyCount];
		}
	}
	for (int i = ids->shapeCount - 1; i >= 0; --i)
	{
		if (ids->shapes[i].world0 == world.index1 - 1)
		{
			RememberShape(ids->deadShapes, &ids->deadShapeCount, ids->shapes[i]);
			ids->shapes[i] = ids->shapes[--ids->shapeCount];
		}
	}
	tbDestroyWorld(world);
}

static tbWorldId CreateWorld(FuzzInput* in)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = FuzzInt(in, 2) ? FuzzVec2(in) : def.gravity;
	def.broadPhase = (tbBroadPhaseMethod)FuzzInt(in, tb_broadPhaseMethodCount);
	def.narrowPhase = (tbNarrowPhaseMethod)FuzzInt(in, 3);
	def.continuous = (tbContinuousMethod)FuzzInt(in, tb_continuousMethodCount);
	def.solver = (tbSolverMethod)FuzzInt(in, tb_solverMethodCount);
	def.enableWideSolver = FuzzInt(in, 2) == 0;
	return tbCreateWorld(&def);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	s_trace = getenv("FUZZ_TRACE") != NULL;
	tbSetErrorCallback(Quiet, NULL);
	FuzzInput in = {data, size, 0};
	Ids ids;
	memset(&ids, 0, sizeof(ids));
	ids.worlds[0] = CreateWorld(&in);
	int steps = 0;
	while (in.offset < in.size)
	{
		int slot = FuzzInt(&in, 4);
		tbWorldId world = ids.worlds[slot];
		int op = FuzzInt(&in, 10);
		TRACE("world slot %d, op %d\n", slot, op);
		if (s_trace)
		{
			CheckStep(&ids); // tracing: stop at the call that broke a body, not at the next step
		}
		switch (op)
		{
			case 0:
			case 1:
				CreateBody(&in, &ids, world);
				break;
			case 2:
				CreateShape(&in, &ids);
				break;
			case 3:
				DestroyBody(&in, &ids);
				break;
			case 4:
				DestroyShape(&in, &ids);
				break;
			case 5:
				Modify(&in, &ids);
				break;
			case 6:
				if (steps < 200)
				{
					float dt = FuzzInt(&in, 2) ? FuzzFloat(&in) : 1.0f / 60.0f;
					int subSteps = 1 + FuzzInt(&in, 8);
					bool stepped = tbWorld_Step(world, dt, subSteps);
					TRACE("step dt %g, %d sub-steps: %s\n", (double)dt, subSteps, stepped ? "stepped" : "refused");
					steps += stepped ? 1 : 0;
				}
				CheckStep(&ids);
				break;
			case 7:
				Query(&in, world);
				break;
			case 8:
				tbWorld_SetGravity(world, FuzzVec2(&in));
				break;
			default:
				if (tbWorld_IsValid(world))
				{
					DestroyWorld(&ids, slot);
				}
				else
				{
					ids.worlds[slot] = CreateWorld(&in);
				}
				CheckStep(&ids);
				break;
		}
	}
	for (int i = 0; i < 4; ++i)
	{
		if (tbWorld_IsValid(ids.worlds[i]))
		{
			tbDestroyWorld(ids.worlds[i]);
		}
	}
	FUZZ_CHECK(tbGetByteCount() == 0, "%lld bytes left after destroying every world", (long long)tbGetByteCount());
	return 0;
}
