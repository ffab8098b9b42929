#include "radiosity/adaptive_refinement.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace radiosity {

namespace {

double elementArea(const Surface& surface, const std::array<uint32_t, 4>& corners) {
  const int n = corners[3] == kNone ? 3 : 4;
  glm::dvec3 sum{0};
  const glm::dvec3& a = surface.vertices[corners[0]];
  for (int k = 1; k + 1 < n; ++k) sum += glm::cross(surface.vertices[corners[k]] - a, surface.vertices[corners[k + 1]] - a);
  return 0.5 * glm::length(sum);
}

double longestEdge(const Surface& surface, const std::array<uint32_t, 4>& corners) {
  const int n = corners[3] == kNone ? 3 : 4;
  double longest = 0;
  for (int k = 0; k < n; ++k)
    longest = std::max(longest, glm::length(surface.vertices[corners[(k + 1) % n]] - surface.vertices[corners[k]]));
  return longest;
}

}  // namespace

double luminance(const glm::dvec3& radiance) { return 0.2126 * radiance.r + 0.7152 * radiance.g + 0.0722 * radiance.b; }

double meanLuminance(std::span<const Surface> surfaces, const Solver& solver, const glm::dvec3& ambient) {
  double sum = 0, area = 0;
  for (uint32_t s = 0; s < surfaces.size(); ++s) {
    const std::span<const glm::dvec3> radiance = solver.elementRadiance(s);
    const glm::dvec3 extra = surfaces[s].reflectance * ambient;
    for (size_t e = 0; e < surfaces[s].elements.size(); ++e) {
      const double a = elementArea(surfaces[s], surfaces[s].elements[e]);
      sum += a * luminance(radiance[e] + extra);
      area += a;
    }
  }
  return area > 0 ? sum / area : 0;
}

std::vector<double> luminanceJumps(const Surface& surface, std::span<const glm::dvec3> radiance, double floor) {
  const size_t count = surface.elements.size();
  std::vector<double> value(count), jump(count, 0.0);
  for (size_t e = 0; e < count; ++e) value[e] = luminance(radiance[e]);
  // Without T-vertices, neighbours within a surface share both ends of an edge.
  std::unordered_map<uint64_t, uint32_t> firstOfEdge;
  firstOfEdge.reserve(2 * count);
  for (uint32_t e = 0; e < count; ++e) {
    const std::array<uint32_t, 4>& c = surface.elements[e];
    const int n = c[3] == kNone ? 3 : 4;
    for (int k = 0; k < n; ++k) {
      const uint32_t a = std::min(c[k], c[(k + 1) % n]), b = std::max(c[k], c[(k + 1) % n]);
      const uint64_t key = (uint64_t{a} << 32) | b;
      const auto [it, first] = firstOfEdge.try_emplace(key, e);
      if (first) continue;
      const uint32_t other = it->second;
      const double difference = std::abs(value[e] - value[other]) / std::max(0.5 * (value[e] + value[other]), floor);
      jump[e] = std::max(jump[e], difference);
      jump[other] = std::max(jump[other], difference);
    }
  }
  return jump;
}

RefinementVerdicts judgeElements(const Surface& surface, std::span<const glm::dvec3> radiance, double floor,
                                 const RefinementSettings& settings) {
  const std::vector<double> jump = luminanceJumps(surface, radiance, floor);
  RefinementVerdicts out;
  out.refine.assign(jump.size(), 0);
  out.coarsen.assign(jump.size(), 0);
  for (size_t e = 0; e < jump.size(); ++e) {
    if (jump[e] > settings.threshold) {
      // Children are half as wide as their parent.
      if (0.5 * longestEdge(surface, surface.elements[e]) >= settings.minElementSize)
        out.refine[e] = 1, ++out.refineCount;
    } else if (jump[e] <= 0.25 * settings.threshold) {
      out.coarsen[e] = 1, ++out.coarsenCount;
    }
  }
  return out;
}

}  // namespace radiosity
