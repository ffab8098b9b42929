// One hemisphere (or hemicube) frame on the emulated Pixel-Planes 5: the room of
// tests/pxpl5/scenes.cpp with 1, 20 and 200 thousand polygons, seen from its floor.
// Run: build/tests/walkrad_bench --benchmark_filter=hemi (figures in docs/BENCHMARKS.md).
#include "pxpl5/hemisphere.h"
#include "tests/pxpl5/scenes.h"

#include <benchmark/benchmark.h>

namespace {

// Args: polygons, resolution, graphics-processor threads.
void frame(benchmark::State& state, pxpl5::Projection projection) {
  pxpl5::Viewpoint view;
  const pxpl5::test::Soup room = pxpl5::test::benchmarkRoom(static_cast<int>(state.range(0)), view);
  pxpl5::HemisphereSettings settings;
  settings.resolution = static_cast<int>(state.range(1));
  settings.graphicsProcessors = static_cast<int>(state.range(2));
  settings.projection = projection;
  pxpl5::HemisphereRenderer renderer(settings);
  double total = 0;
  for (auto _ : state) total = renderer.render(view, room.view()).total;
  const pxpl5::FrameCounters& c = renderer.counters();
  state.counters["polygons"] = static_cast<double>(room.polygons.size());
  state.counters["drawn"] = static_cast<double>(c.primitivesOut);
  state.counters["sum"] = total;
  state.counters["Mpix-ops emulated"] = static_cast<double>(c.emulatedPixelOps) * 1e-6;
  state.counters["Mpix-ops machine"] = static_cast<double>(c.machinePixelOps) * 1e-6;
  state.counters["Mpix written"] = static_cast<double>(c.pixelsWritten) * 1e-6;
  state.counters["polygons/s"] = benchmark::Counter(static_cast<double>(room.polygons.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void hemisphereFrame(benchmark::State& state) { frame(state, pxpl5::Projection::kHemisphere); }
void hemicubeFrame(benchmark::State& state) { frame(state, pxpl5::Projection::kHemicube); }

void arguments(benchmark::internal::Benchmark* b) {
  for (int64_t polygons : {1000, 20000, 200000})
    for (int64_t resolution : {256, 512})
      for (int64_t threads : {1, 2}) b->Args({polygons, resolution, threads});
  b->ArgNames({"polygons", "res", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
}
BENCHMARK(hemisphereFrame)->Apply(arguments);
BENCHMARK(hemicubeFrame)->Apply(arguments);

}  // namespace
