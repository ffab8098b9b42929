#include "engine/io/load_scene.h"

#include "engine/diagnostics.h"
#include "engine/io/input_file.h"
#include "engine/io/scene_loader.h"

namespace engine {

Scene loadScene(const std::string& path, const LoadOptions& options) {
  if (isGltfPath(path)) return loadGltf(path, options);
  refuseGltfOptions(path, options);
  return parseScene(readInputFile(path), path);
}

Scene loadSceneFaces(const std::string& path, const LoadOptions& options) {
  if (isGltfPath(path)) return loadGltfFaces(path, options);
  refuseGltfOptions(path, options);
  return parseSceneFaces(readInputFile(path), path);
}

void refuseGltfOptions(const std::string& path, const LoadOptions& options) {
  if (!options.units.empty()) throw SceneError(Diag::GltfOnly, path, "--units", "a scene file states its own units");
  if (!options.sidecar.empty()) throw SceneError(Diag::GltfOnly, path, "--sidecar");
}

}  // namespace engine
