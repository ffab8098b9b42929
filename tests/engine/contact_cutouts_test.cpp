// Contact cut-outs at any finite offset: a plane's cell index stays a defined integer however far
// the plane lies or however small the tolerance (UBSan once found a double-to-int64 overflow when
// `--move` took a box to 1e308).
#include "engine/geometry/contact_cutouts.h"

#include <gtest/gtest.h>

#include <vector>

namespace engine {
namespace {

// A 4 x 4 floor facing up at height `floorY` (object 0) and a 1 x 1 box bottom facing down at
// `boxY` over its middle (object 1).
std::vector<Surface> boxOverFloor(double floorY, double boxY) {
  Surface floor;
  floor.outer = {{0, floorY, 0}, {0, floorY, 4}, {4, floorY, 4}, {4, floorY, 0}};
  floor.normal = {0, 1, 0};
  floor.area = 16;
  Surface bottom;
  bottom.outer = {{1, boxY, 1}, {2, boxY, 1}, {2, boxY, 2}, {1, boxY, 2}};
  bottom.normal = {0, -1, 0};
  bottom.area = 1;
  bottom.object = 1;
  return {floor, bottom};
}

TEST(ContactCutouts, AFootprintIsCutAtAnyHeightAndTolerance) {
  for (const double y : {0.5, -3.0, 1e12, 1e300, -1e300, 1.7e308})
    for (const double tolerance : {1e-6, 0.0}) {
      std::vector<Surface> surfaces = boxOverFloor(y, y);
      EXPECT_EQ(cutOutContacts(surfaces, tolerance), 1u) << "at height " << y << ", tolerance " << tolerance;
      EXPECT_EQ(surfaces[0].contactHoles, 1u);
    }
}

// Far planes share the end cells of the plane index; the exact comparison still keeps apart those
// that are apart.
TEST(ContactCutouts, FarPlanesApartAreNotCut) {
  for (const auto& [floorY, boxY] : {std::pair{1e300, 2e300}, {1e300, -1e300}, {1.7e308, -1.7e308}, {0.0, 1e-300}}) {
    std::vector<Surface> surfaces = boxOverFloor(floorY, boxY);
    EXPECT_EQ(cutOutContacts(surfaces, 0), 0u) << "floor at " << floorY << ", box at " << boxY;
  }
}

}  // namespace
}  // namespace engine
