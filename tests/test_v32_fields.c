// Box2D v3.2's public struct fields that Tumble took over with their meaning (scripts/port-check.sh
// lists them): each test sets one field and measures what it changes, against a closed form or
// against the same scene with the field left at its default. The defaults are v3.2's
// b2Default*Def() values, checked field by field.
#include "test_helpers.h"
#include "error_recorder.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

// ---------------------------------------------------------------------------------------------
// Defaults

// v3.2's b2DefaultWorldDef, b2DefaultBodyDef and b2DefaultShapeDef (types.c), in metres. Where
// Tumble's default differs on purpose the test says so (docs/porting.md lists it).
Test(v32_fields, defaults_are_box2d_v32s)
{
	tbWorldDef w = tbDefaultWorldDef();
	cr_expect(w.gravity.x == 0.0f && w.gravity.y == -10.0f);
	cr_expect(w.hitEventThreshold == 1.0f && w.restitutionThreshold == 1.0f);
	cr_expect(w.contactSpeed == 3.0f);
	cr_expect(w.contactHertz == 30.0f && w.contactDampingRatio == 10.0f);
	cr_expect(w.enableSleep && w.enableContinuous && w.enableContactSoftening == false);
	cr_expect(w.frictionCallback == NULL && w.restitutionCallback == NULL);
	cr_expect(w.enqueueTask == NULL && w.finishTask == NULL && w.userTaskContext == NULL && w.userData == NULL);
	cr_expect(w.capacity.staticShapeCount == 0 && w.capacity.dynamicShapeCount == 0 && w.capacity.staticBodyCount == 0 &&
			  w.capacity.dynamicBodyCount == 0 && w.capacity.contactCount == 0);
	// Differences kept: maximumLinearSpeed 4000 m/s (v3.2: 400; Tumble's continuous collision is
	// tested to 1000 m/s) and workerCount 1 (v3.2: 0, which it clamps to 1).
	cr_expect(w.maximumLinearSpeed == 4000.0f && w.workerCount == 1);

	tbBodyDef b = tbDefaultBodyDef();
	cr_expect(b.type == tb_staticBody);
	cr_expect(b.rotation.c == 1.0f && b.rotation.s == 0.0f);
	cr_expect(b.linearVelocity.x == 0.0f && b.linearVelocity.y == 0.0f && b.angularVelocity == 0.0f);
	cr_expect(b.linearDamping == 0.0f && b.angularDamping == 0.0f && b.gravityScale == 1.0f);
	cr_expect(b.sleepThreshold == 0.05f && b.safetyFactor == 0.5f);
	cr_expect(b.name == NULL && b.userData == NULL);
	cr_expect(b.motionLocks.linearX == false && b.motionLocks.linearY == false && b.motionLocks.angularZ == false);
	cr_expect(b.enableSleep && b.isAwake && b.isBullet == false);
	cr_expect(b.isEnabled && b.allowFastRotation == false && b.enableContactRecycling);

	tbShapeDef s = tbDefaultShapeDef();
	cr_expect(s.userData == NULL && s.density == 1.0f);
	cr_expect(s.material.friction == 0.6f && s.material.restitution == 0.0f && s.material.rollingResistance == 0.0f &&
			  s.material.tangentSpeed == 0.0f && s.material.userMaterialId == 0u && s.material.customColor == 0u);
	cr_expect(s.filter.categoryBits == 1u && s.filter.maskBits == UINT64_MAX && s.filter.groupIndex == 0);
	cr_expect(s.isSensor == false && s.enableSensorEvents == false && s.enableContactEvents == false &&
			  s.enableHitEvents == false && s.enablePreSolveEvents == false && s.enableCustomFiltering == false);
	cr_expect(s.invokeContactCreation && s.updateBodyMass);
}

// contactSpeed, the one new float: refused like the others when not a positive number.
Test(v32_fields, contact_speed_is_checked, .init = SetupErrors, .fini = TeardownErrors)
{
	float bad[3] = {NAN, -1.0f, 0.0f};
	for (int i = 0; i < 3; ++i)
	{
		tbWorldDef def = tbDefaultWorldDef();
		def.contactSpeed = bad[i];
		int before = s_errors;
		tbWorldId world = tbCreateWorld(&def);
		cr_expect(tbWorld_IsValid(world) == false);
		ExpectError(before, "tbCreateWorld", "contactSpeed");
	}
}

// ---------------------------------------------------------------------------------------------
// tbWorldDef.enableContinuous

// A ball of radius 0.05 m at 300 m/s moves 5 m in a 1/60 s step, a hundred times the 0.05 m width
// of the wall 2 m ahead: without time of impact it is past the wall after one step; with it, the
// ball stops at the wall's face.
static float ShootThroughWall(bool enableContinuous, bool* reported)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = tbVec2_zero;
	def.enableContinuous = enableContinuous;
	tbWorldId world = tbCreateWorld(&def);
	*reported = tbWorld_IsContinuousEnabled(world);
	CreateGround(world, tbMakeVec2(2.0f, 0.0f), 0.025f, 1.0f, NULL);
	tbBodyId ball;
	CreateBall(world, tbVec2_zero, tbMakeVec2(300.0f, 0.0f), 0.05f, NULL, &ball);
	StepWorld(world, 3, 1.0f / 60.0f, 4);
	float x = tbBody_GetPosition(ball).x;
	tbDestroyWorld(world);
	return x;
}

