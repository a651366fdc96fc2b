// Debug drawing: the library walks the world and calls the user's draw functions (tbDebugDraw).
// The headless PNG renderer in samples/ is one implementation of those callbacks.
#include "world.h"

#include "draw.h"

#include "core/union_find.h"
#include "joints/joint.h"
#include "solver/constraint_graph.h"

#include <float.h>
#include <stdio.h>
#include <string.h>

// Graph colours for debug views: a walk round the hue circle in 24 steps (neighbouring colours
// differ, so contacts of adjacent colours stand apart), and grey for the overflow.
static const tbHexColor s_graphColors[TB_GRAPH_COLOR_COUNT + 1] = {
	tb_colorRed,		  tb_colorOrangeRed,	  tb_colorDarkOrange,  tb_colorOrange,		 tb_colorGold,
	tb_colorYellow,		  tb_colorGreenYellow,	  tb_colorLawnGreen,   tb_colorLimeGreen,	 tb_colorSpringGreen,
	tb_colorMediumSeaGreen, tb_colorLightSeaGreen, tb_colorTurquoise,  tb_colorDarkTurquoise, tb_colorDeepSkyBlue,
	tb_colorDodgerBlue,	  tb_colorRoyalBlue,	  tb_colorBlue,		   tb_colorSlateBlue,	 tb_colorBlueViolet,
	tb_colorDarkViolet,	  tb_colorMagenta,		  tb_colorDeepPink,	   tb_colorCrimson,		 tb_colorGray,
};

tbHexColor tbGetGraphColor(int index)
{
	if (index < 0 || index > TB_GRAPH_COLOR_COUNT)
	{
		tbReportError("tbGetGraphColor", "index is %d (must be 0..%d; %d is the overflow)", index,
					  TB_GRAPH_COLOR_COUNT, TB_GRAPH_COLOR_COUNT);
		return tb_colorBlack;
	}
	return s_graphColors[index];
}

static tbHexColor tbBodyColor(const tbBody* body, const tbShape* shape)
{
	if (shape->material.customColor != 0u)
	{
		return (tbHexColor)shape->material.customColor; // the game's choice (tbSurfaceMaterial::customColor)
	}
	if (body->type == tb_staticBody)
	{
		return tb_colorStatic;
	}
	if (body->awakeIndex == TB_NULL_INDEX)
	{
		return tb_colorSleeping;
	}
	if (body->type == tb_kinematicBody)
	{
		return tb_colorKinematic;
	}
	// A stable per-body hue from its id so neighbouring bodies are told apart.
	static const uint32_t palette[6] = {0x4E79A7, 0xF28E2B, 0xE15759, 0x76B7B2, 0xEDC948, 0xB07AA1};
	return (tbHexColor)palette[(uint32_t)(body->headShapeId * 2654435761u) % 6u];
}

// tbDefaultDebugDraw's functions: each draws nothing, so a game sets only the ones it implements.
static void tbNoPolygon(tbWorldTransform t, const tbVec2* v, int n, tbHexColor c, void* context)
{
	(void)t, (void)v, (void)n, (void)c, (void)context;
}
static void tbNoSolidPolygon(tbWorldTransform t, const tbVec2* v, int n, float r, tbHexColor c, void* context)
{
	(void)t, (void)v, (void)n, (void)r, (void)c, (void)context;
}
static void tbNoCircle(tbPos p, float r, tbHexColor c, void* context)
{
	(void)p, (void)r, (void)c, (void)context;
}
static void tbNoSolidCircle(tbWorldTransform t, tbVec2 p, float r, tbHexColor c, void* context)
{
	(void)t, (void)p, (void)r, (void)c, (void)context;
}
static void tbNoCapsule(tbPos a, tbPos b, float r, tbHexColor c, void* context)
{
	(void)a, (void)b, (void)r, (void)c, (void)context;
}
static void tbNoLine(tbPos a, tbPos b, tbHexColor c, void* context)
{
	(void)a, (void)b, (void)c, (void)context;
}
static void tbNoTransform(tbWorldTransform t, void* context)
{
	(void)t, (void)context;
}
static void tbNoPoint(tbPos p, float size, tbHexColor c, void* context)
{
	(void)p, (void)size, (void)c, (void)context;
}
static void tbNoString(tbPos p, const char* s, tbHexColor c, void* context)
{
	(void)p, (void)s, (void)c, (void)context;
}
static void tbNoBounds(tbAABB box, tbHexColor c, void* context)
{
	(void)box, (void)c, (void)context;
}

