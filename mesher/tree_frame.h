// Setup of the tree (thesis section 5.1): the map from a polygon's plane coordinates into the
// quadtree's integer square [0, 2^maxDepth]^2, and the initial depth from the patch size (5.2).
#pragma once

#include "mesher/polygon.h"
#include "mesher/triangulate.h"

namespace mesher {

// The smallest a leaf may be, over its tree's rounding (TreeFrame::rounding): far from the
// origin, 1e-12 of the polygon's coordinates. Corners of elements finer than that can turn the
// other way in the plane. In 250,000 random polygons this leaves 2 elements below the bound, both
// in one polygon, and no invalid mesh; the finest leaf at 1e-8 of the coordinates left 34 in
// 40,000, and no limit (trees 50 levels deep) 345 and three invalid meshes, the smallest
// elements lost in rounding.
constexpr double kFinestLeafOverRounding = 280;

// How far an input vertex must lie from every edge not ending at it, over the rounding: 1.5e-11
// of the polygon's coordinates far from the origin. Nearer, the mesh's points along the edge
// may lie on the wrong side of the vertex, and its elements be thinner than the coordinates
// resolve. The tests' random polygons and the shipped and large models keep 1e7 and more.
constexpr double kClearanceOverRounding = 4096;

struct TreeFrame {
  int maxDepth = 0;      // beta: the root square's edge is 2^beta, the smallest quadrant's 1
  Vec2 origin{0};        // plane point that maps to the tree's (0, 0)
  Vec2 xAxis{1, 0};      // unit plane direction of the tree's x axis: along the longest edge
  double scale = 1;      // uniform scale that maps the longer extent onto the root square
  double stretch = 1;    // extra scale of the shorter axis, up to its next power of two, in [1, 2)
  int shortAxis = 1;     // the tree axis (0 = x, 1 = y) that `stretch` applies to
  // How far a tree point may lie from where its plane point does, in tree units: the rounding of
  // tree coordinates (a deep root square) and of plane coordinates (far from the origin), carried
  // through the turn and the scale, as a power of two. An element's corner must turn by more than
  // this can undo, or it may turn the other way in the plane.
  double rounding = 0;
  // Tree coordinates this close to an integer are taken to lie on that grid line: 1e-6 tree
  // units, or the rounding where that is coarser, so points that belong on a line are not left
  // a rounding error off it.
  double gridSnap = 1e-6;

  Vec2 yAxis() const { return {-xAxis.y, xAxis.x}; }
  // The deepest level whose quadrants are at least kFinestLeafOverRounding times the rounding:
  // no leaf is split finer. maxDepth unless the polygon lies far from the origin against its
  // size; -1 for a frame whose scale rounding has lost (a polygon thinner than its coordinates
  // resolve).
  int finestLevel() const;
  Vec2 toTree(Vec2 plane) const;
  Vec2 toPlane(Vec2 tree) const;
  // Length in plane units of one tree unit along each tree axis.
  Vec2 planePerTree() const;
};

// Turns the polygon so that its longest outer edge runs along +x (exactly, when that edge is
// axis-aligned), then scales it per axis (5.1): the longer extent onto 2^maxDepth, the shorter
// one by the same factor and then up to the next power of two. The polygon must have area.
TreeFrame setupTreeFrame(const PolygonWithHoles& polygon, int maxDepth);

// Tree depth lambda = min(beta, ceil(log2(longerExtent / patchSize))) (equation 5.2), at least 0.
int initialDepth(double longerExtent, double patchSize, int maxDepth);

}  // namespace mesher
