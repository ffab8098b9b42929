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

struct Measured {
  double area = 0, smallestAngle = 180;
  bool convex = true;
};

// The elements' total area, their smallest angle in true proportions, and whether each is
// strictly convex and counter-clockwise.
Measured measure(const std::vector<RingElement>& elements, const std::vector<Vec2>& points, Vec2 scale) {
  Measured m;
  for (const RingElement& e : elements)
    for (uint8_t k = 0; k < e.count; ++k) {
      const Vec2 a = points[e.v[k]], b = points[e.v[(k + 1) % e.count]], c = points[e.v[(k + 2) % e.count]];
      m.area += 0.5 * (a.x * b.y - b.x * a.y);
      m.smallestAngle = std::min(m.smallestAngle, cornerAngleDeg(a * scale, b * scale, c * scale));
      m.convex = m.convex && (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) > 0;
    }
  return m;
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
  const Measured m = measure(elements, remover.points(), scale);
  EXPECT_GE(m.smallestAngle, kAngleBoundDeg);
  EXPECT_NEAR(m.area, 0.5 * ring[1].x * (ring[1].y - ring[0].y), 1e-6 * m.area);  // the triangle the ring is
}

// Meshes the ring and expects every angle within the bound, convex counter-clockwise elements
// tiling it, and points of its own only strictly inside the leaf or on the ring's boundary edges
// (anywhere else on a side they would be T-vertices).
void expectMeshedWithinTheBound(const std::vector<Vec2>& ring, const RingBoundary& boundary, Vec2 inner, Vec2 scale) {
  SubdomainRemover remover;
  std::vector<RingElement> elements;
  remover.mesh(ring, 1, &inner, scale, elements, &boundary);
  EXPECT_TRUE(remover.reachedBound());
  const Measured m = measure(elements, remover.points(), scale);
  EXPECT_GE(m.smallestAngle, kAngleBoundDeg);
  EXPECT_TRUE(m.convex);
  double ringArea = 0;
  for (size_t i = 0; i < ring.size(); ++i) ringArea += 0.5 * (ring[i].x * ring[(i + 1) % ring.size()].y - ring[(i + 1) % ring.size()].x * ring[i].y);
  EXPECT_NEAR(m.area, ringArea, 1e-9 * ringArea);
  for (size_t i = 0; i < remover.points().size(); ++i) {
    if (remover.ringIndexOf(i) >= 0) continue;
    const Vec2 p = remover.points()[i];
    bool onBoundaryEdge = false;
    for (size_t e = 0; e < ring.size(); ++e) {
      const Vec2 a = ring[e], b = ring[(e + 1) % ring.size()];
      const double along = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
      onBoundaryEdge |= boundary.onBoundary(ring, e) && along > 0 && along < 1 && glm::length(a + along * (b - a) - p) < 1e-9 * boundary.size;
    }
    const bool inside = p.x > boundary.x0 && p.x < boundary.x0 + boundary.size && p.y > boundary.y0 && p.y < boundary.y0 + boundary.size;
    EXPECT_TRUE(inside || onBoundaryEdge) << p.x << ", " << p.y;
  }
}

// An input edge enters a leaf of 32,768 tree units through its east side, 5% above the south-east
// corner, turns at a vertex 12% from the west side and leaves through the north side: a
// reflex corner so near a closed side that every chord from it to the west side's ends, and
// every fan of the ring's points, feet on the edges and one inner point, leaves an angle
// below the bound (10.5 degrees at best; a random polygon's ring). Cut along the chord from the
// vertex to the north-west corner, the rest fans around a point of its own inside the leaf.
TEST(SubdomainRemoval, AReflexCornerNearAClosedSideIsCutAndFannedAroundAPointOfItsOwn) {
  const std::vector<Vec2> ring{{655360, 525905.50350682996}, {626397.49567451118, 546217.00681842561},
                               {627489.21875071758, 557056},  {622592, 557056},
                               {622592, 524288},              {655360, 524288}};
  RingBoundary boundary;
  boundary.pathPoints = 3;  // the two input edges; the leaf's sides have leaves inside across them
  boundary.x0 = 622592, boundary.y0 = 524288, boundary.size = 32768;
  expectMeshedWithinTheBound(ring, boundary, {633358.77218781947, 534297.92275087617}, {0.00013169688143235163, 0.00012325572267858409});
}

// A leaf 16,384 units on edge at the root's south border (open there and to the west): an input
// edge runs from the north side down to a vertex on the south side, the next one to the east side
// 25 units up, and a T-vertex on the north side lies 1.8% of the leaf from the first crossing.
// The segment between them is so short that only a point of its own near it meshes the ring
// within the bound; no point of a grid over the ring comes near enough, the apex of a triangle
// on that segment does. (17.6 degrees were left, in a random star polygon.)
TEST(SubdomainRemoval, AShortEdgeTakesAPointOfItsOwnNearIt) {
  const std::vector<Vec2> ring{{24278.820604644388, 16384}, {32522.370443227261, 0}, {32768, 24.973138052761573}, {32768, 16384}, {24576, 16384}};
  RingBoundary boundary;
  boundary.pathPoints = 3;
  boundary.openSides = 5;  // west and south
  boundary.x0 = 16384, boundary.y0 = 0, boundary.size = 16384;
  expectMeshedWithinTheBound(ring, boundary, {29935.853219849287, 10769.551022234667}, {0.00021587705625758516, 0.00034075648335868403});
}

}  // namespace
}  // namespace mesher
