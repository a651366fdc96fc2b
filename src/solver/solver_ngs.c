// Sequential impulses plus non-linear Gauss–Seidel position correction: the Box2D 2.4 emulation
// (Catto GDC 2009 "Modeling and Solving Constraints"; Box2D 2.4's documented b2Island::Solve).
// With one sub-step, one NGS step is 2.4's step, in 2.4's order:
//   1. integrate velocities, v ← (v + h·a)/(1 + h·c) (solver.c, shared);
//   2. prepare (contact_solver.c, NGS branch): points apart at the start of the step (s > 0) are
//      left out for the whole step, since 2.4 has no speculative contacts and reports a polygon
//      point only once the 0.01 m skins touch (Tumble's rounded separation ≤ 0); the restitution
//      velocity bias is taken from the relative normal velocity after step 1:
//          bias = −e·Ċ0 if Ċ0 < −restitutionThreshold, else 0;
//   3. warm start (shared);
//   4. velocity iterations, per contact friction FIRST (bounded by the normal impulse of the
//      previous iteration, as 2.4 does), then the normal, rigid, no position bias:
//          Ċ = J·v, J = [−n, −rA × n, n, rB × n], λ = −m_eff·(Ċ − bias), λ_acc ≥ 0;
//      two-point manifolds use Catto's block solver (below) as 2.4 does with b2_blockSolve;
//   5. integrate positions (shared);
//   6. position iterations: for every active point,
//          s from the current deltas (anchors rotated with the bodies, normal held fixed),
//          C = clamp(β·(s + linear slop), −TB_MAX_LINEAR_CORRECTION, 0), β = 0.2, slop 5 mm,
//          K with the current anchors, P = (−C/K)·n,
//          ΔpA −= mA⁻¹P, ΔθA −= IA⁻¹ rA × P, ΔpB += mB⁻¹P, ΔθB += IB⁻¹ rB × P,
//      stopping when the deepest overlap seen in a pass is within 3 slops (2.4's test).
// Restitution is not applied again after the step (tbApplyRestitution skips NGS).
//
// Block solver (Catto, Box2D's b2ContactSolver notes). The two normal impulses x = (x1, x2) of a
// two-point manifold solve the linear complementarity problem
//     w = K·x + b,  x ≥ 0,  w ≥ 0,  xᵢ·wᵢ = 0,
// with K the 2×2 effective-mass matrix (K11, K22 the single-point K, K12 the coupling) and
// b = Ċ − bias − K·x_acc the velocity the current accumulated impulse leaves. In 2D the LCP is
// solved exactly by trying its four cases in turn and keeping the first consistent one:
//     both active  x = −K⁻¹b                       (needs x1, x2 ≥ 0)
//     only x1      x1 = −b1/K11, x2 = 0            (needs x1 ≥ 0, w2 = K21·x1 + b2 ≥ 0)
//     only x2      x2 = −b2/K22, x1 = 0            (needs x2 ≥ 0, w1 = K12·x2 + b1 ≥ 0)
//     neither      x = 0                           (needs b1, b2 ≥ 0)
// (if none holds, rounding: keep the previous impulse). Solving the pair together removes the
// see-saw of point-by-point Gauss–Seidel on a box resting on two corners, which otherwise leaves
// a small rotation per step that makes stacks walk. K is accepted only when well conditioned,
// K11² < 1000·det K (tested on K/K11, which is scale-free); otherwise, as in 2.4, only the first
// point is solved for velocity (its partner still takes part in the position pass).
//
// Differences from 2.4 that remain: the position pass uses the linearised separation with the
// normal held fixed (2.4 rotates the reference face normal with its body and re-derives the
// point from local coordinates; the two agree to second order in the step's rotation), and the
// contact order is Tumble's (island.c), not 2.4's island traversal.
#include "solver_methods.h"

#include "contact_solver.h"
#include "integrator.h"
#include "joints/joint.h"

#include "tumble/constants.h"

#include <float.h>
#include <stdbool.h>

/// Per-constraint NGS data, rebuilt at every sub-step from the constraint and its manifold.
typedef struct tbNGSConstraint
{
	float bias[2];		  ///< m/s, restitution velocity bias (2.4's velocityBias)
	bool active[2];		  ///< takes part in the velocity iterations
	bool positionActive[2]; ///< takes part in the position iterations
	bool block;			  ///< two active points solved together
	float k11, k12, k22;  ///< K (1/kg)
	float m11, m12, m22;  ///< K⁻¹ (kg)
	bool toi[2];		  ///< made active by the time-of-impact sub-step
	bool toiSolve;		  ///< part of the current time-of-impact solve
	float savedNormalImpulse[2], savedTangentImpulse[2];
} tbNGSConstraint;

