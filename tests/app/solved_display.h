// The solved light on the display mesh, for tests that check pictures of a solution.
#pragma once

#include "engine/document/display_mesh.h"
#include "engine/document/lighting.h"
#include "engine/geometry/meshed_scene.h"

#include <cstdint>

namespace app::test {

// The display mesh of `meshed` (meshed from `scene`) with the light of a solve until 1% of the
// emitted power is unshot, on two graphics processors.
inline engine::DisplayMesh solvedDisplayMesh(const engine::Scene& scene, const engine::MeshedScene& meshed) {
  engine::DisplayMesh mesh = engine::displayMesh(scene, meshed);
  radiosity::SolverSettings settings;
  settings.graphicsProcessors = 2;
  radiosity::Solver solver(engine::radiosityInput(scene, meshed), settings);
  engine::solveTo(solver, 0.01, UINT64_MAX);
  engine::setRadiance(mesh, solver);
  return mesh;
}

}  // namespace app::test
