#include "engine/display_mesh.h"

#include "mesher/triangulate.h"
#include "radiosity/ambient.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace engine {

namespace {

// A 2-D frame in the surface's plane whose counter-clockwise is counter-clockwise about the
// front normal.
struct PlaneFrame {
  Vec3 origin, u, v;
  mesher::Vec2 project(const Vec3& p) const { return {glm::dot(p - origin, u), glm::dot(p - origin, v)}; }
};

PlaneFrame planeFrame(const Surface& s) {
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

    // Points are numbered outer first, then each hole, as triangulate() numbers them.
    mesher::PolygonWithHoles polygon;
    std::vector<mesher::Vec2> points;
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    auto addRing = [&](const Ring3& ring, mesher::Ring2& ring2) {
      for (const Vec3& p : ring) {
        ring2.push_back(frame.project(p));
        points.push_back(ring2.back());
        mesh.positions.emplace_back(p);
        mesh.radiance.push_back(radiance);
        mesh.area.push_back(0);
      }
    };
    addRing(s.outer, polygon.outer);
    for (const Ring3& hole : s.holes) addRing(hole, polygon.holes.emplace_back());

    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (const auto& t : mesher::triangulate(polygon)) {
      const double area = 0.5 * mesher::orient2(points[t[0]], points[t[1]], points[t[2]]);
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t a = first + t[k], b = first + t[(k + 1) % 3];
        mesh.triangles.push_back(a);
        mesh.area[a] += static_cast<float>(area / 3);
        edges.insert(std::minmax(a, b));
      }
    }
    for (const auto& [a, b] : edges) {
      mesh.edges.push_back(a);
      mesh.edges.push_back(b);
    }
  }
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
