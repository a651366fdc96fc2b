// The wide contact solver: the sequential impulses of contact_solver.c, TB_SIMD_WIDTH contacts at
// a time (4 with SSE2 or plain floats, 8 with AVX2).
//
// The constraint graph colouring (constraint_graph.c) puts contacts that share no moving body in
// one colour, and the contacts of a colour in blocks of TB_SIMD_WIDTH. A block gathers its
// 2·TB_SIMD_WIDTH bodies' hot state into wide floats (the 32-byte tbSolverBody is two rows of four
// floats, so a gather is one load per lane and a 4×4 transpose per four lanes: one with four
// lanes, two with eight), runs the same per-point arithmetic as the scalar tbSolveConstraint lane
// by lane, and scatters the velocities back. Within a colour the lanes are independent, so this is
// exactly sequential impulses in the order colour by colour; the maths, the bias policies and the
// references are in contact_solver.c and are not repeated here.
//
// The SIMD is behind simd.h (AVX2 or SSE2, or four plain floats with lane-for-lane identical
// results). A lane whose contact has one point runs the second point with normal and tangent
// mass 0, so its impulses stay 0 and its bodies receive nothing. Restitution and the storing of
// impulses stay scalar: they run once per step, reading the impulses from the lanes
// (tbLoadWideImpulses; a contact with restitution is first copied back to its scalar constraint,
// tbUnpackWideConstraint).
//
// Why wide: the scalar solve is bound by the dependency chain through each body's velocity (each
// contact waits for the velocities the previous one on its bodies stored); the contacts of a
// block share no moving body, so their chains run side by side in the lanes and the solve passes
// take a much smaller share of the step (docs/methods.md, "Wide or scalar contact solver").
#include "contact_solver.h"

#include "tumble/constants.h"

#include <stddef.h>
#include <string.h>

void tbInitWideConstraint(tbWideContactConstraint* block, int staticIndex)
{
	memset(block, 0, sizeof(*block));
	for (int i = 0; i < TB_SIMD_WIDTH; ++i)
	{
		block->indexA[i] = staticIndex;
		block->indexB[i] = staticIndex;
	}
}

void tbUnpackWideConstraint(tbStepContext* context, int constraintIndex)
{
	int location = context->wideLocation[constraintIndex];
	const tbWideContactConstraint* block = context->wideConstraints + location / TB_SIMD_WIDTH;
	int lane = location % TB_SIMD_WIDTH;
	tbContactConstraint* c = context->constraints + constraintIndex;
	for (int j = 0; j < c->pointCount; ++j)
	{
		const tbWideImpulses* ip = block->impulses + j;
		c->points[j].normalImpulse = tbGetLaneW(&ip->normalImpulse, lane);
		c->points[j].tangentImpulse = tbGetLaneW(&ip->tangentImpulse, lane);
		c->points[j].totalNormalImpulse = tbGetLaneW(&ip->totalNormalImpulse, lane);
	}
	if (context->wideRolling != NULL)
	{
		c->rollingImpulse = tbGetLaneW(&context->wideRolling[location / TB_SIMD_WIDTH].impulse, lane);
	}
	context->wideLocation[constraintIndex] = -1;
}

// The block solve and its helpers are forced inline (TB_FORCE_INLINE, core.h): each pass
// (TB_SOLVE_WIDE_LOOP) then gets its own copy with the policy and the `shared` choice folded away.
// Left to itself the compiler kept one large out-of-line copy that tested both at run time.

// The velocities (v.x, v.y, ω) of a block side's bodies (one per lane) and their step deltas
// (Δp.x, Δp.y, Δq.c, Δq.s).
typedef struct tbWideBody
{
	tbFloatW vx, vy, w;
	tbFloatW padding; ///< carried through unchanged so the scatter writes back what it read
	tbFloatW dpx, dpy, qc, qs;
} tbWideBody;

