// walkrad: the command line of spec/cli.md.
#include "app/cli/check_command.h"
#include "app/cli/export_command.h"
#include "app/cli/mesh_command.h"
#include "app/cli/number_option.h"
#include "app/cli/render_command.h"
#include "app/window/walk_window.h"
#include "engine/diagnostics.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"

#include <CLI/CLI.hpp>

#include <malloc.h>

#include <iostream>

namespace {

using app::addNumberOption;

// Limits of the numeric options (numberCheck refuses anything else, NaN and infinities first).
// Lengths and the refinement threshold are the scene file's.
constexpr app::NumberLimits kImageSize = app::inRange(1, 16384);
constexpr app::NumberLimits kWindowSize = app::inRange(64, 16384);
constexpr app::NumberLimits kThreads = app::inRange(1, 64);
constexpr app::NumberLimits kLength = app::positiveUpTo(engine::kMaxLength);
// A radiance scale a float holds with room to spare: radiance times it stays finite.
constexpr app::NumberLimits kExposure = app::inRange(1e-12, 1e12);

// What a glTF model may need beside it: its units and its sidecar.
void addModelOptions(CLI::App* command, engine::LoadOptions& load) {
  command->add_option("--units", load.units, "glTF: the units of the model's coordinates (m, cm, mm, in, ft; default m)");
  command->add_option("--sidecar", load.sidecar, "glTF: the sidecar to use (default: MODEL.walkrad.json beside the model)");
}

void addAdaptOptions(CLI::App& command, app::AdaptOptions& options) {
  CLI::Option* threshold =
      addNumberOption(command, "--adapt-threshold", options.threshold, app::positiveUpTo(10),
                      "refine elements whose luminance differs from a neighbour's by more than this fraction of "
                      "their mean (turns adaptive refinement on; default 0.25 or the scene's settings.adaptive)");
  CLI::Option* size = addNumberOption(command, "--min-element", options.minElementSize, kLength,
                                      "refine no element into parts narrower than this, in scene units (turns "
                                      "adaptive refinement on; default a quarter of the patch size)");
  command.add_flag("--no-adapt", options.off, "no adaptive refinement, whatever the scene says")->excludes(threshold)->excludes(size);
}

// The options of the solve that `render` and `export` both run first.
void addSolveOptions(CLI::App* command, app::SolveOptions& solve) {
  addNumberOption(*command, "--patch-size", solve.patchSize, kLength, "override the scene's initial patch size");
  addNumberOption(*command, "--converge", solve.converge, app::positiveUpTo(1),
                  "shoot until the unshot energy is below this fraction of the emitted (default 0.01)");
  addNumberOption(*command, "--max-shots", solve.maxShots, app::inRange(0, 1e12), "stop after this many shots even if not converged");
  addNumberOption(*command, "--threads", solve.threads, kThreads, "graphics-processor threads of the emulated Pixel-Planes 5 (default 1)");
  command->add_flag("--quiet", solve.quiet, "no progress lines on stdout");
  addAdaptOptions(*command, solve.adapt);
  addModelOptions(command, solve.load);
}

}  // namespace

