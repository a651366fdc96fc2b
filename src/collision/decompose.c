// Convex decomposition of a simple polygon (tbDecomposePolygon): the pieces a concave outline
// becomes so that it can be a body's shapes.
//
// Three steps.
// 1. Pairing reflex corners. A diagonal between two reflex corners that leaves both convex (or
//    straight) on each side removes two reflex corners at once, which is what an optimal
//    decomposition does wherever it can: the fewest pieces without added points is at least
//    ⌈r/2⌉ + 1 for r reflex corners (Chazelle 1980), reached when every diagonal pairs two of them.
//    Candidates are tried shortest first and kept when they cross neither the outline nor a kept
//    diagonal; they cut the outline into faces (O(r²) candidates, each checked in O(n); done only
//    for r ≤ TB_PAIRING_LIMIT, beyond which this step is skipped).
// 2. Ear clipping (Meisters 1975, "Polygons have ears") triangulates each face: a convex corner
//    whose triangle holds no other vertex is cut off; a simple polygon of m ≥ 4 vertices always
//    has one, so m − 2 triangles result.
// 3. Hertel & Mehlhorn (1983, "Fast triangulation of simple polygons") merge the triangles: every
//    diagonal is removed unless removing it would leave a reflex corner at one of its ends. Each
//    diagonal left is essential at one end and a reflex corner has at most two essential
//    diagonals, so there are at most 2r + 1 pieces (against at least ⌈r/2⌉ + 1: four times the
//    fewest at worst); with step 1 the L, U and comb shapes come out optimal. A merge is also refused when the piece would exceed
//    TB_MAX_POLYGON_VERTICES corners, which an optimum must respect too.
//
// Input: 3 to TB_MAX_DECOMPOSE_POINTS points in either winding, no two consecutive points closer
// than TB_LINEAR_SLOP, no edge crossing another (checked, O(n²)), non-zero area. Points within
// TB_LINEAR_SLOP of the chord of the corners kept either side of them are dropped first, as
// tbComputeHull drops them from a convex outline (each drop changes the area by half the chord
// times that distance, under 0.0025 m² per metre of chord). Corners that are straight to rounding (a diagonal's end on a
// straight run) are dropped from the pieces, exactly; corners nearly straight but within the slop
// are never made (thin ears are cut last, such merges refused), because the pieces' hulls would
// drop them and open a gap; a thin ear that must be cut all the same (no fat ear left: corners
// within the slop of one line) is dropped, leaving a gap thinner than the slop. Cost O(n²) for
// the check and typically O(n²) for the clipping, bounded by TB_MAX_DECOMPOSE_POINTS: an outline
// is decomposed once, when its shapes are made, not every step.
#include "core/core.h"

#include "tumble/collision.h"
#include "tumble/constants.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/// Reflex corners beyond which pairing (step 1, O(r²) candidates) is skipped.
#define TB_PAIRING_LIMIT 256

/// The largest difference between the pieces and the outline, as a fraction of its area, that is
/// accepted (what the slop-sized welds and straightening may take from an outline whose features
/// are well above the slop); an outline that would lose more is refused.
#define TB_DECOMPOSE_TOLERANCE 0.01

/// A piece under construction: indices into the outline, counter-clockwise (a merge may hold
/// straight corners for a moment before they are dropped).
typedef struct tbPiece
{
	int index[2 * TB_MAX_POLYGON_VERTICES];
	int count;
	bool merged; ///< absorbed into another piece
} tbPiece;

/// A diagonal of the triangulation and the two pieces on its sides (piece a has the edge i→j).
typedef struct tbDiagonal
{
	int i, j;
	int a, b;
} tbDiagonal;

/// A candidate diagonal between reflex corners i and j, and its squared length.
typedef struct tbCandidate
{
	float lengthSquared;
	int i, j;
} tbCandidate;

/// Working memory: one allocation, sized from the outline's point count n.
typedef struct tbDecomposer
{
	const tbVec2* p;
	int n;
	int* next;	  ///< ear clipping links, later the owner of each triangle
	int* prev;
	int* partner; ///< the corner a pairing diagonal joins, or −1
	int* face;	  ///< faces' corners, one after another (n + 2 per diagonal ≤ 3n)
	bool* visited;
	tbPiece* tri;
	int triCount;
	tbDiagonal* diagonals;
	int diagonalCount;
} tbDecomposer;

