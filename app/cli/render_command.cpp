#include "app/cli/render_command.h"

#include "app/gl/headless_render.h"
#include "app/image/atomic_file.h"
#include "app/view/view_camera.h"
#include "engine/display_mesh.h"
#include "engine/lighting.h"
#include "engine/meshed_scene.h"
#include "engine/scene_editor.h"
#include "engine/scene_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <iostream>
#include <memory>

namespace app {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Move {
  uint32_t object = 0;
  engine::Vec3 offset{0};
};

// OBJECT:DX,DY,DZ (the name may hold colons: the offset follows the last one) for a movable
// object of the scene. Throws std::invalid_argument with a one-line message naming the option.
Move parseMove(const std::string& text, const engine::SceneEditor& editor) {
  const auto fail = [&](const std::string& why) { throw std::invalid_argument("--move \"" + text + "\": " + why); };
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos) fail("expected OBJECT:DX,DY,DZ");
  Move move;
  const std::string name = text.substr(0, colon);
  const auto object = editor.findObject(name);
  if (!object) fail("the scene has no object \"" + name + "\"");
  if (!editor.scene().objects[*object].movable) fail("\"" + name + "\" is not movable");
  move.object = *object;
  const char* at = text.data() + colon + 1;
  const char* end = text.data() + text.size();
  for (int k = 0; k < 3; ++k) {
    const auto [next, error] = std::from_chars(at, end, move.offset[k]);
    if (error != std::errc() || !std::isfinite(move.offset[k])) fail("expected three numbers DX,DY,DZ");
    at = next;
    if (k < 2 && (at == end || *at++ != ',')) fail("expected three numbers DX,DY,DZ");
  }
  if (at != end) fail("expected three numbers DX,DY,DZ");
  return move;
}

}  // namespace

