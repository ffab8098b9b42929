#include "engine/document/display_mesh.h"

#include "engine/document/lit_scene.h"
#include "engine/geometry/surface_mesh.h"
#include "mesher/triangulate.h"
#include "radiosity/ambient.h"
#include "util/check.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace engine {

namespace {

// Per point of the polygon (outer ring, then holes), its vertex in the mesh: the mesh's first
// vertices, unless holes were inserted later (their points come after the vertices made before);
// then found by their exact coordinates, which the mesher keeps. Empty when one is missing.
std::vector<uint32_t> polygonVertices(const mesher::PolygonWithHoles& polygon, const mesher::Mesh& mesh) {
  std::vector<mesher::Vec2> points = polygon.outer;
  for (const mesher::Ring2& hole : polygon.holes) points.insert(points.end(), hole.begin(), hole.end());
  std::vector<uint32_t> vertex(points.size());
  bool first = points.size() <= mesh.vertices.size();
  for (uint32_t i = 0; first && i < points.size(); ++i) first = mesh.vertices[i] == points[i], vertex[i] = i;
  if (first) return vertex;
  std::map<std::pair<double, double>, uint32_t> byPoint;
  for (uint32_t v = 0; v < mesh.vertices.size(); ++v) byPoint.emplace(std::pair{mesh.vertices[v].x, mesh.vertices[v].y}, v);
  for (size_t i = 0; i < points.size(); ++i) {
    const auto found = byPoint.find({points[i].x, points[i].y});
    if (found == byPoint.end()) return {};
    vertex[i] = found->second;
  }
  return vertex;
}

glm::dvec3 middleOfBounds(const MeshedScene& meshed) {
  bool first = true;
  glm::dvec3 low{0}, high{0};
  for (const SurfaceMesh& surfaceMesh : meshed.surfaces)
    for (const Vec3& p : surfaceMesh.positions) {
      low = first ? p : glm::min(low, p);
      high = first ? p : glm::max(high, p);
      first = false;
    }
  return 0.5 * (low + high);
}

}  // namespace

std::vector<uint32_t> surfaceOutline(const SurfaceMesh& meshed) {
  const mesher::PolygonWithHoles& polygon = meshed.polygon;
  const mesher::Mesh& mesh = meshed.mesh;
  double area = 0;
  for (const auto& element : mesh.elements) {
    const size_t n = element[3] == mesher::Mesh::kNone ? 3 : 4;
    for (size_t k = 1; k + 1 < n; ++k) area += 0.5 * mesher::orient2(mesh.vertices[element[0]], mesh.vertices[element[k]], mesh.vertices[element[k + 1]]);
  }
  const std::vector<uint32_t> vertex = polygonVertices(polygon, mesh);
  if (vertex.empty()) return {};
  std::vector<uint32_t> outline;
  double covered = 0;
  for (const std::array<uint32_t, 3>& t : mesher::triangulate(polygon)) {
    if (std::max({t[0], t[1], t[2]}) >= vertex.size()) return {};
    const uint32_t a = vertex[t[0]], b = vertex[t[1]], c = vertex[t[2]];
    covered += 0.5 * mesher::orient2(mesh.vertices[a], mesh.vertices[b], mesh.vertices[c]);
    outline.insert(outline.end(), {a, b, c});
  }
  if (!(std::abs(covered - area) <= 1e-9 * area)) return {};
  return outline;
}

size_t DisplayMesh::triangleCount() const {
  size_t count = 0;
  for (const SurfaceDisplay& s : surfaces) count += s.triangles.size() / 3;
  return count;
}

glm::dmat4 displayFromWorld(const DisplayMesh& mesh) { return glm::translate(glm::dmat4{1.0}, -mesh.origin); }

