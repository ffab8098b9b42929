// The tree setup and edge storage of thesis sections 5.1 and 5.2.
#include "mesher/quadtree.h"

#include "mesher/classify.h"

#include "tests/mesher/random_polygons.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

namespace mesher {
namespace {

// The worked example of 5.1: extents 32 x 12 into a root of 64 give scales 2 and 4/3.
TEST(TreeFrame, ThesisWorkedExample) {
  const PolygonWithHoles rectangle{{{3, 2}, {35, 2}, {35, 14}, {3, 14}}, {}};
  const TreeFrame frame = setupTreeFrame(rectangle, 6);
  EXPECT_EQ(frame.xAxis, (Vec2{1, 0}));
  EXPECT_EQ(frame.shortAxis, 1);
  EXPECT_DOUBLE_EQ(frame.scale, 2);
  EXPECT_DOUBLE_EQ(frame.stretch, 4.0 / 3);
  EXPECT_EQ(frame.toTree({3, 2}), (Vec2{0, 0}));
  EXPECT_EQ(frame.toTree({35, 2}), (Vec2{64, 0}));
  EXPECT_NEAR(frame.toTree({35, 14}).y, 32, 1e-12);
}

TEST(TreeFrame, LongestEdgeRunsAlongX) {
  // Longest edge vertical: the turn is exact.
  const PolygonWithHoles tall{{{0, 0}, {1, 0}, {1, 10}, {0, 9}}, {}};
  const TreeFrame upright = setupTreeFrame(tall, 8);
  EXPECT_EQ(upright.xAxis, (Vec2{0, 1}));
  EXPECT_EQ(upright.toTree({1, 0}).y, upright.toTree({1, 10}).y);
  // Longest edge slanted.
  const PolygonWithHoles slanted{{{0, 0}, {8, 6}, {7, 8}, {-1, 2}}, {}};
  const TreeFrame frame = setupTreeFrame(slanted, 8);
  EXPECT_NEAR(frame.toTree({0, 0}).y, frame.toTree({8, 6}).y, 1e-9);
  for (const Vec2& p : slanted.outer) {
    const Vec2 t = frame.toTree(p);
    EXPECT_GE(t.x, -1e-9);
    EXPECT_GE(t.y, -1e-9);
    EXPECT_LE(t.x, 256 + 1e-9);
    EXPECT_LE(t.y, 256 + 1e-9);
    EXPECT_NEAR(glm::length(frame.toPlane(t) - p), 0, 1e-12);
  }
}

TEST(TreeFrame, ShorterAxisKeepsItsProportionWithinAFactorOfTwo) {
  for (double ratio : {1.0, 0.9, 0.51, 0.5, 0.3, 0.26, 0.1}) {
    const PolygonWithHoles r{{{0, 0}, {100, 0}, {100, 100 * ratio}, {0, 100 * ratio}}, {}};
    const TreeFrame frame = setupTreeFrame(r, 10);
    EXPECT_GE(frame.stretch, 1);
    EXPECT_LT(frame.stretch, 2) << ratio;
    // The shorter extent lands on a power of two.
    const double scaled = frame.toTree({0, 100 * ratio}).y;
    EXPECT_NEAR(std::exp2(std::round(std::log2(scaled))), scaled, 1e-9) << ratio;
  }
}

// Equation 5.2.
TEST(TreeFrame, InitialDepthFromThePatchSize) {
  EXPECT_EQ(initialDepth(240, 12, 20), 5);   // 240 / 12 = 20 -> 2^5 = 32 patches along
  EXPECT_EQ(initialDepth(240, 24, 20), 4);
  EXPECT_EQ(initialDepth(256, 16, 20), 4);   // exact powers need no extra level
  EXPECT_EQ(initialDepth(240, 500, 20), 0);  // larger patches than the polygon
  EXPECT_EQ(initialDepth(1e6, 1e-3, 20), 20);
}

// Brute-force checks of the decomposition rules on every leaf.
void expectRulesHold(const Quadtree& tree) {
  const QuadtreeInput& in = tree.input;
  for (int32_t index : tree.leaves()) {
    const Quadrant& q = tree.quadrants[static_cast<size_t>(index)];
    const double s = static_cast<double>(tree.edgeLength(q));
    const double x0 = static_cast<double>(q.x), y0 = static_cast<double>(q.y);
    std::set<std::pair<double, double>> vertices;
    for (const Vec2& v : in.vertices)
      if (x0 <= v.x && v.x <= x0 + s && y0 <= v.y && v.y <= y0 + s) vertices.insert({v.x, v.y});
    ASSERT_LE(vertices.size(), 1u) << "leaf " << index << " holds two vertices";
    std::set<uint32_t> crossing;
    for (uint32_t e = 0; e < in.edges.size(); ++e)
      if (segmentCrossesOpenSquare(in.vertices[in.edges[e][0]], in.vertices[in.edges[e][1]], x0, y0, x0 + s, y0 + s))
        crossing.insert(e);
    const std::set<uint32_t> stored(q.edges.begin(), q.edges.begin() + q.edgeCount);
    EXPECT_EQ(stored, crossing) << "leaf " << index;
    if (vertices.empty()) {
      EXPECT_LE(q.edgeCount, 1) << "leaf " << index;
      EXPECT_EQ(q.vertex, -1);
    } else {
      ASSERT_GE(q.vertex, 0);
      const Vec2 v = in.vertices[static_cast<size_t>(q.vertex)];
      for (uint32_t e : stored)
        EXPECT_TRUE(in.vertices[in.edges[e][0]] == v || in.vertices[in.edges[e][1]] == v) << "leaf " << index;
    }
    EXPECT_EQ(q.status == QuadStatus::Boundary, q.edgeCount > 0);
  }
}

// Inside leaves lie inside the polygon, outside leaves outside: their centres say so, checked
// with the independent even-odd test of polygon.h.
void expectClassification(const PolygonTree& built, const PolygonWithHoles& polygon) {
  auto inside = [&](Vec2 plane) {
    if (!containsPoint(polygon.outer, plane)) return false;
    for (const Ring2& h : polygon.holes)
      if (containsPoint(h, plane)) return false;
    return true;
  };
  for (int32_t index : built.tree.leaves()) {
    const Quadrant& q = built.tree.quadrants[static_cast<size_t>(index)];
    if (q.status == QuadStatus::Boundary) continue;
    const double half = static_cast<double>(built.tree.edgeLength(q)) / 2;
    const Vec2 center = built.frame.toPlane({q.x + half, q.y + half});
    EXPECT_EQ(q.status == QuadStatus::Inside, inside(center)) << "leaf " << index;
  }
}

TEST(Quadtree, ARectangleHasNoBoundaryQuadrants) {
  const PolygonWithHoles rectangle{{{3, 2}, {35, 2}, {35, 14}, {3, 14}}, {}};
  const PolygonTree built = buildPolygonTree(rectangle, 4);
  EXPECT_EQ(built.tree.uniformDepth, 3);
  int inside = 0;
  for (int32_t index : built.tree.leaves()) {
    const Quadrant& q = built.tree.quadrants[static_cast<size_t>(index)];
    EXPECT_NE(q.status, QuadStatus::Boundary);
    if (q.status == QuadStatus::Outside) continue;
    EXPECT_EQ(q.level, built.tree.uniformDepth);  // nothing forced deeper
    ++inside;
  }
  EXPECT_EQ(inside, 8 * 4);  // 32 x 12 at patch 4: 8 along x, 4 (a power of two) along y
  expectRulesHold(built.tree);
}

// Quadrants wholly outside the polygon are not split to the patch size: a long thin polygon's
// tree grows with the polygon's leaves (here 1,024 x 2: the short side is stretched to a power of
// two), not with its root square (1,024 x 1,024 leaves).
TEST(Quadtree, OutsideQuadrantsStayCoarse) {
  const PolygonWithHoles strip{{{0, 0}, {1000, 0}, {1000, 1}, {0, 1}}, {}};
  const PolygonTree built = buildPolygonTree(strip, 1);
  EXPECT_EQ(built.tree.uniformDepth, 10);
  size_t inside = 0;
  for (int32_t index : built.tree.leaves()) inside += built.tree[index].status == QuadStatus::Inside;
  EXPECT_EQ(inside, 2 * 1024u);
  EXPECT_LT(built.tree.quadrants.size(), 3 * 2 * 1024u);
  expectRulesHold(built.tree);
  expectClassification(built, strip);
}

TEST(Quadtree, NoLeafIsLargerThanThePatchSize) {
  const PolygonWithHoles wall{{{0, 0}, {240, 0}, {240, 96}, {0, 96}}, {{{30, 40}, {30, 80}, {66, 80}, {66, 40}}}};
  const PolygonTree built = buildPolygonTree(wall, 12);
  const Vec2 perTree = built.frame.planePerTree();
  for (int32_t index : built.tree.leaves()) {
    const Quadrant& q = built.tree.quadrants[static_cast<size_t>(index)];
    if (q.status == QuadStatus::Outside) continue;
    const double s = static_cast<double>(built.tree.edgeLength(q));
    EXPECT_LE(s * perTree.x, 12 + 1e-9);
    EXPECT_LE(s * perTree.y, 12 + 1e-9);
  }
  expectRulesHold(built.tree);
  expectClassification(built, wall);
}

TEST(Quadtree, RandomPolygonsKeepTheRules) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const PolygonWithHoles polygon = test::randomPolygonWithHoles(random, trial);
    const double patch = 5 + 40 * std::uniform_real_distribution<double>(0, 1)(random);
    const PolygonTree built = buildPolygonTree(polygon, patch);
    expectRulesHold(built.tree);
    expectClassification(built, polygon);
  }
}

