// Tumble: shape construction, mass properties, bounding boxes, point tests and ray casts for
// the solid shapes (circle, capsule, rounded convex polygon) and the segment.
//
// Mass properties are computed exactly for every shape, rounded polygons included. A polygon
// with rounding radius r is the Minkowski sum of its core polygon and a disc of radius r; its
// area splits into pieces whose moments are closed forms:
//   core polygon      fan of triangles (o, o + e1, o + e2) with D = e1 × e2:
//                       area = D/2, centroid = o + (e1 + e2)/3,
//                       polar moment about o = (D/12)(e1·e1 + e1·e2 + e2·e2)
//   edge rectangles   one per edge of length L, width r, pushed out along the edge normal:
//                       area = L·r, moment about its centre = L·r·(L² + r²)/12
//   corner sectors    one per vertex, radius r, angle φ between the adjacent normals (Σφ = 2π):
//                       area = φr²/2, moment about the vertex = φr⁴/4,
//                       centroid 4r·sin(φ/2)/(3φ) from the vertex along the normals' bisector
// Moments are gathered about a reference point o (the vertex average, to keep the numbers
// small) and moved to the centre of mass with the parallel axis theorem I_c = I_o − m|c − o|².
// References: Ericson, "Real-Time Collision Detection", §3.4 (polygon area and centroid);
// Eberly, "Polyhedral Mass Properties" (2002) for the triangle moments.
//
// Ray casts follow Ericson §5.3: the circle by the quadratic in the ray parameter, solved about
// the point of closest approach to avoid cancellation (§5.3.2); the polygon by Cyrus–Beck
// clipping against its edge half-planes (§5.3.8); the segment by a 2×2 solve with cross
// products. Capsules and rounded polygons are cast against the pieces of their boundary (end or
// corner circles and offset edges): for a ray starting outside, the first boundary crossing is
// the nearest hit among the pieces. A ray that starts inside a solid shape reports no hit.

#include "core/core.h"

#include "tumble/collision.h"

// ---------------------------------------------------------------------------------------------
// Construction

static tbPolygon tbEmptyPolygon(void)
{
	tbPolygon polygon = {0};
	return polygon;
}

// Centroid of a convex polygon's area (triangle fan about the vertex average; Ericson §3.4).
static tbVec2 tbComputePolygonCentroid(const tbVec2* vertices, int count)
{
	tbVec2 origin = tbVec2_zero;
	for (int i = 0; i < count; ++i)
	{
		origin = tbAdd(origin, vertices[i]);
	}
	origin = tbMulSV(1.0f / (float)count, origin);

	tbVec2 weighted = tbVec2_zero;
	float area = 0.0f;
	for (int i = 0; i < count; ++i)
	{
		tbVec2 e1 = tbSub(vertices[i], origin);
		tbVec2 e2 = tbSub(vertices[(i + 1) % count], origin);
		float triangleArea = 0.5f * tbCross(e1, e2);
		// triangle centroid relative to origin: (0 + e1 + e2) / 3
		weighted = tbMulAdd(weighted, triangleArea / 3.0f, tbAdd(e1, e2));
		area += triangleArea;
	}
	if (area < FLT_EPSILON)
	{
		return origin;
	}
	return tbMulAdd(origin, 1.0f / area, weighted);
}

// Fill normals and centroid of a polygon whose vertices are already set (counter-clockwise).
// The outward normal of edge v_i → v_{i+1} is its right perpendicular.
static void tbFinishPolygon(tbPolygon* polygon)
{
	int n = polygon->count;
	for (int i = 0; i < n; ++i)
	{
		tbVec2 edge = tbSub(polygon->vertices[(i + 1) % n], polygon->vertices[i]);
		polygon->normals[i] = tbNormalize(tbRightPerp(edge));
	}
	polygon->centroid = tbComputePolygonCentroid(polygon->vertices, n);
}

tbPolygon tbMakePolygon(const tbHull* hull, float radius)
{
	if (tbCheckPointer("tbMakePolygon", "hull", hull) == false ||
		tbCheckLength("tbMakePolygon", "radius", radius, false) == false)
	{
		return tbEmptyPolygon();
	}
	if (tbValidateHull(hull) == false)
	{
		tbReportError("tbMakePolygon", "hull is not a valid convex hull (count %d); build it with tbComputeHull",
					  hull->count);
		return tbEmptyPolygon();
	}
	tbPolygon polygon = tbEmptyPolygon();
	polygon.count = hull->count;
	for (int i = 0; i < hull->count; ++i)
	{
		polygon.vertices[i] = hull->points[i];
	}
	polygon.radius = radius;
	tbFinishPolygon(&polygon);
	return polygon;
}

