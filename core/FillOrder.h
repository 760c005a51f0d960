#pragma once
// A fill-reducing elimination order (AMD) of a graph given by its adjacency
// lists, for the equation numbering (DofMap) and the block LU's node order.
#include <vector>

namespace c2d {

// adjacency[v]: the neighbours of v (both directions listed, duplicates
// allowed; sorted and made unique in place). Returns perm, perm[k] the vertex
// eliminated k-th, or an empty vector when the graph has no edge or AMD fails
// (the caller keeps its own order).
std::vector<int> fillReducingOrder(std::vector<std::vector<int>>& adjacency);

}  // namespace c2d
