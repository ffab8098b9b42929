#include "engine/geometry/meshed_scene.h"

#include <algorithm>
#include <string>

namespace engine {

void addEdits(std::vector<EditedSurface>& edits, std::span<const EditedSurface> more) {
  for (const EditedSurface& e : more) {
    const auto at = std::lower_bound(edits.begin(), edits.end(), e.surface,
                                     [](const EditedSurface& a, uint32_t surface) { return a.surface < surface; });
    if (at != edits.end() && at->surface == e.surface) {
      at->meshedAnew = at->meshedAnew || e.meshedAnew;
      at->holesChanged = at->holesChanged || e.holesChanged;
    } else {
      edits.insert(at, e);
    }
  }
}

MeshedScene meshScene(const Scene& scene, size_t* repeats) {
  MeshedScene meshed;
  meshed.surfaces.reserve(scene.surfaces.size());
  mesher::Mesher mesher;
  size_t elements = 0;
  for (const Surface& s : scene.surfaces) {
    try {
      meshed.surfaces.push_back(meshSurface(s, mesher));
    } catch (const mesher::MeshRefused& refused) {
      throw meshRefusal(refused, scene.file, s.jsonPath);
    }
    elements += meshed.surfaces.back().mesh.elements.size();
    if (elements > kMaxSceneElements)
      throw SceneError(Diag::MeshTooLarge, scene.file, s.jsonPath, "the scene's meshes pass " + std::to_string(kMaxSceneElements) + " elements here");
  }
  if (repeats) *repeats = mesher.repeats();
  return meshed;
}

radiosity::Surface radiosityInput(const Scene& scene, const MeshedScene& meshed, size_t surface) {
  const Surface& s = scene.surfaces[surface];
  const Material& m = scene.materials[s.material];
  radiosity::Surface r;
  r.vertices = meshed.surfaces[surface].positions;
  r.elements = meshed.surfaces[surface].mesh.elements;
  r.keys = meshed.surfaces[surface].keys;
  r.normal = s.normal;
  r.reflectance = m.reflectance;
  r.emission = m.emission;
  r.patchOfElement = radiosity::groupIntoPatches(r, kShootingPatchPatches * s.patchSize);
  return r;
}

std::vector<radiosity::Surface> radiosityInput(const Scene& scene, const MeshedScene& meshed) {
  std::vector<radiosity::Surface> out;
  out.reserve(scene.surfaces.size());
  for (size_t i = 0; i < scene.surfaces.size(); ++i) out.push_back(radiosityInput(scene, meshed, i));
  return out;
}

std::vector<radiosity::SurfaceChange> radiosityChanges(const Scene& scene, const MeshedScene& meshed,
                                                       std::span<const EditedSurface> edited) {
  std::vector<radiosity::SurfaceChange> changes;
  changes.reserve(edited.size());
  for (const EditedSurface& e : edited) changes.push_back({e.surface, radiosityInput(scene, meshed, e.surface), e.meshedAnew});
  return changes;
}

}  // namespace engine
