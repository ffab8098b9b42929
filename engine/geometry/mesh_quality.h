// What meshes are like, summed over the polygons meshed (`walkrad mesh --stats`): their sizes,
// and their T-vertices and angles as the independent check of mesher/mesh_check.h counts them,
// without trusting the mesher's own bookkeeping.
#pragma once

#include "mesher/mesher.h"

#include <cstddef>

namespace engine {

struct MeshQuality {
  size_t elements = 0, quads = 0, vertices = 0;
  size_t tVertices = 0;        // mesh vertices inside another element's edge
  size_t belowAngleBound = 0;  // elements with an angle below mesher::kAngleBoundDeg (not at a sharper input corner)
  double smallestAngleDeg = 180;
  double smallestAspectRatio = 1;  // the thesis' 2r/R (mesher::MeshCheck)

  // Adds `mesh`, the mesh of `polygon` (both in plane coordinates), to the sums.
  void add(const mesher::PolygonWithHoles& polygon, const mesher::Mesh& mesh);
};

}  // namespace engine
