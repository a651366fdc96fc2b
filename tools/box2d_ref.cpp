// box2d-ref SCENE_FILE [--steps N] [--csv FILE]
//
// Runs a Tumble scene file in Box2D 2.4.1 (called as a reference) and writes the same CSV as
// `tumble run --csv`: header `step,body,x,y,angle,vx,vy,omega`, body = index in the scene's bodies
// array (static bodies counted, not written), step 0 = initial state, then one row per non-static
// body after each step; x, y = body origin, vx, vy = velocity of the centre of mass.
// Box2D settings: the scene's gravity and time step, 8 velocity and 3 position iterations (the
// scene format has no iteration counts), sleep as the scene says. Driven bodies (a scene's
// "drive") get, before each step, the velocity that reaches the step's target from their pose.
//
// Joints map to Box2D 2.4.1's (box2d24_joints.h); a joint feature 2.4.1 lacks is refused with a
// message. Shapes Box2D 2.4 cannot represent exactly are refused with a message:
// - capsules: a box plus two circles has the right outline but not the right mass (the circles
//   overlap the box, so the overlap is counted twice) — refused;
// - polygons: Box2D 2.4 gives every polygon a fixed 0.01 m skin (b2_polygonRadius); a Tumble
//   polygon with radius 0 is run as Box2D's polygon, i.e. 0.01 m larger all round (stated on
//   stderr), one with radius 0.01 m exactly, any other radius is refused.
#include "scene.h"
#include "scene_file.h"

#include "box2d24_joints.h"

#include <box2d/box2d.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

static int Usage()
{
	fprintf(stderr, "usage: box2d-ref SCENE_FILE [--steps N] [--csv FILE]\n");
	return 2;
}

// Adds the scene shape to the Box2D body; false (with a message) when Box2D cannot represent it.
static bool AddShape(b2Body* body, const SceneShape& shape, int bodyIndex, int shapeIndex, bool* warnedSkin)
{
	b2FixtureDef fd;
	fd.density = shape.density;
	fd.friction = shape.friction;
	fd.restitution = shape.restitution;
	fd.isSensor = shape.isSensor;
	const tbGeometry& g = shape.geometry;
	switch (g.type)
	{
		case tb_circleShape:
		{
			b2CircleShape circle;
			circle.m_p.Set(g.circle.center.x, g.circle.center.y);
			circle.m_radius = g.circle.radius;
			fd.shape = &circle;
			body->CreateFixture(&fd);
			return true;
		}
		case tb_segmentShape:
		{
			b2EdgeShape edge;
			edge.SetTwoSided(b2Vec2(g.segment.point1.x, g.segment.point1.y), b2Vec2(g.segment.point2.x, g.segment.point2.y));
			fd.shape = &edge;
			body->CreateFixture(&fd);
			return true;
		}
		case tb_polygonShape:
		{
			float radius = g.polygon.radius;
			if (radius != 0.0f && fabsf(radius - b2_polygonRadius) > 1.0e-6f)
			{
				fprintf(stderr,
						"box2d-ref: bodies[%d].shapes[%d]: polygon radius %g m; Box2D 2.4 polygons have a fixed %g m skin, "
						"so this scene cannot be run in Box2D 2.4\n",
						bodyIndex, shapeIndex, (double)radius, (double)b2_polygonRadius);
				return false;
			}
			if (radius == 0.0f && *warnedSkin == false)
			{
				fprintf(stderr, "box2d-ref: note: sharp polygons run with Box2D 2.4's fixed %g m skin (0.01 m larger)\n",
						(double)b2_polygonRadius);
				*warnedSkin = true;
			}
			b2Vec2 points[b2_maxPolygonVertices];
			for (int i = 0; i < g.polygon.count; ++i)
			{
				points[i].Set(g.polygon.vertices[i].x, g.polygon.vertices[i].y);
			}
			b2PolygonShape polygon;
			polygon.Set(points, g.polygon.count);
			fd.shape = &polygon;
			body->CreateFixture(&fd);
			return true;
		}
		case tb_capsuleShape:
		default:
			fprintf(stderr,
					"box2d-ref: bodies[%d].shapes[%d]: capsule; Box2D 2.4 has no capsule, and a box plus two circles "
					"has the right outline but the wrong mass (the overlaps count twice), so the scene is refused\n",
					bodyIndex, shapeIndex);
			return false;
	}
}

static b2BodyType Box2DType(tbBodyType type)
{
	return type == tb_dynamicBody ? b2_dynamicBody : type == tb_kinematicBody ? b2_kinematicBody : b2_staticBody;
}

static void WriteRows(FILE* csv, const Scene* scene, const std::vector<b2Body*>& bodies, int step)
{
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		if (scene->bodies[i].type == tb_staticBody)
		{
			continue;
		}
		b2Vec2 p = bodies[(size_t)i]->GetPosition();
		b2Vec2 v = bodies[(size_t)i]->GetLinearVelocity();
		fprintf(csv, "%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", step, i, (double)p.x, (double)p.y,
				(double)bodies[(size_t)i]->GetAngle(), (double)v.x, (double)v.y,
				(double)bodies[(size_t)i]->GetAngularVelocity());
	}
}

