#include "engine/io/load_limits.h"

#include "engine/diagnostics.h"

#include <cmath>

namespace engine {

void checkPatchSize(double patchSize, double extent, const std::string& file, const std::string& place) {
  if (std::isnan(patchSize) || extent / patchSize > kMaxPatchesPerEdge)
    throw SceneError(Diag::PatchTooSmall, file, place, "scene extent " + std::to_string(extent));
}

void checkFaceCount(size_t faces, const std::string& file, const std::string& place) {
  if (faces > kMaxFaces)
    throw SceneError(Diag::TooManyFaces, file, place, std::to_string(faces) + " faces by here, at most " + std::to_string(kMaxFaces));
}

void overridePatchSize(Scene& scene, double patchSize) {
  checkPatchSize(patchSize, sceneExtent(scene), scene.file, "--patch-size");
  scene.patchSize = patchSize;
  for (Surface& s : scene.surfaces) s.patchSize = patchSize;
}

}  // namespace engine
