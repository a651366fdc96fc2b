// Contacts: a contact exists while two shapes' fat boxes overlap. This file owns the two stages
// that find and update them: the pair stage turns broad-phase pairs into contacts (after
// filtering), and the collide stage (the narrow phase) recomputes each awake contact's
// manifold with a speculative margin that grows with the pair's approach speed (see
// tbSpeculativeMargin), or, for a touching pair that barely moved since, carries the last one
// along (tbRecycleManifold), carries impulses over by feature id for warm starting, and reports
// begin/end events when a point comes within the fixed TB_SPECULATIVE_DISTANCE.
#include "contact.h"

#include "world.h"

#include "collision/distance_internal.h"
#include "collision/manifold_internal.h"
#include "core/task.h"
#include "joints/joint.h"

#include "core/sort.h"

#include "core/array.h"

#include <math.h>
#include <stdlib.h> // qsort
#include <string.h>

// Material mixing. A callback's answer is user input arriving mid-step: one the solver cannot use
// (friction NaN or negative; restitution NaN, negative or infinite) is reported and replaced by the
// default mix, so the contact still behaves. Infinite friction is allowed: it never slides, in
// either contact solver (the default mix also reaches it, for frictions above about 1.8e19).
static float tbMixFriction(const tbWorld* world, const tbShape* a, const tbShape* b)
{
	float mixed = sqrtf(a->material.friction * b->material.friction);
	if (world->def.frictionCallback == NULL)
	{
		return mixed;
	}
	float value = world->def.frictionCallback(a->material.friction, a->material.userMaterialId, b->material.friction, b->material.userMaterialId);
	if (!(value >= 0.0f))
	{
		tbReportError("tbWorld_Step", "frictionCallback returned %g for frictions %g and %g; it must return a number >= 0 "
					  "(the default mix sqrt(a*b) = %g is used)", (double)value, (double)a->material.friction,
					  (double)b->material.friction, (double)mixed);
		return mixed;
	}
	return value;
}

static float tbMixRestitution(const tbWorld* world, const tbShape* a, const tbShape* b)
{
	float mixed = tbMaxFloat(a->material.restitution, b->material.restitution);
	if (world->def.restitutionCallback == NULL)
	{
		return mixed;
	}
	float value =
		world->def.restitutionCallback(a->material.restitution, a->material.userMaterialId, b->material.restitution, b->material.userMaterialId);
	if (!(value >= 0.0f) || tbIsValidFloat(value) == false)
	{
		tbReportError("tbWorld_Step", "restitutionCallback returned %g for restitutions %g and %g; it must return a "
					  "finite number >= 0 (the default mix max(a, b) = %g is used)", (double)value,
					  (double)a->material.restitution, (double)b->material.restitution, (double)mixed);
		return mixed;
	}
	return value;
}

/// Rounding radius of a shape: what rolls (circle, capsule, rounded polygon); 0 for the rest.
static float tbRollingRadius(const tbShape* shape)
{
	switch (shape->geometry.type)
	{
		case tb_circleShape:
			return shape->geometry.circle.radius;
		case tb_capsuleShape:
			return shape->geometry.capsule.radius;
		case tb_polygonShape:
			return shape->geometry.polygon.radius;
		default:
			return 0.0f;
	}
}

// Rolling resistance and tangent speed as Box2D v3.2 mixes them: the larger coefficient times the
// larger rounding radius (the lever arm of the resisting torque: a torque of c·r·N resists the
// rolling of a wheel of radius r under normal force N), and the two surfaces' speeds added.
void tbMixContactMaterials(const tbWorld* world, tbContact* contact)
{
	const tbShape* a = world->shapes + contact->shapeIdA;
	const tbShape* b = world->shapes + contact->shapeIdB;
	contact->friction = tbMixFriction(world, a, b);
	contact->restitution = tbMixRestitution(world, a, b);
	float resistance = tbMaxFloat(a->material.rollingResistance, b->material.rollingResistance);
	contact->rollingResistance = resistance > 0.0f ? resistance * tbMaxFloat(tbRollingRadius(a), tbRollingRadius(b)) : 0.0f;
	contact->tangentSpeed = a->material.tangentSpeed + b->material.tangentSpeed;
	tbSetContactMaterialFlags(contact);
}

void tbSetContactMaterialFlags(tbContact* contact)
{
	uint32_t bits = (contact->tangentSpeed != 0.0f ? (uint32_t)tb_contactTangentSpeed : 0u) |
					(contact->restitution != 0.0f ? (uint32_t)tb_contactBounces : 0u) |
					(contact->rollingResistance > 0.0f ? (uint32_t)tb_contactRolls : 0u);
	contact->flags = (contact->flags & ~(uint32_t)(tb_contactTangentSpeed | tb_contactBounces | tb_contactRolls)) | bits;
}

static void tbLinkEdge(tbWorld* world, int contactId, int edgeIndex)
{
	tbContact* contact = world->contacts + contactId;
	tbBody* body = world->bodies + contact->edges[edgeIndex].bodyId;
	int key = (contactId << 1) | edgeIndex;
	contact->edges[edgeIndex].prevKey = TB_NULL_INDEX;
	contact->edges[edgeIndex].nextKey = body->headContactKey;
	if (body->headContactKey != TB_NULL_INDEX)
	{
		int head = body->headContactKey;
		world->contacts[head >> 1].edges[head & 1].prevKey = key;
	}
	body->headContactKey = key;
	body->contactCount += 1;
}

static void tbUnlinkEdge(tbWorld* world, int contactId, int edgeIndex)
{
	tbContactEdge* edge = world->contacts[contactId].edges + edgeIndex;
	tbBody* body = world->bodies + edge->bodyId;
	if (edge->prevKey != TB_NULL_INDEX)
	{
		world->contacts[edge->prevKey >> 1].edges[edge->prevKey & 1].nextKey = edge->nextKey;
	}
	else
	{
		body->headContactKey = edge->nextKey;
	}
	if (edge->nextKey != TB_NULL_INDEX)
	{
		world->contacts[edge->nextKey >> 1].edges[edge->nextKey & 1].prevKey = edge->prevKey;
	}
	body->contactCount -= 1;
}

int tbCreateContact(tbWorld* world, int shapeIdA, int shapeIdB)
{
	tbStepCache_ContactsChanged(&world->cache);
	bool isNew;
	int id = tbIdPool_Alloc(&world->contactPool, &isNew);
	if (isNew)
	{
		TB_ARRAY_RESERVE(world->contacts, world->contactCapacity, id + 1);
		TB_ARRAY_RESERVE(world->cache.contactBodies, world->cache.contactBodyCapacity, id + 1);
		// A fresh slot's generations start from the world's generation, so an id kept from an
		// earlier world in the same world slot does not match (64k reuses of one slot per world).
		world->contacts[id].generation = (uint32_t)world->generation << 16;
	}
	tbContact* contact = world->contacts + id;
	uint32_t generation = contact->generation;
	memset(contact, 0, sizeof(tbContact));
	contact->generation = generation;
	const tbShape* a = world->shapes + shapeIdA;
	const tbShape* b = world->shapes + shapeIdB;
	contact->inUse = true;
	contact->shapeIdA = shapeIdA;
	contact->shapeIdB = shapeIdB;
	contact->edges[0].bodyId = a->bodyId;
	contact->edges[1].bodyId = b->bodyId;
	world->cache.contactBodies[id] = (tbBodyPair){a->bodyId, b->bodyId};
	tbMixContactMaterials(world, contact);
	contact->stamp = UINT32_MAX;
	if (a->isSensor || b->isSensor)
	{
		contact->flags |= tb_contactSensor;
		world->sensorContactCount += 1;
	}
	if (a->enableContactEvents || b->enableContactEvents)
	{
		contact->flags |= tb_contactEnableEvents; // either shape asks (Box2D v3.2's rule)
	}
	if (a->enableHitEvents || b->enableHitEvents)
	{
		contact->flags |= tb_contactEnableHits;
		world->hitContactCount += 1;
	}
	if (a->enablePreSolveEvents || b->enablePreSolveEvents)
	{
		contact->flags |= tb_contactEnablePreSolve;
	}
	tbLinkEdge(world, id, 0);
	tbLinkEdge(world, id, 1);
	tbHashSet_Add(&world->pairSet, tbShapePairKey(shapeIdA, shapeIdB));
	return id;
}


/// A sensor reports a visitor when both shapes enable sensor events: the sensor's flag says it
/// reports at all, the visitor's that it wants to be seen (a bullet a trigger should ignore).
static bool tbSensorEventsEnabled(const tbWorld* world, int sensor, int visitor)
{
	return world->shapes[sensor].enableSensorEvents && world->shapes[visitor].enableSensorEvents;
}

/// End events of the step go to the event arrays; those of a change between steps (the world is
/// unlocked) wait in the pending arrays for the next step, so they are neither cleared unseen at its
/// start nor pushed into an array the user may be reading.
static void tbPushSensorEndEvent(tbWorld* world, int sensor, int visitor)
{
	if (world->shapes[sensor].isSensor == false || tbSensorEventsEnabled(world, sensor, visitor) == false)
	{
		return;
	}
	tbSensorEndTouchEvent e = {tbMakeShapeId(world, sensor), tbMakeShapeId(world, visitor)};
	if (world->locked)
	{
		TB_ARRAY_PUSH(world->events.sensorEndEvents, world->events.sensorEndCount, world->events.sensorEndCapacity, e);
	}
	else
	{
		TB_ARRAY_PUSH(world->events.pendingSensorEndEvents, world->events.pendingSensorEndCount,
					  world->events.pendingSensorEndCapacity, e);
	}
}

static void tbPushEndEvent(tbWorld* world, const tbContact* contact)
{
	if (contact->flags & tb_contactSensor)
	{
		tbPushSensorEndEvent(world, contact->shapeIdA, contact->shapeIdB);
		tbPushSensorEndEvent(world, contact->shapeIdB, contact->shapeIdA);
	}
	else if (contact->flags & tb_contactEnableEvents)
	{
		// The contact's id as it is now: a contact being destroyed gets a new generation after this,
		// so the id then reads as invalid, as Box2D v3.2's does.
		tbContactEndTouchEvent e = {tbMakeShapeId(world, contact->shapeIdA), tbMakeShapeId(world, contact->shapeIdB),
									tbMakeContactId(world, (int)(contact - world->contacts))};
		if (world->locked)
		{
			TB_ARRAY_PUSH(world->events.endEvents, world->events.endCount, world->events.endCapacity, e);
		}
		else
		{
			TB_ARRAY_PUSH(world->events.pendingEndEvents, world->events.pendingEndCount, world->events.pendingEndCapacity, e);
		}
	}
}

