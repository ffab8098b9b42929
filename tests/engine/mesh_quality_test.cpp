// The sums of `walkrad mesh --stats`: the independent check's T-vertices and angles, added up
// over the polygons meshed.
#include "engine/geometry/mesh_quality.h"

#include <gtest/gtest.h>

namespace engine {
namespace {

const mesher::PolygonWithHoles kSquare{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {}};

TEST(MeshQuality, CountsTheTVertexOfAHandMadeMeshAndAddsUpMeshes) {
  // The square's lower right half whole, its upper left half split at the centre (1, 1), which
  // lies inside the lower half's diagonal: a T-vertex.
  mesher::Mesh split;
  split.vertices = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}};
  split.elements = {{0, 1, 2, mesher::Mesh::kNone}, {0, 4, 3, mesher::Mesh::kNone}, {4, 2, 3, mesher::Mesh::kNone}};
  MeshQuality quality;
  quality.add(kSquare, split);
  EXPECT_EQ(quality.elements, 3u);
  EXPECT_EQ(quality.quads, 0u);
  EXPECT_EQ(quality.vertices, 5u);
  EXPECT_EQ(quality.tVertices, 1u);
  EXPECT_NEAR(quality.smallestAngleDeg, 45, 1e-9);

  const mesher::Mesh meshed = mesher::meshPolygon(kSquare, {0.5});
  quality.add(kSquare, meshed);
  EXPECT_EQ(quality.elements, 3 + meshed.elements.size());
  EXPECT_EQ(quality.vertices, 5 + meshed.vertices.size());
  EXPECT_EQ(quality.quads, meshed.quadCount());
  EXPECT_EQ(quality.tVertices, 1u);  // the quadtree's mesh has none
}

}  // namespace
}  // namespace engine
