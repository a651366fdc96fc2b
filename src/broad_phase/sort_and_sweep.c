// Sort-and-sweep broad phase (Baraff 1992, "Dynamic simulation of non-penetrating rigid bodies",
// §6.4; Cohen, Lin, Manocha & Ponamgi 1995, I-COLLIDE).
//
// Two boxes overlap exactly when their intervals overlap on both axes. Project every box on one
// sweep axis as two endpoints (min, max) and keep the 2n endpoints sorted. Walking the sorted list
// with an "active" set (proxies whose min has been passed but not their max), the proxies active
// when p's min is reached are exactly those whose sweep interval contains p's min, so every
// overlapping pair on the sweep axis is seen once, from the later min; the other axis confirms.
// At equal values a min sorts before a max, so touching intervals overlap, as in tbAABB_Overlaps.
//
// Temporal coherence: between steps boxes move a little, so the list is nearly sorted and an
// insertion sort re-sorts it in O(n + swaps) (Baraff; I-COLLIDE). New proxies are appended and a
// large batch of them (or a change of axis) takes a full O(n log n) sort instead, as insertion
// sort would be O(n) per appended endpoint. Removed proxies leave dead endpoints that the next
// update compacts away.
//
// Sweep axis: the fewer intervals overlap on the sweep axis, the fewer candidates; we use the
// axis of largest variance of the box centres (the spread-out axis), re-checked every
// TB_SWEEP_AXIS_INTERVAL updates and switched only when the other axis's variance exceeds the
// current one's by the factor TB_SWEEP_AXIS_HYSTERESIS, so a scene spread evenly does not flip
// axes (each flip costs a full sort).
//
// Rejected: I-COLLIDE's incremental pair set (pairs toggled by each swap) — it must track every
// overlapping pair, and the contract asks only for pairs with a moved member, which a sweep finds
// directly by skipping candidates where neither proxy moved.

#include "sort_and_sweep.h"

#include "brute_force.h"
#include "core/core.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/// Updates between checks of the sweep axis: 16 (a variance pass is O(n), cheap next to the sweep).
#define TB_SWEEP_AXIS_INTERVAL 16

/// Switch axis only when the other axis's centre variance is 1.25 times the current one's.
#define TB_SWEEP_AXIS_HYSTERESIS 1.25

/// More appended endpoints than this since the last sort take a full sort: 64 appended
/// endpoints cost about 64·n moves by insertion, comparable with n·log2(n) for n ≈ 2^16.
#define TB_SWEEP_MAX_APPENDED 64

/// An endpoint: value on the sweep axis; id = 2·proxyKey + (1 for a max), or −1 when dead.
typedef struct tbEndpoint
{
	float value;
	int id;
} tbEndpoint;

/// A proxy in the active set, with its interval on the other axis.
typedef struct tbActiveProxy
{
	float lower, upper;
	int key;
	int flags;
} tbActiveProxy;

enum
{
	tb_sweepMoved = 1,
	tb_sweepStatic = 2,
};

struct tbSortAndSweep
{
	tbEndpoint* endpoints;
	int endpointCount;
	int endpointCapacity;

	// Index of each endpoint in `endpoints`, indexed by endpoint id; valid between updates.
	int* positions;
	// Slot of each proxy in the active set during the sweep, indexed by proxy key.
	int* activeSlots;
	int keyCapacity;

	tbActiveProxy* active;
	int activeCount;
	int activeCapacity;

	int axis;		   ///< 0: x, 1: y
	int updateCount;   ///< FindPairs calls so far
	int appendedCount; ///< endpoints appended since the last sort
	bool needsFullSort;
};

tbSortAndSweep* tbSortAndSweep_Create(void)
{
	tbSortAndSweep* sweep = tbAlloc((int)sizeof(tbSortAndSweep));
	memset(sweep, 0, sizeof(*sweep));
	sweep->needsFullSort = true;
	return sweep;
}

void tbSortAndSweep_Destroy(tbSortAndSweep* sweep)
{
	tbFree(sweep->endpoints, sweep->endpointCapacity * (int)sizeof(tbEndpoint));
	tbFree(sweep->positions, 2 * sweep->keyCapacity * (int)sizeof(int));
	tbFree(sweep->activeSlots, sweep->keyCapacity * (int)sizeof(int));
	tbFree(sweep->active, sweep->activeCapacity * (int)sizeof(tbActiveProxy));
	tbFree(sweep, (int)sizeof(tbSortAndSweep));
}

static void tbReserveKeys(tbSortAndSweep* sweep, int keyCount)
{
	if (keyCount <= sweep->keyCapacity)
	{
		return;
	}
	int n = sweep->keyCapacity;
	int m = tbMaxInt(keyCount, 2 * n);
	sweep->positions = tbGrowAlloc(sweep->positions, 2 * n * (int)sizeof(int), 2 * m * (int)sizeof(int));
	sweep->activeSlots = tbGrowAlloc(sweep->activeSlots, n * (int)sizeof(int), m * (int)sizeof(int));
	sweep->keyCapacity = m;
}

