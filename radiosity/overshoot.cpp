#include "radiosity/overshoot.h"

#include <glm/geometric.hpp>

namespace radiosity {

glm::dvec3 gatherUnshot(std::span<const pxpl5::IdFactor> factors, const glm::dvec3& eye, const ElementPlanes& planes,
                        std::span<const glm::dvec3> unshot) {
  glm::dvec3 gathered{0};
  for (const pxpl5::IdFactor& f : factors)
    if (glm::dot(planes.normal(f.id), eye) > planes.offset[f.id]) gathered += f.factor * unshot[f.id];
  return gathered;
}

}  // namespace radiosity
