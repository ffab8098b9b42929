#include "engine/session/walk_controls.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace engine {

double defaultWalkSpeed(const engine::Scene& scene) { return 1.4 / scene.metersPerUnit; }

void applyWalk(const WalkInput& input, double seconds, WalkSettings& settings, ViewCamera& camera) {
  settings.speed = std::clamp(settings.speed * std::pow(1.2, input.scroll), 1e-6, 1e9);

  // Mouse right turns right (yaw toward the image's right), mouse up looks up.
  const double maxPitch = glm::radians(89.0);
  camera.yaw -= input.lookDx * settings.radiansPerPixel;
  camera.pitch = std::clamp(camera.pitch - input.lookDy * settings.radiansPerPixel, -maxPitch, maxPitch);

  const glm::dvec3 heading{std::sin(camera.yaw), 0, std::cos(camera.yaw)};
  const glm::dvec3 side = glm::cross(heading, glm::dvec3{0, 1, 0});
  glm::dvec3 move{0};
  if (input.forward) move += heading;
  if (input.back) move -= heading;
  if (input.right) move += side;
  if (input.left) move -= side;
  if (input.up) move.y += 1;
  if (input.down) move.y -= 1;
  if (glm::length(move) > 0) {
    const double speed = settings.speed * (input.fast ? 4 : 1);
    camera.position += glm::normalize(move) * speed * seconds;
  }
}

}  // namespace engine
