// The mesher on polygons decoded from bytes. Layout (bytes; past the end all zeros):
//   mode   bits 0-1: how the points are written: 0 a star-shaped ring (per point an angle step and
//          a radius, so the ring is simple by construction), 1 int8 pairs, 2 float32 pairs,
//          3 float64 pairs; bit 2: mesh the polygon unchecked (else only a polygon that a
//          polygon case accepts is meshed)
//   scale  star and int8 coordinates are multiplied by 2^(scale % 41 - 20)
//   patch  patch size = the outer ring's extent / (1 + patch % 16): at most 16 x 16 patches
//   holes  holes % 4 holes
//   then the outer ring and each hole: a count byte (3 + count % 8 points), for a star hole
//   its centre (two int8, in 256ths of the outer ring's radius) and size (a byte, in 512ths of
//   it), then the points.
// With WALKRAD_FUZZ_CHECK_MESH set in the environment, a mesh of a valid polygon must also
// pass the independent mesh check (mesher/mesh_check.h), or the process aborts.
#include "tests/fuzz/fuzz_targets.h"

#include "mesher/mesh_check.h"
#include "mesher/mesher.h"
#include "tests/fuzz/byte_reader.h"
#include "tests/fuzz/meshable.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace fuzz::mesh_polygon {

namespace {

using ::mesher::Ring2;
using ::mesher::Vec2;

enum class PointCoding { Star, Int8, Float32, Float64 };

// A star-shaped ring about `centre`: angles advance by each point's step, radii are in 256ths
// of `radius`.
Ring2 starRing(ByteReader& in, size_t count, Vec2 centre, double radius) {
  std::vector<double> steps(count), radii(count);
  double turn = 0;
  for (size_t i = 0; i < count; ++i) {
    steps[i] = 1 + in.next<uint8_t>();
    radii[i] = (1 + in.next<uint8_t>()) / 256.0 * radius;
    turn += steps[i];
  }
  Ring2 ring;
  double angle = 0;
  for (size_t i = 0; i < count; ++i) {
    ring.push_back(centre + radii[i] * Vec2{std::cos(angle), std::sin(angle)});
    angle += 2 * std::numbers::pi * steps[i] / turn;
  }
  return ring;
}

Ring2 listedRing(ByteReader& in, size_t count, PointCoding coding, double scale) {
  Ring2 ring(count);
  for (Vec2& p : ring)
    for (int c = 0; c < 2; ++c)
      p[c] = coding == PointCoding::Int8      ? in.next<int8_t>() * scale
             : coding == PointCoding::Float32 ? in.next<float>()
                                              : in.next<double>();
  return ring;
}

struct Decoded {
  ::mesher::PolygonWithHoles polygon;
  double patchSize = 0;
  bool unchecked = false;
};

Decoded decode(const uint8_t* data, size_t size) {
  ByteReader in(data, size);
  const auto mode = in.next<uint8_t>();
  const double scale = std::ldexp(1.0, in.next<uint8_t>() % 41 - 20);
  const int patches = 1 + in.next<uint8_t>() % 16;
  const int holes = in.next<uint8_t>() % 4;
  const auto coding = static_cast<PointCoding>(mode & 3);

  Decoded out;
  out.unchecked = mode & 4;
  auto count = [&] { return size_t{3} + in.next<uint8_t>() % 8; };
  if (coding == PointCoding::Star) {
    out.polygon.outer = starRing(in, count(), Vec2{0}, scale);
    for (int h = 0; h < holes; ++h) {
      const size_t n = count();
      const Vec2 centre{in.next<int8_t>() / 256.0 * scale, in.next<int8_t>() / 256.0 * scale};
      const double radius = (1 + in.next<uint8_t>()) / 512.0 * scale;
      out.polygon.holes.push_back(starRing(in, n, centre, radius));
    }
  } else {
    out.polygon.outer = listedRing(in, count(), coding, scale);
    for (int h = 0; h < holes; ++h) out.polygon.holes.push_back(listedRing(in, count(), coding, scale));
  }
  out.patchSize = ::mesher::extent(out.polygon.outer) / patches;
  return out;
}

// The mesher's work limit here: 8,192 quadrants, a 512th of the default (mesher.h). The decoded
// polygons start from at most 16 x 16 patches, and a refinement down to any depth at one place
// costs a few quadrants a level, so every depth is still reached; what the limit cuts short are
// meshes of 50,000-200,000 elements (grading around near-touching edges) which took 2-4 s each
// under the sanitizers and which the run kept seeking out, slowing it to 4-5 inputs a second.
constexpr size_t kMaxQuadrants = ::mesher::kMaxQuadrants / 512;

// Coordinates that reach the mesher at all: scenes and polygon cases refuse anything else.
bool finiteAndBounded(const ::mesher::PolygonWithHoles& polygon) {
  auto bounded = [](const Ring2& ring) {
    for (const Vec2& p : ring)
      if (!(std::abs(p.x) <= 1e9 && std::abs(p.y) <= 1e9)) return false;
    return true;
  };
  if (!bounded(polygon.outer)) return false;
  for (const Ring2& hole : polygon.holes)
    if (!bounded(hole)) return false;
  return true;
}

void checkMeshOrAbort(const ::mesher::PolygonWithHoles& polygon, const ::mesher::Mesh& mesh) {
  const ::mesher::MeshCheck c = ::mesher::checkMesh(polygon, mesh);
  if (::mesher::valid(c)) return;
  std::fprintf(stderr, "invalid mesh: area %.17g of %.17g, %zu not counter-clockwise or convex, %zu moved, %zu T-vertices, "
               "%zu unmatched inner edges, %zu repeated edges\n", c.elementArea, c.polygonArea, c.notCounterClockwiseOrConvex,
               c.movedInputVertices, c.tVertices, c.unmatchedInnerEdges, c.repeatedEdges);
  std::abort();
}

}  // namespace

void fuzzOne(const uint8_t* data, size_t size) {
  const Decoded in = decode(data, size);
  if (!finiteAndBounded(in.polygon) || !(in.patchSize > 0)) return;
  // What `walkrad mesh` would accept.
  const bool valid = !refusalAsPolygonCase(in.polygon);
  if (!valid && !in.unchecked) return;
  try {
    const ::mesher::Mesh mesh = ::mesher::meshPolygon(in.polygon, {in.patchSize, kMaxQuadrants});
    static const bool checkMeshes = std::getenv("WALKRAD_FUZZ_CHECK_MESH") != nullptr;
    if (valid && checkMeshes) checkMeshOrAbort(in.polygon, mesh);
  } catch (const std::invalid_argument&) {
    // The mesher's refusal (mesher::MeshRefused): a mesh past its work limit, or detail finer
    // than the coordinates resolve; or an unchecked polygon it cannot take.
  }
}

}  // namespace fuzz::mesh_polygon
