// Internal: allocation through the user hook with a live byte count, error reporting, asserts.
#pragma once

#include "tumble/base.h"
#include "tumble/math_functions.h"

#include <stdarg.h>

#if defined(__GNUC__)
#define TB_BREAKPOINT __builtin_trap()
#define TB_PRINTF_FORMAT(a, b) __attribute__((format(printf, a, b)))
#else
#define TB_BREAKPOINT ((void)0)
#define TB_PRINTF_FORMAT(a, b)
#endif

/// Internal invariant (never user input: that goes through tbReportError).
#define TB_ASSERT(condition)                                                                                          \
	do                                                                                                                \
	{                                                                                                                 \
		if (!(condition) && tbInternalAssert(#condition, __FILE__, __LINE__))                                         \
		{                                                                                                             \
			TB_BREAKPOINT;                                                                                            \
		}                                                                                                             \
	} while (0)

/// Allocate size bytes (64-byte aligned: a cache line) through the hook. Counts toward tbGetByteCount.
void* tbAlloc(int size);

/// Free memory from tbAlloc; size must be the size that was allocated.
void tbFree(void* memory, int size);

/// Grow (or shrink) an allocation, copying min(oldSize, newSize) bytes.
void* tbGrowAlloc(void* oldMemory, int oldSize, int newSize);

/// Store the length units (tbSetLengthUnitsPerMeter checks them and that no world exists).
void tbSetLengthUnits(float lengthUnits);

/// Report a rejected call: "function: message". Formats like printf.
void tbReportError(const char* function, const char* format, ...) TB_PRINTF_FORMAT(2, 3);

/// Told the function's name of every error reported, before the error hook: the world layer's
/// recordings use it to drop the record of a call that was refused (core cannot call upward).
typedef void tbErrorObserver(const char* function);
void tbSetErrorObserver(tbErrorObserver* observer);

/// Checks that report an error naming function and argument, returning false when bad.
bool tbCheckFloat(const char* function, const char* name, float value);
bool tbCheckNonNegative(const char* function, const char* name, float value);
bool tbCheckPositive(const char* function, const char* name, float value);
bool tbCheckPointer(const char* function, const char* name, const void* pointer);
bool tbCheckVec2(const char* function, const char* name, tbVec2 value);
/// Finite and each coordinate within ±TB_MAX_COORDINATE (a point of a shape, a body position).
bool tbCheckCoordinate(const char* function, const char* name, tbVec2 value);
/// Finite, >= 0 (> 0 when positive) and at most TB_MAX_COORDINATE (a radius, a half-width).
bool tbCheckLength(const char* function, const char* name, float value, bool positive);
/// tbCheckCoordinate for each of count points, reported as name[i].
bool tbCheckPoints(const char* function, const char* name, const tbVec2* points, int count);
/// A world transform rounded to float (drawing; exact in the float build).
static inline tbTransform tbRoundTransform(tbWorldTransform t)
{
	tbTransform r = {tbToVec2(t.p), t.q};
	return r;
}

/// True when v is finite and each coordinate within ±TB_MAX_COORDINATE.
bool tbIsCoordinate(tbVec2 v);
/// A world position: finite and within ±TB_MAX_POSITION (tbCheckCoordinate in the float build).
bool tbCheckPosition(const char* function, const char* name, tbPos value);
/// True when p is finite and each coordinate within ±TB_MAX_POSITION.
bool tbIsPosition(tbPos p);
/// A world position: finite (tbCheckVec2 in the float build).
bool tbCheckFinitePosition(const char* function, const char* name, tbPos value);

/// Index of the lowest set bit of x (x ≠ 0): a colour free in a body's mask, a free slot in a set.
static inline int tbLowestSetBit(uint64_t x)
{
#if defined(__GNUC__) || defined(__clang__)
	return __builtin_ctzll((unsigned long long)x);
#else
	int n = 0;
	while ((x & 1u) == 0u)
	{
		x >>= 1;
		n += 1;
	}
	return n;
#endif
}

/// Ask for the cache lines of [p, p + bytes) ahead of use: for walks over a sparse subset of a big
/// array (solver contacts among all contacts), where the hardware prefetcher sees no stream. A hint
/// only: no effect on results.
static inline void tbPrefetch(const void* p, int bytes)
{
#if defined(__GNUC__) || defined(__clang__)
	for (int offset = 0; offset < bytes; offset += 64)
	{
		__builtin_prefetch((const char*)p + offset);
	}
	__builtin_prefetch((const char*)p + bytes - 1);
#else
	(void)p;
	(void)bytes;
#endif
}

/// How many items ahead a walk by index list prefetches (tbPrefetch): far enough to hide a miss to
/// memory behind the work of the items in between.
#define TB_PREFETCH_AHEAD 8

/// Inline whatever the compiler's size heuristics say, for the few hot helpers whose callers
/// gain from constants folded into them (contact_solver_wide.c, contact.c).
#if defined(__GNUC__) || defined(__clang__)
#define TB_FORCE_INLINE inline __attribute__((always_inline))
#elif defined(_MSC_VER)
#define TB_FORCE_INLINE __forceinline
#else
#define TB_FORCE_INLINE inline
#endif

/// Closest point to p on the segment a–b (Ericson, Real-Time Collision Detection, §5.1.2), with
/// its fraction t along a → b; a degenerate segment (a = b) gives a and t = 0.
static inline tbVec2 tbClosestPointOnSegment(float* t, tbVec2 p, tbVec2 a, tbVec2 b)
{
	tbVec2 e = tbSub(b, a);
	float ee = tbDot(e, e);
	*t = ee > 0.0f ? tbClampFloat(tbDot(tbSub(p, a), e) / ee, 0.0f, 1.0f) : 0.0f;
	return tbMulAdd(a, *t, e);
}
