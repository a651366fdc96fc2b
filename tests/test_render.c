// Software renderer: PNG output of the requested size, byte-identical repeats, rounded polygons
// drawn by their true outline, contact sheets laid out as a grid.
#include "catalogue.h"
#include "render.h"

#include <criterion/criterion.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t ReadBigEndian(const uint8_t* bytes)
{
	return (uint32_t)bytes[0] << 24 | (uint32_t)bytes[1] << 16 | (uint32_t)bytes[2] << 8 | (uint32_t)bytes[3];
}

// Signature, then the IHDR chunk: length 13, "IHDR", width, height (big endian).
static void ExpectPngSize(const uint8_t* png, int size, int width, int height)
{
	static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
	cr_assert_geq(size, 24);
	cr_assert_eq(memcmp(png, signature, 8), 0, "not a PNG");
	cr_assert_eq(ReadBigEndian(png + 8), 13u);
	cr_assert_eq(memcmp(png + 12, "IHDR", 4), 0);
	cr_assert_eq(ReadBigEndian(png + 16), (uint32_t)width);
	cr_assert_eq(ReadBigEndian(png + 20), (uint32_t)height);
}

// Build a catalogue scene, step it, render it to PNG bytes.
static uint8_t* RenderScene(const char* name, int steps, int width, int height, int* size)
{
	Scene* scene = Catalogue_Build(name);
	SceneWorld world = Scene_BuildWorld(scene, NULL);
	tbAABB view = Render_FitView(&world, width, height);
	for (int i = 0; i < steps; ++i)
	{
		tbWorld_Step(world.worldId, scene->timeStep, scene->subSteps);
	}
	RenderImage image = RenderImage_Create(width, height, 0);
	RenderOptions options = Render_DefaultOptions();
	options.drawContacts = true;
	options.drawNormals = true;
	Render_World(&image, world.worldId, view, &options);
	uint8_t* png = RenderImage_EncodePNG(&image, size);
	RenderImage_Destroy(&image);
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
	return png;
}

Test(render, frame_is_a_png_of_the_requested_size)
{
	int size = 0;
	uint8_t* png = RenderScene("pyramid", 5, 320, 200, &size);
	cr_assert_not_null(png);
	ExpectPngSize(png, size, 320, 200);
	free(png);
}

Test(render, png_file_has_the_requested_size)
{
	Scene* scene = Catalogue_Build("newtons_cradle");
	SceneWorld world = Scene_BuildWorld(scene, NULL);
	RenderImage image = RenderImage_Create(123, 45, 0x000000);
	RenderOptions options = Render_DefaultOptions();
	Render_World(&image, world.worldId, Render_FitView(&world, 123, 45), &options);
	const char* path = TUMBLE_BINARY_DIR "/test_render_frame.png";
	cr_assert(RenderImage_WritePNG(&image, path));
	uint8_t header[24];
	FILE* file = fopen(path, "rb");
	cr_assert_not_null(file);
	cr_assert_eq(fread(header, 1, 24, file), 24u);
	fclose(file);
	remove(path);
	ExpectPngSize(header, 24, 123, 45);
	RenderImage_Destroy(&image);
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
}

Test(render, same_scene_gives_identical_bytes)
{
	const char* names[] = {"rain_rigid", "confined", "spinner"};
	for (int i = 0; i < 3; ++i)
	{
		int sizeA = 0, sizeB = 0;
		uint8_t* a = RenderScene(names[i], 3, 256, 192, &sizeA);
		uint8_t* b = RenderScene(names[i], 3, 256, 192, &sizeB);
		cr_assert_eq(sizeA, sizeB, "%s", names[i]);
		cr_assert_eq(memcmp(a, b, (size_t)sizeA), 0, "%s renders differ", names[i]);
		free(a);
		free(b);
	}
}

static const uint8_t* Pixel(const RenderImage* image, int i, int j)
{
	return image->pixels + 4 * ((size_t)j * (size_t)image->width + (size_t)i);
}

