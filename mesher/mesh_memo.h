// Meshes of polygons met before, for the repeats in a scene: a chair's four legs, a row of
// cabinet doors, the opposite faces of a box. In tree coordinates a polygon's mesh depends only
// on its tree input (its points turned and scaled into the tree, bit for bit, and its edges),
// the tree's depths and the frame's scales and rounding: not on where the polygon lies or how it
// is turned in its plane. A repeat that comes into the same tree input bit for bit (moved within
// the same power of two of its coordinates' magnitude, by amounts that round alike, or turned by
// quarter turns) gets the same elements, and its vertices are its frame's images of the same
// tree points: the very mesh that meshing it would give.
#pragma once

#include "mesher/mesher.h"
#include "mesher/quadtree.h"

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace mesher {

class MeshMemo {
 public:
  struct Entry {
    std::vector<std::array<uint32_t, 4>> elements;
    std::vector<Vec2> treePoints;  // the vertices after the polygon's own points, tree coordinates
  };

  // Keeps meshes of up to `capacity` elements in all (0: none), forgetting all when full; a
  // mesh larger than a sixteenth of that is not kept.
  explicit MeshMemo(size_t capacity) : capacity_(capacity) {}
  // The mesh kept for the tree set up in `built` (setUpPolygonTree: frame and input) at uniform
  // depth `depth`, or null. add() keeps the next mesh under this key.
  const Entry* find(const PolygonTree& built, int depth);
  // Whether a mesh of about `elements` elements may be kept.
  bool keeps(size_t elements) const { return elements <= capacity_ / 16; }
  // Keeps the mesh of the polygon last looked up, whose tree was built as it was set up (not
  // deepened), unless it is too large.
  void add(const std::vector<std::array<uint32_t, 4>>& elements, const std::vector<Vec2>& treePoints);

 private:
  size_t capacity_;
  size_t kept_ = 0;  // elements, over all entries
  std::string key_;  // of the last find()
  std::unordered_map<std::string, Entry> entries_;
};

}  // namespace mesher
