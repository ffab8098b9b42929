// The part of one quadtree leaf inside the polygon (thesis 5.3, 5.4): a counter-clockwise ring
// holding every mesh vertex on its border, so elements made from it anchor all T-vertices.
#pragma once

#include "mesher/quadtree.h"

#include <vector>

namespace mesher {

struct RegionPoint {
  Vec2 at;                  // tree coordinates
  int32_t inputVertex = -1; // the input vertex it is, if any
};

struct LeafRegion {
  std::vector<RegionPoint> ring;  // counter-clockwise; empty when the leaf has no inside
  int hinge = -1;                 // index in ring of the hinge vertex of 5.4; -1 when no edge passes
};

// Builds the region of leaf q: its corners and the T-vertices of finer neighbours on the inside
// part of its border, the crossings of its stored edges and its vertex. Crossings are computed
// from the edge and the grid line alone, so the leaves on both sides of a line agree exactly;
// crossings within 1e-6 tree units of a grid point snap to it.
LeafRegion leafRegion(const Quadtree& tree, int32_t q);

}  // namespace mesher
