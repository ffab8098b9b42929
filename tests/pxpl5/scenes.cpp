#include "tests/pxpl5/scenes.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace pxpl5::test {

void Soup::add(const std::vector<glm::vec3>& ring, uint32_t id) {
  polygons.push_back({static_cast<uint32_t>(vertices.size()), static_cast<uint32_t>(ring.size()), id});
  vertices.insert(vertices.end(), ring.begin(), ring.end());
}

void Soup::addGrid(glm::vec3 a, glm::vec3 s, glm::vec3 t, int n, uint32_t id) {
  // Corners computed once per grid point, so neighbouring quads share exact coordinates.
  std::vector<glm::vec3> point(static_cast<size_t>((n + 1) * (n + 1)));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      point[static_cast<size_t>(j * (n + 1) + i)] = a + s * (static_cast<float>(i) / static_cast<float>(n)) + t * (static_cast<float>(j) / static_cast<float>(n));
  const auto at = [&](int i, int j) { return point[static_cast<size_t>(j * (n + 1) + i)]; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) add({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, id++);
}

double lambertFactor(glm::dvec3 point, glm::dvec3 normal, const std::vector<glm::dvec3>& ring) {
  // Keep the part above the horizon first.
  std::vector<glm::dvec3> v;
  for (size_t i = 0; i < ring.size(); ++i) {
    const glm::dvec3 a = ring[i] - point, b = ring[(i + 1) % ring.size()] - point;
    const double da = glm::dot(a, normal), db = glm::dot(b, normal);
    if (da >= 0) v.push_back(a);
    if ((da >= 0) != (db >= 0)) v.push_back(a + (da / (da - db)) * (b - a));
  }
  double sum = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 a = glm::normalize(v[i]), b = glm::normalize(v[(i + 1) % v.size()]);
    const glm::dvec3 c = glm::cross(a, b);
    const double s = glm::length(c);
    if (s == 0) continue;
    sum += std::atan2(s, glm::dot(a, b)) * glm::dot(normal, c / s);
  }
  return std::abs(sum) / (2 * std::numbers::pi);
}

Soup closedBox(glm::vec3 lo, glm::vec3 hi, int n) {
  Soup soup;
  const glm::vec3 d = hi - lo;
  const glm::vec3 x(d.x, 0, 0), y(0, d.y, 0), z(0, 0, d.z);
  uint32_t id = 0;
  const auto face = [&](glm::vec3 a, glm::vec3 s, glm::vec3 t) {
    soup.addGrid(a, s, t, n, id);
    id += static_cast<uint32_t>(n * n);
  };
  face(lo, y, x);           // z = lo
  face(lo + z, x, y);       // z = hi
  face(lo, x, z);           // y = lo
  face(lo + y, z, x);       // y = hi
  face(lo, z, y);           // x = lo
  face(lo + x, y, z);       // x = hi
  return soup;
}

Soup benchmarkRoom(int polygons, Viewpoint& view) {
  // Six room faces take about half the polygons, 40 boxes the other half.
  Soup soup;
  const int boxes = 40;
  const int perRoomFace = std::max(1, static_cast<int>(std::sqrt(polygons / 2.0 / 6.0)));
  const int perBoxFace = std::max(1, static_cast<int>(std::sqrt(polygons / 2.0 / (boxes * 5.0))));
  Soup room = closedBox({0, 0, 0}, {10, 8, 3}, perRoomFace);
  soup = room;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> u(0, 1);
  uint32_t id = static_cast<uint32_t>(soup.polygons.size());
  for (int b = 0; b < boxes; ++b) {
    glm::vec3 lo, size;
    do {  // not over the viewpoint
      lo = {0.5f + 8.0f * u(random), 0.5f + 6.0f * u(random), 0.0f};
      size = {0.3f + 1.2f * u(random), 0.3f + 1.2f * u(random), 0.4f + 1.6f * u(random)};
    } while (lo.x < 5.2f && lo.x + size.x > 4.8f && lo.y < 4.2f && lo.y + size.y > 3.8f);
    const glm::vec3 x(size.x, 0, 0), y(0, size.y, 0), z(0, 0, size.z);
    const int n = perBoxFace;
    const auto face = [&](glm::vec3 a, glm::vec3 s, glm::vec3 t) {
      soup.addGrid(a, s, t, n, id);
      id += static_cast<uint32_t>(n * n);
    };
    face(lo + z, x, y);  // top
    face(lo, x, z);
    face(lo + y, z, x);
    face(lo, z, y);
    face(lo + x, y, z);
  }
  view.point = {5.0f, 4.0f, 0.0f};
  view.normal = {0.0f, 0.0f, 1.0f};
  return soup;
}

double factorOfIds(const HemisphereFrame& frame, uint32_t first, uint32_t last) {
  double sum = 0;
  for (const IdFactor& f : frame.factors)
    if (f.id >= first && f.id < last) sum += f.factor;
  return sum;
}

}  // namespace pxpl5::test