Test(v32_fields, enable_continuous_false_lets_a_fast_ball_tunnel)
{
	bool on, off;
	float caught = ShootThroughWall(true, &on);
	float tunnelled = ShootThroughWall(false, &off);
	cr_expect(on && off == false);
	// The wall's face is at x = 1.975: the caught ball's centre stays a radius before it.
	cr_expect(caught < 1.975f - 0.05f + 0.01f, "caught at %g", (double)caught);
	cr_expect(tunnelled > 2.025f, "tunnelled to %g", (double)tunnelled);

	// tbWorld_EnableContinuous keeps the definition's field in step (tbWorld_GetDef would report it).
	tbWorldDef def = tbDefaultWorldDef();
	def.enableContinuous = false;
	tbWorldId world = tbCreateWorld(&def);
	cr_expect(tbWorld_IsContinuousEnabled(world) == false);
	tbWorld_EnableContinuous(world, true);
	cr_expect(tbWorld_IsContinuousEnabled(world));
	tbDestroyWorld(world);
}

// ---------------------------------------------------------------------------------------------
// tbBodyDef.isEnabled

static bool FindShape(tbShapeId shapeId, void* context)
{
	(void)shapeId;
	*(int*)context += 1;
	return true;
}

Test(v32_fields, disabled_body_is_not_simulated_nor_in_the_broad_phase)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	def.position = tbMakeVec2(0.0f, 5.0f);
	def.linearVelocity = tbMakeVec2(1.0f, 0.0f);
	def.isEnabled = false;
	tbBodyId body = CreateBoxFromDef(world, &def, 0.5f, 0.5f, NULL);
	cr_expect(tbBody_IsEnabled(body) == false && tbBody_IsAwake(body) == false);
	cr_expect(tbWorld_GetAwakeBodyCount(world) == 0);

	StepWorld(world, 60, 1.0f / 60.0f, 4);
	tbPos p = tbBody_GetPosition(body);
	cr_expect(p.x == 0.0f && p.y == 5.0f, "moved to (%g, %g)", (double)p.x, (double)p.y);
	int found = 0;
	tbAABB box = {{-1.0f, 4.0f}, {1.0f, 6.0f}};
	tbWorld_OverlapAABB(world, tbPos_zero, box, tbDefaultQueryFilter(), FindShape, &found);
	cr_expect(found == 0, "a disabled body's shape was found %d times", found);

	// Enabled, it is as if created enabled: found by the query, and it falls (1 s of free fall
	// from rest: 5 m).
	tbBody_Enable(body);
	found = 0;
	tbWorld_OverlapAABB(world, tbPos_zero, box, tbDefaultQueryFilter(), FindShape, &found);
	cr_expect(found == 1);
	StepWorld(world, 60, 1.0f / 60.0f, 4);
	cr_expect(tbBody_GetPosition(body).y < 5.0f - 4.0f);
	tbDestroyWorld(world);
}

// ---------------------------------------------------------------------------------------------
// tbBodyDef.allowFastRotation

// Spin is capped at TB_MAX_ROTATION (π/4) per step: 47.1 rad/s at 60 Hz. A wheel asked to spin at
// 200 rad/s keeps its speed only when it allows fast rotation.
static float SpinAfterOneStep(bool allowFastRotation)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	def.angularVelocity = 200.0f;
	def.allowFastRotation = allowFastRotation;
	tbBodyId body = tbCreateBody(world, &def);
	tbCircle wheel = {{0.0f, 0.0f}, 0.5f};
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCreateCircleShape(body, &shapeDef, &wheel);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	float w = tbBody_GetAngularVelocity(body);
	tbDestroyWorld(world);
	return w;
}

Test(v32_fields, allow_fast_rotation_lifts_the_spin_cap)
{
	float capped = SpinAfterOneStep(false);
	float free = SpinAfterOneStep(true);
	cr_expect_float_eq(capped, TB_MAX_ROTATION * 60.0f, 1e-3f, "capped spin %g", (double)capped);
	cr_expect(free == 200.0f, "free spin %g", (double)free);
}

// ---------------------------------------------------------------------------------------------
// tbShapeDef.invokeContactCreation

// A dynamic box at rest without gravity has looked for its pairs when it was created and does not
// move again. A static box then created overlapping it finds the pair only if it looks itself
// (invokeContactCreation, v3.2's default); otherwise no contact, no begin event, until something
// moves.
static int BeginEventsAfterStaticShape(bool invoke)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbShapeDef events = tbDefaultShapeDef();
	events.enableContactEvents = true;
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	def.enableSleep = false;
	CreateBoxFromDef(world, &def, 0.5f, 0.5f, &events);
	StepWorld(world, 3, 1.0f / 60.0f, 4);
	events.invokeContactCreation = invoke;
	CreateGround(world, tbMakeVec2(0.0f, -0.9f), 1.0f, 0.5f, &events);
	StepWorld(world, 1, 1.0f / 60.0f, 4);
	int count = tbWorld_GetContactEvents(world).beginCount;
	tbDestroyWorld(world);
	return count;
}

