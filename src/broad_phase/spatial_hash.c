// Spatial-hash broad phase: a uniform grid of square cells, hashed into buckets so that only cells
// holding something take memory (Teschner et al. 2003, "Optimized spatial hashing for collision
// detection of deformable objects"; Ericson 2005, "Real-Time Collision Detection", §7.1).
//
// Every proxy is entered in each cell its fat box covers. Two boxes that overlap share at least
// the cell holding the lower corner of their overlap, max(lowerA, lowerB): a pair met in several
// cells is reported only from that one, so each query reports it once. Each moved proxy looks at
// the cells it covers; when both proxies of a pair moved, the one with the larger key reports it
// (as the tree does), and the broad phase sorts the pairs, so the set is the tree's exactly.
//
// Cost: the movable grid is brought up to date once its proxies have moved (at the end of the step
// or at the next FindPairs): each moved proxy whose cells changed leaves its old cells and enters
// its new ones, O(entries of the moved proxies); it is built afresh, O(entries) over every movable
// proxy, when movable proxies came or went, the cell size changed, a large proxy moved, or more than
// a quarter of them moved. The static grid is built only when a static proxy changes. A query
// visits the entries of its cells, a ray cast those of the cells along the ray. It suits many
// bodies of one size: with cells twice the typical box, a box covers one to four cells and meets
// only its near neighbours. It suits mixed sizes badly: a box much larger than a cell covers many
// cells, and small boxes in a large cell all meet each other. A proxy covering more than
// TB_HASH_MAX_CELLS cells is kept apart in a "large" list that every query tests directly (a long
// static ground, a big kinematic), so it does not fill thousands of cells.
//
// Cell size: twice the median of the movable proxies' largest box side (their fat boxes), chosen
// when the first proxies are hashed and re-chosen every TB_HASH_RESIZE_INTERVAL updates when the
// median has drifted by more than a factor of two (a new size rebuilds the static grid, so it is
// not re-chosen for small drifts).
//
// Rejected (measured on the junkyard, 8,000 pentagons pushed around): a bucket's entries laid out
// together (a counting sort instead of the chain), each carrying its proxy's box, so that a pair
// query reads one run per cell and visits the table only for boxes that overlap. The pair update
// gained, but the two-pass build doubled the grid's rebuild at the end of the step, a larger
// share, and the step came out slower. The box in the chained entries alone made them larger and
// the pair update slower. The chain's scattered entries are the price of a one-pass build.

#include "spatial_hash.h"

#include "brute_force.h"
#include "core/core.h"
#include "core/sort.h"

#include <math.h>
#include <string.h>

/// A proxy covering more cells than this is "large" (tested directly, not hashed).
#define TB_HASH_MAX_CELLS 16
/// Cell size over the median largest box side of the movable proxies.
#define TB_HASH_CELL_FACTOR 2.0f
/// Updates between checks of the cell size.
#define TB_HASH_RESIZE_INTERVAL 64
/// Cell coordinates are clamped to ±2^30 (beyond TB_MAX_COORDINATE over any useful cell; a large
/// world's positions can reach the clamp, where boxes share the clamped cells).
#define TB_HASH_COORD_LIMIT 1073741824.0f
/// A ray walks the cells only within this many cells of the origin (2^16): farther out a cell
/// boundary the walk computes, (cell + 1)·size − origin, is off by a float step of the coordinate,
/// which can carry it into the wrong neighbour of a corner (and past the clamp, into cells that
/// hold nothing), so the ray scans the table instead.
#define TB_HASH_RAY_CELL_LIMIT 65536.0f

typedef struct tbCellEntry
{
	int64_t cell;
	int key;
	int next;	///< next entry in the bucket (or in the free list), or −1
	int x0, y0; ///< the proxy's lowest cell (tbCellsOf), for the pair query's lower-corner test
} tbCellEntry;

/// Cells hashed into a power-of-two number of buckets, each a chain of entries.
typedef struct tbGrid
{
	int* heads;
	int headCount;
	tbCellEntry* entries;
	int entryCount; ///< entries handed out, freed ones included
	int entryCapacity;
	int freeEntry; ///< first entry freed by a proxy that left its cells, or −1
	int* large; ///< keys of the large proxies
	int largeCount;
	int largeCapacity;
	int* all; ///< keys of every proxy in the grid (a query too large for cells scans these)
	int allCount;
	int allCapacity;
} tbGrid;

typedef struct tbCellRange
{
	int x0, y0, x1, y1;
} tbCellRange;

