// Contact constraints solved by sequential impulses, shared by the three position methods.
//
// Non-penetration. For a manifold point p with normal n (from A to B) and anchors
// rA = p − cA, rB = p − cB, the position constraint is the separation
//     C = dot((cB + rB) − (cA + rA), n) ≥ 0,
// whose time derivative (n held fixed) is the relative normal velocity
//     Ċ = dot(vB + ωB × rB − vA − ωA × rA, n) = J·v,  J = [−n, −rA × n, n, rB × n].
// An impulse λ along J changes Ċ by K·λ with
//     K = mA⁻¹ + mB⁻¹ + IA⁻¹ (rA × n)² + IB⁻¹ (rB × n)²,  m_eff = 1/K,
// so the impulse that brings Ċ to −bias is λ = −m_eff (Ċ + bias). Sequential impulses visit each
// point in turn and clamp the accumulated impulse, not the increment: λn ≥ 0 (contacts push,
// never pull), friction |λt| ≤ μ·λn (Coulomb cone, 2D: a segment), with the same K along the
// tangent t = rightPerp(n). The accumulated impulse is kept between sub-steps and steps (warm
// starting) so that resting stacks start each iteration at the converged answer.
//
// Separation during the step is linearised, not re-collided: with dp the centre motion and dq
// the rotation since the start of the step,
//     s = s0 + dot((dpB + dqB·rB) − (dpA + dqA·rA) − (rB − rA), n).
//
// Bias policies (tbBiasPolicy): speculative gaps s > 0 always get bias s/h, so a body may close
// the gap within one sub-step but not overshoot it (speculative contact, Catto GDC 2014). Overlap
// s ≤ 0 gets a soft spring (soft step), a Baumgarte bias, or nothing (NGS corrects positions).
//
// Soft constraint (Catto GDC 2011 "Soft Constraints", GDC 2024 / Solver2D blog "soft step"):
// a spring of angular frequency ω and damping ratio ζ solved implicitly over h gives
//     λ = −m_eff·massScale·(Ċ + biasRate·C) − impulseScale·λ_acc,
// with the coefficients of tbMakeSoftness. The λ_acc term bleeds the spring's stored impulse.
//
// Restitution is applied once after the sub-steps, on the velocities: target Ċ = −e·Ċ0 with Ċ0
// the relative normal velocity at the start of the step (Catto GDC 2009; Box2D v3 does the same).
//
// References: E. Catto, "Fast and Simple Physics using Sequential Impulses", GDC 2006;
// "Modeling and Solving Constraints", GDC 2009; "Soft Constraints", GDC 2011;
// "Understanding Constraints", GDC 2014; "Solver2D" blog post, 2024.
#include "constraint_graph.h"
#include "contact_solver.h"
#include "core/task.h"

#include "integrator.h"

#include "tumble/constants.h"

#include <stdatomic.h>
#include <stddef.h>
#include <string.h>

/// Contacts per task range when the step runs on workers.
#define TB_CONTACTS_PER_TASK 256

/// Sweeps of impact propagation at most: a chain of n touching bodies needs at most n when swept
/// against its order, one when swept along it.
#define TB_PROPAGATION_SWEEPS 32

// The solver index of a body, or `staticIndex` for bodies that are not in the awake set (static or
// asleep). The solver's bodies are the awake set in its order, gathered this step, and the awake
// set does not change during the solve: the awake index is the solver index.
static int tbGetSolverIndex(const tbWorld* world, int bodyId, int staticIndex)
{
	int index = world->bodies[bodyId].awakeIndex;
	return index >= 0 && index < staticIndex ? index : staticIndex;
}

// Inverse effective mass along direction u for anchors rA, rB.
static float tbInverseMassAlong(float invMassA, float invIA, float invMassB, float invIB, tbVec2 rA, tbVec2 rB, tbVec2 u)
{
	float rnA = tbCross(rA, u);
	float rnB = tbCross(rB, u);
	return invMassA + invMassB + invIA * rnA * rnA + invIB * rnB * rnB;
}

static float tbInverseEffectiveMass(const tbContactConstraint* c, tbVec2 rA, tbVec2 rB, tbVec2 u)
{
	return tbInverseMassAlong(c->invMassA, c->invIA, c->invMassB, c->invIB, rA, rB, u);
}

// Central friction (tbWorldDef::enableCentralFriction). The friction row of manifold point i is
// J_i = [−t, −(rA_i × t), t, rB_i × t], where rA_i and rB_i reach the same world point p_i from the
// two centres of mass. With t = rightPerp(n), r × t = −(r · n): two points' rows differ only in
// their angular terms, by (p_1 − p_2) · n, which is 0 when both points lie on one face (a box on a
// box, a box on the ground) and the difference of their depths otherwise. A force along the face
// then has the same torque wherever on the face it acts, and one row at the points' centre of
// pressure, r = w·r_1 + (1 − w)·r_2 with w point 1's share of the normal impulse, bounded by
// μ·(λn_1 + λn_2), applies the friction the two rows apply (Coulomb's law summed over the face: a
// sliding face's friction acts at its centre of pressure) with half the friction rows per pass.
// The shares are the warm start's normal impulses (the last step's), a half each for a new contact
// (tbPressureWeight); a tilted box resting on one corner then has its friction at that corner, as
// per-point rows would. The row's mass and impulse sit in point 0's tangentMass and tangentImpulse;
// the store splits the impulse back over the points by their normal impulses (tbSplitFriction).
typedef struct tbFrictionRow
{
	tbVec2 anchorA, anchorB;
	float mass;	   ///< kg, 1/K along the tangent at the anchors
	float impulse; ///< N·s, the warm start's: the points' friction impulses summed
} tbFrictionRow;

/// The central friction row of a manifold with pointCount points at anchors rA[j], rB[j] carrying
/// the (warm start) impulses normalImpulse[j] and tangentImpulse[j]; one point's row is its own.
static tbFrictionRow tbCentralFrictionRow(float invMassA, float invIA, float invMassB, float invIB, tbVec2 tangent,
										  int pointCount, const tbVec2 rA[2], const tbVec2 rB[2],
										  const float normalImpulse[2], const float tangentImpulse[2])
{
	tbFrictionRow row;
	row.anchorA = rA[0];
	row.anchorB = rB[0];
	row.impulse = tangentImpulse[0];
	if (pointCount == 2)
	{
		float w0 = tbPressureWeight(normalImpulse[0], normalImpulse[1]);
		float w1 = 1.0f - w0;
		row.anchorA = tbAdd(tbMulSV(w0, rA[0]), tbMulSV(w1, rA[1]));
		row.anchorB = tbAdd(tbMulSV(w0, rB[0]), tbMulSV(w1, rB[1]));
		row.impulse = tangentImpulse[0] + tangentImpulse[1];
	}
	float k = tbInverseMassAlong(invMassA, invIA, invMassB, invIB, row.anchorA, row.anchorB, tangent);
	row.mass = k > 0.0f ? 1.0f / k : 0.0f;
	return row;
}

/// A prepared scalar constraint's friction as one central row (c's points hold the warm start).
static void tbSetCentralFriction(tbContactConstraint* c, tbVec2 tangent)
{
	const tbContactConstraintPoint* p0 = c->points;
	const tbContactConstraintPoint* p1 = c->points + (c->pointCount > 1 ? 1 : 0); // read only with two points
	tbVec2 rA[2] = {p0->anchorA, p1->anchorA};
	tbVec2 rB[2] = {p0->anchorB, p1->anchorB};
	float normalImpulse[2] = {p0->normalImpulse, p1->normalImpulse};
	float tangentImpulse[2] = {p0->tangentImpulse, p1->tangentImpulse};
	tbFrictionRow row = tbCentralFrictionRow(c->invMassA, c->invIA, c->invMassB, c->invIB, tangent, c->pointCount, rA,
											 rB, normalImpulse, tangentImpulse);
	c->frictionAnchorA = row.anchorA;
	c->frictionAnchorB = row.anchorB;
	c->points[0].tangentMass = row.mass;
	c->points[0].tangentImpulse = row.impulse;
	c->points[1].tangentMass = 0.0f;
	c->points[1].tangentImpulse = 0.0f;
}

// Velocity of body `index` after the first velocity integration of the step (the stand-in: 0).
static void tbIntegratedVelocity(const tbStepContext* context, int index, tbVec2* v, float* w)
{
	if (index >= context->bodyCount)
	{
		*v = tbVec2_zero;
		*w = 0.0f;
		return;
	}
	tbSolverBody sb = context->bodies[index];
	const tbSolverMotion* m = context->motions + index;
	sb.linearVelocity = tbMulSV(m->linearDamping, tbAdd(sb.linearVelocity, m->linearDelta));
	sb.angularVelocity = m->angularDamping * (sb.angularVelocity + m->angularDelta);
	tbClampSpeeds(context, &sb, index); // as the integration does (gravity 3e38 m/s²: 5e36 m/s after one step)
	*v = sb.linearVelocity;
	*w = sb.angularVelocity;
}

// NGS at one sub-step is the Box2D 2.4 emulation (solver_ngs.c): 2.4 has no speculative contacts, so a point that is apart at
// the start of the step (s > 0; with the 0.01 m polygon skins, exactly the points 2.4 would not
// report) takes no part in the step: no warm start, no impulse, no position correction (the
// contact itself still exists). 2.4 prepares its constraints after integrating the velocities,
// so the relative normal velocity that decides restitution includes this step's gravity and
// damping: v = (v0 + h·a)/(1 + h·c), as tbIntegrateVelocities will compute it.
static void tbPrepareConstraintNGS(const tbStepContext* context, const tbManifold* manifold, tbContactConstraint* c)
{
	tbVec2 vA, vB;
	float wA, wB;
	tbIntegratedVelocity(context, c->indexA, &vA, &wA);
	tbIntegratedVelocity(context, c->indexB, &vB, &wB);
	for (int j = 0; j < c->pointCount; ++j)
	{
		tbContactConstraintPoint* cp = c->points + j;
		if (manifold->points[j].separation > 0.0f)
		{
			cp->normalImpulse = 0.0f;
			cp->tangentImpulse = 0.0f;
		}
		tbVec2 dvA = tbAdd(vA, tbCrossSV(wA, cp->anchorA));
		tbVec2 dvB = tbAdd(vB, tbCrossSV(wB, cp->anchorB));
		cp->relativeVelocity = tbDot(tbSub(dvB, dvA), c->normal);
	}
}

