// Refinement for element quality beyond the thesis, whose subdomain removal (5.4) leaves some
// boundary patches badly shaped: a leaf holding an input vertex whose region does not mesh with
// every angle at kAngleBoundDeg takes a T-vertex in the middle of a side, from the leaf across
// split finer, or is split itself. The typical case is a reflex corner close to a side: the
// strip between them is too thin for any element on the long side beyond it; a point in the
// middle of that side anchors the strip, and in a leaf half the size the corner sits twice as
// far from the sides, relatively.
#pragma once

#include "mesher/leaf_region.h"
#include "mesher/quadtree.h"
#include "mesher/subdomain_removal.h"

#include <optional>
#include <utility>
#include <vector>

namespace mesher {

// Splits, in a complete and balanced tree, the leaves across a side of a vertex leaf whose
// region falls short of the bound (judged as LeafEmitter meshes it; a handed-over region's
// corners sharper than the polygon's own count too), or the vertex leaf itself,
// when that makes it reach the bound (up to twelve levels down), and the coarsest leaves that
// would take a shallow wedge (wedge_handover.h), each followed by rebalancing; vertex leaves that
// later splits change are looked at again. Returns how many leaves were split. The refiner
// keeps its scratch memory from polygon to polygon rebuilt into the same PolygonTree.
class QualityRefiner {
 public:
  explicit QualityRefiner(PolygonTree& built) : built_(built), regions_(built) {}
  size_t refine();
  // Splits each of `leaves` (their regions, meshed, fell short of the bound:
  // LeafEmitter::collectShortLeaves) that refine() did not look at, holding no input vertex or
  // one on its border, until every leaf below it reaches the bound, a few levels at most, then
  // rebalances; leaves that do not get there stay whole. Their regions are too rarely short for
  // the refiner to look at every such leaf beforehand (that cost the kitchen 12% more meshing):
  // the mesher meshes, and meshes again after these splits. Returns how many leaves were split.
  size_t splitShortLeaves(const std::vector<int32_t>& leaves);
  // Whether the last refine() left a vertex leaf, or a wedge with its giver, short of the bound
  // because the tree allows no deeper split.
  bool shortAtDeepestLevel() const { return shortAtDeepestLevel_; }

 private:
  // Whether leaf q's region meshes within the bound: as SubdomainRemover::reachesBound says, or,
  // when `meshed`, as mesh() does it with every step.
  bool reachesBound(int32_t q, bool innerMayMove = true, bool meshed = false);
  // Splits vertex leaf q, and leaves across its sides, until its region reaches the bound;
  // false when a few levels do not get there (the splits are left for the caller to undo),
  // with `outOfDepth` set when the tree allowed no deeper split.
  bool reachVertexLeaf(int32_t q, bool& outOfDepth);
  // Whether splitting the leaf across one side of vertex leaf q finer than q makes q reach the
  // bound; the first such split is kept, the others are taken back.
  bool splitAcross(int32_t q);
  // The splits (then balancing) for the vertex leaves in leaves_, and the coarse takers' rounds
  // of splits; each returns how many leaves it split.
  size_t refineVertexLeaves();
  size_t splitCoarseTakers();
  // Into leaves_: the vertex leaves among those made by the splits after changes[mark] and their
  // neighbours, in index order, but for those that reached the bound after the last such split.
  void collectVertexLeavesChangedSince(size_t mark);
  // Appends to seeds_ the leaves that the splits after changes[mark] made, to be balanced around.
  void seedLeavesSplitSince(size_t mark);
  // Notes that vertex leaf q reaches the bound as the tree stands.
  void verified(int32_t q) { verified_.emplace_back(q, built_.tree.changes.size()); }

  PolygonTree& built_;
  LeafRegionBuilder regions_;
  SubdomainRemover remover_;
  std::vector<int32_t> leaves_, seeds_, takers_, tried_, neighbors_;
  // (leaf, changes made before it was found to reach the bound), (leaf, a split beside it).
  std::vector<std::pair<int32_t, size_t>> verified_, touched_;
  std::vector<Vec2> ring_;
  std::vector<RingElement> elements_;
  bool shortAtDeepestLevel_ = false;
};

// A polygon's tree as the mesher meshes it, built into `into` (its memory reused):
// buildPolygonTree, balance, the quality splits (all again in a deeper tree when a vertex leaf
// ran out of depth), and no changes left recorded. `refiner` is
// made over `into` when empty and kept for the next polygon. A `setUpDepth` of 0 or more says
// that `into` holds the first tree's frame and input already (setUpPolygonTree gave that depth).
// Throws MeshRefused as buildPolygonTree does, also when the quality splits pass the tree's
// quadrantBudget.
void buildMeshTree(const PolygonWithHoles& polygon, double patchSize, PolygonTree& into,
                   std::optional<QualityRefiner>& refiner, int setUpDepth = -1);
// The same into a new tree, within the settings' work limit.
PolygonTree buildMeshTree(const PolygonWithHoles& polygon, const MeshSettings& settings);

}  // namespace mesher