struct tbSpatialHash
{
	float* sides; ///< scratch for the cell size (grown only)
	int sideCapacity;
	float cellSize;
	float invCellSize;
	tbGrid staticGrid;
	tbGrid movableGrid;
	bool staticDirty;
	int updateCount;
	/// Keys of the movable proxies in ascending order (the order of a scan of the table), remade
	/// when one is added or removed: the movable grid is built afresh from them whenever many of
	/// its proxies moved, and scanning the whole table for it cost a step in proportion to the
	/// static level (a car on a long terrain).
	int* movableKeys;
	int movableCount;
	int movableCapacity;
	bool movableDirty;
	/// The movable grid holds every movable proxy where its box is now: no movable proxy was added,
	/// removed or moved since it was built, nor the cell size changed. Queries and ray casts then
	/// look up cells instead of scanning the table, and the next update need not rebuild it.
	bool movableGridCurrent;
	/// By proxy key, the cells of each movable proxy as the movable grid holds it (valid while
	/// movableGridFiled): a moved proxy's pair query reads its range here instead of converting its
	/// box again, and the grid's update compares it with the proxy's cells now.
	tbCellRange* movableRanges;
	int movableRangeCapacity;
	/// The movable grid holds the same movable proxies as the table, each in the cells of its range
	/// above; what has moved since is listed in movedKeys. False when movable proxies came or went,
	/// the cell size changed or the list overflowed: the grid is then built afresh.
	bool movableGridFiled;
	int* movedKeys; ///< movable proxies moved since the grid was current (a key may repeat)
	int movedCount;
	int movedCapacity;
};

/// floor(value / cell size) clamped to ±TB_HASH_COORD_LIMIT. Clamped first, then floored: the limit
/// is a whole number, so the order does not change the result, and within it the integer part
/// fits an int. floor(s) is the truncation less one where truncating rounded up (s < 0 and not
/// whole); the truncation is exact in float. Without SSE4.1, floorf is a branchy sequence the
/// compiler inlines for every coordinate of every box the hash files, and this is called four
/// times a box for every moving shape in every step.
static int tbCellCoordinate(float value, float invCellSize)
{
	float s = value * invCellSize;
	s = s < -TB_HASH_COORD_LIMIT ? -TB_HASH_COORD_LIMIT : (s > TB_HASH_COORD_LIMIT ? TB_HASH_COORD_LIMIT : s);
	if (s != s)
	{
		return 0; // NaN boxes are refused upstream; stay defined anyway
	}
	int truncated = (int)s;
	return truncated - (s < (float)truncated ? 1 : 0);
}

static tbCellRange tbCellsOf(const tbSpatialHash* hash, tbAABB box)
{
	tbCellRange r;
	r.x0 = tbCellCoordinate(box.lowerBound.x, hash->invCellSize);
	r.y0 = tbCellCoordinate(box.lowerBound.y, hash->invCellSize);
	r.x1 = tbCellCoordinate(box.upperBound.x, hash->invCellSize);
	r.y1 = tbCellCoordinate(box.upperBound.y, hash->invCellSize);
	return r;
}

static int64_t tbCellKey(int x, int y)
{
	return (int64_t)(((uint64_t)(uint32_t)x << 32) | (uint64_t)(uint32_t)y);
}

static bool tbIsLargeRange(tbCellRange r)
{
	int64_t count = ((int64_t)r.x1 - r.x0 + 1) * ((int64_t)r.y1 - r.y0 + 1);
	return count > TB_HASH_MAX_CELLS;
}

static int tbBucketOf(const tbGrid* grid, int64_t cell)
{
	// Fibonacci hashing of the 64-bit cell key (Knuth, TAOCP vol. 3, §6.4).
	uint64_t h = (uint64_t)cell * UINT64_C(0x9E3779B97F4A7C15);
	return (int)((h >> 32) & (uint64_t)(grid->headCount - 1));
}

// --------------------------------------------------------------------------------------------
// Grids

static void tbGrid_Destroy(tbGrid* grid)
{
	tbFree(grid->heads, grid->headCount * (int)sizeof(int));
	tbFree(grid->entries, grid->entryCapacity * (int)sizeof(tbCellEntry));
	tbFree(grid->large, grid->largeCapacity * (int)sizeof(int));
	tbFree(grid->all, grid->allCapacity * (int)sizeof(int));
	memset(grid, 0, sizeof(*grid));
}

static void tbGrid_Clear(tbGrid* grid, int expectedEntries)
{
	int heads = 64;
	while (heads < 2 * expectedEntries)
	{
		heads *= 2;
	}
	if (heads > grid->headCount) // grow only: a settled scene steps without allocating
	{
		tbFree(grid->heads, grid->headCount * (int)sizeof(int));
		grid->heads = tbAlloc(heads * (int)sizeof(int));
		grid->headCount = heads;
	}
	memset(grid->heads, 0xff, (size_t)grid->headCount * sizeof(int)); // every head −1
	grid->entryCount = 0;
	grid->freeEntry = -1;
	grid->largeCount = 0;
	grid->allCount = 0;
}

static void tbPushKey(int** keys, int* count, int* capacity, int key)
{
	if (*count == *capacity)
	{
		int n = *capacity;
		int m = tbMaxInt(16, 2 * n);
		*keys = tbGrowAlloc(*keys, n * (int)sizeof(int), m * (int)sizeof(int));
		*capacity = m;
	}
	(*keys)[(*count)++] = key;
}

static void tbGrid_AddLarge(tbGrid* grid, int key)
{
	tbPushKey(&grid->large, &grid->largeCount, &grid->largeCapacity, key);
}

