// Convex decomposition (tbDecomposePolygon) on known outlines. What is checked, and why it proves
// an exact cover:
// - every piece is convex with 3 to TB_MAX_POLYGON_VERTICES vertices, all of them outline points;
// - the pieces' areas (shoelace formula) sum to the outline's area, to 1e-5 relative (float sums
//   of a few hundred products of coordinates ≤ 100 m carry about 1e-6 relative error) plus, for
//   each outline point within TB_LINEAR_SLOP of its neighbours' chord (dropped, as tbComputeHull
//   drops it), the triangle it spans: half its chord times its distance from the chord;
// - no two pieces overlap: the area of each pair's intersection (clipped exactly as convex
//   polygons, Sutherland–Hodgman) is below 1e-6 of the outline's area;
// - every piece's centroid is inside the outline.
// Pieces inside the outline, not overlapping, with the same total area, cover it exactly.
// Piece counts are bounded by the closed forms for r reflex corners: at least ⌈r/2⌉ + 1 (Chazelle)
// and at most 2r + 1 (Hertel–Mehlhorn); where the fewest is known by hand it is asserted exactly.
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include "error_recorder.h"

#include <math.h>
#include <string.h>

#define MAX_PIECES 1100

static tbPolygon s_pieces[MAX_PIECES];

static double SignedArea(const tbVec2* p, int n)
{
	double sum = 0.0;
	for (int i = 0; i < n; ++i)
	{
		tbVec2 a = p[i], b = p[(i + 1) % n];
		sum += (double)a.x * (double)b.y - (double)a.y * (double)b.x;
	}
	return 0.5 * sum;
}

static int ReflexCount(const tbVec2* p, int n)
{
	double orientation = SignedArea(p, n) > 0.0 ? 1.0 : -1.0;
	int reflex = 0;
	for (int i = 0; i < n; ++i)
	{
		tbVec2 a = p[(i + n - 1) % n], b = p[i], c = p[(i + 1) % n];
		double cross = ((double)b.x - a.x) * ((double)c.y - b.y) - ((double)b.y - a.y) * ((double)c.x - b.x);
		reflex += cross * orientation < 0.0 ? 1 : 0;
	}
	return reflex;
}

/// Area the decomposition may drop: the triangles of points within TB_LINEAR_SLOP of their chord.
static double DroppedArea(const tbVec2* p, int n)
{
	double dropped = 0.0;
	for (int i = 0; i < n; ++i)
	{
		tbVec2 a = p[(i + n - 1) % n], b = p[i], c = p[(i + 1) % n];
		double chord = hypot((double)c.x - a.x, (double)c.y - a.y);
		double cross = ((double)c.x - a.x) * ((double)b.y - a.y) - ((double)c.y - a.y) * ((double)b.x - a.x);
		double distance = fabs(cross) / chord;
		dropped += distance < TB_LINEAR_SLOP ? 0.5 * chord * distance : 0.0;
	}
	return dropped;
}

