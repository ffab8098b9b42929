// 2:1 balancing of the quadtree (thesis 5.2): side-adjacent leaves inside or on the boundary of
// the polygon differ by at most one level, so every leaf side carries at most one T-vertex.
#pragma once

#include "mesher/quadtree.h"

#include <vector>

namespace mesher {

// Splits coarse leaves until the tree is balanced around `seeds` (their neighbourhoods ripple
// as far as splitting forces). Work is proportional to the leaves split. Returns how many were.
// A leaf whose split would need levels the tree does not have (it holds a sharp corner whose
// edges run on close together, with the vertex just outside a child) stays whole: the tree is
// then unbalanced there, which leaf regions handle (all T-vertices on a side are anchored).
// The tree must be complete. Outside leaves take no part.
size_t balanceAround(Quadtree& tree, std::vector<int32_t> seeds);

// Balances the whole tree as built (buildQuadtree: no leaf coarser than its uniform depth, and
// its storage splits listed).
size_t balance(Quadtree& tree);

}  // namespace mesher