/// Restitution needs the approach speed at impact. A speculative point (gap s > 0) meets the
/// surface later in the step, after gravity has sped the approach up: with relative normal
/// acceleration aₙ < 0 (towards each other), energy gives v_impact² = v² + 2·|aₙ|·s, so
/// v_impact = −sqrt(v² − 2·aₙ·s). Without this the rebound of a body whose contact appears one
/// step before impact is up to g·dt too slow, and its apex, which goes as v², up to 2g·dt/v of it
/// too low.
// The relative normal acceleration gravity gives the pair (aₙ above).
static float tbGravityApproach(const tbStepContext* context, int indexA, float invMassA, int indexB, float invMassB,
							   tbVec2 normal)
{
	tbVec2 gravity = context->world->def.gravity;
	tbVec2 gA = invMassA > 0.0f ? tbMulSV(context->masses[indexA].gravityScale, gravity) : tbVec2_zero;
	tbVec2 gB = invMassB > 0.0f ? tbMulSV(context->masses[indexB].gravityScale, gravity) : tbVec2_zero;
	return tbDot(tbSub(gB, gA), normal);
}

// A point's approach speed at impact, from its speed v and gap sep now (aₙ: tbGravityApproach).
static float tbImpactVelocity(const tbStepContext* context, float an, float sep, float v)
{
	if (sep > 0.0f && v < 0.0f && an < 0.0f)
	{
		// no faster than two bodies at the speed clamp (gravity of 3e38 m/s² made this -∞)
		float fastest = tbMinFloat(v, -2.0f * context->world->def.maximumLinearSpeed);
		float impact = -sqrtf(v * v - 2.0f * an * sep);
		return tbMaxFloat(impact, fastest);
	}
	return v;
}

static void tbEstimateImpactVelocity(const tbStepContext* context, const tbManifold* manifold,
									 tbContactConstraint* c)
{
	float an = tbGravityApproach(context, c->indexA, c->invMassA, c->indexB, c->invMassB, c->normal);
	for (int j = 0; j < c->pointCount; ++j)
	{
		tbContactConstraintPoint* cp = c->points + j;
		cp->relativeVelocity = tbImpactVelocity(context, an, manifold->points[j].separation, cp->relativeVelocity);
	}
}

// A point's separation at the start of the step from its base and anchors (tbPrepareConstraint).
static float tbStartSeparation(float baseSeparation, tbVec2 rA, tbVec2 rB, tbVec2 normal)
{
	return baseSeparation + tbDot(tbSub(rB, rA), normal);
}

// True when some point of c overlaps by more than deepOverlap at the start of the step.
static bool tbIsDeepOverlap(const tbContactConstraint* c, float deepOverlap)
{
	for (int j = 0; j < c->pointCount; ++j)
	{
		const tbContactConstraintPoint* cp = c->points + j;
		if (tbStartSeparation(cp->baseSeparation, cp->anchorA, cp->anchorB, c->normal) < -deepOverlap)
		{
			return true;
		}
	}
	return false;
}

// Soft step's settling (solver_soft.c): a dynamic pair touching for `age` steps that does not
// overlap deeply stiffens from contactHertz to settledHertz over the second settleSteps of
// touching. Static pairs start at the resting stiffness (restHertz), deep ones stay at
// contactHertz. `softness` is the
// pair's softness before settling; the caller has ruled out static and deep pairs.
static inline tbSoftness tbSettledSoftness(const tbStepContext* context, tbSoftness softness, int age)
{
	float settleSteps = context->settleSteps;
	// Settled for good (most resting contacts): when age − s ≥ s the rounded quotient below is ≥ 1
	// and the ramp clamps to 1, so the same result without the division.
	if ((float)age - settleSteps >= settleSteps)
	{
		return context->settledSoftness;
	}
	float ramp = tbClampFloat(((float)age - settleSteps) / settleSteps, 0.0f, 1.0f);
	if (ramp >= 1.0f)
	{
		return context->settledSoftness;
	}
	if (ramp > 0.0f)
	{
		float hertz = context->contactHertz + (context->settledHertz - context->contactHertz) * ramp;
		return tbMakeSoftness(hertz, context->dampingRatio, context->h);
	}
	return softness;
}

/// Contact softening (tbWorldDef::enableContactSoftening, Box2D v3.2's experimental option): a pair
/// of dynamic bodies gets its stiffness and damping ratio scaled by the lighter body's mass over the
/// heavier's, at least one half, from softeningHertz. A light body on a heavy one then pushes the
/// heavy one less hard out of overlap, which is where large mass ratios jitter. The pair does not
/// settle (the settling ramp stiffens, the opposite of what was asked for).
static inline tbSoftness tbSoftenedSoftness(const tbStepContext* context, float invMassA, float invMassB)
{
	float ratio = 1.0f;
	if (invMassA < invMassB)
	{
		ratio = tbMaxFloat(0.5f, invMassA / invMassB); // A is the heavier: mB / mA
	}
	else if (invMassB < invMassA)
	{
		ratio = tbMaxFloat(0.5f, invMassB / invMassA);
	}
	return tbMakeSoftness(ratio * context->softeningHertz, ratio * context->dampingRatio, context->h);
}

static bool tbMovesBoth(float invMassA, float invIA, float invMassB, float invIB)
{
	return (invMassA > 0.0f || invIA > 0.0f) && (invMassB > 0.0f || invIB > 0.0f);
}

static void tbSettleSoftness(const tbStepContext* context, tbContactConstraint* c, int age)
{
	if (tbMovesBoth(c->invMassA, c->invIA, c->invMassB, c->invIB) == false || tbIsDeepOverlap(c, context->deepOverlap))
	{
		return;
	}
	c->softness = tbSettledSoftness(context, c->softness, age);
}

// Which bodies of a contact the solve moves, and whether the wide blocks can carry it.
static tbContactKey tbMakeContactKey(const tbStepContext* context, const tbContact* contact)
{
	const tbWorld* world = context->world;
	int bodyIdA = contact->edges[0].bodyId; // the bodies of shapes A and B (contact.c)
	int bodyIdB = contact->edges[1].bodyId;
	tbContactKey key;
	key.indexA = tbGetSolverIndex(world, bodyIdA, context->bodyCount);
	key.indexB = tbGetSolverIndex(world, bodyIdB, context->bodyCount);

	// Only awake dynamic bodies respond; kinematic and static ends have infinite mass (their
	// tbSolverMass is zero, as is the static stand-in's).
	const tbSolverMass* massA = context->masses + key.indexA;
	const tbSolverMass* massB = context->masses + key.indexB;
	uint32_t flags = 0u;
	flags |= massA->invMass > 0.0f || massA->invI > 0.0f ? (uint32_t)tb_keyMovesA : 0u;
	flags |= massB->invMass > 0.0f || massB->invI > 0.0f ? (uint32_t)tb_keyMovesB : 0u;
	bool dynamicA = key.indexA != context->bodyCount && world->bodies[bodyIdA].type == tb_dynamicBody;
	bool dynamicB = key.indexB != context->bodyCount && world->bodies[bodyIdB].type == tb_dynamicBody;
	flags |= dynamicA ? (uint32_t)tb_keyDynamicA : 0u;
	flags |= dynamicB ? (uint32_t)tb_keyDynamicB : 0u;
	flags |= tbContactMaterialKey(contact);
	key.flags = flags;
	return key;
}

static void tbPrepareConstraint(tbStepContext* context, tbContact* contact, tbContactKey key, tbContactConstraint* c)
{
	c->indexA = key.indexA;
	c->indexB = key.indexB;
	const tbSolverMass* massA = context->masses + c->indexA;
	const tbSolverMass* massB = context->masses + c->indexB;
	c->invMassA = massA->invMass;
	c->invIA = massA->invI;
	c->invMassB = massB->invMass;
	c->invIB = massB->invI;
	bool dynamicPair = (key.flags & tb_keyDynamicA) != 0u && (key.flags & tb_keyDynamicB) != 0u;
	c->softness = dynamicPair ? context->contactSoftness : context->staticSoftness;
	bool softened = dynamicPair && context->contactSoftening;
	if (softened)
	{
		c->softness = tbSoftenedSoftness(context, c->invMassA, c->invMassB);
	}

	const tbManifold* manifold = &contact->manifold;
	tbVec2 normal = manifold->normal;
	tbVec2 tangent = tbRightPerp(normal);
	c->normal = normal;
	c->friction = contact->friction;
	c->restitution = contact->restitution;
	c->pointCount = manifold->pointCount;

	const tbSolverBody* sA = context->bodies + c->indexA;
	const tbSolverBody* sB = context->bodies + c->indexB;
	float warmScale = context->enableWarmStarting ? 1.0f : 0.0f;
	c->tangentSpeed = contact->tangentSpeed;
	c->rollingResistance = contact->rollingResistance;
	float kRolling = c->invIA + c->invIB;
	c->rollingMass = kRolling > 0.0f ? 1.0f / kRolling : 0.0f;
	c->rollingImpulse = warmScale * manifold->rollingImpulse;

	for (int j = 0; j < c->pointCount; ++j)
	{
		const tbManifoldPoint* mp = manifold->points + j;
		tbContactConstraintPoint* cp = c->points + j;
		tbVec2 rA = mp->anchorA;
		tbVec2 rB = mp->anchorB;
		cp->anchorA = rA;
		cp->anchorB = rB;
		cp->baseSeparation = mp->separation - tbDot(tbSub(rB, rA), normal);
		cp->normalImpulse = warmScale * mp->normalImpulse;
		cp->tangentImpulse = warmScale * mp->tangentImpulse;
		cp->totalNormalImpulse = 0.0f;

		float kNormal = tbInverseEffectiveMass(c, rA, rB, normal);
		float kTangent = tbInverseEffectiveMass(c, rA, rB, tangent);
		cp->normalMass = kNormal > 0.0f ? 1.0f / kNormal : 0.0f;
		cp->tangentMass = kTangent > 0.0f ? 1.0f / kTangent : 0.0f;

		tbVec2 vA = tbAdd(sA->linearVelocity, tbCrossSV(sA->angularVelocity, rA));
		tbVec2 vB = tbAdd(sB->linearVelocity, tbCrossSV(sB->angularVelocity, rB));
		cp->relativeVelocity = tbDot(tbSub(vB, vA), normal);
	}
	c->frictionAnchorA = c->points[0].anchorA;
	c->frictionAnchorB = c->points[0].anchorB;
	if (context->centralFriction && c->pointCount > 0)
	{
		tbSetCentralFriction(c, tangent);
	}

	if (context->settleSteps > 0.0f && softened == false)
	{
		tbSettleSoftness(context, c, contact->touchingSteps);
	}
	if (context->world->def.solver == tb_solverNGS && context->subStepCount == 1)
	{
		tbPrepareConstraintNGS(context, manifold, c);
	}
	tbEstimateImpactVelocity(context, manifold, c);

	// The approach speed is final here: store it now, while the contact is in cache (hit events
	// and the next step read it; the store after the solve writes only impulses).
	for (int j = 0; j < c->pointCount; ++j)
	{
		contact->manifold.points[j].normalVelocity = c->points[j].relativeVelocity;
	}
}

