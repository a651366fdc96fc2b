// Internal: the debug-draw calls the world and the joints make (draw.c, joints/*.c). Each skips a
// function the game set to NULL, and takes the float points the drawing code computes, handing
// them on as world positions (doubles in the large-world build).
#pragma once

#include "tumble/types.h"

static inline void tbDrawLine(const tbDebugDraw* draw, tbVec2 p1, tbVec2 p2, tbHexColor color)
{
	if (draw->DrawLineFcn != NULL)
	{
		draw->DrawLineFcn(tbToPos(p1), tbToPos(p2), color, draw->context);
	}
}

static inline void tbDrawCircleAt(const tbDebugDraw* draw, tbVec2 center, float radius, tbHexColor color)
{
	if (draw->DrawCircleFcn != NULL)
	{
		draw->DrawCircleFcn(tbToPos(center), radius, color, draw->context);
	}
}

static inline void tbDrawPointAt(const tbDebugDraw* draw, tbVec2 p, float size, tbHexColor color)
{
	if (draw->DrawPointFcn != NULL)
	{
		draw->DrawPointFcn(tbToPos(p), size, color, draw->context);
	}
}

static inline void tbDrawStringAt(const tbDebugDraw* draw, tbVec2 p, const char* s, tbHexColor color)
{
	if (draw->DrawStringFcn != NULL)
	{
		draw->DrawStringFcn(tbToPos(p), s, color, draw->context);
	}
}
