#include "tests/radiosity/scenes.h"

#include "engine/scene_loader.h"
#include "engine/surface_mesh.h"
#include "mesher/mesher.h"

#include <glm/geometric.hpp>

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

std::vector<Surface> closedBox(double size, double patchSize, glm::dvec3 reflectance, glm::dvec3 emission) {
  const glm::dvec3 o{0}, x{size, 0, 0}, y{0, size, 0}, z{0, 0, size};
  return {rectangle(o, x, y, patchSize, reflectance, emission),  // z = 0, facing +z
          rectangle(z, y, x, patchSize, reflectance, emission),  // z = size, facing -z
          rectangle(o, z, x, patchSize, reflectance, emission),  // y = 0, facing +y
          rectangle(y, x, z, patchSize, reflectance, emission),  // y = size, facing -y
          rectangle(o, y, z, patchSize, reflectance, emission),  // x = 0, facing +x
          rectangle(x, z, y, patchSize, reflectance, emission)}; // x = size, facing -x
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

std::vector<Surface> cornellBox() {
  const engine::Scene scene = engine::loadScene(WALKRAD_ASSETS "/cornell.json");
  mesher::Mesher mesher;
  std::vector<Surface> surfaces;
  for (const engine::Surface& in : scene.surfaces) {
    engine::SurfaceMesh m = engine::meshSurface(in, mesher);
    Surface& s = surfaces.emplace_back();
    s.vertices = std::move(m.positions);
    s.elements = std::move(m.mesh.elements);
    s.normal = in.normal;
    s.reflectance = scene.materials[in.material].reflectance;
    s.emission = scene.materials[in.material].emission;
  }
  return surfaces;
}

}  // namespace radiosity::test