// 2.4's b2_maxConditionNumber for the block solver.
#define TB_NGS_MAX_CONDITION 1000.0f

void tbNGSPrepare(tbStepContext* context)
{
	tbSoftness rigid = {0.0f, 1.0f, 0.0f};
	context->contactSoftness = rigid;
	context->staticSoftness = rigid;
}

// Block solver set-up of a constraint whose active points are known: K and K⁻¹ when both points
// are active and K is well conditioned; otherwise, as 2.4, only the first point is solved for
// velocity, and its partner's warm start is taken back (when `context` is given).
static void tbSetupBlock(tbNGSConstraint* info, tbContactConstraint* c, tbStepContext* context)
{
	info->block = false;
	if (info->active[0] == false || info->active[1] == false)
	{
		return;
	}

	const tbContactConstraintPoint* cp1 = c->points + 0;
	const tbContactConstraintPoint* cp2 = c->points + 1;
	tbVec2 n = c->normal;
	float rn1A = tbCross(cp1->anchorA, n), rn1B = tbCross(cp1->anchorB, n);
	float rn2A = tbCross(cp2->anchorA, n), rn2B = tbCross(cp2->anchorB, n);
	float mAB = c->invMassA + c->invMassB;
	float k11 = mAB + c->invIA * rn1A * rn1A + c->invIB * rn1B * rn1B;
	float k22 = mAB + c->invIA * rn2A * rn2A + c->invIB * rn2B * rn2B;
	float k12 = mAB + c->invIA * rn1A * rn2A + c->invIB * rn1B * rn2B;
	// The condition test and the inverse on K/K11 (entries of order 1): for very heavy bodies
	// (1e22 kg) K's entries are of order 1e-23 and det K = K11·K22 − K12² underflowed to a
	// subnormal whose inverse overflowed, giving NaN impulses (found by fuzz_world). With
	// K̂ = K/K11: K11² < 1000·det K ⟺ 1 < 1000·det K̂, and K⁻¹ = K̂⁻¹/K11.
	float invK11 = k11 >= FLT_MIN ? 1.0f / k11 : 0.0f;
	float q12 = k12 * invK11, q22 = k22 * invK11;
	float detQ = q22 - q12 * q12;
	bool conditioned = invK11 > 0.0f && 1.0f < TB_NGS_MAX_CONDITION * detQ;
	float scale = conditioned ? invK11 / detQ : 0.0f; // K11/det K = 1/(K11·det K̂)
	if (conditioned && scale <= FLT_MAX)
	{
		info->block = true;
		info->k11 = k11;
		info->k12 = k12;
		info->k22 = k22;
		info->m11 = scale * q22;
		info->m12 = -scale * q12;
		info->m22 = scale;
	}
	else
	{
		// Ill-conditioned (the points nearly coincide): 2.4 solves the first point alone and
		// does not warm start the second; take back the second point's warm start.
		info->active[1] = false;
		tbContactConstraintPoint* cp = c->points + 1;
		tbVec2 P = tbAdd(tbMulSV(cp->normalImpulse, n), tbMulSV(cp->tangentImpulse, tbRightPerp(n)));
		tbApplyContactImpulse(context->bodies + c->indexA, context->bodies + c->indexB, c, cp->anchorA,
							  cp->anchorB, tbNeg(P));
		cp->totalNormalImpulse -= cp->normalImpulse;
		cp->normalImpulse = 0.0f;
		cp->tangentImpulse = 0.0f;
	}
	}

