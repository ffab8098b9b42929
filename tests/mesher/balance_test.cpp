#include "mesher/balance.h"

#include "tests/mesher/random_polygons.h"

#include <gtest/gtest.h>

#include <random>

namespace mesher {
namespace {

int levelGap(const Quadtree& tree) {
  int worst = 0;
  std::vector<int32_t> across;
  for (int32_t q : tree.leaves()) {
    if (tree[q].status == QuadStatus::Outside) continue;
    for (Side side : {Side::West, Side::East, Side::South, Side::North}) {
      across.clear();
      tree.neighbors(q, side, across);
      for (int32_t n : across)
        if (tree[n].status != QuadStatus::Outside) worst = std::max(worst, std::abs(tree[n].level - tree[q].level));
    }
  }
  return worst;
}

TEST(Balance, NeighboursDifferByAtMostOneLevel) {
  std::mt19937 random(11);
  int unbalancedBefore = 0;
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    PolygonTree built = buildPolygonTree(test::randomPolygonWithHoles(random, trial), 4 + trial % 30);
    unbalancedBefore += levelGap(built.tree) > 1;
    balance(built.tree);
    EXPECT_LE(levelGap(built.tree), 1);
  }
  EXPECT_GT(unbalancedBefore, 20);  // the random polygons do exercise balancing
}

// A deep leaf in the corner of a uniform tree's leaf, against the next leaf, ripples outward.
TEST(Balance, ADeepLeafRipplesOutward) {
  const PolygonWithHoles square{{{0, 0}, {64, 0}, {64, 64}, {0, 64}}, {}};
  PolygonTree built = buildPolygonTree(square, 16);  // 4 x 4 leaves
  int32_t q = built.tree.leafAt({1, 1});
  for (int i = 0; i < 5; ++i) {
    built.tree.splitLeaf(q);
    q = built.tree[q].firstChild + 3;  // the north-east child, toward the neighbours
  }
  EXPECT_GT(levelGap(built.tree), 1);
  EXPECT_GT(balanceAround(built.tree, {q}), 0u);
  EXPECT_LE(levelGap(built.tree), 1);
  for (int32_t leaf : built.tree.leaves()) EXPECT_EQ(built.tree[leaf].status, QuadStatus::Inside);
}

// Splitting a boundary leaf of a finished tree classifies its new leaves from its own edges.
TEST(Balance, SplitBoundaryLeavesKeepTheirSides) {
  std::mt19937 random(3);
  for (int trial = 0; trial < 100; ++trial) {
    const PolygonWithHoles polygon = test::randomPolygonWithHoles(random, trial);
    PolygonTree built = buildPolygonTree(polygon, 20);
    for (int32_t q : built.tree.leaves())
      if (built.tree[q].status == QuadStatus::Boundary && built.tree[q].level < built.tree.maxDepth) built.tree.splitLeaf(q);
    for (int32_t q : built.tree.leaves()) {
      const Quadrant& leaf = built.tree[q];
      if (leaf.status == QuadStatus::Boundary) continue;
      const double half = static_cast<double>(built.tree.edgeLength(leaf)) / 2;
      const Vec2 center = built.frame.toPlane({leaf.x + half, leaf.y + half});
      bool inside = containsPoint(polygon.outer, center);
      for (const Ring2& h : polygon.holes) inside = inside && !containsPoint(h, center);
      EXPECT_EQ(leaf.status == QuadStatus::Inside, inside) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace mesher
