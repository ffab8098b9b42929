// The spatial decomposition of chapter 5: a PM quadtree (Samet and Webber 1985) over a polygon
// with holes, in the integer square of a TreeFrame. Leaves store the input vertices and edges
// under the decomposition rules of section 5.2 and are classified inside, outside or boundary.
#pragma once

#include "mesher/huge_page_allocator.h"
#include "mesher/mesher.h"
#include "mesher/tree_frame.h"
#include "mesher/triangulate.h"

#include <array>
#include <cstdint>
#include <vector>

namespace mesher {


enum class QuadStatus : uint8_t { Node, Undefined, Outside, Boundary, Inside };

// 40 bytes: a million-leaf tree is walked more than once, and its size decides how much of it
// stays in cache.
struct Quadrant {
  int64_t x = 0, y = 0;             // lower-left corner, tree units
  int32_t firstChild = -1;          // children at firstChild + 0..3: SW, SE, NW, NE; -1: a leaf
  int32_t parent = -1;
  int32_t vertex = -1;              // the input vertex in the closed square, if any
  std::array<uint32_t, 2> edges{};  // input edges through the open square
  uint8_t level = 0;                // 0 is the root; its edge is 2^(maxDepth - level)
  uint8_t edgeCount = 0;
  QuadStatus status = QuadStatus::Undefined;
  bool forced = false;              // split only to keep 2:1 balance (may merge back when not needed)

  bool isLeaf() const { return firstChild < 0; }
};
static_assert(sizeof(Quadrant) == 40);

// Edge e runs from vertex edges[e][0] to edges[e][1] with the polygon's inside on its left
// (outer ring counter-clockwise, holes clockwise). Every vertex has one edge in and one out.
struct QuadtreeInput {
  std::vector<Vec2> vertices;                   // tree coordinates, outer ring first, then holes
  std::vector<std::array<uint32_t, 2>> edges;
  std::vector<uint32_t> edgeInto, edgeOutOf;    // per vertex
  std::vector<uint8_t> removed;                 // per edge: its hole has been taken out again
  std::vector<uint8_t> shallow;                 // per edge: meets grid lines at under the angle bound (wedge_handover.h)

  bool active(uint32_t e) const { return e >= removed.size() || !removed[e]; }
};

enum class Side : uint8_t { West, East, South, North };

class Quadtree {
 public:
  int maxDepth = 0;
  int finestLevel = 0;  // no leaf is split finer (TreeFrame::finestLevel): maxDepth, or coarser
  std::vector<Quadrant, HugePageAllocator<Quadrant>> quadrants;  // [0] is the root
  QuadtreeInput input;
  bool complete = false;  // every vertex and edge stored and every leaf classified
  int uniformDepth = 0;   // lambda of 5.2: no leaf is coarser (no merge goes above it)
  // The leaves the build split to store a vertex or an edge (those of the uniform tree and any
  // below them), in the order split: only their children are finer than the uniform tree. As
  // built: later splits and merges leave it as it is.
  std::vector<int32_t> storageSplits;
  double gridSnap = 1e-6;  // the frame's: computed points this close to a grid line lie on it
  // The work limit (MeshSettings::maxQuadrants): making a quadrant past `quadrantBudget` throws
  // MeshRefused. `quadrantsMade` counts every quadrant made since the caller last set it to 0
  // (setUpPolygonTree does for each new polygon), also in trees rebuilt and splits taken back.
  size_t quadrantsMade = 0;
  size_t quadrantBudget = kMaxQuadrants;

  int64_t edgeLength(const Quadrant& q) const { return int64_t{1} << (maxDepth - q.level); }
  const Quadrant& operator[](int32_t q) const { return quadrants[static_cast<size_t>(q)]; }

  // Whether quadrant a comes before quadrant b in the order the refiner visits leaves in, which
  // decides its splits: quadrants no finer than the uniform depth level by level in tree order,
  // then the finer ones in the order they were made (their index).
  bool madeBefore(int32_t a, int32_t b) const;

