#include "app/gl/display_chunks.h"

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <span>
#include <utility>

namespace app {

namespace {

// The low 21 bits of `x` spread to every third bit, for a 63-bit Morton key of three.
uint64_t spreadBits(uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

glm::vec3 centreOf(const engine::SurfaceDisplay& surface) {
  if (surface.positions.empty()) return glm::vec3{0};
  glm::vec3 low = surface.positions.front(), high = low;
  for (const glm::vec3& p : surface.positions) low = glm::min(low, p), high = glm::max(high, p);
  return 0.5f * (low + high);
}

// Surfaces put in the Morton order of their centres on a grid of 2^21 cells along each side of
// the centres' bounds, so that runs of them are compact regions.
void sortAlongMortonCurve(const engine::DisplayMesh& mesh, std::vector<uint32_t>& surfaces) {
  std::vector<glm::vec3> centres;
  centres.reserve(surfaces.size());
  for (uint32_t s : surfaces) centres.push_back(centreOf(mesh.surfaces[s]));
  glm::vec3 low = centres.front(), high = low;
  for (const glm::vec3& c : centres) low = glm::min(low, c), high = glm::max(high, c);
  const glm::vec3 cells = float((1 << 21) - 1) / glm::max(high - low, glm::vec3{1e-30f});

  std::vector<std::pair<uint64_t, uint32_t>> keyed;
  keyed.reserve(surfaces.size());
  for (size_t i = 0; i < surfaces.size(); ++i) {
    const glm::vec3 cell = glm::clamp((centres[i] - low) * cells, glm::vec3{0}, glm::vec3{float((1 << 21) - 1)});
    const uint64_t key = spreadBits(static_cast<uint64_t>(cell.x)) | spreadBits(static_cast<uint64_t>(cell.y)) << 1 |
                         spreadBits(static_cast<uint64_t>(cell.z)) << 2;
    keyed.emplace_back(key, surfaces[i]);
  }
  std::sort(keyed.begin(), keyed.end());
  for (size_t i = 0; i < surfaces.size(); ++i) surfaces[i] = keyed[i].second;
}

}  // namespace

std::vector<ChunkPlan> planChunks(const engine::DisplayMesh& mesh, size_t maxVertices) {
  // Surfaces by object, in order.
  std::vector<std::vector<uint32_t>> surfacesOf;
  std::vector<size_t> verticesOf;
  for (uint32_t s = 0; s < mesh.surfaces.size(); ++s) {
    const uint32_t object = mesh.surfaces[s].object;
    if (object >= surfacesOf.size()) surfacesOf.resize(object + 1), verticesOf.resize(object + 1, 0);
    surfacesOf[object].push_back(s);
    verticesOf[object] += mesh.surfaces[s].positions.size();
  }

  // Each object cut into runs of at most maxVertices (a larger surface alone).
  std::vector<ChunkPlan> chunks;
  for (uint32_t object = 0; object < surfacesOf.size(); ++object) {
    std::vector<uint32_t>& surfaces = surfacesOf[object];
    if (surfaces.empty()) continue;
    if (verticesOf[object] > maxVertices) sortAlongMortonCurve(mesh, surfaces);
    size_t vertices = 0;
    for (uint32_t s : surfaces) {
      const size_t n = mesh.surfaces[s].positions.size();
      if (chunks.empty() || chunks.back().object != object || (vertices > 0 && vertices + n > maxVertices)) {
        chunks.push_back({object, {}});
        vertices = 0;
      }
      chunks.back().surfaces.push_back(s);
      vertices += n;
    }
  }
  return chunks;
}

bool outsideView(const glm::mat4& clipFromBox, const glm::vec3& low, const glm::vec3& high) {
  std::array<glm::vec4, 8> corners;
  for (int k = 0; k < 8; ++k)
    corners[k] = clipFromBox * glm::vec4(k & 1 ? high.x : low.x, k & 2 ? high.y : low.y, k & 4 ? high.z : low.z, 1);
  // Each clip plane as -w <= x, x <= w, and the same for y and z.
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : {-1.0f, 1.0f})
      if (std::all_of(corners.begin(), corners.end(), [&](const glm::vec4& c) { return side * c[axis] > c.w; })) return true;
  return false;
}

}  // namespace app