int main(int argc, char** argv) {
  // glibc raises its mmap threshold to the size of each large block freed (up to 32 MB), after
  // which blocks below it come from the threads' arenas, and what is freed there stays resident
  // among what is not. The lighting thread's shots and snapshots free such blocks every second:
  // the White Room's window grew by 400 MB of arenas as it drew. At glibc's starting 128 KB, fixed,
  // a large block goes back to the system when it is freed.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  CLI::App cli{"walkrad: walk through a building lit by an adaptive radiosity solution"};
  cli.require_subcommand(1);

  app::RenderOptions render;
  CLI::App* renderCommand = cli.add_subcommand("render", "render a camera view headless (OSMesa) to an image");
  renderCommand->add_option("scene", render.scene, "scene file (.json) or glTF model (.gltf, .glb)")->required();
  renderCommand->add_option("--out", render.out, "tone-mapped 8-bit sRGB PNG");
  renderCommand->add_option("--linear", render.linear, "linear radiance, 3-channel float PFM");
  renderCommand->add_option("--camera", render.camera, "a camera of the scene (default: `default`)");
  addNumberOption(*renderCommand, "--width", render.width, kImageSize, "image width");
  addNumberOption(*renderCommand, "--height", render.height, kImageSize, "image height");
  renderCommand->add_flag("--wireframe", render.wireframe, "draw the mesh edges over the shading");
  renderCommand->add_option("--stats", render.stats, "write statistics as JSON");
  addNumberOption(*renderCommand, "--exposure", render.exposure, kExposure, "radiance scale before sRGB (default: automatic)");
  addSolveOptions(renderCommand, render.solve);
  renderCommand->add_option("--move", render.moves, "after converging, move OBJECT by DX,DY,DZ and converge again (OBJECT:DX,DY,DZ; repeatable)")
      ->allow_extra_args(false);

  app::ViewOptions view;
  CLI::App* viewCommand = cli.add_subcommand("view", "open the walkthrough window (GLFW + Dear ImGui)");
  viewCommand->add_option("scene", view.scene, "scene file (.json) or glTF model (.gltf, .glb)")->required();
  addModelOptions(viewCommand, view.load);
  addNumberOption(*viewCommand, "--patch-size", view.patchSize, kLength, "override the scene's initial patch size");
  viewCommand->add_option("--camera", view.camera, "start at this camera (default: `default`)");
  addNumberOption(*viewCommand, "--width", view.width, kWindowSize, "window width");
  addNumberOption(*viewCommand, "--height", view.height, kWindowSize, "window height");
  addNumberOption(*viewCommand, "--frames", view.frames, app::inRange(0, 1e9), "close after this many frames");
  viewCommand->add_option("--screenshot", view.screenshot, "with --frames: save the last frame as PNG");
  viewCommand->add_flag("--wireframe", view.wireframe, "start with the mesh edges drawn");
  viewCommand->add_option("--stats", view.stats, "at the end, write frame times (median, 95th percentile) and peak memory as JSON");
  addNumberOption(*viewCommand, "--threads", view.lighting.solver.graphicsProcessors, kThreads,
                  "graphics-processor threads of the emulated Pixel-Planes 5 (default 1)");
  addAdaptOptions(*viewCommand, view.adapt);

  app::MeshOptions mesh;
  CLI::App* meshCommand = cli.add_subcommand("mesh", "mesh a scene or a polygon case and print statistics");
  meshCommand->add_option("input", mesh.input, "scene file or polygon case (.json), or glTF model (.gltf, .glb)")->required();
  addModelOptions(meshCommand, mesh.load);
  addNumberOption(*meshCommand, "--patch-size", mesh.patchSize, kLength, "override the input's patch size");
  meshCommand->add_option("--dump", mesh.dump, "write the mesh as JSON");
  meshCommand->add_option("--stats", mesh.stats, "write statistics as JSON");
  addNumberOption(*meshCommand, "--repeat", mesh.repeat, app::inRange(1, 100000), "mesh N times, report the best time");

  app::CheckOptions check;
  CLI::App* checkCommand = cli.add_subcommand("check", "list what in a model will light badly, where, and what walkrad does about it");
  checkCommand->add_option("model", check.model, "scene file (.json) or glTF model (.gltf, .glb)")->required();
  addModelOptions(checkCommand, check.load);
  checkCommand->add_option("--json", check.json, "write the findings as JSON");

  app::ExportOptions exporting;
  CLI::App* exportCommand = cli.add_subcommand("export", "mesh and solve a scene, write it as glTF with the light in its vertex colours");
  exportCommand->add_option("scene", exporting.scene, "scene file (.json) or glTF model (.gltf, .glb)")->required();
  exportCommand->add_option("--out", exporting.out, "the glTF file: .glb (binary) or .gltf (text)")->required();
  addNumberOption(*exportCommand, "--exposure", exporting.exposure, kExposure,
                  "radiance scale before clamping to COLOR_0 (default: automatic)");
  addSolveOptions(exportCommand, exporting.solve);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return cli.exit(e);  // --help
    std::cerr << "walkrad: " << e.what() << " (see walkrad --help)\n";
    return 2;
  }

  try {
    if (*renderCommand) return app::runRender(render);
    if (*meshCommand) return app::runMesh(mesh);
    if (*checkCommand) return app::runCheck(check);
    if (*exportCommand) return app::runExport(exporting);
    return app::runView(view);
  } catch (const engine::SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "walkrad: " << e.what() << "\n";
    return 1;
  }
}