  // Leaves only, in tree order (into `out`, replacing what it held).
  std::vector<int32_t> leaves() const;
  void leaves(std::vector<int32_t>& out) const;
  // The leaves holding an input vertex (in their closed square), in tree order, into `out`.
  void vertexLeaves(std::vector<int32_t>& out) const;
  // The leaves below quadrant q (q itself when it is a leaf), in tree order, appended to `out`;
  // a split may have gone deeper than one level where a child broke a storage rule.
  void leavesBelow(int32_t q, std::vector<int32_t>& out) const;
  // The leaf whose half-open square [x, x + s) x [y, y + s) holds p; -1 outside the root.
  int32_t leafAt(Vec2 p) const;
  // The leaves sharing part of `side` of leaf q (one coarser or equal leaf, or several finer),
  // appended to `out`.
  void neighbors(int32_t q, Side side, std::vector<int32_t>& out) const;
  // The quadrant across `side` of quadrant q at q's level, or the coarser leaf there; -1 at the
  // root's border. Constant time on average (Samet's neighbour finding).
  int32_t adjacent(int32_t q, Side side) const;
  // The second half of neighbors(q, side, out) once r = adjacent(q, side) is known: r when it is
  // a leaf (or -1: nothing), else its leaves along the side facing q, appended to `out`.
  void leavesFacing(int32_t r, Side side, std::vector<int32_t>& out) const;
  // Calls visit(q, adjacent) for every leaf q in tree order (as leaves() lists them), with
  // adjacent[side] = adjacent(q, side) for West, East, South, North: handed down from parent to
  // children in constant time each, instead of climbing from every leaf.
  template <typename Visit>
  void forEachLeafWithAdjacent(Visit visit) const;
  // Whether an active input edge passes through quadrant q's open square (as stored edges do).
  bool crossedByAnyEdge(int32_t q) const;
  // A new quadrant's side while the tree of a polygon of few edges is built (classify.h):
  // Undefined when an edge crosses it coarser than the patch size (it will be split), else by a
  // ray from its centre.
  QuadStatus sideWhileBuilding(int32_t q) const;
  // Whether point p of leaf q's closed square lies inside the polygon, from the leaf's own
  // vertex and edges (its status when it holds none). p must not lie on a stored edge.
  bool insideAt(int32_t q, Vec2 p) const;

  // Splits leaf q into four, handing its vertex and edges down under the rules of 5.2 (splitting
  // deeper where a child breaks one) and classifying the new leaves. False at the finest level,
  // and when a child would have to go deeper than that: the split is then left part way, its
  // leaves missing edges, for the caller to take back (undoChanges).
  bool splitLeaf(int32_t q);
  // Stores vertex v / edge e in the leaves below quadrant q that hold it, splitting leaves whose
  // rules it would break. False when that needs a level finer than finestLevel.
  bool insertVertex(uint32_t v);
  bool insertEdge(int32_t q, uint32_t e);

  // Whether node q's four children, all leaves, may become one leaf again (5.5): the merged
  // square is no coarser than the patch size, keeps the rules of 5.2, and no neighbour inside or
  // on the boundary would be more than one level finer.
  bool canMerge(int32_t q) const;
  // Makes node q a leaf holding its children's vertex and edges; canMerge(q) must hold. The
  // children's quadrants are left unused.
  void merge(int32_t q);

  // Every quadrant that stopped (split) or started (merge) being a leaf once the tree was
  // complete, in order, since the caller last cleared the list; with the quadrant as it was.
  struct Change {
    int32_t quadrant;
    Quadrant before;
    bool isMerge() const { return !before.isLeaf(); }
  };
  std::vector<Change> changes;
  // Reverts the changes after the first `keep` (a split that ran out of depth part way), and
  // drops the quadrants their splits made.
  void undoChanges(size_t keep);

  // The leaves storing edge e, appended to `out` (work in proportion to the leaves it crosses).
  void leavesStoring(uint32_t e, std::vector<int32_t>& out) const;
  // The leaves whose closed square meets the box [lo, hi].
  void leavesIn(Vec2 lo, Vec2 hi, std::vector<int32_t>& out) const;
  // Takes edge e out of every leaf that stores it, and vertex v (when given) out of every leaf
  // that holds it; marks the edge removed.
  void forgetEdge(uint32_t e);
  void forgetVertex(uint32_t v);

