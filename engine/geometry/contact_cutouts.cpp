#include "engine/geometry/contact_cutouts.h"

#include "engine/geometry/surface_mesh.h"
#include "mesher/polygon.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace engine {

namespace {

// Surfaces by their plane, so a face finds the surfaces it may rest on without trying them all:
// the unit normal to 1e-6 and the plane offset to a grid of `cell` (neighbouring cells too).
using PlaneKey = std::tuple<int64_t, int64_t, int64_t, int64_t>;

// The cell of a plane offset, for any offset: beyond +-2^62 cells (an offset near the double's
// limit, or a tolerance of 0) planes share an end cell, a neighbour's index still fits an
// int64_t, and the exact test of cutOutContacts tells them apart. Not a number (infinite
// offset over infinite cell, from coordinates near the limit) is cell 0.
int64_t cellOf(double offset, double cell) {
  constexpr double kEnd = 0x1p62;
  const double index = std::floor(offset / cell);
  return std::isnan(index) ? 0 : static_cast<int64_t>(std::clamp(index, -kEnd, kEnd));
}

PlaneKey planeKey(const Vec3& normal, double offset, double cell, int64_t shift = 0) {
  return {std::llround(normal.x * 1e6), std::llround(normal.y * 1e6), std::llround(normal.z * 1e6),
          cellOf(offset, cell) + shift};
}

struct Box {
  mesher::Vec2 lo, hi;
  explicit Box(const mesher::Ring2& ring) : lo(ring.front()), hi(ring.front()) {
    for (const mesher::Vec2& p : ring) lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  bool apart(const Box& other, double gap) const {
    return lo.x > other.hi.x + gap || other.lo.x > hi.x + gap || lo.y > other.hi.y + gap || other.lo.y > hi.y + gap;
  }
};

// Whether `footprint` lies strictly inside the polygon's outline and apart from its holes (a
// floor may hold many: holes whose boxes are apart from the footprint's are passed at once).
bool fitsAsHole(const mesher::Ring2& footprint, const mesher::PolygonWithHoles& polygon, double tolerance) {
  for (const mesher::Vec2& p : footprint)
    if (!mesher::containsPoint(polygon.outer, p)) return false;
  if (mesher::boundaryDistance(footprint, polygon.outer) <= tolerance) return false;
  const Box box(footprint);
  for (const mesher::Ring2& hole : polygon.holes)
    if (!box.apart(Box(hole), tolerance) &&
        (mesher::boundaryDistance(footprint, hole) <= tolerance || mesher::containsPoint(hole, footprint.front()) ||
         mesher::containsPoint(footprint, hole.front())))
      return false;
  return true;
}

// A ring's area in its plane (either winding gives the same magnitude).
double ringArea(const Ring3& ring, const Vec3& normal) {
  Vec3 sum{0};
  for (size_t i = 0; i < ring.size(); ++i) sum += glm::cross(ring[i], ring[(i + 1) % ring.size()]);
  return 0.5 * glm::dot(sum, normal);
}

}  // namespace

size_t cutOutContacts(std::vector<Surface>& surfaces, double tolerance) {
  const double cell = std::max(tolerance * 1e3, 1e-300);
  std::map<PlaneKey, std::vector<size_t>> byPlane;
  for (size_t i = 0; i < surfaces.size(); ++i)
    byPlane[planeKey(surfaces[i].normal, surfaces[i].planeOffset(), cell)].push_back(i);

  size_t cut = 0;
  for (size_t f = 0; f < surfaces.size(); ++f) {
    const Surface& face = surfaces[f];
    // A support faces the other way in the same plane: normal -n, offset -d.
    for (int64_t shift : {-1, 0, 1}) {
      const auto found = byPlane.find(planeKey(-face.normal, -face.planeOffset(), cell, shift));
      if (found == byPlane.end()) continue;
      for (size_t s : found->second) {
        Surface& support = surfaces[s];
        if (support.object == face.object || glm::dot(face.normal, support.normal) > -1 + 1e-9 ||
            std::abs(face.planeOffset() + support.planeOffset()) > tolerance)
          continue;
        if (!fitsAsHole(planePolygon(face, support).outer, planePolygon(support, support), tolerance)) continue;
        // The face runs counter-clockwise about its own normal: clockwise seen from the support's
        // front, as a hole does.
        support.holes.push_back(face.outer);
        support.area -= face.area;
        ++support.contactHoles;
        ++cut;
      }
    }
  }
  return cut;
}

void removeContacts(std::vector<Surface>& surfaces) {
  for (Surface& s : surfaces) {
    for (size_t k = s.holes.size() - s.contactHoles; k < s.holes.size(); ++k) s.area += std::abs(ringArea(s.holes[k], s.normal));
    s.holes.resize(s.holes.size() - s.contactHoles);
    s.contactHoles = 0;
  }
}

double contactTolerance(const Scene& scene) { return 1e-6 * sceneExtent(scene); }

}  // namespace engine
