// Tumble: convex hull of a small point cloud by quickhull, and hull validation.
//
// Quickhull (Barber, Dobkin and Huhdanpaa, "The Quickhull Algorithm for Convex Hulls", 1996;
// Ericson, "Real-Time Collision Detection", §12.4.2):
//   1. The points with least and greatest x, L and R, are on the hull.
//   2. The hull is L, then the chain of hull points below L→R, then R, then the chain above.
//   3. A chain between a and b is built from the points to the right of a→b: the point c
//      farthest from the line is on the hull, and the chains a→c and c→b are built the same
//      way from the points to the right of those lines. Points within TB_LINEAR_SLOP of the
//      line are dropped, so the hull has no nearly collinear vertices.
// With at most TB_MAX_POLYGON_VERTICES input points the recursion is shallow and every array
// lives on the stack.
//
// Tolerances: points closer than TB_LINEAR_SLOP (0.005 m) are welded into one, and a vertex
// closer than TB_LINEAR_SLOP to the chord of its neighbours is removed. Each of the three
// simplifications (weld, drop near an edge, remove a flat vertex) moves the boundary inward by
// at most about one slop, so every input point lies within ~3 × TB_LINEAR_SLOP of the hull;
// in practice far less (worst seen over 2·10⁶ random clouds, some only 4 cm across: 0.012 m).
//
// Rejected alternative: Andrew's monotone chain needs a sort and handles the slop less
// naturally; for ≤ 8 points either is fast, and quickhull's "farthest point" step is also the
// natural place to drop nearly collinear points.

#include "core/core.h"

#include "tumble/collision.h"

// Signed distance of p to the right of the directed line a→b (positive on the right), times |b − a|.
static float tbRightOfLine(tbVec2 a, tbVec2 b, tbVec2 p)
{
	return tbCross(tbSub(p, a), tbSub(b, a));
}

// Copy the points, welding any point within TB_LINEAR_SLOP of one already kept.
static int tbWeldPoints(tbVec2* out, const tbVec2* points, int count)
{
	const float weldSquared = TB_LINEAR_SLOP * TB_LINEAR_SLOP;
	int n = 0;
	for (int i = 0; i < count; ++i)
	{
		bool unique = true;
		for (int j = 0; j < n && unique; ++j)
		{
			unique = tbDistanceSquared(points[i], out[j]) >= weldSquared;
		}
		if (unique)
		{
			out[n++] = points[i];
		}
	}
	return n;
}

// Append to `out` the hull vertices strictly between a and b, in order, from the candidate
// points (those to the right of a→b). Returns the new length of `out`.
static int tbHullChain(tbVec2* out, int outCount, tbVec2 a, tbVec2 b, const tbVec2* points, int count)
{
	if (count == 0)
	{
		return outCount;
	}

	// Farthest candidate from the line a→b; its distance must exceed the slop.
	float length = tbDistance(a, b);
	int best = -1;
	float bestDistance = TB_LINEAR_SLOP * length;
	for (int i = 0; i < count; ++i)
	{
		float d = tbRightOfLine(a, b, points[i]);
		if (d > bestDistance)
		{
			bestDistance = d;
			best = i;
		}
	}
	if (best < 0)
	{
		return outCount;
	}
	tbVec2 c = points[best];

	// Split the remaining candidates into those right of a→c and those right of c→b. A point
	// cannot be right of both (it would lie beyond c, contradicting c being farthest).
	tbVec2 right1[TB_MAX_POLYGON_VERTICES], right2[TB_MAX_POLYGON_VERTICES];
	int count1 = 0, count2 = 0;
	for (int i = 0; i < count; ++i)
	{
		if (i == best)
		{
			continue;
		}
		if (tbRightOfLine(a, c, points[i]) > 0.0f)
		{
			right1[count1++] = points[i];
		}
		else if (tbRightOfLine(c, b, points[i]) > 0.0f)
		{
			right2[count2++] = points[i];
		}
	}

	outCount = tbHullChain(out, outCount, a, c, right1, count1);
	out[outCount++] = c;
	return tbHullChain(out, outCount, c, b, right2, count2);
}

// Distance of b outside the chord a→c (positive when a, b, c turn counter-clockwise at b).
static float tbDistanceOutsideChord(tbVec2 a, tbVec2 b, tbVec2 c)
{
	float length = tbDistance(a, c);
	if (length < FLT_EPSILON)
	{
		return 0.0f;
	}
	return tbRightOfLine(a, c, b) / length;
}

// Remove vertices within TB_LINEAR_SLOP of the chord of their neighbours, the flattest first
// (removing one changes its neighbours' chords, so greedy order keeps the hull tightest).
static int tbRemoveCollinear(tbVec2* points, int count)
{
	while (count >= 3)
	{
		int flattest = -1;
		float smallest = TB_LINEAR_SLOP;
		for (int i = 0; i < count; ++i)
		{
			tbVec2 a = points[(i + count - 1) % count];
			tbVec2 c = points[(i + 1) % count];
			float d = tbDistanceOutsideChord(a, points[i], c);
			if (d < smallest)
			{
				smallest = d;
				flattest = i;
			}
		}
		if (flattest < 0)
		{
			break;
		}
		for (int j = flattest; j < count - 1; ++j)
		{
			points[j] = points[j + 1];
		}
		--count;
	}
	return count;
}

