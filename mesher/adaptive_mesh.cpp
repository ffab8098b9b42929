#include "mesher/adaptive_mesh.h"

#include "mesher/classify.h"
#include "mesher/mesh_check.h"
#include "mesher/quality_refinement.h"
#include "mesher/wedge_handover.h"
#include "util/check.h"

#include <glm/common.hpp>

#include <algorithm>
#include <unordered_set>
#include <utility>

namespace mesher {

namespace {

constexpr Side kSides[] = {Side::West, Side::East, Side::South, Side::North};

// False for a quadrant whose parent (or an ancestor's) has since been merged away.
bool inTree(const Quadtree& tree, int32_t q) {
  while (q != 0) {
    const int32_t p = tree[q].parent;
    if (tree[p].isLeaf() || q < tree[p].firstChild || q >= tree[p].firstChild + 4) return false;
    q = p;
  }
  return true;
}

// Adds delta `d`'s elements to `total`'s.
void append(MeshDelta& total, const MeshDelta& d) {
  total.removed.insert(total.removed.end(), d.removed.begin(), d.removed.end());
  total.added.insert(total.added.end(), d.added.begin(), d.added.end());
}

}  // namespace

AdaptiveMesh::AdaptiveMesh(const PolygonWithHoles& polygon, const MeshSettings& settings, size_t removableHoles)
    : polygon_(polygon), built_(buildMeshTree(polygon, settings)) {
  CHECK_LE(removableHoles, polygon.holes.size());
  handsOver_ = std::find(built_.tree.input.shallow.begin(), built_.tree.input.shallow.end(), 1) != built_.tree.input.shallow.end();
  std::vector<int32_t> leaves = built_.tree.leaves(), shortLeaves;
  emitter_ = std::make_unique<LeafEmitter>(polygon, built_, leaves.size());
  MeshDelta ignored;
  emitter_->collectShortLeaves(&shortLeaves);
  for (int32_t q : leaves) emitLeaf(q, ignored);
  emitter_->collectShortLeaves(nullptr);
  // As Mesher meshes: leaves the refiner did not look at that fell short of the angle bound are
  // split (QualityRefiner::splitShortLeaves), and the tree is meshed again from the start.
  if (!shortLeaves.empty() && QualityRefiner(built_).splitShortLeaves(shortLeaves) > 0) {
    built_.tree.changes.clear();
    slots_.clear();
    freeSlots_.clear();
    leafSlots_.clear();
    leafRings_.clear();
    built_.tree.leaves(leaves);
    emitter_ = std::make_unique<LeafEmitter>(polygon, built_, leaves.size());
    for (int32_t q : leaves) emitLeaf(q, ignored);
  }
  // The limit is meshing's; how far to refine is the caller's to say.
  built_.tree.quadrantBudget = SIZE_MAX;
  // The tree's input holds the rings in order, each ring's edge k leaving its vertex k.
  const QuadtreeInput& in = built_.tree.input;
  auto first = static_cast<uint32_t>(polygon.outer.size());
  for (size_t h = 0; h < polygon.holes.size(); ++h) {
    const auto count = static_cast<uint32_t>(polygon.holes[h].size());
    if (h + removableHoles >= polygon.holes.size()) {
      Vec2 lo = in.vertices[first], hi = lo;
      for (uint32_t i = first; i < first + count; ++i) lo = glm::min(lo, in.vertices[i]), hi = glm::max(hi, in.vertices[i]);
      holes_.push_back({first, first, count, lo, hi, true});
    }
    first += count;
  }
}

AdaptiveMesh::~AdaptiveMesh() = default;

const std::vector<Vec2>& AdaptiveMesh::vertices() const { return emitter_->vertices(); }

std::vector<ElementId> AdaptiveMesh::elements() const {
  std::vector<ElementId> out;
  for (uint32_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].alive) out.push_back({s, slots_[s].generation});
  return out;
}

bool AdaptiveMesh::alive(ElementId e) const {
  return e.slot < slots_.size() && slots_[e.slot].alive && slots_[e.slot].generation == e.generation;
}

const std::array<uint32_t, 4>& AdaptiveMesh::corners(ElementId e) const { return slots_[e.slot].corners; }