/// A new entry's index: a freed one if any (tbGrid_RemoveEntry), else one past the last, the array
/// grown by doubling.
static int tbGrid_NewEntry(tbGrid* grid)
{
	int index = grid->freeEntry;
	if (index >= 0)
	{
		grid->freeEntry = grid->entries[index].next;
		return index;
	}
	if (grid->entryCount == grid->entryCapacity)
	{
		int n = grid->entryCapacity;
		int m = tbMaxInt(256, 2 * n);
		grid->entries = tbGrowAlloc(grid->entries, n * (int)sizeof(tbCellEntry), m * (int)sizeof(tbCellEntry));
		grid->entryCapacity = m;
	}
	return grid->entryCount++;
}

static void tbGrid_AddEntry(tbGrid* grid, int64_t cell, int key, tbCellRange r)
{
	int index = tbGrid_NewEntry(grid);
	int bucket = tbBucketOf(grid, cell);
	grid->entries[index] = (tbCellEntry){cell, key, grid->heads[bucket], r.x0, r.y0};
	grid->heads[bucket] = index;
}

/// Enter one proxy in the cells its box covers (or the large list).
static void tbGrid_AddProxyCells(tbGrid* grid, int key, tbCellRange r)
{
	tbPushKey(&grid->all, &grid->allCount, &grid->allCapacity, key);
	if (tbIsLargeRange(r))
	{
		tbGrid_AddLarge(grid, key);
		return;
	}
	for (int x = r.x0; x <= r.x1; ++x)
	{
		for (int y = r.y0; y <= r.y1; ++y)
		{
			tbGrid_AddEntry(grid, tbCellKey(x, y), key, r);
		}
	}
}

static void tbGrid_AddProxy(tbGrid* grid, const tbSpatialHash* hash, const tbProxyTable* table, int key)
{
	tbGrid_AddProxyCells(grid, key, tbCellsOf(hash, table->proxies[key].aabb));
}

/// Hash every live static proxy into the static grid (when the statics change).
static void tbGrid_BuildStatic(tbGrid* grid, const tbSpatialHash* hash, const tbProxyTable* table)
{
	tbGrid_Clear(grid, 2 * table->count);
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		if (p->isFree == false && p->type == tb_proxyStatic)
		{
			tbGrid_AddProxy(grid, hash, table, key);
		}
	}
}

/// The movable keys listed again from the table, when a movable proxy came or went.
static void tbListMovableKeys(tbSpatialHash* hash, const tbProxyTable* table)
{
	hash->movableCount = 0;
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		if (p->isFree == false && p->type != tb_proxyStatic)
		{
			tbPushKey(&hash->movableKeys, &hash->movableCount, &hash->movableCapacity, key);
		}
	}
	hash->movableDirty = false;
}

/// Hash every movable proxy into the movable grid afresh (tbUpdateMovableGrid says when). Its buckets
/// are sized for the movable proxies alone; the order of entries within a cell does not depend on it.
static void tbGrid_BuildMovable(tbGrid* grid, tbSpatialHash* hash, const tbProxyTable* table)
{
	if (hash->movableDirty)
	{
		tbListMovableKeys(hash, table);
	}
	tbGrid_Clear(grid, 2 * hash->movableCount);
	if (table->capacity > hash->movableRangeCapacity)
	{
		int capacity = tbMaxInt(table->capacity, 2 * hash->movableRangeCapacity);
		tbFree(hash->movableRanges, hash->movableRangeCapacity * (int)sizeof(tbCellRange));
		hash->movableRanges = tbAlloc(capacity * (int)sizeof(tbCellRange));
		hash->movableRangeCapacity = capacity;
	}
	for (int i = 0; i < hash->movableCount; ++i)
	{
		int key = hash->movableKeys[i];
		tbCellRange r = tbCellsOf(hash, table->proxies[key].aabb);
		hash->movableRanges[key] = r;
		tbGrid_AddProxyCells(grid, key, r);
	}
	hash->movableGridCurrent = true;
	hash->movableGridFiled = true;
	hash->movedCount = 0;
}

/// Whether entry e comes before (key, x, y) in a bucket: a build files the proxies in ascending key
/// order, each one's cells x-major in ascending order, and puts each entry at the head of its bucket,
/// so a bucket lists its entries in descending (key, x, y) order. An entry filed later goes where
/// that order puts it, and the grid stays the one a build would make: the same entries in the same
/// order in every bucket, so queries and ray casts meet the proxies in the same order.
static bool tbEntryPrecedes(const tbCellEntry* e, int key, int x, int y)
{
	int ex = (int)(uint32_t)((uint64_t)e->cell >> 32), ey = (int)(uint32_t)(uint64_t)e->cell;
	return e->key != key ? e->key > key : (ex != x ? ex > x : ey > y);
}

/// Enter a proxy in one cell at its place in the bucket (tbEntryPrecedes).
static void tbGrid_InsertEntry(tbGrid* grid, int x, int y, int key, tbCellRange r)
{
	int index = tbGrid_NewEntry(grid);
	int64_t cell = tbCellKey(x, y);
	int* link = grid->heads + tbBucketOf(grid, cell);
	while (*link >= 0 && tbEntryPrecedes(grid->entries + *link, key, x, y))
	{
		link = &grid->entries[*link].next;
	}
	grid->entries[index] = (tbCellEntry){cell, key, *link, r.x0, r.y0};
	*link = index;
}