static float tbCross3(tbVec2 a, tbVec2 b, tbVec2 c)
{
	return tbCross(tbSub(b, a), tbSub(c, b));
}

/// How far corner b of a counter-clockwise outline sticks out of the chord a→c (negative: reflex).
static float tbOutsideChord(tbVec2 a, tbVec2 b, tbVec2 c)
{
	float length = tbLength(tbSub(c, a));
	return length > 0.0f ? tbCross(tbSub(c, a), tbSub(b, a)) / -length : 0.0f;
}

/// Corner b is straight to rounding: within 1e-5 of the chord's length from the chord a→c, and
/// never farther than TB_LINEAR_SLOP from it. On a chord longer than 500 m the relative bound alone
/// would call a notch deeper than the slop straight, and a piece spanning it would leave the outline.
static bool tbIsStraight(tbVec2 a, tbVec2 b, tbVec2 c)
{
	tbVec2 chord = tbSub(c, a);
	float lengthSquared = tbDot(chord, chord);
	float tolerance = tbMinFloat(1e-5f * lengthSquared, TB_LINEAR_SLOP * sqrtf(lengthSquared));
	return tbAbsFloat(tbCross(chord, tbSub(b, a))) <= tolerance;
}

/// A corner a piece may have: convex by at least the slop (its hull keeps it) or straight.
static bool tbIsKeepableCorner(tbVec2 a, tbVec2 b, tbVec2 c)
{
	return tbOutsideChord(a, b, c) >= TB_LINEAR_SLOP || tbIsStraight(a, b, c);
}

/// Point q on segment ab, to rounding (straight corner a-q-b with q between a and b).
static bool tbOnSegment(tbVec2 q, tbVec2 a, tbVec2 b)
{
	tbVec2 ab = tbSub(b, a);
	float t = tbDot(tbSub(q, a), ab);
	return t > 0.0f && t < tbDot(ab, ab) && tbIsStraight(a, q, b);
}

/// Proper intersection of segments p1p2 and q1q2: they cross at a point inside both.
static bool tbSegmentsIntersect(tbVec2 p1, tbVec2 p2, tbVec2 q1, tbVec2 q2)
{
	float d1 = tbCross(tbSub(p2, p1), tbSub(q1, p1));
	float d2 = tbCross(tbSub(p2, p1), tbSub(q2, p1));
	float d3 = tbCross(tbSub(q2, q1), tbSub(p1, q1));
	float d4 = tbCross(tbSub(q2, q1), tbSub(p2, q1));
	return ((d1 > 0.0f && d2 < 0.0f) || (d1 < 0.0f && d2 > 0.0f)) && ((d3 > 0.0f && d4 < 0.0f) || (d3 < 0.0f && d4 > 0.0f));
}

static bool tbIsSimple(const tbVec2* p, int n)
{
	for (int i = 0; i < n; ++i)
	{
		for (int k = i + 2; k < n; ++k)
		{
			if (i == 0 && k == n - 1)
			{
				continue; // neighbours through the closing edge
			}
			if (tbSegmentsIntersect(p[i], p[(i + 1) % n], p[k], p[(k + 1) % n]))
			{
				return false;
			}
		}
		for (int k = 0; k < n; ++k)
		{
			if (k != i && k != (i + 1) % n && tbOnSegment(p[k], p[i], p[(i + 1) % n]))
			{
				return false; // a corner touching another edge
			}
		}
	}
	return true;
}

/// Point strictly inside (or on an edge of) the counter-clockwise triangle abc.
static bool tbInTriangle(tbVec2 p, tbVec2 a, tbVec2 b, tbVec2 c)
{
	return tbCross3(a, b, p) >= 0.0f && tbCross3(b, c, p) >= 0.0f && tbCross3(c, a, p) >= 0.0f;
}

