// The camera conventions of spec/scene-format.md (CAMERA).
#include "engine/session/view_camera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

namespace engine {
namespace {

engine::Scene unitScene() {
  engine::Scene scene;
  scene.boundsMin = glm::dvec3{-10};
  scene.boundsMax = glm::dvec3{10};
  return scene;
}

// Where the world point `p` lands, drawn as a display mesh does: in float, less `origin`.
glm::dvec3 toNdc(const glm::mat4& clipFromDisplay, const glm::dvec3& p, const glm::dvec3& origin = glm::dvec3{0}) {
  const glm::vec4 clip = clipFromDisplay * glm::vec4(glm::vec3(p - origin), 1.0f);
  return glm::dvec3(clip) / static_cast<double>(clip.w);
}

// The image's right is (look_at - position) x up; its vertical is `up` made perpendicular.
TEST(ViewCamera, RightIsViewCrossUpAndUpIsUp) {
  engine::Camera c;
  c.position = {0, 0, 0};
  c.lookAt = {0, 0, 5};
  const engine::Scene scene = unitScene();
  const glm::mat4 m = clipFromDisplay(fromSceneCamera(c), 1.0, scene, {});
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
  const glm::mat4 m = clipFromDisplay(fromSceneCamera(c), 2.0, unitScene(), {});
  const double t = std::tan(glm::radians(20.0));
  EXPECT_NEAR(toNdc(m, {0, 5 * t, 5}).y, 1, 1e-5);
  EXPECT_NEAR(toNdc(m, {-2 * 5 * t, 0, 5}).x, 1, 1e-5);  // square pixels: aspect 2
}

TEST(ViewCamera, TiltedUpVectorsAreKept) {
  engine::Camera c;
  c.position = {0, 10, 0};
  c.lookAt = {0, 0, 0};
  c.up = {0, 0, 1};  // looking straight down, +z at the top of the image
  const glm::mat4 m = clipFromDisplay(fromSceneCamera(c), 1.0, unitScene(), {});
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
  const glm::mat4 m = clipFromDisplay(camera, 4.0 / 3, scene, {});
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p{corner & 1 ? 10 : -10, corner & 2 ? 10 : -10, corner & 4 ? 10 : -10};
    const glm::dvec3 ndc = toNdc(m, p);
    EXPECT_LE(std::abs(ndc.x), 1);
    EXPECT_LE(std::abs(ndc.y), 1);
    EXPECT_LE(std::abs(ndc.z), 1);
  }
}

// A room 900 km from the world's origin (within the format's 1e6 limit) draws as it does at the
// origin: float world coordinates there are 6 cm apart, the display's about its middle are not.
TEST(ViewCamera, ARoomFarFromTheOriginDrawsAsAtTheOrigin) {
  const glm::dvec3 far{900000, 0, 900000};
  engine::Camera c;
  c.position = {0.1, 0.8, 0.1};
  c.lookAt = {0.9, 0.2, 0.9};
  engine::Scene near;
  near.boundsMin = glm::dvec3{0};
  near.boundsMax = glm::dvec3{1};
  engine::Scene away = near;
  away.boundsMin += far;
  away.boundsMax += far;
  engine::Camera farCamera = c;
  farCamera.position += far;
  farCamera.lookAt += far;
  const glm::mat4 m = clipFromDisplay(fromSceneCamera(c), 1.0, near, {});
  const glm::dvec3 origin = far + glm::dvec3{0.5};
  const glm::mat4 mFar = clipFromDisplay(fromSceneCamera(farCamera), 1.0, away, origin);
  for (const glm::dvec3 p : {glm::dvec3{0.5, 0.1, 0.6}, glm::dvec3{0.501, 0.1, 0.6}, glm::dvec3{0.3, 0.7, 0.95}}) {
    const glm::dvec3 expected = toNdc(m, p), got = toNdc(mFar, p + far, origin);
    EXPECT_NEAR(got.x, expected.x, 1e-5);
    EXPECT_NEAR(got.y, expected.y, 1e-5);
  }
  // Two points a millimetre apart stay apart (in float world coordinates they would coincide).
  EXPECT_GT(std::abs(toNdc(mFar, far + glm::dvec3{0.501, 0.1, 0.6}, origin).x - toNdc(mFar, far + glm::dvec3{0.5, 0.1, 0.6}, origin).x), 1e-4);
}

}  // namespace
}  // namespace engine