/// Take a proxy out of one cell; its entry goes to the free list.
static void tbGrid_RemoveEntry(tbGrid* grid, int64_t cell, int key)
{
	int* link = grid->heads + tbBucketOf(grid, cell);
	while (*link >= 0 && (grid->entries[*link].cell != cell || grid->entries[*link].key != key))
	{
		link = &grid->entries[*link].next;
	}
	int index = *link;
	TB_ASSERT(index >= 0);
	*link = grid->entries[index].next;
	grid->entries[index].next = grid->freeEntry;
	grid->freeEntry = index;
}

/// A moved movable proxy filed again where its box is now, when its cells changed. False when the
/// grid cannot take the move in place (the proxy is no longer a live movable one, or it is large
/// before or after: the large list is in key order too, and rare): the caller builds it afresh.
static bool tbRefileMovableProxy(tbGrid* grid, tbSpatialHash* hash, const tbProxyTable* table, int key)
{
	const tbBroadProxy* p = table->proxies + key;
	if (p->isFree || p->type == tb_proxyStatic)
	{
		return false;
	}
	tbCellRange old = hash->movableRanges[key];
	tbCellRange r = tbCellsOf(hash, p->aabb);
	if (r.x0 == old.x0 && r.y0 == old.y0 && r.x1 == old.x1 && r.y1 == old.y1)
	{
		return true; // the same cells: the entries (cells and lowest cell) are the same
	}
	if (tbIsLargeRange(old) || tbIsLargeRange(r))
	{
		return false;
	}
	for (int x = old.x0; x <= old.x1; ++x)
	{
		for (int y = old.y0; y <= old.y1; ++y)
		{
			tbGrid_RemoveEntry(grid, tbCellKey(x, y), key);
		}
	}
	for (int x = r.x0; x <= r.x1; ++x)
	{
		for (int y = r.y0; y <= r.y1; ++y)
		{
			tbGrid_InsertEntry(grid, x, y, key, r);
		}
	}
	hash->movableRanges[key] = r;
	return true;
}

/// The movable grid brought up to date: the moved proxies filed again in place when the grid still
/// holds the table's movable proxies and few moved, else built afresh (the same grid either way).
static void tbUpdateMovableGrid(tbGrid* grid, tbSpatialHash* hash, const tbProxyTable* table)
{
	if (hash->movableGridCurrent)
	{
		return;
	}
	bool inPlace = hash->movableGridFiled && hash->movableDirty == false;
	for (int i = 0; i < hash->movedCount && inPlace; ++i)
	{
		inPlace = tbRefileMovableProxy(grid, hash, table, hash->movedKeys[i]);
	}
	if (inPlace == false)
	{
		tbGrid_BuildMovable(grid, hash, table);
		return;
	}
	hash->movedCount = 0;
	hash->movableGridCurrent = true;
}

// --------------------------------------------------------------------------------------------
// Cell size

/// Twice the median largest side of the movable (else all) proxies' boxes; 1 m without proxies.
static float tbChooseCellSize(tbSpatialHash* hash, const tbProxyTable* table)
{
	int n = 0;
	if (table->count > hash->sideCapacity)
	{
		int capacity = tbMaxInt(table->count, 2 * hash->sideCapacity);
		hash->sides = tbGrowAlloc(hash->sides, hash->sideCapacity * (int)sizeof(float), capacity * (int)sizeof(float));
		hash->sideCapacity = capacity;
	}
	float* sides = hash->sides;
	for (int pass = 0; pass < 2 && n == 0; ++pass)
	{
		for (int key = 0; key < table->capacity; ++key)
		{
			const tbBroadProxy* p = table->proxies + key;
			if (p->isFree || (pass == 0 && p->type == tb_proxyStatic))
			{
				continue;
			}
			tbVec2 d = tbSub(p->aabb.upperBound, p->aabb.lowerBound);
			sides[n++] = tbMaxFloat(d.x, d.y);
		}
	}
	float size = 1.0f;
	if (n > 0)
	{
		tbSortFloats(sides, n);
		size = TB_HASH_CELL_FACTOR * sides[n / 2];
	}
	return size > 1e-3f && size < 1e6f ? size : 1.0f;
}

static void tbUpdateCellSize(tbSpatialHash* hash, const tbProxyTable* table)
{
	if (hash->cellSize > 0.0f && hash->updateCount % TB_HASH_RESIZE_INTERVAL != 0)
	{
		return;
	}
	float size = tbChooseCellSize(hash, table);
	if (hash->cellSize <= 0.0f || size > 2.0f * hash->cellSize || 2.0f * size < hash->cellSize)
	{
		hash->cellSize = size;
		hash->invCellSize = 1.0f / size;
		hash->staticDirty = true;
		hash->movableGridCurrent = false;
		hash->movableGridFiled = false;
	}
}

// --------------------------------------------------------------------------------------------
// Lifetime