// Contacts are read and keyed in contact-id order (memory order): the loads and the stores
// stream. The keys in solve order, which only the colouring and restitution read, are scattered
// from these when needed (tbColorConstraints); walking the solve order instead waited on a cache
// miss per contact.
static void tbKeyContactsTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	tbStepContext* context = taskContext;
	const tbWorld* world = context->world;
	const int* contactIds = world->cache.solverContactsById;
	const tbCollideKey* collideKeys = world->cache.collideKeys;
	// The narrow phase's keys hold when no body has left the awake set since (only then are its
	// awake indices this step's solver indices); a contact it did not key (one side was asleep
	// then) is keyed from its bodies.
	bool useCollideKeys = world->cache.gatheredRemovals == world->cache.awakeRemovals;
	uint32_t step = world->stepIndex;
	int staticIndex = context->bodyCount;
	for (int i = start; i < end; ++i)
	{
		int contactId = contactIds[i];
		const tbCollideKey* ck = collideKeys + contactId;
		tbContactKey key;
		if (useCollideKeys && contactId < world->cache.collideKeyCount && ck->step == step)
		{
			key = ck->key; // awake indices: the static stand-in replaces TB_NULL_INDEX
			key.indexA = key.indexA == TB_NULL_INDEX ? staticIndex : key.indexA;
			key.indexB = key.indexB == TB_NULL_INDEX ? staticIndex : key.indexB;
		}
		else
		{
			key = tbMakeContactKey(context, world->contacts + contactId);
		}
		context->keysById[i] = key;
	}
}

void tbKeyContacts(tbStepContext* context)
{
	int n = context->constraintCount;
	context->keys = tbArenaAlloc(&context->world->stepArena, tbMaxInt((int)sizeof(tbContactKey) * n, 1));
	const tbContactKey* steady = tbSteadyContactKeys(context); // constraint_graph.c
	context->keysFromCache = steady != NULL;
	if (steady != NULL)
	{
		context->keysById = (tbContactKey*)steady; // read only: no contact bounces (tbDropBounce)
		return;
	}
	context->keysById = tbArenaAlloc(&context->world->stepArena, tbMaxInt((int)sizeof(tbContactKey) * n, 1));
	tbParallelFor(&context->world->def, tbKeyContactsTask, n, TB_CONTACTS_PER_TASK, context);
}

// Whether restitution (tbApplyRestitution) can act on c: some point approaches at the restitution
// threshold or faster. Most bouncing contacts in a pile rest or creep and never do, and with the wide
// solver they then need no scalar copy (spinner: every shape has restitution 0.1). Impact
// propagation can speed an approach up after this point, so with it every bouncing contact counts.
static bool tbMayRebound(const tbStepContext* context, const tbContactConstraint* c)
{
	if (context->world->def.enableImpactPropagation)
	{
		return true;
	}
	float threshold = context->world->def.restitutionThreshold;
	for (int j = 0; j < c->pointCount; ++j)
	{
		if (c->points[j].relativeVelocity <= -threshold)
		{
			return true;
		}
	}
	return false;
}

// A contact that goes to a wide lane, prepared straight into the lane: the same numbers as
// tbPrepareConstraint (the same expressions in the same order, so bit for bit), without the scalar
// constraint in between and without what the lanes do not carry (surface extras) or what only
// contacts that may rebound need (the scalar copy, tbFinishLaneBatch). Soft step and Baumgarte
// only: NGS at one sub-step prepares differently (tbPrepareConstraintNGS) and takes
// tbPrepareConstraint.
// Returns whether some point approaches at the restitution threshold or faster (tbMayRebound's test,
// on the same approach speeds, without impact propagation).
bool tbPrepareWideLane(tbStepContext* context, tbContact* contact, tbContactKey key, tbWideContactConstraint* block,
					   int lane)
{
	const tbSolverMass* massA = context->masses + key.indexA;
	const tbSolverMass* massB = context->masses + key.indexB;
	float invMassA = massA->invMass, invIA = massA->invI;
	float invMassB = massB->invMass, invIB = massB->invI;
	bool dynamicPair = (key.flags & tb_keyDynamicA) != 0u && (key.flags & tb_keyDynamicB) != 0u;
	tbSoftness softness = dynamicPair ? context->contactSoftness : context->staticSoftness;
	bool softened = dynamicPair && context->contactSoftening;
	if (softened)
	{
		softness = tbSoftenedSoftness(context, invMassA, invMassB);
	}

	tbManifold* manifold = &contact->manifold;
	tbVec2 normal = manifold->normal;
	tbVec2 tangent = tbRightPerp(normal);
	int pointCount = manifold->pointCount;
	const tbSolverBody* sA = context->bodies + key.indexA;
	const tbSolverBody* sB = context->bodies + key.indexB;
	float warmScale = context->enableWarmStarting ? 1.0f : 0.0f;

	block->indexA[lane] = key.indexA;
	block->indexB[lane] = key.indexB;
	tbSetLaneW(&block->normalX, lane, normal.x);
	tbSetLaneW(&block->normalY, lane, normal.y);
	tbSetLaneW(&block->friction, lane, contact->friction);
	tbSetLaneW(&block->invMassA, lane, invMassA);
	tbSetLaneW(&block->invIA, lane, invIA);
	tbSetLaneW(&block->invMassB, lane, invMassB);
	tbSetLaneW(&block->invIB, lane, invIB);

	bool deep = false;
	float relativeVelocity[2] = {0.0f, 0.0f};
	tbVec2 anchorA[2] = {tbVec2_zero, tbVec2_zero}, anchorB[2] = {tbVec2_zero, tbVec2_zero};
	float normalImpulse[2] = {0.0f, 0.0f}, tangentImpulse[2] = {0.0f, 0.0f};
	for (int j = 0; j < 2; ++j)
	{
		tbWideContactPoint* wp = block->points + j;
		if (j >= pointCount)
		{
			tbSetLaneW(&wp->anchorAX, lane, 0.0f);
			tbSetLaneW(&wp->anchorAY, lane, 0.0f);
			tbSetLaneW(&wp->anchorBX, lane, 0.0f);
			tbSetLaneW(&wp->anchorBY, lane, 0.0f);
			tbSetLaneW(&wp->baseSeparation, lane, 0.0f);
			tbSetLaneW(&block->impulses[j].normalImpulse, lane, 0.0f);
			tbSetLaneW(&block->impulses[j].tangentImpulse, lane, 0.0f);
			tbSetLaneW(&block->impulses[j].totalNormalImpulse, lane, 0.0f);
			tbSetLaneW(&wp->normalMass, lane, 0.0f);
			tbSetLaneW(&wp->tangentMass, lane, 0.0f);
			continue;
		}
		const tbManifoldPoint* mp = manifold->points + j;
		tbVec2 rA = mp->anchorA;
		tbVec2 rB = mp->anchorB;
		float baseSeparation = mp->separation - tbDot(tbSub(rB, rA), normal);
		float kNormal = tbInverseMassAlong(invMassA, invIA, invMassB, invIB, rA, rB, normal);
		float kTangent = tbInverseMassAlong(invMassA, invIA, invMassB, invIB, rA, rB, tangent);
		tbSetLaneW(&wp->anchorAX, lane, rA.x);
		tbSetLaneW(&wp->anchorAY, lane, rA.y);
		tbSetLaneW(&wp->anchorBX, lane, rB.x);
		tbSetLaneW(&wp->anchorBY, lane, rB.y);
		tbSetLaneW(&wp->baseSeparation, lane, baseSeparation);
		tbSetLaneW(&block->impulses[j].normalImpulse, lane, warmScale * mp->normalImpulse);
		tbSetLaneW(&block->impulses[j].tangentImpulse, lane, warmScale * mp->tangentImpulse);
		tbSetLaneW(&block->impulses[j].totalNormalImpulse, lane, 0.0f);
		tbSetLaneW(&wp->normalMass, lane, kNormal > 0.0f ? 1.0f / kNormal : 0.0f);
		tbSetLaneW(&wp->tangentMass, lane, kTangent > 0.0f ? 1.0f / kTangent : 0.0f);
		tbVec2 vA = tbAdd(sA->linearVelocity, tbCrossSV(sA->angularVelocity, rA));
		tbVec2 vB = tbAdd(sB->linearVelocity, tbCrossSV(sB->angularVelocity, rB));
		relativeVelocity[j] = tbDot(tbSub(vB, vA), normal);
		deep = deep || tbStartSeparation(baseSeparation, rA, rB, normal) < -context->deepOverlap;
		anchorA[j] = rA;
		anchorB[j] = rB;
		normalImpulse[j] = warmScale * mp->normalImpulse;
		tangentImpulse[j] = warmScale * mp->tangentImpulse;
	}
	if (context->centralFriction && pointCount > 0)
	{
		tbFrictionRow row = tbCentralFrictionRow(invMassA, invIA, invMassB, invIB, tangent, pointCount, anchorA, anchorB,
												 normalImpulse, tangentImpulse);
		tbSetLaneW(&block->points[0].tangentMass, lane, row.mass);
		tbSetLaneW(&block->impulses[0].tangentImpulse, lane, row.impulse);
		tbSetLaneW(&block->points[1].tangentMass, lane, 0.0f);
		tbSetLaneW(&block->impulses[1].tangentImpulse, lane, 0.0f);
		tbSetLaneW(&block->frictionAnchorAX, lane, row.anchorA.x);
		tbSetLaneW(&block->frictionAnchorAY, lane, row.anchorA.y);
		tbSetLaneW(&block->frictionAnchorBX, lane, row.anchorB.x);
		tbSetLaneW(&block->frictionAnchorBY, lane, row.anchorB.y);
	}

	if (context->settleSteps > 0.0f && softened == false && tbMovesBoth(invMassA, invIA, invMassB, invIB) && deep == false)
	{
		softness = tbSettledSoftness(context, softness, contact->touchingSteps);
	}
	tbSetLaneW(&block->biasRate, lane, softness.biasRate);
	tbSetLaneW(&block->massScale, lane, softness.massScale);
	tbSetLaneW(&block->impulseScale, lane, softness.impulseScale);

	// The approach speed (tbPrepareConstraint's last lines): hit events and the next step read it.
	float an = tbGravityApproach(context, key.indexA, invMassA, key.indexB, invMassB, normal);
	float threshold = context->world->def.restitutionThreshold;
	bool rebound = false;
	for (int j = 0; j < pointCount; ++j)
	{
		tbManifoldPoint* mp = manifold->points + j;
		mp->normalVelocity = tbImpactVelocity(context, an, mp->separation, relativeVelocity[j]);
		rebound = rebound || mp->normalVelocity <= -threshold;
	}
	return rebound;
}

/// a > b ? ifTrue : 0 per lane
static inline tbFloatW tbKeepGreaterW(tbFloatW a, tbFloatW b, tbFloatW ifTrue)
{
	return tbSelectGreaterW(a, b, ifTrue, tbZeroW());
}

