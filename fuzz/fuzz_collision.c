// Fuzz harness for the stateless collision layer: shapes built through the constructors from
// hostile floats (NaN, infinity, FLT_MAX, denormals, sizes beyond TB_MAX_COORDINATE, degenerate
// point sets), and the same bytes as raw structs that bypass the constructors. Every query runs on
// every pair: the manifold functions (through tbCollideShapes with each narrow phase, plus
// tbCollidePolygonsGJK), GJK distance, separation, shape cast, ray casts, both TOI methods and the
// dynamic tree. Checks, for input the constructors accepted and transforms within
// TB_MAX_COORDINATE: finite outputs, 0..2 manifold points, unit normals. Any input: no abort, no
// sanitizer report, ray cast hits with finite numbers and a fraction in [0, 1].
#include "fuzz_input.h"

#include "tumble/tumble.h"

#include <stdio.h>
#include <stdlib.h>

static void Quiet(const char* message, void* context)
{
	(void)message;
	(void)context;
}

typedef struct FuzzShape
{
	tbGeometry geometry;
	bool valid; ///< built by an accepting constructor (checks apply)
} FuzzShape;

static tbVec2 FuzzVec2(FuzzInput* in)
{
	float x = FuzzFloat(in);
	return tbMakeVec2(x, FuzzFloat(in));
}

static bool InBounds(tbVec2 v)
{
	return fabsf(v.x) <= TB_MAX_COORDINATE && fabsf(v.y) <= TB_MAX_COORDINATE;
}

static FuzzShape MakePolygonShape(FuzzInput* in)
{
	FuzzShape shape = {{0}, false};
	shape.geometry.type = tb_polygonShape;
	int kind = FuzzInt(in, 3);
	if (kind == 0)
	{
		float hx = FuzzFloat(in), hy = FuzzFloat(in);
		tbVec2 center = FuzzVec2(in);
		tbRot q = tbMakeRot(FuzzFloat(in));
		shape.geometry.polygon = tbIsValidRotation(q) ? tbMakeOffsetBox(hx, hy, center, q) : tbMakeBox(hx, hy);
	}
	else if (kind == 1)
	{
		float hx = FuzzFloat(in); // one statement each: the same decoding with any compiler
		float hy = FuzzFloat(in);
		float radius = FuzzFloat(in);
		shape.geometry.polygon = tbMakeRoundedBox(hx, hy, radius);
	}
	else
	{
		tbVec2 points[TB_MAX_POLYGON_VERTICES];
		int count = 1 + FuzzInt(in, TB_MAX_POLYGON_VERTICES);
		for (int i = 0; i < count; ++i)
		{
			points[i] = FuzzVec2(in);
		}
		tbHull hull = tbComputeHull(points, count);
		shape.geometry.polygon = tbMakePolygon(&hull, FuzzFloat(in));
	}
	shape.valid = shape.geometry.polygon.count >= 3;
	return shape;
}

static FuzzShape MakeShape(FuzzInput* in)
{
	FuzzShape shape = {{0}, false};
	switch (FuzzInt(in, 5))
	{
		case 0:
			shape.geometry.type = tb_circleShape;
			shape.geometry.circle.center = FuzzVec2(in);
			shape.geometry.circle.radius = FuzzFloat(in);
			break;
		case 1:
			shape.geometry.type = tb_capsuleShape;
			shape.geometry.capsule.center1 = FuzzVec2(in);
			shape.geometry.capsule.center2 = FuzzVec2(in);
			shape.geometry.capsule.radius = FuzzFloat(in);
			break;
		case 2:
			shape.geometry.type = tb_segmentShape;
			shape.geometry.segment.point1 = FuzzVec2(in);
			shape.geometry.segment.point2 = FuzzVec2(in);
			break;
		default:
			return MakePolygonShape(in);
	}
	// Hand-made circles, capsules and segments: valid when a world would accept them. A scratch
	// world asks the library itself (its checks are the definition of valid).
	tbWorldDef def = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&def);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shape.valid = TB_IS_NON_NULL(tbCreateShape(body, &shapeDef, &shape.geometry));
	tbDestroyWorld(world);
	return shape;
}

