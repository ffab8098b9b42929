#include "mesher/leaf_emitter.h"

#include "mesher/mesher.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace mesher {

namespace {

// Ends a ring's ids (LeafEmitter::ringIds) with its open sides' bits: no vertex id gets this
// large.
constexpr uint32_t kOpenSidesMark = 0xfffffff0u;

// How many stretches' templates are kept before starting over.
constexpr size_t kTemplateStretches = 1024;

}  // namespace

// Mesh vertex ids by their exact tree coordinates: leaves sharing a point compute it bit for bit
// alike (corners are integers, crossings come from the edge and the line alone). Open addressing
// over entries (point and id) kept in the order they were listed, so a quarter of a million
// points cost no allocation each and the table stays small. Ids count every point, also those
// never listed (points only one leaf, or the tree order, can ask for).
class PointIds {
 public:
  static constexpr uint32_t kNone = 0xffffffffu;

  // Empties the table for about `expected` listed points in a root square of edge `rootSize`,
  // keeping its memory; it grows as needed.
  void reset(size_t expected, double rootSize) {
    toUnit_ = 1 / rootSize;
    slots_.assign(std::bit_ceil(std::max<size_t>(16, 2 * expected)), kEmpty);
    shift_ = 64 - std::countr_zero(slots_.size());
    windowBits_ = kFirstWindowBits;
    entries_.clear();
    entries_.reserve(expected);
    nextId_ = 0;
  }

  // The id of p, listing it with the next id when it is new (`added` says which).
  uint32_t findOrAdd(const Vec2& p, bool& added) {
    if (2 * (entries_.size() + 1) > slots_.size()) grow();
    const size_t slot = probe(p);
    added = slots_[slot] == kEmpty;
    return added ? list(slot, p) : entries_[slots_[slot]].id;
  }
  // The id of a listed point p, or kNone.
  uint32_t find(const Vec2& p) {
    const size_t slot = probe(p);
    return slots_[slot] == kEmpty ? kNone : entries_[slots_[slot]].id;
  }
  // The next id for a point the caller knows is new, listed without comparisons, or not listed.
  uint32_t addNew(const Vec2& p) {
    if (2 * (entries_.size() + 1) > slots_.size()) grow();
    return list(probe(p, false), p);
  }
  uint32_t addUnlisted() { return nextId_++; }

 private:
  static constexpr uint32_t kEmpty = 0xffffffffu;
  struct Entry {
    Vec2 at;  // tree coordinates
    uint32_t id;
  };

  // The slot holding p (when `compare`), or the empty one ending its probe run. A run longer
  // than kLongRun means points crowd one window: the windows widen.
  size_t probe(const Vec2& p, bool compare = true) {
    size_t slot = slotOf(p), run = 0;
    for (; slots_[slot] != kEmpty && !(compare && entries_[slots_[slot]].at == p); slot = (slot + 1) & (slots_.size() - 1)) ++run;
    if (run <= kLongRun || windowBits_ >= std::countr_zero(slots_.size())) return slot;
    windowBits_ += 4;
    layOut();
    return probe(p, compare);
  }
  uint32_t list(size_t slot, const Vec2& p) {
    slots_[slot] = static_cast<uint32_t>(entries_.size());
    entries_.push_back({p, nextId_});
    return nextId_++;
  }
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
  // gap) do not share one probe run, which made lookups quadratic. Where more points crowd one
  // window than it holds (a comb's thin teeth), the windows widen, up to the whole table.
  size_t slotOf(const Vec2& p) const {
    const auto x = static_cast<uint64_t>(std::clamp(p.x * toUnit_, 0.0, 1.0) * 4294967295.0);
    const auto y = static_cast<uint64_t>(std::clamp(p.y * toUnit_, 0.0, 1.0) * 4294967295.0);
    uint64_t a, b;
    std::memcpy(&a, &p.x, sizeof a);
    std::memcpy(&b, &p.y, sizeof b);
    const uint64_t cell = (spreadBits(x) | spreadBits(y) << 1) >> shift_;
    // The top bits of a product by an odd constant depend on every bit of the coordinate, and
    // the high bits are where small integers differ.
    const uint64_t scatter = (a * 0x9E3779B97F4A7C15ull ^ b * 0xC2B2AE3D27D4EB4Full) >> (64 - windowBits_);
    return static_cast<size_t>(cell ^ scatter) & (slots_.size() - 1);
  }
  void grow() {
    slots_.resize(slots_.size() * 2);
    shift_ -= 1;
    layOut();
  }
  void layOut() {
    std::fill(slots_.begin(), slots_.end(), kEmpty);
    for (uint32_t i = 0; i < entries_.size(); ++i) {
      size_t slot = slotOf(entries_[i].at);
      while (slots_[slot] != kEmpty) slot = (slot + 1) & (slots_.size() - 1);
      slots_[slot] = i;
    }
  }

