// Scene catalogue. Sizes and counts follow the stress scenes of docs/stability.md and the set-ups
// of Box2D v3's benchmark scenes (numbers only). Lengths in metres, densities in kg/m², 60 Hz
// unless said.
#include "catalogue.h"

#include <math.h>
#include <string.h>

#define DEG_TO_RAD (TB_PI / 180.0f)

// ---------------------------------------------------------------------------------------------
// Helpers

// Trigonometry by the library's own functions (tbComputeCosSin, tbAtan2), not the C library's,
// whose last bits differ between platforms (glibc, wasi-libc): a scene is then the same world
// natively and in the browser, to the bit (docs/web.md).
static float Sin(float radians)
{
	return tbComputeCosSin(radians).sine;
}

static float Cos(float radians)
{
	return tbComputeCosSin(radians).cosine;
}

static float Tan(float radians)
{
	tbCosSin cs = tbComputeCosSin(radians);
	return cs.sine / cs.cosine;
}

/// acos(x) for x in [−1, 1], as the angle of the unit vector (x, √(1 − x²)).
static float Acos(float x)
{
	return tbAtan2(sqrtf(1.0f - x * x), x);
}

static tbVec2 V(float x, float y)
{
	return (tbVec2){x, y};
}

static int AddBoxBody(Scene* scene, tbBodyType type, tbVec2 position, float angle, float hx, float hy, float density,
					  float friction)
{
	int body = Scene_AddBody(scene, type, position, angle);
	tbGeometry box = Scene_MakeBoxGeometry(hx, hy, tbVec2_zero, 0.0f);
	Scene_AddGeometry(scene, body, &box, density, friction);
	return body;
}

static int AddCircleBody(Scene* scene, tbBodyType type, tbVec2 position, float radius, float density, float friction)
{
	int body = Scene_AddBody(scene, type, position, 0.0f);
	tbGeometry circle = Scene_MakeCircleGeometry(tbVec2_zero, radius);
	Scene_AddGeometry(scene, body, &circle, density, friction);
	return body;
}

// The usual ground: a static box of half size (hx, 1) whose top is at y = 0.
static int AddGround(Scene* scene, float hx, float friction)
{
	int body = AddBoxBody(scene, tb_staticBody, V(0.0f, -1.0f), 0.0f, hx, 1.0f, 1.0f, friction);
	memcpy(scene->bodies[body].name, "ground", 7);
	return body;
}

static void SetLastShapeRestitution(Scene* scene, int body, float restitution)
{
	SceneBody* b = scene->bodies + body;
	b->shapes[b->shapeCount - 1].restitution = restitution;
}

// Pyramid of squares of half size a whose bottom row rests on y = baseY, centred on centerX.
static void AddPyramid(Scene* scene, int baseCount, float a, float centerX, float baseY, float density, float friction)
{
	for (int row = 0; row < baseCount; ++row)
	{
		float y = baseY + (2.0f * (float)row + 1.0f) * a;
		int count = baseCount - row;
		for (int j = 0; j < count; ++j)
		{
			float x = centerX + (2.0f * (float)j - (float)(count - 1)) * a;
			AddBoxBody(scene, tb_dynamicBody, V(x, y), 0.0f, a, a, density, friction);
		}
	}
}

// ---------------------------------------------------------------------------------------------
// Stacks and pyramids

static Scene* BuildPyramid(void)
{
	Scene* scene = Scene_Create();
	scene->enableSleep = false;
	scene->steps = 300;
	AddGround(scene, 100.0f, 0.6f);
	AddPyramid(scene, 20, 0.5f, 0.0f, 0.0f, 1.0f, 0.6f);
	return scene;
}

/// A column of `count` unit boxes on the ground, `gap` metres apart (0: resting exactly on each
/// other), with x alternating ±`wobble` (0: straight), density 1.
static void AddBoxColumn(Scene* scene, int count, float gap, float wobble, float friction)
{
	for (int i = 0; i < count; ++i)
	{
		float x = (i % 2 == 0) ? wobble : -wobble;
		float y = 0.5f + 0.5f * gap + (1.0f + gap) * (float)i;
		AddBoxBody(scene, tb_dynamicBody, V(x, y), 0.0f, 0.5f, 0.5f, 1.0f, friction);
	}
}

static Scene* BuildVerticalStack(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 300;
	AddGround(scene, 20.0f, 0.6f);
	AddBoxColumn(scene, 10, 0.0f, 0.0f, 0.6f);
	return scene;
}

static Scene* BuildDroppedStack(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	AddGround(scene, 100.0f, 0.6f);
	AddBoxColumn(scene, 15, 0.1f, 0.01f, 0.3f);
	return scene;
}

static Scene* BuildTouchingStack(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	AddGround(scene, 100.0f, 0.6f);
	AddBoxColumn(scene, 20, 0.0f, 0.0f, 0.6f);
	return scene;
}

// Five levels of A-frames (cards leaning ±25°, 0.175 m apart) with flat cards bridging
// neighbouring frames; each level is 0.37 m higher and starts 0.175 m further right.
static Scene* BuildCardHouse(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	AddGround(scene, 10.0f, 0.7f);
	float hx = 0.001f, hy = 0.2f;
	float y = 0.18f, z0 = 0.0f;
	for (int frames = 5; frames > 0; --frames)
	{
		float z = z0;
		for (int i = 0; i < frames; ++i)
		{
			if (i != frames - 1)
			{
				AddBoxBody(scene, tb_dynamicBody, V(z + 0.25f, y + 0.185f), 0.5f * TB_PI, hx, hy, 1.0f, 0.7f);
			}
			AddBoxBody(scene, tb_dynamicBody, V(z, y), -25.0f * DEG_TO_RAD, hx, hy, 1.0f, 0.7f);
			z += 0.175f;
			AddBoxBody(scene, tb_dynamicBody, V(z, y), 25.0f * DEG_TO_RAD, hx, hy, 1.0f, 0.7f);
			z += 0.175f;
		}
		y += 0.37f;
		z0 += 0.175f;
	}
	return scene;
}

// Twenty 0.2 × 2 m dominoes 1 m apart; the first starts tipped 0.25 rad towards the others.
static Scene* BuildDominoes(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 400;
	AddGround(scene, 20.0f, 0.6f);
	float hx = 0.1f, hy = 1.0f, tilt = -0.25f;
	float tippedY = hy * Cos(tilt) + hx * Sin(-tilt);
	for (int i = 0; i < 20; ++i)
	{
		float angle = i == 0 ? tilt : 0.0f;
		float y = i == 0 ? tippedY : hy;
		AddBoxBody(scene, tb_dynamicBody, V(-9.5f + (float)i, y), angle, hx, hy, 1.0f, 0.6f);
	}
	return scene;
}

static Scene* BuildMassRatio(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 300;
	AddGround(scene, 20.0f, 0.6f);
	AddBoxBody(scene, tb_dynamicBody, V(0.0f, 0.5f), 0.0f, 0.5f, 0.5f, 1.0f, 0.6f);
	AddBoxBody(scene, tb_dynamicBody, V(0.0f, 1.5f), 0.0f, 0.5f, 0.5f, 100.0f, 0.6f);
	return scene;
}

// Three base-10 pyramids of 2 m boxes (4 kg); each top box is replaced by one 100, 200 and 300×
// denser, dropped from 2 m above its seat (seat centre at y = 19 m).
static Scene* BuildHeavyOnPyramids(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	AddGround(scene, 100.0f, 0.5f);
	for (int p = 0; p < 3; ++p)
	{
		float centerX = -25.0f + 25.0f * (float)p;
		for (int row = 0; row < 9; ++row)
		{
			int count = 10 - row;
			for (int j = 0; j < count; ++j)
			{
				float x = centerX + (2.0f * (float)j - (float)(count - 1)) * 1.0f;
				AddBoxBody(scene, tb_dynamicBody, V(x, 1.0f + 2.0f * (float)row), 0.0f, 1.0f, 1.0f, 1.0f, 0.5f);
			}
		}
		float density = 100.0f * (float)(p + 1);
		AddBoxBody(scene, tb_dynamicBody, V(centerX, 21.0f), 0.0f, 1.0f, 1.0f, density, 0.5f);
	}
	return scene;
}

// A 20 m box (400 kg) dropped from y = 26 onto two 1 m boxes (1 kg) at x = ±9.
static Scene* BuildBigOnSmall(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	AddGround(scene, 40.0f, 0.6f);
	AddBoxBody(scene, tb_dynamicBody, V(-9.0f, 0.5f), 0.0f, 0.5f, 0.5f, 1.0f, 0.6f);
	AddBoxBody(scene, tb_dynamicBody, V(9.0f, 0.5f), 0.0f, 0.5f, 0.5f, 1.0f, 0.6f);
	AddBoxBody(scene, tb_dynamicBody, V(0.0f, 26.0f), 0.0f, 10.0f, 10.0f, 1.0f, 0.6f);
	return scene;
}

// A base-4 pyramid of 1 m boxes whose centres are 0.75 m apart: every neighbour overlaps by 25%.
static Scene* BuildOverlapRecovery(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 120;
	AddGround(scene, 20.0f, 0.6f);
	float spacing = 0.75f;
	for (int row = 0; row < 4; ++row)
	{
		int count = 4 - row;
		for (int j = 0; j < count; ++j)
		{
			float x = (2.0f * (float)j - (float)(count - 1)) * 0.5f * spacing;
			AddBoxBody(scene, tb_dynamicBody, V(x, 0.5f + spacing * (float)row), 0.0f, 0.5f, 0.5f, 1.0f, 0.6f);
		}
	}
	return scene;
}

// ---------------------------------------------------------------------------------------------
// Friction and restitution

// A point on the top face of a static slab of half height slabHy tilted by angle, at distance
// along from the slab centre, raised by the half height hy of the box resting there.
static tbVec2 OnSlope(tbVec2 center, float angle, float slabHy, float along, float hy)
{
	tbVec2 t = V(Cos(angle), Sin(angle));
	tbVec2 n = V(-Sin(angle), Cos(angle));
	return tbAdd(center, tbAdd(tbMulSV(along, t), tbMulSV(slabHy + hy, n)));
}

