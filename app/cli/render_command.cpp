#include "app/cli/render_command.h"

#include "app/cli/import_stats.h"
#include "app/cli/peak_memory.h"
#include "app/gl/headless_render.h"
#include "engine/document/display_mesh.h"
#include "engine/document/lit_scene.h"
#include "engine/document/scene_poses.h"
#include "engine/document/scene_view.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/atomic_file.h"
#include "engine/io/load_limits.h"
#include "engine/session/view_camera.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace app {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Move {
  uint32_t object = 0;
  engine::Vec3 position{0};  // where the move puts it
};

// "puts NAME at (X, Y, Z), beyond the scene limits (1e+06 on each axis)".
std::string beyondLimits(const std::string& name, const engine::Vec3& p) {
  std::ostringstream text;
  text << "puts \"" << name << "\" at (" << p.x << ", " << p.y << ", " << p.z << "), beyond the scene limits ("
       << engine::kMaxLength << " on each axis)";
  return text.str();
}

// OBJECT:DX,DY,DZ (the name may hold colons: the offset follows the last one) for a movable
// object of the scene, from where `positions` (per object) say earlier moves left it, to within
// the scene limits. Throws std::invalid_argument with a one-line message naming the option.
Move parseMove(const std::string& text, const engine::ScenePoses& poses, std::vector<engine::Vec3>& positions) {
  const auto fail = [&](const std::string& why) { throw std::invalid_argument("--move \"" + text + "\": " + why); };
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos) fail("expected OBJECT:DX,DY,DZ");
  const std::string name = text.substr(0, colon);
  const auto object = poses.findObject(name);
  if (!object) fail("the scene has no object \"" + name + "\"");
  if (!poses.scene().objects[*object].movable) fail("\"" + name + "\" is not movable");
  engine::Vec3 offset{0};
  const char* at = text.data() + colon + 1;
  const char* end = text.data() + text.size();
  for (int k = 0; k < 3; ++k) {
    const auto [next, error] = std::from_chars(at, end, offset[k]);
    if (error != std::errc() || !std::isfinite(offset[k])) fail("expected three numbers DX,DY,DZ");
    at = next;
    if (k < 2 && (at == end || *at++ != ',')) fail("expected three numbers DX,DY,DZ");
  }
  if (at != end) fail("expected three numbers DX,DY,DZ");
  engine::ObjectPose pose = poses.pose(*object);
  pose.position = positions[*object] + offset;
  if (!engine::inSceneLimits(pose)) fail(beyondLimits(name, pose.position));
  positions[*object] = pose.position;
  return {*object, pose.position};
}

}  // namespace

