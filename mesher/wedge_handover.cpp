#include "mesher/wedge_handover.h"

#include "mesher/mesher.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mesher {

namespace {

// Which way the acute inside wedge lies at a crossing of an edge with a grid line: `side` is +1
// when it is on the side of larger coordinates across the line, `along` the direction from the
// crossing along the line into it.
struct WedgeSide {
  int side = 0, along = 0;
};

const double kTanBound = std::tan(kAngleBoundDeg * std::numbers::pi / 180);

// The wedge at a crossing of edge a -> b (inside on its left) with a vertical (x = const) or
// horizontal line, when the edge meets the line at less than the bound in the plane.
std::optional<WedgeSide> shallowWedge(Vec2 a, Vec2 b, bool vertical, Vec2 planePerTree) {
  const int alongAxis = vertical ? 1 : 0, acrossAxis = 1 - alongAxis;
  const Vec2 d = b - a, plane = d * planePerTree;
  if (!(std::abs(plane[acrossAxis]) < kTanBound * std::abs(plane[alongAxis])) || d[acrossAxis] == 0) return {};
  // The edge's ray into the side of larger coordinates, and the direction along the line that
  // makes an acute angle with it: the wedge between them is inside when it lies left of the
  // edge, else the wedge on the other side is.
  const double rayAlong = d[acrossAxis] > 0 ? d[alongAxis] : -d[alongAxis];
  const int u = rayAlong > 0 ? 1 : -1;
  const double leftOfEdge = vertical ? d.x * u : -d.y * u;  // cross(d, u along the line)
  if (leftOfEdge > 0) return WedgeSide{1, u};
  return WedgeSide{-1, -u};
}

// Which side of its own line a leaf lies on: +1 when the line is its west or south side.
int leafSideOf(int side) { return side == 0 || side == 2 ? 1 : -1; }

bool holdsEdge(const Quadrant& leaf, uint32_t edge) {
  return leaf.isLeaf() && std::find(leaf.edges.begin(), leaf.edges.begin() + leaf.edgeCount, edge) != leaf.edges.begin() + leaf.edgeCount;
}

// The leaf across the line through q (q strictly between grid points), towards +1 or -1.
int32_t leafAcross(const Quadtree& tree, Vec2 q, bool vertical, int towards) {
  Vec2 probe = q;
  (vertical ? probe.x : probe.y) += 0.5 * towards;
  return tree.leafAt(probe);
}

// Calls visit(leaf, ends) for each leaf across the giver's side, finer than the giver and not
// Outside, that meets M -> M' (when that runs along one of the giver's sides), with those of
// its two ends on the side that lie strictly between M and M'.
template <typename Visit>
void forEachPointBetween(const Quadtree& tree, const WedgeHandover& handover, Visit visit) {
  const Quadrant& giver = tree[handover.giver];
  const double s = static_cast<double>(tree.edgeLength(giver));
  const double x0 = static_cast<double>(giver.x), y0 = static_cast<double>(giver.y);
  const Vec2 m = handover.m, to = handover.mPrime;
  if (m.x != to.x && m.y != to.y) return;  // through the giver's inside (to its vertex)
  const bool vertical = m.x == to.x;  // M -> M' runs along x = const
  const double line = vertical ? m.x : m.y;
  const double low = vertical ? x0 : y0;
  // Only along one of the giver's sides can its neighbours put points on M -> M'.
  if (line != low && line != low + s) return;
  const Side side = vertical ? (line == x0 ? Side::West : Side::East) : (line == y0 ? Side::South : Side::North);
  std::vector<int32_t> across;
  tree.neighbors(handover.giver, side, across);
  const double from = vertical ? m.y : m.x, until = vertical ? to.y : to.x;
  const double lo = std::min(from, until), hi = std::max(from, until);
  std::vector<Vec2> ends;
  for (int32_t n : across) {
    const Quadrant& other = tree[n];
    if (other.level <= giver.level || other.status == QuadStatus::Outside) continue;
    const double start = static_cast<double>(vertical ? other.y : other.x);
    const double end = start + static_cast<double>(tree.edgeLength(other));
    if (end <= lo || start >= hi) continue;
    ends.clear();
    for (double t : {start, end})
      if (t > lo && t < hi) ends.push_back(vertical ? Vec2{line, t} : Vec2{t, line});
    visit(other, ends);
  }
}

}  // namespace