// The wide preparation reads its inputs as rows of four floats, one row per lane, straight out of
// the solver arrays and the public manifold, and transposes them (tbLoadTransposeRowsW: float k
// of lane l's row becomes lane l of out[k]). These are the columns of those rows; the asserts
// below hold the structures to them, since a field moved in any of them would otherwise be read
// silently as another.
enum
{
	tb_massInvMass = 0, ///< tbSolverMass: invMass, invI, gravityScale, padding
	tb_massInvI = 1,
	tb_massGravityScale = 2,
	tb_velocityX = 0, ///< tbSolverBody's first row: linearVelocity.x, linearVelocity.y, angularVelocity, padding
	tb_velocityY = 1,
	tb_velocityAngular = 2,
	tb_normalX = 0, ///< tbManifold from its normal: normal.x, normal.y, then two floats not used
	tb_normalY = 1,
	tb_anchorAX = 0, ///< tbManifoldPoint from anchorA: anchorA.x, anchorA.y, anchorB.x, anchorB.y
	tb_anchorAY = 1,
	tb_anchorBX = 2,
	tb_anchorBY = 3,
	tb_pointSeparation = 0, ///< tbManifoldPoint from separation: separation, normalImpulse, tangentImpulse,
	tb_pointNormalImpulse = 1, ///< then totalNormalImpulse (not used)
	tb_pointTangentImpulse = 2,
};

_Static_assert(offsetof(tbVec2, x) == 0 && offsetof(tbVec2, y) == 4 && sizeof(tbVec2) == 8,
			   "tbVec2 is two floats, x then y, as the wide preparation's rows read them");
_Static_assert(offsetof(tbSolverMass, invMass) == 4 * tb_massInvMass && offsetof(tbSolverMass, invI) == 4 * tb_massInvI &&
				   offsetof(tbSolverMass, gravityScale) == 4 * tb_massGravityScale && sizeof(tbSolverMass) == 16,
			   "tbSolverMass is one row of (invMass, invI, gravityScale, padding)");
_Static_assert(offsetof(tbSolverBody, linearVelocity) == 4 * tb_velocityX &&
				   offsetof(tbSolverBody, angularVelocity) == 4 * tb_velocityAngular && sizeof(tbSolverBody) >= 16,
			   "tbSolverBody starts with the row (v.x, v.y, ω, padding)");
_Static_assert(offsetof(tbManifold, normal) + 16 <= sizeof(tbManifold),
			   "a row of four floats from tbManifold::normal stays within the manifold");
_Static_assert(offsetof(tbManifoldPoint, anchorB) == offsetof(tbManifoldPoint, anchorA) + 4 * tb_anchorBX,
			   "tbManifoldPoint: anchorB right after anchorA, one row of four floats");
_Static_assert(offsetof(tbManifoldPoint, normalImpulse) ==
					   offsetof(tbManifoldPoint, separation) + 4 * tb_pointNormalImpulse &&
				   offsetof(tbManifoldPoint, tangentImpulse) ==
					   offsetof(tbManifoldPoint, separation) + 4 * tb_pointTangentImpulse &&
				   offsetof(tbManifoldPoint, separation) + 16 <= sizeof(tbManifoldPoint),
			   "tbManifoldPoint: separation, normalImpulse and tangentImpulse in a row within the point");

/// The point numbers of one manifold point j for the lanes of a batch (tbPrepareWideLanes).
typedef struct tbWidePointInput
{
	tbFloatW anchorAX, anchorAY, anchorBX, anchorBY;
	tbFloatW separation, normalImpulse, tangentImpulse;
} tbWidePointInput;

/// What tbPrepareWideLanes computes for point j, one float per lane (stored for the lane writes).
typedef struct tbWidePointOutput
{
	float anchorAX[TB_SIMD_WIDTH], anchorAY[TB_SIMD_WIDTH], anchorBX[TB_SIMD_WIDTH], anchorBY[TB_SIMD_WIDTH];
	float baseSeparation[TB_SIMD_WIDTH], normalImpulse[TB_SIMD_WIDTH], tangentImpulse[TB_SIMD_WIDTH];
	float normalMass[TB_SIMD_WIDTH], tangentMass[TB_SIMD_WIDTH], normalVelocity[TB_SIMD_WIDTH];
	int deep; ///< bit per lane: the point overlaps by more than the deep-overlap depth
	/// central friction's anchors (tb_anchorAX … tb_anchorBY), in the second point's output only
	float centralAnchor[4][TB_SIMD_WIDTH];
} tbWidePointOutput;

static inline void tbStoreLanesW(float* out, tbFloatW a)
{
	memcpy(out, &a, sizeof(a));
}

/// rᵀ·u cross terms and the inverse mass along u (tbInverseMassAlong, lane by lane, same order).
static inline tbFloatW tbInverseMassAlongW(tbFloatW mass[2][4], tbFloatW rAX, tbFloatW rAY, tbFloatW rBX,
										   tbFloatW rBY, tbFloatW uX, tbFloatW uY)
{
	tbFloatW rnA = tbSubW(tbMulW(rAX, uY), tbMulW(rAY, uX));
	tbFloatW rnB = tbSubW(tbMulW(rBX, uY), tbMulW(rBY, uX));
	tbFloatW k = tbAddW(tbAddW(mass[0][tb_massInvMass], mass[1][tb_massInvMass]),
						tbMulW(tbMulW(mass[0][tb_massInvI], rnA), rnA));
	return tbAddW(k, tbMulW(tbMulW(mass[1][tb_massInvI], rnB), rnB));
}

/// Point j of every lane: tbPrepareWideLane's per-point expressions, the branches as selects. The
/// lanes whose contact has no point j get zeros (their numbers are whatever the manifold holds there,
/// masked out). `an`: tbGravityApproach per lane; `mass` and `velocity`: each side's rows (the
/// columns above). With central friction the points' own friction rows are left to
/// tbPrepareCentralFrictionW, which writes both points' (the tangent masses were computed here and
/// overwritten there: work thrown away on every contact, which tumble-bench-prepare showed).
static void tbPreparePointW(const tbStepContext* context, const tbWidePointInput* in, tbFloatW present,
							tbFloatW mass[2][4], tbFloatW velocity[2][4], tbFloatW nX, tbFloatW nY,
							tbFloatW an, tbWidePointOutput* out)
{
	tbFloatW zero = tbZeroW(), one = tbSplatW(1.0f), minusOne = tbSplatW(-1.0f);
	tbFloatW dX = tbSubW(in->anchorBX, in->anchorAX), dY = tbSubW(in->anchorBY, in->anchorAY);
	tbFloatW dn = tbAddW(tbMulW(dX, nX), tbMulW(dY, nY));
	tbFloatW baseSeparation = tbSubW(in->separation, dn);
	tbFloatW tX = nY, tY = tbMulW(minusOne, nX); // tbRightPerp: (n.y, −n.x)
	tbFloatW kNormal = tbInverseMassAlongW(mass, in->anchorAX, in->anchorAY, in->anchorBX, in->anchorBY, nX, nY);
	tbFloatW normalMass = tbKeepGreaterW(kNormal, zero, tbDivW(one, kNormal));

	// v + ω × r on each side (tbCrossSV: (−ω·r.y, ω·r.x)), then the normal part of vB − vA
	const tbFloatW* a = velocity[0];
	const tbFloatW* b = velocity[1];
	tbFloatW vAX = tbAddW(a[tb_velocityX], tbMulW(tbMulW(minusOne, a[tb_velocityAngular]), in->anchorAY));
	tbFloatW vAY = tbAddW(a[tb_velocityY], tbMulW(a[tb_velocityAngular], in->anchorAX));
	tbFloatW vBX = tbAddW(b[tb_velocityX], tbMulW(tbMulW(minusOne, b[tb_velocityAngular]), in->anchorBY));
	tbFloatW vBY = tbAddW(b[tb_velocityY], tbMulW(b[tb_velocityAngular], in->anchorBX));
	tbFloatW v = tbAddW(tbMulW(tbSubW(vBX, vAX), nX), tbMulW(tbSubW(vBY, vAY), nY));

	// tbImpactVelocity: sep > 0, v < 0 and aₙ < 0 give max(−sqrt(v² − 2·aₙ·sep), min(v, −2·vmax))
	tbFloatW fastest = tbMinW(v, tbSplatW(-2.0f * context->world->def.maximumLinearSpeed));
	tbFloatW radicand = tbSubW(tbMulW(v, v), tbMulW(tbMulW(tbSplatW(2.0f), an), in->separation));
	tbFloatW impact = tbMaxW(tbMulW(minusOne, tbSqrtW(radicand)), fastest);
	tbFloatW approaching = tbSelectGreaterW(zero, an, tbSelectGreaterW(zero, v, impact, v), v);
	tbFloatW normalVelocity = tbSelectGreaterW(in->separation, zero, approaching, v);

	tbFloatW startSeparation = tbAddW(baseSeparation, dn); // tbStartSeparation
	out->deep = tbGreaterMaskW(tbSplatW(-context->deepOverlap), startSeparation) & tbGreaterMaskW(present, zero);

	float warmScale = context->enableWarmStarting ? 1.0f : 0.0f;
	tbStoreLanesW(out->anchorAX, tbKeepGreaterW(present, zero, in->anchorAX));
	tbStoreLanesW(out->anchorAY, tbKeepGreaterW(present, zero, in->anchorAY));
	tbStoreLanesW(out->anchorBX, tbKeepGreaterW(present, zero, in->anchorBX));
	tbStoreLanesW(out->anchorBY, tbKeepGreaterW(present, zero, in->anchorBY));
	tbStoreLanesW(out->baseSeparation, tbKeepGreaterW(present, zero, baseSeparation));
	tbStoreLanesW(out->normalImpulse, tbKeepGreaterW(present, zero, tbMulW(tbSplatW(warmScale), in->normalImpulse)));
	tbStoreLanesW(out->normalMass, tbKeepGreaterW(present, zero, normalMass));
	tbStoreLanesW(out->normalVelocity, normalVelocity);
	if (context->centralFriction)
	{
		return; // one friction row for the contact: tbPrepareCentralFrictionW writes both points'
	}
	tbFloatW kTangent = tbInverseMassAlongW(mass, in->anchorAX, in->anchorAY, in->anchorBX, in->anchorBY, tX, tY);
	tbFloatW tangentMass = tbKeepGreaterW(kTangent, zero, tbDivW(one, kTangent));
	tbStoreLanesW(out->tangentImpulse, tbKeepGreaterW(present, zero, tbMulW(tbSplatW(warmScale), in->tangentImpulse)));
	tbStoreLanesW(out->tangentMass, tbKeepGreaterW(present, zero, tangentMass));
}

