#include "engine/geometry/contact_cutouts.h"

#include "engine/geometry/surface_mesh.h"
#include "mesher/polygon.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace engine {

namespace {

using PlaneKey = ContactIndex::Key;

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

ContactIndex::ContactIndex(const std::vector<Surface>& surfaces, double tolerance)
    : tolerance_(tolerance), cell_(std::max(tolerance * 1e3, 1e-300)), bounds_(surfaces.size()) {
  for (size_t i = 0; i < surfaces.size(); ++i) file(static_cast<uint32_t>(i), surfaces[i]);
}

ContactIndex::Bounds ContactIndex::boundsOf(const Surface& surface) {
  Bounds b{surface.outer.front(), surface.outer.front()};
  for (const Vec3& p : surface.outer) b = {glm::min(b.lo, p), glm::max(b.hi, p)};
  return b;
}

bool ContactIndex::near(const Bounds& a, const Bounds& b) const {
  return glm::all(glm::lessThanEqual(a.lo, b.hi + tolerance_)) && glm::all(glm::lessThanEqual(b.lo, a.hi + tolerance_));
}

ContactIndex::Key ContactIndex::asSupport(const Surface& surface, int64_t shift) const {
  return planeKey(surface.normal, surface.planeOffset(), cell_, shift);
}

// A face rests on a support in the same plane facing the other way: normal -n, offset -d.
ContactIndex::Key ContactIndex::asFace(const Surface& surface) const {
  return planeKey(-surface.normal, -surface.planeOffset(), cell_);
}

void ContactIndex::file(uint32_t surface, const Surface& where) {
  bounds_[surface] = boundsOf(where);
  supports_[asSupport(where)].push_back(surface);
  faces_[asFace(where)].push_back(surface);
}

void ContactIndex::unfile(uint32_t surface, const Surface& where) {
  const auto drop = [&](std::map<Key, std::vector<uint32_t>>& index, const Key& key) {
    const auto found = index.find(key);
    if (found == index.end()) return;
    std::erase(found->second, surface);
    if (found->second.empty()) index.erase(found);
  };
  drop(supports_, asSupport(where));
  drop(faces_, asFace(where));
}

void ContactIndex::move(uint32_t surface, const Surface& before, const Surface& after) {
  unfile(surface, before);
  file(surface, after);
}

void ContactIndex::supportsUnder(const Surface& face, std::vector<uint32_t>& out) const {
  // Planes within a cell of the face's (cellOf rounds the offset down) may hold its support, and
  // of those only surfaces whose bounds meet the face's: a footprint lies inside its support.
  const Bounds bounds = boundsOf(face);
  for (int64_t shift : {-1, 0, 1}) {
    Key key = asFace(face);
    std::get<3>(key) += shift;
    if (const auto found = supports_.find(key); found != supports_.end())
      for (uint32_t s : found->second)
        if (near(bounds, bounds_[s])) out.push_back(s);
  }
}

Surface ContactIndex::cut(uint32_t support, const std::function<const Surface&(uint32_t)>& uncut) const {
  Surface result = uncut(support);
  std::vector<uint32_t> faces;
  const Bounds bounds = boundsOf(result);
  for (int64_t shift : {-1, 0, 1})
    if (const auto found = faces_.find(asSupport(result, shift)); found != faces_.end())
      for (uint32_t f : found->second)
        if (near(bounds, bounds_[f])) faces.push_back(f);
  // In the order of the scene's surfaces: whether a footprint fits depends on those cut before it.
  std::sort(faces.begin(), faces.end());
  for (uint32_t f : faces) {
    const Surface& face = uncut(f);
    if (result.object == face.object || glm::dot(face.normal, result.normal) > -1 + 1e-9 ||
        std::abs(face.planeOffset() + result.planeOffset()) > tolerance_)
      continue;
    if (!fitsAsHole(planePolygon(face, result).outer, planePolygon(result, result), tolerance_)) continue;
    // The face runs counter-clockwise about its own normal: clockwise seen from the support's
    // front, as a hole does.
    result.holes.push_back(face.outer);
    result.area -= face.area;
    ++result.contactHoles;
  }
  return result;
}

size_t cutOutContacts(std::vector<Surface>& surfaces, double tolerance) {
  const ContactIndex index(surfaces, tolerance);
  // Every surface is cut from the others as they are uncut; the few with cut-outs change after.
  std::vector<std::pair<uint32_t, Surface>> cut;
  for (uint32_t s = 0; s < surfaces.size(); ++s) {
    Surface withCutouts = index.cut(s, [&](uint32_t i) -> const Surface& { return surfaces[i]; });
    if (withCutouts.contactHoles > 0) cut.emplace_back(s, std::move(withCutouts));
  }
  size_t holes = 0;
  for (auto& [s, surface] : cut) {
    holes += surface.contactHoles;
    surfaces[s] = std::move(surface);
  }
  return holes;
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
