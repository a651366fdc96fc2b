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
// Separating-axis lower bounds. For any unit vector u, projecting both cores on u gives
//   d_core ≥ min over b ∈ B of u·b − max over a ∈ A of u·a = min over core-point pairs of u·(b − a)
// (a linear function on a convex hull is extreme at a vertex; when the cores overlap both sides
// are ≤ 0), with equality for the GJK normal u = n at the time t of the query. So d stays above
// the target as long as, for every pair, h(Δ) = u(Δ)·(b − a)(t + Δ) − rA − rB does, and this
// holds for ANY choice of axis u(Δ) over the rest of the sweep: each choice below gives a safe
// step, the advancement takes the largest, and the choice only decides how far a step gets.
// The steps bound each pair's own motion projected on the axis instead of every point's speed
// (the directional motion bounds of Zhang, Lee and Kim 2006, "Interactive continuous collision
// detection for non-convex polyhedra", and of C2A, Tang, Kim and Manocha 2009, "C2A: controlled
// conservative advancement for continuous collision detection of polygonal models").
//
// Second-order step, fixed axis (u = n). The first-order bound counts every point of a spinning
// body as approaching at |ω|·ρ, even a tip that the spin is carrying away; a thin box spinning
// while it slides in can then need more than TB_TOI_MAX_ITERATIONS steps (tests/test_toi.c,
// conservative_spinning_thin_box_never_tunnels, had such launches). Each core point x of a body moves as x(s) = c(s) + R(θ(s))·r
// with c and θ linear in s, so x'' = −ω²·R r and Taylor's theorem with remainder gives
//   n·x(t + Δ) ≥ n·x(t) + n·x'(t)·Δ − ½ω²|r|·Δ²     (and ≤ with + for the upper bound).
// Hence each pair (a, b) stays above the target until the first positive root of
//   h(Δ) = (n·b − n·a − rA − rB − target) + (n·b' − n·a')·Δ − ½(ωA²|ra| + ωB²|rb|)·Δ².
// This is the idea of Taylor models in continuous collision detection (Zhang, Redon, Lee and Kim
// 2007, "Continuous collision detection for articulated models using Taylor models and temporal
// culling") cut down to one rigid pair in the plane; it costs O(nA·nB) per iteration on top of GJK.
//
// Second-order step, turning axis. Along a fixed n, a face that turns brings one of its ends
// towards the other shape at up to |ω|·(half its length) even while the witness point on it
// barely moves, so the fixed-axis bound itself, not only its Taylor model, reaches the target
// well before d does, and the advancement converges linearly: each step covers only a fraction
// of the remaining time to impact, and the iteration cap is reached short of the target (a circle
// meeting a long box that turns while it moves: tests/test_toi.c,
// conservative_circle_meets_turning_long_box, from Box2D's verification seed 3001, case 3557). A
// tighter model along the fixed axis (support-feature reach, Taylor model re-evaluated on the
// witness pair) cannot step past the bound's own crossing either, and the fixed Taylor step
// already nearly reaches that crossing. When GJK's
// witness is a vertex against a face, the true normal is the face normal, fixed in the face's
// body (Box2D's separation function for a face, Catto 2013, "Continuous collision", GDC; here it
// is bounded, not solved for a root). So the axis is also made to turn with that body,
// u(Δ) = R(λΔ)·n with λ = that body's turn ω over the sweep.
// With ra, rb the pair's arms from the centres of mass, D = cB − cA (affine in time, D' = V =
// vB − vA) and R(α) the rotation by α,
//   u·(b − a) = n·R(−λΔ)·D + n·R(θB(t) + (ωB − λ)Δ)·rb − n·R(θA(t) + (ωA − λ)Δ)·ra,
// so, at Δ = 0 and over the rest of the sweep,
//   h'(0) = n·(b' − a') + λ·perp(n)·(b − a),
//   |h''| ≤ λ²·|D| + 2|λ|·|V| + (ωA − λ)²·|ra| + (ωB − λ)²·|rb|,
// the first two terms being the centripetal and Coriolis terms of the turning frame; |D|, the norm
// of an affine function of time, is convex, so its largest value on [t, maxFraction] is at an end.
// λ = 0 gives back the fixed-axis model. The face's body does not move in the turning frame, so
// near a vertex–face hit the model is exact to first order and the steps converge quadratically
// (cases 3557 and 6129, a long box turning past a triangle, converge well within the cap instead
// of failing at it: tests/test_toi.c logs the iterations). With a vertex–vertex witness the fixed axis is
// already exact to first order (the other vertices lie farther along n) and no turning axis is
// tried; with two parallel edges neither face is singled out and neither is tried.
//
// Stop rules: hit when d − target < tolerance; separated when μ ≤ 0 (nothing approaches) or
// the step would pass maxFraction; failed after TB_TOI_MAX_ITERATIONS distance queries,
// returning the last time at which the distance was measured (a safe time). The bounds are
// exact; the arithmetic trusts GJK's distance and normal at float precision (each pair starts
// at GJK's gap plus its projected offset from the closest pair, so a normal off by rounding
// moves a step by about that rounding and cannot stall the advancement).
//
// Rejected alternatives. Root finding on separating-axis functions (as in Box2D's TOI) converges
// in fewer iterations for spinning polygons but needs a bisection fallback and per-feature cases,
// and a root of d(t) − target in a bracket [t_safe, t_over] is not the first root unless something
// like the bounds above proves that none comes earlier; polishing a bracket by secant or
// bisection was therefore not added: with the turning axis the safe steps already converge
// quadratically at the hits that failed. Trying the turning axes of both bodies on every
// iteration saves nothing over the witness's one (the mean iteration count over random pairs does
// not move) for one more O(nA·nB) pass each time. toi_quadratic.c holds the closed form for
// circles.