void tbDestroyContact(tbWorld* world, int contactId, bool wakeBodies)
{
	tbStepCache_ContactsChanged(&world->cache);
	tbContact* contact = world->contacts + contactId;
	if (contact->flags & tb_contactReported)
	{
		tbPushEndEvent(world, contact);
	}
	tbHashSet_Remove(&world->pairSet, tbShapePairKey(contact->shapeIdA, contact->shapeIdB));
	tbUnlinkEdge(world, contactId, 0);
	tbUnlinkEdge(world, contactId, 1);
	if (wakeBodies && (contact->flags & tb_contactTouching))
	{
		tbWakeBody(world, world->bodies + contact->edges[0].bodyId);
		tbWakeBody(world, world->bodies + contact->edges[1].bodyId);
	}
	world->hitContactCount -= (contact->flags & tb_contactEnableHits) != 0 ? 1 : 0;
	world->sensorContactCount -= (contact->flags & tb_contactSensor) != 0 ? 1 : 0;
	contact->inUse = false;
	contact->flags = 0;
	contact->generation += 1;
	world->cache.contactBodies[contactId] = (tbBodyPair){TB_NULL_INDEX, TB_NULL_INDEX};
	tbIdPool_Free(&world->contactPool, contactId);
}

/// What the narrow phase of one contact found (tbCollideContact), acted on in contact order.
enum tbCollideResult
{
	tb_collideDestroy = 0x01,	 ///< the fat boxes no longer overlap
	tb_collideBegan = 0x02,		 ///< manifold points appeared: wake both bodies
	tb_collideBeginEvent = 0x04, ///< within the begin-touch distance now
	tb_collideEndEvent = 0x08,	 ///< no longer
	tb_collideRecycled = 0x10,
	tb_collideGJK = 0x20,
	tb_collideSAT = 0x40,
	tb_collideSolver = 0x80,   ///< touching and not a sensor: the solver will see it
	tb_collideReported = 0x100, ///< within the begin-touch distance (tb_contactReported)
	tb_collideReady = 0x200,	///< a solver contact as it stands: a dynamic side and no sleeping one
	tb_collideEnded = 0x400,	///< manifold points disappeared (touching ended)
	tb_collideNewKey = 0x800,	///< a ready contact whose solver key differs from the last step's
	tb_collideKeptApart = 0x1000, ///< a pair known to be apart: the narrow phase was skipped (tbStaysApart)
};

/// One worker's sums over its collide ranges, on a cache line of its own (tbCollideStage adds them
/// in worker order).
typedef struct tbCollideTally
{
	int reported, recycled, keptApart, gjk, sat;
	int changed;  ///< destroyed, began or ended touching, or a begin/end event
	int notReady; ///< solver contacts not ready (tb_collideReady)
	int newKeys;  ///< ready contacts with a new key (tb_collideNewKey)
	int padding[8];
} tbCollideTally;

static void tbAddTally(tbCollideTally* sum, const tbCollideTally* part)
{
	sum->reported += part->reported;
	sum->recycled += part->recycled;
	sum->keptApart += part->keptApart;
	sum->gjk += part->gjk;
	sum->sat += part->sat;
	sum->changed += part->changed;
	sum->notReady += part->notReady;
	sum->newKeys += part->newKeys;
}

/// A range's results counted into its worker's tally, in a loop of its own after the range's visits
/// (a short loop over a dense array of flags, where counting inside the visit loop cost a few
/// instructions per flag on every contact).
static void tbTallyResults(const uint16_t* results, int count, tbCollideTally* tally)
{
	const uint32_t change = tb_collideDestroy | tb_collideBegan | tb_collideEnded | tb_collideBeginEvent | tb_collideEndEvent;
	tbCollideTally sum = {0};
	for (int i = 0; i < count; ++i)
	{
		uint32_t result = results[i];
		sum.reported += (result & tb_collideReported) != 0 ? 1 : 0;
		sum.recycled += (result & tb_collideRecycled) != 0 ? 1 : 0;
		sum.keptApart += (result & tb_collideKeptApart) != 0 ? 1 : 0;
		sum.gjk += (result & tb_collideGJK) != 0 ? 1 : 0;
		sum.sat += (result & tb_collideSAT) != 0 ? 1 : 0;
		sum.changed += (result & change) != 0 ? 1 : 0;
		sum.notReady += (result & (tb_collideSolver | tb_collideReady)) == tb_collideSolver ? 1 : 0;
		sum.newKeys += (result & tb_collideNewKey) != 0 ? 1 : 0;
	}
	tbAddTally(tally, &sum);
}

static bool tbIsSegmentKind(tbShapeType type)
{
	return type == tb_segmentShape || type == tb_chainSegmentShape;
}

/// Should a broad-phase pair become a contact? Same body, no dynamic body (unless a shape is a
/// sensor: a kinematic door or lift passing a static or kinematic sensor is reported, and a sensor
/// carried through another sees it), filtered out, or an existing contact: no. Static proxies never
/// pair with each other.
static bool tbShouldCreateContact(const tbWorld* world, int shapeIdA, int shapeIdB)
{
	const tbShape* a = world->shapes + shapeIdA;
	const tbShape* b = world->shapes + shapeIdB;
	if (a->bodyId == b->bodyId)
	{
		return false;
	}
	if (tbIsSegmentKind(a->geometry.type) && tbIsSegmentKind(b->geometry.type))
	{
		return false; // no area on either side: never a contact
	}
	const tbBody* bodyA = world->bodies + a->bodyId;
	const tbBody* bodyB = world->bodies + b->bodyId;
	if (bodyA->type != tb_dynamicBody && bodyB->type != tb_dynamicBody && a->isSensor == false && b->isSensor == false)
	{
		return false;
	}
	if (tbShouldShapesCollide(a->filter, b->filter) == false)
	{
		return false;
	}
	// Most pairs the broad phase reports have their contact already (a moved proxy finds all it
	// overlaps): the pair set answers before the walk of a body's joints does.
	if (tbHashSet_Contains(&world->pairSet, tbShapePairKey(shapeIdA, shapeIdB)))
	{
		return false;
	}
	if ((bodyA->jointCount | bodyB->jointCount) != 0 && tbJointBlocksCollision(world, a->bodyId, b->bodyId))
	{
		return false; // a joint between them forbids it (collideConnected false)
	}
	if ((a->enableCustomFiltering || b->enableCustomFiltering) && world->customFilterFcn != NULL)
	{
		return world->customFilterFcn(tbMakeShapeId(world, shapeIdA), tbMakeShapeId(world, shapeIdB),
									  world->customFilterContext);
	}
	return true;
}

bool tbContactPairFilter(int shapeIdA, int shapeIdB, void* context)
{
	// Most pairs a moving pile finds have a contact already: one hash probe rejects them before
	// the shape and body loads of the full test.
	const tbWorld* world = context;
	if (tbHashSet_Contains(&world->pairSet, tbShapePairKey(shapeIdA, shapeIdB)))
	{
		return false;
	}
	return tbShouldCreateContact(world, shapeIdA, shapeIdB);
}

/// The contact of two shapes, from the contact list of the second one's body (a fast body's,
/// which has few), or TB_NULL_INDEX.
static int tbFindContact(const tbWorld* world, int shapeIdA, int shapeIdB)
{
	const tbBody* body = world->bodies + world->shapes[shapeIdB].bodyId;
	for (int key = body->headContactKey; key != TB_NULL_INDEX;)
	{
		const tbContact* contact = world->contacts + (key >> 1);
		if ((contact->shapeIdA == shapeIdA && contact->shapeIdB == shapeIdB) ||
			(contact->shapeIdA == shapeIdB && contact->shapeIdB == shapeIdA))
		{
			return key >> 1;
		}
		key = contact->edges[key & 1].nextKey;
	}
	return TB_NULL_INDEX;
}

int tbMarkSensorHit(tbWorld* world, int sensorShapeId, int visitorShapeId)
{
	int a = tbMinInt(sensorShapeId, visitorShapeId), b = tbMaxInt(sensorShapeId, visitorShapeId);
	int id = TB_NULL_INDEX;
	if (tbHashSet_Contains(&world->pairSet, tbShapePairKey(a, b)))
	{
		id = tbFindContact(world, sensorShapeId, visitorShapeId);
	}
	else if (tbShouldCreateContact(world, a, b))
	{
		id = tbCreateContact(world, a, b); // as the broad phase would make it: (lower id, higher id)
	}
	if (id == TB_NULL_INDEX || (world->contacts[id].flags & tb_contactSensorHit) != 0)
	{
		return TB_NULL_INDEX;
	}
	world->contacts[id].flags |= tb_contactSensorHit;
	return id;
}

void tbContactPairPrefetch(int shapeIdA, int shapeIdB, void* context)
{
	const tbWorld* world = context;
	tbHashSet_Prefetch(&world->pairSet, tbShapePairKey(shapeIdA, shapeIdB));
}

static void tbRunPairQueries(tbRangeTask* task, int itemCount, int minRange, void* taskContext, void* world)
{
	tbParallelFor(&((tbWorld*)world)->def, task, itemCount, minRange, taskContext);
}

void tbUpdatePairsStage(tbWorld* world)
{
	tbBroadPhase* bp = &world->broadPhase;
	// On workers the movable tree's refresh waits for the collide stage, where the caller runs it
	// while the workers start the narrow phase (tbCollideStage), as Box2D v3 rebuilds its tree
	// beside the narrow phase. Not with a pre-solve callback: it runs in the narrow phase and may
	// query the world.
	int workers = tbWorkerCount(&world->def);
	bool deferRefresh = workers > 1 && world->preSolveFcn == NULL;
	tbBroadPhase_UpdatePairsOnWorkers(bp, tbRunPairQueries, world, workers, tbWorkerSlotCount(&world->def), deferRefresh);
	world->counters.pairCandidates = bp->pairList.count;
	// Every pair passed tbContactPairFilter as it was found, and the pairs are unique: each
	// becomes a contact.
	for (int i = 0; i < bp->pairList.count; ++i)
	{
		tbCreateContact(world, bp->pairList.pairs[i].a, bp->pairList.pairs[i].b);
	}
}

