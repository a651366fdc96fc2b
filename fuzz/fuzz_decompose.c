// Fuzz harness for tbDecomposePolygon: bytes become an outline of 3 to TB_MAX_DECOMPOSE_POINTS
// points at a scale from 1 cm to 1 km, sometimes far from the origin, in either winding: a
// radial star, an x-monotone random walk, a comb, a convex outline with points added within and
// around the slop of its edges, or raw points (which mostly cross themselves), each perhaps with a
// point repeated or nudged by about the slop. The outline goes to tbDecomposePolygon with room for
// count − 2 pieces, or less.
//
// Checks. A refusal (0 pieces) reports exactly one error. Pieces: each has 3 to
// TB_MAX_POLYGON_VERTICES vertices, is convex and counter-clockwise (tbValidateHull and a cross
// product at every corner), with unit normals and no radius; their areas add up to the outline's
// within 1 % (the tolerance tbDecomposePolygon promises); no piece leaves the outline: every
// vertex, points along every edge and the centroid lie inside it or within 2 × TB_LINEAR_SLOP of
// its boundary (points within the slop of a chord are welded away, and a piece's corner within
// the slop of straight may be dropped on top of that), plus the rounding of coordinates that far
// from the origin. A star of at most 32 points with every
// radius between 0.3 and 1 of its scale (1 m or more), centred at the origin, is a simple polygon
// whose features are far above the slop: it must be decomposed, not refused. No bytes left behind.
#include "fuzz_input.h"

#include "tumble/tumble.h"

#include <stdio.h>
#include <stdlib.h>

static int s_errors = 0;
static char s_lastError[512];

static void CountError(const char* message, void* context)
{
	(void)context;
	s_errors += 1;
	snprintf(s_lastError, sizeof(s_lastError), "%s", message);
	if (getenv("FUZZ_TRACE") != NULL)
	{
		fprintf(stderr, "refused: %s\n", message);
	}
}

/// A fraction in [0, 1] from one byte.
static float Unit(FuzzInput* in)
{
	return (float)FuzzByte(in) / 255.0f;
}

/// Twice the signed area, in double about the first point (as the library measures it).
static double Area2(const tbVec2* p, int n)
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

/// Distance from q to segment a–b, in double.
static double SegmentDistance(double qx, double qy, tbVec2 a, tbVec2 b)
{
	double ex = (double)b.x - a.x, ey = (double)b.y - a.y;
	double dx = qx - a.x, dy = qy - a.y;
	double ee = ex * ex + ey * ey;
	double t = ee > 0.0 ? (dx * ex + dy * ey) / ee : 0.0;
	t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
	double px = dx - t * ex, py = dy - t * ey;
	return sqrt(px * px + py * py);
}

/// Inside the outline (crossing number, either winding) or within `tolerance` of its boundary.
static bool InsideOrNear(const tbVec2* p, int n, double qx, double qy, double tolerance)
{
	bool inside = false;
	double nearest = INFINITY;
	for (int i = 0, j = n - 1; i < n; j = i++)
	{
		double yi = p[i].y, yj = p[j].y, xi = p[i].x, xj = p[j].x;
		if ((yi > qy) != (yj > qy) && qx < (xj - xi) * (qy - yi) / (yj - yi) + xi)
		{
			inside = !inside;
		}
		double d = SegmentDistance(qx, qy, p[j], p[i]);
		nearest = d < nearest ? d : nearest;
	}
	return inside || nearest <= tolerance;
}