#include "core/core.h"
#include "distance_internal.h"

#include "tumble/collision.h"

// Convergence tolerance on the separation, 1e-5 m (0.008 × TB_TOI_TARGET_SEPARATION). The hit is
// reported with the separation in [target, target + tolerance). The second-order step converges
// fast near the hit, so a tight tolerance costs about one iteration more than a loose one, while
// a loose one (1e-4 m) leaves conservative advancement visibly off the closed-form circle time at
// oblique impacts (tests/test_toi.c compares the two). It stays above the float noise of GJK
// distances at 10 m coordinates (a float's spacing there is about 1e-6 m).
#ifndef TB_TOI_TOLERANCE
#define TB_TOI_TOLERANCE 1.0e-5f
#endif

// Body transform at time t: centre lerped, angle q1 advanced by t·Δθ, origin = centre − R·localCenter.
// deltaAngle is relativeAngle(q1, q2), passed in so that the advancement computes its atan2 once.
static tbTransform tbSweepTransformAt(const tbSweep* sweep, float deltaAngle, float time)
{
	tbVec2 center = tbAdd(tbMulSV(1.0f - time, sweep->c1), tbMulSV(time, sweep->c2));
	float angle = time * deltaAngle;
	tbTransform transform;
	transform.q = tbMulRot(tbMakeRot(angle), sweep->q1);
	transform.p = tbSub(center, tbRotateVector(transform.q, sweep->localCenter));
	return transform;
}

