#include "radiosity/ambient.h"

#include <glm/common.hpp>

namespace radiosity {

glm::dvec3 ambientRadiance(std::span<const SurfaceLight> surfaces) {
  double totalArea = 0;
  glm::dvec3 reflected{0}, unshot{0};
  for (const SurfaceLight& s : surfaces) {
    totalArea += s.area;
    reflected += s.reflectance * s.area;
    unshot += s.unshotRadiance * s.area;
  }
  if (totalArea <= 0) return glm::dvec3{0};
  const glm::dvec3 meanReflectance = glm::min(reflected / totalArea, glm::dvec3{0.999});
  return unshot / totalArea / (1.0 - meanReflectance);
}

}  // namespace radiosity
