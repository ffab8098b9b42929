#include "engine/session/walk_controls.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

namespace engine {
namespace {

ViewCamera lookingAlongZ() {
  ViewCamera camera;
  camera.position = {0, 1.6, 0};
  return camera;
}

TEST(WalkControls, ForwardWalksAlongTheHeadingAtTheSpeed) {
  ViewCamera camera = lookingAlongZ();
  camera.pitch = glm::radians(30.0);  // looking up does not lift the walker
  WalkSettings settings{2.0};
  WalkInput input;
  input.forward = true;
  applyWalk(input, 0.5, settings, camera);
  EXPECT_NEAR(camera.position.z, 1.0, 1e-12);
  EXPECT_NEAR(camera.position.y, 1.6, 1e-12);
}

TEST(WalkControls, StrafingGoesToTheImageRight) {
  ViewCamera camera = lookingAlongZ();
  WalkSettings settings{1.0};
  WalkInput input;
  input.right = true;
  applyWalk(input, 1, settings, camera);
  EXPECT_NEAR(glm::dot(camera.position - glm::dvec3{0, 1.6, 0}, lookingAlongZ().right()), 1, 1e-12);
}

TEST(WalkControls, UpAndDownAreVerticalAndShiftIsFaster) {
  ViewCamera camera = lookingAlongZ();
  WalkSettings settings{1.0};
  WalkInput input;
  input.up = true;
  input.fast = true;
  applyWalk(input, 1, settings, camera);
  EXPECT_NEAR(camera.position.y, 1.6 + 4, 1e-12);
}

TEST(WalkControls, MouseRightTurnsRightAndMouseUpLooksUp) {
  ViewCamera camera = lookingAlongZ();
  const glm::dvec3 rightBefore = camera.right();
  WalkSettings settings;
  WalkInput input;
  input.lookDx = 50;
  input.lookDy = -50;
  applyWalk(input, 0.016, settings, camera);
  EXPECT_GT(glm::dot(camera.forward(), rightBefore), 0);
  EXPECT_GT(camera.pitch, 0);
}

TEST(WalkControls, PitchStopsShortOfStraightUp) {
  ViewCamera camera = lookingAlongZ();
  WalkSettings settings;
  WalkInput input;
  input.lookDy = -1e6;
  applyWalk(input, 0.016, settings, camera);
  EXPECT_NEAR(camera.pitch, glm::radians(89.0), 1e-12);
}

TEST(WalkControls, WheelScalesTheSpeed) {
  ViewCamera camera = lookingAlongZ();
  WalkSettings settings{1.0};
  WalkInput input;
  input.scroll = 2;
  applyWalk(input, 0, settings, camera);
  EXPECT_NEAR(settings.speed, 1.44, 1e-12);
}

TEST(WalkControls, DefaultSpeedIsWalkingPaceInSceneUnits) {
  engine::Scene scene;
  scene.metersPerUnit = 0.0254;
  EXPECT_NEAR(defaultWalkSpeed(scene), 1.4 / 0.0254, 1e-9);
}

}  // namespace
}  // namespace engine
