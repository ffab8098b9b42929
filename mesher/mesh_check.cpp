#include "mesher/mesh_check.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

namespace mesher {

namespace {

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

double distanceToSegment(Vec2 p, Vec2 a, Vec2 b, double& t) {
  const Vec2 d = b - a;
  t = glm::dot(p - a, d) / glm::dot(d, d);
  return glm::length(p - (a + std::clamp(t, 0.0, 1.0) * d));
}

// 2r/R of triangle abc: 1 for an equilateral triangle, 0 for a degenerate one.
double aspectRatio(Vec2 a, Vec2 b, Vec2 c) {
  const double x = glm::length(b - c), y = glm::length(c - a), z = glm::length(a - b);
  const double twiceArea = std::abs(cross(b - a, c - a));
  if (twiceArea == 0) return 0;
  const double s = 0.5 * (x + y + z);
  const double inscribed = 0.5 * twiceArea / s, circumscribed = x * y * z / (2 * twiceArea);
  return 2 * inscribed / circumscribed;
}

// A quadrilateral's shape: the better of its two splits along a diagonal, each judged by its
// worse triangle (a square: 0.83). Judged by its corner triangles instead, a quad with a corner
// of nearly 180 degrees (a triangle with a point on one side) would count as degenerate.
double aspectRatio(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return std::max(std::min(aspectRatio(a, b, c), aspectRatio(a, c, d)), std::min(aspectRatio(b, c, d), aspectRatio(b, d, a)));
}

// Per input vertex (outer ring, then holes): whether the polygon's inside angle there is below
// kAngleBoundDeg. The inside lies left of a counter-clockwise outer ring and right of it for a
// hole, whichever way the rings are given.
std::vector<bool> sharpInputCorners(const std::vector<Ring2>& rings) {
  std::vector<bool> sharp;
  for (size_t r = 0; r < rings.size(); ++r) {
    const Ring2& ring = rings[r];
    const bool insideLeft = (signedArea(ring) > 0) == (r == 0);
    for (size_t i = 0; i < ring.size(); ++i) {
      const Vec2 at = ring[i], toNext = ring[(i + 1) % ring.size()] - at, toPrev = ring[(i + ring.size() - 1) % ring.size()] - at;
      double turn = std::atan2(cross(toNext, toPrev), glm::dot(toNext, toPrev));  // next to prev, counter-clockwise
      if (turn < 0) turn += 2 * std::numbers::pi;
      const double inside = (insideLeft ? turn : 2 * std::numbers::pi - turn) * 180 / std::numbers::pi;
      sharp.push_back(inside < kAngleBoundDeg);
    }
  }
  return sharp;
}

uint64_t edgeKey(uint32_t a, uint32_t b) { return uint64_t{a} << 32 | b; }

// Undirected edges bucketed on a uniform grid, for "which edges pass near this point".
class EdgeGrid {
 public:
  EdgeGrid(const Mesh& mesh, const std::vector<std::pair<uint32_t, uint32_t>>& edges) : mesh_(mesh), edges_(edges) {
    lo_ = hi_ = mesh.vertices.empty() ? Vec2{0} : mesh.vertices.front();
    for (const Vec2& p : mesh.vertices) lo_ = glm::min(lo_, p), hi_ = glm::max(hi_, p);
    const double area = std::max((hi_.x - lo_.x) * (hi_.y - lo_.y), 1e-300);
    cell_ = std::max(std::sqrt(area / std::max<double>(1, static_cast<double>(edges.size()))), 1e-300);
    for (uint32_t e = 0; e < edges.size(); ++e) {
      const Vec2 a = mesh.vertices[edges[e].first], b = mesh.vertices[edges[e].second];
      const auto [x0, y0] = cellOf(glm::min(a, b));
      const auto [x1, y1] = cellOf(glm::max(a, b));
      for (int64_t x = x0; x <= x1; ++x)
        for (int64_t y = y0; y <= y1; ++y) cells_[key(x, y)].push_back(e);
    }
  }

  template <typename Visit>
  void near(Vec2 p, Visit visit) const {
    const auto [x, y] = cellOf(p);
    const auto found = cells_.find(key(x, y));
    if (found == cells_.end()) return;
    for (uint32_t e : found->second) visit(edges_[e]);
  }

 private:
  std::pair<int64_t, int64_t> cellOf(Vec2 p) const {
    return {static_cast<int64_t>(std::floor((p.x - lo_.x) / cell_)), static_cast<int64_t>(std::floor((p.y - lo_.y) / cell_))};
  }
  static uint64_t key(int64_t x, int64_t y) { return static_cast<uint64_t>(x) * 0x9E3779B97F4A7C15ull ^ static_cast<uint64_t>(y); }

