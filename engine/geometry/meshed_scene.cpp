#include "engine/geometry/meshed_scene.h"

#include <string>

namespace engine {

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

}  // namespace engine
