#include "mesher/leaf_emitter.h"

#include "mesher/mesher.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace mesher {

// Mesh vertex ids by their exact tree coordinates: leaves sharing a point compute it bit for bit
// alike (corners are integers, crossings come from the edge and the line alone). Open addressing
// over ids only, the points themselves kept in id order, so a quarter of a million points cost
// no allocation each and the table stays small.
class PointIds {
 public:
  // Empties the table for about `expected` points in a root square of edge `rootSize`, keeping
  // its memory.
  void reset(size_t expected, double rootSize) {
    toUnit_ = 1 / rootSize;
    slots_.assign(std::bit_ceil(std::max<size_t>(16, 2 * expected)), kEmpty);
    shift_ = 64 - std::countr_zero(slots_.size());
    points_.clear();
    points_.reserve(expected);
    listed_ = 0;
  }

  // The id of p, adding it with the next id when it is new (`added` says which).
  uint32_t findOrAdd(Vec2 p, bool& added) {
    if (2 * (points_.size() + 1) > slots_.size()) grow();
    size_t slot = slotOf(p);
    while (slots_[slot] != kEmpty) {
      if (points_[slots_[slot]] == p) {
        added = false;
        return slots_[slot];
      }
      slot = (slot + 1) & (slots_.size() - 1);
    }
    const auto id = static_cast<uint32_t>(points_.size());
    slots_[slot] = id;
    points_.push_back(p);
    ++listed_;
    added = true;
    return id;
  }

  // The next id for a point the caller knows is new: no comparisons. An unlisted point is not
  // entered in the table (a point nothing will look up again) and only takes its id.
  uint32_t addNew(Vec2 p) {
    if (2 * (listed_ + 1) > slots_.size()) grow();
    size_t slot = slotOf(p);
    while (slots_[slot] != kEmpty) slot = (slot + 1) & (slots_.size() - 1);
    const auto id = static_cast<uint32_t>(points_.size());
    slots_[slot] = id;
    points_.push_back(p);
    ++listed_;
    return id;
  }
  uint32_t addUnlisted(Vec2 p) {
    points_.push_back(p);
    return static_cast<uint32_t>(points_.size() - 1);
  }

 private:
  static constexpr uint32_t kEmpty = 0xffffffffu;

  static uint64_t spreadBits(uint64_t v) {  // 32 bits to the even bits of 64
    v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
    v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
    v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
    v = (v | (v << 2)) & 0x3333333333333333ull;
    return (v | (v << 1)) & 0x5555555555555555ull;
  }
  // The point's Morton (Z-order) cell at the table's resolution (the order leaves are visited
  // in), scattered within a window of 65,536 slots (256 KiB) by a hash of the exact point:
  // lookups stay near each other in memory, and points crowded into one cell (along a narrow
  // gap) do not share one probe run, which made lookups quadratic.
  size_t slotOf(Vec2 p) const {
    const auto x = static_cast<uint64_t>(std::clamp(p.x * toUnit_, 0.0, 1.0) * 4294967295.0);
    const auto y = static_cast<uint64_t>(std::clamp(p.y * toUnit_, 0.0, 1.0) * 4294967295.0);
    uint64_t a, b;
    std::memcpy(&a, &p.x, sizeof a);
    std::memcpy(&b, &p.y, sizeof b);
    const uint64_t cell = (spreadBits(x) | spreadBits(y) << 1) >> shift_;
    // The top bits of a product by an odd constant depend on every bit of the coordinate, and
    // the high bits are where small integers differ.
    const uint64_t scatter = (a * 0x9E3779B97F4A7C15ull ^ b * 0xC2B2AE3D27D4EB4Full) >> 48;
    return static_cast<size_t>(cell ^ scatter) & (slots_.size() - 1);
  }
  void grow() {
    slots_.assign(slots_.size() * 2, kEmpty);
    shift_ -= 1;
    listed_ = points_.size();  // unlisted points are entered too: harmless, nothing asks for them
    for (uint32_t id = 0; id < points_.size(); ++id) {
      size_t slot = slotOf(points_[id]);
      while (slots_[slot] != kEmpty) slot = (slot + 1) & (slots_.size() - 1);
      slots_[slot] = id;
    }
  }

  double toUnit_ = 1;
  int shift_ = 0;
  std::vector<uint32_t> slots_;
  std::vector<Vec2> points_;  // tree coordinates, by id
  size_t listed_ = 0;         // points entered in slots_
};

