// `walkrad check`: lists what is wrong with a model for lighting (engine/geometry/model_check.h), with
// where it is and what walkrad does about it.
#pragma once

#include "engine/io/load_scene.h"

#include <string>

namespace app {

struct CheckOptions {
  std::string model;          // a scene file or a glTF model
  std::string json;           // the findings as JSON
  engine::LoadOptions load;   // glTF: units and sidecar
};

// Runs the command; returns the process exit code: 0 when the model could be checked (whatever
// was found), 2 for bad input, 1 when the JSON cannot be written. Prints one line per finding
// and a count per kind on stdout.
int runCheck(const CheckOptions& options);

}  // namespace app