static bool PointInOutline(tbVec2 q, const tbVec2* p, int n)
{
	bool inside = false;
	for (int i = 0, j = n - 1; i < n; j = i++)
	{
		if ((p[i].y > q.y) != (p[j].y > q.y) &&
			q.x < (p[j].x - p[i].x) * (q.y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
		{
			inside = !inside;
		}
	}
	return inside;
}

/// Clip the convex counter-clockwise polygon `in` by the half plane left of edge a→b.
static int ClipByEdge(const double (*in)[2], int n, const double* a, const double* b, double (*out)[2])
{
	int m = 0;
	for (int i = 0; i < n; ++i)
	{
		const double* p = in[i];
		const double* q = in[(i + 1) % n];
		double sp = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
		double sq = (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]);
		if (sp >= 0.0)
		{
			out[m][0] = p[0], out[m][1] = p[1], m += 1;
		}
		if ((sp >= 0.0) != (sq >= 0.0))
		{
			double t = sp / (sp - sq);
			out[m][0] = p[0] + t * (q[0] - p[0]), out[m][1] = p[1] + t * (q[1] - p[1]), m += 1;
		}
	}
	return m;
}

/// Area of the intersection of two convex counter-clockwise polygons.
static double OverlapArea(const tbPolygon* a, const tbPolygon* b)
{
	double poly[64][2], clipped[64][2];
	int n = a->count;
	for (int i = 0; i < n; ++i)
	{
		poly[i][0] = a->vertices[i].x, poly[i][1] = a->vertices[i].y;
	}
	for (int e = 0; e < b->count && n > 0; ++e)
	{
		double p[2] = {b->vertices[e].x, b->vertices[e].y};
		double q[2] = {b->vertices[(e + 1) % b->count].x, b->vertices[(e + 1) % b->count].y};
		n = ClipByEdge((const double (*)[2])poly, n, p, q, clipped);
		memcpy(poly, clipped, sizeof(double[2]) * (size_t)n);
	}
	double sum = 0.0;
	for (int i = 0; i < n; ++i)
	{
		sum += poly[i][0] * poly[(i + 1) % n][1] - poly[i][1] * poly[(i + 1) % n][0];
	}
	return 0.5 * fabs(sum);
}

static bool IsOutlinePoint(tbVec2 v, const tbVec2* p, int n)
{
	for (int i = 0; i < n; ++i)
	{
		if (v.x == p[i].x && v.y == p[i].y)
		{
			return true;
		}
	}
	return false;
}

/// Decompose and check the cover; returns the piece count.
static int DecomposeAndCheck(const tbVec2* outline, int n)
{
	int count = tbDecomposePolygon(outline, n, s_pieces, MAX_PIECES);
	cr_assert(count > 0, "decomposition failed");
	double area = fabs(SignedArea(outline, n));
	double sum = 0.0;
	for (int i = 0; i < count; ++i)
	{
		const tbPolygon* piece = s_pieces + i;
		cr_assert(piece->count >= 3 && piece->count <= TB_MAX_POLYGON_VERTICES, "piece %d has %d vertices", i,
				  piece->count);
		double pieceArea = SignedArea(piece->vertices, piece->count);
		cr_assert(pieceArea > 0.0, "piece %d is not counter-clockwise", i);
		cr_assert_eq(ReflexCount(piece->vertices, piece->count), 0, "piece %d is not convex", i);
		for (int k = 0; k < piece->count; ++k)
		{
			cr_assert(IsOutlinePoint(piece->vertices[k], outline, n), "piece %d vertex %d is not an outline point", i, k);
		}
		cr_assert(PointInOutline(piece->centroid, outline, n), "piece %d's centroid is outside the outline", i);
		sum += pieceArea;
	}
	double dropped = DroppedArea(outline, n);
	cr_assert(fabs(sum - area) <= 1e-5 * area + dropped, "pieces cover %.9g of area %.9g (%.3g may be dropped)", sum,
			  area, dropped);
	for (int i = 0; i < count; ++i)
	{
		for (int j = i + 1; j < count; ++j)
		{
			double overlap = OverlapArea(s_pieces + i, s_pieces + j);
			if (overlap > 1e-6 * area) // (asserting only on failure keeps 10⁵ pairs fast)
			{
				cr_assert_fail("pieces %d and %d overlap by %.3g", i, j, overlap);
			}
		}
	}
	int reflex = ReflexCount(outline, n);
	cr_assert(count >= (reflex + 1) / 2 + 1 && count <= 2 * reflex + 1, "%d pieces for %d reflex corners", count,
			  reflex);
	return count;
}

static void Reverse(tbVec2* p, int n)
{
	for (int i = 0; i < n / 2; ++i)
	{
		tbVec2 t = p[i];
		p[i] = p[n - 1 - i];
		p[n - 1 - i] = t;
	}
}

// L of three unit squares: one reflex corner, so two pieces (the fewest); either winding.
Test(decompose, l_shape_is_two_pieces)
{
	tbVec2 l[] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
	cr_assert_eq(DecomposeAndCheck(l, 6), 2);
	Reverse(l, 6);
	cr_assert_eq(DecomposeAndCheck(l, 6), 2);
}

// U (3 × 2 with a 1 × 1 notch): two reflex corners; two convex pieces cannot cover a U (each
// would need both notch corners' neighbourhoods), so three is the fewest.
Test(decompose, u_shape_is_three_pieces)
{
	tbVec2 u[] = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
	cr_assert_eq(DecomposeAndCheck(u, 8), 3);
}

// Five-pointed star (outer radius 2, inner 0.8): five reflex corners, 4 to 11 pieces.
Test(decompose, star)
{
	tbVec2 star[10];
	for (int i = 0; i < 10; ++i)
	{
		float angle = 0.5f * 3.14159265f + (float)i * 3.14159265f / 5.0f;
		float radius = (i % 2 == 0) ? 2.0f : 0.8f;
		star[i] = tbMakeVec2(radius * cosf(angle), radius * sinf(angle));
	}
	int count = DecomposeAndCheck(star, 10);
	cr_assert(count <= 6, "%d pieces; the pentagon and five tips make 6", count);
}

// Comb: an 11 × 1 back with five 1 × 3 teeth standing on it, ten reflex corners (two at each
// tooth's foot). The fewest pieces is ⌈10/2⌉ + 1 = 6 (the lower bound, met by the back and the
// five teeth), and pairing the corners at each tooth's foot finds exactly that.
Test(decompose, comb_is_six_pieces)
{
	tbVec2 comb[4 + 5 * 4];
	int n = 0;
	comb[n++] = tbMakeVec2(-1.0f, 0.0f);
	comb[n++] = tbMakeVec2(10.0f, 0.0f);
	comb[n++] = tbMakeVec2(10.0f, 1.0f);
	for (int t = 4; t >= 0; --t)
	{
		float x = 2.0f * (float)t;
		comb[n++] = tbMakeVec2(x + 1.0f, 1.0f);
		comb[n++] = tbMakeVec2(x + 1.0f, 4.0f);
		comb[n++] = tbMakeVec2(x, 4.0f);
		comb[n++] = tbMakeVec2(x, 1.0f);
	}
	comb[n++] = tbMakeVec2(-1.0f, 1.0f);
	cr_assert_eq(ReflexCount(comb, n), 10);
	cr_assert_eq(DecomposeAndCheck(comb, n), 6);
}

// A 100-vertex terrain outline: a flat bottom 1 m below the lowest point and 98 surface points of
// a hilly height field, the shape a level editor exports.
Test(decompose, terrain_of_100_vertices)
{
	tbVec2 terrain[100];
	terrain[0] = tbMakeVec2(0.0f, -1.0f);
	terrain[1] = tbMakeVec2(97.0f, -1.0f);
	for (int i = 0; i < 98; ++i)
	{
		float x = 97.0f - (float)i;
		float y = 2.0f + 1.5f * sinf(0.31f * x) + 0.7f * sinf(1.7f * x + 0.4f);
		terrain[2 + i] = tbMakeVec2(x, y);
	}
	int count = DecomposeAndCheck(terrain, 100);
	cr_assert(count <= 98, "%d pieces", count);
}

// Bad outlines are refused with one error naming the problem, and the pieces are not written.
Test(decompose, bad_input_is_refused, .init = SetupErrors, .fini = TeardownErrors)
{
	tbPolygon sentinel = tbMakeBox(1.0f, 1.0f);
	for (int i = 0; i < 4; ++i)
	{
		s_pieces[i] = sentinel;
	}
	tbVec2 square[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
	struct
	{
		tbVec2 points[6];
		int count;
		int capacity;
		const char* fragment;
	} cases[] = {
		{{{0, 0}, {1, 0}}, 2, 4, "count 2"},
		{{{0, 0}, {1, 0}, {NAN, 1}}, 3, 4, "points[2]"},
		{{{0, 0}, {1, 0}, {INFINITY, 1}}, 3, 4, "points[2]"},
		{{{0, 0}, {1, 0}, {1, 0}, {0, 1}}, 4, 4, "duplicate"},
		{{{0, 0}, {2, 2}, {2, 0}, {0, 1}}, 4, 4, "crosses itself"},
		{{{0, 0}, {1, 0}, {2, 0}}, 3, 4, "no area"},
		{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 6, 1, "capacity"},
	};
	int n = (int)(sizeof(cases) / sizeof(cases[0]));
	for (int c = 0; c < n; ++c)
	{
		int before = s_errors;
		int count = tbDecomposePolygon(cases[c].points, cases[c].count, s_pieces, cases[c].capacity);
		cr_assert_eq(count, 0, "case %d", c);
		ExpectError(before, "tbDecomposePolygon", cases[c].fragment);
	}
	int before = s_errors;
	cr_assert_eq(tbDecomposePolygon(NULL, 4, s_pieces, 4), 0);
	ExpectError(before, "tbDecomposePolygon", "NULL");
	before = s_errors;
	cr_assert_eq(tbDecomposePolygon(square, 4, NULL, 4), 0);
	ExpectError(before, "tbDecomposePolygon", "NULL");
	for (int i = 0; i < 4; ++i)
	{
		cr_assert(memcmp(s_pieces + i, &sentinel, sizeof(sentinel)) == 0, "piece %d was written", i);
	}
	// A convex outline is one piece (when it fits in TB_MAX_POLYGON_VERTICES).
	cr_assert_eq(tbDecomposePolygon(square, 4, s_pieces, 4), 1);
	cr_assert_eq(s_pieces[0].count, 4);
}

static tbBodyId DropBody(tbWorldId world, const tbPolygon* pieces, int count, tbVec2 position)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = position;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	for (int i = 0; i < count; ++i)
	{
		tbCreatePolygonShape(body, &shapeDef, pieces + i);
	}
	return body;
}

// An L-shaped body made of its pieces has the L's mass (density × area 3) and centroid (5/6, 5/6)
// (mean of three unit squares' centres); dropped on its long side it comes to rest upright exactly
// where its convex hull does, since both touch the ground along the same edge: same height (both
// within the soft contact's rest sag of 0.01 m of the exact 0) and angle within 1e-3 rad.
Test(decompose, concave_body_rests_like_its_hull)
{
	tbVec2 l[] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
	tbPolygon pieces[4];
	int count = tbDecomposePolygon(l, 6, pieces, 4);
	cr_assert_eq(count, 2);
	tbHull hull = tbComputeHull(l, 6);
	tbPolygon hullPolygon = tbMakePolygon(&hull, 0.0f);

	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = tbMakeVec2(0.0f, -10.0f);
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef groundDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &groundDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbSegment floor = {{-20.0f, 0.0f}, {20.0f, 0.0f}};
	tbCreateSegmentShape(ground, &shapeDef, &floor);
	tbBodyId concave = DropBody(world, pieces, count, tbMakeVec2(-5.0f, 0.5f));
	tbBodyId convex = DropBody(world, &hullPolygon, 1, tbMakeVec2(5.0f, 0.5f));

	cr_assert_float_eq(tbBody_GetMass(concave), 3.0f, 1e-5f);
	tbVec2 centre = tbBody_GetLocalCenter(concave);
	cr_assert_float_eq(centre.x, 5.0f / 6.0f, 1e-5f);
	cr_assert_float_eq(centre.y, 5.0f / 6.0f, 1e-5f);
	for (int step = 0; step < 240; ++step)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
	}
	float yConcave = tbBody_GetPosition(concave).y, yConvex = tbBody_GetPosition(convex).y;
	cr_assert(fabsf(yConcave) < 0.01f && fabsf(yConvex) < 0.01f, "rest heights %g and %g", (double)yConcave,
			  (double)yConvex);
	cr_assert(fabsf(yConcave - yConvex) < 0.005f, "concave rests at %g, hull at %g", (double)yConcave,
			  (double)yConvex);
	cr_assert(fabsf(tbRot_GetAngle(tbBody_GetRotation(concave))) < 1e-3f);
	cr_assert(fabsf(tbRot_GetAngle(tbBody_GetRotation(convex))) < 1e-3f);
	cr_assert(tbBody_IsAwake(concave) == false, "the concave body should sleep after 4 s at rest");
	tbDestroyWorld(world);
}