Test(v32_fields, invoke_contact_creation_makes_a_new_static_shape_find_its_pairs)
{
	cr_expect(BeginEventsAfterStaticShape(true) == 1);
	cr_expect(BeginEventsAfterStaticShape(false) == 0);
}

// ---------------------------------------------------------------------------------------------
// contactId in hit and end events

Test(v32_fields, hit_and_end_events_carry_their_contact)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbShapeDef events = tbDefaultShapeDef();
	events.enableContactEvents = true;
	events.enableHitEvents = true;
	tbShapeId ground = CreateGround(world, tbMakeVec2(0.0f, -0.5f), 5.0f, 0.5f, &events);
	tbBodyId body;
	tbShapeId ball = CreateBall(world, tbMakeVec2(0.0f, 0.3f), tbMakeVec2(0.0f, -5.0f), 0.25f, &events, &body);
	int hits = 0;
	for (int i = 0; i < 30 && hits == 0; ++i)
	{
		tbWorld_Step(world, 1.0f / 60.0f, 4);
		tbContactEvents e = tbWorld_GetContactEvents(world);
		for (int k = 0; k < e.hitCount; ++k)
		{
			tbContactHitEvent* hit = e.hitEvents + k; // v3.2's arrays are not const
			cr_assert(tbContact_IsValid(hit->contactId));
			tbContactData data = tbContact_GetData(hit->contactId);
			cr_expect(data.contactId.index1 == hit->contactId.index1);
			bool same = (data.shapeIdA.index1 == hit->shapeIdA.index1 && data.shapeIdB.index1 == hit->shapeIdB.index1);
			cr_expect(same, "the hit's contact joins other shapes");
			cr_expect(data.manifold.pointCount > 0);
			hits += 1;
		}
	}
	cr_assert(hits == 1);

	// Lifted 3 cm clear of the ground: beyond the speculative distance (4 × linear slop, 2 cm), so no
	// manifold point, and within the boxes' margins, so the contact stops touching but lives on; the
	// end event's id resolves to it. (5 cm parts the boxes: the contact ends and its id with it.)
	StepWorld(world, 30, 1.0f / 60.0f, 4);
	tbBody_SetTransform(body, tbMakeVec2(0.0f, 0.28f), tbRot_identity);
	tbBody_SetLinearVelocity(body, tbVec2_zero);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	tbContactEvents e = tbWorld_GetContactEvents(world);
	cr_assert(e.endCount == 1, "end events %d", e.endCount);
	tbContactId kept = e.endEvents[0].contactId;
	cr_expect(tbContact_IsValid(kept));
	tbContactData data = tbContact_GetData(kept);
	cr_expect(data.shapeIdA.index1 == e.endEvents[0].shapeIdA.index1 && data.manifold.pointCount == 0);

	// Touching again, then the ball destroyed: the end event names the contact, which is gone.
	StepWorld(world, 30, 1.0f / 60.0f, 4);
	cr_assert(tbShape_GetContactData(ground, &data, 1) == 1);
	tbContactId touching = data.contactId;
	tbDestroyShape(ball, true);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	e = tbWorld_GetContactEvents(world);
	cr_assert(e.endCount == 1);
	cr_expect(e.endEvents[0].contactId.index1 == touching.index1 &&
			  e.endEvents[0].contactId.generation == touching.generation);
	cr_expect(tbContact_IsValid(e.endEvents[0].contactId) == false);
	tbDestroyWorld(world);
}

// ---------------------------------------------------------------------------------------------
// tbManifoldPoint.totalNormalImpulse and baseSeparation

