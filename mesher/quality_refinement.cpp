#include "mesher/quality_refinement.h"

#include "mesher/balance.h"
#include "mesher/wedge_handover.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace mesher {

namespace {

// Whether leaf q's vertex lies inside the leaf's square, off its border: only then is it looked
// at beforehand (a look costs about as much as meshing the leaf, and vertices on grid lines are
// common; one on its leaf's border that falls short is split after meshing, as a short leaf). A
// vertex near a side leaves a strip too thin to mesh; one further in can fall short too, where
// shallow edges leave sharp wedges beside it.
bool offTheBorder(const Quadtree& tree, int32_t q) {
  const Quadrant& leaf = tree[q];
  const double s = static_cast<double>(tree.edgeLength(leaf));
  const Vec2 v = (tree.input.vertices[static_cast<size_t>(leaf.vertex)] - Vec2{static_cast<double>(leaf.x), static_cast<double>(leaf.y)}) / s;
  return v.x > 0 && v.y > 0 && v.x < 1 && v.y < 1;
}

// How many levels below its leaf a vertex may be taken. A vertex a hair from a grid line stays
// that close to the line, but each level doubles its distance relative to the leaf: twelve take
// a ten-thousandth of the leaf to about a third, and random polygons have corners closer than
// that (the tree's own depth stops splits first: 16 levels below the patch size, or a deeper
// tree's). The leaves around are balanced down with it, so the mesh is graded there.
constexpr int kDeeper = 24;

// Rounds of splitting leaves too coarse to take a wedge (each round's balancing can make more).
constexpr int kTakerRounds = 4;

// Times the vertex leaves are looked at at most (the first time all, then those that splits
// changed): in 20,000 random polygons six passes were the most any needed before no split
// changed one (three left some short).
constexpr int kPasses = 10;

// How many levels deeper a tree is built again when a vertex leaf runs out of depth (as
// buildPolygonTree deepens one whose vertices it cannot separate).
constexpr int kDeeperTree = 8;

// How many levels below itself a short leaf without a vertex, or with one on its border, may be
// split (one did in every random polygon that had one).
constexpr int kShortLeafLevels = 3;

// Whether the corner at b of the path a -> b -> c (counter-clockwise, inside on the left) is
// convex and sharper than the bound, in the plane.
bool sharperThanBound(Vec2 a, Vec2 b, Vec2 c, Vec2 planePerTree) {
  static const double kTanBound = std::tan(kAngleBoundDeg * std::numbers::pi / 180);
  const Vec2 u = (a - b) * planePerTree, v = (c - b) * planePerTree;
  const double dot = glm::dot(u, v), turn = v.x * u.y - v.y * u.x;  // > 0: a convex corner
  return turn > 0 && dot > 0 && turn < kTanBound * dot;
}

// Whether a handed-over ring has a corner sharper than the bound that the polygon does not
// make. A wedge handed over up to the giver's vertex V runs the giver from V straight to a grid
// point M on its side, and the taker from M to V (wedge_handover.h): the corner at M is as sharp
// as V is close to that side, relatively, and the one at V can be sharper than the polygon's
// own corner there. No meshing of the ring can help them; a smaller leaf has a grid point nearer
// the vertex. (Crossings on the path are left alone: their corners are the edges' own.)
bool sharpCornerOfItsOwn(const LeafRegion& region, const QuadtreeInput& input, Vec2 planePerTree) {
  const std::vector<RegionPoint>& ring = region.ring;
  const size_t n = ring.size();
  for (size_t i = 0; i < n; ++i) {
    const int32_t v = ring[i].inputVertex;
    if (v < 0 && i < region.boundary.pathPoints) continue;
    if (!sharperThanBound(ring[(i + n - 1) % n].at, ring[i].at, ring[(i + 1) % n].at, planePerTree)) continue;
    if (v < 0) return true;
    const auto at = static_cast<size_t>(v);
    const Vec2 before = input.vertices[input.edges[input.edgeInto[at]][0]], after = input.vertices[input.edges[input.edgeOutOf[at]][1]];
    if (!sharperThanBound(before, input.vertices[at], after, planePerTree)) return true;
  }
  return false;
}

}  // namespace

