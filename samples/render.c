// Software rasteriser behind tbDebugDraw. Every shape is drawn from a signed distance: for each
// pixel centre in the shape's box, d = distance to the shape's surface in pixels (negative
// inside). Coverage of the fill is clamp(½ − d, 0, 1), a one-pixel box filter across the edge,
// which gives ~1 px anti-aliasing; the outline is a 1 px band just inside the surface.
// Rounded polygons are exact: distance to the core polygon minus the radius.
#include "render.h"

#include <stb_image_write.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define FILL_ALPHA 0.5f	   ///< opacity of shape interiors (outlines are opaque)
#define LINE_HALF_WIDTH 0.6f ///< px: half width of segments and outline lines

// ---------------------------------------------------------------------------------------------
// Images

RenderImage RenderImage_Create(int width, int height, uint32_t background)
{
	RenderImage image = {0, 0, NULL};
	if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
	{
		return image;
	}
	image.pixels = malloc((size_t)width * (size_t)height * 4);
	if (image.pixels != NULL)
	{
		image.width = width;
		image.height = height;
		RenderImage_Clear(&image, background);
	}
	return image;
}

void RenderImage_Destroy(RenderImage* image)
{
	free(image->pixels);
	memset(image, 0, sizeof(*image));
}

void RenderImage_Clear(RenderImage* image, uint32_t background)
{
	size_t count = (size_t)image->width * (size_t)image->height;
	for (size_t i = 0; i < count; ++i)
	{
		image->pixels[4 * i + 0] = (uint8_t)(background >> 16);
		image->pixels[4 * i + 1] = (uint8_t)(background >> 8);
		image->pixels[4 * i + 2] = (uint8_t)background;
		image->pixels[4 * i + 3] = 255;
	}
}

void RenderImage_Blit(RenderImage* dst, const RenderImage* src, int x, int y)
{
	for (int row = 0; row < src->height; ++row)
	{
		int dy = y + row;
		if (dy < 0 || dy >= dst->height)
		{
			continue;
		}
		int x0 = x < 0 ? -x : 0;
		int x1 = src->width < dst->width - x ? src->width : dst->width - x;
		if (x1 > x0)
		{
			memcpy(dst->pixels + 4 * ((size_t)dy * (size_t)dst->width + (size_t)(x + x0)),
				   src->pixels + 4 * ((size_t)row * (size_t)src->width + (size_t)x0), 4 * (size_t)(x1 - x0));
		}
	}
}

bool RenderImage_WritePNG(const RenderImage* image, const char* path)
{
	if (image->pixels == NULL)
	{
		return false;
	}
	return stbi_write_png(path, image->width, image->height, 4, image->pixels, image->width * 4) != 0;
}

typedef struct ByteBuffer
{
	uint8_t* data;
	int size;
	bool failed;
} ByteBuffer;

static void AppendBytes(void* context, void* data, int size)
{
	ByteBuffer* buffer = context;
	uint8_t* grown = buffer->failed ? NULL : realloc(buffer->data, (size_t)buffer->size + (size_t)size);
	if (grown == NULL)
	{
		buffer->failed = true;
		return;
	}
	memcpy(grown + buffer->size, data, (size_t)size);
	buffer->data = grown;
	buffer->size += size;
}

uint8_t* RenderImage_EncodePNG(const RenderImage* image, int* size)
{
	ByteBuffer buffer = {NULL, 0, false};
	*size = 0;
	if (image->pixels == NULL)
	{
		return NULL;
	}
	int ok = stbi_write_png_to_func(AppendBytes, &buffer, image->width, image->height, 4, image->pixels,
									image->width * 4);
	if (ok == 0 || buffer.failed)
	{
		free(buffer.data);
		return NULL;
	}
	*size = buffer.size;
	return buffer.data;
}

// ---------------------------------------------------------------------------------------------
// Canvas: world ↔ pixel mapping and blending

typedef struct Canvas
{
	RenderImage* image;
	tbAABB view;
	float scale; ///< pixels per metre
} Canvas;

// World point at the centre of pixel (i, j); y points up in the world, down in the image.
static tbVec2 PixelToWorld(const Canvas* canvas, int i, int j)
{
	float x = canvas->view.lowerBound.x + ((float)i + 0.5f) / canvas->scale;
	float y = canvas->view.upperBound.y - ((float)j + 0.5f) / canvas->scale;
	return (tbVec2){x, y};
}

static float Clamp01(float a)
{
	return a < 0.0f ? 0.0f : (a > 1.0f ? 1.0f : a);
}