/// Build an outline; returns its point count. *mustSucceed: a star whose features are far above the
/// slop (see the file comment).
static int MakeOutline(FuzzInput* in, tbVec2* p, bool* mustSucceed)
{
	*mustSucceed = false;
	int sizeClass = FuzzInt(in, 8);
	int n;
	if (sizeClass < 5)
	{
		n = 3 + FuzzInt(in, 14); // 3..16
	}
	else if (sizeClass < 7)
	{
		n = 3 + FuzzInt(in, 62); // ..64
	}
	else
	{
		n = 3 + (FuzzInt(in, 256) << 2 | FuzzInt(in, 4)) % (TB_MAX_DECOMPOSE_POINTS - 2); // ..1024
	}
	// Scale: 1 cm to 1 km in steps of a factor of about 1.6.
	float scale = powf(10.0f, -2.0f + 5.0f * (float)FuzzInt(in, 26) / 25.0f);
	tbVec2 offset = tbVec2_zero;
	if (FuzzInt(in, 4) == 0)
	{
		float far = powf(10.0f, (float)FuzzInt(in, 6)); // up to 1e5 m from the origin
		float ox = (Unit(in) - 0.5f) * 2.0f * far;
		float oy = (Unit(in) - 0.5f) * 2.0f * far;
		offset = tbMakeVec2(ox, oy);
	}
	int style = FuzzInt(in, 6);
	const float slop = TB_LINEAR_SLOP;
	switch (style)
	{
		case 0: // radial star: increasing angles, so simple whatever the radii
		{
			float low = 0.05f + 0.9f * Unit(in);
			bool jitter = FuzzInt(in, 2) == 0;
			bool conservative = true;
			for (int i = 0; i < n; ++i)
			{
				float u = Unit(in);
				float radius = scale * (low + (1.0f - low) * u);
				float angle = 6.2831853f * ((float)i + (jitter ? 0.8f * (Unit(in) - 0.5f) : 0.0f)) / (float)n;
				p[i] = tbMakeVec2(radius * cosf(angle), radius * sinf(angle));
				conservative = conservative && radius >= 0.3f * scale;
			}
			*mustSucceed = conservative && jitter == false && n <= 32 && scale >= 1.0f;
			break;
		}
		case 1: // x-monotone: a walk above the axis left to right, another below it right to left
		{
			int top = n / 2 + 1, bottom = n - top;
			float y = scale * 0.5f;
			for (int i = 0; i < top; ++i)
			{
				y = fabsf(y + scale * (Unit(in) - 0.5f)) + slop * (float)FuzzInt(in, 3);
				p[i] = tbMakeVec2(scale * (float)i / (float)(top - 1 > 0 ? top - 1 : 1), y);
			}
			y = -scale * 0.5f;
			for (int i = 0; i < bottom; ++i)
			{
				y = -fabsf(y + scale * (Unit(in) - 0.5f)) - slop * (float)FuzzInt(in, 3);
				float x = scale * (1.0f - ((float)i + 0.5f) / (float)bottom);
				p[top + i] = tbMakeVec2(x, y);
			}
			break;
		}
		case 2: // a comb: teeth of random depth and width along the bottom edge of a bar
		{
			int teeth = (n - 2) / 2;
			n = 2 + 2 * teeth;
			if (teeth < 1)
			{
				teeth = 1;
				n = 4;
			}
			float depth = scale;
			for (int i = 0; i < teeth; ++i)
			{
				float x0 = scale * (float)i;
				float width = scale * (0.02f + 0.96f * Unit(in));
				float tooth = depth * (0.001f + Unit(in));
				p[2 * i] = tbMakeVec2(x0, -tooth * (float)(i & 1));
				p[2 * i + 1] = tbMakeVec2(x0 + width, -tooth * (float)(i & 1));
			}
			p[n - 2] = tbMakeVec2(scale * (float)teeth, depth);
			p[n - 1] = tbMakeVec2(0.0f, depth);
			break;
		}
		case 3: // a convex outline with points added along its edges, near the slop off them
		{
			int corners = 3 + FuzzInt(in, 6);
			int perEdge = n / corners > 0 ? n / corners : 1;
			n = 0;
			for (int c = 0; c < corners; ++c)
			{
				float a0 = 6.2831853f * (float)c / (float)corners, a1 = 6.2831853f * (float)(c + 1) / (float)corners;
				tbVec2 q0 = {scale * cosf(a0), scale * sinf(a0)}, q1 = {scale * cosf(a1), scale * sinf(a1)};
				tbVec2 outward = tbNormalize(tbRightPerp(tbSub(q1, q0)));
				for (int k = 0; k < perEdge && n < TB_MAX_DECOMPOSE_POINTS; ++k)
				{
					float t = (float)k / (float)perEdge;
					// Off the edge by a multiple of the slop in [−2, 2], rounded to 0.25: straight,
					// within the slop, just beyond it, either way.
					float off = slop * 0.25f * (float)(FuzzInt(in, 17) - 8);
					p[n++] = tbMulAdd(tbLerp(q0, q1, t), k == 0 ? 0.0f : off, outward);
				}
			}
			break;
		}
		case 4: // a random walk closed by its last edge (often crosses itself)
		{
			tbVec2 at = tbVec2_zero;
			for (int i = 0; i < n; ++i)
			{
				float angle = 6.2831853f * (float)i / (float)n + 2.0f * (Unit(in) - 0.5f);
				float step = scale * (0.1f + Unit(in));
				at = tbMulAdd(at, step, tbMakeVec2(cosf(angle), sinf(angle)));
				p[i] = at;
			}
			break;
		}
		default: // raw points in a square
			for (int i = 0; i < n; ++i)
			{
				float x = scale * (Unit(in) - 0.5f);
				p[i] = tbMakeVec2(x, scale * (Unit(in) - 0.5f));
			}
			break;
	}
	// Mutations: a point repeated, one nudged by about the slop, hostile values now and then.
	int mutation = FuzzInt(in, 8);
	if (mutation == 0 && n >= 4)
	{
		int from = FuzzInt(in, n), to = FuzzInt(in, n);
		p[to] = p[from];
		*mustSucceed = *mustSucceed && from == to;
	}
	else if (mutation == 1)
	{
		int k = FuzzInt(in, n);
		int j = (k + 1) % n;
		tbVec2 d = tbSub(p[j], p[k]);
		float length = tbLength(d);
		if (length > 0.0f)
		{
			// The next point moved to within 0.5 to 2 slops of this one (a near-duplicate).
			float factor = slop * (0.5f + 1.5f * Unit(in)) / length;
			p[j] = tbMulAdd(p[k], factor, d);
			*mustSucceed = false;
		}
	}
	else if (mutation == 2)
	{
		int k = FuzzInt(in, n);
		float x = FuzzFloat(in);
		p[k] = tbMakeVec2(x, FuzzFloat(in));
		*mustSucceed = false;
	}
	if (FuzzInt(in, 2) == 0)
	{
		for (int i = 0; i < n / 2; ++i) // clockwise
		{
			tbVec2 t = p[i];
			p[i] = p[n - 1 - i];
			p[n - 1 - i] = t;
		}
	}
	for (int i = 0; i < n; ++i)
	{
		p[i] = tbAdd(p[i], offset);
	}
	*mustSucceed = *mustSucceed && offset.x == 0.0f && offset.y == 0.0f;
	return n;
}