static tbTransform MakeTransform(FuzzInput* in, bool* valid)
{
	tbTransform xf = {FuzzVec2(in), tbMakeRot(FuzzFloat(in))};
	*valid = InBounds(xf.p) && tbIsValidRotation(xf.q);
	return xf;
}

static void CheckManifold(const tbManifold* m, const char* what)
{
	FUZZ_CHECK(m->pointCount >= 0 && m->pointCount <= 2, "%s: %d points", what, m->pointCount);
	if (m->pointCount == 0)
	{
		return;
	}
	float length = sqrtf(m->normal.x * m->normal.x + m->normal.y * m->normal.y);
	FUZZ_CHECK(fabsf(length - 1.0f) < 1e-3f, "%s: normal (%g, %g)", what, (double)m->normal.x, (double)m->normal.y);
	for (int i = 0; i < m->pointCount; ++i)
	{
		const tbManifoldPoint* p = m->points + i;
		FUZZ_CHECK(FuzzIsFinite2(p->point.x, p->point.y) && isfinite(p->separation), "%s: point %d (%g, %g) sep %g",
				   what, i, (double)p->point.x, (double)p->point.y, (double)p->separation);
	}
}

static void CollideEverything(const FuzzShape* a, tbTransform xfA, const FuzzShape* b, tbTransform xfB, bool check)
{
	for (int method = tb_narrowPhaseAuto; method <= tb_narrowPhaseGJK; ++method)
	{
		tbManifold m = tbCollideShapes(&a->geometry, xfA, &b->geometry, xfB, (tbNarrowPhaseMethod)method);
		if (check)
		{
			CheckManifold(&m, "tbCollideShapes");
		}
	}
	if (a->geometry.type == tb_polygonShape && b->geometry.type == tb_polygonShape)
	{
		tbLocalManifold local =
			tbCollidePolygonsGJK(&a->geometry.polygon, &b->geometry.polygon, tbInvMulTransforms(xfA, xfB));
		tbManifold m = {local.normal, 0.0f, {{0}}, local.pointCount};
		for (int i = 0; i < local.pointCount && i < 2; ++i)
		{
			m.points[i].point = local.points[i].point;
			m.points[i].separation = local.points[i].separation;
		}
		if (check)
		{
			CheckManifold(&m, "tbCollidePolygonsGJK");
		}
	}
}

