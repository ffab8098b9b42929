// The limits every loader holds a file to (scene files, glTF models, sidecars, polygon cases,
// and the command line's --patch-size), so that no file can ask for absurd values or unbounded
// work.
#pragma once

#include "engine/scene.h"

#include <cstddef>
#include <string>

namespace engine {

// Limits that make a value absurd rather than merely unusual.
constexpr double kMaxLength = 1e6;    // any coordinate or size, in scene units
constexpr double kMaxEmission = 1e6;  // radiance
// A patch size that would put more patches than this along a scene's largest extent is a typo
// (a size in metres in a scene in millimetres), not a wish.
constexpr double kMaxPatchesPerEdge = 1e5;
// Faces one file may make (a glTF model's triangles, a scene file's faces before merging): ten
// times the largest real model here (the White Room of ../shared/scenes-external, 394,000
// triangles), so that a small file that sweeps or repeats a lot cannot demand unbounded work.
constexpr size_t kMaxFaces = 4'000'000;

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

}  // namespace engine
