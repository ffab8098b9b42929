#include "engine/document/display_mesh.h"

#include "engine/geometry/surface_mesh.h"
#include "radiosity/ambient.h"
#include "util/check.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <array>
#include <map>
#include <set>
#include <utility>

namespace engine {

namespace {

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace

DisplayMesh displayMesh(const MeshedScene& meshed, std::optional<glm::dvec3> origin) {
  DisplayMesh mesh;
  if (origin) {
    mesh.origin = *origin;
  } else {
    bool first = true;
    glm::dvec3 low{0}, high{0};
    for (const SurfaceMesh& surfaceMesh : meshed.surfaces)
      for (const Vec3& p : surfaceMesh.positions) {
        low = first ? p : glm::min(low, p);
        high = first ? p : glm::max(high, p);
        first = false;
      }
    mesh.origin = 0.5 * (low + high);
  }
  for (const SurfaceMesh& surfaceMesh : meshed.surfaces) {
    const mesher::Mesh& patches = surfaceMesh.mesh;
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    mesh.surfaceVertexStart.push_back(first);
    mesh.surfaceEdgeStart.push_back(static_cast<uint32_t>(mesh.edges.size()));
    for (const Vec3& p : surfaceMesh.positions) {
      mesh.positions.emplace_back(p - mesh.origin);
      mesh.radiance.emplace_back(0.0f);
      mesh.area.push_back(0);
    }

    // GL draws triangles: quads are split along a diagonal; the wireframe shows element edges.
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (const auto& element : patches.elements) {
      const size_t n = element[3] == mesher::Mesh::kNone ? 3 : 4;
      double area = 0;
      for (size_t k = 0; k < n; ++k)
        area += 0.5 * mesher::orient2(patches.vertices[element[0]], patches.vertices[element[k]], patches.vertices[element[(k + 1) % n]]);
      for (size_t k = 0; k < n; ++k) {
        mesh.area[first + element[k]] += static_cast<float>(area / static_cast<double>(n));
        edges.insert(std::minmax(first + element[k], first + element[(k + 1) % n]));
      }
      for (size_t k = 1; k + 1 < n; ++k)
        for (uint32_t corner : {element[0], element[k], element[k + 1]}) mesh.triangles.push_back(first + corner);
      ++mesh.elements;
      mesh.quads += n == 4;
    }
    for (const auto& [a, b] : edges) {
      mesh.edges.push_back(a);
      mesh.edges.push_back(b);
    }
  }
  mesh.surfaceVertexStart.push_back(static_cast<uint32_t>(mesh.positions.size()));
  mesh.surfaceEdgeStart.push_back(static_cast<uint32_t>(mesh.edges.size()));
  return mesh;
}

void carryRadiance(const DisplayMesh& old, DisplayMesh& fresh) {
  DCHECK(old.origin == fresh.origin);
  const size_t surfaces = std::min(old.surfaceVertexStart.size(), fresh.surfaceVertexStart.size()) - 1;
  for (size_t s = 0; s < surfaces; ++s) {
    const uint32_t oldFirst = old.surfaceVertexStart[s], oldEnd = old.surfaceVertexStart[s + 1];
    const uint32_t first = fresh.surfaceVertexStart[s], end = fresh.surfaceVertexStart[s + 1];
    if (end - first == oldEnd - oldFirst) {
      std::copy(old.radiance.begin() + oldFirst, old.radiance.begin() + oldEnd, fresh.radiance.begin() + first);
      continue;
    }
    std::map<std::array<float, 3>, glm::vec3> byPlace;
    glm::vec3 mean{0};
    for (uint32_t v = oldFirst; v < oldEnd; ++v) {
      const glm::vec3& p = old.positions[v];
      byPlace[{p.x, p.y, p.z}] = old.radiance[v];
      mean += old.radiance[v] / static_cast<float>(oldEnd - oldFirst);
    }
    for (uint32_t v = first; v < end; ++v) {
      const glm::vec3& p = fresh.positions[v];
      const auto found = byPlace.find({p.x, p.y, p.z});
      fresh.radiance[v] = found == byPlace.end() ? mean : found->second;
    }
  }
}

void updatePositions(const MeshedScene& meshed, const std::vector<uint32_t>& surfaces, DisplayMesh& mesh) {
  for (uint32_t s : surfaces) {
    const std::vector<Vec3>& positions = meshed.surfaces[s].positions;
    std::transform(positions.begin(), positions.end(), mesh.positions.begin() + mesh.surfaceVertexStart[s],
                   [&](const Vec3& p) { return glm::vec3(p - mesh.origin); });
  }
}

bool followMove(const MeshedScene& meshed, const std::vector<uint32_t>& moved, bool rebuild, DisplayMesh& mesh) {
  if (!rebuild) {
    updatePositions(meshed, moved, mesh);
    return false;
  }
  DisplayMesh fresh = displayMesh(meshed, mesh.origin);
  carryRadiance(mesh, fresh);
  mesh = std::move(fresh);
  return true;
}

glm::dvec3 shadeWithAmbient(const Scene& scene, DisplayMesh& mesh) {
  std::vector<radiosity::SurfaceLight> lights;
  lights.reserve(scene.surfaces.size());
  for (const Surface& s : scene.surfaces) {
    const Material& m = scene.materials[s.material];
    lights.push_back({s.area, m.reflectance, m.emission});
  }
  const glm::dvec3 ambient = radiosity::ambientRadiance(lights);
  for (size_t i = 0; i < scene.surfaces.size(); ++i) {
    const Material& m = scene.materials[scene.surfaces[i].material];
    const glm::vec3 radiance{m.emission + m.reflectance * ambient};
    std::fill(mesh.radiance.begin() + mesh.surfaceVertexStart[i], mesh.radiance.begin() + mesh.surfaceVertexStart[i + 1], radiance);
  }
  return ambient;
}

double autoExposure(const DisplayMesh& mesh, double key) {
  double logSum = 0, areaSum = 0;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const double a = mesh.area[i];
    logSum += a * std::log(1e-4 + luminance(mesh.radiance[i]));
    areaSum += a;
  }
  if (areaSum <= 0) return 1;
  return key / std::exp(logSum / areaSum);
}

}  // namespace engine