static float tbAxisValue(tbVec2 v, int axis)
{
	return axis == 0 ? v.x : v.y;
}

static float tbEndpointValue(const tbProxyTable* table, int id, int axis)
{
	const tbAABB* box = &table->proxies[id >> 1].aabb;
	return tbAxisValue((id & 1) ? box->upperBound : box->lowerBound, axis);
}

void tbSortAndSweep_AddProxy(tbSortAndSweep* sweep, const tbProxyTable* table, int proxyKey)
{
	tbReserveKeys(sweep, proxyKey + 1);
	if (sweep->endpointCount + 2 > sweep->endpointCapacity)
	{
		int n = sweep->endpointCapacity;
		int m = tbMaxInt(64, 2 * n);
		sweep->endpoints = tbGrowAlloc(sweep->endpoints, n * (int)sizeof(tbEndpoint), m * (int)sizeof(tbEndpoint));
		sweep->endpointCapacity = m;
	}
	for (int side = 0; side < 2; ++side)
	{
		int id = 2 * proxyKey + side;
		sweep->positions[id] = sweep->endpointCount;
		sweep->endpoints[sweep->endpointCount++] = (tbEndpoint){tbEndpointValue(table, id, sweep->axis), id};
	}
	sweep->appendedCount += 2;
}

void tbSortAndSweep_RemoveProxy(tbSortAndSweep* sweep, int proxyKey)
{
	TB_ASSERT(proxyKey < sweep->keyCapacity);
	sweep->endpoints[sweep->positions[2 * proxyKey]].id = -1;
	sweep->endpoints[sweep->positions[2 * proxyKey + 1]].id = -1;
}

// --------------------------------------------------------------------------------------------
// Axis choice

/// Variance of the box centres on an axis, Var = E[c²] − E[c]², in double to limit cancellation.
static double tbCentreVariance(const tbProxyTable* table, int axis)
{
	double sum = 0.0, sumSquares = 0.0;
	int n = 0;
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		if (p->isFree)
		{
			continue;
		}
		double c = 0.5 * ((double)tbAxisValue(p->aabb.lowerBound, axis) + (double)tbAxisValue(p->aabb.upperBound, axis));
		sum += c;
		sumSquares += c * c;
		n += 1;
	}
	if (n == 0)
	{
		return 0.0;
	}
	double mean = sum / n;
	return sumSquares / n - mean * mean;
}

static void tbUpdateSweepAxis(tbSortAndSweep* sweep, const tbProxyTable* table)
{
	bool firstUpdate = sweep->updateCount == 0;
	if (firstUpdate == false && sweep->updateCount % TB_SWEEP_AXIS_INTERVAL != 0)
	{
		return;
	}
	double current = tbCentreVariance(table, sweep->axis);
	double other = tbCentreVariance(table, 1 - sweep->axis);
	double threshold = firstUpdate ? 1.0 : TB_SWEEP_AXIS_HYSTERESIS;
	if (other > threshold * current)
	{
		sweep->axis = 1 - sweep->axis;
		sweep->needsFullSort = true;
	}
}

// --------------------------------------------------------------------------------------------
// Sorting

/// Endpoint order: by value, a min before a max at equal values (touching intervals overlap),
/// then by id so the order is total.
static bool tbEndpointLess(tbEndpoint a, tbEndpoint b)
{
	if (a.value != b.value)
	{
		return a.value < b.value;
	}
	if ((a.id & 1) != (b.id & 1))
	{
		return (a.id & 1) < (b.id & 1);
	}
	return a.id < b.id;
}

static int tbCompareEndpoints(const void* a, const void* b)
{
	tbEndpoint ea = *(const tbEndpoint*)a, eb = *(const tbEndpoint*)b;
	return tbEndpointLess(ea, eb) ? -1 : (tbEndpointLess(eb, ea) ? 1 : 0);
}

/// Drop dead endpoints (keeping order) and reload the values of the live ones on the sweep axis.
static void tbRefreshEndpoints(tbSortAndSweep* sweep, const tbProxyTable* table)
{
	int n = 0;
	for (int i = 0; i < sweep->endpointCount; ++i)
	{
		tbEndpoint e = sweep->endpoints[i];
		if (e.id < 0)
		{
			continue;
		}
		e.value = tbEndpointValue(table, e.id, sweep->axis);
		sweep->endpoints[n++] = e;
	}
	sweep->endpointCount = n;
}

/// Insertion sort: O(n + number of inversions), near linear when the list was sorted last step.
static void tbInsertionSortEndpoints(tbEndpoint* endpoints, int count)
{
	for (int i = 1; i < count; ++i)
	{
		tbEndpoint e = endpoints[i];
		int j = i - 1;
		while (j >= 0 && tbEndpointLess(e, endpoints[j]))
		{
			endpoints[j + 1] = endpoints[j];
			j -= 1;
		}
		endpoints[j + 1] = e;
	}
}

