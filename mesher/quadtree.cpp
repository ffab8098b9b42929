// The PM quadtree of chapter 5. Sections, in order:
//   [storage]       splitting, the 5.2 rules, inserting vertices and edges
//   [sides]         local classification, merging back, forgetting a removed hole's edges
//   [geometry]      segment against square, leaves, neighbours (Samet's parent-chain search)
//   [building]      plane to tree coordinates, numbering the rings, the build recipe
#include "mesher/quadtree.h"

#include "mesher/classify.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

namespace mesher {

namespace {

enum class Visit { Done, Again, Fail };

MeshRefused tooFine() {
  return MeshRefused(MeshRefused::Reason::TooFine, "meshing needs leaves finer than the polygon's coordinates resolve");
}

MeshRefused tooLarge(size_t budget) {
  return MeshRefused(MeshRefused::Reason::TooLarge, "meshing needs more than " + std::to_string(budget) + " quadrants");
}

// The pending quadrants of a depth-first walk, on the walker's own stack frame (walks nest:
// storing an edge splits leaves, which stores edges). A node is pushed as its four children when
// popped, so the stack holds at most three per level of the path plus four.
class QuadrantStack {
 public:
  explicit QuadrantStack(std::initializer_list<int32_t> items) {
    for (int32_t q : items) push(q);
  }
  bool empty() const { return size_ == 0; }
  void push(int32_t q) { items_[size_++] = q; }
  int32_t pop() { return items_[--size_]; }