static void tbBuildNGSConstraints(tbStepContext* context, tbNGSConstraint* infos)
{
	const tbWorld* world = context->world;
	float threshold = world->def.restitutionThreshold;
	for (int i = 0; i < context->constraintCount; ++i)
	{
		tbContactConstraint* c = context->constraints + i;
		const tbManifold* manifold = &world->contacts[world->cache.solverContacts[i]].manifold;
		tbNGSConstraint* info = infos + i;
		info->block = false;
		info->k11 = info->k12 = info->k22 = 0.0f;
		info->m11 = info->m12 = info->m22 = 0.0f;
		info->toiSolve = false;
		bool emulate = context->subStepCount == 1;
		for (int j = 0; j < 2; ++j)
		{
			info->toi[j] = false;
			info->savedNormalImpulse[j] = 0.0f;
			info->savedTangentImpulse[j] = 0.0f;
			bool active = j < c->pointCount && (manifold->points[j].separation <= 0.0f || emulate == false);
			info->active[j] = active;
			info->positionActive[j] = active;
			info->bias[j] = 0.0f;
			if (emulate && active && c->points[j].relativeVelocity < -threshold)
			{
				info->bias[j] = tbReboundSpeed(c->restitution, c->points[j].relativeVelocity, context->maxLinearSpeed);
			}
		}
		tbSetupBlock(info, c, context);
	}
}

static float tbLinearSeparation(const tbContactConstraint* c, const tbContactConstraintPoint* cp,
								const tbSolverBody* sA, const tbSolverBody* sB)
{
	tbVec2 rA = tbRotateVector(sA->deltaRotation, cp->anchorA);
	tbVec2 rB = tbRotateVector(sB->deltaRotation, cp->anchorB);
	tbVec2 d = tbAdd(tbSub(sB->deltaPosition, sA->deltaPosition), tbSub(rB, rA));
	return cp->baseSeparation + tbDot(d, c->normal);
}

// Two-point normal constraint by the block solver (see the header comment).
static void tbSolveBlock(tbContactConstraint* c, const tbNGSConstraint* info, tbVec2* vA, float* wA, tbVec2* vB,
						 float* wB)
{
	tbContactConstraintPoint* cp1 = c->points + 0;
	tbContactConstraintPoint* cp2 = c->points + 1;
	tbVec2 n = c->normal;
	tbVec2 r1A = cp1->anchorA, r1B = cp1->anchorB;
	tbVec2 r2A = cp2->anchorA, r2B = cp2->anchorB;

	float a1 = cp1->normalImpulse, a2 = cp2->normalImpulse;
	tbVec2 dv1 = tbSub(tbAdd(*vB, tbCrossSV(*wB, r1B)), tbAdd(*vA, tbCrossSV(*wA, r1A)));
	tbVec2 dv2 = tbSub(tbAdd(*vB, tbCrossSV(*wB, r2B)), tbAdd(*vA, tbCrossSV(*wA, r2A)));
	float vn1 = tbDot(dv1, n), vn2 = tbDot(dv2, n);
	float b1 = vn1 - info->bias[0] - (info->k11 * a1 + info->k12 * a2);
	float b2 = vn2 - info->bias[1] - (info->k12 * a1 + info->k22 * a2);

	float x1, x2;
	bool found = true;
	// Case 1: both points push.
	x1 = -(info->m11 * b1 + info->m12 * b2);
	x2 = -(info->m12 * b1 + info->m22 * b2);
	if (x1 < 0.0f || x2 < 0.0f)
	{
		// Case 2: only point 1 pushes; point 2 must then separate (w2 ≥ 0).
		x1 = -b1 / info->k11;
		x2 = 0.0f;
		if (x1 < 0.0f || info->k12 * x1 + b2 < 0.0f)
		{
			// Case 3: only point 2 pushes.
			x1 = 0.0f;
			x2 = -b2 / info->k22;
			if (x2 < 0.0f || info->k12 * x2 + b1 < 0.0f)
			{
				// Case 4: neither pushes.
				x1 = 0.0f;
				x2 = 0.0f;
				found = b1 >= 0.0f && b2 >= 0.0f;
			}
		}
	}
	if (found == false)
	{
		return; // no consistent case (rounding): keep the accumulated impulses
	}

	float d1 = x1 - a1, d2 = x2 - a2;
	tbVec2 P1 = tbMulSV(d1, n);
	tbVec2 P2 = tbMulSV(d2, n);
	*vA = tbMulSub(*vA, c->invMassA, tbAdd(P1, P2));
	*wA -= c->invIA * (tbCross(r1A, P1) + tbCross(r2A, P2));
	*vB = tbMulAdd(*vB, c->invMassB, tbAdd(P1, P2));
	*wB += c->invIB * (tbCross(r1B, P1) + tbCross(r2B, P2));
	cp1->normalImpulse = x1;
	cp2->normalImpulse = x2;
	cp1->totalNormalImpulse += d1;
	cp2->totalNormalImpulse += d2;
}

