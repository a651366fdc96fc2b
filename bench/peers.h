// Peer engines for tumble-bench: adapters that build the same catalogue Scene in another engine,
// step it and read it back, so Tumble and its peers are timed one after another in one process.
//
// Each adapter is compiled only when its engine is found (bench/peers.cmake defines
// TUMBLE_HAVE_BOX2D / TUMBLE_HAVE_BOX2D3 / TUMBLE_HAVE_CHIPMUNK). Body indices are scene body
// indices. Every adapter drives the scene's scripted bodies (SceneDrive) before each step with the
// velocity that reaches the step's target, as SceneWorld_Step does for Tumble.
//
// Spawn schedules (SceneSpawner: Box2D v3's exact rain) are run by the Box2D v3 adapter as
// SceneWorld_Step runs them, inside the timed step; Box2D 2.4.1 and Chipmunk refuse such a scene
// with a message (the rain's humans need revolute springs, which neither maps). Body indices
// (GetBody, poses) cover the scene's own bodies, not the spawned ones.
#pragma once

#include "scene.h"

#include <stdbool.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct PeerWorld PeerWorld;

/// For the adapters that do not run spawn schedules (Box2D 2.4.1, Chipmunk): false for a scene
/// without one; else says on stderr, naming the engine, the template and whether its revolute
/// joints carry springs (`springNote` says what the engine lacks), and returns true: the scene is
/// not run. The one such scene, v3's exact rain, needs those springs (a stiff spring or none would
/// be another scene).
static inline bool Peer_RefuseSpawnSchedule(const Scene* scene, const char* engine, const char* springNote)
{
	if (scene->spawnerCount == 0)
	{
		return false;
	}
	bool springs = false;
	for (int t = 0; t < scene->templateCount; ++t)
	{
		const Scene* parts = scene->templates[t].parts;
		for (int j = 0; j < parts->jointCount; ++j)
		{
			const SceneJoint* joint = parts->joints + j;
			springs = springs || (joint->type == tb_revoluteJoint && joint->def.revolute.enableSpring);
		}
	}
	fprintf(stderr,
			"%s: the scene spawns and recycles bodies over time (template \"%s\"), which this adapter does not "
			"build%s%s; scene not run\n",
			engine, scene->templates[scene->spawners[0].templateIndex].name,
			springs ? ", and its revolute joints have springs, " : "", springs ? springNote : "");
	return true;
}

/// Milliseconds of one step by stage, in Tumble's stage names (tumble-bench profile). Box2D v3's
/// own profile maps as: setup = solverSetup; solve = constraints (prepare, sub-steps, restitution,
/// store); finalize = transforms + refit; continuous = bullets (v3 sweeps non-bullet fast bodies
/// inside its transforms); events = hitEvents + jointEvents + sensorHits + sensors; sleep =
/// splitIslands + sleepIslands. The parts of the solve are each engine's own, by the same names
/// (tbProfile took v3's); a part an engine does not have is NaN (v3 gathers and scatters no
/// solver bodies: its set-up is the set-up row, its transforms are in finalize).
typedef struct StageProfile
{
	float pairs, collide, setup, solve, finalize, continuous, events, sleep, step;
	float solverSetup, prepareConstraints, integrateVelocities, warmStart, solveImpulses, integratePositions,
		relaxImpulses, applyRestitution, storeImpulses, scatterBodies;
} StageProfile;

/// State of one body read back from a peer: origin position, rotation, velocity of the centre of mass.
typedef struct PeerBody
{
	tbVec2 position;
	tbRot rotation;
	tbVec2 linearVelocity;
	float angularVelocity;
} PeerBody;

/// Counts comparable with tbCounters: bodies, contacts (pairs whose boxes overlap), awake non-static bodies.
typedef struct PeerCounters
{
	int bodyCount;
	int contactCount;
	int awakeBodyCount;
} PeerCounters;

/// Joints: Box2D v3 builds every kind one to one; Box2D 2.4.1 builds revolute, prismatic and wheel
/// joints, distance joints and welds with its own (no revolute or prismatic spring, no motor or
/// filter joint: such a scene is refused, the adapter returns NULL with a message); Chipmunk builds
/// revolute joints (pivot, rotary limit, simple motor) and refuses the rest. Negative collision
/// groups map to each engine's group; category and mask bits to each engine's (Box2D 2.4.1 has 16
/// bits, Chipmunk 32 here: the low ones).
///
/// Box2D 2.4.1: 8 velocity and 3 position iterations, continuous collision on (its default).
/// Polygons carry Box2D's fixed 0.01 m skin (b2_polygonRadius); rounded polygons are inflated
/// by their radius (mitred corners); capsules become two circles and a box on one body.
PeerWorld* PeerBox2D_Create(const Scene* scene);
void PeerBox2D_Step(PeerWorld* world);
PeerBody PeerBox2D_GetBody(PeerWorld* world, int bodyIndex);
PeerCounters PeerBox2D_GetCounters(PeerWorld* world);
void PeerBox2D_Destroy(PeerWorld* world);

