// Which triangles a frame draws at its level of detail, without GL: the depth and pixel measures,
// evenness with its hysteresis, and each surface's choice between its elements and its outline.
#include "app/gl/level_of_detail.h"

#include "engine/document/display_mesh.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace app {
namespace {

// A camera at the origin looking down -z, 60 degrees high, 640 x 480.
glm::mat4 lookingDownZ() {
  return glm::perspective(glm::radians(60.0f), 640.0f / 480.0f, 0.1f, 1000.0f) *
         glm::lookAt(glm::vec3{0}, glm::vec3{0, 0, -1}, glm::vec3{0, 1, 0});
}

// A surface of `n` x `n` unit squares (two triangles each) whose outline is two triangles,
// `extent` across, with radiance 1.
engine::SurfaceDisplay grid(int n, float extent) {
  engine::SurfaceDisplay s;
  s.positions.assign(static_cast<size_t>((n + 1) * (n + 1)), glm::vec3{0});
  s.radiance.assign(s.positions.size(), glm::vec3{1});
  for (int t = 0; t < 2 * n * n; ++t) s.triangles.insert(s.triangles.end(), {0, 1, 2});
  s.outline = {0, 1, 2, 0, 2, 3};
  s.extent = extent;
  return s;
}

TEST(LevelOfDetail, DepthIsThatOfTheNearestCornerAndBandsDoubleIt) {
  const glm::mat4 clip = lookingDownZ();
  EXPECT_NEAR(nearestDepth(clip, {-1, -1, -12}, {1, 1, -5}), 5, 1e-4);
  EXPECT_NEAR(nearestDepth(clip, {2, 0, -9}, {3, 1, -7}), 7, 1e-4);
  EXPECT_LE(nearestDepth(clip, {-1, -1, -1}, {1, 1, 1}), 0);  // around the eye
  EXPECT_EQ(depthBand(5), 2);
  EXPECT_EQ(depthBand(8), 3);
  EXPECT_EQ(depthBand(0.75f), -1);
  EXPECT_EQ(depthBand(0), kNearBand);
  EXPECT_EQ(depthBand(-3), kNearBand);
}

// Half the height over tan(30 degrees): what a unit a unit away covers on the screen, whatever
// the view's turn.
TEST(LevelOfDetail, PixelsPerUnitFollowTheFieldOfView) {
  const float expected = 240.0f / std::tan(glm::radians(30.0f));
  EXPECT_NEAR(pixelsPerUnit(lookingDownZ(), 640), expected, 1e-3 * expected);
  const glm::mat4 turned = glm::perspective(glm::radians(60.0f), 640.0f / 480.0f, 0.1f, 1000.0f) *
                           glm::lookAt(glm::vec3{3, 1, 2}, glm::vec3{-4, 0.5f, 7}, glm::vec3{0, 1, 0});
  EXPECT_NEAR(pixelsPerUnit(turned, 640), expected, 1e-3 * expected);
}

TEST(LevelOfDetail, EvennessHasHysteresis) {
  const DetailSettings settings;
  const std::vector<glm::vec3> flat(4, glm::vec3{2}), slight = {glm::vec3{1}, glm::vec3{1.025f}}, strong = {glm::vec3{1}, glm::vec3{1.5f}};
  EXPECT_TRUE(evenlyLit(flat, false, settings));
  EXPECT_FALSE(evenlyLit(slight, false, settings));  // 2.5% does not make it even...
  EXPECT_TRUE(evenlyLit(slight, true, settings));    // ...nor uneven
  EXPECT_FALSE(evenlyLit(strong, true, settings));
  EXPECT_TRUE(evenlyLit(std::vector<glm::vec3>(3, glm::vec3{0}), false, settings));  // black is even
}

// The elements near the eye or large on the screen and unevenly lit; the outline when the surface
// is a few pixels across at the band's nearest depth, or evenly lit at any depth; never without
// an outline.
TEST(LevelOfDetail, ASurfaceIsDrawnAsItsOutlineOnlyWhereItsElementsCannotShow) {
  const DetailSettings settings;
  const engine::SurfaceDisplay small = grid(4, 0.01f);  // 1 cm
  const float perUnit = 1000;                          // pixels per unit at depth 1
  EXPECT_FALSE(drawsOutline(small, kNearBand, perUnit, false, settings));
  EXPECT_FALSE(drawsOutline(small, -4, perUnit, false, settings));  // 1/16 away: 160 pixels
  EXPECT_FALSE(drawsOutline(small, 1, perUnit, false, settings));   // 2 away: 5 pixels
  EXPECT_TRUE(drawsOutline(small, 2, perUnit, false, settings));    // 4 away: 2.5 pixels
  EXPECT_TRUE(drawsOutline(small, -4, perUnit, true, settings));    // near, but evenly lit
  EXPECT_TRUE(drawsOutline(small, kNearBand, perUnit, true, settings));
  engine::SurfaceDisplay noOutline = small;
  noOutline.outline.clear();
  EXPECT_FALSE(drawsOutline(noOutline, 10, perUnit, true, settings));
}

// A chunk's triangles: each surface's choice, its indices moved past the surfaces before it.
TEST(LevelOfDetail, AChunkGathersEachSurfacesChoice) {
  engine::DisplayMesh mesh;
  mesh.surfaces = {grid(2, 0.01f), grid(3, 10), grid(2, 0.01f)};
  const std::vector<uint8_t> even = {0, 0, 1};
  std::vector<uint32_t> out;
  gatherTriangles(mesh, std::vector<uint32_t>{0, 1, 2}, 3, 1000, even, DetailSettings{}, out);  // 8 away
  const uint32_t second = 9, third = 9 + 16;
  const std::vector<uint32_t> expected = [&] {
    std::vector<uint32_t> e = {0, 1, 2, 0, 2, 3};  // small: its outline
    for (int t = 0; t < 18; ++t) e.insert(e.end(), {second, second + 1, second + 2});  // large: its elements
    e.insert(e.end(), {third, third + 1, third + 2, third, third + 2, third + 3});     // evenly lit: its outline
    return e;
  }();
  EXPECT_EQ(out, expected);
  gatherTriangles(mesh, std::vector<uint32_t>{0, 1, 2}, kNearBand, 1000, even, DetailSettings{}, out);
  EXPECT_EQ(out.size(), 3u * (8 + 18 + 2));  // the evenly lit one still its outline
}

}  // namespace
}  // namespace app
