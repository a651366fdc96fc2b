// tumble-platformer [--png DIR] [--frames N] [--every K] [--size WxH]
//
// The catalogue's platformer level with a character on the mover kit (character.c) instead of its
// dynamic capsule: it walks right at 6 m/s and jumps once a second (when on the ground), pushing
// the props it meets with its kinematic body. Prints the character's path every half second and,
// with --png, writes frames that follow it (frame_00000.png, ...). tests/test_character.c runs the
// same input and asserts the path.
#include "catalogue.h"
#include "character.h"
#include "render.h"
#include "scene.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct Options
{
	const char* pngDir;
	int frames;
	int every;
	int width, height;
} Options;

static int Usage(void)
{
	fprintf(stderr, "usage: tumble-platformer [--png DIR] [--frames N] [--every K] [--size WxH]\n");
	return 2;
}

static bool ParseOptions(int argc, char** argv, Options* o)
{
	*o = (Options){NULL, 900, 10, 640, 360};
	for (int i = 1; i < argc; ++i)
	{
		const char* value = i + 1 < argc ? argv[i + 1] : NULL;
		if (value == NULL)
		{
			return false;
		}
		if (strcmp(argv[i], "--png") == 0)
		{
			o->pngDir = value;
		}
		else if (strcmp(argv[i], "--frames") == 0)
		{
			o->frames = atoi(value);
		}
		else if (strcmp(argv[i], "--every") == 0)
		{
			o->every = atoi(value);
		}
		else if (strcmp(argv[i], "--size") == 0)
		{
			if (sscanf(value, "%dx%d", &o->width, &o->height) != 2)
			{
				return false;
			}
		}
		else
		{
			return false;
		}
		i += 1;
	}
	return o->frames > 0 && o->every > 0 && o->width >= 16 && o->height >= 16 && o->width <= 8192 && o->height <= 8192;
}

/// A 24 × 13.5 m window on the character, its feet a third of the way up.
static tbAABB CameraView(const Character* c, int width, int height)
{
	tbAABB view = {{c->position.x - 12.0f, c->position.y - 4.5f}, {c->position.x + 12.0f, c->position.y + 9.0f}};
	return Render_MatchAspect(view, width, height);
}

int main(int argc, char** argv)
{
	Options o;
	if (ParseOptions(argc, argv, &o) == false)
	{
		return Usage();
	}
	if (o.pngDir != NULL && mkdir(o.pngDir, 0777) != 0 && errno != EEXIST)
	{
		fprintf(stderr, "tumble-platformer: cannot create %s (%s)\n", o.pngDir, strerror(errno));
		return 1;
	}
	Scene* scene = Catalogue_Build("platformer");
	SceneWorld sw = Scene_BuildWorld(scene, NULL);
	int hero = -1;
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		hero = strcmp(scene->bodies[i].name, "hero") == 0 ? i : hero;
	}
	tbVec2 start = tbBody_GetPosition(sw.bodyIds[hero]);
	tbDestroyBody(sw.bodyIds[hero]);
	Character c = Character_Create(sw.worldId, (tbVec2){start.x, start.y - 0.7f}, 0.3f, 1.4f);

	RenderImage image = RenderImage_Create(o.width, o.height, 0xFFFFFF);
	RenderOptions render = Render_DefaultOptions();
	bool wantJump = false;
	int status = 0;
	for (int frame = 0; frame < o.frames && status == 0; ++frame)
	{
		wantJump = wantJump || frame % 60 == 30;
		bool jump = wantJump && c.onGround;
		wantJump = wantJump && jump == false;
		Character_Step(&c, sw.worldId, 6.0f, jump, scene->timeStep);
		SceneWorld_Step(&sw, scene, scene->subSteps);
		if (frame % 30 == 0)
		{
			printf("t %5.2f s  feet (%7.3f, %6.3f)  velocity (%6.3f, %6.3f)  %s\n", (double)(frame + 1) * scene->timeStep,
				   (double)c.position.x, (double)c.position.y, (double)c.velocity.x, (double)c.velocity.y,
				   c.onGround ? "on ground" : "in the air");
		}
		if (o.pngDir != NULL && frame % o.every == 0)
		{
			char path[1024];
			snprintf(path, sizeof(path), "%s/frame_%05d.png", o.pngDir, frame);
			Render_World(&image, sw.worldId, CameraView(&c, o.width, o.height), &render);
			if (RenderImage_WritePNG(&image, path) == false)
			{
				fprintf(stderr, "tumble-platformer: cannot write %s\n", path);
				status = 1;
			}
		}
	}
	RenderImage_Destroy(&image);
	SceneWorld_Destroy(&sw);
	Scene_Destroy(scene);
	return status;
}
