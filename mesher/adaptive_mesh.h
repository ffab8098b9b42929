// A mesh that changes locally (thesis 5.5): refine one element's quadrant, coarsen four sibling
// quadrants back into one, each followed by local 2:1 rebalancing and re-emission of the
// elements whose quadrants changed, reported as a delta. Untouched elements keep their ids.
// What to refine or coarsen is decided outside (by the solver's gradients, or a test).
#pragma once

#include "mesher/balance.h"
#include "mesher/leaf_emitter.h"
#include "mesher/mesher.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace mesher {

// A handle that stays valid while its element lives; a slot reused later has a new generation.
struct ElementId {
  uint32_t slot = 0;
  uint32_t generation = 0;
  bool operator==(const ElementId&) const = default;
};

struct MeshDelta {
  std::vector<ElementId> removed;
  std::vector<ElementId> added;
  uint32_t firstNewVertex = 0, vertexCount = 0;  // vertices [firstNewVertex, vertexCount) are new

  bool empty() const { return removed.empty() && added.empty(); }
};

class AdaptiveMesh {
 public:
  // Meshes the polygon as meshPolygon() does, within the settings' work limit; throws MeshRefused
  // as it does. Later refines and inserted holes are not limited: the caller says how far to go.
  // The polygon's last `removableHoles` holes (cut-outs it was meshed with, that may go again)
  // take the ids 0 to removableHoles - 1, as if inserted in that order: removeHole takes them out.
  AdaptiveMesh(const PolygonWithHoles& polygon, const MeshSettings& settings, size_t removableHoles = 0);
  ~AdaptiveMesh();
  AdaptiveMesh(const AdaptiveMesh&) = delete;
  AdaptiveMesh& operator=(const AdaptiveMesh&) = delete;

  const std::vector<Vec2>& vertices() const;
  std::vector<ElementId> elements() const;  // the live ones, in slot order
  bool alive(ElementId e) const;
  // Corner vertex ids, counter-clockwise; [3] == Mesh::kNone for triangles. e must be alive.
  const std::array<uint32_t, 4>& corners(ElementId e) const;
  // The tree level of e's quadrant (0 is the root): deeper is finer.
  int level(ElementId e) const;
  // The live elements as a plain mesh, in slot order.
  Mesh snapshot() const;

  // Splits e's quadrant into four (nothing at the tree's deepest level), rebalances around it
  // and re-emits what changed. e must be alive.
  MeshDelta refine(ElementId e);
  // Merges e's quadrant with its three siblings when all are leaves, the merged quadrant keeps
  // the storage rules and 2:1 balance allows it; then merges quadrants nearby that were split
  // only for balance and no longer need to be. Otherwise nothing. e must be alive.
  MeshDelta coarsen(ElementId e);

  // One pass of adaptive refinement as the caller decides it (a radiosity gradient, a test):
  // refines every live element `refineIt` accepts, then coarsens every live element
  // `coarsenIt` accepts (four siblings merge only when all of them agree to go and the rules
  // allow). Returns the combined delta: removed and added ids of elements that lived through the
  // pass are dropped from both.
  MeshDelta adapt(const std::function<bool(ElementId)>& refineIt, const std::function<bool(ElementId)>& coarsenIt);