// A local transform a caller passed: finite position, unit rotation (reported naming f).
static bool tbCheckOffset(const char* f, const char* positionName, tbVec2 position, tbRot rotation)
{
	if (tbCheckVec2(f, positionName, position) == false)
	{
		return false;
	}
	if (tbIsValidRotation(rotation) == false)
	{
		tbReportError(f, "rotation is (%g, %g), not a unit rotation; make it with tbMakeRot", (double)rotation.c,
					  (double)rotation.s);
		return false;
	}
	return true;
}

// The polygon of a hull with a radius, moved by (position, rotation); f names the caller.
static tbPolygon tbMakeOffsetPolygonNamed(const char* f, const tbHull* hull, tbVec2 position, tbRot rotation,
										  float radius)
{
	if (tbCheckOffset(f, "position", position, rotation) == false ||
		tbCheckLength(f, "radius", radius, false) == false)
	{
		return tbEmptyPolygon();
	}
	tbPolygon polygon = tbMakePolygon(hull, radius);
	tbTransform transform = {position, rotation};
	polygon = tbTransformPolygon(transform, &polygon);
	return tbCheckPoints(f, "vertices", polygon.vertices, polygon.count) ? polygon : tbEmptyPolygon();
}

tbPolygon tbMakeOffsetPolygon(const tbHull* hull, tbVec2 position, tbRot rotation)
{
	return tbMakeOffsetPolygonNamed("tbMakeOffsetPolygon", hull, position, rotation, 0.0f);
}

tbPolygon tbMakeOffsetRoundedPolygon(const tbHull* hull, tbVec2 position, tbRot rotation, float radius)
{
	return tbMakeOffsetPolygonNamed("tbMakeOffsetRoundedPolygon", hull, position, rotation, radius);
}

tbPolygon tbMakeSquare(float halfWidth)
{
	return tbMakeBox(halfWidth, halfWidth);
}

// Axis-aligned box polygon with the given core half-widths; caller checks the arguments.
static tbPolygon tbMakeAlignedBox(float hx, float hy, float radius)
{
	tbPolygon box = tbEmptyPolygon();
	box.count = 4;
	box.vertices[0] = tbMakeVec2(-hx, -hy);
	box.vertices[1] = tbMakeVec2(hx, -hy);
	box.vertices[2] = tbMakeVec2(hx, hy);
	box.vertices[3] = tbMakeVec2(-hx, hy);
	box.normals[0] = tbMakeVec2(0.0f, -1.0f);
	box.normals[1] = tbMakeVec2(1.0f, 0.0f);
	box.normals[2] = tbMakeVec2(0.0f, 1.0f);
	box.normals[3] = tbMakeVec2(-1.0f, 0.0f);
	box.radius = radius;
	box.centroid = tbVec2_zero;
	return box;
}

static bool tbCheckBoxSize(const char* function, float halfWidth, float halfHeight)
{
	return tbCheckLength(function, "halfWidth", halfWidth, true) && tbCheckLength(function, "halfHeight", halfHeight, true);
}

tbPolygon tbMakeBox(float halfWidth, float halfHeight)
{
	if (tbCheckBoxSize("tbMakeBox", halfWidth, halfHeight) == false)
	{
		return tbEmptyPolygon();
	}
	return tbMakeAlignedBox(halfWidth, halfHeight, 0.0f);
}

tbPolygon tbMakeRoundedBox(float halfWidth, float halfHeight, float radius)
{
	if (tbCheckBoxSize("tbMakeRoundedBox", halfWidth, halfHeight) == false ||
		tbCheckLength("tbMakeRoundedBox", "radius", radius, false) == false)
	{
		return tbEmptyPolygon();
	}
	return tbMakeAlignedBox(halfWidth, halfHeight, radius);
}

// A box of core half-widths (hx, hy) and a radius, moved by (center, rotation); f names the caller.
static tbPolygon tbMakeOffsetBoxNamed(const char* f, float hx, float hy, tbVec2 center, tbRot rotation, float radius)
{
	if (tbCheckBoxSize(f, hx, hy) == false || tbCheckLength(f, "radius", radius, false) == false ||
		tbCheckOffset(f, "center", center, rotation) == false)
	{
		return tbEmptyPolygon();
	}
	tbPolygon box = tbMakeAlignedBox(hx, hy, radius);
	tbTransform transform = {center, rotation};
	box = tbTransformPolygon(transform, &box);
	return tbCheckPoints(f, "vertices", box.vertices, box.count) ? box : tbEmptyPolygon();
}