static void Blend(Canvas* canvas, int i, int j, uint32_t color, float alpha)
{
	if (alpha <= 0.0f)
	{
		return;
	}
	uint8_t* p = canvas->image->pixels + 4 * ((size_t)j * (size_t)canvas->image->width + (size_t)i);
	float src[3] = {(float)((color >> 16) & 0xFF), (float)((color >> 8) & 0xFF), (float)(color & 0xFF)};
	for (int c = 0; c < 3; ++c)
	{
		float value = src[c] * alpha + (float)p[c] * (1.0f - alpha);
		p[c] = (uint8_t)(value + 0.5f);
	}
}

// Pixel rectangle [i0, i1) × [j0, j1) covering a world box grown by pad pixels, clipped.
typedef struct PixelRect
{
	int i0, j0, i1, j1;
} PixelRect;

static PixelRect PixelBounds(const Canvas* canvas, tbAABB box, float pad)
{
	float x0 = (box.lowerBound.x - canvas->view.lowerBound.x) * canvas->scale - pad;
	float x1 = (box.upperBound.x - canvas->view.lowerBound.x) * canvas->scale + pad;
	float y0 = (canvas->view.upperBound.y - box.upperBound.y) * canvas->scale - pad;
	float y1 = (canvas->view.upperBound.y - box.lowerBound.y) * canvas->scale + pad;
	PixelRect rect;
	float w = (float)canvas->image->width, h = (float)canvas->image->height;
	rect.i0 = (int)floorf(tbClampFloat(x0, 0.0f, w));
	rect.i1 = (int)ceilf(tbClampFloat(x1, 0.0f, w));
	rect.j0 = (int)floorf(tbClampFloat(y0, 0.0f, h));
	rect.j1 = (int)ceilf(tbClampFloat(y1, 0.0f, h));
	return rect;
}

// ---------------------------------------------------------------------------------------------
// Signed distances (world units, negative inside)

typedef enum SdfKind
{
	sdf_polygon,
	sdf_capsule,
	sdf_ring,
} SdfKind;

typedef struct Sdf
{
	SdfKind kind;
	tbTransform transform; ///< polygon frame
	tbVec2 vertices[TB_MAX_POLYGON_VERTICES];
	tbVec2 normals[TB_MAX_POLYGON_VERTICES];
	int count;
	tbVec2 p1, p2; ///< capsule/segment ends (world); ring centre in p1
	float radius;
} Sdf;

static float SegmentDistance(tbVec2 p, tbVec2 a, tbVec2 b)
{
	tbVec2 ab = tbSub(b, a);
	float lengthSquared = tbDot(ab, ab);
	float t = lengthSquared > 0.0f ? tbClampFloat(tbDot(tbSub(p, a), ab) / lengthSquared, 0.0f, 1.0f) : 0.0f;
	return tbDistance(p, tbMulAdd(a, t, ab));
}

// Convex counter-clockwise polygon: inside, the largest plane distance; outside, the distance
// to the nearest edge. Exact in both cases, so corners round correctly when a radius is subtracted.
static float PolygonDistance(const Sdf* sdf, tbVec2 worldPoint)
{
	tbVec2 p = tbInvTransformPoint(sdf->transform, worldPoint);
	float separation = -FLT_MAX;
	for (int i = 0; i < sdf->count; ++i)
	{
		separation = tbMaxFloat(separation, tbDot(sdf->normals[i], tbSub(p, sdf->vertices[i])));
	}
	if (separation > 0.0f && sdf->count > 1)
	{
		separation = FLT_MAX;
		for (int i = 0; i < sdf->count; ++i)
		{
			int next = i + 1 < sdf->count ? i + 1 : 0;
			separation = tbMinFloat(separation, SegmentDistance(p, sdf->vertices[i], sdf->vertices[next]));
		}
	}
	return separation - sdf->radius;
}

static float SignedDistance(const Sdf* sdf, tbVec2 p)
{
	switch (sdf->kind)
	{
		case sdf_polygon:
			return PolygonDistance(sdf, p);
		case sdf_capsule:
			return SegmentDistance(p, sdf->p1, sdf->p2) - sdf->radius;
		default:
			return fabsf(tbDistance(p, sdf->p1) - sdf->radius);
	}
}

typedef enum PaintStyle
{
	paint_solid,   ///< translucent fill with an opaque outline
	paint_opaque,  ///< opaque fill (lines, points): the sdf already includes the half width
} PaintStyle;