_Static_assert(offsetof(tbSolverBody, angularVelocity) == 8 && offsetof(tbSolverBody, padding) == 12 &&
				   offsetof(tbSolverBody, deltaPosition) == 16 && offsetof(tbSolverBody, deltaRotation) == 24,
			   "tbSolverBody rows: (v, ω, padding) then (Δp, Δq), as the gathers read them");

// The two 16-byte rows of a tbSolverBody: (v.x, v.y, ω, padding) and (Δp.x, Δp.y, Δq.c, Δq.s).
static inline void* tbVelocityRow(tbSolverBody* bodies, int index)
{
	return (char*)(bodies + index) + offsetof(tbSolverBody, linearVelocity);
}

static inline void* tbDeltaRow(tbSolverBody* bodies, int index)
{
	return (char*)(bodies + index) + offsetof(tbSolverBody, deltaPosition);
}

// The rows of the bodies of one side of a block, one per lane.
static TB_FORCE_INLINE void tbVelocityRows(tbSolverBody* bodies, const int index[TB_SIMD_WIDTH],
										   void* rows[TB_SIMD_WIDTH])
{
	for (int i = 0; i < TB_SIMD_WIDTH; ++i)
	{
		rows[i] = tbVelocityRow(bodies, index[i]);
	}
}

static TB_FORCE_INLINE void tbGatherVelocities(tbSolverBody* bodies, const int index[TB_SIMD_WIDTH], tbWideBody* out)
{
	void* rowPointers[TB_SIMD_WIDTH];
	tbVelocityRows(bodies, index, rowPointers);
	tbFloatW rows[4];
	tbLoadTransposeRowsW((const void* const*)rowPointers, rows);
	out->vx = rows[0], out->vy = rows[1], out->w = rows[2], out->padding = rows[3];
}

static TB_FORCE_INLINE void tbGatherDeltas(tbSolverBody* bodies, const int index[TB_SIMD_WIDTH], tbWideBody* out)
{
	void* rowPointers[TB_SIMD_WIDTH];
	for (int i = 0; i < TB_SIMD_WIDTH; ++i)
	{
		rowPointers[i] = tbDeltaRow(bodies, index[i]);
	}
	tbFloatW rows[4];
	tbLoadTransposeRowsW((const void* const*)rowPointers, rows);
	out->dpx = rows[0], out->dpy = rows[1], out->qc = rows[2], out->qs = rows[3];
}

// Written lane 0 to the last. Only a body that does not move (static stand-in, kinematic) can appear
// in two lanes, and it is written with the velocity it was read with.
static TB_FORCE_INLINE void tbScatterVelocities(tbSolverBody* bodies, const int index[TB_SIMD_WIDTH],
												const tbWideBody* in)
{
	void* rowPointers[TB_SIMD_WIDTH];
	tbVelocityRows(bodies, index, rowPointers);
	tbFloatW rows[4] = {in->vx, in->vy, in->w, in->padding};
	tbTransposeStoreRowsW(rowPointers, rows, TB_ALL_LANES);
}

// The same, for a solve spread over workers: lanes of bodies that do not move (inverse mass and
// inertia zero: the static stand-in, kinematic bodies) are not written, since several blocks of one
// colour may hold them. The values skipped are the ones read, so the result is the same.
static TB_FORCE_INLINE void tbScatterMovingVelocities(tbSolverBody* bodies, const int index[TB_SIMD_WIDTH],
													  const tbWideBody* in, tbFloatW invMass, tbFloatW invI)
{
	void* rowPointers[TB_SIMD_WIDTH];
	tbVelocityRows(bodies, index, rowPointers);
	tbFloatW rows[4] = {in->vx, in->vy, in->w, in->padding};
	tbTransposeStoreRowsW(rowPointers, rows, tbNonZeroMaskW(invMass, invI));
}

