#include "app/cli/render_command.h"

#include "app/gl/headless_render.h"
#include "app/image/atomic_file.h"
#include "app/view/view_camera.h"
#include "engine/display_mesh.h"
#include "engine/lighting.h"
#include "engine/meshed_scene.h"
#include "engine/scene_loader.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>

namespace app {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

int runRender(const RenderOptions& options) {
  if (options.out.empty() && options.linear.empty()) {
    std::cerr << "walkrad render: nothing to write: give --out FILE.png and/or --linear FILE.pfm\n";
    return 2;
  }
  auto start = Clock::now();
  engine::Scene scene = engine::loadScene(options.scene);
  // Outputs are checked after the scene (bad input is exit 2 first) and before the long part.
  for (const std::string& file : {options.out, options.linear, options.stats})
    if (!file.empty()) checkCanWrite(file);
  if (options.patchSize)
    for (engine::Surface& s : scene.surfaces) s.patchSize = *options.patchSize;
  const double loadMs = millisecondsSince(start);

  ViewCamera camera;
  if (!chooseCamera(scene, options.camera, camera)) {
    std::cerr << options.scene << ": cameras: no camera named \"" << options.camera << "\"\n";
    return 2;
  }

  start = Clock::now();
  const engine::MeshedScene meshed = engine::meshScene(scene);
  engine::DisplayMesh mesh = engine::displayMesh(meshed);
  const double meshMs = millisecondsSince(start);

  // Solve first (progress on stdout about once a second), then light the display from it.
  start = Clock::now();
  radiosity::SolverSettings settings;
  settings.graphicsProcessors = options.threads;
  radiosity::Solver solver(engine::radiosityInput(scene, meshed), settings);
  auto lastReport = start;
  const uint64_t shots = engine::solveTo(solver, options.converge, options.maxShots, [&](const radiosity::Solver& s, uint64_t n) {
    if (options.quiet || std::chrono::duration<double>(Clock::now() - lastReport).count() < 1) return;
    lastReport = Clock::now();
    std::cout << "walkrad render: " << n << " shots, unshot " << 100 * s.unshotFraction() << "%" << std::endl;
  });
  engine::displayRadiance(solver, mesh.radiance);
  const double solveMs = millisecondsSince(start);
  if (!options.quiet)
    std::cout << "walkrad render: solved in " << solveMs / 1000 << " s: " << shots << " shots, unshot "
              << 100 * solver.unshotFraction() << "%, " << solver.patchCount() << " patches, " << solver.elementCount()
              << " elements" << std::endl;

  start = Clock::now();
  const float exposure = static_cast<float>(options.exposure.value_or(engine::autoExposure(mesh)));
  const HeadlessImages images = renderHeadless(scene, mesh, camera, options.width, options.height,
                                               exposure, options.wireframe, !options.linear.empty());
  const double renderMs = millisecondsSince(start);

  if (!options.out.empty()) writePng(options.out, images.color);
  if (!options.linear.empty()) writePfm(options.linear, images.linear);
  if (!options.stats.empty()) {
    const nlohmann::ordered_json stats = {
        {"load_ms", loadMs},
        {"mesh_ms", meshMs},
        {"solve_ms", solveMs},
        {"render_ms", renderMs},
        {"patches", solver.patchCount()},
        {"elements", solver.elementCount()},
        {"vertices", mesh.positions.size()},
        {"shots", shots},
        {"unshot_fraction", solver.unshotFraction()},
        {"shots_per_second", solveMs > 0 ? 1000.0 * static_cast<double>(shots) / solveMs : 0.0},
        {"graphics_processors", options.threads},
        {"surfaces", scene.surfaces.size()},
        {"objects", scene.objects.size()},
        {"exposure", exposure},
    };
    writeFileAtomically(options.stats, stats.dump(2) + "\n");
  }
  return 0;
}

}  // namespace app
