// Debug drawing: the library walks the world and calls the user's draw functions (tbDebugDraw).
// The headless PNG renderer in samples/ is one implementation of those callbacks.
#include "world.h"

#include "joints/joint.h"

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

static uint32_t tbBodyColor(const tbBody* body, const tbShape* shape)
{
	if (shape->material.customColor != 0u)
	{
		return shape->material.customColor; // the game's choice (tbSurfaceMaterial::customColor)
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
	return palette[(uint32_t)(body->headShapeId * 2654435761u) % 6u];
}

static void tbDrawShape(const tbDebugDraw* draw, const tbShape* shape, tbTransform xf, uint32_t color)
{
	const tbGeometry* g = &shape->geometry;
	switch (g->type)
	{
		case tb_circleShape:
			if (draw->DrawSolidCircle != NULL)
			{
				tbTransform t = {tbTransformPoint(xf, g->circle.center), xf.q};
				draw->DrawSolidCircle(t, g->circle.radius, color, draw->context);
			}
			break;
		case tb_capsuleShape:
			if (draw->DrawSolidCapsule != NULL)
			{
				draw->DrawSolidCapsule(tbTransformPoint(xf, g->capsule.center1), tbTransformPoint(xf, g->capsule.center2),
									   g->capsule.radius, color, draw->context);
			}
			break;
		case tb_segmentShape:
			if (draw->DrawSegment != NULL)
			{
				draw->DrawSegment(tbTransformPoint(xf, g->segment.point1), tbTransformPoint(xf, g->segment.point2), color,
								  draw->context);
			}
			break;
		case tb_chainSegmentShape:
			if (draw->DrawSegment != NULL)
			{
				draw->DrawSegment(tbTransformPoint(xf, g->chainSegment.segment.point1),
								  tbTransformPoint(xf, g->chainSegment.segment.point2), color, draw->context);
			}
			break;
		case tb_polygonShape:
			if (draw->DrawSolidPolygon != NULL)
			{
				draw->DrawSolidPolygon(xf, g->polygon.vertices, g->polygon.count, g->polygon.radius, color,
									   draw->context);
			}
			break;
		default:
			break;
	}
}

static void tbDrawBox(const tbDebugDraw* draw, tbAABB box, uint32_t color)
{
	if (draw->DrawPolygon == NULL)
	{
		return;
	}
	tbVec2 v[4] = {box.lowerBound, {box.upperBound.x, box.lowerBound.y}, box.upperBound, {box.lowerBound.x, box.upperBound.y}};
	draw->DrawPolygon(v, 4, color, draw->context);
}

static void tbDrawTreeNode(tbAABB aabb, int depth, bool isLeaf, void* context)
{
	(void)depth;
	if (isLeaf == false)
	{
		tbDrawBox(context, aabb, tb_colorTree);
	}
}

static void tbDrawContacts(tbWorld* world, const tbDebugDraw* draw)
{
	for (int i = 0; i < world->contactPool.highWater; ++i)
	{
		const tbContact* contact = world->contacts + i;
		if (contact->inUse == false || (contact->flags & tb_contactTouching) == 0)
		{
			continue;
		}
		for (int j = 0; j < contact->manifold.pointCount; ++j)
		{
			tbVec2 p = contact->manifold.points[j].point;
			if (draw->drawContacts && draw->DrawPoint != NULL)
			{
				draw->DrawPoint(p, 5.0f, tb_colorContact, draw->context);
			}
			if (draw->drawContactNormals && draw->DrawSegment != NULL)
			{
				draw->DrawSegment(p, tbMulAdd(p, 0.3f, contact->manifold.normal), tb_colorNormal, draw->context);
			}
		}
	}
}

void tbWorld_Draw(tbWorldId worldId, tbDebugDraw* draw)
{
	tbWorld* world = tbGetWorldChecked(worldId, "tbWorld_Draw");
	if (world == NULL || tbCheckPointer("tbWorld_Draw", "draw", draw) == false)
	{
		return;
	}
	for (int i = 0; i < world->shapePool.highWater; ++i)
	{
		const tbShape* shape = world->shapes + i;
		if (shape->inUse == false)
		{
			continue;
		}
		const tbBody* body = world->bodies + shape->bodyId;
		if (draw->useDrawingBounds && tbAABB_Overlaps(draw->drawingBounds, shape->fatAABB) == false)
		{
			continue;
		}
		if (draw->drawShapes)
		{
			tbDrawShape(draw, shape, tbRoundTransform(body->transform), tbBodyColor(body, shape));
		}
		if (draw->drawAABBs)
		{
			tbDrawBox(draw, shape->fatAABB, tb_colorAABB);
		}
	}
	if (draw->drawTree)
	{
		tbBroadPhase_VisitTreeNodes(&world->broadPhase, tbDrawTreeNode, (void*)draw);
	}
	if (draw->drawContacts || draw->drawContactNormals)
	{
		tbDrawContacts(world, draw);
	}
	tbDrawJoints(world, draw); // joint.c (when drawJoints)
}