static TB_FORCE_INLINE void tbScatterPair(tbSolverBody* bodies, const tbWideContactConstraint* c, const tbWideBody* a,
								 const tbWideBody* b, bool shared)
{
	if (shared)
	{
		tbScatterMovingVelocities(bodies, c->indexA, a, c->invMassA, c->invIA);
		tbScatterMovingVelocities(bodies, c->indexB, b, c->invMassB, c->invIB);
	}
	else
	{
		tbScatterVelocities(bodies, c->indexA, a);
		tbScatterVelocities(bodies, c->indexB, b);
	}
}

// Apply the impulse (px, py) at anchors rA, rB: A receives −P, B receives +P.
static TB_FORCE_INLINE void tbApplyImpulseW(tbWideBody* a, tbWideBody* b, const tbWideContactConstraint* c, tbFloatW rAx,
								   tbFloatW rAy, tbFloatW rBx, tbFloatW rBy, tbFloatW px, tbFloatW py)
{
	a->vx = tbSubW(a->vx, tbMulW(c->invMassA, px));
	a->vy = tbSubW(a->vy, tbMulW(c->invMassA, py));
	a->w = tbSubW(a->w, tbMulW(c->invIA, tbSubW(tbMulW(rAx, py), tbMulW(rAy, px))));
	b->vx = tbAddW(b->vx, tbMulW(c->invMassB, px));
	b->vy = tbAddW(b->vy, tbMulW(c->invMassB, py));
	b->w = tbAddW(b->w, tbMulW(c->invIB, tbSubW(tbMulW(rBx, py), tbMulW(rBy, px))));
}

static void tbZeroWideImpulses(tbStepContext* context)
{
	for (int i = 0; i < context->wideCount; ++i)
	{
		tbWideContactConstraint* c = context->wideConstraints + i;
		for (int j = 0; j < 2; ++j)
		{
			c->impulses[j].normalImpulse = tbZeroW();
			c->impulses[j].tangentImpulse = tbZeroW();
		}
		if (context->wideRolling != NULL)
		{
			context->wideRolling[i].impulse = tbZeroW();
		}
	}
}

/// Whether some lane of the block has rolling resistance (the rest of the row is then skipped).
static TB_FORCE_INLINE bool tbBlockRolls(const tbWideRolling* rolling)
{
	return rolling != NULL && tbGreaterMaskW(rolling->resistance, tbZeroW()) != 0;
}

/// The rolling impulse's change of the bodies' spin, in the lanes that have rolling resistance only.
static TB_FORCE_INLINE void tbApplyRollingW(tbWideBody* a, tbWideBody* b, const tbWideContactConstraint* c,
											const tbWideRolling* rolling, tbFloatW impulse)
{
	tbFloatW zero = tbZeroW();
	a->w = tbSelectGreaterW(rolling->resistance, zero, tbSubW(a->w, tbMulW(c->invIA, impulse)), a->w);
	b->w = tbSelectGreaterW(rolling->resistance, zero, tbAddW(b->w, tbMulW(c->invIB, impulse)), b->w);
}

/// Rolling resistance, lane by lane as the scalar tbSolveConstraint: the impulse against the
/// relative spin, its total bounded by rollingResistance × the points' normal impulses together.
static TB_FORCE_INLINE void tbSolveRollingW(const tbWideContactConstraint* c, tbWideRolling* rolling, tbWideBody* a,
											tbWideBody* b)
{
	tbFloatW minusOne = tbSplatW(-1.0f); // x·(−1) is −x exactly, the sign of a zero included
	tbFloatW totalNormalImpulse = tbAddW(c->impulses[0].normalImpulse, c->impulses[1].normalImpulse);
	tbFloatW maxImpulse = tbMulW(rolling->resistance, totalNormalImpulse);
	tbFloatW impulse = tbMulW(tbMulW(rolling->mass, minusOne), tbSubW(b->w, a->w));
	tbFloatW newImpulse = tbClampW(tbAddW(rolling->impulse, impulse), tbMulW(maxImpulse, minusOne), maxImpulse);
	impulse = tbSubW(newImpulse, rolling->impulse);
	rolling->impulse = tbSelectGreaterW(rolling->resistance, tbZeroW(), newImpulse, rolling->impulse);
	tbApplyRollingW(a, b, c, rolling, impulse);
}

