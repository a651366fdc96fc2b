// Software rasteriser for tbDebugDraw: anti-aliased shapes into an RGBA image, written as PNG.
// Deterministic: the same world and view give byte-identical images (no time, no uninitialised
// memory, no threads).
#pragma once

#include "scene.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/// RGBA image, 8 bits per channel, rows top to bottom.
typedef struct RenderImage
{
	int width;
	int height;
	uint8_t* pixels; ///< width · height · 4 bytes
} RenderImage;

/// Image filled with the background colour (0xRRGGBB). pixels is NULL on bad size or no memory.
RenderImage RenderImage_Create(int width, int height, uint32_t background);
void RenderImage_Destroy(RenderImage* image);
void RenderImage_Clear(RenderImage* image, uint32_t background);

/// Copy src into dst with its top-left corner at (x, y), clipped.
void RenderImage_Blit(RenderImage* dst, const RenderImage* src, int x, int y);

/// Write a PNG file. False on failure.
bool RenderImage_WritePNG(const RenderImage* image, const char* path);

/// Encode as PNG in memory (free with free()); NULL on failure.
uint8_t* RenderImage_EncodePNG(const RenderImage* image, int* size);

/// What to draw on top of the shapes.
typedef struct RenderOptions
{
	bool drawContacts;
	bool drawNormals;
	bool drawAABBs;
	bool drawTree;
	uint32_t background; ///< 0xRRGGBB
} RenderOptions;

RenderOptions Render_DefaultOptions(void);

/// World rectangle that fits the world's bodies (moving ones first, see render.c) with a margin,
/// widened to the image's aspect ratio.
tbAABB Render_FitView(const SceneWorld* world, int width, int height);

/// Widen a view rectangle to the aspect ratio width:height, keeping its centre.
tbAABB Render_MatchAspect(tbAABB view, int width, int height);

/// Clear the image and draw the world as seen through view (world rectangle → whole image).
void Render_World(RenderImage* image, tbWorldId worldId, tbAABB view, const RenderOptions* options);

/// Contact sheet: frames laid out in a grid of tiles, each tile a rendered frame.
typedef struct RenderSheet
{
	RenderImage image;
	RenderImage tile;
	int columns;
	int rows;
	int frameCount;
	int added;
} RenderSheet;

/// Sheet for frameCount tiles of tileWidth × tileHeight (grid as square as possible, 2 px gaps).
RenderSheet RenderSheet_Create(int frameCount, int tileWidth, int tileHeight, uint32_t background);

/// Render the world into the next tile. False when the sheet is full.
bool RenderSheet_Add(RenderSheet* sheet, tbWorldId worldId, tbAABB view, const RenderOptions* options);

void RenderSheet_Destroy(RenderSheet* sheet);

#ifdef __cplusplus
}
#endif
