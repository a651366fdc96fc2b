// Wind: the force of a moving air mass on a shape (Box2D v3.2's b2Shape_ApplyWind).
//
// Flow. The air moves at `wind`; the shape's centroid at v = vB + ωB × r (r from the body's centre
// of mass to the centroid). The flow the shape sees is u = wind − drag·v: drag = 1 gives the true
// relative velocity, drag = 0 a shape that does not notice its own motion (v3's meaning of the drag
// coefficient). With û = u/|u| and the dynamic pressure q = ½·ρ·|u|² (ρ = 1.225 kg/m³, sea-level
// air; in 2D per metre of depth), a face of width w seen by the flow takes
//     F = q·w·(û + lift·ℓ),   ℓ = (n × û)·perp(û),
// where n is the face's outward normal and perp(û) the flow turned a quarter left: ℓ is the part of
// the flow across the face, signed so that a face tilted into the flow is pushed sideways (lift), and
// vanishes for a face square to the flow. The force acts at the face, so it also turns the body:
// τ = (p − c) × F about the centre of mass c.
//
// Faces per shape:
// - circle: width 2r, no face direction (no lift), at the centre;
// - capsule: width 2r + |d × û| (the two caps and the flat side's projection, d the axis), its face
//   the flat side that faces the flow, acting r off the centroid along that side's normal;
// - polygon: each edge e (counter-clockwise) with outward normal n = rightPerp(ê) facing the flow,
//   n·û < 0, whose projected width is w = e × û = |e|·(−n·û) > 0, acting at the edge's midpoint
//   (the rounding radius is ignored, as in v3).
// Segments and chain segments are one-sided boundaries of no area: no wind.
#include "world.h"
#include "recording.h"

/// Density of air at sea level and 15 °C (kg/m³, ISA), per cubed length unit (tbSetLengthUnitsPerMeter).
#define TB_AIR_DENSITY (1.225f / (tbGetLengthUnitsPerMeter() * tbGetLengthUnitsPerMeter() * tbGetLengthUnitsPerMeter()))

/// The force of flow û at pressure q on a face of width w and normal n, lift-weighted (see above).
static tbVec2 tbFaceForce(float q, float width, tbVec2 direction, tbVec2 normal, float lift)
{
	tbVec2 across = tbMulSV(tbCross(normal, direction), tbLeftPerp(direction));
	return tbMulSV(q * width, tbMulAdd(direction, lift, across));
}

/// The flow a shape meets: its direction û, the dynamic pressure q = ½ρ|u|² (0: no flow), and the
/// lever from the body's centre of mass to the shape's centroid (world axes).
typedef struct tbFlow
{
	tbVec2 direction;
	float pressure;
	tbVec2 lever;
} tbFlow;

static tbFlow tbFlowAt(const tbShape* shape, const tbBody* body, tbVec2 wind, float drag)
{
	const tbGeometry* g = &shape->geometry;
	tbVec2 localCentroid = g->type == tb_circleShape	? g->circle.center
						   : g->type == tb_capsuleShape ? tbLerp(g->capsule.center1, g->capsule.center2, 0.5f)
														: g->polygon.centroid;
	tbFlow flow;
	flow.lever = tbSubPos(tbTransformWorldPoint(body->transform, localCentroid), body->center);
	tbVec2 v = tbAdd(body->linearVelocity, tbCrossSV(body->angularVelocity, flow.lever));
	float speed;
	flow.direction = tbGetLengthAndNormalize(&speed, tbMulSub(wind, drag, v));
	flow.pressure = 0.5f * TB_AIR_DENSITY * speed * speed;
	return flow;
}

