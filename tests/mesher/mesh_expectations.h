// What every mesh must be, as gtest expectations on its independent check; and finding an
// adaptive mesh's element by place.
#pragma once

#include "mesher/adaptive_mesh.h"
#include "mesher/mesh_check.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace mesher::test {

// Tiles the polygon exactly with convex counter-clockwise elements, no T-vertex, no overlap;
// with `inputFirst`, the polygon's own points come first in the vertex list, unmoved.
inline void expectValidMesh(const MeshCheck& c, bool inputFirst = true) {
  EXPECT_NEAR(c.elementArea, c.polygonArea, c.areaTolerance);
  EXPECT_EQ(c.notCounterClockwiseOrConvex, 0u);
  if (inputFirst) {
    EXPECT_EQ(c.movedInputVertices, 0u);
  }
  EXPECT_EQ(c.tVertices, 0u);
  EXPECT_EQ(c.unmatchedInnerEdges, 0u);
  EXPECT_EQ(c.repeatedEdges, 0u);
}

// The live element whose corners' mean lies nearest p.
inline ElementId elementNear(const AdaptiveMesh& mesh, Vec2 p) {
  ElementId best;
  double bestDistance = 1e300;
  for (ElementId e : mesh.elements()) {
    Vec2 center{0};
    int n = 0;
    for (uint32_t v : mesh.corners(e))
      if (v != Mesh::kNone) center += mesh.vertices()[v], ++n;
    const double d = glm::length(center / static_cast<double>(n) - p);
    if (d < bestDistance) bestDistance = d, best = e;
  }
  return best;
}

}  // namespace mesher::test
