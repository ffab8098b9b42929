// Leaf-by-leaf element emission (thesis 5.3 and 5.4) over a balanced tree: each leaf's region
// becomes convex quads and triangles whose corners are shared mesh vertex ids. Used for a whole
// mesh at once and again for the leaves a local refine or coarsen touches.
#pragma once

#include "mesher/huge_page_allocator.h"
#include "mesher/leaf_region.h"
#include "mesher/quadtree.h"
#include "mesher/subdomain_removal.h"
#include "mesher/triangulate.h"

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace mesher {

class PointIds;

class LeafEmitter {
 public:
  // `built` must outlive the emitter; its frame must not change. Vertices start as the
  // polygon's own points (outer ring, then holes), exact.
  LeafEmitter(const PolygonWithHoles& polygon, const PolygonTree& built, size_t expectedLeaves);
  ~LeafEmitter();
  // Starts over for a new polygon in `built` (rebuilt in place), keeping memory.
  void reset(const PolygonWithHoles& polygon, size_t expectedLeaves);

  // Appends leaf q's elements to `out` (corner ids, counter-clockwise, [3] = 0xffffffff for
  // triangles) and any new vertex to vertices(). Outside leaves add nothing.
  void emit(int32_t q, std::vector<std::array<uint32_t, 4>>& out);
  // emit() for every leaf of the tree in tree order (Quadtree::leaves), right after
  // construction or reset(): the same elements and vertices, found mostly without the point
  // table (see inOrder_). The emitter is then fit for emit() again.
  void emitAll(std::vector<std::array<uint32_t, 4>>& out);
  // The vertex ids around leaf q's region, as emit() would use them, then one more word when
  // some side of a meshed (not templated) ring is open (RingBoundary::openSides): equal rings give
  // equal elements. lastRingIds() is the ring of the last emit() or ringIds() call.
  const std::vector<uint32_t>& ringIds(int32_t q);
  const std::vector<uint32_t>& lastRingIds() const { return ringIds_; }

  // While set, emit() appends to `leaves` the leaves whose regions it could not mesh within the
  // angle bound (QualityRefiner::splitShortLeaves takes them).
  void collectShortLeaves(std::vector<int32_t>* leaves) { shortLeaves_ = leaves; }

  // Registers input vertices added to the tree after the emitter was made (a hole inserted):
  // plane[i] is the exact plane position of tree input vertex `first + i`.
  void addInputVertices(uint32_t first, const std::vector<Vec2>& plane);

  const std::vector<Vec2>& vertices() const { return vertices_; }
  // While set (it is not at first), the tree coordinates of every vertex after the polygon's own
  // points are kept too, in id order (reset() starts them over): a mesh kept for repeats of its
  // polygon (MeshMemo) is placed anew from them.
  void keepTreePoints(bool keep) { keepTreePoints_ = keep; }
  const std::vector<Vec2>& treePoints() const { return treePoints_; }
  // Hands the vertices over and takes `other`'s memory for the next polygon's.
  void swapVertices(std::vector<Vec2>& other) { vertices_.swap(other); }

 private:
  const LeafRegion& region(int32_t q, const std::array<int32_t, 4>* adjacent = nullptr);
  void emit(int32_t q, const std::array<int32_t, 4>* adjacent, std::vector<std::array<uint32_t, 4>>& out);
  uint32_t newPoint(const Vec2& at, bool listed);
  // Appends the vertex at tree point `at` (plane coordinates to vertices_).
  void addVertex(const Vec2& at);
  // In tree order: the id leaf m recorded at point `at` of its east or north side, and the id a
  // leaf before q gave point `at` of q's west or south side; kNone when there is none.
  uint32_t recordedBy(int32_t m, const Vec2& at) const;
  uint32_t earlierId(int32_t q, const LeafRegion& region, const Vec2& at) const;

  const PolygonTree& built_;
  std::unique_ptr<PointIds> ids_;
  std::vector<Vec2> vertices_;
  std::vector<Vec2> treePoints_;
  bool keepTreePoints_ = false;
  std::vector<uint32_t> inputToMesh_;  // mesh vertex id of each tree input vertex
  LeafRegionBuilder regions_;
  std::vector<Vec2> ring_;  // tree coordinates
  std::vector<uint32_t> ringIds_;
  SubdomainRemover subdomains_;
  std::vector<RingElement> pieces_;
  std::vector<int32_t>* shortLeaves_ = nullptr;
  // Interior squares differ only in which sides carry a T-vertex: their subdomains (the
  // templates of 5.3) are worked out once per pattern. They depend only on the frame's stretch
  // (angles are judged in true proportions), so they are worked out on the unit square and kept
  // for every stretch met (a scene's surfaces share few: the kitchen's 1,229 have 158).
  struct Templates {
    std::array<std::vector<RingElement>, 16> pieces;
    std::array<bool, 16> have{};
  };
  std::vector<Templates> templates_;
  std::map<std::pair<double, int>, size_t> templatesOf_;  // by the frame's stretch and its axis
  size_t stretchTemplates_ = 0;                           // templates_ entry of the current frame
  std::vector<Vec2> unitRing_;
  // Set by emitAll. Leaves then come in tree (Morton) order, in which every leaf touching a
  // point on a leaf's east or north side, other than its south-east and north-west corners,
  // comes later: such a point is new there, unless it is an input vertex. A new point at one of
  // the positions eastAndNorth_ records is found there later, by the leaves across or around
  // it that came earlier, and stays out of the point table; so does an interior square's inner
  // point, which no other leaf touches. Everything else is listed as before.
  bool inOrder_ = false;
  // Set once emitAll has listed a point off a leaf's border (a handed-over wedge's): a leaf
  // meeting it later on its east or north side must look it up instead of taking it as new.
  bool handedOver_ = false;
  // Per quadrant, the ids on its east and north sides: south-east corner, east midpoint,
  // north-east corner, north midpoint, north-west corner (0xffffffff: none there). Written for
  // every leaf emitAll meets that is not Outside, read only for such leaves it has passed.
  std::vector<std::array<uint32_t, 5>, HugePageAllocator<std::array<uint32_t, 5>>> eastAndNorth_;
};

}  // namespace mesher