/// Is v (between a and c) an ear: a convex corner whose triangle holds no other outline vertex?
/// A fat ear also has every height of its triangle ≥ TB_LINEAR_SLOP, so its hull keeps 3 corners.
static bool tbIsEar(const tbVec2* p, const int* next, int a, int v, int c, bool fat)
{
	float cross = tbCross3(p[a], p[v], p[c]);
	if (cross <= 0.0f)
	{
		return false;
	}
	if (fat)
	{
		float longest = tbMaxFloat(tbDistance(p[a], p[v]), tbMaxFloat(tbDistance(p[v], p[c]), tbDistance(p[c], p[a])));
		if (cross < TB_LINEAR_SLOP * longest)
		{
			return false; // smallest height = 2·area / longest side = cross / longest
		}
	}
	for (int k = next[c]; k != a; k = next[k])
	{
		// Only reflex corners can lie in an ear; testing every vertex is simpler and as exact.
		if (tbInTriangle(p[k], p[a], p[v], p[c]) && tbVec2Equals(p[k], p[a]) == false &&
			tbVec2Equals(p[k], p[c]) == false)
		{
			return false;
		}
	}
	return true;
}

/// Ear clipping over one face (its corners' indices, counter-clockwise): appends m − 2 triangles.
/// Fat ears are cut first; a thin one only when no fat ear is left (its piece is refused later).
static bool tbTriangulate(tbDecomposer* d, const int* corners, int m)
{
	int* next = d->next;
	int* prev = d->prev;
	for (int k = 0; k < m; ++k)
	{
		next[corners[k]] = corners[(k + 1) % m];
		prev[corners[k]] = corners[(k + m - 1) % m];
	}
	int remaining = m, v = corners[0], guard = 0;
	bool fat = true;
	while (remaining > 3)
	{
		int a = prev[v], c = next[v];
		if (tbIsEar(d->p, next, a, v, c, fat) == false)
		{
			v = c;
			guard += 1;
			if (guard > remaining)
			{
				if (fat == false)
				{
					return false; // no ear at all: not simple after all (numerically)
				}
				fat = false;
				guard = 0;
			}
			continue;
		}
		d->tri[d->triCount++] = (tbPiece){{a, v, c}, 3, false};
		next[a] = c;
		prev[c] = a;
		remaining -= 1;
		v = c;
		guard = 0;
		fat = true;
	}
	d->tri[d->triCount++] = (tbPiece){{prev[v], v, next[v]}, 3, false};
	return true;
}

/// Where edge i→j sits in a piece (its start), or −1.
static int tbFindEdge(const tbPiece* piece, int i, int j)
{
	for (int k = 0; k < piece->count; ++k)
	{
		if (piece->index[k] == i && piece->index[(k + 1) % piece->count] == j)
		{
			return k;
		}
	}
	return -1;
}

/// Drop the straight corners of a cycle of outline indices; returns the corners left.
static int tbDropStraight(const tbVec2* p, int* index, int m)
{
	for (bool changed = true; changed && m > 3;)
	{
		changed = false;
		for (int k = 0; k < m && m > 3; ++k)
		{
			if (tbIsStraight(p[index[(k + m - 1) % m]], p[index[k]], p[index[(k + 1) % m]]))
			{
				memmove(index + k, index + k + 1, (size_t)(m - k - 1) * sizeof(int));
				m -= 1;
				changed = true;
			}
		}
	}
	return m;
}