SurfaceDisplay surfaceDisplay(const SurfaceMesh& meshed, uint32_t object, const glm::dmat4& displayFromWorld,
                              std::vector<uint32_t> outline) {
  const mesher::Mesh& patches = meshed.mesh;
  SurfaceDisplay display;
  display.object = object;
  display.positions.reserve(meshed.positions.size());
  for (const Vec3& p : meshed.positions) display.positions.emplace_back(displayFromWorld * glm::dvec4(p, 1));
  display.radiance.assign(meshed.positions.size(), glm::vec3{0});
  display.area.assign(meshed.positions.size(), 0);

  // GL draws triangles: quads are split along a diagonal; the wireframe shows element edges, each
  // once (an inner edge is in two elements).
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(4 * patches.elements.size());
  display.triangles.reserve(6 * patches.elements.size());
  for (const auto& element : patches.elements) {
    const size_t n = element[3] == mesher::Mesh::kNone ? 3 : 4;
    double area = 0;
    for (size_t k = 0; k < n; ++k)
      area += 0.5 * mesher::orient2(patches.vertices[element[0]], patches.vertices[element[k]], patches.vertices[element[(k + 1) % n]]);
    for (size_t k = 0; k < n; ++k) {
      display.area[element[k]] += static_cast<float>(area / static_cast<double>(n));
      edges.push_back(std::minmax(element[k], element[(k + 1) % n]));
    }
    for (size_t k = 1; k + 1 < n; ++k)
      for (uint32_t corner : {element[0], element[k], element[k + 1]}) display.triangles.push_back(corner);
    ++display.elements;
    display.quads += n == 4;
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  display.edges.reserve(2 * edges.size());
  for (const auto& [a, b] : edges) display.edges.insert(display.edges.end(), {a, b});
  display.outline = std::move(outline);
  if (!display.positions.empty()) {
    glm::vec3 low = display.positions.front(), high = low;
    for (const glm::vec3& p : display.positions) low = glm::min(low, p), high = glm::max(high, p);
    display.extent = glm::length(high - low);
  }
  return display;
}

DisplayMesh displayMesh(const Scene& scene, const MeshedScene& meshed, std::optional<glm::dvec3> origin) {
  CHECK_EQ(scene.surfaces.size(), meshed.surfaces.size());
  DisplayMesh mesh;
  mesh.origin = origin ? *origin : middleOfBounds(meshed);
  const glm::dmat4 fromWorld = displayFromWorld(mesh);
  mesh.surfaces.reserve(meshed.surfaces.size());
  for (size_t s = 0; s < meshed.surfaces.size(); ++s) {
    mesh.surfaces.push_back(surfaceDisplay(meshed.surfaces[s], scene.surfaces[s].object, fromWorld, surfaceOutline(meshed.surfaces[s])));
    mesh.elements += mesh.surfaces.back().elements;
    mesh.quads += mesh.surfaces.back().quads;
    mesh.vertices += mesh.surfaces.back().positions.size();
  }
  return mesh;
}

void replaceSurface(DisplayMesh& mesh, uint32_t surface, SurfaceDisplay display) {
  SurfaceDisplay& old = mesh.surfaces.at(surface);
  mesh.elements += display.elements - old.elements;
  mesh.quads += display.quads - old.quads;
  mesh.vertices += display.positions.size() - old.positions.size();
  old = std::move(display);
}

bool setRadiance(DisplayMesh& mesh, std::span<const glm::vec3> perVertex) {
  if (perVertex.size() != mesh.vertices) return false;
  for (SurfaceDisplay& s : mesh.surfaces) {
    std::copy_n(perVertex.begin(), s.radiance.size(), s.radiance.begin());
    perVertex = perVertex.subspan(s.radiance.size());
  }
  return true;
}

void setRadiance(DisplayMesh& mesh, const radiosity::Solver& solver) {
  std::vector<glm::vec3> radiance;
  displayRadiance(solver, radiance);
  CHECK(setRadiance(mesh, radiance));
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
    std::fill(mesh.surfaces[i].radiance.begin(), mesh.surfaces[i].radiance.end(), glm::vec3{m.emission + m.reflectance * ambient});
  }
  return ambient;
}

double autoExposure(const DisplayMesh& mesh, double key) {
  double logSum = 0, areaSum = 0;
  for (const SurfaceDisplay& s : mesh.surfaces)
    for (size_t v = 0; v < s.positions.size(); ++v) {
      const double a = s.area[v];
      logSum += a * std::log(1e-4 + luminance(s.radiance[v]));
      areaSum += a;
    }
  if (areaSum <= 0) return 1;
  return key / std::exp(logSum / areaSum);
}

}  // namespace engine