// A 1 m box (friction 0.6) at rest on a 20° slope (friction 0.6): μ = 0.6 > tan 20° = 0.36, so it must hold.
static Scene* BuildSlope(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	float angle = 20.0f * DEG_TO_RAD;
	AddBoxBody(scene, tb_staticBody, V(0.0f, 0.0f), angle, 10.0f, 0.5f, 1.0f, 0.6f);
	AddBoxBody(scene, tb_dynamicBody, OnSlope(V(0.0f, 0.0f), angle, 0.5f, 0.0f, 0.5f), angle, 0.5f, 0.5f, 1.0f, 0.6f);
	return scene;
}

// Five 30° ramps (friction 0.8), one above the other, each with a box of friction 0.8, 0.6, 0.4,
// 0.2, 0 near its top. Mixed friction is sqrt(a·b): 0.8, 0.69, 0.57, 0.4, 0 against tan 30° = 0.577.
static Scene* BuildRamp(void)
{
	static const float frictions[5] = {0.8f, 0.6f, 0.4f, 0.2f, 0.0f};
	Scene* scene = Scene_Create();
	scene->steps = 300;
	AddGround(scene, 30.0f, 0.6f);
	float angle = -30.0f * DEG_TO_RAD;
	for (int i = 0; i < 5; ++i)
	{
		tbVec2 center = V(0.0f, 4.0f + 4.0f * (float)i);
		AddBoxBody(scene, tb_staticBody, center, angle, 5.0f, 0.25f, 1.0f, 0.8f);
		tbVec2 p = OnSlope(center, angle, 0.25f, -3.5f, 0.5f);
		AddBoxBody(scene, tb_dynamicBody, p, angle, 0.5f, 0.5f, 1.0f, frictions[i]);
	}
	return scene;
}

// Five balls (r 0.5, e = 1, frictionless) touching in a row, a sixth arriving at 2.71 m/s; no gravity.
static Scene* BuildNewtonsCradle(void)
{
	Scene* scene = Scene_Create();
	scene->gravity = V(0.0f, 0.0f);
	scene->steps = 180;
	for (int i = 0; i < 5; ++i)
	{
		int body = AddCircleBody(scene, tb_dynamicBody, V((float)i, 0.0f), 0.5f, 1.0f, 0.0f);
		SetLastShapeRestitution(scene, body, 1.0f);
	}
	int striker = AddCircleBody(scene, tb_dynamicBody, V(-3.0f, 0.0f), 0.5f, 1.0f, 0.0f);
	SetLastShapeRestitution(scene, striker, 1.0f);
	scene->bodies[striker].linearVelocity = V(2.71f, 0.0f);
	return scene;
}

// ---------------------------------------------------------------------------------------------
// Continuous collision

// Five r 0.1 bullets at 300 m/s into a static 0.1 m thick wall; no gravity.
static Scene* BuildBulletsWall(void)
{
	Scene* scene = Scene_Create();
	scene->gravity = V(0.0f, 0.0f);
	scene->steps = 60;
	AddBoxBody(scene, tb_staticBody, V(0.0f, 0.0f), 0.0f, 0.05f, 3.0f, 1.0f, 0.6f);
	for (int i = 0; i < 5; ++i)
	{
		int body = AddCircleBody(scene, tb_dynamicBody, V(-10.0f, -2.0f + (float)i), 0.1f, 1.0f, 0.6f);
		scene->bodies[body].linearVelocity = V(300.0f, 0.0f);
		scene->bodies[body].bullet = true;
	}
	return scene;
}

// A thin 4 × 0.1 m box at 100 m/s spinning at 50 rad/s towards a static 0.1 m wall; no gravity.
static Scene* BuildSpinningBox(void)
{
	Scene* scene = Scene_Create();
	scene->gravity = V(0.0f, 0.0f);
	scene->steps = 60;
	AddBoxBody(scene, tb_staticBody, V(0.0f, 0.0f), 0.0f, 0.05f, 5.0f, 1.0f, 0.6f);
	int body = AddBoxBody(scene, tb_dynamicBody, V(-10.0f, 0.0f), 0.0f, 2.0f, 0.05f, 1.0f, 0.6f);
	scene->bodies[body].linearVelocity = V(100.0f, 0.0f);
	scene->bodies[body].angularVelocity = 50.0f;
	return scene;
}

// ---------------------------------------------------------------------------------------------
// Crowds

// Four static capsules (r 0.5) around a 20 × 19.5 m box; 625 circles r 0.5 on a 25 × 25 grid
// 0.72 m apart (more circle area than box area); no gravity.
static Scene* BuildConfined(void)
{
	Scene* scene = Scene_Create();
	scene->gravity = V(0.0f, 0.0f);
	scene->steps = 600;
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	tbGeometry walls[4] = {
		Scene_MakeCapsuleGeometry(V(-10.5f, 0.0f), V(10.5f, 0.0f), 0.5f),
		Scene_MakeCapsuleGeometry(V(-10.5f, 0.0f), V(-10.5f, 20.5f), 0.5f),
		Scene_MakeCapsuleGeometry(V(10.5f, 0.0f), V(10.5f, 20.5f), 0.5f),
		Scene_MakeCapsuleGeometry(V(-10.5f, 20.5f), V(10.5f, 20.5f), 0.5f),
	};
	for (int i = 0; i < 4; ++i)
	{
		Scene_AddGeometry(scene, ground, walls + i, 1.0f, 0.6f);
	}
	for (int i = 0; i < 25; ++i)
	{
		for (int j = 0; j < 25; ++j)
		{
			tbVec2 p = V(-8.64f + 0.72f * (float)i, 10.25f - 8.64f + 0.72f * (float)j);
			AddCircleBody(scene, tb_dynamicBody, p, 0.5f, 1.0f, 0.6f);
		}
	}
	return scene;
}

// One rigid "human" (no joints): legs and torso capsules and a head circle, origin at the feet.
static void AddRigidHuman(Scene* scene, int body)
{
	tbGeometry legs = Scene_MakeCapsuleGeometry(V(0.0f, 0.2f), V(0.0f, 0.75f), 0.12f);
	tbGeometry torso = Scene_MakeCapsuleGeometry(V(0.0f, 1.0f), V(0.0f, 1.35f), 0.15f);
	tbGeometry head = Scene_MakeCircleGeometry(V(0.0f, 1.68f), 0.13f);
	Scene_AddGeometry(scene, body, &legs, 1.0f, 0.6f);
	Scene_AddGeometry(scene, body, &torso, 1.0f, 0.6f);
	Scene_AddGeometry(scene, body, &head, 1.0f, 0.6f);
}

// A body of one of four kinds, chosen by kind % 4: rigid human, circle, box, triangle.
static void AddRainBody(Scene* scene, tbVec2 position, int kind)
{
	int body = Scene_AddBody(scene, tb_dynamicBody, position, 0.0f);
	tbVec2 triangle[3] = {V(-0.3f, 0.0f), V(0.3f, 0.0f), V(0.0f, 0.5f)};
	tbGeometry geometry;
	switch (kind % 4)
	{
		case 0:
			AddRigidHuman(scene, body);
			return;
		case 1:
			geometry = Scene_MakeCircleGeometry(V(0.0f, 0.25f), 0.25f);
			break;
		case 2:
			geometry = Scene_MakeBoxGeometry(0.2f, 0.2f, V(0.0f, 0.2f), 0.0f);
			break;
		default:
			geometry = Scene_MakePolygonGeometry(triangle, 3, 0.0f);
			break;
	}
	Scene_AddGeometry(scene, body, &geometry, 1.0f, 0.6f);
}

// The floors of Box2D v3's rain benchmark: `rows` floors 45 m apart, each a row of gridCount + 1
// static boxes of side gridSize on one static body (friction 0.6).
static void AddRainFloors(Scene* scene, int rows, int gridCount, float gridSize)
{
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	for (int i = 0; i < rows; ++i)
	{
		for (int j = 0; j <= gridCount; ++j)
		{
			tbVec2 center = V(-0.5f * (float)gridCount * gridSize + (float)j * gridSize, 45.0f * (float)i);
			tbGeometry box = Scene_MakeBoxGeometry(0.5f * gridSize, 0.5f * gridSize, center, 0.0f);
			Scene_AddGeometry(scene, ground, &box, 1.0f, 0.6f);
		}
	}
}

// Box2D v3's rain benchmark without joints: 5 floors (each 501 static 0.5 m boxes, 45 m apart);
// above each floor 40 groups of 5 bodies, every body a rigid human or a circle, box or triangle.
// Box2D drops jointed humans a column at a time (the exact scene is `rain`); here everything is
// present from the start.
static Scene* BuildRainRigid(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 1000;
	const int rowCount = 5, columnCount = 40, groupSize = 5, gridCount = 500;
	const float gridSize = 0.5f;
	AddRainFloors(scene, rowCount, gridCount, gridSize);
	float span = (float)gridCount * gridSize;
	float groupDistance = span / (float)columnCount;
	for (int row = 0; row < rowCount; ++row)
	{
		for (int column = 0; column < columnCount; ++column)
		{
			float x = -0.5f * span + groupDistance * ((float)column + 0.5f);
			for (int k = 0; k < groupSize; ++k)
			{
				AddRainBody(scene, V(x + 0.5f * (float)k, 40.0f + 45.0f * (float)row), row + column + k);
			}
		}
	}
	return scene;
}

// ---------------------------------------------------------------------------------------------
// Box2D v3 benchmark scenes

// Base 100: 5,050 unit boxes on a ground box of half size (100, 1); sleep off.
static Scene* BuildLargePyramid(void)
{
	Scene* scene = Scene_Create();
	scene->enableSleep = false;
	scene->steps = 500;
	AddGround(scene, 100.0f, 0.6f);
	AddPyramid(scene, 100, 0.5f, 0.0f, 0.0f, 1.0f, 0.6f);
	return scene;
}