LeafEmitter::LeafEmitter(const PolygonWithHoles& polygon, const PolygonTree& built, size_t expectedLeaves)
    : built_(built), ids_(std::make_unique<PointIds>()), regions_(built.tree) {
  reset(polygon, expectedLeaves);
}

void LeafEmitter::reset(const PolygonWithHoles& polygon, size_t expectedLeaves) {
  ids_->reset(expectedLeaves + built_.tree.input.vertices.size(), std::exp2(built_.tree.maxDepth));
  vertices_.clear();
  vertices_.reserve(expectedLeaves * 2);
  vertices_.insert(vertices_.end(), polygon.outer.begin(), polygon.outer.end());
  for (const Ring2& hole : polygon.holes) vertices_.insert(vertices_.end(), hole.begin(), hole.end());
  // Input vertices take ids 0..n-1, as in the vertex list (two at one tree point cannot occur:
  // the tree would have refused them).
  inputToMesh_.clear();
  bool added;
  for (const Vec2& v : built_.tree.input.vertices) inputToMesh_.push_back(ids_->findOrAdd(v, added));
  // Templates depend on the frame's stretch.
  haveTemplate_.fill(false);
}

void LeafEmitter::addInputVertices(uint32_t first, const std::vector<Vec2>& plane) {
  inputToMesh_.resize(first);
  bool added;
  for (size_t i = 0; i < plane.size(); ++i) {
    const uint32_t id = ids_->findOrAdd(built_.tree.input.vertices[first + i], added);
    if (added) vertices_.push_back(plane[i]);
    else vertices_[id] = plane[i];  // a grid point there already: it is the input vertex now
    inputToMesh_.push_back(id);
  }
}

LeafEmitter::~LeafEmitter() = default;

void LeafEmitter::emitAll(const std::vector<int32_t>& leaves, std::vector<std::array<uint32_t, 4>>& out) {
  eastAndNorth_.resize(built_.tree.quadrants.size());
  inOrder_ = true;
  for (int32_t q : leaves) emit(q, out);
  inOrder_ = false;
}

uint32_t LeafEmitter::newPoint(Vec2 at, bool listed) {
  const uint32_t id = listed ? ids_->addNew(at) : ids_->addUnlisted(at);
  vertices_.push_back(built_.frame.toPlane(at));
  return id;
}

uint32_t LeafEmitter::idOnWestOrSouth(const LeafRegion& region, Vec2 at) const {
  const Quadtree& tree = built_.tree;
  for (int32_t n : region.westLeaves) {
    const Quadrant& west = tree[n];
    const double s = static_cast<double>(tree.edgeLength(west)), y = static_cast<double>(west.y);
    if (west.status == QuadStatus::Outside || static_cast<double>(west.x) + s != at.x) continue;
    const auto& ids = eastAndNorth_[static_cast<size_t>(n)];
    const uint32_t id = at.y == y ? ids[0] : at.y == y + s / 2 ? ids[1] : at.y == y + s ? ids[2] : Mesh::kNone;
    if (id != Mesh::kNone) return id;
  }
  for (int32_t n : region.southLeaves) {
    const Quadrant& south = tree[n];
    const double s = static_cast<double>(tree.edgeLength(south)), x = static_cast<double>(south.x);
    if (south.status == QuadStatus::Outside || static_cast<double>(south.y) + s != at.y) continue;
    const auto& ids = eastAndNorth_[static_cast<size_t>(n)];
    const uint32_t id = at.x == x ? ids[4] : at.x == x + s / 2 ? ids[3] : at.x == x + s ? ids[2] : Mesh::kNone;
    if (id != Mesh::kNone) return id;
  }
  return Mesh::kNone;
}

void LeafEmitter::recordEastAndNorth(int32_t q) {
  const Quadrant& leaf = built_.tree[q];
  const double s = static_cast<double>(built_.tree.edgeLength(leaf));
  const double x0 = static_cast<double>(leaf.x), y0 = static_cast<double>(leaf.y), x1 = x0 + s, y1 = y0 + s;
  auto& ids = eastAndNorth_[static_cast<size_t>(q)];
  ids.fill(Mesh::kNone);
  for (size_t i = 0; i < ring_.size(); ++i) {
    const Vec2 p = ring_[i];
    if (p.x == x1) {
      if (p.y == y0) ids[0] = ringIds_[i];
      else if (p.y == y0 + s / 2) ids[1] = ringIds_[i];
      else if (p.y == y1) ids[2] = ringIds_[i];
    } else if (p.y == y1) {
      if (p.x == x0) ids[4] = ringIds_[i];
      else if (p.x == x0 + s / 2) ids[3] = ringIds_[i];
    }
  }
}

