// `walkrad mesh`: meshes a scene or one polygon case and reports on the mesh (spec/cli.md).
#pragma once

#include "engine/io/load_scene.h"

#include <optional>
#include <string>

namespace app {

struct MeshOptions {
  std::string input;                 // a scene file, a glTF model or a polygon case
  engine::LoadOptions load;          // glTF: units and sidecar
  std::optional<double> patchSize;   // overrides the input's
  std::string dump;                  // the mesh as JSON
  std::string stats;                 // statistics as JSON
  int repeat = 1;                    // mesh this many times; mesh_ms is the best
};

// Runs the command; returns the process exit code, having printed one line on stderr for any
// failure. Prints a one-line summary on stdout.
int runMesh(const MeshOptions& options);

}  // namespace app