// 20 rows × 20 columns of base-10 pyramids of unit boxes, each row on its own ground segment
// (11 m apart); 22,000 boxes, sleep off.
static Scene* BuildManyPyramids(void)
{
	Scene* scene = Scene_Create();
	scene->enableSleep = false;
	scene->steps = 200;
	const int baseCount = 10, rowCount = 20, columnCount = 20;
	const float extent = 0.5f;
	float groundDeltaY = 2.0f * extent * ((float)baseCount + 1.0f);
	float groundWidth = 2.0f * extent * (float)columnCount * ((float)baseCount + 1.0f);
	float baseWidth = 2.0f * extent * (float)baseCount;
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	for (int i = 0; i < rowCount; ++i)
	{
		float y = groundDeltaY * (float)i;
		tbGeometry segment = Scene_MakeSegmentGeometry(V(-0.5f * groundWidth, y), V(0.5f * groundWidth, y));
		Scene_AddGeometry(scene, ground, &segment, 1.0f, 0.6f);
	}
	for (int i = 0; i < rowCount; ++i)
	{
		for (int j = 0; j < columnCount; ++j)
		{
			// left edge of the pyramid's base, as Box2D places it
			float left = -0.5f * groundWidth + (float)j * (baseWidth + 2.0f * extent) + 2.0f * extent - 0.5f;
			AddPyramid(scene, baseCount, extent, left + baseWidth * 0.5f, groundDeltaY * (float)i, 1.0f, 0.6f);
		}
	}
	return scene;
}

// A 20 m drum of four boxes (density 50) turning at 25°/s about (0, 10) with 2,025 boxes of
// half size 0.125 inside. Box2D drives a dynamic drum with a motorised revolute joint to ground
// (1e8 N·m): `tumbler_motor` does the same; `tumbler` makes the drum a kinematic body with that
// angular velocity (the variant every engine ran before Tumble had joints).
static Scene* MakeTumbler(bool motorised)
{
	Scene* scene = Scene_Create();
	scene->steps = 750;
	int ground = motorised ? Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f) : -1;
	int drum = Scene_AddBody(scene, motorised ? tb_dynamicBody : tb_kinematicBody, V(0.0f, 10.0f), 0.0f);
	scene->bodies[drum].angularVelocity = motorised ? 0.0f : 25.0f * DEG_TO_RAD;
	tbGeometry walls[4] = {
		Scene_MakeBoxGeometry(0.5f, 10.0f, V(10.0f, 0.0f), 0.0f),
		Scene_MakeBoxGeometry(0.5f, 10.0f, V(-10.0f, 0.0f), 0.0f),
		Scene_MakeBoxGeometry(10.0f, 0.5f, V(0.0f, 10.0f), 0.0f),
		Scene_MakeBoxGeometry(10.0f, 0.5f, V(0.0f, -10.0f), 0.0f),
	};
	for (int i = 0; i < 4; ++i)
	{
		Scene_AddGeometry(scene, drum, walls + i, 50.0f, 0.6f);
	}
	if (motorised)
	{
		SceneJoint* axle = Scene_AddJoint(scene, tb_revoluteJoint, ground, drum);
		Scene_SetJointAnchor(scene, axle, V(0.0f, 10.0f));
		axle->def.revolute.enableMotor = true;
		axle->def.revolute.motorSpeed = 25.0f * DEG_TO_RAD;
		axle->def.revolute.maxMotorTorque = 1e8f;
	}
	const int gridCount = 45;
	for (int i = 0; i < gridCount; ++i)
	{
		for (int j = 0; j < gridCount; ++j)
		{
			tbVec2 p = V(-0.2f * (float)gridCount + 0.4f * (float)j, -0.2f * (float)gridCount + 10.0f + 0.4f * (float)i);
			AddBoxBody(scene, tb_dynamicBody, p, 0.0f, 0.125f, 0.125f, 1.0f, 0.6f);
		}
	}
	return scene;
}

static Scene* BuildTumbler(void)
{
	return MakeTumbler(false);
}

static Scene* BuildTumblerMotor(void)
{
	return MakeTumbler(true);
}

// An 8 m box (density 8) at 40 m/s into a 120 × 80 block of 0.4 m boxes that start asleep; no gravity.
static Scene* BuildSmash(void)
{
	Scene* scene = Scene_Create();
	scene->gravity = V(0.0f, 0.0f);
	scene->steps = 300;
	int hammer = AddBoxBody(scene, tb_dynamicBody, V(-20.0f, 0.0f), 0.0f, 4.0f, 4.0f, 8.0f, 0.6f);
	scene->bodies[hammer].linearVelocity = V(40.0f, 0.0f);
	const int columns = 120, rows = 80;
	const float d = 0.4f;
	for (int i = 0; i < columns; ++i)
	{
		for (int j = 0; j < rows; ++j)
		{
			tbVec2 p = V((float)i * d + 30.0f, ((float)j - (float)rows / 2.0f) * d);
			int body = AddBoxBody(scene, tb_dynamicBody, p, 0.0f, 0.5f * d, 0.5f * d, 1.0f, 0.6f);
			scene->bodies[body].isAwake = false;
		}
	}
	return scene;
}

// Box2D v3's spinner: a rounded blade (0.8 × 40 m, radius 0.2) spinning at 5 rad/s about (0, 12)
// inside a 360-segment circle of radius 40 centred at (0, 32) (Box2D uses a chain loop), stirring
// 6,076 capsules, circles and squares (density 0.25, friction 0.1, restitution 0.1). Box2D drives
// a dynamic blade with a motorised revolute joint of unbounded torque: `spinner_motor` does the
// same; `spinner` makes the blade a kinematic body with that angular velocity.
static Scene* MakeSpinner(bool motorised)
{
	Scene* scene = Scene_Create();
	scene->steps = 1000;
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	const int pointCount = 360;
	for (int i = 0; i < pointCount; ++i)
	{
		float a1 = -2.0f * TB_PI * (float)i / (float)pointCount;
		float a2 = -2.0f * TB_PI * (float)(i + 1) / (float)pointCount;
		tbGeometry segment = Scene_MakeSegmentGeometry(V(40.0f * Cos(a1), 32.0f + 40.0f * Sin(a1)),
													   V(40.0f * Cos(a2), 32.0f + 40.0f * Sin(a2)));
		Scene_AddGeometry(scene, ground, &segment, 1.0f, 0.1f);
	}
	int blade = Scene_AddBody(scene, motorised ? tb_dynamicBody : tb_kinematicBody, V(0.0f, 12.0f), 0.0f);
	scene->bodies[blade].angularVelocity = motorised ? 0.0f : 5.0f;
	tbGeometry bladeShape = Scene_MakeBoxGeometry(0.4f, 20.0f, tbVec2_zero, 0.0f);
	bladeShape.polygon = tbMakeRoundedBox(0.4f, 20.0f, 0.2f);
	Scene_AddGeometry(scene, blade, &bladeShape, 1.0f, 0.0f);
	if (motorised)
	{
		SceneJoint* axle = Scene_AddJoint(scene, tb_revoluteJoint, ground, blade);
		Scene_SetJointAnchor(scene, axle, V(0.0f, 12.0f));
		axle->def.revolute.enableMotor = true;
		axle->def.revolute.motorSpeed = 5.0f;
		axle->def.revolute.maxMotorTorque = 1e30f; // unbounded (v3: FLT_MAX, which a scene file cannot round-trip)
	}
	tbGeometry kinds[3] = {
		Scene_MakeCapsuleGeometry(V(-0.25f, 0.0f), V(0.25f, 0.0f), 0.25f),
		Scene_MakeCircleGeometry(tbVec2_zero, 0.35f),
		Scene_MakeBoxGeometry(0.35f, 0.35f, tbVec2_zero, 0.0f),
	};
	float x = -23.0f, y = 2.0f;
	for (int i = 0; i < 6076; ++i)
	{
		int body = Scene_AddBody(scene, tb_dynamicBody, V(x, y), 0.0f);
		int shape = Scene_AddGeometry(scene, body, kinds + i % 3, 0.25f, 0.1f);
		scene->bodies[body].shapes[shape].restitution = 0.1f;
		x += 0.5f;
		if (x >= 23.0f)
		{
			x = -23.0f;
			y += 0.5f;
		}
	}
	return scene;
}

static Scene* BuildSpinner(void)
{
	return MakeSpinner(false);
}

static Scene* BuildSpinnerMotor(void)
{
	return MakeSpinner(true);
}

// Box2D v3's washer: a kinematic drum about (0, 10) turning at 25°/s (and drifting at
// (0.001, −0.002) m/s, as v3 sets it) built from 36 ring pieces between radii 16 and 18 (each
// spans its 10° and 1° more on either side, so neighbours overlap) and 4 paddles from radius 14
// to 16; inside, 90 × 90 squares of half size 0.1 on a 0.21 m grid with hit events on.
static void AddWasherDrum(Scene* scene, int drum)
{
	const float r0 = 14.0f, r1 = 16.0f, r2 = 18.0f;
	const float piece = TB_PI / 18.0f, overlap = 0.1f * piece;
	for (int i = 0; i < 36; ++i)
	{
		float a1 = piece * (float)i, a2 = i == 35 ? 0.0f : piece * (float)(i + 1);
		tbVec2 u1 = V(Cos(a1), Sin(a1)), u2 = V(Cos(a2), Sin(a2));
		tbVec2 o1 = V(Cos(a1 - overlap), Sin(a1 - overlap)), o2 = V(Cos(a2 + overlap), Sin(a2 + overlap));
		tbVec2 ring[4] = {tbMulSV(r1, o1), tbMulSV(r2, o1), tbMulSV(r1, o2), tbMulSV(r2, o2)};
		tbGeometry ringPiece = Scene_MakePolygonGeometry(ring, 4, 0.0f);
		Scene_AddGeometry(scene, drum, &ringPiece, 1.0f, 0.6f);
		if (i % 9 == 0)
		{
			tbVec2 paddle[4] = {tbMulSV(r0, u1), tbMulSV(r1, u1), tbMulSV(r0, u2), tbMulSV(r1, u2)};
			tbGeometry paddlePiece = Scene_MakePolygonGeometry(paddle, 4, 0.0f);
			Scene_AddGeometry(scene, drum, &paddlePiece, 1.0f, 0.6f);
		}
	}
}

static Scene* BuildWasher(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 500;
	int drum = Scene_AddBody(scene, tb_kinematicBody, V(0.0f, 10.0f), 0.0f);
	scene->bodies[drum].angularVelocity = 25.0f * DEG_TO_RAD;
	scene->bodies[drum].linearVelocity = V(0.001f, -0.002f);
	AddWasherDrum(scene, drum);
	const int gridCount = 90;
	const float a = 0.1f;
	for (int i = 0; i < gridCount; ++i)
	{
		for (int j = 0; j < gridCount; ++j)
		{
			tbVec2 p = V(-1.1f * a * (float)gridCount + 2.1f * a * (float)j,
						 -1.1f * a * (float)gridCount + 10.0f + 2.1f * a * (float)i);
			int body = AddBoxBody(scene, tb_dynamicBody, p, 0.0f, a, a, 1.0f, 0.6f);
			scene->bodies[body].shapes[0].enableHitEvents = true;
		}
	}
	return scene;
}

