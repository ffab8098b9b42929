// The best partition of a small ring into convex pieces: it tiles the ring exactly with strictly
// convex counter-clockwise pieces, scores what it claims, takes the fewest pieces among those
// that reach the bound, and meshes thin strips no fan from one point can.
#include "mesher/convex_partition.h"

#include "mesher/mesher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>

namespace mesher {
namespace {

double angleDeg(Vec2 prev, Vec2 at, Vec2 next) {
  const Vec2 u = prev - at, v = next - at;
  return std::atan2(std::abs(u.x * v.y - u.y * v.x), u.x * v.x + u.y * v.y) * 180 / std::numbers::pi;
}

// What each corner may reach: the bound, or the ring's own angle where that is sharper.
std::vector<double> reachOf(const std::vector<Vec2>& ring) {
  std::vector<double> reach(ring.size(), kAngleBoundDeg);
  for (size_t i = 0; i < ring.size(); ++i) {
    const Vec2 prev = ring[(i + ring.size() - 1) % ring.size()], next = ring[(i + 1) % ring.size()];
    if (orient2(prev, ring[i], next) > 0) reach[i] = std::min(reach[i], angleDeg(prev, ring[i], next));
  }
  return reach;
}

struct Partitioned {
  double score = -1;
  std::vector<RingElement> pieces;
};

Partitioned partitionOf(const std::vector<Vec2>& ring) {
  Partitioned p;
  p.score = ConvexPartition().partition(ring, ring, reachOf(ring), p.pieces);
  return p;
}

// Exact tiling: every piece strictly convex and counter-clockwise, areas adding up to the
// ring's, every ring edge in one piece and every other piece edge in two, once each way.
void expectTiles(const std::vector<Vec2>& ring, const Partitioned& p) {
  double area = 0;
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (const RingElement& e : p.pieces) {
    ASSERT_TRUE(e.count == 3 || e.count == 4);
    for (uint8_t k = 0; k < e.count; ++k) {
      const Vec2 a = ring[e.v[k]], b = ring[e.v[(k + 1) % e.count]], c = ring[e.v[(k + 2) % e.count]];
      EXPECT_GT(orient2(a, b, c), 0) << "piece corner not strictly convex";
      area += 0.5 * (a.x * b.y - a.y * b.x);
      ++uses[{e.v[k], e.v[(k + 1) % e.count]}];
    }
  }
  EXPECT_NEAR(area, signedArea(ring), 1e-9 * std::abs(signedArea(ring)));
  const auto n = static_cast<uint32_t>(ring.size());
  for (const auto& [edge, count] : uses) {
    EXPECT_EQ(count, 1);
    const bool ringEdge = edge.second == (edge.first + 1) % n;
    EXPECT_EQ(uses.count({edge.second, edge.first}), ringEdge ? 0u : 1u);
  }
  for (uint32_t i = 0; i < n; ++i) EXPECT_EQ(uses.count({i, (i + 1) % n}), 1u) << "ring edge " << i;
}

// The partition's worst corner over what it may reach, recomputed here.
double scoreOf(const std::vector<Vec2>& ring, const Partitioned& p) {
  const std::vector<double> reach = reachOf(ring);
  double worst = std::numeric_limits<double>::infinity();
  for (const RingElement& e : p.pieces)
    for (uint8_t k = 0; k < e.count; ++k)
      worst = std::min(worst, angleDeg(ring[e.v[(k + e.count - 1) % e.count]], ring[e.v[k]], ring[e.v[(k + 1) % e.count]]) /
                                  reach[e.v[k]]);
  return worst;
}

TEST(ConvexPartition, ConvexRingsAreOnePiece) {
  const Partitioned strip = partitionOf({{0, 0}, {10, 0}, {10, 1}, {0, 1}});
  ASSERT_EQ(strip.pieces.size(), 1u);
  EXPECT_EQ(strip.pieces[0].count, 4);
  EXPECT_GE(strip.score, 1);  // a thin rectangle is all right angles
  const Partitioned triangle = partitionOf({{0, 0}, {4, 0}, {1, 3}});
  ASSERT_EQ(triangle.pieces.size(), 1u);
  EXPECT_EQ(triangle.pieces[0].count, 3);
}

// An L of two arms is two rectangles, not three or more pieces.
TEST(ConvexPartition, AnLIsTwoQuadrilaterals) {
  const std::vector<Vec2> ring{{0, 0}, {6, 0}, {6, 1}, {1, 1}, {1, 6}, {0, 6}};
  const Partitioned p = partitionOf(ring);
  expectTiles(ring, p);
  ASSERT_EQ(p.pieces.size(), 2u);
  EXPECT_EQ(p.pieces[0].count + p.pieces[1].count, 8);
  EXPECT_GE(p.score, 1);
}

// A shelf's strip meeting a thin upright (the office bookcase's side, in metres): the strip
// carries a point near its far end and the feet added on the boundary. Every angle reaches the
// bound, with pieces around several points: no one point is a corner of them all, as in a fan.
TEST(ConvexPartition, AThinStripWithAPointNearItsEnd) {
  const std::vector<Vec2> ring{{4.85, 1.49},  {4.925, 1.49}, {4.99, 1.49}, {4.99, 1.25},
                               {5.0, 1.25},   {5.0, 1.49},   {5.0, 1.5},   {4.925, 1.5}, {4.85, 1.5}};
  const Partitioned p = partitionOf(ring);
  expectTiles(ring, p);
  EXPECT_GE(p.score, 1);
  EXPECT_NEAR(p.score, scoreOf(ring, p), 1e-6);  // the partition measures with a fast atan2
  EXPECT_LE(p.pieces.size(), 4u);
  for (uint32_t i = 0; i < ring.size(); ++i)
    EXPECT_FALSE(std::all_of(p.pieces.begin(), p.pieces.end(), [&](const RingElement& e) {
      return std::find(e.v.begin(), e.v.begin() + e.count, i) != e.v.begin() + e.count;
    })) << "a fan from point " << i;
}

// Random star-shaped rings, some with points on their edges: the partition always tiles, and
// its score is what its pieces give.
TEST(ConvexPartition, PiecesTileRandomRings) {
  std::mt19937 random(31);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 500; ++trial) {
    SCOPED_TRACE(trial);
    const int n = 4 + trial % 11;
    std::vector<Vec2> ring;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * (i + 0.8 * unit(random)) / n, r = 0.2 + unit(random);
      ring.push_back({r * std::cos(a), r * std::sin(a)});
      if (trial % 3 == 0 && i % 2 == 0) ring.push_back(ring.back());  // replaced below by a point on the edge
    }
    for (size_t i = 0; i < ring.size(); ++i)
      if (ring[i] == ring[(i + 1) % ring.size()]) ring[i] = 0.5 * (ring[i == 0 ? ring.size() - 1 : i - 1] + ring[(i + 1) % ring.size()]);
    const Partitioned p = partitionOf(ring);
    ASSERT_GT(p.score, 0);  // a simple ring always has a partition into triangles
    expectTiles(ring, p);
    EXPECT_NEAR(p.score, scoreOf(ring, p), 1e-6);  // the partition measures with a fast atan2
  }
}

}  // namespace
}  // namespace mesher
