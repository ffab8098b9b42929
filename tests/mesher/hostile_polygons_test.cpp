// The polygons of issue 19 that hung the mesher or meshed with T-vertices, and random hostile
// polygons (hostile_polygons.h): each is meshed validly or refused (MeshRefused, with its
// reason), with the work (quadrants made) within the limit of mesher.h.
#include "mesher/mesh_check.h"
#include "mesher/mesher.h"
#include "tests/mesher/hostile_polygons.h"
#include "tests/mesher/mesh_expectations.h"

#include <gtest/gtest.h>

#include <optional>

namespace mesher {
namespace {

// The reason the mesher refused the polygon, or nothing when it meshed it (then validly).
std::optional<MeshRefused::Reason> refusal(const PolygonWithHoles& polygon, double patchSize, size_t maxQuadrants = kMaxQuadrants) {
  Mesher mesher;
  try {
    const Mesh mesh = mesher.mesh(polygon, {patchSize, maxQuadrants});
    test::expectValidMesh(checkMesh(polygon, mesh));
    EXPECT_LE(mesher.quadrantsMade(), maxQuadrants);
    return std::nullopt;
  } catch (const MeshRefused& refused) {
    EXPECT_LE(mesher.quadrantsMade(), maxQuadrants);
    return refused.reason();
  }
}

// A valid mesh, made with work in proportion to it: a few quadrants an element.
MeshCheck expectMeshedInProportion(const PolygonWithHoles& polygon, double patchSize) {
  Mesher mesher;
  const Mesh mesh = mesher.mesh(polygon, {patchSize});
  const MeshCheck c = checkMesh(polygon, mesh);
  test::expectValidMesh(c);
  EXPECT_LE(mesher.quadrantsMade(), 8 * mesh.elements.size());
  return c;
}

// The issue's needle: a triangle 0.375 wide and 1.7 million long. Leaves as fine as its width
// along its length pass the limit: it is refused as its tree reaches it (it ran past 20 s). A
// smaller limit keeps the test short; cli.mesh_needle_refused runs it at the default.
TEST(HostilePolygons, TheIssuesNeedleIsRefusedAsTooLarge) {
  const PolygonWithHoles needle{{{0, 0}, {1.52587890625e-05, 0.375}, {1737920, 0}}, {}};
  EXPECT_EQ(refusal(needle, 579306.67, size_t{1} << 18), MeshRefused::Reason::TooLarge);
}

// Thin but meshable at their patch sizes: a triangle a millionth as wide as it is long, a sliver
// pentagon, a hexagon with two vertices a nanometre apart.
TEST(HostilePolygons, AThinTriangleASliverAndVerticesAHairApartMesh) {
  expectMeshedInProportion({{{0, 0}, {1000, 0}, {1000, 0.001}}, {}}, 1);
  expectMeshedInProportion({{{0, 0}, {10, 0}, {20, 0.0001}, {10, 0.0002}, {0, 0.0001}}, {}}, 0.5);
  expectMeshedInProportion({{{0, 0}, {4, 0}, {5, 2}, {4, 4}, {0, 4}, {0, 3.999999999}}, {}}, 1);
}

// Combs of 50 and 2,000 teeth, one unit apart: the 50 meshed with 42 T-vertices and an element
// of 0 degrees; the 2,000 ran past 20 s.
TEST(HostilePolygons, CombsMeshWithoutTVertices) {
  for (const int teeth : {50, 2000}) {
    const MeshCheck c = expectMeshedInProportion({test::comb(teeth, 2, 1, 10), {}}, 1);
    EXPECT_EQ(c.belowAngleBound, 0u);
    EXPECT_GE(c.smallestAngleDeg, kAngleBoundDeg);
  }
}

// A patch size of 1e-12 on a unit square, or just under the scenes' limit (100,000 patches
// along an edge), needs more quadrants for its area alone than the limit: refused before any is
// made.
TEST(HostilePolygons, APatchSizeTooSmallForTheAreaIsRefusedAtOnce) {
  const PolygonWithHoles square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  for (const double patchSize : {1e-12, 1 / 99999.0}) {
    Mesher mesher;
    try {
      (void)mesher.mesh(square, {patchSize});
      ADD_FAILURE() << "meshed at patch size " << patchSize;
    } catch (const MeshRefused& refused) {
      EXPECT_EQ(refused.reason(), MeshRefused::Reason::TooLarge);
      EXPECT_EQ(mesher.quadrantsMade(), 0u);
    }
  }
}

// Two vertices a ten-billionth apart a hundred thousand from the origin: closer than its
// coordinates resolve the mesh's points, so refused as too fine (it used to mesh as deep as the
// tree goes, or give up as "cannot be separated").
TEST(HostilePolygons, VerticesAHairApartFarFromTheOriginAreTooFine) {
  const Vec2 o{1e5, 1e5};
  const PolygonWithHoles polygon{{o, o + Vec2{1, 0}, o + Vec2{1, 1}, o + Vec2{0, 1}, o + Vec2{0, 1 - 1e-10}}, {}};
  EXPECT_EQ(refusal(polygon, 0.25), MeshRefused::Reason::TooFine);
}

// Random needles, slivers, combs, stars and holes a hair apart, scaled from a millionth to a
// million and placed up to 3e8 from the origin, at patch sizes down to a hundred-thousandth of
// their extent: under a limit of 2^16 quadrants each is meshed validly or refused, and both
// happen often.
TEST(HostilePolygons, RandomHostilePolygonsMeshValidlyOrAreRefused) {
  std::mt19937 random(19);
  int meshed = 0, refused = 0;
  for (int i = 0; i < 120; ++i) {
    const test::HostilePolygon hostile = test::randomHostilePolygon(random);
    SCOPED_TRACE(hostile.kind + " " + test::polygonCaseJson(hostile));
    (refusal(hostile.polygon, hostile.patchSize, size_t{1} << 16) ? refused : meshed) += 1;
  }
  EXPECT_GT(meshed, 30);  // 53 and 67 when written
  EXPECT_GT(refused, 30);
}

}  // namespace
}  // namespace mesher