  static constexpr int kFirstWindowBits = 16;
  static constexpr size_t kLongRun = 64;
  double toUnit_ = 1;
  int shift_ = 0;
  int windowBits_ = kFirstWindowBits;
  std::vector<uint32_t> slots_;  // entry indices
  std::vector<Entry> entries_;
  uint32_t nextId_ = 0;
};

LeafEmitter::LeafEmitter(const PolygonWithHoles& polygon, const PolygonTree& built, size_t expectedLeaves)
    : built_(built), ids_(std::make_unique<PointIds>()), regions_(built) {
  reset(polygon, expectedLeaves);
}

void LeafEmitter::reset(const PolygonWithHoles& polygon, size_t expectedLeaves) {
  // Emitted in tree order, few points are listed (see inOrder_); leaf by leaf, the table grows.
  ids_->reset(expectedLeaves / 8 + built_.tree.input.vertices.size(), std::exp2(built_.tree.maxDepth));
  vertices_.clear();
  vertices_.reserve(expectedLeaves * 2);
  treePoints_.clear();
  vertices_.insert(vertices_.end(), polygon.outer.begin(), polygon.outer.end());
  for (const Ring2& hole : polygon.holes) vertices_.insert(vertices_.end(), hole.begin(), hole.end());
  // Input vertices take ids 0..n-1, as in the vertex list (two at one tree point cannot occur:
  // the tree would have refused them).
  inputToMesh_.clear();
  bool added;
  for (const Vec2& v : built_.tree.input.vertices) inputToMesh_.push_back(ids_->findOrAdd(v, added));
  const std::pair<double, int> stretch{built_.frame.stretch, built_.frame.shortAxis};
  auto found = templatesOf_.find(stretch);
  if (found == templatesOf_.end()) {
    if (templates_.size() >= kTemplateStretches) templates_.clear(), templatesOf_.clear();
    found = templatesOf_.emplace(stretch, templates_.size()).first;
    templates_.emplace_back();
  }
  stretchTemplates_ = found->second;
}

void LeafEmitter::addInputVertices(uint32_t first, const std::vector<Vec2>& plane) {
  inputToMesh_.resize(first);
  bool added;
  for (size_t i = 0; i < plane.size(); ++i) {
    const uint32_t id = ids_->findOrAdd(built_.tree.input.vertices[first + i], added);
    if (added) {
      vertices_.push_back(plane[i]);
      if (keepTreePoints_) treePoints_.push_back(built_.tree.input.vertices[first + i]);
    } else {
      vertices_[id] = plane[i];  // a grid point there already: it is the input vertex now
    }
    inputToMesh_.push_back(id);
  }
}

LeafEmitter::~LeafEmitter() = default;

void LeafEmitter::emitAll(std::vector<std::array<uint32_t, 4>>& out) {
  eastAndNorth_.resize(built_.tree.quadrants.size());
  inOrder_ = true;
  handedOver_ = false;
  built_.tree.forEachLeafWithAdjacent([&](int32_t q, const std::array<int32_t, 4>& adjacent) { emit(q, &adjacent, out); });
  inOrder_ = false;
}

uint32_t LeafEmitter::newPoint(const Vec2& at, bool listed) {
  const uint32_t id = listed ? ids_->addNew(at) : ids_->addUnlisted();
  addVertex(at);
  return id;
}

void LeafEmitter::addVertex(const Vec2& at) {
  vertices_.push_back(built_.frame.toPlane(at));
  if (keepTreePoints_) treePoints_.push_back(at);
}

namespace {

// Which of the recorded east and north positions (LeafEmitter::eastAndNorth_) of the leaf
// square at (x0, y0) of edge s point p is, or -1.
int eastOrNorthPosition(double x0, double y0, double s, const Vec2& p) {
  const double x1 = x0 + s, y1 = y0 + s;
  if (p.x == x1) return p.y == y0 ? 0 : p.y == y0 + s / 2 ? 1 : p.y == y1 ? 2 : -1;
  if (p.y == y1) return p.x == x0 ? 4 : p.x == x0 + s / 2 ? 3 : -1;
  return -1;
}

}  // namespace

