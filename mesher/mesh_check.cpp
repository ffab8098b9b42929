#include "mesher/mesh_check.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

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

// An element's edge: its ends in increasing order, and whether the element runs it from the
// higher to the lower.
struct EdgeUse {
  uint32_t low, high;
  bool reversed;
  auto operator<=>(const EdgeUse&) const = default;
};

// Segments in the cells of a grid per power-of-two size: each in those cells, of the size next
// above its own length (padded by `pad`), that its box meets: four at most. A point meets one
// cell of each size, so the segments passing within `pad` of it are among a handful per size
// wherever segments are about as far apart as they are long, as a mesh's are. Work and memory
// grow with the segments, whatever their lengths or the mesh's shape (a uniform grid's cells
// suit one scale: a long edge of a thin mesh crossed millions of them).
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<std::pair<Vec2, Vec2>>& segments, double pad) : pad_(pad) {
    if (segments.empty()) return;
    lo_ = hi_ = segments.front().first;
    for (const auto& [a, b] : segments) lo_ = glm::min(lo_, glm::min(a, b)), hi_ = glm::max(hi_, glm::max(a, b));
    lo_ -= Vec2{pad};
    int span = 0;
    std::frexp(std::max({hi_.x - lo_.x, hi_.y - lo_.y, pad}) + pad, &span);
    // Indices stay below 2^41: shorter segments share the finest size.
    finest_ = span - 40;
    std::vector<std::pair<Cell, uint32_t>> entries;
    for (uint32_t i = 0; i < segments.size(); ++i) {
      const auto& [a, b] = segments[i];
      int size = 0;
      std::frexp(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)) + 2 * pad, &size);
      size = std::max(size, finest_);
      if (std::find(sizes_.begin(), sizes_.end(), size) == sizes_.end()) sizes_.push_back(size);
      const auto [x0, y0] = cellOf(glm::min(a, b) - Vec2{pad}, size);
      const auto [x1, y1] = cellOf(glm::max(a, b) + Vec2{pad}, size);
      for (int64_t x = x0; x <= x1; ++x)
        for (int64_t y = y0; y <= y1; ++y) entries.push_back({{size, x, y}, i});
    }
    // The cells' segments listed cell by cell, and an open-addressed table of the cells: a
    // lookup, found or not, is a probe or two in one array (a hash map's nodes cost a cache miss
    // each, for most of the check's time on large meshes).
    std::sort(entries.begin(), entries.end(), [](const auto& u, const auto& v) { return u.first < v.first || (u.first == v.first && u.second < v.second); });
    table_.assign(std::bit_ceil(2 * entries.size()), Slot{});
    segments_.reserve(entries.size());
    size_t open = 0;  // the slot of the cell being listed
    for (size_t k = 0; k < entries.size(); ++k) {
      if (k == 0 || !(entries[k].first == entries[k - 1].first)) {
        size_t slot = slotOf(entries[k].first);
        while (table_[slot].end != 0) slot = (slot + 1) & (table_.size() - 1);
        table_[slot] = {entries[k].first, static_cast<uint32_t>(segments_.size()), 0};
        open = slot;
      }
      segments_.push_back(entries[k].second);
      table_[open].end = static_cast<uint32_t>(segments_.size());
    }
  }

  // Calls visit(i) for every segment i that may pass within `pad` of p (once each).
  template <typename Visit>
  void near(Vec2 p, Visit visit) const {
    if (table_.empty()) return;
    for (int size : sizes_) {
      const auto [x, y] = cellOf(p, size);
      const Cell cell{size, x, y};
      for (size_t slot = slotOf(cell); table_[slot].end != 0; slot = (slot + 1) & (table_.size() - 1))
        if (table_[slot].cell == cell) {
          for (uint32_t k = table_[slot].begin; k < table_[slot].end; ++k) visit(segments_[k]);
          break;
        }
    }
  }

 private:
  struct Cell {
    int size;
    int64_t x, y;
    auto operator<=>(const Cell&) const = default;
  };
  struct Slot {
    Cell cell{0, 0, 0};
    uint32_t begin = 0, end = 0;  // the cell's segments in segments_; end 0 for an empty slot
  };
  size_t slotOf(const Cell& c) const {
    const uint64_t h = (static_cast<uint64_t>(c.x) * 0x9E3779B97F4A7C15ull) ^ (static_cast<uint64_t>(c.y) * 0xC2B2AE3D27D4EB4Full) ^
                       (static_cast<uint64_t>(c.size) * 0x165667B19E3779F9ull);
    return static_cast<size_t>(h ^ h >> 32) & (table_.size() - 1);
  }
  // The cell of a given size (an exponent: cells of edge 2^size) holding p, clamped to the box.
  std::pair<int64_t, int64_t> cellOf(Vec2 p, int size) const {
    const Vec2 at = glm::clamp(p, lo_, hi_ + Vec2{pad_}) - lo_;
    return {static_cast<int64_t>(std::ldexp(at.x, -size)), static_cast<int64_t>(std::ldexp(at.y, -size))};
  }

  double pad_;
  Vec2 lo_{0}, hi_{0};
  int finest_ = 0;
  std::vector<int> sizes_;
  std::vector<Slot> table_;
  std::vector<uint32_t> segments_;
};

}  // namespace