// Vertices a millionth of the polygon's size apart need a deeper tree; they are never merged.
TEST(Quadtree, CloseVerticesDeepenTheTree) {
  const PolygonWithHoles sliver{{{0, 0}, {1, 0}, {1, 1}, {1e-6, 1}, {0, 1 - 1e-6}}, {}};
  const PolygonTree built = buildPolygonTree(sliver, 0.25);
  EXPECT_GT(built.frame.maxDepth, built.tree.uniformDepth + 16);
  expectRulesHold(built.tree);
  std::set<int32_t> owners;
  for (int32_t index : built.tree.leaves())
    if (built.tree.quadrants[static_cast<size_t>(index)].vertex >= 3) owners.insert(built.tree.quadrants[static_cast<size_t>(index)].vertex);
  EXPECT_EQ(owners, (std::set<int32_t>{3, 4}));
}

TEST(Quadtree, FarFromTheOrigin) {
  const Vec2 offset{1e7, -3e6};
  const PolygonWithHoles p{{offset + Vec2{0, 0}, offset + Vec2{50, 0}, offset + Vec2{50, 20}, offset + Vec2{0, 20}},
                           {{offset + Vec2{10, 5}, offset + Vec2{10, 15}, offset + Vec2{20, 15}, offset + Vec2{20, 5}}}};
  const PolygonTree built = buildPolygonTree(p, 2);
  expectRulesHold(built.tree);
  expectClassification(built, p);
}

