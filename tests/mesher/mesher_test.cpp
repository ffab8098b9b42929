// The whole of chapter 5: meshes tile their polygon exactly, conform, keep every input vertex.
#include "mesher/mesher.h"

#include "mesher/adaptive_mesh.h"
#include "mesher/mesh_check.h"

#include "tests/mesher/hostile_polygons.h"
#include "tests/mesher/mesh_expectations.h"
#include "tests/mesher/random_polygons.h"
#include "tests/mesher/scene_polygons.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace mesher {
namespace {

using test::regularPolygon;

// Elements meshed and, of them, those below the angle bound (other than at sharper input corners).
struct Quality {
  size_t elements = 0, belowAngleBound = 0;
};

void expectGoodMesh(const PolygonWithHoles& polygon, double patchSize, Quality* quality = nullptr,
                    int line = __builtin_LINE()) {
  SCOPED_TRACE("mesh of line " + std::to_string(line));
  const Mesh mesh = meshPolygon(polygon, {patchSize});
  const MeshCheck c = checkMesh(polygon, mesh);
  test::expectValidMesh(c);
  EXPECT_LE(c.largestDiameter, patchSize * std::sqrt(2.0) * (1 + 1e-9));
  if (quality) quality->elements += mesh.elements.size(), quality->belowAngleBound += c.belowAngleBound;
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

// Valid meshes, and no element below the angle bound other than at sharper input corners: the
// quality steps each have their own tests (quality_refinement_test.cpp, wedge_handover_test.cpp,
// subdomain_removal_test.cpp, convex_partition_test.cpp); these hold them all to the bound.
TEST(Mesher, RandomPolygonsWithHoles) {
  std::mt19937 random(77);
  Quality quality;
  for (int trial = 0; trial < 1000; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const test::RandomTestPolygon randomPolygon = test::randomTestPolygon(random, false, trial);
    expectGoodMesh(randomPolygon.polygon, randomPolygon.patchSize, &quality);
  }
  EXPECT_EQ(quality.belowAngleBound, 0u) << "of " << quality.elements << " elements";
}

TEST(Mesher, RandomConcavePolygons) {
  std::mt19937 random(78);
  Quality quality;
  for (int trial = 0; trial < 1000; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const test::RandomTestPolygon randomPolygon = test::randomTestPolygon(random, true, trial);
    expectGoodMesh(randomPolygon.polygon, randomPolygon.patchSize, &quality);
  }
  EXPECT_EQ(quality.belowAngleBound, 0u) << "of " << quality.elements << " elements";
}

// Ten thousand more, of five further seeds of the broad sweep (forEachSweepPolygon): corners
// nearer a grid line than the tree goes deep, spikes whose edges run closer than its finest leaf,
// and points added on edges far from the origin turn up only in so many.
TEST(Mesher, TenThousandMoreRandomPolygons) {
  Quality quality;
  test::forEachSweepPolygon(6000, 5, [&](const test::RandomTestPolygon& randomPolygon, unsigned seed, bool concave, int trial) {
    SCOPED_TRACE("seed " + std::to_string(seed) + (concave ? " concave" : " with holes") + " trial " + std::to_string(trial));
    expectGoodMesh(randomPolygon.polygon, randomPolygon.patchSize, &quality);
  });
  EXPECT_EQ(quality.belowAngleBound, 0u) << "of " << quality.elements << " elements";
}

// Turned inputs put vertices a rounding error off grid lines and edges a hair past corners.
TEST(Mesher, TurnedPolygonsAtManyAngles) {
  for (double turn = 0; turn < 90; turn += 1.7) {
    SCOPED_TRACE(std::to_string(turn) + " degrees");
    expectGoodMesh({regularPolygon({3.5, -2}, 3.455, 16, turn), {}}, 12);
    expectGoodMesh({regularPolygon({0, 0}, 10, 4, turn + 45), {regularPolygon({1, 1}, 2, 4, turn + 45)}}, 1.3);
    expectGoodMesh({regularPolygon({100, 50}, 40, 24, turn), {regularPolygon({90, 50}, 5, 6, turn), regularPolygon({115, 50}, 5, 3, turn)}}, 7);
  }
}

// Near-degenerate input from the issue: close vertices, sharp spikes, slivers, far offsets.
TEST(Mesher, NearDegeneratePolygons) {
  expectGoodMesh({{{0, 0}, {1, 0}, {1, 1}, {1e-6, 1}, {0, 1 - 1e-6}}, {}}, 0.25);          // vertices 1e-6 apart
  const double spike = std::tan(std::numbers::pi / 180);                                      // a 1-degree spike
  expectGoodMesh({{{0, 0}, {10, 0}, {10, 1}, {20, 1 + 10 * spike / 2}, {10, 1 + 10 * spike}, {10, 2}, {0, 2}}, {}}, 1);
  expectGoodMesh({{{0, 0}, {100, 0}, {100, 0.01}, {0, 0.01}}, {}}, 5);                        // a sliver
  expectGoodMesh({{{0, 0}, {100, 0}, {0, 0.5}}, {}}, 5);                                      // a thin triangle
  const Vec2 far{3e6, -7e6};
  expectGoodMesh({{far, far + Vec2{50, 0}, far + Vec2{50, 20}, far + Vec2{0, 20}},
                  {{far + Vec2{10, 5}, far + Vec2{10, 15}, far + Vec2{20, 15}, far + Vec2{20, 5}}}},
                 2);
}

TEST(MeshChecks, AspectRatioIsOneForEquilateralAndFallsForSlivers) {
  const double h = std::sqrt(3.0) / 2;
  const PolygonWithHoles equilateral{{{0, 0}, {1, 0}, {0.5, h}}, {}};
  Mesh one;
  one.vertices = equilateral.outer;
  one.elements = {{0, 1, 2, Mesh::kNone}};
  EXPECT_NEAR(checkMesh(equilateral, one).smallestAspectRatio, 1, 1e-12);
  EXPECT_NEAR(checkMesh(equilateral, one).smallestAngleDeg, 60, 1e-9);
  const PolygonWithHoles square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  Mesh quad;
  quad.vertices = square.outer;
  quad.elements = {{0, 1, 2, 3}};
  // Its corner triangle is right isosceles: r = (2 - sqrt 2) / 2, R = sqrt 2 / 2.
  EXPECT_NEAR(checkMesh(square, quad).smallestAspectRatio, 2 * std::sqrt(2.0) - 2, 1e-12);
  const PolygonWithHoles sliver{{{0, 0}, {1, 0}, {0.5, 0.01}}, {}};
  Mesh thin;
  thin.vertices = sliver.outer;
  thin.elements = {{0, 1, 2, Mesh::kNone}};
  EXPECT_LT(checkMesh(sliver, thin).smallestAspectRatio, 0.05);
  // A quad with a corner of nearly 180 degrees is a good triangle with a point on one side; a
  // long thin quad is a sliver whichever way it is split.
  const PolygonWithHoles flatCorner{{{0, 0}, {1, 0}, {2, 0.005}, {1, 1.7}}, {}};
  Mesh bent;
  bent.vertices = flatCorner.outer;
  bent.elements = {{0, 1, 2, 3}};
  EXPECT_GT(checkMesh(flatCorner, bent).smallestAspectRatio, 0.5);
  const PolygonWithHoles strip{{{0, 0}, {1, 0}, {1, 0.01}, {0, 0.01}}, {}};
  Mesh long_;
  long_.vertices = strip.outer;
  long_.elements = {{0, 1, 2, 3}};
  EXPECT_LT(checkMesh(strip, long_).smallestAspectRatio, 0.05);
}

// A Mesher carries memory from polygon to polygon, nothing else: each mesh equals a fresh one,
// also when it is written over the previous one.
TEST(Mesher, ReusedForManyPolygonsGivesWhatFreshMeshingGives) {
  std::mt19937 random(5);
  Mesher mesher;
  Mesh overwritten;
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(trial);
    const PolygonWithHoles polygon = trial % 2 ? test::randomStarPolygon(random, trial) : test::randomPolygonWithHoles(random, trial);
    const double patch = 3 + trial % 17;
    const Mesh reused = mesher.mesh(polygon, {patch}), fresh = meshPolygon(polygon, {patch});
    EXPECT_EQ(reused.vertices, fresh.vertices);
    EXPECT_EQ(reused.elements, fresh.elements);
    mesher.mesh(polygon, {patch}, overwritten);
    EXPECT_EQ(overwritten.vertices, fresh.vertices);
    EXPECT_EQ(overwritten.elements, fresh.elements);
  }
}

// A whole mesh welds its vertices in tree order, mostly without the point table; an adaptive
// mesh's leaf-by-leaf emission looks every point up there. Both give the same mesh, and the
// adaptive mesh's handles number its elements in that order (slot i, generation 0), which is
// how a mesh as meshed knows its elements' handles (engine/surface_mesh.h).
TEST(Mesher, TreeOrderWeldingGivesWhatThePointTableGives) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(trial);
    const PolygonWithHoles polygon = trial % 2 ? test::randomStarPolygon(random, trial) : test::randomPolygonWithHoles(random, trial);
    const double patch = 2 + trial % 13;
    const AdaptiveMesh adaptive(polygon, {patch});
    const Mesh whole = meshPolygon(polygon, {patch}), leafByLeaf = adaptive.snapshot();
    EXPECT_EQ(whole.vertices, leafByLeaf.vertices);
    EXPECT_EQ(whole.elements, leafByLeaf.elements);
    const std::vector<ElementId> ids = adaptive.elements();
    for (uint32_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], (ElementId{i, 0}));
  }
}