// The pit of v3's junkyard and compounds benchmarks on one static body: a floor of unit cells
// (boxes of half size 0.55 × 0.5, so neighbours overlap) centred on y = 0 from x = −halfSpan to
// +halfSpan, and a wall of `wallCount` cells (0.5 × 0.55) at each end from y = 1 up.
static int AddPit(Scene* scene, int halfSpan, int wallCount)
{
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	for (int i = -halfSpan; i <= halfSpan; ++i)
	{
		tbGeometry cell = Scene_MakeBoxGeometry(0.55f, 0.5f, V((float)i, 0.0f), 0.0f);
		Scene_AddGeometry(scene, ground, &cell, 1.0f, 0.6f);
	}
	for (int side = -1; side <= 1; side += 2)
	{
		for (int i = 1; i <= wallCount; ++i)
		{
			tbGeometry cell = Scene_MakeBoxGeometry(0.5f, 0.55f, V((float)(side * halfSpan), (float)i), 0.0f);
			Scene_AddGeometry(scene, ground, &cell, 1.0f, 0.6f);
		}
	}
	return ground;
}

// Box2D v3's junkyard: 200 columns × 40 rows of pentagons (radius 0.25, vertices at angles
// k·π(√5 − 1), k = 0..4) dropped into a 160 m pit from y = 15, alternately 0.1 m left and right
// of their column; a kinematic box (4 × 8 m, bottom at its origin) driven along x = 60·sin(0.2·t).
static Scene* BuildJunkyard(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 800;
	AddPit(scene, 80, 50);
	const int columnCount = 200, rowCount = 40;
	const float radius = 0.25f, phi = TB_PI * (sqrtf(5.0f) - 1.0f);
	tbVec2 points[5];
	for (int k = 0; k < 5; ++k)
	{
		points[k] = V(radius * Cos(phi * (float)k), radius * Sin(phi * (float)k));
	}
	tbGeometry pentagon = Scene_MakePolygonGeometry(points, 5, 0.0f);
	float side = -0.1f;
	for (int i = 0; i < columnCount; ++i)
	{
		float x = 1.5f * (2.0f * (float)i - (float)columnCount) * radius;
		for (int j = 0; j < rowCount; ++j)
		{
			int body = Scene_AddBody(scene, tb_dynamicBody, V(x + side, 4.0f * radius * (float)j + 15.0f), 0.0f);
			Scene_AddGeometry(scene, body, &pentagon, 1.0f, 0.6f);
			side = -side;
		}
	}
	int pusher = Scene_AddBody(scene, tb_kinematicBody, tbVec2_zero, 0.0f);
	tbGeometry blade = Scene_MakeBoxGeometry(2.0f, 4.0f, V(0.0f, 4.0f), 0.0f);
	Scene_AddGeometry(scene, pusher, &blade, 1.0f, 0.6f);
	scene->bodies[pusher].drive = (SceneDrive){true, V(60.0f, 0.0f), 0.2f};
	return scene;
}

// Box2D v3's compounds: 20 columns × 150 rows of bodies made of two triangles, (−1, 0), (0.5, 1),
// (0, 2) and its mirror image (density 1, friction 0.5), 2 m apart in x (alternately ±0.25 m off)
// and 2.25 m in y from y = 5.575, falling into an 80 m pit 100 cells deep; a segment at y = −80
// catches what spills out.
static Scene* BuildCompounds(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 500;
	int ground = AddPit(scene, 40, 100);
	tbGeometry catcher = Scene_MakeSegmentGeometry(V(-800.0f, -80.0f), V(800.0f, -80.0f));
	Scene_AddGeometry(scene, ground, &catcher, 1.0f, 0.6f);
	const tbVec2 left[3] = {V(-1.0f, 0.0f), V(0.5f, 1.0f), V(0.0f, 2.0f)};
	const tbVec2 right[3] = {V(1.0f, 0.0f), V(-0.5f, 1.0f), V(0.0f, 2.0f)};
	tbGeometry halves[2] = {Scene_MakePolygonGeometry(left, 3, 0.0f), Scene_MakePolygonGeometry(right, 3, 0.0f)};
	const int columnCount = 20, rowCount = 150;
	float side = 0.25f;
	for (int i = 0; i < columnCount; ++i)
	{
		float x = 2.0f * (float)i - (float)columnCount + 1.0f;
		for (int j = 0; j < rowCount; ++j)
		{
			int body = Scene_AddBody(scene, tb_dynamicBody, V(x + side, 2.25f * (float)j + 0.575f + 5.0f), 0.0f);
			Scene_AddGeometry(scene, body, halves + 0, 1.0f, 0.5f);
			Scene_AddGeometry(scene, body, halves + 1, 1.0f, 0.5f);
			side = -side;
		}
	}
	return scene;
}

// ---------------------------------------------------------------------------------------------
// Joints

/// Box2D v3's ball and chain with the numbers of Tumble's joint issue: 30 capsule links 0.5 m from
/// pivot to pivot (radius 0.05, density 20) on revolute joints from a static pivot at y = 20,
/// holding a ball of 100 times a link's mass, released horizontally. The joint-tree test measures
/// its stretch (tests/test_joint.c).
static Scene* BuildPendulumChain(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	int ground = AddGround(scene, 40.0f, 0.6f);
	const int count = 30;
	const float hx = 0.25f, top = 20.0f;
	int previous = ground;
	float linkMass = 0.0f;
	for (int i = 0; i < count; ++i)
	{
		int link = Scene_AddBody(scene, tb_dynamicBody, V(2.0f * hx * (float)i + hx, top), 0.0f);
		tbGeometry capsule = Scene_MakeCapsuleGeometry(V(-hx, 0.0f), V(hx, 0.0f), 0.05f);
		Scene_AddGeometry(scene, link, &capsule, 20.0f, 0.6f);
		linkMass = tbComputeShapeMass(&capsule, 20.0f).mass;
		SceneJoint* joint = Scene_AddJoint(scene, tb_revoluteJoint, previous, link);
		Scene_SetJointAnchor(scene, joint, V(2.0f * hx * (float)i, top));
		previous = link;
	}
	const float radius = 0.5f;
	int ball = Scene_AddBody(scene, tb_dynamicBody, V(2.0f * hx * (float)count + radius, top), 0.0f);
	tbGeometry circle = Scene_MakeCircleGeometry(tbVec2_zero, radius);
	Scene_AddGeometry(scene, ball, &circle, 100.0f * linkMass / (TB_PI * radius * radius), 0.6f);
	SceneJoint* joint = Scene_AddJoint(scene, tb_revoluteJoint, previous, ball);
	Scene_SetJointAnchor(scene, joint, V(2.0f * hx * (float)count, top));
	return scene;
}

/// A rope bridge: 20 planks (1 x 0.1 m, density 2) on revolute joints between two posts 18 m
/// apart, hung in a shallow V (a taut bridge could not sag without stretching), with 12 boxes
/// (0.5 m, density 2) dropped on it.
static Scene* BuildRopeBridge(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	int ground = AddGround(scene, 40.0f, 0.6f);
	const int count = 20;
	const float span = 18.0f, y = 8.0f;
	float half = 0.5f * (float)count;
	float slope = Acos(0.5f * span / half); // each half of the V is `half` planks of 1 m
	tbVec2 pivot = V(-0.5f * span, y);
	int previous = ground;
	for (int i = 0; i < count; ++i)
	{
		float angle = i < count / 2 ? -slope : slope;
		tbVec2 along = V(Cos(angle), Sin(angle));
		int plank = Scene_AddBody(scene, tb_dynamicBody, tbMulAdd(pivot, 0.5f, along), angle);
		tbGeometry box = Scene_MakeBoxGeometry(0.5f, 0.05f, tbVec2_zero, 0.0f);
		Scene_AddGeometry(scene, plank, &box, 2.0f, 0.6f);
		SceneJoint* joint = Scene_AddJoint(scene, tb_revoluteJoint, previous, plank);
		Scene_SetJointAnchor(scene, joint, pivot);
		pivot = tbAdd(pivot, along);
		previous = plank;
	}
	SceneJoint* joint = Scene_AddJoint(scene, tb_revoluteJoint, previous, ground);
	Scene_SetJointAnchor(scene, joint, pivot);
	for (int i = 0; i < 12; ++i)
	{
		AddBoxBody(scene, tb_dynamicBody, V(-6.0f + (float)i, y + 2.0f + 0.6f * (float)(i % 3)), 0.0f, 0.25f, 0.25f, 2.0f,
				   0.6f);
	}
	return scene;
}

/// A car on hills: a 4 x 0.6 m chassis (density 1) on two wheels (radius 0.4, density 1, friction
/// 1.2) with wheel joints: vertical suspension 5 Hz, damping ratio 0.7, travel ±0.25 m, rear motor
/// at −12 rad/s up to 100 N·m. The ground is 200 segments of a sum of two sines (amplitude 1 m).
static Scene* BuildCar(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 900;
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	memcpy(scene->bodies[ground].name, "ground", 7);
	for (int i = 0; i < 200; ++i)
	{
		float x1 = -20.0f + (float)i, x2 = x1 + 1.0f;
		float y1 = x1 < 0.0f ? 0.0f : 0.6f * Sin(0.35f * x1) + 0.4f * Sin(0.9f * x1);
		float y2 = x2 < 0.0f ? 0.0f : 0.6f * Sin(0.35f * x2) + 0.4f * Sin(0.9f * x2);
		tbGeometry segment = Scene_MakeSegmentGeometry(V(x1, y1), V(x2, y2));
		Scene_AddGeometry(scene, ground, &segment, 1.0f, 0.9f);
	}
	int chassis = AddBoxBody(scene, tb_dynamicBody, V(-10.0f, 1.5f), 0.0f, 2.0f, 0.3f, 1.0f, 0.6f);
	memcpy(scene->bodies[chassis].name, "chassis", 8);
	for (int side = 0; side < 2; ++side)
	{
		float x = side == 0 ? -11.4f : -8.6f;
		int wheel = AddCircleBody(scene, tb_dynamicBody, V(x, 0.6f), 0.4f, 1.0f, 1.2f);
		SceneJoint* joint = Scene_AddJoint(scene, tb_wheelJoint, chassis, wheel);
		Scene_SetJointAnchor(scene, joint, V(x, 0.6f));
		joint->def.base.localFrameA.q = tbMakeRot(0.5f * TB_PI); // the suspension axis is vertical
		tbWheelJointDef* def = &joint->def.wheel;
		def->hertz = 5.0f;
		def->dampingRatio = 0.7f;
		def->enableLimit = true;
		def->lowerTranslation = -0.25f;
		def->upperTranslation = 0.25f;
		def->enableMotor = side == 0;
		def->motorSpeed = -12.0f;
		def->maxMotorTorque = side == 0 ? 100.0f : 0.0f;
	}
	return scene;
}

