// Shapes: validation of geometry and materials, creation and destruction, broad-phase proxies,
// filtering, getters and setters.
#include "world.h"

#include "core/array.h"

#include "tumble/constants.h"
#include "recording.h"

#include <string.h>

#define TB_SHAPE_DEF_MAGIC 0x7B3A1C03

tbShapeDef tbDefaultShapeDef(void)
{
	tbShapeDef def;
	memset(&def, 0, sizeof(def));
	def.material = tbDefaultSurfaceMaterial();
	def.density = 1.0f;
	def.filter = tbDefaultFilter();
	// Events are off unless asked for (Box2D v3.2's defaults): a contact reports begin and end when
	// either shape enables contact events, a sensor a visitor when both enable sensor events.
	def.updateBodyMass = true;
	def.invokeContactCreation = true;
	def.internalValue = TB_SHAPE_DEF_MAGIC;
	return def;
}

tbFilter tbDefaultFilter(void)
{
	tbFilter filter = {TB_DEFAULT_CATEGORY_BITS, TB_DEFAULT_MASK_BITS, 0};
	return filter;
}

tbQueryFilter tbDefaultQueryFilter(void)
{
	tbQueryFilter filter = {TB_DEFAULT_CATEGORY_BITS, TB_DEFAULT_MASK_BITS};
	return filter;
}

tbShapeId tbMakeShapeId(const tbWorld* world, int shapeId)
{
	tbShapeId id = {shapeId + 1, world->worldId, world->shapes[shapeId].generation};
	return id;
}

tbShape* tbGetShapeChecked(tbShapeId id, const char* function, tbWorld** worldOut, bool mutating)
{
	if (id.index1 <= 0)
	{
		tbReportError(function, "shapeId is null; pass an id returned by a tbCreate*Shape function");
		return NULL;
	}
	tbWorld* world = id.world0 < TB_MAX_WORLDS ? tbGetWorldFromIndex(id.world0) : NULL;
	int index = id.index1 - 1;
	if (world == NULL || index >= world->shapePool.highWater || world->shapes[index].inUse == false ||
		world->shapes[index].generation != id.generation)
	{
		tbReportError(function, "shapeId refers to a destroyed shape, body or world; do not use a shape id after it "
								"was destroyed (check with tbShape_IsValid)");
		return NULL;
	}
	if (mutating && world->locked)
	{
		tbReportError(function, "the world is locked (stepping); change shapes between steps");
		return NULL;
	}
	if (worldOut != NULL)
	{
		*worldOut = world;
	}
	return world->shapes + index;
}

bool tbShape_IsValid(tbShapeId id)
{
	if (id.index1 <= 0 || id.world0 >= TB_MAX_WORLDS)
	{
		return false;
	}
	tbWorld* world = tbGetWorldFromIndex(id.world0);
	int index = id.index1 - 1;
	return world != NULL && index < world->shapePool.highWater && world->shapes[index].inUse &&
		   world->shapes[index].generation == id.generation;
}

tbAABB tbComputeShapeAABBInternal(const tbShape* shape, tbWorldTransform transform)
{
	return tbComputeShapeAABB(&shape->geometry, transform);
}

#if defined(TUMBLE_DOUBLE_PRECISION)
// The box is found about the body's origin in float (the shape's extent, small), then moved to
// the body's position in double and rounded outwards (tbOffsetAABB): far from the origin, where a
// float's spacing can exceed the extent, the box still contains the shape. The margin is added
// before the move, so a margin below that spacing is not lost.
tbAABB tbComputeFatShapeAABB(const tbShape* shape, tbWorldTransform transform, float extra)
{
	tbWorldTransform turn = {tbPos_zero, transform.q};
	return tbOffsetAABB(tbAABB_Fatten(tbComputeShapeAABB(&shape->geometry, turn), extra), transform.p);
}
#else
tbAABB tbComputeFatShapeAABB(const tbShape* shape, tbWorldTransform transform, float extra)
{
	return tbAABB_Fatten(tbComputeShapeAABB(&shape->geometry, transform), extra);
}
#endif