int AdaptiveMesh::level(ElementId e) const { return built_.tree[slots_[e.slot].leaf].level; }

Mesh AdaptiveMesh::snapshot() const {
  Mesh mesh;
  mesh.vertices = vertices();
  for (const Slot& slot : slots_)
    if (slot.alive) mesh.elements.push_back(slot.corners);
  return mesh;
}

size_t AdaptiveMesh::tVertices() const { return checkMesh(polygon_, snapshot()).tVertices; }

void AdaptiveMesh::emitLeaf(int32_t leaf, MeshDelta& delta) {
  const size_t size = built_.tree.quadrants.size();
  if (leafSlots_.size() < size) leafSlots_.resize(size), leafRings_.resize(size);
  scratch_.clear();
  emitter_->emit(leaf, scratch_);
  leafRings_[static_cast<size_t>(leaf)] = emitter_->lastRingIds();
  for (const auto& corners : scratch_) {
    uint32_t s;
    if (!freeSlots_.empty()) {
      s = freeSlots_.back();
      freeSlots_.pop_back();
      ++slots_[s].generation;
    } else {
      s = static_cast<uint32_t>(slots_.size());
      slots_.emplace_back();
    }
    Slot& slot = slots_[s];
    slot.corners = corners;
    slot.leaf = leaf;
    slot.alive = true;
    leafSlots_[static_cast<size_t>(leaf)].push_back(s);
    delta.added.push_back({s, slot.generation});
  }
}

void AdaptiveMesh::removeLeafElements(int32_t leaf, MeshDelta& delta) {
  if (static_cast<size_t>(leaf) >= leafSlots_.size()) return;
  for (uint32_t s : leafSlots_[static_cast<size_t>(leaf)]) {
    slots_[s].alive = false;
    delta.removed.push_back({s, slots_[s].generation});
    freeSlots_.push_back(s);
  }
  leafSlots_[static_cast<size_t>(leaf)].clear();
  leafRings_[static_cast<size_t>(leaf)].clear();
}

MeshDelta AdaptiveMesh::applyChanges(uint32_t firstNewVertex, const std::vector<int32_t>& restyled) {
  Quadtree& tree = built_.tree;
  MeshDelta delta;
  // Leaves that changed side without splitting (inside a hole now, or again) lose their elements.
  std::vector<int32_t> fresh;
  for (int32_t q : restyled)
    if (tree[q].isLeaf() && inTree(tree, q)) {
      removeLeafElements(q, delta);
      fresh.push_back(q);
    }
  // Leaves that are gone lose their elements; the quadrants that are leaves now are new.
  for (const Quadtree::Change& change : tree.changes) {
    if (change.isMerge()) {
      for (int32_t c = change.before.firstChild; c < change.before.firstChild + 4; ++c) removeLeafElements(c, delta);
    } else {
      removeLeafElements(change.quadrant, delta);
    }
    if (inTree(tree, change.quadrant)) tree.leavesBelow(change.quadrant, fresh);
  }
  tree.changes.clear();
  const auto madeBefore = [&](int32_t a, int32_t b) { return tree.madeBefore(a, b); };
  std::sort(fresh.begin(), fresh.end(), madeBefore);
  fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
  fresh.erase(std::remove_if(fresh.begin(), fresh.end(), [&](int32_t q) { return !tree[q].isLeaf(); }), fresh.end());
  for (int32_t q : fresh) emitLeaf(q, delta);

  // Neighbours whose border gained or lost a T-vertex are emitted again; the rest keep theirs.
  // Where wedges may be handed over, a leaf's ring also depends on leaves two steps away (the
  // points along the giver's far side: wedge_handover.h): neighbours of neighbours too.
  std::vector<int32_t> near;
  for (int32_t q : fresh)
    for (Side side : kSides) tree.neighbors(q, side, near);
  const size_t firstStep = handsOver_ ? near.size() : 0;
  for (size_t i = 0; i < firstStep; ++i)
    for (Side side : kSides) tree.neighbors(near[i], side, near);
  std::sort(near.begin(), near.end(), madeBefore);
  near.erase(std::unique(near.begin(), near.end()), near.end());
  for (int32_t n : near) {
    if (std::binary_search(fresh.begin(), fresh.end(), n, madeBefore)) continue;
    if (emitter_->ringIds(n) == leafRings_[static_cast<size_t>(n)]) continue;
    removeLeafElements(n, delta);
    emitLeaf(n, delta);
  }
  delta.firstNewVertex = firstNewVertex;
  delta.vertexCount = static_cast<uint32_t>(vertices().size());
  return delta;
}

