// Independent checks of a mesh against its polygon: tiling, conformity, exactness. They share no
// code with the mesher beyond the plain data types.
#pragma once

#include "mesher/mesher.h"

#include <string>

namespace mesher::test {

struct MeshCheck {
  double elementArea = 0, polygonArea = 0;
  size_t notCounterClockwiseOrConvex = 0;
  size_t movedInputVertices = 0;
  size_t tVertices = 0;             // mesh vertices inside another element's edge
  size_t unmatchedInnerEdges = 0;   // edges used once that do not lie on the polygon's boundary
  size_t repeatedEdges = 0;         // a directed edge used by two elements (overlap)
  double largestDiameter = 0;
  double smallestAngleDeg = 180;
};

MeshCheck checkMesh(const PolygonWithHoles& polygon, const Mesh& mesh);

}  // namespace mesher::test
