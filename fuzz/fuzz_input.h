// Fuzz input decoding shared by the harnesses: a cursor over the fuzzer's bytes that yields
// integers and floats. Floats come either from a table of hostile values (NaN, ±infinity,
// ±FLT_MAX, denormals, TB_MAX_COORDINATE and just beyond it, 1e30, tiny sizes) or as raw bits,
// so every harness sees the values that broke the library before as often as ordinary ones.
#pragma once

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct FuzzInput
{
	const uint8_t* data;
	size_t size;
	size_t offset;
} FuzzInput;

static inline uint8_t FuzzByte(FuzzInput* in)
{
	return in->offset < in->size ? in->data[in->offset++] : 0;
}

static inline int FuzzInt(FuzzInput* in, int count)
{
	return count > 0 ? (int)(FuzzByte(in) % (unsigned)count) : 0;
}

static inline float FuzzFloat(FuzzInput* in)
{
	static const float special[] = {0.0f, 1.0f, -1.0f, 0.5f, 0.005f, 10.0f, -10.0f, 100.0f, NAN, INFINITY,
									-INFINITY, FLT_MAX, -FLT_MAX, 1e-40f, -1e-40f, FLT_MIN, 1e-20f, 1e6f,
									-1e6f, 1.0001e6f, 1e30f, -1e30f, 1e20f, 3e38f};
	uint8_t selector = FuzzByte(in);
	if (selector < 128)
	{
		// ordinary magnitudes: a signed value from -12.8 to 12.7 in steps of 0.1
		return ((float)selector - 64.0f) * 0.2f;
	}
	if (selector < 224)
	{
		return special[selector % (sizeof(special) / sizeof(special[0]))];
	}
	uint32_t bits = 0;
	for (int i = 0; i < 4; ++i)
	{
		bits = (bits << 8) | FuzzByte(in);
	}
	float value;
	memcpy(&value, &bits, sizeof(value));
	return value;
}

static inline bool FuzzIsFinite2(float x, float y)
{
	return isfinite(x) && isfinite(y);
}

// A finding: stop with a message the fuzzer prints and records as a crash.
#define FUZZ_CHECK(condition, ...)                                                                                   \
	do                                                                                                                \
	{                                                                                                                 \
		if (!(condition))                                                                                             \
		{                                                                                                             \
			fprintf(stderr, "fuzz check failed: %s: ", #condition);                                                   \
			fprintf(stderr, __VA_ARGS__);                                                                             \
			fprintf(stderr, "\n");                                                                                    \
			abort();                                                                                                  \
		}                                                                                                             \
	} while (0)
