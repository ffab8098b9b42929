#include "radiosity/item_buffer.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace radiosity {

HemisphereAxes hemisphereAxes(const glm::vec3& normal) {
  HemisphereAxes a;
  a.z = glm::normalize(glm::dvec3(normal));
  const double sign = std::copysign(1.0, a.z.z);
  const double p = -1.0 / (sign + a.z.z), q = a.z.x * a.z.y * p;
  a.x = {1.0 + sign * a.z.x * a.z.x * p, sign * q, -sign * a.z.x};
  a.y = {q, sign + a.z.y * a.z.y * p, -a.z.y};
  return a;
}

double itemBufferVisibility(const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes, const glm::dvec3& eye,
                            std::span<const glm::dvec3> targets, uint32_t element, const ElementPlanes& planes) {
  const int resolution = frame.width;
  int visible = 0, considered = 0;
  for (const glm::dvec3& target : targets) {
    int i = 0, j = 0;
    if (!targetPixel(axes, eye, resolution, target, i, j)) continue;
    const glm::dvec3 d = target - eye;
    ++considered;
    const uint32_t seen = frame.items[static_cast<size_t>(j) * frame.stride + i];
    if (seen == pxpl5::kNoValue || seen == element || planes.surface[seen] == planes.surface[element]) {
      ++visible;
      continue;
    }
    // Where the seen polygon's plane meets the segment, as a fraction of it.
    const double along = glm::dot(planes.normal(seen), d);
    const double t = along != 0 ? (planes.offset[seen] - glm::dot(planes.normal(seen), eye)) / along : -1;
    if (!(t > 0 && t < 1 - 1e-9)) ++visible;
  }
  return considered > 0 ? double(visible) / double(considered) : 1.0;
}

}  // namespace radiosity