// Angles below the bound count against a mesh except at input corners that are sharper.
TEST(MeshChecks, AnglesBelowTheBoundCountExceptAtSharperInputCorners) {
  // A 10-degree spike meshed as one triangle: its only small angle is the input corner's own.
  const double t = std::tan(10 * std::numbers::pi / 180);
  const PolygonWithHoles spike{{{0, 0}, {10, -5 * t}, {10, 5 * t}}, {}};
  Mesh one;
  one.vertices = spike.outer;
  one.elements = {{0, 1, 2, Mesh::kNone}};
  EXPECT_EQ(checkMesh(spike, one).belowAngleBound, 0u);
  // The same spike cut across near its tip: the new corners are not input corners.
  Mesh cut;
  cut.vertices = {spike.outer[0], spike.outer[1], spike.outer[2], {1, -t / 2}, {1, t / 2}};
  cut.elements = {{0, 3, 4, Mesh::kNone}, {3, 1, 2, 4}};
  EXPECT_EQ(checkMesh(spike, cut).belowAngleBound, 0u);  // the quad's angles are 80 and 100
  Mesh sliced;
  sliced.vertices = cut.vertices;
  sliced.elements = {{0, 3, 4, Mesh::kNone}, {3, 1, 2, Mesh::kNone}, {3, 2, 4, Mesh::kNone}};
  EXPECT_EQ(checkMesh(spike, sliced).belowAngleBound, 2u);
  // Either winding, holes included: a square hole's corners are 270 degrees inside the polygon.
  const PolygonWithHoles frame{{{0, 0}, {0, 3}, {3, 3}, {3, 0}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}};
  EXPECT_EQ(checkMesh(frame, meshPolygon(frame, {1})).belowAngleBound, 0u);
}

