// Box2D 2.4.1 adapter for tumble-bench (see peers.h): builds a Scene as b2World bodies and fixtures.
#include "peers.h"

#include "../tools/box2d24_joints.h"

#include <box2d/box2d.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <vector>

struct PeerWorld
{
	b2World* world;
	std::vector<b2Body*> bodies; // scene body index -> body
	std::vector<int> driven;	 // scene indices of the bodies with a SceneDrive
	const Scene* scene;
	int stepIndex;
	float timeStep;
};

static b2Vec2 ToB2(tbVec2 v)
{
	return b2Vec2(v.x, v.y);
}

static void AddFixture(b2Body* body, const SceneShape& shape, const b2Shape& geometry)
{
	b2FixtureDef def;
	def.shape = &geometry;
	def.density = shape.density;
	def.friction = shape.friction;
	def.restitution = shape.restitution;
	def.isSensor = shape.isSensor;
	def.filter.groupIndex = (int16)shape.groupIndex;
	def.filter.categoryBits = (uint16)shape.categoryBits; // Box2D 2.4.1 has 16 filter bits: the low ones
	def.filter.maskBits = (uint16)shape.maskBits;
	body->CreateFixture(&def);
}

// A rounded polygon as a sharp one: each vertex moves out along the mitre of its two edge
// normals by radius / cos(half the turn), so every edge moves out by exactly radius.
static void AddPolygon(b2Body* body, const SceneShape& shape)
{
	const tbPolygon& polygon = shape.geometry.polygon;
	b2Vec2 points[b2_maxPolygonVertices];
	int count = polygon.count < b2_maxPolygonVertices ? polygon.count : b2_maxPolygonVertices;
	for (int i = 0; i < count; ++i)
	{
		tbVec2 v = polygon.vertices[i];
		if (polygon.radius > 0.0f)
		{
			tbVec2 n1 = polygon.normals[(i + count - 1) % count], n2 = polygon.normals[i];
			float scale = polygon.radius / (1.0f + n1.x * n2.x + n1.y * n2.y);
			v.x += scale * (n1.x + n2.x);
			v.y += scale * (n1.y + n2.y);
		}
		points[i] = ToB2(v);
	}
	b2PolygonShape geometry;
	geometry.Set(points, count);
	AddFixture(body, shape, geometry);
}

// Box2D 2.4 has no capsule: two end circles and the box between them, on the same body.
static void AddCapsule(b2Body* body, const SceneShape& shape)
{
	const tbCapsule& capsule = shape.geometry.capsule;
	b2CircleShape end;
	end.m_radius = capsule.radius;
	end.m_p = ToB2(capsule.center1);
	AddFixture(body, shape, end);
	end.m_p = ToB2(capsule.center2);
	AddFixture(body, shape, end);
	b2Vec2 axis = ToB2(capsule.center2) - ToB2(capsule.center1);
	float length = axis.Length();
	if (length > 2.0f * b2_linearSlop)
	{
		b2PolygonShape box;
		b2Vec2 center = 0.5f * (ToB2(capsule.center1) + ToB2(capsule.center2));
		box.SetAsBox(0.5f * length, capsule.radius, center, std::atan2(axis.y, axis.x));
		AddFixture(body, shape, box);
	}
}

static void AddShape(b2Body* body, const SceneShape& shape)
{
	const tbGeometry& g = shape.geometry;
	switch (g.type)
	{
		case tb_circleShape:
		{
			b2CircleShape circle;
			circle.m_p = ToB2(g.circle.center);
			circle.m_radius = g.circle.radius;
			AddFixture(body, shape, circle);
			break;
		}
		case tb_capsuleShape:
			AddCapsule(body, shape);
			break;
		case tb_segmentShape:
		{
			b2EdgeShape edge;
			edge.SetTwoSided(ToB2(g.segment.point1), ToB2(g.segment.point2));
			AddFixture(body, shape, edge);
			break;
		}
		case tb_polygonShape:
			AddPolygon(body, shape);
			break;
		default:
			break;
	}
}

static b2BodyType ToB2Type(tbBodyType type)
{
	switch (type)
	{
		case tb_dynamicBody:
			return b2_dynamicBody;
		case tb_kinematicBody:
			return b2_kinematicBody;
		default:
			return b2_staticBody;
	}
}

