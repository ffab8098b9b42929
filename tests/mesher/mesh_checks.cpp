#include "tests/mesher/mesh_checks.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

namespace mesher::test {

namespace {

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

double distanceToSegment(Vec2 p, Vec2 a, Vec2 b, double& t) {
  const Vec2 d = b - a;
  t = glm::dot(p - a, d) / glm::dot(d, d);
  return glm::length(p - (a + std::clamp(t, 0.0, 1.0) * d));
}

}  // namespace

MeshCheck checkMesh(const PolygonWithHoles& polygon, const Mesh& mesh) {
  MeshCheck check;
  std::vector<Ring2> rings{polygon.outer};
  rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  check.polygonArea = std::abs(signedArea(polygon.outer));
  for (const Ring2& h : polygon.holes) check.polygonArea -= std::abs(signedArea(h));
  double size = 0;
  for (const Vec2& p : polygon.outer) size = std::max({size, std::abs(p.x), std::abs(p.y)});
  const double extent = mesher::extent(polygon.outer);
  // On the boundary: within 1e-9 of the polygon's size. A T-vertex: on an element edge up to the
  // rounding of computed points (1e-12 of the coordinates), not merely close to it, as the
  // corners of a sliver at a sharp spike are.
  const double tolerance = 1e-9 * std::max(extent, 1e-9 * size);
  const double onEdge = 1e-12 * (size + extent);

  size_t index = 0;
  for (const Ring2& ring : rings)
    for (const Vec2& p : ring) check.movedInputVertices += mesh.vertices[index++] != p;

  std::map<std::pair<uint32_t, uint32_t>, int> edgeUse;
  for (const auto& e : mesh.elements) {
    const size_t n = e[3] == Mesh::kNone ? 3 : 4;
    double area = 0, diameter = 0;
    for (size_t k = 0; k < n; ++k) {
      const Vec2 a = mesh.vertices[e[k]], b = mesh.vertices[e[(k + 1) % n]], c = mesh.vertices[e[(k + 2) % n]];
      area += 0.5 * cross(a, b);
      const double turn = cross(b - a, c - b);
      if (!(turn > 0)) ++check.notCounterClockwiseOrConvex;
      const Vec2 u = a - b, v = c - b;
      check.smallestAngleDeg = std::min(check.smallestAngleDeg, std::atan2(std::abs(cross(u, v)), glm::dot(u, v)) * 180 / std::numbers::pi);
      for (size_t j = 0; j < n; ++j) diameter = std::max(diameter, glm::length(mesh.vertices[e[j]] - a));
      if (++edgeUse[{e[k], e[(k + 1) % n]}] > 1) ++check.repeatedEdges;
    }
    check.elementArea += area;
    check.largestDiameter = std::max(check.largestDiameter, diameter);
  }

  // Edges used once must lie on the polygon's boundary; every vertex must be an element corner
  // wherever it touches an element edge.
  for (const auto& [edge, uses] : edgeUse) {
    if (edgeUse.count({edge.second, edge.first})) continue;
    const Vec2 mid = 0.5 * (mesh.vertices[edge.first] + mesh.vertices[edge.second]);
    bool onBoundary = false;
    for (const Ring2& ring : rings)
      for (size_t i = 0; i < ring.size() && !onBoundary; ++i) {
        double t;
        onBoundary = distanceToSegment(mid, ring[i], ring[(i + 1) % ring.size()], t) <= tolerance;
      }
    check.unmatchedInnerEdges += !onBoundary;
  }
  std::set<std::pair<uint32_t, uint32_t>> undirected;
  for (const auto& [edge, uses] : edgeUse) undirected.insert(std::minmax(edge.first, edge.second));
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    for (const auto& edge : undirected) {
      if (edge.first == v || edge.second == v) continue;
      double t;
      const double d = distanceToSegment(mesh.vertices[v], mesh.vertices[edge.first], mesh.vertices[edge.second], t);
      if (d <= onEdge && t > 1e-12 && t < 1 - 1e-12) ++check.tVertices;
    }
  return check;
}

}  // namespace mesher::test
