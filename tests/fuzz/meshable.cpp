#include "tests/fuzz/meshable.h"

#include "engine/diagnostics.h"
#include "engine/geometry/surface_mesh.h"
#include "engine/io/polygon_case.h"

#include <cstdio>
#include <cstdlib>

namespace fuzz {

namespace {

engine::Json ringJson(const mesher::Ring2& ring) {
  engine::Json points = engine::Json::array();
  for (const mesher::Vec2& p : ring) points.push_back({p.x, p.y});
  return points;
}

}  // namespace

std::optional<std::string> refusalAsPolygonCase(const mesher::PolygonWithHoles& polygon) {
  engine::Json root = {{"outer", ringJson(polygon.outer)}, {"holes", engine::Json::array()}};
  for (const mesher::Ring2& hole : polygon.holes) root["holes"].push_back(ringJson(hole));
  const engine::JsonReader in("surface");
  try {
    engine::parsePolygonCase(root, in);
    return std::nullopt;
  } catch (const engine::SceneError& e) {
    return e.what();
  }
}

void expectMeshableSurfaces(const engine::Scene& scene) {
  for (size_t i = 0; i < scene.surfaces.size(); ++i) {
    const engine::Surface& s = scene.surfaces[i];
    const std::optional<std::string> refusal = refusalAsPolygonCase(engine::planePolygon(s, s));
    if (!refusal) continue;
    std::fprintf(stderr, "surface %zu (%s, %s) is not a polygon the mesher accepts: %s\n", i, s.jsonPath.c_str(),
                 s.face.c_str(), refusal->c_str());
    std::abort();
  }
}

}  // namespace fuzz
