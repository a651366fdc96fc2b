// Explosions (tbWorld_Explode): the impulse each dynamic shape receives is impulsePerLength × the
// width it shows the blast × the falloff scale, at its point closest to the centre, away from it.
// Expected velocities are that impulse over the body's mass (Δv = J/m, Δω = (r × J)/I), computed
// here by hand; float arithmetic on numbers of order 1 gives a tolerance of 1e-5.
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include "error_recorder.h"
#include "test_helpers.h"

#include <math.h>
#include <string.h>

// A unit box (1 kg) centred 3 m to the right: closest point (2.5, 0), blast direction +x, width
// across it 1 m, so J = 2 N·s·m⁻¹ × 1 m = 2 N·s along +x through the centre line: v = (2, 0), no
// spin. A 2 m × 1 m box (2 kg) 3 m above shows its 2 m width: J = 4 N·s, v = (0, 2). A circle of
// radius 0.5 (π/4 kg) 3 m to the left shows 1 m: v = (−2/(π/4), 0). A static box is not moved.
Test(explosion, impulse_is_exposed_width_times_impulse_per_length)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId right = CreateBox(world, tb_dynamicBody, tbMakeVec2(3.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	tbBodyId above = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 3.0f), 1.0f, 0.5f, 1.0f);
	tbBodyId wall = CreateBox(world, tb_staticBody, tbMakeVec2(0.0f, -3.0f), 1.0f, 0.5f, 1.0f);
	tbBodyDef ballDef = tbDefaultBodyDef();
	ballDef.type = tb_dynamicBody;
	ballDef.position = tbMakeVec2(-3.0f, 0.0f);
	tbBodyId ball = tbCreateBody(world, &ballDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, 0.5f};
	tbCreateCircleShape(ball, &shapeDef, &circle);

	tbExplosionDef def = tbDefaultExplosionDef();
	def.position = tbMakeVec2(0.0f, 0.0f);
	def.radius = 5.0f;
	def.impulsePerLength = 2.0f;
	tbWorld_Explode(world, &def);

	tbVec2 v = tbBody_GetLinearVelocity(right);
	cr_assert(fabsf(v.x - 2.0f) < 1e-5f && fabsf(v.y) < 1e-5f, "right box v (%g, %g)", (double)v.x, (double)v.y);
	cr_assert(fabsf(tbBody_GetAngularVelocity(right)) < 1e-5f);
	v = tbBody_GetLinearVelocity(above);
	cr_assert(fabsf(v.x) < 1e-5f && fabsf(v.y - 2.0f) < 1e-5f, "upper box v (%g, %g)", (double)v.x, (double)v.y);
	v = tbBody_GetLinearVelocity(ball);
	float expected = -2.0f / (3.14159265f * 0.25f);
	cr_assert(fabsf(v.x - expected) < 1e-5f && fabsf(v.y) < 1e-5f, "ball v (%g, %g), expected (%g, 0)", (double)v.x,
			  (double)v.y, (double)expected);
	cr_assert(tbBody_GetPosition(wall).y == -3.0f && tbBody_GetLinearVelocity(wall).x == 0.0f);
	tbDestroyWorld(world);
}