// Robustness: random radial outlines of 64 to 1,024 points (radius 5 to 9 m, every point seen
// from the centre, many nearly collinear triples) decompose without error into convex pieces
// that do not overlap and cover the outline, except for thin ears dropped where three corners
// lie within the slop of one line: each leaves a gap thinner than TB_LINEAR_SLOP along an edge
// of at most the outline's diameter, 18 m, so the area may fall short by up to 0.005 × 18 m² per
// such ear; at most 1 % of the points are allowed to make one (they are far fewer).
Test(decompose, random_radial_outlines)
{
	static tbVec2 outline[1024];
	unsigned seed = 12345u;
	for (int n = 64; n <= 1024; n *= 2)
	{
		for (int i = 0; i < n; ++i)
		{
			seed = seed * 1664525u + 1013904223u;
			float radius = 5.0f + 4.0f * (float)(seed >> 8) / 16777216.0f;
			float angle = 2.0f * 3.14159265f * (float)i / (float)n;
			outline[i] = tbMakeVec2(radius * cosf(angle), radius * sinf(angle));
		}
		int count = tbDecomposePolygon(outline, n, s_pieces, MAX_PIECES);
		cr_assert(count > 0, "%d points: decomposition failed", n);
		double area = fabs(SignedArea(outline, n)), sum = 0.0;
		for (int i = 0; i < count; ++i)
		{
			cr_assert_eq(ReflexCount(s_pieces[i].vertices, s_pieces[i].count), 0);
			sum += SignedArea(s_pieces[i].vertices, s_pieces[i].count);
		}
		// Dropping a nearly straight corner adds area at a reflex one and removes it at a convex one.
		double dropped = DroppedArea(outline, n);
		double allowed = 1e-5 * area + dropped + 0.01 * n * TB_LINEAR_SLOP * 18.0;
		cr_assert(sum - area <= 1e-5 * area + dropped && area - sum <= allowed, "%d points: %.6g of %.6g covered", n, sum, area);
		for (int i = 0; i < count; ++i)
		{
			for (int j = i + 1; j < count; ++j)
			{
				if (OverlapArea(s_pieces + i, s_pieces + j) > 1e-6 * area)
				{
					cr_assert_fail("%d points: pieces %d, %d overlap", n, i, j);
				}
			}
		}
	}
}