/// Carry accumulated impulses from the old manifold to points of the new one with the same
/// feature id (warm starting).
static void tbMatchPoints(tbManifold* manifold, const tbManifold* old)
{
	manifold->rollingImpulse = old->rollingImpulse;
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		tbManifoldPoint* mp = manifold->points + i;
		mp->normalImpulse = 0.0f;
		mp->tangentImpulse = 0.0f;
		mp->persisted = false;
		for (int j = 0; j < old->pointCount; ++j)
		{
			if (old->points[j].id == mp->id)
			{
				mp->normalImpulse = old->points[j].normalImpulse;
				mp->tangentImpulse = old->points[j].tangentImpulse;
				mp->persisted = true;
				break;
			}
		}
	}
}

static bool tbIsSensorOverlap(const tbManifold* manifold)
{
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		if (manifold->points[i].separation < 0.0f)
		{
			return true;
		}
	}
	return false;
}

/// True when a point is closer than the fixed speculative distance: the begin/end event notion
/// of touching (tb_contactReported), independent of the speed-dependent manifold margin.
static bool tbIsWithinSpeculativeDistance(const tbManifold* manifold)
{
	for (int i = 0; i < manifold->pointCount; ++i)
	{
		if (manifold->points[i].separation < TB_SPECULATIVE_DISTANCE)
		{
			return true;
		}
	}
	return false;
}

/// Gravity scale that acts on a body (only dynamic bodies are accelerated by gravity).
static float tbEffectiveGravityScale(const tbBody* body)
{
	return body->type == tb_dynamicBody ? body->gravityScale : 0.0f;
}

/// Speculative margin of a pair for this step (m): how far apart the manifold keeps points.
///
/// A point kept at separation s lets the solver stop an approach that would close s within the
/// step; a point not kept cannot, so the pair penetrates by (closing distance − s). The margin
/// is therefore a bound on how far the surfaces of A and B can approach during the step, from
/// what is known when the narrow phase runs (positions and velocities at the end of the last step):
/// - the distance between two shapes is the distance between their cores (a circle's centre, a
///   capsule's segment, a polygon before rounding) less both radii, so only the cores' motion
///   counts; a core point of body X at r from its centre of mass moves at v_X + ω_X × r, and
///   |ω_X × r| ≤ |ω_X|·coreExtent_X, so two core points close at most at
///       |vA − vB| + |ωA|·coreExtentA + |ωB|·coreExtentB
///   (a ball spinning in place closes on nothing; its radius taken as the arm of the turn would
///   give its pairs the widest margins of a pile);
/// - during the step gravity adds g·sX·t to the velocity of a dynamic body X (sX its gravity
///   scale); the sub-stepped symplectic Euler moves it by at most g·sX·dt² (exactly
///   g·sX·dt²·(n + 1)/(2n) after n sub-steps), so the relative displacement grows by at most
///   |g|·|sA − sB|·dt²;
/// - damping only slows bodies; forces applied by the user are not included (small, and a
///   body pushed hard enough is caught by the fixed TB_SPECULATIVE_DISTANCE or pushed out).
/// Margin = TB_SPECULATIVE_DISTANCE + min(cap, dt·(relative point speed + dt·|g|·|sA − sB|)), with
/// cap the larger of the two bodies' reaches (tbSpeculativeReach: a body moving farther per step is
/// swept by continuous collision instead). The cap also bounds the extra points a fast scene pays
/// for. Points need no contact beyond this: broad-phase boxes contain each body's predicted sweep
/// (shape.c), so a pair that can touch during the step has its contact. Resting bodies get
/// TB_SPECULATIVE_DISTANCE + g·dt² (0.0228 m at 60 Hz) against the ground and exactly
/// TB_SPECULATIVE_DISTANCE against each other.
static TB_FORCE_INLINE float tbSpeculativeMargin(const tbWorld* world, const tbBody* bodyA, const tbBody* bodyB)
{
	float dt = world->stepTime;
	tbVec2 dv = tbSub(bodyA->linearVelocity, bodyB->linearVelocity);
	// fabsf, one instruction clearing the sign, where tbAbsFloat's comparison (which keeps −0) is a
	// branch on the spin's sign, unpredictable in a pile; added to a length, a zero's sign cannot show.
	float speed = tbLength(dv) + fabsf(bodyA->angularVelocity) * bodyA->coreExtent +
				  fabsf(bodyB->angularVelocity) * bodyB->coreExtent;
	float gravity = world->gravityLength * fabsf(tbEffectiveGravityScale(bodyA) - tbEffectiveGravityScale(bodyB));
	float closing = dt * (speed + dt * gravity);
	// NaN-safe: a non-finite velocity gets the cap rather than poisoning the comparison.
	float cap = tbMaxFloat(tbSpeculativeReach(bodyA), tbSpeculativeReach(bodyB));
	float extra = closing < cap ? closing : cap;
	return TB_SPECULATIVE_DISTANCE + tbMaxFloat(extra, 0.0f);
}

/// Remember where a touching manifold was computed: the relative pose, the normal in each body's
/// frame and each point (midway between the surfaces, so the same world point for both bodies) in
/// each body's origin frame. Origin frames, not centre-of-mass ones: a body's centre moves when a
/// shape is added or its density changes, its origin does not.
static void tbStoreManifoldBase(tbContact* contact, tbWorldTransform xfA, tbWorldTransform xfB, const tbPos points[2],
								float margin)
{
	tbFillManifoldBase(&contact->base, &contact->manifold, xfA, xfB, points);
	contact->base.margin = margin;
	contact->flags |= tb_contactRecyclable;
}

/// How far any point of one body can have moved relative to the other since the base pose (m).
/// In A's frame, a point of B at r from B's origin (|r| ≤ extentB) sits at q·r + p, where (p, q)
/// is B's pose in A's frame, so it moved by (q − q0)·r + (p − p0), at most
/// |p − p0| + |q − q0|·extentB, with |q − q0| = 2·sin(|Δθ|/2) the chord of the relative turn
/// (q as the vector (cos, sin)). The same holds in B's frame with A's extent; both bound the change
/// of every distance between a point of A and a point of B, so the smaller one is taken (a box on a
/// kinematic drum: the drum's 14 m extent does not count, the box's 0.18 m does).
/// True when the smaller bound is below tolerance; B's frame is looked at only when A's bound is not
/// (most resting pairs pass on it). False for a non-finite pose: then A's bound is NaN, and B's,
/// made of the same numbers, too.
static TB_FORCE_INLINE bool tbMovedLessThan(tbTransform relative0, tbTransform relative, const tbBody* bodyA, const tbBody* bodyB,
							float tolerance)
{
	float chord = sqrtf((relative.q.c - relative0.q.c) * (relative.q.c - relative0.q.c) +
						(relative.q.s - relative0.q.s) * (relative.q.s - relative0.q.s));
	float inA = tbDistance(relative.p, relative0.p) + chord * bodyB->originExtent;
	if (inA < tolerance)
	{
		return true;
	}
	// B's pose in A's frame inverted: A's origin in B's frame is −qᵀ·p.
	tbVec2 pB = tbNeg(tbInvRotateVector(relative.q, relative.p));
	tbVec2 pB0 = tbNeg(tbInvRotateVector(relative0.q, relative0.p));
	float inB = tbDistance(pB, pB0) + chord * bodyA->originExtent;
	return inB < tolerance;
}

/// Manifold recycling (Box2D v3's contact recycling; the persistent manifolds of Coumans'
/// Bullet and PhysX keep points in the same spirit). A touching pair whose bodies barely moved
/// relative to each other since the narrow phase ran keeps its points, feature ids and impulses;
/// only the geometry is carried along:
/// - the point fixed in A, xA = xfA·pointA, and the one fixed in B, xB = xfB·pointB, were the same
///   world point when the manifold was computed, so xB − xA is the relative motion of the two
///   surfaces there and the separation becomes s = s0 + (xB − xA)·n. This is the solver's own
///   sub-step update (contact_solver.c, baseSeparation) carried across steps; its error is second
///   order, |xB − xA|·|n − n_true| plus s0·Δθ²/2;
/// - the normal and the anchors (the lever arms of the contact's impulses) stay as the narrow phase
///   gave them, in the world orientation of that moment, and do not turn with the bodies (Box2D v3
///   keeps them the same way). This is what lets a tall column of soft contacts stand: a soft
///   contact lets the boxes of a stack rock by F/(m_eff·ω²), and lever arms that turned with that
///   rocking would shift every load towards the lean by the turn times the box height, the
///   destabilising moment of a column under its own weight. The rocking stiffness of a face is
///   m_eff·ω²·w²/2 for a face of width w, whatever the load, so against turning arms a column
///   buckles once its weight times its height outgrows that (the buckling load of a chain of
///   rotational springs: about 21 unit boxes at the settled stiffness, tests/test_stability.c);
///   Box2D v3's columns buckle the same way with its recycling off. The arms are off by at most
///   each body's turn since the narrow phase times the arm, which is bounded below;
///   the normal, a face normal, is off by at most its face's turn, under the same bound; a round
///   pair's one-point normal may instead be the line between the closest points of the cores (two
///   circles, a circle beyond a polygon's corner), which turns with their relative motion δ by at
///   most δ/d for cores d apart: 1.3° for two circles of 0.45 m at the default 0.02 m. Holding δ
///   below d·sin 2° as well made a deep pile flip between kept and new normals, each change a
///   small kick: 20,000 mixed bodies never fell asleep (docs/methods.md).
/// Chain segments are never recycled: their one-sided rules depend on the neighbouring segments.
/// When to recycle: a feature pair not in the manifold was at least margin0 (the speculative margin
/// then) apart and has closed by at most the relative motion δ since (tbMovedLessThan); in this
/// step it closes by at most margin − TB_SPECULATIVE_DISTANCE more. So while
///     δ < min(recycleDistance, margin0 − margin + TB_SPECULATIVE_DISTANCE)
/// no feature the narrow phase would add can reach contact during the step (a faster approach than
/// when the manifold was made shrinks the allowance to nothing); the relative turn must stay below
/// TB_RECYCLE_ANGLE and each body's own turn below the angle of TB_RECYCLE_COS_BODY_TURN, so that the
/// kept normal and lever arms stay within a few degrees (a pair turning together, a box on a drum,
/// gets new ones). What is lost: a speculative
/// point for a feature coming within the margin (caught later, before it touches), and the
/// clipping against face ends (a point stays while a box slides less than δ past an edge). Bodies
/// that were swept by continuous collision last step always get a new manifold.
/// Pairs apart keep their empty manifold under an exact bound of their own (tbStaysApart), except
/// pairs of two polygons: most of those are ruled out by their tight boxes or their separating axes
/// before the narrow phase does any more, so keeping them saved nothing on piles of polygons.
/// Rejected: keeping every empty manifold under the touching pairs' bound above (no pair then gets within
/// reach during the step, as Box2D v3 keeps its non-touching pairs) saved little on a falling pile,
/// and a pile of ragdolls never fell asleep: two limbs kept swinging at about 0.1 m/s, met by their
/// contacts only once the bound tripped, without the speculative point that would have slowed
/// them on the way.
// cos(TB_RECYCLE_ANGLE) = cos(2°), rounded to float.
#define TB_RECYCLE_COS_ANGLE 0.99939083f

