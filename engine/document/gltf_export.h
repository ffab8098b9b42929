// The lit scene as glTF 2.0, so baked radiosity opens in Blender or any glTF viewer: the meshed
// surfaces with their vertex radiance in COLOR_0 under unlit materials (KHR_materials_unlit).
#pragma once

#include "engine/document/display_mesh.h"
#include "engine/scene.h"

#include <string>

namespace engine {

struct GltfExportSettings {
  // COLOR_0 is radiance times this, clamped to 0..1 (linear, as glTF wants it: a viewer shows
  // what `walkrad render` does with the same exposure). The unclamped radiance is kept too, in
  // the vertex attribute _RADIANCE.
  double exposure = 1;
  bool binary = true;  // .glb; otherwise .gltf text with the buffer inside as base64
};

// The file's bytes. `mesh` is the scene's DisplayMesh (one display per surface, in
// Scene::surfaces order) with its radiance set. One node and one mesh per object that has
// surfaces, named after it; one primitive per material the object uses, named after it; one
// glTF material per scene material, unlit, with baseColorFactor 1 so COLOR_0 is the colour
// shown. Positions are in metres (glTF's unit: scene units times Scene::metersPerUnit), float;
// indices uint32, counter-clockwise from the front (glTF's front faces); materials are one-sided
// as the scene's faces are. asset.extras holds the exposure and the scene's units; a material's
// extras its reflectance and emission.
std::string exportGltf(const Scene& scene, const DisplayMesh& mesh, const GltfExportSettings& settings = {});

}  // namespace engine