bool tbShouldShapesCollide(tbFilter a, tbFilter b)
{
	if (a.groupIndex == b.groupIndex && a.groupIndex != 0)
	{
		return a.groupIndex > 0;
	}
	return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

void tbCreateShapeProxy(tbWorld* world, tbShape* shape, tbBody* body, bool findPairs)
{
	shape->aabb = tbComputeShapeAABBInternal(shape, body->transform);
	if (body->isDisabled)
	{
		shape->fatAABB = shape->aabb;
		shape->proxyKey = TB_NULL_INDEX; // a disabled body's shapes are not in the broad phase
		return;
	}
	// Static shapes never move: no margin, so static boxes stay tight. A new movable shape gets the
	// largest margin (its body's extent may not include it yet); the first finalize that finds the
	// box too small re-makes it from the body's motion.
	float margin = body->type == tb_staticBody ? 0.0f : TB_AABB_MARGIN;
	shape->fatAABB = tbComputeFatShapeAABB(shape, body->transform, margin);
	tbProxyType type = body->type == tb_staticBody ? tb_proxyStatic : tb_proxyMovable;
	shape->proxyKey = tbBroadPhase_CreateProxyMarked(&world->broadPhase, shape->fatAABB, shape->filter.categoryBits,
													 (int)(shape - world->shapes), type,
													 findPairs || type != tb_proxyStatic);
	world->staticProxyCount += type == tb_proxyStatic ? 1 : 0;
}

void tbDestroyShapeProxy(tbWorld* world, tbShape* shape)
{
	if (shape->proxyKey != TB_NULL_INDEX)
	{
		world->staticProxyCount -= world->broadPhase.table.proxies[shape->proxyKey].type == tb_proxyStatic ? 1 : 0;
		tbBroadPhase_DestroyProxy(&world->broadPhase, shape->proxyKey);
		shape->proxyKey = TB_NULL_INDEX;
	}
}

/// The box swept by `box` moving by d, grown by pad on every side.
static tbAABB tbSweepBox(tbAABB box, tbVec2 d, float pad)
{
	tbAABB moved = {tbAdd(box.lowerBound, d), tbAdd(box.upperBound, d)};
	return tbAABB_Fatten(tbAABB_Union(box, moved), pad);
}

/// Broad-phase boxes must contain where a body's shapes can go during the next step, so that every
/// pair that can touch in that step has its contact (and speculative points) when the step begins:
/// two bodies that meet during the step have overlapping sweeps, hence overlapping fat boxes. The
/// next step moves the centre of mass by d = dt·(v + dt·g) (the velocity after the next step's
/// gravity) and turns the body by Δθ = ω·dt. Displacements beyond the body's reach
/// (tbSpeculativeReach) are clipped there: faster bodies are continuous collision's job.
///
/// The sweep of a body that barely turns (arc |Δθ|·maxExtent at most TB_LINEAR_SLOP) is the bounding
/// box of the tight box and the tight box displaced by d, grown by that arc (no point moves farther
/// than its arc). One that turns more is bounded exactly instead (tbPredictedTransform, tbTurnPad): a point at r from
/// the centre follows x(t) = c + t·d + R(θ + t·Δθ)·r, whose distance from the chord between its two
/// ends is largest halfway, where it is the sagitta |r|·(1 − cos(Δθ/2)). So the box around the
/// shape's boxes at the start and at the predicted end pose, grown by maxExtent·(1 − cos(Δθ/2)),
/// holds the whole sweep. Growing by the arc instead counted a spinning body's turn in every
/// direction, and a spinning blade (the spinner) kept many more contacts than Box2D v3; with the
/// exact bound it keeps about as many (docs/methods.md, "Broad-phase boxes"). A round shape about
/// its centre of mass does not grow at all.
///
/// When the fat box no longer contains that sweep it is re-made as the sweep enlarged by the margin
/// min(TB_AABB_MARGIN, TB_AABB_MARGIN_FRACTION·maxExtent), the hysteresis that keeps a resting or
/// jiggling body from moving its proxy every step. A moving body whose d exceeds the margin gets a
/// new box every step. Rejected: sweeping the new box by 2·d so that steady motion stays inside it
/// for two steps (half the proxy moves of a tumbling pile): every box then reaches a step further
/// ahead than the body can go, and bodies moving together overlap each other's boxes (a tumbling
/// pile kept far more contacts than Box2D v3; with one step's sweep about as many, at no more
/// time per step).
/// The shapes' tight boxes, and the fat boxes of those whose sweep left their fat box, which are
/// flagged (shape->proxyMoved) for tbMoveFlaggedProxies: writes only this body's shapes, so
/// bodies may be done on several workers at once.

/// Where a body is predicted to be after the step: centre moved by d, turned by atan(Δθ)
/// (tbIntegrateRotation, the solver's own rotation update), origin placed about the new centre.
static tbWorldTransform tbPredictedTransform(const tbBody* body, tbVec2 d, float turn)
{
	tbWorldTransform xf;
	xf.q = tbIntegrateRotation(body->transform.q, turn);
	tbPos center = tbOffsetPos(body->center, d);
	xf.p = tbOffsetPos(center, tbNeg(tbRotateVector(xf.q, body->localCenter)));
	return xf;
}

/// Growth that covers the turn from the start pose to tbPredictedTransform's and on to the full
/// Δθ: the end pose is turned by φ = atan(|Δθ|), so the sagitta is maxExtent·(1 − cos(φ/2)), with
/// cos φ = 1/√(1 + Δθ²) and 1 − cos(φ/2) = (1 − cos φ)/(2·(1 + cos(φ/2))) (no cancellation); the
/// rest of the turn, Δθ − atan(Δθ) ≤ |Δθ|³/3, moves no point farther than maxExtent·|Δθ|³/3. The
/// sub-stepped solver turns by n·atan(Δθ/n) ≤ Δθ.
static float tbTurnPad(float maxExtent, float turn)
{
	float t2 = turn * turn;
	float cosPhi = 1.0f / sqrtf(1.0f + t2);
	float cosHalf = sqrtf(0.5f * (1.0f + cosPhi));
	float sagitta = (1.0f - cosPhi) / (2.0f * (1.0f + cosHalf));
	return maxExtent * (sagitta + tbAbsFloat(turn) * t2 / 3.0f);
}

/// How a body's shapes sweep over the next step (tbComputeBodyShapeBoxes): each shape's tight box
/// displaced by d, or its boxes at the start and the predicted end pose when turning, grown by pad;
/// a re-made fat box is that sweep grown by margin.
typedef struct tbShapeSweep
{
	tbVec2 d;
	float pad;
	float margin;
	bool turning;
	tbWorldTransform end;
} tbShapeSweep;

static tbShapeSweep tbBodySweep(const tbWorld* world, const tbBody* body)
{
	tbShapeSweep s;
	s.margin = body->type == tb_staticBody ? 0.0f : tbMinFloat(TB_AABB_MARGIN, TB_AABB_MARGIN_FRACTION * body->maxExtent);
	s.d = tbVec2_zero;
	s.pad = 0.0f;
	s.turning = false;
	s.end = body->transform;
	if (body->type != tb_staticBody)
	{
		float dt = world->stepTime;
		float cap = tbSpeculativeReach(body);
		tbVec2 g = body->type == tb_dynamicBody ? tbMulSV(body->gravityScale, world->def.gravity) : tbVec2_zero;
		tbVec2 d = tbMulSV(dt, tbMulAdd(body->linearVelocity, dt, g));
		float length = tbLength(d);
		// NaN-safe: a non-finite displacement is replaced by none (the step rejects nothing here).
		// That includes an infinite one (gravity × gravityScale beyond FLT_MAX), which scaled down
		// to the reach would give 0 · ∞ = NaN in the box.
		s.d = length <= cap ? d : (length > cap && length <= FLT_MAX ? tbMulSV(cap / length, d) : tbVec2_zero);
		float turn = body->angularVelocity * dt;
		float arc = tbAbsFloat(turn) * body->maxExtent;
		s.pad = tbMinFloat(arc, cap);
		// The margin is hysteresis for a body that stays inside its box for a while; one that moves
		// farther than the margin in a step gets a new box every step anyway, and the margin only
		// makes it overlap more boxes (bodies falling together, as in the washer, then keep many
		// more contacts, for nothing; docs/methods.md, "Broad-phase boxes").
		s.margin = length > s.margin ? 0.0f : s.margin;
		// A turn of at most half a radian whose arc is within the reach: bounded exactly (a larger
		// one keeps the arc, which is then close to the exact bound anyway).
		if (arc > TB_LINEAR_SLOP && arc <= cap && tbAbsFloat(turn) <= 0.5f)
		{
			s.turning = true;
			s.end = tbPredictedTransform(body, s.d, turn);
			s.pad = tbTurnPad(body->maxExtent, turn);
		}
	}
	return s;
}

/// The box a shape with tight box `aabb` sweeps over the next step.
static tbAABB tbShapeSweepBox(const tbShape* shape, tbAABB aabb, const tbShapeSweep* s)
{
	return s->turning ? tbAABB_Fatten(tbAABB_Union(aabb, tbComputeShapeAABBInternal(shape, s->end)), s->pad)
					  : tbSweepBox(aabb, s->d, s->pad);
}

tbAABB tbRemadeFatAABB(const tbWorld* world, const tbBody* body, const tbShape* shape)
{
	tbShapeSweep s = tbBodySweep(world, body);
	return tbAABB_Fatten(tbShapeSweepBox(shape, shape->aabb, &s), s.margin);
}

bool tbComputeBodyShapeBoxes(const tbWorld* world, tbBody* body, bool forceMove)
{
	bool moved = false;
	tbShapeSweep s = tbBodySweep(world, body);
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		tbShape* shape = world->shapes + id;
		shape->aabb = tbComputeShapeAABBInternal(shape, body->transform);
		tbAABB sweep = tbShapeSweepBox(shape, shape->aabb, &s);
		if (shape->proxyKey != TB_NULL_INDEX && (forceMove || tbAABB_Contains(shape->fatAABB, sweep) == false))
		{
			shape->fatAABB = tbAABB_Fatten(sweep, s.margin);
			shape->proxyMoved = true;
			moved = true;
		}
	}
	return moved;
}