// cos(5°), rounded to float: how far each body may turn on its own while its contacts keep their
// normal and lever arms. A tall column rocks further than the 2° of the relative bound at its top
// while it stands (its boxes turn together, each little against its neighbours); a new manifold
// there would take the lean into the arms and start the buckling the kept arms prevent. Box2D v3
// allows about 11°; 5° keeps a kept arm within 0.09 of its length of the true one.
#define TB_RECYCLE_COS_BODY_TURN 0.99619470f

/// A chain segment's manifold depends on its neighbours (the one-sided rules of its joints), which
/// the relative motion of the pair does not bound: chain contacts always get a new manifold.
static bool tbMayRecycle(const tbShape* shape)
{
	return shape->geometry.type != tb_chainSegmentShape;
}

/// Whether a new manifold may be recycled in later steps. Not a chain segment's (tbMayRecycle);
/// and not the one point a rounded corner facing a corner gets (a capsule's end cap beside a box's
/// corner, manifold_internal.h's corner ids): that point stands for the pair, but the face beside
/// it may lie within the margin too (a capsule levelling onto the box's face touches it along its
/// length, the narrow phase then clips two points), so the recycling's premise, every feature
/// within the margin in the manifold, does not hold. Recycled, such a point was measured to lag the
/// narrow phase by up to 1.1 cm while the capsule settled onto the face (tumble-bench-recycling,
/// the spinner). Sharp polygons meet corner to corner only apart, never touching.
static bool tbMayRecycleManifold(const tbShape* a, const tbShape* b, const tbManifold* m)
{
	if (tbMayRecycle(a) == false || tbMayRecycle(b) == false)
	{
		return false;
	}
	// tbRollingRadius is the rounding radius (a circle's counts too; its pairs never make corner ids).
	bool rounded = tbRollingRadius(a) > 0.0f || tbRollingRadius(b) > 0.0f;
	return (rounded && m->pointCount == 1 && tbIsCornerToCornerId(m->points[0].id)) == false;
}

/// recycleDistance is the world's (TB_RECYCLE_DISTANCE by default, tbWorld_SetContactRecycleDistance).
static TB_FORCE_INLINE bool tbRecycleManifold(tbContact* contact, const tbBody* bodyA, const tbBody* bodyB, float margin,
											  float recycleDistance)
{
	const tbManifoldBase* base = &contact->base;
	if ((contact->flags & tb_contactRecyclable) == 0 || bodyA->isFast || bodyB->isFast ||
		bodyA->enableContactRecycling == false || bodyB->enableContactRecycling == false)
	{
		return false;
	}
	tbWorldTransform xfA = bodyA->transform;
	tbWorldTransform xfB = bodyB->transform;
	tbTransform relative = tbInvMulWorldTransforms(xfA, xfB);
	float tolerance = tbMinFloat(recycleDistance, base->margin - margin + TB_SPECULATIVE_DISTANCE);
	// |turn| < TB_RECYCLE_ANGLE ⟺ cos(turn) > cos(TB_RECYCLE_ANGLE): the cosine is the dot product of
	// the two unit rotations: no atan2 for every touching contact in every step.
	float cosTurn = base->relative.q.c * relative.q.c + base->relative.q.s * relative.q.s;
	// Written so that NaN fails: a non-finite pose always gets a new manifold.
	if (!(cosTurn > TB_RECYCLE_COS_ANGLE && tbMovedLessThan(base->relative, relative, bodyA, bodyB, tolerance)))
	{
		return false;
	}
	// Each body's own turn since the narrow phase: its frame normal now against the kept normal,
	// which is that frame normal as it was then (the manifold's normal is not changed while recycled).
	tbManifold* m = &contact->manifold;
	float cosA = tbDot(tbRotateVector(xfA.q, base->normalA), m->normal);
	float cosB = tbDot(tbRotateVector(xfB.q, base->normalB), m->normal);
	if (!(tbMinFloat(cosA, cosB) > TB_RECYCLE_COS_BODY_TURN))
	{
		return false;
	}
	tbMoveRecycledPoints(m, base, xfA, xfB);
	for (int i = 0; i < m->pointCount; ++i)
	{
		m->points[i].persisted = true; // anchors kept: see above
	}
	return true;
}

/// Pairs apart. Most contacts of a pile are pairs whose fat boxes overlap while their shapes lie
/// farther apart than the margin: the narrow phase finds no point. When it finds a pair apart,
/// tbShapeGapBound gives a distance d0 the shapes were at least apart; since then every point of B
/// moved by at most δ relative to A (tbMovedLessThan), so the shapes are at least d0 − δ apart now,
/// and while d0 − δ > margin every point the narrow phase could make would be farther than the
/// margin (d0 is taken less TB_GAP_ALLOWANCE, which covers how far a point's separation may fall
/// below the distance of the shapes): it would find them apart again, and is not asked. Exact: the
/// step comes out bit for bit as with the narrow phase run (the empty manifold's normal is zero,
/// so the one it would have written is known). Box2D
/// v3 keeps its non-touching pairs under a fixed allowance instead (the speculative distance),
/// which lets a pair come within the margin unseen; Tumble's touching pairs have that kind of
/// bound (tbRecycleManifold), its pairs apart this exact one.
static bool tbStaysApart(const tbContact* contact, const tbBody* bodyA, const tbBody* bodyB, float margin)
{
	if ((contact->flags & tb_contactApart) == 0 || !(contact->apart.gap > margin))
	{
		return false;
	}
	tbTransform relative = tbInvMulWorldTransforms(bodyA->transform, bodyB->transform);
	return tbMovedLessThan(contact->apart.relative, relative, bodyA, bodyB, contact->apart.gap - margin);
}

/// The narrow phase found the pair apart: the empty manifold's normal cleared (the same whether
/// the narrow phase ran or tbStaysApart kept it) and, when the shapes are farther apart than the
/// margin, the base tbStaysApart reads.
static void tbStoreApartBase(tbContact* contact, const tbShape* a, const tbShape* b, const tbBody* bodyA,
							 const tbBody* bodyB, float margin)
{
	contact->manifold.normal = tbVec2_zero;
	// Not two polygons: their narrow phase finds most pairs apart from its separating axes alone,
	// for about what the gap (GJK) would cost, and it saved nothing on piles of polygons. Not a pair
	// closing faster than TB_AABB_MARGIN a step (margin − TB_SPECULATIVE_DISTANCE is its closing,
	// tbSpeculativeMargin): shapes whose fat boxes overlap are seldom farther apart than about that
	// margin, so such a pair would be asked again next step anyway (a wheel rolling along a chain).
	if ((contact->flags & tb_contactSensor) != 0 ||
		(a->geometry.type == tb_polygonShape && b->geometry.type == tb_polygonShape) ||
		!(margin - TB_SPECULATIVE_DISTANCE < TB_AABB_MARGIN))
	{
		return;
	}
	tbTransform relative = tbInvMulWorldTransforms(bodyA->transform, bodyB->transform);
	float gap = tbShapeGapBound(&a->geometry, &b->geometry, relative);
	if (gap > margin)
	{
		contact->apart.relative = relative;
		contact->apart.gap = gap;
		contact->flags |= tb_contactApart;
	}
}

/// The narrow phase proper: a new manifold from the shapes, anchors, impulses carried over by
/// feature id, and (for touching non-sensor contacts) the base for later recycling; or the empty
/// manifold of a pair known to be apart (tbStaysApart).
static uint32_t tbComputeManifold(const tbWorld* world, tbContact* contact, const tbShape* a, const tbShape* b,
								  const tbBody* bodyA, const tbBody* bodyB, float margin)
{
	tbNarrowPhaseMethod method = world->def.narrowPhase;
	contact->flags &= ~(uint32_t)tb_contactRecyclable;
	// Most contacts (fat boxes overlapping) are not touching. The tight boxes, current since the
	// last finalize, grown by the speculative margin, rule them out for a few comparisons.
	if (tbAABB_Overlaps(tbAABB_Fatten(a->aabb, margin), b->aabb) == false)
	{
		contact->manifold.pointCount = 0;
		return 0;
	}
	if (tbStaysApart(contact, bodyA, bodyB, margin))
	{
		return tb_collideKeptApart; // the manifold is empty, its normal zero (tbStoreApartBase)
	}
	contact->flags &= ~(uint32_t)tb_contactApart;
	tbManifold old = contact->manifold; // for warm starting (tbMatchPoints)
	tbPos points[2];
	tbCollideInWorld(&contact->manifold, &a->geometry, bodyA->transform, &b->geometry, bodyB->transform, method, margin,
					 points);
	uint32_t result = 0;
	if (a->geometry.type == tb_polygonShape && b->geometry.type == tb_polygonShape)
	{
		result = method == tb_narrowPhaseGJK ? tb_collideGJK : tb_collideSAT;
	}
	tbManifold* m = &contact->manifold;
	for (int i = 0; i < m->pointCount; ++i)
	{
		m->points[i].anchorA = tbSubPos(points[i], bodyA->center);
		m->points[i].anchorB = tbSubPos(points[i], bodyB->center);
	}
	if (world->def.enableWarmStarting)
	{
		tbMatchPoints(m, &old);
	}
	// What the narrow phase measured, kept while recycling moves `separation` with the bodies.
	for (int i = 0; i < m->pointCount; ++i)
	{
		m->points[i].baseSeparation = m->points[i].separation;
	}
	if (m->pointCount > 0 && (contact->flags & tb_contactSensor) == 0 && tbMayRecycleManifold(a, b, m))
	{
		tbStoreManifoldBase(contact, bodyA->transform, bodyB->transform, points, margin);
	}
	else if (m->pointCount == 0)
	{
		tbStoreApartBase(contact, a, b, bodyA, bodyB, margin);
	}
	return result;
}