uint32_t LeafEmitter::recordedBy(int32_t m, const Vec2& at) const {
  const Quadrant& leaf = built_.tree[m];
  if (leaf.status == QuadStatus::Outside) return Mesh::kNone;
  const int position = eastOrNorthPosition(static_cast<double>(leaf.x), static_cast<double>(leaf.y),
                                            static_cast<double>(built_.tree.edgeLength(leaf)), at);
  return position < 0 ? Mesh::kNone : eastAndNorth_[static_cast<size_t>(m)][static_cast<size_t>(position)];
}

uint32_t LeafEmitter::earlierId(int32_t q, const LeafRegion& region, const Vec2& at) const {
  // The leaves across first (the region found them), then the table, then every leaf around the
  // point that came earlier (a corner shared only across a diagonal, a neighbour Outside).
  const Quadtree& tree = built_.tree;
  if (at.x == static_cast<double>(tree[q].x))
    for (int32_t n : region.westLeaves)
      if (const uint32_t id = recordedBy(n, at); id != Mesh::kNone) return id;
  if (at.y == static_cast<double>(tree[q].y))
    for (int32_t n : region.southLeaves)
      if (const uint32_t id = recordedBy(n, at); id != Mesh::kNone) return id;
  if (const uint32_t id = ids_->find(at); id != Mesh::kNone) return id;
  const Quadrant& leaf = tree[q];
  const double s = static_cast<double>(tree.edgeLength(leaf)), root = static_cast<double>(tree.edgeLength(tree[0]));
  for (int k = 0; k < 4; ++k) {
    const Vec2 probe = at + Vec2{k & 1 ? 0.25 : -0.25, k & 2 ? 0.25 : -0.25};  // leaves are 1 unit or more
    const bool inLeaf = probe.x >= static_cast<double>(leaf.x) && probe.x < static_cast<double>(leaf.x) + s &&
                        probe.y >= static_cast<double>(leaf.y) && probe.y < static_cast<double>(leaf.y) + s;
    if (inLeaf || probe.x < 0 || probe.y < 0 || probe.x >= root || probe.y >= root) continue;
    const int32_t m = tree.leafAt(probe);
    if (m < 0 || m == q || !comesBefore(tree[m], leaf)) continue;
    if (const uint32_t id = recordedBy(m, at); id != Mesh::kNone) return id;
  }
  return Mesh::kNone;
}