tbTransform tbGetSweepTransform(const tbSweep* sweep, float time)
{
	return tbSweepTransformAt(sweep, tbRelativeAngle(sweep->q1, sweep->q2), time);
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

static bool tbValidTOIInput(const char* function, const tbTOIInput* input, float targetSeparation)
{
	if (tbCheckPointer(function, "input", input) == false ||
		tbCheckNonNegative(function, "targetSeparation", targetSeparation) == false ||
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
	return tbCheckProxyPair(function, &input->proxyA, &input->proxyB);
}

// Per-query constants of the advancement: the motion over the sweep and the angular reach.
typedef struct tbAdvanceBound
{
	tbVec2 relativeVelocity; // V = vB − vA (m per sweep)
	float relativeSpeed;	 // |V|
	float omegaA, omegaB;	 // signed turns over the sweep, ωA and ωB (rad per sweep)
	float angularReach;		 // |ωA|·ρA + |ωB|·ρB (m per sweep)
} tbAdvanceBound;

static tbAdvanceBound tbMakeAdvanceBound(const tbTOIInput* input)
{
	const tbSweep* sA = &input->sweepA;
	const tbSweep* sB = &input->sweepB;
	tbAdvanceBound bound;
	bound.relativeVelocity = tbSub(tbSub(sB->c2, sB->c1), tbSub(sA->c2, sA->c1));
	bound.relativeSpeed = tbLength(bound.relativeVelocity);
	bound.omegaA = tbRelativeAngle(sA->q1, sA->q2);
	bound.omegaB = tbRelativeAngle(sB->q1, sB->q2);
	bound.angularReach = tbAbsFloat(bound.omegaA) * tbMaxRadiusAboutCenter(&input->proxyA, sA->localCenter) +
						 tbAbsFloat(bound.omegaB) * tbMaxRadiusAboutCenter(&input->proxyB, sB->localCenter);
	return bound;
}

// One core point at time t, projected for the Taylor steps: n·x and n·x' (fixed axis), m·x with
// m = λ·perp(n) the rate of change of the turning axis, and the spin curvature bounds ω²|r|
// (fixed axis) and (ω − λ)²|r| (turning axis).
typedef struct tbPointMotion
{
	float position;
	float velocity;
	float turning;
	float curvature;
	float turningCurvature;
} tbPointMotion;

static tbPointMotion tbProjectPointMotion(const tbSweep* sweep, tbTransform transform, tbVec2 localPoint, float omega,
										  tbVec2 normal, float lambda)
{
	tbVec2 point = tbTransformPoint(transform, localPoint);
	tbVec2 arm = tbRotateVector(transform.q, tbSub(localPoint, sweep->localCenter));
	tbVec2 velocity = tbAdd(tbSub(sweep->c2, sweep->c1), tbCrossSV(omega, arm));
	float armLength = tbLength(arm);
	tbPointMotion motion;
	motion.position = tbDot(normal, point);
	motion.velocity = tbDot(normal, velocity);
	motion.curvature = omega * omega * armLength;
	motion.turning = 0.0f;
	motion.turningCurvature = 0.0f;
	if (lambda != 0.0f)
	{
		motion.turning = tbDot(tbCrossSV(lambda, normal), point);
		motion.turningCurvature = (omega - lambda) * (omega - lambda) * armLength;
	}
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

// Turning rate λ of the witness feature's normal (see the top of the file). A GJK simplex of two
// vertices sharing their point of A is a vertex of A against an edge of B: the normal is B's face
// normal and turns with B. Sharing the point of B, it turns with A. Anything else (vertex–vertex,
// or two parallel edges, which GJK reports as two distinct pairs) gets only the fixed axis.
static float tbWitnessTurnRate(const tbSimplexCache* cache, const tbAdvanceBound* bound)
{
	if (cache->count == 2 && cache->indexA[0] == cache->indexA[1])
	{
		return bound->omegaB;
	}
	if (cache->count == 2 && cache->indexB[0] == cache->indexB[1])
	{
		return bound->omegaA;
	}
	return 0.0f;
}

// Second-order safe step (see the top of the file): over point pairs, the smallest first root of
// the Taylor lower bound along the fixed axis n and, when the witness is a face (λ ≠ 0), along
// the axis turning with that face; the larger of the two.
static float tbSecondOrderStep(const tbTOIInput* input, const tbAdvanceBound* bound, tbTransform xfA, tbTransform xfB,
							   tbVec2 normal, float gap, float t, float lambda)
{
	const tbShapeProxy* proxyA = &input->proxyA;
	const tbShapeProxy* proxyB = &input->proxyB;
	const tbSweep* sA = &input->sweepA;
	const tbSweep* sB = &input->sweepB;
	tbPointMotion motionA[TB_MAX_POLYGON_VERTICES];
	tbPointMotion motionB[TB_MAX_POLYGON_VERTICES];
	// The core separation along n is the minimum over pairs, min n·b − max n·a, and gap is measured
	// from the closest pair, so each pair starts at gap + (its own projected separation − closest).
	float farthestA = -FLT_MAX;
	float nearestB = FLT_MAX;
	for (int i = 0; i < proxyA->count; ++i)
	{
		motionA[i] = tbProjectPointMotion(sA, xfA, proxyA->points[i], bound->omegaA, normal, lambda);
		farthestA = tbMaxFloat(farthestA, motionA[i].position);
	}
	for (int j = 0; j < proxyB->count; ++j)
	{
		motionB[j] = tbProjectPointMotion(sB, xfB, proxyB->points[j], bound->omegaB, normal, lambda);
		nearestB = tbMinFloat(nearestB, motionB[j].position);
	}
	float closest = nearestB - farthestA;

	float fixedStep = FLT_MAX;
	for (int j = 0; j < proxyB->count; ++j)
	{
		for (int i = 0; i < proxyA->count; ++i)
		{
			float h0 = gap + (motionB[j].position - motionA[i].position - closest);
			float h1 = motionB[j].velocity - motionA[i].velocity;
			float K = motionA[i].curvature + motionB[j].curvature;
			fixedStep = tbMinFloat(fixedStep, tbFirstRootConcave(h0, h1, K));
		}
	}
	if (lambda == 0.0f)
	{
		return fixedStep;
	}

	// Frame term λ²·max|D| + 2|λ|·|V| with D = cB − cA: |D| is the norm of an affine function of
	// time, convex, so on [t, maxFraction] it is largest at one of the ends.
	float tMax = input->maxFraction;
	tbVec2 dNow = tbSub(tbLerp(sB->c1, sB->c2, t), tbLerp(sA->c1, sA->c2, t));
	tbVec2 dEnd = tbSub(tbLerp(sB->c1, sB->c2, tMax), tbLerp(sA->c1, sA->c2, tMax));
	float centerReach = tbMaxFloat(tbLength(dNow), tbLength(dEnd));
	float frame = lambda * lambda * centerReach + 2.0f * tbAbsFloat(lambda) * bound->relativeSpeed;
	float turningStep = FLT_MAX;
	for (int j = 0; j < proxyB->count; ++j)
	{
		for (int i = 0; i < proxyA->count; ++i)
		{
			float h0 = gap + (motionB[j].position - motionA[i].position - closest);
			float h1 = (motionB[j].velocity - motionA[i].velocity) + (motionB[j].turning - motionA[i].turning);
			float K = frame + motionA[i].turningCurvature + motionB[j].turningCurvature;
			turningStep = tbMinFloat(turningStep, tbFirstRootConcave(h0, h1, K));
		}
	}
	return tbMaxFloat(fixedStep, turningStep);
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
	return tbTimeOfImpactToTarget(input, TB_TOI_TARGET_SEPARATION);
}

tbTOIOutput tbTimeOfImpactToTarget(const tbTOIInput* input, float targetSeparation)
{
	tbTOIOutput output = {tb_toiStateUnknown, 0.0f, 0, {0.0f, 0.0f}, {0.0f, 0.0f}};
	if (tbValidTOIInput("tbTimeOfImpact", input, targetSeparation) == false)
	{
		return output;
	}

	tbAdvanceBound bound = tbMakeAdvanceBound(input);
	float radiusA = input->proxyA.radius;
	float radiusB = input->proxyB.radius;
	float target = targetSeparation;
	float tMax = input->maxFraction;

	tbSimplexCache cache = {0};

	float t = 0.0f;
	for (int iteration = 1;; ++iteration)
	{
		tbTransform transformA = tbSweepTransformAt(&input->sweepA, bound.omegaA, t);
		tbTransform transformB = tbSweepTransformAt(&input->sweepB, bound.omegaB, t);
		tbDistanceOutput distance = tbShapeDistanceBetween(&input->proxyA, transformA, &input->proxyB, transformB, false,
														   &cache, NULL);
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
		float lambda = tbWitnessTurnRate(&cache, &bound);
		float step = tbMaxFloat(gap / closingSpeed,
								tbSecondOrderStep(input, &bound, transformA, transformB,
												  distance.normal, gap, t, lambda));
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
