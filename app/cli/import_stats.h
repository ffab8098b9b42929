// What a glTF import found, as the statistics files of `render` and `mesh` list it.
#pragma once

#include "engine/scene.h"

#include <nlohmann/json.hpp>

namespace app {

// {"nodes", "triangles", "degenerate", "t_junctions", "single_triangles", "surfaces"}; null
// for a scene file.
inline nlohmann::ordered_json importStats(const engine::Scene& scene) {
  if (!scene.imported) return nullptr;
  const engine::ImportCounts& c = *scene.imported;
  return {{"nodes", c.nodes},           {"triangles", c.triangles},      {"degenerate", c.degenerate},
          {"t_junctions", c.tJunctions}, {"single_triangles", c.singles}, {"surfaces", scene.surfaces.size()}};
}

}  // namespace app
