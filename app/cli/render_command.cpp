#include "app/cli/render_command.h"

#include "app/gl/headless_render.h"
#include "app/image/atomic_file.h"
#include "app/view/view_camera.h"
#include "engine/display_mesh.h"
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
  const engine::Scene scene = engine::loadScene(options.scene);
  const double loadMs = millisecondsSince(start);

  ViewCamera camera;
  if (!chooseCamera(scene, options.camera, camera)) {
    std::cerr << options.scene << ": cameras: no camera named \"" << options.camera << "\"\n";
    return 2;
  }

  start = Clock::now();
  const engine::DisplayMesh mesh = engine::buildPlaceholderDisplay(scene);
  const double meshMs = millisecondsSince(start);

  start = Clock::now();
  const float exposure = static_cast<float>(options.exposure.value_or(engine::autoExposure(mesh)));
  const HeadlessImages images = renderHeadless(scene, mesh, camera, options.width, options.height,
                                               exposure, options.wireframe, !options.linear.empty());
  const double renderMs = millisecondsSince(start);

  if (!options.out.empty()) writePng(options.out, images.color);
  if (!options.linear.empty()) writePfm(options.linear, images.linear);
  if (!options.stats.empty()) {
    // Keys of spec/cli.md. There is no solver yet: every surface is one patch, nothing is shot.
    // Elements are the quadtree's quads and triangles.
    const nlohmann::ordered_json stats = {
        {"load_ms", loadMs},
        {"mesh_ms", meshMs},
        {"solve_ms", 0.0},
        {"render_ms", renderMs},
        {"patches", scene.surfaces.size()},
        {"elements", mesh.elements},
        {"vertices", mesh.positions.size()},
        {"shots", 0},
        {"unshot_fraction", 1.0},
        {"surfaces", scene.surfaces.size()},
        {"objects", scene.objects.size()},
        {"exposure", exposure},
        {"shading", "ambient placeholder: emission + reflectance x ambient, no radiosity yet"},
    };
    writeFileAtomically(options.stats, stats.dump(2) + "\n");
  }
  return 0;
}

}  // namespace app