static void PaintPixel(Canvas* canvas, int i, int j, float d, uint32_t color, PaintStyle style)
{
	float fill = Clamp01(0.5f - d);
	if (style == paint_opaque)
	{
		Blend(canvas, i, j, color, fill);
		return;
	}
	Blend(canvas, i, j, color, FILL_ALPHA * fill);
	float line = Clamp01(LINE_HALF_WIDTH + 0.5f - fabsf(d + LINE_HALF_WIDTH));
	Blend(canvas, i, j, color, line);
}

// Rasterise: every pixel of the box, coverage from the signed distance in pixels minus offset.
static void Paint(Canvas* canvas, const Sdf* sdf, tbAABB box, float offset, uint32_t color, PaintStyle style)
{
	PixelRect rect = PixelBounds(canvas, box, 2.0f + offset);
	for (int j = rect.j0; j < rect.j1; ++j)
	{
		for (int i = rect.i0; i < rect.i1; ++i)
		{
			float d = SignedDistance(sdf, PixelToWorld(canvas, i, j)) * canvas->scale - offset;
			if (d < 1.0f)
			{
				PaintPixel(canvas, i, j, d, color, style);
			}
		}
	}
}

static tbAABB SegmentBox(tbVec2 p1, tbVec2 p2, float radius)
{
	tbAABB box = {tbMin(p1, p2), tbMax(p1, p2)};
	box.lowerBound = tbSub(box.lowerBound, (tbVec2){radius, radius});
	box.upperBound = tbAdd(box.upperBound, (tbVec2){radius, radius});
	return box;
}

// ---------------------------------------------------------------------------------------------
// tbDebugDraw callbacks

static void DrawSegmentLine(Canvas* canvas, tbVec2 p1, tbVec2 p2, uint32_t color)
{
	Sdf sdf;
	memset(&sdf, 0, sizeof(sdf));
	sdf.kind = sdf_capsule;
	sdf.p1 = p1;
	sdf.p2 = p2;
	Paint(canvas, &sdf, SegmentBox(p1, p2, 0.0f), LINE_HALF_WIDTH, color, paint_opaque);
}

// The image is float: world transforms are rounded to it (exact in the float build).
static tbTransform ToTransform(tbWorldTransform t)
{
	tbTransform r = {tbToVec2(t.p), t.q};
	return r;
}

static void DrawPolygonCallback(tbWorldTransform transform, const tbVec2* vertices, int vertexCount, tbHexColor color,
								void* context)
{
	tbTransform xf = ToTransform(transform);
	for (int i = 0; i < vertexCount; ++i)
	{
		DrawSegmentLine(context, tbTransformPoint(xf, vertices[i]),
						tbTransformPoint(xf, vertices[i + 1 < vertexCount ? i + 1 : 0]), (uint32_t)color);
	}
}

static void DrawSolidPolygonCallback(tbWorldTransform worldTransform, const tbVec2* vertices, int vertexCount,
									 float radius, tbHexColor color, void* context)
{
	tbTransform transform = ToTransform(worldTransform);
	Sdf sdf;
	memset(&sdf, 0, sizeof(sdf));
	sdf.kind = sdf_polygon;
	sdf.transform = transform;
	sdf.count = vertexCount < TB_MAX_POLYGON_VERTICES ? vertexCount : TB_MAX_POLYGON_VERTICES;
	sdf.radius = radius;
	tbAABB box = {{FLT_MAX, FLT_MAX}, {-FLT_MAX, -FLT_MAX}};
	for (int i = 0; i < sdf.count; ++i)
	{
		sdf.vertices[i] = vertices[i];
		tbVec2 edge = tbSub(vertices[i + 1 < sdf.count ? i + 1 : 0], vertices[i]);
		sdf.normals[i] = tbNormalize((tbVec2){edge.y, -edge.x});
		tbVec2 w = tbTransformPoint(transform, vertices[i]);
		box.lowerBound = tbMin(box.lowerBound, w);
		box.upperBound = tbMax(box.upperBound, w);
	}
	if (sdf.count == 0)
	{
		return;
	}
	box.lowerBound = tbSub(box.lowerBound, (tbVec2){radius, radius});
	box.upperBound = tbAdd(box.upperBound, (tbVec2){radius, radius});
	Paint(context, &sdf, box, 0.0f, (uint32_t)color, paint_solid);
}

