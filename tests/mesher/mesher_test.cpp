// The whole of chapter 5: meshes tile their polygon exactly, conform, keep every input vertex.
#include "mesher/mesher.h"

#include "tests/mesher/mesh_checks.h"
#include "tests/mesher/random_polygons.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mesher {
namespace {

void expectGoodMesh(const PolygonWithHoles& polygon, double patchSize) {
  const Mesh mesh = meshPolygon(polygon, {patchSize});
  const test::MeshCheck c = test::checkMesh(polygon, mesh);
  EXPECT_NEAR(c.elementArea, c.polygonArea, 1e-9 * c.polygonArea);
  EXPECT_EQ(c.notCounterClockwiseOrConvex, 0u);
  EXPECT_EQ(c.movedInputVertices, 0u);
  EXPECT_EQ(c.tVertices, 0u);
  EXPECT_EQ(c.unmatchedInnerEdges, 0u);
  EXPECT_EQ(c.repeatedEdges, 0u);
  EXPECT_LE(c.largestDiameter, patchSize * std::sqrt(2.0) * (1 + 1e-9));
}

TEST(Mesher, ARectangleBecomesQuads) {
  const PolygonWithHoles rectangle{{{3, 2}, {35, 2}, {35, 14}, {3, 14}}, {}};
  const Mesh mesh = meshPolygon(rectangle, {4});
  EXPECT_EQ(mesh.triangleCount(), 0u);
  EXPECT_EQ(mesh.quadCount(), 8u * 4);
  expectGoodMesh(rectangle, 4);
}

TEST(Mesher, WallWithWindow) {
  expectGoodMesh({{{0, 0}, {240, 0}, {240, 96}, {0, 96}}, {{{30, 40}, {30, 80}, {66, 80}, {66, 40}}}}, 12);
}

TEST(Mesher, ConcavePolygonWithAHole) {
  expectGoodMesh({{{0, 0}, {10, 0}, {10, 6}, {6, 6}, {6, 10}, {0, 10}}, {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}}, 1.5);
}

TEST(Mesher, RandomPolygonsWithHoles) {
  std::mt19937 random(77);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const PolygonWithHoles polygon = test::randomPolygonWithHoles(random, trial);
    expectGoodMesh(polygon, 5 + trial % 40);
  }
}

}  // namespace
}  // namespace mesher