bool valid(const MeshCheck& c) {
  return std::abs(c.elementArea - c.polygonArea) <= c.areaTolerance && c.notCounterClockwiseOrConvex == 0 && c.movedInputVertices == 0 &&
         c.tVertices == 0 && c.unmatchedInnerEdges == 0 && c.repeatedEdges == 0;
}

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
  const double tolerance = std::max(1e-9 * extent, 1e-12 * size);
  const double onEdge = 1e-12 * (size + extent);
  constexpr double kInLine = 0.01;  // largest distance from the edge's line over that from its nearer end
  // The area: its points on the boundary may lie as far off it as points on an edge may.
  double perimeter = 0;
  for (const Ring2& ring : rings)
    for (size_t i = 0; i < ring.size(); ++i) perimeter += glm::length(ring[(i + 1) % ring.size()] - ring[i]);
  check.areaTolerance = 1e-9 * check.polygonArea + onEdge * perimeter;

  size_t index = 0;
  for (const Ring2& ring : rings)
    for (const Vec2& p : ring) check.movedInputVertices += index >= mesh.vertices.size() || mesh.vertices[index++] != p;
  const std::vector<bool> sharpCorner = sharpInputCorners(rings);

  // Element shape and area, and the edges they use.
  std::vector<EdgeUse> edgeUses;
  edgeUses.reserve(mesh.elements.size() * 4);
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
      const uint32_t from = e[k], to = e[(k + 1) % n];
      edgeUses.push_back({std::min(from, to), std::max(from, to), from > to});
    }
    const Vec2 a = mesh.vertices[e[0]], b = mesh.vertices[e[1]], c = mesh.vertices[e[2]];
    check.smallestAspectRatio = std::min(check.smallestAspectRatio, n == 3 ? aspectRatio(a, b, c) : aspectRatio(a, b, c, mesh.vertices[e[3]]));
    check.elementArea += area;
    check.belowAngleBound += belowBound;
    check.largestDiameter = std::max(check.largestDiameter, diameter);
  }

  // An edge run one way by more than one element is repeated. Edges used once (no element runs
  // them the other way) must lie on the polygon's boundary.
  std::sort(edgeUses.begin(), edgeUses.end());
  std::vector<std::pair<uint32_t, uint32_t>> once;
  for (size_t i = 0; i < edgeUses.size();) {
    const EdgeUse& first = edgeUses[i];
    size_t forward = 0, reversed = 0;
    for (; i < edgeUses.size() && edgeUses[i].low == first.low && edgeUses[i].high == first.high; ++i) ++(edgeUses[i].reversed ? reversed : forward);
    check.repeatedEdges += (forward > 1 ? forward - 1 : 0) + (reversed > 1 ? reversed - 1 : 0);
    if (reversed == 0) once.push_back({first.low, first.high});
    if (forward == 0) once.push_back({first.high, first.low});
  }
  std::vector<std::pair<Vec2, Vec2>> segments;
  for (const Ring2& ring : rings)
    for (size_t i = 0; i < ring.size(); ++i) segments.push_back({ring[i], ring[(i + 1) % ring.size()]});
  const SegmentGrid boundary(segments, tolerance);
  for (const auto& [a, b] : once) {
    const Vec2 mid = 0.5 * (mesh.vertices[a] + mesh.vertices[b]);
    bool onBoundary = false;
    boundary.near(mid, [&](uint32_t i) {
      double t;
      onBoundary = onBoundary || distanceToSegment(mid, segments[i].first, segments[i].second, t) <= tolerance;
    });
    check.unmatchedInnerEdges += !onBoundary;
  }

  // No vertex of an element may lie inside an element edge it is not a corner of. In a tiling
  // such a vertex ends edges used once (the finer side's) and lies on another (the coarser
  // side's, which no element runs the other way): those are what is looked at.
  segments.clear();
  for (const auto& [a, b] : once) segments.push_back({mesh.vertices[a], mesh.vertices[b]});
  const SegmentGrid edges(segments, onEdge);
  std::vector<uint32_t> ends;
  for (const auto& [a, b] : once) ends.push_back(a), ends.push_back(b);
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  for (uint32_t v : ends) {
    const Vec2 p = mesh.vertices[v];
    edges.near(p, [&](uint32_t i) {
      if (once[i].first == v || once[i].second == v) return;
      double t;
      const Vec2 a = segments[i].first, b = segments[i].second;
      const double d = distanceToSegment(p, a, b, t);
      if (d <= onEdge && t > 1e-12 && t < 1 - 1e-12 && d <= kInLine * std::min(glm::length(p - a), glm::length(p - b)))
        ++check.tVertices;
    });
  }
  return check;
}

}  // namespace mesher
