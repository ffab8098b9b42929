#include "mesher/mesher.h"

#include "mesher/balance.h"
#include "mesher/leaf_region.h"
#include "mesher/quadtree.h"
#include "mesher/subdomain_removal.h"

#include <cstring>
#include <stdexcept>
#include <unordered_map>

namespace mesher {

namespace {

// Mesh vertices by their exact tree coordinates: leaves sharing a point compute it bit for bit
// alike (corners are integers, crossings come from the edge and the line alone).
struct PointKey {
  double x, y;
  bool operator==(const PointKey& o) const { return x == o.x && y == o.y; }
};
struct PointHash {
  size_t operator()(const PointKey& k) const {
    uint64_t a, b;
    std::memcpy(&a, &k.x, sizeof a);
    std::memcpy(&b, &k.y, sizeof b);
    return std::hash<uint64_t>()(a * 0x9E3779B97F4A7C15ull ^ b);
  }
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
  std::unordered_map<PointKey, uint32_t, PointHash> ids;
  mesh.vertices = polygon.outer;
  for (const Ring2& hole : polygon.holes) mesh.vertices.insert(mesh.vertices.end(), hole.begin(), hole.end());
  for (uint32_t v = 0; v < tree.input.vertices.size(); ++v)
    ids.emplace(PointKey{tree.input.vertices[v].x, tree.input.vertices[v].y}, v);

  std::vector<Vec2> ring;
  std::vector<uint32_t> ringIds;
  std::vector<RingElement> pieces;
  for (int32_t q : tree.leaves()) {
    const LeafRegion region = leafRegion(tree, q);
    if (region.ring.empty()) continue;
    ring.clear();
    ringIds.clear();
    for (const RegionPoint& p : region.ring) {
      uint32_t id;
      if (p.inputVertex >= 0) {
        id = static_cast<uint32_t>(p.inputVertex);
      } else {
        const auto [it, added] = ids.emplace(PointKey{p.at.x, p.at.y}, static_cast<uint32_t>(mesh.vertices.size()));
        if (added) mesh.vertices.push_back(built.frame.toPlane(p.at));
        id = it->second;
      }
      ringIds.push_back(id);
      ring.push_back(mesh.vertices[id]);
    }
    pieces.clear();
    removeSubdomains(ring, region.hinge, pieces);
    for (const RingElement& piece : pieces) {
      std::array<uint32_t, 4> element{Mesh::kNone, Mesh::kNone, Mesh::kNone, Mesh::kNone};
      for (uint8_t k = 0; k < piece.count; ++k) element[k] = ringIds[piece.v[k]];
      mesh.elements.push_back(element);
    }
  }
  return mesh;
}

}  // namespace mesher
