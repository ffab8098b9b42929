#include "mesher/classify.h"

#include <algorithm>
#include <cmath>

namespace mesher {

namespace {

constexpr Side kSides[] = {Side::West, Side::East, Side::South, Side::North};

// Marks, for every leaf, the sides along which an input edge lies (no leaf stores such an edge:
// it crosses no leaf's open square), and seeds the leaves either side of each such edge from its
// direction: the inside is on its left.
class SideLyingEdges {
 public:
  SideLyingEdges(const Quadtree& tree, std::vector<uint8_t>& blocked, std::vector<std::pair<int32_t, bool>>& seeds) {
    const QuadtreeInput& in = tree.input;
    for (uint32_t e = 0; e < in.edges.size(); ++e) {
      if (!in.active(e)) continue;
      const Vec2 a = in.vertices[in.edges[e][0]], b = in.vertices[in.edges[e][1]];
      const bool vertical = a.x == b.x && a.x == std::round(a.x);
      const bool horizontal = a.y == b.y && a.y == std::round(a.y);
      if (!vertical && !horizontal) continue;
      // Going up a vertical edge the inside is west; going east along a horizontal one, north.
      const bool lowSideInside = vertical ? b.y > a.y : b.x < a.x;
      const int axis = vertical ? 1 : 0;  // the coordinate that runs along the edge
      const double lo = std::min(a[axis], b[axis]), hi = std::max(a[axis], b[axis]);
      const double line = vertical ? a.x : a.y;
      for (int lowSide = 0; lowSide < 2; ++lowSide) {
        // Walk the leaves along this side of the edge.
        for (double t = lo; t < hi;) {
          const double across = lowSide ? line - 0.5 : line;  // leaves are at least 1 unit wide
          const int32_t q = tree.leafAt(vertical ? Vec2{across, t} : Vec2{t, across});
          if (q < 0) break;
          const Quadrant& leaf = tree[q];
          const Side facing = vertical ? (lowSide ? Side::East : Side::West) : (lowSide ? Side::North : Side::South);
          blocked[static_cast<size_t>(q)] |= static_cast<uint8_t>(1u << static_cast<int>(facing));
          seeds.push_back({q, (lowSide == 1) == lowSideInside});
          t = static_cast<double>(vertical ? leaf.y : leaf.x) + static_cast<double>(tree.edgeLength(leaf));
        }
      }
    }
  }
};

struct Shared {
  bool vertical;  // the shared side lies on a vertical line
  double line, lo, hi;
};

Shared sharedSide(const Quadtree& tree, int32_t q, int32_t n, Side side) {
  const Quadrant& a = tree[q];
  const Quadrant& b = tree[n];
  const double sa = static_cast<double>(tree.edgeLength(a)), sb = static_cast<double>(tree.edgeLength(b));
  const double ax = static_cast<double>(a.x), ay = static_cast<double>(a.y);
  const double bx = static_cast<double>(b.x), by = static_cast<double>(b.y);
  if (side == Side::West || side == Side::East)
    return {true, side == Side::West ? ax : ax + sa, std::max(ay, by), std::min(ay + sa, by + sb)};
  return {false, side == Side::South ? ay : ay + sa, std::max(ax, bx), std::min(ax + sa, bx + sb)};
}

}  // namespace

bool rayCastInside(const QuadtreeInput& input, Vec2 p) {
  bool inside = false;
  for (uint32_t e = 0; e < input.edges.size(); ++e) {
    if (!input.active(e)) continue;
    const Vec2 a = input.vertices[input.edges[e][0]], b = input.vertices[input.edges[e][1]];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

QuadStatus castFromCentre(const Quadtree& tree, int32_t q) {
  const Quadrant& quad = tree[q];
  const double half = static_cast<double>(tree.edgeLength(quad)) / 2;
  return rayCastInside(tree.input, {quad.x + half, quad.y + half}) ? QuadStatus::Inside : QuadStatus::Outside;
}

size_t classifyLeaves(Quadtree& tree) {
  const std::vector<int32_t> leaves = tree.leaves();
  std::vector<uint8_t> blocked(tree.quadrants.size(), 0);  // per leaf: sides an edge lies along
  std::vector<std::pair<int32_t, bool>> seeds;
  SideLyingEdges(tree, blocked, seeds);
  std::vector<int32_t> fill, across;
  auto set = [&](int32_t n, bool inside) {
    if (tree[n].status != QuadStatus::Undefined) return;
    tree.quadrants[static_cast<size_t>(n)].status = inside ? QuadStatus::Inside : QuadStatus::Outside;
    fill.push_back(n);
  };
  auto isBlocked = [&](int32_t q, Side side) { return (blocked[static_cast<size_t>(q)] >> static_cast<int>(side)) & 1; };
  for (const auto& [q, inside] : seeds) set(q, inside);

  // Seeds from boundary leaves: each judges its edge-free neighbours with its own edges, at the
  // point of the shared side farthest from their lines.
  for (int32_t q : leaves) {
    if (tree[q].status != QuadStatus::Boundary) continue;
    for (Side side : kSides) {
      if (isBlocked(q, side)) continue;
      across.clear();
      tree.neighbors(q, side, across);
      for (int32_t n : across) {
        if (tree[n].status != QuadStatus::Undefined) continue;
        const Shared shared = sharedSide(tree, q, n, side);
        Vec2 best{0};
        double bestClearance = -1;
        for (double t : {0.25, 0.5, 0.75}) {
          const double along = shared.lo + t * (shared.hi - shared.lo);
          const Vec2 p = shared.vertical ? Vec2{shared.line, along} : Vec2{along, shared.line};
          double clearance = INFINITY;
          const Quadrant& leaf = tree[q];
          for (uint8_t k = 0; k < leaf.edgeCount; ++k) {
            const Vec2 a = tree.input.vertices[tree.input.edges[leaf.edges[k]][0]];
            const Vec2 b = tree.input.vertices[tree.input.edges[leaf.edges[k]][1]];
            clearance = std::min(clearance, std::abs(orient2(a, b, p)) / std::max(1e-300, std::hypot(b.x - a.x, b.y - a.y)));
          }
          if (clearance > bestClearance) bestClearance = clearance, best = p;
        }
        set(n, tree.insideAt(q, best));
      }
    }
  }

  // Flood fill through leaves without edges, stopped where an edge lies along a side.
  while (!fill.empty()) {
    const int32_t q = fill.back();
    fill.pop_back();
    const bool inside = tree[q].status == QuadStatus::Inside;
    for (Side side : kSides) {
      if (isBlocked(q, side)) continue;
      across.clear();
      tree.neighbors(q, side, across);
      for (int32_t n : across)
        if (tree[n].status == QuadStatus::Undefined) set(n, inside);
    }
  }

  // Whatever the fill did not reach is tested directly (a side only partly along an edge is
  // blocked whole, which can leave a leaf unreached).
  size_t cast = 0;
  for (int32_t q : leaves) {
    if (tree[q].status != QuadStatus::Undefined) continue;
    tree.quadrants[static_cast<size_t>(q)].status = castFromCentre(tree, q);
    ++cast;
  }
  return cast;
}

}  // namespace mesher
