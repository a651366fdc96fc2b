// Sorting of index arrays. Contact ids and the like are small non-negative ints, so a least-
// significant-digit radix sort (Knuth, TAOCP vol. 3, §5.2.5) with 8-bit digits sorts them in
// O(passes · n) with sequential memory traffic, where passes = bytes of the largest value (2 for
// fewer than 65,536 contacts). Each pass is a stable counting sort, so the whole sort is stable.
#include "sort.h"

#include <stdlib.h>
#include <string.h>

static void tbCountingPass(const int* in, int* out, int count, int shift)
{
	int offsets[256];
	memset(offsets, 0, sizeof(offsets));
	for (int i = 0; i < count; ++i)
	{
		offsets[(in[i] >> shift) & 0xff] += 1;
	}
	int total = 0;
	for (int d = 0; d < 256; ++d)
	{
		int n = offsets[d];
		offsets[d] = total;
		total += n;
	}
	for (int i = 0; i < count; ++i)
	{
		out[offsets[(in[i] >> shift) & 0xff]++] = in[i];
	}
}

void tbSortIndices(int* values, int count, int* scratch)
{
	int largest = 0;
	for (int i = 0; i < count; ++i)
	{
		largest = values[i] > largest ? values[i] : largest;
	}
	int* in = values;
	int* out = scratch;
	for (int shift = 0; shift < 32 && (largest >> shift) != 0; shift += 8)
	{
		tbCountingPass(in, out, count, shift);
		int* swap = in;
		in = out;
		out = swap;
	}
	if (in != values)
	{
		memcpy(values, in, (size_t)count * sizeof(int));
	}
}

static int tbCompareFloats(const void* a, const void* b)
{
	float x = *(const float*)a, y = *(const float*)b;
	return x < y ? -1 : (x > y ? 1 : 0);
}

void tbSortFloats(float* values, int count)
{
	qsort(values, (size_t)count, sizeof(float), tbCompareFloats);
}
