// Internal: what the two manifold builders (manifold.c: SAT and clipping; manifold_gjk.c: GJK/EPA)
// share. Both build a manifold in the local frame of shape A, where shapes far from the world
// origin keep their float precision, and move it to the world at the end.
#pragma once

#include "tumble/collision.h"
#include "tumble/math_functions.h"

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

/// tbCollidePolygonsGJK keeping points whose separation is below `keep` (manifold_gjk.c); the
/// narrow phase calls it through manifold.c's dispatch with the contact's speculative margin.
tbManifold tbCollidePolygonsGJKWithMargin(const tbPolygon* polygonA, tbTransform xfA, const tbPolygon* polygonB,
										  tbTransform xfB, float keep);