/// Merge piece q into piece p across their shared diagonal if the result is convex and small enough.
static bool tbTryMerge(const tbVec2* pts, tbPiece* p, tbPiece* q, int i, int j)
{
	int kp = tbFindEdge(p, i, j), kq = tbFindEdge(q, j, i);
	if (kp < 0 || kq < 0)
	{
		return false; // the diagonal's end was dropped as straight from one side: keep it
	}
	int merged[4 * TB_MAX_POLYGON_VERTICES];
	int m = 0;
	for (int s = 1; s <= p->count; ++s)
	{
		merged[m++] = p->index[(kp + s) % p->count]; // from j round to i
	}
	for (int s = 2; s < q->count; ++s)
	{
		merged[m++] = q->index[(kq + s) % q->count]; // q's corners strictly between i and j
	}
	for (int s = 0; s < m; ++s)
	{
		if (tbIsKeepableCorner(pts[merged[(s + m - 1) % m]], pts[merged[s]], pts[merged[(s + 1) % m]]) == false)
		{
			// A reflex corner at one end of the diagonal (it is essential, keep it), or one so
			// nearly straight that the piece's hull would drop it and open a gap.
			return false;
		}
	}
	m = tbDropStraight(pts, merged, m);
	if (m > TB_MAX_POLYGON_VERTICES)
	{
		return false;
	}
	memcpy(p->index, merged, (size_t)m * sizeof(int));
	p->count = m;
	q->merged = true;
	return true;
}

/// Is every outline point strictly between corners a and c (going forward) within TB_LINEAR_SLOP
/// of the chord a→c?
static bool tbSpanNearChord(const tbVec2* p, int n, int a, int c)
{
	for (int j = (a + 1) % n; j != c; j = (j + 1) % n)
	{
		if (tbAbsFloat(tbOutsideChord(p[a], p[j], p[c])) >= TB_LINEAR_SLOP)
		{
			return false;
		}
	}
	return true;
}

/// Drop points within TB_LINEAR_SLOP of the chord of the corners kept either side of them, as
/// tbComputeHull does for a convex outline: the pieces' hulls would drop them anyway and leave a
/// gap beside them. A point goes only if the points dropped before it between the same two corners
/// stay within the slop of their chord too: tested against its neighbours alone, one drop after
/// another could carry the chord several slops away from the outline, and a piece outside it.
/// `kept` is scratch for n indices; the corners left are moved to the front of p, in order, and
/// counted.
static int tbDropCollinear(tbVec2* p, int n, int* kept)
{
	for (int i = 0; i < n; ++i)
	{
		kept[i] = i;
	}
	int count = n;
	for (bool changed = true; changed && count > 3;)
	{
		changed = false;
		for (int i = 0; i < count && count > 3; ++i)
		{
			if (tbSpanNearChord(p, n, kept[(i + count - 1) % count], kept[(i + 1) % count]))
			{
				memmove(kept + i, kept + i + 1, (size_t)(count - i - 1) * sizeof(int));
				count -= 1;
				changed = true;
			}
		}
	}
	for (int k = 0; k < count; ++k)
	{
		p[k] = p[kept[k]]; // kept[k] >= k: no point is overwritten before it is read
	}
	return count;
}

/// Does the diagonal v→w leave corner v keepable on both sides (v reflex)?
static bool tbResolves(const tbVec2* p, int n, int v, int w)
{
	int before = (v + n - 1) % n, after = (v + 1) % n;
	return tbIsKeepableCorner(p[w], p[v], p[after]) && tbIsKeepableCorner(p[before], p[v], p[w]);
}

/// Is i–j a diagonal inside the outline crossing none of the kept diagonals? (Both ends are
/// reflex corners it resolves, so it leaves each end into the inside.)
static bool tbIsFreeDiagonal(const tbDecomposer* d, int i, int j)
{
	const tbVec2* p = d->p;
	for (int k = 0; k < d->n; ++k)
	{
		int l = (k + 1) % d->n;
		if (k != i && k != j && tbOnSegment(p[k], p[i], p[j]))
		{
			return false;
		}
		if (k != i && k != j && l != i && l != j && tbSegmentsIntersect(p[i], p[j], p[k], p[l]))
		{
			return false;
		}
		if (d->partner[k] > k && tbSegmentsIntersect(p[i], p[j], p[k], p[d->partner[k]]))
		{
			return false;
		}
	}
	return true;
}

static int tbCompareCandidates(const void* a, const void* b)
{
	const tbCandidate* x = a;
	const tbCandidate* y = b;
	if (x->lengthSquared != y->lengthSquared)
	{
		return x->lengthSquared < y->lengthSquared ? -1 : 1;
	}
	return x->i != y->i ? x->i - y->i : x->j - y->j;
}

