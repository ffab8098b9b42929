#include "app/cli/mesh_command.h"

#include "app/cli/import_stats.h"
#include "app/cli/peak_memory.h"
#include "engine/geometry/mesh_quality.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/geometry/surface_mesh.h"
#include "engine/io/atomic_file.h"
#include "engine/io/gltf_loader.h"
#include "engine/io/input_file.h"
#include "engine/io/load_limits.h"
#include "engine/io/load_scene.h"
#include "engine/io/polygon_case.h"
#include "engine/io/scene_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>

namespace app {

namespace {

using Clock = std::chrono::steady_clock;
using OrderedJson = nlohmann::ordered_json;

// Runs `meshOnce` `repeat` times and returns the best wall time in milliseconds.
template <typename MeshOnce>
double bestOf(int repeat, MeshOnce meshOnce) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::max(1, repeat); ++i) {
    const auto start = Clock::now();
    meshOnce();
    best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  return best;
}

OrderedJson elementJson(const std::array<uint32_t, 4>& e) {
  OrderedJson out = OrderedJson::array({e[0], e[1], e[2]});
  if (e[3] != mesher::Mesh::kNone) out.push_back(e[3]);
  return out;
}

}  // namespace

int runMesh(const MeshOptions& options) {
  const bool gltf = engine::isGltfPath(options.input);
  if (!gltf) engine::refuseGltfOptions(options.input, options.load);  // polygon cases too
  const std::string text = gltf ? std::string() : engine::readInputFile(options.input);
  const engine::JsonReader in(options.input);
  const engine::Json root = gltf ? engine::Json::object() : in.parse(text);

  engine::MeshQuality quality;
  double meshMs = 0;
  size_t repeats = 0;  // surfaces that were repeats of one meshed before (Mesher::repeats)
  OrderedJson dump;
  OrderedJson imported;
  if (engine::isPolygonCase(root)) {
    const engine::PolygonCase polygonCase = engine::parsePolygonCase(root, in);
    const double patch = engine::casePatchSize(polygonCase, options.patchSize, in);
    mesher::Mesh mesh;
    try {
      meshMs = bestOf(options.repeat, [&] { mesh = mesher::meshPolygon(polygonCase.polygon, {patch}); });
    } catch (const mesher::MeshRefused& refused) {
      throw engine::meshRefusal(refused, options.input, "outer");
    }
    quality.add(polygonCase.polygon, mesh);
    if (!options.dump.empty()) {
      dump["vertices"] = OrderedJson::array();
      for (const mesher::Vec2& p : mesh.vertices) dump["vertices"].push_back({p.x, p.y});
      dump["elements"] = OrderedJson::array();
      for (const auto& e : mesh.elements) dump["elements"].push_back(elementJson(e));
    }
  } else {
    engine::Scene scene = gltf ? engine::loadScene(options.input, options.load) : engine::parseScene(text, options.input);
    imported = importStats(scene);
    if (options.patchSize) engine::overridePatchSize(scene, *options.patchSize);
    std::vector<engine::SurfaceMesh> meshes;
    meshMs = bestOf(options.repeat, [&] { meshes = engine::meshScene(scene, &repeats).surfaces; });
    for (const engine::SurfaceMesh& m : meshes) quality.add(m.polygon, m.mesh);
    if (!options.dump.empty()) {
      dump["vertices"] = OrderedJson::array();
      dump["elements"] = OrderedJson::array();
      dump["surface"] = OrderedJson::array();
      uint32_t first = 0;
      for (size_t i = 0; i < meshes.size(); ++i) {
        for (const engine::Vec3& p : meshes[i].positions) dump["vertices"].push_back({p.x, p.y, p.z});
        for (auto e : meshes[i].mesh.elements) {
          for (uint32_t& v : e)
            if (v != mesher::Mesh::kNone) v += first;
          dump["elements"].push_back(elementJson(e));
          dump["surface"].push_back(i);
        }
        first += static_cast<uint32_t>(meshes[i].positions.size());
      }
    }
  }

  if (!options.dump.empty()) engine::writeFileAtomically(options.dump, dump.dump() + "\n");
  if (!options.stats.empty()) {
    OrderedJson stats = {
        {"elements", quality.elements},   {"quads", quality.quads},
        {"triangles", quality.elements - quality.quads}, {"vertices", quality.vertices},
        {"t_vertices", quality.tVertices}, {"min_angle_deg", quality.smallestAngleDeg},
        {"min_aspect_ratio", quality.smallestAspectRatio}, {"below_angle_bound", quality.belowAngleBound},
        {"mesh_ms", meshMs}, {"repeats", repeats}, {"peak_rss_mb", peakResidentMegabytes()},
    };
    if (!imported.is_null()) stats["import"] = imported;
    engine::writeFileAtomically(options.stats, stats.dump(2) + "\n");
  }
  std::printf("%zu elements (%zu quads, %zu triangles), %zu vertices, %zu T-vertices, smallest angle %.2f deg "
              "(%zu elements below %.1f), %.3f ms\n",
              quality.elements, quality.quads, quality.elements - quality.quads, quality.vertices, quality.tVertices,
              quality.smallestAngleDeg, quality.belowAngleBound, mesher::kAngleBoundDeg, meshMs);
  return 0;
}

}  // namespace app
