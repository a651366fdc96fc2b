// The public headers compile as C++ (g++ -std=c++17 -Wall -Wextra -Wpedantic -Werror) and the
// library links from C++. The numbers checked are closed forms: a unit box has mass 1 at density 1
// and 1/60 s of free fall from rest under g = −10 gives v = −10/60 m/s (symplectic Euler, exact
// up to float rounding).
#include <criterion/criterion.h>

#include <tumble/tumble.h>

Test(cpp, headers_compile_and_link)
{
	tbWorldDef def = tbDefaultWorldDef();
	tbWorldId world = tbCreateWorld(&def);
	cr_assert(tbWorld_IsValid(world));
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	tbPolygon box = tbMakeBox(0.5f, 0.5f);
	tbShapeId shape = tbCreatePolygonShape(body, &shapeDef, &box);
	cr_assert(tbShape_IsValid(shape));
	float mass = tbBody_GetMass(body);
	cr_assert_float_eq(mass, 1.0f, 1e-6f);
	tbWorld_Step(world, 1.0f / 60.0f, 1);
	tbVec2 v = tbBody_GetLinearVelocity(body);
	cr_assert_float_eq(v.y, -10.0f / 60.0f, 1e-6f);
	tbDestroyWorld(world);
	cr_assert(tbWorld_IsValid(world) == false);
	cr_assert(TB_IS_NULL(TB_NULL_BODY_ID));
}
