#include "mesher/classify.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace mesher {

namespace {

constexpr Side kSides[] = {Side::West, Side::East, Side::South, Side::North};

// Input edges lying on a vertical or horizontal grid line, where leaf sides lie.
struct LineEdge {
  double lo, hi;        // extent along the line
  bool insideIsHigher;  // the polygon's inside is on the side of larger coordinate across the line
};
struct SideLyingEdges {
  std::map<double, std::vector<LineEdge>> vertical, horizontal;  // by x, by y

  explicit SideLyingEdges(const QuadtreeInput& in) {
    for (const auto& [i, j] : in.edges) {
      const Vec2 a = in.vertices[i], b = in.vertices[j];
      if (a.x == b.x && a.x == std::round(a.x))  // inside is left of a->b: west when going up
        vertical[a.x].push_back({std::min(a.y, b.y), std::max(a.y, b.y), b.y < a.y});
      else if (a.y == b.y && a.y == std::round(a.y))  // inside north when going east
        horizontal[a.y].push_back({std::min(a.x, b.x), std::max(a.x, b.x), b.x > a.x});
    }
  }

  // The edge lying along [lo, hi] of the given line, if any.
  const LineEdge* along(bool verticalLine, double line, double lo, double hi) const {
    const auto& lines = verticalLine ? vertical : horizontal;
    const auto found = lines.find(line);
    if (found == lines.end()) return nullptr;
    for (const LineEdge& e : found->second)
      if (std::min(e.hi, hi) > std::max(e.lo, lo)) return &e;
    return nullptr;
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
  if (side == Side::West || side == Side::East) {
    const double line = side == Side::West ? static_cast<double>(a.x) : a.x + sa;
    return {true, line, std::max<double>(static_cast<double>(a.y), static_cast<double>(b.y)), std::min(a.y + sa, b.y + sb)};
  }
  const double line = side == Side::South ? static_cast<double>(a.y) : a.y + sa;
  return {false, line, std::max<double>(static_cast<double>(a.x), static_cast<double>(b.x)), std::min(a.x + sa, b.x + sb)};
}

bool rayCastInside(const QuadtreeInput& input, Vec2 p) {
  bool inside = false;
  for (const auto& [i, j] : input.edges) {
    const Vec2 a = input.vertices[i], b = input.vertices[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

}  // namespace

size_t classifyLeaves(Quadtree& tree) {
  const SideLyingEdges lying(tree.input);
  std::vector<int32_t> fill;
  std::vector<int32_t> across;
  auto set = [&](int32_t n, bool inside) {
    if (tree[n].status != QuadStatus::Undefined) return;
    tree.quadrants[static_cast<size_t>(n)].status = inside ? QuadStatus::Inside : QuadStatus::Outside;
    fill.push_back(n);
  };
  // Which side of a side-lying edge leaf q is on: across `side` of q lies the edge.
  auto insideBeside = [](const LineEdge& e, Side side) {
    const bool edgeIsHigher = side == Side::East || side == Side::North;
    return e.insideIsHigher != edgeIsHigher;
  };

  // Seeds from boundary leaves and from edges lying along leaf sides.
  const std::vector<int32_t> leaves = tree.leaves();
  for (int32_t q : leaves) {
    const bool boundary = tree[q].status == QuadStatus::Boundary;
    for (Side side : kSides) {
      across.clear();
      tree.neighbors(q, side, across);
      for (int32_t n : across) {
        if (tree[n].status != QuadStatus::Undefined) continue;
        const Shared shared = sharedSide(tree, q, n, side);
        if (const LineEdge* e = lying.along(shared.vertical, shared.line, shared.lo, shared.hi)) {
          // The neighbour is across the edge from q: on the other side of it.
          const Side back = side == Side::West ? Side::East : side == Side::East ? Side::West
                            : side == Side::South ? Side::North : Side::South;
          set(n, insideBeside(*e, back));
          continue;
        }
        if (!boundary) continue;
        // Judge at the point of the shared side farthest from the leaf's edges' lines.
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

  // Flood fill through leaves without edges, stopped by side-lying edges.
  while (!fill.empty()) {
    const int32_t q = fill.back();
    fill.pop_back();
    const bool inside = tree[q].status == QuadStatus::Inside;
    for (Side side : kSides) {
      across.clear();
      tree.neighbors(q, side, across);
      for (int32_t n : across) {
        if (tree[n].status != QuadStatus::Undefined) continue;
        const Shared shared = sharedSide(tree, q, n, side);
        if (lying.along(shared.vertical, shared.line, shared.lo, shared.hi)) continue;
        set(n, inside);
      }
    }
  }

  // Whatever the fill did not reach (no boundary anywhere near it) is tested directly.
  size_t cast = 0;
  for (int32_t q : leaves) {
    if (tree[q].status != QuadStatus::Undefined) continue;
    const Quadrant& leaf = tree[q];
    const double half = static_cast<double>(tree.edgeLength(leaf)) / 2;
    tree.quadrants[static_cast<size_t>(q)].status =
        rayCastInside(tree.input, {leaf.x + half, leaf.y + half}) ? QuadStatus::Inside : QuadStatus::Outside;
    ++cast;
  }
  return cast;
}

}  // namespace mesher
