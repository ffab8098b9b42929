// `walkrad render`: a headless image of a scene (spec/cli.md).
#pragma once

#include "engine/scene_loader.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace app {

struct RenderOptions {
  std::string scene;
  engine::LoadOptions load;  // glTF: units and sidecar
  std::string out;     // PNG, tone-mapped sRGB
  std::string linear;  // PFM, radiance
  std::string camera;  // empty: the scene's default
  std::string stats;   // JSON statistics
  int width = 640, height = 480;
  bool wireframe = false;
  std::optional<double> exposure;  // none: automatic
  std::optional<double> patchSize; // none: the scene's
  double converge = 0.01;          // shoot until the unshot fraction is below this
  uint64_t maxShots = UINT64_MAX;  // or until this many shots
  int threads = 1;                 // pxpl5 graphics processors
  bool quiet = false;              // no progress lines (stdout)
  std::vector<std::string> moves;  // OBJECT:DX,DY,DZ, applied in order after converging
};

// Runs the command; returns the process exit code (0, 2 for bad input, 1 otherwise), having
// printed one line on stderr for any failure.
int runRender(const RenderOptions& options);

}  // namespace app