MeshDelta AdaptiveMesh::refineQuadrant(ElementId e) {
  Quadtree& tree = built_.tree;
  const int32_t q = slots_[e.slot].leaf;
  const auto firstNewVertex = static_cast<uint32_t>(vertices().size());
  if (tree[q].level >= tree.finestLevel) return {};
  // A split whose edges would need levels the tree does not have is taken back: the mesh stays
  // as it was.
  if (!tree.splitLeaf(q)) {
    tree.undoChanges(0);
    return {};
  }
  std::vector<int32_t> seeds;
  tree.leavesBelow(q, seeds);
  balanceAround(tree, std::move(seeds));
  return applyChanges(firstNewVertex);
}

void AdaptiveMesh::mergeUnneededBalanceSplits(std::vector<int32_t> candidates) {
  Quadtree& tree = built_.tree;
  std::vector<int32_t> across;
  while (!candidates.empty()) {
    const int32_t c = candidates.back();
    candidates.pop_back();
    if (c < 0 || tree[c].isLeaf() || !tree[c].forced || !tree.canMerge(c)) continue;
    tree.merge(c);
    candidates.push_back(tree[c].parent);
    for (Side side : kSides) {
      across.clear();
      tree.neighbors(c, side, across);
      for (int32_t n : across) candidates.push_back(tree[n].parent);
    }
  }
}

MeshDelta AdaptiveMesh::coarsenQuadrant(ElementId e) {
  Quadtree& tree = built_.tree;
  const int32_t parent = tree[slots_[e.slot].leaf].parent;
  const auto firstNewVertex = static_cast<uint32_t>(vertices().size());
  if (parent < 0 || !tree.canMerge(parent)) return {};
  tree.merge(parent);
  // Quadrants split only to balance against the finer ones just merged may merge back too.
  std::vector<int32_t> candidates{tree[parent].parent};
  std::vector<int32_t> across;
  for (Side side : kSides) {
    across.clear();
    tree.neighbors(parent, side, across);
    for (int32_t n : across) candidates.push_back(tree[n].parent);
  }
  mergeUnneededBalanceSplits(std::move(candidates));
  return applyChanges(firstNewVertex);
}

MeshDelta AdaptiveMesh::refine(ElementId e) {
  MeshDelta delta = refineQuadrant(e);
  DCHECK_EQ(tVertices(), 0u);
  return delta;
}

MeshDelta AdaptiveMesh::coarsen(ElementId e) {
  MeshDelta delta = coarsenQuadrant(e);
  DCHECK_EQ(tVertices(), 0u);
  return delta;
}

MeshDelta AdaptiveMesh::adapt(const std::function<bool(ElementId)>& refineIt,
                              const std::function<bool(ElementId)>& coarsenIt) {
  MeshDelta total;
  total.firstNewVertex = static_cast<uint32_t>(vertices().size());
  const auto collect = [&](const MeshDelta& d) { append(total, d); };
  for (ElementId e : elements())
    if (alive(e) && refineIt(e)) collect(refineQuadrant(e));
  // Coarsening asks each of the four siblings: merge only when every one agrees.
  for (ElementId e : elements()) {
    if (!alive(e) || !coarsenIt(e)) continue;
    const int32_t parent = built_.tree[slots_[e.slot].leaf].parent;
    if (parent < 0 || built_.tree[parent].isLeaf()) continue;
    bool allAgree = true;
    for (int32_t c = built_.tree[parent].firstChild; c < built_.tree[parent].firstChild + 4 && allAgree; ++c) {
      if (!built_.tree[c].isLeaf()) allAgree = false;
      else if (static_cast<size_t>(c) < leafSlots_.size())
        for (uint32_t s : leafSlots_[static_cast<size_t>(c)]) allAgree = allAgree && coarsenIt({s, slots_[s].generation});
    }
    if (allAgree) collect(coarsenQuadrant(e));
  }
  settle(total);
  DCHECK_EQ(tVertices(), 0u);
  return total;
}

