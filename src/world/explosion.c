// Explosions (tbWorld_Explode): an impulse on every dynamic shape within reach of a point, in
// proportion to the width the shape shows the blast.
//
// A blast wave of pressure p acting for a time t pushes a surface element dA facing it with the
// impulse p·t·dA. In 2D the "area" a body shows the blast is the width of its shadow across the
// blast direction d: the extent of the shape projected on the line perpendicular to d (its
// projected perimeter). So each shape receives
//     J = impulsePerLength · width⊥(shape, d) · scale,   d = (closest point − centre)/|…|,
// applied at the shape's point closest to the centre, so that a shape struck off its centre of
// mass also turns. scale is 1 within `radius` and falls linearly to 0 over `falloff` beyond it.
// Box2D v3.2 defines its explosions in these terms; this is written from the definition above.
#include "core/core.h"

#include "broad_phase/broad_phase.h"
#include "world.h"

#include "tumble/collision.h"
#include "tumble/tumble.h"
#include "recording.h"

#include <float.h>

tbExplosionDef tbDefaultExplosionDef(void)
{
	tbExplosionDef def = {0};
	def.maskBits = TB_DEFAULT_MASK_BITS;
	return def;
}

/// Width of the shape's shadow on the unit line `line` (local frame): the extent of its
/// projection, rounded shapes counting their radius on both sides. A segment shows its length.
static float tbProjectedWidth(const tbGeometry* g, tbVec2 line)
{
	switch (g->type)
	{
		case tb_circleShape:
			return 2.0f * g->circle.radius;
		case tb_capsuleShape:
			return tbAbsFloat(tbDot(tbSub(g->capsule.center2, g->capsule.center1), line)) + 2.0f * g->capsule.radius;
		case tb_segmentShape:
			return tbAbsFloat(tbDot(tbSub(g->segment.point2, g->segment.point1), line));
		case tb_chainSegmentShape:
			return tbAbsFloat(tbDot(tbSub(g->chainSegment.segment.point2, g->chainSegment.segment.point1), line));
		case tb_polygonShape:
		default:
		{
			float lower = FLT_MAX, upper = -FLT_MAX;
			for (int i = 0; i < g->polygon.count; ++i)
			{
				float value = tbDot(g->polygon.vertices[i], line);
				lower = tbMinFloat(lower, value);
				upper = tbMaxFloat(upper, value);
			}
			return upper - lower + 2.0f * g->polygon.radius;
		}
	}
}

/// A point inside the shape, for a centre that lies in it (no closest surface point to aim from).
static tbVec2 tbShapeInnerPoint(const tbGeometry* g)
{
	switch (g->type)
	{
		case tb_circleShape:
			return g->circle.center;
		case tb_capsuleShape:
			return tbLerp(g->capsule.center1, g->capsule.center2, 0.5f);
		case tb_segmentShape:
			return tbLerp(g->segment.point1, g->segment.point2, 0.5f);
		case tb_chainSegmentShape:
			return tbLerp(g->chainSegment.segment.point1, g->chainSegment.segment.point2, 0.5f);
		case tb_polygonShape:
		default:
			return g->polygon.centroid;
	}
}

typedef struct tbExplosionContext
{
	tbWorld* world;
	tbExplosionDef def;
} tbExplosionContext;

static bool tbExplosionCallback(int proxyKey, int shapeIndex, void* context)
{
	(void)proxyKey;
	tbExplosionContext* c = context;
	tbWorld* world = c->world;
	const tbShape* shape = world->shapes + shapeIndex;
	tbBody* body = world->bodies + shape->bodyId;
	if (body->type != tb_dynamicBody)
	{
		return true;
	}
	// Work in the shape's frame: the distance stays precise far from the origin.
	tbWorldTransform xf = body->transform;
	tbVec2 centre = tbInvTransformWorldPoint(xf, c->def.position);
	tbDistanceInput input;
	input.proxyA = tbMakeShapeProxy(&shape->geometry);
	input.proxyB = tbMakeProxy(&centre, 1, 0.0f);
	input.transform = tbTransform_identity; // the centre is in the shape's frame already
	input.useRadii = true;
	tbDistanceOutput output = tbShapeDistance(&input, NULL, NULL, 0);
	float radius = c->def.radius, falloff = c->def.falloff;
	if (output.distance > radius + falloff)
	{
		return true;
	}
	tbVec2 struck = output.distance > 0.0f ? output.pointA : tbShapeInnerPoint(&shape->geometry);
	tbVec2 direction = tbSub(struck, centre);
	float length = tbLength(direction);
	direction = length > 10.0f * FLT_EPSILON ? tbMulSV(1.0f / length, direction) : tbMakeVec2(1.0f, 0.0f);
	float scale = 1.0f;
	if (output.distance > radius && falloff > 0.0f)
	{
		scale = tbClampFloat((radius + falloff - output.distance) / falloff, 0.0f, 1.0f);
	}
	float magnitude = c->def.impulsePerLength * tbProjectedWidth(&shape->geometry, tbLeftPerp(direction)) * scale;
	tbVec2 impulse = tbMulSV(magnitude, tbRotateVector(xf.q, direction));
	tbPos point = tbTransformWorldPoint(xf, struck);
	// The public entry checks the result is finite and wakes the body. A recording holds the
	// explosion, not its impulses (replaying both would push twice): it is set aside meanwhile.
	struct tbRecording* recording = world->recording;
	world->recording = NULL;
	tbBody_ApplyLinearImpulse(tbMakeBodyId(world, shape->bodyId), impulse, point, true);
	world->recording = recording;
	return true;
}

void tbWorld_Explode(tbWorldId worldId, const tbExplosionDef* def)
{
	TB_RECORD(WorldExplode, &worldId, def);
	const char* f = "tbWorld_Explode";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL || tbCheckPointer(f, "def", def) == false)
	{
		return;
	}
	if (tbCheckPosition(f, "def->position", def->position) == false ||
		tbCheckNonNegative(f, "def->radius", def->radius) == false ||
		tbCheckNonNegative(f, "def->falloff", def->falloff) == false ||
		tbCheckFloat(f, "def->impulsePerLength", def->impulsePerLength) == false)
	{
		return;
	}
	if (world->locked)
	{
		tbReportError(f, "the world is locked (stepping); explode between steps");
		return;
	}
	float extent = def->radius + def->falloff;
	if (extent > TB_MAX_COORDINATE)
	{
		tbReportError(f, "def->radius + def->falloff is %g m, beyond the world's extent %g m",
					  (double)extent, (double)TB_MAX_COORDINATE);
		return;
	}
	tbExplosionContext context = {world, *def};
	tbAABB reach = {{-extent, -extent}, {extent, extent}};
	tbAABB box = tbOffsetAABB(reach, def->position);
	world->queryDepth += 1; // the callback changes velocities only (see tbStructureLocked)
	tbBroadPhase_Query(&world->broadPhase, box, def->maskBits, tbExplosionCallback, &context);
	world->queryDepth -= 1;
}
