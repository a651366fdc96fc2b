// Time of impact by conservative advancement, for any convex pair with linear and angular motion.
//
// Motion. A tbSweep moves the centre of mass linearly, c(t) = (1 − t)·c1 + t·c2, and the angle
// linearly, θ(t) = θ1 + t·Δθ with Δθ = relativeAngle(q1, q2) ∈ [−π, π]. Over the sweep (t is
// the unit of time) every body has constant linear velocity v = c2 − c1 and constant angular
// velocity ω = Δθ.
//
// Bound (Mirtich 1996, "Impulse-based dynamic simulation of rigid body systems", PhD thesis,
// §2.3; Coumans 2005, "Continuous collision detection and physics"). Let d(t) be the surface
// separation and n the unit separating normal from A to B found by GJK at time t. Any point of
// B at offset r from B's centre of mass moves along n at rate vB·n + (ωB × r)·n ≥ vB·n − |ωB|·|r|;
// any point of A moves along n at rate ≤ vA·n + |ωA|·|r|. The gap between the two supporting
// lines with fixed normal n, a lower bound of d, therefore shrinks no faster than
//   μ = (vA − vB)·n + |ωA|·ρA + |ωB|·ρB,
// where ρ is the largest distance of a proxy's core points from its centre of mass. The radius
// of a rounded proxy is not added to ρ: the support point of a rounded shape is a core point
// plus radius·n, and the offset radius·n does not turn relative to the fixed n, so only the core
// point's motion counts. Since μ is constant on the rest of the sweep, the shapes cannot come
// closer than the target before t + (d − target)/μ. Advancing by that step is safe; repeating
// it converges to the time of impact from below (for circles without rotation it is Newton's
// method on the convex function d(t), quadratically convergent).
//
// Second-order step. The first-order bound counts every point of a spinning body as approaching
// at |ω|·ρ, even a tip that the spin is carrying away; a thin box spinning while it slides in can
// then need more than TB_TOI_MAX_ITERATIONS steps (measured: 3 launches in 100 of the spinning-box
// test). Each core point x of a body moves as x(s) = c(s) + R(θ(s))·r with c linear and θ linear
// in s, so x'' = −ω²·R r and, along the fixed n, Taylor's theorem with remainder gives
//   n·x(t + Δ) ≥ n·x(t) + n·x'(t)·Δ − ½ω²|r|·Δ²     (and ≤ with + for the upper bound).
// The separation along n is min over B's points minus max over A's points, so it stays above the
// target until the first positive root of, for some pair (a, b),
//   h(Δ) = (n·b − n·a − rA − rB − target) + (n·b' − n·a')·Δ − ½(ωA²|ra| + ωB²|rb|)·Δ².
// Both steps are proven safe, so the advancement takes the larger. This is the idea of Taylor
// models in continuous collision detection (Zhang, Redon, Lee and Kim 2007, "Continuous
// collision detection for articulated models using Taylor models and temporal culling") cut
// down to one rigid pair in the plane; it costs O(nA·nB) per iteration on top of GJK.
//
// Stop rules: hit when d − target < tolerance; separated when μ ≤ 0 (nothing approaches) or
// the step would pass maxFraction; failed after TB_TOI_MAX_ITERATIONS distance queries,
// returning the last time at which the distance was measured (a safe time).
//
// Rejected alternative: root finding on separating-axis functions (as in Box2D's TOI) converges
// in fewer iterations for spinning polygons but needs a bisection fallback and per-feature cases;
// conservative advancement is a few lines on top of GJK and is safe by construction, which is
// what this file is for (toi_quadratic.c holds the closed form for circles).

#include "core.h"

#include "tumble/collision.h"

// Convergence tolerance on the separation, 1e-5 m (0.008 × TB_TOI_TARGET_SEPARATION). The hit is
// reported with the separation in [target, target + tolerance). With the second-order step the
// cost of a tight tolerance is small (spinning thin box: at most 6 iterations at 1e-5 m, 5 at
// 1e-4 m), while 1e-4 m leaves conservative advancement up to 4.8e-4 of the step away from the
// closed-form circle time at oblique impacts (tests/test_toi.c; 5.4e-5 at 1e-5 m). It stays
// above the float noise of GJK distances at 10 m coordinates (~1e-6 m).
#ifndef TB_TOI_TOLERANCE
#define TB_TOI_TOLERANCE 1.0e-5f
#endif

