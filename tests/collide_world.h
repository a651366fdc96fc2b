// World-frame forms of the pair routines for the tests: each places B in A's frame
// (xf = A⁻¹·B), calls the public local-form routine (Box2D v3.2's signature) and moves the
// manifold to the world by A's transform, the same arithmetic the narrow phase uses, so a world
// manifold here is bit-identical to the world's. C and C++ (the verification tests use it).
#pragma once

#include "tumble/collision.h"
#include "tumble/math_functions.h"

#include <string.h>

static inline tbManifold WorldManifold(tbLocalManifold local, tbTransform xfA)
{
	tbManifold m;
	memset(&m, 0, sizeof(m));
	m.normal = tbRotateVector(xfA.q, local.normal);
	m.pointCount = local.pointCount;
	for (int i = 0; i < local.pointCount; ++i)
	{
		m.points[i].point = tbTransformPoint(xfA, local.points[i].point);
		m.points[i].separation = local.points[i].separation;
		m.points[i].id = local.points[i].id;
	}
	return m;
}

static inline tbManifold WorldCollideCircles(const tbCircle* a, tbTransform xfA, const tbCircle* b, tbTransform xfB)
{
	return WorldManifold(tbCollideCircles(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollideCapsuleAndCircle(const tbCapsule* a, tbTransform xfA, const tbCircle* b, tbTransform xfB)
{
	return WorldManifold(tbCollideCapsuleAndCircle(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollideSegmentAndCircle(const tbSegment* a, tbTransform xfA, const tbCircle* b, tbTransform xfB)
{
	return WorldManifold(tbCollideSegmentAndCircle(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollidePolygonAndCircle(const tbPolygon* a, tbTransform xfA, const tbCircle* b, tbTransform xfB)
{
	return WorldManifold(tbCollidePolygonAndCircle(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollideCapsules(const tbCapsule* a, tbTransform xfA, const tbCapsule* b, tbTransform xfB)
{
	return WorldManifold(tbCollideCapsules(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollideSegmentAndCapsule(const tbSegment* a, tbTransform xfA, const tbCapsule* b, tbTransform xfB)
{
	return WorldManifold(tbCollideSegmentAndCapsule(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollidePolygonAndCapsule(const tbPolygon* a, tbTransform xfA, const tbCapsule* b, tbTransform xfB)
{
	return WorldManifold(tbCollidePolygonAndCapsule(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollidePolygons(const tbPolygon* a, tbTransform xfA, const tbPolygon* b, tbTransform xfB)
{
	return WorldManifold(tbCollidePolygons(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollideSegmentAndPolygon(const tbSegment* a, tbTransform xfA, const tbPolygon* b, tbTransform xfB)
{
	return WorldManifold(tbCollideSegmentAndPolygon(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollidePolygonsGJK(const tbPolygon* a, tbTransform xfA, const tbPolygon* b, tbTransform xfB)
{
	return WorldManifold(tbCollidePolygonsGJK(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollideChainSegmentAndCircle(const tbChainSegment* a, tbTransform xfA, const tbCircle* b, tbTransform xfB)
{
	return WorldManifold(tbCollideChainSegmentAndCircle(a, b, tbInvMulTransforms(xfA, xfB)), xfA);
}

static inline tbManifold WorldCollideChainSegmentAndCapsule(const tbChainSegment* a, tbTransform xfA, const tbCapsule* b,
															tbTransform xfB)
{
	return WorldManifold(tbCollideChainSegmentAndCapsule(a, b, tbInvMulTransforms(xfA, xfB), NULL), xfA);
}

static inline tbManifold WorldCollideChainSegmentAndPolygon(const tbChainSegment* a, tbTransform xfA, const tbPolygon* b,
															tbTransform xfB)
{
	return WorldManifold(tbCollideChainSegmentAndPolygon(a, b, tbInvMulTransforms(xfA, xfB), NULL), xfA);
}