/// One ragdoll of 10 bodies at (x, y): head (circle 0.15), torso (capsule), upper and lower arms,
/// thighs and shins (capsules), density 1, on revolute joints with limits and a little friction (a
/// motor at speed 0 with 0.5 N·m). Its bones overlap one another and share the negative collision
/// group `group`, so they never collide with each other (as Box2D's ragdolls), only with the rest.
static void AddRagdoll(Scene* scene, float x, float y, int group)
{
	typedef struct Bone
	{
		int parent; ///< index in this ragdoll, −1 for the torso
		tbVec2 from, to;
		float radius, lower, upper;
	} Bone;
	static const Bone bones[10] = {
		{-1, {0.0f, 0.35f}, {0.0f, -0.25f}, 0.14f, 0.0f, 0.0f},	 // torso
		{0, {0.0f, 0.55f}, {0.0f, 0.55f}, 0.15f, -0.5f, 0.5f},	 // head
		{0, {-0.05f, 0.3f}, {-0.05f, -0.05f}, 0.06f, -2.5f, 1.5f}, // upper arms
		{0, {0.05f, 0.3f}, {0.05f, -0.05f}, 0.06f, -2.5f, 1.5f},
		{2, {-0.05f, -0.05f}, {-0.05f, -0.35f}, 0.05f, 0.0f, 2.5f}, // lower arms
		{3, {0.05f, -0.05f}, {0.05f, -0.35f}, 0.05f, 0.0f, 2.5f},
		{0, {-0.07f, -0.3f}, {-0.07f, -0.75f}, 0.08f, -1.5f, 0.5f}, // thighs
		{0, {0.07f, -0.3f}, {0.07f, -0.75f}, 0.08f, -1.5f, 0.5f},
		{6, {-0.07f, -0.75f}, {-0.07f, -1.2f}, 0.07f, 0.0f, 2.0f}, // shins
		{7, {0.07f, -0.75f}, {0.07f, -1.2f}, 0.07f, 0.0f, 2.0f},
	};
	int ids[10];
	for (int i = 0; i < 10; ++i)
	{
		const Bone* bone = bones + i;
		tbVec2 center = V(x + 0.5f * (bone->from.x + bone->to.x), y + 0.5f * (bone->from.y + bone->to.y));
		ids[i] = Scene_AddBody(scene, tb_dynamicBody, center, 0.0f);
		tbVec2 half = V(0.5f * (bone->to.x - bone->from.x), 0.5f * (bone->to.y - bone->from.y));
		tbGeometry shape = i == 1 ? Scene_MakeCircleGeometry(tbVec2_zero, bone->radius)
								  : Scene_MakeCapsuleGeometry(tbNeg(half), half, bone->radius);
		int shapeIndex = Scene_AddGeometry(scene, ids[i], &shape, 1.0f, 0.6f);
		scene->bodies[ids[i]].shapes[shapeIndex].groupIndex = group;
		if (bone->parent < 0)
		{
			continue;
		}
		SceneJoint* joint = Scene_AddJoint(scene, tb_revoluteJoint, ids[bone->parent], ids[i]);
		tbVec2 pivot = i == 1 ? V(x, y + 0.45f) : V(x + bone->from.x, y + bone->from.y);
		Scene_SetJointAnchor(scene, joint, pivot);
		tbRevoluteJointDef* def = &joint->def.revolute;
		def->enableLimit = true;
		def->lowerAngle = bone->lower;
		def->upperAngle = bone->upper;
		def->enableMotor = true;
		def->maxMotorTorque = 0.5f;
	}
}

/// Box2D v3's joint_grid benchmark: 100 × 100 circles of radius 0.4 one metre apart, each joined
/// by a revolute joint to the one above and the one to its left; the seven bodies at the top
/// middle are static, so the grid hangs and swings; sleep off. As in v3, the circles are kept from
/// colliding with one another by their filter: category 2, mask everything but 2.
static Scene* BuildJointGrid(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 300;
	scene->enableSleep = false;
	const int n = 100;
	for (int k = 0; k < n; ++k)
	{
		for (int i = 0; i < n; ++i)
		{
			bool anchored = k >= n / 2 - 3 && k <= n / 2 + 3 && i == 0;
			int body = AddCircleBody(scene, anchored ? tb_staticBody : tb_dynamicBody, V((float)k, -(float)i), 0.4f,
									 1.0f, 0.6f);
			scene->bodies[body].shapes[0].categoryBits = 2u;
			scene->bodies[body].shapes[0].maskBits = ~(uint64_t)2u;
			if (i > 0)
			{
				SceneJoint* joint = Scene_AddJoint(scene, tb_revoluteJoint, body - 1, body);
				joint->def.base.localFrameA.p = V(0.0f, -0.5f);
				joint->def.base.localFrameB.p = V(0.0f, 0.5f);
				joint->def.base.drawScale = 0.4f;
			}
			if (k > 0)
			{
				SceneJoint* joint = Scene_AddJoint(scene, tb_revoluteJoint, body - n, body);
				joint->def.base.localFrameA.p = V(0.5f, 0.0f);
				joint->def.base.localFrameB.p = V(-0.5f, 0.0f);
				joint->def.base.drawScale = 0.4f;
			}
		}
	}
	return scene;
}

/// Box2D v3's rain benchmark with jointed ragdolls: its five floors (501 static 0.5 m boxes each,
/// 45 m apart) and 40 columns of 5 ragdolls over each floor (the catalogue's 10-bone ragdoll:
/// capsules and a head on revolute joints with limits and 0.5 N·m friction motors). v3 drops its
/// 11-bone humans a column at a time and recycles the oldest column; here all 1,000 ragdolls
/// (10,000 bodies, 9,000 joints) are present from the start and fall together.
static Scene* BuildRainRagdolls(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	const int rowCount = 5, columnCount = 40, groupSize = 5, gridCount = 500;
	const float gridSize = 0.5f;
	AddRainFloors(scene, rowCount, gridCount, gridSize);
	float span = (float)gridCount * gridSize;
	float groupDistance = span / (float)columnCount;
	int group = -1;
	for (int row = 0; row < rowCount; ++row)
	{
		for (int column = 0; column < columnCount; ++column)
		{
			float x = -0.5f * span + groupDistance * ((float)column + 0.5f);
			for (int k = 0; k < groupSize; ++k)
			{
				AddRagdoll(scene, x + 0.5f * (float)k, 41.5f + 45.0f * (float)row, group--);
			}
		}
	}
	return scene;
}

/// A door: a 0.1 × 2 m plank hinged at its bottom-left corner to the ground (revolute, limits 0 to
/// 90°), shoved by a 2 m/s box sliding into it from the right on frictionless ground.
static Scene* BuildDoor(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 240;
	int ground = AddGround(scene, 20.0f, 0.0f);
	int door = AddBoxBody(scene, tb_dynamicBody, V(0.05f, 1.0f), 0.0f, 0.05f, 1.0f, 1.0f, 0.0f);
	SceneJoint* hinge = Scene_AddJoint(scene, tb_revoluteJoint, ground, door);
	Scene_SetJointAnchor(scene, hinge, V(0.0f, 0.0f));
	hinge->def.revolute.enableLimit = true;
	hinge->def.revolute.lowerAngle = 0.0f;
	hinge->def.revolute.upperAngle = 0.5f * TB_PI;
	int box = AddBoxBody(scene, tb_dynamicBody, V(3.0f, 1.5f), 0.0f, 0.5f, 0.5f, 4.0f, 0.0f);
	scene->bodies[box].linearVelocity = V(-2.0f, 0.0f);
	scene->bodies[box].gravityScale = 0.0f; // slides at 1.5 m so it meets the door's upper half
	return scene;
}

/// A piston: a pusher on a horizontal prismatic joint to the ground, driven by a motor at 1 m/s
/// (200 N) between limits 0 and 4 m, pushing three boxes along the ground.
static Scene* BuildPiston(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 300;
	int ground = AddGround(scene, 20.0f, 0.6f);
	int pusher = AddBoxBody(scene, tb_dynamicBody, V(-4.0f, 0.5f), 0.0f, 0.25f, 0.5f, 1.0f, 0.6f);
	SceneJoint* slide = Scene_AddJoint(scene, tb_prismaticJoint, ground, pusher);
	Scene_SetJointAnchor(scene, slide, V(-4.0f, 0.5f));
	tbPrismaticJointDef* p = &slide->def.prismatic;
	p->enableMotor = true;
	p->motorSpeed = 1.0f;
	p->maxMotorForce = 200.0f;
	p->enableLimit = true;
	p->lowerTranslation = 0.0f;
	p->upperTranslation = 4.0f;
	for (int i = 0; i < 3; ++i)
	{
		AddBoxBody(scene, tb_dynamicBody, V(-2.0f + 0.8f * (float)i, 0.35f), 0.0f, 0.35f, 0.35f, 1.0f, 0.6f);
	}
	return scene;
}