tbSpatialHash* tbSpatialHash_Create(void)
{
	tbSpatialHash* hash = tbAlloc((int)sizeof(tbSpatialHash));
	memset(hash, 0, sizeof(*hash));
	hash->staticDirty = true;
	hash->movableDirty = true;
	hash->staticGrid.freeEntry = -1;
	hash->movableGrid.freeEntry = -1;
	return hash;
}

void tbSpatialHash_Destroy(tbSpatialHash* hash)
{
	tbGrid_Destroy(&hash->staticGrid);
	tbGrid_Destroy(&hash->movableGrid);
	tbFree(hash->sides, hash->sideCapacity * (int)sizeof(float));
	tbFree(hash->movableKeys, hash->movableCapacity * (int)sizeof(int));
	tbFree(hash->movableRanges, hash->movableRangeCapacity * (int)sizeof(tbCellRange));
	tbFree(hash->movedKeys, hash->movedCapacity * (int)sizeof(int));
	tbFree(hash, (int)sizeof(tbSpatialHash));
}

void tbSpatialHash_AddProxy(tbSpatialHash* hash, const tbProxyTable* table, int proxyKey)
{
	bool isStatic = table->proxies[proxyKey].type == tb_proxyStatic;
	hash->staticDirty = hash->staticDirty || isStatic;
	hash->movableDirty = hash->movableDirty || isStatic == false;
	hash->movableGridCurrent = hash->movableGridCurrent && isStatic;
	hash->movableGridFiled = hash->movableGridFiled && isStatic;
}

void tbSpatialHash_RemoveProxy(tbSpatialHash* hash, const tbProxyTable* table, int proxyKey)
{
	bool isStatic = table->proxies[proxyKey].type == tb_proxyStatic;
	hash->staticDirty = hash->staticDirty || isStatic;
	hash->movableDirty = hash->movableDirty || isStatic == false;
	hash->movableGridCurrent = hash->movableGridCurrent && isStatic;
	hash->movableGridFiled = hash->movableGridFiled && isStatic;
}

void tbSpatialHash_MoveStaticProxy(tbSpatialHash* hash)
{
	hash->staticDirty = true;
}

void tbSpatialHash_MoveMovableProxy(tbSpatialHash* hash, int proxyKey)
{
	hash->movableGridCurrent = false;
	if (hash->movableGridFiled == false)
	{
		return;
	}
	// More than a quarter of the movable proxies moved: building the grid afresh costs about what
	// filing them again would, and the list need not grow.
	if (4 * hash->movedCount >= hash->movableCount)
	{
		hash->movableGridFiled = false;
		hash->movedCount = 0;
		return;
	}
	tbPushKey(&hash->movedKeys, &hash->movedCount, &hash->movedCapacity, proxyKey);
}

void tbSpatialHash_Refresh(tbSpatialHash* hash, const tbProxyTable* table)
{
	if (hash->cellSize <= 0.0f)
	{
		return; // no update yet: the first one chooses the cell size
	}
	if (hash->staticDirty)
	{
		tbGrid_BuildStatic(&hash->staticGrid, hash, table);
		hash->staticDirty = false;
	}
	tbUpdateMovableGrid(&hash->movableGrid, hash, table);
}

tbSpatialHashState tbSpatialHash_GetState(const tbSpatialHash* hash)
{
	tbSpatialHashState state = {hash->cellSize, hash->staticDirty, hash->updateCount};
	return state;
}

void tbSpatialHash_SetState(tbSpatialHash* hash, const tbProxyTable* table, tbSpatialHashState state)
{
	hash->cellSize = state.cellSize;
	hash->invCellSize = state.cellSize > 0.0f ? 1.0f / state.cellSize : 0.0f;
	hash->staticDirty = state.staticDirty;
	hash->updateCount = state.updateCount;
	hash->movableDirty = true;
	hash->movableGridCurrent = false;
	hash->movableGridFiled = false;
	if (hash->staticDirty == false && hash->cellSize > 0.0f)
	{
		tbGrid_BuildStatic(&hash->staticGrid, hash, table);
	}
}

// --------------------------------------------------------------------------------------------
// Pairs

typedef struct tbPairQuery
{
	const tbSpatialHash* hash;
	const tbProxyTable* table;
	tbPairList* pairs;
	int key;
	const tbBroadProxy* proxy;
} tbPairQuery;

/// Report (query, other) unless it is not a pair, or the other query reports it.
static TB_FORCE_INLINE void tbConsider(const tbPairQuery* q, int otherKey)
{
	if (otherKey == q->key)
	{
		return;
	}
	const tbBroadProxy* other = q->table->proxies + otherKey;
	if (other->moveIndex >= 0 && otherKey > q->key)
	{
		return; // both moved: the larger key reports it
	}
	if (other->type == tb_proxyStatic && q->proxy->type == tb_proxyStatic)
	{
		return;
	}
	if (tbAABB_Overlaps(q->proxy->aabb, other->aabb))
	{
		tbPairList_Add(q->pairs, q->table, q->key, otherKey);
	}
}

