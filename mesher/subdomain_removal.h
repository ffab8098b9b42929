// Meshing one leaf's region by subdomain removal (thesis 5.4): convex quadrilaterals and
// triangles that all share a hinge vertex, quadrilaterals preferred. Interior squares use the
// same procedure over every hinge, which yields the templates of 5.3.
#pragma once

#include "mesher/mesher.h"
#include "mesher/polygon.h"

#include <array>
#include <cstdint>
#include <vector>

namespace mesher {

// Three or four indices into a ring, counter-clockwise.
struct RingElement {
  std::array<uint32_t, 4> v{};
  uint8_t count = 0;
};

// Fans the ring out from ring[hinge], merging neighbouring fan triangles into strictly convex
// quadrilaterals, first come first served. Returns false, writing nothing, when some fan
// triangle would have no area (a ring point hidden from the hinge or in line with it and a
// neighbour): the fan would leave a T-vertex. Points equal to the hinge (a region pinched at
// its vertex) split the fan.
bool fanFromHinge(const std::vector<Vec2>& ring, size_t hinge, std::vector<RingElement>& out);

// Fans the ring out from `points[ring size]`, a point strictly inside that sees every ring edge,
// starting at ring[start]; `points` is the ring with that point appended. False, writing
// nothing, when the point does not see some edge.
bool fanFromInside(const std::vector<Vec2>& points, size_t start, std::vector<RingElement>& out);

// The mesh of a ring: among the fans from each hinge and, when `inner` is given (a point inside
// the ring, index ring.size() in the elements), the fans around it, one whose angles all reach
// kAngleBoundDeg (or the ring's own corner there, when that is sharper) with the fewest elements;
// when none does, the one closest to it. `preferredHinge`, the rule of 5.4, wins ties. A ring
// no point sees whole is ear clipped, triangle pairs merged into convex quads. Shapes are judged
// on `ring` (tree coordinates, where collinear grid points are exact), angles on the ring scaled
// by `shapeScale` (plane units per tree unit on each axis).
void removeSubdomains(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
                      std::vector<RingElement>& out);

}  // namespace mesher
