// The platformer sample's character (samples/character.c, on the mover kit) run through the
// catalogue's platformer level with scripted input: walk right at 6 m/s, jump once a second. Its
// path is asserted against closed forms and the level's geometry.
#include "catalogue.h"
#include "character.h"
#include "scene.h"

#include <criterion/criterion.h>

#include <math.h>
#include <string.h>

static float s_deepest;

static bool DeepestStaticPlane(tbShapeId shapeId, const tbPlaneResult* result, void* context)
{
	(void)context;
	if (tbBody_GetType(tbShape_GetBody(shapeId)) != tb_dynamicBody && result->plane.offset > s_deepest)
	{
		s_deepest = result->plane.offset;
	}
	return true;
}

Test(character, walks_jumps_and_pushes_through_the_platformer_level)
{
	Scene* scene = Catalogue_Build("platformer");
	cr_assert_not_null(scene);
	SceneWorld sw = Scene_BuildWorld(scene, NULL);
	int hero = -1;
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		hero = strcmp(scene->bodies[i].name, "hero") == 0 ? i : hero;
	}
	cr_assert_geq(hero, 0);
	// The scene's dynamic hero is replaced by the mover character, feet where its capsule's were.
	tbVec2 start = tbBody_GetPosition(sw.bodyIds[hero]);
	tbDestroyBody(sw.bodyIds[hero]);
	Character c = Character_Create(sw.worldId, (tbVec2){start.x, start.y - 0.7f}, 0.3f, 1.4f);
	const float dt = scene->timeStep, speed = 6.0f;

	tbVec2 before[64];
	cr_assert_leq(scene->bodyCount, 64);
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		before[i] = i == hero ? tbVec2_zero : tbBody_GetPosition(sw.bodyIds[i]);
	}
	tbQueryFilter filter = tbDefaultQueryFilter();
	filter.maskBits &= ~CHARACTER_CATEGORY;
	bool wantJump = false;
	float takeoff = 0.0f, takeoffX = -100.0f, apex = 0.0f;
	int flatJumps = 0;
	s_deepest = 0.0f;
	for (int frame = 0; frame < 900; ++frame)
	{
		wantJump = wantJump || frame % 60 == 30;
		bool jump = wantJump && c.onGround;
		if (jump)
		{
			// The last jump's apex, if it took off from level ground in the open (−15 < x < 0: past
			// the ledge at x −22…−16, whose underside at y = 3 stops a 1.4 m character's head at 1.6 m).
			if (takeoffX > -15.0f && takeoffX < 0.0f)
			{
				// Discrete closed form: the jump sets v0 = 9 m/s, then each frame takes g·dt off before
				// moving, so the rise is dt·Σ_{k=0}^{n}(v0 − k·g·dt) up to the last k with v0 − k·g·dt ≥ 0:
				// n = 27 at 60 Hz and g = 20 m/s², a rise of (28·9 − 20/60·27·28/2)/60 = 2.1 m (the
				// continuous v0²/2g would be 2.025 m).
				cr_expect_float_eq(apex - takeoff, 2.1f, 1e-3f, "jump rose %.4f m", (double)(apex - takeoff));
			}
			flatJumps += c.position.x < 0.0f ? 1 : 0;
			wantJump = false;
			takeoff = c.position.y;
			takeoffX = c.position.x;
			apex = takeoff;
			// On level ground the character rests a linear slop deep (the plane solver's allowance).
			if (c.position.x < 0.0f)
			{
				cr_expect_float_eq(c.position.y, -TB_LINEAR_SLOP, 1e-4f, "standing at y = %.5f", (double)c.position.y);
			}
		}
		Character_Step(&c, sw.worldId, speed, jump, dt);
		SceneWorld_Step(&sw, scene, scene->subSteps);
		apex = fmaxf(apex, c.position.y);
		// Never inside the level: the deepest static plane stays within the slop.
		tbWorld_CollideMover(sw.worldId, c.position, &c.capsule, filter, DeepestStaticPlane, NULL);
	}
	cr_expect_geq(flatJumps, 3);
	cr_expect_leq(s_deepest, TB_LINEAR_SLOP + 1e-4f, "%.5f m inside the level", (double)s_deepest);

	// It ends against the level's end wall (its face at x = 60), on the ground (y = 0 there).
	cr_expect_float_eq(c.position.x, 60.0f - 0.3f + TB_LINEAR_SLOP, 1e-4f, "ended at x = %.4f", (double)c.position.x);
	// Its body followed it (one step behind at most: the body reaches the pose during the step).
	tbVec2 body = tbBody_GetPosition(c.body);
	cr_expect_float_eq(body.x, c.position.x, 1e-3f);

	// The balls in the cup (x 46–52) were shoved aside by the character's kinematic body.
	int pushed = 0;
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		if (i == hero || scene->bodies[i].type != tb_dynamicBody)
		{
			continue;
		}
		tbVec2 now = tbBody_GetPosition(sw.bodyIds[i]);
		bool inCup = before[i].x > 46.0f && before[i].x < 52.0f;
		pushed += inCup && tbLength(tbSub(now, before[i])) > 0.1f ? 1 : 0;
	}
	cr_expect_geq(pushed, 4, "%d balls in the cup moved", pushed);
	SceneWorld_Destroy(&sw);
	Scene_Destroy(scene);
}