/// The entries of one cell: each pair is reported only from the cell holding its overlap's lower
/// corner, max(lowerA, lowerB). Its cell is max(cell(lowerA), cell(lowerB)) coordinate by
/// coordinate, since the cell coordinate (a product by a positive factor, floored and clamped) never
/// decreases as the value grows: so the test compares the two proxies' lowest cells, (x0, y0) of the
/// query and of the entry, without converting a coordinate per entry.
static void tbConsiderCell(const tbPairQuery* q, const tbGrid* grid, int x, int y, int x0, int y0)
{
	int64_t cell = tbCellKey(x, y);
	for (int e = grid->heads[tbBucketOf(grid, cell)]; e >= 0; e = grid->entries[e].next)
	{
		const tbCellEntry* entry = grid->entries + e;
		if (entry->cell == cell && tbMaxInt(x0, entry->x0) == x && tbMaxInt(y0, entry->y0) == y)
		{
			tbConsider(q, entry->key);
		}
	}
}

static void tbConsiderLarge(const tbPairQuery* q, const tbGrid* grid)
{
	for (int i = 0; i < grid->largeCount; ++i)
	{
		tbConsider(q, grid->large[i]);
	}
}

static void tbQueryMoved(const tbSpatialHash* hash, const tbProxyTable* table, tbPairList* pairs, int key)
{
	const tbBroadProxy* p = table->proxies + key;
	tbPairQuery q = {hash, table, pairs, key, p};
	bool isStatic = p->type == tb_proxyStatic;
	// A movable proxy's cells as the current movable grid filed it (PrepareFind built it after the
	// last move): the same range, without converting the box again.
	tbCellRange r = isStatic == false && hash->movableGridCurrent ? hash->movableRanges[key] : tbCellsOf(hash, p->aabb);
	if (tbIsLargeRange(r))
	{
		// A large proxy meets everything it overlaps: scan the table.
		for (int other = 0; other < table->capacity; ++other)
		{
			if (table->proxies[other].isFree == false)
			{
				tbConsider(&q, other);
			}
		}
		return;
	}
	for (int x = r.x0; x <= r.x1; ++x)
	{
		for (int y = r.y0; y <= r.y1; ++y)
		{
			tbConsiderCell(&q, &hash->movableGrid, x, y, r.x0, r.y0);
			if (isStatic == false)
			{
				tbConsiderCell(&q, &hash->staticGrid, x, y, r.x0, r.y0);
			}
		}
	}
	tbConsiderLarge(&q, &hash->movableGrid);
	if (isStatic == false)
	{
		tbConsiderLarge(&q, &hash->staticGrid);
	}
}

void tbSpatialHash_PrepareFind(tbSpatialHash* hash, const tbProxyTable* table)
{
	tbUpdateCellSize(hash, table);
	if (hash->staticDirty)
	{
		tbGrid_BuildStatic(&hash->staticGrid, hash, table);
		hash->staticDirty = false;
	}
	tbUpdateMovableGrid(&hash->movableGrid, hash, table);
	hash->updateCount += 1;
}

void tbSpatialHash_QueryMoved(const tbSpatialHash* hash, const tbProxyTable* table, tbPairList* pairs, int proxyKey)
{
	tbQueryMoved(hash, table, pairs, proxyKey);
}

void tbSpatialHash_FindPairs(tbSpatialHash* hash, const tbProxyTable* table, tbPairList* pairs)
{
	tbSpatialHash_PrepareFind(hash, table);
	for (int key = 0; key < table->capacity; ++key)
	{
		if (table->proxies[key].isFree == false && table->proxies[key].moveIndex >= 0)
		{
			tbQueryMoved(hash, table, pairs, key);
		}
	}
}

// --------------------------------------------------------------------------------------------
// Queries

typedef struct tbBoxQuery
{
	const tbSpatialHash* hash;
	const tbProxyTable* table;
	tbAABB aabb;
	uint64_t maskBits;
	tbProxyQueryFcn* callback;
	void* context;
} tbBoxQuery;

/// Call back for one proxy if its box and bits match; false when the callback asks to stop.
static bool tbVisit(const tbBoxQuery* q, int key)
{
	const tbBroadProxy* p = q->table->proxies + key;
	if ((p->categoryBits & q->maskBits) == 0 || tbAABB_Overlaps(p->aabb, q->aabb) == false)
	{
		return true;
	}
	return q->callback(key, p->shapeIndex, q->context);
}

/// The proxies of a current grid that the query box meets: each once, from its overlap's lower
/// corner (tbConsiderCell). r: the query box's cells; a box covering too many cells scans the grid's
/// list of proxies instead.
static bool tbQueryGrid(const tbBoxQuery* q, const tbGrid* grid, tbCellRange r)
{
	if (tbIsLargeRange(r))
	{
		for (int i = 0; i < grid->allCount; ++i)
		{
			if (tbVisit(q, grid->all[i]) == false)
			{
				return false;
			}
		}
		return true;
	}
	for (int i = 0; i < grid->largeCount; ++i)
	{
		if (tbVisit(q, grid->large[i]) == false)
		{
			return false;
		}
	}
	for (int x = r.x0; x <= r.x1; ++x)
	{
		for (int y = r.y0; y <= r.y1; ++y)
		{
			int64_t cell = tbCellKey(x, y);
			for (int e = grid->heads[tbBucketOf(grid, cell)]; e >= 0; e = grid->entries[e].next)
			{
				const tbCellEntry* entry = grid->entries + e;
				int rx = tbMaxInt(r.x0, entry->x0);
				int ry = tbMaxInt(r.y0, entry->y0);
				if (entry->cell == cell && rx == x && ry == y && tbVisit(q, entry->key) == false)
				{
					return false;
				}
			}
		}
	}
	return true;
}