void AdaptiveMesh::settle(MeshDelta& total) const {
  // Elements both added and removed within the run never reached the caller.
  std::unordered_set<uint64_t> addedHere;
  for (ElementId e : total.added) addedHere.insert(uint64_t{e.slot} << 32 | e.generation);
  std::vector<ElementId> removed, added;
  for (ElementId e : total.removed)
    if (!addedHere.count(uint64_t{e.slot} << 32 | e.generation)) removed.push_back(e);
  for (ElementId e : total.added)
    if (alive(e)) added.push_back(e);
  total.removed = std::move(removed);
  total.added = std::move(added);
  total.vertexCount = static_cast<uint32_t>(vertices().size());
}

std::optional<Ring2> AdaptiveMesh::fittingTreeRing(const Ring2& plane) const {
  const QuadtreeInput& in = built_.tree.input;
  if (plane.size() < 3 || !isSimple(plane) || signedArea(plane) == 0) return std::nullopt;
  Ring2 points;
  for (const Vec2& p : plane) points.push_back(treePoint(built_.frame, p));
  if (!isSimple(points)) return std::nullopt;
  // Strictly inside the polygon as it is: every point inside, no edge meeting an active edge,
  // no active edge's end inside the ring (a hole within the hole). Apart by the clearance the
  // mesher asks of a polygon's vertices from its edges (kClearanceOverRounding), the ring's own
  // included: nearer, the mesher would refuse the polygon with the ring as too fine.
  const double clearance = std::max(built_.tree.gridSnap, kClearanceOverRounding * built_.frame.rounding);
  for (const Vec2& p : points)
    if (!rayCastInside(in, p)) return std::nullopt;
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t k = 0; k < points.size(); ++k) {
      const size_t next = (k + 1) % points.size();
      if (k != i && next != i && segmentDistance(points[i], points[i], points[k], points[next]) <= clearance)
        return std::nullopt;
    }
  for (uint32_t e = 0; e < in.edges.size(); ++e) {
    if (!in.active(e)) continue;
    const Vec2 a = in.vertices[in.edges[e][0]], b = in.vertices[in.edges[e][1]];
    if (containsPoint(points, a)) return std::nullopt;
    for (size_t i = 0; i < points.size(); ++i)
      if (segmentDistance(a, b, points[i], points[(i + 1) % points.size()]) <= clearance) return std::nullopt;
  }
  return points;
}

bool AdaptiveMesh::storeRing(const Ring2& plane, const Ring2& points) {
  Quadtree& tree = built_.tree;
  QuadtreeInput& in = tree.input;
  const auto firstVertex = static_cast<uint32_t>(in.vertices.size());
  const auto firstEdge = static_cast<uint32_t>(in.edges.size());
  const auto count = static_cast<uint32_t>(points.size());
  Vec2 lo = points.front(), hi = points.front();
  for (uint32_t i = 0; i < count; ++i) {
    in.vertices.push_back(points[i]);
    lo = glm::min(lo, points[i]), hi = glm::max(hi, points[i]);
    in.edges.push_back({firstVertex + i, firstVertex + (i + 1) % count});
    in.edgeOutOf.push_back(firstEdge + i);
    in.edgeInto.push_back(firstEdge + (i + count - 1) % count);
  }
  in.removed.resize(in.edges.size(), 0);
  handsOver_ = markShallowEdges(in, built_.frame.planePerTree());
  emitter_->addInputVertices(firstVertex, plane);
  holes_.push_back({firstVertex, firstEdge, count, lo, hi, true});

  // Its vertices and edges (5.2); a ring needing more levels than the tree has is refused.
  bool stored = true;
  for (uint32_t i = 0; i < count && stored; ++i) stored = tree.insertVertex(firstVertex + i);
  for (uint32_t i = 0; i < count && stored; ++i) stored = tree.insertEdge(0, firstEdge + i);
  return stored;
}

void AdaptiveMesh::takeBackRings(size_t holesBefore) {
  Quadtree& tree = built_.tree;
  tree.undoChanges(0);
  for (size_t h = holesBefore; h < holes_.size(); ++h) {
    const InsertedHole& hole = holes_[h];
    for (uint32_t i = 0; i < hole.count; ++i) tree.forgetVertex(hole.firstVertex + i);
    for (uint32_t i = 0; i < hole.count; ++i) tree.forgetEdge(hole.firstEdge + i);
  }
  holes_.resize(holesBefore);
}