/// Step 1: join pairs of reflex corners by diagonals that resolve both, shortest first.
static void tbPairReflexCorners(tbDecomposer* d)
{
	const tbVec2* p = d->p;
	int n = d->n;
	int* reflex = d->prev; // free until triangulation
	int r = 0;
	for (int v = 0; v < n; ++v)
	{
		d->partner[v] = -1;
		if (tbCross3(p[(v + n - 1) % n], p[v], p[(v + 1) % n]) < 0.0f)
		{
			reflex[r++] = v;
		}
	}
	if (r < 2 || r > TB_PAIRING_LIMIT)
	{
		return;
	}
	int bytes = r * (r - 1) / 2 * (int)sizeof(tbCandidate);
	tbCandidate* candidates = tbAlloc(bytes);
	int count = 0;
	for (int a = 0; a < r; ++a)
	{
		for (int b = a + 1; b < r; ++b)
		{
			int i = reflex[a], j = reflex[b];
			if (j != (i + 1) % n && i != (j + 1) % n && tbResolves(p, n, i, j) && tbResolves(p, n, j, i))
			{
				candidates[count++] = (tbCandidate){tbDistanceSquared(p[i], p[j]), i, j};
			}
		}
	}
	if (count > 0)
	{
		qsort(candidates, (size_t)count, sizeof(tbCandidate), tbCompareCandidates);
	}
	for (int c = 0; c < count; ++c)
	{
		int i = candidates[c].i, j = candidates[c].j;
		if (d->partner[i] < 0 && d->partner[j] < 0 && tbIsFreeDiagonal(d, i, j))
		{
			d->partner[i] = j;
			d->partner[j] = i;
		}
	}
	tbFree(candidates, bytes);
}

/// Steps 1 and 2: cut the outline into faces along the pairing diagonals and triangulate each.
/// A face is walked with the inside on its left: leave a corner along the outline; on reaching a
/// corner with a diagonal, take the diagonal (the face on the left of the outline edge ends there).
static bool tbTriangulateFaces(tbDecomposer* d)
{
	tbPairReflexCorners(d);
	int n = d->n;
	memset(d->visited, 0, (size_t)n * sizeof(bool));
	d->triCount = 0;
	for (int start = 0; start < n; ++start)
	{
		if (d->visited[start])
		{
			continue;
		}
		int m = 0, corner = start;
		do
		{
			d->face[m++] = corner;
			d->visited[corner] = true;
			int after = (corner + 1) % n;
			if (d->partner[after] >= 0)
			{
				d->face[m++] = after;
				corner = d->partner[after];
			}
			else
			{
				corner = after;
			}
		} while (corner != start);
		m = tbDropStraight(d->p, d->face, m);
		if (tbTriangulate(d, d->face, m) == false)
		{
			return false;
		}
	}
	return true;
}

static int tbFindOwner(int* owner, int t)
{
	while (owner[t] != t)
	{
		owner[t] = owner[owner[t]];
		t = owner[t];
	}
	return t;
}

/// Step 3, Hertel–Mehlhorn: list the triangulation's diagonals (edges met from both sides) and
/// remove each whose removal keeps both ends convex.
static void tbMergeTriangles(tbDecomposer* d)
{
	tbPiece* tri = d->tri;
	int n = d->n, triangles = d->triCount;
	d->diagonalCount = 0;
	for (int t = 0; t < triangles; ++t)
	{
		for (int e = 0; e < 3; ++e)
		{
			int i = tri[t].index[e], j = tri[t].index[(e + 1) % 3];
			if (i < j && j != (i + 1) % n && i != (j + 1) % n)
			{
				for (int u = 0; u < triangles; ++u)
				{
					if (u != t && tbFindEdge(tri + u, j, i) >= 0)
					{
						d->diagonals[d->diagonalCount++] = (tbDiagonal){i, j, t, u};
						break;
					}
				}
			}
		}
	}
	int* owner = d->next; // free now: the piece each triangle has merged into (union-find)
	for (int t = 0; t < triangles; ++t)
	{
		owner[t] = t;
	}
	for (int k = 0; k < d->diagonalCount; ++k)
	{
		const tbDiagonal* g = d->diagonals + k;
		int a = tbFindOwner(owner, g->a), b = tbFindOwner(owner, g->b);
		if (a != b && tbTryMerge(d->p, tri + a, tri + b, g->i, g->j))
		{
			owner[b] = a;
		}
	}
}