/// Central friction for every lane of a batch (tbCentralFrictionRow, lane by lane, the same
/// expressions): point 0's tangent mass and impulse become the central row's, point 1's zeros, and
/// the row's anchors go to centralAnchor (tb_anchorAX … tb_anchorBY). `separationAndImpulses[j]`:
/// point j's row as read from the manifolds (tb_pointSeparation …).
static void tbPrepareCentralFrictionW(const tbStepContext* context, tbFloatW mass[2][4], tbFloatW anchors[2][4],
									  tbFloatW separationAndImpulses[2][4], tbFloatW pointCount, tbFloatW nX,
									  tbFloatW nY, tbWidePointOutput points[2])
{
	tbFloatW zero = tbZeroW(), one = tbSplatW(1.0f);
	tbFloatW warmScale = tbSplatW(context->enableWarmStarting ? 1.0f : 0.0f);
	const tbFloatW* p0 = separationAndImpulses[0];
	const tbFloatW* p1 = separationAndImpulses[1];
	tbFloatW n0 = tbMulW(warmScale, p0[tb_pointNormalImpulse]), n1 = tbMulW(warmScale, p1[tb_pointNormalImpulse]);
	tbFloatW t0 = tbMulW(warmScale, p0[tb_pointTangentImpulse]), t1 = tbMulW(warmScale, p1[tb_pointTangentImpulse]);
	tbFloatW total = tbAddW(n0, n1);
	tbFloatW w0 = tbSelectGreaterW(total, zero, tbDivW(n0, total), tbSplatW(0.5f)); // tbPressureWeight
	tbFloatW w1 = tbSubW(one, w0);
	tbFloatW hasSecondPoint = tbSubW(pointCount, one); // > 0 in the lanes whose contact has two points
	tbFloatW row[4];
	for (int k = tb_anchorAX; k <= tb_anchorBY; ++k)
	{
		tbFloatW blend = tbAddW(tbMulW(w0, anchors[0][k]), tbMulW(w1, anchors[1][k]));
		row[k] = tbSelectGreaterW(hasSecondPoint, zero, blend, anchors[0][k]);
		tbStoreLanesW(points[1].centralAnchor[k], row[k]);
	}
	tbFloatW impulse = tbSelectGreaterW(hasSecondPoint, zero, tbAddW(t0, t1), t0);
	tbFloatW tX = nY, tY = tbMulW(tbSplatW(-1.0f), nX);
	tbFloatW k = tbInverseMassAlongW(mass, row[tb_anchorAX], row[tb_anchorAY], row[tb_anchorBX], row[tb_anchorBY], tX, tY);
	tbStoreLanesW(points[0].tangentMass, tbKeepGreaterW(k, zero, tbDivW(one, k)));
	tbStoreLanesW(points[0].tangentImpulse, impulse);
	tbStoreLanesW(points[1].tangentMass, zero);
	tbStoreLanesW(points[1].tangentImpulse, zero);
}

/// A batch's inputs, transposed: one wide float per column of the rows above.
typedef struct tbWideBatchRows
{
	tbFloatW mass[2][4];				  ///< side A, side B: tbSolverMass (tb_massInvMass …)
	tbFloatW velocity[2][4];			  ///< side A, side B: tbSolverBody's first row (tb_velocityX …)
	tbFloatW normalRow[4];				  ///< the manifold's normal (tb_normalX, tb_normalY)
	tbFloatW anchors[2][4];				  ///< point j's anchors (tb_anchorAX …)
	tbFloatW separationAndImpulses[2][4]; ///< point j's separation and impulses (tb_pointSeparation …)
	tbFloatW pointCount;				  ///< the manifold's point count, as a float
} tbWideBatchRows;

static void tbLoadBatchRows(const tbStepContext* context, const tbLaneBatch* batch, tbWideBatchRows* in)
{
	const void* rows[TB_SIMD_WIDTH];
	for (int side = 0; side < 2; ++side)
	{
		for (int l = 0; l < TB_SIMD_WIDTH; ++l)
		{
			rows[l] = context->masses + (side == 0 ? batch->keys[l].indexA : batch->keys[l].indexB);
		}
		tbLoadTransposeRowsW(rows, in->mass[side]);
	}
	for (int side = 0; side < 2; ++side)
	{
		for (int l = 0; l < TB_SIMD_WIDTH; ++l)
		{
			rows[l] = context->bodies + (side == 0 ? batch->keys[l].indexA : batch->keys[l].indexB);
		}
		tbLoadTransposeRowsW(rows, in->velocity[side]);
	}
	for (int l = 0; l < TB_SIMD_WIDTH; ++l)
	{
		rows[l] = &batch->contacts[l]->manifold.normal;
	}
	tbLoadTransposeRowsW(rows, in->normalRow);
	for (int j = 0; j < 2; ++j)
	{
		for (int l = 0; l < TB_SIMD_WIDTH; ++l)
		{
			rows[l] = &batch->contacts[l]->manifold.points[j].anchorA;
		}
		tbLoadTransposeRowsW(rows, in->anchors[j]);
		for (int l = 0; l < TB_SIMD_WIDTH; ++l)
		{
			rows[l] = &batch->contacts[l]->manifold.points[j].separation;
		}
		tbLoadTransposeRowsW(rows, in->separationAndImpulses[j]);
	}
	float pointCounts[TB_SIMD_WIDTH];
	for (int l = 0; l < TB_SIMD_WIDTH; ++l)
	{
		pointCounts[l] = (float)batch->contacts[l]->manifold.pointCount;
	}
	memcpy(&in->pointCount, pointCounts, sizeof(in->pointCount));
}

/// tbGravityApproach per lane: gB − gA along the normal, each side's g·gravityScale when it has mass.
static tbFloatW tbGravityApproachW(const tbStepContext* context, const tbWideBatchRows* in)
{
	tbFloatW zero = tbZeroW();
	tbVec2 gravity = context->world->def.gravity;
	tbFloatW gX = tbSplatW(gravity.x), gY = tbSplatW(gravity.y);
	const tbFloatW* a = in->mass[0];
	const tbFloatW* b = in->mass[1];
	tbFloatW gAX = tbKeepGreaterW(a[tb_massInvMass], zero, tbMulW(a[tb_massGravityScale], gX));
	tbFloatW gAY = tbKeepGreaterW(a[tb_massInvMass], zero, tbMulW(a[tb_massGravityScale], gY));
	tbFloatW gBX = tbKeepGreaterW(b[tb_massInvMass], zero, tbMulW(b[tb_massGravityScale], gX));
	tbFloatW gBY = tbKeepGreaterW(b[tb_massInvMass], zero, tbMulW(b[tb_massGravityScale], gY));
	return tbAddW(tbMulW(tbSubW(gBX, gAX), in->normalRow[tb_normalX]),
				  tbMulW(tbSubW(gBY, gAY), in->normalRow[tb_normalY]));
}

/// What the lanes of a batch are written from: the points computed in wide floats, and lane-by-lane
/// copies of the inverse masses and the normal.
typedef struct tbWideBatchResult
{
	tbWidePointOutput points[2];
	float invMass[2][2][TB_SIMD_WIDTH]; ///< side, then its invMass and invI
	float normal[2][TB_SIMD_WIDTH];		///< x, y
	int deep;							///< bit per lane: some point overlaps deeply
} tbWideBatchResult;

/// Writes lane l of a batch into its block (every field but the relaxing bias, as tbPackWideLane)
/// and the approach speeds into its manifold; returns 1 << l when some point approaches at the
/// restitution threshold or faster, else 0.
static int tbWriteBatchLane(const tbStepContext* context, const tbLaneBatch* batch, const tbWideBatchResult* r, int l)
{
	tbContact* contact = batch->contacts[l];
	tbContactKey key = batch->keys[l];
	tbWideContactConstraint* block = context->wideConstraints + batch->locations[l] / TB_SIMD_WIDTH;
	int lane = batch->locations[l] % TB_SIMD_WIDTH;
	int count = contact->manifold.pointCount;
	float threshold = context->world->def.restitutionThreshold;
	int rebound = 0;
	block->indexA[lane] = key.indexA;
	block->indexB[lane] = key.indexB;
	tbSetLaneW(&block->normalX, lane, r->normal[0][l]);
	tbSetLaneW(&block->normalY, lane, r->normal[1][l]);
	tbSetLaneW(&block->friction, lane, contact->friction);
	tbSetLaneW(&block->invMassA, lane, r->invMass[0][0][l]);
	tbSetLaneW(&block->invIA, lane, r->invMass[0][1][l]);
	tbSetLaneW(&block->invMassB, lane, r->invMass[1][0][l]);
	tbSetLaneW(&block->invIB, lane, r->invMass[1][1][l]);
	for (int j = 0; j < 2; ++j)
	{
		const tbWidePointOutput* p = r->points + j;
		tbWideContactPoint* wp = block->points + j;
		tbSetLaneW(&wp->anchorAX, lane, p->anchorAX[l]);
		tbSetLaneW(&wp->anchorAY, lane, p->anchorAY[l]);
		tbSetLaneW(&wp->anchorBX, lane, p->anchorBX[l]);
		tbSetLaneW(&wp->anchorBY, lane, p->anchorBY[l]);
		tbSetLaneW(&wp->baseSeparation, lane, p->baseSeparation[l]);
		tbSetLaneW(&block->impulses[j].normalImpulse, lane, p->normalImpulse[l]);
		tbSetLaneW(&block->impulses[j].tangentImpulse, lane, p->tangentImpulse[l]);
		tbSetLaneW(&block->impulses[j].totalNormalImpulse, lane, 0.0f);
		tbSetLaneW(&wp->normalMass, lane, p->normalMass[l]);
		tbSetLaneW(&wp->tangentMass, lane, p->tangentMass[l]);
		if (j < count)
		{
			contact->manifold.points[j].normalVelocity = p->normalVelocity[l];
			rebound |= p->normalVelocity[l] <= -threshold ? 1 << l : 0;
		}
	}

	if (context->centralFriction)
	{
		const float(*anchor)[TB_SIMD_WIDTH] = r->points[1].centralAnchor;
		tbSetLaneW(&block->frictionAnchorAX, lane, anchor[tb_anchorAX][l]);
		tbSetLaneW(&block->frictionAnchorAY, lane, anchor[tb_anchorAY][l]);
		tbSetLaneW(&block->frictionAnchorBX, lane, anchor[tb_anchorBX][l]);
		tbSetLaneW(&block->frictionAnchorBY, lane, anchor[tb_anchorBY][l]);
	}

	bool dynamicPair = (key.flags & tb_keyDynamicA) != 0u && (key.flags & tb_keyDynamicB) != 0u;
	tbSoftness softness = dynamicPair ? context->contactSoftness : context->staticSoftness;
	bool softened = dynamicPair && context->contactSoftening;
	if (softened)
	{
		softness = tbSoftenedSoftness(context, r->invMass[0][0][l], r->invMass[1][0][l]);
	}
	bool movesBoth = tbMovesBoth(r->invMass[0][0][l], r->invMass[0][1][l], r->invMass[1][0][l], r->invMass[1][1][l]);
	if (context->settleSteps > 0.0f && softened == false && movesBoth && (r->deep & (1 << l)) == 0)
	{
		softness = tbSettledSoftness(context, softness, contact->touchingSteps);
	}
	tbSetLaneW(&block->biasRate, lane, softness.biasRate);
	tbSetLaneW(&block->massScale, lane, softness.massScale);
	tbSetLaneW(&block->impulseScale, lane, softness.impulseScale);
	return rebound;
}

