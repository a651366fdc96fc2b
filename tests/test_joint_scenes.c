// The catalogue's game scenes on joints — a door, a piston, a mouse drag, Newton's cradle on
// rods, a dynamic character on mover and pogo joints — each checked against what its joint
// promises in closed form.
#include "catalogue.h"
#include "scene.h"

#include <criterion/criterion.h>

#include <math.h>

static SceneWorld Build(const char* name, Scene** scene, bool impactPropagation)
{
	*scene = Catalogue_Build(name);
	cr_assert_not_null(*scene, "%s is in the catalogue", name);
	SceneOverrides overrides = {0};
	overrides.impactPropagation = impactPropagation;
	SceneWorld world = Scene_BuildWorld(*scene, &overrides);
	cr_assert(tbWorld_IsValid(world.worldId));
	return world;
}

// The door swings open under the box's shove and stops at its 90° limit: the limit is a
// speculative constraint (it may close its gap within a sub-step, no more), so the door never
// passes it by more than the soft correction of one sub-step; bound 0.5° (measured 0.012°).
Test(joint_scenes, door_stops_at_its_limit)
{
	Scene* scene;
	SceneWorld world = Build("door", &scene, false);
	tbBodyId door = world.bodyIds[1];
	float widest = 0.0f, narrowest = 0.0f;
	for (int step = 0; step < scene->steps; ++step)
	{
		SceneWorld_Step(&world, scene, scene->subSteps);
		float angle = tbRot_GetAngle(tbBody_GetRotation(door));
		widest = fmaxf(widest, angle);
		narrowest = fminf(narrowest, angle);
	}
	const float degree = TB_PI / 180.0f;
	cr_expect_leq(widest, 90.5f * degree, "opened to %.3f deg", (double)(widest / degree));
	cr_expect_geq(widest, 89.0f * degree, "the shove should open it fully (%.3f deg)", (double)(widest / degree));
	cr_expect_geq(narrowest, -0.5f * degree, "closed past 0 by %.3f deg", (double)(-narrowest / degree));
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
}

// The piston's motor holds its speed while nothing loads it (1 m/s, within 1 %: measured exact to
// 5 digits), pushes the boxes (the first moves on), and stops at its 4 m limit (within 1 cm).
Test(joint_scenes, piston_keeps_its_speed_and_stops_at_its_limit)
{
	Scene* scene;
	SceneWorld world = Build("piston", &scene, false);
	tbBodyId pusher = world.bodyIds[1], box = world.bodyIds[2];
	float start = tbBody_GetPosition(pusher).x, boxStart = tbBody_GetPosition(box).x;
	for (int step = 0; step < scene->steps; ++step)
	{
		SceneWorld_Step(&world, scene, scene->subSteps);
		if (step == 45)
		{
			float speed = tbBody_GetLinearVelocity(pusher).x;
			cr_expect(fabsf(speed - 1.0f) <= 0.01f, "unloaded piston at %.5f m/s", (double)speed);
		}
	}
	cr_expect(fabsf(tbBody_GetPosition(pusher).x - start - 4.0f) <= 0.01f, "piston stopped at %.4f m",
			  (double)(tbBody_GetPosition(pusher).x - start));
	cr_expect_gt(tbBody_GetPosition(box).x - boxStart, 1.0f, "the first box was pushed %.3f m",
				 (double)(tbBody_GetPosition(box).x - boxStart));
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
}

// The dragged box follows the mouse. Its spring (4 Hz) holds it below the target by the static
// sag g/ω² = 10/(8π)² = 0.0158 m; the target moves slowly (ω = 1 rad/s ≪ 8π), so once settled
// (after 2 s) the box stays within 0.02 m of the target (measured 0.0165 m).
Test(joint_scenes, mouse_drag_follows_the_target)
{
	Scene* scene;
	SceneWorld world = Build("mouse_drag", &scene, false);
	tbBodyId mouse = world.bodyIds[1], box = world.bodyIds[2];
	float worst = 0.0f, sag = 0.0f;
	for (int step = 0; step < scene->steps; ++step)
	{
		SceneWorld_Step(&world, scene, scene->subSteps);
		if (step >= 120)
		{
			tbVec2 m = tbBody_GetPosition(mouse), b = tbBody_GetPosition(box);
			worst = fmaxf(worst, hypotf(m.x - b.x, m.y - b.y));
			sag = m.y - b.y;
		}
	}
	const float omega = 2.0f * TB_PI * 4.0f;
	cr_expect_leq(worst, 0.02f, "box %.4f m from the target", (double)worst);
	cr_expect(fabsf(sag - 10.0f / (omega * omega)) <= 0.002f, "sag %.4f m, closed form %.4f m", (double)sag,
			  (double)(10.0f / (omega * omega)));
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
}