static void DistanceEverything(const FuzzShape* a, tbTransform xfA, const FuzzShape* b, tbTransform xfB,
							   tbVec2 translation, bool check)
{
	tbDistanceInput input;
	memset(&input, 0, sizeof(input));
	input.proxyA = tbMakeShapeProxy(&a->geometry);
	input.proxyB = tbMakeShapeProxy(&b->geometry);
	input.transform = tbInvMulTransforms(xfA, xfB);
	input.useRadii = true;
	tbSimplexCache cache = {0};
	tbDistanceOutput distance = tbShapeDistance(&input, &cache, NULL, 0);
	tbSeparationOutput separation = tbShapeSeparation(&input, NULL);

	tbShapeCastPairInput cast;
	memset(&cast, 0, sizeof(cast));
	cast.proxyA = input.proxyA;
	cast.proxyB = input.proxyB;
	cast.transform = input.transform;
	cast.translationB = tbInvRotateVector(xfA.q, translation);
	cast.maxFraction = 1.0f;
	tbCastOutput hit = tbShapeCast(&cast);

	tbTOIInput toi;
	memset(&toi, 0, sizeof(toi));
	toi.proxyA = input.proxyA;
	toi.proxyB = input.proxyB;
	toi.sweepA = (tbSweep){{0.0f, 0.0f}, xfA.p, xfA.p, xfA.q, xfA.q};
	toi.sweepB = (tbSweep){{0.0f, 0.0f}, xfB.p, tbAdd(xfB.p, translation), xfB.q, tbMakeRot(0.3f)};
	toi.maxFraction = 1.0f;
	tbTOIOutput impact = tbTimeOfImpact(&toi);
	if (a->geometry.type == tb_circleShape && b->geometry.type == tb_circleShape)
	{
		tbTOIOutput closed = tbTimeOfImpactCircles(&a->geometry.circle, &toi.sweepA, &b->geometry.circle, &toi.sweepB,
												   1.0f, TB_TOI_TARGET_SEPARATION);
		if (check)
		{
			FUZZ_CHECK(closed.fraction >= 0.0f && closed.fraction <= 1.0f, "circle TOI fraction %g",
					   (double)closed.fraction);
		}
	}
	if (check == false)
	{
		return;
	}
	FUZZ_CHECK(isfinite(distance.distance) && distance.distance >= 0.0f, "distance %g", (double)distance.distance);
	FUZZ_CHECK(FuzzIsFinite2(distance.pointA.x, distance.pointA.y) && FuzzIsFinite2(distance.pointB.x, distance.pointB.y),
			   "distance points");
	FUZZ_CHECK(isfinite(separation.separation), "separation %g", (double)separation.separation);
	float n = sqrtf(separation.normal.x * separation.normal.x + separation.normal.y * separation.normal.y);
	FUZZ_CHECK(fabsf(n - 1.0f) < 1e-3f, "separation normal (%g, %g)", (double)separation.normal.x,
			   (double)separation.normal.y);
	FUZZ_CHECK(FuzzIsFinite2(hit.point.x, hit.point.y) && FuzzIsFinite2(hit.normal.x, hit.normal.y) &&
				   isfinite(hit.fraction),
			   "shape cast");
	FUZZ_CHECK(impact.fraction >= 0.0f && impact.fraction <= 1.0f, "TOI fraction %g", (double)impact.fraction);
	FUZZ_CHECK(FuzzIsFinite2(impact.point.x, impact.point.y) && FuzzIsFinite2(impact.normal.x, impact.normal.y),
			   "TOI point or normal");
}

static void RayCastEverything(const FuzzShape* shape, tbVec2 origin, tbVec2 translation, bool check)
{
	tbRayCastInput ray = {origin, translation, 1.0f};
	tbCastOutput out = tbRayCastShape(&shape->geometry, &ray);
	(void)tbPointInShape(&shape->geometry, origin);
	tbAABB box = tbComputeShapeAABB(&shape->geometry, tbTransform_identity);
	tbMassData mass = tbComputeShapeMass(&shape->geometry, 1.0f);
	// any input: a hit has finite numbers and a fraction in [0, 1] (a translation of any length)
	bool finite = FuzzIsFinite2(out.point.x, out.point.y) && FuzzIsFinite2(out.normal.x, out.normal.y);
	FUZZ_CHECK(out.hit == false || (finite && out.fraction >= 0.0f && out.fraction <= 1.0f),
			   "ray cast point (%g, %g) fraction %g", (double)out.point.x, (double)out.point.y, (double)out.fraction);
	if (check)
	{
		FUZZ_CHECK(tbIsValidAABB(box), "shape box");
		FUZZ_CHECK(isfinite(mass.mass) && isfinite(mass.rotationalInertia), "mass %g inertia %g", (double)mass.mass,
				   (double)mass.rotationalInertia);
	}
}

static bool TreeCallback(int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	(void)userData;
	*(int*)context += 1;
	return true;
}

static float TreeRayCallback(const tbRayCastInput* input, int proxyId, uint64_t userData, void* context)
{
	(void)proxyId;
	(void)userData;
	(void)context;
	return input->maxFraction * 0.5f;
}

