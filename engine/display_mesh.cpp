#include "engine/display_mesh.h"

#include "mesher/mesher.h"
#include "radiosity/ambient.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace engine {

namespace {

// A 2-D frame in the surface's plane whose counter-clockwise is counter-clockwise about the
// front normal. Surfaces facing along a world axis use two world axes, so their coordinates are
// exact and axis-aligned edges stay axis-aligned for the quadtree.
struct PlaneFrame {
  Vec3 origin, u, v;
  mesher::Vec2 project(const Vec3& p) const { return {glm::dot(p - origin, u), glm::dot(p - origin, v)}; }
  Vec3 lift(mesher::Vec2 p, const Vec3& normal, double offset) const {
    return origin + u * p.x + v * p.y + normal * (offset - glm::dot(origin, normal));
  }
};

PlaneFrame planeFrame(const Surface& s) {
  const Vec3 n = s.normal;
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  if (n == x) return {Vec3{0}, y, z};
  if (n == -x) return {Vec3{0}, z, y};
  if (n == y) return {Vec3{0}, z, x};
  if (n == -y) return {Vec3{0}, x, z};
  if (n == z) return {Vec3{0}, x, y};
  if (n == -z) return {Vec3{0}, y, x};
  size_t longest = 0;
  double best = -1;
  for (size_t i = 0; i < s.outer.size(); ++i) {
    const double len = glm::length(s.outer[(i + 1) % s.outer.size()] - s.outer[i]);
    if (len > best) best = len, longest = i;
  }
  const Vec3 u = glm::normalize(s.outer[(longest + 1) % s.outer.size()] - s.outer[longest]);
  return {s.outer[longest], u, glm::cross(s.normal, u)};
}

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace

DisplayMesh buildPlaceholderDisplay(const Scene& scene, glm::dvec3* ambientOut) {
  std::vector<radiosity::SurfaceLight> lights;
  lights.reserve(scene.surfaces.size());
  for (const Surface& s : scene.surfaces) {
    const Material& m = scene.materials[s.material];
    lights.push_back({s.area, m.reflectance, m.emission});
  }
  const glm::dvec3 ambient = radiosity::ambientRadiance(lights);
  if (ambientOut) *ambientOut = ambient;

  DisplayMesh mesh;
  for (const Surface& s : scene.surfaces) {
    const Material& m = scene.materials[s.material];
    const glm::vec3 radiance{m.emission + m.reflectance * ambient};
    const PlaneFrame frame = planeFrame(s);

    // The polygon in its plane, then the quadtree mesh of chapter 5 lifted back to 3-D (input
    // points keep their exact 3-D coordinates).
    mesher::PolygonWithHoles polygon;
    std::vector<Vec3> points3(s.outer);
    for (const Vec3& p : s.outer) polygon.outer.push_back(frame.project(p));
    for (const Ring3& hole : s.holes) {
      mesher::Ring2& ring = polygon.holes.emplace_back();
      for (const Vec3& p : hole) ring.push_back(frame.project(p)), points3.push_back(p);
    }
    const mesher::Mesh patches = mesher::meshPolygon(polygon, {s.patchSize});
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    mesh.surfaceVertexStart.push_back(first);
    const double offset = s.planeOffset();
    for (size_t i = 0; i < patches.vertices.size(); ++i) {
      mesh.positions.emplace_back(i < points3.size() ? points3[i] : frame.lift(patches.vertices[i], s.normal, offset));
      mesh.radiance.push_back(radiance);
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
  return mesh;
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
