#include "engine/session/view_camera.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace engine {

glm::dvec3 ViewCamera::forward() const {
  return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

glm::dvec3 ViewCamera::right() const { return glm::normalize(glm::cross(forward(), up)); }

ViewCamera fromSceneCamera(const engine::Camera& camera) {
  const glm::dvec3 d = glm::normalize(camera.lookAt - camera.position);
  ViewCamera view;
  view.position = camera.position;
  view.yaw = std::atan2(d.x, d.z);
  view.pitch = std::asin(std::clamp(d.y, -1.0, 1.0));
  view.up = glm::normalize(camera.up);
  view.fovYDeg = camera.fovYDeg;
  return view;
}

ViewCamera overviewCamera(const engine::Scene& scene) {
  const glm::dvec3 center = 0.5 * (scene.boundsMin + scene.boundsMax);
  const double radius = std::max(0.5 * glm::length(scene.boundsMax - scene.boundsMin), 1e-9);
  const glm::dvec3 direction = glm::normalize(glm::dvec3{0.5, -0.4, 1.0});
  engine::Camera camera;
  camera.fovYDeg = 50;
  camera.lookAt = center;
  camera.position = center - direction * (radius / std::sin(glm::radians(camera.fovYDeg / 2)));
  return fromSceneCamera(camera);
}

bool chooseCamera(const engine::Scene& scene, const std::string& name, ViewCamera& out) {
  if (!name.empty()) {
    const engine::Camera* camera = scene.findCamera(name);
    if (!camera) return false;
    out = fromSceneCamera(*camera);
    return true;
  }
  if (const engine::Camera* camera = scene.findCamera("default")) out = fromSceneCamera(*camera);
  else if (!scene.cameras.empty()) out = fromSceneCamera(scene.cameras.front());
  else out = overviewCamera(scene);
  return true;
}

glm::mat4 clipFromDisplay(const ViewCamera& camera, double aspect, const engine::Scene& scene, const glm::dvec3& origin) {
  const glm::dvec3 center = 0.5 * (scene.boundsMin + scene.boundsMax);
  const double diagonal = std::max(glm::length(scene.boundsMax - scene.boundsMin), 1e-9);
  const double farPlane = glm::length(camera.position - center) + diagonal;
  const double nearPlane = std::min(diagonal * 5e-4, farPlane * 1e-3);
  const glm::dmat4 viewFromWorld = glm::lookAt(camera.position, camera.position + camera.forward(), camera.up);
  const glm::dmat4 clipFromView = glm::perspective(glm::radians(camera.fovYDeg), aspect, nearPlane, farPlane);
  return glm::mat4(clipFromView * glm::translate(viewFromWorld, origin));
}

glm::dvec3 rayThrough(const ViewCamera& camera, double aspect, glm::dvec2 ndc) {
  const glm::dvec3 forward = camera.forward(), right = camera.right();
  const glm::dvec3 up = glm::cross(right, forward);  // the image's vertical (glm::lookAt's)
  const double halfHeight = std::tan(glm::radians(camera.fovYDeg) / 2);
  return glm::normalize(forward + ndc.x * halfHeight * aspect * right + ndc.y * halfHeight * up);
}

}  // namespace engine
