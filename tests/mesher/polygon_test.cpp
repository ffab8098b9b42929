#include "mesher/polygon.h"

#include <cmath>
#include <numbers>
#include <gtest/gtest.h>

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