/// Dragging a box with the mouse, the Box2D v3.2 way: a motor joint pulls the box toward a
/// target with a spring (4 Hz, damping ratio 0.7, at most 500 N). The target is a kinematic body
/// (no shape) driven along x = 3 sin(t) at height 3 m, standing for the mouse.
static Scene* BuildMouseDrag(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	AddGround(scene, 20.0f, 0.6f);
	int mouse = Scene_AddBody(scene, tb_kinematicBody, V(0.0f, 3.0f), 0.0f);
	scene->bodies[mouse].drive = (SceneDrive){true, V(3.0f, 0.0f), 1.0f};
	int box = AddBoxBody(scene, tb_dynamicBody, V(0.0f, 0.5f), 0.0f, 0.5f, 0.5f, 1.0f, 0.6f);
	SceneJoint* drag = Scene_AddJoint(scene, tb_motorJoint, mouse, box);
	tbMotorJointDef* m = &drag->def.motor;
	m->linearHertz = 4.0f;
	m->linearDampingRatio = 0.7f;
	m->maxSpringForce = 500.0f;
	m->angularHertz = 2.0f;
	m->angularDampingRatio = 1.0f;
	m->maxSpringTorque = 50.0f;
	return scene;
}

/// A dynamic character (Box2D v3.2's mover and pogo joints): a 6 kg upright box, frictionless,
/// held 1 m above the ground by a pogo (5 Hz, damping ratio 0.8, pushing up to 3 times its weight,
/// pulling down up to half of it) and walked right at 2 m/s by a mover capped at 100 N along x
/// (nothing along y: gravity and the pogo hold the height). It walks into three 1 kg boxes and
/// shoves them along. The pogo's anchor on the ground stays where the walk starts: its length is
/// measured along the world's up, so it holds the height wherever the character is. Sleep is off,
/// as a pogo character needs (pogo_joint.c says why).
static Scene* BuildDynamicCharacter(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 300;
	scene->enableSleep = false;
	int ground = AddGround(scene, 20.0f, 0.6f);
	const float start = -6.0f, rest = 1.0f, weight = 60.0f;
	int character = AddBoxBody(scene, tb_dynamicBody, V(start, rest), 0.0f, 0.3f, 0.5f, 10.0f, 0.0f);
	scene->bodies[character].fixedRotation = true;
	for (int i = 0; i < 3; ++i)
	{
		AddBoxBody(scene, tb_dynamicBody, V(0.9f * (float)i, 0.4f), 0.0f, 0.4f, 0.4f, 1.5625f, 0.4f);
	}
	SceneJoint* pogo = Scene_AddJoint(scene, tb_pogoJoint, ground, character);
	pogo->def.base.localFrameA.p = V(start, 1.0f); // the ground's top under the start (ground origin 1 m down)
	pogo->def.pogo.restLength = rest;
	pogo->def.pogo.hertz = 5.0f;
	pogo->def.pogo.dampingRatio = 0.8f;
	pogo->def.pogo.maxCompressionForce = 3.0f * weight;
	pogo->def.pogo.maxTensionForce = 0.5f * weight;
	SceneJoint* mover = Scene_AddJoint(scene, tb_moverJoint, ground, character);
	mover->def.mover.linearVelocity = V(2.0f, 0.0f);
	mover->def.mover.maxVelocityForce = V(100.0f, 0.0f);
	return scene;
}

/// Newton's cradle on joints: five balls (radius 0.25 m, restitution 1, no friction) each hanging
/// on a rigid 2 m distance joint from a static bar, touching; the first pulled out to the side
/// 1.5 m higher. With impact propagation (`tumble run newtons_cradle_joints --impact-propagation`)
/// the impact passes down the row as the closed form says.
static Scene* BuildCradleJoints(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 300;
	int bar = Scene_AddBody(scene, tb_staticBody, V(0.0f, 4.0f), 0.0f);
	const float r = 0.25f, length = 2.0f;
	for (int i = 0; i < 5; ++i)
	{
		float x = 2.0f * r * ((float)i - 2.0f);
		tbVec2 position = V(x, 4.0f - length);
		if (i == 0)
		{
			float angle = Acos((length - 1.5f) / length); // 1.5 m up: released from rest
			position = V(x - length * Sin(angle), 4.0f - length * Cos(angle));
		}
		int ball = Scene_AddBody(scene, tb_dynamicBody, position, 0.0f);
		tbGeometry circle = Scene_MakeCircleGeometry(tbVec2_zero, r);
		int shape = Scene_AddGeometry(scene, ball, &circle, 1.0f, 0.0f);
		scene->bodies[ball].shapes[shape].restitution = 1.0f;
		SceneJoint* rod = Scene_AddJoint(scene, tb_distanceJoint, bar, ball);
		rod->def.base.localFrameA.p = V(x, 0.0f);
		rod->def.distance.length = length;
	}
	return scene;
}

/// 24 ragdolls dropped in a pile (rows of 6, 1.5 m apart, 3 m between rows).
static Scene* BuildRagdolls(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	AddGround(scene, 40.0f, 0.6f);
	for (int i = 0; i < 24; ++i)
	{
		AddRagdoll(scene, -3.75f + 1.5f * (float)(i % 6) + 0.2f * (float)(i / 6), 2.0f + 3.0f * (float)(i / 6), -1 - i);
	}
	return scene;
}

// ---------------------------------------------------------------------------------------------
// Table

/// Static concave outline on body `body`, cut into convex pieces by tbDecomposePolygon.
static void AddConcaveShape(Scene* scene, int body, const tbVec2* outline, int count, float friction)
{
	tbPolygon pieces[16];
	int pieceCount = tbDecomposePolygon(outline, count, pieces, 16);
	for (int i = 0; i < pieceCount; ++i)
	{
		tbGeometry geometry;
		memset(&geometry, 0, sizeof(geometry));
		geometry.type = tb_polygonShape;
		geometry.polygon = pieces[i];
		Scene_AddGeometry(scene, body, &geometry, 1.0f, friction);
	}
}

/// Height of the platformer's ground at x: a flat run of 1 m segments (−30..0), a 15° slope up
/// (0..10), a plateau (10..20), a cosine valley 1 m below the start (20..40) and a flat run (40..60).
static float PlatformerGround(float x)
{
	float plateau = 10.0f * Tan(15.0f * TB_PI / 180.0f);
	if (x <= 0.0f || x >= 40.0f)
	{
		return 0.0f;
	}
	if (x <= 10.0f)
	{
		return x * plateau / 10.0f;
	}
	if (x <= 20.0f)
	{
		return plateau;
	}
	if (x <= 30.0f)
	{
		return plateau - (plateau + 1.0f) * 0.5f * (1.0f - Cos(TB_PI * (x - 20.0f) / 10.0f));
	}
	return -1.0f + 0.5f * (1.0f - Cos(TB_PI * (x - 30.0f) / 10.0f));
}

/// A platformer level: ground as one chain (points every metre on the flats and curves, every 2 m
/// on the slope; solid below), an L-shaped ledge and a U-shaped cup made concave by
/// tbDecomposePolygon, boxes behind the start and on the ledge, balls in the cup, and an upright capsule character
/// (fixed rotation, no friction) sent across at 8 m/s; a wall at the far end.
static Scene* BuildPlatformer(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 900;
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	memcpy(scene->bodies[ground].name, "ground", 7);
	tbVec2 points[128];
	int count = 0;
	for (float x = 61.0f; x >= -31.0f; x -= (x > 0.0f && x <= 10.0f) ? 2.0f : 1.0f)
	{
		points[count++] = V(x, PlatformerGround(x));
	}
	Scene_AddChain(scene, ground, points, count, false);
	tbVec2 ledge[6] = {V(-22.0f, 3.0f), V(-16.0f, 3.0f), V(-16.0f, 3.4f), V(-21.4f, 3.4f), V(-21.4f, 5.0f), V(-22.0f, 5.0f)};
	AddConcaveShape(scene, ground, ledge, 6, 0.6f);
	tbVec2 cup[8] = {V(46.0f, 0.0f), V(52.0f, 0.0f), V(52.0f, 2.0f), V(51.6f, 2.0f),
					 V(51.6f, 0.4f), V(46.4f, 0.4f), V(46.4f, 2.0f), V(46.0f, 2.0f)};
	AddConcaveShape(scene, ground, cup, 8, 0.6f);
	tbGeometry wall = Scene_MakeBoxGeometry(0.5f, 3.0f, V(60.5f, 3.0f), 0.0f);
	Scene_AddGeometry(scene, ground, &wall, 1.0f, 0.6f);
	for (int i = 0; i < 6; ++i)
	{
		AddBoxBody(scene, tb_dynamicBody, V(-26.0f - 0.9f * (float)(i % 3), 0.4f + 0.8f * (float)(i / 3)), 0.0f, 0.4f,
				   0.4f, 1.0f, 0.6f);
	}
	for (int i = 0; i < 8; ++i)
	{
		AddCircleBody(scene, tb_dynamicBody, V(47.0f + 0.6f * (float)(i % 4), 1.0f + 0.6f * (float)(i / 4)), 0.25f, 1.0f,
					  0.4f);
	}
	AddBoxBody(scene, tb_dynamicBody, V(-19.0f, 3.9f), 0.0f, 0.5f, 0.5f, 1.0f, 0.6f);
	int hero = Scene_AddBody(scene, tb_dynamicBody, V(-23.0f, 0.7f), 0.0f);
	memcpy(scene->bodies[hero].name, "hero", 5);
	scene->bodies[hero].fixedRotation = true;
	scene->bodies[hero].linearVelocity = V(8.0f, 0.0f);
	tbGeometry capsule = Scene_MakeCapsuleGeometry(V(0.0f, -0.4f), V(0.0f, 0.4f), 0.3f);
	Scene_AddGeometry(scene, hero, &capsule, 1.0f, 0.0f);
	return scene;
}

/// Loop-the-loop: two vertical loops of radius 5 m (clockwise chains of 256 segments, solid
/// outside, no friction) each with a frictionless ball (radius 0.25) at the bottom. The left ball
/// starts at 1.1 √(5 g (R − r)) = 16.9 m/s and runs round the top; the right one at 0.9 × that
/// speed leaves the track before the top and falls back inside.
static Scene* BuildLoopTheLoop(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 300;
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	memcpy(scene->bodies[ground].name, "ground", 7);
	const float R = 5.0f, r = 0.25f;
	float critical = sqrtf(5.0f * 10.0f * (R - r));
	for (int side = 0; side < 2; ++side)
	{
		float cx = side == 0 ? -6.0f : 6.0f;
		tbVec2 points[256];
		for (int i = 0; i < 256; ++i)
		{
			float angle = -2.0f * TB_PI * (float)i / 256.0f;
			points[i] = V(cx + R * Cos(angle), R + R * Sin(angle));
		}
		SceneChain* chain = Scene_AddChain(scene, ground, points, 256, true);
		chain->friction = 0.0f;
		int ball = AddCircleBody(scene, tb_dynamicBody, V(cx, r), r, 1.0f, 0.0f);
		scene->bodies[ball].linearVelocity = V((side == 0 ? 1.1f : 0.9f) * critical, 0.0f);
	}
	return scene;
}

