// Internal: the wide float and the few operations the wide contact solver needs
// (contact_solver_wide.c). This is the one place with SIMD intrinsics: eight lanes of AVX2 when the
// build asks for it (CMake option TUMBLE_AVX2, which defines TB_SIMD_AVX2 and compiles with
// -mavx2), else four lanes of SSE2 where the compiler targets it (every x86-64 compiler does),
// otherwise four plain floats. Each lane of every operation is the IEEE single-precision result of
// the scalar expression written beside it, so the implementations give bit-identical results: max
// and min keep the scalar rule `a > b ? a : b` (MAXPS returns its second operand when the
// comparison is false, NaN included), and there is no fused multiply-add, reciprocal estimate or
// other approximation. The width does not change results either: the lanes of a block are
// contacts of one colour, which share no moving body, so how they are grouped is invisible.
#pragma once

#include <math.h>
#include <stdint.h>
#include <string.h>

// 32-bit MSVC is left out: it cannot pass more than three __m128 by value.
#if !defined(TB_SIMD_NONE) && (defined(__SSE2__) || defined(_M_X64))
#define TB_SIMD_SSE2 1
#include <emmintrin.h>
#elif !defined(TB_SIMD_NONE) && defined(__wasm_simd128__)
// WebAssembly's 128-bit SIMD (-msimd128): its lane arithmetic is IEEE single precision like SSE2's;
// its own min and max (NaN-propagating, or pmin/pmax) follow other rules, so the comparisons below
// select lanes with the scalar rule instead.
#define TB_SIMD_WASM 1
#include <wasm_simd128.h>
#endif

#if defined(TB_SIMD_AVX2) && !defined(TB_SIMD_NONE)
#if !defined(__AVX2__)
#error "TB_SIMD_AVX2 needs a compiler targeting AVX2 (-mavx2)"
#endif
#include <immintrin.h>
#define TB_SIMD_WIDTH 8
#else
#undef TB_SIMD_AVX2
#define TB_SIMD_WIDTH 4
#endif

#if defined(TB_SIMD_AVX2)

typedef __m256 tbFloatW;

static inline tbFloatW tbZeroW(void)
{
	return _mm256_setzero_ps();
}

static inline tbFloatW tbSplatW(float a)
{
	return _mm256_set1_ps(a);
}

static inline tbFloatW tbAddW(tbFloatW a, tbFloatW b)
{
	return _mm256_add_ps(a, b);
}

static inline tbFloatW tbSubW(tbFloatW a, tbFloatW b)
{
	return _mm256_sub_ps(a, b);
}

static inline tbFloatW tbMulW(tbFloatW a, tbFloatW b)
{
	return _mm256_mul_ps(a, b);
}

static inline tbFloatW tbDivW(tbFloatW a, tbFloatW b)
{
	return _mm256_div_ps(a, b);
}

static inline tbFloatW tbSqrtW(tbFloatW a)
{
	return _mm256_sqrt_ps(a);
}

/// Bit k set where lane k of a > lane k of b (false for NaN, as the scalar `>`).
static inline int tbGreaterMaskW(tbFloatW a, tbFloatW b)
{
	return _mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_GT_OQ));
}

/// a > b ? a : b per lane (VMAXPS returns its second operand when the comparison is false)
static inline tbFloatW tbMaxW(tbFloatW a, tbFloatW b)
{
	return _mm256_max_ps(a, b);
}

/// a < b ? a : b per lane
static inline tbFloatW tbMinW(tbFloatW a, tbFloatW b)
{
	return _mm256_min_ps(a, b);
}

/// a > b ? ifTrue : ifFalse per lane (ordered comparison: false for NaN, as the scalar `>`)
static inline tbFloatW tbSelectGreaterW(tbFloatW a, tbFloatW b, tbFloatW ifTrue, tbFloatW ifFalse)
{
	__m256 mask = _mm256_cmp_ps(a, b, _CMP_GT_OQ);
	return _mm256_blendv_ps(ifFalse, ifTrue, mask);
}

