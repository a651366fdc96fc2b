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

/// Allocation hook. Must return memory aligned to `alignment` bytes (a power of two, at most 64).
typedef void* tbAllocFcn(unsigned int size, int alignment);

/// Release hook for memory returned by the matching tbAllocFcn.
typedef void tbFreeFcn(void* memory);

/// Replace the allocator used for all of Tumble's memory. Pass NULLs to restore malloc/free.
/// Only call this while no world exists.
TB_API void tbSetAllocator(tbAllocFcn* allocFcn, tbFreeFcn* freeFcn);

/// Bytes currently allocated by Tumble across all worlds. Zero once every world is destroyed.
TB_API int tbGetByteCount(void);

/// Error hook: receives one message per rejected call. The message names the function,
/// the bad argument and what to do, e.g.
/// "tbCreateCircleShape: circle->radius is -1 (must be finite and > 0); give the circle a positive radius".
typedef void tbErrorFcn(const char* message, void* context);

/// Replace the error hook. NULL restores the default, which prints to stderr.
TB_API void tbSetErrorCallback(tbErrorFcn* errorFcn, void* context);

/// Number of errors reported since the program started (a convenience for tests and tools).
TB_API int tbGetErrorCount(void);

/// Assertion hook for internal invariants (not for user errors, which go to the error hook).
/// Return non-zero to break into the debugger.
typedef int tbAssertFcn(const char* condition, const char* fileName, int lineNumber);
TB_API void tbSetAssertFcn(tbAssertFcn* assertFcn);

/// Milliseconds and ticks for profiling. Not used by the simulation itself.
TB_API uint64_t tbGetTicks(void);
TB_API float tbGetMilliseconds(uint64_t ticks);

#ifdef __cplusplus
}
#endif