/// Move the flagged proxies of a body in the broad phase (serial: the broad phase changes).
void tbMoveFlaggedProxies(tbWorld* world, const tbBody* body)
{
	for (int id = body->headShapeId; id != TB_NULL_INDEX; id = world->shapes[id].nextShapeId)
	{
		tbShape* shape = world->shapes + id;
		if (shape->proxyMoved)
		{
			tbBroadPhase_MoveProxy(&world->broadPhase, shape->proxyKey, shape->fatAABB);
			world->counters.proxyMoves += 1;
			shape->proxyMoved = false;
		}
	}
}

void tbUpdateBodyShapeBoxes(tbWorld* world, tbBody* body, bool forceMove)
{
	tbComputeBodyShapeBoxes(world, body, forceMove);
	tbMoveFlaggedProxies(world, body);
}

tbSurfaceMaterial tbDefaultSurfaceMaterial(void)
{
	tbSurfaceMaterial material;
	memset(&material, 0, sizeof(material));
	material.friction = 0.6f;
	return material;
}

bool tbCheckSurfaceMaterial(const char* f, const char* name, const tbSurfaceMaterial* material)
{
	if (tbCheckPointer(f, name, material) == false)
	{
		return false;
	}
	const float values[3] = {material->friction, material->restitution, material->rollingResistance};
	const char* const fields[3] = {"friction", "restitution", "rollingResistance"};
	for (int i = 0; i < 3; ++i)
	{
		if (tbIsValidFloat(values[i]) == false || values[i] < 0.0f)
		{
			tbReportError(f, "%s.%s is %g; it must be finite and >= 0", name, fields[i], (double)values[i]);
			return false;
		}
	}
	if (tbIsValidFloat(material->tangentSpeed) == false)
	{
		tbReportError(f, "%s.tangentSpeed is %g; it must be finite", name, (double)material->tangentSpeed);
		return false;
	}
	return true;
}

static bool tbCheckShapeDef(const tbShapeDef* def, const char* f)
{
	if (tbCheckPointer(f, "def", def) == false)
	{
		return false;
	}
	if (def->internalValue != TB_SHAPE_DEF_MAGIC)
	{
		tbReportError(f, "def was not initialised by tbDefaultShapeDef(); start from tbDefaultShapeDef() and change "
						 "fields");
		return false;
	}
	return tbCheckNonNegative(f, "def->density", def->density) && tbCheckSurfaceMaterial(f, "def->material", &def->material);
}

static bool tbCheckRadius(const char* f, const char* name, float radius)
{
	return tbCheckLength(f, name, radius, true);
}

/// Is the polygon strictly convex and counter-clockwise, with no duplicate or collinear vertices,
/// and do its normals match its edges? This is a geometric check, not tbValidateHull: a hull from
/// tbComputeHull welds points closer than the linear slop, but a valid thin box (a 2 mm card from
/// tbMakeBox) has edges shorter than that. Tolerances are relative to the polygon's size:
/// an edge shorter than 1e-6 × size is a duplicate, and |sin| < 1e-6 between neighbouring edges is
/// collinear; a normal must be unit (1e-3) and perpendicular to its edge (1e-3).
bool tbIsConvexPolygon(const tbPolygon* p)
{
	float size = 0.0f;
	for (int i = 0; i < p->count; ++i)
	{
		size = tbMaxFloat(size, tbLength(tbSub(p->vertices[i], p->vertices[0])));
	}
	for (int i = 0; i < p->count; ++i)
	{
		tbVec2 e1 = tbSub(p->vertices[(i + 1) % p->count], p->vertices[i]);
		tbVec2 e2 = tbSub(p->vertices[(i + 2) % p->count], p->vertices[(i + 1) % p->count]);
		float l1 = tbLength(e1), l2 = tbLength(e2);
		if (l1 <= 1e-6f * size || l2 <= 1e-6f * size || tbCross(e1, e2) <= 1e-6f * l1 * l2)
		{
			return false;
		}
		tbVec2 n = p->normals[i];
		if (tbAbsFloat(tbLength(n) - 1.0f) > 1e-3f || tbAbsFloat(tbDot(n, e1)) > 1e-3f * l1 ||
			tbDot(n, tbRightPerp(e1)) <= 0.0f)
		{
			return false;
		}
	}
	return true;
}