tbPolygon tbMakeOffsetBox(float halfWidth, float halfHeight, tbVec2 center, tbRot rotation)
{
	return tbMakeOffsetBoxNamed("tbMakeOffsetBox", halfWidth, halfHeight, center, rotation, 0.0f);
}

tbPolygon tbMakeOffsetRoundedBox(float halfWidth, float halfHeight, tbVec2 center, tbRot rotation, float radius)
{
	return tbMakeOffsetBoxNamed("tbMakeOffsetRoundedBox", halfWidth, halfHeight, center, rotation, radius);
}

tbPolygon tbTransformPolygon(tbTransform transform, const tbPolygon* polygon)
{
	tbPolygon result = *polygon;
	for (int i = 0; i < polygon->count; ++i)
	{
		result.vertices[i] = tbTransformPoint(transform, polygon->vertices[i]);
		result.normals[i] = tbRotateVector(transform.q, polygon->normals[i]);
	}
	result.centroid = tbTransformPoint(transform, polygon->centroid);
	return result;
}

// ---------------------------------------------------------------------------------------------
// Mass

// Area, first moment (area × centroid) and polar second moment of a region, all about the
// same reference point o. Pieces add; density multiplies at the end.
typedef struct tbAreaMoments
{
	float area;
	tbVec2 first;
	float second;
} tbAreaMoments;

// Final mass data from moments about o: c = o + first/area, I_c = ρ·second − m|c − o|².
static tbMassData tbMassFromMoments(tbAreaMoments moments, tbVec2 origin, float density)
{
	tbMassData data = {0};
	data.center = origin;
	if (!(moments.area >= FLT_MIN))
	{
		// No area, or less than FLT_MIN (a 1e-20 m box: 4e-40 m²): 1/area would overflow to ∞ and
		// the centre become ∞ · 0 = NaN. Such a shape has no mass, as a segment has none.
		return data;
	}
	tbVec2 offset = tbMulSV(1.0f / moments.area, moments.first);
	data.mass = density * moments.area;
	data.center = tbAdd(origin, offset);
	float inertia = density * moments.second - data.mass * tbLengthSquared(offset);
	data.rotationalInertia = tbMaxFloat(inertia, 0.0f);
	return data;
}

static bool tbCheckDensity(const char* function, float density)
{
	return tbCheckNonNegative(function, "density", density);
}

tbMassData tbComputeCircleMass(const tbCircle* shape, float density)
{
	tbMassData data = {0};
	if (tbCheckDensity("tbComputeCircleMass", density) == false)
	{
		return data;
	}
	// Disc: m = ρπr², I = m·r²/2 about the centre.
	float rr = shape->radius * shape->radius;
	data.mass = density * TB_PI * rr;
	data.center = shape->center;
	data.rotationalInertia = 0.5f * data.mass * rr;
	return data;
}

tbMassData tbComputeCapsuleMass(const tbCapsule* shape, float density)
{
	tbMassData data = {0};
	if (tbCheckDensity("tbComputeCapsuleMass", density) == false)
	{
		return data;
	}
	// Rectangle L × 2r plus two half discs of radius r at the ends. About the capsule centre:
	//   rectangle  I = m_rect (L² + 4r²)/12
	//   half disc  I about its flat-side centre = m_half r²/2; its centroid sits d = 4r/(3π)
	//              further out, so by the parallel axis theorem (twice)
	//              I = m_half (r²/2 − d² + (L/2 + d)²) = m_half (r²/2 + L²/4 + L·d)
	float r = shape->radius;
	float length = tbDistance(shape->center1, shape->center2);
	float rectMass = density * 2.0f * r * length;
	float discMass = density * TB_PI * r * r;
	float d = 4.0f * r / (3.0f * TB_PI);
	data.mass = rectMass + discMass;
	data.center = tbLerp(shape->center1, shape->center2, 0.5f);
	float rectInertia = rectMass * (length * length + 4.0f * r * r) / 12.0f;
	float discInertia = discMass * (0.5f * r * r + 0.25f * length * length + length * d);
	data.rotationalInertia = rectInertia + discInertia;
	return data;
}

// Core polygon moments about o by a triangle fan (see the file header).
static tbAreaMoments tbCorePolygonMoments(const tbPolygon* shape, tbVec2 origin)
{
	tbAreaMoments m = {0};
	int n = shape->count;
	for (int i = 0; i < n; ++i)
	{
		tbVec2 e1 = tbSub(shape->vertices[i], origin);
		tbVec2 e2 = tbSub(shape->vertices[(i + 1) % n], origin);
		float D = tbCross(e1, e2);
		float area = 0.5f * D;
		m.area += area;
		m.first = tbMulAdd(m.first, area / 3.0f, tbAdd(e1, e2));
		m.second += (D / 12.0f) * (tbDot(e1, e1) + tbDot(e1, e2) + tbDot(e2, e2));
	}
	return m;
}

