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

}  // namespace

void setupHemisphere(const ProjectionInput& in, size_t begin, size_t end, Emitter& out) {
  const DiskGrid grid(in.resolution);
  glm::dvec3 v[kMaxPolygonVertices], clipped[kMaxPolygonVertices + 1];
  Expression edges[kMaxPolygonVertices + 1];
  for (size_t i = begin; i < end; ++i) {
    glm::dvec3 m;
    double d = 0;
    int n = localPolygon(in, i, v, m, d);
    if (n == 0) continue;

    // Clip at the horizon (z >= 0); nothing above it, nothing to draw.
    double zMin = v[0].z, zMax = v[0].z;
    for (int k = 1; k < n; ++k) zMin = std::min(zMin, v[k].z), zMax = std::max(zMax, v[k].z);
    if (zMax <= 0) continue;
    const glm::dvec3* poly = v;
    if (zMin < 0) {
      n = clipToHalfSpace(v, n, {0, 0, 1}, clipped);
      poly = clipped;
      if (n < 3) continue;
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
    if (edgeCount == 0) continue;

    PixelRect bounds;
    grid.pixels(xLo, xHi, bounds.x0, bounds.x1);
    grid.pixels(yLo, yHi, bounds.y0, bounds.y1);
    Expression depth;
    grid.expression(m * (1.0 / d), depth);
    out.convex(bounds, std::span(edges, static_cast<size_t>(edgeCount)), depth, static_cast<uint32_t>(i));
  }
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