/// A pile of same-size balls, the spatial hash's case: 4,000 balls of radius 0.25 m (friction
/// 0.4) dropped in a grid of rows 0.6 m apart into a 40 m wide open box of static segments.
static Scene* BuildBallPile(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 600;
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	memcpy(scene->bodies[ground].name, "box", 4);
	tbVec2 corners[4] = {V(-20.0f, 40.0f), V(-20.0f, 0.0f), V(20.0f, 0.0f), V(20.0f, 40.0f)};
	for (int i = 0; i < 3; ++i)
	{
		tbGeometry side = Scene_MakeSegmentGeometry(corners[i], corners[i + 1]);
		Scene_AddGeometry(scene, ground, &side, 1.0f, 0.4f);
	}
	for (int i = 0; i < 4000; ++i)
	{
		float x = -19.4f + 0.6f * (float)(i % 64) + 0.05f * (float)((i / 64) % 2);
		float y = 0.5f + 0.6f * (float)(i / 64);
		AddCircleBody(scene, tb_dynamicBody, V(x, y), 0.25f, 1.0f, 0.4f);
	}
	return scene;
}

/// Game-scale falling bodies (the game benchmarks' falling_1000, tumble-bench-games, without its
/// rolling resistance): 1,000 bodies about a metre across (boxes of half size 0.4, circles of
/// radius 0.45, capsules 0.7 m long of radius 0.25, in turn; density 1, friction 0.6) in rows 1.25 m
/// apart from y = 3, x jittered by up to 0.1 m and turned at random, falling onto a 125 m floor
/// between 20 m walls and coming to rest in a pile about six deep. The jitter and angles come from a
/// fixed integer sequence, so the scene is the same everywhere.
static Scene* BuildFallingMix(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 240;
	const int count = 1000;
	const float width = 125.0f, wallHeight = 20.0f, spacing = 1.25f;
	int ground = Scene_AddBody(scene, tb_staticBody, tbVec2_zero, 0.0f);
	memcpy(scene->bodies[ground].name, "ground", 7);
	tbGeometry floor = Scene_MakeBoxGeometry(0.5f * width + 1.0f, 0.5f, V(0.0f, -0.5f), 0.0f);
	Scene_AddGeometry(scene, ground, &floor, 1.0f, 0.6f);
	for (int side = -1; side <= 1; side += 2)
	{
		tbGeometry wall =
			Scene_MakeBoxGeometry(0.5f, 0.5f * wallHeight, V((float)side * (0.5f * width + 0.5f), 0.5f * wallHeight), 0.0f);
		Scene_AddGeometry(scene, ground, &wall, 1.0f, 0.6f);
	}
	int columns = (int)(width / spacing) - 1;
	uint32_t state = 12345u;
	for (int i = 0; i < count; ++i)
	{
		// Numerical Recipes' linear congruential sequence, its top 24 bits as a fraction in [0, 1).
		state = 1664525u * state + 1013904223u;
		float jitter = (float)(state >> 8) / 16777216.0f;
		state = 1664525u * state + 1013904223u;
		float turn = (float)(state >> 8) / 16777216.0f;
		float x = -0.5f * width + spacing * (float)(i % columns + 1) + 0.2f * jitter - 0.1f;
		float y = 3.0f + spacing * (float)(i / columns);
		int body = Scene_AddBody(scene, tb_dynamicBody, V(x, y), TB_PI * (2.0f * turn - 1.0f));
		tbGeometry shape;
		switch (i % 3)
		{
			case 0:
				shape = Scene_MakeBoxGeometry(0.4f, 0.4f, tbVec2_zero, 0.0f);
				break;
			case 1:
				shape = Scene_MakeCircleGeometry(tbVec2_zero, 0.45f);
				break;
			default:
				shape = Scene_MakeCapsuleGeometry(V(-0.35f, 0.0f), V(0.35f, 0.0f), 0.25f);
				break;
		}
		Scene_AddGeometry(scene, body, &shape, 1.0f, 0.6f);
	}
	return scene;
}

// ---------------------------------------------------------------------------------------------
// Box2D v3's rain, exactly: its human and its spawn schedule

/// One bone of Box2D v3's human (shared/human.c), lengths in metres at scale 1, angles in
/// multiples of π: the body's height above the feet, its capsule (vertical, from y1 to y2 in the
/// body frame), the parent it hangs from (−1 for the hip, which has no joint), the pivot's height,
/// the joint's limits and the rotation of the joint frame on the parent (the forearms are bent
/// 45°), and the scale of the joint's friction torque. The shins also carry a foot.
typedef struct HumanBone
{
	int parent;
	float height, linearDamping;
	float capsuleY1, capsuleY2, radius;
	float pivot, lower, upper, parentFrameAngle, frictionScale;
	bool foot;
} HumanBone;

static const HumanBone s_humanBones[11] = {
	{-1, 0.95f, 0.0f, -0.02f, 0.02f, 0.095f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, false},		// hip
	{0, 1.2f, 0.0f, -0.135f, 0.135f, 0.09f, 1.0f, -0.25f, 0.0f, 0.0f, 0.5f, false},		// torso
	{1, 1.475f, 0.1f, -0.038f, 0.039f, 0.075f, 1.4f, -0.3f, 0.1f, 0.0f, 0.25f, false},	// head
	{0, 0.775f, 0.0f, -0.125f, 0.125f, 0.06f, 0.9f, -0.05f, 0.4f, 0.0f, 1.0f, false},	// left thigh
	{3, 0.475f, 0.0f, -0.155f, 0.125f, 0.045f, 0.625f, -0.5f, -0.02f, 0.0f, 0.5f, true}, // left shin
	{0, 0.775f, 0.0f, -0.125f, 0.125f, 0.06f, 0.9f, -0.05f, 0.4f, 0.0f, 1.0f, false},	// right thigh
	{5, 0.475f, 0.0f, -0.155f, 0.125f, 0.045f, 0.625f, -0.5f, -0.02f, 0.0f, 0.5f, true}, // right shin
	{1, 1.225f, 0.0f, -0.125f, 0.125f, 0.035f, 1.35f, -0.1f, 0.8f, 0.0f, 0.5f, false},	// left upper arm
	{7, 0.975f, 0.1f, -0.125f, 0.125f, 0.03f, 1.1f, -0.2f, 0.3f, 0.25f, 0.1f, false},	// left forearm
	{1, 1.225f, 0.0f, -0.125f, 0.125f, 0.035f, 1.35f, -0.1f, 0.8f, 0.0f, 0.5f, false},	// right upper arm
	{9, 0.975f, 0.1f, -0.125f, 0.125f, 0.03f, 1.1f, -0.2f, 0.3f, 0.25f, 0.1f, false},	// right forearm
};

/// Human joints: a friction motor (speed 0, torque frictionScale·frictionTorque·scale), a spring
/// towards angle 0 and the limits, as v3's rain sets them.
typedef struct HumanJoints
{
	float frictionTorque; ///< N·m at scale 1 (v3's rain: 0.05)
	float hertz;		  ///< spring stiffness (v3's rain: 5 Hz)
	float dampingRatio;	  ///< spring damping (v3's rain: 0.5)
} HumanJoints;

/// Shapes of a human: friction 0.2, category 2 colliding with 1 (the ground) and 2 (other humans),
/// in the negative group −group so that a human's own bones never touch. The feet (a rounded
/// quadrilateral on each shin, friction 0.05) collide with the ground only.
static void AddHumanShapes(Scene* scene, int body, const HumanBone* bone, float scale, int group)
{
	SceneShape shape = Scene_DefaultShape();
	shape.friction = 0.2f;
	shape.groupIndex = -group;
	shape.categoryBits = 2u;
	shape.maskBits = 1u | 2u;
	shape.geometry = Scene_MakeCapsuleGeometry(V(0.0f, bone->capsuleY1 * scale), V(0.0f, bone->capsuleY2 * scale),
											   bone->radius * scale);
	Scene_AddShape(scene, body, &shape);
	if (bone->foot)
	{
		tbVec2 outline[4] = {V(-0.03f * scale, -0.185f * scale), V(0.11f * scale, -0.185f * scale),
							 V(0.11f * scale, -0.16f * scale), V(-0.03f * scale, -0.14f * scale)};
		shape.geometry = Scene_MakePolygonGeometry(outline, 4, 0.015f * scale);
		shape.friction = 0.05f;
		shape.maskBits = 1u;
		Scene_AddShape(scene, body, &shape);
	}
}

/// Box2D v3's human (11 bodies, 10 revolute joints) standing with its feet at `feet`: bodies in
/// s_humanBones order, sleep threshold 0.1 m/s.
static void AddHuman(Scene* scene, tbVec2 feet, float scale, const HumanJoints* joints, int group)
{
	int first = scene->bodyCount;
	for (int i = 0; i < 11; ++i)
	{
		const HumanBone* bone = s_humanBones + i;
		int body = Scene_AddBody(scene, tb_dynamicBody, V(feet.x, feet.y + bone->height * scale), 0.0f);
		scene->bodies[body].linearDamping = bone->linearDamping;
		scene->bodies[body].sleepThreshold = 0.1f;
		AddHumanShapes(scene, body, bone, scale, group);
		if (bone->parent < 0)
		{
			continue;
		}
		SceneJoint* joint = Scene_AddJoint(scene, tb_revoluteJoint, first + bone->parent, body);
		Scene_SetJointAnchor(scene, joint, V(feet.x, feet.y + bone->pivot * scale));
		joint->def.base.localFrameA.q = tbMakeRot(bone->parentFrameAngle * TB_PI);
		joint->def.base.drawScale = 0.05f;
		tbRevoluteJointDef* def = &joint->def.revolute;
		def->enableLimit = true;
		def->lowerAngle = bone->lower * TB_PI;
		def->upperAngle = bone->upper * TB_PI;
		def->enableMotor = true;
		def->maxMotorTorque = bone->frictionScale * joints->frictionTorque * scale;
		def->enableSpring = joints->hertz > 0.0f;
		def->hertz = joints->hertz;
		def->dampingRatio = joints->dampingRatio;
	}
}

