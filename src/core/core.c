#define _POSIX_C_SOURCE 200112L
// Allocation with a live byte count, the error hook and the assert hook.
#include "core.h"

#include "tumble/constants.h"
#include "tumble/math_functions.h"

#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if !defined(_WIN32)
#include <sched.h>
#endif

// The call the C standard does not give portably: aligned allocation (MSVC's C runtime has no
// aligned_alloc). Everything else here is C17; the clock is in timer.c.
#if defined(_WIN32)
#include <malloc.h>
#include <windows.h>
static void* tbSystemAlignedAlloc(size_t alignment, size_t size)
{
	return _aligned_malloc(size, alignment);
}
static void tbSystemAlignedFree(void* memory)
{
	_aligned_free(memory);
}
#else
static void* tbSystemAlignedAlloc(size_t alignment, size_t size)
{
	return aligned_alloc(alignment, size);
}
static void tbSystemAlignedFree(void* memory)
{
	free(memory);
}
#endif

#define TB_ALIGNMENT 64

static tbAllocFcn* s_allocFcn = NULL;
static tbFreeFcn* s_freeFcn = NULL;
static _Atomic int64_t s_byteCount = 0;
static _Atomic int s_errorCount = 0;
static tbErrorFcn* s_errorFcn = NULL;
// Told of every refused call before the game's hook (a recording takes the call's record back).
static tbErrorObserver* s_errorObserver = NULL;
static void* s_errorContext = NULL;
static tbAssertFcn* s_assertFcn = NULL;
static tbLogFcn* s_logFcn = NULL;
float tb_lengthUnitsPerMeter = 1.0f; // constants.h reads it inside the library

tbVersion tbGetVersion(void)
{
	tbVersion v = {0, 1, 0};
	return v;
}

bool tbIsDoublePrecision(void)
{
#if defined(TUMBLE_DOUBLE_PRECISION)
	return true;
#else
	return false;
#endif
}

void tbSetAllocator(tbAllocFcn* allocFcn, tbFreeFcn* freeFcn)
{
	s_allocFcn = allocFcn;
	s_freeFcn = freeFcn;
}

int64_t tbGetByteCount(void)
{
	return atomic_load(&s_byteCount);
}

/// The size rounded up to the alignment, so that aligned_alloc accepts it: in size_t, where an
/// int's largest value still rounds up (in int it would overflow).
static size_t tbRoundedSize(int size)
{
	return ((size_t)size + (TB_ALIGNMENT - 1)) & ~(size_t)(TB_ALIGNMENT - 1);
}

void* tbAlloc(int size)
{
	if (size <= 0)
	{
		return NULL;
	}
	size_t rounded = tbRoundedSize(size);
	void* p = s_allocFcn != NULL ? s_allocFcn(rounded, TB_ALIGNMENT) : tbSystemAlignedAlloc(TB_ALIGNMENT, rounded);
	if (p == NULL)
	{
		fprintf(stderr, "tumble: out of memory allocating %d bytes\n", size);
		abort();
	}
	atomic_fetch_add(&s_byteCount, size);
	return p;
}

void tbFree(void* memory, int size)
{
	if (memory == NULL)
	{
		return;
	}
	if (s_freeFcn != NULL)
	{
		// The hook hears the size its allocation was asked for: the same rounding as tbAlloc.
		s_freeFcn(memory, tbRoundedSize(size));
	}
	else
	{
		tbSystemAlignedFree(memory);
	}
	atomic_fetch_sub(&s_byteCount, size);
}

void* tbGrowAlloc(void* oldMemory, int oldSize, int newSize)
{
	void* p = tbAlloc(newSize);
	if (oldSize > 0 && oldMemory != NULL)
	{
		memcpy(p, oldMemory, (size_t)(oldSize < newSize ? oldSize : newSize));
		tbFree(oldMemory, oldSize);
	}
	return p;
}

float tbGetLengthUnitsPerMeter(void)
{
	return tb_lengthUnitsPerMeter;
}

void tbSetLengthUnits(float lengthUnits)
{
	tb_lengthUnitsPerMeter = lengthUnits;
}

void tbSetLogFcn(tbLogFcn* logFcn)
{
	s_logFcn = logFcn;
}

/// Without an error hook a refusal is logged: through the log hook when one is set (v3 programs
/// set only that), else on stderr.
static void tbDefaultErrorFcn(const char* message, void* context)
{
	(void)context;
	if (s_logFcn != NULL)
	{
		char line[540];
		snprintf(line, sizeof(line), "tumble error: %s", message);
		s_logFcn(line);
		return;
	}
	fprintf(stderr, "tumble error: %s\n", message);
}

void tbSetErrorCallback(tbErrorFcn* errorFcn, void* context)
{
	s_errorFcn = errorFcn;
	s_errorContext = context;
}

int tbGetErrorCount(void)
{
	return atomic_load(&s_errorCount);
}

void tbSetErrorObserver(tbErrorObserver* observer)
{
	s_errorObserver = observer;
}

void tbReportError(const char* function, const char* format, ...)
{
	char message[512];
	int n = snprintf(message, sizeof(message), "%s: ", function);
	va_list args;
	va_start(args, format);
	vsnprintf(message + n, sizeof(message) - (size_t)n, format, args);
	va_end(args);
	atomic_fetch_add(&s_errorCount, 1);
	if (s_errorObserver != NULL)
	{
		s_errorObserver(function);
	}
	tbErrorFcn* fcn = s_errorFcn != NULL ? s_errorFcn : tbDefaultErrorFcn;
	fcn(message, s_errorContext);
}