/// Reject a polygon that is not convex and counter-clockwise with 3..8 finite vertices.
static bool tbCheckPolygon(const char* f, const tbPolygon* p)
{
	if (p->count < 3 || p->count > TB_MAX_POLYGON_VERTICES)
	{
		tbReportError(f, "polygon->count is %d (must be 3..%d); build polygons with tbMakePolygon(tbComputeHull(...))",
					  p->count, TB_MAX_POLYGON_VERTICES);
		return false;
	}
	if (tbCheckLength(f, "polygon->radius", p->radius, false) == false ||
		tbCheckCoordinate(f, "polygon->centroid", p->centroid) == false ||
		tbCheckPoints(f, "polygon->vertices", p->vertices, p->count) == false)
	{
		return false;
	}
	for (int i = 0; i < p->count; ++i)
	{
		if (tbIsValidVec2(p->vertices[i]) == false || tbIsValidVec2(p->normals[i]) == false)
		{
			tbReportError(f, "polygon->vertices[%d] or normals[%d] is not finite; pass finite coordinates", i, i);
			return false;
		}
	}
	if (tbIsConvexPolygon(p) == false)
	{
		tbReportError(f, "polygon is degenerate or not convex and counter-clockwise (duplicate or collinear vertices, "
						 "or normals that do not match the edges); build it with tbMakePolygon(tbComputeHull(...))");
		return false;
	}
	return true;
}

bool tbCheckGeometry(const char* f, const tbGeometry* g)
{
	switch (g->type)
	{
		case tb_circleShape:
			return tbCheckCoordinate(f, "circle->center", g->circle.center) &&
				   tbCheckRadius(f, "circle->radius", g->circle.radius);
		case tb_capsuleShape:
			if (tbCheckCoordinate(f, "capsule->center1", g->capsule.center1) == false ||
				tbCheckCoordinate(f, "capsule->center2", g->capsule.center2) == false ||
				tbCheckRadius(f, "capsule->radius", g->capsule.radius) == false)
			{
				return false;
			}
			if (tbDistanceSquared(g->capsule.center1, g->capsule.center2) < TB_LINEAR_SLOP * TB_LINEAR_SLOP)
			{
				tbReportError(f, "capsule centers are closer than %g m; use a circle instead", (double)TB_LINEAR_SLOP);
				return false;
			}
			return true;
		case tb_segmentShape:
			if (tbCheckCoordinate(f, "segment->point1", g->segment.point1) == false ||
				tbCheckCoordinate(f, "segment->point2", g->segment.point2) == false)
			{
				return false;
			}
			if (tbDistanceSquared(g->segment.point1, g->segment.point2) < TB_LINEAR_SLOP * TB_LINEAR_SLOP)
			{
				tbReportError(f, "segment points are closer than %g m; give the segment a length", (double)TB_LINEAR_SLOP);
				return false;
			}
			return true;
		case tb_polygonShape:
			return tbCheckPolygon(f, &g->polygon);
		case tb_chainSegmentShape:
			// A segment with its ghost points (an orphan, tbCreateChainSegmentShape; a chain makes its own).
			if (tbCheckCoordinate(f, "chainSegment->ghost1", g->chainSegment.ghost1) == false ||
				tbCheckCoordinate(f, "chainSegment->segment.point1", g->chainSegment.segment.point1) == false ||
				tbCheckCoordinate(f, "chainSegment->segment.point2", g->chainSegment.segment.point2) == false ||
				tbCheckCoordinate(f, "chainSegment->ghost2", g->chainSegment.ghost2) == false)
			{
				return false;
			}
			if (tbDistanceSquared(g->chainSegment.segment.point1, g->chainSegment.segment.point2) <
				TB_LINEAR_SLOP * TB_LINEAR_SLOP)
			{
				tbReportError(f, "chain segment points are closer than %g m; give the segment a length",
							  (double)TB_LINEAR_SLOP);
				return false;
			}
			return true;
		default:
			tbReportError(f, "geometry->type is %d; use a tbShapeType value", (int)g->type);
			return false;
	}
}

// A density that gives the shape a mass above TB_MAX_SHAPE_MASS, or a rotational inertia that
// overflows float, is refused: the body would get an infinite mass and NaN positions, or impulses
// that overflow (constants.h).
static bool tbCheckShapeMass(const char* f, const tbGeometry* geometry, float density)
{
	tbMassData md = tbComputeShapeMass(geometry, density);
	if (md.mass <= TB_MAX_SHAPE_MASS && tbIsValidFloat(md.rotationalInertia))
	{
		return true;
	}
	tbReportError(f, "density %g gives this shape a mass of %g kg and a rotational inertia of %g kg m^2 (the mass "
					 "must be at most TB_MAX_SHAPE_MASS = %g kg, the inertia finite); lower the density",
				  (double)density, (double)md.mass, (double)md.rotationalInertia, (double)TB_MAX_SHAPE_MASS);
	return false;
}

static int tbAllocShapeSlot(tbWorld* world)
{
	bool isNew;
	int id = tbIdPool_Alloc(&world->shapePool, &isNew);
	if (isNew)
	{
		TB_ARRAY_RESERVE(world->shapes, world->shapeCapacity, id + 1);
		memset(world->shapes + id, 0, sizeof(tbShape));
		world->shapes[id].generation = world->shapeGenerationBase;
	}
	return id;
}

static tbShapeId tbCreateShapeInternal(tbBodyId bodyId, const tbShapeDef* def, const tbGeometry* geometry, const char* f)
{
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, f, &world, true);
	if (body == NULL || tbCheckShapeDef(def, f) == false || tbCheckGeometry(f, geometry) == false ||
		tbCheckShapeMass(f, geometry, def->density) == false || tbStructureLocked(world, f, "create shapes"))
	{
		return TB_NULL_SHAPE_ID;
	}
	int id = tbAddShape(world, bodyId.index1 - 1, def, geometry);
	return tbMakeShapeId(world, id);
}

