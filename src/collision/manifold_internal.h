// Internal: what the two manifold builders (manifold.c: SAT and clipping; manifold_gjk.c: GJK/EPA)
// share. Both build a manifold in the local frame of shape A, where shapes far from the world
// origin keep their float precision, and move it to the world at the end.
#pragma once

#include "tumble/collision.h"
#include "tumble/math_functions.h"

/// Feature bytes of manifold ids (TB_MAKE_FEATURE_ID(featureOnA, featureOnB)), both builders: a
/// plain index is a vertex touching a face, TB_FEATURE_EDGE | i the edge from vertex i to i + 1,
/// and TB_FEATURE_VERTEX | i on both bytes a corner facing a corner (the closest points of the
/// cores, one point for the pair). Polygons have at most TB_MAX_POLYGON_VERTICES (8) vertices, so
/// the indices stay below the flags.
#define TB_FEATURE_EDGE 0x80
#define TB_FEATURE_VERTEX 0x20
#define TB_FEATURE_FLAGS 0xE0

/// Whether a manifold point is a corner facing a corner (both feature bytes TB_FEATURE_VERTEX).
static inline bool tbIsCornerToCornerId(uint16_t id)
{
	return ((id >> 8) & TB_FEATURE_FLAGS) == TB_FEATURE_VERTEX && (id & TB_FEATURE_FLAGS) == TB_FEATURE_VERTEX;
}

/// The manifold m, computed in A's frame, moved to the world by A's transform.
static inline tbManifold tbManifoldToWorld(tbManifold m, tbTransform xfA)
{
	m.normal = tbRotateVector(xfA.q, m.normal);
	for (int i = 0; i < m.pointCount; ++i)
	{
		m.points[i].point = tbTransformPoint(xfA, m.points[i].point);
	}
	return m;
}

/// Polygon pair by GJK/EPA with B placed in A's frame by xf = A⁻¹·B, keeping points whose
/// separation is below `keep`; the manifold in A's frame (manifold_gjk.c).
tbManifold tbPolygonsGJKFrameA(const tbPolygon* polygonA, const tbPolygon* polygonB, tbTransform xf, float keep);

/// Any pair in routine order (the order the pair routines take them: manifold.c's dispatch rank of
/// a's type at least b's), B placed in A's frame by xf = A⁻¹·B, keeping points whose separation is
/// below `keep`; the manifold in A's frame, its normal from A to B (manifold.c). The narrow phase
/// calls it with the relative transform of the two bodies, taken in the precision of world
/// positions. Written into *m (every field).
void tbCollideOrderedInto(tbManifold* m, const tbGeometry* a, const tbGeometry* b, tbTransform xf,
						  tbNarrowPhaseMethod method, float keep);

/// The manifold of two shapes placed by world transforms (the narrow phase): the pair collided in
/// the frame of the shape the routine takes first, with the relative transform taken in the
/// precision of positions, then moved to the world. Each point's world position also in `points`
/// (the manifold's own point is a float vector: rounded in the large-world build). Written into *m
/// (every field), which may be the contact's own manifold: nothing reads it before it is written.
void tbCollideInWorld(tbManifold* m, const tbGeometry* a, tbWorldTransform xfA, const tbGeometry* b,
					  tbWorldTransform xfB, tbNarrowPhaseMethod method, float keep, tbPos points[2]);

/// The manifold of (B, A) as one of (A, B): normal reversed, feature bytes swapped so that the
/// first names a feature of A. Points and separations do not depend on the order.
tbManifold tbSwapManifoldRoles(tbManifold m);

/// The point, separation and id of each point of m, as Box2D v3.2's local manifold.
tbLocalManifold tbMakeLocalManifold(const tbManifold* m);