// A box of mass m resting on the ground, not allowed to sleep. Its momentum over one step changes by
// the contact's applied normal impulse less the weight's: m·Δv = Σ totalNormalImpulse − m·g·Δt,
// exactly, for everything the contact applied is counted (warm starts, sub-step and relaxing
// changes; no restitution here). At rest Δv is the solver's residue. So the points' sum is m·g·Δt
// within m·|Δv| plus float rounding of the sums (a few ulps of the per-sub-step impulses summed over
// the sub-steps and passes: 1e-5 of m·g·Δt is well above that).
Test(v32_fields, total_normal_impulse_of_a_resting_box_is_its_weight_times_the_step)
{
	for (int method = 0; method < tb_solverMethodCount; ++method)
	{
		tbWorldDef worldDef = tbDefaultWorldDef();
		worldDef.solver = (tbSolverMethod)method;
		tbWorldId world = tbCreateWorld(&worldDef);
		tbShapeId ground = CreateGround(world, tbMakeVec2(0.0f, -0.5f), 5.0f, 0.5f, NULL);
		tbBodyDef def = tbDefaultBodyDef();
		def.type = tb_dynamicBody;
		def.position = tbMakeVec2(0.0f, 0.5f);
		def.enableSleep = false;
		tbShapeDef shapeDef = tbDefaultShapeDef();
		shapeDef.density = 3.0f;
		tbBodyId box = CreateBoxFromDef(world, &def, 0.5f, 0.5f, &shapeDef);
		float dt = 1.0f / 60.0f;
		StepWorld(world, 120, dt, 4);
		float v0 = tbBody_GetLinearVelocity(box).y;
		tbWorld_Step(world, dt, 4);
		float v1 = tbBody_GetLinearVelocity(box).y;
		tbContactData data;
		cr_assert(tbShape_GetContactData(ground, &data, 1) == 1);
		float m = tbBody_GetMass(box);
		float sum = 0.0f;
		for (int j = 0; j < data.manifold.pointCount; ++j)
		{
			sum += data.manifold.points[j].totalNormalImpulse;
			cr_expect(data.manifold.points[j].totalNormalImpulse > 0.0f);
		}
		// The manifold's normal points from the ground (A) to the box (B): the box is pushed up.
		float weight = m * 10.0f * dt;
		float tolerance = m * fabsf(v1 - v0) + 1e-5f * weight;
		cr_expect(fabsf(sum - weight) <= tolerance, "method %d: Σ total %g, m·g·Δt %g, tolerance %g", method,
				  (double)sum, (double)weight, (double)tolerance);
		tbDestroyWorld(world);
	}
}

// A speculative point that never pushed has total 0 (v3.2: how a game tells a near miss from a
// touch): a ball falling past the ground's edge gets speculative points but no impulse.
Test(v32_fields, total_normal_impulse_is_zero_for_a_point_that_never_pushed)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbShapeId ground = CreateGround(world, tbMakeVec2(0.0f, -0.5f), 1.0f, 0.5f, NULL);
	tbBodyId body;
	// Moving up and slowing: its lowest point comes within the speculative margin of the ground's
	// top face while always moving away from it.
	CreateBall(world, tbMakeVec2(0.0f, 0.26f), tbMakeVec2(0.0f, 1.0f), 0.25f, NULL, &body);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	tbContactData data;
	if (tbShape_GetContactData(ground, &data, 1) == 1)
	{
		for (int j = 0; j < data.manifold.pointCount; ++j)
		{
			cr_expect(data.manifold.points[j].totalNormalImpulse == 0.0f);
		}
	}
	tbDestroyWorld(world);
}

// baseSeparation is what the narrow phase measured. With recycling off every step measures anew, so
// it equals the separation; with recycling on, the recycled steps move the separation with the
// bodies and keep the base.
Test(v32_fields, base_separation_is_the_narrow_phase_measure)
{
	for (int recycle = 0; recycle < 2; ++recycle)
	{
		tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
		if (recycle == 0)
		{
			tbWorld_SetContactRecycleDistance(world, 0.0f);
		}
		tbShapeId ground = CreateGround(world, tbMakeVec2(0.0f, -0.5f), 5.0f, 0.5f, NULL);
		tbBodyDef def = tbDefaultBodyDef();
		def.type = tb_dynamicBody;
		def.position = tbMakeVec2(0.0f, 0.5f);
		def.enableSleep = false;
		CreateBoxFromDef(world, &def, 0.5f, 0.5f, NULL);
		float lastBase = NAN;
		int recycledSteps = 0, keptBase = 0;
		for (int i = 0; i < 60; ++i)
		{
			tbWorld_Step(world, 1.0f / 60.0f, 4);
			tbContactData data;
			cr_assert(tbShape_GetContactData(ground, &data, 1) == 1);
			const tbManifoldPoint* p = data.manifold.points;
			int recycled = tbWorld_GetCounters(world).recycledContactCount;
			if (recycle == 0)
			{
				cr_expect(recycled == 0 && p->baseSeparation == p->separation, "step %d: base %g, separation %g", i,
						  (double)p->baseSeparation, (double)p->separation);
			}
			else if (recycled > 0)
			{
				recycledSteps += 1;
				keptBase += p->baseSeparation == lastBase ? 1 : 0;
			}
			lastBase = p->baseSeparation;
		}
		if (recycle == 1)
		{
			cr_expect(recycledSteps > 10 && keptBase == recycledSteps, "recycled %d steps, base kept in %d",
					  recycledSteps, keptBase);
		}
		tbDestroyWorld(world);
	}
}

// ---------------------------------------------------------------------------------------------
// tbWorldDef.enableContactSoftening

