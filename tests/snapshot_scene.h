// Test helper: the 200-body scene of tests/test_snapshot.c (snapshots, rollback). Everything a
// world can hold in one scene: a chain and a segment on a static ground, a sensor, a pyramid, a
// pile of circles, capsules, hexagons, rounded boxes and two-shape bodies (some rolling, some
// bouncy), a stack created asleep on a shelf, a rope bridge of revolute joints, a car on wheel
// joints, distance, weld, prismatic, motor, pogo and filter joints, a kinematic paddle and two
// bullets. Written with Box2D v3.2's names and a tb prefix only, so that the same code builds the
// same scene in Box2D v3.2 after renaming (the snapshot size comparison in docs/guide.md).
#pragma once

#include "tumble/tumble.h"

#include <string.h>

#define SNAP_SCENE_BODIES 200

/// Bodies of the scene: ids[0] is the ground, ids[SNAP_SCENE_ASLEEP_FIRST ...] the stack created asleep.
#define SNAP_SCENE_ASLEEP_FIRST 4
#define SNAP_SCENE_ASLEEP_COUNT 8

static tbBodyId SnapScene_Body(tbWorldId worldId, tbBodyType type, float x, float y, float angle)
{
	tbBodyDef def = tbDefaultBodyDef();
	def.type = type;
	def.position = (tbVec2){x, y};
	def.rotation = tbMakeRot(angle);
	return tbCreateBody(worldId, &def);
}