// Moments about o of the edge rectangle on edge i, pushed out by r along its normal.
static tbAreaMoments tbEdgeSkinMoments(const tbPolygon* shape, int i, tbVec2 origin)
{
	float r = shape->radius;
	tbVec2 v1 = shape->vertices[i];
	tbVec2 v2 = shape->vertices[(i + 1) % shape->count];
	float length = tbDistance(v1, v2);
	tbVec2 center = tbMulAdd(tbLerp(v1, v2, 0.5f), 0.5f * r, shape->normals[i]);
	tbVec2 c = tbSub(center, origin);

	tbAreaMoments m;
	m.area = length * r;
	m.first = tbMulSV(m.area, c);
	m.second = m.area * (length * length + r * r) / 12.0f + m.area * tbLengthSquared(c);
	return m;
}

// Moments about o of the circular sector at vertex i, between the normals of its two edges.
static tbAreaMoments tbCornerSkinMoments(const tbPolygon* shape, int i, tbVec2 origin)
{
	int n = shape->count;
	float r = shape->radius;
	tbVec2 n1 = shape->normals[(i + n - 1) % n];
	tbVec2 n2 = shape->normals[i];
	float phi = tbAtan2(tbCross(n1, n2), tbDot(n1, n2)); // tbAtan2 and tbComputeCosSin: no libm, same everywhere
	phi = tbMaxFloat(phi, 0.0f);

	tbAreaMoments m = {0};
	if (phi <= 0.0f)
	{
		return m;
	}
	// Centroid offset from the vertex along the bisector: 4r·sin(φ/2)/(3φ).
	tbVec2 bisector = tbNormalize(tbAdd(n1, n2));
	tbVec2 toCentroid = tbMulSV(4.0f * r * tbComputeCosSin(0.5f * phi).sine / (3.0f * phi), bisector);
	tbVec2 v = tbSub(shape->vertices[i], origin);

	// ∫|x − o|² = ∫|(x − v) + v|² = I_v + 2 v·(area·(c − v)) + area·|v|²
	m.area = 0.5f * phi * r * r;
	m.first = tbMulSV(m.area, tbAdd(v, toCentroid));
	float momentAboutVertex = 0.25f * phi * r * r * r * r;
	m.second = momentAboutVertex + 2.0f * m.area * tbDot(v, toCentroid) + m.area * tbLengthSquared(v);
	return m;
}

static void tbAddMoments(tbAreaMoments* sum, tbAreaMoments piece)
{
	sum->area += piece.area;
	sum->first = tbAdd(sum->first, piece.first);
	sum->second += piece.second;
}

tbMassData tbComputePolygonMass(const tbPolygon* shape, float density)
{
	tbMassData empty = {0};
	if (tbCheckDensity("tbComputePolygonMass", density) == false || shape->count < 3)
	{
		return empty;
	}

	tbVec2 origin = tbVec2_zero;
	for (int i = 0; i < shape->count; ++i)
	{
		origin = tbAdd(origin, shape->vertices[i]);
	}
	origin = tbMulSV(1.0f / (float)shape->count, origin);

	tbAreaMoments moments = tbCorePolygonMoments(shape, origin);
	if (shape->radius > 0.0f)
	{
		for (int i = 0; i < shape->count; ++i)
		{
			tbAddMoments(&moments, tbEdgeSkinMoments(shape, i, origin));
			tbAddMoments(&moments, tbCornerSkinMoments(shape, i, origin));
		}
	}
	return tbMassFromMoments(moments, origin, density);
}

tbMassData tbComputeShapeMass(const tbGeometry* shape, float density)
{
	switch (shape->type)
	{
		case tb_circleShape:
			return tbComputeCircleMass(&shape->circle, density);
		case tb_capsuleShape:
			return tbComputeCapsuleMass(&shape->capsule, density);
		case tb_polygonShape:
			return tbComputePolygonMass(&shape->polygon, density);
		case tb_segmentShape:
		case tb_chainSegmentShape:
		default:
		{
			// A segment has no area, so no mass; its centre is its midpoint.
			tbMassData data = {0};
			if (shape->type == tb_segmentShape)
			{
				data.center = tbLerp(shape->segment.point1, shape->segment.point2, 0.5f);
			}
			else if (shape->type == tb_chainSegmentShape)
			{
				data.center = tbLerp(shape->chainSegment.segment.point1, shape->chainSegment.segment.point2, 0.5f);
			}
			return data;
		}
	}
}