// Body transform at time t: centre lerped, angle q1 advanced by t·Δθ, origin = centre − R·localCenter.
tbTransform tbGetSweepTransform(const tbSweep* sweep, float time)
{
	tbVec2 center = tbAdd(tbMulSV(1.0f - time, sweep->c1), tbMulSV(time, sweep->c2));
	float angle = time * tbRelativeAngle(sweep->q1, sweep->q2);
	tbTransform transform;
	transform.q = tbMulRot(tbMakeRot(angle), sweep->q1);
	transform.p = tbSub(center, tbRotateVector(transform.q, sweep->localCenter));
	return transform;
}

// ρ: largest distance of the proxy's core points from the body's centre of mass (see the bound above).
static float tbMaxRadiusAboutCenter(const tbShapeProxy* proxy, tbVec2 localCenter)
{
	float maxDistanceSquared = 0.0f;
	for (int i = 0; i < proxy->count; ++i)
	{
		maxDistanceSquared = tbMaxFloat(maxDistanceSquared, tbDistanceSquared(proxy->points[i], localCenter));
	}
	return sqrtf(maxDistanceSquared);
}

static bool tbValidTOIInput(const char* function, const tbTOIInput* input)
{
	if (tbCheckPointer(function, "input", input) == false ||
		tbCheckNonNegative(function, "input->targetSeparation", input->targetSeparation) == false ||
		tbCheckNonNegative(function, "input->maxFraction", input->maxFraction) == false)
	{
		return false;
	}
	if (input->maxFraction > 1.0f)
	{
		tbReportError(function, "input->maxFraction is %g; it must lie in [0, 1], a fraction of the sweep.",
					  (double)input->maxFraction);
		return false;
	}
	return true;
}

// Per-query constants of the advancement: velocities over the sweep and the angular reach.
typedef struct tbAdvanceBound
{
	tbVec2 relativeVelocity; // vB − vA (m per sweep)
	float angularReach;		 // |ωA|·ρA + |ωB|·ρB (m per sweep)
} tbAdvanceBound;

static tbAdvanceBound tbMakeAdvanceBound(const tbTOIInput* input)
{
	const tbSweep* sA = &input->sweepA;
	const tbSweep* sB = &input->sweepB;
	float omegaA = tbAbsFloat(tbRelativeAngle(sA->q1, sA->q2));
	float omegaB = tbAbsFloat(tbRelativeAngle(sB->q1, sB->q2));
	tbAdvanceBound bound;
	bound.relativeVelocity = tbSub(tbSub(sB->c2, sB->c1), tbSub(sA->c2, sA->c1));
	bound.angularReach = omegaA * tbMaxRadiusAboutCenter(&input->proxyA, sA->localCenter) +
						 omegaB * tbMaxRadiusAboutCenter(&input->proxyB, sB->localCenter);
	return bound;
}

// Projection on n of one core point at time t: position, velocity and curvature bound ω²|r|.
typedef struct tbPointMotion
{
	float position;
	float velocity;
	float curvature;
} tbPointMotion;

static tbPointMotion tbProjectPointMotion(const tbSweep* sweep, tbTransform transform, tbVec2 localPoint,
										  float omega, tbVec2 normal)
{
	tbVec2 point = tbTransformPoint(transform, localPoint);
	tbVec2 arm = tbRotateVector(transform.q, tbSub(localPoint, sweep->localCenter));
	tbVec2 velocity = tbAdd(tbSub(sweep->c2, sweep->c1), tbCrossSV(omega, arm));
	tbPointMotion motion = {tbDot(normal, point), tbDot(normal, velocity), omega * omega * tbLength(arm)};
	return motion;
}

// First positive root of h0 + h1·Δ − ½K·Δ² for h0 > 0, K ≥ 0; FLT_MAX when there is none.
// Stable form Δ = 2h0/(−h1 + √(h1² + 2K·h0)): the denominator only vanishes when K = 0 and
// h1 ≥ 0 (never closing), which is exactly the no-root case.
static float tbFirstRootConcave(float h0, float h1, float K)
{
	float denominator = -h1 + sqrtf(h1 * h1 + 2.0f * K * h0);
	return denominator > 0.0f ? 2.0f * h0 / denominator : FLT_MAX;
}

