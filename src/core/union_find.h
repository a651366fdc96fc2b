// Internal: union–find over dense indices (Tarjan 1975, "Efficiency of a good but not linear set
// union algorithm"), for the groups the step finds from scratch: the sleep stage's islands
// (island.c) and the joints' mechanisms (constraint_graph.c). parent[i] = i makes i a group of its
// own; the caller owns the array and sets it up.
#pragma once

/// The root of i's group, halving the path on the way (each visited node is pointed at its
/// grandparent): near-constant amortised time with the linking below, and no recursion.
static inline int tbFindRoot(int* parent, int i)
{
	while (parent[i] != i)
	{
		parent[i] = parent[parent[i]];
		i = parent[i];
	}
	return i;
}

/// Joins the groups of a and b. The smaller root stays the root, so each group's root is its
/// smallest index whatever the order of the links: the groups, and the order they are met in,
/// depend only on which links there are.
static inline void tbLinkRoots(int* parent, int a, int b)
{
	a = tbFindRoot(parent, a);
	b = tbFindRoot(parent, b);
	if (a < b)
	{
		parent[b] = a;
	}
	else if (b < a)
	{
		parent[a] = b;
	}
}

/// Points every node straight at its group's root, in one pass. tbLinkRoots keeps each root the
/// smallest index of its group and path halving only moves a node to a smaller ancestor, so
/// parent[i] ≤ i always holds: by the time node i is met, its parent (a smaller index) already
/// points at the root, and one step from it reaches the root. Afterwards parent[i] is i's root, a
/// single load for every later question.
static inline void tbFlattenRoots(int* parent, int count)
{
	for (int i = 0; i < count; ++i)
	{
		parent[i] = parent[parent[i]];
	}
}