// Box2D 2.4 has no target-transform call: the velocity that reaches the drive's target this step.
static void DriveBodies(const Scene* scene, const std::vector<b2Body*>& bodies, int step)
{
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		tbTransform target;
		if (Scene_DriveTarget(scene, i, step, &target) == false)
		{
			continue;
		}
		b2Body* body = bodies[(size_t)i];
		const b2Transform& xf = body->GetTransform();
		tbTransform current = {{xf.p.x, xf.p.y}, {xf.q.c, xf.q.s}};
		tbVec2 localCenter = {body->GetLocalCenter().x, body->GetLocalCenter().y};
		tbVec2 v;
		float w;
		Scene_TargetVelocity(current, localCenter, target, scene->timeStep, &v, &w);
		body->SetLinearVelocity(b2Vec2(v.x, v.y));
		body->SetAngularVelocity(w);
	}
}

int main(int argc, char** argv)
{
	const char* scenePath = nullptr;
	const char* csvPath = nullptr;
	int steps = -1;
	for (int i = 1; i < argc; ++i)
	{
		if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc)
		{
			char* end = nullptr;
			long value = strtol(argv[++i], &end, 10);
			if (*end != '\0' || value < 0 || value > 100000000)
			{
				fprintf(stderr, "box2d-ref: --steps must be a whole number >= 0\n");
				return 2;
			}
			steps = (int)value;
		}
		else if (strcmp(argv[i], "--csv") == 0 && i + 1 < argc)
		{
			csvPath = argv[++i];
		}
		else if (argv[i][0] != '-' && scenePath == nullptr)
		{
			scenePath = argv[i];
		}
		else
		{
			return Usage();
		}
	}
	if (scenePath == nullptr)
	{
		return Usage();
	}
	char error[512];
	Scene* scene = SceneFile_Load(scenePath, error, (int)sizeof(error));
	if (scene == nullptr)
	{
		fprintf(stderr, "box2d-ref: %s\n", error);
		return 1;
	}
	if (steps < 0)
	{
		steps = scene->steps;
	}

	b2World world(b2Vec2(scene->gravity.x, scene->gravity.y));
	world.SetAllowSleeping(scene->enableSleep);
	std::vector<b2Body*> bodies;
	bool warnedSkin = false;
	for (int i = 0; i < scene->bodyCount; ++i)
	{
		const SceneBody& sb = scene->bodies[i];
		b2BodyDef bd;
		bd.type = Box2DType(sb.type);
		bd.position.Set(sb.position.x, sb.position.y);
		bd.angle = sb.angle;
		bd.linearDamping = sb.linearDamping;
		bd.angularDamping = sb.angularDamping;
		bd.gravityScale = sb.gravityScale;
		bd.bullet = sb.bullet;
		bd.awake = sb.isAwake;
		b2Body* body = world.CreateBody(&bd);
		for (int k = 0; k < sb.shapeCount; ++k)
		{
			if (AddShape(body, sb.shapes[k], i, k, &warnedSkin) == false)
			{
				Scene_Destroy(scene);
				return 1;
			}
		}
		// Velocities after the shapes: the scene's velocity is the centre of mass's (Tumble's
		// convention), and Box2D's SetLinearVelocity is the centre of mass's too.
		body->SetLinearVelocity(b2Vec2(sb.linearVelocity.x, sb.linearVelocity.y));
		body->SetAngularVelocity(sb.angularVelocity);
		bodies.push_back(body);
	}
	for (int j = 0; j < scene->jointCount; ++j)
	{
		if (Box2D24_AddJoint(&world, bodies, scene->joints[j]) == false)
		{
			fprintf(stderr,
					"box2d-ref: joints[%d]: a %s joint with a feature Box2D 2.4.1 does not have (revolute or prismatic "
					"spring, distance motor, soft linear weld, motor or filter joint)\n",
					j, Scene_JointTypeName(scene->joints[j].type));
			Scene_Destroy(scene);
			return 1;
		}
	}

	FILE* csv = nullptr;
	if (csvPath != nullptr)
	{
		csv = fopen(csvPath, "w");
		if (csv == nullptr)
		{
			fprintf(stderr, "box2d-ref: cannot write %s\n", csvPath);
			Scene_Destroy(scene);
			return 1;
		}
		fprintf(csv, "step,body,x,y,angle,vx,vy,omega\n");
		WriteRows(csv, scene, bodies, 0);
	}
	for (int step = 1; step <= steps; ++step)
	{
		DriveBodies(scene, bodies, step - 1);
		world.Step(scene->timeStep, 8, 3);
		if (csv != nullptr)
		{
			WriteRows(csv, scene, bodies, step);
		}
	}
	int status = 0;
	if (csv != nullptr && fclose(csv) != 0)
	{
		fprintf(stderr, "box2d-ref: cannot write %s\n", csvPath);
		status = 1;
	}
	Scene_Destroy(scene);
	return status;
}
