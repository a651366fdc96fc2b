// Brute-force broad phase: test every pair of proxies, O(n²). It is the ground truth for the tree
// and sort-and-sweep: it has no state to get wrong and no pruning to be wrong about.
//
// To keep n² tests cheap, each FindPairs copies the live proxies into structure-of-arrays form
// (four float arrays of bounds plus a flag byte), so the inner loop is four comparisons over
// contiguous memory. Two boxes overlap unless separated on an axis (touching counts, as in
// tbAABB_Overlaps): !(a.lo > b.hi || b.lo > a.hi) on x and on y. Only then are the moved/static
// flags looked at, because overlaps are rare next to tests.

#include "brute_force.h"

#include "core/core.h"

#include <stdint.h>
#include <string.h>

/// Flag bits of the structure-of-arrays copy.
enum
{
	tb_bruteMoved = 1,
	tb_bruteStatic = 2,
};

struct tbBruteForce
{
	float* lowerX;
	float* lowerY;
	float* upperX;
	float* upperY;
	int* keys;
	uint8_t* flags;
	int capacity;
};

tbBruteForce* tbBruteForce_Create(void)
{
	tbBruteForce* brute = tbAlloc((int)sizeof(tbBruteForce));
	memset(brute, 0, sizeof(*brute));
	return brute;
}

static void tbFreeBruteArrays(tbBruteForce* brute)
{
	int n = brute->capacity;
	tbFree(brute->lowerX, n * (int)sizeof(float));
	tbFree(brute->lowerY, n * (int)sizeof(float));
	tbFree(brute->upperX, n * (int)sizeof(float));
	tbFree(brute->upperY, n * (int)sizeof(float));
	tbFree(brute->keys, n * (int)sizeof(int));
	tbFree(brute->flags, n * (int)sizeof(uint8_t));
}

void tbBruteForce_Destroy(tbBruteForce* brute)
{
	tbFreeBruteArrays(brute);
	tbFree(brute, (int)sizeof(tbBruteForce));
}

void tbBruteForce_AddProxy(tbBruteForce* brute, const tbProxyTable* table, int proxyKey)
{
	(void)brute;
	(void)table;
	(void)proxyKey;
}

void tbBruteForce_RemoveProxy(tbBruteForce* brute, int proxyKey)
{
	(void)brute;
	(void)proxyKey;
}

static void tbReserveBrute(tbBruteForce* brute, int count)
{
	if (count <= brute->capacity)
	{
		return;
	}
	tbFreeBruteArrays(brute);
	int n = count + count / 2;
	brute->lowerX = tbAlloc(n * (int)sizeof(float));
	brute->lowerY = tbAlloc(n * (int)sizeof(float));
	brute->upperX = tbAlloc(n * (int)sizeof(float));
	brute->upperY = tbAlloc(n * (int)sizeof(float));
	brute->keys = tbAlloc(n * (int)sizeof(int));
	brute->flags = tbAlloc(n * (int)sizeof(uint8_t));
	brute->capacity = n;
}

/// Copy the live proxies into the structure of arrays; returns their number.
static int tbGatherProxies(tbBruteForce* brute, const tbProxyTable* table)
{
	tbReserveBrute(brute, table->count);
	int n = 0;
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		if (p->isFree)
		{
			continue;
		}
		brute->lowerX[n] = p->aabb.lowerBound.x;
		brute->lowerY[n] = p->aabb.lowerBound.y;
		brute->upperX[n] = p->aabb.upperBound.x;
		brute->upperY[n] = p->aabb.upperBound.y;
		brute->keys[n] = key;
		brute->flags[n] = (uint8_t)((p->moveIndex >= 0 ? tb_bruteMoved : 0) | (p->type == tb_proxyStatic ? tb_bruteStatic : 0));
		n += 1;
	}
	return n;
}

void tbBruteForce_FindPairs(tbBruteForce* brute, const tbProxyTable* table, tbPairList* pairs)
{
	int n = tbGatherProxies(brute, table);
	const float* lx = brute->lowerX;
	const float* ly = brute->lowerY;
	const float* ux = brute->upperX;
	const float* uy = brute->upperY;
	const uint8_t* flags = brute->flags;
	for (int i = 0; i < n; ++i)
	{
		float lxi = lx[i], lyi = ly[i], uxi = ux[i], uyi = uy[i];
		int fi = flags[i];
		for (int j = i + 1; j < n; ++j)
		{
			// Bitwise & (not &&): four branch-free comparisons, one branch.
			int overlap = (lx[j] <= uxi) & (lxi <= ux[j]) & (ly[j] <= uyi) & (lyi <= uy[j]);
			if (overlap == 0)
			{
				continue;
			}
			int fj = flags[j];
			if (((fi | fj) & tb_bruteMoved) && ((fi & fj & tb_bruteStatic) == 0))
			{
				tbPairList_Add(pairs, table, brute->keys[i], brute->keys[j]);
			}
		}
	}
}

void tbBruteForce_Query(const tbProxyTable* table, tbAABB aabb, uint64_t maskBits, tbProxyQueryFcn* callback,
						void* context)
{
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		if (p->isFree || (p->categoryBits & maskBits) == 0 || tbAABB_Overlaps(p->aabb, aabb) == false)
		{
			continue;
		}
		if (callback(key, p->shapeIndex, context) == false)
		{
			return;
		}
	}
}

/// Clip the parameter interval [t0, t1] of p + t·d to the slab lower ≤ x ≤ upper on one axis
/// (Kay & Kajiya 1986 slabs; Ericson 2005, §5.3.3). False when the interval becomes empty.
static bool tbClipSlab(float p, float d, float lower, float upper, float* t0, float* t1)
{
	if (d == 0.0f)
	{
		return lower <= p && p <= upper; // parallel: inside the slab or never
	}
	float inverse = 1.0f / d;
	float a = (lower - p) * inverse;
	float b = (upper - p) * inverse;
	*t0 = tbMaxFloat(*t0, tbMinFloat(a, b));
	*t1 = tbMinFloat(*t1, tbMaxFloat(a, b));
	return *t0 <= *t1;
}

bool tbSegmentHitsBox(tbVec2 p, tbVec2 d, float maxFraction, tbAABB box)
{
	float t0 = 0.0f, t1 = maxFraction;
	return tbClipSlab(p.x, d.x, box.lowerBound.x, box.upperBound.x, &t0, &t1) &&
		   tbClipSlab(p.y, d.y, box.lowerBound.y, box.upperBound.y, &t0, &t1);
}

void tbBruteForce_RayCast(const tbProxyTable* table, const tbRayCastInput* input, uint64_t maskBits,
						  tbProxyRayCastFcn* callback, void* context)
{
	tbRayCastInput subInput = *input;
	for (int key = 0; key < table->capacity; ++key)
	{
		const tbBroadProxy* p = table->proxies + key;
		if (p->isFree || (p->categoryBits & maskBits) == 0 ||
			tbSegmentHitsBox(input->origin, input->translation, subInput.maxFraction, p->aabb) == false)
		{
			continue;
		}
		float value = callback(&subInput, key, p->shapeIndex, context);
		if (value == 0.0f)
		{
			return;
		}
		if (0.0f < value && value < subInput.maxFraction)
		{
			subInput.maxFraction = value;
		}
	}
}

bool tbBruteForce_Validate(const tbBruteForce* brute, const tbProxyTable* table)
{
	(void)table;
	return brute != NULL;
}