bool QualityRefiner::reachesBound(int32_t q, bool innerMayMove, bool meshed) {
  const LeafRegion& region = regions_.build(q);
  if (region.ring.empty()) return true;
  if (region.handedOver && sharpCornerOfItsOwn(region, built_.tree.input, built_.frame.planePerTree())) return false;
  ring_.clear();
  for (const RegionPoint& p : region.ring) ring_.push_back(p.at);
  if (!meshed)
    return remover_.reachesBound(ring_, region.hinge, &region.inner, built_.frame.planePerTree(), &region.boundary,
                                 innerMayMove, built_.frame.rounding);
  elements_.clear();
  remover_.mesh(ring_, region.hinge, &region.inner, built_.frame.planePerTree(), elements_, &region.boundary, built_.frame.rounding);
  return remover_.reachedBound();
}

bool QualityRefiner::reachVertexLeaf(int32_t q, bool& outOfDepth) {
  Quadtree& tree = built_.tree;
  // The vertex's leaf is split, kDeeper levels at most, until it reaches the bound; at each level
  // it may also take a T-vertex at the middle of a side, from the leaf across split finer. Splits
  // that do not get there are taken back by the caller.
  int32_t at = q;
  for (int depth = 0;; ++depth) {
    if (splitAcross(at)) return verified(at), true;
    if (depth == kDeeper) return false;
    if (!tree.splitLeaf(at)) {
      outOfDepth = true;
      return false;
    }
    tried_.clear();
    tree.leavesBelow(at, tried_);
    bool reached = true;
    for (int32_t c : tried_) {
      if (tree[c].vertex < 0) continue;
      if (reachesBound(c)) verified(c);
      else reached = false, at = c;
    }
    if (reached) return true;
  }
}

bool QualityRefiner::splitAcross(int32_t q) {
  Quadtree& tree = built_.tree;
  const Quadrant leaf = tree[q];
  const double s = static_cast<double>(tree.edgeLength(leaf)), root = static_cast<double>(tree.edgeLength(tree[0]));
  const Vec2 v = tree.input.vertices[static_cast<size_t>(leaf.vertex)];
  const Vec2 lo{static_cast<double>(leaf.x), static_cast<double>(leaf.y)};
  // The sides nearest the vertex first (a far one can help too: the strip may run along it);
  // just across each, beside the vertex's foot, the leaf there is split until it is finer
  // than q.
  std::array<std::pair<double, Vec2>, 4> sides{{{v.x - lo.x, {lo.x - 0.25, v.y}},
                                                {lo.x + s - v.x, {lo.x + s + 0.25, v.y}},
                                                {v.y - lo.y, {v.x, lo.y - 0.25}},
                                                {lo.y + s - v.y, {v.x, lo.y + s + 0.25}}}};
  std::sort(sides.begin(), sides.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [distance, across] : sides) {
    if (across.x < 0 || across.y < 0 || across.x >= root || across.y >= root) continue;
    const size_t mark = tree.changes.size();
    // A leaf across that is finer already gives q nothing new.
    bool split = tree[tree.leafAt(across)].level <= leaf.level;
    for (int32_t n = tree.leafAt(across); split && tree[n].level <= leaf.level; n = tree.leafAt(across))
      split = tree[n].status != QuadStatus::Outside && tree.splitLeaf(n);
    // Leaf q itself has been tried with its inner point moved: with a T-vertex more, that
    // (the dearest step) is left out.
    if (split && reachesBound(q, false)) return true;
    tree.undoChanges(mark);
  }
  return false;
}

void QualityRefiner::seedLeavesSplitSince(size_t mark) {
  const Quadtree& tree = built_.tree;
  for (size_t i = mark; i < tree.changes.size(); ++i)
    if (!tree.changes[i].isMerge()) tree.leavesBelow(tree.changes[i].quadrant, seeds_);
}

