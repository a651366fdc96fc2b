// Helpers shared by the Criterion tests: the worlds, bodies and shapes many test files build the
// same way, a fixed-step loop, an overlap counter, an int comparison for qsort and the tests'
// pseudo-random numbers. Each helper makes exactly what its parameters say from the default
// definitions, so a test reads its set-up from the call.
#pragma once

#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/// A world of the default definition but for its gravity.
static inline tbWorldId CreateWorld(tbVec2 gravity)
{
	tbWorldDef def = tbDefaultWorldDef();
	def.gravity = gravity;
	tbWorldId world = tbCreateWorld(&def);
	cr_assert(tbWorld_IsValid(world));
	return world;
}

/// A body of the given type at `position`, without shapes.
static inline tbBodyId CreateBody(tbWorldId world, tbBodyType type, tbVec2 position)
{
	tbBodyDef def = tbDefaultBodyDef();
	def.type = type;
	def.position = position;
	return tbCreateBody(world, &def);
}

/// A box of half-widths hx × hy centred on the body's origin, made from shapeDef (the default
/// definition when NULL).
static inline tbShapeId AddBoxShape(tbBodyId body, float hx, float hy, const tbShapeDef* shapeDef)
{
	tbShapeDef def = shapeDef != NULL ? *shapeDef : tbDefaultShapeDef();
	tbPolygon box = tbMakeBox(hx, hy);
	return tbCreatePolygonShape(body, &def, &box);
}

/// A body made from bodyDef carrying one box of half-widths hx × hy (AddBoxShape).
static inline tbBodyId CreateBoxFromDef(tbWorldId world, const tbBodyDef* bodyDef, float hx, float hy,
										const tbShapeDef* shapeDef)
{
	tbBodyId body = tbCreateBody(world, bodyDef);
	AddBoxShape(body, hx, hy, shapeDef);
	return body;
}

/// A body of the given type at `position`, at rest, carrying one box of half-widths hx × hy and
/// the given density (kg/m²; the default shape definition's is 1).
static inline tbBodyId CreateBox(tbWorldId world, tbBodyType type, tbVec2 position, float hx, float hy, float density)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = type;
	bodyDef.position = position;
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.density = density;
	return CreateBoxFromDef(world, &bodyDef, hx, hy, &shapeDef);
}

/// A dynamic disc of the given radius and mass (kg) centred on the body's origin at `position`.
static inline tbBodyId CreateDiscOfMass(tbWorldId world, tbVec2 position, float radius, float mass)
{
	tbBodyId body = CreateBody(world, tb_dynamicBody, position);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.density = mass / (TB_PI * radius * radius);
	tbCircle circle = {{0.0f, 0.0f}, radius};
	tbCreateCircleShape(body, &shapeDef, &circle);
	cr_assert_float_eq(tbBody_GetMass(body), mass, 1e-5f * mass);
	return body;
}

/// A dynamic ball of the given radius at `position` moving at `velocity`, made from shapeDef (the
/// default definition when NULL). Returns the shape; the body goes to *bodyOut.
static inline tbShapeId CreateBall(tbWorldId world, tbVec2 position, tbVec2 velocity, float radius,
								   const tbShapeDef* shapeDef, tbBodyId* bodyOut)
{
	tbBodyDef bodyDef = tbDefaultBodyDef();
	bodyDef.type = tb_dynamicBody;
	bodyDef.position = position;
	bodyDef.linearVelocity = velocity;
	tbBodyId body = tbCreateBody(world, &bodyDef);
	tbShapeDef def = shapeDef != NULL ? *shapeDef : tbDefaultShapeDef();
	tbCircle circle = {{0.0f, 0.0f}, radius};
	tbShapeId shape = tbCreateCircleShape(body, &def, &circle);
	cr_assert(tbShape_IsValid(shape));
	*bodyOut = body;
	return shape;
}

/// A static body at `position` carrying one box of half-widths hx × hy made from shapeDef (the
/// default definition when NULL): ground whose top face is at position.y + hy. Returns the box.
static inline tbShapeId CreateGround(tbWorldId world, tbVec2 position, float hx, float hy, const tbShapeDef* shapeDef)
{
	tbShapeId shape = AddBoxShape(CreateBody(world, tb_staticBody, position), hx, hy, shapeDef);
	cr_assert(tbShape_IsValid(shape));
	return shape;
}

/// `steps` steps of timeStep seconds, subSteps sub-steps each.
static inline void StepWorld(tbWorldId world, int steps, float timeStep, int subSteps)
{
	for (int i = 0; i < steps; ++i)
	{
		tbWorld_Step(world, timeStep, subSteps);
	}
}

/// Overlap callback counting the shapes it is given in *(int*)context; never stops the query.
static inline bool CountOverlap(tbShapeId shapeId, void* context)
{
	(void)shapeId;
	*(int*)context += 1;
	return true;
}

/// qsort comparison of two ints, ascending.
static inline int CompareInts(const void* a, const void* b)
{
	int x = *(const int*)a, y = *(const int*)b;
	return (x > y) - (x < y);
}

/// A float in [lower, upper) from the linear congruential generator whose state is *seed (24 bits
/// of it per number): the tests' reproducible random numbers.
static inline float RandomFloat(uint32_t* seed, float lower, float upper)
{
	*seed = 1664525u * *seed + 1013904223u;
	float unit = (float)(*seed >> 8) * (1.0f / 16777216.0f);
	return lower + (upper - lower) * unit;
}