/// An 11-pointed star, tips `outer` and notches `inner` from (cx, cy) (metres).
static void MakeStar(tbVec2* p, float cx, float cy, float outer, float inner)
{
	for (int i = 0; i < 11; ++i)
	{
		float radius = i % 2 == 0 ? outer : inner;
		float angle = 2.0f * 3.14159265f * (float)i / 11.0f;
		p[i] = tbMakeVec2(cx + radius * cosf(angle), cy + radius * sinf(angle));
	}
}

// The pieces cover the outline to within 1 % of its area (TB_DECOMPOSE_TOLERANCE: what the
// slop-sized welds may take from features well above TB_LINEAR_SLOP = 5 mm) or the outline is
// refused naming the reason, at every scale from 1.5 cm to 1.5 km. A star 3 cm across has notches
// of millimetres, which polygons cannot hold (refused); from 30 cm up every star is cut, and the
// cover is checked in full (DecomposeAndCheck: convex pieces of outline points, no overlaps, the
// area within the dropped slivers).
Test(decompose, star_covers_or_is_refused_at_every_scale, .init = SetupErrors, .fini = TeardownErrors)
{
	float scales[] = {1.0f, 2.0f, 10.0f, 100.0f, 1000.0f, 10000.0f, 100000.0f};
	for (int k = 0; k < (int)(sizeof(scales) / sizeof(scales[0])); ++k)
	{
		float s = scales[k];
		tbVec2 star[11];
		MakeStar(star, 0.0f, 0.0f, 0.015f * s, 0.006f * s);
		int before = s_errors;
		int count = tbDecomposePolygon(star, 11, s_pieces, MAX_PIECES);
		double area = fabs(SignedArea(star, 11)), sum = 0.0;
		for (int i = 0; i < count; ++i)
		{
			sum += SignedArea(s_pieces[i].vertices, s_pieces[i].count);
		}
		if (count == 0)
		{
			cr_assert(s < 10.0f, "scale %g: refused", (double)s);
			ExpectError(before, "tbDecomposePolygon", "too small for polygons");
			continue;
		}
		cr_assert(fabs(sum - area) <= 0.01 * area, "scale %g: pieces cover %.6g of %.6g", (double)s, sum, area);
		if (s >= 10.0f)
		{
			DecomposeAndCheck(star, 11);
		}
	}
}

