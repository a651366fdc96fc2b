// Internal: a shape as the world keeps it, its bounding boxes, and what the other parts of the
// world ask of shapes (shape.c). Includes only public headers: Box2D v3's renamed collision test
// includes it by this name (scripts/port-tests.sh).
#pragma once

#include "tumble/collision.h"
#include "tumble/math_functions.h"
#include "tumble/types.h"

#include <stddef.h>

typedef struct tbWorld tbWorld;
typedef struct tbBody tbBody;

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

/// The fat box the finalize stage makes for the shape now, from its body's pose and velocity, when
/// the shape's sweep leaves its fat box (shape.c; a snapshot predicts a stored fat box with it).
tbAABB tbRemadeFatAABB(const tbWorld* world, const tbBody* body, const tbShape* shape);

/// The shape's world box enlarged by `extra` (m) on every side: the broad-phase (fat) box.
tbAABB tbComputeFatShapeAABB(const tbShape* shape, tbWorldTransform transform, float extra);

/// The shape for a shape id and its world, or NULL after reporting an error naming `function`;
/// also refuses a locked world when `mutating`.
tbShape* tbGetShapeChecked(tbShapeId id, const char* function, tbWorld** world, bool mutating);
tbShapeId tbMakeShapeId(const tbWorld* world, int shapeId);

/// `findPairs`: the new proxy looks for the shapes it overlaps at the next step. Movable proxies
/// always do; a static one only when asked (tbShapeDef::invokeContactCreation at creation; always
/// when re-created for a change of geometry, filter, body type or enabling, as Box2D v3.2 does).
void tbCreateShapeProxy(tbWorld* world, tbShape* shape, tbBody* body, bool findPairs);
void tbDestroyShapeProxy(tbWorld* world, tbShape* shape);
bool tbShouldShapesCollide(tbFilter a, tbFilter b);
/// The polygon is strictly convex and counter-clockwise and its normals match its edges (reports
/// nothing: tbCheckGeometry reports, snapshot.c checks an image's polygons with it).
bool tbIsConvexPolygon(const tbPolygon* p);
/// Check user geometry (finite, positive radii, valid polygon); reports an error naming `f`.
bool tbCheckGeometry(const char* f, const tbGeometry* geometry);
/// A surface material's values are usable (finite; friction, restitution, rolling resistance ≥ 0),
/// or an error naming `name`'s field.
bool tbCheckSurfaceMaterial(const char* function, const char* name, const tbSurfaceMaterial* material);
/// The shape's contacts remix their materials (after the shape's material changed).
void tbRemixShapeContacts(tbWorld* world, const tbShape* shape);

/// Which event flag of a shape tbSetShapeEventFlag changes.
typedef enum tbShapeEventKind
{
	tb_shapeEventContacts,
	tb_shapeEventHits,
	tb_shapeEventSensors,
	tb_shapeEventPreSolve,
} tbShapeEventKind;

/// Turn one of a shape's event flags on or off and refresh the flags its contacts hold.
void tbSetShapeEventFlag(tbWorld* world, tbShape* shape, tbShapeEventKind kind, bool flag);

// Shapes added and removed without the public checks (chains check their own input).
/// Add a shape to a body (geometry and def already checked); returns its index.
int tbAddShape(tbWorld* world, int bodyIndex, const tbShapeDef* def, const tbGeometry* geometry);
/// Remove a shape: its contacts, proxy and slot.
void tbRemoveShape(tbWorld* world, int shapeIndex, bool updateBodyMass);