/// Hull of a piece; fewer than 3 corners for a sliver (a triangle thinner than the slop).
static tbHull tbPieceHull(const tbDecomposer* d, const tbPiece* piece)
{
	tbVec2 corners[2 * TB_MAX_POLYGON_VERTICES];
	for (int k = 0; k < piece->count; ++k)
	{
		corners[k] = d->p[piece->index[k]];
	}
	return tbComputeHull(corners, piece->count);
}

/// Twice the signed area of a closed outline, in double and about the outline's first point (so that
/// an outline far from the origin keeps its digits).
static double tbArea2(const tbVec2* p, int n)
{
	double sum = 0.0;
	for (int i = 1; i + 1 < n; ++i)
	{
		double ax = (double)p[i].x - p[0].x, ay = (double)p[i].y - p[0].y;
		double bx = (double)p[i + 1].x - p[0].x, by = (double)p[i + 1].y - p[0].y;
		sum += ax * by - ay * bx;
	}
	return sum;
}

/// Twice the area of a piece's own corners (a face of the triangulation, merged).
static double tbPieceArea2(const tbDecomposer* d, const tbPiece* piece)
{
	tbVec2 corners[2 * TB_MAX_POLYGON_VERTICES];
	for (int k = 0; k < piece->count; ++k)
	{
		corners[k] = d->p[piece->index[k]];
	}
	return tbArea2(corners, piece->count);
}

/// How far the pieces are from covering the outline exactly, as twice an area: what the hulls add
/// to or take from their faces (a hull adds where a face is not convex by more than rounding, and
/// takes away nothing but corners within the slop of straight), plus the faces of dropped slivers
/// and the corners dropped from the outline. The faces partition the outline, so this is zero when
/// each hull is its face.
static double tbCoverageError2(const tbDecomposer* d, double outlineArea2)
{
	double error = 0.0, kept = 0.0;
	for (int t = 0; t < d->triCount; ++t)
	{
		if (d->tri[t].merged == false)
		{
			tbHull hull = tbPieceHull(d, d->tri + t);
			if (hull.count >= 3)
			{
				double face = tbPieceArea2(d, d->tri + t);
				error += fabs(tbArea2(hull.points, hull.count) - face);
				kept += face;
			}
		}
	}
	return error + fabs(outlineArea2 - kept);
}

/// Write the pieces as polygons. A sliver left unmerged (a thin ear cut when no fat one was left,
/// thinner than TB_LINEAR_SLOP everywhere) is dropped: no polygon can hold it, and the gap it
/// leaves is thinner than the contact slop. Nothing is written when capacity is too small, or when
/// the pieces would miss or exceed the outline by more than TB_DECOMPOSE_TOLERANCE of its area:
/// an outline whose features are near the slop's size, which polygons cannot hold.
static int tbWritePieces(const char* f, const tbDecomposer* d, double outlineArea2, tbPolygon* pieces, int capacity)
{
	double error2 = tbCoverageError2(d, outlineArea2);
	if (error2 > TB_DECOMPOSE_TOLERANCE * outlineArea2)
	{
		tbReportError(f, "the pieces would differ from the outline by %.2g%% of its area: it has features (spikes, "
						 "notches, corners within %g m of straight) too small for polygons, whose corners are welded "
						 "and straightened within TB_LINEAR_SLOP; scale it up or simplify it",
					  100.0 * error2 / outlineArea2, (double)TB_LINEAR_SLOP);
		return 0;
	}
	int count = 0;
	for (int t = 0; t < d->triCount; ++t)
	{
		count += d->tri[t].merged == false && tbPieceHull(d, d->tri + t).count >= 3 ? 1 : 0;
	}
	if (count > capacity)
	{
		tbReportError(f, "the outline makes %d pieces and capacity is %d; pass room for %d", count, capacity, count);
		return 0;
	}
	int written = 0;
	for (int t = 0; t < d->triCount; ++t)
	{
		if (d->tri[t].merged == false)
		{
			tbHull hull = tbPieceHull(d, d->tri + t);
			if (hull.count >= 3)
			{
				pieces[written++] = tbMakePolygon(&hull, 0.0f);
			}
		}
	}
	return written;
}

