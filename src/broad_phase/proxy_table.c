// The pair list the broad-phase methods append to (proxy_table.h).
#include "proxy_table.h"

#include "core/core.h"

void tbPairList_Add(tbPairList* list, const tbProxyTable* table, int proxyKeyA, int proxyKeyB)
{
	int a = table->proxies[proxyKeyA].shapeIndex;
	int b = table->proxies[proxyKeyB].shapeIndex;
	if (list->filter == NULL)
	{
		tbPairList_Append(list, a < b ? (tbShapePair){a, b} : (tbShapePair){b, a});
		return;
	}
	if (list->prefetch != NULL)
	{
		list->prefetch(a, b, list->filterContext);
	}
	list->pending[list->pendingCount++] = (tbShapePair){a, b};
	if (list->pendingCount == TB_PAIR_BATCH)
	{
		tbPairList_Flush(list);
	}
}

void tbPairList_Flush(tbPairList* list)
{
	for (int i = 0; i < list->pendingCount; ++i)
	{
		int a = list->pending[i].a, b = list->pending[i].b;
		if (list->filter(a, b, list->filterContext))
		{
			tbPairList_Append(list, a < b ? (tbShapePair){a, b} : (tbShapePair){b, a});
		}
	}
	list->pendingCount = 0;
}

void tbPairList_Append(tbPairList* list, tbShapePair pair)
{
	if (list->count == list->capacity)
	{
		int n = list->capacity;
		int m = tbMaxInt(64, 2 * n);
		list->pairs = tbGrowAlloc(list->pairs, n * (int)sizeof(tbShapePair), m * (int)sizeof(tbShapePair));
		list->capacity = m;
	}
	list->pairs[list->count++] = pair;
}

void tbPairList_Destroy(tbPairList* list)
{
	tbFree(list->pairs, list->capacity * (int)sizeof(tbShapePair));
	list->pairs = NULL;
	list->count = 0;
	list->capacity = 0;
}
