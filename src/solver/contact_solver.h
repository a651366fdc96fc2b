// Internal: the sequential-impulse contact solver shared by the position methods, scalar
// (contact_solver.c) and TB_SIMD_WIDTH contacts of one colour at a time (contact_solver_wide.c).
#pragma once

#include "solver_types.h"

/// Restitution's rebound speed −e·Ċ0 for an approach at Ċ0 < 0, at most the approach speed or
/// twice maximumLinearSpeed, whichever is larger: e > 1 (a bumper) still rebounds faster than it
/// came, but a huge e (3e38) cannot overflow the impulse or store one that warm starting would
/// re-apply after the speed clamp. For e ≤ 1 the bound never acts.
static inline float tbReboundSpeed(float restitution, float approach, float maxLinearSpeed)
{
	return tbMinFloat(-restitution * approach, tbMaxFloat(-approach, 2.0f * maxLinearSpeed));
}

/// A contact's impulse P at its anchors rA, rB (from the centres of mass): B receives +P and A −P,
/// each through its inverse mass and inverse inertia (v += P/m, ω += (r × P)/I). The scalar solve,
/// restitution and NGS's undoing of warm starts all apply impulses so.
static inline void tbApplyContactImpulse(tbSolverBody* sA, tbSolverBody* sB, const tbContactConstraint* c, tbVec2 rA,
										 tbVec2 rB, tbVec2 P)
{
	sA->linearVelocity = tbMulSub(sA->linearVelocity, c->invMassA, P);
	sA->angularVelocity -= c->invIA * tbCross(rA, P);
	sB->linearVelocity = tbMulAdd(sB->linearVelocity, c->invMassB, P);
	sB->angularVelocity += c->invIB * tbCross(rB, P);
}

/// Central friction (tbWorldDef::enableCentralFriction, contact_solver.c): the share of point 0 in
/// the centre of pressure of a two-point manifold whose points carry normal impulses n0 and n1; a
/// half when neither carries any. Point 1's share is 1 − this.
static inline float tbPressureWeight(float n0, float n1)
{
	float total = n0 + n1;
	return total > 0.0f ? n0 / total : 0.5f;
}

/// The central friction impulse λt back over the manifold's points for the next step's warm start,
/// in proportion to their normal impulses: the next step's row takes the sum, t0 + t1 = λt, and a
/// point that leaves the manifold takes its share with it, as its own friction would have.
static inline void tbSplitFriction(float tangentImpulse, int pointCount, float n0, float n1, float* t0, float* t1)
{
	if (pointCount < 2)
	{
		*t0 = tangentImpulse;
		*t1 = 0.0f;
		return;
	}
	*t0 = tbPressureWeight(n0, n1) * tangentImpulse;
	*t1 = tangentImpulse - *t0;
}

// contact_solver.c
/// The wide solver's keys (tbContactKey), before colouring: read in contact-id order.
void tbKeyContacts(tbStepContext* context);
/// Constraints from the contacts; with the wide solver (colours known) straight into the lanes.
void tbPrepareContacts(tbStepContext* context);
void tbWarmStartContacts(tbStepContext* context);
void tbSolveContacts(tbStepContext* context, tbBiasPolicy policy);
void tbApplyRestitution(tbStepContext* context);
/// Impact propagation before the solve (tbWorldDef::enableImpactPropagation; contact_solver.c).
void tbPropagateImpacts(tbStepContext* context);
void tbStoreImpulses(tbStepContext* context);
/// One coloured contact that takes the lane path, prepared into lane `lane` of `block` (the scalar
/// constraint's numbers, written field by field); returns whether a point approaches at the
/// restitution threshold or faster. Declared here for the test of the wide preparation.
bool tbPrepareWideLane(tbStepContext* context, tbContact* contact, tbContactKey key, tbWideContactConstraint* block,
					   int lane);
/// TB_SIMD_WIDTH contacts for tbPrepareWideLanes, each with its place.
typedef struct tbLaneBatch
{
	int count;
	tbContact* contacts[TB_SIMD_WIDTH];
	tbContactKey keys[TB_SIMD_WIDTH];
	int locations[TB_SIMD_WIDTH]; ///< block·TB_SIMD_WIDTH + lane
	int slots[TB_SIMD_WIDTH];
	int indices[TB_SIMD_WIDTH]; ///< place in contact-id order (world->cache.solverContactsById)
} tbLaneBatch;
/// tbPrepareWideLane for a full batch of contacts, computed in wide floats: bit for bit the same
/// lanes and approach speeds (tests/test_contact_solver.c checks it). Returns a bit per lane: set
/// where tbPrepareWideLane would return true (some point approaches at the restitution threshold
/// or faster).
int tbPrepareWideLanes(tbStepContext* context, const tbLaneBatch* batch);

