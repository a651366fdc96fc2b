// Allocation failure: an allocator hook (tbSetAllocator) that returns NULL. The library's answer
// (tbAlloc, src/core/core.c) is to print "tumble: out of memory allocating N bytes" on stderr and
// abort; nothing returns a half-made object. The sweep below holds it to that at every allocation
// of a scene with every kind of object: a world with two workers, every shape kind, sensors,
// chains, a concave body, the nine joint kinds, callbacks, steps with events, queries of every
// kind, an explosion, method and worker changes, and destruction of each kind. The scene is run
// once with an allocator that counts (N allocations); then, for every n in 1..N, a child process
// runs it with an allocator that fails the n-th allocation, and must die of SIGABRT with the
// message on its stderr, having printed nothing else: no sanitizer report, no crash, no refusal
// (a refusal would mean a failed allocation surfaced as a bad argument). The scene also runs to
// the end under the hook, with every allocation aligned as asked and the byte count back to zero.
#include <criterion/criterion.h>

#include "tumble/tumble.h"

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

// --- the allocator hook ---------------------------------------------------------------------------

static long s_allocations; ///< allocations so far
static long s_failAt;	   ///< the allocation that returns NULL (0: none)
static bool s_misaligned;  ///< an allocation the hook could not align as asked

static void* HookAlloc(size_t size, int alignment)
{
	s_allocations += 1;
	if (s_allocations == s_failAt)
	{
		return NULL;
	}
	if (alignment <= 0 || (alignment & (alignment - 1)) != 0 || alignment > 64 || size % (size_t)alignment != 0)
	{
		s_misaligned = true; // base.h: a power of two, at most 64 (aligned_alloc also needs size a multiple)
		return malloc(size);
	}
	return aligned_alloc((size_t)alignment, size);
}

static void HookFree(void* memory, size_t size)
{
	(void)size;
	free(memory);
}

// --- a serial task system, so that the per-worker buffers are allocated --------------------------

static void* EnqueueTask(tbTaskCallback* task, void* taskContext, void* userContext)
{
	(void)userContext;
	task(taskContext); // run before returning: NULL tells the library there is nothing to finish
	return NULL;
}

static void FinishTask(void* userTask, void* userContext)
{
	(void)userTask;
	(void)userContext;
}

// --- the scene ---------------------------------------------------------------------------------------

static void PreSolve(tbShapeId shapeIdA, tbShapeId shapeIdB, tbManifold* manifold, void* context)
{
	(void)shapeIdA;
	(void)shapeIdB;
	(void)context;
	if (manifold->normal.y < -0.9f)
	{
		manifold->pointCount = 0; // one-way from below
	}
}

static bool CustomFilter(tbShapeId shapeIdA, tbShapeId shapeIdB, void* context)
{
	(void)context;
	return (shapeIdA.index1 + shapeIdB.index1) % 7 != 0;
}

static bool CountOverlap(tbShapeId shapeId, void* context)
{
	(void)shapeId;
	*(int*)context += 1;
	return true;
}

static float ClipRay(tbShapeId shapeId, tbPos point, tbVec2 normal, float fraction, void* context)
{
	(void)shapeId;
	(void)point;
	(void)normal;
	*(int*)context += 1;
	return fraction;
}

static bool CountPlane(tbShapeId shapeId, const tbPlaneResult* plane, void* context)
{
	(void)shapeId;
	(void)plane;
	*(int*)context += 1;
	return true;
}

static tbBodyId MakeBody(tbWorldId world, tbBodyType type, float x, float y)
{
	tbBodyDef def = tbDefaultBodyDef();
	def.type = type;
	def.position = tbMakeVec2(x, y);
	return tbCreateBody(world, &def);
}

