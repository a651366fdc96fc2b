// The step arena (arena.c) and the rule it exists for: once a scene has settled into its working
// set, a step makes no call to the allocator hook.
//
// The hook counts calls; a whole step's worth of calls is compared with 0, exactly. "Settled"
// means the contact and body counts no longer grow: the scenes below rest (pyramid, stack) or
// repeat (a kinematic paddle sweeping through boxes), and the warm-up is long enough that every
// growable array has reached its size (measured: the counts stop changing within 2 s; the warm-up
// is 3 s).
#include "core/arena.h"
#include "core/core.h"
#include "catalogue.h"
#include "scene.h"

#include "tumble/tumble.h"

#include <criterion/criterion.h>

#include <stdint.h>
#include <stdlib.h>

static int s_allocCalls = 0;

static void* CountingAlloc(size_t size, int alignment)
{
	s_allocCalls += 1;
	return aligned_alloc((size_t)alignment, size);
}

static void CountingFree(void* memory, size_t size)
{
	(void)size;
	free(memory);
}

static void InstallCounter(void)
{
	s_allocCalls = 0;
	tbSetAllocator(CountingAlloc, CountingFree);
}

static void RemoveCounter(void)
{
	tbSetAllocator(NULL, NULL);
}

Test(arena, pieces_are_aligned_and_disjoint, .init = InstallCounter, .fini = RemoveCounter)
{
	tbArena arena = {0};
	int sizes[] = {1, 31, 32, 33, 100, 0, 4096};
	char* pieces[7];
	for (int i = 0; i < 7; ++i)
	{
		pieces[i] = tbArenaAlloc(&arena, sizes[i]);
		cr_assert_not_null(pieces[i]);
		cr_expect_eq((uintptr_t)pieces[i] % 32u, 0u, "piece %d misaligned", i);
		for (int k = 0; k < sizes[i]; ++k)
		{
			pieces[i][k] = (char)i; // ASan reports a write outside the piece
		}
	}
	for (int i = 0; i < 7; ++i)
	{
		for (int k = 0; k < sizes[i]; ++k)
		{
			cr_expect_eq(pieces[i][k], (char)i, "piece %d overwritten by another", i);
		}
	}
	tbArenaDestroy(&arena);
	cr_expect_eq(tbGetByteCount(), 0);
}

// The first round overflows to the heap; the reset grows the arena to the round's total; the same
// round then makes no allocation, and the overflow blocks are returned at the reset.
Test(arena, grows_to_the_largest_step_then_allocates_nothing, .init = InstallCounter, .fini = RemoveCounter)
{
	tbArena arena = {0};
	for (int round = 0; round < 3; ++round)
	{
		int before = s_allocCalls;
		for (int i = 0; i < 10; ++i)
		{
			(void)tbArenaAlloc(&arena, 1000 * (i + 1));
		}
		int calls = s_allocCalls - before;
		if (round == 0)
		{
			cr_expect_gt(calls, 0);
		}
		else
		{
			cr_expect_eq(calls, 0, "round %d allocated %d times", round, calls);
		}
		tbArenaReset(&arena);
		cr_expect_eq(arena.overflowCount, 0);
		cr_expect_geq(arena.capacity, 55 * 1024 - 1024); // Σ 1000·k rounded to 32 bytes each: 55,040 + padding
	}
	tbArenaDestroy(&arena);
	cr_expect_eq(tbGetByteCount(), 0);
}

static int CountStepAllocations(const char* sceneName, tbSolverMethod solver, tbBroadPhaseMethod broadPhase)
{
	Scene* scene = Catalogue_Build(sceneName);
	cr_assert_not_null(scene, "catalogue scene %s", sceneName);
	SceneOverrides overrides = {0};
	overrides.methods.solver = solver;
	overrides.methods.hasSolver = true;
	overrides.methods.broadPhase = broadPhase;
	overrides.methods.hasBroadPhase = true;
	SceneWorld sw = Scene_BuildWorld(scene, &overrides);
	cr_assert(TB_IS_NON_NULL(sw.worldId));
	int subSteps = solver == tb_solverSoft ? 4 : 1;
	for (int i = 0; i < 180; ++i)
	{
		tbWorld_Step(sw.worldId, 1.0f / 60.0f, subSteps);
	}
	int before = s_allocCalls;
	for (int i = 0; i < 60; ++i)
	{
		tbWorld_Step(sw.worldId, 1.0f / 60.0f, subSteps);
	}
	int calls = s_allocCalls - before;
	SceneWorld_Destroy(&sw);
	Scene_Destroy(scene);
	return calls;
}

Test(arena, settled_scenes_step_without_allocating, .init = InstallCounter, .fini = RemoveCounter)
{
	const char* scenes[] = {"pyramid", "vertical_stack"};
	for (int s = 0; s < 2; ++s)
	{
		for (int solver = 0; solver < tb_solverMethodCount; ++solver)
		{
			int calls = CountStepAllocations(scenes[s], (tbSolverMethod)solver, tb_broadPhaseAuto);
			cr_expect_eq(calls, 0, "%s, solver %d: %d allocations in 60 settled steps", scenes[s], solver, calls);
		}
		for (int bp = tb_broadPhaseTree; bp < tb_broadPhaseMethodCount; ++bp)
		{
			int calls = CountStepAllocations(scenes[s], tb_solverSoft, (tbBroadPhaseMethod)bp);
			cr_expect_eq(calls, 0, "%s, broad phase %d: %d allocations in 60 settled steps", scenes[s], bp, calls);
		}
	}
	cr_expect_eq(tbGetByteCount(), 0);
}

// The allocator hook hears each size rounded up to the alignment it is given, and the same size
// when the block is freed, up to the largest size an int holds (2^31 - 1 bytes, which a snapshot
// buffer may grow to): rounding it in int overflowed. The hook here hands out one static block
// without touching it, so nothing that large is allocated.
static size_t s_askedSize, s_freedSize;
static int s_askedAlignment;
static char s_block[64] __attribute__((aligned(64)));

static void* RecordingAlloc(size_t size, int alignment)
{
	s_askedSize = size;
	s_askedAlignment = alignment;
	return s_block;
}

static void RecordingFree(void* memory, size_t size)
{
	cr_expect(memory == s_block);
	s_freedSize = size;
}

Test(arena, the_hook_hears_sizes_rounded_up_to_the_alignment)
{
	tbSetAllocator(RecordingAlloc, RecordingFree);
	int64_t before = tbGetByteCount();
	int sizes[] = {1, 63, 64, 65, 2147483647};
	for (int i = 0; i < 5; ++i)
	{
		void* p = tbAlloc(sizes[i]);
		size_t a = (size_t)s_askedAlignment;
		cr_expect(a >= 16 && a <= 64 && (a & (a - 1)) == 0, "alignment %d", s_askedAlignment);
		cr_expect(s_askedSize % a == 0 && s_askedSize >= (size_t)sizes[i] && s_askedSize < (size_t)sizes[i] + a,
				  "size %d asked as %zu", sizes[i], s_askedSize);
		cr_expect(tbGetByteCount() == before + sizes[i]);
		tbFree(p, sizes[i]);
		cr_expect(s_freedSize == s_askedSize, "size %d freed as %zu, asked as %zu", sizes[i], s_freedSize, s_askedSize);
	}
	cr_expect(tbGetByteCount() == before);
	tbSetAllocator(NULL, NULL);
}