// ---------------------------------------------------------------------------------------------
// Bounding boxes

static tbAABB tbMakeInflatedAABB(tbVec2 lower, tbVec2 upper, float radius)
{
	tbAABB box = {{lower.x - radius, lower.y - radius}, {upper.x + radius, upper.y + radius}};
	return box;
}

static tbAABB tbCircleBox(const tbCircle* shape, tbTransform transform)
{
	tbVec2 p = tbTransformPoint(transform, shape->center);
	return tbMakeInflatedAABB(p, p, shape->radius);
}

static tbAABB tbCapsuleBox(const tbCapsule* shape, tbTransform transform)
{
	tbVec2 p1 = tbTransformPoint(transform, shape->center1);
	tbVec2 p2 = tbTransformPoint(transform, shape->center2);
	return tbMakeInflatedAABB(tbMin(p1, p2), tbMax(p1, p2), shape->radius);
}

static tbAABB tbPolygonBox(const tbPolygon* shape, tbTransform transform)
{
	if (shape->count < 1)
	{
		return tbMakeInflatedAABB(transform.p, transform.p, 0.0f);
	}
	tbVec2 lower = tbTransformPoint(transform, shape->vertices[0]);
	tbVec2 upper = lower;
	for (int i = 1; i < shape->count; ++i)
	{
		tbVec2 v = tbTransformPoint(transform, shape->vertices[i]);
		lower = tbMin(lower, v);
		upper = tbMax(upper, v);
	}
	return tbMakeInflatedAABB(lower, upper, shape->radius);
}

static tbAABB tbSegmentBox(const tbSegment* shape, tbTransform transform)
{
	tbVec2 p1 = tbTransformPoint(transform, shape->point1);
	tbVec2 p2 = tbTransformPoint(transform, shape->point2);
	return tbMakeInflatedAABB(tbMin(p1, p2), tbMax(p1, p2), 0.0f);
}

static tbAABB tbShapeBox(const tbGeometry* shape, tbTransform transform)
{
	switch (shape->type)
	{
		case tb_circleShape:
			return tbCircleBox(&shape->circle, transform);
		case tb_capsuleShape:
			return tbCapsuleBox(&shape->capsule, transform);
		case tb_segmentShape:
			return tbSegmentBox(&shape->segment, transform);
		case tb_chainSegmentShape:
			return tbSegmentBox(&shape->chainSegment.segment, transform);
		case tb_polygonShape:
			return tbPolygonBox(&shape->polygon, transform);
		default:
			TB_ASSERT(false);
			return tbMakeInflatedAABB(transform.p, transform.p, 0.0f);
	}
}

#if defined(TUMBLE_DOUBLE_PRECISION)
// Large-world build: the box is found about the shape's own position in float (its extent is
// small) and moved out in double, rounded outwards, so it contains the shape at any distance.
#define TB_WORLD_BOX(box, shape, transform) tbOffsetAABB(box(shape, (tbTransform){tbVec2_zero, (transform).q}), (transform).p)
#else
#define TB_WORLD_BOX(box, shape, transform) box(shape, transform)
#endif

tbAABB tbComputeCircleAABB(const tbCircle* shape, tbWorldTransform transform)
{
	return TB_WORLD_BOX(tbCircleBox, shape, transform);
}

tbAABB tbComputeCapsuleAABB(const tbCapsule* shape, tbWorldTransform transform)
{
	return TB_WORLD_BOX(tbCapsuleBox, shape, transform);
}

tbAABB tbComputePolygonAABB(const tbPolygon* shape, tbWorldTransform transform)
{
	return TB_WORLD_BOX(tbPolygonBox, shape, transform);
}

tbAABB tbComputeSegmentAABB(const tbSegment* shape, tbWorldTransform transform)
{
	return TB_WORLD_BOX(tbSegmentBox, shape, transform);
}

tbAABB tbComputeShapeAABB(const tbGeometry* shape, tbWorldTransform transform)
{
	return TB_WORLD_BOX(tbShapeBox, shape, transform);
}

// ---------------------------------------------------------------------------------------------
// Point tests

bool tbPointInCircle(const tbCircle* shape, tbVec2 point)
{
	return tbDistanceSquared(point, shape->center) <= shape->radius * shape->radius;
}

