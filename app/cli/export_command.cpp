#include "app/cli/export_command.h"

#include "engine/document/display_mesh.h"
#include "engine/document/gltf_export.h"
#include "engine/document/lit_scene.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/atomic_file.h"

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
  engine::Scene loaded = loadForSolve(options.scene, {options.out}, options.solve);

  // Meshed and solved as `walkrad render` does, then the display's vertex radiance is baked.
  engine::MeshedScene meshed = engine::meshScene(loaded);
  const engine::LitSceneSettings settings = litSceneSettings(options.solve, loaded);
  engine::LitScene document(std::move(loaded), std::move(meshed), settings);
  solveWithProgress(document, options.solve, "export", "solved", start);
  const engine::Scene& scene = document.scene();
  engine::DisplayMesh mesh = engine::displayMesh(scene, document.meshed());
  engine::setRadiance(mesh, document.solver());

  const double exposure = options.exposure.value_or(engine::autoExposure(mesh));
  const std::string bytes = engine::exportGltf(scene, mesh, {.exposure = exposure, .binary = binary});
  engine::writeFileAtomically(options.out, bytes);
  if (!options.solve.quiet)
    std::cout << "walkrad export: " << options.out << ": " << bytes.size() << " bytes, " << mesh.triangleCount()
              << " triangles, " << mesh.vertices << " vertices, exposure " << exposure << std::endl;
  return 0;
}

}  // namespace app