// One velocity iteration over all contacts, Box2D 2.4's order: friction, then normal.
// With `toiOnly`, only the constraints of the current time-of-impact solve.
static void tbSolveVelocityConstraints(tbStepContext* context, const tbNGSConstraint* infos, bool toiOnly)
{
	tbSolverBody* bodies = context->bodies;
	for (int i = 0; i < context->constraintCount; ++i)
	{
		tbContactConstraint* c = context->constraints + i;
		const tbNGSConstraint* info = infos + i;
		if (toiOnly && info->toiSolve == false)
		{
			continue;
		}
		tbSolverBody* sA = bodies + c->indexA;
		tbSolverBody* sB = bodies + c->indexB;
		tbVec2 vA = sA->linearVelocity;
		float wA = sA->angularVelocity;
		tbVec2 vB = sB->linearVelocity;
		float wB = sB->angularVelocity;
		float mA = c->invMassA, iA = c->invIA;
		float mB = c->invMassB, iB = c->invIB;
		tbVec2 normal = c->normal;
		tbVec2 tangent = tbRightPerp(normal);

		// Sub-stepped: speculative gaps s > 0 may close within the sub-step, no more (bias s/h).
		tbNGSConstraint biased = *info;
		if (context->subStepCount > 1)
		{
			for (int j = 0; j < c->pointCount; ++j)
			{
				float s = tbLinearSeparation(c, c->points + j, sA, sB);
				if (s > 0.0f)
				{
					biased.bias[j] -= s * context->inv_h;
				}
			}
		}
		info = &biased;

		// Friction first, bounded by the normal impulse of the previous iteration (or warm start).
		for (int j = 0; j < c->pointCount; ++j)
		{
			if (info->active[j] == false)
			{
				continue;
			}
			tbContactConstraintPoint* cp = c->points + j;
			tbVec2 rA = cp->anchorA;
			tbVec2 rB = cp->anchorB;
			tbVec2 dv = tbSub(tbAdd(vB, tbCrossSV(wB, rB)), tbAdd(vA, tbCrossSV(wA, rA)));
			float vt = tbDot(dv, tangent) - c->tangentSpeed;
			float impulse = -cp->tangentMass * vt;
			float maxFriction = c->friction * cp->normalImpulse;
			float newImpulse = tbClampFloat(cp->tangentImpulse + impulse, -maxFriction, maxFriction);
			impulse = newImpulse - cp->tangentImpulse;
			cp->tangentImpulse = newImpulse;
			tbVec2 P = tbMulSV(impulse, tangent);
			vA = tbMulSub(vA, mA, P);
			wA -= iA * tbCross(rA, P);
			vB = tbMulAdd(vB, mB, P);
			wB += iB * tbCross(rB, P);
		}

		if (info->block)
		{
			tbSolveBlock(c, info, &vA, &wA, &vB, &wB);
		}
		else
		{
			for (int j = 0; j < c->pointCount; ++j)
			{
				if (info->active[j] == false)
				{
					continue;
				}
				tbContactConstraintPoint* cp = c->points + j;
				tbVec2 rA = cp->anchorA;
				tbVec2 rB = cp->anchorB;
				tbVec2 dv = tbSub(tbAdd(vB, tbCrossSV(wB, rB)), tbAdd(vA, tbCrossSV(wA, rA)));
				float vn = tbDot(dv, normal);
				float impulse = -cp->normalMass * (vn - info->bias[j]);
				float newImpulse = tbMaxFloat(cp->normalImpulse + impulse, 0.0f);
				impulse = newImpulse - cp->normalImpulse;
				cp->normalImpulse = newImpulse;
				cp->totalNormalImpulse += impulse;
				tbVec2 P = tbMulSV(impulse, normal);
				vA = tbMulSub(vA, mA, P);
				wA -= iA * tbCross(rA, P);
				vB = tbMulAdd(vB, mB, P);
				wB += iB * tbCross(rB, P);
			}
		}

		if (c->rollingResistance > 0.0f)
		{
			// Rolling resistance as in the soft step's scalar solver (contact_solver.c).
			float maxImpulse = c->rollingResistance * (c->points[0].normalImpulse +
													   (c->pointCount > 1 ? c->points[1].normalImpulse : 0.0f));
			float impulse = -c->rollingMass * (wB - wA);
			float newImpulse = tbClampFloat(c->rollingImpulse + impulse, -maxImpulse, maxImpulse);
			impulse = newImpulse - c->rollingImpulse;
			c->rollingImpulse = newImpulse;
			wA -= iA * impulse;
			wB += iB * impulse;
		}

		sA->linearVelocity = vA;
		sA->angularVelocity = wA;
		sB->linearVelocity = vB;
		sB->angularVelocity = wB;
	}
}

