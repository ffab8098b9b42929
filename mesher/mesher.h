// walkrad's mesher: the modified quadtree of Nimscheck's thesis, chapter 5. Plain data in, plain
// data out; GLM only.
//
// A polygon with holes (2-D, in its plane) is turned and scaled into a quadtree (5.1), its
// vertices and edges are stored under the PM-quadtree rules (5.2), the leaves are classified and
// 2:1 balanced, and each leaf inside or on the boundary becomes convex quadrilaterals and
// triangles: interior squares by templates that anchor T-vertices (5.3), boundary leaves by
// subdomain removal around a hinge vertex (5.4). No input vertex or edge moves.
#pragma once

#include "mesher/triangulate.h"

#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesher {

// The smallest element angle Bern, Eppstein and Gilbert's provably good quadtree meshing
// guarantees, atan(1/3) in degrees: the mesher aims for no angle below it except at input
// corners that are sharper.
constexpr double kAngleBoundDeg = 18.4;

// The guarantee: meshing a polygon always ends, in time and memory in proportion to the
// quadrants its trees make (about 40 bytes each), which bound the elements it outputs (about one
// and a half an inside or boundary leaf). A polygon that would make more than `maxQuadrants` is
// refused (MeshRefused) instead, before they are made: one whose patch size is too small for its
// area is refused at once; one so thin that leaves as fine as its width run along its length (a
// needle, a sliver) or one whose vertices lie a hair apart along a long stretch, as its tree
// reaches the limit. The limit counts every tree built (a deeper one when a vertex needs it) and
// the splits the quality refinement tries and takes back. The default, 2^22 quadrants (170 MB of
// tree, a few million elements), is far above the shipped scenes' largest polygon and the large
// models' (docs/BENCHMARKS.md).
constexpr size_t kMaxQuadrants = size_t{1} << 22;

struct MeshSettings {
  double patchSize = 1;  // largest element edge along either axis of the tree, in plane units (> 0)
  size_t maxQuadrants = kMaxQuadrants;  // the work limit above
};

// Why a polygon was not meshed: its mesh would exceed MeshSettings::maxQuadrants (TooLarge), or
// it has detail finer than its coordinates resolve (TooFine): two vertices, or a vertex and an
// edge, closer than a few thousand roundings of its coordinates (repeated or crossing vertices,
// a polygon a hair wide far from the origin), or a patch size that fine.
class MeshRefused : public std::invalid_argument {
 public:
  enum class Reason { TooLarge, TooFine };
  MeshRefused(Reason reason, const std::string& what) : std::invalid_argument(what), reason_(reason) {}
  Reason reason() const { return reason_; }

 private:
  Reason reason_;
};

struct Mesh {
  static constexpr uint32_t kNone = 0xffffffffu;
  // Plane coordinates. The polygon's points come first, numbered as triangulate() numbers them
  // (outer ring, then each hole), with their exact input coordinates.
  std::vector<Vec2> vertices;
  // Counter-clockwise; triangles have [3] == kNone.
  std::vector<std::array<uint32_t, 4>> elements;

  size_t quadCount() const;
  size_t triangleCount() const { return elements.size() - quadCount(); }
};

// Meshes a valid polygon (simple rings, holes strictly inside and disjoint; either winding).
// Throws MeshRefused beyond the limit above, or for detail finer than the coordinates resolve.
Mesh meshPolygon(const PolygonWithHoles& polygon, const MeshSettings& settings);

// meshPolygon for polygon after polygon: keeps the last one's tree and scratch memory, so a
// scene of many small surfaces is meshed without allocating much more than the meshes. It also
// keeps the meshes of small polygons, up to `rememberedElements` elements in all (0: none), and
// gives a repeat of one (the same shape, size and patch size, moved or turned so that it comes
// into the tree bit for bit alike: mesh_memo.h) the same mesh, placed by its own frame.
class Mesher {
 public:
  static constexpr size_t kRememberedElements = size_t{1} << 18;
  explicit Mesher(size_t rememberedElements = kRememberedElements);
  ~Mesher();
  Mesh mesh(const PolygonWithHoles& polygon, const MeshSettings& settings);
  // The same into `out`, reusing its memory: meshing polygon after polygon into one Mesh touches
  // no fresh pages, which for a million elements cost a tenth of the time. After a MeshRefused,
  // `out` holds nothing useful; the Mesher meshes the next polygon as ever.
  void mesh(const PolygonWithHoles& polygon, const MeshSettings& settings, Mesh& out);
  // How many meshes so far were those of repeats.
  size_t repeats() const;
  // The work of the last mesh() call, refused or not: the quadrants its trees made (0 for a
  // repeat), what MeshSettings::maxQuadrants limits.
  size_t quadrantsMade() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace mesher
