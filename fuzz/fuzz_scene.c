// Fuzz harness for the JSON scene loader: parse the bytes as a scene file; a scene that loads is
// built into a world and stepped by SceneWorld_Step (at most 20 steps, spawn schedules included),
// then exported and parsed again. Checks: no
// abort or sanitizer report, every position finite after every step, the export of a loaded
// scene succeeds and reloads (the loader accepts only what the library accepts).
#include "fuzz_input.h"

#include "scene_file.h"

#include <stdio.h>
#include <stdlib.h>

static void Quiet(const char* message, void* context)
{
	(void)message;
	(void)context;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	tbSetErrorCallback(Quiet, NULL);
	char* text = malloc(size + 1);
	memcpy(text, data, size);
	text[size] = '\0';
	char error[256];
	Scene* scene = SceneFile_Parse(text, error, (int)sizeof(error));
	free(text);
	if (scene == NULL)
	{
		return 0;
	}
	SceneWorld world = Scene_BuildWorld(scene, NULL);
	FUZZ_CHECK(TB_IS_NON_NULL(world.worldId), "a loaded scene did not build");
	int steps = scene->steps < 20 ? scene->steps : 20;
	int capacity = SceneWorld_BodyCapacity(&world);
	tbBodyId* ids = malloc(sizeof(tbBodyId) * (size_t)capacity);
	for (int i = 0; i < steps; ++i)
	{
		FUZZ_CHECK(SceneWorld_Step(&world, scene, scene->subSteps), "step refused");
		int count = SceneWorld_CollectBodies(&world, ids, capacity);
		for (int b = 0; b < count; ++b)
		{
			tbVec2 p = tbBody_GetPosition(ids[b]);
			FUZZ_CHECK(FuzzIsFinite2(p.x, p.y), "body %d (scene's, then spawned) at (%g, %g) after step %d", b,
					   (double)p.x, (double)p.y, i);
		}
	}
	free(ids);
	SceneWorld_Destroy(&world);
	char* exported = SceneFile_Export(scene, error, (int)sizeof(error));
	FUZZ_CHECK(exported != NULL, "export of a loaded scene failed: %s", error);
	Scene* reloaded = SceneFile_Parse(exported, error, (int)sizeof(error));
	FUZZ_CHECK(reloaded != NULL, "the export did not reload: %s", error);
	Scene_Destroy(reloaded);
	free(exported);
	Scene_Destroy(scene);
	FUZZ_CHECK(tbGetByteCount() == 0, "%lld bytes left", (long long)tbGetByteCount());
	return 0;
}