static void CheckPiece(const tbPolygon* piece, int index, const tbVec2* outline, int n, double tolerance)
{
	int m = piece->count;
	FUZZ_CHECK(m >= 3 && m <= TB_MAX_POLYGON_VERTICES, "piece %d has %d vertices", index, m);
	FUZZ_CHECK(piece->radius == 0.0f, "piece %d has radius %g", index, (double)piece->radius);
	tbHull hull;
	memset(&hull, 0, sizeof(hull));
	memcpy(hull.points, piece->vertices, (size_t)m * sizeof(tbVec2));
	hull.count = m;
	FUZZ_CHECK(tbValidateHull(&hull), "piece %d (%d vertices, first (%g, %g)) is not a valid hull", index, m,
			   (double)piece->vertices[0].x, (double)piece->vertices[0].y);
	for (int k = 0; k < m; ++k)
	{
		tbVec2 a = piece->vertices[(k + m - 1) % m], b = piece->vertices[k], c = piece->vertices[(k + 1) % m];
		double cross = ((double)b.x - a.x) * ((double)c.y - b.y) - ((double)b.y - a.y) * ((double)c.x - b.x);
		FUZZ_CHECK(cross > 0.0, "piece %d turns the wrong way (or not at all) at vertex %d: cross %g", index, k, cross);
		tbVec2 normal = piece->normals[k];
		FUZZ_CHECK(fabsf(tbLength(normal) - 1.0f) < 1e-3f, "piece %d normal %d has length %g", index, k,
				   (double)tbLength(normal));
		FUZZ_CHECK(InsideOrNear(outline, n, b.x, b.y, tolerance), "piece %d vertex %d (%g, %g) is outside the outline",
				   index, k, (double)b.x, (double)b.y);
		// Along the edge: its midpoint, and for outlines small enough to keep the harness fast, 16
		// points (a long edge may pass outside the outline away from its middle).
		int samples = n <= 128 ? 16 : 2;
		for (int s = 1; s < samples; ++s)
		{
			double t = (double)s / samples;
			double mx = b.x + t * ((double)c.x - b.x), my = b.y + t * ((double)c.y - b.y);
			FUZZ_CHECK(InsideOrNear(outline, n, mx, my, tolerance),
					   "piece %d edge %d at %g (%.9g, %.9g) is outside the outline (tolerance %g)", index, k, t, mx,
					   my, tolerance);
		}
	}
	FUZZ_CHECK(InsideOrNear(outline, n, piece->centroid.x, piece->centroid.y, tolerance),
			   "piece %d's centroid (%g, %g) is outside the outline", index, (double)piece->centroid.x,
			   (double)piece->centroid.y);
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static tbVec2 outline[TB_MAX_DECOMPOSE_POINTS];
	static tbPolygon pieces[TB_MAX_DECOMPOSE_POINTS];
	tbSetErrorCallback(CountError, NULL);
	int64_t startBytes = tbGetByteCount();
	FuzzInput in = {data, size, 0};
	bool mustSucceed;
	int n = MakeOutline(&in, outline, &mustSucceed);
	int capacity = n - 2;
	int room = FuzzInt(&in, 16);
	if (room == 0)
	{
		capacity = FuzzInt(&in, 4); // perhaps too small: refused with a message, never overrun
		mustSucceed = false;
	}
	s_errors = 0;
	s_lastError[0] = '\0';
	int count = tbDecomposePolygon(outline, n, room == 1 ? NULL : pieces, capacity);
	if (getenv("FUZZ_TRACE") != NULL)
	{
		// The outline and the pieces, for a finding to be read (./fuzz_decompose CRASH_FILE).
		fprintf(stderr, "outline of %d points, capacity %d -> %d pieces\n", n, capacity, count);
		for (int i = 0; i < n; ++i)
		{
			fprintf(stderr, "  (%.9g, %.9g)\n", (double)outline[i].x, (double)outline[i].y);
		}
		for (int i = 0; i < count; ++i)
		{
			fprintf(stderr, "piece %d:", i);
			for (int k = 0; k < pieces[i].count; ++k)
			{
				fprintf(stderr, " (%.9g, %.9g)", (double)pieces[i].vertices[k].x, (double)pieces[i].vertices[k].y);
			}
			fprintf(stderr, "\n");
		}
	}
	if (room == 1)
	{
		FUZZ_CHECK(count == 0, "pieces NULL but %d returned", count);
	}
	FUZZ_CHECK(tbGetByteCount() == startBytes, "%lld bytes left", (long long)(tbGetByteCount() - startBytes));
	FUZZ_CHECK(count >= 0 && count <= (capacity > 0 ? capacity : 0), "%d pieces for capacity %d", count, capacity);
	if (count == 0)
	{
		FUZZ_CHECK(s_errors == 1, "refused with %d errors reported (must be one)", s_errors);
		FUZZ_CHECK(mustSucceed == false || room == 1, "a star of %d points, features far above the slop, refused: %s",
				   n, s_lastError);
		return 0;
	}
	FUZZ_CHECK(s_errors == 0, "%d pieces and %d errors reported (last: %s)", count, s_errors, s_lastError);
	double extent = 0.0;
	for (int i = 0; i < n; ++i)
	{
		extent = fmax(extent, fmax(fabs((double)outline[i].x), fabs((double)outline[i].y)));
	}
	// What a piece may stick out: a point within the slop of the chord of its kept neighbours is
	// welded away (tbComputeHull's rule), and a corner within the slop of straight may be dropped
	// from a piece on top of that; plus a few units in the last place of the outline's largest
	// coordinate (a piece's centroid is computed in float).
	double tolerance = 2.0 * (double)TB_LINEAR_SLOP + 8.0 * extent * FLT_EPSILON;
	double outlineArea = fabs(Area2(outline, n)) * 0.5;
	double piecesArea = 0.0;
	for (int i = 0; i < count; ++i)
	{
		CheckPiece(pieces + i, i, outline, n, tolerance);
		piecesArea += Area2(pieces[i].vertices, pieces[i].count) * 0.5;
	}
	FUZZ_CHECK(fabs(piecesArea - outlineArea) <= 0.01 * outlineArea,
			   "%d pieces cover %.9g of an outline of area %.9g (%d points): %.3g %% off", count, piecesArea,
			   outlineArea, n, 100.0 * fabs(piecesArea - outlineArea) / outlineArea);
	return 0;
}