tbDebugDraw tbDefaultDebugDraw(void)
{
	tbDebugDraw draw;
	memset(&draw, 0, sizeof(draw));
	draw.DrawPolygonFcn = tbNoPolygon;
	draw.DrawSolidPolygonFcn = tbNoSolidPolygon;
	draw.DrawCircleFcn = tbNoCircle;
	draw.DrawSolidCircleFcn = tbNoSolidCircle;
	draw.DrawSolidCapsuleFcn = tbNoCapsule;
	draw.DrawLineFcn = tbNoLine;
	draw.DrawTransformFcn = tbNoTransform;
	draw.DrawPointFcn = tbNoPoint;
	draw.DrawStringFcn = tbNoString;
	draw.DrawBoundsFcn = tbNoBounds;
	draw.drawingBounds = (tbAABB){{-FLT_MAX, -FLT_MAX}, {FLT_MAX, FLT_MAX}};
	draw.forceScale = 1.0f;
	draw.jointScale = 1.0f;
	draw.drawShapes = true;
	return draw;
}

static void tbDrawBounds(const tbDebugDraw* draw, tbAABB box, tbHexColor color)
{
	if (draw->DrawBoundsFcn != NULL)
	{
		draw->DrawBoundsFcn(box, color, draw->context);
	}
}

/// The chain's outward side is its right (solid on the left of each segment's direction).
static void tbDrawChainNormal(const tbDebugDraw* draw, tbTransform xf, tbVec2 p1, tbVec2 p2)
{
	tbVec2 a = tbTransformPoint(xf, p1);
	tbVec2 b = tbTransformPoint(xf, p2);
	tbVec2 mid = tbLerp(a, b, 0.5f);
	tbVec2 n = tbRightPerp(tbNormalize(tbSub(b, a)));
	tbDrawLine(draw, mid, tbMulAdd(mid, 0.5f, n), tb_colorNormal);
}

static void tbDrawShape(const tbDebugDraw* draw, const tbShape* shape, tbWorldTransform transform, tbHexColor color)
{
	const tbGeometry* g = &shape->geometry;
	tbTransform xf = tbRoundTransform(transform);
	switch (g->type)
	{
		case tb_circleShape:
			if (draw->DrawSolidCircleFcn != NULL)
			{
				draw->DrawSolidCircleFcn(transform, g->circle.center, g->circle.radius, color, draw->context);
			}
			break;
		case tb_capsuleShape:
			if (draw->DrawSolidCapsuleFcn != NULL)
			{
				draw->DrawSolidCapsuleFcn(tbTransformWorldPoint(transform, g->capsule.center1),
										  tbTransformWorldPoint(transform, g->capsule.center2), g->capsule.radius, color,
										  draw->context);
			}
			break;
		case tb_segmentShape:
			tbDrawLine(draw, tbTransformPoint(xf, g->segment.point1), tbTransformPoint(xf, g->segment.point2), color);
			break;
		case tb_chainSegmentShape:
			tbDrawLine(draw, tbTransformPoint(xf, g->chainSegment.segment.point1),
					   tbTransformPoint(xf, g->chainSegment.segment.point2), color);
			if (draw->drawChainNormals)
			{
				tbDrawChainNormal(draw, xf, g->chainSegment.segment.point1, g->chainSegment.segment.point2);
			}
			break;
		case tb_polygonShape:
			if (draw->DrawSolidPolygonFcn != NULL)
			{
				draw->DrawSolidPolygonFcn(transform, g->polygon.vertices, g->polygon.count, g->polygon.radius, color,
										  draw->context);
			}
			break;
		default:
			break;
	}
}

