#include "app/cli/render_command.h"

#include "app/cli/import_stats.h"
#include "app/cli/peak_memory.h"
#include "app/gl/headless_render.h"
#include "app/image/atomic_file.h"
#include "app/view/view_camera.h"
#include "engine/document/display_mesh.h"
#include "engine/document/lighting.h"
#include "engine/document/mesh_adaptation.h"
#include "engine/document/scene_editor.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_limits.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <iostream>
#include <memory>
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
Move parseMove(const std::string& text, const engine::SceneEditor& editor, std::vector<engine::Vec3>& positions) {
  const auto fail = [&](const std::string& why) { throw std::invalid_argument("--move \"" + text + "\": " + why); };
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos) fail("expected OBJECT:DX,DY,DZ");
  const std::string name = text.substr(0, colon);
  const auto object = editor.findObject(name);
  if (!object) fail("the scene has no object \"" + name + "\"");
  if (!editor.scene().objects[*object].movable) fail("\"" + name + "\" is not movable");
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
  engine::ObjectPose pose = engine::poseOf(editor.scene().objects[*object]);
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

  ViewCamera camera;
  if (!chooseCamera(loaded, options.camera, camera)) {
    std::cerr << options.scene << ": cameras: no camera named \"" << options.camera << "\"\n";
    return 2;
  }

  start = Clock::now();
  engine::MeshedScene meshed = engine::meshScene(loaded);
  engine::SceneEditor editor(std::move(loaded), std::move(meshed));
  engine::DisplayMesh mesh = engine::displayMesh(editor.scene(), editor.meshed());
  const double meshMs = millisecondsSince(start);
  std::vector<Move> moves;
  try {
    std::vector<engine::Vec3> positions;
    for (const engine::Object& o : editor.scene().objects) positions.push_back(o.position);
    for (const std::string& text : options.moves) moves.push_back(parseMove(text, editor, positions));
  } catch (const std::invalid_argument& e) {
    std::cerr << "walkrad render: " << e.what() << "\n";
    return 2;
  }

  // Solve first (progress on stdout about once a second), then light the display from it.
  start = Clock::now();
  const radiosity::SolverSettings settings = solverSettings(options.solve);
  // With adaptive refinement the solver lights the adaptation's meshes, which follow the light.
  const std::unique_ptr<engine::MeshAdaptation> adaptation = adaptationFor(options.solve, editor.scene(), editor.meshed());
  auto solver = std::make_unique<radiosity::Solver>(
      adaptation ? adaptation->input() : engine::radiosityInput(editor.scene(), editor.meshed()), settings);
  const auto solve = [&](const std::string& what) {
    return solveWithProgress(*solver, options.solve, "render", what, start, adaptation.get());
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
    pose.position = move.position;
    try {
      editor.setPose(move.object, pose);
    } catch (const engine::SceneError& e) {  // a surface the move would cut is refused by the mesher
      std::cerr << "walkrad render: --move \"" << options.moves[i] << "\": " << e.what() << "\n";
      return 2;
    }
    const double remeshMs = millisecondsSince(start);
    // What the window's thread that draws does for this move: the edit above, the display
    // following it, and the copy of the edited scene and meshes that the lighting thread takes
    // the edit from (LightingThread::edit). The solver's part runs on the lighting thread.
    engine::followMove(editor.meshed(), editor.surfacesOf(move.object), editor.remeshed(), mesh);
    const auto handedOver = std::make_unique<std::pair<engine::Scene, engine::MeshedScene>>(editor.scene(), editor.meshed());
    const double uiMs = millisecondsSince(start);
    engine::applyEdit(*solver, handedOver->first, handedOver->second, editor.takeEdited(), adaptation.get());
    const bool first = solver->step();  // the first relit solution a display could show
    const double firstUpdateMs = millisecondsSince(start);
    shots += first + solve("move " + std::to_string(i + 1) + " converged");
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
                         {"ui_ms", uiMs},
                         {"first_update_ms", firstUpdateMs},
                         {"converge_ms", millisecondsSince(start)},
                         {"elements_changed", changed},
                         {"corrections", solver->stats().corrections},
                         {"windowed_corrections", solver->stats().windowedCorrections},
                         {"shots", solver->stats().shots},
                         {"unshot_fraction", solver->unshotFraction()}});
  }
  const engine::Scene& scene = editor.scene();
  if (adaptation) mesh = engine::displayMesh(scene, adaptation->meshed());
  else if (!moves.empty()) mesh = engine::displayMesh(scene, editor.meshed());
  engine::setRadiance(mesh, *solver);

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
        {"vertices", mesh.vertices},
        {"shots", shots},
        {"unshot_fraction", solver->unshotFraction()},
        {"shots_per_second", solveMs > 0 ? 1000.0 * static_cast<double>(shots) / solveMs : 0.0},
        {"graphics_processors", options.solve.threads},
        {"surfaces", scene.surfaces.size()},
        {"objects", scene.objects.size()},
        {"exposure", exposure},
        {"peak_rss_mb", peakResidentMegabytes()},
    };
    if (!moves.empty()) stats["moves"] = moveStats;
    if (adaptation) stats["adaptive_passes"] = adaptation->passes();
    if (scene.imported) stats["import"] = importStats(scene);
    writeFileAtomically(options.stats, stats.dump(2) + "\n");
  }
  return 0;
}

}  // namespace app
