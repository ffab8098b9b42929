#include "engine/io/polygon_case.h"

#include "engine/io/load_limits.h"

#include <cmath>

namespace engine {

namespace {

constexpr double kMaxCoordinate = 1e9;

mesher::Ring2 simpleRing(const Json& value, const std::string& path, const JsonReader& in) {
  mesher::Ring2 ring = in.ring2(value, path, -kMaxCoordinate, kMaxCoordinate);
  for (size_t i = 0; i < ring.size(); ++i)
    if (ring[i] == ring[(i + 1) % ring.size()]) in.fail(Diag::Degenerate, path, "point " + std::to_string(i) + " is repeated");
  if (!mesher::isSimple(ring)) in.fail(Diag::SelfIntersecting, path);
  const double size = mesher::extent(ring);
  if (std::abs(mesher::signedArea(ring)) <= 1e-12 * size * size) in.fail(Diag::Degenerate, path, "no area");
  return ring;
}

}  // namespace

bool isPolygonCase(const Json& root) { return root.is_object() && root.contains("outer") && !root.contains("format"); }

PolygonCase parsePolygonCase(const Json& root, const JsonReader& in) {
  in.expectObject(root, "");
  in.allowOnly(root, "", {"name", "patch_size", "outer", "holes"});
  PolygonCase result;
  if (const auto v = root.find("name"); v != root.end()) result.name = in.string(*v, "name");
  if (const auto v = root.find("patch_size"); v != root.end()) {
    result.patchSize = in.number(*v, "patch_size", 0, kMaxCoordinate);
    if (*result.patchSize <= 0) in.fail(Diag::OutOfRange, "patch_size", "must be greater than 0");
  }
  result.polygon.outer = simpleRing(in.required(root, "", "outer"), "outer", in);
  const mesher::Ring2& outer = result.polygon.outer;
  if (result.patchSize) checkPatchSize(*result.patchSize, mesher::extent(outer), in.file(), "patch_size");
  const double margin = 1e-9 * mesher::extent(outer);
  if (const auto holes = root.find("holes"); holes != root.end()) {
    in.expectArray(*holes, "holes");
    for (size_t h = 0; h < holes->size(); ++h) {
      const std::string path = child("holes", h);
      mesher::Ring2 hole = simpleRing((*holes)[h], path, in);
      if (!mesher::containsPoint(outer, hole.front()) || mesher::boundaryDistance(outer, hole) <= margin)
        in.fail(Diag::HoleOutsideFace, path, "not strictly inside `outer`");
      for (size_t g = 0; g < h; ++g) {
        const mesher::Ring2& other = result.polygon.holes[g];
        if (mesher::boundaryDistance(hole, other) <= margin || mesher::containsPoint(hole, other.front()) ||
            mesher::containsPoint(other, hole.front()))
          in.fail(Diag::HolesTouch, path, "with hole " + std::to_string(g));
      }
      result.polygon.holes.push_back(std::move(hole));
    }
  }
  return result;
}

double casePatchSize(const PolygonCase& polygonCase, std::optional<double> override, const JsonReader& in) {
  if (!override && !polygonCase.patchSize) in.fail(Diag::MissingField, "patch_size", "give it in the file or with --patch-size");
  if (!override) return *polygonCase.patchSize;
  checkPatchSize(*override, mesher::extent(polygonCase.polygon.outer), in.file(), "--patch-size");
  return *override;
}

}  // namespace engine