/// Box2D v3 (3.2, C): the settings of v3's own benchmark program: one worker and no task system
/// (single-threaded), the scene's sub-steps (4 in every catalogue scene, as v3's benchmark) at the
/// scene's 60 Hz, continuous collision on, its defaults otherwise (soft contacts, 0.005 m linear slop,
/// sleep after 0.5 s below the body's sleep threshold, 0.05 m/s by default). Shapes map one to
/// one (v3 has capsules and rounded polygons; polygons are copied as they are). Driven bodies use
/// b2Body_SetTargetTransform. Spawned instances are built and destroyed as Tumble's are.
PeerWorld* PeerBox2D3_Create(const Scene* scene);
/// Workers of the worlds created from now on (default 1; more use v3's own scheduler).
void PeerBox2D3_SetWorkerCount(int workerCount);
void PeerBox2D3_Step(PeerWorld* world);
PeerBody PeerBox2D3_GetBody(PeerWorld* world, int bodyIndex);
PeerCounters PeerBox2D3_GetCounters(PeerWorld* world);
StageProfile PeerBox2D3_GetProfile(PeerWorld* world);
void PeerBox2D3_Destroy(PeerWorld* world);
/// Sub-steps of this world from now on (the solver chart's cost-against-error points; 0 keeps the scene's).
void PeerBox2D3_SetSubSteps(PeerWorld* world, int subSteps);

// Box2D v3's collision layer alone, for the charts that time Tumble's routines on the same inputs
// (tumble-bench narrowphase-chart and toi-chart, tumble-bench-broadphase). Each set of inputs is
// converted to v3's types once, outside the clock; a pass runs v3's own function over every item
// and returns a sum of its results, so that the caller times the pass and nothing is optimised away.

/// A manifold read back in world terms: the normal from A to B and the deepest penetration
/// (m, > 0 when the cores overlap), as the narrow-phase chart measures Tumble's.
typedef struct PeerManifold
{
	tbVec2 normal;
	float depth;
	int pointCount;
} PeerManifold;

typedef struct PeerPolygonPairs PeerPolygonPairs;
/// `count` polygon pairs (A's polygon and pose, B's) for b2CollidePolygons.
PeerPolygonPairs* PeerBox2D3_CreatePolygonPairs(const tbPolygon* a, const tbTransform* xfA, const tbPolygon* b,
												const tbTransform* xfB, int count);
/// Pair i's manifold, in the world frame.
PeerManifold PeerBox2D3_CollidePolygonPair(const PeerPolygonPairs* pairs, int i);
/// Every pair once, as a world collides one: B's pose in A's frame, b2CollidePolygons, the normal
/// turned into the world. Returns the sum of the normals' x.
float PeerBox2D3_CollidePolygonPass(const PeerPolygonPairs* pairs);
void PeerBox2D3_DestroyPolygonPairs(PeerPolygonPairs* pairs);

typedef struct PeerTOICases PeerTOICases;
/// `count` time-of-impact queries: two proxies (points and radius) and two sweeps each.
PeerTOICases* PeerBox2D3_CreateTOICases(const tbShapeProxy* a, const tbSweep* sweepA, const tbShapeProxy* b,
										const tbSweep* sweepB, int count);
/// Every query once with b2TimeOfImpact (maximum fraction 1): writes each one's fraction and
/// whether it hit (fractions and hits may be NULL). Returns the sum of the fractions.
float PeerBox2D3_TimeOfImpactPass(const PeerTOICases* cases, float* fractions, bool* hits);
/// The surface separation v3's time of impact stops at for these two radii: its target is the
/// core distance max(slop, rA + rB − slop), so circles end overlapping by the slop and polygons
/// without radius end the slop apart.
float PeerBox2D3_TOITargetSeparation(float radiusA, float radiusB);
void PeerBox2D3_DestroyTOICases(PeerTOICases* cases);

/// v3's broad phase without a world: its b2DynamicTree of fat boxes kept the way a v3 world keeps
/// its tree of moving proxies. A proxy whose box is re-made is enlarged in place and remembered
/// as moved; the pair update queries the tree with every moved proxy's box (a pair of two moved
/// proxies found once, from the higher id, as v3 does), then rebuilds the enlarged part of the
/// tree (b2DynamicTree_Rebuild, not a full build), as v3's step does beside its narrow phase.
typedef struct PeerTree PeerTree;
PeerTree* PeerBox2D3_CreateTree(int proxyCapacity);
int PeerBox2D3_TreeCreateProxy(PeerTree* tree, tbAABB fatAABB);
void PeerBox2D3_TreeMoveProxy(PeerTree* tree, int proxyId, tbAABB fatAABB);
/// Returns the number of pairs found (every overlapping pair with a moved member, once).
int PeerBox2D3_TreeUpdatePairs(PeerTree* tree);
void PeerBox2D3_DestroyTree(PeerTree* tree);

/// Chipmunk 7: 10 iterations, collision slop 0.01 m (its default 0.1 m is ten box skins),
/// spatial hash by default (cell = median dynamic shape size) or the BBTree (useTree),
/// sleep time threshold 0.5 s when the scene allows sleep. Chipmunk multiplies friction and
/// restitution where Tumble takes sqrt(a·b) and max(a, b): the adapter passes sqrt of each value,
/// which reproduces friction mixing exactly and restitution whenever both sides agree.
/// Capsules are rounded segments, rounded polygons keep their radius; no per-body damping or gravity scale.
PeerWorld* PeerChipmunk_Create(const Scene* scene, bool useTree);
void PeerChipmunk_Step(PeerWorld* world);
PeerBody PeerChipmunk_GetBody(PeerWorld* world, int bodyIndex);
PeerCounters PeerChipmunk_GetCounters(PeerWorld* world);
void PeerChipmunk_Destroy(PeerWorld* world);

#ifdef __cplusplus
}
#endif