/// tbPrepareWideLane for a full batch of contacts, one per lane of wide floats: the same expressions
/// in the same order, so bit for bit the same lanes; the arithmetic is done TB_SIMD_WIDTH contacts
/// at a time and only the stores into the blocks stay lane by lane (the contacts of a batch are
/// consecutive in id order, so their lanes are spread over the colours' blocks). Rejected: preparing
/// block by block instead, each block's contacts read where they lie and the block written a row at
/// a time (Box2D v3's order, whose contacts are stored by colour): the same bits and fewer
/// instructions, but slower steps on the pyramids, the scattered reads of the contacts costing more
/// than the row stores save. Also rejected, both giving the same bits and neither a faster step on
/// the pyramids: reading in id order but holding each colour's block until its lanes are all met,
/// then writing it a row at a time (nearly every block went whole); and, when the last step's
/// colouring and blocks are kept, refreshing only what changes in a recycled contact's lane (its
/// separations, impulses, friction row and softness). The preparation waits on memory, the contacts
/// read and the blocks written, more than on its arithmetic or its stores. The inputs are
/// read as rows of four floats and transposed (tbLoadBatchRows): the two bodies' masses and
/// velocities, the manifold's normal, each point's anchors and each point's separation and
/// impulses. Returns a bit per lane, set where a point approaches at the restitution threshold or
/// faster.
int tbPrepareWideLanes(tbStepContext* context, const tbLaneBatch* batch)
{
	tbWideBatchRows in;
	tbLoadBatchRows(context, batch, &in);
	tbFloatW an = tbGravityApproachW(context, &in);
	tbFloatW nX = in.normalRow[tb_normalX], nY = in.normalRow[tb_normalY];
	tbWideBatchResult r;
	for (int j = 0; j < 2; ++j)
	{
		const tbFloatW* anchor = in.anchors[j];
		const tbFloatW* values = in.separationAndImpulses[j];
		tbWidePointInput point = {anchor[tb_anchorAX],		 anchor[tb_anchorAY],		anchor[tb_anchorBX],
								  anchor[tb_anchorBY],		 values[tb_pointSeparation], values[tb_pointNormalImpulse],
								  values[tb_pointTangentImpulse]};
		tbFloatW present = tbSubW(in.pointCount, tbSplatW((float)j)); // > 0 where the contact has point j
		tbPreparePointW(context, &point, present, in.mass, in.velocity, nX, nY, an, r.points + j);
	}
	if (context->centralFriction)
	{
		tbPrepareCentralFrictionW(context, in.mass, in.anchors, in.separationAndImpulses, in.pointCount, nX, nY,
								  r.points);
	}
	for (int side = 0; side < 2; ++side)
	{
		tbStoreLanesW(r.invMass[side][0], in.mass[side][tb_massInvMass]);
		tbStoreLanesW(r.invMass[side][1], in.mass[side][tb_massInvI]);
	}
	tbStoreLanesW(r.normal[0], nX);
	tbStoreLanesW(r.normal[1], nY);
	r.deep = r.points[0].deep | r.points[1].deep;
	int rebound = 0;
	for (int l = 0; l < TB_SIMD_WIDTH; ++l)
	{
		rebound |= tbWriteBatchLane(context, batch, &r, l);
	}
	return rebound;
}

/// The rolling row of a coloured contact's lane (tbWideRolling), as tbPrepareConstraint prepares
/// the scalar one.
static void tbPrepareRollingLane(tbStepContext* context, const tbContact* contact, tbContactKey key, int location)
{
	tbWideRolling* rolling = context->wideRolling + location / TB_SIMD_WIDTH;
	int lane = location % TB_SIMD_WIDTH;
	float kRolling = context->masses[key.indexA].invI + context->masses[key.indexB].invI;
	float warmScale = context->enableWarmStarting ? 1.0f : 0.0f;
	tbSetLaneW(&rolling->resistance, lane, contact->rollingResistance);
	tbSetLaneW(&rolling->mass, lane, kRolling > 0.0f ? 1.0f / kRolling : 0.0f);
	tbSetLaneW(&rolling->impulse, lane, warmScale * contact->manifold.rollingImpulse);
}

typedef struct tbPrepareTaskContext
{
	tbStepContext* context;
	atomic_int restitutionCount;
} tbPrepareTaskContext;

/// The contact at place i (contact-id order) will not rebound: solved and stored from its lane like
/// any other, with no scalar copy.
static void tbDropBounce(tbStepContext* context, int i, int slot, tbContactKey* key)
{
	key->flags &= ~(uint32_t)tb_keyBounces;
	context->keys[slot].flags = key->flags;
	context->keysById[i].flags = key->flags;
}

/// A coloured contact with restitution whose lane is prepared and which may rebound (a point
/// approaches at the restitution threshold or faster): restitution needs its scalar constraint,
/// prepared here. Its lane already holds the same numbers (tbPrepareWideLane's expressions are the
/// scalar ones), so it is not written again. Returns 1 if it still bounces.
static int tbPrepareBounce(tbStepContext* context, tbContact* contact, int i, int slot)
{
	tbContactKey key = context->keysById[i];
	tbContactConstraint local;
	tbPrepareConstraint(context, contact, key, &local);
	if (tbMayRebound(context, &local) == false)
	{
		tbDropBounce(context, i, slot, &key);
		return 0;
	}
	context->constraints[slot] = local;
	return 1;
}

/// After a batch's lanes are prepared: its contacts with restitution either drop the bounce (no
/// point approaches fast enough: most of the spinner's, where every shape has restitution 0.1 and
/// most contacts rest or creep) or get their scalar copy. `rebound`: a bit per lane
/// (tbPrepareWideLanes). Returns how many still bounce.
static int tbFinishLaneBatch(tbStepContext* context, const tbLaneBatch* batch, int rebound)
{
	int bounceCount = 0;
	for (int l = 0; l < batch->count; ++l)
	{
		tbContactKey key = batch->keys[l];
		if ((key.flags & tb_keyBounces) == 0u)
		{
			continue;
		}
		if ((rebound & (1 << l)) == 0)
		{
			tbDropBounce(context, batch->indices[l], batch->slots[l], &key);
			continue;
		}
		bounceCount += tbPrepareBounce(context, batch->contacts[l], batch->indices[l], batch->slots[l]);
	}
	return bounceCount;
}

// With the wide solver the colours are known (constraint_graph.c), and a coloured contact is
// prepared on the stack and written straight into its lane: the scalar constraint is written only
// for the overflow and for bouncing contacts (restitution and impact propagation read it).
static void tbPrepareContactsTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	tbPrepareTaskContext* task = taskContext;
	tbStepContext* context = task->context;
	tbWorld* world = context->world;
	const int* contactIds = world->cache.solverContactsById;
	const int* slots = world->cache.solverSlots;
	const int* wideLocation = context->wideLocation;
	bool laneFastPath = (world->def.solver == tb_solverNGS && context->subStepCount == 1) == false;
	bool impactPropagation = world->def.enableImpactPropagation;
	int restitutionCount = 0;
	tbLaneBatch batch;
	batch.count = 0;
	uint32_t bounceInBatch = 0u; // the batch's keys' flags together
	for (int i = start; i < end; ++i)
	{
		int slot = slots[i];
		tbContact* contact = world->contacts + contactIds[i];
		if (i + TB_PREFETCH_AHEAD < end)
		{
			// what is read here: up to the settle clock after the manifold
			tbPrefetch(world->contacts + contactIds[i + TB_PREFETCH_AHEAD], (int)offsetof(tbContact, base));
			// and the block of the lane ahead, whichever lane it is: each lane writes a float in every
			// line of its block, and a block's TB_SIMD_WIDTH lanes are written some dozens of
			// contacts apart (one per colour in turn), by which time its lines may have left L1
			// (prefetching only for the first lane left the later lanes' writes missing the cache)
			int ahead = wideLocation != NULL ? context->locationById[i + TB_PREFETCH_AHEAD] : -1;
			if (ahead >= 0)
			{
				tbPrefetch(context->wideConstraints + ahead / TB_SIMD_WIDTH, (int)sizeof(tbWideContactConstraint));
			}
		}
		tbContactConstraint* c = context->constraints + slot;
		if (wideLocation == NULL)
		{
			tbPrepareConstraint(context, contact, tbMakeContactKey(context, contact), c);
			restitutionCount += c->restitution != 0.0f ? 1 : 0;
			continue;
		}
		// Key and lane by contact-id order: both stream (by slot they were scattered loads).
		tbContactKey key = context->keysById[i];
		int location = context->locationById[i];
		if (location >= 0 && (key.flags & tb_keyRolling) != 0u)
		{
			tbPrepareRollingLane(context, contact, key, location);
		}
		bool bounces = (key.flags & tb_keyBounces) != 0u;
		if (location >= 0 && laneFastPath && (bounces == false || impactPropagation == false))
		{
			// Gathered until a batch is full, then prepared together (tbPrepareWideLanes); those
			// with restitution then drop the bounce or get their scalar copy (tbFinishLaneBatch).
			batch.contacts[batch.count] = contact;
			batch.keys[batch.count] = key;
			batch.locations[batch.count] = location;
			batch.slots[batch.count] = slot;
			batch.indices[batch.count] = i;
			bounceInBatch |= key.flags;
			if (++batch.count == TB_SIMD_WIDTH)
			{
				int rebound = tbPrepareWideLanes(context, &batch);
				if ((bounceInBatch & tb_keyBounces) != 0u) // most batches have none: no call
				{
					restitutionCount += tbFinishLaneBatch(context, &batch, rebound);
				}
				batch.count = 0;
				bounceInBatch = 0u;
			}
			continue;
		}
		// The overflow, the scalar-only prepare (NGS at one sub-step), and with impact propagation the
		// bouncing contacts (it reads every bouncing contact's scalar copy).
		tbContactConstraint local;
		tbPrepareConstraint(context, contact, key, &local);
		if ((key.flags & tb_keyBounces) != 0u && tbMayRebound(context, &local) == false)
		{
			tbDropBounce(context, i, slot, &key); // restitution will not touch it
		}
		if (location >= 0)
		{
			tbPackWideLane(context->wideConstraints + location / TB_SIMD_WIDTH, location % TB_SIMD_WIDTH, &local);
		}
		if (location < 0 || (key.flags & tb_keyBounces) != 0u)
		{
			*c = local;
		}
		restitutionCount += (key.flags & tb_keyBounces) != 0u ? 1 : 0;
	}
	int rebound = 0;
	for (int l = 0; l < batch.count; ++l)
	{
		bool approaching = tbPrepareWideLane(context, batch.contacts[l], batch.keys[l],
											 context->wideConstraints + batch.locations[l] / TB_SIMD_WIDTH,
											 batch.locations[l] % TB_SIMD_WIDTH);
		rebound |= approaching ? 1 << l : 0;
	}
	restitutionCount += tbFinishLaneBatch(context, &batch, rebound);
	atomic_fetch_add_explicit(&task->restitutionCount, restitutionCount, memory_order_relaxed);
}