/// Capsule: one face, the flat side the flow meets, of width 2r + |d × û|, pushed r off the centroid.
static void tbWindOnCapsule(const tbCapsule* c, tbRot q, const tbFlow* flow, float lift, tbVec2* force, float* torque)
{
	tbVec2 d = tbRotateVector(q, tbSub(c->center2, c->center1));
	tbVec2 n = tbLeftPerp(tbNormalize(d));
	n = tbDot(n, flow->direction) > 0.0f ? tbNeg(n) : n;
	float width = 2.0f * c->radius + tbAbsFloat(tbCross(d, flow->direction));
	*force = tbFaceForce(flow->pressure, width, flow->direction, n, lift);
	*torque = tbCross(tbMulAdd(flow->lever, c->radius, n), *force);
}

/// Polygon: each edge facing the flow (width e × û > 0), pushed at its midpoint.
static void tbWindOnPolygon(const tbPolygon* p, const tbBody* body, const tbFlow* flow, float lift, tbVec2* force,
							float* torque)
{
	tbWorldTransform xf = body->transform;
	for (int i = 0; i < p->count; ++i)
	{
		tbVec2 a = p->vertices[i];
		tbVec2 b = p->vertices[i + 1 < p->count ? i + 1 : 0];
		tbVec2 e = tbRotateVector(xf.q, tbSub(b, a));
		float width = tbCross(e, flow->direction);
		if (width <= 0.0f)
		{
			continue; // faces away from the flow (or edge-on)
		}
		tbVec2 f = tbFaceForce(flow->pressure, width, flow->direction, tbRightPerp(tbNormalize(e)), lift);
		tbVec2 arm = tbSubPos(tbTransformWorldPoint(xf, tbLerp(a, b, 0.5f)), body->center);
		*force = tbAdd(*force, f);
		*torque += tbCross(arm, f);
	}
}

/// The wind's force and torque (about the centre of mass) on one shape whose body is `body`.
static void tbWindOnShape(const tbShape* shape, const tbBody* body, tbVec2 wind, float drag, float lift, tbVec2* force,
						  float* torque)
{
	const tbGeometry* g = &shape->geometry;
	tbFlow flow = tbFlowAt(shape, body, wind, drag);
	*force = tbVec2_zero;
	*torque = 0.0f;
	if (flow.pressure == 0.0f)
	{
		return;
	}
	if (g->type == tb_circleShape)
	{
		*force = tbMulSV(flow.pressure * 2.0f * g->circle.radius, flow.direction); // width 2r, at the centre
		*torque = tbCross(flow.lever, *force);
	}
	else if (g->type == tb_capsuleShape)
	{
		tbWindOnCapsule(&g->capsule, body->transform.q, &flow, lift, force, torque);
	}
	else
	{
		tbWindOnPolygon(&g->polygon, body, &flow, lift, force, torque);
	}
}

bool tbShape_ApplyWind(tbShapeId shapeId, tbVec2 wind, float drag, float lift, bool wake)
{
	TB_RECORD(ShapeApplyWind, &shapeId, &wind, &drag, &lift, &wake);
	const char* f = "tbShape_ApplyWind";
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, f, &world, true);
	if (shape == NULL || tbCheckVec2(f, "wind", wind) == false || tbCheckNonNegative(f, "drag", drag) == false ||
		tbCheckFloat(f, "lift", lift) == false)
	{
		return false;
	}
	tbShapeType type = shape->geometry.type;
	tbBody* body = world->bodies + shape->bodyId;
	// Ignored without an error, false as for tbBody_ApplyForce: nothing to push.
	if ((type != tb_circleShape && type != tb_capsuleShape && type != tb_polygonShape) ||
		body->type != tb_dynamicBody || body->isDisabled)
	{
		return false;
	}
	if (body->awakeIndex == TB_NULL_INDEX)
	{
		if (wake == false)
		{
			return false;
		}
		tbWakeBody(world, body);
	}
	tbVec2 force;
	float torque;
	tbWindOnShape(shape, body, wind, drag, lift, &force, &torque);
	body->force = tbAdd(body->force, force);
	body->torque += torque;
	return true;
}
