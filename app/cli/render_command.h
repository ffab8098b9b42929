// `walkrad render`: a headless image of a scene (spec/cli.md).
#pragma once

#include "app/cli/scene_solve.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace app {

struct RenderOptions {
  std::string scene;
  std::string out;     // PNG, tone-mapped sRGB
  std::string linear;  // PFM, radiance
  std::string camera;  // empty: the scene's default
  std::string stats;   // JSON statistics
  int width = 640, height = 480;
  bool wireframe = false;
  std::optional<double> exposure;  // none: automatic
  SolveOptions solve;
  std::vector<std::string> moves;  // OBJECT:DX,DY,DZ, applied in order after converging
};

// Runs the command; returns the process exit code (0, 2 for bad input, 1 otherwise), having
// printed one line on stderr for any failure.
int runRender(const RenderOptions& options);

}  // namespace app