// One position pass over all contacts; returns the smallest separation seen (m).
static float tbSolvePositionConstraints(tbStepContext* context, const tbNGSConstraint* infos)
{
	float minSeparation = 0.0f;
	tbSolverBody* bodies = context->bodies;
	for (int i = 0; i < context->constraintCount; ++i)
	{
		const tbContactConstraint* c = context->constraints + i;
		tbSolverBody* sA = bodies + c->indexA;
		tbSolverBody* sB = bodies + c->indexB;
		tbVec2 normal = c->normal;
		for (int j = 0; j < c->pointCount; ++j)
		{
			if (infos[i].positionActive[j] == false)
			{
				continue;
			}
			const tbContactConstraintPoint* cp = c->points + j;
			tbVec2 rA = tbRotateVector(sA->deltaRotation, cp->anchorA);
			tbVec2 rB = tbRotateVector(sB->deltaRotation, cp->anchorB);
			tbVec2 d = tbAdd(tbSub(sB->deltaPosition, sA->deltaPosition), tbSub(rB, rA));
			float s = cp->baseSeparation + tbDot(d, normal);
			minSeparation = tbMinFloat(minSeparation, s);

			float C = tbClampFloat(TB_BAUMGARTE * (s + TB_LINEAR_SLOP), -TB_MAX_LINEAR_CORRECTION, 0.0f);
			float rnA = tbCross(rA, normal);
			float rnB = tbCross(rB, normal);
			float K = c->invMassA + c->invMassB + c->invIA * rnA * rnA + c->invIB * rnB * rnB;
			float impulse = K > 0.0f ? -C / K : 0.0f;
			tbVec2 P = tbMulSV(impulse, normal);

			sA->deltaPosition = tbMulSub(sA->deltaPosition, c->invMassA, P);
			sA->deltaRotation = tbIntegrateRotation(sA->deltaRotation, -c->invIA * tbCross(rA, P));
			sB->deltaPosition = tbMulAdd(sB->deltaPosition, c->invMassB, P);
			sB->deltaRotation = tbIntegrateRotation(sB->deltaRotation, c->invIB * tbCross(rB, P));
		}
	}
	return minSeparation;
}

// Box2D 2.4's time-of-impact sub-step for a dynamic body against static or kinematic ground
// (b2World::SolveTOI as documented: 2.4 sweeps every such pair continuously). A point that was
// apart at the start of the step took no part in it; if the body's motion over the step carries
// that point below 2.4's time-of-impact target (surface separation −3·slop, i.e. core distance
// totalRadius − 3·slop), then, as 2.4 does:
//   1. the body is moved back to the time α at which the separation reaches the target
//      (linear in the sweep: α = (s0 − target)/(s0 − s1));
//   2. its contacts with infinite-mass partners are solved with the points overlapping there:
//      up to 20 position passes with β = 0.75 until the deepest overlap is within 1.5 slops,
//      then the velocity iterations from zero impulse (no warm start), with the restitution bias
//      of the current approach speed;
//   3. the body moves on with its new velocity for the remaining (1 − α)·h.
// TOI impulses are not kept for warm starting (2.4 discards them too). Only with one sub-step:
// sub-stepped NGS keeps speculative contacts' own protection from the next sub-step.
#define TB_NGS_TOI_BAUMGARTE 0.75f
#define TB_NGS_TOI_POSITION_ITERATIONS 20

static bool tbIsGroundPair(const tbContactConstraint* c)
{
	bool fixedA = c->invMassA == 0.0f && c->invIA == 0.0f;
	bool fixedB = c->invMassB == 0.0f && c->invIB == 0.0f;
	return fixedA != fixedB;
}