void tbSpatialHash_Query(const tbSpatialHash* hash, const tbProxyTable* table, tbAABB aabb, uint64_t maskBits,
						 bool staticOnly, tbProxyQueryFcn* callback, void* context)
{
	tbBoxQuery q = {hash, table, aabb, maskBits, callback, context};
	// Each grid is looked up when it is current: the static one unless a static proxy changed since
	// the last update; the movable one unless a movable proxy did (the step rebuilds it once its
	// proxies have moved: tbSpatialHash_Refresh). Otherwise the table is scanned.
	bool staticCurrent = hash->staticDirty == false && hash->cellSize > 0.0f;
	bool movableCurrent = hash->movableGridCurrent && hash->cellSize > 0.0f;
	tbCellRange cells = staticCurrent || movableCurrent ? tbCellsOf(hash, aabb) : (tbCellRange){0, 0, 0, 0};
	if (staticCurrent && tbQueryGrid(&q, &hash->staticGrid, cells) == false)
	{
		return;
	}
	if (staticOnly && staticCurrent)
	{
		return;
	}
	if (staticOnly == false && movableCurrent)
	{
		if (tbQueryGrid(&q, &hash->movableGrid, cells) == false)
		{
			return;
		}
		if (staticCurrent)
		{
			return;
		}
	}
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		bool isStatic = p->type == tb_proxyStatic;
		if (p->isFree || (staticCurrent && isStatic) || (isStatic == false && (staticOnly || movableCurrent)))
		{
			continue;
		}
		if (tbVisit(&q, key) == false)
		{
			return;
		}
	}
}

/// A ray through a grid's cells (Amanatides and Woo, "A fast voxel traversal algorithm for ray
/// tracing", 1987): the cells it crosses in order, each proxy reported in the first of its cells the
/// ray reaches (the ray's cells within a proxy's range of cells are consecutive: a segment meets a
/// rectangle in one piece). Every proxy of both grids is reported once; the callback's clipping
/// shortens the walk.
typedef struct tbRayWalk
{
	const tbSpatialHash* hash;
	const tbProxyTable* table;
	tbRayCastInput input; ///< maxFraction clipped by the callback
	uint64_t maskBits;
	tbProxyRayCastFcn* callback;
	void* context;
	bool stopped;
} tbRayWalk;

static void tbRayVisit(tbRayWalk* w, int key)
{
	const tbBroadProxy* p = w->table->proxies + key;
	if ((p->categoryBits & w->maskBits) == 0 ||
		tbSegmentHitsBox(w->input.origin, w->input.translation, w->input.maxFraction, p->aabb) == false)
	{
		return;
	}
	float value = w->callback(&w->input, key, p->shapeIndex, w->context);
	if (value == 0.0f)
	{
		w->stopped = true;
	}
	else if (0.0f < value && value < w->input.maxFraction)
	{
		w->input.maxFraction = value;
	}
}

/// The entries of one cell the ray reaches. A proxy's range of cells is that of its box as hashed (the
/// grid is current: the table holds that box), found only for entries the previous cell might share:
/// the entries keep their lowest cell alone, which keeps the grid small for the pair updates.
static void tbRayVisitCell(tbRayWalk* w, const tbGrid* grid, int x, int y, int px, int py, bool first)
{
	int64_t cell = tbCellKey(x, y);
	for (int e = grid->heads[tbBucketOf(grid, cell)]; e >= 0 && w->stopped == false; e = grid->entries[e].next)
	{
		const tbCellEntry* entry = grid->entries + e;
		if (entry->cell != cell)
		{
			continue;
		}
		bool seen = false;
		if (first == false && entry->x0 <= px && entry->y0 <= py)
		{
			tbCellRange r = tbCellsOf(w->hash, w->table->proxies[entry->key].aabb);
			seen = px <= r.x1 && py <= r.y1;
		}
		if (seen == false)
		{
			tbRayVisit(w, entry->key);
		}
	}
}

/// Cells along one axis: the first boundary crossed (as a fraction of the ray) and the fraction
/// between boundaries; infinite when the ray does not move along the axis.
static void tbRayAxis(float origin, float direction, int cell, float cellSize, int* step, float* next, float* delta)
{
	if (direction > 0.0f)
	{
		*step = 1;
		*next = ((float)(cell + 1) * cellSize - origin) / direction;
		*delta = cellSize / direction;
	}
	else if (direction < 0.0f)
	{
		*step = -1;
		*next = ((float)cell * cellSize - origin) / direction;
		*delta = -cellSize / direction;
	}
	else
	{
		*step = 0;
		*next = INFINITY;
		*delta = INFINITY;
	}
}