size_t QualityRefiner::refineVertexLeaves() {
  Quadtree& tree = built_.tree;
  size_t splits = 0;
  seeds_.clear();
  for (int32_t q : leaves_) {
    if (!tree[q].isLeaf() || tree[q].vertex < 0 || !offTheBorder(tree, q)) continue;
    if (reachesBound(q)) {
      verified(q);
      continue;
    }
    const size_t mark = tree.changes.size(), verifiedMark = verified_.size();
    bool outOfDepth = false;
    if (!reachVertexLeaf(q, outOfDepth)) {
      tree.undoChanges(mark);
      verified_.resize(verifiedMark);
      // A deeper tree could split it further, unless meshing reaches the bound after all (with
      // the cut that reachesBound leaves out).
      if (outOfDepth && !reachesBound(q, true, true)) shortAtDeepestLevel_ = true;
      continue;
    }
    seedLeavesSplitSince(mark);
    ++splits;
  }
  if (!seeds_.empty()) balanceAround(tree, seeds_);
  return splits;
}

size_t QualityRefiner::splitCoarseTakers() {
  Quadtree& tree = built_.tree;
  size_t splits = 0;
  for (int round = 0; round < kTakerRounds; ++round) {
    // Givers and takers both store the shallow edge: the leaves along those edges.
    leaves_.clear();
    for (uint32_t e = 0; e < tree.input.shallow.size(); ++e)
      if (tree.input.shallow[e]) tree.leavesStoring(e, leaves_);
    takers_.clear();
    regions_.collectCoarseTakers(&takers_);
    for (int32_t q : leaves_) regions_.build(q);
    regions_.collectCoarseTakers(nullptr);
    std::sort(takers_.begin(), takers_.end(), [&](int32_t a, int32_t b) { return tree.madeBefore(a, b); });
    takers_.erase(std::unique(takers_.begin(), takers_.end()), takers_.end());
    seeds_.clear();
    for (int32_t q : takers_) {
      if (!tree[q].isLeaf()) continue;
      // A split can run out of depth part way (two edges nearer each other than the finest
      // leaf, beside the vertex they meet at): its leaves would have lost them, so it is taken
      // back, and the wedge it would take stays with its giver, short of the bound: a deeper
      // tree may split it.
      const size_t mark = tree.changes.size();
      if (!tree.splitLeaf(q)) {
        tree.undoChanges(mark);
        shortAtDeepestLevel_ = true;
        continue;
      }
      tree.leavesBelow(q, seeds_);
      ++splits;
    }
    if (seeds_.empty()) break;
    balanceAround(tree, seeds_);
  }
  return splits;
}

void QualityRefiner::collectVertexLeavesChangedSince(size_t mark) {
  const Quadtree& tree = built_.tree;
  // Each leaf made by a split, or beside one, with the last such split.
  touched_.clear();
  for (size_t i = mark; i < tree.changes.size(); ++i) {
    if (tree.changes[i].isMerge()) continue;
    tried_.clear();
    tree.leavesBelow(tree.changes[i].quadrant, tried_);
    for (int32_t q : tried_) {
      neighbors_.assign(1, q);
      for (Side side : {Side::West, Side::East, Side::South, Side::North}) tree.neighbors(q, side, neighbors_);
      for (int32_t n : neighbors_)
        if (tree[n].vertex >= 0) touched_.emplace_back(n, i);
    }
  }
  const auto before = [&](const std::pair<int32_t, size_t>& a, const std::pair<int32_t, size_t>& b) {
    return a.first != b.first ? tree.madeBefore(a.first, b.first) : a.second < b.second;
  };
  std::sort(touched_.begin(), touched_.end(), before);
  std::sort(verified_.begin(), verified_.end(), before);
  leaves_.clear();
  for (size_t k = 0; k < touched_.size(); ++k) {
    const auto [q, lastSplit] = touched_[k];
    if (k + 1 < touched_.size() && touched_[k + 1].first == q) continue;
    // Left out when it reached the bound after the last split that touched it.
    const auto after = std::upper_bound(verified_.begin(), verified_.end(), std::pair{q, lastSplit}, before);
    if (after == verified_.end() || after->first != q) leaves_.push_back(q);
  }
}

