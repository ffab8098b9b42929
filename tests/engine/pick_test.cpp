// Picking surfaces with rays, as a click in the window does.
#include "engine/geometry/pick.h"
#include "tests/engine/test_scenes.h"

#include <gtest/gtest.h>

namespace engine {
namespace {

TEST(Pick, TheNearestSurfaceAlongTheRay) {
  const Scene scene = test::parse(test::baseScene());
  // Looking down from inside the room onto the box's top (y = 1, x and z in 1..2).
  const auto hit = pickSurface(scene, {1.5, 2, 1.5}, {0, -1, 0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(scene.objects[scene.surfaces[hit->surface].object].name, "box");
  EXPECT_EQ(scene.surfaces[hit->surface].face, "top");
  EXPECT_DOUBLE_EQ(hit->distance, 1);
  EXPECT_EQ(hit->point, (Vec3{1.5, 1, 1.5}));
  // Beside the box, the floor.
  const auto floor = pickSurface(scene, {3, 2, 2.5}, {0, -2, 0});
  ASSERT_TRUE(floor);
  EXPECT_EQ(scene.objects[scene.surfaces[floor->surface].object].name, "room");
  EXPECT_DOUBLE_EQ(floor->distance, 1);
}

TEST(Pick, HolesAreSeenThroughAndFillsAreHit) {
  const Scene scene = test::parse(test::baseScene());
  // Straight up through the ceiling's filled hole (x, z in 1..2): the lamp, not the ceiling.
  const auto lamp = pickSurface(scene, {1.5, 1.5, 1.5}, {0, 1, 0});
  ASSERT_TRUE(lamp);
  EXPECT_NE(scene.surfaces[lamp->surface].face.find("fill"), std::string::npos);
  const auto ceiling = pickSurface(scene, {3, 1.5, 2.5}, {0, 1, 0});
  ASSERT_TRUE(ceiling);
  EXPECT_EQ(scene.surfaces[ceiling->surface].face, "top");
}

TEST(Pick, NothingBehindOrBesideTheScene) {
  const Scene scene = test::parse(test::baseScene());
  EXPECT_FALSE(pickSurface(scene, {10, 1, 1}, {1, 0, 0}));
  EXPECT_FALSE(pickSurface(scene, {1.5, 1, 1.5}, {0, 0, 0}));
}

}  // namespace
}  // namespace engine