// `central`: the friction impulse is one, at the block's friction anchors (central friction,
// contact_solver.c), applied after the points' normal impulses as the scalar warm start does.
static TB_FORCE_INLINE void tbWarmStartWideBlock(tbWideContactConstraint* c, const tbWideRolling* rolling,
												 tbSolverBody* bodies, bool shared, bool central)
{
	tbWideBody a, b;
	tbGatherVelocities(bodies, c->indexA, &a);
	tbGatherVelocities(bodies, c->indexB, &b);
	// tangent = rightPerp(normal) = (n.y, −n.x)
	tbFloatW tx = c->normalY;
	tbFloatW ty = tbSubW(tbZeroW(), c->normalX);
	for (int j = 0; j < 2; ++j)
	{
		const tbWideContactPoint* cp = c->points + j;
		tbWideImpulses* ip = c->impulses + j;
		ip->totalNormalImpulse = tbAddW(ip->totalNormalImpulse, ip->normalImpulse); // applied again
		tbFloatW px, py;
		if (central)
		{
			px = tbMulW(ip->normalImpulse, c->normalX);
			py = tbMulW(ip->normalImpulse, c->normalY);
		}
		else
		{
			px = tbMulAddPairW(ip->normalImpulse, c->normalX, ip->tangentImpulse, tx);
			py = tbMulAddPairW(ip->normalImpulse, c->normalY, ip->tangentImpulse, ty);
		}
		tbApplyImpulseW(&a, &b, c, cp->anchorAX, cp->anchorAY, cp->anchorBX, cp->anchorBY, px, py);
	}
	if (central)
	{
		tbFloatW impulse = c->impulses[0].tangentImpulse;
		tbApplyImpulseW(&a, &b, c, c->frictionAnchorAX, c->frictionAnchorAY, c->frictionAnchorBX, c->frictionAnchorBY,
						tbMulW(impulse, tx), tbMulW(impulse, ty));
	}
	if (tbBlockRolls(rolling))
	{
		tbApplyRollingW(&a, &b, c, rolling, rolling->impulse); // after the points, as the scalar warm start
	}
	tbScatterPair(bodies, c, &a, &b, shared);
}

#define TB_WARM_START_WIDE_LOOP(SHARED, CENTRAL)                                                                       \
	for (int i = start; i < end; ++i)                                                                                  \
	{                                                                                                                  \
		tbWarmStartWideBlock(context->wideConstraints + i, rolling != NULL ? rolling + i : NULL, bodies, SHARED,         \
							 CENTRAL);                                                                                 \
	}

// One loop per scatter kind and friction kind, so that no block tests them.
void tbWarmStartWideRange(tbStepContext* context, int start, int end, bool shared)
{
	tbSolverBody* bodies = context->bodies;
	const tbWideRolling* rolling = context->wideRolling;
	if (context->centralFriction)
	{
		if (shared)
		{
			TB_WARM_START_WIDE_LOOP(true, true)
			return;
		}
		TB_WARM_START_WIDE_LOOP(false, true)
		return;
	}
	if (shared)
	{
		TB_WARM_START_WIDE_LOOP(true, false)
		return;
	}
	TB_WARM_START_WIDE_LOOP(false, false)
}

#undef TB_WARM_START_WIDE_LOOP

void tbWarmStartContactsWide(tbStepContext* context)
{
	if (context->enableWarmStarting == false)
	{
		tbZeroWideImpulses(context);
		return;
	}
	tbWarmStartWideRange(context, 0, context->wideCount, false);
}

// Constants of one solve pass, splatted once.
typedef struct tbWidePass
{
	tbFloatW inv_h;
	tbFloatW minPushBias;	///< −contactSpeed
	tbFloatW baumgarteRate; ///< TB_BAUMGARTE/h
	tbFloatW minBaumgarteBias; ///< −maxLinearSpeed
	tbFloatW slop;			///< TB_LINEAR_SLOP
} tbWidePass;