/// Every kind of object, stepped, queried and destroyed. Returns a checksum of what it read so
/// that the run is not optimised into less than it looks.
static int RunScene(void)
{
	int seen = 0;
	tbWorldDef worldDef = tbDefaultWorldDef();
	worldDef.workerCount = 2;
	worldDef.enqueueTask = EnqueueTask;
	worldDef.finishTask = FinishTask;
	tbWorldId world = tbCreateWorld(&worldDef);

	// A second world with its capacity reserved up front, the tree broad phase and NGS: a body
	// stepped on a box, then the world destroyed while the first lives on.
	tbWorldDef otherDef = tbDefaultWorldDef();
	otherDef.capacity = (tbCapacity){4, 8, 4, 8, 16};
	otherDef.broadPhase = tb_broadPhaseTree;
	otherDef.solver = tb_solverNGS;
	tbWorldId other = tbCreateWorld(&otherDef);
	tbShapeDef otherShapeDef = tbDefaultShapeDef();
	tbPolygon otherBox = tbMakeBox(1.0f, 0.5f);
	tbCreatePolygonShape(MakeBody(other, tb_staticBody, 0.0f, 0.0f), &otherShapeDef, &otherBox);
	tbCreatePolygonShape(MakeBody(other, tb_dynamicBody, 0.0f, 1.1f), &otherShapeDef, &otherBox);
	for (int step = 0; step < 3; ++step)
	{
		tbWorld_Step(other, 1.0f / 60.0f, 4);
	}
	tbDestroyWorld(other);

	tbWorld_SetPreSolveCallback(world, PreSolve, NULL, NULL);
	tbWorld_SetCustomFilterCallback(world, CustomFilter, NULL);

	// Ground: a box, a segment, an orphan chain segment, an open chain with a material per
	// segment, a looped chain, a sensor.
	tbBodyId ground = MakeBody(world, tb_staticBody, 0.0f, 0.0f);
	tbShapeDef shapeDef = tbDefaultShapeDef();
	shapeDef.enableHitEvents = true;
	tbPolygon floor = tbMakeOffsetBox(20.0f, 0.5f, tbMakeVec2(0.0f, -0.5f), tbRot_identity);
	tbCreatePolygonShape(ground, &shapeDef, &floor);
	tbSegment wall = {{-20.0f, 0.0f}, {-20.0f, 10.0f}};
	tbCreateSegmentShape(ground, &shapeDef, &wall);
	tbChainSegment ledge = {{26.0f, 2.0f}, {{25.0f, 2.0f}, {22.0f, 2.0f}}, {21.0f, 2.0f}, -1};
	tbCreateChainSegmentShape(ground, &shapeDef, &ledge);
	tbVec2 hill[8];
	tbSurfaceMaterial materials[5];
	for (int i = 0; i < 8; ++i)
	{
		hill[i] = tbMakeVec2(40.0f - 2.0f * (float)i, 0.3f * (float)(i % 3));
	}
	for (int i = 0; i < 5; ++i)
	{
		materials[i] = tbDefaultSurfaceMaterial();
		materials[i].friction = 0.2f * (float)i;
	}
	tbChainDef chainDef = tbDefaultChainDef();
	chainDef.points = hill;
	chainDef.count = 8;
	chainDef.materials = materials;
	chainDef.materialCount = 5;
	tbChainId openChain = tbCreateChain(ground, &chainDef);
	tbVec2 ring[6];
	for (int i = 0; i < 6; ++i)
	{
		ring[i] = tbMakeVec2(-10.0f + 3.0f * cosf(1.0472f * (float)i), 8.0f + 3.0f * sinf(1.0472f * (float)i));
	}
	tbChainDef loopDef = tbDefaultChainDef();
	loopDef.points = ring;
	loopDef.count = 6;
	loopDef.isLoop = true;
	loopDef.enableSensorEvents = true;
	tbChainId loop = tbCreateChain(ground, &loopDef);
	tbShapeDef sensorDef = tbDefaultShapeDef();
	sensorDef.isSensor = true;
	sensorDef.enableSensorEvents = true;
	tbPolygon zone = tbMakeOffsetBox(3.0f, 3.0f, tbMakeVec2(0.0f, 2.0f), tbRot_identity);
	tbShapeId sensor = tbCreatePolygonShape(ground, &sensorDef, &zone);

	// Dynamic bodies of every shape kind, one of them concave (decomposed), one a bullet.
	tbShapeDef bodyShapeDef = tbDefaultShapeDef();
	bodyShapeDef.enableSensorEvents = true;
	bodyShapeDef.enableHitEvents = true;
	bodyShapeDef.enablePreSolveEvents = true;
	bodyShapeDef.enableCustomFiltering = true;
	tbBodyId bodies[8];
	for (int i = 0; i < 8; ++i)
	{
		bodies[i] = MakeBody(world, tb_dynamicBody, -6.0f + 1.5f * (float)i, 1.0f + 0.6f * (float)(i % 3));
	}
	tbCircle circle = {{0.0f, 0.0f}, 0.4f};
	tbCreateCircleShape(bodies[0], &bodyShapeDef, &circle);
	tbCapsule capsule = {{-0.3f, 0.0f}, {0.3f, 0.0f}, 0.25f};
	tbCreateCapsuleShape(bodies[1], &bodyShapeDef, &capsule);
	tbPolygon box = tbMakeBox(0.4f, 0.3f);
	tbCreatePolygonShape(bodies[2], &bodyShapeDef, &box);
	tbPolygon rounded = tbMakeRoundedBox(0.3f, 0.3f, 0.1f);
	tbCreatePolygonShape(bodies[3], &bodyShapeDef, &rounded);
	tbVec2 hullPoints[5] = {{-0.4f, -0.3f}, {0.4f, -0.3f}, {0.5f, 0.1f}, {0.0f, 0.5f}, {-0.5f, 0.1f}};
	tbHull hull = tbComputeHull(hullPoints, 5);
	tbPolygon pentagon = tbMakePolygon(&hull, 0.0f);
	tbShapeId pentagonShape = tbCreatePolygonShape(bodies[4], &bodyShapeDef, &pentagon);
	tbSegment stick = {{-0.5f, 0.0f}, {0.5f, 0.0f}};
	tbCreateSegmentShape(bodies[5], &bodyShapeDef, &stick);
	tbCreateCircleShape(bodies[5], &bodyShapeDef, &circle);
	tbVec2 star[10];
	for (int i = 0; i < 10; ++i)
	{
		float r = i % 2 == 0 ? 0.8f : 0.35f;
		star[i] = tbMakeVec2(r * cosf(0.6283f * (float)i), r * sinf(0.6283f * (float)i));
	}
	tbPolygon pieces[8];
	int pieceCount = tbDecomposePolygon(star, 10, pieces, 8);
	for (int i = 0; i < pieceCount; ++i)
	{
		tbCreatePolygonShape(bodies[6], &bodyShapeDef, pieces + i);
	}
	tbCreateCircleShape(bodies[7], &bodyShapeDef, &circle);
	tbBody_SetBullet(bodies[7], true);
	tbBody_SetLinearVelocity(bodies[7], tbMakeVec2(0.0f, -200.0f));
	tbBodyId mover = MakeBody(world, tb_kinematicBody, 10.0f, 3.0f);
	tbCreatePolygonShape(mover, &bodyShapeDef, &box);

	// The nine joint kinds.
	tbDistanceJointDef distance = tbDefaultDistanceJointDef();
	distance.base.bodyIdA = bodies[0];
	distance.base.bodyIdB = bodies[1];
	distance.enableSpring = true;
	distance.hertz = 2.0f;
	tbCreateDistanceJoint(world, &distance);
	tbFilterJointDef filter = tbDefaultFilterJointDef();
	filter.base.bodyIdA = bodies[1];
	filter.base.bodyIdB = bodies[2];
	tbCreateFilterJoint(world, &filter);
	tbMotorJointDef motor = tbDefaultMotorJointDef();
	motor.base.bodyIdA = ground;
	motor.base.bodyIdB = bodies[2];
	motor.linearHertz = 3.0f;
	motor.maxSpringForce = 100.0f;
	tbJointId drag = tbCreateMotorJoint(world, &motor);
	tbMoverJointDef moverJoint = tbDefaultMoverJointDef();
	moverJoint.base.bodyIdA = ground;
	moverJoint.base.bodyIdB = bodies[3];
	moverJoint.linearVelocity = tbMakeVec2(1.0f, 0.0f);
	moverJoint.maxVelocityForce = tbMakeVec2(50.0f, 0.0f);
	tbCreateMoverJoint(world, &moverJoint);
	tbPogoJointDef pogo = tbDefaultPogoJointDef();
	pogo.base.bodyIdA = ground;
	pogo.base.bodyIdB = bodies[4];
	pogo.hertz = 5.0f;
	pogo.restLength = 1.0f;
	pogo.maxCompressionForce = 100.0f;
	tbCreatePogoJoint(world, &pogo);
	tbPrismaticJointDef prismatic = tbDefaultPrismaticJointDef();
	prismatic.base.bodyIdA = bodies[4];
	prismatic.base.bodyIdB = bodies[5];
	prismatic.enableLimit = true;
	prismatic.lowerTranslation = -1.0f;
	prismatic.upperTranslation = 1.0f;
	tbCreatePrismaticJoint(world, &prismatic);
	tbRevoluteJointDef revolute = tbDefaultRevoluteJointDef();
	revolute.base.bodyIdA = bodies[5];
	revolute.base.bodyIdB = bodies[6];
	revolute.enableMotor = true;
	revolute.maxMotorTorque = 10.0f;
	revolute.motorSpeed = 1.0f;
	tbJointId hinge = tbCreateRevoluteJoint(world, &revolute);
	tbWeldJointDef weld = tbDefaultWeldJointDef();
	weld.base.bodyIdA = bodies[6];
	weld.base.bodyIdB = bodies[7];
	weld.linearHertz = 5.0f;
	tbCreateWeldJoint(world, &weld);
	tbWheelJointDef wheel = tbDefaultWheelJointDef();
	wheel.base.bodyIdA = mover;
	wheel.base.bodyIdB = bodies[0];
	wheel.enableMotor = true;
	wheel.maxMotorTorque = 5.0f;
	tbCreateWheelJoint(world, &wheel);

	// A pile of boxes (contacts enough to grow every contact array and colour the graph) and a
	// hanging chain of links (a joint tree), so that the steps below let bodies fall asleep.
	for (int i = 0; i < 24; ++i)
	{
		tbBodyId brick = MakeBody(world, tb_dynamicBody, 12.0f + 0.9f * (float)(i % 6) + 0.45f * (float)((i / 6) % 2),
								  0.5f + 0.8f * (float)(i / 6));
		tbPolygon brickBox = tbMakeBox(0.4f, 0.4f);
		tbCreatePolygonShape(brick, &shapeDef, &brickBox);
	}
	tbBodyId previous = ground;
	for (int i = 0; i < 6; ++i)
	{
		tbBodyId link = MakeBody(world, tb_dynamicBody, -14.0f + 0.5f * (float)i, 6.0f);
		tbCapsule linkShape = {{-0.25f, 0.0f}, {0.25f, 0.0f}, 0.1f};
		tbCreateCapsuleShape(link, &shapeDef, &linkShape);
		tbRevoluteJointDef linkJoint = tbDefaultRevoluteJointDef();
		linkJoint.base.bodyIdA = previous;
		linkJoint.base.bodyIdB = link;
		linkJoint.base.localFrameA.p = i == 0 ? tbMakeVec2(-14.25f, 6.0f) : tbMakeVec2(0.25f, 0.0f);
		linkJoint.base.localFrameB.p = tbMakeVec2(-0.25f, 0.0f);
		tbCreateRevoluteJoint(world, &linkJoint);
		previous = link;
	}

	// Steps, with events read after each and the drag's frame moved (a mouse drag).
	for (int step = 0; step < 40; ++step)
	{
		tbTransform frame = {tbMakeVec2(-3.0f + 0.2f * (float)step, 3.0f), tbRot_identity};
		tbJoint_SetLocalFrameA(drag, frame);
		tbWorldTransform target = {tbMakeVec2(10.0f - 0.1f * (float)step, 3.0f), tbRot_identity};
		tbBody_SetTargetTransform(mover, target, 1.0f / 60.0f, true);
		tbWorld_Step(world, 1.0f / 60.0f, 4);
		tbContactEvents contacts = tbWorld_GetContactEvents(world);
		tbSensorEvents sensors = tbWorld_GetSensorEvents(world);
		tbBodyEvents moves = tbWorld_GetBodyEvents(world);
		tbJointEvents joints = tbWorld_GetJointEvents(world);
		seen += contacts.beginCount + contacts.endCount + contacts.hitCount + sensors.beginCount + sensors.endCount +
				moves.moveCount + joints.count;
		if (step == 4)
		{
			tbWorld_SetWorkerCount(world, 3);
			tbWorld_SetBroadPhaseMethod(world, tb_broadPhaseSpatialHash);
			tbBody_SetType(bodies[2], tb_kinematicBody);
			tbBody_Disable(bodies[3]);
		}
		if (step == 8)
		{
			tbWorld_SetBroadPhaseMethod(world, tb_broadPhaseSortAndSweep);
			tbWorld_SetSolverMethod(world, tb_solverNGS, 8, 3);
			tbBody_Enable(bodies[3]);
			tbBody_SetType(bodies[2], tb_dynamicBody);
		}
	}
	tbContactData data[16];
	seen += tbBody_GetContactData(bodies[0], data, 16);
	tbShapeId visitors[16];
	seen += tbShape_GetSensorData(sensor, visitors, 16);

	// Queries of every kind, and an explosion.
	tbAABB region = {{-20.0f, -1.0f}, {20.0f, 10.0f}};
	tbWorld_OverlapAABB(world, tbPos_zero, region, tbDefaultQueryFilter(), CountOverlap, &seen);
	tbWorld_OverlapPoint(world, tbMakeVec2(0.0f, 0.5f), tbDefaultQueryFilter(), CountOverlap, &seen);
	tbGeometry probe = {.type = tb_circleShape, .circle = {{0.0f, 0.0f}, 1.0f}};
	tbShapeProxy proxy = tbMakeShapeProxy(&probe);
	tbWorld_OverlapShape(world, tbMakeVec2(0.0f, 1.0f), &proxy, tbDefaultQueryFilter(), CountOverlap, &seen);
	tbWorld_CastRay(world, tbMakeVec2(-15.0f, 5.0f), tbMakeVec2(30.0f, -6.0f), tbDefaultQueryFilter(), ClipRay, &seen);
	tbWorld_CastShape(world, tbMakeVec2(-15.0f, 5.0f), &proxy, tbMakeVec2(30.0f, -6.0f), tbDefaultQueryFilter(),
					  ClipRay, &seen);
	seen += tbWorld_CastRayClosest(world, tbMakeVec2(0.0f, 8.0f), tbMakeVec2(0.0f, -10.0f), tbDefaultQueryFilter()).hit;
	tbCapsule character = {{0.0f, -0.5f}, {0.0f, 0.5f}, 0.3f};
	seen += (int)tbWorld_CastMover(world, tbMakeVec2(15.0f, 3.0f), &character, tbMakeVec2(0.0f, -5.0f),
								   tbDefaultQueryFilter());
	tbWorld_CollideMover(world, tbMakeVec2(15.0f, 1.0f), &character, tbDefaultQueryFilter(), CountPlane, &seen);
	tbExplosionDef explosion = tbDefaultExplosionDef();
	explosion.position = tbMakeVec2(0.0f, 1.0f);
	explosion.radius = 2.0f;
	explosion.falloff = 2.0f;
	explosion.impulsePerLength = 5.0f;
	tbWorld_Explode(world, &explosion);
	tbWorld_RebuildStaticTree(world);
	tbWorld_Step(world, 1.0f / 60.0f, 4);

	// Destruction of each kind, then of the world.
	tbDestroyJoint(hinge);
	tbDestroyShape(pentagonShape, true);
	tbDestroyChain(openChain);
	tbDestroyChain(loop);
	tbDestroyBody(bodies[7]);
	tbWorld_Step(world, 1.0f / 60.0f, 4);
	tbDestroyWorld(world);
	return seen;
}

