// Determinism: the same scene gives bit-identical trajectories whatever the broad phase (every
// method reports the same pairs in the same order), and stepping the same scene twice gives the
// same bits. The scene is the shared catalogue's rain of mixed shapes, so contacts begin and end
// throughout.
#include <criterion/criterion.h>

#include "catalogue.h"
#include "scene.h"

#include "tumble/tumble.h"

#include <string.h>

/// FNV-1a over the bytes of every body's transform and velocities.
static uint64_t HashWorld(const SceneWorld* sw)
{
	uint64_t hash = 1469598103934665603ull;
	for (int i = 0; i < sw->bodyCount; ++i)
	{
		tbTransform xf = tbBody_GetTransform(sw->bodyIds[i]);
		tbVec2 v = tbBody_GetLinearVelocity(sw->bodyIds[i]);
		float w = tbBody_GetAngularVelocity(sw->bodyIds[i]);
		float values[7] = {xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y, w};
		const unsigned char* bytes = (const unsigned char*)values;
		for (size_t k = 0; k < sizeof(values); ++k)
		{
			hash = (hash ^ bytes[k]) * 1099511628211ull;
		}
	}
	return hash;
}

static uint64_t RunRain(tbBroadPhaseMethod method, int steps, int* contacts)
{
	Scene* scene = Catalogue_Build("rain");
	cr_assert_not_null(scene);
	SceneOverrides overrides;
	memset(&overrides, 0, sizeof(overrides));
	overrides.methods.broadPhase = method;
	overrides.methods.hasBroadPhase = true;
	SceneWorld sw = Scene_BuildWorld(scene, &overrides);
	cr_assert(tbWorld_IsValid(sw.worldId));
	cr_assert_eq(tbWorld_GetDef(sw.worldId).broadPhase, method == tb_broadPhaseAuto ? tb_broadPhaseTree : method);
	*contacts = 0;
	for (int i = 0; i < steps; ++i)
	{
		tbWorld_Step(sw.worldId, scene->timeStep, scene->subSteps);
		*contacts += tbWorld_GetCounters(sw.worldId).touchingCount;
	}
	uint64_t hash = HashWorld(&sw);
	SceneWorld_Destroy(&sw);
	Scene_Destroy(scene);
	return hash;
}

Test(determinism, trajectories_identical_under_every_broad_phase)
{
	int contactsTree, contactsSweep, contactsBrute;
	uint64_t tree = RunRain(tb_broadPhaseTree, 240, &contactsTree);
	uint64_t sweep = RunRain(tb_broadPhaseSortAndSweep, 240, &contactsSweep);
	uint64_t brute = RunRain(tb_broadPhaseBruteForce, 240, &contactsBrute);
	// The scene must actually collide, or the comparison proves nothing.
	cr_assert_gt(contactsTree, 1000);
	cr_assert_eq(tree, sweep, "sort-and-sweep trajectory differs from the tree's");
	cr_assert_eq(tree, brute, "brute-force trajectory differs from the tree's");
	cr_assert_eq(contactsTree, contactsSweep);
	cr_assert_eq(contactsTree, contactsBrute);
}

Test(determinism, same_scene_twice_gives_same_bits)
{
	int a, b;
	cr_assert_eq(RunRain(tb_broadPhaseAuto, 180, &a), RunRain(tb_broadPhaseAuto, 180, &b));
	cr_assert_eq(a, b);
}