TEST(Quadtree, SameInputSameTree) {
  std::mt19937 random(9);
  const PolygonWithHoles polygon = test::randomPolygonWithHoles(random, 7);
  const PolygonTree a = buildPolygonTree(polygon, 10), b = buildPolygonTree(polygon, 10);
  ASSERT_EQ(a.tree.quadrants.size(), b.tree.quadrants.size());
  for (size_t i = 0; i < a.tree.quadrants.size(); ++i) {
    EXPECT_EQ(a.tree.quadrants[i].x, b.tree.quadrants[i].x);
    EXPECT_EQ(a.tree.quadrants[i].status, b.tree.quadrants[i].status);
  }
}

TEST(Quadtree, RepeatedVerticesAreRefused) {
  const PolygonWithHoles repeated{{{0, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 1}}, {}};
  EXPECT_THROW(buildPolygonTree(repeated, 0.5), std::invalid_argument);
}

TEST(Quadtree, LeafAtFindsTheHalfOpenOwner) {
  const PolygonWithHoles square{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}};
  const PolygonTree built = buildPolygonTree(square, 1);
  const Quadtree& tree = built.tree;
  const double root = std::exp2(tree.maxDepth);
  EXPECT_EQ(tree.leafAt({-1, 0}), -1);
  EXPECT_EQ(tree.leafAt({root, 0}), -1);
  const Quadrant& corner = tree.quadrants[static_cast<size_t>(tree.leafAt({0, 0}))];
  EXPECT_EQ(corner.x, 0);
  EXPECT_EQ(corner.y, 0);
  const double s = static_cast<double>(tree.edgeLength(corner));
  EXPECT_EQ(tree.quadrants[static_cast<size_t>(tree.leafAt({s, 0}))].x, static_cast<int64_t>(s));
}

}  // namespace
}  // namespace mesher

