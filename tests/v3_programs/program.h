// What the programs share: names for shapes in the printed lines (ids are compared, never
// printed, so the lines do not depend on how an engine numbers its objects) and a hash of body
// state for comparing runs of the same engine. Written against Box2D v3.2's API.
#pragma once

#include "box2d/box2d.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define MAX_NAMED 32

typedef struct NamedShape
{
	b2ShapeId id;
	const char* name;
} NamedShape;

static NamedShape g_named[MAX_NAMED];
static int g_namedCount;

static inline void NameShape(b2ShapeId id, const char* name)
{
	if (g_namedCount < MAX_NAMED)
	{
		g_named[g_namedCount].id = id;
		g_named[g_namedCount].name = name;
		g_namedCount += 1;
	}
}

static inline const char* ShapeName(b2ShapeId id)
{
	for (int i = 0; i < g_namedCount; ++i)
	{
		if (B2_ID_EQUALS(g_named[i].id, id))
		{
			return g_named[i].name;
		}
	}
	return "unnamed";
}

/// The two names of a pair in alphabetical order: which shape an engine calls A is its own choice.
static inline void PrintPair(int step, const char* what, b2ShapeId a, b2ShapeId b)
{
	const char* first = ShapeName(a);
	const char* second = ShapeName(b);
	if (strcmp(first, second) > 0)
	{
		const char* t = first;
		first = second;
		second = t;
	}
	printf("step %d: %s %s %s\n", step, what, first, second);
}

/// A box shape, a sensor or not, with sensor events on or off, named for the printed lines.
static inline b2ShapeId AddBox(b2BodyId body, float halfWidth, float halfHeight, bool isSensor, bool sensorEvents,
							   const char* name)
{
	b2ShapeDef shapeDef = b2DefaultShapeDef();
	shapeDef.isSensor = isSensor;
	shapeDef.enableSensorEvents = sensorEvents;
	b2Polygon box = b2MakeBox(halfWidth, halfHeight);
	b2ShapeId shape = b2CreatePolygonShape(body, &shapeDef, &box);
	NameShape(shape, name);
	return shape;
}

/// Print the step's sensor begin and end events; returns how many there were.
static inline int PrintSensorEvents(int step, b2WorldId world)
{
	b2SensorEvents events = b2World_GetSensorEvents(world);
	for (int i = 0; i < events.beginCount; ++i)
	{
		printf("step %d: %s sees %s begin\n", step, ShapeName(events.beginEvents[i].sensorShapeId),
			   ShapeName(events.beginEvents[i].visitorShapeId));
	}
	for (int i = 0; i < events.endCount; ++i)
	{
		printf("step %d: %s sees %s end\n", step, ShapeName(events.endEvents[i].sensorShapeId),
			   ShapeName(events.endEvents[i].visitorShapeId));
	}
	return events.beginCount + events.endCount;
}

/// FNV-1a over the bytes of each body's position, rotation and velocities.
static inline uint64_t HashBodies(const b2BodyId* bodies, int count)
{
	uint64_t hash = 14695981039346656037ull;
	for (int i = 0; i < count; ++i)
	{
		struct
		{
			b2Pos p;
			b2Rot q;
			b2Vec2 v;
			float w;
		} state;
		memset(&state, 0, sizeof(state));
		state.p = b2Body_GetPosition(bodies[i]);
		state.q = b2Body_GetRotation(bodies[i]);
		state.v = b2Body_GetLinearVelocity(bodies[i]);
		state.w = b2Body_GetAngularVelocity(bodies[i]);
		const unsigned char* bytes = (const unsigned char*)&state;
		for (size_t k = 0; k < sizeof(state); ++k)
		{
			hash = (hash ^ bytes[k]) * 1099511628211ull;
		}
	}
	return hash;
}
