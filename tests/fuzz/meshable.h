// What the mesher may be given (mesher::meshPolygon: simple rings, holes strictly inside and
// apart), checked as a polygon case is (engine/io/polygon_case.h), for the fuzz targets' oracles.
#pragma once

#include "engine/scene.h"
#include "mesher/triangulate.h"

#include <optional>
#include <string>

namespace fuzz {

// Why a polygon case of this polygon would be refused, or nothing when it would be accepted.
std::optional<std::string> refusalAsPolygonCase(const mesher::PolygonWithHoles& polygon);

// The loaders promise that every surface they make is a polygon the mesher accepts (coplanar
// merging splits off what would touch itself). Aborts, naming the surface and the refusal, when
// one of `scene`'s is not.
void expectMeshableSurfaces(const engine::Scene& scene);

}  // namespace fuzz