bool AdaptiveMesh::addRing(const Ring2& ring) {
  // Clockwise in the plane as in the tree (the polygon's inside on the left of each edge).
  Ring2 plane = ring;
  if (signedArea(plane) > 0) std::reverse(plane.begin(), plane.end());
  const std::optional<Ring2> points = fittingTreeRing(plane);
  return points && storeRing(plane, *points);
}

MeshDelta AdaptiveMesh::cutOut(size_t hole, uint32_t firstNewVertex) {
  Quadtree& tree = built_.tree;
  const InsertedHole& h = holes_[hole];
  const Ring2 points(tree.input.vertices.begin() + h.firstVertex, tree.input.vertices.begin() + h.firstVertex + h.count);
  // Leaves with no edge inside the ring are outside the polygon now. Every leaf the ring's box
  // touches may have taken a vertex or an edge without splitting: all are emitted again.
  std::vector<int32_t> around;
  tree.leavesIn(h.lo, h.hi, around);
  for (int32_t q : around) {
    const Quadrant& leaf = tree[q];
    if (leaf.edgeCount > 0 || leaf.status == QuadStatus::Outside) continue;
    const double half = static_cast<double>(tree.edgeLength(leaf)) / 2;
    if (containsPoint(points, {leaf.x + half, leaf.y + half})) tree.quadrants[static_cast<size_t>(q)].status = QuadStatus::Outside;
  }
  // Balance around the box and around every leaf the insertion split (their children reach
  // beyond the box).
  std::vector<int32_t> seeds = around;
  for (const Quadtree::Change& change : tree.changes)
    if (!change.isMerge()) tree.leavesBelow(change.quadrant, seeds);
  balanceAround(tree, std::move(seeds));
  return applyChanges(firstNewVertex, around);
}

std::pair<int, MeshDelta> AdaptiveMesh::insertHole(const Ring2& ring) {
  const size_t holesBefore = holes_.size();
  const auto firstNewVertex = static_cast<uint32_t>(vertices().size());
  if (!addRing(ring)) {
    takeBackRings(holesBefore);
    return {-1, {}};
  }
  MeshDelta delta = cutOut(holesBefore, firstNewVertex);
  DCHECK_EQ(tVertices(), 0u);
  return {static_cast<int>(holesBefore), std::move(delta)};
}

MeshDelta AdaptiveMesh::fillIn(size_t hole) {
  InsertedHole& h = holes_[hole];
  h.active = false;
  Quadtree& tree = built_.tree;
  const auto firstNewVertex = static_cast<uint32_t>(vertices().size());
  for (uint32_t i = 0; i < h.count; ++i) tree.forgetEdge(h.firstEdge + i);
  for (uint32_t i = 0; i < h.count; ++i) tree.forgetVertex(h.firstVertex + i);

  // Leaves left without edges, and those inside the former hole, take their side again; every
  // leaf the box touches is emitted again.
  std::vector<int32_t> around;
  tree.leavesIn(h.lo, h.hi, around);
  for (int32_t q : around) {
    const Quadrant& leaf = tree[q];
    if (leaf.edgeCount > 0) continue;
    const double half = static_cast<double>(tree.edgeLength(leaf)) / 2;
    tree.quadrants[static_cast<size_t>(q)].status =
        rayCastInside(tree.input, {leaf.x + half, leaf.y + half}) ? QuadStatus::Inside : QuadStatus::Outside;
  }
  const std::vector<int32_t> restyled = around;

  // Merge back, bottom up, whatever the rules, the patch size and balance allow. Leaves that
  // were outside (and so took no part in balancing) are inside now: balance around them.
  for (bool merged = true; merged;) {
    merged = false;
    around.clear();
    tree.leavesIn(h.lo, h.hi, around);
    for (int32_t q : around) {
      const int32_t parent = tree[q].parent;
      if (parent >= 0 && !tree[parent].isLeaf() && tree.canMerge(parent)) {
        tree.merge(parent);
        merged = true;
      }
    }
  }
  around.clear();
  tree.leavesIn(h.lo, h.hi, around);
  // Quadrants around the box split only to balance against leaves that merged may merge back too
  // (a cut-out dragged across a floor would leave a trail of them).
  std::vector<int32_t> candidates, across;
  for (int32_t q : around)
    for (Side side : kSides) {
      across.clear();
      tree.neighbors(q, side, across);
      for (int32_t n : across) candidates.push_back(tree[n].parent);
    }
  mergeUnneededBalanceSplits(std::move(candidates));
  around.clear();
  tree.leavesIn(h.lo, h.hi, around);
  balanceAround(tree, around);
  return applyChanges(firstNewVertex, restyled);
}

