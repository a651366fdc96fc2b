#define _POSIX_C_SOURCE 200112L
// Ticks and milliseconds for the step's profile (tbWorld_GetProfile) and for the game's own timing.
// Nothing the simulation computes depends on them.
//
// A step reads the clock twice per stage, ten stages and more, so the read must cost next to
// nothing next to a step that has nothing to do. On x86 with an invariant time-stamp counter
// (CPUID 0x80000007, EDX bit 8: the counter runs at one rate in every power state, on every core)
// a tick is a counter cycle, read in a few cycles; the monotonic clock (clock_gettime) can cost a
// system call's path on virtual machines whose clock source the vDSO cannot read. The counter's
// rate is measured once against the monotonic clock, over TB_CALIBRATION_NS, the first time ticks
// are converted. Elsewhere a tick is a nanosecond of the monotonic clock.
#include "core.h"

#include <stdatomic.h>
#include <time.h>

#if defined(_WIN32)
#include <windows.h>
#elif (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <x86intrin.h>
#define TB_HAS_TSC 1
#endif

/// How long the counter's rate is measured against the clock: long enough that the clock's
/// resolution (a nanosecond or a few) is a part in ten thousand of it.
#define TB_CALIBRATION_NS 200000u

/// Nanoseconds of the monotonic clock.
static uint64_t tbClockNanoseconds(void)
{
#if defined(_WIN32)
	LARGE_INTEGER counter, frequency;
	QueryPerformanceCounter(&counter);
	QueryPerformanceFrequency(&frequency);
	return (uint64_t)((double)counter.QuadPart * (1e9 / (double)frequency.QuadPart));
#else
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
#endif
}

#if defined(TB_HAS_TSC)
enum
{
	tb_tickSourceUnknown,
	tb_tickSourceCounter,
	tb_tickSourceClock,
};
static atomic_int s_tickSource = tb_tickSourceUnknown;
static _Atomic double s_nanosecondsPerTick = 0.0;

static bool tbHasInvariantCounter(void)
{
	unsigned a, b, c, d;
	return __get_cpuid(0x80000007u, &a, &b, &c, &d) != 0 && (d & (1u << 8)) != 0;
}

/// The source of ticks, chosen once (racing threads choose the same).
static int tbTickSource(void)
{
	int source = atomic_load_explicit(&s_tickSource, memory_order_relaxed);
	if (source == tb_tickSourceUnknown)
	{
		source = tbHasInvariantCounter() ? tb_tickSourceCounter : tb_tickSourceClock;
		atomic_store_explicit(&s_tickSource, source, memory_order_relaxed);
	}
	return source;
}

/// Nanoseconds per counter cycle, measured the first time it is asked for.
static double tbNanosecondsPerCycle(void)
{
	double rate = atomic_load_explicit(&s_nanosecondsPerTick, memory_order_relaxed);
	if (rate > 0.0)
	{
		return rate;
	}
	uint64_t start = tbClockNanoseconds();
	uint64_t startCycles = __rdtsc();
	uint64_t end;
	do
	{
		end = tbClockNanoseconds();
	} while (end - start < TB_CALIBRATION_NS);
	uint64_t cycles = __rdtsc() - startCycles;
	rate = cycles > 0 ? (double)(end - start) / (double)cycles : 1.0;
	atomic_store_explicit(&s_nanosecondsPerTick, rate, memory_order_relaxed);
	return rate;
}
#endif

uint64_t tbGetTicks(void)
{
#if defined(TB_HAS_TSC)
	if (tbTickSource() == tb_tickSourceCounter)
	{
		return __rdtsc();
	}
#endif
	return tbClockNanoseconds();
}

/// Milliseconds of a number of ticks.
static double tbTicksToMilliseconds(uint64_t ticks)
{
#if defined(TB_HAS_TSC)
	if (tbTickSource() == tb_tickSourceCounter)
	{
		return (double)ticks * tbNanosecondsPerCycle() * 1e-6;
	}
#endif
	return (double)ticks * 1e-6;
}

float tbGetMilliseconds(uint64_t ticks)
{
	return (float)tbTicksToMilliseconds(tbGetTicks() - ticks);
}

float tbGetMillisecondsAndReset(uint64_t* ticks)
{
	if (tbCheckPointer("tbGetMillisecondsAndReset", "ticks", ticks) == false)
	{
		return 0.0f;
	}
	uint64_t now = tbGetTicks();
	float ms = (float)tbTicksToMilliseconds(now - *ticks);
	*ticks = now;
	return ms;
}
