#include "mesher/balance.h"

#include <algorithm>

namespace mesher {

size_t balanceAround(Quadtree& tree, std::vector<int32_t> seeds) {
  size_t splits = 0;
  while (!seeds.empty()) {
    const int32_t q = seeds.back();
    seeds.pop_back();
    const Quadrant& leaf = tree[q];
    if (!leaf.isLeaf() || leaf.status == QuadStatus::Outside) continue;
    for (Side side : {Side::West, Side::East, Side::South, Side::North}) {
      // Only a coarser neighbour can be too coarse, and it is the one leaf across the side
      // (finer ones are the children of a node there).
      const int32_t n = tree.adjacent(q, side);
      if (n < 0) continue;
      const Quadrant& neighbor = tree[n];
      if (!neighbor.isLeaf() || neighbor.status == QuadStatus::Outside || neighbor.level >= tree[q].level - 1) continue;
      const size_t mark = tree.changes.size();
      if (!tree.splitLeaf(n)) {
        tree.undoChanges(mark);
        continue;
      }
      tree.quadrants[static_cast<size_t>(n)].forced = true;
      tree.leavesBelow(n, seeds);
      seeds.push_back(q);  // its neighbour there may still be too coarse
      ++splits;
    }
  }
  return splits;
}

size_t balance(Quadtree& tree) {
  // No leaf is coarser than the uniform depth, so only leaves two levels below it can have a
  // neighbour too coarse: those below the leaves of the uniform tree that the build split to
  // store a vertex or an edge. The rest of a large floor is not looked at. They are taken in
  // tree order: where a split leaves only outside leaves beside a coarse neighbour, that
  // neighbour need not be split, so the order decides the tree.
  std::vector<int32_t> split;
  for (int32_t q : tree.storageSplits)
    if (tree[q].level == tree.uniformDepth) split.push_back(q);
  std::sort(split.begin(), split.end(), [&](int32_t a, int32_t b) { return comesBefore(tree[a], tree[b]); });
  std::vector<int32_t> deep;
  for (int32_t q : split) tree.leavesBelow(q, deep);
  deep.erase(std::remove_if(deep.begin(), deep.end(), [&](int32_t q) { return tree[q].level < tree.uniformDepth + 2; }), deep.end());
  return balanceAround(tree, std::move(deep));
}

}  // namespace mesher