// --- the sweep ---------------------------------------------------------------------------------------

static void RecordError(const char* message, void* context)
{
	(void)context;
	fprintf(stderr, "refused: %s\n", message); // the parent fails on any
}

typedef struct ChildResult
{
	int status;
	char output[4096];
} ChildResult;

/// Run the scene in a child process whose allocator fails allocation `failAt` (0: none).
static ChildResult RunChild(long failAt)
{
	ChildResult result;
	memset(&result, 0, sizeof(result));
	int channel[2];
	cr_assert_eq(pipe(channel), 0);
	fflush(NULL);
	pid_t pid = fork();
	if (pid == 0)
	{
		// The child must die of the abort itself, whatever handler the test runner installed; a
		// child that hangs dies of the alarm instead (and fails the check below).
		signal(SIGABRT, SIG_DFL);
		alarm(60);
		close(channel[0]);
		dup2(channel[1], STDERR_FILENO);
		close(channel[1]);
		tbSetErrorCallback(RecordError, NULL);
		s_allocations = 0;
		s_failAt = failAt;
		tbSetAllocator(HookAlloc, HookFree);
		RunScene();
		_exit(0);
	}
	// Asserted only here, in the parent: with --full-stats Criterion reports passing assertions to
	// its runner too, and one made by the child would reach the runner from a process it does not
	// know.
	cr_assert(pid > 0, "fork failed");
	close(channel[1]);
	size_t used = 0;
	for (;;)
	{
		ssize_t n = read(channel[0], result.output + used, sizeof(result.output) - 1 - used);
		if (n <= 0)
		{
			break;
		}
		used += (size_t)n;
		if (used == sizeof(result.output) - 1)
		{
			char sink[256];
			while (read(channel[0], sink, sizeof(sink)) > 0)
			{
				// the rest is drained so the child never blocks; the start is what the checks read
			}
			break;
		}
	}
	close(channel[0]);
	cr_assert_eq(waitpid(pid, &result.status, 0), pid);
	return result;
}