/// The deepest two shapes can overlap (m): the diagonal of the smaller of their tight boxes.
static float tbDeepestOverlap(const tbShape* a, const tbShape* b)
{
	tbVec2 da = tbSub(a->aabb.upperBound, a->aabb.lowerBound);
	tbVec2 db = tbSub(b->aabb.upperBound, b->aabb.lowerBound);
	return tbMinFloat(tbLength(da), tbLength(db));
}

/// A point the pre-solve callback kept carries the impulses the solver accumulated for its feature:
/// the callback may move, drop or deepen points, not change what warm starting will apply.
static bool tbKeepsImpulses(const tbManifoldPoint* point, const tbManifold* before)
{
	for (int j = 0; j < before->pointCount; ++j)
	{
		const tbManifoldPoint* old = before->points + j;
		if (old->id == point->id)
		{
			return point->normalImpulse == old->normalImpulse && point->tangentImpulse == old->tangentImpulse &&
				   point->totalNormalImpulse == old->totalNormalImpulse && point->normalVelocity == old->normalVelocity &&
				   point->baseSeparation == old->baseSeparation;
		}
	}
	return false;
}

/// The user's pre-solve callback on a touching contact (tbPreSolveFcn). What it may do is bounded:
/// no more points than it was given, a finite unit normal, anchors within reach of their bodies
/// (a manifold point lies within the speculative margin of both shapes: an anchor farther than
/// twice that beyond the body's extent is none it could have), separations no deeper than the two
/// shapes could overlap (a deeper one would be an overlap the solver pushes out of at speeds no
/// contact can ask for), and the impulses of each point as the solver left them (warm starting
/// applies them at the anchors: a huge one overflows the velocities); anything else is reported
/// and the manifold restored. A manifold it changed is not recycled next step (the recycled one
/// would carry its change along instead of asking again).
static void tbCallPreSolve(tbWorld* world, tbContact* contact)
{
	tbManifold before = contact->manifold;
	tbManifold* m = &contact->manifold;
	world->preSolveFcn(tbMakeShapeId(world, contact->shapeIdA), tbMakeShapeId(world, contact->shapeIdB), m,
					   world->preSolveContext);
	bool valid = tbIsValidVec2(m->normal) && tbAbsFloat(tbLength(m->normal) - 1.0f) < 1e-3f &&
				 m->rollingImpulse == before.rollingImpulse;
	m->pointCount = tbMinInt(tbMaxInt(m->pointCount, 0), before.pointCount);
	const tbShape* a = world->shapes + contact->shapeIdA;
	const tbShape* b = world->shapes + contact->shapeIdB;
	const tbBody* bodyA = world->bodies + a->bodyId;
	const tbBody* bodyB = world->bodies + b->bodyId;
	float deepest = -tbDeepestOverlap(a, b);
	float margin = tbSpeculativeMargin(world, bodyA, bodyB);
	float reachA = bodyA->maxExtent + 2.0f * margin, reachB = bodyB->maxExtent + 2.0f * margin;
	for (int i = 0; i < m->pointCount; ++i)
	{
		const tbManifoldPoint* point = m->points + i;
		valid = valid && tbIsValidFloat(point->separation) && point->separation >= deepest &&
				tbIsValidVec2(point->anchorA) && tbIsValidVec2(point->anchorB) && tbLength(point->anchorA) <= reachA &&
				tbLength(point->anchorB) <= reachB && tbKeepsImpulses(point, &before);
	}
	if (valid == false)
	{
		tbReportError("tbPreSolveFcn",
					  "the callback left a non-finite or non-unit normal, an anchor that is not finite or beyond its "
					  "body's reach, a separation below %g m (deeper than the two shapes can overlap), or changed an "
					  "impulse; the manifold is restored (set pointCount to 0 to disable the contact)",
					  (double)deepest);
		*m = before;
		return;
	}
	if (memcmp(m, &before, sizeof(before)) != 0)
	{
		contact->flags &= ~(uint32_t)tb_contactRecyclable;
	}
}

/// For tests (tbWorld_EnableSpeculative(false), Box2D v3.2's switch): of two manifold points, one
/// more than 1.5 × TB_LINEAR_SLOP apart is dropped, so the solver sees no speculative second point.
/// The manifold then no longer matches its recycling base, which is forgotten.
static void tbDropSpeculativePoint(tbContact* contact)
{
	tbManifold* m = &contact->manifold;
	if (m->pointCount != 2)
	{
		return;
	}
	float apart = 1.5f * TB_LINEAR_SLOP;
	int drop = m->points[0].separation > apart ? 0 : (m->points[1].separation > apart ? 1 : -1);
	if (drop < 0)
	{
		return;
	}
	m->points[0] = m->points[1 - drop];
	m->pointCount = 1;
	contact->flags &= ~(uint32_t)tb_contactRecyclable;
}

/// The narrow phase of one contact, writing only the contact (safe on any worker): returns
/// tbCollideResult flags for the caller to act on in contact order.
static TB_FORCE_INLINE uint32_t tbCollideContact(tbWorld* world, tbContact* contact, const tbShape* a, const tbShape* b,
												  const tbBody* bodyA, const tbBody* bodyB)
{
	bool isSensor = (contact->flags & tb_contactSensor) != 0;
	// Sensors only ask whether the shapes overlap: the fixed distance is plenty.
	float margin = isSensor ? TB_SPECULATIVE_DISTANCE : tbSpeculativeMargin(world, bodyA, bodyB);
	uint32_t result = 0;
	if (world->def.enableManifoldRecycling && world->contactRecycleDistance > 0.0f &&
		tbRecycleManifold(contact, bodyA, bodyB, margin, world->contactRecycleDistance))
	{
		result |= tb_collideRecycled;
		contact->flags |= tb_contactRecycled;
	}
	else
	{
		result |= tbComputeManifold(world, contact, a, b, bodyA, bodyB, margin);
		contact->flags &= ~(uint32_t)tb_contactRecycled;
	}
	if ((contact->flags & tb_contactEnablePreSolve) != 0 && isSensor == false && world->preSolveFcn != NULL &&
		contact->manifold.pointCount > 0 && (bodyA->type == tb_dynamicBody || bodyB->type == tb_dynamicBody))
	{
		tbCallPreSolve(world, contact);
	}
	if (world->enableSpeculative == false && isSensor == false)
	{
		tbDropSpeculativePoint(contact);
	}
	const tbManifold* m = &contact->manifold;
	bool touching = isSensor ? tbIsSensorOverlap(m) : m->pointCount > 0;
	bool reported = isSensor ? touching : tbIsWithinSpeculativeDistance(m);
	bool wasTouching = (contact->flags & tb_contactTouching) != 0;
	bool wasReported = (contact->flags & tb_contactReported) != 0;
	contact->flags &= ~(uint32_t)(tb_contactTouching | tb_contactReported);
	contact->flags |= (touching ? (uint32_t)tb_contactTouching : 0u) | (reported ? (uint32_t)tb_contactReported : 0u);
	contact->touchingSteps = touching ? (uint16_t)(contact->touchingSteps + (contact->touchingSteps < UINT16_MAX)) : 0u;
	contact->hitSpeed = touching ? contact->hitSpeed : 0.0f; // an impact that never touched is dropped
	result |= touching && wasTouching == false ? tb_collideBegan : 0u;
	result |= touching == false && wasTouching ? tb_collideEnded : 0u;
	result |= reported != wasReported ? (reported ? tb_collideBeginEvent : tb_collideEndEvent) : 0u;
	return result;
}

/// tbCollideContact with the contact's shapes and bodies looked up (the callers outside the
/// collide walk, which has them at hand).
static uint32_t tbCollideContactOf(tbWorld* world, tbContact* contact)
{
	const tbShape* a = world->shapes + contact->shapeIdA;
	const tbShape* b = world->shapes + contact->shapeIdB;
	return tbCollideContact(world, contact, a, b, world->bodies + a->bodyId, world->bodies + b->bodyId);
}

/// Counters of one contact's narrow phase (on the caller, after the workers).
static void tbCountCollideResult(tbWorld* world, uint32_t result)
{
	world->counters.recycledContactCount += (result & tb_collideRecycled) != 0 ? 1 : 0;
	world->counters.keptApartCount += (result & tb_collideKeptApart) != 0 ? 1 : 0;
	world->counters.gjkManifolds += (result & tb_collideGJK) != 0 ? 1 : 0;
	world->counters.satManifolds += (result & tb_collideSAT) != 0 ? 1 : 0;
}


int tbUpdateContact(tbWorld* world, tbContact* contact, bool* beganTouching)
{
	uint32_t result = tbCollideContactOf(world, contact);
	tbCountCollideResult(world, result);
	*beganTouching = (result & tb_collideBegan) != 0;
	return (result & tb_collideBeginEvent) != 0 ? 1 : ((result & tb_collideEndEvent) != 0 ? -1 : 0);
}

static void tbPushSensorBeginEvent(tbWorld* world, int sensor, int visitor)
{
	if (world->shapes[sensor].isSensor && tbSensorEventsEnabled(world, sensor, visitor))
	{
		tbSensorBeginTouchEvent e = {tbMakeShapeId(world, sensor), tbMakeShapeId(world, visitor)};
		TB_ARRAY_PUSH(world->events.sensorBeginEvents, world->events.sensorBeginCount, world->events.sensorBeginCapacity, e);
	}
}

static void tbPushBeginEvent(tbWorld* world, const tbContact* contact)
{
	if (contact->flags & tb_contactSensor)
	{
		// Each sensor of the pair reports the other shape: two sensors overlapping see each other.
		tbPushSensorBeginEvent(world, contact->shapeIdA, contact->shapeIdB);
		tbPushSensorBeginEvent(world, contact->shapeIdB, contact->shapeIdA);
	}
	else if (contact->flags & tb_contactEnableEvents)
	{
		tbContactBeginTouchEvent e = {tbMakeShapeId(world, contact->shapeIdA), tbMakeShapeId(world, contact->shapeIdB),
									  tbMakeContactId(world, (int)(contact - world->contacts))};
		TB_ARRAY_PUSH(world->events.beginEvents, world->events.beginCount, world->events.beginCapacity, e);
	}
}

