// Bodies at run time: mass data set by hand and from the shapes, names, and the response to an
// impulse that follows from the mass data (Δv = J/m, Δω = (r × J)/I).
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include "error_recorder.h"

#include <math.h>

// A unit box (1 kg, I = 1/6 kg·m²) given mass 4 kg, inertia 2 kg·m² and centre (0.5, 0) by hand:
// an impulse (0, 4) N·s at the origin gives v = (0, 1) and ω = (r × J)/I with r = (−0.5, 0) from
// the centre of mass, (−0.5·4)/2 = −1 rad/s. ApplyMassFromShapes puts back 1 kg at the origin.
// Bad mass data is refused with the body unchanged.
Test(body, mass_data_by_hand_and_from_shapes, .init = SetupErrors, .fini = TeardownErrors)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = tbMakeVec2(0.0f, 0.0f);
	tbWorldId world = tbCreateWorld(&worldDef);
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeSquare(0.5f);
	tbCreatePolygonShape(body, &shapeDef, &box);
	cr_assert_float_eq(tbBody_GetMass(body), 1.0f, 1e-6f);

	tbMassData md = {4.0f, {0.5f, 0.0f}, 2.0f};
	cr_assert(tbBody_SetMassData(body, md));
	tbMassData got = tbBody_GetMassData(body);
	cr_assert(got.mass == 4.0f && got.rotationalInertia == 2.0f && got.center.x == 0.5f && got.center.y == 0.0f);
	cr_assert(tbBody_ApplyLinearImpulse(body, tbMakeVec2(0.0f, 4.0f), tbMakeVec2(0.0f, 0.0f), true));
	cr_assert_float_eq(tbBody_GetLinearVelocity(body).y, 1.0f, 1e-6f);
	cr_assert_float_eq(tbBody_GetAngularVelocity(body), -1.0f, 1e-6f);

	int before = s_errors;
	tbMassData bad = {-1.0f, {0.0f, 0.0f}, 1.0f};
	cr_assert(tbBody_SetMassData(body, bad) == false);
	ExpectError(before, "tbBody_SetMassData", "massData.mass");
	cr_assert_float_eq(tbBody_GetMass(body), 4.0f, 0.0f);

	tbBody_ApplyMassFromShapes(body);
	got = tbBody_GetMassData(body);
	cr_assert_float_eq(got.mass, 1.0f, 1e-6f);
	cr_assert_float_eq(got.rotationalInertia, 1.0f / 6.0f, 1e-6f);
	cr_assert_float_eq(got.center.x, 0.0f, 1e-6f);

	tbBody_SetName(body, "crate");
	cr_assert_str_eq(tbBody_GetName(body), "crate");
	tbDestroyWorld(world);
}
