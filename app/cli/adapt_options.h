// The command line's say on adaptive refinement (render and view): --adapt-threshold and
// --min-element turn it on (the scene's settings.adaptive fill what they leave), --no-adapt
// turns it off, and without any of them the scene decides.
#pragma once

#include "engine/scene.h"

#include <optional>

namespace app {

struct AdaptOptions {
  std::optional<double> threshold;       // --adapt-threshold
  std::optional<double> minElementSize;  // --min-element
  bool off = false;                      // --no-adapt
};

// The refinement to run while solving `scene`, or none.
std::optional<engine::AdaptiveSettings> adaptiveSettings(const AdaptOptions& options, const engine::Scene& scene);

}  // namespace app