int runRender(const RenderOptions& options) {
  if (options.out.empty() && options.linear.empty()) {
    std::cerr << "walkrad render: nothing to write: give --out FILE.png and/or --linear FILE.pfm\n";
    return 2;
  }
  auto start = Clock::now();
  engine::Scene loaded = loadForSolve(options.scene, {options.out, options.linear, options.stats}, options.solve);
  const double loadMs = millisecondsSince(start);
  // A model from a modeller often has no lamps: say why the picture will be black.
  if (std::none_of(loaded.materials.begin(), loaded.materials.end(), [](const engine::Material& m) { return m.emission != engine::Vec3{0}; }))
    std::cerr << "walkrad render: " << options.scene << ": nothing emits light, so the picture is black"
              << (loaded.imported ? " (give a material an emission, or a sky, in its .walkrad.json sidecar)" : "") << "\n";

  engine::ViewCamera camera;
  if (!engine::chooseCamera(loaded, options.camera, camera)) {
    std::cerr << options.scene << ": cameras: no camera named \"" << options.camera << "\"\n";
    return 2;
  }

  start = Clock::now();
  engine::MeshedScene meshed = engine::meshScene(loaded);
  // For moves, what the window's thread that draws holds: the objects' poses and the display.
  std::optional<engine::SceneView> view;
  if (!options.moves.empty()) view.emplace(loaded, meshed);
  const double meshMs = millisecondsSince(start);
  std::vector<Move> moves;
  try {
    std::vector<engine::Vec3> positions;
    for (const engine::Object& o : loaded.objects) positions.push_back(o.position);
    for (const std::string& text : options.moves) moves.push_back(parseMove(text, view->poses(), positions));
  } catch (const std::invalid_argument& e) {
    std::cerr << "walkrad render: " << e.what() << "\n";
    return 2;
  }

  // Solve first (progress on stdout about once a second), then light the display from it.
  start = Clock::now();
  const engine::LitSceneSettings settings = litSceneSettings(options.solve, loaded);
  engine::LitScene document(std::move(loaded), std::move(meshed), settings);
  const auto solve = [&](const std::string& what) { return solveWithProgress(document, options.solve, "render", what, start); };
  uint64_t shots = solve("solved");
  const double solveMs = millisecondsSince(start);
  if (view) view->take({nullptr, document.takeUpdates(), {}});  // refined and coarsened while solving

  // Moves go through the window's edit path: the thread that draws moves the object's picture,
  // the document (on the window's lighting thread) cuts, meshes and takes the edit into the light,
  // the display takes the surfaces that changed, and shooting goes on to convergence.
  nlohmann::ordered_json moveStats = nlohmann::ordered_json::array();
  for (size_t i = 0; i < moves.size(); ++i) {
    const Move& move = moves[i];
    engine::ObjectPose pose = view->poses().pose(move.object);
    pose.position = move.position;
    start = Clock::now();
    view->setPose(move.object, pose);
    double uiMs = millisecondsSince(start);
    const auto edit = Clock::now();
    try {
      document.setPose(move.object, pose);
    } catch (const engine::SceneError& e) {  // a surface the move would cut is refused by the mesher
      std::cerr << "walkrad render: --move \"" << options.moves[i] << "\": " << e.what() << "\n";
      return 2;
    }
    const double remeshMs = millisecondsSince(edit);
    const engine::LightingUpdate update{nullptr, document.takeUpdates(), {}};
    const auto shown = Clock::now();
    view->take(update);
    uiMs += millisecondsSince(shown);
    // The first relit solution a display could show.
    const bool first = document.step(options.solve.converge) == engine::SolveStep::kShot;
    const double firstUpdateMs = millisecondsSince(start);
    shots += first + solve("move " + std::to_string(i + 1) + " converged");
    // Elements that moved or were made anew (the object's, and those of surfaces whose footprints
    // changed).
    size_t changed = 0;
    for (const engine::SurfaceUpdate& u : update.meshes) changed += u.mesh.mesh.elements.size();
    const radiosity::Solver& solver = document.solver();
    moveStats.push_back({{"object", view->scene().objects[move.object].name},
                         {"remesh_ms", remeshMs},
                         {"ui_ms", uiMs},
                         {"first_update_ms", firstUpdateMs},
                         {"converge_ms", millisecondsSince(start)},
                         {"elements_changed", changed},
                         {"corrections", solver.stats().corrections},
                         {"windowed_corrections", solver.stats().windowedCorrections},
                         {"shots", solver.stats().shots},
                         {"unshot_fraction", solver.unshotFraction()}});
  }
  const engine::Scene& scene = document.scene();
  const radiosity::Solver& solver = document.solver();
  engine::DisplayMesh mesh = engine::displayMesh(scene, document.meshed());
  engine::setRadiance(mesh, solver);

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
        {"patches", solver.patchCount()},
        {"elements", solver.elementCount()},
        {"vertices", mesh.vertices},
        {"shots", shots},
        {"unshot_fraction", solver.unshotFraction()},
        {"shots_per_second", solveMs > 0 ? 1000.0 * static_cast<double>(shots) / solveMs : 0.0},
        {"graphics_processors", options.solve.threads},
        {"surfaces", scene.surfaces.size()},
        {"objects", scene.objects.size()},
        {"exposure", exposure},
        {"peak_rss_mb", peakResidentMegabytes()},
    };
    if (!moves.empty()) stats["moves"] = moveStats;
    if (settings.adaptive) stats["adaptive_passes"] = document.adaptivePasses();
    if (scene.imported) stats["import"] = importStats(scene);
    engine::writeFileAtomically(options.stats, stats.dump(2) + "\n");
  }
  return 0;
}

}  // namespace app
