// Internal: sorting of index arrays and of floats (sort.c).
#pragma once

/// Sort non-negative ints ascending in place (stable LSD radix sort, 8 bits per pass, as many
/// passes as the largest value needs). scratch holds count ints.
void tbSortIndices(int* values, int count, int* scratch);

/// Sort floats ascending in place (qsort; not stable, which equal floats do not show). For the
/// medians and percentiles of box sizes (the spatial hash's cell size, the automatic broad phase).
void tbSortFloats(float* values, int count);