// Second-order safe step (see the top of the file): the smallest first root over point pairs.
static float tbSecondOrderStep(const tbTOIInput* input, tbTransform xfA, tbTransform xfB, tbVec2 normal, float gap)
{
	const tbShapeProxy* proxyA = &input->proxyA;
	const tbShapeProxy* proxyB = &input->proxyB;
	float omegaA = tbRelativeAngle(input->sweepA.q1, input->sweepA.q2);
	float omegaB = tbRelativeAngle(input->sweepB.q1, input->sweepB.q2);
	tbPointMotion motionA[TB_MAX_POLYGON_VERTICES];
	for (int i = 0; i < proxyA->count; ++i)
	{
		motionA[i] = tbProjectPointMotion(&input->sweepA, xfA, proxyA->points[i], omegaA, normal);
	}
	// The core separation along n is min over pairs, and gap is measured from the closest pair, so
	// each pair starts at gap + (its own projected separation − the closest one).
	float closest = FLT_MAX;
	float step = FLT_MAX;
	tbPointMotion motionB[TB_MAX_POLYGON_VERTICES];
	for (int j = 0; j < proxyB->count; ++j)
	{
		motionB[j] = tbProjectPointMotion(&input->sweepB, xfB, proxyB->points[j], omegaB, normal);
		for (int i = 0; i < proxyA->count; ++i)
		{
			closest = tbMinFloat(closest, motionB[j].position - motionA[i].position);
		}
	}
	for (int j = 0; j < proxyB->count; ++j)
	{
		for (int i = 0; i < proxyA->count; ++i)
		{
			float h0 = gap + (motionB[j].position - motionA[i].position - closest);
			float h1 = motionB[j].velocity - motionA[i].velocity;
			float K = motionA[i].curvature + motionB[j].curvature;
			step = tbMinFloat(step, tbFirstRootConcave(h0, h1, K));
		}
	}
	return step;
}

// Normal and contact point from a GJK result on the cores: the surfaces are the core closest
// points pushed out by the radii; the point is midway between the surfaces, like a manifold point.
static void tbSetContact(tbTOIOutput* output, const tbDistanceOutput* distance, float radiusA, float radiusB)
{
	tbVec2 surfaceA = tbMulAdd(distance->pointA, radiusA, distance->normal);
	tbVec2 surfaceB = tbMulSub(distance->pointB, radiusB, distance->normal);
	output->normal = distance->normal;
	output->point = tbLerp(surfaceA, surfaceB, 0.5f);
}

tbTOIOutput tbTimeOfImpact(const tbTOIInput* input)
{
	tbTOIOutput output = {tb_toiStateUnknown, 0.0f, 0, {0.0f, 0.0f}, {0.0f, 0.0f}};
	if (tbValidTOIInput("tbTimeOfImpact", input) == false)
	{
		return output;
	}

	tbAdvanceBound bound = tbMakeAdvanceBound(input);
	float radiusA = input->proxyA.radius;
	float radiusB = input->proxyB.radius;
	float target = input->targetSeparation;
	float tMax = input->maxFraction;

	tbDistanceInput distanceInput;
	distanceInput.proxyA = input->proxyA;
	distanceInput.proxyB = input->proxyB;
	distanceInput.useRadii = false;
	tbSimplexCache cache = {0};

	float t = 0.0f;
	for (int iteration = 1;; ++iteration)
	{
		distanceInput.transformA = tbGetSweepTransform(&input->sweepA, t);
		distanceInput.transformB = tbGetSweepTransform(&input->sweepB, t);
		tbDistanceOutput distance = tbShapeDistance(&distanceInput, &cache, NULL);
		float separation = distance.distance - radiusA - radiusB;
		output.iterations = iteration;

		// Cores touching leave no normal. At t = 0 that is an overlap; later it can only come from
		// rounding (each step stops at the target), so report the last measured time as failed.
		bool coresOverlap = distance.distance <= 0.0f || tbLengthSquared(distance.normal) == 0.0f;
		if (coresOverlap && iteration > 1)
		{
			output.state = tb_toiStateFailed;
			return output;
		}
		output.fraction = t;
		if (coresOverlap == false)
		{
			tbSetContact(&output, &distance, radiusA, radiusB);
		}
		if (iteration == 1 && (separation < target || coresOverlap))
		{
			output.state = tb_toiStateOverlapped;
			return output;
		}
		// μ = (vA − vB)·n + angular reach; the shapes stay apart until t + (d − target)/μ.
		// Nothing approaching (μ ≤ 0) means separated, even when touching within the tolerance.
		float closingSpeed = -tbDot(bound.relativeVelocity, distance.normal) + bound.angularReach;
		float gap = separation - target;
		if (closingSpeed <= 0.0f)
		{
			output.state = tb_toiStateSeparated;
			output.fraction = tMax;
			return output;
		}
		if (gap < TB_TOI_TOLERANCE)
		{
			output.state = tb_toiStateHit;
			return output;
		}
		float step = tbMaxFloat(gap / closingSpeed, tbSecondOrderStep(input, distanceInput.transformA,
																	  distanceInput.transformB, distance.normal, gap));
		if (step >= tMax - t)
		{
			output.state = tb_toiStateSeparated;
			output.fraction = tMax;
			return output;
		}
		if (iteration == TB_TOI_MAX_ITERATIONS)
		{
			output.state = tb_toiStateFailed;
			return output;
		}
		t += step;
	}
}
