#include "radiosity/item_buffer.h"

#include <glm/geometric.hpp>

#include <bit>
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

TargetsSeen itemBufferTargets(const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes, const glm::dvec3& eye,
                              std::span<const glm::dvec3> targets, uint32_t element, const ElementPlanes& planes) {
  const int resolution = frame.width;
  TargetsSeen seen;
  for (size_t k = 0; k < targets.size(); ++k) {
    const glm::dvec3 d = targets[k] - eye;
    if (glm::dot(d, axes.z) <= 0) continue;  // on or below the horizon
    // Pixel (i, j) looks along x = (i + 0.5) * 2 / resolution - 1: the nearest centre to x, as
    // floor((x + 1) * resolution / 2); x + 1 >= 0, so the conversion truncates it the same.
    const double scale = 0.5 * resolution / std::sqrt(glm::dot(d, d));
    const int i = static_cast<int>(glm::dot(d, axes.x) * scale + 0.5 * resolution);
    const int j = static_cast<int>(glm::dot(d, axes.y) * scale + 0.5 * resolution);
    if (i < 0 || j < 0 || i >= resolution || j >= frame.height) continue;
    const uint32_t bit = 1u << k;
    seen.considered |= bit;
    const uint32_t item = frame.items[static_cast<size_t>(j) * frame.stride + i];
    if (item == pxpl5::kNoValue || item == element || planes.surface[item] == planes.surface[element]) {
      seen.visible |= bit;
      continue;
    }
    // Where the seen polygon's plane meets the segment, as a fraction of it.
    const double along = glm::dot(planes.normal[item], d);
    const double t = along != 0 ? (planes.offset[item] - glm::dot(planes.normal[item], eye)) / along : -1;
    if (!(t > 0 && t < 1 - 1e-9)) seen.visible |= bit;
  }
  return seen;
}

double visibleShare(const TargetsSeen& seen, uint32_t mask) {
  const int considered = std::popcount(seen.considered & mask);
  return considered > 0 ? double(std::popcount(seen.visible & mask)) / double(considered) : 1.0;
}

double itemBufferVisibility(const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes, const glm::dvec3& eye,
                            std::span<const glm::dvec3> targets, uint32_t element, const ElementPlanes& planes) {
  return visibleShare(itemBufferTargets(frame, axes, eye, targets, element, planes), ~0u);
}

}  // namespace radiosity