MeshDelta AdaptiveMesh::removeHole(int hole) {
  if (hole < 0 || static_cast<size_t>(hole) >= holes_.size() || !holes_[static_cast<size_t>(hole)].active) return {};
  MeshDelta delta = fillIn(static_cast<size_t>(hole));
  DCHECK_EQ(tVertices(), 0u);
  return delta;
}

std::vector<size_t> AdaptiveMesh::activeHoles(std::span<const int> ids) const {
  std::vector<size_t> active;
  for (const int h : ids)
    if (h >= 0 && static_cast<size_t>(h) < holes_.size() && holes_[static_cast<size_t>(h)].active &&
        std::find(active.begin(), active.end(), static_cast<size_t>(h)) == active.end())
      active.push_back(static_cast<size_t>(h));
  return active;
}

bool AdaptiveMesh::holesFit(std::span<const int> remove, std::span<const Ring2> insert) {
  // The holes that go leave the tree (a moved cut-out may overlap where it was) and the rings are
  // stored; then everything is put back as it was, the leaves that stored the holes from copies.
  Quadtree& tree = built_.tree;
  const size_t holesBefore = holes_.size();
  const std::vector<size_t> going = activeHoles(remove);
  std::vector<int32_t> oldLeaves;
  for (size_t h : going) tree.leavesIn(holes_[h].lo, holes_[h].hi, oldLeaves);
  std::vector<std::pair<int32_t, Quadrant>> kept;
  for (int32_t q : oldLeaves) kept.emplace_back(q, tree[q]);
  for (size_t h : going) {
    for (uint32_t i = 0; i < holes_[h].count; ++i) tree.forgetEdge(holes_[h].firstEdge + i);
    for (uint32_t i = 0; i < holes_[h].count; ++i) tree.forgetVertex(holes_[h].firstVertex + i);
  }
  bool fits = true;
  for (size_t k = 0; k < insert.size() && fits; ++k) fits = addRing(insert[k]);
  takeBackRings(holesBefore);
  for (const auto& [q, quadrant] : kept) tree.quadrants[static_cast<size_t>(q)] = quadrant;
  for (size_t h : going)
    for (uint32_t i = 0; i < holes_[h].count; ++i) tree.input.removed[holes_[h].firstEdge + i] = 0;
  handsOver_ = markShallowEdges(tree.input, built_.frame.planePerTree());
  return fits;
}

std::optional<AdaptiveMesh::HoleChange> AdaptiveMesh::replaceHoles(std::span<const int> remove,
                                                                   std::span<const Ring2> insert) {
  // The rings' needs do not depend on the leaves they start from, so rings that fit in the trial
  // fit below.
  if (!holesFit(remove, insert)) return std::nullopt;
  const std::vector<size_t> going = activeHoles(remove);

  // The change itself: each hole removed as removeHole does, then each ring inserted as
  // insertHole does, so that a cut-out moved and moved back is an insert and a remove, which
  // undo each other.
  HoleChange change;
  change.delta.firstNewVertex = static_cast<uint32_t>(vertices().size());
  for (size_t h : going) append(change.delta, fillIn(h));
  for (const Ring2& ring : insert) {
    const auto firstNewVertex = static_cast<uint32_t>(vertices().size());
    const size_t hole = holes_.size();
    CHECK(addRing(ring));
    append(change.delta, cutOut(hole, firstNewVertex));
    change.inserted.push_back(static_cast<int>(hole));
  }
  settle(change.delta);
  DCHECK_EQ(tVertices(), 0u);
  return change;
}

}  // namespace mesher
