#include "app/gl/level_of_detail.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace app {

int depthBand(float nearestDepth) {
  if (!(nearestDepth > 0)) return kNearBand;
  return static_cast<int>(std::floor(std::log2(nearestDepth)));
}

float nearestDepth(const glm::mat4& clipFromBox, const glm::vec3& low, const glm::vec3& high) {
  float nearest = INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec4 p{corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y, corner & 4 ? high.z : low.z, 1};
    nearest = std::min(nearest, (clipFromBox * p).w);
  }
  return nearest;  // depth is linear in position: least at a corner
}

float pixelsPerUnit(const glm::mat4& clipFromDisplay, int width) {
  const glm::vec3 x{clipFromDisplay[0][0], clipFromDisplay[1][0], clipFromDisplay[2][0]};
  const glm::vec3 w{clipFromDisplay[0][3], clipFromDisplay[1][3], clipFromDisplay[2][3]};
  const float depthScale = glm::length(w);
  return depthScale > 0 ? 0.5f * static_cast<float>(width) * glm::length(x) / depthScale : 0;
}

bool evenlyLit(std::span<const glm::vec3> radiance, bool wasEven, const DetailSettings& settings) {
  if (radiance.empty()) return true;
  float low = INFINITY, high = -INFINITY, sum = 0;
  for (const glm::vec3& c : radiance) {
    const float l = engine::luminance(c);
    low = std::min(low, l), high = std::max(high, l), sum += l;
  }
  const float mean = sum / static_cast<float>(radiance.size());
  return high - low <= (wasEven ? settings.unevenContrast : settings.evenContrast) * std::abs(mean);
}

bool drawsOutline(const engine::SurfaceDisplay& surface, int band, float pixelsPerUnit, bool even,
                  const DetailSettings& settings) {
  if (surface.outline.empty()) return false;
  if (even) return true;
  return band != kNearBand && surface.extent * pixelsPerUnit <= settings.outlinePixels * std::ldexp(1.0f, band);
}

void gatherTriangles(const engine::DisplayMesh& mesh, std::span<const uint32_t> surfaces, int band, float pixelsPerUnit,
                     std::span<const uint8_t> even, const DetailSettings& settings, std::vector<uint32_t>& out) {
  out.clear();
  uint32_t first = 0;
  for (uint32_t s : surfaces) {
    const engine::SurfaceDisplay& surface = mesh.surfaces[s];
    const bool outline = drawsOutline(surface, band, pixelsPerUnit, even[s] != 0, settings);
    for (uint32_t i : outline ? surface.outline : surface.triangles) out.push_back(first + i);
    first += static_cast<uint32_t>(surface.positions.size());
  }
}

}  // namespace app
