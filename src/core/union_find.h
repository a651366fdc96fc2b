// Internal: union–find over dense indices (Tarjan 1975, "Efficiency of a good but not linear set
// union algorithm"; the linking is Rem's, see tbLinkRoots), for the groups the step finds from
// scratch: the sleep stage's islands (island.c) and the joints' mechanisms (constraint_graph.c).
// parent[i] = i makes i a group of its own; the caller owns the array and sets it up.
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

/// Joins the groups of a and b, by Rem's splicing (Dijkstra 1976, "A Discipline of Programming",
/// ch. 23; measured the fastest union–find in practice by Patwary, Blair and Manne 2010): walk up
/// from whichever of a, b has the larger parent, pointing each node passed at the other's parent,
/// until the two meet or a root is reached, which then hangs under the other's parent. Parents only
/// ever get smaller (parent[i] ≤ i always holds), so each group's root is its smallest index
/// whatever the order of the links: the groups, and the order they are met in, depend only on which
/// links there are (and tbFindRoot reads the same roots as with find-and-link).
static inline void tbLinkRoots(int* parent, int a, int b)
{
	while (parent[a] != parent[b])
	{
		if (parent[a] < parent[b])
		{
			int t = a;
			a = b;
			b = t;
		}
		// parent[a] > parent[b]
		if (a == parent[a])
		{
			parent[a] = parent[b];
			return;
		}
		int next = parent[a];
		parent[a] = parent[b];
		a = next;
	}
}

/// Points every node straight at its group's root, in one pass. Linking (tbLinkRoots) and path
/// halving (tbFindRoot) only ever move a node to a smaller parent, so parent[i] ≤ i always holds:
/// by the time node i is met, its parent (a smaller index) already points at the root, and one
/// step from it reaches the root. Afterwards parent[i] is i's root, a single load for every later
/// question.
static inline void tbFlattenRoots(int* parent, int count)
{
	for (int i = 0; i < count; ++i)
	{
		parent[i] = parent[parent[i]];
	}
}