// Newton's cradle on rods with impact propagation: the first ball, released 1.5 m up, arrives at
// v0 = sqrt(2·g·h) = 5.477 m/s (measured 5.464: the sub-step discretisation, 0.25 %); the impact
// passes down the row and the last ball leaves at v0 (within 1 %) while the middle ones stay
// nearly at rest (≤ 2 % of v0; measured 0.072 m/s). Without propagation the speed is shared.
// The dynamic character walks at the mover's 2 m/s (nothing resists it before the boxes: within
// 1e-4 relative, float rounding) at the pogo's rest height (no sag: the pogo's push is a velocity
// target, not a force law; within 1 mm, measured at 1.5 s once the start has settled), then
// shoves the boxes: the mover's 100 N cap outweighs their friction (0.4·10 N each), so the first
// box moves on. Pushing (horizontal contact forces only: the character is frictionless), the
// height stays at the rest length too, within the same 1 mm (measured within 3.2e-5 m).
Test(joint_scenes, dynamic_character_walks_on_its_pogo)
{
	Scene* scene;
	SceneWorld world = Build("dynamic_character", &scene, false);
	tbBodyId character = world.bodyIds[1], box = world.bodyIds[2];
	tbJointId pogo = world.jointIds[0];
	cr_assert_eq(tbJoint_GetType(pogo), tb_pogoJoint);
	float boxStart = tbBody_GetPosition(box).x;
	float lowest = 1.0f, highest = 1.0f;
	for (int step = 0; step < scene->steps; ++step)
	{
		SceneWorld_Step(&world, scene, scene->subSteps);
		float height = tbBody_GetPosition(character).y;
		if (step == 89)
		{
			float speed = tbBody_GetLinearVelocity(character).x;
			cr_expect(fabsf(speed - 2.0f) < 2e-4f, "walking at %.6f m/s", (double)speed);
			cr_expect(fabsf(height - 1.0f) < 1e-3f, "walking %.5f m high, rest 1 m", (double)height);
			cr_expect(fabsf(tbPogoJoint_GetLength(pogo) - height) < 1e-5f, "the pogo's length is the height");
		}
		if (step >= 89)
		{
			lowest = fminf(lowest, height);
			highest = fmaxf(highest, height);
		}
	}
	cr_log_info("dynamic character: height %.6f..%.6f m while walking and pushing; first box moved %.3f m",
				(double)lowest, (double)highest, (double)(tbBody_GetPosition(box).x - boxStart));
	cr_expect(lowest > 0.999f && highest < 1.001f, "height %.6f..%.6f m", (double)lowest, (double)highest);
	cr_expect_gt(tbBody_GetPosition(box).x - boxStart, 1.0f, "the first box was shoved %.3f m",
				 (double)(tbBody_GetPosition(box).x - boxStart));
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
}

Test(joint_scenes, cradle_on_rods_passes_the_impact)
{
	for (int propagate = 0; propagate < 2; ++propagate)
	{
		Scene* scene;
		SceneWorld world = Build("newtons_cradle_joints", &scene, propagate == 1);
		float fastest[6] = {0.0f};
		for (int step = 0; step < 120; ++step)
		{
			SceneWorld_Step(&world, scene, scene->subSteps);
			for (int k = 1; k <= 5; ++k)
			{
				fastest[k] = fmaxf(fastest[k], fabsf(tbBody_GetLinearVelocity(world.bodyIds[k]).x));
			}
		}
		float v0 = sqrtf(2.0f * 10.0f * 1.5f);
		cr_expect(fabsf(fastest[1] - v0) <= 0.005f * v0, "striker at %.3f m/s", (double)fastest[1]);
		if (propagate)
		{
			cr_expect(fabsf(fastest[5] - fastest[1]) <= 0.01f * v0, "last ball %.3f m/s, striker %.3f m/s",
					  (double)fastest[5], (double)fastest[1]);
			for (int k = 2; k <= 4; ++k)
			{
				cr_expect_leq(fastest[k], 0.02f * v0, "ball %d moved at %.3f m/s", k, (double)fastest[k]);
			}
		}
		else
		{
			cr_expect_lt(fastest[5], 0.8f * v0, "without propagation the last ball shares the impact (%.3f)",
						 (double)fastest[5]);
		}
		SceneWorld_Destroy(&world);
		Scene_Destroy(scene);
	}
}

// Box2D v3's tumbler and spinner as v3 builds them: a dynamic drum (blade) on a motorised revolute
// joint to ground. The motor's torque is ample (1e8 N·m; unbounded), so after 1 s the drum turns
// at its motor speed, 25°/s (the blade at 5 rad/s), within 1 % — the load of the boxes it tumbles
// is far below the torque cap.
Test(joint_scenes, motorised_drum_and_blade_turn_at_the_motor_speed)
{
	const char* names[2] = {"tumbler_motor", "spinner_motor"};
	const float speeds[2] = {25.0f * TB_PI / 180.0f, 5.0f};
	const int rotor[2] = {1, 1};
	for (int k = 0; k < 2; ++k)
	{
		Scene* scene;
		SceneWorld world = Build(names[k], &scene, false);
		cr_assert_eq(scene->jointCount, 1);
		tbBodyId body = world.bodyIds[rotor[k]];
		cr_assert_eq(tbBody_GetType(body), tb_dynamicBody);
		for (int step = 0; step < 60; ++step)
		{
			SceneWorld_Step(&world, scene, scene->subSteps);
		}
		float w = tbBody_GetAngularVelocity(body);
		cr_expect(fabsf(w - speeds[k]) <= 0.01f * speeds[k], "%s turns at %.5f rad/s, motor %.5f", names[k], (double)w,
				  (double)speeds[k]);
		SceneWorld_Destroy(&world);
		Scene_Destroy(scene);
	}
}