// Falloff: a unit box whose nearest face is 5.5 m away, radius 5, falloff 2: scale (5 + 2 − 5.5)/2
// = 0.75, so v = 2 × 0.75 = 1.5 m/s. At 7.5 m (beyond radius + falloff) nothing happens, and a
// mask that excludes the box's category leaves it alone too.
Test(explosion, falloff_scales_and_ends_the_blast)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId near = CreateBox(world, tb_dynamicBody, tbMakeVec2(6.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	tbBodyId far = CreateBox(world, tb_dynamicBody, tbMakeVec2(0.0f, 8.0f), 0.5f, 0.5f, 1.0f);
	tbExplosionDef def = tbDefaultExplosionDef();
	def.radius = 5.0f;
	def.falloff = 2.0f;
	def.impulsePerLength = 2.0f;
	tbWorld_Explode(world, &def);
	cr_assert(fabsf(tbBody_GetLinearVelocity(near).x - 1.5f) < 1e-5f, "v %g", (double)tbBody_GetLinearVelocity(near).x);
	cr_assert(tbBody_GetLinearVelocity(far).y == 0.0f);

	def.maskBits = 0;
	tbWorld_Explode(world, &def);
	cr_assert(fabsf(tbBody_GetLinearVelocity(near).x - 1.5f) < 1e-5f, "a masked blast changed the box");
	tbDestroyWorld(world);
}

// A blast off a box's centre line turns it: centre (2, 0.25), unit box (1 kg, I = 1/6 kg·m²) at
// (3, 0): closest point (2.5, 0.25) on its left face, direction +x, width 1 m, J = (2, 0) N·s at
// r = (−0.5, 0.25) from the centre of mass: v = (2, 0), ω = (r × J)/I = (0 − 0.25·2)·6 = −3 rad/s.
Test(explosion, a_blast_off_the_centre_line_turns_the_body)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId box = CreateBox(world, tb_dynamicBody, tbMakeVec2(3.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	tbExplosionDef def = tbDefaultExplosionDef();
	def.position = tbMakeVec2(2.0f, 0.25f);
	def.radius = 2.0f;
	def.impulsePerLength = 2.0f;
	tbWorld_Explode(world, &def);
	tbVec2 v = tbBody_GetLinearVelocity(box);
	cr_assert(fabsf(v.x - 2.0f) < 1e-5f && fabsf(v.y) < 1e-5f, "v (%g, %g)", (double)v.x, (double)v.y);
	cr_assert(fabsf(tbBody_GetAngularVelocity(box) + 3.0f) < 1e-4f, "ω %g, expected −3",
			  (double)tbBody_GetAngularVelocity(box));
	tbDestroyWorld(world);
}

// A sleeping body in reach is woken and pushed.
Test(explosion, wakes_sleeping_bodies)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId box = CreateBox(world, tb_dynamicBody, tbMakeVec2(3.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	tbBody_SetAwake(box, false);
	cr_assert(tbBody_IsAwake(box) == false);
	tbExplosionDef def = tbDefaultExplosionDef();
	def.radius = 5.0f;
	def.impulsePerLength = 1.0f;
	tbWorld_Explode(world, &def);
	cr_assert(tbBody_IsAwake(box));
	cr_assert(fabsf(tbBody_GetLinearVelocity(box).x - 1.0f) < 1e-5f);
	tbDestroyWorld(world);
}

// Bad definitions are refused with an error naming the field, and nothing moves.
Test(explosion, bad_input_is_refused_without_change, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldId world = CreateWorld(tbVec2_zero);
	tbBodyId box = CreateBox(world, tb_dynamicBody, tbMakeVec2(3.0f, 0.0f), 0.5f, 0.5f, 1.0f);
	tbExplosionDef good = tbDefaultExplosionDef();
	good.radius = 5.0f;
	good.impulsePerLength = 1.0f;
	struct
	{
		const char* field;
		tbExplosionDef def;
	} cases[5];
	for (int i = 0; i < 5; ++i)
	{
		cases[i].def = good;
	}
	cases[0].field = "def->radius", cases[0].def.radius = NAN;
	cases[1].field = "def->radius", cases[1].def.radius = -1.0f;
	cases[2].field = "def->falloff", cases[2].def.falloff = -0.5f;
	cases[3].field = "def->impulsePerLength", cases[3].def.impulsePerLength = INFINITY;
	cases[4].field = "def->position", cases[4].def.position = tbMakeVec2(NAN, 0.0f);
	for (int i = 0; i < 5; ++i)
	{
		int before = s_errors;
		tbWorld_Explode(world, &cases[i].def);
		ExpectError(before, "tbWorld_Explode", cases[i].field);
		cr_assert(tbBody_GetLinearVelocity(box).x == 0.0f, "case %d moved the box", i);
	}
	int before = s_errors;
	tbWorld_Explode(world, NULL);
	ExpectError(before, "tbWorld_Explode", "def");
	tbDestroyWorld(world);
}