// Thin strips from the office: a bookcase's side (scene_polygons.h) and a wall with an opening
// 1 cm from its end. Fans alone left 6 and 2 elements below the bound.
TEST(Mesher, ThinStripsMeetTheBound) {
  const std::vector<PolygonWithHoles> strips{test::bookcaseSide(),
                                             {{{0, 5}, {0, 0}, {2.8, 0}, {2.8, 5}}, {{{0.01, 3.6}, {0.01, 4.5}, {2.05, 4.5}, {2.05, 3.6}}}}};
  for (const PolygonWithHoles& strip : strips) {
    const MeshCheck check = checkMesh(strip, meshPolygon(strip, {0.25}));
    test::expectValidMesh(check);
    EXPECT_EQ(check.belowAngleBound, 0u);
  }
}

// Edges grazing a quadrant corner by a rounding error: the leaf is wholly in or out, not both.
TEST(Mesher, EdgesGrazingACorner) {
  for (double d : {1e-12, -1e-12, 0.0}) {
    SCOPED_TRACE(d);
    expectGoodMesh({{{0, 0}, {4, 0}, {4, 1}, {3.7, 1.3 + d}, {1.3 + d, 3.7}, {1, 4}, {0, 4}}, {}}, 1);
    expectGoodMesh({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1.3, 1.7 + d}, {2.7 + d, 2.0}, {1.3, 2.7}}}}, 1);
  }
  // An equilateral triangle off the origin: symmetry runs its edges through grid corners.
  expectGoodMesh({{{12345.678, 12345.678}, {12346.610327345606, 12346.039615431964}, {12345.830995522321, 12346.66622688192}}, {}}, 0.3);
  expectGoodMesh({{{1000047.7668244563, -333318.55732300022}, {999963.32018745679, -333299.35405506258}, {999988.91298808693, -333382.08862193709}}, {}}, 5);
}

// Deep trees (vertices 1e-9 apart) and far offsets round more coarsely than 1e-6 tree units; the
// snapping tolerance follows.
TEST(Mesher, RoundingOfDeepTreesAndFarOffsets) {
  expectGoodMesh({{{0, 0}, {0.80802750831215187, 0.5891447579422695}, {0.21888275036988236, 1.3971722662544215},
                   {-0.58914475713424197, 0.8080275089012966}, {-0.58914475735312477, 0.80802750750412433}}, {}},
                 0.25);
  expectGoodMesh({{{-7416671.1031101998, 1502475.9262439848}, {-7416670.0739553943, 1502510.0250075285},
                   {-7416637.326077804, 1502519.5833205667}, {-7416618.1159311989, 1502491.3919193558},
                   {-7416638.9912852589, 1502464.4103621789}}, {}},
                 18.823691242856832);
}