static void tbDrawTreeNode(tbAABB aabb, int depth, bool isLeaf, void* context)
{
	(void)depth;
	if (isLeaf == false)
	{
		tbDrawBounds(context, aabb, tb_colorTree);
	}
}

/// Mass (drawMass) and name (drawBodyNames) of the bodies with a shape in view.
static void tbDrawBodies(tbWorld* world, const tbDebugDraw* draw, const uint8_t* inView)
{
	for (int i = 0; i < world->bodyPool.highWater; ++i)
	{
		const tbBody* body = world->bodies + i;
		if (body->inUse == false || inView[i] == 0)
		{
			continue;
		}
		tbWorldTransform frame = {body->center, body->transform.q};
		tbVec2 label = tbToVec2(tbTransformWorldPoint(frame, tbMakeVec2(0.1f, 0.1f)));
		if (draw->drawBodyNames && body->name != NULL && body->name[0] != 0)
		{
			tbDrawStringAt(draw, label, body->name, tb_colorBlueViolet);
		}
		if (draw->drawMass && body->type == tb_dynamicBody)
		{
			// The centre of mass's path this step, its frame, and the mass in kg.
			tbDrawLine(draw, tbToVec2(body->center0), tbToVec2(body->center), tb_colorWhiteSmoke);
			if (draw->DrawTransformFcn != NULL)
			{
				draw->DrawTransformFcn(frame, draw->context);
			}
			char text[32];
			snprintf(text, sizeof(text), "%.2f kg", (double)body->mass);
			tbDrawStringAt(draw, label, text, tb_colorWhite);
		}
	}
}

