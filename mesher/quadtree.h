// The spatial decomposition of chapter 5: a PM quadtree (Samet and Webber 1985) over a polygon
// with holes, in the integer square of a TreeFrame. Leaves store the input vertices and edges
// under the decomposition rules of section 5.2 and are classified inside, outside or boundary.
#pragma once

#include "mesher/tree_frame.h"
#include "mesher/triangulate.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace mesher {

enum class QuadStatus : uint8_t { Node, Undefined, Outside, Boundary, Inside };

struct Quadrant {
  int64_t x = 0, y = 0;             // lower-left corner, tree units
  int level = 0;                    // 0 is the root; its edge is 2^(maxDepth - level)
  int32_t firstChild = -1;          // children at firstChild + 0..3: SW, SE, NW, NE; -1: a leaf
  int32_t parent = -1;
  QuadStatus status = QuadStatus::Undefined;
  int32_t vertex = -1;              // the input vertex in the closed square, if any
  uint8_t edgeCount = 0;
  std::array<uint32_t, 2> edges{};  // input edges through the open square

  bool isLeaf() const { return firstChild < 0; }
};

// Edge e runs from vertex edges[e][0] to edges[e][1] with the polygon's inside on its left
// (outer ring counter-clockwise, holes clockwise).
struct QuadtreeInput {
  std::vector<Vec2> vertices;                      // tree coordinates, outer ring first, then holes
  std::vector<std::array<uint32_t, 2>> edges;
};

struct Quadtree {
  int maxDepth = 0;
  std::vector<Quadrant> quadrants;  // [0] is the root
  QuadtreeInput input;

  int64_t edgeLength(const Quadrant& q) const { return int64_t{1} << (maxDepth - q.level); }
  // Leaves only, in tree order.
  std::vector<int32_t> leaves() const;
  // The leaf whose half-open square [x, x + s) x [y, y + s) holds p; -1 outside the root.
  int32_t leafAt(Vec2 p) const;
};

// Orients and numbers the polygon's rings into quadtree input (tree coordinates via `frame`).
QuadtreeInput quadtreeInput(const PolygonWithHoles& polygon, const TreeFrame& frame);

// Subdivides the root uniformly to `depth`, stores every vertex and edge under the rules of 5.2:
// a leaf holds at most one distinct vertex (in its closed square); with a vertex, only edges
// ending at it; without one, at most one edge. Leaves holding edges are Boundary; every other
// leaf is Inside or Outside by its centre. Returns nothing when two vertices cannot be separated
// within maxDepth levels (the caller builds a deeper tree: vertices are never merged).
std::optional<Quadtree> buildQuadtree(QuadtreeInput input, int maxDepth, int depth);

// A polygon's tree for a patch size: the frame of 5.1, the depth of 5.2, and a maximum depth
// that starts 16 levels below the patch size and grows by 8 (up to 50) whenever two vertices
// cannot be separated. Throws std::invalid_argument for a polygon no depth can store (repeated
// or crossing vertices).
struct PolygonTree {
  TreeFrame frame;
  int depth = 0;  // lambda: the uniform depth of the patch size
  Quadtree tree;
};
PolygonTree buildPolygonTree(const PolygonWithHoles& polygon, double patchSize);

// True when segment a-b passes through the open square [x0, x1] x [y0, y1] (touching its border
// only does not count).
bool segmentCrossesOpenSquare(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1);

}  // namespace mesher
