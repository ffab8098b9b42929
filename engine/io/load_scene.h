// Loading any file walkrad takes as a scene, by its extension: a glTF model (.gltf, .glb:
// gltf_loader.h) or a walkrad-scene/1 file (scene_loader.h).
#pragma once

#include "engine/io/gltf_loader.h"
#include "engine/scene.h"

#include <string>

namespace engine {

// Reads, validates and builds the surfaces of a scene file or a glTF model. Throws SceneError
// (file, JSON path, problem) for anything that breaks the spec, and GltfOnly for options given
// with a scene file; nothing is returned half-loaded.
Scene loadScene(const std::string& path, const LoadOptions& options = {});

// The model as it was described, for checks (walkrad check): a scene file's faces
// (parseSceneFaces), a glTF model's triangles (loadGltfFaces).
Scene loadSceneFaces(const std::string& path, const LoadOptions& options = {});

// Throws GltfOnly when `options` give units or a sidecar for a scene file, which states its own
// units and needs no sidecar.
void refuseGltfOptions(const std::string& path, const LoadOptions& options);

}  // namespace engine
