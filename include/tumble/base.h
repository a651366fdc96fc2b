// Tumble: base definitions shared by every public header.
// Export macro, version, the allocator hook with its live byte count, and the
// error hook that receives a message for every rejected call.
#pragma once

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#if defined(TUMBLE_SHARED)
#if defined(_WIN32)
#if defined(TUMBLE_BUILDING)
#define TB_API __declspec(dllexport)
#else
#define TB_API __declspec(dllimport)
#endif
#else
#define TB_API __attribute__((visibility("default")))
#endif
#else
#define TB_API
#endif

#ifdef __cplusplus
#define TB_INLINE inline
#define TB_LITERAL(T) T
#define TB_ZERO_INIT {}
extern "C" {
#else
#define TB_INLINE static inline
// Compound literal; C++ uses aggregate initialisation instead.
#define TB_LITERAL(T) (T)
#define TB_ZERO_INIT {0}
#endif

/// The null index (Box2D v3's B2_NULL_INDEX): no proxy, no node, no entry.
#define TB_NULL_INDEX (-1)

/// Library version (semantic versioning).
typedef struct tbVersion
{
	int major;
	int minor;
	int revision;
} tbVersion;

TB_API tbVersion tbGetVersion(void);

/// True when the library was built for large worlds (CMake option TUMBLE_DOUBLE_PRECISION: world
/// positions in double precision).
TB_API bool tbIsDoublePrecision(void);

/// Allocation hook (Box2D v3.2's b2AllocFcn). Must return memory aligned to `alignment` bytes (a
/// power of two, at most 64).
typedef void* tbAllocFcn(size_t size, int alignment);

/// Release hook for memory returned by the matching tbAllocFcn (Box2D v3.2's b2FreeFcn): `size` is
/// the size that allocation was asked for, so a pool or arena allocator needs no header of its own.
typedef void tbFreeFcn(void* memory, size_t size);

/// Replace the allocator used for all of Tumble's memory. Pass NULLs to restore malloc/free.
/// Only call this while no world exists.
TB_API void tbSetAllocator(tbAllocFcn* allocFcn, tbFreeFcn* freeFcn);

/// Bytes currently allocated by Tumble across all worlds. Zero once every world is destroyed.
TB_API int64_t tbGetByteCount(void);

/// Error hook: receives one message per rejected call. The message names the function,
/// the bad argument and what to do, e.g.
/// "tbCreateCircleShape: circle->radius is -1 (must be finite and > 0); give the circle a positive radius".
typedef void tbErrorFcn(const char* message, void* context);

/// Replace the error hook. NULL restores the default, which prints to stderr.
TB_API void tbSetErrorCallback(tbErrorFcn* errorFcn, void* context);

/// Number of errors reported since the program started (a convenience for tests and tools).
TB_API int tbGetErrorCount(void);

/// Log hook (Box2D v3.2's b2LogFcn): receives what Tumble has to say outside a return value, one
/// line without its newline. While no error hook is set (tbSetErrorCallback), refusals reach it
/// too, as "tumble error: <message>", so a program ported from v3 that only sets a log function
/// sees them in its log; an error hook, when set, takes them instead.
typedef void tbLogFcn(const char* message);

/// Replace the log hook. NULL restores the default, which prints to stderr.
TB_API void tbSetLogFcn(tbLogFcn* logFcn);

/// Assertion hook for internal invariants (not for user errors, which go to the error hook).
/// Return non-zero to break into the debugger.
typedef int tbAssertFcn(const char* condition, const char* fileName, int lineNumber);
TB_API void tbSetAssertFcn(tbAssertFcn* assertFcn);

/// Report a failed internal invariant (what TB_ASSERT calls, Box2D v3.2's b2InternalAssert): the
/// assert hook decides (its return value is returned: non-zero asks the caller to break into the
/// debugger); without a hook it prints the condition and location to stderr and aborts.
TB_API int tbInternalAssert(const char* condition, const char* fileName, int lineNumber);

/// Length units per metre (Box2D v3.2's): 1 by default (metres). A game in pixels (say 32 per
/// metre) or centimetres (100) passes that number before it creates any world, and then gives every
/// length in its units; Tumble scales its length tolerances with it (constants.h: linear slop,
/// speculative distances, broad-phase margins, sleep speed, default thresholds and speed caps, and
/// the air density of tbShape_ApplyWind). Mass, gravity and forces are the game's to choose in the
/// same units. Refused (false, error hook, nothing changed): not finite or outside [0.001, 1000],
/// or a world exists.
TB_API bool tbSetLengthUnitsPerMeter(float lengthUnits);
TB_API float tbGetLengthUnitsPerMeter(void);

/// Ticks and milliseconds for profiling: tbGetTicks is a cheap counter read (the processor's
/// time-stamp counter where it is invariant, else nanoseconds of a monotonic clock); take
/// differences of ticks through tbGetMilliseconds. Not used by the simulation itself.
TB_API uint64_t tbGetTicks(void);
TB_API float tbGetMilliseconds(uint64_t ticks);

/// Milliseconds since *ticks (tbGetTicks), and *ticks set to now: the lap time of a loop.
TB_API float tbGetMillisecondsAndReset(uint64_t* ticks);

/// Give up the rest of this thread's time slice (sched_yield, SwitchToThread): for a task system's
/// busy wait.
TB_API void tbYield(void);

/// Start value of tbHash (djb2's).
#define TB_HASH_INIT 5381

/// djb2 hash (Bernstein): for i in 0..count−1, hash = 33·hash + data[i], modulo 2^32. Chain calls
/// to hash several buffers; start from TB_HASH_INIT. For determinism checks, not for security.
TB_API uint32_t tbHash(uint32_t hash, const uint8_t* data, int count);

#ifdef __cplusplus
}
#endif