  const Mesh& mesh_;
  const std::vector<std::pair<uint32_t, uint32_t>>& edges_;
  Vec2 lo_, hi_;
  double cell_ = 1;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

}  // namespace

MeshCheck checkMesh(const PolygonWithHoles& polygon, const Mesh& mesh) {
  MeshCheck check;
  std::vector<Ring2> rings{polygon.outer};
  rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  check.polygonArea = std::abs(signedArea(polygon.outer));
  for (const Ring2& h : polygon.holes) check.polygonArea -= std::abs(signedArea(h));
  double size = 0;
  for (const Vec2& p : polygon.outer) size = std::max({size, std::abs(p.x), std::abs(p.y)});
  const double extent = mesher::extent(polygon.outer);
  // On the boundary: within 1e-9 of the polygon's size. A T-vertex: on an element edge up to the
  // rounding of computed points (1e-12 of the coordinates), not merely close to it, as the
  // corners of a sliver at a sharp spike are; and in line with it, as seen from the edge's nearer
  // end. Far from the origin elements can be smaller than that rounding (1e-7 at 1e5): the
  // corners beside an edge's end lie as close to it, but at the elements' angles (a distance
  // from the line a third or more of that from the end, or a thirtieth beside a sliver of 2
  // degrees, where rounding gives under a hundredth).
  const double tolerance = 1e-9 * std::max(extent, 1e-9 * size);
  const double onEdge = 1e-12 * (size + extent);
  constexpr double kInLine = 0.01;  // largest distance from the edge's line over that from its nearer end

  size_t index = 0;
  for (const Ring2& ring : rings)
    for (const Vec2& p : ring) check.movedInputVertices += index >= mesh.vertices.size() || mesh.vertices[index++] != p;
  const std::vector<bool> sharpCorner = sharpInputCorners(rings);

  // Element shape, area, and how often each directed edge is used.
  std::unordered_map<uint64_t, int> edgeUse;
  edgeUse.reserve(mesh.elements.size() * 4);
  for (const auto& e : mesh.elements) {
    const size_t n = e[3] == Mesh::kNone ? 3 : 4;
    double area = 0, diameter = 0;
    bool belowBound = false;
    const Vec2 origin = mesh.vertices[e[0]];  // areas relative to a corner keep far meshes precise
    for (size_t k = 0; k < n; ++k) {
      const Vec2 a = mesh.vertices[e[k]], b = mesh.vertices[e[(k + 1) % n]], c = mesh.vertices[e[(k + 2) % n]];
      area += 0.5 * cross(a - origin, b - origin);
      if (!(cross(b - a, c - b) > 0)) ++check.notCounterClockwiseOrConvex;
      const Vec2 u = a - b, v = c - b;
      const double angle = std::atan2(std::abs(cross(u, v)), glm::dot(u, v)) * 180 / std::numbers::pi;
      check.smallestAngleDeg = std::min(check.smallestAngleDeg, angle);
      const uint32_t corner = e[(k + 1) % n];
      belowBound |= angle < kAngleBoundDeg && !(corner < sharpCorner.size() && sharpCorner[corner]);
      for (size_t j = 0; j < n; ++j) diameter = std::max(diameter, glm::length(mesh.vertices[e[j]] - a));
      if (++edgeUse[edgeKey(e[k], e[(k + 1) % n])] > 1) ++check.repeatedEdges;
    }
    const Vec2 a = mesh.vertices[e[0]], b = mesh.vertices[e[1]], c = mesh.vertices[e[2]];
    check.smallestAspectRatio = std::min(check.smallestAspectRatio, n == 3 ? aspectRatio(a, b, c) : aspectRatio(a, b, c, mesh.vertices[e[3]]));
    check.elementArea += area;
    check.belowAngleBound += belowBound;
    check.largestDiameter = std::max(check.largestDiameter, diameter);
  }

  // Edges used once must lie on the polygon's boundary.
  std::vector<std::pair<uint32_t, uint32_t>> undirected;
  undirected.reserve(edgeUse.size());
  for (const auto& [key, uses] : edgeUse) {
    const auto a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
    if (a < b || !edgeUse.count(edgeKey(b, a))) undirected.push_back({a, b});
    if (edgeUse.count(edgeKey(b, a))) continue;
    const Vec2 mid = 0.5 * (mesh.vertices[a] + mesh.vertices[b]);
    bool onBoundary = false;
    for (const Ring2& ring : rings)
      for (size_t i = 0; i < ring.size() && !onBoundary; ++i) {
        double t;
        onBoundary = distanceToSegment(mid, ring[i], ring[(i + 1) % ring.size()], t) <= tolerance;
      }
    check.unmatchedInnerEdges += !onBoundary;
  }

  // No vertex of an element may lie inside an element edge it is not a corner of. (Vertices no
  // element uses, as a coarsened mesh keeps, are not part of the mesh.)
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& e : mesh.elements)
    for (uint32_t v : e)
      if (v != Mesh::kNone) used[v] = true;
  const EdgeGrid grid(mesh, undirected);
  for (uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!used[v]) continue;
    grid.near(mesh.vertices[v], [&](const std::pair<uint32_t, uint32_t>& edge) {
      if (edge.first == v || edge.second == v) return;
      double t;
      const Vec2 p = mesh.vertices[v], a = mesh.vertices[edge.first], b = mesh.vertices[edge.second];
      const double d = distanceToSegment(p, a, b, t);
      if (d <= onEdge && t > 1e-12 && t < 1 - 1e-12 && d <= kInLine * std::min(glm::length(p - a), glm::length(p - b)))
        ++check.tVertices;
    });
  }
  return check;
}

}  // namespace mesher
