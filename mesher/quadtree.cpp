#include "mesher/quadtree.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mesher {

namespace {

bool inClosedSquare(Vec2 p, double x0, double y0, double x1, double y1) {
  return x0 <= p.x && p.x <= x1 && y0 <= p.y && p.y <= y1;
}

class TreeBuilder {
 public:
  TreeBuilder(Quadtree& tree) : tree_(tree) {}

  // False when a leaf at the deepest level would still break a rule.
  bool subdivideUniformly(int32_t q, int depth) {
    if (tree_.quadrants[static_cast<size_t>(q)].level >= depth) return true;
    split(q);
    const int32_t first = tree_.quadrants[static_cast<size_t>(q)].firstChild;
    for (int32_t c = 0; c < 4; ++c)
      if (!subdivideUniformly(first + c, depth)) return false;
    return true;
  }

  bool insertVertex(uint32_t v) {
    std::vector<int32_t> stack{0};
    while (!stack.empty()) {
      const int32_t q = stack.back();
      stack.pop_back();
      if (!touches(q, tree_.input.vertices[v])) continue;
      Quadrant& quad = tree_.quadrants[static_cast<size_t>(q)];
      if (!quad.isLeaf()) {
        for (int32_t c = 0; c < 4; ++c) stack.push_back(quad.firstChild + c);
        continue;
      }
      if (quad.vertex < 0) {
        quad.vertex = static_cast<int32_t>(v);
        continue;
      }
      if (tree_.input.vertices[static_cast<size_t>(quad.vertex)] == tree_.input.vertices[v]) return false;
      if (!splitLeaf(q)) return false;  // the children take the old vertex; retry the new one
      stack.push_back(q);
    }
    return true;
  }

  bool insertEdge(uint32_t e) { return insertEdgeBelow(0, e); }

 private:
  Vec2 lower(const Quadrant& q) const { return {static_cast<double>(q.x), static_cast<double>(q.y)}; }

  bool touches(int32_t q, Vec2 p) const {
    const Quadrant& quad = tree_.quadrants[static_cast<size_t>(q)];
    const double s = static_cast<double>(tree_.edgeLength(quad));
    return inClosedSquare(p, static_cast<double>(quad.x), static_cast<double>(quad.y), quad.x + s, quad.y + s);
  }

  bool crosses(int32_t q, uint32_t e) const {
    const Quadrant& quad = tree_.quadrants[static_cast<size_t>(q)];
    const double s = static_cast<double>(tree_.edgeLength(quad));
    const auto& [a, b] = tree_.input.edges[e];
    return segmentCrossesOpenSquare(tree_.input.vertices[a], tree_.input.vertices[b], static_cast<double>(quad.x),
                                    static_cast<double>(quad.y), quad.x + s, quad.y + s);
  }

  // The rules of 5.2 for adding edge e to a leaf.
  bool accepts(const Quadrant& quad, uint32_t e) const {
    const auto& ends = tree_.input.edges[e];
    if (quad.vertex >= 0) {
      // Only edges ending at the leaf's vertex, and by position: another vertex at the same
      // point would be a duplicate, which insertVertex refuses.
      const Vec2 v = tree_.input.vertices[static_cast<size_t>(quad.vertex)];
      return (tree_.input.vertices[ends[0]] == v || tree_.input.vertices[ends[1]] == v) && quad.edgeCount < 2;
    }
    // Without a vertex: one edge; and an edge must not end inside the square without the
    // square holding that end (insertVertex put every end in place first).
    return quad.edgeCount == 0;
  }

  void split(int32_t q) {
    const auto first = static_cast<int32_t>(tree_.quadrants.size());
    const Quadrant parent = tree_.quadrants[static_cast<size_t>(q)];
    const int64_t half = tree_.edgeLength(parent) / 2;
    for (int c = 0; c < 4; ++c) {
      Quadrant child;
      child.x = parent.x + (c & 1 ? half : 0);
      child.y = parent.y + (c & 2 ? half : 0);
      child.level = parent.level + 1;
      child.parent = q;
      tree_.quadrants.push_back(child);
    }
    Quadrant& node = tree_.quadrants[static_cast<size_t>(q)];
    node.firstChild = first;
    node.status = QuadStatus::Node;
  }