// Linearised current separation of point cp (see contact_solver.c): s0 + dot(Δp_B + Δq_B·rB − Δp_A −
// Δq_A·rA, n) with s0 folded into baseSeparation.
static TB_FORCE_INLINE tbFloatW tbSeparationW(const tbWideContactPoint* cp, const tbWideContactConstraint* c,
									 const tbWideBody* a, const tbWideBody* b)
{
	tbFloatW prAx = tbSubW(tbMulW(a->qc, cp->anchorAX), tbMulW(a->qs, cp->anchorAY));
	tbFloatW prAy = tbAddW(tbMulW(a->qs, cp->anchorAX), tbMulW(a->qc, cp->anchorAY));
	tbFloatW prBx = tbSubW(tbMulW(b->qc, cp->anchorBX), tbMulW(b->qs, cp->anchorBY));
	tbFloatW prBy = tbAddW(tbMulW(b->qs, cp->anchorBX), tbMulW(b->qc, cp->anchorBY));
	tbFloatW dx = tbAddW(tbSubW(b->dpx, a->dpx), tbSubW(prBx, prAx));
	tbFloatW dy = tbAddW(tbSubW(b->dpy, a->dpy), tbSubW(prBy, prAy));
	return tbAddW(cp->baseSeparation, tbMulAddPairW(dx, c->normalX, dy, c->normalY));
}

// Relative velocity of the anchors, vB + ωB × rB − vA − ωA × rA, along (ux, uy).
static TB_FORCE_INLINE tbFloatW tbRelativeVelocityW(const tbWideContactPoint* cp, const tbWideBody* a, const tbWideBody* b,
										   tbFloatW ux, tbFloatW uy)
{
	tbFloatW dvx = tbSubW(tbSubW(b->vx, tbMulW(b->w, cp->anchorBY)), tbSubW(a->vx, tbMulW(a->w, cp->anchorAY)));
	tbFloatW dvy = tbSubW(tbAddW(b->vy, tbMulW(b->w, cp->anchorBX)), tbAddW(a->vy, tbMulW(a->w, cp->anchorAX)));
	return tbMulAddPairW(dvx, ux, dvy, uy);
}

static TB_FORCE_INLINE void tbSolveNormalW(tbWideContactPoint* cp, tbWideImpulses* ip, const tbWideContactConstraint* c, tbWideBody* a,
								  tbWideBody* b, const tbWidePass* pass, tbBiasPolicy policy)
{
	tbFloatW zero = tbZeroW();
	tbFloatW bias, massScale, impulseScale;
	if (policy == tb_biasRelaxRepeat)
	{
		// The positions have not moved since the sub-step's first relaxing pass: same bias, and
		// the same arithmetic as below with massScale 1 and impulseScale 0, so the same impulses.
		bias = cp->relaxBias;
		massScale = tbSplatW(1.0f);
		impulseScale = zero;
	}
	else
	{
		tbFloatW s = tbSeparationW(cp, c, a, b);

		// Speculative (s > 0): bias s/h, rigid. Overlap: the policy's push-out (contact_solver.c).
		tbFloatW overlapBias = zero;
		tbFloatW overlapMassScale = tbSplatW(1.0f);
		tbFloatW overlapImpulseScale = zero;
		if (policy == tb_biasSoft)
		{
			overlapBias = tbMaxW(tbMulW(c->biasRate, s), pass->minPushBias);
			overlapMassScale = c->massScale;
			overlapImpulseScale = c->impulseScale;
		}
		else if (policy == tb_biasBaumgarte)
		{
			overlapBias = tbMaxW(tbMulW(pass->baumgarteRate, tbMinW(zero, tbAddW(s, pass->slop))), pass->minBaumgarteBias);
		}
		bias = tbSelectGreaterW(s, zero, tbMulW(s, pass->inv_h), overlapBias);
		massScale = tbSelectGreaterW(s, zero, tbSplatW(1.0f), overlapMassScale);
		impulseScale = tbSelectGreaterW(s, zero, zero, overlapImpulseScale);
		if (policy == tb_biasRelax)
		{
			cp->relaxBias = bias;
		}
	}

	tbFloatW vn = tbRelativeVelocityW(cp, a, b, c->normalX, c->normalY);
	tbFloatW impulse = tbSubW(tbSubW(zero, tbMulW(tbMulW(cp->normalMass, massScale), tbAddW(vn, bias))),
							  tbMulW(impulseScale, ip->normalImpulse));
	tbFloatW newImpulse = tbMaxW(tbAddW(ip->normalImpulse, impulse), zero);
	impulse = tbSubW(newImpulse, ip->normalImpulse);
	ip->normalImpulse = newImpulse;
	ip->totalNormalImpulse = tbAddW(ip->totalNormalImpulse, impulse);

	tbApplyImpulseW(a, b, c, cp->anchorAX, cp->anchorAY, cp->anchorBX, cp->anchorBY, tbMulW(impulse, c->normalX),
					tbMulW(impulse, c->normalY));
}

