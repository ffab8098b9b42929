// Coplanar merging of triangles (thesis 3.2 for modellers' meshes): whole walls from their
// triangles, holes, T-junctions, boundaries touching themselves, curved parts left alone.
#include "engine/geometry/coplanar_merge.h"

#include "engine/geometry/surface_mesh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace engine {
namespace {

Scene sceneOf(size_t objects, bool movable = true) {
  Scene scene;
  scene.materials.resize(2);
  scene.objects.resize(objects);
  for (size_t i = 0; i < objects; ++i) {
    scene.objects[i].name = std::to_string(i);
    scene.objects[i].movable = movable;
  }
  return scene;
}

// The unit square [x, x+1] x [z, z+1] on the floor (y = 0), facing up, as two triangles.
void addSquare(std::vector<SceneTriangle>& out, double x, double z, uint32_t material = 0, uint32_t object = 0) {
  const Vec3 a{x, 0, z}, b{x, 0, z + 1}, c{x + 1, 0, z + 1}, d{x + 1, 0, z};
  out.push_back({{a, b, c}, material, object});
  out.push_back({{a, c, d}, material, object});
}

// The 1 x 2 panel [0, 1] x [0, 2] on the floor (y = 0), facing up, as two triangles; its long
// edge runs from (1, 0, 0) to (1, 0, 2).
void addLongPanel(std::vector<SceneTriangle>& out) {
  const Vec3 a{0, 0, 0}, b{0, 0, 2}, c{1, 0, 2}, d{1, 0, 0};
  out.push_back({{a, b, c}, 0, 0});
  out.push_back({{a, c, d}, 0, 0});
}

double totalArea(const std::vector<Surface>& surfaces) {
  double sum = 0;
  for (const Surface& s : surfaces) sum += s.area;
  return sum;
}

// Every surface is a polygon the mesher takes, and its rings enclose its area.
void expectMeshable(const std::vector<Surface>& surfaces) {
  for (Surface s : surfaces) {
    s.patchSize = 0.5;  // the merge leaves patch sizes to the loader
    SurfaceMesh mesh;
    mesher::Mesher mesher;
    ASSERT_NO_THROW(mesh = meshSurface(s, mesher)) << s.face;
    double ring = mesher::signedArea(mesh.polygon.outer);
    for (const auto& h : mesh.polygon.holes) ring += mesher::signedArea(h);
    EXPECT_NEAR(ring, s.area, 1e-9 * std::max(1.0, s.area)) << s.face;
  }
}

TEST(TriangleMerge, TheTwoTrianglesOfAQuadBecomeOneSurface) {
  std::vector<SceneTriangle> t;
  addSquare(t, 0, 0);
  TriangleMergeCounts counts;
  const auto surfaces = mergeTriangles(sceneOf(1), t, 1e-6, &counts);
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_EQ(surfaces[0].outer.size(), 4u);
  EXPECT_TRUE(surfaces[0].holes.empty());
  EXPECT_EQ(surfaces[0].normal, Vec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(surfaces[0].area, 1);
  EXPECT_EQ(surfaces[0].face, "2 triangles");
  EXPECT_EQ(counts.triangles, 2u);
  EXPECT_EQ(counts.surfaces, 1u);
  EXPECT_EQ(counts.singles, 0u);
  expectMeshable(surfaces);
}

// A 3 x 3 floor of squares without its middle one: one polygon, one hole, corners only (the
// grid's collinear points on the rings are used by nothing else and dropped).
TEST(TriangleMerge, AFloorAroundAGapBecomesAPolygonWithAHole) {
  std::vector<SceneTriangle> t;
  for (int x = 0; x < 3; ++x)
    for (int z = 0; z < 3; ++z)
      if (x != 1 || z != 1) addSquare(t, x, z);
  const auto surfaces = mergeTriangles(sceneOf(1), t, 1e-6);
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_EQ(surfaces[0].outer.size(), 4u);
  ASSERT_EQ(surfaces[0].holes.size(), 1u);
  EXPECT_EQ(surfaces[0].holes[0].size(), 4u);
  EXPECT_DOUBLE_EQ(surfaces[0].area, 8);
  expectMeshable(surfaces);
}

// A 1 x 2 panel beside two 1 x 1 panels: the panel's long edge meets the two short ones at a
// T-junction (no shared vertex); it is split and the three become one surface.
TEST(TriangleMerge, TJunctionsAreResolved) {
  std::vector<SceneTriangle> t;
  addLongPanel(t);
  addSquare(t, 1, 0);
  addSquare(t, 1, 1);
  TriangleMergeCounts counts;
  const auto surfaces = mergeTriangles(sceneOf(1), t, 1e-6, &counts);
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_GE(counts.tJunctions, 1u);
  EXPECT_EQ(surfaces[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(surfaces[0].area, 4);
  expectMeshable(surfaces);
}

// A junction vertex off the edge by less than the tolerance (a modeller's rounding) still joins.
TEST(TriangleMerge, TJunctionsWithinTheToleranceJoin) {
  std::vector<SceneTriangle> t;
  addLongPanel(t);
  const Vec3 c{1, 0, 2}, d{1, 0, 0};  // the panel's long edge
  const Vec3 m{1 + 1e-8, 0, 1}, e{2, 0, 0}, f{2, 0, 1}, g{2, 0, 2};
  t.push_back({{d, m, f}, 0, 0});
  t.push_back({{d, f, e}, 0, 0});
  t.push_back({{m, c, g}, 0, 0});
  t.push_back({{m, g, f}, 0, 0});
  EXPECT_EQ(mergeTriangles(sceneOf(1), t, 1e-6).size(), 1u);
  EXPECT_EQ(mergeTriangles(sceneOf(1), t, 1e-9).size(), 2u);  // beyond a tighter tolerance: apart
}

TEST(TriangleMerge, MaterialsPlanesAndFacingsKeepSurfacesApart) {
  std::vector<SceneTriangle> t;
  addSquare(t, 0, 0, 0);
  addSquare(t, 1, 0, 1);  // another material beside it
  // A wall standing on the floor's far edge (x = 2), facing -x: shares no plane.
  t.push_back({{Vec3{2, 0, 0}, Vec3{2, 1, 0}, Vec3{2, 1, 1}}, 0, 0});
  t.push_back({{Vec3{2, 0, 0}, Vec3{2, 1, 1}, Vec3{2, 0, 1}}, 0, 0});
  const auto surfaces = mergeTriangles(sceneOf(1), t, 1e-6);
  EXPECT_EQ(surfaces.size(), 3u);
  EXPECT_DOUBLE_EQ(totalArea(surfaces), 3);
}

// As scene files: movable objects keep their own surfaces; fixed ones merge with each other.
TEST(TriangleMerge, OnlyFixedObjectsMergeWithEachOther) {
  std::vector<SceneTriangle> t;
  addSquare(t, 0, 0, 0, 0);
  addSquare(t, 1, 0, 0, 1);
  EXPECT_EQ(mergeTriangles(sceneOf(2, true), t, 1e-6).size(), 2u);
  EXPECT_EQ(mergeTriangles(sceneOf(2, false), t, 1e-6).size(), 1u);
}

// Two squares touching at one corner, and a floor whose hole touches its outline at a corner:
// the mesher refuses rings that touch themselves, so the triangles at the touching corner are
// split off and what remains is merged.
TEST(TriangleMerge, BoundariesTouchingThemselvesAreSplitNotRefused) {
  std::vector<SceneTriangle> bowtie;
  addSquare(bowtie, 0, 0);
  addSquare(bowtie, 1, 1);
  auto surfaces = mergeTriangles(sceneOf(1), bowtie, 1e-6);
  EXPECT_DOUBLE_EQ(totalArea(surfaces), 2);
  expectMeshable(surfaces);

  // 4 x 3 squares without (1, 1), a hole, and (2, 2), a notch in the far edge: the hole's corner
  // (2, 2) touches the outline.
  std::vector<SceneTriangle> notched;
  for (int x = 0; x < 4; ++x)
    for (int z = 0; z < 3; ++z)
      if (!(x == 1 && z == 1) && !(x == 2 && z == 2)) addSquare(notched, x, z);
  TriangleMergeCounts counts;
  surfaces = mergeTriangles(sceneOf(1), notched, 1e-6, &counts);
  EXPECT_DOUBLE_EQ(totalArea(surfaces), 10);
  EXPECT_GT(counts.singles, 0u);
  EXPECT_LT(surfaces.size(), 10u);  // most of it still merged
  expectMeshable(surfaces);
}

// A cone's facets have no coplanar neighbour: each stays a triangle of its own.
TEST(TriangleMerge, CurvedPartsStayAsTheirOwnSurfaces) {
  std::vector<SceneTriangle> t;
  const int n = 16;
  for (int i = 0; i < n; ++i) {
    const double a0 = 2 * std::numbers::pi * i / n, a1 = 2 * std::numbers::pi * (i + 1) / n;
    t.push_back({{Vec3{0, 1, 0}, Vec3{std::cos(a0), 0, -std::sin(a0)}, Vec3{std::cos(a1), 0, -std::sin(a1)}}, 0, 0});
  }
  TriangleMergeCounts counts;
  const auto surfaces = mergeTriangles(sceneOf(1), t, 1e-6, &counts);
  EXPECT_EQ(surfaces.size(), static_cast<size_t>(n));
  EXPECT_EQ(counts.singles, static_cast<size_t>(n));
  for (const Surface& s : surfaces) EXPECT_GT(s.normal.y, 0);
  expectMeshable(surfaces);
}

TEST(TriangleMerge, DegenerateTrianglesAreSkippedAndCounted) {
  std::vector<SceneTriangle> t;
  addSquare(t, 0, 0);
  t.push_back({{Vec3{0, 0, 0}, Vec3{0, 0, 0}, Vec3{1, 0, 0}}, 0, 0});      // a repeated corner
  t.push_back({{Vec3{0, 0, 0}, Vec3{0.5, 0, 1e-9}, Vec3{1, 0, 0}}, 0, 0});  // no height
  TriangleMergeCounts counts;
  const auto surfaces = mergeTriangles(sceneOf(1), t, 1e-6, &counts);
  EXPECT_EQ(counts.degenerate, 2u);
  EXPECT_EQ(surfaces.size(), 1u);
}

// A 300 x 300 grid (180,000 triangles, like a finely triangulated floor) becomes one square in
// well under the time a pairwise merge would take; twice gives the same result.
// Speed is measured by loading the real models (docs/BENCHMARKS.md), not here.
TEST(TriangleMerge, AFineFloorMergesIntoOneSquareDeterministically) {
  std::vector<SceneTriangle> t;
  for (int x = 0; x < 300; ++x)
    for (int z = 0; z < 300; ++z) addSquare(t, x, z);
  const auto surfaces = mergeTriangles(sceneOf(1), t, 1e-6);
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_EQ(surfaces[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(surfaces[0].area, 90000);
  const auto again = mergeTriangles(sceneOf(1), t, 1e-6);
  EXPECT_EQ(again[0].outer, surfaces[0].outer);
}

}  // namespace
}  // namespace engine