bool tbCheckFloat(const char* function, const char* name, float value)
{
	if (tbIsValidFloat(value) == false)
	{
		tbReportError(function, "%s is %g (NaN or infinity); pass a finite number", name, (double)value);
		return false;
	}
	return true;
}

bool tbCheckNonNegative(const char* function, const char* name, float value)
{
	if (tbIsValidFloat(value) == false || value < 0.0f)
	{
		tbReportError(function, "%s is %g (must be finite and >= 0); pass a non-negative number", name, (double)value);
		return false;
	}
	return true;
}

bool tbCheckPositive(const char* function, const char* name, float value)
{
	if (tbIsValidFloat(value) == false || value <= 0.0f)
	{
		tbReportError(function, "%s is %g (must be finite and > 0); pass a positive number", name, (double)value);
		return false;
	}
	return true;
}

bool tbCheckPointer(const char* function, const char* name, const void* pointer)
{
	if (pointer == NULL)
	{
		tbReportError(function, "%s is NULL; pass a valid pointer", name);
		return false;
	}
	return true;
}

void tbSetAssertFcn(tbAssertFcn* assertFcn)
{
	s_assertFcn = assertFcn;
}

int tbInternalAssert(const char* condition, const char* fileName, int lineNumber)
{
	if (s_assertFcn != NULL)
	{
		return s_assertFcn(condition, fileName, lineNumber);
	}
	fprintf(stderr, "tumble assertion failed: %s, %s:%d\n", condition, fileName, lineNumber);
	abort();
}

void tbYield(void)
{
#if defined(_WIN32)
	SwitchToThread();
#else
	sched_yield();
#endif
}

uint32_t tbHash(uint32_t hash, const uint8_t* data, int count)
{
	if (count < 0)
	{
		tbReportError("tbHash", "count is %d; pass the number of bytes (>= 0)", count);
		return hash;
	}
	if (count > 0 && tbCheckPointer("tbHash", "data", data) == false)
	{
		return hash;
	}
	for (int i = 0; i < count; ++i)
	{
		hash = (hash << 5) + hash + data[i]; // 33·hash + byte, wrapping at 2^32
	}
	return hash;
}

bool tbIsCoordinate(tbVec2 v)
{
	// false for NaN too: every comparison with NaN is false
	return tbAbsFloat(v.x) <= TB_MAX_COORDINATE && tbAbsFloat(v.y) <= TB_MAX_COORDINATE;
}

bool tbCheckCoordinate(const char* function, const char* name, tbVec2 value)
{
	if (tbCheckVec2(function, name, value) == false)
	{
		return false;
	}
	if (tbIsCoordinate(value) == false)
	{
		tbReportError(function, "%s is (%g, %g), beyond TB_MAX_COORDINATE (%g m); keep coordinates within it "
								"(float spacing there is 6 cm)", name, (double)value.x, (double)value.y,
					  (double)TB_MAX_COORDINATE);
		return false;
	}
	return true;
}

#if defined(TUMBLE_DOUBLE_PRECISION)
bool tbIsPosition(tbPos p)
{
	return fabs(p.x) <= TB_MAX_POSITION && fabs(p.y) <= TB_MAX_POSITION; // false for NaN
}

bool tbCheckPosition(const char* function, const char* name, tbPos value)
{
	if (tbIsPosition(value) == false)
	{
		tbReportError(function, "%s is (%g, %g): not finite or beyond TB_MAX_POSITION (%g m)", name, value.x, value.y,
					  TB_MAX_POSITION);
		return false;
	}
	return true;
}

bool tbCheckFinitePosition(const char* function, const char* name, tbPos value)
{
	if (isfinite(value.x) == false || isfinite(value.y) == false)
	{
		tbReportError(function, "%s is (%g, %g); must be finite", name, value.x, value.y);
		return false;
	}
	return true;
}
#else
bool tbCheckFinitePosition(const char* function, const char* name, tbPos value)
{
	return tbCheckVec2(function, name, value);
}

bool tbIsPosition(tbPos p)
{
	return tbIsCoordinate(p);
}

bool tbCheckPosition(const char* function, const char* name, tbPos value)
{
	return tbCheckCoordinate(function, name, value);
}
#endif

bool tbCheckLength(const char* function, const char* name, float value, bool positive)
{
	if ((positive ? tbCheckPositive(function, name, value) : tbCheckNonNegative(function, name, value)) == false)
	{
		return false;
	}
	if (value > TB_MAX_COORDINATE)
	{
		tbReportError(function, "%s is %g, beyond TB_MAX_COORDINATE (%g m); pass a smaller length", name, (double)value,
					  (double)TB_MAX_COORDINATE);
		return false;
	}
	return true;
}

bool tbCheckPoints(const char* function, const char* name, const tbVec2* points, int count)
{
	for (int i = 0; i < count; ++i)
	{
		if (tbIsCoordinate(points[i]) == false)
		{
			tbReportError(function, "%s[%d] is (%g, %g): not finite or beyond TB_MAX_COORDINATE (%g m); pass finite "
									"coordinates within it", name, i, (double)points[i].x, (double)points[i].y,
						  (double)TB_MAX_COORDINATE);
			return false;
		}
	}
	return true;
}

bool tbCheckVec2(const char* function, const char* name, tbVec2 value)
{
	if (tbIsValidVec2(value) == false)
	{
		tbReportError(function, "%s is (%g, %g) (NaN or infinity); pass finite coordinates", name, (double)value.x,
					  (double)value.y);
		return false;
	}
	return true;
}