 private:
  std::array<int32_t, 3 * kDeepestTree + 8> items_;
  size_t size_ = 0;
};

// Visits leaves from quadrant `from` down: `pushMeeting(q, stack)` answers false for a leaf, and
// for a node pushes those of its children (SW to NE) the walk goes on into. `atLeaf` may split
// the leaf and answer Again to have it visited as a node, or Fail to stop; the result is false
// then.
template <typename PushMeeting, typename AtLeaf>
bool walk(int32_t from, PushMeeting pushMeeting, AtLeaf atLeaf) {
  QuadrantStack stack{from};
  while (!stack.empty()) {
    const int32_t q = stack.pop();
    if (pushMeeting(q, stack)) continue;
    const Visit visit = atLeaf(q);
    if (visit == Visit::Fail) return false;
    if (visit == Visit::Again) stack.push(q);
  }
  return true;
}

// walk() asking `meets` of every quadrant on the way down.
template <typename Meets, typename AtLeaf>
bool descend(const Quadtree& tree, int32_t from, Meets meets, AtLeaf atLeaf) {
  if (!meets(from)) return true;
  return walk(from, [&](int32_t q, QuadrantStack& stack) {
    if (tree[q].isLeaf()) return false;
    for (int32_t c = tree[q].firstChild; c < tree[q].firstChild + 4; ++c)
      if (meets(c)) stack.push(c);
    return true;
  }, atLeaf);
}

// descend() to the leaves whose closed square holds p. A node's children that hold p are those on
// its side of each midline (both, on the line): two comparisons instead of each child's square.
template <typename AtLeaf>
bool descendToPoint(const Quadtree& tree, Vec2 p, AtLeaf atLeaf) {
  const auto root = static_cast<double>(tree.edgeLength(tree[0]));
  if (!(0 <= p.x && p.x <= root && 0 <= p.y && p.y <= root)) return true;
  return walk(0, [&](int32_t q, QuadrantStack& stack) {
    const Quadrant& node = tree[q];
    if (node.isLeaf()) return false;
    const auto half = static_cast<double>(tree.edgeLength(node) / 2);
    const double midX = static_cast<double>(node.x) + half, midY = static_cast<double>(node.y) + half;
    const bool west = p.x <= midX, east = p.x >= midX, south = p.y <= midY, north = p.y >= midY;
    for (int c = 0; c < 4; ++c)
      if ((c & 1 ? east : west) && (c & 2 ? north : south)) stack.push(node.firstChild + c);
    return true;
  }, atLeaf);
}

bool inClosedSquare(Vec2 p, double x0, double y0, double x1, double y1) {
  return x0 <= p.x && p.x <= x1 && y0 <= p.y && p.y <= y1;
}

}  // namespace

// [storage]

void Quadtree::addChildren(int32_t q) {
  if (quadrantsMade + 4 > quadrantBudget) throw tooLarge(quadrantBudget);
  quadrantsMade += 4;
  const auto first = static_cast<int32_t>(quadrants.size());
  const Quadrant parent = quadrants[static_cast<size_t>(q)];
  const int64_t half = edgeLength(parent) / 2;
  // Written in place: a child built aside and copied in was stored field by field and read back
  // whole, which stalled on every copy.
  quadrants.resize(quadrants.size() + 4);
  for (int c = 0; c < 4; ++c) {
    Quadrant& child = quadrants[static_cast<size_t>(first + c)];
    child.x = parent.x + (c & 1 ? half : 0);
    child.y = parent.y + (c & 2 ? half : 0);
    child.level = static_cast<uint8_t>(parent.level + 1);
    child.parent = q;
  }
  Quadrant& node = quadrants[static_cast<size_t>(q)];
  node.firstChild = first;
  node.status = QuadStatus::Node;
  node.vertex = -1;
  node.edgeCount = 0;
}

bool Quadtree::holdsPoint(int32_t q, Vec2 p) const {
  const Quadrant& quad = (*this)[q];
  const double s = static_cast<double>(edgeLength(quad));
  return inClosedSquare(p, static_cast<double>(quad.x), static_cast<double>(quad.y), quad.x + s, quad.y + s);
}

bool Quadtree::crossedBy(int32_t q, uint32_t e) const {
  const Quadrant& quad = (*this)[q];
  const double s = static_cast<double>(edgeLength(quad));
  const auto& [a, b] = input.edges[e];
  return segmentCrossesOpenSquare(input.vertices[a], input.vertices[b], static_cast<double>(quad.x),
                                  static_cast<double>(quad.y), quad.x + s, quad.y + s);
}

// The rules of 5.2 for adding edge e to a leaf: with a vertex, only (at most two) edges ending
// at it; without one, a single edge. (Every end of an edge that lies in the closed square is
// the leaf's vertex: vertices go in first.)
bool Quadtree::accepts(const Quadrant& leaf, uint32_t e) const {
  if (leaf.level < uniformDepth) return false;
  if (leaf.vertex < 0) return leaf.edgeCount == 0;
  const auto v = static_cast<uint32_t>(leaf.vertex);
  return (input.edgeInto[v] == e || input.edgeOutOf[v] == e) && leaf.edgeCount < 2;
}

bool Quadtree::insertVertex(uint32_t v) {
  const Vec2 p = input.vertices[v];
  return descendToPoint(*this, p, [&](int32_t q) {
    Quadrant& quad = quadrants[static_cast<size_t>(q)];
    const bool edgesEndHere = std::all_of(quad.edges.begin(), quad.edges.begin() + quad.edgeCount, [&](uint32_t e) {
      return input.edges[e][0] == v || input.edges[e][1] == v;
    });
    if (quad.vertex < 0 && edgesEndHere && quad.level >= uniformDepth) {
      quad.vertex = static_cast<int32_t>(v);
      return Visit::Done;
    }
    if (quad.vertex >= 0 && input.vertices[static_cast<size_t>(quad.vertex)] == p) return Visit::Fail;  // repeated
    return splitLeaf(q) ? Visit::Again : Visit::Fail;  // the children take the old content
  });
}

bool Quadtree::insertEdge(int32_t below, uint32_t e) {
  return descend(*this, below, [&](int32_t q) { return crossedBy(q, e); }, [&](int32_t q) {
    Quadrant& quad = quadrants[static_cast<size_t>(q)];
    if (accepts(quad, e)) {
      quad.edges[quad.edgeCount++] = e;
      quad.status = QuadStatus::Boundary;
      return Visit::Done;
    }
    return splitLeaf(q) ? Visit::Again : Visit::Fail;
  });
}

bool Quadtree::splitLeaf(int32_t q) {
  if ((*this)[q].level >= finestLevel) return false;
  const Quadrant old = (*this)[q];
  addChildren(q);
  if (complete) changes.push_back({q, old});
  else if (old.level >= uniformDepth) storageSplits.push_back(q);
  const int32_t first = (*this)[q].firstChild;
  if (!complete && old.level < uniformDepth) {
    // Coarser than the patch size it held nothing; a few edges' children take their side now.
    if (input.edges.size() <= kFewEdges)
      for (int32_t c = first; c < first + 4; ++c) quadrants[static_cast<size_t>(c)].status = old.status == QuadStatus::Undefined ? sideWhileBuilding(c) : old.status;
    return true;
  }
  for (int32_t c = first; c < first + 4; ++c) {
    if (old.vertex >= 0 && holdsPoint(c, input.vertices[static_cast<size_t>(old.vertex)]))
      quadrants[static_cast<size_t>(c)].vertex = old.vertex;
    for (uint8_t i = 0; i < old.edgeCount; ++i)
      if (!insertEdge(c, old.edges[i])) return false;
  }
  // New leaves without edges take their side from the old leaf's vertex and edges, or its status;
  // while the tree is being built, more edges may still arrive, so they wait for the end.
  if (!complete) return true;
  QuadrantStack stack{first, first + 1, first + 2, first + 3};
  while (!stack.empty()) {
    const int32_t c = stack.pop();
    const Quadrant& child = (*this)[c];
    if (!child.isLeaf()) {
      for (int32_t k = 0; k < 4; ++k) stack.push(child.firstChild + k);
    } else if (child.edgeCount == 0) {
      const double half = static_cast<double>(edgeLength(child)) / 2;
      const bool inside = old.edgeCount == 0 ? old.status == QuadStatus::Inside
                                             : insideOf(old, {child.x + half, child.y + half});
      quadrants[static_cast<size_t>(c)].status = inside ? QuadStatus::Inside : QuadStatus::Outside;
    }
  }
  return true;
}

// [sides]

bool Quadtree::insideOf(const Quadrant& leaf, Vec2 p) const {
  if (leaf.vertex >= 0) {
    // The wedge left of the vertex's two edges: both sides for a convex corner, either for a
    // reflex one. They are the only edges near p.
    const auto v = static_cast<uint32_t>(leaf.vertex);
    const Vec2 a = input.vertices[input.edges[input.edgeInto[v]][0]];
    const Vec2 corner = input.vertices[v];
    const Vec2 b = input.vertices[input.edges[input.edgeOutOf[v]][1]];
    const bool leftOfIn = orient2(a, corner, p) > 0, leftOfOut = orient2(corner, b, p) > 0;
    return orient2(a, corner, b) > 0 ? leftOfIn && leftOfOut : leftOfIn || leftOfOut;
  }
  if (leaf.edgeCount > 0) {
    const auto& [i, j] = input.edges[leaf.edges[0]];
    return orient2(input.vertices[i], input.vertices[j], p) > 0;
  }
  return leaf.status == QuadStatus::Inside;
}

bool Quadtree::crossedByAnyEdge(int32_t q) const {
  for (uint32_t e = 0; e < input.edges.size(); ++e)
    if (input.active(e) && crossedBy(q, e)) return true;
  return false;
}

QuadStatus Quadtree::sideWhileBuilding(int32_t q) const {
  return (*this)[q].level < uniformDepth && crossedByAnyEdge(q) ? QuadStatus::Undefined : castFromCentre(*this, q);
}

void Quadtree::edgesThrough(int32_t q, std::vector<uint32_t>& out) const {
  for (uint32_t e = 0; e < input.edges.size(); ++e)
    if (input.active(e) && crossedBy(q, e)) out.push_back(e);
}

void Quadtree::leavesIn(Vec2 lo, Vec2 hi, std::vector<int32_t>& out) const {
  const auto meets = [&](int32_t q) {
    const Quadrant& quad = (*this)[q];
    const double s = static_cast<double>(edgeLength(quad));
    return !(quad.x > hi.x || quad.y > hi.y || quad.x + s < lo.x || quad.y + s < lo.y);
  };
  descend(*this, 0, meets, [&](int32_t q) {
    out.push_back(q);
    return Visit::Done;
  });
}

void Quadtree::leavesStoring(uint32_t e, std::vector<int32_t>& out) const {
  descend(*this, 0, [&](int32_t q) { return crossedBy(q, e); }, [&](int32_t q) {
    const Quadrant& leaf = (*this)[q];
    if (std::find(leaf.edges.begin(), leaf.edges.begin() + leaf.edgeCount, e) != leaf.edges.begin() + leaf.edgeCount) out.push_back(q);
    return Visit::Done;
  });
}

void Quadtree::forgetEdge(uint32_t e) {
  descend(*this, 0, [&](int32_t q) { return crossedBy(q, e); }, [&](int32_t q) {
    Quadrant& quad = quadrants[static_cast<size_t>(q)];
    auto* end = std::remove(quad.edges.begin(), quad.edges.begin() + quad.edgeCount, e);
    quad.edgeCount = static_cast<uint8_t>(end - quad.edges.begin());
    return Visit::Done;
  });
  if (input.removed.size() < input.edges.size()) input.removed.resize(input.edges.size(), 0);
  input.removed[e] = 1;
}

void Quadtree::forgetVertex(uint32_t v) {
  descendToPoint(*this, input.vertices[v], [&](int32_t q) {
    if (quadrants[static_cast<size_t>(q)].vertex == static_cast<int32_t>(v)) quadrants[static_cast<size_t>(q)].vertex = -1;
    return Visit::Done;
  });
}

bool Quadtree::canMerge(int32_t q) const {
  const Quadrant& node = (*this)[q];
  if (node.isLeaf() || node.level < uniformDepth) return false;
  int32_t vertex = -1;
  bool outside = true;
  for (int32_t c = node.firstChild; c < node.firstChild + 4; ++c) {
    const Quadrant& child = (*this)[c];
    if (!child.isLeaf()) return false;
    outside = outside && child.status == QuadStatus::Outside;
    if (child.vertex < 0) continue;
    if (vertex >= 0 && input.vertices[static_cast<size_t>(vertex)] != input.vertices[static_cast<size_t>(child.vertex)]) return false;
    vertex = child.vertex;
  }
  // The rules of 5.2 for the merged square.
  std::vector<uint32_t> edges;
  edgesThrough(q, edges);
  if (vertex < 0 && edges.size() > 1) return false;
  if (vertex >= 0) {
    const auto v = static_cast<uint32_t>(vertex);
    if (edges.size() > 2) return false;
    for (uint32_t e : edges)
      if (e != input.edgeInto[v] && e != input.edgeOutOf[v]) return false;
  }
  // 2:1 balance with the neighbours that take part in it.
  if (outside) return true;
  std::vector<int32_t> across;
  for (Side side : {Side::West, Side::East, Side::South, Side::North}) {
    across.clear();
    neighbors(q, side, across);
    for (int32_t n : across)
      if ((*this)[n].status != QuadStatus::Outside && (*this)[n].level > node.level + 1) return false;
  }
  return true;
}

void Quadtree::undoChanges(size_t keep) {
  // The children of the splits taken back are the last quadrants made (the first of those splits
  // made its children at the end of the array, the others after them): their room is reused.
  size_t made = quadrants.size();
  while (changes.size() > keep) {
    const Change& change = changes.back();
    Quadrant& quadrant = quadrants[static_cast<size_t>(change.quadrant)];
    if (!change.isMerge()) made = std::min(made, static_cast<size_t>(quadrant.firstChild));
    quadrant = change.before;
    changes.pop_back();
  }
  quadrants.resize(made);
}

void Quadtree::merge(int32_t q) {
  const Quadrant before = (*this)[q];
  const int32_t first = before.firstChild;
  int32_t vertex = -1;
  for (int32_t c = first; c < first + 4; ++c)
    if ((*this)[c].vertex >= 0) vertex = (*this)[c].vertex;
  std::vector<uint32_t> edges;
  edgesThrough(q, edges);
  const QuadStatus childStatus = (*this)[first].status;
  Quadrant& node = quadrants[static_cast<size_t>(q)];
  node.firstChild = -1;
  node.forced = false;
  node.vertex = vertex;
  node.edgeCount = static_cast<uint8_t>(edges.size());
  std::copy(edges.begin(), edges.end(), node.edges.begin());
  // Without edges through it the square lies wholly on one side, as each child did.
  node.status = edges.empty() ? childStatus : QuadStatus::Boundary;
  changes.push_back({q, before});
}

bool Quadtree::insideAt(int32_t q, Vec2 p) const {
  const Quadrant& leaf = (*this)[q];
  if (leaf.edgeCount == 0 && leaf.vertex < 0) return leaf.status == QuadStatus::Inside;
  return insideOf(leaf, p);
}

// [geometry]

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

bool Quadtree::madeBefore(int32_t a, int32_t b) const {
  const Quadrant &qa = (*this)[a], &qb = (*this)[b];
  const bool coarseA = qa.level <= uniformDepth, coarseB = qb.level <= uniformDepth;
  if (coarseA != coarseB) return coarseA;
  if (!coarseA) return a < b;
  return qa.level != qb.level ? qa.level < qb.level : comesBefore(qa, qb);
}

std::vector<int32_t> Quadtree::leaves() const {
  std::vector<int32_t> out;
  leaves(out);
  return out;
}

void Quadtree::leaves(std::vector<int32_t>& out) const {
  out.clear();
  out.reserve(quadrants.size() * 3 / 4 + 1);
  QuadrantStack stack{0};
  while (!stack.empty()) {
    const int32_t q = stack.pop();
    const Quadrant& quad = quadrants[static_cast<size_t>(q)];
    if (quad.isLeaf()) {
      out.push_back(q);
      continue;
    }
    for (int32_t c = 3; c >= 0; --c) stack.push(quad.firstChild + c);
  }
}

void Quadtree::vertexLeaves(std::vector<int32_t>& out) const {
  // From each vertex down to the leaves holding it, instead of a walk through every leaf.
  out.clear();
  for (const Vec2& p : input.vertices)
    descendToPoint(*this, p, [&](int32_t q) {
      if ((*this)[q].vertex >= 0) out.push_back(q);
      return Visit::Done;
    });
  std::sort(out.begin(), out.end(), [&](int32_t a, int32_t b) { return comesBefore((*this)[a], (*this)[b]); });
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void Quadtree::leavesBelow(int32_t q, std::vector<int32_t>& out) const {
  const Quadrant& quad = quadrants[static_cast<size_t>(q)];
  if (quad.isLeaf()) {
    out.push_back(q);
    return;
  }
  for (int32_t c = 0; c < 4; ++c) leavesBelow(quad.firstChild + c, out);
}

int32_t Quadtree::leafAt(Vec2 p) const {
  const auto root = static_cast<double>(int64_t{1} << maxDepth);  // exact: maxDepth is at most kDeepestTree
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

int32_t Quadtree::adjacent(int32_t q, Side side) const {
  // Children are numbered SW 0, SE 1, NW 2, NE 3: bit 0 is east, bit 1 north. A sibling across
  // the side is found at once; otherwise the parent's neighbour is, and its mirrored child. Up
  // the parent chain, then down the mirrored children as far as the tree goes.
  const bool horizontal = side == Side::West || side == Side::East;
  const int bit = horizontal ? 1 : 2;
  const bool towardHigh = side == Side::East || side == Side::North;
  std::array<uint8_t, kDeepestTree> climbed;  // the child numbers on the way up
  size_t depth = 0;
  int32_t across = q;
  for (;;) {
    const Quadrant& node = (*this)[across];
    if (node.parent < 0) return -1;
    const int32_t first = (*this)[node.parent].firstChild;
    const int child = across - first;
    if (((child & bit) != 0) != towardHigh) {
      across = first + (child ^ bit);
      break;
    }
    climbed[depth++] = static_cast<uint8_t>(child);
    across = node.parent;
  }
  while (depth > 0 && !(*this)[across].isLeaf()) across = (*this)[across].firstChild + (climbed[--depth] ^ bit);
  return across;
}

void Quadtree::neighbors(int32_t q, Side side, std::vector<int32_t>& out) const { leavesFacing(adjacent(q, side), side, out); }

void Quadtree::leavesFacing(int32_t r, Side side, std::vector<int32_t>& out) const {
  if (r < 0) return;
  // A leaf there is the one neighbour; otherwise its leaves along the facing side, found in
  // `out` itself (no allocation): a node is replaced by its first facing child and the second is
  // appended.
  out.push_back(r);
  if ((*this)[r].isLeaf()) return;  // the usual case, answered before the loop
  static constexpr int32_t facing[4][2] = {{1, 3}, {0, 2}, {2, 3}, {0, 1}};  // SW 0, SE 1, NW 2, NE 3
  const size_t start = out.size() - 1;
  for (size_t i = start; i < out.size();) {
    const Quadrant& node = (*this)[out[i]];
    if (node.isLeaf()) {
      ++i;
      continue;
    }
    out[i] = node.firstChild + facing[static_cast<int>(side)][0];
    out.push_back(node.firstChild + facing[static_cast<int>(side)][1]);
  }
}

// [building]

Vec2 treePoint(const TreeFrame& frame, Vec2 plane) {
  // Rounding in the turn and scale leaves points a hair off the grid lines they belong on (the
  // far side of a rectangle, an extreme point just outside the root square): snap them onto the
  // grid and into the root. Only the tree sees this; output keeps the input coordinates.
  const double root = std::exp2(frame.maxDepth);
  Vec2 t = glm::clamp(frame.toTree(plane), Vec2{0}, Vec2{root});
  for (int k = 0; k < 2; ++k)
    if (std::abs(t[k] - std::round(t[k])) <= frame.gridSnap) t[k] = std::round(t[k]);
  // Plus zero for a zero of either sign (the turn gives -0 beside +0 for alike points), so that
  // repeats of a polygon have the same tree input bit for bit (MeshMemo).
  return t + Vec2{0.0};
}

void quadtreeInput(const PolygonWithHoles& polygon, const TreeFrame& frame, QuadtreeInput& input) {
  input.vertices.clear();
  input.edges.clear();
  input.removed.clear();
  auto addRing = [&](const Ring2& ring, bool counterClockwise) {
    const auto first = static_cast<uint32_t>(input.vertices.size());
    for (const Vec2& p : ring) input.vertices.push_back(treePoint(frame, p));
    const bool reverse = (signedArea(ring) > 0) != counterClockwise;
    const auto n = static_cast<uint32_t>(ring.size());
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = first + i, b = first + (i + 1) % n;
      input.edges.push_back(reverse ? std::array{b, a} : std::array{a, b});
    }
  };
  auto linkEdges = [&] {
    input.edgeInto.assign(input.vertices.size(), 0);
    input.edgeOutOf.assign(input.vertices.size(), 0);
    for (uint32_t e = 0; e < input.edges.size(); ++e) {
      input.edgeOutOf[input.edges[e][0]] = e;
      input.edgeInto[input.edges[e][1]] = e;
    }
  };
  addRing(polygon.outer, true);
  for (const Ring2& hole : polygon.holes) addRing(hole, false);
  linkEdges();
}

namespace {

// The area of the polygon (tree units): outer ring counter-clockwise, holes clockwise.
double inputArea(const QuadtreeInput& input) {
  double twice = 0;
  for (const auto& [a, b] : input.edges) twice += orient2(Vec2{0}, input.vertices[a], input.vertices[b]);
  return twice / 2;
}

// Whether every input vertex lies at least `clearance` (tree units) from every edge that does
// not end at it, found through the tree: the leaves near a vertex store the edges crossing them
// (two at most each), and edges along grid lines, which lie along leaves' sides instead, are
// looked up by their line. Work per vertex is bounded: leaves are no finer than a fraction of the
// clearance (TreeFrame::finestLevel).
bool verticesClearOfEdges(const Quadtree& tree, double clearance) {
  const QuadtreeInput& in = tree.input;
  struct OnLine {
    double line, lo, hi;
    uint32_t edge;
    bool operator<(const OnLine& o) const { return line < o.line || (line == o.line && lo < o.lo); }
  };
  std::array<std::vector<OnLine>, 2> onLines;  // along x = line, along y = line
  for (uint32_t e = 0; e < in.edges.size(); ++e) {
    const Vec2 a = in.vertices[in.edges[e][0]], b = in.vertices[in.edges[e][1]];
    for (int axis = 0; axis < 2; ++axis)  // the axis the line is across
      if (a[axis] == b[axis] && a[axis] == std::round(a[axis]))
        onLines[static_cast<size_t>(axis)].push_back({a[axis], std::min(a[1 - axis], b[1 - axis]), std::max(a[1 - axis], b[1 - axis]), e});
  }
  for (auto& lines : onLines) std::sort(lines.begin(), lines.end());
  std::vector<int32_t> near;
  for (uint32_t v = 0; v < in.vertices.size(); ++v) {
    const Vec2 p = in.vertices[v];
    bool clear = true;
    auto check = [&](uint32_t e) {
      const auto& [i, j] = in.edges[e];
      if (i == v || j == v) return;
      const Vec2 a = in.vertices[i], d = in.vertices[j] - a;
      const double t = std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0);
      clear = clear && glm::length(p - (a + t * d)) >= clearance;
    };
    near.clear();
    tree.leavesIn(p - Vec2{clearance}, p + Vec2{clearance}, near);
    for (int32_t q : near) {
      const Quadrant& leaf = tree[q];
      for (uint8_t k = 0; k < leaf.edgeCount; ++k) check(leaf.edges[k]);
      const double s = static_cast<double>(tree.edgeLength(leaf));
      const Vec2 lo{static_cast<double>(leaf.x), static_cast<double>(leaf.y)};
      for (int axis = 0; axis < 2; ++axis)
        for (const double line : {lo[axis], lo[axis] + s}) {
          const std::vector<OnLine>& lines = onLines[static_cast<size_t>(axis)];
          // Edges on one line do not overlap: those along this side are consecutive.
          auto at = std::partition_point(lines.begin(), lines.end(), [&](const OnLine& o) { return o.line < line || (o.line == line && o.hi < lo[1 - axis]); });
          for (; at != lines.end() && at->line == line && at->lo <= lo[1 - axis] + s; ++at) check(at->edge);
        }
    }
    if (!clear) return false;
  }
  return true;
}

// The last phase of a build: inside leaves coarser than the patch size (no vertex or edge met
// them) split down to it, their quadrants all inside. How many that makes is known first.
void splitInsideToUniformDepth(Quadtree& tree) {
  std::vector<int32_t> coarse;
  tree.leaves(coarse);
  coarse.erase(std::remove_if(coarse.begin(), coarse.end(), [&](int32_t q) {
                 return tree[q].status != QuadStatus::Inside || tree[q].level >= tree.uniformDepth;
               }), coarse.end());
  double toMake = 0;  // 4 + 16 + ... + 4^k for a leaf k levels coarser
  for (int32_t q : coarse) toMake += (std::exp2(2 * (tree.uniformDepth - tree[q].level + 1)) - 4) / 3;
  if (static_cast<double>(tree.quadrantsMade) + toMake > static_cast<double>(tree.quadrantBudget)) throw tooLarge(tree.quadrantBudget);
  tree.quadrants.reserve(tree.quadrants.size() + static_cast<size_t>(toMake));
  for (size_t i = 0; i < coarse.size(); ++i) {
    const int32_t q = coarse[i];
    tree.splitLeaf(q);
    for (int32_t c = tree[q].firstChild; c < tree[q].firstChild + 4; ++c) {
      tree.quadrants[static_cast<size_t>(c)].status = QuadStatus::Inside;
      if (tree[c].level < tree.uniformDepth) coarse.push_back(c);
    }
  }
}

}  // namespace

bool buildQuadtree(Quadtree& tree, int maxDepth, int depth, double gridSnap, int finestLevel) {
  // Deeper trees would lose exact quadrant corners, and overflow the walks' fixed stacks.
  if (maxDepth < 0 || maxDepth > kDeepestTree || depth < 0 || depth > maxDepth)
    throw std::invalid_argument("quadtree depth " + std::to_string(depth) + " of " + std::to_string(maxDepth) +
                                " outside 0.." + std::to_string(kDeepestTree));
  // The polygon's leaves at the patch size cover its area: their quadrants, about a third more,
  // must fit the budget, or the polygon is refused before any is made (also a patch size finer
  // than the coordinates resolve, for which a mesh would be too large first). The boundary's
  // leaves, what a thin polygon needs, are counted as they are made.
  const double cell = std::exp2(maxDepth - depth);
  const double quadrantsForArea = 4.0 / 3 * std::abs(inputArea(tree.input)) / (cell * cell);
  if (static_cast<double>(tree.quadrantsMade) + quadrantsForArea > static_cast<double>(tree.quadrantBudget))
    throw tooLarge(tree.quadrantBudget);
  tree.maxDepth = maxDepth;
  tree.finestLevel = finestLevel < 0 ? maxDepth : std::min(finestLevel, maxDepth);
  if (depth > tree.finestLevel) return false;  // a patch size finer than the coordinates resolve
  tree.gridSnap = gridSnap;
  tree.complete = false;
  tree.changes.clear();
  tree.quadrants.clear();
  tree.quadrants.reserve(static_cast<size_t>(quadrantsForArea) + 64 * tree.input.vertices.size());
  tree.quadrants.push_back(Quadrant{});
  tree.uniformDepth = depth;
  tree.storageSplits.clear();

  // Phases: vertices, then edges, stored from the root (5.2), then the sides of the leaves, then
  // the inside split down to the patch size. A quadrant coarser than the patch size holds
  // nothing: one that a vertex or an edge meets is split. So the tree is uniform to the patch
  // size inside the polygon and along its boundary, and a quadrant wholly outside stays as
  // coarse as it is: a thin polygon's tree does not fill its root square. A polygon of few
  // edges has its leaves classified as they are made (classify.h): a square no edge crosses
  // hands its side down, a leaf crossed below the patch size or split to store casts its own
  // ray (edges stored make it Boundary).
  const bool fewEdges = tree.input.edges.size() <= kFewEdges;
  if (fewEdges) tree.quadrants[0].status = tree.sideWhileBuilding(0);
  for (uint32_t v = 0; v < tree.input.vertices.size(); ++v)
    if (!tree.insertVertex(v)) return false;
  for (uint32_t e = 0; e < tree.input.edges.size(); ++e)
    if (!tree.insertEdge(0, e)) return false;

  // Leaves holding edges are boundary (set as they were stored), the others lie wholly on one side.
  if (fewEdges) {
    for (int32_t q : tree.storageSplits)
      for (int32_t c = tree[q].firstChild; c < tree[q].firstChild + 4; ++c)
        if (tree[c].isLeaf() && tree[c].status == QuadStatus::Undefined) tree.quadrants[static_cast<size_t>(c)].status = castFromCentre(tree, c);
  } else {
    classifyLeaves(tree);
  }
  splitInsideToUniformDepth(tree);
  tree.complete = true;
  return true;
}

PolygonTree buildPolygonTree(const PolygonWithHoles& polygon, double patchSize, int deeper) {
  PolygonTree result;
  buildPolygonTree(polygon, patchSize, result, deeper);
  return result;
}

void buildPolygonTree(const PolygonWithHoles& polygon, double patchSize, PolygonTree& into, int deeper) {
  buildSetUpTree(polygon, setUpPolygonTree(polygon, patchSize, into, deeper), into);
}

int setUpPolygonTree(const PolygonWithHoles& polygon, double patchSize, PolygonTree& into, int deeper) {
  if (deeper == 0) into.tree.quadrantsMade = 0;
  if (!(patchSize > 0)) throw std::invalid_argument("patch size " + std::to_string(patchSize) + " is not above 0");
  const double longerExtent = 1 / setupTreeFrame(polygon, 0).scale;  // a root of edge 1
  const int depth = initialDepth(longerExtent, patchSize, kDeepestTree);
  into.frame = setupTreeFrame(polygon, std::min(kDeepestTree, depth + 16 + deeper));
  if (into.frame.finestLevel() < 0) throw tooFine();
  quadtreeInput(polygon, into.frame, into.tree.input);
  return depth;
}

void buildSetUpTree(const PolygonWithHoles& polygon, int depth, PolygonTree& into) {
  while (!buildQuadtree(into.tree, into.frame.maxDepth, depth, into.frame.gridSnap, std::max(0, into.frame.finestLevel()))) {
    // A deeper tree has finer levels, unless the rounding stopped this one short: it stops a
    // deeper one at the same size.
    if (into.frame.maxDepth == kDeepestTree || into.tree.finestLevel < into.frame.maxDepth)
      throw tooFine();
    into.frame = setupTreeFrame(polygon, std::min(kDeepestTree, into.frame.maxDepth + 8));
    quadtreeInput(polygon, into.frame, into.tree.input);
  }
  if (!verticesClearOfEdges(into.tree, kClearanceOverRounding * into.frame.rounding)) throw tooFine();
}

}  // namespace mesher