// A rounded box (core half size 1, radius 0.5) at the origin, seen through [−2, 2]²
// at 100 px/m: the corner is round, the sides are at ±1.5 m.
Test(render, rounded_polygon_follows_its_outline)
{
	Scene* scene = Scene_Create();
	int body = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	tbGeometry geometry = Scene_MakeBoxGeometry(1.0f, 1.0f, tbVec2_zero, 0.0f);
	geometry.polygon = tbMakeRoundedBox(1.0f, 1.0f, 0.5f);
	Scene_AddGeometry(scene, body, &geometry, 1.0f, 0.6f);
	SceneWorld world = Scene_BuildWorld(scene, NULL);
	RenderImage image = RenderImage_Create(400, 400, 0);
	RenderOptions options = Render_DefaultOptions();
	options.background = 0x000000;
	tbAABB view = {{-2.0f, -2.0f}, {2.0f, 2.0f}};
	Render_World(&image, world.worldId, view, &options);
	// pixel (i, j) is centred on world (−2 + (i + ½)/100, 2 − (j + ½)/100)
	const uint8_t* center = Pixel(&image, 200, 200);
	cr_assert(center[0] + center[1] + center[2] > 0, "interior is filled");
	const uint8_t* side = Pixel(&image, 200 + 130, 200);		  // x = 1.305: inside the rounded side
	const uint8_t* beyond = Pixel(&image, 200 + 160, 200);		  // x = 1.605: outside
	const uint8_t* cutCorner = Pixel(&image, 200 + 145, 200 - 146); // (1.455, 1.455): 0.64 m from the core corner
	const uint8_t* inCorner = Pixel(&image, 200 + 125, 200 - 126);	  // (1.255, 1.255): 0.36 m from the core corner
	cr_assert(side[0] + side[1] + side[2] > 0);
	cr_assert_eq(beyond[0] + beyond[1] + beyond[2], 0);
	cr_assert_eq(cutCorner[0] + cutCorner[1] + cutCorner[2], 0, "the corner is round");
	cr_assert(inCorner[0] + inCorner[1] + inCorner[2] > 0);
	RenderImage_Destroy(&image);
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
}

Test(render, fitted_view_contains_the_moving_bodies)
{
	Scene* scene = Catalogue_Build("dominoes");
	SceneWorld world = Scene_BuildWorld(scene, NULL);
	tbAABB view = Render_FitView(&world, 400, 300);
	for (int i = 0; i < world.bodyCount; ++i)
	{
		if (scene->bodies[i].type == tb_dynamicBody)
		{
			cr_assert(tbAABB_Contains(view, tbBody_ComputeAABB(world.bodyIds[i])), "body %d", i);
		}
	}
	tbVec2 extent = tbAABB_Extents(view);
	cr_assert_float_eq(extent.x / extent.y, 400.0f / 300.0f, 1e-4f);
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
}

Test(render, contact_sheet_is_a_grid)
{
	Scene* scene = Catalogue_Build("vertical_stack");
	SceneWorld world = Scene_BuildWorld(scene, NULL);
	RenderOptions options = Render_DefaultOptions();
	RenderSheet sheet = RenderSheet_Create(5, 64, 48, options.background);
	tbAABB view = Render_FitView(&world, 64, 48);
	for (int i = 0; i < 5; ++i)
	{
		cr_assert(RenderSheet_Add(&sheet, world.worldId, view, &options));
	}
	cr_assert_not(RenderSheet_Add(&sheet, world.worldId, view, &options), "sheet is full");
	cr_assert_eq(sheet.columns, 3);
	cr_assert_eq(sheet.rows, 2);
	int size = 0;
	uint8_t* png = RenderImage_EncodePNG(&sheet.image, &size);
	ExpectPngSize(png, size, 3 * 64 + 4 * 2, 2 * 48 + 3 * 2);
	free(png);
	RenderSheet_Destroy(&sheet);
	SceneWorld_Destroy(&world);
	Scene_Destroy(scene);
}
