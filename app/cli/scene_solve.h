// What `walkrad render` and `walkrad export` share: the scene loaded with the command's
// overrides, and the solve with its progress lines.
#pragma once

#include "app/cli/adapt_options.h"
#include "engine/document/lit_scene.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"
#include "engine/scene.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace app {

struct SolveOptions {
  std::optional<double> patchSize;  // none: the scene's
  double converge = 0.01;           // shoot until the unshot fraction is below this
  uint64_t maxShots = UINT64_MAX;   // or until this many shots
  int threads = 1;                  // pxpl5 graphics processors
  bool quiet = false;               // no progress lines (stdout)
  AdaptOptions adapt;               // adaptive refinement while solving
  engine::LoadOptions load;         // glTF: units and sidecar
};

// Loads the scene and applies the options' patch-size override (SceneError for bad input), then
// checks that each non-empty `outputs` can be written (std::runtime_error naming it): bad input
// is reported before an unwritable output, and both before the long part.
engine::Scene loadForSolve(const std::string& path, const std::vector<std::string>& outputs, const SolveOptions& options);

// How to light `scene` for the options: their graphics processors, with overshooting (the
// application's choice; radiosity/overshoot.h), and the adaptive refinement the options and the
// scene's settings ask for.
engine::LitSceneSettings litSceneSettings(const SolveOptions& options, const engine::Scene& scene);

// Shoots until the options' convergence or shot limit (LitScene::solve). Unless quiet, prints
// "walkrad COMMAND: N shots, unshot X%" about once a second and at the end "walkrad COMMAND:
// WHAT in S s: ..." with the time since `start`. Returns the shots taken.
uint64_t solveWithProgress(engine::LitScene& document, const SolveOptions& options, const std::string& command,
                           const std::string& what, std::chrono::steady_clock::time_point start);

}  // namespace app
