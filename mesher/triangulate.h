// Triangulation of a polygon with holes by ear clipping, holes joined to the outer boundary by
// bridges. This is the plain reference meshing (no Steiner points): the scene's display uses it
// until the modified quadtree of chapter 5 lands, and mesher tests can use it as an oracle.
#pragma once

#include "mesher/polygon.h"

#include <array>
#include <cstdint>
#include <vector>

namespace mesher {

struct PolygonWithHoles {
  Ring2 outer;               // simple, either winding
  std::vector<Ring2> holes;  // simple, either winding, strictly inside `outer`, disjoint
};

// Returns triangles as index triples into the polygon's points numbered outer first, then each
// hole in order; every triangle is counter-clockwise. For valid input the triangles tile the
// polygon exactly and use every point (no T-junctions along edges). Degenerate input never
// hangs: it yields a partial triangulation.
std::vector<std::array<uint32_t, 3>> triangulate(const PolygonWithHoles& polygon);

}  // namespace mesher
