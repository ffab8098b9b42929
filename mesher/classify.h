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
//
// A polygon of at most `rayCastBelow` edges skips the fill: casting a ray against a few edges
// per leaf is cheaper than visiting every leaf's neighbours (a 261k-leaf floor of 11 edges: 90
// against 110 ms).
size_t classifyLeaves(Quadtree& tree, size_t rayCastBelow = 0);

// Even-odd test of a point against the polygon's active edges (tree coordinates); the point must
// not lie on an edge.
bool rayCastInside(const QuadtreeInput& input, Vec2 p);

}  // namespace mesher
