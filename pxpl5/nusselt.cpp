// The Nusselt analog on the machine: each polygon, seen from the point, becomes a spherical
// polygon on the unit hemisphere; projected straight down onto the base disk, its area over
// pi is its form factor. A pixel of the disk at (x, y) looks along p = (x, y, z) with
// z = sqrt(1 - x^2 - y^2) held in pixel memory (the stored term).
//
// An edge from a to b is a great-circle arc; the pixels inside it satisfy n . p >= 0 with
// n = a x b, which is linear in x and y plus n.z times the stored z. (Squared, that is the
// conic n.z^2 (1 - x^2 - y^2) - (n.x x + n.y y)^2 with sign cases, what the real machine's
// quadratic evaluator would be given; README.) Depth: the polygon's plane m . q = d meets the
// ray t p at 1/t = (m . p) / d, again linear plus a stored-term coefficient; nearer is larger.
#include "pxpl5/projections.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pxpl5 {

namespace {

// Pixel i of the disk has its centre at x = i * step + first (the same for rows and y).
struct DiskGrid {
  double step = 0, first = 0, perStep = 0;
  explicit DiskGrid(int resolution) : step(2.0 / resolution), first(1.0 / resolution - 1.0), perStep(resolution / 2.0) {}
  // n . (x, y, z) over pixel coordinates (i, j) and the stored z, written field by field into
  // its place: GCC builds a returned Expression in pieces and copies it with wider loads, a
  // store-forwarding stall that cost half of this setup.
  void expression(const glm::dvec3& n, Expression& e) const {
    e.a = static_cast<float>(n.x * step);
    e.b = static_cast<float>(n.y * step);
    e.c = static_cast<float>((n.x + n.y) * first);
    e.d = e.e = e.f = 0;
    e.t = static_cast<float>(n.z);
  }
  // Pixels whose centres lie in [lo, hi], widened by a quarter pixel each side for the
  // rounding of the float edge expressions (the edges, not the bounds, decide coverage).
  void pixels(double lo, double hi, int& p0, int& p1) const {
    p0 = static_cast<int>(std::ceil((lo - first) * perStep - 0.25));
    p1 = static_cast<int>(std::floor((hi - first) * perStep + 0.25)) + 1;
  }
};

// One polygon, plainly: the reference set-up, and the vector set-up's path for the polygons its
// lanes do not take (those crossing the horizon). `edges` is scratch memory for
// kMaxPolygonVertices + 1 expressions (zeroed once per batch, not per polygon).
void setupPolygon(const ProjectionInput& in, const DiskGrid& grid, size_t i, Expression* edges, Emitter& out) {
  glm::dvec3 m;
  double d = 0;
  glm::dvec3 v[kMaxPolygonVertices], clipped[kMaxPolygonVertices + 1];
  int n = localPolygon(in, i, v, m, d);
  if (n == 0) return;

  // Clip at the horizon (z >= 0); nothing above it, nothing to draw.
  double zMin = v[0].z, zMax = v[0].z;
  for (int k = 1; k < n; ++k) zMin = std::min(zMin, v[k].z), zMax = std::max(zMax, v[k].z);
  if (zMax <= 0) return;
  const glm::dvec3* poly = v;
  if (zMin < 0) {
    n = clipToHalfSpace(v, n, {0, 0, 1}, clipped);
    poly = clipped;
    if (n < 3) return;
  }

  // Directions on the unit sphere; the disk bounds of the projected arcs. An arc from a to b
  // strays from its chord by at most the sagitta 1 - cos(angle / 2) <= (1 - a . b) / 2, and
  // the projection does not lengthen, so the chord's bounds grown by that hold the arc.
  glm::dvec3 u[kMaxPolygonVertices + 1];
  for (int k = 0; k < n; ++k) u[k] = poly[k] * (1.0 / glm::length(poly[k]));
  const double orientation = d > 0 ? 1.0 : -1.0;
  double xLo = 1, xHi = -1, yLo = 1, yHi = -1;
  int edgeCount = 0;
  for (int k = 0; k < n; ++k) {
    const glm::dvec3& a = u[k];
    const glm::dvec3& b = u[k + 1 < n ? k + 1 : 0];
    const double sagitta = 0.5 * (1.0 - glm::dot(a, b));
    xLo = std::min(xLo, std::min(a.x, b.x) - sagitta), xHi = std::max(xHi, std::max(a.x, b.x) + sagitta);
    yLo = std::min(yLo, std::min(a.y, b.y) - sagitta), yHi = std::max(yHi, std::max(a.y, b.y) + sagitta);
    // The test n . p >= 0 does not care about n's length, so n is not normalised; a and b
    // are unit vectors, so |n| is the sine of the edge's angle, well within float range.
    const glm::dvec3 normal = orientation * glm::cross(a, b);
    if (normal.x == 0 && normal.y == 0 && normal.z == 0) continue;  // a repeated vertex: no edge
    grid.expression(normal, edges[edgeCount++]);
  }
  if (edgeCount == 0) return;

  PixelRect bounds;
  grid.pixels(xLo, xHi, bounds.x0, bounds.x1);
  grid.pixels(yLo, yHi, bounds.y0, bounds.y1);
  Expression depth;
  grid.expression(m * (1.0 / d), depth);
  out.convex(bounds, std::span(edges, static_cast<size_t>(edgeCount)), depth, static_cast<uint32_t>(i));
}

// ---- four polygons at a time ----
//
// The vector set-up runs setupPolygon's formulas on four consecutive polygons at once, one per
// lane, each operation the same as the reference's in the same order (glm's dot and cross
// written out), so every lane gives the reference's bits; the primitives are then emitted in the
// polygons' order. A lane with fewer vertices than the others repeats its first vertex: the
// edges from it to itself add exact zeros to the Newell normal (a sum that starts at +0 is never
// -0, so adding a zero leaves it as it is) and are masked out of the centre and the bounds.

// GCC's vector extension: four doubles fill an AVX2 register (two SSE2 ones in the baseline).
constexpr int kPolygonLanes = 4;
using Lanes = double __attribute__((vector_size(kPolygonLanes * sizeof(double))));
using LaneMask = int64_t __attribute__((vector_size(kPolygonLanes * sizeof(int64_t))));  // a comparison's all ones or zero
using FloatLanes = float __attribute__((vector_size(kPolygonLanes * sizeof(float))));

struct Lanes3 {
  Lanes x, y, z;
};

[[gnu::always_inline]] inline Lanes dot(const Lanes3& a, const Lanes3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
[[gnu::always_inline]] inline Lanes dot(const Lanes3& a, const glm::dvec3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
[[gnu::always_inline]] inline Lanes3 cross(const Lanes3& a, const Lanes3& b) {
  return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}
[[gnu::always_inline]] inline Lanes3 times(const Lanes3& a, Lanes s) { return {a.x * s, a.y * s, a.z * s}; }
[[gnu::always_inline]] inline Lanes select(LaneMask m, Lanes a, Lanes b) { return m ? a : b; }
// std::sqrt lane by lane: the compiler makes it one vector square root (-fno-math-errno).
[[gnu::always_inline]] inline Lanes sqrtLanes(Lanes v) {
  for (int l = 0; l < kPolygonLanes; ++l) v[l] = std::sqrt(v[l]);
  return v;
}

// DiskGrid::expression over lanes, as floats.
struct LaneExpressions {
  FloatLanes a, b, c, t;
};
[[gnu::always_inline]] inline LaneExpressions laneExpressions(const DiskGrid& grid, const Lanes3& n) {
  return {__builtin_convertvector(n.x * grid.step, FloatLanes), __builtin_convertvector(n.y * grid.step, FloatLanes),
          __builtin_convertvector((n.x + n.y) * grid.first, FloatLanes), __builtin_convertvector(n.z, FloatLanes)};
}

[[gnu::always_inline]] inline void setupFour(const ProjectionInput& in, const DiskGrid& grid, size_t first, Expression* laneEdges, Emitter& out) {
  const PolygonSoup& soup = *in.soup;
  const LocalFrame& frame = in.frame;
  const Polygon* polygons = soup.polygons.data() + first;
  int most = 0;
  Lanes count;
  bool skipped[kPolygonLanes];
  for (int l = 0; l < kPolygonLanes; ++l) {
    most = std::max(most, static_cast<int>(polygons[l].vertexCount));
    count[l] = polygons[l].vertexCount;
    skipped[l] = false;
    for (uint32_t skip : in.skipIds) skipped[l] = skipped[l] || skip == polygons[l].id;
  }

  // localPolygon: the vertices in the local frame (v[most] is each lane's first vertex again),
  // Newell's normal, the centre, the extent and the plane's offset.
  const auto localVertex = [&](int k) __attribute__((always_inline)) {
    const glm::vec3* w[kPolygonLanes];
    for (int l = 0; l < kPolygonLanes; ++l)
      w[l] = &soup.vertices[polygons[l].firstVertex + (static_cast<uint32_t>(k) < polygons[l].vertexCount ? static_cast<uint32_t>(k) : 0u)];
    static_assert(kPolygonLanes == 4);
    const Lanes3 world{{w[0]->x, w[1]->x, w[2]->x, w[3]->x}, {w[0]->y, w[1]->y, w[2]->y, w[3]->y}, {w[0]->z, w[1]->z, w[2]->z, w[3]->z}};
    const Lanes3 d{world.x - frame.origin.x, world.y - frame.origin.y, world.z - frame.origin.z};
    return Lanes3{dot(d, frame.x), dot(d, frame.y), dot(d, frame.z)};
  };
  Lanes3 v[kMaxPolygonVertices + 1];
  v[0] = localVertex(0);
  for (int k = 1; k < most; ++k) v[k] = localVertex(k);
  v[most] = v[0];
  Lanes3 normal{}, centre{};
  Lanes extent2{};
  for (int k = 0; k < most; ++k) {
    const Lanes3& a = v[k];
    const Lanes3& b = v[k + 1];
    normal.x += (a.y - b.y) * (a.z + b.z);
    normal.y += (a.z - b.z) * (a.x + b.x);
    normal.z += (a.x - b.x) * (a.y + b.y);
    const LaneMask inside = k < count;
    centre = {select(inside, centre.x + a.x, centre.x), select(inside, centre.y + a.y, centre.y), select(inside, centre.z + a.z, centre.z)};
    const Lanes3 e{b.x - v[0].x, b.y - v[0].y, b.z - v[0].z};
    const Lanes e2 = dot(e, e);
    extent2 = select(extent2 < e2, e2, extent2);
  }
  const Lanes offset = dot(normal, centre) / count;
  const Lanes normal2 = dot(normal, normal);
  const LaneMask culled = ~(normal2 > 0) | (offset * offset <= 1e-12 * normal2 * extent2);

  // The horizon: nothing above it, or a clip (left to setupPolygon).
  Lanes zMin = v[0].z, zMax = v[0].z;
  for (int k = 1; k < most; ++k) zMin = select(v[k].z < zMin, v[k].z, zMin), zMax = select(zMax < v[k].z, v[k].z, zMax);
  const LaneMask below = zMax <= 0, crossing = zMin < 0;

  // Directions on the unit sphere, bounds of the arcs and edge expressions.
  Lanes3 u[kMaxPolygonVertices + 1];
  for (int k = 0; k < most; ++k) u[k] = times(v[k], 1.0 / sqrtLanes(dot(v[k], v[k])));
  u[most] = u[0];
  const Lanes orientation = select(offset > 0, Lanes{} + 1.0, Lanes{} - 1.0);
  Lanes xLo = Lanes{} + 1.0, xHi = Lanes{} - 1.0, yLo = Lanes{} + 1.0, yHi = Lanes{} - 1.0;
  LaneExpressions edges[kMaxPolygonVertices];
  LaneMask noEdge[kMaxPolygonVertices];
  for (int k = 0; k < most; ++k) {
    const Lanes3& a = u[k];
    const Lanes3& b = u[k + 1];
    const Lanes sagitta = 0.5 * (1.0 - dot(a, b));
    const LaneMask inside = k < count;
    const Lanes xl = select(b.x < a.x, b.x, a.x) - sagitta, xh = select(a.x < b.x, b.x, a.x) + sagitta;
    const Lanes yl = select(b.y < a.y, b.y, a.y) - sagitta, yh = select(a.y < b.y, b.y, a.y) + sagitta;
    xLo = select(inside & (xl < xLo), xl, xLo), xHi = select(inside & (xHi < xh), xh, xHi);
    yLo = select(inside & (yl < yLo), yl, yLo), yHi = select(inside & (yHi < yh), yh, yHi);
    const Lanes3 n = times(cross(a, b), orientation);
    noEdge[k] = (n.x == 0) & (n.y == 0) & (n.z == 0);
    edges[k] = laneExpressions(grid, n);
  }
  const LaneExpressions depth = laneExpressions(grid, times(normal, 1.0 / offset));
  // DiskGrid::pixels, lane by lane. The rectangles are stored well before they are passed on:
  // made one lane at a time, each was built in a vector register, stored and reloaded at once
  // in two halves, a store-forwarding stall.
  // Lanes not drawn here may hold anything (a culled polygon's infinities), which must not be
  // converted to int: they are set to zero first.
  PixelRect bounds[kPolygonLanes];
  {
    LaneMask unused = culled | below | crossing;
    for (int l = 0; l < kPolygonLanes; ++l) unused[l] |= skipped[l] ? -1 : 0;
    const auto pixels = [&](Lanes p) __attribute__((always_inline)) { return select(unused, Lanes{}, (p - grid.first) * grid.perStep); };
    const Lanes x0 = pixels(xLo) - 0.25, x1 = pixels(xHi) + 0.25, y0 = pixels(yLo) - 0.25, y1 = pixels(yHi) + 0.25;
    for (int l = 0; l < kPolygonLanes; ++l)
      bounds[l] = {static_cast<int>(std::ceil(x0[l])), static_cast<int>(std::ceil(y0[l])), static_cast<int>(std::floor(x1[l])) + 1,
                   static_cast<int>(std::floor(y1[l])) + 1};
  }

  // Emitted in the polygons' order.
  for (int l = 0; l < kPolygonLanes; ++l) {
    if (skipped[l] || culled[l] || below[l]) continue;
    if (crossing[l]) {
      setupPolygon(in, grid, first + static_cast<size_t>(l), laneEdges, out);
      continue;
    }
    size_t edgeCount = 0;
    for (uint32_t k = 0; k < polygons[l].vertexCount; ++k) {
      if (noEdge[k][l]) continue;  // a repeated vertex
      const LaneExpressions& e = edges[k];
      laneEdges[edgeCount++] = {e.a[l], e.b[l], e.c[l], 0, 0, 0, e.t[l]};
    }
    if (edgeCount == 0) continue;
    out.convex(bounds[l], std::span(laneEdges, edgeCount), {depth.a[l], depth.b[l], depth.c[l], 0, 0, 0, depth.t[l]},
               static_cast<uint32_t>(first) + static_cast<uint32_t>(l));
  }
}

}  // namespace

void setupHemisphereReference(const ProjectionInput& in, size_t begin, size_t end, Emitter& out) {
  const DiskGrid grid(in.resolution);
  Expression edges[kMaxPolygonVertices + 1];
  for (size_t i = begin; i < end; ++i) setupPolygon(in, grid, i, edges, out);
}

// Four polygons at a time where the CPU has AVX2 (one register of four doubles), two SSE2
// registers elsewhere; the choice is made once at load time. (ThreadSanitizer's runtime is not
// ready when the clone's resolver runs.)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
[[gnu::target_clones("avx2", "default")]]
#endif
void setupHemisphere(const ProjectionInput& in, size_t begin, size_t end, Emitter& out) {
  const DiskGrid grid(in.resolution);
  Expression edges[kMaxPolygonVertices + 1];
  size_t i = begin;
  for (; i + kPolygonLanes <= end; i += kPolygonLanes) setupFour(in, grid, i, edges, out);
  for (; i < end; ++i) setupPolygon(in, grid, i, edges, out);
}

void loadHemispherePlanes(Machine& machine, int resolution, std::vector<float>& weights) {
  const DiskGrid grid(resolution);
  const size_t stride = static_cast<size_t>(machine.pixelStride());
  std::span<float> term = machine.termPlane(), clearDepth = machine.clearDepthPlane();
  weights.assign(term.size(), 0.0f);
  size_t inside = 0;
  for (int j = 0; j < resolution; ++j) {
    for (int i = 0; i < resolution; ++i) {
      const double x = i * grid.step + grid.first, y = j * grid.step + grid.first, r2 = x * x + y * y;
      const size_t at = static_cast<size_t>(j) * stride + static_cast<size_t>(i);
      // Outside the disk a pixel processor is never enabled: its depth clears to +infinity.
      term[at] = r2 < 1 ? static_cast<float>(std::sqrt(1 - r2)) : 0.0f;
      clearDepth[at] = r2 < 1 ? 0.0f : std::numeric_limits<float>::infinity();
      inside += r2 < 1;
    }
  }
  // Every disk pixel carries the same share, pixel area / pi, normalised by the pixels the disk
  // actually has so that a closed scene sums to exactly 1.
  const float share = static_cast<float>(1.0 / static_cast<double>(inside));
  for (size_t at = 0; at < weights.size(); ++at) weights[at] = clearDepth[at] == 0.0f ? share : 0.0f;
}

}  // namespace pxpl5