// A 1 kg box resting on a 100 kg box. A soft contact at rest is a spring: each point holds
// λᵢ = normalMassᵢ·h·ω²·|s| per sub-step (the biased pass's zero increment), and the points together
// hold the top box's weight, m·g·h; so |s| = m·g / (ω²·Σ normalMassᵢ). Unit boxes: a point's normal
// mass is 1 / (Σ over both bodies of 1/m + (½)²/I), I = m/6, which is 1/(2.5/1 + 2.5/100). Without
// softening the pair settles at 1.75 × 30 Hz; with it, v3.2's rule gives
// max(½, 1/100) × min(30 Hz, ⅛ × 240 Hz) = 15 Hz, so the top box sinks (52.5/15)² = 12.25 times deeper.
static float RestingOverlap(bool soften, float* predicted)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.enableContactSoftening = soften;
	tbWorldId world = tbCreateWorld(&worldDef);
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 5.0f, 0.5f, NULL);
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	def.enableSleep = false;
	tbShapeDef heavy = tbDefaultShapeDef();
	heavy.density = 100.0f;
	def.position = tbMakeVec2(0.0f, 0.5f);
	CreateBoxFromDef(world, &def, 0.5f, 0.5f, &heavy);
	def.position = tbMakeVec2(0.0f, 1.5f);
	tbBodyId top = CreateBoxFromDef(world, &def, 0.5f, 0.5f, NULL);
	StepWorld(world, 240, 1.0f / 60.0f, 4);
	tbContactData data;
	cr_assert(tbBody_GetContactData(top, &data, 1) == 1);
	float depth = 0.0f;
	for (int j = 0; j < data.manifold.pointCount; ++j)
	{
		depth += -data.manifold.points[j].separation / (float)data.manifold.pointCount;
	}
	float normalMass = 1.0f / (2.5f + 2.5f / 100.0f);
	float hertz = soften ? 15.0f : 52.5f;
	float omega = 2.0f * TB_PI * hertz;
	*predicted = 1.0f * 10.0f / (omega * omega * 2.0f * normalMass);
	tbDestroyWorld(world);
	return depth;
}

Test(v32_fields, contact_softening_softens_a_light_body_on_a_heavy_one)
{
	float predictedHard, predictedSoft;
	float hard = RestingOverlap(false, &predictedHard);
	float soft = RestingOverlap(true, &predictedSoft);
	// The spring law holds to the residue of the relaxing passes and the lean of the stack: 10 %.
	cr_expect(fabsf(soft - predictedSoft) < 0.1f * predictedSoft, "softened depth %g m, predicted %g m", (double)soft,
			  (double)predictedSoft);
	cr_expect(fabsf(hard - predictedHard) < 0.1f * predictedHard, "default depth %g m, predicted %g m", (double)hard,
			  (double)predictedHard);
}

// ---------------------------------------------------------------------------------------------
// Allocator hooks (v3.2's b2AllocFcn and b2FreeFcn): the free hook hears the size its allocation
// was asked for.

#define MAX_BLOCKS 4096
static void* s_blocks[MAX_BLOCKS];
static size_t s_sizes[MAX_BLOCKS];
static int s_blockCount;
static int s_mismatches;

static void* SizedAlloc(size_t size, int alignment)
{
	void* p = aligned_alloc((size_t)alignment, size);
	if (s_blockCount < MAX_BLOCKS)
	{
		s_blocks[s_blockCount] = p;
		s_sizes[s_blockCount] = size;
		s_blockCount += 1;
	}
	return p;
}

static void SizedFree(void* memory, size_t size)
{
	for (int i = 0; i < s_blockCount; ++i)
	{
		if (s_blocks[i] == memory)
		{
			s_mismatches += s_sizes[i] != size ? 1 : 0;
			s_blocks[i] = s_blocks[s_blockCount - 1];
			s_sizes[i] = s_sizes[s_blockCount - 1];
			s_blockCount -= 1;
			break;
		}
	}
	free(memory);
}

Test(v32_fields, free_hook_hears_the_allocated_size)
{
	s_blockCount = 0;
	s_mismatches = 0;
	tbSetAllocator(SizedAlloc, SizedFree);
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 5.0f, 0.5f, NULL);
	for (int i = 0; i < 20; ++i)
	{
		CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 0.5f + 1.1f * (float)i), 0.5f, 0.5f, 1.0f);
	}
	StepWorld(world, 60, 1.0f / 60.0f, 4);
	tbDestroyWorld(world);
	tbSetAllocator(NULL, NULL);
	cr_expect(s_mismatches == 0, "%d frees with another size than allocated", s_mismatches);
	cr_expect(s_blockCount == 0, "%d blocks not freed", s_blockCount);
}

// ---------------------------------------------------------------------------------------------
// tbDebugDraw's fields

typedef struct DrawLog
{
	int lines, points, strings, transforms, bounds, polygons;
	float longestLine;		   ///< m
	char lastString[64];
	tbHexColor pointColors[64];
	int pointColorCount;
} DrawLog;

static void LogLine(tbPos p1, tbPos p2, tbHexColor color, void* context)
{
	(void)color;
	DrawLog* log = context;
	log->lines += 1;
	float length = tbDistance(tbToVec2(p1), tbToVec2(p2));
	log->longestLine = length > log->longestLine ? length : log->longestLine;
}

static void LogPoint(tbPos p, float size, tbHexColor color, void* context)
{
	(void)p, (void)size;
	DrawLog* log = context;
	if (log->pointColorCount < 64)
	{
		log->pointColors[log->pointColorCount++] = color;
	}
	log->points += 1;
}

static void LogString(tbPos p, const char* s, tbHexColor color, void* context)
{
	(void)p, (void)color;
	DrawLog* log = context;
	log->strings += 1;
	strncpy(log->lastString, s, sizeof(log->lastString) - 1);
}

