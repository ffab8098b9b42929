#include "mesher/polygon.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace mesher {
namespace {

const Ring2 kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};

TEST(Polygon, SignedAreaFollowsWinding) {
  EXPECT_DOUBLE_EQ(signedArea(kSquare), 4);
  EXPECT_DOUBLE_EQ(signedArea(Ring2(kSquare.rbegin(), kSquare.rend())), -4);
}

TEST(Polygon, CentroidOfATriangleFarFromTheOrigin) {
  const Ring2 t{{1e6, 1e6}, {1e6 + 3, 1e6}, {1e6, 1e6 + 3}};
  EXPECT_NEAR(centroid(t).x, 1e6 + 1, 1e-9);
  EXPECT_NEAR(centroid(t).y, 1e6 + 1, 1e-9);
}

TEST(Polygon, ConvexityIgnoresWindingAndCollinearCorners) {
  EXPECT_TRUE(isConvex(kSquare));
  EXPECT_TRUE(isConvex(Ring2(kSquare.rbegin(), kSquare.rend())));
  EXPECT_TRUE(isConvex({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}));
  EXPECT_FALSE(isConvex({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}));  // a notch
}

// Edges running back along each other turn half a circle at each end of the fold, once as +0 and
// once as -0 (the fuzzed profile of tests/fuzz/regressions/scene_text/bottom_face_crosses_itself):
// summed, the two turns cancel and the ring, a triangle with a spike along one side, turned once.
TEST(Polygon, EdgesFoldingBackAreNotConvex) {
  const Ring2 spiked{{0, 1}, {0, 0}, {1, 2}, {0, 2}, {0, -1}};
  EXPECT_FALSE(isConvex(spiked));
  EXPECT_FALSE(isConvex(Ring2(spiked.rbegin(), spiked.rend())));
  Ring2 mirrored;
  for (Vec2 p : spiked) mirrored.push_back({-p.x, p.y});
  EXPECT_FALSE(isConvex(mirrored));
  EXPECT_FALSE(isConvex(Ring2(mirrored.rbegin(), mirrored.rend())));
}

// Rings of 3-8 points on a 4 x 4 grid fold back, cross, touch and repeat points in every way: each
// one taken as convex must be simple, as the scene loader relies on for a solid's bottom (which
// is its profile). Points repeating their neighbour are left out: the loader refuses them first.
TEST(Polygon, EveryRingTakenAsConvexIsSimple) {
  std::mt19937 random(19);
  std::uniform_int_distribution<int> grid(0, 3);
  size_t convex = 0;
  for (int trial = 0; trial < 50000; ++trial) {
    Ring2 ring(3 + trial % 6);
    for (Vec2& p : ring) p = {grid(random), grid(random)};
    bool repeats = false;
    for (size_t i = 0; i < ring.size(); ++i) repeats |= ring[i] == ring[(i + 1) % ring.size()];
    if (repeats || !isConvex(ring)) continue;
    ASSERT_TRUE(isSimple(ring)) << "trial " << trial;
    ++convex;
  }
  EXPECT_GT(convex, 2000u);  // not only triangles
}

TEST(Polygon, APentagramTurnsOneWayButIsNotConvex) {
  Ring2 star;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * std::numbers::pi * (2 * i) / 5;
    star.push_back({std::cos(a), std::sin(a)});
  }
  EXPECT_FALSE(isConvex(star));
  EXPECT_FALSE(isSimple(star));
}

