#include "engine/coplanar_merge.h"

#include "engine/surface_mesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

namespace engine {

namespace {

using mesher::Vec2;

// Surfaces that may merge: same material, same owner (or all fixed), the same plane and facing.
bool sameGroup(const Scene& scene, const Surface& a, const Surface& b, double tolerance) {
  if (a.material != b.material) return false;
  const bool fixedA = !scene.objects[a.object].movable, fixedB = !scene.objects[b.object].movable;
  if (a.object != b.object && !(fixedA && fixedB)) return false;
  return glm::dot(a.normal, b.normal) > 1 - 1e-12 && std::abs(a.planeOffset() - b.planeOffset()) <= tolerance;
}

struct Edge {
  Vec2 a, b;
};

void ringEdges(const mesher::Ring2& ring, std::vector<Edge>& out) {
  for (size_t i = 0; i < ring.size(); ++i) out.push_back({ring[i], ring[(i + 1) % ring.size()]});
}

// True when p lies strictly inside segment a-b (within `tolerance` of it).
bool strictlyOn(Vec2 p, Vec2 a, Vec2 b, double tolerance) {
  if (p == a || p == b) return false;
  const Vec2 d = b - a;
  const double length2 = glm::dot(d, d);
  const double t = glm::dot(p - a, d) / length2;
  if (t <= 0 || t >= 1) return false;
  return glm::length(p - (a + t * d)) <= tolerance;
}

// Whether two surfaces' boundaries share a stretch of positive length, run opposite ways.
bool touch(const std::vector<Edge>& a, const std::vector<Edge>& b, double tolerance) {
  for (const Edge& e : a)
    for (const Edge& f : b) {
      const Vec2 d = e.b - e.a, g = f.b - f.a;
      if (glm::dot(d, g) >= 0) continue;  // must run against each other
      const double cross = d.x * g.y - d.y * g.x;
      if (std::abs(cross) > tolerance * (glm::length(d) + glm::length(g))) continue;
      // Collinear and opposed: overlap when some end of one lies on the other (or they coincide).
      if ((e.a == f.b && e.b == f.a) || strictlyOn(f.a, e.a, e.b, tolerance) || strictlyOn(f.b, e.a, e.b, tolerance) ||
          strictlyOn(e.a, f.a, f.b, tolerance) || strictlyOn(e.b, f.a, f.b, tolerance))
        return true;
    }
  return false;
}

// The union of polygons that only touch: split every edge at the vertices lying on it, cancel
// edges that run both ways, and trace what is left into rings. Empty when that does not give
// exactly one counter-clockwise ring and any clockwise rings inside it.
std::optional<mesher::PolygonWithHoles> unite(const std::vector<mesher::PolygonWithHoles>& parts, double tolerance) {
  std::vector<Edge> edges;
  std::vector<Vec2> points;
  for (const auto& p : parts) {
    ringEdges(p.outer, edges);
    points.insert(points.end(), p.outer.begin(), p.outer.end());
    for (const auto& h : p.holes) {
      ringEdges(h, edges);
      points.insert(points.end(), h.begin(), h.end());
    }
  }
  // Split edges at T-junctions.
  std::vector<Edge> split;
  for (const Edge& e : edges) {
    std::vector<std::pair<double, Vec2>> cuts;
    for (const Vec2& p : points)
      if (strictlyOn(p, e.a, e.b, tolerance)) cuts.push_back({glm::dot(p - e.a, e.b - e.a), p});
    std::sort(cuts.begin(), cuts.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    Vec2 from = e.a;
    for (const auto& [t, p] : cuts) {
      if (p != from) split.push_back({from, p});
      from = p;
    }
    split.push_back({from, e.b});
  }
  // Cancel shared edges.
  auto key = [](Vec2 a, Vec2 b) { return std::array<double, 4>{a.x, a.y, b.x, b.y}; };
  std::map<std::array<double, 4>, int> count;
  for (const Edge& e : split) ++count[key(e.a, e.b)];
  std::multimap<std::pair<double, double>, Vec2> next;
  for (const Edge& e : split) {
    auto& forward = count[key(e.a, e.b)];
    auto& backward = count[key(e.b, e.a)];
    if (forward > 0 && backward > 0) {
      --forward, --backward;
      continue;
    }
    if (forward > 0) {
      --forward;
      next.insert({{e.a.x, e.a.y}, e.b});
    }
  }
  // Trace rings; a point left with several ways on (a pinch) ends the attempt.
  std::vector<mesher::Ring2> rings;
  while (!next.empty()) {
    mesher::Ring2 ring;
    auto at = next.begin();
    const Vec2 start{at->first.first, at->first.second};
    Vec2 p = start;
    while (true) {
      const auto range = next.equal_range({p.x, p.y});
      if (range.first == range.second) return std::nullopt;
      if (std::next(range.first) != range.second) return std::nullopt;
      ring.push_back(p);
      const Vec2 q = range.first->second;
      next.erase(range.first);
      p = q;
      if (p == start) break;
    }
    rings.push_back(std::move(ring));
  }
  mesher::PolygonWithHoles out;
  for (auto& ring : rings) {
    if (mesher::signedArea(ring) > 0) {
      if (!out.outer.empty()) return std::nullopt;
      out.outer = std::move(ring);
    } else {
      out.holes.push_back(std::move(ring));
    }
  }
  if (out.outer.empty()) return std::nullopt;
  return out;
}

}  // namespace

std::vector<Surface> mergeCoplanarSurfaces(const Scene& scene, std::vector<Surface> surfaces, double tolerance) {
  // Group candidates, then join touching members (union-find by index).
  const size_t n = surfaces.size();
  std::vector<size_t> root(n);
  for (size_t i = 0; i < n; ++i) root[i] = i;
  auto find = [&](size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  // Candidates sorted by material, owner, facing and plane offset: only neighbours in that order
  // can belong together. (Facings rounded to 1e-6 may rarely split a group: it then stays apart.)
  struct Key {
    uint32_t material;
    int64_t owner, nx, ny, nz;
    double offset;
    size_t index;
  };
  std::vector<Key> keys;
  for (size_t i = 0; i < n; ++i) {
    const Surface& s = surfaces[i];
    auto round = [](double v) { return static_cast<int64_t>(std::llround(v * 1e6)); };
    keys.push_back({s.material, scene.objects[s.object].movable ? static_cast<int64_t>(s.object) : -1,
                    round(s.normal.x), round(s.normal.y), round(s.normal.z), s.planeOffset(), i});
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return std::tie(a.material, a.owner, a.nx, a.ny, a.nz, a.offset) < std::tie(b.material, b.owner, b.nx, b.ny, b.nz, b.offset);
  });
  for (size_t k = 0; k < n; ++k)
    for (size_t l = k + 1; l < n; ++l) {
      const Key& first = keys[k];
      const Key& second = keys[l];
      if (std::tie(first.material, first.owner, first.nx, first.ny, first.nz) !=
              std::tie(second.material, second.owner, second.nx, second.ny, second.nz) ||
          second.offset - first.offset > tolerance)
        break;
      const size_t i = first.index, j = second.index;
      if (!sameGroup(scene, surfaces[i], surfaces[j], tolerance)) continue;
      const mesher::PolygonWithHoles a = planePolygon(surfaces[i], surfaces[i]);
      const mesher::PolygonWithHoles b = planePolygon(surfaces[j], surfaces[i]);
      std::vector<Edge> ea, eb;
      ringEdges(a.outer, ea);
      ringEdges(b.outer, eb);
      if (touch(ea, eb, tolerance)) root[find(j)] = find(i);
    }

  std::map<size_t, std::vector<size_t>> groups;
  for (size_t i = 0; i < n; ++i) groups[find(i)].push_back(i);
  std::vector<Surface> out;
  for (const auto& [first, members] : groups) {
    if (members.size() == 1) {
      out.push_back(std::move(surfaces[first]));
      continue;
    }
    // Unite in the first member's plane coordinates, then lift back to its plane.
    const Surface& base = surfaces[members.front()];
    std::vector<mesher::PolygonWithHoles> parts;
    std::map<std::pair<double, double>, Vec3> lifted;
    for (size_t m : members) {
      parts.push_back(planePolygon(surfaces[m], base));
      const Surface& s = surfaces[m];
      size_t k = 0;
      for (const Vec3& p : s.outer) lifted[{parts.back().outer[k].x, parts.back().outer[k].y}] = p, ++k;
      for (size_t h = 0; h < s.holes.size(); ++h)
        for (size_t i = 0; i < s.holes[h].size(); ++i)
          lifted[{parts.back().holes[h][i].x, parts.back().holes[h][i].y}] = s.holes[h][i];
    }
    const auto united = unite(parts, tolerance);
    if (!united) {
      for (size_t m : members) out.push_back(std::move(surfaces[m]));
      continue;
    }
    Surface merged = base;
    merged.outer.clear();
    merged.holes.clear();
    for (const Vec2& p : united->outer) merged.outer.push_back(lifted.at({p.x, p.y}));
    for (const auto& hole : united->holes) {
      Ring3& ring = merged.holes.emplace_back();
      for (const Vec2& p : hole) ring.push_back(lifted.at({p.x, p.y}));
    }
    merged.area = 0;
    for (size_t m : members) {
      merged.area += surfaces[m].area;
      merged.patchSize = std::min(merged.patchSize, surfaces[m].patchSize);
      if (m != members.front()) merged.face += " + " + surfaces[m].face;
    }
    out.push_back(std::move(merged));
  }
  return out;
}

}  // namespace engine
