// Internal: the wide float, four lanes, and the few operations the wide contact solver needs
// (contact_solver_wide.c). This is the one place with SIMD intrinsics: SSE2 where the compiler
// targets it (every x86-64 compiler does), otherwise four plain floats. Each lane of every
// operation is the IEEE single-precision result of the scalar expression written beside it, so
// the two implementations give bit-identical results: max and min keep the scalar rule
// `a > b ? a : b` (MAXPS returns its second operand when the comparison is false, NaN included),
// and there is no fused multiply-add, reciprocal estimate or other approximation.
#pragma once

#include <stdint.h>

#if !defined(TB_SIMD_NONE) && (defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2))
#define TB_SIMD_SSE2 1
#include <emmintrin.h>
#endif

#define TB_SIMD_WIDTH 4

#if defined(TB_SIMD_SSE2)

typedef __m128 tbFloatW;

static inline tbFloatW tbZeroW(void)
{
	return _mm_setzero_ps();
}

static inline tbFloatW tbSplatW(float a)
{
	return _mm_set1_ps(a);
}

static inline tbFloatW tbAddW(tbFloatW a, tbFloatW b)
{
	return _mm_add_ps(a, b);
}

static inline tbFloatW tbSubW(tbFloatW a, tbFloatW b)
{
	return _mm_sub_ps(a, b);
}

static inline tbFloatW tbMulW(tbFloatW a, tbFloatW b)
{
	return _mm_mul_ps(a, b);
}

/// a > b ? a : b per lane
static inline tbFloatW tbMaxW(tbFloatW a, tbFloatW b)
{
	return _mm_max_ps(a, b);
}

/// a < b ? a : b per lane
static inline tbFloatW tbMinW(tbFloatW a, tbFloatW b)
{
	return _mm_min_ps(a, b);
}

/// a > b ? ifTrue : ifFalse per lane
static inline tbFloatW tbSelectGreaterW(tbFloatW a, tbFloatW b, tbFloatW ifTrue, tbFloatW ifFalse)
{
	__m128 mask = _mm_cmpgt_ps(a, b);
	return _mm_or_ps(_mm_and_ps(mask, ifTrue), _mm_andnot_ps(mask, ifFalse));
}

/// Loads lanes 0..3 from four 16-byte rows and transposes: out[k] lane i = rows[i][k].
static inline void tbLoadTransposeW(const float* row0, const float* row1, const float* row2, const float* row3,
									tbFloatW out[4])
{
	__m128 r0 = _mm_loadu_ps(row0), r1 = _mm_loadu_ps(row1);
	__m128 r2 = _mm_loadu_ps(row2), r3 = _mm_loadu_ps(row3);
	_MM_TRANSPOSE4_PS(r0, r1, r2, r3);
	out[0] = r0, out[1] = r1, out[2] = r2, out[3] = r3;
}

/// The inverse of tbLoadTransposeW: rows[i][k] = in[k] lane i, stored in the order row 0..3.
static inline void tbTransposeStoreW(float* row0, float* row1, float* row2, float* row3, const tbFloatW in[4])
{
	__m128 r0 = in[0], r1 = in[1], r2 = in[2], r3 = in[3];
	_MM_TRANSPOSE4_PS(r0, r1, r2, r3);
	_mm_storeu_ps(row0, r0);
	_mm_storeu_ps(row1, r1);
	_mm_storeu_ps(row2, r2);
	_mm_storeu_ps(row3, r3);
}

static inline float tbLaneW(tbFloatW a, int lane)
{
	float values[4];
	_mm_storeu_ps(values, a);
	return values[lane];
}

static inline tbFloatW tbSetLaneW(tbFloatW a, int lane, float value)
{
	float values[4];
	_mm_storeu_ps(values, a);
	values[lane] = value;
	return _mm_loadu_ps(values);
}

#else // four plain floats: the portable reference, same results lane by lane

typedef struct tbFloatW
{
	float v[4];
} tbFloatW;

static inline tbFloatW tbZeroW(void)
{
	tbFloatW r = {{0.0f, 0.0f, 0.0f, 0.0f}};
	return r;
}

static inline tbFloatW tbSplatW(float a)
{
	tbFloatW r = {{a, a, a, a}};
	return r;
}

#define TB_LANEWISE(EXPR)                                                                                              \
	tbFloatW r;                                                                                                        \
	for (int i = 0; i < 4; ++i)                                                                                        \
	{                                                                                                                  \
		r.v[i] = (EXPR);                                                                                               \
	}                                                                                                                  \
	return r

static inline tbFloatW tbAddW(tbFloatW a, tbFloatW b)
{
	TB_LANEWISE(a.v[i] + b.v[i]);
}

static inline tbFloatW tbSubW(tbFloatW a, tbFloatW b)
{
	TB_LANEWISE(a.v[i] - b.v[i]);
}

static inline tbFloatW tbMulW(tbFloatW a, tbFloatW b)
{
	TB_LANEWISE(a.v[i] * b.v[i]);
}

static inline tbFloatW tbMaxW(tbFloatW a, tbFloatW b)
{
	TB_LANEWISE(a.v[i] > b.v[i] ? a.v[i] : b.v[i]);
}

static inline tbFloatW tbMinW(tbFloatW a, tbFloatW b)
{
	TB_LANEWISE(a.v[i] < b.v[i] ? a.v[i] : b.v[i]);
}

static inline tbFloatW tbSelectGreaterW(tbFloatW a, tbFloatW b, tbFloatW ifTrue, tbFloatW ifFalse)
{
	TB_LANEWISE(a.v[i] > b.v[i] ? ifTrue.v[i] : ifFalse.v[i]);
}

#undef TB_LANEWISE

static inline void tbLoadTransposeW(const float* row0, const float* row1, const float* row2, const float* row3,
									tbFloatW out[4])
{
	const float* rows[4] = {row0, row1, row2, row3};
	for (int k = 0; k < 4; ++k)
	{
		for (int i = 0; i < 4; ++i)
		{
			out[k].v[i] = rows[i][k];
		}
	}
}

static inline void tbTransposeStoreW(float* row0, float* row1, float* row2, float* row3, const tbFloatW in[4])
{
	float* rows[4] = {row0, row1, row2, row3};
	for (int i = 0; i < 4; ++i)
	{
		for (int k = 0; k < 4; ++k)
		{
			rows[i][k] = in[k].v[i];
		}
	}
}

static inline float tbLaneW(tbFloatW a, int lane)
{
	return a.v[lane];
}

static inline tbFloatW tbSetLaneW(tbFloatW a, int lane, float value)
{
	a.v[lane] = value;
	return a;
}

#endif

/// a·b + c·d per lane, evaluated as (a·b) + (c·d): the scalar order, no fused multiply-add.
static inline tbFloatW tbMulAddPairW(tbFloatW a, tbFloatW b, tbFloatW c, tbFloatW d)
{
	return tbAddW(tbMulW(a, b), tbMulW(c, d));
}
