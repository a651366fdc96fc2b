// A scene joint as Box2D 2.4.1's joint, for the programs that run scenes in Box2D 2.4.1: the
// reference runner (tools/box2d_ref.cpp) and the benchmark peer (bench/peer_box2d.cpp). C++,
// header only: both include Box2D 2.4.1's box2d/box2d.h before it.
#pragma once

#include "scene.h"

#include <box2d/box2d.h>

#include <cfloat>
#include <cmath>
#include <vector>

inline float Box2D24_FrameAngle(tbTransform frame)
{
	return std::atan2(frame.q.s, frame.q.c);
}

inline void Box2D24_SetJointBase(const std::vector<b2Body*>& bodies, const SceneJoint& sj, b2JointDef* def)
{
	def->bodyA = bodies[(size_t)sj.bodyA];
	def->bodyB = bodies[(size_t)sj.bodyB];
	def->collideConnected = sj.def.base.collideConnected;
}

// Box2D 2.4.1's joints for the scene's: revolute (its angle is θB − θA − referenceAngle, Tumble's
// (θB + φB) − (θA + φA) with φ the frames' angles, so referenceAngle = φA − φB), prismatic and
// wheel (axis: frame A's x axis), distance (spring by b2LinearStiffness from hertz and damping
// ratio) and weld (rigid, or soft by b2AngularStiffness). 2.4.1 has no revolute or prismatic
// spring, no motor, mover or pogo joint of v3's kind and no filter joint: a scene with one is not
// run (false).
inline bool Box2D24_AddJoint(b2World* world, const std::vector<b2Body*>& bodies, const SceneJoint& sj)
{
	const tbJointDef& base = sj.def.base;
	b2Vec2 anchorA(base.localFrameA.p.x, base.localFrameA.p.y), anchorB(base.localFrameB.p.x, base.localFrameB.p.y);
	float reference = Box2D24_FrameAngle(base.localFrameA) - Box2D24_FrameAngle(base.localFrameB);
	b2Vec2 axis(base.localFrameA.q.c, base.localFrameA.q.s);
	switch (sj.type)
	{
		case tb_revoluteJoint:
		{
			const tbRevoluteJointDef& s = sj.def.revolute;
			if (s.enableSpring)
			{
				return false;
			}
			b2RevoluteJointDef d;
			Box2D24_SetJointBase(bodies, sj, &d);
			d.localAnchorA = anchorA;
			d.localAnchorB = anchorB;
			d.referenceAngle = reference;
			d.enableLimit = s.enableLimit;
			d.lowerAngle = s.lowerAngle;
			d.upperAngle = s.upperAngle;
			d.enableMotor = s.enableMotor;
			d.maxMotorTorque = s.maxMotorTorque;
			d.motorSpeed = s.motorSpeed;
			world->CreateJoint(&d);
			return true;
		}
		case tb_prismaticJoint:
		{
			const tbPrismaticJointDef& s = sj.def.prismatic;
			if (s.enableSpring)
			{
				return false;
			}
			b2PrismaticJointDef d;
			Box2D24_SetJointBase(bodies, sj, &d);
			d.localAnchorA = anchorA;
			d.localAnchorB = anchorB;
			d.localAxisA = axis;
			d.referenceAngle = reference;
			d.enableLimit = s.enableLimit;
			d.lowerTranslation = s.lowerTranslation;
			d.upperTranslation = s.upperTranslation;
			d.enableMotor = s.enableMotor;
			d.maxMotorForce = s.maxMotorForce;
			d.motorSpeed = s.motorSpeed;
			world->CreateJoint(&d);
			return true;
		}
		case tb_wheelJoint:
		{
			const tbWheelJointDef& s = sj.def.wheel;
			b2WheelJointDef d;
			Box2D24_SetJointBase(bodies, sj, &d);
			d.localAnchorA = anchorA;
			d.localAnchorB = anchorB;
			d.localAxisA = axis;
			d.enableLimit = s.enableLimit;
			d.lowerTranslation = s.lowerTranslation;
			d.upperTranslation = s.upperTranslation;
			d.enableMotor = s.enableMotor;
			d.maxMotorTorque = s.maxMotorTorque;
			d.motorSpeed = s.motorSpeed;
			if (s.enableSpring)
			{
				b2LinearStiffness(d.stiffness, d.damping, s.hertz, s.dampingRatio, d.bodyA, d.bodyB);
			}
			world->CreateJoint(&d);
			return true;
		}
		case tb_distanceJoint:
		{
			const tbDistanceJointDef& s = sj.def.distance;
			if (s.enableMotor)
			{
				return false;
			}
			b2DistanceJointDef d;
			Box2D24_SetJointBase(bodies, sj, &d);
			d.localAnchorA = anchorA;
			d.localAnchorB = anchorB;
			d.length = s.length;
			d.minLength = s.enableLimit ? s.minLength : s.length;
			d.maxLength = s.enableLimit ? s.maxLength : s.length;
			if (s.enableSpring)
			{
				b2LinearStiffness(d.stiffness, d.damping, s.hertz, s.dampingRatio, d.bodyA, d.bodyB);
				d.minLength = s.enableLimit ? s.minLength : 0.0f;
				d.maxLength = s.enableLimit ? s.maxLength : FLT_MAX;
			}
			world->CreateJoint(&d);
			return true;
		}
		case tb_weldJoint:
		{
			const tbWeldJointDef& s = sj.def.weld;
			if (s.linearHertz > 0.0f)
			{
				return false;
			}
			b2WeldJointDef d;
			Box2D24_SetJointBase(bodies, sj, &d);
			d.localAnchorA = anchorA;
			d.localAnchorB = anchorB;
			d.referenceAngle = reference;
			if (s.angularHertz > 0.0f)
			{
				b2AngularStiffness(d.stiffness, d.damping, s.angularHertz, s.angularDampingRatio, d.bodyA, d.bodyB);
			}
			world->CreateJoint(&d);
			return true;
		}
		default:
			return false;
	}
}

