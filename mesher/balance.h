// 2:1 balancing of the quadtree (thesis 5.2): side-adjacent leaves inside or on the boundary of
// the polygon differ by at most one level, so every leaf side carries at most one T-vertex.
#pragma once

#include "mesher/quadtree.h"

#include <optional>
#include <vector>

namespace mesher {

// Splits coarse leaves until the tree is balanced around `seeds` (their neighbourhoods ripple
// as far as splitting forces). Work is proportional to the leaves split. Returns how many were,
// or nothing when a split leaf's edges would need a level deeper than maxDepth (a sharp corner
// whose leaf had held it whole): the tree is then unusable and must be rebuilt deeper.
// The tree must be complete. Outside leaves take no part.
std::optional<size_t> balanceAround(Quadtree& tree, std::vector<int32_t> seeds);

// Balances the whole tree.
std::optional<size_t> balance(Quadtree& tree);

// A polygon's balanced tree (buildPolygonTree, then balance), built deeper when balancing splits
// a leaf that held a sharp corner whole and its edges then need more levels than the tree has.
// Throws std::invalid_argument as buildPolygonTree does.
PolygonTree buildBalancedTree(const PolygonWithHoles& polygon, double patchSize);

}  // namespace mesher
