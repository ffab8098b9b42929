#include "engine/geometry/mesh_quality.h"

#include "mesher/mesh_check.h"

#include <algorithm>

namespace engine {

void MeshQuality::add(const mesher::PolygonWithHoles& polygon, const mesher::Mesh& mesh) {
  const mesher::MeshCheck check = mesher::checkMesh(polygon, mesh);
  elements += mesh.elements.size();
  quads += mesh.quadCount();
  vertices += mesh.vertices.size();
  tVertices += check.tVertices;
  belowAngleBound += check.belowAngleBound;
  smallestAngleDeg = std::min(smallestAngleDeg, check.smallestAngleDeg);
  smallestAspectRatio = std::min(smallestAspectRatio, check.smallestAspectRatio);
}

}  // namespace engine