// Reject input that is a caller's mistake (not a degenerate cloud, which simply has no hull).
static bool tbCheckHullInput(const tbVec2* points, int count)
{
	if (count > TB_MAX_POLYGON_VERTICES)
	{
		tbReportError("tbComputeHull", "count is %d (at most TB_MAX_POLYGON_VERTICES = %d); pass fewer points", count,
					  TB_MAX_POLYGON_VERTICES);
		return false;
	}
	if (count > 0 && points == NULL)
	{
		tbReportError("tbComputeHull", "points is NULL with count %d; pass an array of count points", count);
		return false;
	}
	return tbCheckPoints("tbComputeHull", "points", points, count);
}

// Indices of the leftmost and rightmost points (ties broken by y, so L ≠ R for distinct points).
static void tbFindExtremes(const tbVec2* points, int count, int* left, int* right)
{
	*left = 0;
	*right = 0;
	for (int i = 1; i < count; ++i)
	{
		tbVec2 p = points[i];
		tbVec2 l = points[*left];
		tbVec2 r = points[*right];
		if (p.x < l.x || (p.x == l.x && p.y < l.y))
		{
			*left = i;
		}
		if (p.x > r.x || (p.x == r.x && p.y > r.y))
		{
			*right = i;
		}
	}
}

tbHull tbComputeHull(const tbVec2* points, int count)
{
	tbHull hull = {0};
	if (count < 3 || tbCheckHullInput(points, count) == false)
	{
		return hull;
	}

	tbVec2 welded[TB_MAX_POLYGON_VERTICES];
	int n = tbWeldPoints(welded, points, count);
	if (n < 3)
	{
		return hull;
	}

	int left, right;
	tbFindExtremes(welded, n, &left, &right);
	tbVec2 L = welded[left];
	tbVec2 R = welded[right];

	// Points below L→R (right of it) feed the lower chain, points above feed the upper chain.
	tbVec2 below[TB_MAX_POLYGON_VERTICES], above[TB_MAX_POLYGON_VERTICES];
	int belowCount = 0, aboveCount = 0;
	for (int i = 0; i < n; ++i)
	{
		if (i == left || i == right)
		{
			continue;
		}
		float side = tbRightOfLine(L, R, welded[i]);
		if (side > 0.0f)
		{
			below[belowCount++] = welded[i];
		}
		else if (side < 0.0f)
		{
			above[aboveCount++] = welded[i];
		}
	}

	int m = 0;
	hull.points[m++] = L;
	m = tbHullChain(hull.points, m, L, R, below, belowCount);
	hull.points[m++] = R;
	m = tbHullChain(hull.points, m, R, L, above, aboveCount);

	m = tbRemoveCollinear(hull.points, m);
	hull.count = m >= 3 ? m : 0;
	// Points that span more than float's precision (one a million metres from others a few
	// centimetres apart) can leave turns that rounding hides when the hull is checked again: no
	// hull then, rather than one that tbValidateHull, and so tbMakePolygon, refuses.
	if (hull.count > 0 && tbValidateHull(&hull) == false)
	{
		hull.count = 0;
	}
	return hull;
}

// Every vertex not on edge i lies strictly inside it (counter-clockwise and convex).
static bool tbHullEdgeIsSupporting(const tbHull* hull, int i)
{
	int n = hull->count;
	tbVec2 a = hull->points[i];
	tbVec2 b = hull->points[(i + 1) % n];
	for (int j = 0; j < n; ++j)
	{
		if (j == i || j == (i + 1) % n)
		{
			continue;
		}
		if (tbRightOfLine(a, b, hull->points[j]) >= 0.0f)
		{
			return false;
		}
	}
	return true;
}

bool tbValidateHull(const tbHull* hull)
{
	if (hull == NULL || hull->count < 3 || hull->count > TB_MAX_POLYGON_VERTICES)
	{
		return false;
	}
	int n = hull->count;
	for (int i = 0; i < n; ++i)
	{
		tbVec2 a = hull->points[(i + n - 1) % n];
		tbVec2 b = hull->points[i];
		tbVec2 c = hull->points[(i + 1) % n];
		if (tbIsValidVec2(b) == false)
		{
			return false;
		}
		// No duplicates (welded points are at least the slop apart).
		if (tbDistanceSquared(b, c) < TB_LINEAR_SLOP * TB_LINEAR_SLOP)
		{
			return false;
		}
		// No collinear vertex: b must stick out of the chord a→c by at least the slop.
		if (tbDistanceOutsideChord(a, b, c) < TB_LINEAR_SLOP)
		{
			return false;
		}
		if (tbHullEdgeIsSupporting(hull, i) == false)
		{
			return false;
		}
	}
	return true;
}
