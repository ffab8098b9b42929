// Speed of the path from a scene file to pixels: loading, display meshing, one headless frame.
// Run: build/tests/walkrad_bench (figures in docs/BENCHMARKS.md).
#include "app/gl/osmesa_context.h"
#include "app/gl/scene_renderer.h"
#include "engine/document/display_mesh.h"
#include "engine/document/lit_scene.h"
#include "engine/io/load_scene.h"
#include "engine/io/scene_loader.h"
#include "engine/session/view_camera.h"

#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace {

const char* const kScenes[] = {"cornell.json", "office.json", "kitchen.json"};

std::string assetText(const char* name) {
  std::ifstream file(std::string(WALKRAD_ASSETS) + "/" + name);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

void loadScene(benchmark::State& state) {
  const char* name = kScenes[state.range(0)];
  const std::string text = assetText(name);
  size_t surfaces = 0;
  for (auto _ : state) {
    const engine::Scene scene = engine::parseScene(text, name);
    surfaces = scene.surfaces.size();
    benchmark::DoNotOptimize(scene.surfaces.data());
  }
  state.SetLabel(name);
  state.counters["surfaces"] = static_cast<double>(surfaces);
  state.counters["surfaces/s"] = benchmark::Counter(static_cast<double>(surfaces), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(loadScene)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

void placeholderDisplay(benchmark::State& state) {
  const char* name = kScenes[state.range(0)];
  const engine::Scene scene = engine::parseScene(assetText(name), name);
  size_t triangles = 0;
  for (auto _ : state) {
    engine::DisplayMesh mesh = engine::displayMesh(scene, engine::meshScene(scene));
    engine::shadeWithAmbient(scene, mesh);
    triangles = mesh.triangleCount();
    benchmark::DoNotOptimize(mesh.surfaces.data());
  }
  state.SetLabel(name);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(placeholderDisplay)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

// An OSMesa context with its GL functions loaded.
struct Headless {
  app::OsmesaContext context;
  Headless(int width, int height) : context(width, height) {
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(&app::OsmesaContext::procAddress))) throw std::runtime_error("no GL");
  }
};

// A width x height frame of `mesh` from the camera `scene` opens with, exposed automatically.
app::FrameSettings openingFrame(const engine::Scene& scene, const engine::DisplayMesh& mesh, int width, int height) {
  engine::ViewCamera camera;
  engine::chooseCamera(scene, "", camera);
  app::FrameSettings frame;
  frame.clipFromDisplay = engine::clipFromDisplay(camera, static_cast<double>(width) / height, scene, mesh.origin);
  frame.width = width;
  frame.height = height;
  frame.exposure = static_cast<float>(engine::autoExposure(mesh));
  return frame;
}

// Draws `frame` of `mesh` once per iteration and reads it back to memory; with `newRadiance`,
// taking the mesh's radiance as a new snapshot first.
void drawFrames(benchmark::State& state, app::SceneRenderer& renderer, const engine::DisplayMesh& mesh,
                const app::FrameSettings& frame, bool newRadiance) {
  for (auto _ : state) {
    if (newRadiance) renderer.updateRadiance(mesh);
    renderer.draw(mesh, frame);
    benchmark::DoNotOptimize(app::readFramebuffer(frame.width, frame.height, GL_FRONT).pixels.data());
  }
}

// One frame as `walkrad render` draws it (context and upload done once), read back to memory.
void headlessFrame(benchmark::State& state) {
  const char* name = kScenes[state.range(0)];
  const int width = 640, height = 480;
  const engine::Scene scene = engine::parseScene(assetText(name), name);
  engine::DisplayMesh mesh = engine::displayMesh(scene, engine::meshScene(scene));
  engine::shadeWithAmbient(scene, mesh);
  const Headless headless(width, height);
  app::SceneRenderer renderer;
  renderer.upload(mesh);
  app::FrameSettings frame = openingFrame(scene, mesh, width, height);
  frame.wireframe = state.range(1) != 0;
  drawFrames(state, renderer, mesh, frame, false);
  state.SetLabel(std::string(name) + (frame.wireframe ? " wireframe" : ""));
}
BENCHMARK(headlessFrame)->ArgsProduct({{0, 1, 2}, {0, 1}})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

// One 1280x720 frame of the kitchen lit to 1% unshot, or of a large model (../shared/
// scenes-external with the sidecars of tests/app/sidecars) after its first shots, from the camera
// it opens with, as the window draws it without the solver: every element (range(1) 0) or at the
// level of detail (1); with range(2), a new snapshot's radiance taken first, as while the light
// changes. What llvmpipe costs apart from the solver's share of the cores.
void modelFrame(benchmark::State& state) {
  struct Model {
    const char *name, *path, *sidecar;
    uint64_t shots;
  };
  const std::string source = WALKRAD_SOURCE, external = source + "/../shared/scenes-external/";
  const Model models[] = {{"kitchen", "/assets/kitchen.json", "", UINT64_MAX},
                          {"sponza", "sponza-crytek/sponza.gltf", "sponza", 3},
                          {"white_room", "white-room-living/white_room.gltf", "white_room", 3}};
  const Model& model = models[state.range(0)];
  const int width = 1280, height = 720;
  const engine::Scene scene =
      *model.sidecar ? engine::loadScene(external + model.path, {.units = "", .sidecar = source + "/tests/app/sidecars/" + model.sidecar + ".walkrad.json"})
                     : engine::loadScene(source + model.path);
  engine::LitScene lit(scene, engine::meshScene(scene), {});
  lit.solve(0.01, model.shots);
  engine::DisplayMesh mesh = engine::displayMesh(scene, lit.meshed());
  engine::setRadiance(mesh, lit.solver());
  const Headless headless(width, height);
  app::SceneRenderer renderer;
  renderer.upload(mesh);
  app::FrameSettings frame = openingFrame(scene, mesh, width, height);
  frame.levelOfDetail = state.range(1) != 0;
  frame.toneMapVertices = true;
  drawFrames(state, renderer, mesh, frame, state.range(2) != 0);
  state.SetLabel(std::string(model.name) + (frame.levelOfDetail ? " level of detail" : " every element") +
                 (state.range(2) != 0 ? ", new radiance" : ""));
  state.counters["triangles"] = static_cast<double>(renderer.lastFrame().triangles);
  state.counters["chunks_drawn"] = static_cast<double>(renderer.lastFrame().chunksDrawn);
}
BENCHMARK(modelFrame)->ArgsProduct({{0, 1, 2}, {0, 1}, {0, 1}})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()->Iterations(10);

}  // namespace