/// A friction row at anchors (rAx, rAy), (rBx, rBy) with mass `tangentMass`, its impulse in
/// ip->tangentImpulse, bounded by μ·normalImpulse.
static TB_FORCE_INLINE void tbSolveFrictionRowW(tbFloatW rAx, tbFloatW rAy, tbFloatW rBx, tbFloatW rBy, tbFloatW tangentMass,
									   tbFloatW normalImpulse, tbWideImpulses* ip, const tbWideContactConstraint* c,
									   tbWideBody* a, tbWideBody* b, tbFloatW tx, tbFloatW ty)
{
	tbFloatW dvx = tbSubW(tbSubW(b->vx, tbMulW(b->w, rBy)), tbSubW(a->vx, tbMulW(a->w, rAy)));
	tbFloatW dvy = tbSubW(tbAddW(b->vy, tbMulW(b->w, rBx)), tbAddW(a->vy, tbMulW(a->w, rAx)));
	tbFloatW vt = tbMulAddPairW(dvx, tx, dvy, ty);
	tbFloatW impulse = tbSubW(tbZeroW(), tbMulW(tangentMass, vt));
	tbFloatW maxFriction = tbMulW(c->friction, normalImpulse);
	tbFloatW minFriction = tbSubW(tbZeroW(), maxFriction);
	// clamp(λt + Δλ, −μλn, μλn) with the scalar clamp's rule for NaN bounds (μ = ∞ and λn = 0).
	tbFloatW newImpulse = tbClampW(tbAddW(ip->tangentImpulse, impulse), minFriction, maxFriction);
	impulse = tbSubW(newImpulse, ip->tangentImpulse);
	ip->tangentImpulse = newImpulse;
	tbApplyImpulseW(a, b, c, rAx, rAy, rBx, rBy, tbMulW(impulse, tx), tbMulW(impulse, ty));
}

static TB_FORCE_INLINE void tbSolveFrictionW(const tbWideContactPoint* cp, tbWideImpulses* ip, const tbWideContactConstraint* c, tbWideBody* a,
									tbWideBody* b, tbFloatW tx, tbFloatW ty)
{
	tbSolveFrictionRowW(cp->anchorAX, cp->anchorAY, cp->anchorBX, cp->anchorBY, cp->tangentMass, ip->normalImpulse, ip, c,
						a, b, tx, ty);
}

/// Central friction: one row at the block's friction anchors, bounded by both points' normal
/// impulses (a lane with one point has 0 in the second), its mass and impulse in point 0's.
static TB_FORCE_INLINE void tbSolveCentralFrictionW(tbWideContactConstraint* c, tbWideBody* a, tbWideBody* b, tbFloatW tx,
										   tbFloatW ty)
{
	tbFloatW normalImpulse = tbAddW(c->impulses[0].normalImpulse, c->impulses[1].normalImpulse);
	tbSolveFrictionRowW(c->frictionAnchorAX, c->frictionAnchorAY, c->frictionAnchorBX, c->frictionAnchorBY,
						c->points[0].tangentMass, normalImpulse, c->impulses + 0, c, a, b, tx, ty);
}

