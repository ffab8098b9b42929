#include "engine/geometry/surface_mesh.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

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
  if (const auto axes = axisPlaneAxes(s.normal)) return {Vec3{0}, axes->first, axes->second};
  size_t longest = 0;
  double best = -1;
  for (size_t i = 0; i < s.outer.size(); ++i) {
    const double len = glm::length(s.outer[(i + 1) % s.outer.size()] - s.outer[i]);
    if (len > best) best = len, longest = i;
  }
  const Vec3 u = glm::normalize(s.outer[(longest + 1) % s.outer.size()] - s.outer[longest]);
  return {s.outer[longest], u, glm::cross(s.normal, u)};
}

// A triangle no longer than the patch size whose angles all reach the mesher's bound is already
// an element the quadtree aims for, so it is its own mesh: the curved parts of modellers' models
// are mostly such triangles, and the quadtree would cut each into about eight.
bool isOneElement(const mesher::PolygonWithHoles& polygon, double patchSize) {
  if (polygon.outer.size() != 3 || !polygon.holes.empty() || mesher::signedArea(polygon.outer) <= 0) return false;
  const double minSine = std::sin(glm::radians(mesher::kAngleBoundDeg));
  for (int k = 0; k < 3; ++k) {
    const mesher::Vec2 a = polygon.outer[k], b = polygon.outer[(k + 1) % 3], c = polygon.outer[(k + 2) % 3];
    const double ab = glm::length(b - a), ac = glm::length(c - a);
    if (ab > patchSize) return false;
    // The sine of the angle at a is twice the area over the two sides; every angle between the
    // bound and 180 minus it is the same as every angle above the bound.
    if (mesher::orient2(a, b, c) < minSine * ab * ac) return false;
  }
  return true;
}

}  // namespace

mesher::PolygonWithHoles planePolygon(const Surface& surface, const Surface& frameOf) {
  const PlaneFrame frame = planeFrame(frameOf);
  mesher::PolygonWithHoles polygon;
  polygon.outer.reserve(surface.outer.size());
  for (const Vec3& p : surface.outer) polygon.outer.push_back(frame.project(p));
  polygon.holes.reserve(surface.holes.size());
  for (const Ring3& hole : surface.holes) {
    mesher::Ring2& ring = polygon.holes.emplace_back();
    ring.reserve(hole.size());
    for (const Vec3& p : hole) ring.push_back(frame.project(p));
  }
  return polygon;
}

std::vector<mesher::Vec2> planeVertices(const Surface& surface, const std::vector<Vec3>& positions) {
  const PlaneFrame frame = planeFrame(surface);
  std::vector<mesher::Vec2> vertices;
  vertices.reserve(positions.size());
  for (const Vec3& p : positions) vertices.push_back(frame.project(p));
  return vertices;
}

std::optional<std::pair<Vec3, Vec3>> axisPlaneAxes(const Vec3& n) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  if (n == x) return std::pair{y, z};
  if (n == -x) return std::pair{z, y};
  if (n == y) return std::pair{z, x};
  if (n == -y) return std::pair{x, z};
  if (n == z) return std::pair{x, y};
  if (n == -z) return std::pair{y, x};
  return std::nullopt;
}

SurfaceMesh meshSurface(const Surface& surface, mesher::Mesher& mesher) {
  SurfaceMesh result;
  result.polygon = planePolygon(surface, surface);
  if (isOneElement(result.polygon, surface.patchSize))
    result.mesh = {result.polygon.outer, {{0, 1, 2, mesher::Mesh::kNone}}};
  else
    result.mesh = mesher.mesh(result.polygon, {surface.patchSize});
  result.positions = worldPositions(surface, result.mesh.vertices);
  return result;
}

SceneError meshRefusal(const mesher::MeshRefused& refused, const std::string& file, const std::string& place,
                       const std::string& which) {
  const bool tooLarge = refused.reason() == mesher::MeshRefused::Reason::TooLarge;
  return SceneError(tooLarge ? Diag::MeshTooLarge : Diag::MeshTooFine, file, place,
                    which.empty() ? refused.what() : which + ": " + refused.what());
}

std::vector<Vec3> worldPositions(const Surface& surface, const std::vector<mesher::Vec2>& vertices) {
  const PlaneFrame frame = planeFrame(surface);
  // The surface's own points come first in the mesh, in the same order: keep them exact.
  std::vector<Vec3> positions;
  positions.reserve(vertices.size());
  positions = surface.outer;
  for (const Ring3& hole : surface.holes) positions.insert(positions.end(), hole.begin(), hole.end());
  const double offset = surface.planeOffset();
  for (size_t i = positions.size(); i < vertices.size(); ++i) positions.push_back(frame.lift(vertices[i], surface.normal, offset));
  return positions;
}

}  // namespace engine
