#include "mesher/mesher.h"

#include "mesher/balance.h"
#include "mesher/leaf_region.h"
#include "mesher/quadtree.h"
#include "mesher/subdomain_removal.h"

#include <cstring>
#include <stdexcept>
#include <algorithm>
#include <bit>
#include <cmath>

namespace mesher {

namespace {

// Mesh vertex ids by their exact tree coordinates: leaves sharing a point compute it bit for bit
// alike (corners are integers, crossings come from the edge and the line alone). Open addressing
// over ids only, the points themselves kept in id order. Slots follow the Morton (Z) order of
// the point in the root square, the order the leaves are visited in, so lookups of a million
// points stay in cache instead of jumping across the table.
class PointIds {
 public:
  PointIds(size_t expected, double rootSize) : toUnit_(1 / rootSize) {
    slots_.assign(std::bit_ceil(std::max<size_t>(16, 2 * expected)), kEmpty);
    shift_ = 64 - std::countr_zero(slots_.size());
    points_.reserve(expected);
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
    added = true;
    return id;
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
  size_t slotOf(Vec2 p) const {
    const auto x = static_cast<uint64_t>(std::clamp(p.x * toUnit_, 0.0, 1.0) * 4294967295.0);
    const auto y = static_cast<uint64_t>(std::clamp(p.y * toUnit_, 0.0, 1.0) * 4294967295.0);
    return static_cast<size_t>((spreadBits(x) | spreadBits(y) << 1) >> shift_);
  }
  void grow() {
    slots_.assign(slots_.size() * 2, kEmpty);
    shift_ -= 1;
    for (uint32_t id = 0; id < points_.size(); ++id) {
      size_t slot = slotOf(points_[id]);
      while (slots_[slot] != kEmpty) slot = (slot + 1) & (slots_.size() - 1);
      slots_[slot] = id;
    }
  }

  double toUnit_;
  int shift_ = 0;
  std::vector<uint32_t> slots_;
  std::vector<Vec2> points_;  // tree coordinates, by id
};

}  // namespace

size_t Mesh::quadCount() const {
  size_t quads = 0;
  for (const auto& e : elements) quads += e[3] != kNone;
  return quads;
}

Mesh meshPolygon(const PolygonWithHoles& polygon, const MeshSettings& settings) {
  // Phases of chapter 5: tree setup and edge storage, balancing, leaf by leaf meshing. Balancing
  // can split a leaf that held a sharp corner whole; when its edges then need more levels than
  // the tree has, the tree is built deeper.
  PolygonTree built = buildPolygonTree(polygon, settings.patchSize);
  for (int deeper = 8; !balance(built.tree); deeper += 8) {
    if (built.tree.maxDepth >= kDeepestTree) throw std::invalid_argument("polygon corner too sharp to balance");
    built = buildPolygonTree(polygon, settings.patchSize, deeper);
  }
  Quadtree& tree = built.tree;

  Mesh mesh;
  const std::vector<int32_t> leaves = tree.leaves();
  PointIds ids(leaves.size() + tree.input.vertices.size(), std::exp2(tree.maxDepth));
  mesh.vertices = polygon.outer;
  for (const Ring2& hole : polygon.holes) mesh.vertices.insert(mesh.vertices.end(), hole.begin(), hole.end());
  // Input vertices take ids 0..n-1, as in the mesh (two at one tree point cannot occur: the
  // tree would have refused them).
  bool added;
  for (const Vec2& v : tree.input.vertices) ids.findOrAdd(v, added);

  // Scratch reused for every leaf. Interior squares differ only in which sides carry a
  // T-vertex, so their subdomains (the templates of 5.3) are worked out once per pattern.
  mesh.vertices.reserve(leaves.size() * 2);
  mesh.elements.reserve(leaves.size() * 2);
  std::vector<Vec2> ring;
  std::vector<uint32_t> ringIds;
  std::vector<RingElement> pieces;
  std::array<std::vector<RingElement>, 16> templates;
  std::array<bool, 16> haveTemplate{};
  LeafRegionBuilder regions(tree);
  for (int32_t q : leaves) {
    const LeafRegion& region = regions.build(q);
    if (region.ring.empty()) continue;
    ring.clear();
    ringIds.clear();
    for (const RegionPoint& p : region.ring) {
      uint32_t id;
      if (p.inputVertex >= 0) {
        id = static_cast<uint32_t>(p.inputVertex);
      } else {
        id = ids.findOrAdd(p.at, added);
        if (added) mesh.vertices.push_back(built.frame.toPlane(p.at));
      }
      ringIds.push_back(id);
      ring.push_back(mesh.vertices[id]);
    }
    const std::vector<RingElement>* elements = &pieces;
    if (region.templateKey >= 0) {
      const auto key = static_cast<size_t>(region.templateKey);
      if (!haveTemplate[key]) {
        removeSubdomains(ring, -1, templates[key]);
        haveTemplate[key] = true;
      }
      elements = &templates[key];
    } else {
      pieces.clear();
      removeSubdomains(ring, region.hinge, pieces);
    }
    for (const RingElement& piece : *elements) {
      std::array<uint32_t, 4> element{Mesh::kNone, Mesh::kNone, Mesh::kNone, Mesh::kNone};
      for (uint8_t k = 0; k < piece.count; ++k) element[k] = ringIds[piece.v[k]];
      mesh.elements.push_back(element);
    }
  }
  return mesh;
}

}  // namespace mesher
