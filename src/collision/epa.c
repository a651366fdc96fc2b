// Tumble: signed separation of two convex shapes; GJK when the cores are apart, EPA when they
// overlap.
//
// When the cores (the shapes without their radii) are apart, GJK gives the distance d and the
// closest points, and the separation is d − (rA + rB).
//
// When the cores overlap, the origin lies inside the Minkowski difference D = B − A and the
// penetration depth is the distance from the origin to the boundary of D:
//     depth = min over unit n of h_D(n),   h_D(n) = max over w in D of n·w  (the support value).
// The expanding polytope algorithm (van den Bergen, "Proximity queries and penetration depth
// computation on 3D game objects", GDC 2001; "Collision Detection in Interactive 3D
// Environments", 2003, §4.3.8) keeps a convex polygon P ⊂ D, counter-clockwise, starting from
// GJK's final simplex. Each edge has an outward unit normal n and a signed distance n·w from the
// origin. The closest edge gives a lower bound on the depth (P ⊂ D), its support value h_D(n)
// an upper bound; when they meet within a tolerance, the depth is that edge's distance and the
// direction that separates B from A fastest is −n (B must move by −depth·n to clear A), so the
// normal from A to B is −n. Otherwise the support point splits the edge and P grows towards D.
// Signed distances keep this correct when the origin sits just outside P (touching cores): the
// closest edge then has a negative distance, it is expanded first, and a negative final depth is
// simply a tiny positive separation.
//
// A simplex of 1 or 2 points (cores touching at a vertex or along an edge) is not a polygon. The
// initial polygon is then the convex hull of the simplex and the support points along ±x, ±y and
// the edge's ±perpendicular; if D itself is flat or a point (segments on one line, coincident
// circles) the hull has 2 or 1 vertices, and the answer is depth 0 with the segment's
// perpendicular, or A's local y axis, as the normal, so the normal is always a unit vector.
//
// Everything runs in A's local frame (see distance.c), and the results are mapped to world.

#include "core/core.h"
#include "distance_internal.h"

#include "tumble/collision.h"

#include <float.h>

// A pair of 8-gons has at most 16 Minkowski vertices; the degenerate start adds at most a few
// that are not vertices of D. 24 leaves room for both.
#define TB_EPA_MAX_VERTICES (2 * TB_MAX_POLYGON_VERTICES + 8)

// Iteration cap, 24: each iteration adds one vertex, so the cap matches the capacity.
#define TB_EPA_MAX_ITERATIONS TB_EPA_MAX_VERTICES

// Relative tolerance, 16 float ulps (1.9e-6) of the pair's length scale: the gap between the lower
// and upper depth bounds below which the closest edge is accepted, and the core distance below
// which GJK's normal is not trusted and EPA decides (touching cores).
#define TB_EPA_RELATIVE_TOLERANCE (16.0f * FLT_EPSILON)

typedef struct tbPolytope
{
	tbSimplexVertex vertices[TB_EPA_MAX_VERTICES];
	int count;
} tbPolytope;

// Result of EPA in A's frame: deepest points of the cores and the normal from A to B.
typedef struct tbPenetration
{
	tbVec2 pointA;
	tbVec2 pointB;
	tbVec2 normal;
	float depth;
	int iterations;
} tbPenetration;

static bool tbPolytopeContains(const tbPolytope* polytope, const tbSimplexVertex* vertex)
{
	for (int i = 0; i < polytope->count; ++i)
	{
		if (polytope->vertices[i].indexA == vertex->indexA && polytope->vertices[i].indexB == vertex->indexB)
		{
			return true;
		}
	}
	return false;
}