  // Splits a leaf and hands its vertex and edges to the children, splitting further wherever a
  // child breaks a rule. False at the deepest level.
  bool splitLeaf(int32_t q) {
    if (tree_.quadrants[static_cast<size_t>(q)].level >= tree_.maxDepth) return false;
    const Quadrant old = tree_.quadrants[static_cast<size_t>(q)];
    split(q);
    Quadrant& node = tree_.quadrants[static_cast<size_t>(q)];
    node.vertex = -1;
    node.edgeCount = 0;
    const int32_t first = node.firstChild;
    for (int32_t c = first; c < first + 4; ++c) {
      if (old.vertex >= 0 && touches(c, tree_.input.vertices[static_cast<size_t>(old.vertex)]))
        tree_.quadrants[static_cast<size_t>(c)].vertex = old.vertex;
      for (uint8_t i = 0; i < old.edgeCount; ++i)
        if (!insertEdgeBelow(c, old.edges[i])) return false;
    }
    return true;
  }

  // Stores edge e in the leaves below quadrant q that it passes through, splitting leaves whose
  // rules it would break.
  bool insertEdgeBelow(int32_t q, uint32_t e) {
    std::vector<int32_t> stack{q};
    while (!stack.empty()) {
      const int32_t r = stack.back();
      stack.pop_back();
      if (!crosses(r, e)) continue;
      Quadrant& quad = tree_.quadrants[static_cast<size_t>(r)];
      if (!quad.isLeaf()) {
        for (int32_t c = 0; c < 4; ++c) stack.push_back(quad.firstChild + c);
        continue;
      }
      if (accepts(quad, e)) {
        quad.edges[quad.edgeCount++] = e;
        continue;
      }
      if (!splitLeaf(r)) return false;
      stack.push_back(r);
    }
    return true;
  }

