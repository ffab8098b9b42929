// The part of one quadtree leaf inside the polygon (thesis 5.3, 5.4): a counter-clockwise ring
// holding every mesh vertex on its border, so elements made from it anchor all T-vertices.
#pragma once

#include "mesher/quadtree.h"
#include "mesher/subdomain_removal.h"

#include <array>
#include <vector>

namespace mesher {

struct RegionPoint {
  Vec2 at;                  // tree coordinates
  int32_t inputVertex = -1; // the input vertex it is, if any
};

struct LeafRegion {
  std::vector<RegionPoint> ring;  // counter-clockwise; empty when the leaf has no inside
  int hinge = -1;                 // index in ring of the hinge vertex of 5.4; -1 when no edge passes
  // Which ring edges lie on the polygon's boundary. The ring starts with the polygon's boundary
  // through the leaf: its first boundary.pathPoints points run along input edges (entry
  // crossing, the vertex, exit crossing), the rest along the border. Not filled in for
  // templated squares.
  RingBoundary boundary;
  // Whole squares (no edge through them; a vertex, if any, at a corner or a side's midpoint):
  // which of their sides carry one midpoint T-vertex, as bits (1 west, 2 east, 4 south, 8
  // north); their rings then start at the lower-left corner and differ only in that. -1 for
  // every other leaf.
  int templateKey = -1;
  // A point its elements may share inside the leaf: the centre of a whole square, else the
  // region's centroid. Only this leaf can use it, so it cannot make a T-vertex.
  Vec2 inner{0};
  // Whether a shallow wedge was handed over to or from the leaf: only then can the ring hold
  // points off the leaf's border.
  bool handedOver = false;
  // The leaves across the west and south sides (any status), as Quadtree::neighbors lists them.
  std::vector<int32_t> westLeaves, southLeaves;
};

// Builds the region of leaf q: its corners and the T-vertices of finer neighbours on the inside
// part of its border, the crossings of its stored edges and its vertex. Crossings are computed
// from the edge and the grid line alone, so the leaves on both sides of a line agree exactly;
// crossings within the tree's gridSnap of a grid point snap to it. Where an edge meets a grid
// line too shallowly, the wedge it leaves is handed across the line (wedge_handover.h). The
// builder keeps its scratch memory from leaf to leaf; a returned region lives until the next
// build.
class LeafRegionBuilder {
 public:
  // Angles are judged in the plane of `built`'s frame (which may change: a tree rebuilt in place).
  explicit LeafRegionBuilder(const PolygonTree& built) : tree_(built.tree), frame_(built.frame) {}
  // `adjacent`, when given, is tree.adjacent(q, side) for West, East, South, North.
  const LeafRegion& build(int32_t q, const std::array<int32_t, 4>* adjacent = nullptr);
  // While set, build() appends to `takers` the leaves that would take a shallow wedge from the
  // leaf built if they were one level finer (wedge_handover.h).
  void collectCoarseTakers(std::vector<int32_t>* takers) { coarseTakers_ = takers; }

 private:
  // Where the polygon's boundary enters (or leaves) the leaf: the edge and the side (0 west,
  // 1 east, 2 south, 3 north; -1 when it does not cross the border).
  struct PathCrossing {
    uint32_t edge = 0;
    int side = -1;
  };
  // Shallow crossings' wedges handed over (wedge_handover.h): the region loses or gains them.
  void handOverWedges(int32_t q, const std::array<PathCrossing, 2>& crossings, Vec2& hinge);

  const Quadtree& tree_;
  const TreeFrame& frame_;
  LeafRegion region_;
  std::vector<RegionPoint> onBorder_, path_, ring_, handed_;
  std::vector<Vec2> between_, closing_;
  std::vector<int32_t>* coarseTakers_ = nullptr;
  std::vector<int32_t> across_;
  std::vector<std::pair<double, RegionPoint>> keyed_;  // border points by their place along the border
  Ring2 at_;
};

}  // namespace mesher