int tbAddShape(tbWorld* world, int bodyIndex, const tbShapeDef* def, const tbGeometry* geometry)
{
	int id = tbAllocShapeSlot(world);
	tbBody* body = world->bodies + bodyIndex;
	tbShape* shape = world->shapes + id;
	uint16_t generation = shape->generation; // advanced when the last shape here was destroyed
	memset(shape, 0, sizeof(tbShape));
	shape->generation = generation;
	shape->inUse = true;
	shape->geometry = *geometry;
	shape->userData = def->userData;
	shape->filter = def->filter;
	shape->density = def->density;
	shape->material = def->material;
	shape->isSensor = def->isSensor;
	shape->enableSensorEvents = def->enableSensorEvents;
	shape->enableContactEvents = def->enableContactEvents;
	shape->enableHitEvents = def->enableHitEvents;
	shape->enableCustomFiltering = def->enableCustomFiltering;
	shape->enablePreSolveEvents = def->enablePreSolveEvents;
	shape->bodyId = bodyIndex;
	shape->nextShapeId = body->headShapeId;
	shape->proxyKey = TB_NULL_INDEX;
	body->headShapeId = id;
	body->shapeCount += 1;
	// Box2D v3.2: a sensor always looks for what it overlaps, whatever invokeContactCreation says.
	tbCreateShapeProxy(world, shape, body, def->invokeContactCreation || def->isSensor);
	if (def->updateBodyMass)
	{
		tbUpdateBodyMass(world, body);
	}
	else
	{
		tbAddShapeExtents(body, &shape->geometry);
	}
	return id;
}

tbShapeId tbCreateShape(tbBodyId bodyId, const tbShapeDef* def, const tbGeometry* geometry)
{
	TB_RECORD(CreateShape, &bodyId, def, geometry);
	if (tbCheckPointer("tbCreateShape", "geometry", geometry) == false)
	{
		return TB_NULL_SHAPE_ID;
	}
	return tbCreateShapeInternal(bodyId, def, geometry, "tbCreateShape");
}

