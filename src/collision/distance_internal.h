// Internal: GJK building blocks shared by distance.c (GJK, shape cast), epa.c (EPA) and
// manifold_gjk.c. Everything here works in one frame, normally the local frame of shape A, so
// that shapes far from the world origin keep their float precision.
#pragma once

#include "tumble/collision.h"

#include <float.h>

/// What tbShapeGapBound takes off (m): 0.2 × linear slop = 0.001 m, plus TB_GAP_SCALE_ALLOWANCE of
/// the largest coordinate of the shapes in A's frame. The first covers the narrow phase's clip slack
/// (manifold.c, TB_CLIP_SLACK = 0.0005 m: a kept point may lie that far beside its face, its
/// separation then up to that much below the distance of the shapes) and GJK's stopping tolerance;
/// the second the narrow phase's rounding, in proportion to its coordinates (16 float epsilons of
/// them: 9.5 mm for a ground 5 km from its body's origin), so that no manifold point can be nearer
/// than the bound says.
#define TB_GAP_ALLOWANCE (0.2f * TB_LINEAR_SLOP)
#define TB_GAP_SCALE_ALLOWANCE (16.0f * FLT_EPSILON)

/// A distance two valid shapes are at least apart, less the allowances above (m, radii included; ≤ 0
/// when they may touch), B placed in A's frame by relative = A⁻¹·B: the distance of the cores,
/// computed with A's first point moved to the origin, by the closed form of tbSegmentDistance when
/// neither is a polygon and by GJK otherwise (GJK stops once its support plane, a lower bound, is
/// within its tolerance of the distance found). The narrow phase keeps a pair apart on it
/// (contact.c, tbStaysApart).
float tbShapeGapBound(const tbGeometry* a, const tbGeometry* b, tbTransform relative);

/// Index of the proxy point furthest along direction (the support mapping of a point cloud).
/// Both proxies have 1..TB_MAX_POLYGON_VERTICES points; otherwise reports to the error hook (an
/// empty proxy is what a refused tbMakeProxy returns) and returns false.
bool tbCheckProxyPair(const char* function, const tbShapeProxy* proxyA, const tbShapeProxy* proxyB);

int tbFindSupport(const tbShapeProxy* proxy, tbVec2 direction);

/// tbMakeProxy without its checks, for points the engine already holds valid (a shape's vertices,
/// 1..TB_MAX_POLYGON_VERTICES of them): the narrow phase makes proxies for every pair it hands to
/// GJK, where the checks cost more than the copy.
tbShapeProxy tbMakeValidProxy(const tbVec2* points, int count, float radius);

/// proxyB with its points mapped by the relative transform A⁻¹·B, i.e. expressed in A's frame.
tbShapeProxy tbMakeRelativeProxy(const tbShapeProxy* proxyB, tbTransform relative);

/// Largest |point| of two proxies in their common frame: the length scale for relative tolerances.
float tbProxyScale(const tbShapeProxy* proxyA, const tbShapeProxy* proxyB);

/// GJK on two proxies given in one frame, radii ignored (core to core). The output points, normal
/// and simplex are in that frame. cache and simplex may be NULL.
tbDistanceOutput tbLocalShapeDistance(const tbShapeProxy* proxyA, const tbShapeProxy* proxyB, tbSimplexCache* cache,
									  tbSimplex* simplex);

/// tbShapeDistance for proxies placed in the world by their transforms, with the answer in the
/// world (the engine's form: continuous collision, queries). simplex may be NULL.
tbDistanceOutput tbShapeDistanceBetween(const tbShapeProxy* proxyA, tbTransform transformA, const tbShapeProxy* proxyB,
										tbTransform transformB, bool useRadii, tbSimplexCache* cache, tbSimplex* simplex);

/// tbShapeCast for proxies placed in the world, B moving by translationB (world); point and normal
/// in the world.
tbCastOutput tbShapeCastBetween(const tbShapeProxy* proxyA, tbTransform transformA, const tbShapeProxy* proxyB,
								tbTransform transformB, tbVec2 translationB, float maxFraction, bool canEncroach);

/// Vertex of the Minkowski difference B − A furthest along direction: s_B(d) − s_A(−d).
tbSimplexVertex tbMakeSupportVertex(const tbShapeProxy* proxyA, const tbShapeProxy* proxyB, tbVec2 direction);