static bool tbLexicographicLess(tbVec2 a, tbVec2 b)
{
	return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// Convex hull of a few candidate vertices by Andrew's monotone chain, counter-clockwise,
// dropping repeated support points and (near-)collinear ones: a turn counts only when
// (b − a) × (c − b) > ε·|b − a|·|c − b| (a turn of more than ε radians), and points closer than
// `tolerance` (a length) to the previous hull point.
static void tbBuildHull(tbPolytope* hull, tbSimplexVertex* points, int count, float tolerance)
{
	// insertion sort by (x, y); count ≤ 8
	for (int i = 1; i < count; ++i)
	{
		tbSimplexVertex key = points[i];
		int j = i - 1;
		while (j >= 0 && tbLexicographicLess(key.w, points[j].w))
		{
			points[j + 1] = points[j];
			--j;
		}
		points[j + 1] = key;
	}

	hull->count = 0;
	tbSimplexVertex chain[2 * 8 + 1];
	int size = 0;
	for (int pass = 0; pass < 2; ++pass)
	{
		int start = size;
		for (int k = 0; k < count; ++k)
		{
			const tbSimplexVertex* p = &points[pass == 0 ? k : count - 1 - k];
			while (size >= start + 2)
			{
				tbVec2 e1 = tbSub(chain[size - 1].w, chain[size - 2].w);
				tbVec2 e2 = tbSub(p->w, chain[size - 1].w);
				if (tbCross(e1, e2) > TB_EPA_RELATIVE_TOLERANCE * tbLength(e1) * tbLength(e2))
				{
					break;
				}
				--size;
			}
			if (size > start && tbDistanceSquared(chain[size - 1].w, p->w) <= tolerance * tolerance)
			{
				continue; // coincident with the last hull point
			}
			chain[size++] = *p;
		}
		--size; // the last point of each chain starts the other one
	}

	if (size <= 0)
	{
		// all candidates coincide
		chain[0] = points[0];
		size = 1;
	}
	for (int i = 0; i < size && hull->count < TB_EPA_MAX_VERTICES; ++i)
	{
		if (tbPolytopeContains(hull, &chain[i]) == false)
		{
			hull->vertices[hull->count++] = chain[i];
		}
	}
}

// Initial polygon from GJK's simplex: the triangle itself (made counter-clockwise), or for a
// 1- or 2-point simplex the hull of it and a few support points around it.
static void tbInitializePolytope(tbPolytope* polytope, const tbSimplex* simplex, const tbShapeProxy* proxyA,
								 const tbShapeProxy* proxyB, float scale)
{
	if (simplex->count == 3)
	{
		bool counterClockwise = tbCross(tbSub(simplex->v2.w, simplex->v1.w), tbSub(simplex->v3.w, simplex->v1.w)) > 0.0f;
		polytope->vertices[0] = simplex->v1;
		polytope->vertices[1] = counterClockwise ? simplex->v2 : simplex->v3;
		polytope->vertices[2] = counterClockwise ? simplex->v3 : simplex->v2;
		polytope->count = 3;
		return;
	}

	tbSimplexVertex candidates[8];
	int count = 0;
	candidates[count++] = simplex->v1;
	tbVec2 directions[6] = {{1.0f, 0.0f}, {-1.0f, 0.0f}, {0.0f, 1.0f}, {0.0f, -1.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}};
	int directionCount = 4;
	if (simplex->count == 2)
	{
		candidates[count++] = simplex->v2;
		tbVec2 perp = tbLeftPerp(tbSub(simplex->v2.w, simplex->v1.w));
		directions[4] = perp;
		directions[5] = tbNeg(perp);
		directionCount = 6;
	}
	for (int i = 0; i < directionCount; ++i)
	{
		candidates[count++] = tbMakeSupportVertex(proxyA, proxyB, directions[i]);
	}

	tbBuildHull(polytope, candidates, count, TB_EPA_RELATIVE_TOLERANCE * scale);
}

// Closest edge of the polygon to the origin: index of its first vertex, outward normal, signed distance.
static int tbFindClosestEdge(const tbPolytope* polytope, tbVec2* normal, float* distance)
{
	int best = 0;
	float bestDistance = FLT_MAX;
	tbVec2 bestNormal = {0.0f, 1.0f};
	for (int i = 0; i < polytope->count; ++i)
	{
		tbVec2 a = polytope->vertices[i].w;
		tbVec2 b = polytope->vertices[(i + 1) % polytope->count].w;
		tbVec2 outward = tbNormalize(tbRightPerp(tbSub(b, a))); // counter-clockwise: outside is right
		if (outward.x == 0.0f && outward.y == 0.0f)
		{
			continue;
		}
		float d = tbDot(outward, a);
		if (d < bestDistance)
		{
			best = i;
			bestDistance = d;
			bestNormal = outward;
		}
	}
	*normal = bestNormal;
	*distance = bestDistance;
	return best;
}

static void tbRemoveVertex(tbPolytope* polytope, int index)
{
	for (int i = index; i + 1 < polytope->count; ++i)
	{
		polytope->vertices[i] = polytope->vertices[i + 1];
	}
	polytope->count -= 1;
}

// True when vertex `index` is a strict left turn (a convex corner of a counter-clockwise polygon).
static bool tbIsConvexCorner(const tbPolytope* polytope, int index)
{
	int n = polytope->count;
	tbVec2 previous = polytope->vertices[(index + n - 1) % n].w;
	tbVec2 current = polytope->vertices[index].w;
	tbVec2 next = polytope->vertices[(index + 1) % n].w;
	return tbCross(tbSub(current, previous), tbSub(next, current)) > 0.0f;
}

// Insert the support point after vertex `edge`, then restore convexity. The polygon's vertices
// are support points of D but not necessarily its extreme points (GJK's cold start and warm
// starts begin from arbitrary vertex pairs), so the new point can swallow its neighbours: as on
// the horizon of 3D EPA, every neighbour that is no longer a convex corner is removed, walking
// away from the new point on both sides. The result is conv(P ∪ {s}), which still contains P.
static void tbInsertSupport(tbPolytope* polytope, int edge, tbSimplexVertex support)
{
	int k = edge + 1;
	for (int i = polytope->count; i > k; --i)
	{
		polytope->vertices[i] = polytope->vertices[i - 1];
	}
	polytope->vertices[k] = support;
	polytope->count += 1;

	while (polytope->count > 3)
	{
		int previous = (k + polytope->count - 1) % polytope->count;
		if (tbIsConvexCorner(polytope, previous))
		{
			break;
		}
		tbRemoveVertex(polytope, previous);
		k = previous < k ? k - 1 : k;
	}
	while (polytope->count > 3)
	{
		int next = (k + 1) % polytope->count;
		if (tbIsConvexCorner(polytope, next))
		{
			break;
		}
		tbRemoveVertex(polytope, next);
		k = next < k ? k - 1 : k;
	}
}

// Deepest points from the closest edge a–b: the origin's projection a.w + t·(b.w − a.w), with the
// same weight t on the support points of A and of B.
static void tbEdgeWitness(tbPenetration* result, const tbSimplexVertex* a, const tbSimplexVertex* b)
{
	tbVec2 e = tbSub(b->w, a->w);
	float ee = tbDot(e, e);
	float t = ee > 0.0f ? tbClampFloat(-tbDot(a->w, e) / ee, 0.0f, 1.0f) : 0.0f;
	result->pointA = tbLerp(a->wA, b->wA, t);
	result->pointB = tbLerp(a->wB, b->wB, t);
}

static tbPenetration tbRunEPA(const tbSimplex* simplex, const tbShapeProxy* proxyA, const tbShapeProxy* proxyB,
							  float scale)
{
	tbPolytope polytope;
	tbInitializePolytope(&polytope, simplex, proxyA, proxyB, scale);

	tbPenetration result = {0};
	if (polytope.count == 1)
	{
		// D is a single point: any direction is as good; take A's local y axis
		result.pointA = polytope.vertices[0].wA;
		result.pointB = polytope.vertices[0].wB;
		result.normal = tbMakeVec2(0.0f, 1.0f);
		return result;
	}

	float tolerance = TB_EPA_RELATIVE_TOLERANCE * scale;
	tbVec2 normal = {0.0f, 1.0f};
	float distance = 0.0f;
	int edge = 0;
	int iteration = 0;
	while (iteration < TB_EPA_MAX_ITERATIONS)
	{
		++iteration;
		edge = tbFindClosestEdge(&polytope, &normal, &distance);

		tbSimplexVertex support = tbMakeSupportVertex(proxyA, proxyB, normal);
		if (tbPolytopeContains(&polytope, &support))
		{
			break; // the edge is on D's boundary
		}
		if (tbDot(normal, support.w) - distance <= tolerance)
		{
			break; // upper and lower bounds meet
		}
		if (polytope.count == TB_EPA_MAX_VERTICES)
		{
			break;
		}
		tbInsertSupport(&polytope, edge, support);
	}

	tbEdgeWitness(&result, &polytope.vertices[edge], &polytope.vertices[(edge + 1) % polytope.count]);
	result.normal = tbNeg(normal);
	result.depth = distance;
	result.iterations = iteration;
	return result;
}

tbSeparationOutput tbShapeSeparation(const tbDistanceInput* input, tbSimplexCache* cache)
{
	if (tbCheckProxyPair("tbShapeSeparation", &input->proxyA, &input->proxyB) == false)
	{
		tbSeparationOutput refused = {{0.0f, 1.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f, 0, false};
		return refused;
	}
	const tbShapeProxy* proxyA = &input->proxyA;
	tbShapeProxy proxyB = tbMakeRelativeProxy(&input->proxyB, input->transform);
	float scale = tbProxyScale(proxyA, &proxyB);

	tbSimplex simplex;
	tbDistanceOutput distance = tbLocalShapeDistance(proxyA, &proxyB, cache, &simplex);

	tbVec2 pointA, pointB, normal;
	float coreSeparation;
	tbSeparationOutput output = {0};
	bool apart = distance.simplexCount < 3 && distance.distance > TB_EPA_RELATIVE_TOLERANCE * scale;
	if (apart && tbIsNormalized(distance.normal))
	{
		pointA = distance.pointA;
		pointB = distance.pointB;
		normal = distance.normal;
		coreSeparation = distance.distance;
		output.iterations = distance.iterations;
	}
	else
	{
		tbPenetration penetration = tbRunEPA(&simplex, proxyA, &proxyB, scale);
		pointA = penetration.pointA;
		pointB = penetration.pointB;
		normal = penetration.normal;
		coreSeparation = -penetration.depth;
		output.iterations = distance.iterations + penetration.iterations;
		output.usedEPA = true;
	}

	// surfaces: A's core point pushed out by rA along the normal, B's by rB against it
	float radiusA = proxyA->radius;
	float radiusB = proxyB.radius;
	output.separation = coreSeparation - (radiusA + radiusB);
	output.normal = normal;
	output.pointA = tbMulAdd(pointA, radiusA, normal);
	output.pointB = tbMulSub(pointB, radiusB, normal);
	return output;
}