const LeafRegion& LeafEmitter::region(int32_t q, const std::array<int32_t, 4>* adjacent) {
  const LeafRegion& region = regions_.build(q, adjacent);
  ring_.clear();
  ringIds_.clear();
  const Quadtree& tree = built_.tree;
  const Quadrant& leaf = tree[q];
  const double s = static_cast<double>(tree.edgeLength(leaf));
  const double x0 = static_cast<double>(leaf.x), y0 = static_cast<double>(leaf.y), x1 = x0 + s, y1 = y0 + s;
  bool added;
  // In tree order the ids on the leaf's east and north sides are recorded as they are found
  // (only later leaves read them).
  std::array<uint32_t, 5>* recorded = inOrder_ && leaf.status != QuadStatus::Outside ? &eastAndNorth_[static_cast<size_t>(q)] : nullptr;
  if (recorded) recorded->fill(Mesh::kNone);
  for (const RegionPoint& p : region.ring) {
    uint32_t id = Mesh::kNone;
    const int position = recorded ? eastOrNorthPosition(x0, y0, s, p.at) : -1;
    auto onBorder = [&] {
      return (p.at.x == x0 || p.at.x == x1) ? (p.at.y >= y0 && p.at.y <= y1)
                                            : (p.at.y == y0 || p.at.y == y1) && p.at.x >= x0 && p.at.x <= x1;
    };
    if (p.inputVertex >= 0) {
      id = inputToMesh_[static_cast<size_t>(p.inputVertex)];
    } else if (!inOrder_ || (region.handedOver && !onBorder())) {
      // Off the border only a handed-over wedge puts points (wedge_handover.h), which the
      // tree order does not foresee: they go in the table. In tree order a grid point among
      // them (a T-vertex on the giver's side) may be a corner or midpoint that an earlier
      // leaf across that side kept out of the table: it is looked for there first, or the
      // taker would make it a second vertex that leaf does not share.
      if (inOrder_) id = earlierId(q, region, p.at);
      if (id == Mesh::kNone) {
        id = ids_->findOrAdd(p.at, added);
        if (added) addVertex(p.at);
        handedOver_ = handedOver_ || (inOrder_ && added);
      }
    } else if ((p.at.x == x1 && p.at.y > y0) || (p.at.y == y1 && p.at.x > x0)) {
      // New (see inOrder_), unless it is the leaf's input vertex or this ring had it already
      // (a template's ring has no point twice).
      if (leaf.vertex >= 0 && p.at == tree.input.vertices[static_cast<size_t>(leaf.vertex)])
        id = inputToMesh_[static_cast<size_t>(leaf.vertex)];
      if (region.templateKey < 0)
        for (size_t i = 0; i < ring_.size() && id == Mesh::kNone; ++i)
          if (ring_[i] == p.at) id = ringIds_[i];
      if (id == Mesh::kNone && handedOver_) id = ids_->find(p.at);
      // A point at a recorded position is found there; any other one goes in the table.
      if (id == Mesh::kNone) id = newPoint(p.at, position < 0);
    } else {
      id = earlierId(q, region, p.at);
      if (id == Mesh::kNone) id = newPoint(p.at, true);
    }
    ringIds_.push_back(id);
    // Shapes are judged in tree coordinates, where points on one grid line are exactly in line;
    // plane coordinates far from the origin would blur a straight corner into a convex one.
    ring_.push_back(p.at);
    if (position >= 0) (*recorded)[static_cast<size_t>(position)] = id;
  }
  // Points may be added along open sides (RingBoundary::openSides): a ring whose sides open or
  // close as a neighbour turns inside or out is not the same ring.
  if (region.templateKey < 0 && region.boundary.openSides != 0) ringIds_.push_back(kOpenSidesMark | static_cast<uint32_t>(region.boundary.openSides));
  return region;
}

const std::vector<uint32_t>& LeafEmitter::ringIds(int32_t q) {
  region(q);
  return ringIds_;
}

void LeafEmitter::emit(int32_t q, std::vector<std::array<uint32_t, 4>>& out) { emit(q, nullptr, out); }

void LeafEmitter::emit(int32_t q, const std::array<int32_t, 4>* adjacent, std::vector<std::array<uint32_t, 4>>& out) {
  const LeafRegion& leaf = region(q, adjacent);
  if (leaf.ring.empty()) return;
  const Vec2 inner = leaf.inner;
  const size_t n = ring_.size();
  const std::vector<RingElement>* elements = &pieces_;
  const bool fromTemplate = leaf.templateKey >= 0;
  if (fromTemplate) {
    const auto key = static_cast<size_t>(leaf.templateKey);
    Templates& templates = templates_[stretchTemplates_];
    if (!templates.have[key]) {
      // The ring on the unit square (it starts at the lower-left corner; leaf edges are powers
      // of two, so this is exact), in the frame's proportions. Its points are exact in every
      // leaf too: no rounding to allow for.
      const double s = static_cast<double>(built_.tree.edgeLength(built_.tree[q]));
      unitRing_.clear();
      for (const Vec2& p : ring_) unitRing_.push_back((p - ring_[0]) / s);
      Vec2 proportions{1, 1};
      proportions[built_.frame.shortAxis] /= built_.frame.stretch;
      const Vec2 centre{0.5, 0.5};
      subdomains_.mesh(unitRing_, -1, &centre, proportions, templates.pieces[key]);
      templates.have[key] = true;
    }
    elements = &templates.pieces[key];
  } else {
    pieces_.clear();
    subdomains_.mesh(ring_, leaf.hinge, &inner, built_.frame.planePerTree(), pieces_, &leaf.boundary, built_.frame.rounding);
    if (shortLeaves_ && !subdomains_.reachedBound()) shortLeaves_->push_back(q);
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
    if (added) addVertex(at);
    return id;
  };
  for (const RingElement& piece : *elements) {
    std::array<uint32_t, 4> element{Mesh::kNone, Mesh::kNone, Mesh::kNone, Mesh::kNone};
    for (uint8_t k = 0; k < piece.count; ++k) element[k] = idOf(piece.v[k]);
    out.push_back(element);
  }
}

}  // namespace mesher
