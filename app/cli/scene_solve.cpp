#include "app/cli/scene_solve.h"

#include "engine/io/atomic_file.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"

#include <iostream>

namespace app {

engine::Scene loadForSolve(const std::string& path, const std::vector<std::string>& outputs, const SolveOptions& options) {
  engine::Scene scene = engine::loadScene(path, options.load);
  if (options.patchSize) engine::overridePatchSize(scene, *options.patchSize);
  for (const std::string& file : outputs)
    if (!file.empty()) engine::checkCanWrite(file);
  return scene;
}

engine::LitSceneSettings litSceneSettings(const SolveOptions& options, const engine::Scene& scene) {
  return {.solver = {.graphicsProcessors = options.threads, .overshoot = true}, .adaptive = adaptiveSettings(options.adapt, scene)};
}

uint64_t solveWithProgress(engine::LitScene& document, const SolveOptions& options, const std::string& command,
                           const std::string& what, std::chrono::steady_clock::time_point start) {
  using Clock = std::chrono::steady_clock;
  auto lastReport = Clock::now();
  const uint64_t shots = document.solve(options.converge, options.maxShots, [&](const radiosity::Solver& s, uint64_t n) {
    if (options.quiet || std::chrono::duration<double>(Clock::now() - lastReport).count() < 1) return;
    lastReport = Clock::now();
    std::cout << "walkrad " << command << ": " << n << " shots, unshot " << 100 * s.unshotFraction() << "%" << std::endl;
  });
  const radiosity::Solver& solver = document.solver();
  if (!options.quiet)
    std::cout << "walkrad " << command << ": " << what << " in " << std::chrono::duration<double>(Clock::now() - start).count()
              << " s: " << shots << " shots, unshot " << 100 * solver.unshotFraction() << "%, " << solver.patchCount()
              << " patches, " << solver.elementCount() << " elements" << std::endl;
  return shots;
}

}  // namespace app