std::optional<WedgeHandover> wedgeHandover(const Quadtree& tree, Vec2 planePerTree, int32_t leaf, uint32_t edge,
                                           int side, Vec2 q, Vec2 m, int32_t* tooCoarse) {
  if (edge >= tree.input.shallow.size() || !tree.input.shallow[edge]) return {};
  const bool vertical = side < 2;
  const int alongAxis = vertical ? 1 : 0, acrossAxis = 1 - alongAxis;
  const Vec2 a = tree.input.vertices[tree.input.edges[edge][0]], b = tree.input.vertices[tree.input.edges[edge][1]];
  const std::optional<WedgeSide> wedge = shallowWedge(a, b, vertical, planePerTree);
  if (!wedge || m[acrossAxis] != q[acrossAxis] || (m[alongAxis] - q[alongAxis]) * wedge->along <= 0) return {};
  const int32_t other = leafAcross(tree, q, vertical, -leafSideOf(side));
  if (other < 0) return {};
  // A crossing on a leaf's corner (snapped there) touches more leaves than two; on a grid point
  // of the finest level that is no leaf's corner, it touches these two alone.
  auto cornerOf = [&](const Quadrant& l) {
    return std::fmod(q[alongAxis] - static_cast<double>(vertical ? l.y : l.x), static_cast<double>(tree.edgeLength(l))) == 0;
  };
  if (cornerOf(tree[leaf]) || cornerOf(tree[other])) return {};
  WedgeHandover handover;
  const bool leafGives = leafSideOf(side) == wedge->side;
  handover.giver = leafGives ? leaf : other;
  handover.taker = leafGives ? other : leaf;
  const Quadrant& giver = tree[handover.giver];
  const Quadrant& taker = tree[handover.taker];
  if (!holdsEdge(taker, edge) || !holdsEdge(giver, edge)) return {};
  auto refuseCoarse = [&]() -> std::optional<WedgeHandover> {
    if (tooCoarse) *tooCoarse = handover.taker;
    return {};
  };
  if (taker.level <= tree.uniformDepth) return refuseCoarse();
  handover.m = m;
  // A vertex leaf holds only edges ending at its vertex: the wedge ends there when the vertex
  // comes before M' does, and the triangle handed over is (Q, M, V).
  if (giver.vertex >= 0) {
    const Vec2 v = tree.input.vertices[static_cast<size_t>(giver.vertex)];
    if ((m[alongAxis] - v[alongAxis]) * wedge->along >= 0) {
      handover.vertex = giver.vertex;
      handover.mPrime = v;
      return handover;
    }
  }
  // M' lies on the giver's square, computed as the giver computes a crossing of that line (its
  // clamp to the square then changes nothing).
  const double lo = static_cast<double>(acrossAxis == 0 ? giver.x : giver.y);
  const double hi = lo + static_cast<double>(tree.edgeLength(giver));
  const double unbounded = std::numeric_limits<double>::infinity();
  handover.mPrime = crossingOnLine(a, b, !vertical, m[alongAxis], -unbounded, unbounded, tree.gridSnap);
  if (handover.mPrime[acrossAxis] < lo || handover.mPrime[acrossAxis] > hi || handover.mPrime == m) return {};
  // The taker's elements along M -> M' meet the leaves across the giver's side there: those
  // must be at most one level finer than the taker, as balance keeps side neighbours.
  bool graded = true;
  forEachPointBetween(tree, handover,
                      [&](const Quadrant& across, const std::vector<Vec2>&) { graded = graded && across.level <= taker.level + 1; });
  if (!graded) return refuseCoarse();
  return handover;
}

void pointsBetween(const Quadtree& tree, const WedgeHandover& handover, std::vector<Vec2>& out) {
  const size_t first = out.size();
  forEachPointBetween(tree, handover, [&](const Quadrant&, const std::vector<Vec2>& ends) { out.insert(out.end(), ends.begin(), ends.end()); });
  const Vec2 m = handover.m;
  const bool vertical = m.x == handover.mPrime.x;
  const double from = vertical ? m.y : m.x;
  auto distance = [&](Vec2 p) { return std::abs((vertical ? p.y : p.x) - from); };
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(), [&](Vec2 p, Vec2 r) { return distance(p) < distance(r); });
  out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(first), out.end()), out.end());
}

bool markShallowEdges(QuadtreeInput& input, Vec2 planePerTree) {
  input.shallow.assign(input.edges.size(), 0);
  bool any = false;
  for (uint32_t e = 0; e < input.edges.size(); ++e) {
    if (!input.active(e)) continue;
    const Vec2 a = input.vertices[input.edges[e][0]], b = input.vertices[input.edges[e][1]];
    input.shallow[e] = shallowWedge(a, b, true, planePerTree) || shallowWedge(a, b, false, planePerTree);
    any = any || input.shallow[e];
  }
  return any;
}

}  // namespace mesher