// The scene runs to the end with the allocator hook, every allocation aligned as asked, and the
// byte count back to zero once the world is destroyed.
Test(allocation_failures, the_scene_runs_under_the_allocator_hook)
{
	tbSetErrorCallback(RecordError, NULL);
	s_allocations = 0;
	s_failAt = 0;
	s_misaligned = false;
	tbSetAllocator(HookAlloc, HookFree);
	int seen = RunScene();
	tbSetAllocator(NULL, NULL);
	tbSetErrorCallback(NULL, NULL);
	cr_assert(seen > 0, "the scene saw no contacts, events or query results");
	cr_assert(s_allocations > 100, "only %ld allocations: the scene does less than it should", s_allocations);
	cr_assert_not(s_misaligned, "an allocation asked for an alignment or size base.h does not allow");
	cr_assert_eq(tbGetByteCount(), 0, "%lld bytes left", (long long)tbGetByteCount());
}

// Every allocation of the scene, failed in turn: each run aborts with the message, and nothing
// else reaches stderr.
Test(allocation_failures, every_failed_allocation_aborts_with_a_message)
{
	s_allocations = 0;
	s_failAt = 0;
	tbSetAllocator(HookAlloc, HookFree);
	RunScene();
	tbSetAllocator(NULL, NULL);
	long total = s_allocations;
	cr_assert(total > 100, "only %ld allocations", total);
	cr_log_info("the scene makes %ld allocations", total);

	ChildResult clean = RunChild(0);
	cr_assert(WIFEXITED(clean.status) && WEXITSTATUS(clean.status) == 0,
			  "the scene without a failure ended with status %#x:\n%s", clean.status, clean.output);
	cr_assert_eq(clean.output[0], '\0', "the scene without a failure wrote:\n%s", clean.output);

	for (long n = 1; n <= total; ++n)
	{
		ChildResult r = RunChild(n);
		cr_assert(WIFSIGNALED(r.status) && WTERMSIG(r.status) == SIGABRT,
				  "allocation %ld of %ld failed: the child %s %d instead of aborting; it wrote:\n%s", n, total,
				  WIFSIGNALED(r.status) ? "died of signal" : "exited with",
				  WIFSIGNALED(r.status) ? WTERMSIG(r.status) : WEXITSTATUS(r.status),
				  r.output);
		const char* expected = "tumble: out of memory allocating ";
		cr_assert(strncmp(r.output, expected, strlen(expected)) == 0,
				  "allocation %ld of %ld failed: stderr does not start with the message:\n%s", n, total, r.output);
		const char* end = strchr(r.output, '\n');
		cr_assert(end != NULL && end[1] == '\0',
				  "allocation %ld of %ld failed: more than the one line on stderr:\n%s", n, total, r.output);
	}
}
