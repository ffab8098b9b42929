// Substructuring: which elements of a surface shoot together.
#include "radiosity/radiosity.h"

#include "radiosity/item_buffer.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace radiosity {

std::vector<uint32_t> groupIntoPatches(const Surface& surface, double patchEdge) {
  if (!(patchEdge > 0)) throw std::invalid_argument("groupIntoPatches: patchEdge must be positive");
  // Any fixed pair of axes in the plane will do; the hemisphere's are at hand.
  const HemisphereAxes axes = hemisphereAxes(glm::vec3(surface.normal));
  const glm::dvec3 origin = surface.vertices.empty() ? glm::dvec3(0) : surface.vertices.front();
  std::map<std::pair<long long, long long>, uint32_t> patchOfCell;
  std::vector<uint32_t> patches;
  patches.reserve(surface.elements.size());
  for (const std::array<uint32_t, 4>& e : surface.elements) {
    const int n = e[3] == kNone ? 3 : 4;
    glm::dvec3 centre{0};
    for (int k = 0; k < n; ++k) centre += surface.vertices.at(e[k]);
    centre = centre / double(n) - origin;
    const std::pair<long long, long long> cell{static_cast<long long>(std::floor(glm::dot(centre, axes.x) / patchEdge)),
                                               static_cast<long long>(std::floor(glm::dot(centre, axes.y) / patchEdge))};
    const auto [it, added] = patchOfCell.try_emplace(cell, static_cast<uint32_t>(patchOfCell.size()));
    patches.push_back(it->second);
  }
  return patches;
}

}  // namespace radiosity
