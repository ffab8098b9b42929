// Independent checks of a mesh against its polygon: tiling, conformity, exactness, quality.
// They share no code with the mesher beyond its plain data types, so tests and `walkrad mesh
// --stats` count T-vertices without trusting the mesher's own bookkeeping.
#pragma once

#include "mesher/mesher.h"

namespace mesher {

struct MeshCheck {
  double elementArea = 0, polygonArea = 0;
  // How far elementArea may lie from polygonArea in a tiling: 1e-9 of it, and what moving the
  // mesh's points on the boundary as far off it as a point on an edge may lie (1e-12 of the
  // coordinates) changes: much of the area of a thin polygon.
  double areaTolerance = 0;
  size_t notCounterClockwiseOrConvex = 0;
  size_t movedInputVertices = 0;
  size_t tVertices = 0;             // mesh vertices inside another element's edge
  size_t unmatchedInnerEdges = 0;   // edges used once that do not lie on the polygon's boundary
  size_t repeatedEdges = 0;         // a directed edge used by two elements (overlap)
  double largestDiameter = 0;
  double smallestAngleDeg = 180;
  // Elements with an angle below kAngleBoundDeg other than at an input corner that is sharper.
  size_t belowAngleBound = 0;
  // The thesis' shape measure, inscribed over circumscribed radius, scaled so an equilateral
  // triangle has 1 (2r/R); a quad counts as the better of its two splits along a diagonal, each
  // as its worse triangle (a square: 0.83).
  double smallestAspectRatio = 1;
};

// Whether the elements tile the polygon exactly with convex counter-clockwise elements, no
// T-vertex, no overlap, its points first and unmoved.
bool valid(const MeshCheck& check);

// Runs every check, in time and memory about linear in the mesh's size (edges are bucketed on
// grids of their own sizes; vertices are looked up against edges used once).
MeshCheck checkMesh(const PolygonWithHoles& polygon, const Mesh& mesh);

}  // namespace mesher
