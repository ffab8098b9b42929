// Speed of the modified quadtree mesher (thesis chapter 5, figure 6.1).
// Run: build/tests/walkrad_bench --benchmark_filter=mesh (figures in docs/BENCHMARKS.md).
#include "engine/geometry/surface_mesh.h"
#include "engine/io/load_scene.h"
#include "mesher/adaptive_mesh.h"
#include "mesher/mesher.h"

#include <benchmark/benchmark.h>

namespace {

// The kitchen at the thesis' patch sizes (figure 6.1: 24, 20, 16, 12 and 8 inches), as a scene
// is loaded: one Mesher for all its surfaces, which gives repeats of a surface met before its
// mesh (memo:1), or meshes every surface (memo:0).
void meshKitchen(benchmark::State& state) {
  engine::Scene scene = engine::loadScene(std::string(WALKRAD_ASSETS) + "/kitchen.json");
  for (engine::Surface& s : scene.surfaces) s.patchSize = static_cast<double>(state.range(0));
  size_t elements = 0;
  for (auto _ : state) {
    elements = 0;
    mesher::Mesher mesher(state.range(1) ? mesher::Mesher::kRememberedElements : 0);
    for (const engine::Surface& s : scene.surfaces) elements += engine::meshSurface(s, mesher).mesh.elements.size();
  }
  state.counters["elements"] = static_cast<double>(elements);
  state.counters["elements/s"] = benchmark::Counter(static_cast<double>(elements), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(meshKitchen)->ArgNames({"inches", "memo"})->ArgsProduct({{24, 20, 16, 12, 8}, {1, 0}})->Unit(benchmark::kMillisecond);

// One floor with two holes, from 10 thousand to about a million elements: time per element
// should stay flat (linear growth). reuse:1 meshes into the same Mesher and Mesh each time (a caller
// that keeps its output buffers; the engine keeps the Mesher only); reuse:0 is the one-shot meshPolygon, which also
// pays the kernel for fresh pages once the arrays outgrow the allocator's heap.
void meshFloor(benchmark::State& state) {
  const mesher::PolygonWithHoles floor{{{0, 0}, {45, 0}, {45, 45}, {0, 45}},
                                       {{{10, 10}, {10, 12}, {13, 12}, {13, 10}}, {{30.3, 20.1}, {31.7, 22.2}, {33, 20}}}};
  const mesher::MeshSettings settings{45.0 / static_cast<double>(state.range(0))};
  mesher::Mesher mesher;
  mesher::Mesh mesh;
  // Reuse is measured from the second mesh on: a million elements take only a few iterations,
  // and the first one's fresh pages (more than 100 MB) would otherwise count as half of them.
  if (state.range(1)) mesher.mesh(floor, settings, mesh);
  for (auto _ : state) {
    if (state.range(1)) mesher.mesh(floor, settings, mesh);
    else mesh = mesher::meshPolygon(floor, settings);
  }
  const auto elements = static_cast<double>(mesh.elements.size());
  state.counters["elements"] = elements;
  state.counters["elements/s"] = benchmark::Counter(elements, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ns/element"] = benchmark::Counter(elements, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(meshFloor)->ArgNames({"patches", "reuse"})->ArgsProduct({{100, 200, 450, 1000}, {1, 0}})->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

// One local refine followed by the coarsen that undoes it, each with its rebalance and re-emit,
// on a floor of 40,000 elements; the time is per operation (half a pair).
void refineAndCoarsen(benchmark::State& state) {
  const mesher::PolygonWithHoles floor{{{0, 0}, {45, 0}, {45, 45}, {0, 45}}, {{{10, 10}, {10, 12}, {13, 12}, {13, 10}}}};
  mesher::AdaptiveMesh mesh(floor, {45.0 / 200});
  std::vector<mesher::ElementId> live = mesh.elements();
  size_t next = 0, touched = 0;
  for (auto _ : state) {
    next = (next + 7919) % live.size();
    if (!mesh.alive(live[next])) {  // touched by an earlier pair: list the live ones again
      state.PauseTiming();
      live = mesh.elements();
      state.ResumeTiming();
    }
    const mesher::MeshDelta refined = mesh.refine(live[next]);
    const mesher::MeshDelta coarsened = mesh.coarsen(refined.added.front());
    touched += refined.removed.size() + refined.added.size() + coarsened.removed.size() + coarsened.added.size();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * 2);
  state.counters["elements touched/op"] = static_cast<double>(touched) / static_cast<double>(state.iterations() * 2);
  state.counters["us/op"] = benchmark::Counter(static_cast<double>(state.iterations() * 2), benchmark::Counter::kIsRate | benchmark::Counter::kInvert, benchmark::Counter::kIs1000);
}
BENCHMARK(refineAndCoarsen)->Unit(benchmark::kMicrosecond);

}  // namespace
