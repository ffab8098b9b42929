// What every mesh must be, as gtest expectations on its independent check.
#pragma once

#include "mesher/mesh_check.h"

#include <gtest/gtest.h>

namespace mesher::test {

// Tiles the polygon exactly with convex counter-clockwise elements, no T-vertex, no overlap;
// with `inputFirst`, the polygon's own points come first in the vertex list, unmoved.
inline void expectValidMesh(const MeshCheck& c, bool inputFirst = true) {
  EXPECT_NEAR(c.elementArea, c.polygonArea, 1e-9 * c.polygonArea);
  EXPECT_EQ(c.notCounterClockwiseOrConvex, 0u);
  if (inputFirst) {
    EXPECT_EQ(c.movedInputVertices, 0u);
  }
  EXPECT_EQ(c.tVertices, 0u);
  EXPECT_EQ(c.unmatchedInnerEdges, 0u);
  EXPECT_EQ(c.repeatedEdges, 0u);
}

}  // namespace mesher::test