bool tbPointInCapsule(const tbCapsule* shape, tbVec2 point)
{
	float t;
	tbVec2 closest = tbClosestPointOnSegment(&t, point, shape->center1, shape->center2);
	return tbDistanceSquared(point, closest) <= shape->radius * shape->radius;
}

// True when the point is inside every edge half-plane of the core polygon.
static bool tbPointInCore(tbVec2 point, const tbPolygon* shape)
{
	for (int i = 0; i < shape->count; ++i)
	{
		if (tbDot(shape->normals[i], tbSub(point, shape->vertices[i])) > 0.0f)
		{
			return false;
		}
	}
	return true;
}

bool tbPointInPolygon(const tbPolygon* shape, tbVec2 point)
{
	if (shape->count < 3)
	{
		return false;
	}
	if (tbPointInCore(point, shape))
	{
		return true;
	}
	// Rounded: inside when within radius of the core boundary.
	float rr = shape->radius * shape->radius;
	for (int i = 0; i < shape->count && shape->radius > 0.0f; ++i)
	{
		tbVec2 a = shape->vertices[i];
		tbVec2 b = shape->vertices[(i + 1) % shape->count];
		float t;
		if (tbDistanceSquared(point, tbClosestPointOnSegment(&t, point, a, b)) <= rr)
		{
			return true;
		}
	}
	return false;
}

bool tbPointInShape(const tbGeometry* shape, tbVec2 point)
{
	switch (shape->type)
	{
		case tb_circleShape:
			return tbPointInCircle(&shape->circle, point);
		case tb_capsuleShape:
			return tbPointInCapsule(&shape->capsule, point);
		case tb_polygonShape:
			return tbPointInPolygon(&shape->polygon, point);
		case tb_segmentShape:
		case tb_chainSegmentShape:
		default:
			return false;
	}
}

// ---------------------------------------------------------------------------------------------
// Ray casts

static tbCastOutput tbNoHit(void)
{
	tbCastOutput output = {0};
	return output;
}

// A hit whose numbers are not finite floats is no hit: the products of a ray cast overflow for a
// ray or a shape far beyond TB_MAX_COORDINATE, and ∞ − ∞ = NaN passes every range test.
static tbCastOutput tbMakeHit(tbVec2 point, tbVec2 normal, float fraction)
{
	tbCastOutput output = {0};
	if (tbIsValidVec2(point) == false || tbIsValidVec2(normal) == false || tbIsValidFloat(fraction) == false)
	{
		return output;
	}
	output.point = point;
	output.normal = normal;
	output.fraction = fraction;
	output.hit = true;
	return output;
}

bool tbIsValidRay(const tbRayCastInput* input)
{
	if (tbCheckPointer("tbIsValidRay", "input", input) == false)
	{
		return false;
	}
	// NaN fails every comparison, so the fraction test also refuses a NaN maxFraction.
	return tbIsValidVec2(input->origin) && tbIsValidVec2(input->translation) && 0.0f <= input->maxFraction &&
		   input->maxFraction < TB_HUGE;
}

// Report non-finite ray input; a zero-length ray is valid and simply hits nothing.
static bool tbCheckRayInput(const char* function, const tbRayCastInput* input)
{
	return tbCheckVec2(function, "input->origin", input->origin) &&
		   tbCheckVec2(function, "input->translation", input->translation) &&
		   tbCheckNonNegative(function, "input->maxFraction", input->maxFraction);
}

// A translation whose squared length overflows float (|d| above ~1.8e19 m) made the lengths and
// cross products of the casts below infinite, and circles, capsules and segments were missed.
// Such a ray is cast as the same ray with d·2⁻⁶⁶ and maxFraction·2⁶⁶ (power-of-two scalings are
// exact; the components of d·2⁻⁶⁶ are below 4.7e18, so |d·2⁻⁶⁶|² < FLT_MAX) and the fraction of
// its hit is scaled back.
#define TB_HUGE_RAY_SCALE 0x1p-66f

static bool tbScaleHugeRay(const tbRayCastInput* input, tbRayCastInput* scaled)
{
	if (tbIsValidFloat(tbLengthSquared(input->translation)))
	{
		return false;
	}
	*scaled = *input;
	scaled->translation = tbMulSV(TB_HUGE_RAY_SCALE, input->translation);
	scaled->maxFraction = input->maxFraction / TB_HUGE_RAY_SCALE; // ∞ when beyond float: no clip
	return true;
}

static tbCastOutput tbUnscaleHit(tbCastOutput output)
{
	output.fraction *= TB_HUGE_RAY_SCALE;
	return output;
}