static void tbSolveTimeOfImpact(tbStepContext* context, tbNGSConstraint* infos)
{
	const tbWorld* world = context->world;
	const float target = -3.0f * TB_LINEAR_SLOP;
	int bodyCount = context->bodyCount;
	tbSolverBody* bodies = context->bodies;

	for (int i = 0; i < context->constraintCount; ++i)
	{
		const tbContactConstraint* c = context->constraints + i;
		if (tbIsGroundPair(c) == false)
		{
			continue;
		}
		int bodyIndex = c->invMassA == 0.0f && c->invIA == 0.0f ? c->indexB : c->indexA;
		if (bodyIndex >= bodyCount)
		{
			continue;
		}

		// Earliest time of impact of this body over all its ground contacts.
		float alpha = 1.0f;
		for (int k = 0; k < context->constraintCount; ++k)
		{
			const tbContactConstraint* ck = context->constraints + k;
			if (tbIsGroundPair(ck) == false || (ck->indexA != bodyIndex && ck->indexB != bodyIndex))
			{
				continue;
			}
			const tbManifold* manifold = &world->contacts[world->cache.solverContacts[k]].manifold;
			for (int j = 0; j < ck->pointCount; ++j)
			{
				float s0 = manifold->points[j].separation;
				if (infos[k].positionActive[j] || s0 <= target)
				{
					continue;
				}
				float s1 = tbLinearSeparation(ck, ck->points + j, bodies + ck->indexA, bodies + ck->indexB);
				if (s1 < target)
				{
					alpha = tbMinFloat(alpha, (s0 - target) / (s0 - s1));
				}
			}
		}
		if (alpha >= 1.0f)
		{
			continue;
		}

		// 1. Back to the time of impact.
		tbSolverBody* body = bodies + bodyIndex;
		float angle = tbAtan2(body->deltaRotation.s, body->deltaRotation.c); // not libm's: the same everywhere
		body->deltaPosition = tbMulSV(alpha, body->deltaPosition);
		body->deltaRotation = tbMakeRot(alpha * angle);

		// 2. Points overlapping at the time of impact become active (for the rest of the step).
		for (int k = 0; k < context->constraintCount; ++k)
		{
			tbContactConstraint* ck = context->constraints + k;
			if (tbIsGroundPair(ck) == false || (ck->indexA != bodyIndex && ck->indexB != bodyIndex))
			{
				continue;
			}
			for (int j = 0; j < ck->pointCount; ++j)
			{
				if (infos[k].positionActive[j] == false &&
					tbLinearSeparation(ck, ck->points + j, bodies + ck->indexA, bodies + ck->indexB) <= 0.0f)
				{
					infos[k].positionActive[j] = true;
					infos[k].toi[j] = true;
				}
			}
		}

		for (int iteration = 0; iteration < TB_NGS_TOI_POSITION_ITERATIONS; ++iteration)
		{
			float minSeparation = 0.0f;
			for (int k = 0; k < context->constraintCount; ++k)
			{
				const tbContactConstraint* ck = context->constraints + k;
				if (tbIsGroundPair(ck) == false || (ck->indexA != bodyIndex && ck->indexB != bodyIndex))
				{
					continue;
				}
				tbSolverBody* sA = bodies + ck->indexA;
				tbSolverBody* sB = bodies + ck->indexB;
				for (int j = 0; j < ck->pointCount; ++j)
				{
					if (infos[k].positionActive[j] == false)
					{
						continue;
					}
					const tbContactConstraintPoint* cp = ck->points + j;
					float sep = tbLinearSeparation(ck, cp, sA, sB);
					minSeparation = tbMinFloat(minSeparation, sep);
					float C = tbClampFloat(TB_NGS_TOI_BAUMGARTE * (sep + TB_LINEAR_SLOP), -TB_MAX_LINEAR_CORRECTION, 0.0f);
					tbVec2 rA = tbRotateVector(sA->deltaRotation, cp->anchorA);
					tbVec2 rB = tbRotateVector(sB->deltaRotation, cp->anchorB);
					float rnA = tbCross(rA, ck->normal);
					float rnB = tbCross(rB, ck->normal);
					float K = ck->invMassA + ck->invMassB + ck->invIA * rnA * rnA + ck->invIB * rnB * rnB;
					float impulse = K > 0.0f ? -C / K : 0.0f;
					tbVec2 P = tbMulSV(impulse, ck->normal);
					sA->deltaPosition = tbMulSub(sA->deltaPosition, ck->invMassA, P);
					sA->deltaRotation = tbIntegrateRotation(sA->deltaRotation, -ck->invIA * tbCross(rA, P));
					sB->deltaPosition = tbMulAdd(sB->deltaPosition, ck->invMassB, P);
					sB->deltaRotation = tbIntegrateRotation(sB->deltaRotation, ck->invIB * tbCross(rB, P));
				}
			}
			if (minSeparation >= -1.5f * TB_LINEAR_SLOP)
			{
				break;
			}
		}

		// Velocity solve of this body's ground contacts only, from zero impulse; restitution bias
		// from the current approach speed.
		float threshold = world->def.restitutionThreshold;
		for (int k = 0; k < context->constraintCount; ++k)
		{
			tbContactConstraint* ck = context->constraints + k;
			tbNGSConstraint* info = infos + k;
			bool mine = tbIsGroundPair(ck) && (ck->indexA == bodyIndex || ck->indexB == bodyIndex);
			info->toiSolve = mine;
			if (mine == false)
			{
				continue;
			}
			const tbSolverBody* sA = bodies + ck->indexA;
			const tbSolverBody* sB = bodies + ck->indexB;
			for (int j = 0; j < ck->pointCount; ++j)
			{
				tbContactConstraintPoint* cp = ck->points + j;
				info->savedNormalImpulse[j] = cp->normalImpulse;
				info->savedTangentImpulse[j] = cp->tangentImpulse;
				cp->normalImpulse = 0.0f;
				cp->tangentImpulse = 0.0f;
				info->active[j] = info->positionActive[j];
				info->bias[j] = 0.0f;
				tbVec2 vA = tbAdd(sA->linearVelocity, tbCrossSV(sA->angularVelocity, cp->anchorA));
				tbVec2 vB = tbAdd(sB->linearVelocity, tbCrossSV(sB->angularVelocity, cp->anchorB));
				float vRel = tbDot(tbSub(vB, vA), ck->normal);
				if (vRel < -threshold)
				{
					// Bounded as every rebound is (contact_solver.h): restitution 9e18 made it ∞.
					info->bias[j] = tbReboundSpeed(ck->restitution, vRel, context->maxLinearSpeed);
				}
			}
			tbSetupBlock(info, ck, context);
		}
		int velocityIterations = tbMaxInt(world->def.velocityIterations, 1);
		for (int iteration = 0; iteration < velocityIterations; ++iteration)
		{
			tbSolveVelocityConstraints(context, infos, true);
		}
		for (int k = 0; k < context->constraintCount; ++k)
		{
			tbContactConstraint* ck = context->constraints + k;
			tbNGSConstraint* info = infos + k;
			if (info->toiSolve == false)
			{
				continue;
			}
			info->toiSolve = false;
			for (int j = 0; j < ck->pointCount; ++j)
			{
				tbContactConstraintPoint* cp = ck->points + j;
				cp->normalImpulse = info->savedNormalImpulse[j];
				cp->tangentImpulse = info->savedTangentImpulse[j];
			}
		}

		// 3. The rest of the step.
		float rest = (1.0f - alpha) * context->h;
		body->deltaPosition = tbMulAdd(body->deltaPosition, rest, body->linearVelocity);
		body->deltaRotation = tbIntegrateRotation(body->deltaRotation, rest * body->angularVelocity);
	}
}

void tbNGSSubStep(tbStepContext* context)
{
	const tbWorldDef* def = &context->world->def;
	if (context->ngsScratch == NULL)
	{
		int byteCount = (int)sizeof(tbNGSConstraint) * context->constraintCount;
		context->ngsScratch = tbArenaAlloc(&context->world->stepArena, byteCount); // once per step
	}
	tbNGSConstraint* infos = context->ngsScratch;
	tbBuildNGSConstraints(context, infos);

	int velocityIterations = tbMaxInt(def->velocityIterations, 1);
	for (int i = 0; i < velocityIterations; ++i)
	{
		tbSolveJoints(context, true); // joint.c: velocity rows with a Baumgarte bias, no position pass
		tbSolveVelocityConstraints(context, infos, false);
	}
	tbIntegratePositions(context);
	for (int i = 0; i < def->positionIterations; ++i)
	{
		if (tbSolvePositionConstraints(context, infos) >= -3.0f * TB_LINEAR_SLOP)
		{
			break;
		}
	}
	if (context->subStepCount == 1)
	{
		tbSolveTimeOfImpact(context, infos);
	}
}
