#include "engine/scene.h"

#include <glm/common.hpp>

#include <algorithm>

namespace engine {

void Scene::computeBounds() {
  bool first = true;
  for (const Surface& s : surfaces)
    for (const Vec3& p : s.outer) {
      boundsMin = first ? p : glm::min(boundsMin, p);
      boundsMax = first ? p : glm::max(boundsMax, p);
      first = false;
    }
}

const Camera* Scene::findCamera(const std::string& name) const {
  for (const Camera& camera : cameras)
    if (camera.name == name) return &camera;
  return nullptr;
}

double sceneExtent(const Scene& scene) {
  const Vec3 size = scene.boundsMax - scene.boundsMin;
  return std::max({size.x, size.y, size.z});
}

double metersPerUnit(std::string_view units) {
  if (units == "m") return 1;
  if (units == "cm") return 0.01;
  if (units == "mm") return 0.001;
  if (units == "in") return 0.0254;
  if (units == "ft") return 0.3048;
  return 0;
}

}  // namespace engine