// A hexagon 2 cm across with a notch 3 mm deep in one side: within the slop, so no piece can keep
// the notch, and a piece that spans it would leave the outline (by the notch's 6 % of the area).
// Refused, naming the reason; the same outline ×100 (a 30 cm notch) is cut exactly.
Test(decompose, a_notch_within_the_slop_is_refused_not_covered_over, .init = SetupErrors, .fini = TeardownErrors)
{
	for (int k = 0; k < 2; ++k)
	{
		float s = k == 0 ? 1.0f : 100.0f;
		tbVec2 outline[7];
		for (int i = 0; i < 6; ++i)
		{
			float angle = 2.0f * 3.14159265f * (float)i / 6.0f;
			outline[i < 1 ? i : i + 1] = tbMakeVec2(4.0f + 0.01f * s * cosf(angle), 5.0f + 0.01f * s * sinf(angle));
		}
		// Between corners 0 and 1 (now 0 and 2): the side's midpoint moved 3 mm toward the centre.
		tbVec2 mid = tbMulSV(0.5f, tbAdd(outline[0], outline[2]));
		tbVec2 inward = tbNormalize(tbSub(tbMakeVec2(4.0f, 5.0f), mid));
		outline[1] = tbMulAdd(mid, 0.003f * s, inward);
		int before = s_errors;
		int count = tbDecomposePolygon(outline, 7, s_pieces, MAX_PIECES);
		if (k == 0)
		{
			cr_assert_eq(count, 0);
			ExpectError(before, "tbDecomposePolygon", "too small for polygons");
		}
		else
		{
			cr_assert_eq(s_errors, before, "'%s'", s_lastError);
			DecomposeAndCheck(outline, 7);
		}
	}
}

