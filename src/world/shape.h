// Internal: a shape as the world keeps it (shape.c), and its bounding boxes.
#pragma once

#include "tumble/collision.h"
#include "tumble/math_functions.h"
#include "tumble/types.h"

#include <stddef.h>

typedef struct tbShape
{
	// Hot in the collide stage, which visits every contact each step (most are only fat-box
	// overlaps, rejected with these fields): first cache line.
	tbAABB aabb; ///< tight world box, updated after each step
	int bodyId;
	int proxyKey;
	bool isSensor;
	bool proxyMoved; ///< finalize: the fat box changed, the proxy is to be moved (shape.c)

	// The geometry in the body frame, also under Box2D v3's names for a shape's fields
	// (shape->type, shape->polygon, ...): two views of the same bytes (C11 anonymous members).
	union
	{
		tbGeometry geometry;
		struct
		{
			tbShapeType type;
			union
			{
				tbCircle circle;
				tbCapsule capsule;
				tbSegment segment;
				tbPolygon polygon;
				tbChainSegment chainSegment;
			};
		};
	};
	void* userData;
	tbAABB fatAABB; ///< the broad-phase box (aabb enlarged by TB_AABB_MARGIN)
	tbFilter filter;
	float density;
	tbSurfaceMaterial material;
	int nextShapeId;
	uint16_t generation;
	bool inUse;
	bool enableSensorEvents;
	bool enableContactEvents;
	bool enableHitEvents;
	bool enableCustomFiltering;
	bool enablePreSolveEvents;
} tbShape;

// The two views of a shape's geometry must be the same bytes: tbGeometry's fields, mirrored above.
_Static_assert(offsetof(tbShape, type) == offsetof(tbShape, geometry) + offsetof(tbGeometry, type),
			   "tbShape.type aliases tbShape.geometry.type");
_Static_assert(offsetof(tbShape, polygon) == offsetof(tbShape, geometry) + offsetof(tbGeometry, polygon),
			   "tbShape's geometry fields alias tbShape.geometry's");
_Static_assert(sizeof(((tbShape*)0)->chainSegment) == sizeof(((tbGeometry*)0)->chainSegment) &&
				   offsetof(tbShape, chainSegment) == offsetof(tbShape, geometry) + offsetof(tbGeometry, chainSegment),
			   "tbShape's geometry fields alias tbShape.geometry's");

/// Tight world box of the shape placed by `transform`.
tbAABB tbComputeShapeAABBInternal(const tbShape* shape, tbWorldTransform transform);

/// The shape's world box enlarged by `extra` (m) on every side: the broad-phase (fat) box.
tbAABB tbComputeFatShapeAABB(const tbShape* shape, tbWorldTransform transform, float extra);