// Circle cast for a ray known to be valid (Ericson §5.3.2). With u the unit direction and
// s = origin − centre, the closest approach is at distance tc = −s·u along the ray, where the
// ray passes at squared distance |s + tc·u|² from the centre; the entry is tc − √(r² − that).
static tbCastOutput tbRayCastCircleUnchecked(const tbRayCastInput* input, tbVec2 center, float radius)
{
	float length;
	tbVec2 u = tbGetLengthAndNormalize(&length, input->translation);
	tbVec2 s = tbSub(input->origin, center);
	if (length < FLT_EPSILON || tbDot(s, s) < radius * radius)
	{
		return tbNoHit();
	}
	float tc = -tbDot(s, u);
	tbVec2 closest = tbMulAdd(s, tc, u);
	float h2 = radius * radius - tbDot(closest, closest);
	if (h2 < 0.0f)
	{
		return tbNoHit();
	}
	float t = tc - sqrtf(h2);
	if (t < 0.0f || t > input->maxFraction * length)
	{
		return tbNoHit();
	}
	tbVec2 point = tbMulAdd(input->origin, t, u);
	return tbMakeHit(point, tbNormalize(tbSub(point, center)), t / length);
}

tbCastOutput tbRayCastCircle(const tbCircle* shape, const tbRayCastInput* input)
{
	if (tbCheckRayInput("tbRayCastCircle", input) == false)
	{
		return tbNoHit();
	}
	tbRayCastInput scaled;
	if (tbScaleHugeRay(input, &scaled))
	{
		return tbUnscaleHit(tbRayCastCircle(shape, &scaled));
	}
	return tbRayCastCircleUnchecked(input, shape->center, shape->radius);
}

// Segment cast for a valid ray. Solving origin + t·d = p1 + s·e with crosses against e and d:
// t = ((p1 − origin) × e)/(d × e), s = ((p1 − origin) × d)/(d × e). Parallel rays miss.
// The normal is the segment's right perpendicular, flipped to face the ray.
static tbCastOutput tbRayCastSegmentUnchecked(const tbRayCastInput* input, tbVec2 p1, tbVec2 p2)
{
	tbVec2 d = input->translation;
	tbVec2 e = tbSub(p2, p1);
	float denominator = tbCross(d, e);
	float scale = tbLength(d) * tbLength(e);
	if (tbAbsFloat(denominator) <= FLT_EPSILON * scale || scale == 0.0f)
	{
		return tbNoHit();
	}
	tbVec2 w = tbSub(p1, input->origin);
	float t = tbCross(w, e) / denominator;
	float s = tbCross(w, d) / denominator;
	if (t < 0.0f || t > input->maxFraction || s < 0.0f || s > 1.0f)
	{
		return tbNoHit();
	}
	tbVec2 normal = tbNormalize(tbRightPerp(e));
	if (tbDot(normal, d) > 0.0f)
	{
		normal = tbNeg(normal);
	}
	return tbMakeHit(tbMulAdd(input->origin, t, d), normal, t);
}

/// One-sided segments are solid only from the right of point1 → point2 (the side of the
/// normal rightPerp(point2 − point1)); a ray starting on the left passes through.
tbCastOutput tbRayCastSegment(const tbSegment* shape, const tbRayCastInput* input, bool oneSided)
{
	if (tbCheckRayInput("tbRayCastSegment", input) == false)
	{
		return tbNoHit();
	}
	tbRayCastInput scaled;
	if (tbScaleHugeRay(input, &scaled))
	{
		return tbUnscaleHit(tbRayCastSegment(shape, &scaled, oneSided));
	}
	if (oneSided)
	{
		tbVec2 e = tbSub(shape->point2, shape->point1);
		if (tbCross(e, tbSub(input->origin, shape->point1)) > 0.0f)
		{
			return tbNoHit();
		}
	}
	return tbRayCastSegmentUnchecked(input, shape->point1, shape->point2);
}

// Keep the nearer of two hits.
static tbCastOutput tbNearerHit(tbCastOutput best, tbCastOutput candidate)
{
	if (candidate.hit && (best.hit == false || candidate.fraction < best.fraction))
	{
		return candidate;
	}
	return best;
}

// Nearest hit on the edge v1 → v2 pushed out by radius along its outward normal.
static tbCastOutput tbRayCastOffsetEdge(const tbRayCastInput* input, tbVec2 v1, tbVec2 v2, tbVec2 normal, float radius)
{
	tbVec2 offset = tbMulSV(radius, normal);
	return tbRayCastSegmentUnchecked(input, tbAdd(v1, offset), tbAdd(v2, offset));
}

