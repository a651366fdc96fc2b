// Seams: how much a shape sliding along flat ground made of 100 one-metre pieces is kicked up at
// the joints, for three ways of building the ground: a chain (one-sided segments with ghost
// points), 100 separate segment shapes, and a row of 100 adjacent 1 × 1 boxes (what a tile map
// gives). A box (0.5 × 0.5) and a capsule (length 0.5, radius 0.25) are driven at 1, 10 and 30 m/s
// (velocity reset each step; no rotation, no friction, gravity 10 m/s²; 60 Hz, 4 sub-steps).
// On flat ground the exact vertical velocity is zero; what is printed is measured.
//
//   tumble-bench-seams
//
// Output: CSV ground,mover,speed_mps,max_vy_mps,max_rise_m,bumps (bumps: steps with |vy| > 0.01 m/s).

#include "tumble/tumble.h"

#include <math.h>
#include <stdio.h>

#define PIECES 100
#define TIME_STEP (1.0f / 60.0f)

typedef enum Ground
{
	GroundChain,
	GroundSegments,
	GroundBoxes,
	GroundCount
} Ground;

static const char* const s_groundNames[GroundCount] = {"chain", "segments", "box_row"};

static void CreateGround(tbWorldId world, Ground kind)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	tbBodyId ground = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	if (kind == GroundChain)
	{
		tbVec2 points[PIECES + 3];
		for (int i = 0; i < PIECES + 3; ++i)
		{
			points[i] = tbMakeVec2((float)(PIECES + 1 - i), 0.0f); // right to left: solid below
		}
		tbChainDef def = tbDefaultChainDef();
		def.points = points;
		def.count = PIECES + 3;
		tbCreateChain(ground, &def);
		return;
	}
	for (int i = 0; i < PIECES; ++i)
	{
		if (kind == GroundSegments)
		{
			tbSegment segment = {{(float)i, 0.0f}, {(float)(i + 1), 0.0f}};
			tbCreateSegmentShape(ground, &shapeDef, &segment);
		}
		else
		{
			tbPolygon box = tbMakeOffsetBox(0.5f, 0.5f, tbMakeVec2((float)i + 0.5f, -0.5f), tbMakeRot(0.0f));
			tbCreatePolygonShape(ground, &shapeDef, &box);
		}
	}
}

static tbBodyId CreateMover(tbWorldId world, bool capsule)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.fixedRotation = true;
	bodyDef.position = tbMakeVec2(1.0f, 0.25f);
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.material.friction = 0.0f;
	if (capsule)
	{
		tbCapsule shape = {{-0.25f, 0.0f}, {0.25f, 0.0f}, 0.25f};
		tbCreateCapsuleShape(body, &shapeDef, &shape);
	}
	else
	{
		tbPolygon shape = tbMakeBox(0.25f, 0.25f);
		tbCreatePolygonShape(body, &shapeDef, &shape);
	}
	return body;
}

static void Measure(Ground ground, bool capsule, float speed)
{
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.gravity = tbMakeVec2(0.0f, -10.0f);
	tbWorldId world = tbCreateWorld(&worldDef);
	CreateGround(world, ground);
	tbBodyId body = CreateMover(world, capsule);
	for (int step = 0; step < 30; ++step)
	{
		tbWorld_Step(world, TIME_STEP, 4);
	}
	float restY = tbBody_GetPosition(body).y;
	float maxVy = 0.0f, maxRise = 0.0f;
	int bumps = 0;
	for (int step = 0; step < 100000; ++step)
	{
		tbVec2 v = tbBody_GetLinearVelocity(body);
		tbBody_SetLinearVelocity(body, tbMakeVec2(speed, v.y));
		tbWorld_Step(world, TIME_STEP, 4);
		tbVec2 p = tbBody_GetPosition(body);
		if (p.x > (float)PIECES - 2.0f || p.y < -1.0f)
		{
			break;
		}
		if (p.x > 2.0f)
		{
			float vy = fabsf(tbBody_GetLinearVelocity(body).y);
			maxVy = fmaxf(maxVy, vy);
			maxRise = fmaxf(maxRise, p.y - restY);
			bumps += vy > 0.01f ? 1 : 0;
		}
	}
	printf("%s,%s,%g,%.4f,%.4f,%d\n", s_groundNames[ground], capsule ? "capsule" : "box", (double)speed, (double)maxVy,
		   (double)maxRise, bumps);
	tbDestroyWorld(world);
}

int main(void)
{
	const float speeds[3] = {1.0f, 10.0f, 30.0f};
	printf("ground,mover,speed_mps,max_vy_mps,max_rise_m,bumps\n");
	for (int g = 0; g < GroundCount; ++g)
	{
		for (int c = 0; c < 2; ++c)
		{
			for (int s = 0; s < 3; ++s)
			{
				Measure((Ground)g, c == 1, speeds[s]);
			}
		}
	}
	return 0;
}