  Quadtree& tree_;
};

// Even-odd test against every input edge: only for leaves no edge passes through, so the
// centre never lies on an edge.
bool insidePolygon(const QuadtreeInput& input, Vec2 p) {
  bool inside = false;
  for (const auto& [i, j] : input.edges) {
    const Vec2 a = input.vertices[i], b = input.vertices[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

}  // namespace

bool segmentCrossesOpenSquare(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1) {
  // Liang-Barsky: the part of the segment within the closed square is [t0, t1].
  double t0 = 0, t1 = 1;
  const Vec2 d = b - a;
  auto clip = [&](double p, double q) {  // keeps t with p * t <= q
    if (p == 0) return q >= 0;
    const double r = q / p;
    if (p < 0) {
      if (r > t1) return false;
      t0 = std::max(t0, r);
    } else {
      if (r < t0) return false;
      t1 = std::min(t1, r);
    }
    return true;
  };
  if (!clip(-d.x, a.x - x0) || !clip(d.x, x1 - a.x) || !clip(-d.y, a.y - y0) || !clip(d.y, y1 - a.y)) return false;
  // A chord of a square either lies in its border or runs through its inside: test its middle.
  const Vec2 m = a + d * (0.5 * (t0 + t1));
  return t0 <= t1 && x0 < m.x && m.x < x1 && y0 < m.y && m.y < y1;
}

std::vector<int32_t> Quadtree::leaves() const {
  std::vector<int32_t> out;
  std::vector<int32_t> stack{0};
  while (!stack.empty()) {
    const int32_t q = stack.back();
    stack.pop_back();
    const Quadrant& quad = quadrants[static_cast<size_t>(q)];
    if (quad.isLeaf()) {
      out.push_back(q);
      continue;
    }
    for (int32_t c = 3; c >= 0; --c) stack.push_back(quad.firstChild + c);
  }
  return out;
}

int32_t Quadtree::leafAt(Vec2 p) const {
  const double root = std::exp2(maxDepth);
  if (!(p.x >= 0 && p.y >= 0 && p.x < root && p.y < root)) return -1;
  int32_t q = 0;
  while (!quadrants[static_cast<size_t>(q)].isLeaf()) {
    const Quadrant& quad = quadrants[static_cast<size_t>(q)];
    const double half = static_cast<double>(edgeLength(quad) / 2);
    const int c = (p.x >= quad.x + half ? 1 : 0) + (p.y >= quad.y + half ? 2 : 0);
    q = quad.firstChild + c;
  }
  return q;
}

QuadtreeInput quadtreeInput(const PolygonWithHoles& polygon, const TreeFrame& frame) {
  QuadtreeInput input;
  auto addRing = [&](const Ring2& ring, bool counterClockwise) {
    const auto first = static_cast<uint32_t>(input.vertices.size());
    // Rounding in the turn and scale can put an extreme point a hair outside the root square,
    // where no leaf could hold it: clamp onto the border.
    const double root = std::exp2(frame.maxDepth);
    for (const Vec2& p : ring) input.vertices.push_back(glm::clamp(frame.toTree(p), Vec2{0}, Vec2{root}));
    const bool reverse = (signedArea(ring) > 0) != counterClockwise;
    const auto n = static_cast<uint32_t>(ring.size());
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = first + i, b = first + (i + 1) % n;
      input.edges.push_back(reverse ? std::array{b, a} : std::array{a, b});
    }
  };
  addRing(polygon.outer, true);
  for (const Ring2& hole : polygon.holes) addRing(hole, false);
  return input;
}

std::optional<Quadtree> buildQuadtree(QuadtreeInput input, int maxDepth, int depth) {
  Quadtree tree;
  tree.maxDepth = maxDepth;
  tree.input = std::move(input);
  tree.quadrants.reserve(size_t{4} << (2 * std::min(depth, 10)));
  tree.quadrants.push_back(Quadrant{});

  // Phases: the uniform tree of the patch size, then vertices, then edges (5.2).
  TreeBuilder builder(tree);
  if (!builder.subdivideUniformly(0, depth)) return std::nullopt;
  for (uint32_t v = 0; v < tree.input.vertices.size(); ++v)
    if (!builder.insertVertex(v)) return std::nullopt;
  for (uint32_t e = 0; e < tree.input.edges.size(); ++e)
    if (!builder.insertEdge(e)) return std::nullopt;

  // Classification: leaves holding edges are boundary, the others lie wholly on one side.
  for (Quadrant& q : tree.quadrants) {
    if (!q.isLeaf()) continue;
    if (q.edgeCount > 0) {
      q.status = QuadStatus::Boundary;
      continue;
    }
    const double half = static_cast<double>(tree.edgeLength(q)) / 2;
    q.status = insidePolygon(tree.input, {q.x + half, q.y + half}) ? QuadStatus::Inside : QuadStatus::Outside;
  }
  return tree;
}

PolygonTree buildPolygonTree(const PolygonWithHoles& polygon, double patchSize) {
  constexpr int kDeepest = 50;  // quadrant corners stay exact doubles
  const double longerExtent = 1 / setupTreeFrame(polygon, 0).scale;  // a root of edge 1
  const int depth = initialDepth(longerExtent, patchSize, kDeepest);
  for (int maxDepth = std::min(kDeepest, depth + 16);; maxDepth = std::min(kDeepest, maxDepth + 8)) {
    PolygonTree result{setupTreeFrame(polygon, maxDepth), depth, {}};
    if (auto tree = buildQuadtree(quadtreeInput(polygon, result.frame), maxDepth, depth)) {
      result.tree = std::move(*tree);
      return result;
    }
    if (maxDepth == kDeepest) throw std::invalid_argument("polygon vertices cannot be separated (repeated or crossing)");
  }
}

}  // namespace mesher
