// Polygon soups and closed forms for the pxpl5 tests and benchmark.
#pragma once

#include "pxpl5/hemisphere.h"

#include <glm/vec3.hpp>

#include <random>
#include <vector>

namespace pxpl5::test {

// A soup that owns its arrays.
struct Soup {
  std::vector<glm::vec3> vertices;
  std::vector<Polygon> polygons;

  PolygonSoup view() const { return {vertices, polygons}; }
  void add(const std::vector<glm::vec3>& ring, uint32_t id);
  // The quad a, a + s, a + s + t, a + t cut into n x n quads with ids id, id + 1, ... (rows
  // along t), sharing vertices exactly.
  void addGrid(glm::vec3 a, glm::vec3 s, glm::vec3 t, int n, uint32_t id);
};

// Lambert's contour formula: the unoccluded form factor from a point with unit normal to a
// planar polygon (the part above the point's horizon is taken).
double lambertFactor(glm::dvec3 point, glm::dvec3 normal, const std::vector<glm::dvec3>& ring);

// The inside of the axis-aligned box [lo, hi] as six faces, each cut into n x n quads; ids run
// face by face from 0.
Soup closedBox(glm::vec3 lo, glm::vec3 hi, int n);

// A room for the benchmark: walls, floor and ceiling of a 10 x 3 x 8 room cut into quads, plus
// furniture boxes, about `polygons` in all; the viewpoint is on the floor looking up.
Soup benchmarkRoom(int polygons, Viewpoint& view);

// The sum of all factors of a frame for the ids in [first, last).
double factorOfIds(const HemisphereFrame& frame, uint32_t first, uint32_t last);

}  // namespace pxpl5::test
