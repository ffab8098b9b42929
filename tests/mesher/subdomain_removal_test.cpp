// Meshing one leaf's region by subdomain removal, beyond the thesis where no fan from one point
// reaches the angle bound.
#include "mesher/subdomain_removal.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mesher {
namespace {

double cornerAngleDeg(Vec2 before, Vec2 at, Vec2 after) {
  const Vec2 u = before - at, v = after - at;
  return std::atan2(std::abs(u.x * v.y - u.y * v.x), glm::dot(u, v)) * 180 / std::numbers::pi;
}

// An edge cuts the north-west corner off a leaf of 65,536 tree units (stretched 1.145 times
// along y in the plane, as in a random polygon that fell short) and crosses its west side 32
// units below the T-vertex in the side's middle: an element with both as corners has a tiny
// angle unless it is tiny itself. A point on the edge at the foot of the T-vertex gives one (the
// triangle of the T-vertex, the crossing and the foot, right-angled), with a quadrilateral for
// the rest; feet were left out so near an end of the edge (under a thousandth of it).
TEST(SubdomainRemoval, APointOnTheBoundaryCutsOffATinyCornerWhole) {
  const std::vector<Vec2> ring{{0, 32736.278787866578}, {45461.72695787949, 65536}, {0, 65536}, {0, 32768}};
  RingBoundary boundary;
  boundary.pathPoints = 2;  // the edge from the crossing to the north side
  boundary.size = 65536;
  const Vec2 inner{15153.909, 54602.760}, scale{1, 1.1453};  // the region's centroid
  SubdomainRemover remover;
  EXPECT_TRUE(remover.reachesBound(ring, 1, &inner, scale, &boundary));

  std::vector<RingElement> elements;
  remover.mesh(ring, 1, &inner, scale, elements, &boundary);
  const std::vector<Vec2>& points = remover.points();
  double area = 0, smallest = 180;
  for (const RingElement& e : elements) {
    for (uint8_t k = 0; k < e.count; ++k) {
      const Vec2 a = points[e.v[k]], b = points[e.v[(k + 1) % e.count]], c = points[e.v[(k + 2) % e.count]];
      area += 0.5 * (a.x * b.y - b.x * a.y);
      smallest = std::min(smallest, cornerAngleDeg(a * scale, b * scale, c * scale));
    }
  }
  EXPECT_GE(smallest, kAngleBoundDeg);
  EXPECT_NEAR(area, 0.5 * ring[1].x * (ring[1].y - ring[0].y), 1e-6 * area);  // the triangle the ring is
}

}  // namespace
}  // namespace mesher
