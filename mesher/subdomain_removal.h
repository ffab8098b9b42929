// Meshing one leaf's region by subdomain removal (thesis 5.4): convex quadrilaterals and
// triangles that all share a hinge vertex, quadrilaterals preferred. Interior squares use the
// same procedure over every hinge, which yields the templates of 5.3.
#pragma once

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

// The mesh of a ring: the fan from the hinge whose elements have the largest smallest angle
// (within a degree, the one with fewer elements; `preferredHinge`, the rule of 5.4, first among
// equals), else (a ring no point sees whole) ear clipping with triangle pairs merged into convex
// quads. Shapes are judged on `ring` (tree coordinates, where collinear grid points are exact),
// angles on the ring scaled by `shapeScale` (plane units per tree unit on each axis).
void removeSubdomains(const std::vector<Vec2>& ring, int preferredHinge, Vec2 shapeScale, std::vector<RingElement>& out);

// The smallest interior angle of an element, in degrees.
double smallestAngleDeg(const std::vector<Vec2>& points, const RingElement& element);

}  // namespace mesher
