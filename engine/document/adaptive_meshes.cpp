#include "engine/document/adaptive_meshes.h"

namespace engine {

namespace {

// An adaptive mesh of `surfaceMesh`'s polygon, its last `removableHoles` holes removable, when it
// is that mesh, element for element under the same keys; else null.
std::unique_ptr<mesher::AdaptiveMesh> adaptiveMeshOf(const SurfaceMesh& surfaceMesh, double patchSize,
                                                     size_t removableHoles) {
  if (removableHoles > surfaceMesh.polygon.holes.size()) return nullptr;
  try {
    auto adaptive =
        std::make_unique<mesher::AdaptiveMesh>(surfaceMesh.polygon, mesher::MeshSettings{patchSize}, removableHoles);
    const mesher::Mesh snapshot = adaptive->snapshot();
    if (snapshot.elements == surfaceMesh.mesh.elements && snapshot.vertices == surfaceMesh.mesh.vertices &&
        elementKeys(adaptive->elements()) == surfaceMesh.keys)
      return adaptive;
  } catch (const mesher::MeshRefused&) {
  }
  return nullptr;
}

}  // namespace

AdaptiveMeshes::AdaptiveMeshes(size_t surfaces) : unadaptable_(surfaces, 0) {}

AdaptiveMeshes::~AdaptiveMeshes() = default;

mesher::AdaptiveMesh* AdaptiveMeshes::get(uint32_t s, const Surface& surface, const SurfaceMesh& mesh) {
  if (mesher::AdaptiveMesh* found = find(s)) return found;
  if (unadaptable_[s]) return nullptr;
  std::unique_ptr<mesher::AdaptiveMesh> made = adaptiveMeshOf(mesh, surface.patchSize, surface.contactHoles);
  if (!made) {
    unadaptable_[s] = 1;
    return nullptr;
  }
  // The footprints were made with the mesh: ids 0 to contactHoles - 1 (AdaptiveMesh).
  std::vector<int> footprints(surface.contactHoles);
  for (size_t k = 0; k < footprints.size(); ++k) footprints[k] = static_cast<int>(k);
  Entry& entry = entries_[s];
  entry = {std::move(made), std::move(footprints)};
  return entry.mesh.get();
}

mesher::AdaptiveMesh* AdaptiveMeshes::find(uint32_t s) const {
  const auto found = entries_.find(s);
  return found == entries_.end() ? nullptr : found->second.mesh.get();
}

void AdaptiveMeshes::forget(uint32_t s) {
  entries_.erase(s);
  unadaptable_[s] = 0;
}

void takeAdaptiveMesh(const Surface& surface, const mesher::AdaptiveMesh& adaptive, SurfaceMesh& mesh) {
  mesh.mesh = adaptive.snapshot();
  mesh.keys = elementKeys(adaptive.elements());
  addWorldPositions(surface, mesh);  // the vertices it had keep theirs
}

}  // namespace engine