tbCastOutput tbRayCastCapsule(const tbCapsule* shape, const tbRayCastInput* input)
{
	if (tbCheckRayInput("tbRayCastCapsule", input) == false || tbPointInCapsule(shape, input->origin))
	{
		return tbNoHit();
	}
	tbRayCastInput scaled;
	if (tbScaleHugeRay(input, &scaled))
	{
		return tbUnscaleHit(tbRayCastCapsule(shape, &scaled));
	}
	// Boundary: the two end circles and the two sides of the core segment offset by ±r.
	tbVec2 c1 = shape->center1, c2 = shape->center2;
	float r = shape->radius;
	tbCastOutput best = tbRayCastCircleUnchecked(input, c1, r);
	best = tbNearerHit(best, tbRayCastCircleUnchecked(input, c2, r));
	tbVec2 side = tbNormalize(tbRightPerp(tbSub(c2, c1)));
	if (tbLengthSquared(side) > 0.0f)
	{
		best = tbNearerHit(best, tbRayCastOffsetEdge(input, c1, c2, side, r));
		best = tbNearerHit(best, tbRayCastOffsetEdge(input, c1, c2, tbNeg(side), r));
	}
	return best;
}

// Cyrus–Beck clipping of the ray against the half-planes n_i·(x − v_i) ≤ 0 (Ericson §5.3.8).
// Along the ray, n·(origin + t·d − v) ≤ 0 ⇔ t·(n·d) ≤ n·(v − origin): entering edges
// (n·d < 0) raise the lower bound, leaving edges lower the upper bound.
static tbCastOutput tbRayCastCorePolygon(const tbRayCastInput* input, const tbPolygon* shape)
{
	float lower = 0.0f, upper = input->maxFraction;
	int index = -1;
	for (int i = 0; i < shape->count; ++i)
	{
		float numerator = tbDot(shape->normals[i], tbSub(shape->vertices[i], input->origin));
		float denominator = tbDot(shape->normals[i], input->translation);
		if (denominator == 0.0f)
		{
			if (numerator < 0.0f)
			{
				return tbNoHit();
			}
		}
		else if (denominator < 0.0f && numerator < lower * denominator)
		{
			lower = numerator / denominator;
			index = i;
		}
		else if (denominator > 0.0f && numerator < upper * denominator)
		{
			upper = numerator / denominator;
		}
		if (upper < lower)
		{
			return tbNoHit();
		}
	}
	// index < 0: no edge was entered, so the origin is inside (or the ray is empty).
	if (index < 0)
	{
		return tbNoHit();
	}
	return tbMakeHit(tbMulAdd(input->origin, lower, input->translation), shape->normals[index], lower);
}

tbCastOutput tbRayCastPolygon(const tbPolygon* shape, const tbRayCastInput* input)
{
	if (tbCheckRayInput("tbRayCastPolygon", input) == false || shape->count < 3)
	{
		return tbNoHit();
	}
	tbRayCastInput scaled;
	if (tbScaleHugeRay(input, &scaled))
	{
		return tbUnscaleHit(tbRayCastPolygon(shape, &scaled));
	}
	if (shape->radius == 0.0f)
	{
		return tbRayCastCorePolygon(input, shape);
	}
	if (tbPointInPolygon(shape, input->origin))
	{
		return tbNoHit();
	}
	// Rounded: boundary is the corner circles and the edges pushed out by the radius.
	tbCastOutput best = tbNoHit();
	int n = shape->count;
	for (int i = 0; i < n; ++i)
	{
		tbVec2 v1 = shape->vertices[i];
		tbVec2 v2 = shape->vertices[(i + 1) % n];
		best = tbNearerHit(best, tbRayCastCircleUnchecked(input, v1, shape->radius));
		best = tbNearerHit(best, tbRayCastOffsetEdge(input, v1, v2, shape->normals[i], shape->radius));
	}
	return best;
}

tbCastOutput tbRayCastShape(const tbGeometry* shape, const tbRayCastInput* input)
{
	switch (shape->type)
	{
		case tb_circleShape:
			return tbRayCastCircle(&shape->circle, input);
		case tb_capsuleShape:
			return tbRayCastCapsule(&shape->capsule, input);
		case tb_segmentShape:
			return tbRayCastSegment(&shape->segment, input, false);
		case tb_chainSegmentShape:
			return tbRayCastSegment(&shape->chainSegment.segment, input, true); // one-sided, as it collides
		case tb_polygonShape:
			return tbRayCastPolygon(&shape->polygon, input);
		default:
			TB_ASSERT(false);
			return tbNoHit();
	}
}