/// Build the scene into worldId; ids receives SNAP_SCENE_BODIES body ids. Returns the body count.
static int SnapScene_Build(tbWorldId worldId, tbBodyId* ids)
{
	int n = 0;
	tbShapeDef shapeDef = tbDefaultShapeDef();

	// The ground: an open chain valley (its first and last points are ghosts) and a conveyor segment.
	tbBodyId ground = SnapScene_Body(worldId, tb_staticBody, 0.0f, 0.0f, 0.0f);
	ids[n++] = ground;
	{
		// Right to left: a chain is solid on the left of its direction, so this ground is solid below.
		tbVec2 points[10] = {{52.0f, 22.0f}, {50.0f, 20.0f}, {44.0f, 10.0f}, {36.0f, 3.0f},	 {26.0f, 0.0f},
							 {-26.0f, 0.0f}, {-36.0f, 3.0f}, {-44.0f, 10.0f}, {-50.0f, 20.0f}, {-52.0f, 22.0f}};
		tbSurfaceMaterial material = tbDefaultSurfaceMaterial();
		material.friction = 0.7f;
		tbChainDef chainDef = tbDefaultChainDef();
		chainDef.points = points;
		chainDef.count = 10;
		chainDef.materials = &material;
		chainDef.materialCount = 1;
		tbCreateChain(ground, &chainDef);
		tbShapeDef conveyor = tbDefaultShapeDef();
		conveyor.material.tangentSpeed = 1.5f;
		tbSegment segment = {{20.0f, 0.0f}, {25.0f, 0.0f}};
		tbCreateSegmentShape(ground, &conveyor, &segment);
		tbShapeDef sensor = tbDefaultShapeDef();
		sensor.isSensor = true;
		sensor.enableSensorEvents = true;
		tbPolygon zone = tbMakeOffsetBox(3.0f, 2.0f, (tbVec2){-2.0f, 2.0f}, tbMakeRot(0.0f));
		tbCreatePolygonShape(ground, &sensor, &zone);
	}

	// Two bridge anchors and a shelf (static).
	tbBodyId anchorA = SnapScene_Body(worldId, tb_staticBody, -9.0f, 8.0f, 0.0f);
	tbBodyId anchorB = SnapScene_Body(worldId, tb_staticBody, 5.0f, 8.0f, 0.0f);
	tbBodyId shelf = SnapScene_Body(worldId, tb_staticBody, -15.0f, 14.0f, 0.0f);
	ids[n++] = anchorA;
	ids[n++] = anchorB;
	ids[n++] = shelf;
	{
		tbCircle pin = {{0.0f, 0.0f}, 0.25f};
		tbCreateCircleShape(anchorA, &shapeDef, &pin);
		tbCreateCircleShape(anchorB, &shapeDef, &pin);
		tbSegment top = {{-3.0f, 0.0f}, {3.0f, 0.0f}};
		tbCreateSegmentShape(shelf, &shapeDef, &top);
	}

	// A stack created asleep on the shelf: it stays asleep until something wakes it.
	{
		tbPolygon box = tbMakeBox(0.5f, 0.5f);
		for (int i = 0; i < SNAP_SCENE_ASLEEP_COUNT; ++i)
		{
			tbBodyDef def = tbDefaultBodyDef();
			def.type = tb_dynamicBody;
			def.position = (tbVec2){-15.0f + 0.5f * (float)(i % 2), 14.5f + 1.0f * (float)i};
			def.isAwake = false;
			tbBodyId id = tbCreateBody(worldId, &def);
			tbCreatePolygonShape(id, &shapeDef, &box);
			ids[n++] = id;
		}
	}

	// A pyramid of 36 boxes on the right.
	{
		tbPolygon box = tbMakeBox(0.5f, 0.5f);
		for (int row = 0; row < 8; ++row)
		{
			for (int k = 0; k < 8 - row; ++k)
			{
				float x = 12.0f + 1.05f * (float)k + 0.525f * (float)row;
				tbBodyId id = SnapScene_Body(worldId, tb_dynamicBody, x, 0.5f + 1.0f * (float)row, 0.0f);
				tbCreatePolygonShape(id, &shapeDef, &box);
				ids[n++] = id;
			}
		}
	}

	// A rope bridge of 14 planks between the anchors, revolute joints at every pin.
	{
		tbCapsule plank = {{-0.4f, 0.0f}, {0.4f, 0.0f}, 0.1f};
		tbBodyId previous = anchorA;
		tbVec2 previousPin = {0.0f, 0.0f};
		for (int i = 0; i < 14; ++i)
		{
			tbBodyId id = SnapScene_Body(worldId, tb_dynamicBody, -8.5f + 1.0f * (float)i, 8.0f, 0.0f);
			tbCreateCapsuleShape(id, &shapeDef, &plank);
			tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
			def.base.bodyIdA = previous;
			def.base.bodyIdB = id;
			def.base.localFrameA.p = previousPin;
			def.base.localFrameB.p = (tbVec2){-0.5f, 0.0f};
			tbCreateRevoluteJoint(worldId, &def);
			previous = id;
			previousPin = (tbVec2){0.5f, 0.0f};
			ids[n++] = id;
		}
		tbRevoluteJointDef def = tbDefaultRevoluteJointDef();
		def.base.bodyIdA = previous;
		def.base.bodyIdB = anchorB;
		def.base.localFrameA.p = previousPin;
		def.enableLimit = true;
		def.lowerAngle = -0.5f;
		def.upperAngle = 0.5f;
		tbCreateRevoluteJoint(worldId, &def);
	}

	// A car on the left slope: a chassis and two wheels on sprung, motorised wheel joints.
	{
		tbBodyId chassis = SnapScene_Body(worldId, tb_dynamicBody, -30.0f, 6.0f, 0.0f);
		tbPolygon body = tbMakeBox(1.2f, 0.3f);
		tbCreatePolygonShape(chassis, &shapeDef, &body);
		ids[n++] = chassis;
		for (int side = 0; side < 2; ++side)
		{
			float x = side == 0 ? -30.8f : -29.2f;
			tbBodyId wheel = SnapScene_Body(worldId, tb_dynamicBody, x, 5.4f, 0.0f);
			tbShapeDef tyre = tbDefaultShapeDef();
			tyre.material.friction = 0.9f;
			tyre.material.rollingResistance = 0.05f;
			tbCircle circle = {{0.0f, 0.0f}, 0.4f};
			tbCreateCircleShape(wheel, &tyre, &circle);
			tbWheelJointDef def = tbDefaultWheelJointDef();
			def.base.bodyIdA = chassis;
			def.base.bodyIdB = wheel;
			def.base.localFrameA.p = (tbVec2){x + 30.0f, -0.6f};
			def.base.localFrameA.q = tbMakeRot(0.5f * 3.14159265f);
			def.enableMotor = true;
			def.maxMotorTorque = 20.0f;
			def.motorSpeed = -4.0f;
			def.enableLimit = true;
			def.lowerTranslation = -0.25f;
			def.upperTranslation = 0.25f;
			tbCreateWheelJoint(worldId, &def);
			ids[n++] = wheel;
		}
	}

	// A pendulum on the shelf (distance joint with a spring and limits).
	{
		tbBodyId ball = SnapScene_Body(worldId, tb_dynamicBody, -19.0f, 11.0f, 0.0f);
		tbCircle circle = {{0.0f, 0.0f}, 0.3f};
		tbCreateCircleShape(ball, &shapeDef, &circle);
		tbDistanceJointDef def = tbDefaultDistanceJointDef();
		def.base.bodyIdA = shelf;
		def.base.bodyIdB = ball;
		def.base.localFrameA.p = (tbVec2){-3.0f, 0.0f};
		def.length = 3.0f;
		def.enableSpring = true;
		def.hertz = 2.0f;
		def.dampingRatio = 0.2f;
		def.enableLimit = true;
		def.minLength = 2.0f;
		def.maxLength = 4.0f;
		tbCreateDistanceJoint(worldId, &def);
		ids[n++] = ball;
	}

	// Two boxes welded together, dropped on the pile.
	{
		tbPolygon box = tbMakeBox(0.6f, 0.3f);
		tbBodyId a = SnapScene_Body(worldId, tb_dynamicBody, -4.0f, 20.0f, 0.3f);
		tbBodyId b = SnapScene_Body(worldId, tb_dynamicBody, -2.9f, 20.33f, 0.3f);
		tbCreatePolygonShape(a, &shapeDef, &box);
		tbCreatePolygonShape(b, &shapeDef, &box);
		tbWeldJointDef def = tbDefaultWeldJointDef();
		def.base.bodyIdA = a;
		def.base.bodyIdB = b;
		def.base.localFrameA.p = (tbVec2){0.55f, 0.0f};
		def.base.localFrameB.p = (tbVec2){-0.55f, 0.0f};
		def.linearHertz = 5.0f;
		def.angularHertz = 5.0f;
		def.linearDampingRatio = 0.5f;
		def.angularDampingRatio = 0.5f;
		tbCreateWeldJoint(worldId, &def);
		ids[n++] = a;
		ids[n++] = b;
	}

	// A piston: a box on a prismatic joint, motor against its limits.
	{
		tbBodyId piston = SnapScene_Body(worldId, tb_dynamicBody, 30.0f, 6.0f, 0.0f);
		tbPolygon box = tbMakeBox(0.8f, 0.4f);
		tbCreatePolygonShape(piston, &shapeDef, &box);
		tbPrismaticJointDef def = tbDefaultPrismaticJointDef();
		def.base.bodyIdA = ground;
		def.base.bodyIdB = piston;
		def.base.localFrameA.p = (tbVec2){30.0f, 6.0f};
		def.base.localFrameA.q = tbMakeRot(0.5f * 3.14159265f);
		def.enableLimit = true;
		def.lowerTranslation = -2.0f;
		def.upperTranslation = 2.0f;
		def.enableMotor = true;
		def.maxMotorForce = 500.0f;
		def.motorSpeed = 1.0f;
		tbCreatePrismaticJoint(worldId, &def);
		ids[n++] = piston;
	}

	// A box held near a point by a motor joint's springs.
	{
		tbBodyId held = SnapScene_Body(worldId, tb_dynamicBody, 8.0f, 12.0f, 0.0f);
		tbPolygon box = tbMakeBox(0.4f, 0.4f);
		tbCreatePolygonShape(held, &shapeDef, &box);
		tbMotorJointDef def = tbDefaultMotorJointDef();
		def.base.bodyIdA = ground;
		def.base.bodyIdB = held;
		def.base.localFrameA.p = (tbVec2){8.0f, 12.0f};
		def.linearHertz = 3.0f;
		def.linearDampingRatio = 0.7f;
		def.maxSpringForce = 200.0f;
		def.angularHertz = 3.0f;
		def.angularDampingRatio = 0.7f;
		def.maxSpringTorque = 100.0f;
		tbCreateMotorJoint(worldId, &def);
		ids[n++] = held;
	}

	// A hopper on a pogo spring above the conveyor.
	{
		tbBodyId hopper = SnapScene_Body(worldId, tb_dynamicBody, 22.0f, 3.0f, 0.0f);
		tbCircle circle = {{0.0f, 0.0f}, 0.35f};
		tbCreateCircleShape(hopper, &shapeDef, &circle);
		tbPogoJointDef def = tbDefaultPogoJointDef();
		def.base.bodyIdA = ground;
		def.base.bodyIdB = hopper;
		def.base.localFrameA.p = (tbVec2){22.0f, 0.0f};
		def.hertz = 4.0f;
		def.dampingRatio = 0.3f;
		def.restLength = 2.0f;
		def.maxCompressionForce = 300.0f;
		def.maxTensionForce = 0.0f;
		tbCreatePogoJoint(worldId, &def);
		ids[n++] = hopper;
	}

	// A kinematic paddle turning over the middle of the valley.
	{
		tbBodyDef def = tbDefaultBodyDef();
		def.type = tb_kinematicBody;
		def.position = (tbVec2){-6.0f, 4.0f};
		def.angularVelocity = 0.8f;
		tbBodyId paddle = tbCreateBody(worldId, &def);
		tbPolygon box = tbMakeBox(2.5f, 0.15f);
		tbCreatePolygonShape(paddle, &shapeDef, &box);
		ids[n++] = paddle;
	}

	// Two bullets fired at the pyramid.
	for (int i = 0; i < 2; ++i)
	{
		tbBodyDef def = tbDefaultBodyDef();
		def.type = tb_dynamicBody;
		def.position = (tbVec2){-20.0f, 1.0f + 2.0f * (float)i};
		def.linearVelocity = (tbVec2){60.0f, 1.0f};
		def.isBullet = true;
		tbBodyId bullet = tbCreateBody(worldId, &def);
		tbShapeDef hit = tbDefaultShapeDef();
		hit.enableHitEvents = true;
		hit.density = 5.0f;
		tbCircle circle = {{0.0f, 0.0f}, 0.15f};
		tbCreateCircleShape(bullet, &hit, &circle);
		ids[n++] = bullet;
	}

	// The pile: the rest of the bodies, five kinds in turn, dropped over the valley.
	{
		tbVec2 hexPoints[6];
		for (int k = 0; k < 6; ++k)
		{
			float a = 1.04719755f * (float)k;
			tbRot q = tbMakeRot(a);
			hexPoints[k] = (tbVec2){0.45f * q.c, 0.45f * q.s};
		}
		tbHull hull = tbComputeHull(hexPoints, 6);
		tbPolygon hexagon = tbMakePolygon(&hull, 0.0f);
		tbPolygon rounded = tbMakeRoundedBox(0.35f, 0.25f, 0.1f);
		tbCircle circle = {{0.0f, 0.0f}, 0.4f};
		tbCapsule capsule = {{-0.35f, 0.0f}, {0.35f, 0.0f}, 0.2f};
		tbPolygon plank = tbMakeOffsetBox(0.5f, 0.15f, (tbVec2){0.0f, -0.1f}, tbMakeRot(0.0f));
		tbCircle knob = {{0.0f, 0.25f}, 0.2f};
		int k = 0;
		while (n < SNAP_SCENE_BODIES)
		{
			float x = -22.0f + 1.3f * (float)(k % 24) + 0.2f * (float)((k / 24) % 2);
			float y = 6.0f + 1.4f * (float)(k / 24);
			tbBodyId id = SnapScene_Body(worldId, tb_dynamicBody, x, y, 0.1f * (float)k);
			tbShapeDef def = tbDefaultShapeDef();
			switch (k % 5)
			{
				case 0:
					def.material.rollingResistance = 0.1f;
					tbCreateCircleShape(id, &def, &circle);
					break;
				case 1:
					tbCreateCapsuleShape(id, &def, &capsule);
					break;
				case 2:
					def.material.restitution = 0.4f;
					tbCreatePolygonShape(id, &def, &hexagon);
					break;
				case 3:
					tbCreatePolygonShape(id, &def, &rounded);
					break;
				default:
					tbCreatePolygonShape(id, &def, &plank);
					tbCreateCircleShape(id, &def, &knob);
					break;
			}
			ids[n++] = id;
			k += 1;
		}
	}

	// A filter joint keeps two bodies of the pile from colliding.
	{
		tbFilterJointDef def = tbDefaultFilterJointDef();
		def.base.bodyIdA = ids[SNAP_SCENE_BODIES - 1];
		def.base.bodyIdB = ids[SNAP_SCENE_BODIES - 2];
		tbCreateFilterJoint(worldId, &def);
	}
	return n;
}