/// Loads eight rows of four floats (16 bytes each, any alignment) and transposes: out[k] lane i =
/// float k of row i. Two 4×4 transposes, rows 0–3 into the low halves and rows 4–7 into the high.
static inline void tbLoadTransposeRowsW(const void* const rows[TB_SIMD_WIDTH], tbFloatW out[4])
{
	__m128 a0 = _mm_loadu_ps((const float*)rows[0]), a1 = _mm_loadu_ps((const float*)rows[1]);
	__m128 a2 = _mm_loadu_ps((const float*)rows[2]), a3 = _mm_loadu_ps((const float*)rows[3]);
	__m128 b0 = _mm_loadu_ps((const float*)rows[4]), b1 = _mm_loadu_ps((const float*)rows[5]);
	__m128 b2 = _mm_loadu_ps((const float*)rows[6]), b3 = _mm_loadu_ps((const float*)rows[7]);
	_MM_TRANSPOSE4_PS(a0, a1, a2, a3);
	_MM_TRANSPOSE4_PS(b0, b1, b2, b3);
	out[0] = _mm256_set_m128(b0, a0);
	out[1] = _mm256_set_m128(b1, a1);
	out[2] = _mm256_set_m128(b2, a2);
	out[3] = _mm256_set_m128(b3, a3);
}

/// The inverse of tbLoadTransposeRowsW: row i, float k = in[k] lane i, for the rows whose bit is
/// set in `mask` (rows 0 to 7 in order; a row left out is a body that does not move).
static inline void tbTransposeStoreRowsW(void* const rows[TB_SIMD_WIDTH], const tbFloatW in[4], int mask)
{
	__m128 a0 = _mm256_castps256_ps128(in[0]), a1 = _mm256_castps256_ps128(in[1]);
	__m128 a2 = _mm256_castps256_ps128(in[2]), a3 = _mm256_castps256_ps128(in[3]);
	__m128 b0 = _mm256_extractf128_ps(in[0], 1), b1 = _mm256_extractf128_ps(in[1], 1);
	__m128 b2 = _mm256_extractf128_ps(in[2], 1), b3 = _mm256_extractf128_ps(in[3], 1);
	_MM_TRANSPOSE4_PS(a0, a1, a2, a3);
	_MM_TRANSPOSE4_PS(b0, b1, b2, b3);
	__m128 r[8] = {a0, a1, a2, a3, b0, b1, b2, b3};
	for (int i = 0; i < 8; ++i)
	{
		if (mask & (1 << i))
		{
			_mm_storeu_ps((float*)rows[i], r[i]);
		}
	}
}

/// Bit k set where lane k of a or of b is not zero.
static inline int tbNonZeroMaskW(tbFloatW a, tbFloatW b)
{
	__m256 zero = _mm256_setzero_ps();
	__m256 nonZero = _mm256_or_ps(_mm256_cmp_ps(a, zero, _CMP_NEQ_UQ), _mm256_cmp_ps(b, zero, _CMP_NEQ_UQ));
	return _mm256_movemask_ps(nonZero);
}

#elif defined(TB_SIMD_SSE2)

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

static inline tbFloatW tbDivW(tbFloatW a, tbFloatW b)
{
	return _mm_div_ps(a, b);
}

static inline tbFloatW tbSqrtW(tbFloatW a)
{
	return _mm_sqrt_ps(a);
}

