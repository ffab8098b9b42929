#include "engine/meshed_scene.h"

namespace engine {

MeshedScene meshScene(const Scene& scene) {
  MeshedScene meshed;
  meshed.surfaces.reserve(scene.surfaces.size());
  mesher::Mesher mesher;
  for (const Surface& s : scene.surfaces) meshed.surfaces.push_back(meshSurface(s, mesher));
  return meshed;
}

std::vector<radiosity::Surface> radiosityInput(const Scene& scene, const MeshedScene& meshed) {
  std::vector<radiosity::Surface> out;
  out.reserve(scene.surfaces.size());
  for (size_t i = 0; i < scene.surfaces.size(); ++i) {
    const Surface& s = scene.surfaces[i];
    const Material& m = scene.materials[s.material];
    radiosity::Surface& r = out.emplace_back();
    r.vertices = meshed.surfaces[i].positions;
    r.elements = meshed.surfaces[i].mesh.elements;
    r.normal = s.normal;
    r.reflectance = m.reflectance;
    r.emission = m.emission;
    r.patchOfElement = radiosity::groupIntoPatches(r, kShootingPatchPatches * s.patchSize);
  }
  return out;
}

}  // namespace engine