static void TreeEverything(FuzzInput* in)
{
	tbDynamicTree tree = tbDynamicTree_Create(0);
	int ids[32];
	int count = 0;
	int operations = FuzzInt(in, 64);
	for (int i = 0; i < operations; ++i)
	{
		tbVec2 a = FuzzVec2(in), b = FuzzVec2(in);
		tbAABB box = {tbMin(a, b), tbMax(a, b)};
		bool valid = tbIsValidAABB(box);
		int op = FuzzInt(in, 6);
		if (op <= 1 && valid && count < 32)
		{
			ids[count++] = tbDynamicTree_CreateProxy(&tree, box, 1, i);
		}
		else if (op == 2 && count > 0)
		{
			int k = FuzzInt(in, count);
			tbDynamicTree_DestroyProxy(&tree, ids[k]);
			ids[k] = ids[--count];
		}
		else if (op == 3 && count > 0 && valid)
		{
			tbDynamicTree_MoveProxy(&tree, ids[FuzzInt(in, count)], box);
		}
		else if (op == 4)
		{
			tbDynamicTree_Rebuild(&tree, true);
		}
		else if (valid)
		{
			int found = 0;
			tbDynamicTree_Query(&tree, box, ~0ull, TreeCallback, &found);
			tbRayCastInput ray = {a, tbSub(b, a), 1.0f};
			if (tbIsValidVec2(ray.translation))
			{
				tbDynamicTree_RayCast(&tree, &ray, ~0ull, TreeRayCallback, NULL);
			}
		}
	}
	FUZZ_CHECK(tbDynamicTree_Validate(&tree), "tree invalid");
	tbDynamicTree_Destroy(&tree);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	tbSetErrorCallback(Quiet, NULL);
	FuzzInput in = {data, size, 0};
	FuzzShape a = MakeShape(&in);
	FuzzShape b = MakeShape(&in);
	bool validA, validB;
	tbTransform xfA = MakeTransform(&in, &validA);
	tbTransform xfB = MakeTransform(&in, &validB);
	tbVec2 translation = FuzzVec2(&in);
	bool check = a.valid && b.valid && validA && validB && InBounds(translation);
	if (getenv("FUZZ_VERBOSE") != NULL)
	{
		const FuzzShape* shapes[2] = {&a, &b};
		for (int i = 0; i < 2; ++i)
		{
			const tbGeometry* g = &shapes[i]->geometry;
			fprintf(stderr, "shape %d type %d valid %d:", i, (int)g->type, shapes[i]->valid);
			for (int k = 0; k < (int)(sizeof(tbGeometry) / sizeof(float)) - 1; ++k)
			{
				fprintf(stderr, " %.9g", (double)((const float*)&g->circle)[k]);
			}
			fprintf(stderr, "\n");
		}
		fprintf(stderr, "xfA (%.9g, %.9g; %.9g, %.9g) xfB (%.9g, %.9g; %.9g, %.9g) translation (%.9g, %.9g)\n",
				(double)xfA.p.x, (double)xfA.p.y, (double)xfA.q.c, (double)xfA.q.s, (double)xfB.p.x, (double)xfB.p.y,
				(double)xfB.q.c, (double)xfB.q.s, (double)translation.x, (double)translation.y);
	}

	CollideEverything(&a, xfA, &b, xfB, check);
	CollideEverything(&b, xfB, &a, xfA, check);
	if (a.geometry.type != tb_polygonShape || a.valid)
	{
		// tbMakeShapeProxy reads count vertices: a refused polygon (count 0) is refused in turn
		DistanceEverything(&a, xfA, &b, xfB, translation, check);
	}
	RayCastEverything(&a, xfB.p, translation, a.valid && validB);
	TreeEverything(&in);
	FUZZ_CHECK(tbGetByteCount() == 0, "%lld bytes left", (long long)tbGetByteCount());
	return 0;
}