static inline int tbGreaterMaskW(tbFloatW a, tbFloatW b)
{
	return _mm_movemask_ps(_mm_cmpgt_ps(a, b));
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

/// Loads four rows of four floats (16 bytes each, any alignment) and transposes:
/// out[k] lane i = float k of row i.
static inline void tbLoadTransposeW(const void* row0, const void* row1, const void* row2, const void* row3,
									tbFloatW out[4])
{
	__m128 r0 = _mm_loadu_ps((const float*)row0), r1 = _mm_loadu_ps((const float*)row1);
	__m128 r2 = _mm_loadu_ps((const float*)row2), r3 = _mm_loadu_ps((const float*)row3);
	_MM_TRANSPOSE4_PS(r0, r1, r2, r3);
	out[0] = r0, out[1] = r1, out[2] = r2, out[3] = r3;
}

/// The inverse of tbLoadTransposeW: float k of row i = in[k] lane i, stored row 0 to 3.
static inline void tbTransposeStoreW(void* row0, void* row1, void* row2, void* row3, const tbFloatW in[4])
{
	__m128 r0 = in[0], r1 = in[1], r2 = in[2], r3 = in[3];
	_MM_TRANSPOSE4_PS(r0, r1, r2, r3);
	_mm_storeu_ps((float*)row0, r0);
	_mm_storeu_ps((float*)row1, r1);
	_mm_storeu_ps((float*)row2, r2);
	_mm_storeu_ps((float*)row3, r3);
}

/// As tbTransposeStoreW, storing row k only where bit k of `mask` is set (the others are bodies
/// that do not move: several workers may hold them, so nobody writes them).
static inline void tbTransposeStoreMaskedW(void* row0, void* row1, void* row2, void* row3, const tbFloatW in[4],
										   int mask)
{
	__m128 r0 = in[0], r1 = in[1], r2 = in[2], r3 = in[3];
	_MM_TRANSPOSE4_PS(r0, r1, r2, r3);
	if (mask & 1)
	{
		_mm_storeu_ps((float*)row0, r0);
	}
	if (mask & 2)
	{
		_mm_storeu_ps((float*)row1, r1);
	}
	if (mask & 4)
	{
		_mm_storeu_ps((float*)row2, r2);
	}
	if (mask & 8)
	{
		_mm_storeu_ps((float*)row3, r3);
	}
}

/// Bit k set where lane k of a or of b is not zero.
static inline int tbNonZeroMaskW(tbFloatW a, tbFloatW b)
{
	__m128 zero = _mm_setzero_ps();
	return _mm_movemask_ps(_mm_or_ps(_mm_cmpneq_ps(a, zero), _mm_cmpneq_ps(b, zero)));
}

static inline void tbLoadTransposeRowsW(const void* const rows[TB_SIMD_WIDTH], tbFloatW out[4])
{
	tbLoadTransposeW(rows[0], rows[1], rows[2], rows[3], out);
}

static inline void tbTransposeStoreRowsW(void* const rows[TB_SIMD_WIDTH], const tbFloatW in[4], int mask)
{
	if (mask == 15)
	{
		tbTransposeStoreW(rows[0], rows[1], rows[2], rows[3], in);
		return;
	}
	tbTransposeStoreMaskedW(rows[0], rows[1], rows[2], rows[3], in, mask);
}

#elif defined(TB_SIMD_WASM)

typedef v128_t tbFloatW;

static inline tbFloatW tbZeroW(void)
{
	return wasm_f32x4_splat(0.0f);
}

static inline tbFloatW tbSplatW(float a)
{
	return wasm_f32x4_splat(a);
}

static inline tbFloatW tbAddW(tbFloatW a, tbFloatW b)
{
	return wasm_f32x4_add(a, b);
}

static inline tbFloatW tbSubW(tbFloatW a, tbFloatW b)
{
	return wasm_f32x4_sub(a, b);
}

static inline tbFloatW tbMulW(tbFloatW a, tbFloatW b)
{
	return wasm_f32x4_mul(a, b);
}

static inline tbFloatW tbDivW(tbFloatW a, tbFloatW b)
{
	return wasm_f32x4_div(a, b);
}

static inline tbFloatW tbSqrtW(tbFloatW a)
{
	return wasm_f32x4_sqrt(a);
}

static inline int tbGreaterMaskW(tbFloatW a, tbFloatW b)
{
	return (int)wasm_i32x4_bitmask(wasm_f32x4_gt(a, b));
}

/// a > b ? a : b per lane (bitselect takes its first operand where the mask is set)
static inline tbFloatW tbMaxW(tbFloatW a, tbFloatW b)
{
	return wasm_v128_bitselect(a, b, wasm_f32x4_gt(a, b));
}

/// a < b ? a : b per lane
static inline tbFloatW tbMinW(tbFloatW a, tbFloatW b)
{
	return wasm_v128_bitselect(a, b, wasm_f32x4_lt(a, b));
}

static inline tbFloatW tbSelectGreaterW(tbFloatW a, tbFloatW b, tbFloatW ifTrue, tbFloatW ifFalse)
{
	return wasm_v128_bitselect(ifTrue, ifFalse, wasm_f32x4_gt(a, b));
}

/// Rows of four floats in, columns out (the 4×4 transpose, in two rounds of interleaving).
static inline void tbLoadTransposeW(const void* row0, const void* row1, const void* row2, const void* row3,
									tbFloatW out[4])
{
	v128_t r0 = wasm_v128_load(row0), r1 = wasm_v128_load(row1);
	v128_t r2 = wasm_v128_load(row2), r3 = wasm_v128_load(row3);
	v128_t low01 = wasm_i32x4_shuffle(r0, r1, 0, 4, 1, 5), high01 = wasm_i32x4_shuffle(r0, r1, 2, 6, 3, 7);
	v128_t low23 = wasm_i32x4_shuffle(r2, r3, 0, 4, 1, 5), high23 = wasm_i32x4_shuffle(r2, r3, 2, 6, 3, 7);
	out[0] = wasm_i64x2_shuffle(low01, low23, 0, 2);
	out[1] = wasm_i64x2_shuffle(low01, low23, 1, 3);
	out[2] = wasm_i64x2_shuffle(high01, high23, 0, 2);
	out[3] = wasm_i64x2_shuffle(high01, high23, 1, 3);
}

static inline void tbTransposeStoreMaskedW(void* row0, void* row1, void* row2, void* row3, const tbFloatW in[4],
										   int mask)
{
	tbFloatW rows[4];
	tbLoadTransposeW(&in[0], &in[1], &in[2], &in[3], rows);
	void* targets[4] = {row0, row1, row2, row3};
	for (int i = 0; i < 4; ++i)
	{
		if (mask & (1 << i))
		{
			wasm_v128_store(targets[i], rows[i]);
		}
	}
}

static inline void tbTransposeStoreW(void* row0, void* row1, void* row2, void* row3, const tbFloatW in[4])
{
	tbTransposeStoreMaskedW(row0, row1, row2, row3, in, 15);
}

static inline int tbNonZeroMaskW(tbFloatW a, tbFloatW b)
{
	tbFloatW zero = wasm_f32x4_splat(0.0f);
	return (int)wasm_i32x4_bitmask(wasm_v128_or(wasm_f32x4_ne(a, zero), wasm_f32x4_ne(b, zero)));
}

static inline void tbLoadTransposeRowsW(const void* const rows[TB_SIMD_WIDTH], tbFloatW out[4])
{
	tbLoadTransposeW(rows[0], rows[1], rows[2], rows[3], out);
}

static inline void tbTransposeStoreRowsW(void* const rows[TB_SIMD_WIDTH], const tbFloatW in[4], int mask)
{
	tbTransposeStoreMaskedW(rows[0], rows[1], rows[2], rows[3], in, mask);
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

static inline tbFloatW tbDivW(tbFloatW a, tbFloatW b)
{
	TB_LANEWISE(a.v[i] / b.v[i]);
}

static inline tbFloatW tbSqrtW(tbFloatW a)
{
	TB_LANEWISE(sqrtf(a.v[i]));
}

static inline int tbGreaterMaskW(tbFloatW a, tbFloatW b)
{
	int mask = 0;
	for (int i = 0; i < 4; ++i)
	{
		mask |= a.v[i] > b.v[i] ? 1 << i : 0;
	}
	return mask;
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

static inline void tbLoadTransposeW(const void* row0, const void* row1, const void* row2, const void* row3,
									tbFloatW out[4])
{
	const void* rows[4] = {row0, row1, row2, row3};
	for (int i = 0; i < 4; ++i)
	{
		float row[4];
		memcpy(row, rows[i], sizeof(row));
		for (int k = 0; k < 4; ++k)
		{
			out[k].v[i] = row[k];
		}
	}
}

static inline void tbTransposeStoreW(void* row0, void* row1, void* row2, void* row3, const tbFloatW in[4])
{
	void* rows[4] = {row0, row1, row2, row3};
	for (int i = 0; i < 4; ++i)
	{
		float row[4] = {in[0].v[i], in[1].v[i], in[2].v[i], in[3].v[i]};
		memcpy(rows[i], row, sizeof(row));
	}
}

static inline void tbTransposeStoreMaskedW(void* row0, void* row1, void* row2, void* row3, const tbFloatW in[4],
										   int mask)
{
	void* rows[4] = {row0, row1, row2, row3};
	for (int i = 0; i < 4; ++i)
	{
		if (mask & (1 << i))
		{
			float row[4] = {in[0].v[i], in[1].v[i], in[2].v[i], in[3].v[i]};
			memcpy(rows[i], row, sizeof(row));
		}
	}
}

static inline int tbNonZeroMaskW(tbFloatW a, tbFloatW b)
{
	int mask = 0;
	for (int i = 0; i < 4; ++i)
	{
		mask |= (a.v[i] != 0.0f || b.v[i] != 0.0f) ? 1 << i : 0;
	}
	return mask;
}

static inline void tbLoadTransposeRowsW(const void* const rows[TB_SIMD_WIDTH], tbFloatW out[4])
{
	tbLoadTransposeW(rows[0], rows[1], rows[2], rows[3], out);
}

static inline void tbTransposeStoreRowsW(void* const rows[TB_SIMD_WIDTH], const tbFloatW in[4], int mask)
{
	tbTransposeStoreMaskedW(rows[0], rows[1], rows[2], rows[3], in, mask);
}

#endif

/// Every lane: the mask tbTransposeStoreRowsW takes to store all rows.
#define TB_ALL_LANES ((1 << TB_SIMD_WIDTH) - 1)

/// clamp(a, lower, upper) per lane with the scalar rule a < lower ? lower : (a > upper ? upper : a):
/// a NaN bound lets a through unchanged, as tbClampFloat does (min/max would return the bound).
static inline tbFloatW tbClampW(tbFloatW a, tbFloatW lower, tbFloatW upper)
{
	tbFloatW below = tbSelectGreaterW(a, upper, upper, a);
	return tbSelectGreaterW(lower, a, lower, below);
}

/// Lane `lane` of a wide float in memory, read or written through its bytes (well defined for
/// either representation; compilers turn the memcpy into one move).
static inline float tbGetLaneW(const tbFloatW* w, int lane)
{
	float value;
	memcpy(&value, (const char*)w + sizeof(float) * (size_t)lane, sizeof(float));
	return value;
}

static inline void tbSetLaneW(tbFloatW* w, int lane, float value)
{
	memcpy((char*)w + sizeof(float) * (size_t)lane, &value, sizeof(float));
}

/// a·b + c·d per lane, evaluated as (a·b) + (c·d): the scalar order, no fused multiply-add.
static inline tbFloatW tbMulAddPairW(tbFloatW a, tbFloatW b, tbFloatW c, tbFloatW d)
{
	return tbAddW(tbMulW(a, b), tbMulW(c, d));
}