static void LogTransform(tbWorldTransform transform, void* context)
{
	(void)transform;
	((DrawLog*)context)->transforms += 1;
}

static void LogBounds(tbAABB box, tbHexColor color, void* context)
{
	(void)box, (void)color;
	((DrawLog*)context)->bounds += 1;
}

static void LogPolygon(tbWorldTransform transform, const tbVec2* vertices, int count, float radius, tbHexColor color,
					   void* context)
{
	(void)transform, (void)vertices, (void)count, (void)radius, (void)color;
	((DrawLog*)context)->polygons += 1;
}

/// Only the functions and flags given: everything else off.
static DrawLog DrawWith(tbWorldId world, tbDebugDraw draw)
{
	DrawLog log;
	memset(&log, 0, sizeof(log));
	draw.DrawLineFcn = LogLine;
	draw.DrawPointFcn = LogPoint;
	draw.DrawStringFcn = LogString;
	draw.DrawTransformFcn = LogTransform;
	draw.DrawBoundsFcn = LogBounds;
	draw.DrawSolidPolygonFcn = LogPolygon;
	draw.context = &log;
	tbWorld_Draw(world, &draw);
	return log;
}

static tbDebugDraw NothingDrawn(void)
{
	tbDebugDraw draw = tbDefaultDebugDraw();
	draw.drawShapes = false;
	return draw;
}

Test(v32_fields, debug_draw_defaults_are_box2d_v32s)
{
	tbDebugDraw d = tbDefaultDebugDraw();
	cr_expect(d.DrawPolygonFcn != NULL && d.DrawSolidPolygonFcn != NULL && d.DrawCircleFcn != NULL &&
			  d.DrawSolidCircleFcn != NULL && d.DrawSolidCapsuleFcn != NULL && d.DrawLineFcn != NULL &&
			  d.DrawTransformFcn != NULL && d.DrawPointFcn != NULL && d.DrawStringFcn != NULL && d.DrawBoundsFcn != NULL);
	cr_expect(d.drawingBounds.lowerBound.x == -FLT_MAX && d.drawingBounds.upperBound.y == FLT_MAX);
	cr_expect(d.forceScale == 1.0f && d.jointScale == 1.0f);
	cr_expect(d.drawShapes && d.drawJoints == false && d.drawJointExtras == false && d.drawBounds == false &&
			  d.drawMass == false && d.drawBodyNames == false && d.drawContacts == false && d.drawGraphColors == false &&
			  d.drawContactNormals == false && d.drawContactForces == false && d.drawFrictionForces == false &&
			  d.drawContactFeatures == false && d.drawIslands == false && d.drawAnchorA == false &&
			  d.drawChainNormals == false && d.context == NULL);
}