/// Gather each contact of an awake body once, in contact-id order: every later stage inherits
/// this order (solver order included), so it must not depend on how the contacts were found.
/// A mostly awake world scans the contact array (sequential memory, the fast case for a moving
/// pile); a mostly sleeping one walks the awake bodies' contact lists (cost proportional to the
/// awake part) and sorts the ids.
static void tbGatherAwakeContacts(tbWorld* world)
{
	world->cache.gatheredVersion = world->cache.awakeSetVersion;
	world->cache.gatheredRemovals = world->cache.awakeRemovals;
	world->cache.gatheredAwakeCount = world->awakeBodyCount;
	world->cache.stepContactCount = 0;
	if (2 * world->awakeBodyCount >= world->bodyPool.count)
	{
		// A byte per body says awake: the scan then reads the contacts in memory order and this
		// small array, instead of two scattered bodies per contact.
		TB_ARRAY_RESERVE(world->cache.stepContacts, world->cache.stepContactCapacity, world->contactPool.count + 1); // + 1: the walk writes one past
		// A free contact slot has both bodies TB_NULL_INDEX (−1): awake[−1] is a 0 kept for it.
		uint8_t* awake = (uint8_t*)tbArenaAlloc(&world->stepArena, world->bodyPool.highWater + 1) + 1;
		memset(awake - 1, 0, (size_t)world->bodyPool.highWater + 1);
		for (int i = 0; i < world->awakeBodyCount; ++i)
		{
			awake[world->awakeBodies[i]] = 1;
		}
		// Locals: through world-> each append reloaded and stored the count (the int stores may
		// alias the world's fields), a store-to-load chain through every contact, in a walk that
		// runs on one thread before the narrow phase's workers start.
		const tbBodyPair* bodies = world->cache.contactBodies;
		int* stepContacts = world->cache.stepContacts;
		int count = 0;
		int highWater = world->contactPool.highWater;
		for (int id = 0; id < highWater; ++id)
		{
			stepContacts[count] = id;
			count += (awake[bodies[id].bodyIdA] | awake[bodies[id].bodyIdB]) != 0 ? 1 : 0;
		}
		world->cache.stepContactCount = count;
		return;
	}
	uint32_t stamp = 2u * world->stepIndex;
	for (int i = 0; i < world->awakeBodyCount; ++i)
	{
		const tbBody* body = world->bodies + world->awakeBodies[i];
		for (int key = body->headContactKey; key != TB_NULL_INDEX;)
		{
			tbContact* contact = world->contacts + (key >> 1);
			if (contact->stamp != stamp)
			{
				contact->stamp = stamp;
				TB_ARRAY_PUSH(world->cache.stepContacts, world->cache.stepContactCount, world->cache.stepContactCapacity, key >> 1);
			}
			key = contact->edges[key & 1].nextKey;
		}
	}
	// islandStack is free scratch here: the island stage uses it later in the step.
	TB_ARRAY_RESERVE(world->cache.islandStack, world->cache.islandStackCapacity, world->cache.stepContactCount);
	tbSortIndices(world->cache.stepContacts, world->cache.stepContactCount, world->cache.islandStack);
}

/// A contact between bodies a and b that the island stage can hand to the solver without looking at
/// it again: one side is
/// dynamic and neither sleeps. Between here and the island stage bodies only wake, so it stays so;
/// and a body that wakes after this has none of these contacts (island.c relies on both).
static bool tbIsReadySolverContact(const tbBody* a, const tbBody* b)
{
	bool asleepA = a->type != tb_staticBody && a->awakeIndex == TB_NULL_INDEX;
	bool asleepB = b->type != tb_staticBody && b->awakeIndex == TB_NULL_INDEX;
	return (a->type == tb_dynamicBody || b->type == tb_dynamicBody) && asleepA == false && asleepB == false;
}

/// The solver key of a ready contact, from its bodies A and B as the narrow phase just read them
/// (tbCollideKey).
/// The flags are those contact_solver.c derives from the solver's mass arrays: a body moves when
/// it is dynamic with a positive inverse mass or (rotation not fixed) inverse inertia.
/// Returns whether the key is the one written in the last step.
static bool tbWriteCollideKey(tbWorld* world, int contactId, const tbContact* contact, const tbBody* a, const tbBody* b)
{
	bool dynamicA = a->type == tb_dynamicBody, dynamicB = b->type == tb_dynamicBody;
	bool movesA = a->solverMoves, movesB = b->solverMoves;
	uint32_t flags = (movesA ? (uint32_t)tb_keyMovesA : 0u) | (movesB ? (uint32_t)tb_keyMovesB : 0u) |
					 (dynamicA ? (uint32_t)tb_keyDynamicA : 0u) | (dynamicB ? (uint32_t)tb_keyDynamicB : 0u);
	flags |= tbContactMaterialKey(contact);
	tbCollideKey* written = world->cache.collideKeys + contactId;
	tbContactKey* key = &written->key;
	// The same key as written in the last step (a steady step can keep the solver's keys).
	bool same = written->step == world->stepIndex - 1u && key->indexA == a->awakeIndex &&
				key->indexB == b->awakeIndex && key->flags == flags;
	key->indexA = a->awakeIndex; // TB_NULL_INDEX for a static body; no side sleeps (ready)
	key->indexB = b->awakeIndex;
	key->flags = flags;
	written->step = world->stepIndex;
	return same;
}

/// Proxy slots (16 bytes each) beyond which the collide walk prefetches the proxies too: up to
/// here the table stays in cache between steps (the smaller piles: falling_1000, the ragdoll pile),
/// and the prefetches cost more than they save; beyond it (junkyard, smash, the washer) they pay.
#define TB_PREFETCH_PROXIES_MIN 4096

/// The collide walk's loads form a chain: the contact names its shapes and bodies, a shape names
/// its proxy. Each is a miss to memory in a large pile (contact ids, shapes and bodies are in no
/// common order), and the chain serialises them. So the walk prefetches in stages: the contact
/// 2·TB_PREFETCH_AHEAD items ahead, the shapes and bodies of the one TB_PREFETCH_AHEAD ahead (its
/// contact is in cache by then), and, in a large table (TB_PREFETCH_PROXIES_MIN), the proxies of
/// the one half as far ahead (its shapes are).
static TB_FORCE_INLINE void tbPrefetchCollideAhead(const tbWorld* world, int i, int endIndex, bool proxies)
{
	const int* ids = world->cache.stepContacts;
	if (i + 2 * TB_PREFETCH_AHEAD < endIndex)
	{
		tbPrefetch(world->contacts + ids[i + 2 * TB_PREFETCH_AHEAD], (int)sizeof(tbContact));
	}
	if (i + TB_PREFETCH_AHEAD < endIndex)
	{
		const tbContact* ahead = world->contacts + ids[i + TB_PREFETCH_AHEAD];
		// A contact recycled last step most often is again, and reads its shapes' first line only
		// (box, body, proxy); any other reads their geometry too, and nothing after it (prefetching
		// the whole 280-byte shape fetches lines nobody reads). Prefetching the geometry for every
		// contact would help scenes whose touching pairs move too far to be recycled and cost
		// scenes that recycle every pair (a pyramid), so the flags choose per contact.
		// A pair kept apart (tb_contactApart) most often stays apart, and reads the same first line.
		const uint32_t recycling = tb_contactRecyclable | tb_contactRecycled;
		bool firstLine = (ahead->flags & recycling) == recycling || (ahead->flags & tb_contactApart) != 0;
		int shapeBytes = firstLine ? 32 : (int)(offsetof(tbShape, geometry) + sizeof(tbGeometry));
		tbPrefetch(world->shapes + ahead->shapeIdA, shapeBytes);
		tbPrefetch(world->shapes + ahead->shapeIdB, shapeBytes);
		int bodyBytes = (int)offsetof(tbBody, solverMoves) + 1; // the hot group at the front (body.h)
		tbPrefetch(world->bodies + ahead->edges[0].bodyId, bodyBytes);
		tbPrefetch(world->bodies + ahead->edges[1].bodyId, bodyBytes);
	}
	if (proxies && i + TB_PREFETCH_AHEAD / 2 < endIndex)
	{
		const tbContact* ahead = world->contacts + ids[i + TB_PREFETCH_AHEAD / 2];
		const tbBroadProxy* table = world->broadPhase.table.proxies;
		tbPrefetch(table + world->shapes[ahead->shapeIdA].proxyKey, 16);
		tbPrefetch(table + world->shapes[ahead->shapeIdB].proxyKey, 16);
	}
}

/// Collide task: the narrow phase of stepContacts[start..end), results into world->cache.collideResults
/// and sums into the worker's tally.
static void tbCollideTask(int startIndex, int endIndex, uint32_t workerIndex, void* context)
{
	tbWorld* world = context;
	const tbBroadPhase* bp = &world->broadPhase;
	uint16_t* results = world->cache.collideResults;
	bool prefetchProxies = bp->table.capacity > TB_PREFETCH_PROXIES_MIN;
	for (int i = startIndex; i < endIndex; ++i)
	{
		int contactId = world->cache.stepContacts[i];
		tbContact* contact = world->contacts + contactId;
		tbPrefetchCollideAhead(world, i, endIndex, prefetchProxies);
		const tbShape* a = world->shapes + contact->shapeIdA;
		const tbShape* b = world->shapes + contact->shapeIdB;
		bool overlap = tbBroadPhase_TestOverlap(bp, a->proxyKey, b->proxyKey);
		uint32_t result = tb_collideDestroy;
		if (overlap && (contact->flags & tb_contactSensor) != 0)
		{
			// A sensor's overlap is decided from the poses this step makes (tbSensorStage); here
			// only whether the pair lives on.
			result = (contact->flags & tb_contactReported) != 0 ? (uint32_t)tb_collideReported : 0u;
		}
		else if (overlap)
		{
			// The flags the caller's serial walk needs ride along, so it need not load the contact.
			const tbBody* bodyA = world->bodies + a->bodyId;
			const tbBody* bodyB = world->bodies + b->bodyId;
			result = tbCollideContact(world, contact, a, b, bodyA, bodyB);
			bool solver = (contact->flags & (tb_contactTouching | tb_contactSensor)) == tb_contactTouching;
			result |= solver ? (uint32_t)tb_collideSolver : 0u;
			result |= (contact->flags & tb_contactReported) != 0 ? (uint32_t)tb_collideReported : 0u;
			if (solver && tbIsReadySolverContact(bodyA, bodyB))
			{
				result |= tb_collideReady;
				result |= tbWriteCollideKey(world, contactId, contact, bodyA, bodyB) ? 0u : (uint32_t)tb_collideNewKey;
			}
		}
		results[i] = (uint16_t)result;
	}
	tbTallyResults(results + startIndex, endIndex - startIndex, world->cache.collideTallies + workerIndex);
}

