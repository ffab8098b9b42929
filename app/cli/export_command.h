// `walkrad export`: the meshed, solved scene as glTF with its light baked into vertex colours
// (engine/document/gltf_export.h), for Blender or any glTF viewer.
#pragma once

#include "app/cli/scene_solve.h"

#include <optional>
#include <string>

namespace app {

struct ExportOptions {
  std::string scene;
  std::string out;                 // .glb (binary) or .gltf (text, buffer inside)
  std::optional<double> exposure;  // none: automatic, as `walkrad render` chooses it
  SolveOptions solve;
};

// Runs the command; returns the process exit code (0, 2 for bad input, 1 otherwise), having
// printed one line on stderr for any failure.
int runExport(const ExportOptions& options);

}  // namespace app