/// Box2D v3's rain benchmark (shared/benchmarks.c, release settings), exactly: the five floors of
/// rain_rigid, and over each floor a group of five humans (0.5 m apart, collision groups −1 … −5
/// by place in the group, so humans in the same place of different groups never touch either,
/// as in v3) dropped from 40 m above it every 8 steps, from step 0. The groups fill 40 columns
/// 6.25 m apart from the left; from then on each spawn first destroys the oldest group of its
/// floor and takes its column. One spawner per floor, in floor order as v3 creates them, so a
/// step destroys and builds floor by floor. Differences from v3's own program, none of which
/// changes the set-up: the joint anchors are computed in the group's frame, so they differ from
/// v3's (computed at the drop height) by float rounding (≤ 4e-6 m); the forearms' 45° frame comes
/// from cosf and sinf where v3's b2MakeRot approximates them (~1e-3 rad; the Box2D v3 peer gets
/// the scene's frame, so both engines of tumble-bench build the same joint); a group's joints
/// are all destroyed before its bodies, where v3 goes human by human (ids are reused in another
/// order); and v3's program leaves its first step off the clock, tumble-bench times every step.
static Scene* BuildRain(void)
{
	Scene* scene = Scene_Create();
	scene->steps = 1000;
	const int rowCount = 5, columnCount = 40, groupSize = 5, gridCount = 500;
	const float gridSize = 0.5f;
	AddRainFloors(scene, rowCount, gridCount, gridSize);
	int group = Scene_AddTemplate(scene, "human_group");
	HumanJoints joints = {0.05f, 5.0f, 0.5f};
	for (int k = 0; k < groupSize; ++k)
	{
		AddHuman(scene->templates[group].parts, V(0.5f * (float)k, 0.0f), 1.0f, &joints, k + 1);
	}
	float span = (float)gridCount * gridSize;
	float groupDistance = span / (float)columnCount;
	for (int row = 0; row < rowCount; ++row)
	{
		tbVec2 origin = V(-0.5f * span + 0.5f * groupDistance, 40.0f + 45.0f * (float)row);
		SceneSpawner* spawner = Scene_AddSpawner(scene, group, 8, origin);
		spawner->keep = columnCount;
		spawner->slotCount = columnCount;
		spawner->slotStep = V(groupDistance, 0.0f);
	}
	return scene;
}

typedef Scene* SceneBuilder(void);

typedef struct CatalogueEntry
{
	const char* name;
	const char* description;
	SceneBuilder* build;
} CatalogueEntry;

static const CatalogueEntry s_entries[] = {
	{"pyramid", "pyramid of 210 unit boxes (base 20), friction 0.6, sleep off", BuildPyramid},
	{"vertical_stack", "10 unit boxes stacked touching on the ground", BuildVerticalStack},
	{"dropped_stack", "15 unit boxes dropped with 0.1 m gaps, x alternating +-0.01, friction 0.3", BuildDroppedStack},
	{"touching_stack", "20 unit boxes resting exactly on each other", BuildTouchingStack},
	{"card_house", "40 cards (0.002 x 0.4 m): 5 levels of A-frames at +-25 deg with flat cards, friction 0.7",
	 BuildCardHouse},
	{"dominoes", "20 dominoes 0.2 x 2 m, 1 m apart; the first starts tipped", BuildDominoes},
	{"newtons_cradle", "5 touching balls e = 1 hit by a sixth at 2.71 m/s, no gravity, no friction",
	 BuildNewtonsCradle},
	{"ramp", "five 30 deg ramps with boxes of friction 0.8, 0.6, 0.4, 0.2, 0", BuildRamp},
	{"slope", "a unit box at rest on a 20 deg slope, friction 0.6 (must not creep)", BuildSlope},
	{"mass_ratio", "100 kg box resting on a 1 kg box", BuildMassRatio},
	{"heavy_on_pyramids", "three base-10 pyramids of 2 m boxes; top boxes 100, 200, 300x denser dropped 2 m",
	 BuildHeavyOnPyramids},
	{"big_on_small", "20 m box (400 kg) dropped from y = 26 onto two 1 kg boxes at x = +-9", BuildBigOnSmall},
	{"overlap_recovery", "base-4 pyramid of unit boxes 0.75 m apart (25% overlap)", BuildOverlapRecovery},
	{"bullets_wall", "five r 0.1 bullets at 300 m/s into a 0.1 m static wall, no gravity", BuildBulletsWall},
	{"spinning_box", "thin 4 x 0.1 m box at 100 m/s spinning 50 rad/s into a 0.1 m wall, no gravity",
	 BuildSpinningBox},
	{"confined", "625 circles r 0.5 packed 0.72 m apart inside four static capsules, no gravity", BuildConfined},
	{"rain", "Box2D v3 rain benchmark: a column of 25 jointed 11-bone humans over each of five floors every 8 "
			 "steps, up to 40 columns (11,000 bodies), then the oldest column is recycled",
	 BuildRain},
	{"rain_rigid", "Box2D v3 rain benchmark, jointless variant: 1,000 rigid humans, circles, boxes and "
				   "triangles over five floors, all dropped at once",
	 BuildRainRigid},
	{"large_pyramid", "Box2D v3 benchmark: pyramid of base 100 (5,050 boxes), sleep off", BuildLargePyramid},
	{"many_pyramids", "Box2D v3 benchmark: 400 base-10 pyramids on 20 ground segments (22,000 boxes), sleep off",
	 BuildManyPyramids},
	{"tumbler", "Box2D v3 benchmark variant: 2,025 small boxes in a kinematic drum turning at 25 deg/s (no joint)",
	 BuildTumbler},
	{"tumbler_motor", "Box2D v3 benchmark: 2,025 small boxes in a dynamic drum on a motorised revolute joint "
					  "(25 deg/s)",
	 BuildTumblerMotor},
	{"spinner_motor", "Box2D v3 benchmark: a dynamic blade on a motorised revolute joint (5 rad/s) stirring 6,076 "
					  "shapes in a 360-segment ring",
	 BuildSpinnerMotor},
	{"smash", "Box2D v3 benchmark: 8 m box at 40 m/s into 9,600 sleeping boxes, no gravity", BuildSmash},
	{"spinner", "Box2D v3 benchmark variant: kinematic blade at 5 rad/s (no joint) stirring 6,076 shapes in a "
				"360-segment ring",
	 BuildSpinner},
	{"washer", "Box2D v3 benchmark: kinematic drum (36 ring pieces, 4 paddles) turning at 25 deg/s with 8,100 "
			   "small squares, hit events on",
	 BuildWasher},
	{"junkyard", "Box2D v3 benchmark: 8,000 pentagons in a 160 m pit, pushed by a kinematic box driven to "
				 "x = 60 sin(0.2 t)",
	 BuildJunkyard},
	{"compounds", "Box2D v3 benchmark: 3,000 bodies of two triangles each falling into an 80 m pit", BuildCompounds},
	{"pendulum_chain", "30 capsule links (0.5 m) on revolute joints holding a ball 100x a link, released "
					   "horizontally",
	 BuildPendulumChain},
	{"rope_bridge", "20 planks on revolute joints between two posts, 12 boxes dropped on it", BuildRopeBridge},
	{"car", "a chassis on two wheel joints (5 Hz suspension, rear motor) driving over sine hills", BuildCar},
	{"ragdolls", "24 ragdolls of 10 bodies (revolute joints with limits and friction) dropped in a pile",
	 BuildRagdolls},
	{"door", "a door on a revolute hinge with a 0-90 deg limit, shoved open by a sliding box", BuildDoor},
	{"piston", "a pusher on a motorised prismatic joint (1 m/s, limits 0-4 m) pushing three boxes", BuildPiston},
	{"mouse_drag", "a box dragged by a motor joint's spring toward a moving target (Box2D v3.2's mouse drag)",
	 BuildMouseDrag},
	{"dynamic_character", "a box character on a pogo joint (1 m, 5 Hz) walked at 2 m/s by a mover joint into three "
						  "boxes (Box2D v3.2's dynamic mover joints)",
	 BuildDynamicCharacter},
	{"newtons_cradle_joints", "five balls on rigid distance joints from a bar, the first released 1.5 m up "
							  "(run with --impact-propagation)",
	 BuildCradleJoints},
	{"joint_grid", "Box2D v3 benchmark: 100 x 100 circles on 19,800 revolute joints hanging from 7 static bodies, "
				   "sleep off",
	 BuildJointGrid},
	{"rain_ragdolls", "Box2D v3 rain benchmark with jointed ragdolls: 1,000 ragdolls of 10 bodies over five "
					  "floors, all dropped at once",
	 BuildRainRagdolls},
	{"platformer", "a level: chain ground with slopes and a valley, concave ledge and cup, boxes and balls, an "
				   "upright capsule character sent across at 8 m/s",
	 BuildPlatformer},
	{"ball_pile", "4,000 balls of radius 0.25 m dropped into a 40 m open box (the spatial hash's case)",
	 BuildBallPile},
	{"falling_mix", "1,000 boxes, circles and capsules about a metre across dropped in rows onto a 125 m floor "
					"between walls (the game benchmarks' falling_1000, without rolling resistance)",
	 BuildFallingMix},
	{"loop_the_loop", "two frictionless balls in vertical 5 m loops at 1.1 and 0.9 times the closed-form speed "
					  "sqrt(5 g (R - r)) that just reaches the top",
	 BuildLoopTheLoop},
};

#define ENTRY_COUNT ((int)(sizeof(s_entries) / sizeof(s_entries[0])))

int Catalogue_Count(void)
{
	return ENTRY_COUNT;
}

const char* Catalogue_Name(int index)
{
	return index >= 0 && index < ENTRY_COUNT ? s_entries[index].name : NULL;
}

const char* Catalogue_Description(int index)
{
	return index >= 0 && index < ENTRY_COUNT ? s_entries[index].description : NULL;
}

int Catalogue_Find(const char* name)
{
	for (int i = 0; name != NULL && i < ENTRY_COUNT; ++i)
	{
		if (strcmp(s_entries[i].name, name) == 0)
		{
			return i;
		}
	}
	return -1;
}

Scene* Catalogue_Build(const char* name)
{
	int index = Catalogue_Find(name);
	return index >= 0 ? s_entries[index].build() : NULL;
}