PeerWorld* PeerBox2D_Create(const Scene* scene)
{
	if (Peer_RefuseSpawnSchedule(scene, "box2d-2.4.1", "which Box2D 2.4.1's revolute joint lacks"))
	{
		return nullptr;
	}
	PeerWorld* peer = new PeerWorld;
	peer->world = new b2World(ToB2(scene->gravity));
	peer->world->SetAllowSleeping(scene->enableSleep);
	peer->timeStep = scene->timeStep;
	peer->scene = scene;
	peer->stepIndex = 0;
	peer->bodies.resize((size_t)scene->bodyCount);
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		const SceneBody& sb = scene->bodies[i];
		b2BodyDef def;
		def.type = ToB2Type(sb.type);
		def.position = ToB2(sb.position);
		def.angle = sb.angle;
		def.linearDamping = sb.linearDamping;
		def.angularDamping = sb.angularDamping;
		def.gravityScale = sb.gravityScale;
		def.bullet = sb.bullet;
		def.awake = sb.isAwake;
		b2Body* body = peer->world->CreateBody(&def);
		for (int s = 0; s < sb.shapeCount; ++s)
		{
			AddShape(body, sb.shapes[s]);
		}
		// Box2D's linear velocity is of the centre of mass, as the scene's; set after the mass is known.
		body->SetLinearVelocity(ToB2(sb.linearVelocity));
		body->SetAngularVelocity(sb.angularVelocity);
		if (!sb.isAwake)
		{
			body->SetAwake(false);
		}
		peer->bodies[(size_t)i] = body;
		if (sb.drive.enabled)
		{
			peer->driven.push_back(i);
		}
	}
	for (int j = 0; j < scene->jointCount; ++j)
	{
		if (Box2D24_AddJoint(peer->world, peer->bodies, scene->joints[j]) == false)
		{
			fprintf(stderr, "box2d-2.4.1: joint %d (%s) has no Box2D 2.4.1 equivalent; scene not run\n", j,
					Scene_JointTypeName(scene->joints[j].type));
			PeerBox2D_Destroy(peer);
			return nullptr;
		}
	}
	return peer;
}

// Box2D 2.4 has no target-transform call: the velocity that reaches the target, from the body's pose.
static void DriveBody(PeerWorld* peer, int index)
{
	tbTransform target;
	Scene_DriveTarget(peer->scene, index, peer->stepIndex, &target);
	b2Body* body = peer->bodies[(size_t)index];
	const b2Transform& xf = body->GetTransform();
	tbTransform current = {{xf.p.x, xf.p.y}, {xf.q.c, xf.q.s}};
	tbVec2 localCenter = {body->GetLocalCenter().x, body->GetLocalCenter().y};
	tbVec2 v;
	float w;
	Scene_TargetVelocity(current, localCenter, target, peer->timeStep, &v, &w);
	body->SetLinearVelocity(ToB2(v));
	body->SetAngularVelocity(w);
}

void PeerBox2D_Step(PeerWorld* peer)
{
	for (int index : peer->driven)
	{
		DriveBody(peer, index);
	}
	peer->stepIndex += 1;
	peer->world->Step(peer->timeStep, 8, 3);
}

PeerBody PeerBox2D_GetBody(PeerWorld* peer, int bodyIndex)
{
	const b2Body* body = peer->bodies[(size_t)bodyIndex];
	PeerBody result;
	result.position = tbVec2{body->GetPosition().x, body->GetPosition().y};
	result.rotation = tbRot{std::cos(body->GetAngle()), std::sin(body->GetAngle())};
	result.linearVelocity = tbVec2{body->GetLinearVelocity().x, body->GetLinearVelocity().y};
	result.angularVelocity = body->GetAngularVelocity();
	return result;
}

PeerCounters PeerBox2D_GetCounters(PeerWorld* peer)
{
	PeerCounters counters = {peer->world->GetBodyCount(), peer->world->GetContactCount(), 0};
	for (const b2Body* body = peer->world->GetBodyList(); body != nullptr; body = body->GetNext())
	{
		counters.awakeBodyCount += body->GetType() != b2_staticBody && body->IsAwake() ? 1 : 0;
	}
	return counters;
}

void PeerBox2D_Destroy(PeerWorld* peer)
{
	delete peer->world;
	delete peer;
}
