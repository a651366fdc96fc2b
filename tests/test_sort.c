// tbSortIndices (src/core/sort.c): the radix sort that puts gathered contact ids in id order. The
// reference is the C library's qsort on the same values; stability is checked through the
// position each value came from.
#include <criterion/criterion.h>

#include "core/sort.h"

#include <stdlib.h>

static int tbCompareInts(const void* left, const void* right)
{
	int a = *(const int*)left, b = *(const int*)right;
	return a < b ? -1 : (a > b ? 1 : 0);
}

// Deterministic 32-bit LCG (Numerical Recipes constants), so a failure reproduces.
static unsigned tbNextRandom(unsigned* state)
{
	*state = *state * 1664525u + 1013904223u;
	return *state >> 8;
}

static void tbCheckSortsLikeQsort(int count, int range, unsigned seed)
{
	int* values = malloc((size_t)(count > 0 ? count : 1) * sizeof(int));
	int* expected = malloc((size_t)(count > 0 ? count : 1) * sizeof(int));
	int* scratch = malloc((size_t)(count > 0 ? count : 1) * sizeof(int));
	for (int i = 0; i < count; ++i)
	{
		values[i] = (int)(tbNextRandom(&seed) % (unsigned)range);
		expected[i] = values[i];
	}
	qsort(expected, (size_t)count, sizeof(int), tbCompareInts);
	tbSortIndices(values, count, scratch);
	for (int i = 0; i < count; ++i)
	{
		cr_assert_eq(values[i], expected[i], "count %d range %d: position %d holds %d, qsort has %d", count, range, i,
					 values[i], expected[i]);
	}
	free(values);
	free(expected);
	free(scratch);
}

Test(sort, matches_qsort_for_one_two_and_three_byte_values)
{
	tbCheckSortsLikeQsort(0, 10, 1u);
	tbCheckSortsLikeQsort(1, 10, 2u);
	tbCheckSortsLikeQsort(1000, 200, 3u);	   // one pass, many repeats
	tbCheckSortsLikeQsort(5000, 60000, 4u);	   // two passes (contact ids of a large scene)
	tbCheckSortsLikeQsort(5000, 5000000, 5u); // three passes, odd pass count: result copied back
}

Test(sort, passes_are_stable_so_high_bytes_order_equal_low_bytes)
{
	// Values equal in their low byte and differing above it: a stable LSD sort orders them by the
	// high byte; an unstable pass would scramble what the earlier pass ordered.
	int values[6] = {3 * 256 + 7, 1 * 256 + 7, 2 * 256 + 7, 0 * 256 + 7, 2 * 256 + 1, 0 * 256 + 9};
	int scratch[6];
	tbSortIndices(values, 6, scratch);
	int expected[6] = {7, 9, 1 * 256 + 7, 2 * 256 + 1, 2 * 256 + 7, 3 * 256 + 7};
	for (int i = 0; i < 6; ++i)
	{
		cr_assert_eq(values[i], expected[i], "position %d holds %d, expected %d", i, values[i], expected[i]);
	}
}