// Two boxes of 2 kg resting apart on the ground, one named: what each flag adds, counted.
Test(v32_fields, debug_draw_flags_each_draw_what_they_name)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 10.0f, 0.5f, NULL);
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	def.enableSleep = false;
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.density = 2.0f;
	def.position = tbMakeVec2(-3.0f, 0.5f);
	def.name = "left";
	CreateBoxFromDef(world, &def, 0.5f, 0.5f, &shapeDef);
	def.position = tbMakeVec2(3.0f, 0.5f);
	def.name = NULL;
	CreateBoxFromDef(world, &def, 0.5f, 0.5f, &shapeDef);
	float dt = 1.0f / 60.0f;
	StepWorld(world, 60, dt, 4);

	tbDebugDraw draw = NothingDrawn();
	DrawLog none = DrawWith(world, draw);
	cr_expect(none.lines + none.points + none.strings + none.transforms + none.bounds + none.polygons == 0);

	draw = NothingDrawn();
	draw.drawShapes = true;
	cr_expect(DrawWith(world, draw).polygons == 3);
	draw.drawingBounds = (tbAABB){{-5.0f, 0.0f}, {-1.0f, 2.0f}}; // the left box and the ground
	cr_expect(DrawWith(world, draw).polygons == 2);

	draw = NothingDrawn();
	draw.drawBounds = true;
	cr_expect(DrawWith(world, draw).bounds == 3);

	draw = NothingDrawn();
	draw.drawMass = true;
	DrawLog mass = DrawWith(world, draw);
	cr_expect(mass.transforms == 2 && mass.strings == 2 && strcmp(mass.lastString, "2.00 kg") == 0, "'%s'",
			  mass.lastString);

	draw = NothingDrawn();
	draw.drawBodyNames = true;
	DrawLog names = DrawWith(world, draw);
	cr_expect(names.strings == 1 && strcmp(names.lastString, "left") == 0);

	// Two points on each box's bottom face; resting ones persisted (blue).
	draw = NothingDrawn();
	draw.drawContacts = true;
	DrawLog contacts = DrawWith(world, draw);
	cr_expect(contacts.points == 4);
	for (int i = 0; i < contacts.pointColorCount; ++i)
	{
		cr_expect(contacts.pointColors[i] == tb_colorBlue);
	}
	// Graph colours: both contacts are with the ground (one colour each box may share).
	draw.drawGraphColors = true;
	DrawLog colors = DrawWith(world, draw);
	cr_expect(colors.points == 4);
	for (int i = 0; i < colors.pointColorCount; ++i)
	{
		bool isGraphColor = false;
		for (int k = 0; k <= TB_GRAPH_COLOR_COUNT; ++k)
		{
			isGraphColor = isGraphColor || colors.pointColors[i] == tbGetGraphColor(k);
		}
		cr_expect(isGraphColor);
	}

	// Contact forces: each box's two lines sum to its weight, 20 N; with forceScale 0.1 m/N the
	// longest line is at most 2 m and at least 1 m (the larger share of 20 N).
	draw = NothingDrawn();
	draw.drawContactForces = true;
	draw.forceScale = 0.1f;
	DrawLog forces = DrawWith(world, draw);
	cr_expect(forces.lines == 4 && forces.strings == 4);
	cr_expect(forces.longestLine >= 1.0f - 1e-3f && forces.longestLine <= 2.0f + 1e-3f, "longest %g m",
			  (double)forces.longestLine);

	draw = NothingDrawn();
	draw.drawContactFeatures = true;
	cr_expect(DrawWith(world, draw).strings == 4);
	draw = NothingDrawn();
	draw.drawContactNormals = true;
	DrawLog normals = DrawWith(world, draw);
	cr_expect(normals.lines == 4 && fabsf(normals.longestLine - 0.3f) < 1e-5f);
	draw = NothingDrawn();
	draw.drawFrictionForces = true;
	cr_expect(DrawWith(world, draw).lines == 4);

	// Islands: the two boxes touch only the ground, so two islands.
	draw = NothingDrawn();
	draw.drawIslands = true;
	cr_expect(DrawWith(world, draw).bounds == 2);

	// A NaN or negative scale is refused, and nothing is drawn.
	tbSetErrorCallback(RecordError, NULL);
	float badScales[2] = {NAN, -1.0f};
	for (int i = 0; i < 2; ++i)
	{
		draw = NothingDrawn();
		draw.drawShapes = true;
		draw.forceScale = badScales[i];
		int before = s_errors;
		cr_expect(DrawWith(world, draw).polygons == 0);
		ExpectError(before, "tbWorld_Draw", "forceScale");
		draw.forceScale = 1.0f;
		draw.jointScale = badScales[i];
		before = s_errors;
		cr_expect(DrawWith(world, draw).polygons == 0);
		ExpectError(before, "tbWorld_Draw", "jointScale");
	}
	tbSetErrorCallback(NULL, NULL);
	tbDestroyWorld(world);
}

// Joints: drawn only with drawJoints; their size follows jointScale; the extras add the constraint
// force line (forceScale m/N) and its value.
Test(v32_fields, debug_draw_joint_scale_and_extras)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	tbBodyId ground = CreateBody(world, tb_staticBody, tbVec2_zero);
	tbBodyId bob = CreateDiscOfMass(world, tbMakeVec2(0.0f, -1.0f), 0.1f, 1.0f);
	tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
	def.base.bodyIdA = ground;
	def.base.bodyIdB = bob;
	def.base.localFrameB.p = tbMakeVec2(0.0f, 1.0f);
	tbCreateRevoluteJoint(world, &def);
	StepWorld(world, 10, 1.0f / 60.0f, 4);

	tbDebugDraw draw = NothingDrawn();
	cr_expect(DrawWith(world, draw).lines == 0);
	draw.drawJoints = true;
	DrawLog one = DrawWith(world, draw);
	draw.jointScale = 3.0f;
	DrawLog three = DrawWith(world, draw);
	cr_expect(one.lines > 0 && fabsf(three.longestLine - 3.0f * one.longestLine) < 1e-4f, "%g then %g",
			  (double)one.longestLine, (double)three.longestLine);

	// The pin holds the hanging 1 kg bob: 10 N, drawn 1 m long at 0.1 m/N.
	draw.jointScale = 1.0f;
	draw.drawJointExtras = true;
	draw.forceScale = 0.1f;
	DrawLog extras = DrawWith(world, draw);
	cr_expect(extras.lines == one.lines + 1 && extras.strings == 1);
	cr_expect(fabsf(extras.longestLine - 1.0f) < 0.02f, "force line %g m", (double)extras.longestLine);
	tbDestroyWorld(world);
}

// ---------------------------------------------------------------------------------------------
// tbCounters and tbRayResult's new numbers

static void* RunTaskNow(tbTaskCallback* task, void* taskContext, void* userContext)
{
	(void)userContext;
	task(taskContext);
	return NULL; // ran before returning: nothing to finish
}

static void FinishNothing(void* userTask, void* userContext)
{
	(void)userTask, (void)userContext;
}

