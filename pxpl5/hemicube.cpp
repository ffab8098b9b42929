// Cohen and Greenberg's hemicube (1985) on the same machine, for comparison: five perspective
// views from the point, the top face resolution x resolution over [-1, 1]^2 at distance 1, the
// four sides resolution x resolution/2 above the horizon. A pixel of a face looks along
// p = (u, v, 1) in that face's axes, so edges n . p >= 0 and depth (m . p) / d are linear: the
// stored term is not used. Pixels carry the delta form factors
//   top:  dA / (pi (u^2 + v^2 + 1)^2)      side:  v dA / (pi (u^2 + v^2 + 1)^2)
// normalised to sum to 1.
#include "pxpl5/projections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace pxpl5 {

namespace {

// A face's axes as a rotation of the local frame (each has determinant +1, so windings and
// hence edge orientations are kept), its clip planes and where its rows sit on the screen.
struct Face {
  glm::dvec3 u, v, w;  // face coordinates are (dot(u, q), dot(v, q), dot(w, q))
  bool side;           // a side face: v is local z and runs over [0, 1]
  glm::dvec3 fromLocal(const glm::dvec3& q) const { return {glm::dot(u, q), glm::dot(v, q), glm::dot(w, q)}; }
};

const std::array<Face, 5> kFaces = {{
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, false},   // top
    {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}, true},    // +x
    {{0, -1, 0}, {0, 0, 1}, {-1, 0, 0}, true},  // -x
    {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}, true},   // +y
    {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}, true},   // -y
}};

int firstRow(int face, int resolution) { return face == 0 ? 0 : resolution + (face - 1) * (resolution / 2); }

// Face pixel (i, r) (r counted from the face's first row) has its centre at
// u = i * step + uFirst, v = r * step + vFirst.
struct FaceGrid {
  double step, uFirst, vFirst;
  int rows, rowOffset;
  FaceGrid(int face, int resolution)
      : step(2.0 / resolution),
        uFirst(1.0 / resolution - 1.0),
        vFirst(kFaces[static_cast<size_t>(face)].side ? 1.0 / resolution : 1.0 / resolution - 1.0),
        rows(kFaces[static_cast<size_t>(face)].side ? resolution / 2 : resolution),
        rowOffset(firstRow(face, resolution)) {}
  // n . (u, v, 1) over screen pixel coordinates.
  Expression expression(const glm::dvec3& n) const {
    Expression e;
    e.a = static_cast<float>(n.x * step);
    e.b = static_cast<float>(n.y * step);
    e.c = static_cast<float>(n.x * uFirst + n.y * (vFirst - rowOffset * step) + n.z);
    return e;
  }
};

}  // namespace

void setupHemicube(const ProjectionInput& in, size_t begin, size_t end, Emitter& out) {
  glm::dvec3 v[kMaxPolygonVertices], f[kMaxPolygonVertices + 6], g[kMaxPolygonVertices + 6];
  Expression edges[kMaxPolygonVertices + 6];
  for (size_t i = begin; i < end; ++i) {
    glm::dvec3 m;
    double d = 0;
    const int count = localPolygon(in, i, v, m, d);
    if (count == 0) continue;
    const double orientation = d > 0 ? 1.0 : -1.0;
    for (int faceIndex = 0; faceIndex < 5; ++faceIndex) {
      const Face& face = kFaces[static_cast<size_t>(faceIndex)];
      const FaceGrid grid(faceIndex, in.resolution);
      // Clip to the face's pyramid: w >= |u|, w >= |v| (top) or w >= v >= 0 (sides).
      int n = count;
      for (int k = 0; k < n; ++k) f[k] = face.fromLocal(v[k]);
      const glm::dvec3 planes[4] = {{-1, 0, 1}, {1, 0, 1}, {0, -1, 1}, face.side ? glm::dvec3{0, 1, 0} : glm::dvec3{0, 1, 1}};
      for (const glm::dvec3& k : planes) {
        n = clipToHalfSpace(f, n, k, g);
        std::copy(g, g + n, f);
        if (n < 3) break;
      }
      if (n < 3) continue;

      // Inside the pyramid the projection is a convex polygon: its vertices bound it.
      double uLo = 1, uHi = -1, vLo = 1, vHi = -1;
      int edgeCount = 0;
      for (int k = 0; k < n; ++k) {
        const glm::dvec3& a = f[k];
        const glm::dvec3& b = f[k + 1 < n ? k + 1 : 0];
        uLo = std::min(uLo, a.x / a.z), uHi = std::max(uHi, a.x / a.z);
        vLo = std::min(vLo, a.y / a.z), vHi = std::max(vHi, a.y / a.z);
        const glm::dvec3 normal = orientation * glm::cross(a, b);
        const double length = glm::length(normal);
        if (!(length > 0)) continue;
        edges[edgeCount++] = grid.expression(normal / length);
      }
      if (edgeCount == 0) continue;
      PixelRect bounds{static_cast<int>(std::ceil((uLo - grid.uFirst) / grid.step)) - 1,
                       static_cast<int>(std::ceil((vLo - grid.vFirst) / grid.step)) - 1,
                       static_cast<int>(std::floor((uHi - grid.uFirst) / grid.step)) + 2,
                       static_cast<int>(std::floor((vHi - grid.vFirst) / grid.step)) + 2};
      bounds.y0 = std::max(bounds.y0, 0) + grid.rowOffset;
      bounds.y1 = std::min(bounds.y1, grid.rows) + grid.rowOffset;
      const glm::dvec3 depth = face.fromLocal(m) / d;
      out.convex(bounds, std::span(edges, static_cast<size_t>(edgeCount)), grid.expression(depth), static_cast<uint32_t>(i));
    }
  }
}

void loadHemicubePlanes(Machine& machine, int resolution, std::vector<float>& weights) {
  const size_t stride = static_cast<size_t>(machine.pixelStride());
  std::span<float> term = machine.termPlane(), clearDepth = machine.clearDepthPlane();
  std::fill(term.begin(), term.end(), 0.0f);
  weights.assign(term.size(), 0.0f);
  std::vector<double> delta(term.size(), 0.0);
  double sum = 0;
  for (int faceIndex = 0; faceIndex < 5; ++faceIndex) {
    const FaceGrid grid(faceIndex, resolution);
    for (int r = 0; r < grid.rows; ++r) {
      for (int i = 0; i < resolution; ++i) {
        const double u = i * grid.step + grid.uFirst, v = r * grid.step + grid.vFirst, q = u * u + v * v + 1;
        const double cosine = kFaces[static_cast<size_t>(faceIndex)].side ? v : 1.0;
        const size_t at = static_cast<size_t>(r + grid.rowOffset) * stride + static_cast<size_t>(i);
        delta[at] = cosine * grid.step * grid.step / (std::numbers::pi * q * q);
        clearDepth[at] = 0.0f;
        sum += delta[at];
      }
    }
  }
  for (size_t at = 0; at < weights.size(); ++at) weights[at] = static_cast<float>(delta[at] / sum);
}

}  // namespace pxpl5
