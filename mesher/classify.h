// Inside/outside classification of the leaves that hold no edge (thesis 5.2): the inside lies to
// the left of every directed edge, so a boundary leaf tells on which side its neighbours are, and
// the answer spreads by flood fill.
#pragma once

#include "mesher/quadtree.h"

namespace mesher {

// Sets every Undefined leaf to Inside or Outside. Seeds: neighbours of boundary leaves, judged
// from that leaf's own edges at a point of their shared side; leaves either side of an edge
// lying exactly along leaf sides (no leaf stores such an edge), judged by its direction. The
// fill does not cross those edges. A leaf the fill cannot reach is tested by ray casting.
// Returns how many leaves needed the ray cast (0 for any polygon the rules describe).
size_t classifyLeaves(Quadtree& tree);

// A polygon of at most kFewEdges edges is classified by ray casting as the build makes its
// leaves (buildQuadtree) instead: a ray against a few edges is cheaper than the fill's visits
// to every leaf's neighbours (a 261k-leaf floor of 11 edges: 90 against 110 ms), and one ray
// serves every leaf below a square no edge crosses.
constexpr size_t kFewEdges = 32;

// Inside or Outside by a ray from the centre of quadrant q.
QuadStatus castFromCentre(const Quadtree& tree, int32_t q);

// Even-odd test of a point against the polygon's active edges (tree coordinates); the point must
// not lie on an edge.
bool rayCastInside(const QuadtreeInput& input, Vec2 p);

}  // namespace mesher
