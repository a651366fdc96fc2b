// Internal: growable arrays of plain data through tbAlloc/tbFree.
#pragma once

#include "core.h"

/// Ensure capacity for `needed` elements in a growable array (pointer, count, capacity).
#define TB_ARRAY_RESERVE(array, capacity, needed)                                                                      \
	do                                                                                                                 \
	{                                                                                                                  \
		if ((needed) > (capacity))                                                                                     \
		{                                                                                                              \
			int newCapacity_ = (capacity) < 16 ? 16 : (capacity);                                                      \
			while (newCapacity_ < (needed))                                                                            \
			{                                                                                                          \
				newCapacity_ *= 2;                                                                                     \
			}                                                                                                          \
			(array) = tbGrowAlloc((array), (capacity) * (int)sizeof(*(array)), newCapacity_ * (int)sizeof(*(array)));   \
			(capacity) = newCapacity_;                                                                                 \
		}                                                                                                              \
	} while (0)

/// Append one element.
#define TB_ARRAY_PUSH(array, count, capacity, value)                                                                   \
	do                                                                                                                 \
	{                                                                                                                  \
		TB_ARRAY_RESERVE(array, capacity, (count) + 1);                                                                \
		(array)[(count)++] = (value);                                                                                  \
	} while (0)

/// Release an array.
#define TB_ARRAY_FREE(array, capacity)                                                                                 \
	do                                                                                                                 \
	{                                                                                                                  \
		tbFree((array), (capacity) * (int)sizeof(*(array)));                                                           \
		(array) = NULL;                                                                                                \
		(capacity) = 0;                                                                                                \
	} while (0)