// contact_solver_wide.c
// Inline so that a contact prepared on the stack goes to its lane without a round trip through
// memory (contact_solver.c). Every field of the lane is written (a second point the contact does not
// have as zeros) but the relaxing bias, which the first relaxing pass writes before any pass reads
// it; so the block needs no clearing first.
static inline void tbPackWideLane(tbWideContactConstraint* block, int lane, const tbContactConstraint* c)
{
	block->indexA[lane] = c->indexA;
	block->indexB[lane] = c->indexB;
	tbSetLaneW(&block->normalX, lane, c->normal.x);
	tbSetLaneW(&block->normalY, lane, c->normal.y);
	tbSetLaneW(&block->friction, lane, c->friction);
	tbSetLaneW(&block->invMassA, lane, c->invMassA);
	tbSetLaneW(&block->invIA, lane, c->invIA);
	tbSetLaneW(&block->invMassB, lane, c->invMassB);
	tbSetLaneW(&block->invIB, lane, c->invIB);
	tbSetLaneW(&block->biasRate, lane, c->softness.biasRate);
	tbSetLaneW(&block->massScale, lane, c->softness.massScale);
	tbSetLaneW(&block->impulseScale, lane, c->softness.impulseScale);
	static const tbContactConstraintPoint absent = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
	for (int j = 0; j < 2; ++j)
	{
		const tbContactConstraintPoint* cp = j < c->pointCount ? c->points + j : &absent;
		tbWideContactPoint* wp = block->points + j;
		tbSetLaneW(&wp->anchorAX, lane, cp->anchorA.x);
		tbSetLaneW(&wp->anchorAY, lane, cp->anchorA.y);
		tbSetLaneW(&wp->anchorBX, lane, cp->anchorB.x);
		tbSetLaneW(&wp->anchorBY, lane, cp->anchorB.y);
		tbSetLaneW(&wp->baseSeparation, lane, cp->baseSeparation);
		tbSetLaneW(&block->impulses[j].normalImpulse, lane, cp->normalImpulse);
		tbSetLaneW(&block->impulses[j].tangentImpulse, lane, cp->tangentImpulse);
		tbSetLaneW(&block->impulses[j].totalNormalImpulse, lane, cp->totalNormalImpulse);
		tbSetLaneW(&wp->normalMass, lane, cp->normalMass);
		tbSetLaneW(&wp->tangentMass, lane, cp->tangentMass);
	}
	tbSetLaneW(&block->frictionAnchorAX, lane, c->frictionAnchorA.x);
	tbSetLaneW(&block->frictionAnchorAY, lane, c->frictionAnchorA.y);
	tbSetLaneW(&block->frictionAnchorBX, lane, c->frictionAnchorB.x);
	tbSetLaneW(&block->frictionAnchorBY, lane, c->frictionAnchorB.y);
}

void tbInitWideConstraint(tbWideContactConstraint* block, int staticIndex);
void tbWarmStartContactsWide(tbStepContext* context);
void tbSolveContactsWide(tbStepContext* context, tbBiasPolicy policy);
/// Blocks [start, end) of the wide constraints (one colour's, for a worker). `shared`: other
/// workers solve other blocks of the colour at the same time, so bodies that do not move are not
/// written (the same result, without two threads storing to one body).
void tbWarmStartWideRange(tbStepContext* context, int start, int end, bool shared);
void tbSolveWideRange(tbStepContext* context, tbBiasPolicy policy, int start, int end, bool shared);
/// The wide solver's overflow (constraints that found no colour), one at a time after the colours.
void tbWarmStartOverflow(tbStepContext* context);
void tbSolveOverflow(tbStepContext* context, tbBiasPolicy policy);
/// Copy the impulses of the lane at `location` into manifold points (central friction's impulse
/// split over them, tbSplitFriction).
/// (Inline: the store runs it for every contact.) A lane's location is block·TB_SIMD_WIDTH + lane
/// (tbStepContext::wideLocation).
static inline void tbLoadWideImpulses(const tbStepContext* context, int location, int pointCount,
									  tbManifoldPoint* points)
{
	const tbWideContactConstraint* block = context->wideConstraints + location / TB_SIMD_WIDTH;
	int lane = location % TB_SIMD_WIDTH;
	for (int j = 0; j < pointCount; ++j)
	{
		const tbWideImpulses* ip = block->impulses + j;
		points[j].normalImpulse = tbGetLaneW(&ip->normalImpulse, lane);
		points[j].tangentImpulse = tbGetLaneW(&ip->tangentImpulse, lane);
		points[j].totalNormalImpulse = tbGetLaneW(&ip->totalNormalImpulse, lane);
	}
	if (context->centralFriction && pointCount > 0)
	{
		float n1 = pointCount > 1 ? points[1].normalImpulse : 0.0f;
		float t1 = 0.0f;
		tbSplitFriction(points[0].tangentImpulse, pointCount, points[0].normalImpulse, n1, &points[0].tangentImpulse, &t1);
		if (pointCount > 1)
		{
			points[1].tangentImpulse = t1;
		}
	}
}
/// Copy a constraint's impulses from its lane to the scalar constraint, which holds them from then on.
void tbUnpackWideConstraint(tbStepContext* context, int constraintIndex);