static void tbSortEndpoints(tbSortAndSweep* sweep)
{
	if (sweep->endpointCount < 2)
	{
		// nothing to order (and qsort may not be given the NULL array of an empty world)
	}
	else if (sweep->needsFullSort || sweep->appendedCount > TB_SWEEP_MAX_APPENDED)
	{
		qsort(sweep->endpoints, (size_t)sweep->endpointCount, sizeof(tbEndpoint), tbCompareEndpoints);
	}
	else
	{
		tbInsertionSortEndpoints(sweep->endpoints, sweep->endpointCount);
	}
	for (int i = 0; i < sweep->endpointCount; ++i)
	{
		sweep->positions[sweep->endpoints[i].id] = i;
	}
	sweep->needsFullSort = false;
	sweep->appendedCount = 0;
}

// --------------------------------------------------------------------------------------------
// Sweep

static void tbActivate(tbSortAndSweep* sweep, tbActiveProxy proxy)
{
	if (sweep->activeCount == sweep->activeCapacity)
	{
		int n = sweep->activeCapacity;
		int m = tbMaxInt(64, 2 * n);
		sweep->active = tbGrowAlloc(sweep->active, n * (int)sizeof(tbActiveProxy), m * (int)sizeof(tbActiveProxy));
		sweep->activeCapacity = m;
	}
	sweep->activeSlots[proxy.key] = sweep->activeCount;
	sweep->active[sweep->activeCount++] = proxy;
}

/// Remove from the active set by moving the last entry into the hole (order does not matter).
static void tbDeactivate(tbSortAndSweep* sweep, int key)
{
	int slot = sweep->activeSlots[key];
	tbActiveProxy last = sweep->active[--sweep->activeCount];
	sweep->active[slot] = last;
	sweep->activeSlots[last.key] = slot;
}

/// Pair the proxy whose min endpoint was reached with every active proxy overlapping it on the
/// other axis, when one of the two moved and they are not both static.
static void tbPairWithActive(const tbSortAndSweep* sweep, const tbProxyTable* table, tbPairList* pairs, tbActiveProxy p)
{
	for (int i = 0; i < sweep->activeCount; ++i)
	{
		const tbActiveProxy* q = sweep->active + i;
		if (q->lower > p.upper || p.lower > q->upper)
		{
			continue;
		}
		if (((p.flags | q->flags) & tb_sweepMoved) && (p.flags & q->flags & tb_sweepStatic) == 0)
		{
			tbPairList_Add(pairs, table, q->key, p.key);
		}
	}
}

static void tbSweepEndpoints(tbSortAndSweep* sweep, const tbProxyTable* table, tbPairList* pairs)
{
	int otherAxis = 1 - sweep->axis;
	sweep->activeCount = 0;
	for (int i = 0; i < sweep->endpointCount; ++i)
	{
		int id = sweep->endpoints[i].id;
		int key = id >> 1;
		if (id & 1)
		{
			tbDeactivate(sweep, key);
			continue;
		}
		const tbBroadProxy* proxy = table->proxies + key;
		tbActiveProxy p;
		p.lower = tbAxisValue(proxy->aabb.lowerBound, otherAxis);
		p.upper = tbAxisValue(proxy->aabb.upperBound, otherAxis);
		p.key = key;
		p.flags = (proxy->moveIndex >= 0 ? tb_sweepMoved : 0) | (proxy->type == tb_proxyStatic ? tb_sweepStatic : 0);
		tbPairWithActive(sweep, table, pairs, p);
		tbActivate(sweep, p);
	}
	TB_ASSERT(sweep->activeCount == 0);
}

void tbSortAndSweep_FindPairs(tbSortAndSweep* sweep, const tbProxyTable* table, tbPairList* pairs)
{
	tbReserveKeys(sweep, table->capacity);
	tbUpdateSweepAxis(sweep, table);
	tbRefreshEndpoints(sweep, table);
	tbSortEndpoints(sweep);
	tbSweepEndpoints(sweep, table, pairs);
	sweep->updateCount += 1;
}

void tbSortAndSweep_Query(const tbProxyTable* table, tbAABB aabb, uint64_t maskBits, tbProxyQueryFcn* callback,
						  void* context)
{
	tbBruteForce_Query(table, aabb, maskBits, callback, context);
}

void tbSortAndSweep_RayCast(const tbProxyTable* table, const tbRayCastInput* input, uint64_t maskBits,
							tbProxyRayCastFcn* callback, void* context)
{
	tbBruteForce_RayCast(table, input, maskBits, callback, context);
}

bool tbSortAndSweep_Validate(const tbSortAndSweep* sweep, const tbProxyTable* table)
{
	int live = 0;
	int sortedCount = sweep->endpointCount - sweep->appendedCount;
	const tbEndpoint* previous = NULL;
	for (int i = 0; i < sweep->endpointCount; ++i)
	{
		const tbEndpoint* e = sweep->endpoints + i;
		if (e->id < 0)
		{
			continue;
		}
		int key = e->id >> 1;
		if (key >= table->capacity || table->proxies[key].isFree || sweep->positions[e->id] != i)
		{
			return false;
		}
		if (i < sortedCount && previous != NULL && tbEndpointLess(*e, *previous))
		{
			return false;
		}
		previous = e;
		live += 1;
	}
	return live == 2 * table->count;
}
