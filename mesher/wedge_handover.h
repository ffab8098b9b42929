// Shallow crossings, beyond the thesis: where an input edge meets a grid line at less than
// kAngleBoundDeg (in the plane), the leaf on one side of the line holds the inside as a wedge
// with that angle at the crossing Q, and no meshing of that leaf alone can avoid it: the angle
// is the same at every level. The wedge's first triangle (Q, M, M': M the next grid point
// along the line, M' the edge's point straight across from M) is handed to the leaf across the
// line at Q, whose inside there is the obtuse side. The taker's ring drops Q and runs
// M -> M' instead (corner 90 - theta), the giver's drops Q for M' (corners 90 and 90 + theta).
// Where the edge ends at the giver's vertex V before M', the triangle is (Q, M, V): the taker
// runs M -> V, the giver V -> M. Both leaves decide from the same data, so they always agree.
#pragma once

#include "mesher/quadtree.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace mesher {

struct WedgeHandover {
  int32_t giver = -1, taker = -1;
  Vec2 m{0}, mPrime{0};  // tree coordinates; M' is computed as leaf regions compute crossings
  int32_t vertex = -1;   // the giver's vertex when the triangle ends there (mPrime is then V)
};

// The handover at crossing `q` of edge `edge` with side `side` (0 west, 1 east, 2 south,
// 3 north) of leaf `leaf`, whose ring runs from q along that side to the grid point `m`; nothing
// when the crossing is not shallow or the wedge cannot be handed over whole. The taker must be
// finer than the uniform depth (its grown region then stays within a coarsest leaf, the patch
// size) and at most one level coarser than the leaves it meets across the giver's side; when it
// is too coarse only for that, `tooCoarse` (if given) is set to it: split, it would do.
std::optional<WedgeHandover> wedgeHandover(const Quadtree& tree, Vec2 planePerTree, int32_t leaf, uint32_t edge,
                                           int side, Vec2 q, Vec2 m, int32_t* tooCoarse = nullptr);

// The mesh vertices strictly between M and M' (the T-vertices of the giver's finer neighbours
// when M -> M' runs along the giver's side), ordered from M to M', appended to `out`.
void pointsBetween(const Quadtree& tree, const WedgeHandover& handover, std::vector<Vec2>& out);

// Marks the edges that meet the grid lines of one axis or the other shallowly (input.shallow)
// and says whether any does: most surfaces are rectangles along the axes, and none of their
// leaves needs a look.
bool markShallowEdges(QuadtreeInput& input, Vec2 planePerTree);

// The point where edge a -> b meets the grid line x = line (`vertical`) or y = line, from the
// edge and the line alone (so every leaf computes it bit for bit alike), clamped to [lo, hi]
// and snapped onto a grid line within `snap`. Inline: every boundary leaf computes two.
inline Vec2 crossingOnLine(Vec2 a, Vec2 b, bool vertical, double line, double lo, double hi, double snap) {
  auto snapToGrid = [snap](double v) {
    const double r = std::round(v);
    return std::abs(v - r) <= snap ? r : v;
  };
  // Always interpolated from the edge's own start so both leaves of the line agree.
  if (vertical) return {line, snapToGrid(std::clamp(a.y + (line - a.x) * (b.y - a.y) / (b.x - a.x), lo, hi))};
  return {snapToGrid(std::clamp(a.x + (line - a.y) * (b.x - a.x) / (b.y - a.y), lo, hi)), line};
}

}  // namespace mesher
