#include "app/cli/scene_solve.h"

#include "app/image/atomic_file.h"
#include "engine/document/lighting.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"

#include <iostream>

namespace app {

engine::Scene loadForSolve(const std::string& path, const std::vector<std::string>& outputs, const SolveOptions& options) {
  engine::Scene scene = engine::loadScene(path, options.load);
  if (options.patchSize) engine::overridePatchSize(scene, *options.patchSize);
  for (const std::string& file : outputs)
    if (!file.empty()) checkCanWrite(file);
  return scene;
}

radiosity::SolverSettings solverSettings(const SolveOptions& options) {
  return {.graphicsProcessors = options.threads, .overshoot = true};
}

std::unique_ptr<engine::MeshAdaptation> adaptationFor(const SolveOptions& options, const engine::Scene& scene,
                                                      const engine::MeshedScene& meshed) {
  const auto settings = adaptiveSettings(options.adapt, scene);
  return settings ? std::make_unique<engine::MeshAdaptation>(scene, meshed, *settings) : nullptr;
}

uint64_t solveWithProgress(radiosity::Solver& solver, const SolveOptions& options, const std::string& command,
                           const std::string& what, std::chrono::steady_clock::time_point start,
                           engine::MeshAdaptation* adaptation) {
  using Clock = std::chrono::steady_clock;
  auto lastReport = Clock::now();
  const uint64_t shots = engine::solveTo(solver, options.converge, options.maxShots, [&](const radiosity::Solver& s, uint64_t n) {
    if (options.quiet || std::chrono::duration<double>(Clock::now() - lastReport).count() < 1) return;
    lastReport = Clock::now();
    std::cout << "walkrad " << command << ": " << n << " shots, unshot " << 100 * s.unshotFraction() << "%" << std::endl;
  }, adaptation);
  if (!options.quiet)
    std::cout << "walkrad " << command << ": " << what << " in " << std::chrono::duration<double>(Clock::now() - start).count()
              << " s: " << shots << " shots, unshot " << 100 * solver.unshotFraction() << "%, " << solver.patchCount()
              << " patches, " << solver.elementCount() << " elements" << std::endl;
  return shots;
}

}  // namespace app