tbShapeId tbCreateCircleShape(tbBodyId bodyId, const tbShapeDef* def, const tbCircle* circle)
{
	TB_RECORD(CreateCircleShape, &bodyId, def, circle);
	if (tbCheckPointer("tbCreateCircleShape", "circle", circle) == false)
	{
		return TB_NULL_SHAPE_ID;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_circleShape;
	g.circle = *circle;
	return tbCreateShapeInternal(bodyId, def, &g, "tbCreateCircleShape");
}

tbShapeId tbCreateCapsuleShape(tbBodyId bodyId, const tbShapeDef* def, const tbCapsule* capsule)
{
	TB_RECORD(CreateCapsuleShape, &bodyId, def, capsule);
	if (tbCheckPointer("tbCreateCapsuleShape", "capsule", capsule) == false)
	{
		return TB_NULL_SHAPE_ID;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_capsuleShape;
	g.capsule = *capsule;
	return tbCreateShapeInternal(bodyId, def, &g, "tbCreateCapsuleShape");
}

tbShapeId tbCreatePolygonShape(tbBodyId bodyId, const tbShapeDef* def, const tbPolygon* polygon)
{
	TB_RECORD(CreatePolygonShape, &bodyId, def, polygon);
	if (tbCheckPointer("tbCreatePolygonShape", "polygon", polygon) == false)
	{
		return TB_NULL_SHAPE_ID;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_polygonShape;
	g.polygon = *polygon;
	return tbCreateShapeInternal(bodyId, def, &g, "tbCreatePolygonShape");
}

tbShapeId tbCreateChainSegmentShape(tbBodyId bodyId, const tbShapeDef* def, const tbChainSegment* chainSegment)
{
	TB_RECORD(CreateChainSegmentShape, &bodyId, def, chainSegment);
	if (tbCheckPointer("tbCreateChainSegmentShape", "chainSegment", chainSegment) == false)
	{
		return TB_NULL_SHAPE_ID;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_chainSegmentShape;
	g.chainSegment = *chainSegment;
	g.chainSegment.chainId = TB_NULL_INDEX; // an orphan: no chain owns it
	return tbCreateShapeInternal(bodyId, def, &g, "tbCreateChainSegmentShape");
}

tbShapeId tbCreateSegmentShape(tbBodyId bodyId, const tbShapeDef* def, const tbSegment* segment)
{
	TB_RECORD(CreateSegmentShape, &bodyId, def, segment);
	if (tbCheckPointer("tbCreateSegmentShape", "segment", segment) == false)
	{
		return TB_NULL_SHAPE_ID;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_segmentShape;
	g.segment = *segment;
	return tbCreateShapeInternal(bodyId, def, &g, "tbCreateSegmentShape");
}

static void tbUnlinkShape(tbWorld* world, tbBody* body, int shapeId)
{
	int* link = &body->headShapeId;
	while (*link != TB_NULL_INDEX)
	{
		if (*link == shapeId)
		{
			*link = world->shapes[shapeId].nextShapeId;
			body->shapeCount -= 1;
			return;
		}
		link = &world->shapes[*link].nextShapeId;
	}
}

/// Destroy every contact of one shape (walking its body's contact list), waking the other bodies.
static void tbDestroyShapeContacts(tbWorld* world, const tbBody* body, int id)
{
	int key = body->headContactKey;
	while (key != TB_NULL_INDEX)
	{
		tbContact* contact = world->contacts + (key >> 1);
		int next = contact->edges[key & 1].nextKey;
		if (contact->shapeIdA == id || contact->shapeIdB == id)
		{
			tbDestroyContact(world, key >> 1, true);
		}
		key = next;
	}
}

/// Is this shape a segment of a chain (destroyed and changed only with its chain)?
static bool tbIsChainOwned(const tbShape* shape, const char* f)
{
	if (shape->geometry.type == tb_chainSegmentShape && shape->geometry.chainSegment.chainId >= 0)
	{
		tbReportError(f, "the shape is a segment of a chain; destroy or change the chain instead (tbDestroyChain)");
		return true;
	}
	return false;
}

void tbRemoveShape(tbWorld* world, int id, bool updateBodyMass)
{
	tbShape* shape = world->shapes + id;
	tbBody* body = world->bodies + shape->bodyId;
	tbDestroyShapeContacts(world, body, id);
	tbDestroyShapeProxy(world, shape);
	tbUnlinkShape(world, body, id);
	shape->inUse = false;
	tbIdPool_Release(&world->shapePool, id, &shape->generation, world->shapeGenerationBase);
	if (updateBodyMass)
	{
		tbUpdateBodyMass(world, body);
	}
	else
	{
		float minExtent, maxExtent; // these stay as they were: still bounds
		tbComputeBodyExtents(world, body, &minExtent, &maxExtent, &body->coreExtent);
	}
}

void tbDestroyShape(tbShapeId shapeId, bool updateBodyMass)
{
	TB_RECORD(DestroyShape, &shapeId, &updateBodyMass);
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbDestroyShape", &world, true);
	if (shape == NULL || tbIsChainOwned(shape, "tbDestroyShape") ||
		tbStructureLocked(world, "tbDestroyShape", "destroy shapes"))
	{
		return;
	}
	tbRemoveShape(world, shapeId.index1 - 1, updateBodyMass);
}

tbShapeType tbShape_GetType(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetType", NULL, false);
	return shape != NULL ? shape->geometry.type : tb_circleShape;
}

tbBodyId tbShape_GetBody(tbShapeId shapeId)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetBody", &world, false);
	return shape != NULL ? tbMakeBodyId(world, shape->bodyId) : TB_NULL_BODY_ID;
}

tbWorldId tbShape_GetWorld(tbShapeId shapeId)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetWorld", &world, false);
	if (shape == NULL)
	{
		return TB_NULL_WORLD_ID;
	}
	tbWorldId id = {(uint16_t)(world->worldId + 1), world->generation};
	return id;
}

tbGeometry tbShape_GetGeometry(tbShapeId shapeId)
{
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetGeometry", NULL, false);
	return shape != NULL ? shape->geometry : g;
}

// --- geometry by kind (Box2D v3's grammar) ---------------------------------------------------

/// The shape's geometry of the given kind; an error and zeros when the shape is of another kind.
static const tbGeometry* tbGetGeometryOfType(tbShapeId shapeId, tbShapeType type, const char* f)
{
	tbShape* shape = tbGetShapeChecked(shapeId, f, NULL, false);
	if (shape == NULL)
	{
		return NULL;
	}
	if (shape->geometry.type != type)
	{
		tbReportError(f, "the shape is of type %d, not %d (tbShape_GetType says which)", (int)shape->geometry.type,
					  (int)type);
		return NULL;
	}
	return &shape->geometry;
}

tbCircle tbShape_GetCircle(tbShapeId shapeId)
{
	const tbGeometry* g = tbGetGeometryOfType(shapeId, tb_circleShape, "tbShape_GetCircle");
	tbCircle none = {{0.0f, 0.0f}, 0.0f};
	return g != NULL ? g->circle : none;
}

tbCapsule tbShape_GetCapsule(tbShapeId shapeId)
{
	const tbGeometry* g = tbGetGeometryOfType(shapeId, tb_capsuleShape, "tbShape_GetCapsule");
	tbCapsule none = {{0.0f, 0.0f}, {0.0f, 0.0f}, 0.0f};
	return g != NULL ? g->capsule : none;
}

tbSegment tbShape_GetSegment(tbShapeId shapeId)
{
	const tbGeometry* g = tbGetGeometryOfType(shapeId, tb_segmentShape, "tbShape_GetSegment");
	tbSegment none = {{0.0f, 0.0f}, {0.0f, 0.0f}};
	return g != NULL ? g->segment : none;
}

tbChainSegment tbShape_GetChainSegment(tbShapeId shapeId)
{
	const tbGeometry* g = tbGetGeometryOfType(shapeId, tb_chainSegmentShape, "tbShape_GetChainSegment");
	tbChainSegment none = {{0.0f, 0.0f}, {{0.0f, 0.0f}, {0.0f, 0.0f}}, {0.0f, 0.0f}, -1};
	return g != NULL ? g->chainSegment : none;
}

tbPolygon tbShape_GetPolygon(tbShapeId shapeId)
{
	const tbGeometry* g = tbGetGeometryOfType(shapeId, tb_polygonShape, "tbShape_GetPolygon");
	tbPolygon none;
	memset(&none, 0, sizeof(none));
	return g != NULL ? g->polygon : none;
}

/// Replace a shape's geometry (any kind may become any other): checked as at creation, then its
/// contacts are destroyed (woken bodies find the new ones next step), its proxy re-made and its
/// body's mass recomputed.
static bool tbSetGeometry(tbShapeId shapeId, const tbGeometry* geometry, const char* f)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, f, &world, true);
	if (shape == NULL || tbIsChainOwned(shape, f) || tbCheckGeometry(f, geometry) == false ||
		tbCheckShapeMass(f, geometry, shape->density) == false || tbStructureLocked(world, f, "change shapes"))
	{
		return false;
	}
	tbBody* body = world->bodies + shape->bodyId;
	tbDestroyShapeContacts(world, body, shapeId.index1 - 1);
	shape->geometry = *geometry;
	tbDestroyShapeProxy(world, shape);
	tbCreateShapeProxy(world, shape, body, true);
	tbUpdateBodyMass(world, body);
	tbWakeBody(world, body);
	return true;
}

bool tbShape_SetCircle(tbShapeId shapeId, const tbCircle* circle)
{
	TB_RECORD(ShapeSetCircle, &shapeId, circle);
	if (tbCheckPointer("tbShape_SetCircle", "circle", circle) == false)
	{
		return false;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_circleShape;
	g.circle = *circle;
	return tbSetGeometry(shapeId, &g, "tbShape_SetCircle");
}

bool tbShape_SetCapsule(tbShapeId shapeId, const tbCapsule* capsule)
{
	TB_RECORD(ShapeSetCapsule, &shapeId, capsule);
	if (tbCheckPointer("tbShape_SetCapsule", "capsule", capsule) == false)
	{
		return false;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_capsuleShape;
	g.capsule = *capsule;
	return tbSetGeometry(shapeId, &g, "tbShape_SetCapsule");
}

bool tbShape_SetSegment(tbShapeId shapeId, const tbSegment* segment)
{
	TB_RECORD(ShapeSetSegment, &shapeId, segment);
	if (tbCheckPointer("tbShape_SetSegment", "segment", segment) == false)
	{
		return false;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_segmentShape;
	g.segment = *segment;
	return tbSetGeometry(shapeId, &g, "tbShape_SetSegment");
}

bool tbShape_SetChainSegment(tbShapeId shapeId, const tbChainSegment* chainSegment)
{
	TB_RECORD(ShapeSetChainSegment, &shapeId, chainSegment);
	if (tbCheckPointer("tbShape_SetChainSegment", "chainSegment", chainSegment) == false)
	{
		return false;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_chainSegmentShape;
	g.chainSegment = *chainSegment;
	g.chainSegment.chainId = TB_NULL_INDEX; // the result is an orphan (a chain's own segments are refused)
	return tbSetGeometry(shapeId, &g, "tbShape_SetChainSegment");
}

bool tbShape_SetPolygon(tbShapeId shapeId, const tbPolygon* polygon)
{
	TB_RECORD(ShapeSetPolygon, &shapeId, polygon);
	if (tbCheckPointer("tbShape_SetPolygon", "polygon", polygon) == false)
	{
		return false;
	}
	tbGeometry g;
	memset(&g, 0, sizeof(g));
	g.type = tb_polygonShape;
	g.polygon = *polygon;
	return tbSetGeometry(shapeId, &g, "tbShape_SetPolygon");
}

// --- events at run time ----------------------------------------------------------------------

static void tbEnableShapeEvents(tbShapeId shapeId, const char* f, tbShapeEventKind kind, bool flag)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, f, &world, true);
	if (shape != NULL)
	{
		tbSetShapeEventFlag(world, shape, kind, flag);
	}
}

void tbShape_EnableContactEvents(tbShapeId shapeId, bool flag)
{
	TB_RECORD(ShapeEnableContactEvents, &shapeId, &flag);
	tbEnableShapeEvents(shapeId, "tbShape_EnableContactEvents", tb_shapeEventContacts, flag);
}

void tbShape_EnableHitEvents(tbShapeId shapeId, bool flag)
{
	TB_RECORD(ShapeEnableHitEvents, &shapeId, &flag);
	tbEnableShapeEvents(shapeId, "tbShape_EnableHitEvents", tb_shapeEventHits, flag);
}

void tbShape_EnableSensorEvents(tbShapeId shapeId, bool flag)
{
	TB_RECORD(ShapeEnableSensorEvents, &shapeId, &flag);
	tbEnableShapeEvents(shapeId, "tbShape_EnableSensorEvents", tb_shapeEventSensors, flag);
}

bool tbShape_AreContactEventsEnabled(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_AreContactEventsEnabled", NULL, false);
	return shape != NULL && shape->enableContactEvents;
}

bool tbShape_AreHitEventsEnabled(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_AreHitEventsEnabled", NULL, false);
	return shape != NULL && shape->enableHitEvents;
}

bool tbShape_AreSensorEventsEnabled(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_AreSensorEventsEnabled", NULL, false);
	return shape != NULL && shape->enableSensorEvents;
}

void tbShape_EnablePreSolveEvents(tbShapeId shapeId, bool flag)
{
	TB_RECORD(ShapeEnablePreSolveEvents, &shapeId, &flag);
	tbEnableShapeEvents(shapeId, "tbShape_EnablePreSolveEvents", tb_shapeEventPreSolve, flag);
}

bool tbShape_ArePreSolveEventsEnabled(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_ArePreSolveEventsEnabled", NULL, false);
	return shape != NULL && shape->enablePreSolveEvents;
}

bool tbShape_IsSensor(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_IsSensor", NULL, false);
	return shape != NULL && shape->isSensor;
}

bool tbShape_SetDensity(tbShapeId shapeId, float density, bool updateBodyMass)
{
	TB_RECORD(ShapeSetDensity, &shapeId, &density, &updateBodyMass);
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_SetDensity", &world, true);
	if (shape == NULL || tbCheckNonNegative("tbShape_SetDensity", "density", density) == false ||
		tbCheckShapeMass("tbShape_SetDensity", &shape->geometry, density) == false)
	{
		return false;
	}
	shape->density = density;
	if (updateBodyMass)
	{
		tbUpdateBodyMass(world, world->bodies + shape->bodyId);
	}
	return true;
}

float tbShape_GetDensity(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetDensity", NULL, false);
	return shape != NULL ? shape->density : 0.0f;
}

// The shape's contacts take a changed material from the next step on (as when they were made).
void tbRemixShapeContacts(tbWorld* world, const tbShape* shape)
{
	int shapeId = (int)(shape - world->shapes);
	const tbBody* body = world->bodies + shape->bodyId;
	for (int key = body->headContactKey; key != TB_NULL_INDEX;)
	{
		tbContact* contact = world->contacts + (key >> 1);
		key = contact->edges[key & 1].nextKey;
		if (contact->shapeIdA == shapeId || contact->shapeIdB == shapeId)
		{
			tbMixContactMaterials(world, contact);
		}
	}
}

static bool tbSetShapeMaterial(const char* f, tbShapeId shapeId, const tbSurfaceMaterial* material, const char* name)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, f, &world, true);
	if (shape == NULL || tbCheckSurfaceMaterial(f, name, material) == false)
	{
		return false;
	}
	shape->material = *material;
	tbRemixShapeContacts(world, shape);
	return true;
}

bool tbShape_SetSurfaceMaterial(tbShapeId shapeId, const tbSurfaceMaterial* material)
{
	TB_RECORD(ShapeSetSurfaceMaterial, &shapeId, material);
	return tbSetShapeMaterial("tbShape_SetSurfaceMaterial", shapeId, material, "material");
}

tbSurfaceMaterial tbShape_GetSurfaceMaterial(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetSurfaceMaterial", NULL, false);
	return shape != NULL ? shape->material : tbDefaultSurfaceMaterial();
}

bool tbShape_SetFriction(tbShapeId shapeId, float friction)
{
	TB_RECORD(ShapeSetFriction, &shapeId, &friction);
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_SetFriction", NULL, true);
	if (shape == NULL)
	{
		return false;
	}
	tbSurfaceMaterial material = shape->material;
	material.friction = friction;
	return tbSetShapeMaterial("tbShape_SetFriction", shapeId, &material, "new material");
}

float tbShape_GetFriction(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetFriction", NULL, false);
	return shape != NULL ? shape->material.friction : 0.0f;
}

bool tbShape_SetRestitution(tbShapeId shapeId, float restitution)
{
	TB_RECORD(ShapeSetRestitution, &shapeId, &restitution);
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_SetRestitution", NULL, true);
	if (shape == NULL)
	{
		return false;
	}
	tbSurfaceMaterial material = shape->material;
	material.restitution = restitution;
	return tbSetShapeMaterial("tbShape_SetRestitution", shapeId, &material, "new material");
}

float tbShape_GetRestitution(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetRestitution", NULL, false);
	return shape != NULL ? shape->material.restitution : 0.0f;
}

void tbShape_SetUserMaterial(tbShapeId shapeId, uint64_t material)
{
	TB_RECORD(ShapeSetUserMaterial, &shapeId, &material);
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_SetUserMaterial", &world, true);
	if (shape != NULL)
	{
		shape->material.userMaterialId = material;
		tbRemixShapeContacts(world, shape); // the mixing callbacks see the id
	}
}

uint64_t tbShape_GetUserMaterial(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetUserMaterial", NULL, false);
	return shape != NULL ? shape->material.userMaterialId : 0u;
}

tbFilter tbShape_GetFilter(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetFilter", NULL, false);
	return shape != NULL ? shape->filter : tbDefaultFilter();
}

bool tbShape_SetFilter(tbShapeId shapeId, tbFilter filter)
{
	TB_RECORD(ShapeSetFilter, &shapeId, &filter);
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_SetFilter", &world, true);
	if (shape == NULL || tbStructureLocked(world, "tbShape_SetFilter", "change filters"))
	{
		return false;
	}
	shape->filter = filter;
	// Re-create the proxy so that pairs are re-evaluated under the new filter.
	tbBody* body = world->bodies + shape->bodyId;
	tbDestroyShapeContacts(world, body, shapeId.index1 - 1);
	tbDestroyShapeProxy(world, shape);
	tbCreateShapeProxy(world, shape, body, true);
	return true;
}

void tbShape_SetUserData(tbShapeId shapeId, void* userData)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_SetUserData", NULL, false);
	if (shape != NULL)
	{
		shape->userData = userData;
	}
}

