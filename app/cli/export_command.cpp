#include "app/cli/export_command.h"

#include "app/image/atomic_file.h"
#include "engine/document/display_mesh.h"
#include "engine/document/gltf_export.h"
#include "engine/document/lighting.h"
#include "engine/geometry/meshed_scene.h"

#include <chrono>
#include <iostream>

namespace app {

namespace {

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

int runExport(const ExportOptions& options) {
  const bool binary = endsWith(options.out, ".glb");
  if (!binary && !endsWith(options.out, ".gltf")) {
    std::cerr << "walkrad export: --out \"" << options.out << "\": expected a .glb or .gltf file name\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const engine::Scene scene = loadForSolve(options.scene, {options.out}, options.solve);

  // Meshed and solved as `walkrad render` does, then the display's vertex radiance is baked.
  const engine::MeshedScene meshed = engine::meshScene(scene);
  const std::unique_ptr<engine::MeshAdaptation> adaptation = adaptationFor(options.solve, scene, meshed);
  radiosity::Solver solver(adaptation ? adaptation->input() : engine::radiosityInput(scene, meshed), solverSettings(options.solve));
  solveWithProgress(solver, options.solve, "export", "solved", start, adaptation.get());
  engine::DisplayMesh mesh = engine::displayMesh(scene, adaptation ? adaptation->meshed() : meshed);
  engine::setRadiance(mesh, solver);

  const double exposure = options.exposure.value_or(engine::autoExposure(mesh));
  const std::string bytes = engine::exportGltf(scene, mesh, {.exposure = exposure, .binary = binary});
  writeFileAtomically(options.out, bytes);
  if (!options.solve.quiet)
    std::cout << "walkrad export: " << options.out << ": " << bytes.size() << " bytes, " << mesh.triangleCount()
              << " triangles, " << mesh.vertices << " vertices, exposure " << exposure << std::endl;
  return 0;
}

}  // namespace app