/// Contact points and what the view asks about them. The point is the manifold's at body B's
/// anchor (or A's, drawAnchorA), coloured by graph colour (drawGraphColors, when the last step
/// coloured its contacts) or else by state: speculative (apart by more than the linear slop),
/// new this step, persisted.
static void tbDrawContacts(tbWorld* world, const tbDebugDraw* draw, const uint8_t* inView)
{
	int n = world->cache.solverContactCount;
	int* colorById = NULL;
	int colorBytes = (int)sizeof(int) * tbMaxInt(world->contactPool.highWater, 1);
	if (draw->drawGraphColors && n > 0)
	{
		int* ordinalColors = tbAlloc((int)sizeof(int) * n);
		if (tbGetContactGraphColors(world, ordinalColors, NULL))
		{
			colorById = tbAlloc(colorBytes);
			for (int i = 0; i < world->contactPool.highWater; ++i)
			{
				colorById[i] = -1;
			}
			for (int i = 0; i < n; ++i)
			{
				colorById[world->cache.solverContactsById[i]] = ordinalColors[i];
			}
		}
		tbFree(ordinalColors, (int)sizeof(int) * n);
	}
	float invStep = world->stepTime > 0.0f ? 1.0f / world->stepTime : 0.0f;
	float invSubStep = world->jointInvH; // the last step's sub-step rate (joint.c keeps it)
	char text[32];
	for (int i = 0; i < world->contactPool.highWater; ++i)
	{
		const tbContact* contact = world->contacts + i;
		if (contact->inUse == false || (contact->flags & tb_contactTouching) == 0)
		{
			continue;
		}
		const tbBody* bodyA = world->bodies + contact->edges[0].bodyId;
		const tbBody* bodyB = world->bodies + contact->edges[1].bodyId;
		if (inView[contact->edges[0].bodyId] == 0 && inView[contact->edges[1].bodyId] == 0)
		{
			continue;
		}
		tbVec2 normal = contact->manifold.normal;
		for (int j = 0; j < contact->manifold.pointCount; ++j)
		{
			const tbManifoldPoint* mp = contact->manifold.points + j;
			tbVec2 p = draw->drawAnchorA ? tbToVec2(tbOffsetPos(bodyA->center, mp->anchorA))
										 : tbToVec2(tbOffsetPos(bodyB->center, mp->anchorB));
			if (draw->drawContacts)
			{
				if (colorById != NULL && colorById[i] >= 0)
				{
					float size = colorById[i] == TB_GRAPH_COLOR_COUNT ? 7.5f : 5.0f;
					tbDrawPointAt(draw, p, size, tbGetGraphColor(colorById[i]));
				}
				else if (mp->separation > TB_LINEAR_SLOP)
				{
					tbDrawPointAt(draw, p, 5.0f, tb_colorGainsboro);
				}
				else if (mp->persisted == false)
				{
					tbDrawPointAt(draw, p, 10.0f, tb_colorGreen);
				}
				else
				{
					tbDrawPointAt(draw, p, 5.0f, tb_colorBlue);
				}
			}
			if (draw->drawContactNormals)
			{
				tbDrawLine(draw, p, tbMulAdd(p, 0.3f, normal), tb_colorDimGray);
				snprintf(text, sizeof(text), " %.3f", (double)mp->separation);
				tbDrawStringAt(draw, p, text, tb_colorWhite);
			}
			if (draw->drawContactForces)
			{
				// The step's mean normal force: all it applied (totalNormalImpulse) over Δt.
				float force = mp->totalNormalImpulse * invStep;
				tbDrawLine(draw, p, tbMulAdd(p, draw->forceScale * force, normal), tb_colorMagenta);
				snprintf(text, sizeof(text), "%.1f", (double)force);
				tbDrawStringAt(draw, p, text, tb_colorWhite);
			}
			if (draw->drawContactFeatures)
			{
				snprintf(text, sizeof(text), "%d", (int)mp->id);
				tbDrawStringAt(draw, p, text, tb_colorOrange);
			}
			if (draw->drawFrictionForces)
			{
				// The friction impulse of the last sub-step over that sub-step.
				float force = mp->tangentImpulse * invSubStep;
				tbDrawLine(draw, p, tbMulAdd(p, draw->forceScale * force, tbRightPerp(normal)), tb_colorYellow);
				snprintf(text, sizeof(text), "%.1f", (double)force);
				tbDrawStringAt(draw, p, text, tb_colorWhite);
			}
		}
	}
	if (colorById != NULL)
	{
		tbFree(colorById, colorBytes);
	}
}

/// Islands of awake bodies: joined by touching contacts and joints between two awake bodies (a
/// static or sleeping body joins nothing, as in the sleep stage), each drawn as the box of its
/// bodies' shapes.
static void tbDrawIslands(tbWorld* world, const tbDebugDraw* draw)
{
	int n = world->bodyPool.highWater;
	if (n == 0)
	{
		return;
	}
	int* parent = tbAlloc((int)sizeof(int) * n);
	tbAABB* boxes = tbAlloc((int)sizeof(tbAABB) * n);
	for (int i = 0; i < n; ++i)
	{
		parent[i] = i;
	}
	for (int i = 0; i < world->contactPool.highWater; ++i)
	{
		const tbContact* c = world->contacts + i;
		if (c->inUse && (c->flags & tb_contactTouching) != 0 && (c->flags & tb_contactSensor) == 0)
		{
			int a = c->edges[0].bodyId, b = c->edges[1].bodyId;
			if (world->bodies[a].awakeIndex != TB_NULL_INDEX && world->bodies[b].awakeIndex != TB_NULL_INDEX)
			{
				tbLinkRoots(parent, a, b);
			}
		}
	}
	for (int i = 0; i < world->jointPool.highWater; ++i)
	{
		const tbJoint* joint = world->joints + i;
		if (joint->inUse)
		{
			int a = joint->edges[0].bodyId, b = joint->edges[1].bodyId;
			if (world->bodies[a].awakeIndex != TB_NULL_INDEX && world->bodies[b].awakeIndex != TB_NULL_INDEX)
			{
				tbLinkRoots(parent, a, b);
			}
		}
	}
	tbAABB empty = {{FLT_MAX, FLT_MAX}, {-FLT_MAX, -FLT_MAX}};
	for (int i = 0; i < n; ++i)
	{
		boxes[i] = empty;
	}
	for (int i = 0; i < world->shapePool.highWater; ++i)
	{
		const tbShape* shape = world->shapes + i;
		if (shape->inUse && world->bodies[shape->bodyId].awakeIndex != TB_NULL_INDEX)
		{
			int root = tbFindRoot(parent, shape->bodyId);
			boxes[root] = tbAABB_Union(boxes[root], shape->aabb);
		}
	}
	for (int i = 0; i < n; ++i)
	{
		if (parent[i] == i && boxes[i].lowerBound.x <= boxes[i].upperBound.x)
		{
			tbDrawBounds(draw, boxes[i], tb_colorOrchid);
		}
	}
	tbFree(boxes, (int)sizeof(tbAABB) * n);
	tbFree(parent, (int)sizeof(int) * n);
}