static void DrawCircleCallback(tbPos worldCenter, float radius, tbHexColor color, void* context)
{
	tbVec2 center = tbToVec2(worldCenter);
	Sdf sdf;
	memset(&sdf, 0, sizeof(sdf));
	sdf.kind = sdf_ring;
	sdf.p1 = center;
	sdf.radius = radius;
	Paint(context, &sdf, SegmentBox(center, center, radius), LINE_HALF_WIDTH, (uint32_t)color, paint_opaque);
}

static void DrawCapsule(void* context, tbVec2 p1, tbVec2 p2, float radius, uint32_t color)
{
	Sdf sdf;
	memset(&sdf, 0, sizeof(sdf));
	sdf.kind = sdf_capsule;
	sdf.p1 = p1;
	sdf.p2 = p2;
	sdf.radius = radius;
	Paint(context, &sdf, SegmentBox(p1, p2, radius), 0.0f, color, paint_solid);
}

static void DrawSolidCapsuleCallback(tbPos p1, tbPos p2, float radius, tbHexColor color, void* context)
{
	DrawCapsule(context, tbToVec2(p1), tbToVec2(p2), radius, (uint32_t)color);
}

static void DrawSolidCircleCallback(tbWorldTransform transform, tbVec2 localCenter, float radius, tbHexColor color,
									void* context)
{
	tbTransform xf = ToTransform(transform);
	tbVec2 center = tbTransformPoint(xf, localCenter);
	DrawCapsule(context, center, center, radius, (uint32_t)color);
	tbVec2 rim = tbAdd(center, tbMulSV(radius, tbRot_GetXAxis(xf.q)));
	DrawSegmentLine(context, center, rim, (uint32_t)color);
}

static void DrawLineCallback(tbPos p1, tbPos p2, tbHexColor color, void* context)
{
	DrawSegmentLine(context, tbToVec2(p1), tbToVec2(p2), (uint32_t)color);
}

static void DrawBoundsCallback(tbAABB box, tbHexColor color, void* context)
{
	tbVec2 v[4] = {box.lowerBound, {box.upperBound.x, box.lowerBound.y}, box.upperBound, {box.lowerBound.x, box.upperBound.y}};
	for (int i = 0; i < 4; ++i)
	{
		DrawSegmentLine(context, v[i], v[(i + 1) % 4], (uint32_t)color);
	}
}

// A disc of diameter size pixels.
static void DrawPointCallback(tbPos worldPoint, float size, tbHexColor color, void* context)
{
	tbVec2 p = tbToVec2(worldPoint);
	Canvas* canvas = context;
	Sdf sdf;
	memset(&sdf, 0, sizeof(sdf));
	sdf.kind = sdf_capsule;
	sdf.p1 = p;
	sdf.p2 = p;
	sdf.radius = 0.5f * size / canvas->scale;
	Paint(canvas, &sdf, SegmentBox(p, p, sdf.radius), 0.0f, color, paint_opaque);
}

// ---------------------------------------------------------------------------------------------
// Views and drawing

RenderOptions Render_DefaultOptions(void)
{
	RenderOptions options;
	memset(&options, 0, sizeof(options));
	options.background = 0x1E1E24;
	return options;
}

tbAABB Render_MatchAspect(tbAABB view, int width, int height)
{
	tbVec2 center = tbAABB_Center(view);
	tbVec2 extent = tbMax(tbAABB_Extents(view), (tbVec2){0.5f, 0.5f});
	float aspect = (float)width / (float)(height > 0 ? height : 1);
	if (extent.x < extent.y * aspect)
	{
		extent.x = extent.y * aspect;
	}
	else
	{
		extent.y = extent.x / aspect;
	}
	tbAABB result = {tbSub(center, extent), tbAdd(center, extent)};
	return result;
}

// Union of the boxes of the bodies of one kind (moving or static); false when there are none.
static bool UnionBodies(const SceneWorld* world, bool moving, tbAABB* box)
{
	bool found = false;
	int capacity = SceneWorld_BodyCapacity(world);
	tbBodyId* ids = malloc(sizeof(tbBodyId) * (size_t)capacity);
	int count = ids != NULL ? SceneWorld_CollectBodies(world, ids, capacity) : 0;
	for (int i = 0; i < count; ++i)
	{
		tbBodyId id = ids[i];
		if (tbBody_IsValid(id) == false || tbBody_GetShapeCount(id) == 0 ||
			(tbBody_GetType(id) != tb_staticBody) != moving)
		{
			continue;
		}
		tbAABB b = tbBody_ComputeAABB(id);
		*box = found ? tbAABB_Union(*box, b) : b;
		found = true;
	}
	free(ids);
	return found;
}

