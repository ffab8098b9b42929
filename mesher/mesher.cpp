#include "mesher/mesher.h"

#include "mesher/balance.h"
#include "mesher/leaf_emitter.h"
#include "mesher/quadtree.h"

#include <stdexcept>

namespace mesher {

size_t Mesh::quadCount() const {
  size_t quads = 0;
  for (const auto& e : elements) quads += e[3] != kNone;
  return quads;
}

Mesh meshPolygon(const PolygonWithHoles& polygon, const MeshSettings& settings) {
  // Phases of chapter 5: tree setup, edge storage and balancing; then leaf by leaf meshing.
  const PolygonTree built = buildBalancedTree(polygon, settings.patchSize);
  const std::vector<int32_t> leaves = built.tree.leaves();
  LeafEmitter emitter(polygon, built, leaves.size());
  Mesh mesh;
  mesh.elements.reserve(leaves.size() * 2);
  for (int32_t q : leaves) emitter.emit(q, mesh.elements);
  mesh.vertices = emitter.takeVertices();
  return mesh;
}

}  // namespace mesher
