// The camera conventions of spec/scene-format.md (CAMERA).
#include "app/view/view_camera.h"

#include "engine/scene_loader.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

namespace app {
namespace {

engine::Scene unitScene() {
  engine::Scene scene;
  scene.boundsMin = glm::dvec3{-10};
  scene.boundsMax = glm::dvec3{10};
  return scene;
}

glm::dvec3 toNdc(const glm::mat4& clipFromWorld, const glm::dvec3& p) {
  const glm::vec4 clip = clipFromWorld * glm::vec4(glm::vec3(p), 1.0f);
  return glm::dvec3(clip) / static_cast<double>(clip.w);
}

// The image's right is (look_at - position) x up; its vertical is `up` made perpendicular.
TEST(ViewCamera, RightIsViewCrossUpAndUpIsUp) {
  engine::Camera c;
  c.position = {0, 0, 0};
  c.lookAt = {0, 0, 5};
  const engine::Scene scene = unitScene();
  const glm::mat4 m = clipFromWorld(fromSceneCamera(c), 1.0, scene);
  const glm::dvec3 right = glm::cross(c.lookAt - c.position, c.up);  // -x
  EXPECT_GT(toNdc(m, c.lookAt + glm::normalize(right)).x, 0.1);
  EXPECT_GT(toNdc(m, c.lookAt + glm::dvec3{0, 1, 0}).y, 0.1);
  EXPECT_NEAR(toNdc(m, c.lookAt).x, 0, 1e-6);
}

// fov_y is the full vertical field: a point at the half-angle lands on the top edge.
TEST(ViewCamera, VerticalFieldOfViewSpansTheImage) {
  engine::Camera c;
  c.position = {0, 0, 0};
  c.lookAt = {0, 0, 1};
  c.fovYDeg = 40;
  const glm::mat4 m = clipFromWorld(fromSceneCamera(c), 2.0, unitScene());
  const double t = std::tan(glm::radians(20.0));
  EXPECT_NEAR(toNdc(m, {0, 5 * t, 5}).y, 1, 1e-5);
  EXPECT_NEAR(toNdc(m, {-2 * 5 * t, 0, 5}).x, 1, 1e-5);  // square pixels: aspect 2
}

TEST(ViewCamera, TiltedUpVectorsAreKept) {
  engine::Camera c;
  c.position = {0, 10, 0};
  c.lookAt = {0, 0, 0};
  c.up = {0, 0, 1};  // looking straight down, +z at the top of the image
  const glm::mat4 m = clipFromWorld(fromSceneCamera(c), 1.0, unitScene());
  EXPECT_GT(toNdc(m, {0, 0, 1}).y, 0.01);
}

TEST(ViewCamera, ChooseCameraPrefersTheNamedThenDefaultThenFirst) {
  engine::Scene scene = unitScene();
  engine::Camera a, b;
  a.name = "a";
  a.position = {1, 0, 0};
  b.name = "default";
  b.position = {2, 0, 0};
  scene.cameras = {a, b};
  ViewCamera chosen;
  ASSERT_TRUE(chooseCamera(scene, "", chosen));
  EXPECT_EQ(chosen.position.x, 2);
  ASSERT_TRUE(chooseCamera(scene, "a", chosen));
  EXPECT_EQ(chosen.position.x, 1);
  EXPECT_FALSE(chooseCamera(scene, "nope", chosen));
  scene.cameras = {a};
  ASSERT_TRUE(chooseCamera(scene, "", chosen));
  EXPECT_EQ(chosen.position.x, 1);
}

TEST(ViewCamera, OverviewSeesTheWholeScene) {
  const engine::Scene scene = unitScene();
  ViewCamera camera;
  ASSERT_TRUE(chooseCamera(scene, "", camera));
  const glm::mat4 m = clipFromWorld(camera, 4.0 / 3, scene);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p{corner & 1 ? 10 : -10, corner & 2 ? 10 : -10, corner & 4 ? 10 : -10};
    const glm::dvec3 ndc = toNdc(m, p);
    EXPECT_LE(std::abs(ndc.x), 1);
    EXPECT_LE(std::abs(ndc.y), 1);
    EXPECT_LE(std::abs(ndc.z), 1);
  }
}

}  // namespace
}  // namespace app