namespace mesher {
namespace {

// The flood fill classifies every leaf without falling back on ray casting, and agrees with it.
void expectFloodFillAlone(PolygonTree built) {
  std::vector<QuadStatus> before;
  for (Quadrant& q : built.tree.quadrants) {
    before.push_back(q.status);
    if (q.isLeaf() && q.status != QuadStatus::Boundary) q.status = QuadStatus::Undefined;
  }
  EXPECT_EQ(classifyLeaves(built.tree), 0u);
  for (size_t i = 0; i < before.size(); ++i) EXPECT_EQ(built.tree.quadrants[i].status, before[i]) << i;
}

TEST(Classification, FloodFillReachesEveryLeaf) {
  // A rectangle has no boundary leaf at all: its edges lie along leaf sides and seed the fill.
  expectFloodFillAlone(buildPolygonTree({{{3, 2}, {35, 2}, {35, 14}, {3, 14}}, {}}, 4));
  // An L whose reflex corner and edges lie on grid lines.
  expectFloodFillAlone(buildPolygonTree({{{0, 0}, {8, 0}, {8, 4}, {4, 4}, {4, 8}, {0, 8}}, {}}, 1));
  std::mt19937 random(13);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    expectFloodFillAlone(buildPolygonTree(trial % 2 ? test::randomStarPolygon(random, trial) : test::randomPolygonWithHoles(random, trial), 3 + trial % 20));
  }
}

// A polygon of few edges is classified as its tree is built, a ray cast once per square no edge
// crosses; every leaf ends as a ray from its own centre finds it.
TEST(Classification, FewEdgesAsBuiltAgreeWithARayPerLeaf) {
  std::mt19937 random(29);
  size_t judged = 0, polygons = 0;
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const PolygonTree built = buildPolygonTree(trial % 2 ? test::randomStarPolygon(random, trial) : test::randomPolygonWithHoles(random, trial), 1 + trial % 20);
    const Quadtree& tree = built.tree;
    if (tree.input.edges.size() > kFewEdges) continue;
    ++polygons;
    for (int32_t q : tree.leaves()) {
      const Quadrant& leaf = tree[q];
      if (leaf.edgeCount > 0) {
        ASSERT_EQ(leaf.status, QuadStatus::Boundary) << "leaf " << q;
        continue;
      }
      ASSERT_EQ(leaf.status, castFromCentre(tree, q)) << "leaf " << q;
      ++judged;
    }
  }
  EXPECT_GT(polygons, 100u);
  EXPECT_GT(judged, 10000u);
}


}  // namespace
}  // namespace mesher
