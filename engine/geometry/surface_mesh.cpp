#include "engine/geometry/surface_mesh.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace engine {

namespace {

// Surfaces facing along a world axis use two world axes, so their coordinates are exact and
// axis-aligned edges stay axis-aligned for the quadtree.
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

mesher::Vec2 PlaneFrame::project(const Vec3& p) const { return {glm::dot(p - origin, u), glm::dot(p - origin, v)}; }

Vec3 PlaneFrame::lift(mesher::Vec2 p, const Vec3& normal, double offset) const {
  return origin + u * p.x + v * p.y + normal * (offset - glm::dot(origin, normal));
}

uint64_t elementKey(mesher::ElementId id) { return uint64_t{id.generation} << 32 | id.slot; }

std::vector<uint64_t> elementKeys(std::span<const mesher::ElementId> ids) {
  std::vector<uint64_t> keys;
  keys.reserve(ids.size());
  for (const mesher::ElementId id : ids) keys.push_back(elementKey(id));
  return keys;
}

mesher::PolygonWithHoles planePolygon(const Surface& surface, const Surface& frameOf) {
  return planePolygon(surface, planeFrame(frameOf));
}

mesher::PolygonWithHoles planePolygon(const Surface& surface, const PlaneFrame& frame) {
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
  result.worldFromPlane = planeFrame(surface);
  result.polygon = planePolygon(surface, surface);
  if (isOneElement(result.polygon, surface.patchSize))
    result.mesh = {result.polygon.outer, {{0, 1, 2, mesher::Mesh::kNone}}};
  else
    result.mesh = mesher.mesh(result.polygon, {surface.patchSize});
  // The mesher's buffers are sized for the tree's leaves, about twice what the mesh uses; a scene's
  // meshes are held while it is lit (on the White Room 120 MB of the 230 were spare).
  result.mesh.vertices.shrink_to_fit();
  result.mesh.elements.shrink_to_fit();
  result.keys.reserve(result.mesh.elements.size());
  for (uint32_t i = 0; i < result.mesh.elements.size(); ++i) result.keys.push_back(elementKey({i, 0}));
  addWorldPositions(surface, result);
  return result;
}

SceneError meshRefusal(const mesher::MeshRefused& refused, const std::string& file, const std::string& place,
                       const std::string& which) {
  const bool tooLarge = refused.reason() == mesher::MeshRefused::Reason::TooLarge;
  return SceneError(tooLarge ? Diag::MeshTooLarge : Diag::MeshTooFine, file, place,
                    which.empty() ? refused.what() : which + ": " + refused.what());
}

void addWorldPositions(const Surface& surface, SurfaceMesh& mesh) {
  std::vector<Vec3>& positions = mesh.positions;
  const std::vector<mesher::Vec2>& vertices = mesh.mesh.vertices;
  positions.reserve(vertices.size());
  if (positions.empty()) {
    // The surface's own points come first in the mesh, in the same order: keep them exact.
    positions = surface.outer;
    for (const Ring3& hole : surface.holes) positions.insert(positions.end(), hole.begin(), hole.end());
  }
  const double offset = surface.planeOffset();
  for (size_t i = positions.size(); i < vertices.size(); ++i)
    positions.push_back(mesh.worldFromPlane.lift(vertices[i], surface.normal, offset));
}

}  // namespace engine
