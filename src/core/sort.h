// Internal: sorting of index arrays (sort.c).
#pragma once

/// Sort non-negative ints ascending in place (stable LSD radix sort, 8 bits per pass, as many
/// passes as the largest value needs). scratch holds count ints.
void tbSortIndices(int* values, int count, int* scratch);