// `count` blocks of one colour (1 or TB_SOLVE_GROUP, a constant where it is inlined), each solved
// as the scalar solver solves a contact: normal impulses first, then friction against the fresh
// normal impulses. The blocks go side by side, each step of one beside the same step of the others:
// a block is a chain of dependent arithmetic (point 0's impulse feeds point 1's velocities, both
// feed the friction row) several hundred instructions long, longer than the processor's window of
// instructions in flight, so that solved one after the other the next block's independent work
// could hardly start while this one's chain was waiting. Blocks of one colour share no moving body,
// so a group gives exactly what solving its blocks in turn gives: each reads bodies the others do
// not write (the static stand-in and kinematic bodies they may share are written back with the
// velocity read). Two at a time measured fastest with four lanes (SSE2); three or four spilled the
// registers. With eight lanes (AVX2) a block is twice the work on the same chain and two spilled:
// one at a time.
#if TB_SIMD_WIDTH == 8
#define TB_SOLVE_GROUP 1
#else
#define TB_SOLVE_GROUP 2
#endif

static TB_FORCE_INLINE void tbSolveWideBlocks(tbWideContactConstraint* c, tbWideRolling* rolling, int count,
											  tbSolverBody* bodies, const tbWidePass* pass, tbBiasPolicy policy,
											  bool shared, bool central)
{
	tbWideBody a[TB_SOLVE_GROUP], b[TB_SOLVE_GROUP];
	for (int n = 0; n < count; ++n)
	{
		a[n] = (tbWideBody){0};
		b[n] = (tbWideBody){0};
		tbGatherVelocities(bodies, c[n].indexA, a + n);
		tbGatherVelocities(bodies, c[n].indexB, b + n);
		if (policy != tb_biasRelaxRepeat)
		{
			tbGatherDeltas(bodies, c[n].indexA, a + n); // only the separation reads the deltas
			tbGatherDeltas(bodies, c[n].indexB, b + n);
		}
	}
	for (int j = 0; j < 2; ++j)
	{
		for (int n = 0; n < count; ++n)
		{
			tbSolveNormalW(c[n].points + j, c[n].impulses + j, c + n, a + n, b + n, pass, policy);
		}
	}
	for (int n = 0; n < count; ++n)
	{
		if (tbBlockRolls(rolling != NULL ? rolling + n : NULL))
		{
			tbSolveRollingW(c + n, rolling + n, a + n, b + n); // between normal and friction, as the scalar solver
		}
	}
	// tangent = rightPerp(normal) = (n.y, −n.x)
	if (central)
	{
		for (int n = 0; n < count; ++n)
		{
			tbSolveCentralFrictionW(c + n, a + n, b + n, c[n].normalY, tbSubW(tbZeroW(), c[n].normalX));
		}
	}
	else
	{
		for (int j = 0; j < 2; ++j)
		{
			for (int n = 0; n < count; ++n)
			{
				tbSolveFrictionW(c[n].points + j, c[n].impulses + j, c + n, a + n, b + n, c[n].normalY,
								 tbSubW(tbZeroW(), c[n].normalX));
			}
		}
	}
	for (int n = 0; n < count; ++n)
	{
		tbScatterPair(bodies, c + n, a + n, b + n, shared);
	}
}

/// The colour whose blocks hold block `block` (the first colour that ends past it).
static int tbColorOfBlock(const tbStepContext* context, int block)
{
	int k = 0;
	while (k < TB_GRAPH_COLOR_COUNT && context->colorBlockStart[k + 1] <= block)
	{
		++k;
	}
	return k;
}