  // Cuts a hole into the mesh (a contact cut-out, a window appearing): `ring` is simple, either
  // winding, and lies strictly inside the polygon, apart from its boundary and other holes.
  // The hole's edges are stored, the leaves inside it drop out, and the tree splits and
  // rebalances around it. Returns the hole's id and the delta, or -1 and no change when the ring
  // is not valid there or needs more tree levels than there are.
  std::pair<int, MeshDelta> insertHole(const Ring2& ring);
  // Takes an inserted hole out again: the leaves around it merge back as far as the rules,
  // the patch size and balance allow (an insert then a remove restores the mesh). Nothing for
  // an unknown or already removed id.
  MeshDelta removeHole(int hole);
  // The holes `remove` taken out and the rings `insert` cut in as one change (a cut-out that
  // moved, which may overlap where it was): each ring as insertHole takes it, valid once the
  // removed holes are gone. Returns the new holes' ids, in the order of `insert`, and the delta;
  // or nothing when a ring is refused as insertHole refuses it, and then the mesh, its element
  // ids and its holes are as they were (only vertices() may have grown, by unused points).
  // Unknown or already removed ids are passed over.
  struct HoleChange {
    std::vector<int> inserted;
    MeshDelta delta;
  };
  std::optional<HoleChange> replaceHoles(std::span<const int> remove, std::span<const Ring2> insert);
  // Whether replaceHoles(remove, insert) would make the change; the mesh stays as it is (only
  // vertices() may grow, by unused points). For a caller that must know before changing anything.
  bool holesFit(std::span<const int> remove, std::span<const Ring2> insert);

 private:
  struct Slot {
    std::array<uint32_t, 4> corners{};
    int32_t leaf = -1;
    uint32_t generation = 0;
    bool alive = false;
  };

  // refine() and coarsen() but for their check, which adapt() makes once for its pass.
  MeshDelta refineQuadrant(ElementId e);
  MeshDelta coarsenQuadrant(ElementId e);
  // The live mesh's T-vertices as the independent check (mesh_check.h) counts them: 0 after
  // every change (checked in debug builds).
  size_t tVertices() const;
  MeshDelta applyChanges(uint32_t firstNewVertex, const std::vector<int32_t>& restyled = {});
  void removeLeafElements(int32_t leaf, MeshDelta& delta);
  void emitLeaf(int32_t leaf, MeshDelta& delta);
  void mergeUnneededBalanceSplits(std::vector<int32_t> candidates);
  // Drops from `total` (a run of changes) the elements both added and removed within it, and
  // sets its vertex count.
  void settle(MeshDelta& total) const;
  // Adds a ring to the tree's input and stores it (insertHole's check and storage, no status,
  // balance or emission); false when it is refused (the caller takes it back: takeBackRings).
  bool addRing(const Ring2& ring);
  // Takes back the rings added since there were `holesBefore` holes, and the tree's changes.
  void takeBackRings(size_t holesBefore);
  // The rest of an insertion of hole `hole` just added (addRing): its sides, balance, emission.
  MeshDelta cutOut(size_t hole, uint32_t firstNewVertex);
  // The ids among `ids` of holes that are there, each once.
  std::vector<size_t> activeHoles(std::span<const int> ids) const;
  // removeHole's work for an active hole.
  MeshDelta fillIn(size_t hole);
  // The ring in tree coordinates, clockwise (the polygon's inside on the left of each edge), when
  // it fits strictly inside the polygon as it is now (insertHole); else nothing.
  std::optional<Ring2> fittingTreeRing(const Ring2& ring) const;
  // Adds the ring (plane coordinates, and the same points in tree coordinates) to the tree's
  // input and stores it; false when it needs more tree levels than there are (the caller takes
  // the tree's changes back).
  bool storeRing(const Ring2& plane, const Ring2& points);

  PolygonWithHoles polygon_;  // as given (inserted holes not added): the check's measure of scale
  PolygonTree built_;
  std::unique_ptr<LeafEmitter> emitter_;
  std::vector<Slot> slots_;
  std::vector<uint32_t> freeSlots_;
  std::vector<std::vector<uint32_t>> leafSlots_;    // per quadrant: its elements' slots
  std::vector<std::vector<uint32_t>> leafRings_;    // per quadrant: the ring ids it was emitted with
  std::vector<std::array<uint32_t, 4>> scratch_;
  struct InsertedHole {
    uint32_t firstVertex, firstEdge, count;
    Vec2 lo, hi;  // tree bounding box
    bool active;
  };
  std::vector<InsertedHole> holes_;
  bool handsOver_ = false;  // some edge meets grid lines shallowly (wedge_handover.h)
};

}  // namespace mesher