 private:
  void addChildren(int32_t q);
  bool holdsPoint(int32_t q, Vec2 p) const;
  bool crossedBy(int32_t q, uint32_t e) const;
  bool accepts(const Quadrant& leaf, uint32_t e) const;
  bool insideOf(const Quadrant& leaf, Vec2 p) const;
  // The input edges through node q's open square (all of them are checked: a merge is rare).
  void edgesThrough(int32_t q, std::vector<uint32_t>& out) const;
};

// Whether leaf a comes before leaf b in tree order: the Morton order of their lower-left
// corners, y above x at each level as the children SW, SE, NW, NE are numbered.
inline bool comesBefore(const Quadrant& a, const Quadrant& b) {
  const auto dx = static_cast<uint64_t>(a.x ^ b.x), dy = static_cast<uint64_t>(a.y ^ b.y);
  const bool xDecides = dy < dx && dy < (dy ^ dx);  // the highest differing bit is x's
  return xDecides ? a.x < b.x : a.y < b.y;
}

// A plane point in tree coordinates: within the root square, snapped onto grid lines it lies
// within frame.gridSnap of.
Vec2 treePoint(const TreeFrame& frame, Vec2 plane);

// Orients and numbers the polygon's rings into quadtree input (tree coordinates via `frame`) in
// `into`, reusing its memory.
void quadtreeInput(const PolygonWithHoles& polygon, const TreeFrame& frame, QuadtreeInput& into);

// Stores every vertex and edge of `tree.input` under the rules of 5.2, reusing the tree's memory:
// a leaf holds at most one distinct vertex (in its closed square); with a vertex, only edges
// ending at it; without one, at most one edge. No leaf inside the polygon or on its boundary is
// coarser than `depth`; leaves wholly outside may be. Leaves holding edges are Boundary; every
// other leaf is Inside or Outside by its centre. Returns false when two vertices cannot be
// separated within maxDepth levels, or within `finestLevel` (when given, and finer than the
// uniform depth), as TreeFrame::finestLevel says (the caller builds a deeper tree, or gives up:
// vertices are never merged). Throws std::invalid_argument for a maxDepth above kDeepestTree (or
// depth outside 0..maxDepth), and MeshRefused when the polygon's area alone needs more quadrants
// at `depth` than the tree's budget leaves, or when making them reaches it.
bool buildQuadtree(Quadtree& tree, int maxDepth, int depth, double gridSnap, int finestLevel = -1);

// A polygon's tree for a patch size: the frame of 5.1, the depth of 5.2, and a maximum depth
// that starts 16 + `deeper` levels below the patch size and grows by 8 (up to 50) whenever two
// vertices cannot be separated. Throws MeshRefused for a polygon no depth can store (repeated or
// crossing vertices, or vertices nearer than the frame's finest level), or one whose tree would
// pass the tree's quadrantBudget.
struct PolygonTree {
  TreeFrame frame;
  Quadtree tree;
};
PolygonTree buildPolygonTree(const PolygonWithHoles& polygon, double patchSize, int deeper = 0);
// The same into `into`, reusing its memory (meshing surface after surface).
void buildPolygonTree(const PolygonWithHoles& polygon, double patchSize, PolygonTree& into, int deeper = 0);
// buildPolygonTree in two steps, for a caller that looks at the tree's input first: the frame
// and input of the first tree it tries, into `into` (returns the depth of 5.2); then the tree
// itself, deepened as buildPolygonTree does. With `deeper` 0 (a new polygon) the work count
// starts over.
int setUpPolygonTree(const PolygonWithHoles& polygon, double patchSize, PolygonTree& into, int deeper = 0);
void buildSetUpTree(const PolygonWithHoles& polygon, int depth, PolygonTree& into);

// The deepest tree buildPolygonTree makes: quadrant corners stay exact doubles.
constexpr int kDeepestTree = 50;

// True when segment a-b passes through the open square [x0, x1] x [y0, y1] (touching its border
// only does not count).
bool segmentCrossesOpenSquare(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1);

template <typename Visit>
void Quadtree::forEachLeafWithAdjacent(Visit visit) const {
  struct Pending {
    int32_t q;
    std::array<int32_t, 4> adjacent;
  };
  // Depth first, children pushed NE to SW: at most three waiting per level of the path, plus four.
  std::array<Pending, 3 * kDeepestTree + 8> stack;
  size_t size = 0;
  stack[size++] = {0, {-1, -1, -1, -1}};
  while (size > 0) {
    const Pending at = stack[--size];
    const Quadrant& node = (*this)[at.q];
    if (node.isLeaf()) {
      visit(at.q, at.adjacent);
      continue;
    }
    // As adjacent() finds them: a sibling on the inner sides, else the parent's neighbour or its
    // mirrored child (children SW 0, SE 1, NW 2, NE 3: bit 0 is east, bit 1 north).
    auto across = [&](int32_t parentSide, int child, int bit) {
      if (parentSide < 0 || (*this)[parentSide].isLeaf()) return parentSide;
      return (*this)[parentSide].firstChild + (child ^ bit);
    };
    for (int c = 3; c >= 0; --c) {
      const int32_t first = node.firstChild;
      const bool east = c & 1, north = c & 2;
      stack[size++] = {first + c,
                       {east ? first + (c ^ 1) : across(at.adjacent[0], c, 1), east ? across(at.adjacent[1], c, 1) : first + (c ^ 1),
                        north ? first + (c ^ 2) : across(at.adjacent[2], c, 2), north ? across(at.adjacent[3], c, 2) : first + (c ^ 2)}};
    }
  }
}

}  // namespace mesher