static bool tbCheckOutline(const char* f, const tbVec2* points, int count)
{
	if (points == NULL || count < 3 || count > TB_MAX_DECOMPOSE_POINTS)
	{
		tbReportError(f, "points is %s with count %d; pass 3 to %d points", points == NULL ? "NULL" : "given", count,
					  TB_MAX_DECOMPOSE_POINTS);
		return false;
	}
	for (int i = 0; i < count; ++i)
	{
		if (tbIsValidVec2(points[i]) == false || tbAbsFloat(points[i].x) > TB_MAX_COORDINATE ||
			tbAbsFloat(points[i].y) > TB_MAX_COORDINATE)
		{
			tbReportError(f, "points[%d] is (%g, %g): not finite or beyond %g m", i, (double)points[i].x,
						  (double)points[i].y, (double)TB_MAX_COORDINATE);
			return false;
		}
	}
	// Every pair, not only neighbours: a simple outline visits each point once (a point repeated
	// further along would pinch the polygon into two that touch).
	for (int i = 0; i < count; ++i)
	{
		for (int j = i + 1; j < count; ++j)
		{
			if (tbDistance(points[i], points[j]) < TB_LINEAR_SLOP)
			{
				tbReportError(f, "points[%d] and points[%d] are closer than %g m (duplicate points: a simple polygon "
								 "visits each point once); remove one",
							  i, j, (double)TB_LINEAR_SLOP);
				return false;
			}
		}
	}
	return true;
}

int tbDecomposePolygon(const tbVec2* points, int count, tbPolygon* pieces, int capacity)
{
	const char* f = "tbDecomposePolygon";
	if (tbCheckOutline(f, points, count) == false)
	{
		return 0;
	}
	if (pieces == NULL || capacity < 1)
	{
		tbReportError(f, "pieces is NULL or capacity %d < 1; pass room for up to count − 2 pieces", capacity);
		return 0;
	}
	double area2 = tbArea2(points, count);
	if (fabs(area2) < 2.0 * TB_LINEAR_SLOP * TB_LINEAR_SLOP)
	{
		tbReportError(f, "the outline has no area; pass at least three points not on one line");
		return 0;
	}
	if (tbIsSimple(points, count) == false)
	{
		tbReportError(f, "the outline crosses itself; pass a simple polygon (no edge may cross another)");
		return 0;
	}
	// Work on a counter-clockwise copy without collinear points.
	int bytes = count * (int)(sizeof(tbVec2) + 6 * sizeof(int) + sizeof(bool) + sizeof(tbPiece) + sizeof(tbDiagonal));
	char* memory = tbAlloc(bytes);
	tbDecomposer d = {0};
	tbVec2* p = (tbVec2*)memory;
	d.next = (int*)(p + count);
	d.prev = d.next + count;
	d.partner = d.prev + count;
	d.face = d.partner + count;
	d.tri = (tbPiece*)(d.face + 3 * count);
	d.diagonals = (tbDiagonal*)(d.tri + count);
	d.visited = (bool*)(d.diagonals + count);
	for (int i = 0; i < count; ++i)
	{
		p[i] = area2 >= 0.0 ? points[i] : points[count - 1 - i];
	}
	d.p = p;
	d.n = tbDropCollinear(p, count, d.next);
	int result = 0;
	if (d.n < 3)
	{
		tbReportError(f, "the outline has no area; pass at least three points not on one line");
	}
	else if (tbTriangulateFaces(&d) == false)
	{
		tbReportError(f, "the outline could not be triangulated (nearly touching edges?); pass a simple polygon");
	}
	else
	{
		tbMergeTriangles(&d);
		result = tbWritePieces(f, &d, fabs(area2), pieces, capacity);
	}
	tbFree(memory, bytes);
	return result;
}
