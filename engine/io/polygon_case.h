// Polygon cases for `walkrad mesh` (spec/cli.md): one 2-D polygon with holes and a patch size.
#pragma once

#include "engine/io/json_reader.h"
#include "mesher/triangulate.h"

#include <optional>
#include <string>

namespace engine {

struct PolygonCase {
  std::string name;
  std::optional<double> patchSize;
  mesher::PolygonWithHoles polygon;  // as given: outer and holes, either winding accepted
};

// True when a parsed file is a polygon case rather than a scene (it has "outer", no "format").
bool isPolygonCase(const Json& root);

// Validates a polygon case: rings of 3 or more finite points without repeats, simple, with
// area; holes strictly inside the outer ring and apart from each other; a patch size within
// checkPatchSize's limit for the outer ring's extent. Throws SceneError with
// the JSON path of the problem.
PolygonCase parsePolygonCase(const Json& root, const JsonReader& in);

// The patch size to mesh the case at: `override` (--patch-size) when given, else the file's.
// Throws SceneError: MissingField without either, PatchTooSmall for an override too small for
// the polygon (the file's own is checked by parsePolygonCase).
double casePatchSize(const PolygonCase& polygonCase, std::optional<double> override, const JsonReader& in);

}  // namespace engine