// A pyramid of 10 rows (55 boxes) on the ground and one joint: the counts v3.2 adds. On the tree
// broad phase, v3.2's only one, whose heights and visits it counts (the weld pulls the top of the
// pyramid down, and the automatic choice may take this small pile off the tree).
Test(v32_fields, counters_count_what_v32_counts)
{
	for (int tasks = 0; tasks < 2; ++tasks)
	{
		tbWorldDef def = tbDefaultWorldDef();
		def.broadPhase = tb_broadPhaseTree;
		if (tasks)
		{
			def.workerCount = 2;
			def.enqueueTask = RunTaskNow;
			def.finishTask = FinishNothing;
		}
		tbWorldId world = tbCreateWorld(&def);
		CreateGround(world, tbMakeVec2(0.0f, -0.5f), 20.0f, 0.5f, NULL);
		CreateGround(world, tbMakeVec2(30.0f, -0.5f), 5.0f, 0.5f, NULL);
		tbBodyId first = TB_NULL_BODY_ID, second = TB_NULL_BODY_ID;
		for (int row = 0; row < 10; ++row)
		{
			for (int i = 0; i < 10 - row; ++i)
			{
				tbVec2 p = {(float)i * 1.05f + 0.525f * (float)row - 5.0f, 0.5f + (float)row};
				tbBodyId box = CreateBox(world, tb_dynamicBody, p, 0.5f, 0.5f, 1.0f);
				first = row == 9 ? box : first;
				second = row == 8 && i == 0 ? box : second;
			}
		}
		tbWeldJointDef weld = tbDefaultWeldJointDef();
		weld.base.bodyIdA = first;
		weld.base.bodyIdB = second;
		tbCreateWeldJoint(world, &weld);
		StepWorld(world, 10, 1.0f / 60.0f, 4);
		tbCounters c = tbWorld_GetCounters(world);
		cr_expect(c.bodyCount == 57 && c.jointCount == 1);
		cr_expect(c.byteCount == tbGetByteCount() && c.byteCount > 0);
		cr_expect(c.stackUsed > 0);
		cr_expect(c.staticTreeHeight == 1 && c.treeHeight > 0, "tree heights %d, %d", c.staticTreeHeight, c.treeHeight);
		// Every touching contact of the awake pile is solved, in a colour or the overflow; so are those
		// whose points are still speculative (not counted as touching): between the two counts.
		int coloured = c.overflowCount;
		for (int k = 0; k < 24; ++k)
		{
			coloured += c.colorCounts[k];
		}
		cr_expect(coloured >= c.touchingCount && coloured <= c.awakeContactCount && coloured > 0,
				  "coloured %d, touching %d, awake %d", coloured, c.touchingCount, c.awakeContactCount);
		cr_expect(c.awakeContactCount >= c.touchingCount && c.awakeContactCount <= c.contactCount);
		cr_expect(tasks ? c.taskCount > 0 : c.taskCount == 0, "tasks %d", c.taskCount);

		tbRayResult ray = tbWorld_CastRayClosest(world, tbMakeVec2(-20.0f, 0.5f), tbMakeVec2(40.0f, 0.0f),
												 tbDefaultQueryFilter());
		cr_expect(ray.hit && ray.leafVisits >= 1 && ray.nodeVisits >= 1, "visits %d nodes, %d leaves", ray.nodeVisits,
				  ray.leafVisits);
		tbDestroyWorld(world);
	}
}

// The profile's new parts lie within the stages that hold them (each is timed inside its stage;
// the tolerance is the float rounding of the millisecond sums).
Test(v32_fields, profile_parts_lie_within_their_stages)
{
	tbWorldId world = CreateWorld(tbMakeVec2(0.0f, -10.0f));
	CreateGround(world, tbMakeVec2(0.0f, -0.5f), 10.0f, 0.5f, NULL);
	tbBodyDef def = tbDefaultBodyDef();
	def.type = tb_dynamicBody;
	def.isBullet = true;
	def.position = tbMakeVec2(0.0f, 3.0f);
	def.linearVelocity = tbMakeVec2(0.0f, -200.0f);
	CreateBoxFromDef(world, &def, 0.1f, 0.1f, NULL);
	tbBodyId a = CreateBox(world, tb_dynamicBody, tbMakeVec2(3.0f, 0.5f), 0.5f, 0.5f, 1.0f);
	tbBodyId b = CreateBox(world, tb_dynamicBody, tbMakeVec2(3.0f, 1.5f), 0.5f, 0.5f, 1.0f);
	tbWeldJointDef weld = tbDefaultWeldJointDef();
	weld.base.bodyIdA = a;
	weld.base.bodyIdB = b;
	weld.base.forceThreshold = 1.0f; // joint events to gather
	tbCreateWeldJoint(world, &weld);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	tbProfile p = tbWorld_GetProfile(world);
	float eps = 1e-3f;
	cr_expect(p.constraints >= 0.0f && p.constraints <= p.solve + eps, "constraints %g, solve %g", (double)p.constraints,
			  (double)p.solve);
	cr_expect(p.jointEvents >= 0.0f && p.jointEvents <= p.storeImpulses + eps);
	cr_expect(p.bullets > 0.0f && p.bullets <= p.continuous + eps, "bullets %g, continuous %g", (double)p.bullets,
			  (double)p.continuous);
	tbDestroyWorld(world);
}