// Each contact writes its own constraint (and its manifold's approach speeds): ranges of contacts
// may go to workers; only the count of bouncing ones is shared (an integer sum, in any order).
void tbPrepareContacts(tbStepContext* context)
{
	tbPrepareTaskContext task;
	task.context = context;
	atomic_init(&task.restitutionCount, 0);
	tbParallelFor(&context->world->def, tbPrepareContactsTask, context->constraintCount, TB_CONTACTS_PER_TASK, &task);
	context->restitutionCount = atomic_load_explicit(&task.restitutionCount, memory_order_relaxed);
}

// Whether constraint i bounces. With the wide solver only bouncing constraints have a scalar copy,
// so the key says it without reading the constraint.
static inline bool tbConstraintBounces(const tbStepContext* context, int i)
{
	if (context->keys != NULL)
	{
		return (context->keys[i].flags & tb_keyBounces) != 0u;
	}
	return context->constraints[i].restitution != 0.0f;
}

static void tbWarmStartConstraint(tbSolverBody* bodies, tbContactConstraint* c, bool centralFriction)
{
	tbSolverBody* sA = bodies + c->indexA;
	tbSolverBody* sB = bodies + c->indexB;
	tbVec2 normal = c->normal;
	tbVec2 tangent = tbRightPerp(normal);
	if (centralFriction)
	{
		// normal impulses at the points, the friction impulse at the centre of pressure
		for (int j = 0; j < c->pointCount; ++j)
		{
			tbContactConstraintPoint* cp = c->points + j;
			cp->totalNormalImpulse += cp->normalImpulse; // the warm start applies it again
			tbApplyContactImpulse(sA, sB, c, cp->anchorA, cp->anchorB, tbMulSV(cp->normalImpulse, normal));
		}
		if (c->pointCount > 0)
		{
			tbApplyContactImpulse(sA, sB, c, c->frictionAnchorA, c->frictionAnchorB,
								  tbMulSV(c->points[0].tangentImpulse, tangent));
		}
	}
	else
	{
		for (int j = 0; j < c->pointCount; ++j)
		{
			tbContactConstraintPoint* cp = c->points + j;
			cp->totalNormalImpulse += cp->normalImpulse; // the warm start applies it again
			tbVec2 P = tbAdd(tbMulSV(cp->normalImpulse, normal), tbMulSV(cp->tangentImpulse, tangent));
			tbApplyContactImpulse(sA, sB, c, cp->anchorA, cp->anchorB, P);
		}
	}
	sA->angularVelocity -= c->invIA * c->rollingImpulse;
	sB->angularVelocity += c->invIB * c->rollingImpulse;
}

static void tbZeroImpulses(tbContactConstraint* c)
{
	c->rollingImpulse = 0.0f;
	for (int j = 0; j < c->pointCount; ++j)
	{
		c->points[j].normalImpulse = 0.0f;
		c->points[j].tangentImpulse = 0.0f;
	}
}

// Without warm starting each sub-step starts from zero accumulated impulse instead. With the wide
// solver, the coloured constraints first, then the overflow (the solve order, constraint_graph.c).
void tbWarmStartOverflow(tbStepContext* context)
{
	for (int i = 0; i < context->overflowCount; ++i)
	{
		tbContactConstraint* c = context->constraints + context->overflowConstraints[i];
		if (context->enableWarmStarting)
		{
			tbWarmStartConstraint(context->bodies, c, context->centralFriction);
		}
		else
		{
			tbZeroImpulses(c);
		}
	}
}

void tbWarmStartContacts(tbStepContext* context)
{
	if (context->wideConstraints != NULL)
	{
		tbWarmStartContactsWide(context);
		tbWarmStartOverflow(context);
		return;
	}
	for (int i = 0; i < context->constraintCount; ++i)
	{
		tbContactConstraint* c = context->constraints + i;
		if (context->enableWarmStarting)
		{
			tbWarmStartConstraint(context->bodies, c, context->centralFriction);
		}
		else
		{
			tbZeroImpulses(c);
		}
	}
}

// Relative velocity of the anchors: vB + ωB × rB − vA − ωA × rA.
static inline tbVec2 tbRelativeVelocity(const tbSolverBody* sA, const tbSolverBody* sB, tbVec2 rA, tbVec2 rB)
{
	tbVec2 vA = tbAdd(sA->linearVelocity, tbCrossSV(sA->angularVelocity, rA));
	tbVec2 vB = tbAdd(sB->linearVelocity, tbCrossSV(sB->angularVelocity, rB));
	return tbSub(vB, vA);
}