// Points a leaf adds on an input edge (the feet of its other points) lie off the edge's line by
// the rounding of tree coordinates: near this spike's tip (43.2, -77.4), in a tree 22 levels
// deep, by a billionth of their distance apart. Three such made a quad's corner that turned left
// by a sine of 1.1e-9 in tree coordinates, just past kMinTurnSine, and right in the plane.
// Corners must turn by more than rounding can undo.
TEST(Mesher, PointsAddedOnAnEdgeMakeNoStraightCorner) {
  expectGoodMesh({{{83, 10}, {79.523845026884885, 49.91850765512585}, {25, 41}, {-13, 43}, {-21, 3},
                   {-65.067745551664729, 3.2371183673459143}, {-45, -42}, {-1.9183419929839758, -41.802144787858367},
                   {-11.26714809816627, -99.106160158870424}, {7, -102}, {18.900425323933124, -47.591120786923767},
                   {43.245563627600916, -77.365357381076407}, {30, -42}, {51, -44}, {88.624591243366538, -59.486001445851713},
                   {92, -18}},
                  {}},
                 4);
}

// Two holes a hair apart crowd many vertices along the gap; meshing stays fast (this once took
// seconds with spatially laid-out vertex ids).
TEST(Mesher, HolesAHairApart) {
  const double g = 1e-4;
  expectGoodMesh({{{0, 0}, {16, 0}, {16, 16}, {0, 16}},
                  {{{4, 4}, {4, 12}, {7.3 - g / 2, 12}, {7.3 - g / 2, 4}}, {{7.3 + g / 2, 4}, {7.3 + g / 2, 12}, {12, 12}, {12, 4}}}},
                 1);
}

// The checks themselves catch broken meshes, so a passing mesh means something.
TEST(MeshChecks, CatchBrokenMeshes) {
  const PolygonWithHoles square{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {}};
  Mesh mesh = meshPolygon(square, {1});
  ASSERT_EQ(mesh.elements.size(), 4u);
  EXPECT_EQ(checkMesh(square, mesh).tVertices, 0u);

  Mesh missing = mesh;
  missing.elements.pop_back();
  const MeshCheck holed = checkMesh(square, missing);
  EXPECT_LT(holed.elementArea, holed.polygonArea);
  EXPECT_GT(holed.unmatchedInnerEdges, 0u);

  Mesh moved = mesh;
  moved.vertices[0].x += 1e-3;
  EXPECT_EQ(checkMesh(square, moved).movedInputVertices, 1u);

  // Replace the two right quads by one: the centre of its left edge becomes a T-vertex.
  Mesh coarse;
  coarse.vertices = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0}, {1, 1}, {1, 2}, {0, 1}};
  coarse.elements = {{0, 4, 5, 7}, {7, 5, 6, 3}, {4, 1, 2, 6}};
  EXPECT_GT(checkMesh(square, coarse).tVertices, 0u);

  Mesh flipped = mesh;
  std::swap(flipped.elements[0][1], flipped.elements[0][3]);
  EXPECT_GT(checkMesh(square, flipped).notCounterClockwiseOrConvex, 0u);
}

// Far from the origin the rounding of computed points (1e-12 of the coordinates) is as large as
// an element can be: at (1e5, 1e5), 1e-7. The corners of a triangle that small lie as close to
// the opposite edges, at an angle to them, and counted as T-vertices. A broken mesh that small
// still shows its one: the centre of the right quad's left edge in the mesh above.
TEST(MeshChecks, CornersOfElementsSmallerThanTheRoundingAreNoTVertices) {
  const Vec2 far{1e5, 1e5};
  const PolygonWithHoles triangle{{far, far + Vec2{1e-7, 0}, far + Vec2{0.4e-7, 0.6e-7}}, {}};
  Mesh one;
  one.vertices = triangle.outer;
  one.elements = {{0, 1, 2, Mesh::kNone}};
  EXPECT_EQ(checkMesh(triangle, one).tVertices, 0u);

  Mesh coarse;
  for (const Vec2 v : {Vec2{0, 0}, Vec2{2, 0}, Vec2{2, 2}, Vec2{0, 2}, Vec2{1, 0}, Vec2{1, 1}, Vec2{1, 2}, Vec2{0, 1}})
    coarse.vertices.push_back(far + 1e-7 * v);
  coarse.elements = {{0, 4, 5, 7}, {7, 5, 6, 3}, {4, 1, 2, 6}};
  const PolygonWithHoles square{{coarse.vertices.begin(), coarse.vertices.begin() + 4}, {}};
  EXPECT_EQ(checkMesh(square, coarse).tVertices, 1u);
}

}  // namespace
}  // namespace mesher