void* tbShape_GetUserData(tbShapeId shapeId)
{
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetUserData", NULL, false);
	return shape != NULL ? shape->userData : NULL;
}

tbAABB tbShape_GetAABB(tbShapeId shapeId)
{
	tbWorld* world;
	tbAABB empty = {{0.0f, 0.0f}, {0.0f, 0.0f}};
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetAABB", &world, false);
	return shape != NULL ? tbComputeShapeAABBInternal(shape, world->bodies[shape->bodyId].transform) : empty;
}

/// A shape's own test in the world's recording (a query of the player's frame): its one result, if any,
/// at the point (a hit's point for a ray: the origin moved by the fraction).
static void tbRecordShapeTest(const tbWorld* world, tbRecQueryType type, tbShapeId shapeId, tbPos origin,
							  tbVec2 translation, bool hit, tbVec2 normal, float fraction)
{
	tbRecQueryInfo info;
	memset(&info, 0, sizeof(info));
	info.type = type;
	info.origin = origin;
	info.translation = translation;
	info.shape = shapeId;
	tbQueryLog log;
	tbQueryLog* record = tbQueryLogBegin(&log, world, &info);
	if (hit)
	{
		tbQueryLogHit(record, shapeId, tbOffsetPos(origin, tbMulSV(fraction, translation)), normal, fraction);
	}
	tbQueryLogEnd(record);
}

