// `walkrad view`: the walkthrough window (GLFW + Dear ImGui).
#pragma once

#include "app/cli/adapt_options.h"
#include "engine/document/lighting.h"
#include "engine/io/load_scene.h"

#include <optional>
#include <string>

namespace app {

struct ViewOptions {
  std::string scene;
  engine::LoadOptions load;  // glTF: units and sidecar
  std::optional<double> patchSize;  // none: the scene's
  std::string camera;      // empty: the scene's default
  int width = 1280, height = 720;
  int frames = 0;          // > 0: close after this many frames (scripts, tests)
  std::string screenshot;  // with `frames`: save the last frame here
  bool wireframe = false;  // start with the mesh edges drawn
  std::string stats;       // when not empty: frame times and memory written here as JSON at the end
  engine::LightingSettings lighting;  // the solver thread's (its `adaptive` from `adapt` and the scene)
  AdaptOptions adapt;                 // adaptive refinement while solving
};

// Runs the window until it is closed; returns the process exit code, having printed one line on
// stderr for any failure (2 for bad input, 1 when no window can be opened).
int runView(const ViewOptions& options);

}  // namespace app