// Body state is loaded into locals once per constraint and stored once at the end: the two
// bodies never alias, and keeping them in registers avoids a store-to-load round trip per impulse.
static inline void tbSolveConstraint(tbContactConstraint* c, tbSolverBody* sA, tbSolverBody* sB,
									 const tbStepContext* context, tbBiasPolicy policy)
{
	tbVec2 vA = sA->linearVelocity;
	float wA = sA->angularVelocity;
	tbVec2 vB = sB->linearVelocity;
	float wB = sB->angularVelocity;
	tbRot qA = sA->deltaRotation;
	tbRot qB = sB->deltaRotation;
	tbVec2 dp = tbSub(sB->deltaPosition, sA->deltaPosition);

	float mA = c->invMassA, iA = c->invIA;
	float mB = c->invMassB, iB = c->invIB;
	tbVec2 normal = c->normal;
	tbVec2 tangent = tbRightPerp(normal);
	float inv_h = context->inv_h;
	int pointCount = c->pointCount;

	// Normal first, then friction against the fresh normal impulse: the friction bound is then
	// exact for this pass and the last thing a pass does is stop sliding (slopes do not creep).
	for (int j = 0; j < pointCount; ++j)
	{
		tbContactConstraintPoint* cp = c->points + j;
		tbVec2 rA = cp->anchorA;
		tbVec2 rB = cp->anchorB;

		// Linearised current separation from the body deltas.
		tbVec2 prA = tbRotateVector(qA, rA);
		tbVec2 prB = tbRotateVector(qB, rB);
		float s = cp->baseSeparation + tbDot(tbAdd(dp, tbSub(prB, prA)), normal);

		// Speculative (s > 0): close the gap, no more. Overlap: the policy's push-out. Written as
		// selects, not branches: whether a point is speculative is data, and a mispredicted branch
		// per point costs more than computing both (the policy is a constant in each caller's loop).
		bool speculative = s > 0.0f;
		float overlapBias = 0.0f;
		float overlapMassScale = 1.0f;
		float overlapImpulseScale = 0.0f;
		if (policy == tb_biasSoft)
		{
			overlapBias = tbMaxFloat(c->softness.biasRate * s, -context->contactSpeed);
			overlapMassScale = c->softness.massScale;
			overlapImpulseScale = c->softness.impulseScale;
		}
		else if (policy == tb_biasBaumgarte)
		{
			// Bounded like every push: an overlap no contact can have (a pre-solve callback's) must
			// not launch the body past the speed limit.
			overlapBias = TB_BAUMGARTE * inv_h * tbMinFloat(0.0f, s + TB_LINEAR_SLOP);
			overlapBias = tbMaxFloat(overlapBias, -context->maxLinearSpeed);
		}
		float bias = speculative ? s * inv_h : overlapBias;
		float massScale = speculative ? 1.0f : overlapMassScale;
		float impulseScale = speculative ? 0.0f : overlapImpulseScale;

		tbVec2 dv = tbSub(tbAdd(vB, tbCrossSV(wB, rB)), tbAdd(vA, tbCrossSV(wA, rA)));
		float vn = tbDot(dv, normal);
		float impulse = -cp->normalMass * massScale * (vn + bias) - impulseScale * cp->normalImpulse;
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

	if (c->rollingResistance > 0.0f)
	{
		// Rolling resistance: an angular impulse against the relative spin, bounded by a torque of
		// rollingResistance × the normal force (Box2D v3.2's model): a ball of radius r rolling
		// without slipping on level ground then decelerates at c·g/(1 + I/(m·r²)).
		float totalNormalImpulse = 0.0f;
		for (int j = 0; j < pointCount; ++j)
		{
			totalNormalImpulse += c->points[j].normalImpulse;
		}
		float maxImpulse = c->rollingResistance * totalNormalImpulse;
		float impulse = -c->rollingMass * (wB - wA);
		float newImpulse = tbClampFloat(c->rollingImpulse + impulse, -maxImpulse, maxImpulse);
		impulse = newImpulse - c->rollingImpulse;
		c->rollingImpulse = newImpulse;
		wA -= iA * impulse;
		wB += iB * impulse;
	}

	// Friction drives the relative tangential speed to the surfaces' tangent speed (0 but on belts):
	// a row per point, or one row at the centre of pressure bounded by the points' normal impulses
	// together (central friction, its mass and impulse in point 0).
	float friction = c->friction;
	bool central = context->centralFriction;
	int rowCount = central ? tbMinInt(pointCount, 1) : pointCount;
	for (int j = 0; j < rowCount; ++j)
	{
		tbContactConstraintPoint* cp = c->points + j;
		tbVec2 rA = central ? c->frictionAnchorA : cp->anchorA;
		tbVec2 rB = central ? c->frictionAnchorB : cp->anchorB;
		float normalImpulse = cp->normalImpulse;
		if (central && pointCount > 1)
		{
			normalImpulse = c->points[0].normalImpulse + c->points[1].normalImpulse;
		}
		tbVec2 dv = tbSub(tbAdd(vB, tbCrossSV(wB, rB)), tbAdd(vA, tbCrossSV(wA, rA)));
		float vt = tbDot(dv, tangent) - c->tangentSpeed;
		float impulse = -cp->tangentMass * vt;
		float maxFriction = friction * normalImpulse;
		float newImpulse = tbClampFloat(cp->tangentImpulse + impulse, -maxFriction, maxFriction);
		impulse = newImpulse - cp->tangentImpulse;
		cp->tangentImpulse = newImpulse;

		tbVec2 P = tbMulSV(impulse, tangent);
		vA = tbMulSub(vA, mA, P);
		wA -= iA * tbCross(rA, P);
		vB = tbMulAdd(vB, mB, P);
		wB += iB * tbCross(rB, P);
	}

	sA->linearVelocity = vA;
	sA->angularVelocity = wA;
	sB->linearVelocity = vB;
	sB->angularVelocity = wB;
}

// One loop per policy, each with the policy a compile-time constant, so the per-point code has no
// policy tests left in it. COUNT and INDEX say which constraints: all in order, or the overflow of
// the wide solver.
#define TB_SOLVE_LOOP(POLICY, COUNT, INDEX)                                                                            \
	for (int i = 0; i < (COUNT); ++i)                                                                                  \
	{                                                                                                                  \
		tbContactConstraint* c = context->constraints + (INDEX);                                                       \
		tbSolveConstraint(c, bodies + c->indexA, bodies + c->indexB, context, POLICY);                                 \
	}

#define TB_SOLVE_LOOPS(COUNT, INDEX)                                                                                   \
	switch (policy)                                                                                                    \
	{                                                                                                                  \
		case tb_biasSoft:                                                                                              \
			TB_SOLVE_LOOP(tb_biasSoft, COUNT, INDEX)                                                                   \
			break;                                                                                                     \
		case tb_biasRelax:                                                                                             \
		case tb_biasRelaxRepeat:                                                                                       \
			TB_SOLVE_LOOP(tb_biasRelax, COUNT, INDEX)                                                                  \
			break;                                                                                                     \
		case tb_biasBaumgarte:                                                                                         \
			TB_SOLVE_LOOP(tb_biasBaumgarte, COUNT, INDEX)                                                              \
			break;                                                                                                     \
		default:                                                                                                       \
			TB_SOLVE_LOOP(tb_biasSpeculative, COUNT, INDEX)                                                            \
			break;                                                                                                     \
	}

void tbSolveOverflow(tbStepContext* context, tbBiasPolicy policy)
{
	tbSolverBody* bodies = context->bodies;
	TB_SOLVE_LOOPS(context->overflowCount, context->overflowConstraints[i])
}

void tbSolveContacts(tbStepContext* context, tbBiasPolicy policy)
{
	tbSolverBody* bodies = context->bodies;
	if (context->wideConstraints != NULL)
	{
		tbSolveContactsWide(context, policy);
		TB_SOLVE_LOOPS(context->overflowCount, context->overflowConstraints[i])
		return;
	}
	TB_SOLVE_LOOPS(context->constraintCount, i)
}

#undef TB_SOLVE_LOOPS
#undef TB_SOLVE_LOOP

/// Impact propagation (tbWorldDef::enableImpactPropagation), before the solve: every contact that
/// bounces (restitution > 0) and approaches faster than the restitution threshold gets the impulse
/// of a two-body collision, −(1 + e)·vn·m_n, with vn its approach at that moment; the contacts are
/// swept again until none approaches (at most TB_PROPAGATION_SWEEPS sweeps). This is sequential
/// collision processing (Guendelman, Bridson & Fedkiw 2003, "Nonconvex rigid bodies with
/// stacking", §6): an impact travels along a chain of touching bodies one pair at a time, as in
/// Newton's cradle, where solving all contacts together (the restitution pass after the solve,
/// below) shares the striker's momentum among the chain (the last ball leaves at 0.35 v0). Each
/// contact's approach speed is then refreshed, so that pass does not bounce it again.
void tbPropagateImpacts(tbStepContext* context)
{
	if (context->world->def.enableImpactPropagation == false || context->restitutionCount == 0)
	{
		return;
	}
	float threshold = context->world->def.restitutionThreshold;
	tbSolverBody* bodies = context->bodies;
	for (int sweep = 0; sweep < TB_PROPAGATION_SWEEPS; ++sweep)
	{
		bool approaching = false;
		for (int i = 0; i < context->constraintCount; ++i)
		{
			if (tbConstraintBounces(context, i) == false)
			{
				continue;
			}
			tbContactConstraint* c = context->constraints + i;
			tbSolverBody* sA = bodies + c->indexA;
			tbSolverBody* sB = bodies + c->indexB;
			for (int j = 0; j < c->pointCount; ++j)
			{
				tbContactConstraintPoint* cp = c->points + j;
				float vn = tbDot(tbRelativeVelocity(sA, sB, cp->anchorA, cp->anchorB), c->normal);
				if (!(vn <= -threshold)) // NaN: no impact
				{
					continue;
				}
				float impulse = -cp->normalMass * (vn - tbReboundSpeed(c->restitution, vn, context->maxLinearSpeed));
				tbApplyContactImpulse(sA, sB, c, cp->anchorA, cp->anchorB, tbMulSV(impulse, c->normal));
				approaching = true;
			}
		}
		if (approaching == false)
		{
			break;
		}
	}
	for (int i = 0; i < context->constraintCount; ++i)
	{
		if (tbConstraintBounces(context, i) == false)
		{
			continue;
		}
		tbContactConstraint* c = context->constraints + i;
		for (int j = 0; j < c->pointCount; ++j)
		{
			tbContactConstraintPoint* cp = c->points + j;
			cp->relativeVelocity = tbDot(tbRelativeVelocity(bodies + c->indexA, bodies + c->indexB, cp->anchorA, cp->anchorB),
										 c->normal);
		}
	}
}

void tbApplyRestitution(tbStepContext* context)
{
	if (context->world->def.solver == tb_solverNGS && context->subStepCount == 1)
	{
		return; // NGS at one sub-step (Box2D 2.4) applies restitution as a velocity bias in its iterations
	}
	if (context->restitutionCount == 0)
	{
		return; // no contact bounces (most piles): skip the walk over the constraints
	}
	float threshold = context->world->def.restitutionThreshold;
	tbSolverBody* bodies = context->bodies;
	for (int i = 0; i < context->constraintCount; ++i)
	{
		if (tbConstraintBounces(context, i) == false)
		{
			continue;
		}
		tbContactConstraint* c = context->constraints + i;
		float e = c->restitution;
		if (context->wideLocation != NULL && context->wideLocation[i] >= 0)
		{
			tbUnpackWideConstraint(context, i); // from now on the scalar copy holds its impulses
		}
		tbSolverBody* sA = bodies + c->indexA;
		tbSolverBody* sB = bodies + c->indexB;
		tbVec2 normal = c->normal;
		for (int j = 0; j < c->pointCount; ++j)
		{
			tbContactConstraintPoint* cp = c->points + j;
			// Only real impacts: fast enough and the point actually pushed during the step.
			if (!(cp->relativeVelocity <= -threshold) || cp->totalNormalImpulse == 0.0f) // NaN: no impact
			{
				continue;
			}
			tbVec2 rA = cp->anchorA;
			tbVec2 rB = cp->anchorB;
			float vn = tbDot(tbRelativeVelocity(sA, sB, rA, rB), normal);
			float impulse = -cp->normalMass * (vn - tbReboundSpeed(e, cp->relativeVelocity, context->maxLinearSpeed));
			float newImpulse = tbMaxFloat(cp->normalImpulse + impulse, 0.0f);
			impulse = newImpulse - cp->normalImpulse;
			cp->normalImpulse = newImpulse;
			cp->totalNormalImpulse += impulse;
			tbApplyContactImpulse(sA, sB, c, rA, rB, tbMulSV(impulse, normal));
		}
	}
}

// Impulses go back to the manifolds for the next step's warm start, walking the contacts in
// contact-id order. A constraint solved in a wide lane is read from its lane (its scalar copy
// holds the impulses of before the solve); the others from the scalar constraint.
// The lines holding the impulses of the lane of contact i (contact-id order): the blocks were last
// touched colour by colour in the final pass and have mostly left the cache (a large scene's
// blocks far exceed it); this walk visits them in contact-id order, one stream per colour, with
// a stride of a whole block (sizeof(tbWideContactConstraint)) the hardware prefetcher does not
// follow.
static inline void tbPrefetchLaneImpulses(const tbStepContext* context, int i)
{
	if (context->locationById == NULL || context->locationById[i] < 0)
	{
		return;
	}
	int location = context->locationById[i];
	const tbWideContactConstraint* block = context->wideConstraints + location / TB_SIMD_WIDTH;
	tbPrefetch(block->impulses, (int)sizeof(block->impulses));
}

static void tbStoreImpulsesTask(int start, int end, uint32_t workerIndex, void* taskContext)
{
	(void)workerIndex;
	tbStepContext* context = taskContext;
	tbWorld* world = context->world;
	const int* contactIds = world->cache.solverContactsById;
	const int* slots = world->cache.solverSlots;
	const int* wideLocation = context->wideLocation;
	for (int i = start; i < end; ++i)
	{
		int index = slots[i];
		tbManifold* manifold = &world->contacts[contactIds[i]].manifold;
		// Twice the usual distance: the loop body is short, and both loads usually miss (the solve
		// passes since the last visit have pushed the contacts and most blocks out of the cache).
		if (i + 2 * TB_PREFETCH_AHEAD < end)
		{
			tbPrefetch(&world->contacts[contactIds[i + 2 * TB_PREFETCH_AHEAD]].manifold, (int)sizeof(tbManifold));
			tbPrefetchLaneImpulses(context, i + 2 * TB_PREFETCH_AHEAD);
		}
		int location = -1;
		if (wideLocation != NULL)
		{
			// A bouncing constraint may have been unpacked by restitution (wideLocation says so).
			bool bounces = (context->keysById[i].flags & tb_keyBounces) != 0u;
			location = bounces ? wideLocation[index] : context->locationById[i];
		}
		if (location >= 0)
		{
			tbLoadWideImpulses(context, location, manifold->pointCount, manifold->points);
			manifold->rollingImpulse = context->wideRolling != NULL
										   ? tbGetLaneW(&context->wideRolling[location / TB_SIMD_WIDTH].impulse,
														location % TB_SIMD_WIDTH)
										   : 0.0f;
			continue;
		}
		const tbContactConstraint* c = context->constraints + index;
		for (int j = 0; j < c->pointCount; ++j)
		{
			const tbContactConstraintPoint* cp = c->points + j;
			tbManifoldPoint* mp = manifold->points + j;
			mp->normalImpulse = cp->normalImpulse;
			mp->tangentImpulse = cp->tangentImpulse;
			mp->totalNormalImpulse = cp->totalNormalImpulse;
		}
		if (context->centralFriction && c->pointCount > 0)
		{
			float n1 = c->pointCount > 1 ? c->points[1].normalImpulse : 0.0f;
			float t1 = 0.0f;
			tbSplitFriction(c->points[0].tangentImpulse, c->pointCount, c->points[0].normalImpulse, n1,
							&manifold->points[0].tangentImpulse, &t1);
			if (c->pointCount > 1)
			{
				manifold->points[1].tangentImpulse = t1;
			}
		}
		manifold->rollingImpulse = c->rollingImpulse;
	}
}

// Each contact's impulses back into its manifold (ranges of contacts on workers).
void tbStoreImpulses(tbStepContext* context)
{
	tbParallelFor(&context->world->def, tbStoreImpulsesTask, context->constraintCount, TB_CONTACTS_PER_TASK, context);
}