TEST(Polygon, SimplicityCatchesBowtiesRepeatsAndFoldBacks) {
  EXPECT_TRUE(isSimple(kSquare));
  EXPECT_FALSE(isSimple({{0, 0}, {2, 2}, {2, 0}, {0, 2}}));          // bowtie
  EXPECT_FALSE(isSimple({{0, 0}, {2, 0}, {2, 0}, {2, 2}}));          // repeated point
  EXPECT_FALSE(isSimple({{0, 0}, {2, 0}, {1, 0}, {1, 2}}));          // edge folds back
  EXPECT_FALSE(isSimple({{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}));  // vertex on an edge
}

// isSimple sweeps the ring's edges (n log n); every pair of edges, tested as it once was, is the
// reference. Points on a small grid make rings that cross, touch, repeat a point, run along each
// other or are simple; stars of many points and circles are simple or nearly.
bool simpleByEveryPair(const Ring2& ring) {
  const size_t n = ring.size();
  if (n < 3) return false;
  for (size_t i = 0; i < n; ++i)
    if (ring[i] == ring[(i + 1) % n]) return false;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) {
        const size_t shared = j == i + 1 ? j : i;
        const Vec2 s = ring[shared], p = ring[(shared + n - 1) % n], q = ring[(shared + 1) % n];
        if (orient2(p, s, q) == 0 && glm::dot(p - s, q - s) > 0) return false;
        continue;
      }
      if (segmentsIntersect(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) return false;
    }
  return true;
}

TEST(Polygon, SimplicityAgreesWithTestingEveryPairOfEdges) {
  std::mt19937 random(21);
  std::uniform_int_distribution<int> grid(0, 6);
  size_t simple = 0, trials = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Ring2 ring;
    const int n = 3 + trial % 9;
    for (int i = 0; i < n; ++i) ring.push_back({grid(random), grid(random)});
    ASSERT_EQ(isSimple(ring), simpleByEveryPair(ring)) << "trial " << trial;
    simple += isSimple(ring), ++trials;
  }
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 3 + trial % 200;
    Ring2 ring;
    std::uniform_real_distribution<double> unit(0, 1);
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * (i + 0.999 * unit(random)) / n, r = trial % 2 ? 1 : 0.05 + unit(random);
      ring.push_back({r * std::cos(a), r * std::sin(a)});
    }
    if (trial % 3 == 0) ring[static_cast<size_t>(n / 2)] = ring[0] + 0.5 * (ring[1] - ring[0]);  // a point on an edge
    ASSERT_EQ(isSimple(ring), simpleByEveryPair(ring)) << "star " << trial;
    simple += isSimple(ring), ++trials;
  }
  EXPECT_GT(simple, trials / 10);  // both kinds of ring are common
  EXPECT_LT(simple, trials - trials / 10);
}

// A ring of a hundred thousand points is checked in n log n: this took minutes pair by pair.
TEST(Polygon, SimplicityOfAHundredThousandPointCircle) {
  Ring2 circle;
  for (int i = 0; i < 100000; ++i) circle.push_back({std::cos(2 * std::numbers::pi * i / 100000), std::sin(2 * std::numbers::pi * i / 100000)});
  EXPECT_TRUE(isSimple(circle));
  std::swap(circle[1000], circle[60000]);  // two spikes across the circle cross each other
  EXPECT_FALSE(isSimple(circle));
}

TEST(Polygon, StrictlyInsideHonoursTheMargin) {
  EXPECT_TRUE(strictlyInsideConvex(kSquare, {1, 1}, 0.5));
  EXPECT_FALSE(strictlyInsideConvex(kSquare, {1, 1}, 1.0));
  EXPECT_FALSE(strictlyInsideConvex(kSquare, {0, 1}, 0));  // on the edge
  EXPECT_FALSE(strictlyInsideConvex(kSquare, {3, 1}, 0));
  EXPECT_TRUE(strictlyInsideConvex(Ring2(kSquare.rbegin(), kSquare.rend()), {1, 1}, 0.5));
}

TEST(Polygon, BoundaryDistance) {
  const Ring2 far{{5, 0}, {6, 0}, {6, 1}};
  EXPECT_DOUBLE_EQ(boundaryDistance(kSquare, far), 3);
  const Ring2 touching{{2, 1}, {3, 1}, {3, 2}};
  EXPECT_DOUBLE_EQ(boundaryDistance(kSquare, touching), 0);
  EXPECT_DOUBLE_EQ(segmentDistance({0, 0}, {2, 2}, {0, 2}, {2, 0}), 0);  // crossing
}

}  // namespace
}  // namespace mesher