// Two squares that touch at one corner, given as one outline that visits the shared corner twice
// (points 1 and 4): not simple, though no two edges cross. Refused, naming both points.
Test(decompose, a_point_repeated_anywhere_is_refused, .init = SetupErrors, .fini = TeardownErrors)
{
	tbVec2 pinched[6] = {{0.0f, 0.0f}, {1.0f, 1.0f}, {2.0f, 0.0f}, {2.0f, 2.0f}, {1.0f, 1.0f}, {0.0f, 2.0f}};
	int before = s_errors;
	cr_assert_eq(tbDecomposePolygon(pinched, 6, s_pieces, MAX_PIECES), 0);
	ExpectError(before, "tbDecomposePolygon", "points[1] and points[4]");
}

/// How far q lies outside the outline: 0 inside, else its distance to the nearest edge.
static double OutsideBy(double qx, double qy, const tbVec2* p, int n)
{
	tbVec2 q = {(float)qx, (float)qy};
	if (PointInOutline(q, p, n))
	{
		return 0.0;
	}
	double nearest = INFINITY;
	for (int i = 0, j = n - 1; i < n; j = i++)
	{
		double ex = (double)p[i].x - p[j].x, ey = (double)p[i].y - p[j].y;
		double dx = qx - p[j].x, dy = qy - p[j].y;
		double t = fmax(0.0, fmin(1.0, (dx * ex + dy * ey) / (ex * ex + ey * ey)));
		nearest = fmin(nearest, hypot(dx - t * ex, dy - t * ey));
	}
	return nearest;
}

