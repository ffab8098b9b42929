// Speed of the radiosity solver (issue 5, point 5): time to 1% unshot energy and shots per
// second for shipped scenes meshed at their patch sizes, shooting patches twice that across,
// with one and two pxpl5 graphics processors. Meshing is outside the timing.
// Run: build/tests/walkrad_bench --benchmark_filter=radiosity
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"
#include "radiosity/radiosity.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

const char* const kScenes[] = {"cornell.json", "office.json", "kitchen.json"};

std::vector<radiosity::Surface> meshedScene(const char* name) {
  const engine::Scene scene = engine::loadScene(std::string(WALKRAD_ASSETS) + "/" + name);
  return engine::radiosityInput(scene, engine::meshScene(scene));
}

// range(0): scene; range(1): graphics processors.
void radiosityToOnePercent(benchmark::State& state) {
  const char* name = kScenes[state.range(0)];
  const std::vector<radiosity::Surface> surfaces = meshedScene(name);
  radiosity::SolverSettings settings;
  settings.graphicsProcessors = static_cast<int>(state.range(1));
  settings.overshoot = true;  // as the application solves
  radiosity::Stats stats;
  size_t elements = 0, patches = 0;
  for (auto _ : state) {
    radiosity::Solver solver(surfaces, settings);
    solver.solve(0.01);
    stats = solver.stats();
    elements = solver.elementCount();
    patches = solver.patchCount();
  }
  state.SetLabel(name);
  state.counters["elements"] = static_cast<double>(elements);
  state.counters["patches"] = static_cast<double>(patches);
  state.counters["shots"] = static_cast<double>(stats.shots);
  state.counters["shots/s"] = static_cast<double>(stats.shots) / stats.seconds;
  state.counters["frames"] = static_cast<double>(stats.frames);
  state.counters["reused"] = static_cast<double>(stats.reusedShots);
  state.counters["near/shot"] = static_cast<double>(stats.nearReceivers) / static_cast<double>(stats.shots);
  state.counters["small/shot"] = static_cast<double>(stats.smallReceivers) / static_cast<double>(stats.shots);
  state.counters["split"] = static_cast<double>(stats.splitPatches);
  state.counters["renormalised"] = static_cast<double>(stats.renormalisedShots);
}
BENCHMARK(radiosityToOnePercent)->ArgsProduct({{0, 1, 2}, {1, 2}})->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