/// The broad phase's deferred tree refresh (tbUpdatePairsStage), beside the narrow phase: it
/// touches only the movable tree, which the narrow phase does not read.
static void tbFinishTreeRefresh(void* broadPhase)
{
	tbBroadPhase_FinishRefresh(broadPhase);
}

/// The collide results in contact order, on the caller: contacts whose fat boxes parted are
/// destroyed, touching ones listed (world->cache.touchingContacts), bodies woken, events appended.
static void tbWalkCollideResults(tbWorld* world)
{
	int kept = 0;
	// Every kept contact may touch: room for all of them, so the walk appends without checks.
	TB_ARRAY_RESERVE(world->cache.touchingContacts, world->cache.touchingContactCapacity, world->cache.stepContactCount);
	int* touching = world->cache.touchingContacts;
	int touchingCount = 0;
	bool allReady = true;
	int* stepContacts = world->cache.stepContacts; // locals: the stores below may alias the world's fields
	const uint16_t* results = world->cache.collideResults;
	int stepContactCount = world->cache.stepContactCount;
	for (int i = 0; i < stepContactCount; ++i)
	{
		int contactId = stepContacts[i];
		uint32_t result = results[i];
		if (result & tb_collideDestroy)
		{
			tbDestroyContact(world, contactId, false);
			continue;
		}
		stepContacts[kept++] = contactId;
		if (result & tb_collideSolver)
		{
			// The sign says "ready" (tb_collideReady): the island stage takes it as it is.
			bool ready = (result & tb_collideReady) != 0;
			touching[touchingCount++] = ready ? contactId : -1 - contactId;
			allReady = allReady && ready;
		}
		if ((result & (tb_collideBegan | tb_collideBeginEvent | tb_collideEndEvent)) == 0)
		{
			continue; // most contacts: nothing changed, and the contact itself is not loaded
		}
		tbContact* contact = world->contacts + contactId;
		if (result & tb_collideBegan)
		{
			// New manifold points (speculative ones too) wake both bodies: the sleeping one joins
			// the awake island, so the solver never sees a contact with a sleeping body.
			tbWakeBody(world, world->bodies + world->shapes[contact->shapeIdA].bodyId);
			tbWakeBody(world, world->bodies + world->shapes[contact->shapeIdB].bodyId);
		}
		if (result & tb_collideBeginEvent)
		{
			tbPushBeginEvent(world, contact);
		}
		else if (result & tb_collideEndEvent)
		{
			tbPushEndEvent(world, contact);
		}
	}
	world->cache.stepContactCount = kept;
	world->cache.touchingContactCount = touchingCount;
	world->cache.touchingAllReady = allReady;
	world->cache.touchingEpoch = world->cache.contactEpoch; // after this walk's destroys
}

/// The narrow phase over every awake contact, on the workers; then, on the caller and in contact
/// order, what changes the world (tbWalkCollideResults), unless nothing did: a settled pile's step
/// keeps the last touching list, and the solver its keys (contact_solver.c). The result is the
/// same for any number of workers.
void tbCollideStage(tbWorld* world)
{
	// The awake contacts are those gathered last, less the ones the walk destroyed, if neither the
	// awake set nor the set of contacts has changed since (touchingEpoch: the contact set after the
	// last walk). The last touching list still holds too if every contact on it was ready and no
	// contact changes below (tbCollideTally).
	bool sameList = world->cache.gatheredVersion == world->cache.awakeSetVersion && world->cache.gatheredRemovals == world->cache.awakeRemovals &&
					world->cache.touchingEpoch == world->cache.contactEpoch;
	bool sameContacts = sameList && world->cache.touchingAllReady;
	if (sameList == false)
	{
		tbGatherAwakeContacts(world);
	}
	TB_ARRAY_RESERVE(world->cache.collideResults, world->cache.collideResultCapacity, world->cache.stepContactCount);
	// Keys for every contact slot in use; new entries start stale, two steps back, so that neither
	// the key pass (this step) nor tbWriteCollideKey's comparison (the last step) takes an unwritten
	// key for a written one.
	TB_ARRAY_RESERVE(world->cache.collideKeys, world->cache.collideKeyCapacity, world->contactPool.highWater);
	for (; world->cache.collideKeyCount < world->contactPool.highWater; ++world->cache.collideKeyCount)
	{
		world->cache.collideKeys[world->cache.collideKeyCount].step = world->stepIndex - 2u;
	}
	int slots = tbWorkerSlotCount(&world->def);
	char* tallyBytes = tbArenaAlloc(&world->stepArena, (slots + 1) * (int)sizeof(tbCollideTally));
	world->cache.collideTallies = (tbCollideTally*)(((uintptr_t)tallyBytes + 63) & ~(uintptr_t)63);
	memset(world->cache.collideTallies, 0, (size_t)slots * sizeof(tbCollideTally));
	if (tbBroadPhase_RefreshPending(&world->broadPhase))
	{
		tbParallelForAlongside(&world->def, tbCollideTask, world->cache.stepContactCount, 64, world, tbFinishTreeRefresh,
							   &world->broadPhase);
	}
	else
	{
		tbParallelFor(&world->def, tbCollideTask, world->cache.stepContactCount, 64, world);
	}
	tbCollideTally total = {0};
	for (int w = 0; w < slots; ++w)
	{
		tbAddTally(&total, world->cache.collideTallies + w);
	}
	world->cache.collideTallies = NULL; // arena memory: gone with the step
	world->counters.recycledContactCount += total.recycled;
	world->counters.keptApartCount += total.keptApart;
	world->counters.gjkManifolds += total.gjk;
	world->counters.satManifolds += total.sat;
	world->counters.touchingCount = total.reported;
	// A steady step (a settled pile): nothing was destroyed, began or ended touching or made an
	// event, and every solver contact is ready, so the walk would write the last list again.
	world->cache.touchingUnchanged = sameContacts && total.changed == 0 && total.notReady == 0;
	world->cache.collideKeysUnchanged = world->cache.touchingUnchanged && total.newKeys == 0;
	if (world->cache.touchingUnchanged == false)
	{
		tbWalkCollideResults(world);
	}
}

/// Sensor events by sensor shape, then visitor shape (slot indices: unique among live shapes).
static int tbCompareSensorEvents(const void* a, const void* b)
{
	const tbSensorBeginTouchEvent* x = a;
	const tbSensorBeginTouchEvent* y = b;
	if (x->sensorShapeId.index1 != y->sensorShapeId.index1)
	{
		return x->sensorShapeId.index1 < y->sensorShapeId.index1 ? -1 : 1;
	}
	return x->visitorShapeId.index1 < y->visitorShapeId.index1 ? -1 : (x->visitorShapeId.index1 > y->visitorShapeId.index1);
}

/// Hit events: one per impact, in the step its contact begins to touch or later. A solved contact
/// whose point approached faster than the world's threshold and took a normal impulse holds that
/// impact (the fastest seen, kept in contact->hitSpeed); it is reported once the contact is within
/// the fixed distance that makes begin events (tb_contactReported), so a landing met by a
/// speculative point a step early is reported with its begin event, not before it and not twice.
/// An impact on a contact that separates before touching is dropped (tbUpdateContact).
void tbReportHitEvents(tbWorld* world)
{
	if (world->hitContactCount == 0)
	{
		return; // no contact wants hit events (the common case): no walk over every touching contact
	}
	float threshold = world->def.hitEventThreshold;
	// Contact-id order: the walk streams through contact memory (the solve order would not).
	for (int i = 0; i < world->cache.solverContactCount; ++i)
	{
		int contactIndex = world->cache.solverContactsById[i];
		tbContact* contact = world->contacts + contactIndex;
		if ((contact->flags & tb_contactEnableHits) == 0)
		{
			continue;
		}
		for (int j = 0; j < contact->manifold.pointCount; ++j)
		{
			const tbManifoldPoint* mp = contact->manifold.points + j;
			float approach = -mp->normalVelocity;
			if (approach > threshold && approach > contact->hitSpeed && mp->totalNormalImpulse > 0.0f)
			{
				contact->hitSpeed = approach;
				contact->hitPoint = mp->point;
			}
		}
		if (contact->hitSpeed > 0.0f && (contact->flags & tb_contactReported) != 0)
		{
			tbContactHitEvent event;
			event.shapeIdA = tbMakeShapeId(world, contact->shapeIdA);
			event.shapeIdB = tbMakeShapeId(world, contact->shapeIdB);
			event.contactId = tbMakeContactId(world, contactIndex);
			event.point = tbToPos(contact->hitPoint);
			event.normal = contact->manifold.normal;
			event.approachSpeed = contact->hitSpeed;
			contact->hitSpeed = 0.0f;
			TB_ARRAY_PUSH(world->events.hitEvents, world->events.hitCount, world->events.hitCapacity, event);
		}
	}
}

/// Sensor events in the step their overlap changes (Box2D v3.2 reports them "without delay"):
/// the collide stage runs on the poses the last step left, so a sensor judged there would see an
/// overlap one step after the step that made it. Here, after the poses are final, each sensor
/// contact of the step is collided again and its begin or end event pushed. A sensor never wakes
/// a body (v3.2's rule too). The step's sensor events are put in (sensor, visitor) order, so that
/// they do not depend on contact ids, which differ between engines and after a snapshot.
/// The pairs whose sensor a fast shape crossed this step (continuous.c) overlap for this step, as
/// Box2D v3.2 counts them: a begin event unless already overlapping. Whether they still do is left
/// to the next step, which ends them unless the shapes overlap then (or destroys the contact with
/// its end event when the boxes have parted). A contact made for a hit is not among the step's
/// gathered contacts, so the hits are walked apart; the walk over the gathered ones skips them.
static void tbReportSensorHits(tbWorld* world)
{
	for (int i = 0; i < world->cache.sensorHitCount; ++i)
	{
		tbContact* contact = world->contacts + world->cache.sensorHitContacts[i];
		bool wasReported = (contact->flags & tb_contactReported) != 0;
		tbCountCollideResult(world, tbCollideContactOf(world, contact)); // the manifold of the final poses
		contact->flags |= tb_contactTouching | tb_contactReported;
		if (wasReported == false)
		{
			tbPushBeginEvent(world, contact);
		}
	}
}