const LeafRegion& LeafEmitter::region(int32_t q) {
  const LeafRegion& region = regions_.build(q);
  ring_.clear();
  ringIds_.clear();
  const Quadrant& leaf = built_.tree[q];
  // In tree order (inOrder_), for a leaf holding no input vertex: which points are new, which
  // the leaves across know. A leaf holding one keeps to the table (its points may be the vertex).
  const bool inOrder = inOrder_ && leaf.vertex < 0;
  const double s = static_cast<double>(built_.tree.edgeLength(leaf));
  const double x0 = static_cast<double>(leaf.x), y0 = static_cast<double>(leaf.y), x1 = x0 + s, y1 = y0 + s;
  bool added;
  for (const RegionPoint& p : region.ring) {
    uint32_t id = Mesh::kNone;
    if (p.inputVertex >= 0) {
      id = inputToMesh_[static_cast<size_t>(p.inputVertex)];
    } else if (inOrder && ((p.at.x == x1 && p.at.y > y0) || (p.at.y == y1 && p.at.x > x0))) {
      // New, unless this ring had it already (only a template's ring is known to be free of that).
      if (region.templateKey < 0)
        for (size_t i = 0; i < ring_.size() && id == Mesh::kNone; ++i)
          if (ring_[i] == p.at) id = ringIds_[i];
      if (id == Mesh::kNone) id = newPoint(p.at, true);
    } else if (inOrder) {
      id = idOnWestOrSouth(region, p.at);
    }
    if (id == Mesh::kNone) {
      id = ids_->findOrAdd(p.at, added);
      if (added) vertices_.push_back(built_.frame.toPlane(p.at));
    }
    ringIds_.push_back(id);
    // Shapes are judged in tree coordinates, where points on one grid line are exactly in line;
    // plane coordinates far from the origin would blur a straight corner into a convex one.
    ring_.push_back(p.at);
  }
  if (inOrder_ && leaf.status != QuadStatus::Outside) recordEastAndNorth(q);
  return region;
}

const std::vector<uint32_t>& LeafEmitter::ringIds(int32_t q) {
  region(q);
  return ringIds_;
}

void LeafEmitter::emit(int32_t q, std::vector<std::array<uint32_t, 4>>& out) {
  const LeafRegion& leaf = region(q);
  if (leaf.ring.empty()) return;
  const Vec2 inner = leaf.inner;
  const size_t n = ring_.size();
  const std::vector<RingElement>* elements = &pieces_;
  const bool fromTemplate = leaf.templateKey >= 0;
  if (fromTemplate) {
    const auto key = static_cast<size_t>(leaf.templateKey);
    if (!haveTemplate_[key]) {
      templates_[key].clear();
      subdomains_.mesh(ring_, -1, &inner, built_.frame.planePerTree(), templates_[key]);
      haveTemplate_[key] = true;
    }
    elements = &templates_[key];
  } else {
    pieces_.clear();
    subdomains_.mesh(ring_, leaf.hinge, &inner, built_.frame.planePerTree(), pieces_, leaf.pathPoints);
  }
  // Ring points have their ids; the inner point and points added on the boundary are this
  // leaf's own (a template's indices are the ring's, then the inner point).
  uint32_t innerId = Mesh::kNone;  // a template's inner point, in tree order: new, once
  auto idOf = [&](uint32_t index) {
    const int ringIndex = fromTemplate ? (index < n ? static_cast<int>(index) : -1) : subdomains_.ringIndexOf(index);
    if (ringIndex >= 0) return ringIds_[static_cast<size_t>(ringIndex)];
    if (fromTemplate && inOrder_) {
      if (innerId == Mesh::kNone) innerId = newPoint(inner, false);
      return innerId;
    }
    const Vec2 at = fromTemplate ? inner : subdomains_.points()[index];
    bool added;
    const uint32_t id = ids_->findOrAdd(at, added);
    if (added) vertices_.push_back(built_.frame.toPlane(at));
    return id;
  };
  for (const RingElement& piece : *elements) {
    std::array<uint32_t, 4> element{Mesh::kNone, Mesh::kNone, Mesh::kNone, Mesh::kNone};
    for (uint8_t k = 0; k < piece.count; ++k) element[k] = idOf(piece.v[k]);
    out.push_back(element);
  }
}

}  // namespace mesher