bool tbSpatialHash_RayCast(const tbSpatialHash* hash, const tbProxyTable* table, const tbRayCastInput* input,
						   uint64_t maskBits, tbProxyRayCastFcn* callback, void* context)
{
	if (hash->staticDirty || hash->movableGridCurrent == false || hash->cellSize <= 0.0f)
	{
		return false;
	}
	tbVec2 p = input->origin, d = input->translation;
	tbVec2 end = tbMulAdd(p, input->maxFraction, d);
	float reach = tbMaxFloat(tbMaxFloat(tbAbsFloat(p.x), tbAbsFloat(p.y)), tbMaxFloat(tbAbsFloat(end.x), tbAbsFloat(end.y)));
	if (!(reach * hash->invCellSize < TB_HASH_RAY_CELL_LIMIT))
	{
		return false; // far from the origin (or not finite): see TB_HASH_RAY_CELL_LIMIT
	}
	tbCellRange span = tbCellsOf(hash, (tbAABB){tbMin(p, end), tbMax(p, end)});
	int64_t crossed = ((int64_t)span.x1 - span.x0 + 1) + ((int64_t)span.y1 - span.y0 + 1);
	if (crossed > (int64_t)hash->staticGrid.allCount + hash->movableGrid.allCount)
	{
		return false; // a ray crossing more cells than there are proxies: the scan is cheaper
	}
	tbRayWalk w = {hash, table, *input, maskBits, callback, context, false};
	const tbGrid* grids[2] = {&hash->staticGrid, &hash->movableGrid};
	for (int g = 0; g < 2 && w.stopped == false; ++g)
	{
		for (int i = 0; i < grids[g]->largeCount && w.stopped == false; ++i)
		{
			tbRayVisit(&w, grids[g]->large[i]);
		}
	}
	int x = tbCellCoordinate(p.x, hash->invCellSize), y = tbCellCoordinate(p.y, hash->invCellSize);
	int stepX, stepY;
	float nextX, nextY, deltaX, deltaY;
	tbRayAxis(p.x, d.x, x, hash->cellSize, &stepX, &nextX, &deltaX);
	tbRayAxis(p.y, d.y, y, hash->cellSize, &stepY, &nextY, &deltaY);
	int px = x, py = y;
	// At most the cells of the span (each step moves one cell along one axis); the bound also ends
	// a walk that rounding would carry past its last cell.
	for (int64_t n = 0; n < crossed && w.stopped == false; ++n)
	{
		for (int g = 0; g < 2 && w.stopped == false; ++g)
		{
			tbRayVisitCell(&w, grids[g], x, y, px, py, n == 0);
		}
		float t = nextX < nextY ? nextX : nextY;
		if (!(t <= w.input.maxFraction))
		{
			break; // the next cell begins beyond the (clipped) ray
		}
		px = x, py = y;
		if (nextX < nextY)
		{
			x += stepX;
			nextX += deltaX;
		}
		else
		{
			y += stepY;
			nextY += deltaY;
		}
	}
	return true;
}

// --------------------------------------------------------------------------------------------
// Validation

static bool tbGridHolds(const tbGrid* grid, int64_t cell, int key)
{
	for (int e = grid->heads[tbBucketOf(grid, cell)]; e >= 0; e = grid->entries[e].next)
	{
		if (grid->entries[e].cell == cell && grid->entries[e].key == key)
		{
			return true;
		}
	}
	return false;
}

static bool tbLargeHolds(const tbGrid* grid, int key)
{
	for (int i = 0; i < grid->largeCount; ++i)
	{
		if (grid->large[i] == key)
		{
			return true;
		}
	}
	return false;
}

/// Whether a grid holds the proxy in every cell its box covers (or in its large list).
static bool tbGridHoldsProxy(const tbSpatialHash* hash, const tbGrid* grid, const tbBroadProxy* p, int key)
{
	tbCellRange r = tbCellsOf(hash, p->aabb);
	if (tbIsLargeRange(r))
	{
		return tbLargeHolds(grid, key);
	}
	for (int x = r.x0; x <= r.x1; ++x)
	{
		for (int y = r.y0; y <= r.y1; ++y)
		{
			if (tbGridHolds(grid, tbCellKey(x, y), key) == false)
			{
				return false;
			}
		}
	}
	return true;
}

/// Each grid that claims to be current holds every proxy of its kind where its box is now.
bool tbSpatialHash_Validate(const tbSpatialHash* hash, const tbProxyTable* table)
{
	if (hash->cellSize <= 0.0f)
	{
		return true; // rebuilt before it is next used
	}
	bool staticCurrent = hash->staticDirty == false;
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		if (p->isFree)
		{
			continue;
		}
		bool isStatic = p->type == tb_proxyStatic;
		if (isStatic && staticCurrent && tbGridHoldsProxy(hash, &hash->staticGrid, p, key) == false)
		{
			return false;
		}
		if (isStatic == false && hash->movableGridCurrent && tbGridHoldsProxy(hash, &hash->movableGrid, p, key) == false)
		{
			return false;
		}
	}
	return true;
}