// The blocks [start, end), colour by colour (context->colorBlockStart), TB_SOLVE_GROUP at a time
// within a colour; a colour's last one alone. The walk starts at start's colour and stops at the
// first colour that begins at or past end: a small scene's few colours do not pay for the 24.
#define TB_SOLVE_WIDE_BLOCKS(POLICY, SHARED, CENTRAL)                                                                  \
	for (int k = tbColorOfBlock(context, start); k < TB_GRAPH_COLOR_COUNT && context->colorBlockStart[k] < end; ++k)  \
	{                                                                                                                  \
		int first = tbMaxInt(start, context->colorBlockStart[k]);                                                      \
		int last = tbMinInt(end, context->colorBlockStart[k + 1]);                                                     \
		for (int i = first; i < last; i += TB_SOLVE_GROUP)                                                             \
		{                                                                                                              \
			tbWideContactConstraint* blocks = context->wideConstraints + i;                                            \
			tbWideRolling* blockRolling = rolling != NULL ? rolling + i : NULL;                                        \
			if (i + TB_SOLVE_GROUP <= last)                                                                            \
			{                                                                                                          \
				tbSolveWideBlocks(blocks, blockRolling, TB_SOLVE_GROUP, context->bodies, &pass, POLICY, SHARED,        \
								  CENTRAL);                                                                            \
			}                                                                                                          \
			else                                                                                                       \
			{                                                                                                          \
				tbSolveWideBlocks(blocks, blockRolling, 1, context->bodies, &pass, POLICY, SHARED, CENTRAL);           \
			}                                                                                                          \
		}                                                                                                              \
	}

// A loop per policy, scatter kind and friction kind: none of them is tested block by block.
#define TB_SOLVE_WIDE_LOOP(POLICY)                                                                                     \
	if (central)                                                                                                       \
	{                                                                                                                  \
		if (shared)                                                                                                    \
		{                                                                                                              \
			TB_SOLVE_WIDE_BLOCKS(POLICY, true, true)                                                                   \
		}                                                                                                              \
		else                                                                                                           \
		{                                                                                                              \
			TB_SOLVE_WIDE_BLOCKS(POLICY, false, true)                                                                  \
		}                                                                                                              \
	}                                                                                                                  \
	else if (shared)                                                                                                   \
	{                                                                                                                  \
		TB_SOLVE_WIDE_BLOCKS(POLICY, true, false)                                                                      \
	}                                                                                                                  \
	else                                                                                                               \
	{                                                                                                                  \
		TB_SOLVE_WIDE_BLOCKS(POLICY, false, false)                                                                     \
	}

void tbSolveWideRange(tbStepContext* context, tbBiasPolicy policy, int start, int end, bool shared)
{
	tbWidePass pass;
	pass.inv_h = tbSplatW(context->inv_h);
	pass.minPushBias = tbSplatW(-context->contactSpeed);
	pass.baumgarteRate = tbSplatW(TB_BAUMGARTE * context->inv_h);
	pass.minBaumgarteBias = tbSplatW(-context->maxLinearSpeed);
	pass.slop = tbSplatW(TB_LINEAR_SLOP);
	bool central = context->centralFriction;
	tbWideRolling* rolling = context->wideRolling;
	switch (policy)
	{
		case tb_biasSoft:
			TB_SOLVE_WIDE_LOOP(tb_biasSoft)
			break;
		case tb_biasRelax:
			TB_SOLVE_WIDE_LOOP(tb_biasRelax)
			break;
		case tb_biasRelaxRepeat:
			TB_SOLVE_WIDE_LOOP(tb_biasRelaxRepeat)
			break;
		case tb_biasBaumgarte:
			TB_SOLVE_WIDE_LOOP(tb_biasBaumgarte)
			break;
		default:
			TB_SOLVE_WIDE_LOOP(tb_biasSpeculative)
			break;
	}
}

void tbSolveContactsWide(tbStepContext* context, tbBiasPolicy policy)
{
	tbSolveWideRange(context, policy, 0, context->wideCount, false);
}

#undef TB_SOLVE_WIDE_LOOP
#undef TB_SOLVE_WIDE_BLOCKS