bool tbShape_TestPoint(tbShapeId shapeId, tbPos point)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_TestPoint", &world, false);
	if (shape == NULL || tbCheckFinitePosition("tbShape_TestPoint", "point", point) == false)
	{
		return false;
	}
	tbVec2 local = tbInvTransformWorldPoint(world->bodies[shape->bodyId].transform, point);
	bool inside = tbPointInShape(&shape->geometry, local);
	tbRecordShapeTest(world, tb_recQueryShapeTestPoint, shapeId, point, tbVec2_zero, inside, tbVec2_zero, 0.0f);
	return inside;
}

tbPos tbShape_GetClosestPoint(tbShapeId shapeId, tbPos target)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetClosestPoint", &world, false);
	if (shape == NULL || tbCheckPosition("tbShape_GetClosestPoint", "target", target) == false)
	{
		return tbPos_zero;
	}
	// Distance from the shape (A, in its body frame) to a point proxy (B) placed at the target:
	// GJK's witness on A is the closest point (on the rounded surface with useRadii).
	tbWorldTransform transform = world->bodies[shape->bodyId].transform;
	tbWorldTransform at = {target, tbRot_identity};
	tbVec2 origin = tbVec2_zero;
	tbDistanceInput input;
	input.proxyA = tbMakeShapeProxy(&shape->geometry);
	input.proxyB = tbMakeProxy(&origin, 1, 0.0f);
	input.transform = tbInvMulWorldTransforms(transform, at);
	input.useRadii = true;
	tbSimplexCache cache;
	memset(&cache, 0, sizeof(cache));
	tbDistanceOutput output = tbShapeDistance(&input, &cache, NULL, 0);
	return output.distance > 0.0f ? tbTransformWorldPoint(transform, output.pointA) : target;
}

tbWorldCastOutput tbShape_RayCast(tbShapeId shapeId, tbPos origin, tbVec2 translation)
{
	tbWorldCastOutput output;
	memset(&output, 0, sizeof(output));
	const char* f = "tbShape_RayCast";
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, f, &world, false);
	if (shape == NULL || tbCheckPosition(f, "origin", origin) == false ||
		tbCheckVec2(f, "translation", translation) == false)
	{
		return output;
	}
	// In the shape's frame: the origin's offset from the body taken in the precision of positions.
	tbWorldTransform xf = world->bodies[shape->bodyId].transform;
	tbRayCastInput local;
	local.origin = tbInvTransformWorldPoint(xf, origin);
	local.translation = tbInvRotateVector(xf.q, translation);
	local.maxFraction = 1.0f;
	tbCastOutput hit = tbRayCastShape(&shape->geometry, &local);
	if (hit.hit)
	{
		output.point = tbTransformWorldPoint(xf, hit.point);
		output.normal = tbRotateVector(xf.q, hit.normal);
		output.fraction = hit.fraction;
		output.iterations = hit.iterations;
		output.hit = true;
	}
	tbRecordShapeTest(world, tb_recQueryShapeRayCast, shapeId, origin, translation, output.hit, output.normal,
					  output.fraction);
	return output;
}

tbMassData tbShape_ComputeMassData(tbShapeId shapeId)
{
	tbMassData md = {0};
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_ComputeMassData", NULL, false);
	return shape != NULL ? tbComputeShapeMass(&shape->geometry, shape->density) : md;
}
