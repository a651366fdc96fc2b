// Segment against an axis-aligned box by slabs (Kay & Kajiya, "Ray tracing complex scenes",
// SIGGRAPH 1986; Ericson, Real-Time Collision Detection, 2005, §5.3.3). On each axis the box is
// the slab lower ≤ x ≤ upper and the segment p(t) = p1 + t·(p2 − p1) lies in it for t between
// (lower − p1)/d and (upper − p1)/d. The segment is in the box while it is in both slabs: from
// the later of the two entries to the earlier of the two exits. The slab entered last names the
// face hit, whose outward normal points against the segment's direction on that axis.
#include "aabb.h"

#include <float.h>

/// The parameter interval [*enter, *exit] narrowed to one axis's slab; the entry's normal sign
/// on that axis in *sign when this axis's entry is the latest so far (*sign left 0 otherwise).
/// False when the interval is empty.
static bool tbClipToSlab(float p, float d, float lower, float upper, float* enter, float* exit, float* sign)
{
	*sign = 0.0f;
	if (tbAbsFloat(d) < FLT_EPSILON)
	{
		return lower <= p && p <= upper; // parallel to the slab: inside it for every t, or never
	}
	float inverse = 1.0f / d;
	float tLower = (lower - p) * inverse;
	float tUpper = (upper - p) * inverse;
	float tIn = d > 0.0f ? tLower : tUpper;
	float tOut = d > 0.0f ? tUpper : tLower;
	if (tIn > *enter)
	{
		*enter = tIn;
		*sign = d > 0.0f ? -1.0f : 1.0f; // entering through the lower face, normal −axis
	}
	*exit = tbMinFloat(*exit, tOut);
	return *enter <= *exit;
}

tbCastOutput tbAABB_RayCast(tbAABB a, tbVec2 p1, tbVec2 p2)
{
	tbCastOutput output = {0};
	tbVec2 d = tbSub(p2, p1);
	float enter = -FLT_MAX;
	float exit = FLT_MAX;
	float signX, signY;
	tbVec2 normal = tbVec2_zero;
	if (tbClipToSlab(p1.x, d.x, a.lowerBound.x, a.upperBound.x, &enter, &exit, &signX) == false)
	{
		return output;
	}
	if (signX != 0.0f)
	{
		normal = tbMakeVec2(signX, 0.0f);
	}
	if (tbClipToSlab(p1.y, d.y, a.lowerBound.y, a.upperBound.y, &enter, &exit, &signY) == false)
	{
		return output;
	}
	if (signY != 0.0f)
	{
		normal = tbMakeVec2(0.0f, signY);
	}
	if (enter < 0.0f || 1.0f < enter)
	{
		return output; // starts inside the box, or reaches it only beyond p2
	}
	output.fraction = enter;
	output.normal = normal;
	output.point = tbLerp(p1, p2, enter);
	output.hit = true;
	return output;
}
