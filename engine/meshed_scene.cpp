#include "engine/meshed_scene.h"

namespace engine {

MeshedScene meshScene(const Scene& scene) {
  MeshedScene meshed;
  meshed.surfaces.reserve(scene.surfaces.size());
  mesher::Mesher mesher;
  for (const Surface& s : scene.surfaces) meshed.surfaces.push_back(meshSurface(s, mesher));
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