void tbSensorStage(tbWorld* world)
{
	if (world->sensorContactCount == 0)
	{
		return; // no sensor in contact with anything: nothing to walk
	}
	int beginFirst = world->events.sensorBeginCount;
	int endFirst = world->events.sensorEndCount;
	tbReportSensorHits(world);
	const int* ids = world->cache.stepContacts;
	for (int i = 0; i < world->cache.stepContactCount; ++i)
	{
		tbContact* contact = world->contacts + ids[i];
		if ((contact->flags & (tb_contactSensor | tb_contactSensorHit)) != tb_contactSensor)
		{
			continue; // not a sensor, or a hit reported above
		}
		uint32_t result = tbCollideContactOf(world, contact);
		tbCountCollideResult(world, result);
		if (result & tb_collideBeginEvent)
		{
			tbPushBeginEvent(world, contact);
		}
		else if (result & tb_collideEndEvent)
		{
			tbPushEndEvent(world, contact);
		}
	}
	for (int i = 0; i < world->cache.sensorHitCount; ++i)
	{
		world->contacts[world->cache.sensorHitContacts[i]].flags &= ~(uint32_t)tb_contactSensorHit;
	}
	world->cache.sensorHitCount = 0;
	// Begin and end events share their layout (two shape ids): one comparator serves both.
	_Static_assert(sizeof(tbSensorBeginTouchEvent) == sizeof(tbSensorEndTouchEvent), "sensor events differ in layout");
	// Sorted only when there are two or more: an array never pushed to is NULL.
	if (world->events.sensorBeginCount - beginFirst > 1)
	{
		qsort(world->events.sensorBeginEvents + beginFirst, (size_t)(world->events.sensorBeginCount - beginFirst),
			  sizeof(tbSensorBeginTouchEvent), tbCompareSensorEvents);
	}
	if (world->events.sensorEndCount - endFirst > 1)
	{
		qsort(world->events.sensorEndEvents + endFirst, (size_t)(world->events.sensorEndCount - endFirst),
			  sizeof(tbSensorEndTouchEvent), tbCompareSensorEvents);
	}
}

// ---------------------------------------------------------------------------------------------
// Contact data (the public queries of what touches what)

tbContactId tbMakeContactId(const tbWorld* world, int contactId)
{
	tbContactId id = {contactId + 1, (uint16_t)(world->worldId), 0, world->contacts[contactId].generation};
	return id;
}

/// Touching, not a sensor overlap: what GetContactData reports (the touchingCount's contacts).
static bool tbIsReportedContact(const tbContact* contact)
{
	return (contact->flags & (tb_contactReported | tb_contactSensor)) == tb_contactReported;
}

static tbContactData tbMakeContactData(const tbWorld* world, int contactId)
{
	const tbContact* contact = world->contacts + contactId;
	tbContactData data;
	data.contactId = tbMakeContactId(world, contactId);
	data.shapeIdA = tbMakeShapeId(world, contact->shapeIdA);
	data.shapeIdB = tbMakeShapeId(world, contact->shapeIdB);
	data.manifold = contact->manifold;
	return data;
}

/// The reported contacts of a body, or of one of its shapes (shapeId ≥ 0), or a sensor shape's
/// visitors (sensors), from the body's contact list, written in contact-id order (the list's own
/// order depends on history): the ids are gathered, insertion-sorted (a body touches few), then
/// written up to capacity.
static int tbCollectContacts(const tbWorld* world, const tbBody* body, int shapeId, bool sensors,
							 tbContactData* data, tbShapeId* visitors, int capacity)
{
	int count = 0;
	for (int key = body->headContactKey; key != TB_NULL_INDEX && count < capacity;)
	{
		int id = key >> 1;
		const tbContact* contact = world->contacts + id;
		key = contact->edges[key & 1].nextKey;
		if (shapeId >= 0 && contact->shapeIdA != shapeId && contact->shapeIdB != shapeId)
		{
			continue;
		}
		bool wanted = sensors ? (contact->flags & (tb_contactSensor | tb_contactReported)) ==
									(tb_contactSensor | tb_contactReported)
							  : tbIsReportedContact(contact);
		if (wanted == false)
		{
			continue;
		}
		int visitorId = contact->shapeIdA == shapeId ? contact->shapeIdB : contact->shapeIdA;
		if (sensors && tbSensorEventsEnabled(world, shapeId, visitorId) == false)
		{
			continue; // a sensor lists the visitors it reports (Box2D v3.2: both shapes enable sensor events)
		}
		int i = count++;
		if (sensors)
		{
			tbShapeId visitor = tbMakeShapeId(world, visitorId);
			for (; i > 0 && visitors[i - 1].index1 > visitor.index1; --i)
			{
				visitors[i] = visitors[i - 1];
			}
			visitors[i] = visitor;
		}
		else
		{
			tbContactData entry = tbMakeContactData(world, id);
			for (; i > 0 && data[i - 1].contactId.index1 > entry.contactId.index1; --i)
			{
				data[i] = data[i - 1];
			}
			data[i] = entry;
		}
	}
	return count;
}

// An output array the caller passes with its capacity: capacity ≥ 0, and an array when it is > 0.
static bool tbCheckOutputArray(const char* f, const void* array, int capacity)
{
	if (capacity < 0 || (capacity > 0 && array == NULL))
	{
		tbReportError(f, "capacity is %d with %s array; pass an array of at least capacity entries", capacity,
					  array == NULL ? "a NULL" : "an");
		return false;
	}
	return true;
}

int tbBody_GetContactCapacity(tbBodyId bodyId)
{
	tbBody* body = tbGetBodyChecked(bodyId, "tbBody_GetContactCapacity", NULL, false);
	return body != NULL ? body->contactCount : 0;
}

int tbBody_GetContactData(tbBodyId bodyId, tbContactData* contactData, int capacity)
{
	const char* f = "tbBody_GetContactData";
	tbWorld* world;
	tbBody* body = tbGetBodyChecked(bodyId, f, &world, false);
	if (body == NULL || tbCheckOutputArray(f, contactData, capacity) == false)
	{
		return 0;
	}
	return tbCollectContacts(world, body, -1, false, contactData, NULL, capacity);
}

int tbShape_GetContactCapacity(tbShapeId shapeId)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetContactCapacity", &world, false);
	return shape != NULL && shape->isSensor == false ? world->bodies[shape->bodyId].contactCount : 0;
}

int tbShape_GetContactData(tbShapeId shapeId, tbContactData* contactData, int capacity)
{
	const char* f = "tbShape_GetContactData";
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, f, &world, false);
	if (shape == NULL || tbCheckOutputArray(f, contactData, capacity) == false || shape->isSensor)
	{
		return 0;
	}
	return tbCollectContacts(world, world->bodies + shape->bodyId, shapeId.index1 - 1, false, contactData, NULL,
							 capacity);
}

int tbShape_GetSensorCapacity(tbShapeId shapeId)
{
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, "tbShape_GetSensorCapacity", &world, false);
	return shape != NULL && shape->isSensor ? world->bodies[shape->bodyId].contactCount : 0;
}

int tbShape_GetSensorData(tbShapeId shapeId, tbShapeId* visitorIds, int capacity)
{
	const char* f = "tbShape_GetSensorData";
	tbWorld* world;
	tbShape* shape = tbGetShapeChecked(shapeId, f, &world, false);
	if (shape == NULL || tbCheckOutputArray(f, visitorIds, capacity) == false || shape->isSensor == false)
	{
		return 0;
	}
	return tbCollectContacts(world, world->bodies + shape->bodyId, shapeId.index1 - 1, true, NULL, visitorIds,
							 capacity);
}

static tbWorld* tbGetContactWorld(tbContactId id, int* contactOut)
{
	if (id.index1 <= 0 || id.world0 >= TB_MAX_WORLDS)
	{
		return NULL;
	}
	tbWorld* world = tbGetWorldFromIndex(id.world0);
	int index = id.index1 - 1;
	if (world == NULL || index >= world->contactPool.highWater || world->contacts[index].inUse == false ||
		world->contacts[index].generation != id.generation)
	{
		return NULL;
	}
	*contactOut = index;
	return world;
}

bool tbContact_IsValid(tbContactId contactId)
{
	int index;
	return tbGetContactWorld(contactId, &index) != NULL;
}

tbContactData tbContact_GetData(tbContactId contactId)
{
	int index;
	tbWorld* world = tbGetContactWorld(contactId, &index);
	if (world == NULL)
	{
		tbReportError("tbContact_GetData", "contactId refers to a destroyed contact or world; contacts end when "
										   "their shapes' boxes part (check with tbContact_IsValid)");
		tbContactData none;
		memset(&none, 0, sizeof(none));
		return none;
	}
	return tbMakeContactData(world, index);
}

// ---------------------------------------------------------------------------------------------
// Event flags changed at run time

/// The hit-event flag a contact takes from its shapes, read again when a shape's changes.
static void tbRefreshContactHitFlag(tbWorld* world, tbContact* contact)
{
	const tbShape* a = world->shapes + contact->shapeIdA;
	const tbShape* b = world->shapes + contact->shapeIdB;
	world->hitContactCount -= (contact->flags & tb_contactEnableHits) != 0 ? 1 : 0;
	contact->flags &= ~(uint32_t)tb_contactEnableHits;
	contact->flags |= a->enableHitEvents || b->enableHitEvents ? (uint32_t)tb_contactEnableHits : 0u;
	world->hitContactCount += (contact->flags & tb_contactEnableHits) != 0 ? 1 : 0;
}

/// Box2D v3.2's rules for a flag changed at run time: contact and pre-solve events are decided
/// when a contact is made (tbCreateContact), so a contact that began reporting also reports its
/// end, and one made before pre-solve was enabled is not passed to the callback; sensor events are
/// read whenever overlaps are judged; hit events when an impact is reported, so the contacts of
/// the shape take the new hit flag now.
void tbSetShapeEventFlag(tbWorld* world, tbShape* shape, tbShapeEventKind kind, bool flag)
{
	switch (kind)
	{
		case tb_shapeEventContacts:
			shape->enableContactEvents = flag; // contacts made from now on
			return;
		case tb_shapeEventHits:
			shape->enableHitEvents = flag;
			break;
		case tb_shapeEventPreSolve:
			shape->enablePreSolveEvents = flag; // contacts made from now on
			return;
		default:
			shape->enableSensorEvents = flag; // read when events are made: no contact holds it
			return;
	}
	int shapeId = (int)(shape - world->shapes);
	const tbBody* body = world->bodies + shape->bodyId;
	for (int key = body->headContactKey; key != TB_NULL_INDEX;)
	{
		tbContact* contact = world->contacts + (key >> 1);
		key = contact->edges[key & 1].nextKey;
		if (contact->shapeIdA == shapeId || contact->shapeIdB == shapeId)
		{
			tbRefreshContactHitFlag(world, contact);
		}
	}
}