void tbWorld_Draw(tbWorldId worldId, tbDebugDraw* draw)
{
	const char* f = "tbWorld_Draw";
	tbWorld* world = tbGetWorldChecked(worldId, f);
	if (world == NULL || tbCheckPointer(f, "draw", draw) == false)
	{
		return;
	}
	if (world->locked)
	{
		tbReportError(f, "called during the step; draw after tbWorld_Step returns");
		return;
	}
	// Written so that NaN fails.
	if (!(draw->forceScale >= 0.0f && draw->forceScale <= FLT_MAX && draw->jointScale >= 0.0f &&
		  draw->jointScale <= FLT_MAX) ||
		tbIsValidAABB(draw->drawingBounds) == false)
	{
		tbReportError(f, "draw->forceScale is %g and draw->jointScale %g (each finite and ≥ 0), or draw->drawingBounds "
						 "is not a box (finite, lower ≤ upper); start from tbDefaultDebugDraw()",
					  (double)draw->forceScale, (double)draw->jointScale);
		return;
	}
	// The bodies with a shape in view: their masses, names and contacts are drawn.
	int bodyBytes = tbMaxInt(world->bodyPool.highWater, 1);
	uint8_t* inView = tbAlloc(bodyBytes);
	memset(inView, 0, (size_t)bodyBytes);
	for (int i = 0; i < world->shapePool.highWater; ++i)
	{
		const tbShape* shape = world->shapes + i;
		if (shape->inUse == false || tbAABB_Overlaps(draw->drawingBounds, shape->fatAABB) == false)
		{
			continue;
		}
		const tbBody* body = world->bodies + shape->bodyId;
		inView[shape->bodyId] = 1;
		if (draw->drawShapes)
		{
			tbDrawShape(draw, shape, body->transform, tbBodyColor(body, shape));
		}
		if (draw->drawBounds)
		{
			tbDrawBounds(draw, shape->fatAABB, tb_colorGold);
		}
	}
	if (draw->drawTree)
	{
		tbBroadPhase_VisitTreeNodes(&world->broadPhase, tbDrawTreeNode, (void*)draw);
	}
	if (draw->drawMass || draw->drawBodyNames)
	{
		tbDrawBodies(world, draw, inView);
	}
	if (draw->drawContacts || draw->drawContactNormals || draw->drawContactForces || draw->drawContactFeatures ||
		draw->drawFrictionForces)
	{
		tbDrawContacts(world, draw, inView);
	}
	tbDrawJoints(world, draw); // joint.c (when drawJoints)
	if (draw->drawIslands)
	{
		tbDrawIslands(world, draw);
	}
	tbFree(inView, bodyBytes);
}
