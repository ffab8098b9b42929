#include "tests/radiosity/scenes.h"

#include "mesher/mesher.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace radiosity::test {

Surface rectangle(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, double patchSize, glm::dvec3 reflectance,
                  glm::dvec3 emission) {
  const double lu = glm::length(u), lv = glm::length(v);
  const mesher::Mesh mesh = mesher::meshPolygon({{{0, 0}, {lu, 0}, {lu, lv}, {0, lv}}, {}}, {patchSize});
  Surface s;
  for (const mesher::Vec2& p : mesh.vertices) s.vertices.push_back(origin + u * (p.x / lu) + v * (p.y / lv));
  s.elements = mesh.elements;
  s.normal = glm::normalize(glm::cross(u, v));
  s.reflectance = reflectance;
  s.emission = emission;
  return s;
}

Surface quad(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, glm::dvec3 reflectance, glm::dvec3 emission) {
  Surface s;
  s.vertices = {origin, origin + u, origin + u + v, origin + v};
  s.elements = {{0, 1, 2, 3}};
  s.normal = glm::normalize(glm::cross(u, v));
  s.reflectance = reflectance;
  s.emission = emission;
  return s;
}

std::vector<Surface> closedBox(double size, double patchSize, glm::dvec3 reflectance, glm::dvec3 emission) {
  const glm::dvec3 o{0}, x{size, 0, 0}, y{0, size, 0}, z{0, 0, size};
  return {rectangle(o, x, y, patchSize, reflectance, emission),  // z = 0, facing +z
          rectangle(z, y, x, patchSize, reflectance, emission),  // z = size, facing -z
          rectangle(o, z, x, patchSize, reflectance, emission),  // y = 0, facing +y
          rectangle(y, x, z, patchSize, reflectance, emission),  // y = size, facing -y
          rectangle(o, y, z, patchSize, reflectance, emission),  // x = 0, facing +x
          rectangle(x, z, y, patchSize, reflectance, emission)}; // x = size, facing -x
}

std::vector<Surface> roomWithBoard(double dx, double height) {
  std::vector<Surface> room = closedBox(1, 0.125, glm::dvec3(0.6), glm::dvec3(0));
  room.push_back(rectangle({0.4, 0.4, 0.999}, {0, 0.2, 0}, {0.2, 0, 0}, 0.1, glm::dvec3(0.5), {10, 10, 10}));
  // The board faces up (its top is lit) and down (its underside casts the shadow).
  room.push_back(rectangle({0.3 + dx, 0.3, height}, {0.4, 0, 0}, {0, 0.4, 0}, 0.1, glm::dvec3(0.6)));
  room.push_back(rectangle({0.3 + dx, 0.3, height}, {0, 0.4, 0}, {0.4, 0, 0}, 0.1, glm::dvec3(0.6)));
  return room;
}

std::vector<SurfaceChange> changesOf(const std::vector<Surface>& now, std::span<const uint32_t> surfaces) {
  std::vector<SurfaceChange> changes;
  for (uint32_t s : surfaces) changes.push_back({s, now[s]});
  return changes;
}

double area(const Surface& s, uint32_t e) {
  const auto& c = s.elements[e];
  double a = 0.5 * glm::length(glm::cross(s.vertices[c[1]] - s.vertices[c[0]], s.vertices[c[2]] - s.vertices[c[0]]));
  if (c[3] != kNone) a += 0.5 * glm::length(glm::cross(s.vertices[c[2]] - s.vertices[c[0]], s.vertices[c[3]] - s.vertices[c[0]]));
  return a;
}

glm::dvec3 areaTimesRadiance(const Solver& solver, const Surface& surface, uint32_t index) {
  const std::span<const glm::dvec3> radiance = solver.elementRadiance(index);
  glm::dvec3 sum{0};
  for (uint32_t e = 0; e < surface.elements.size(); ++e) sum += area(surface, e) * radiance[e];
  return sum;
}

double channelSum(const glm::dvec3& v) { return v.x + v.y + v.z; }

double meanDifference(const Solver& a, const Solver& b) {
  double diff = 0, level = 0;
  for (uint32_t s = 0; s < a.surfaceCount(); ++s) {
    const auto ra = a.elementRadiance(s), rb = b.elementRadiance(s);
    for (size_t e = 0; e < ra.size(); ++e)
      for (int c = 0; c < 3; ++c) diff += std::abs(ra[e][c] - rb[e][c]), level += std::abs(rb[e][c]);
  }
  return diff / level;
}

double worstDifference(const Solver& a, const Solver& b) {
  double sum = 0, count = 0;
  for (uint32_t s = 0; s < b.surfaceCount(); ++s)
    for (const auto& r : b.elementRadiance(s)) sum += r.x + r.y + r.z, count += 3;
  const double dark = 1e-6 * sum / count;
  double worst = 0;
  for (uint32_t s = 0; s < a.surfaceCount(); ++s) {
    const auto ra = a.elementRadiance(s), rb = b.elementRadiance(s);
    for (size_t e = 0; e < ra.size(); ++e)
      for (int c = 0; c < 3; ++c)
        if (rb[e][c] > dark) worst = std::max(worst, std::abs(ra[e][c] / rb[e][c] - 1));
  }
  return worst;
}

}  // namespace radiosity::test