// Fits the moving bodies (the ground is usually far wider than the action) plus a 10% margin in
// which the ground shows; a scene with only static bodies is fitted whole.
tbAABB Render_FitView(const SceneWorld* world, int width, int height)
{
	tbAABB box = {{-10.0f, -10.0f}, {10.0f, 10.0f}};
	if (UnionBodies(world, true, &box) == false)
	{
		UnionBodies(world, false, &box);
	}
	tbVec2 extent = tbAABB_Extents(box);
	float margin = tbMaxFloat(0.5f, 0.1f * tbMaxFloat(extent.x, extent.y) * 2.0f);
	box.lowerBound = tbSub(box.lowerBound, (tbVec2){margin, margin});
	box.upperBound = tbAdd(box.upperBound, (tbVec2){margin, margin});
	return Render_MatchAspect(box, width, height);
}

void Render_World(RenderImage* image, tbWorldId worldId, tbAABB view, const RenderOptions* options)
{
	RenderImage_Clear(image, options->background);
	Canvas canvas;
	canvas.image = image;
	canvas.view = Render_MatchAspect(view, image->width, image->height);
	canvas.scale = (float)image->width / (canvas.view.upperBound.x - canvas.view.lowerBound.x);
	tbDebugDraw draw = tbDefaultDebugDraw();
	draw.DrawPolygonFcn = DrawPolygonCallback;
	draw.DrawSolidPolygonFcn = DrawSolidPolygonCallback;
	draw.DrawCircleFcn = DrawCircleCallback;
	draw.DrawSolidCircleFcn = DrawSolidCircleCallback;
	draw.DrawSolidCapsuleFcn = DrawSolidCapsuleCallback;
	draw.DrawLineFcn = DrawLineCallback;
	draw.DrawPointFcn = DrawPointCallback;
	draw.DrawBoundsFcn = DrawBoundsCallback;
	draw.drawingBounds = canvas.view;
	draw.drawShapes = true;
	draw.drawJoints = true; // the renderer shows joints (v3.2's default view leaves them off)
	draw.drawBounds = options->drawAABBs;
	draw.drawTree = options->drawTree;
	draw.drawContacts = options->drawContacts;
	draw.drawContactNormals = options->drawNormals;
	draw.context = &canvas;
	tbWorld_Draw(worldId, &draw);
}

// ---------------------------------------------------------------------------------------------
// Contact sheets

#define SHEET_GAP 2

RenderSheet RenderSheet_Create(int frameCount, int tileWidth, int tileHeight, uint32_t background)
{
	RenderSheet sheet;
	memset(&sheet, 0, sizeof(sheet));
	if (frameCount <= 0)
	{
		return sheet;
	}
	int columns = (int)ceil(sqrt((double)frameCount));
	int rows = (frameCount + columns - 1) / columns;
	int width = columns * tileWidth + (columns + 1) * SHEET_GAP;
	int height = rows * tileHeight + (rows + 1) * SHEET_GAP;
	uint32_t gapColor = background ^ 0x404040;
	sheet.image = RenderImage_Create(width, height, gapColor);
	sheet.tile = RenderImage_Create(tileWidth, tileHeight, background);
	if (sheet.image.pixels == NULL || sheet.tile.pixels == NULL)
	{
		RenderSheet_Destroy(&sheet);
		return sheet;
	}
	sheet.columns = columns;
	sheet.rows = rows;
	sheet.frameCount = frameCount;
	return sheet;
}

bool RenderSheet_Add(RenderSheet* sheet, tbWorldId worldId, tbAABB view, const RenderOptions* options)
{
	if (sheet->added >= sheet->frameCount || sheet->image.pixels == NULL)
	{
		return false;
	}
	Render_World(&sheet->tile, worldId, view, options);
	int column = sheet->added % sheet->columns;
	int row = sheet->added / sheet->columns;
	int x = SHEET_GAP + column * (sheet->tile.width + SHEET_GAP);
	int y = SHEET_GAP + row * (sheet->tile.height + SHEET_GAP);
	RenderImage_Blit(&sheet->image, &sheet->tile, x, y);
	sheet->added += 1;
	return true;
}

void RenderSheet_Destroy(RenderSheet* sheet)
{
	RenderImage_Destroy(&sheet->image);
	RenderImage_Destroy(&sheet->tile);
	memset(sheet, 0, sizeof(*sheet));
}
