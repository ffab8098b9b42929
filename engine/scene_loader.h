// Reading walkrad-scene/1 files (spec/scene-format.md) into a fully validated Scene.
#pragma once

#include "engine/scene.h"

#include <string>
#include <string_view>

namespace engine {

// Limits that make a value absurd rather than merely unusual, in every loader (scene files,
// glTF models, sidecars).
constexpr double kMaxLength = 1e6;    // any coordinate or size, in scene units
constexpr double kMaxEmission = 1e6;  // radiance
// A patch size that would put more patches than this along a scene's largest extent is a typo
// (a size in metres in a scene in millimetres), not a wish.
constexpr double kMaxPatchesPerEdge = 1e5;
// Faces one file may make (a glTF model's triangles, a scene file's faces before merging): ten
// times the largest real model here (the White Room of ../shared/scenes-external, 394,000
// triangles), so that a small file that sweeps or repeats a lot cannot demand unbounded work.
constexpr size_t kMaxFaces = 4'000'000;

// What the command line may add to a model file.
struct LoadOptions {
  std::string units;    // glTF only: the units of the model's coordinates (else the sidecar's, else m)
  std::string sidecar;  // glTF only: this sidecar instead of MODEL.walkrad.json beside the model
};

// Reads, validates and builds the surfaces of a scene file, or of a glTF model (.gltf, .glb:
// gltf_loader.h). Throws SceneError (file, JSON path, problem) for anything that breaks the
// spec, and GltfOnly for options given with a scene file; nothing is returned half-loaded.
Scene loadScene(const std::string& path, const LoadOptions& options = {});

// The same for scene text already in memory; `file` names it in messages.
Scene parseScene(std::string_view text, const std::string& file);

// The two halves of loadScene, for tools that look at a model as it was described (walkrad
// check). loadSceneFaces reads and validates like loadScene but leaves Scene::surfaces as the
// faces themselves, one surface per face and per filled hole, in file order. preprocessSurfaces
// then makes them the surfaces that are meshed: coplanar merging (thesis 3.2) and contact
// cut-outs. loadScene is the one followed by the other. A glTF model's faces are its triangles
// (loadGltfFaces).
Scene loadSceneFaces(const std::string& path, const LoadOptions& options = {});
Scene parseSceneFaces(std::string_view text, const std::string& file);
void preprocessSurfaces(Scene& scene);

// Throws GltfOnly when `options` give units or a sidecar for a scene file, which states its own
// units and needs no sidecar.
void refuseGltfOptions(const std::string& path, const LoadOptions& options);

// Throws SceneError (PatchTooSmall, naming `file` and `place`) when `patchSize` would put more
// than kMaxPatchesPerEdge patches along `extent`. Every patch size a user gives passes here: a
// scene file's, a sidecar's, a polygon case's and --patch-size.
void checkPatchSize(double patchSize, double extent, const std::string& file, const std::string& place);

// Throws SceneError (TooManyFaces, naming `file` and `place`, what brought the count there) when
// `faces` is beyond kMaxFaces. The loaders call it as they make faces, so the refusal comes
// before the work.
void checkFaceCount(size_t faces, const std::string& file, const std::string& place);

// --patch-size: every surface of a loaded scene gets `patchSize`, refused as the file's own
// would be (SceneError at place "--patch-size").
void overridePatchSize(Scene& scene, double patchSize);

// The largest side of the scene's bounding box (Scene::computeBounds), in scene units.
double sceneExtent(const Scene& scene);

// The whole text of a file (input_file.h: a regular file of at most kMaxInputFileBytes, opened
// without blocking); throws SceneError naming it when it cannot be read (FileUnreadable,
// NotRegularFile, FileTooLarge).
std::string readInputFile(const std::string& path);

// Metres per unit for a `units` value, or 0 when unknown.
double metersPerUnit(std::string_view units);

}  // namespace engine