int runRender(const RenderOptions& options) {
  if (options.out.empty() && options.linear.empty()) {
    std::cerr << "walkrad render: nothing to write: give --out FILE.png and/or --linear FILE.pfm\n";
    return 2;
  }
  auto start = Clock::now();
  engine::Scene loaded = engine::loadScene(options.scene);
  // Outputs are checked after the scene (bad input is exit 2 first) and before the long part.
  for (const std::string& file : {options.out, options.linear, options.stats})
    if (!file.empty()) checkCanWrite(file);
  if (options.patchSize)
    for (engine::Surface& s : loaded.surfaces) s.patchSize = *options.patchSize;
  const double loadMs = millisecondsSince(start);

  ViewCamera camera;
  if (!chooseCamera(loaded, options.camera, camera)) {
    std::cerr << options.scene << ": cameras: no camera named \"" << options.camera << "\"\n";
    return 2;
  }

  start = Clock::now();
  engine::MeshedScene meshed = engine::meshScene(loaded);
  engine::SceneEditor editor(std::move(loaded), std::move(meshed));
  engine::DisplayMesh mesh = engine::displayMesh(editor.meshed());
  const double meshMs = millisecondsSince(start);
  std::vector<Move> moves;
  try {
    for (const std::string& text : options.moves) moves.push_back(parseMove(text, editor));
  } catch (const std::invalid_argument& e) {
    std::cerr << "walkrad render: " << e.what() << "\n";
    return 2;
  }

  // Solve first (progress on stdout about once a second), then light the display from it.
  start = Clock::now();
  radiosity::SolverSettings settings;
  settings.graphicsProcessors = options.threads;
  settings.overshoot = true;
  auto solver = std::make_unique<radiosity::Solver>(engine::radiosityInput(editor.scene(), editor.meshed()), settings);
  auto lastReport = start;
  const auto solve = [&](const char* what) {
    const uint64_t shots = engine::solveTo(*solver, options.converge, options.maxShots, [&](const radiosity::Solver& s, uint64_t n) {
      if (options.quiet || std::chrono::duration<double>(Clock::now() - lastReport).count() < 1) return;
      lastReport = Clock::now();
      std::cout << "walkrad render: " << n << " shots, unshot " << 100 * s.unshotFraction() << "%" << std::endl;
    });
    if (!options.quiet)
      std::cout << "walkrad render: " << what << " in " << millisecondsSince(start) / 1000 << " s: " << shots
                << " shots, unshot " << 100 * solver->unshotFraction() << "%, " << solver->patchCount() << " patches, "
                << solver->elementCount() << " elements" << std::endl;
    return shots;
  };
  uint64_t shots = solve("solved");
  const double solveMs = millisecondsSince(start);

  // Moves go through the window's edit path: the editor moves the object, the solution takes
  // the edit, and shooting goes on to convergence.
  nlohmann::ordered_json moveStats = nlohmann::ordered_json::array();
  for (size_t i = 0; i < moves.size(); ++i) {
    const Move& move = moves[i];
    start = Clock::now();
    engine::ObjectPose pose = engine::poseOf(editor.scene().objects[move.object]);
    pose.position += move.offset;
    editor.setPose(move.object, pose);
    std::vector<radiosity::Surface> input = engine::radiosityInput(editor.scene(), editor.meshed());
    const double remeshMs = millisecondsSince(start);
    engine::applyEdit(solver, input, settings);
    const bool first = solver->step();  // the first relit solution a display could show
    const double firstUpdateMs = millisecondsSince(start);
    shots += first + solve(("move " + std::to_string(i + 1) + " converged").c_str());
    // Elements that moved or were made anew (the object's, and those of surfaces whose footprints
    // changed).
    std::vector<uint32_t> touched = editor.surfacesOf(move.object);
    touched.insert(touched.end(), editor.remeshed().begin(), editor.remeshed().end());
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    size_t changed = 0;
    for (uint32_t s : touched) changed += editor.meshed().surfaces[s].mesh.elements.size();
    moveStats.push_back({{"object", editor.scene().objects[move.object].name},
                         {"remesh_ms", remeshMs},
                         {"first_update_ms", firstUpdateMs},
                         {"converge_ms", millisecondsSince(start)},
                         {"elements_changed", changed},
                         {"corrections", solver->stats().corrections},
                         {"shots", solver->stats().shots},
                         {"unshot_fraction", solver->unshotFraction()}});
  }
  if (!moves.empty()) mesh = engine::displayMesh(editor.meshed());
  engine::displayRadiance(*solver, mesh.radiance);
  const engine::Scene& scene = editor.scene();

  start = Clock::now();
  const float exposure = static_cast<float>(options.exposure.value_or(engine::autoExposure(mesh)));
  const HeadlessImages images = renderHeadless(scene, mesh, camera, options.width, options.height,
                                               exposure, options.wireframe, !options.linear.empty());
  const double renderMs = millisecondsSince(start);

  if (!options.out.empty()) writePng(options.out, images.color);
  if (!options.linear.empty()) writePfm(options.linear, images.linear);
  if (!options.stats.empty()) {
    nlohmann::ordered_json stats = {
        {"load_ms", loadMs},
        {"mesh_ms", meshMs},
        {"solve_ms", solveMs},
        {"render_ms", renderMs},
        {"patches", solver->patchCount()},
        {"elements", solver->elementCount()},
        {"vertices", mesh.positions.size()},
        {"shots", shots},
        {"unshot_fraction", solver->unshotFraction()},
        {"shots_per_second", solveMs > 0 ? 1000.0 * static_cast<double>(shots) / solveMs : 0.0},
        {"graphics_processors", options.threads},
        {"surfaces", scene.surfaces.size()},
        {"objects", scene.objects.size()},
        {"exposure", exposure},
    };
    if (!moves.empty()) stats["moves"] = moveStats;
    writeFileAtomically(options.stats, stats.dump(2) + "\n");
  }
  return 0;
}

}  // namespace app