size_t QualityRefiner::refine() {
  Quadtree& tree = built_.tree;
  const bool shallowEdges = markShallowEdges(tree.input, built_.frame.planePerTree());
  // The vertex leaves, in tree order: found from the vertices down in a tree large beside them,
  // by a walk through the leaves in a small one.
  if (tree.input.vertices.size() * 256 < tree.quadrants.size()) tree.vertexLeaves(leaves_);
  else tree.leaves(leaves_);
  size_t splits = 0;
  verified_.clear();
  shortAtDeepestLevel_ = false;
  for (int pass = 0; pass < kPasses; ++pass) {
    const size_t mark = tree.changes.size();
    splits += refineVertexLeaves();
    // Leaves that would take a shallow wedge but are too coarse to (grown by it, their elements
    // would be longer than the patch size, or meet much finer ones) are split, round by round
    // as splits and their balancing make new ones.
    if (shallowEdges) splits += splitCoarseTakers();
    if (tree.changes.size() == mark) break;
    // A vertex leaf looked at before later splits (its own by balancing, or its neighbours', a
    // new T-vertex on its side) may fall short now: those are looked at again.
    collectVertexLeavesChangedSince(mark);
  }
  return splits;
}

size_t QualityRefiner::splitShortLeaves(const std::vector<int32_t>& leaves) {
  Quadtree& tree = built_.tree;
  size_t splits = 0;
  seeds_.clear();
  for (int32_t q : leaves) {
    if (!tree[q].isLeaf() || (tree[q].vertex >= 0 && offTheBorder(tree, q))) continue;
    const size_t mark = tree.changes.size();
    bool reached = false;
    for (int32_t at = q, level = 0; !reached && level < kShortLeafLevels && tree.splitLeaf(at); ++level) {
      tried_.clear();
      tree.leavesBelow(at, tried_);
      reached = true;
      for (int32_t c : tried_)
        if (!reachesBound(c)) reached = false, at = c;
    }
    if (!reached) {
      tree.undoChanges(mark);
      continue;
    }
    seedLeavesSplitSince(mark);
    ++splits;
  }
  if (!seeds_.empty()) balanceAround(tree, seeds_);
  return splits;
}

void buildMeshTree(const PolygonWithHoles& polygon, double patchSize, PolygonTree& into,
                   std::optional<QualityRefiner>& refiner, int setUpDepth) {
  // A vertex leaf that could not be split far enough, the tree being as deep as it goes, gets a
  // tree kDeeperTree levels deeper, while its finest leaves stay well above its rounding.
  int maxDepth = -1;
  for (int deeper = 0;; deeper += kDeeperTree) {
    if (deeper == 0 && setUpDepth >= 0) buildSetUpTree(polygon, setUpDepth, into);
    else buildPolygonTree(polygon, patchSize, into, deeper);
    if (into.tree.maxDepth <= maxDepth) continue;  // the vertices needed this depth anyway: tried
    maxDepth = into.tree.maxDepth;
    balance(into.tree);
    if (!refiner) refiner.emplace(into);
    refiner->refine();
    // In the deeper tree's units, where its finest leaf is 1.
    const double deeperRounding = into.frame.rounding * std::exp2(kDeeperTree);
    if (!refiner->shortAtDeepestLevel() || maxDepth + kDeeperTree > kDeepestTree || kFinestLeafOverRounding * deeperRounding > 1)
      break;
  }
  into.tree.changes.clear();
}

PolygonTree buildMeshTree(const PolygonWithHoles& polygon, const MeshSettings& settings) {
  PolygonTree built;
  built.tree.quadrantBudget = settings.maxQuadrants;
  std::optional<QualityRefiner> refiner;
  buildMeshTree(polygon, settings.patchSize, built, refiner);
  return built;
}

}  // namespace mesher
