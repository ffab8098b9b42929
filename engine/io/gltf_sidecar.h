// The sidecar of a glTF model: what a modeller's file cannot say about a model for radiosity
// (its units when the exporter did not write metres, the patch size, which materials emit or
// should be left out, which objects may be moved, a sky over open models). It is a small JSON
// file, MODEL.walkrad.json next to MODEL.gltf, read with the scene format's located errors:
//
//   { "units": "m", "patch_size": 0.5, "emission_scale": 1, "movable": true,
//     "materials": { "NAME": { "reflectance": [r, g, b], "emission": [r, g, b], "omit": false,
//                              "two_sided": false } },
//     "objects": { "NODE NAME": { "movable": false } },
//     "sky": { "emission": [r, g, b] } }
//
// Every key is optional; unknown keys are errors, as in scene files.
#pragma once

#include "engine/scene.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace engine {

struct MaterialOverride {
  std::optional<Vec3> reflectance, emission;  // replace the model's
  bool omit = false;                          // leave its triangles out (glass, say)
  bool twoSided = false;                      // its triangles face both ways (a thin partition)
};

struct GltfSidecar {
  std::string units;                 // of the model's coordinates; empty: glTF's metres
  std::optional<double> patchSize;   // scene units
  double emissionScale = 1;          // multiplies every emission the model gives
  std::optional<bool> movable;       // every object's default (else movable)
  std::map<std::string, MaterialOverride> materials;  // by glTF material name
  std::map<std::string, bool> movableObjects;         // by top-level node name
  std::optional<Vec3> sky;           // emission of a sky above the model, facing down
};

// The sidecar's path for a model: MODEL.walkrad.json beside MODEL.gltf or MODEL.glb.
std::string sidecarPathFor(const std::string& model);

// Parses a sidecar; throws SceneError naming `file` and the JSON path for anything wrong.
// Names are checked against the model by the loader.
GltfSidecar parseGltfSidecar(std::string_view text, const std::string& file);

}  // namespace engine
