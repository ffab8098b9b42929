#include "mesher/triangulate.h"

#include "tests/mesher/random_polygons.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

namespace mesher {
namespace {

std::vector<Vec2> allPoints(const PolygonWithHoles& p) {
  std::vector<Vec2> points(p.outer);
  for (const Ring2& h : p.holes) points.insert(points.end(), h.begin(), h.end());
  return points;
}

double polygonArea(const PolygonWithHoles& p) {
  double area = std::abs(signedArea(p.outer));
  for (const Ring2& h : p.holes) area -= std::abs(signedArea(h));
  return area;
}

// The triangles tile the polygon: counter-clockwise, summing to its area, using every point,
// and no point lies strictly inside any triangle.
void expectTiling(const PolygonWithHoles& p) {
  const auto triangles = triangulate(p);
  const std::vector<Vec2> points = allPoints(p);
  double area = 0;
  std::set<uint32_t> used;
  for (const auto& t : triangles) {
    const double a = 0.5 * orient2(points[t[0]], points[t[1]], points[t[2]]);
    EXPECT_GT(a, 0);
    area += a;
    used.insert(t.begin(), t.end());
    for (uint32_t i = 0; i < points.size(); ++i) {
      if (points[i] == points[t[0]] || points[i] == points[t[1]] || points[i] == points[t[2]]) continue;
      const bool inside = orient2(points[t[0]], points[t[1]], points[i]) > 0 &&
                          orient2(points[t[1]], points[t[2]], points[i]) > 0 &&
                          orient2(points[t[2]], points[t[0]], points[i]) > 0;
      EXPECT_FALSE(inside) << "point " << i << " inside a triangle";
    }
  }
  EXPECT_NEAR(area, polygonArea(p), 1e-9 * polygonArea(p));
  EXPECT_EQ(used.size(), points.size());
  EXPECT_EQ(triangles.size(), points.size() - 2 + 2 * p.holes.size());
}

TEST(Triangulate, ConvexPolygonEitherWinding) {
  Ring2 hexagon;
  for (int i = 0; i < 6; ++i) hexagon.push_back({std::cos(i * std::numbers::pi / 3), std::sin(i * std::numbers::pi / 3)});
  expectTiling({hexagon, {}});
  expectTiling({Ring2(hexagon.rbegin(), hexagon.rend()), {}});
}

TEST(Triangulate, ConcaveComb) {
  expectTiling({{{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}, {}});
}

TEST(Triangulate, CollinearPointsOnEdgesAreKept) {
  expectTiling({{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {0, 1}}, {}});
}

TEST(Triangulate, WallWithWindowAndDoor) {
  expectTiling({{{0, 0}, {240, 0}, {240, 96}, {0, 96}},
                {{{30, 40}, {30, 80}, {66, 80}, {66, 40}}, {{100, 0.5}, {136, 0.5}, {136, 84}, {100, 84}}}});
}

TEST(Triangulate, HolesSharingTheRightmostXAndAligned) {
  expectTiling({{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                {{{2, 2}, {4, 2}, {4, 4}, {2, 4}}, {{2, 6}, {4, 6}, {4, 8}, {2, 8}}, {{6, 2}, {8, 2}, {8, 8}, {6, 8}}}});
}

TEST(Triangulate, RandomPolygonsWithHolesTileExactly) {
  std::mt19937 random(20261121);
  for (int trial = 0; trial < 300; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    expectTiling(test::randomPolygonWithHoles(random, trial));
  }
}

Ring2 rotated(const Ring2& ring, double degrees) {
  const double a = degrees * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
  Ring2 out;
  for (const Vec2& p : ring) out.push_back({c * p.x - s * p.y, s * p.x + c * p.y});
  return out;
}

// A hole corner exactly on the wall's diagonal: after a rotation, rounding leaves it a hair to
// either side of the line, which must not let an ear through that touches it.
TEST(Triangulate, RotatedWallsWithAHoleCornerOnTheDiagonal) {
  const PolygonWithHoles walls[] = {
      {{{0, 0}, {5, 0}, {5, 5}, {0, 5}}, {{{2, 1}, {3, 1}, {3, 2}, {2, 2}}}},
      {{{0, 0}, {15, 0}, {15, 10}, {0, 10}}, {{{10, 5}, {12, 5}, {12, 8}, {10, 8}}}},
      {{{0, 0}, {3, 0}, {6, 0}, {6, 6}, {0, 6}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}, {{4, 4}, {5, 4}, {5, 5}, {4, 5}}}},
  };
  for (const PolygonWithHoles& wall : walls)
    for (double degrees = 0; degrees < 360; degrees += 0.5) {
      PolygonWithHoles turned{rotated(wall.outer, degrees), {}};
      for (const Ring2& hole : wall.holes) turned.holes.push_back(rotated(hole, degrees));
      SCOPED_TRACE(std::to_string(degrees) + " degrees");
      expectTiling(turned);
    }
}

TEST(Triangulate, SameInputSameTriangles) {
  const PolygonWithHoles p{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{2, 2}, {4, 2}, {4, 4}, {2, 4}}}};
  EXPECT_EQ(triangulate(p), triangulate(p));
}

TEST(Triangulate, DegenerateInputEndsWithoutHanging) {
  EXPECT_TRUE(triangulate({{{0, 0}, {1, 0}}, {}}).empty());
  EXPECT_TRUE(triangulate({{{0, 0}, {1, 0}, {2, 0}, {3, 0}}, {}}).empty());  // no area
  const auto bowtie = triangulate({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}});
  EXPECT_LE(bowtie.size(), 2u);
}

}  // namespace
}  // namespace mesher