/// The farthest a piece's boundary lies outside the outline (sampled at 64 points per edge).
static double LargestExcursion(const tbVec2* outline, int n, int count)
{
	double largest = 0.0;
	for (int i = 0; i < count; ++i)
	{
		const tbPolygon* piece = s_pieces + i;
		for (int k = 0; k < piece->count; ++k)
		{
			tbVec2 a = piece->vertices[k], b = piece->vertices[(k + 1) % piece->count];
			for (int s = 0; s < 64; ++s)
			{
				double t = (double)s / 64.0;
				largest = fmax(largest, OutsideBy(a.x + t * ((double)b.x - a.x), a.y + t * ((double)b.y - a.y), outline, n));
			}
		}
	}
	return largest;
}

// A square 1.4 km on a side with a notch 1 cm deep (twice the slop) in the middle of each side.
// A corner counts as straight to rounding within 1e-5 of its chord's length, which on these
// 1.4 km chords was 1.4 cm: the notches were dropped as straight and the pieces spanned them, 1 cm
// outside the outline. Straight now also means within TB_LINEAR_SLOP of the chord.
Test(decompose, a_notch_deeper_than_the_slop_on_a_long_side_is_not_spanned)
{
	tbVec2 outline[8];
	for (int i = 0; i < 4; ++i)
	{
		float angle = 0.5f * 3.14159265f * (float)i, next = angle + 0.5f * 3.14159265f;
		tbVec2 corner = {1000.0f * cosf(angle), 1000.0f * sinf(angle)};
		tbVec2 mid = tbMulSV(0.5f, tbAdd(corner, tbMakeVec2(1000.0f * cosf(next), 1000.0f * sinf(next))));
		outline[2 * i] = corner;
		outline[2 * i + 1] = tbMulAdd(mid, 0.01f, tbNormalize(tbNeg(mid)));
	}
	int count = tbDecomposePolygon(outline, 8, s_pieces, MAX_PIECES);
	cr_assert(count > 0);
	double excursion = LargestExcursion(outline, 8, count);
	cr_assert(excursion <= TB_LINEAR_SLOP, "a piece leaves the outline by %.3g m", excursion);
}

// A box whose bottom side is a run of 257 points 10 cm apart, each lifted from the chord of the
// points two levels up (midpoint displacement) by 0.8 of the slop: every point is within the slop
// of the chord of its neighbours when it is tested, and the points pile up to several slops above
// the side's end-to-end chord. Dropped one after another against their neighbours alone, they
// carried the chord up to the top of the pile: a piece spanning the whole side, centimetres
// outside the outline. A point is now dropped only when the points dropped before it between the
// same corners stay within the slop of the chord too.
Test(decompose, welded_points_do_not_carry_a_side_beyond_the_slop)
{
	enum
	{
		side = 257,
		count = side + 2
	};
	static tbVec2 outline[count];
	double height[side];
	height[0] = 0.0;
	height[side - 1] = 0.0;
	for (int step = (side - 1) / 2; step >= 1; step /= 2)
	{
		for (int i = step; i < side - 1; i += 2 * step)
		{
			height[i] = 0.5 * (height[i - step] + height[i + step]) + 0.8 * TB_LINEAR_SLOP;
		}
	}
	for (int i = 0; i < side; ++i)
	{
		outline[i] = tbMakeVec2(0.1f * (float)i, (float)height[i]); // inward: the box lies above
	}
	outline[side] = tbMakeVec2(0.1f * (float)(side - 1), 5.0f);
	outline[side + 1] = tbMakeVec2(0.0f, 5.0f);
	int pieces = tbDecomposePolygon(outline, count, s_pieces, MAX_PIECES);
	cr_assert(pieces > 0);
	double excursion = LargestExcursion(outline, count, pieces);
	cr_assert(excursion <= TB_LINEAR_SLOP * 1.001, "a piece leaves the outline by %.3g m", excursion);
}
