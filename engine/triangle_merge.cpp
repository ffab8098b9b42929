// Sections: welding and plane groups | edges: pairing and T-junction splits | tracing rings |
// a group into surfaces | mergeTriangles.
#include "engine/triangle_merge.h"

#include "mesher/polygon.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <compare>
#include <numbers>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>

namespace engine {

namespace {

using mesher::Vec2;
constexpr uint32_t kNone = 0xffffffffu;
constexpr size_t kMaxHoles = 256;  // as in scene files: the display's hole bridging is quadratic
constexpr int kSplitRounds = 8;    // times a group may shed the triangles at its touching corners
constexpr double kNormalGrid = 1e4;  // plane groups: unit normals rounded to 1e-4
constexpr double kOffsetCells = 4;   // plane groups: offsets rounded to this many tolerances

// ---- welding and plane groups ----

// Corners are welded when their coordinates are equal exactly: exporters repeat a corner once
// per normal and texture coordinate. (-0.0 + 0.0 is +0.0, so both zeros hash alike.)
struct PointHash {
  size_t operator()(const Vec3& p) const {
    uint64_t h = 1469598103934665603ull;
    for (int k = 0; k < 3; ++k) h = (h ^ std::bit_cast<uint64_t>(p[k] + 0.0)) * 1099511628211ull;
    return h;
  }
};

struct PlaneKey {
  int64_t owner;  // the object, or -1 for fixed objects, which may merge with each other
  uint32_t material;
  int64_t nx, ny, nz, offset;
  auto operator<=>(const PlaneKey&) const = default;
};

struct Triangle {
  std::array<uint32_t, 3> v;  // welded corners
  Vec3 normal;
  double area;
  uint32_t source;  // index into the input
  PlaneKey key;
};

// A plane group's 2-D frame, counter-clockwise about its normal; world axes when the normal is
// one, so coordinates stay exact (as surface_mesh.cpp lays surfaces down).
struct Frame {
  Vec3 u, v;
  Vec2 project(const Vec3& p) const { return {glm::dot(p, u), glm::dot(p, v)}; }
};

Frame frameFor(const Vec3& n) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  if (n == x) return {y, z};
  if (n == -x) return {z, y};
  if (n == y) return {z, x};
  if (n == -y) return {x, z};
  if (n == z) return {x, y};
  if (n == -z) return {y, x};
  const Vec3 a = glm::abs(n);
  const Vec3 helper = a.x <= a.y && a.x <= a.z ? x : (a.y <= a.z ? y : z);
  const Vec3 u = glm::normalize(glm::cross(helper, n));
  return {u, glm::cross(n, u)};
}

// ---- edges: pairing and T-junction splits ----

struct HalfEdge {
  uint32_t a, b;  // local vertices, in the triangle's order
  uint32_t tri;   // local triangle
};

// For each half-edge its twin running the other way (a triangle across it), or kNone. Several
// half-edges on one segment pair up as far as they go (non-manifold input).
std::vector<uint32_t> pairEdges(const std::vector<HalfEdge>& edges) {
  auto key = [&](uint32_t i) {
    const HalfEdge& e = edges[i];
    return std::tuple(std::min(e.a, e.b), std::max(e.a, e.b), e.a > e.b, i);
  };
  std::vector<uint32_t> order(edges.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t i, uint32_t j) { return key(i) < key(j); });
  std::vector<uint32_t> twin(edges.size(), kNone);
  for (size_t i = 0; i < order.size();) {
    const HalfEdge& e = edges[order[i]];
    const auto segment = std::pair(std::min(e.a, e.b), std::max(e.a, e.b));
    size_t backwardStart = i, end = i;
    for (; end < order.size(); ++end) {
      const HalfEdge& f = edges[order[end]];
      if (std::pair(std::min(f.a, f.b), std::max(f.a, f.b)) != segment) break;
      if (f.a < f.b) backwardStart = end + 1;
    }
    for (size_t f = i, b = backwardStart; f < backwardStart && b < end; ++f, ++b) {
      twin[order[f]] = order[b];
      twin[order[b]] = order[f];
    }
    i = end;
  }
  return twin;
}

// ---- tracing rings ----

// Turning clockwise from direction `back` to `out`, in (0, 2 pi].
double clockwiseTurn(Vec2 back, Vec2 out) {
  double angle = std::atan2(back.y, back.x) - std::atan2(out.y, out.x);
  while (angle <= 0) angle += 2 * std::numbers::pi;
  while (angle > 2 * std::numbers::pi) angle -= 2 * std::numbers::pi;
  return angle;
}

// One plane group after splitting: local vertices, triangles and their half-edges.
struct Bucket {
  Vec3 normal;
  std::vector<uint32_t> global;      // local vertex -> welded vertex
  std::vector<Vec2> p2;              // local vertex in the group's frame
  std::vector<uint32_t> tris;        // local triangle -> index into the triangles
  std::vector<HalfEdge> edges;       // after splitting; a triangle's are contiguous, in order
  std::vector<uint32_t> firstEdge;   // per local triangle, and one past the last
  std::vector<uint32_t> twin;        // per half-edge
};

class Merger {
 public:
  Merger(const Scene& scene, const std::vector<SceneTriangle>& input, double tolerance, TriangleMergeCounts& counts)
      : scene_(scene), input_(input), tolerance_(tolerance), counts_(counts) {}

  std::vector<Surface> run() {
    weld();
    std::vector<Bucket> buckets = groupByPlane();
    for (const Bucket& b : buckets)
      for (const HalfEdge& e : b.edges) ++uses_[b.global[e.a]];
    for (const Bucket& b : buckets) emitBucket(b);
    counts_.surfaces = out_.size();
    return std::move(out_);
  }

 private:
  void weld() {
    std::unordered_map<Vec3, uint32_t, PointHash> index;
    index.reserve(input_.size());
    auto id = [&](const Vec3& p) {
      const auto [at, added] = index.try_emplace(p, static_cast<uint32_t>(points_.size()));
      if (added) points_.push_back(p);
      return at->second;
    };
    triangles_.reserve(input_.size());
    for (uint32_t i = 0; i < input_.size(); ++i) {
      const SceneTriangle& in = input_[i];
      Triangle t;
      for (int k = 0; k < 3; ++k) t.v[k] = id(in.corners[k]);
      const Vec3 cross = glm::cross(in.corners[1] - in.corners[0], in.corners[2] - in.corners[0]);
      const double twiceArea = glm::length(cross);
      const double longest = std::max({glm::length(in.corners[1] - in.corners[0]), glm::length(in.corners[2] - in.corners[1]),
                                       glm::length(in.corners[0] - in.corners[2])});
      // No area: its height above the longest edge is within the tolerance.
      if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[2] == t.v[0] || !(twiceArea > tolerance_ * longest)) {
        ++counts_.degenerate;
        continue;
      }
      t.normal = cross / twiceArea;
      t.area = twiceArea / 2;
      t.source = i;
      const double offset = glm::dot(t.normal, (in.corners[0] + in.corners[1] + in.corners[2]) / 3.0);
      auto grid = [](double c) { return static_cast<int64_t>(std::llround(c * kNormalGrid)); };
      t.key = {scene_.objects[in.object].movable ? static_cast<int64_t>(in.object) : -1, in.material, grid(t.normal.x),
               grid(t.normal.y), grid(t.normal.z), static_cast<int64_t>(std::llround(offset / (kOffsetCells * tolerance_)))};
      triangles_.push_back(t);
    }
    uses_.assign(points_.size(), 0);
  }

  std::vector<Bucket> groupByPlane() {
    std::vector<uint32_t> order(triangles_.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t i, uint32_t j) {
      return std::tie(triangles_[i].key, i) < std::tie(triangles_[j].key, j);
    });
    std::vector<Bucket> buckets;
    std::vector<uint32_t> localOf(points_.size(), kNone);
    for (size_t i = 0; i < order.size();) {
      size_t end = i;
      while (end < order.size() && triangles_[order[end]].key == triangles_[order[i]].key) ++end;
      buckets.push_back(makeBucket(std::vector<uint32_t>(order.begin() + i, order.begin() + end), localOf));
      i = end;
    }
    return buckets;
  }

  // Lays the group into its plane, splits its unmatched edges at the group's vertices lying on
  // them (T-junctions), and pairs the pieces.
  Bucket makeBucket(std::vector<uint32_t> tris, std::vector<uint32_t>& localOf) {
    Bucket b;
    const PlaneKey& key = triangles_[tris.front()].key;
    const int64_t g = static_cast<int64_t>(kNormalGrid);
    const bool axis = std::abs(key.nx) + std::abs(key.ny) + std::abs(key.nz) == g &&
                      (std::abs(key.nx) == g || std::abs(key.ny) == g || std::abs(key.nz) == g);
    Vec3 sum{0};
    for (uint32_t t : tris) sum += triangles_[t].normal * triangles_[t].area;
    b.normal = axis ? Vec3(key.nx / g, key.ny / g, key.nz / g) : glm::normalize(sum);
    const Frame frame = frameFor(b.normal);
    b.tris = std::move(tris);

    // Local vertices and whole edges.
    std::vector<HalfEdge> whole;
    whole.reserve(3 * b.tris.size());
    for (uint32_t t = 0; t < b.tris.size(); ++t) {
      std::array<uint32_t, 3> local;
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = triangles_[b.tris[t]].v[k];
        if (localOf[v] == kNone) {
          localOf[v] = static_cast<uint32_t>(b.global.size());
          b.global.push_back(v);
          b.p2.push_back(frame.project(points_[v]));
        }
        local[k] = localOf[v];
      }
      for (int k = 0; k < 3; ++k) whole.push_back({local[k], local[(k + 1) % 3], t});
    }
    for (uint32_t v : b.global) localOf[v] = kNone;
    const std::vector<uint32_t> wholeTwin = pairEdges(whole);

    // Only unmatched edges can hold a T-junction, and only at an end of another unmatched edge:
    // those ends, sorted along u, are searched for each such edge.
    std::vector<uint32_t> ends;
    for (size_t e = 0; e < whole.size(); ++e)
      if (wholeTwin[e] == kNone) ends.push_back(whole[e].a), ends.push_back(whole[e].b);
    std::sort(ends.begin(), ends.end(), [&](uint32_t i, uint32_t j) { return std::tie(b.p2[i].x, i) < std::tie(b.p2[j].x, j); });
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    std::vector<std::pair<double, uint32_t>> cuts;
    b.edges.reserve(whole.size());
    b.firstEdge.reserve(b.tris.size() + 1);
    for (size_t e = 0; e < whole.size(); ++e) {
      if (e % 3 == 0) b.firstEdge.push_back(static_cast<uint32_t>(b.edges.size()));
      const HalfEdge& edge = whole[e];
      cuts.clear();
      if (wholeTwin[e] == kNone) {
        const Vec2 a = b.p2[edge.a], d = b.p2[edge.b] - a;
        const double length = glm::length(d);
        const double lo = std::min(a.x, a.x + d.x) - tolerance_, hi = std::max(a.x, a.x + d.x) + tolerance_;
        auto first = std::lower_bound(ends.begin(), ends.end(), lo, [&](uint32_t i, double x) { return b.p2[i].x < x; });
        const HalfEdge* corners = &whole[e - e % 3];
        for (auto it = first; it != ends.end() && b.p2[*it].x <= hi; ++it) {
          // A sliver's own third corner may lie within the tolerance of its edge: not a junction.
          if (*it == corners[0].a || *it == corners[1].a || *it == corners[2].a) continue;
          const Vec2 p = b.p2[*it] - a;
          const double along = glm::dot(p, d) / length;
          if (along <= tolerance_ || along >= length - tolerance_) continue;
          if (std::abs(p.x * d.y - p.y * d.x) / length > tolerance_) continue;
          cuts.push_back({along, *it});
        }
        std::sort(cuts.begin(), cuts.end());
        counts_.tJunctions += cuts.size();
      }
      uint32_t from = edge.a;
      for (const auto& [along, v] : cuts) {
        b.edges.push_back({from, v, edge.tri});
        from = v;
      }
      b.edges.push_back({from, edge.b, edge.tri});
    }
    b.firstEdge.push_back(static_cast<uint32_t>(b.edges.size()));
    b.twin = pairEdges(b.edges);
    return b;
  }

  // ---- a group into surfaces ----

  void emitBucket(const Bucket& b) {
    // Triangles joined across paired half-edges (union-find by local triangle).
    std::vector<uint32_t> root(b.tris.size());
    std::iota(root.begin(), root.end(), 0u);
    unite(b, root, [](uint32_t) { return true; });
    std::vector<std::vector<uint32_t>> groups = groupsOf(root, [](uint32_t) { return true; });
    member_.assign(b.tris.size(), kNone);
    for (std::vector<uint32_t>& group : groups) emitGroup(b, std::move(group), 0);
  }

  template <class Keep>
  void unite(const Bucket& b, std::vector<uint32_t>& root, Keep keep) {
    auto find = [&](uint32_t i) {
      while (root[i] != i) i = root[i] = root[root[i]];
      return i;
    };
    for (size_t e = 0; e < b.edges.size(); ++e) {
      const uint32_t t = b.twin[e];
      if (t == kNone || !keep(b.edges[e].tri) || !keep(b.edges[t].tri)) continue;
      root[find(b.edges[e].tri)] = find(b.edges[t].tri);
    }
    for (uint32_t i = 0; i < root.size(); ++i) root[i] = find(i);
  }

  template <class Keep>
  static std::vector<std::vector<uint32_t>> groupsOf(const std::vector<uint32_t>& root, Keep keep) {
    std::unordered_map<uint32_t, size_t> slot;
    std::vector<std::vector<uint32_t>> groups;
    for (uint32_t i = 0; i < root.size(); ++i) {
      if (!keep(i)) continue;
      const auto [at, added] = slot.try_emplace(root[i], groups.size());
      if (added) groups.emplace_back();
      groups[at->second].push_back(i);
    }
    return groups;
  }

  void emitGroup(const Bucket& b, std::vector<uint32_t> group, int round) {
    if (group.size() == 1) return emitSingle(b, group.front());
    const uint32_t stamp = ++stamp_;
    for (uint32_t t : group) member_[t] = stamp;
    std::vector<std::vector<uint32_t>> rings = traceRings(b, group, stamp);

    // Corners where the boundary touches itself: the triangles there go on their own, the rest
    // is tried again (it may fall apart into several groups).
    std::unordered_map<uint32_t, int> seen;
    std::vector<uint32_t> touching;
    for (const auto& ring : rings)
      for (uint32_t v : ring)
        if (++seen[v] == 2) touching.push_back(v);
    if (!touching.empty() || rings.empty()) {
      if (round >= kSplitRounds || rings.empty()) {
        for (uint32_t t : group) emitSingle(b, t);
        return;
      }
      std::sort(touching.begin(), touching.end());
      std::vector<uint8_t> single(b.tris.size(), 0);
      for (uint32_t t : group)
        for (uint32_t e = b.firstEdge[t]; e < b.firstEdge[t + 1]; ++e)
          if (std::binary_search(touching.begin(), touching.end(), b.edges[e].a)) single[t] = 1;
      std::vector<uint32_t> root(b.tris.size());
      std::iota(root.begin(), root.end(), 0u);
      auto rest = [&](uint32_t t) { return member_[t] == stamp && !single[t]; };
      unite(b, root, rest);
      std::vector<std::vector<uint32_t>> parts = groupsOf(root, rest);
      for (uint32_t t : group)
        if (single[t]) emitSingle(b, t);
      for (std::vector<uint32_t>& part : parts) emitGroup(b, std::move(part), round + 1);
      return;
    }

    std::unordered_map<uint32_t, uint32_t> groupUses;
    for (uint32_t t : group)
      for (uint32_t e = b.firstEdge[t]; e < b.firstEdge[t + 1]; ++e) ++groupUses[b.edges[e].a];
    for (auto& ring : rings) dropCollinear(b, ring, groupUses);
    if (!emitPolygon(b, group, rings))
      for (uint32_t t : group) emitSingle(b, t);
  }

  // The group's boundary: half-edges without a twin in the group, traced into rings; where
  // several leave one vertex, the one turning most to the left (the first clockwise from the way
  // back) keeps each ring from crossing into another.
  std::vector<std::vector<uint32_t>> traceRings(const Bucket& b, const std::vector<uint32_t>& group, uint32_t stamp) const {
    std::vector<uint32_t> boundary;
    for (uint32_t t : group)
      for (uint32_t e = b.firstEdge[t]; e < b.firstEdge[t + 1]; ++e)
        if (b.twin[e] == kNone || member_[b.edges[b.twin[e]].tri] != stamp) boundary.push_back(e);
    std::sort(boundary.begin(), boundary.end(), [&](uint32_t i, uint32_t j) {
      return std::tie(b.edges[i].a, i) < std::tie(b.edges[j].a, j);
    });
    auto leaving = [&](uint32_t v) {
      const auto lo = std::lower_bound(boundary.begin(), boundary.end(), v, [&](uint32_t e, uint32_t x) { return b.edges[e].a < x; });
      auto hi = lo;
      while (hi != boundary.end() && b.edges[*hi].a == v) ++hi;
      return std::pair(lo, hi);
    };
    std::unordered_map<uint32_t, uint8_t> used;
    std::vector<std::vector<uint32_t>> rings;
    for (uint32_t start : boundary) {
      if (used[start]) continue;
      std::vector<uint32_t>& ring = rings.emplace_back();
      for (uint32_t e = start;;) {
        used[e] = 1;
        ring.push_back(b.edges[e].a);
        const uint32_t v = b.edges[e].b;
        const auto [lo, hi] = leaving(v);
        uint32_t next = kNone;
        double best = 1e300;
        for (auto it = lo; it != hi; ++it) {
          const double turn = clockwiseTurn(b.p2[b.edges[e].a] - b.p2[v], b.p2[b.edges[*it].b] - b.p2[v]);
          if (turn < best) best = turn, next = *it;
        }
        if (next == start) break;
        if (next == kNone || used[next] || ring.size() > boundary.size()) return {};  // an open or tangled boundary
        e = next;
      }
    }
    return rings;
  }

  // Drops ring corners that are exactly collinear with their neighbours and that no triangle
  // outside the group uses (those would leave a T-vertex in a neighbour).
  void dropCollinear(const Bucket& b, std::vector<uint32_t>& ring, const std::unordered_map<uint32_t, uint32_t>& groupUses) const {
    for (bool changed = true; changed && ring.size() > 3;) {
      changed = false;
      for (size_t i = 0; i < ring.size() && ring.size() > 3; ++i) {
        const uint32_t v = ring[i];
        const Vec2 p = b.p2[ring[(i + ring.size() - 1) % ring.size()]], q = b.p2[ring[(i + 1) % ring.size()]];
        if (mesher::orient2(p, b.p2[v], q) != 0 || glm::dot(p - b.p2[v], q - b.p2[v]) >= 0) continue;
        if (groupUses.at(v) != uses_[b.global[v]]) continue;
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }

  // One counter-clockwise outer ring and clockwise holes inside it, all simple and apart, as the
  // mesher needs; false when the rings are not that.
  bool emitPolygon(const Bucket& b, const std::vector<uint32_t>& group, const std::vector<std::vector<uint32_t>>& rings) {
    auto ring2 = [&](const std::vector<uint32_t>& ring) {
      mesher::Ring2 r;
      r.reserve(ring.size());
      for (uint32_t v : ring) r.push_back(b.p2[v]);
      return r;
    };
    size_t outerIndex = rings.size();
    std::vector<size_t> holes;
    for (size_t i = 0; i < rings.size(); ++i) {
      const double area = mesher::signedArea(ring2(rings[i]));
      if (area > 0) {
        if (outerIndex != rings.size()) return false;
        outerIndex = i;
      } else if (area < 0) {
        holes.push_back(i);
      } else {
        return false;
      }
    }
    if (outerIndex == rings.size() || holes.size() > kMaxHoles) return false;
    const mesher::Ring2 outer = ring2(rings[outerIndex]);
    if (!mesher::isSimple(outer)) return false;
    std::vector<mesher::Ring2> holes2;
    for (size_t h : holes) {
      holes2.push_back(ring2(rings[h]));
      if (!mesher::isSimple(holes2.back()) || !mesher::containsPoint(outer, holes2.back().front()) ||
          mesher::boundaryDistance(holes2.back(), outer) <= 0)
        return false;
    }
    for (size_t i = 0; i < holes2.size(); ++i)
      for (size_t j = i + 1; j < holes2.size(); ++j)
        if (mesher::boundaryDistance(holes2[i], holes2[j]) <= 0) return false;

    Surface s = surfaceOf(b, group);
    s.normal = b.normal;
    for (uint32_t v : rings[outerIndex]) s.outer.push_back(points_[b.global[v]]);
    for (size_t h : holes) {
      Ring3& ring = s.holes.emplace_back();
      for (uint32_t v : rings[h]) ring.push_back(points_[b.global[v]]);
    }
    out_.push_back(std::move(s));
    return true;
  }

  // A triangle on its own, with the vertices splitting its edges, so neighbours meet it corner
  // to corner.
  void emitSingle(const Bucket& b, uint32_t t) {
    Surface s = surfaceOf(b, {t});
    s.normal = triangles_[b.tris[t]].normal;
    mesher::Ring2 ring;
    for (uint32_t e = b.firstEdge[t]; e < b.firstEdge[t + 1]; ++e) ring.push_back(b.p2[b.edges[e].a]);
    // Near a needle-sharp corner one vertex may lie on both of its edges: the split ring would
    // touch itself, so such a triangle keeps its three corners only.
    const bool simple = mesher::isSimple(ring);
    const std::array<uint32_t, 3>& corners = triangles_[b.tris[t]].v;
    for (uint32_t e = b.firstEdge[t]; e < b.firstEdge[t + 1]; ++e) {
      const uint32_t v = b.global[b.edges[e].a];
      if (simple || std::find(corners.begin(), corners.end(), v) != corners.end()) s.outer.push_back(points_[v]);
    }
    out_.push_back(std::move(s));
    ++counts_.singles;
  }

  Surface surfaceOf(const Bucket& b, const std::vector<uint32_t>& group) const {
    const SceneTriangle& first = input_[triangles_[b.tris[group.front()]].source];
    Surface s;
    s.material = first.material;
    s.object = first.object;
    for (uint32_t t : group) s.area += triangles_[b.tris[t]].area;
    s.face = std::to_string(group.size()) + (group.size() == 1 ? " triangle" : " triangles");
    return s;
  }

  const Scene& scene_;
  const std::vector<SceneTriangle>& input_;
  double tolerance_;
  TriangleMergeCounts& counts_;
  std::vector<Vec3> points_;         // welded
  std::vector<Triangle> triangles_;  // with area
  std::vector<uint32_t> uses_;       // per welded vertex: half-edges starting there, all groups
  std::vector<uint32_t> member_;     // per local triangle of the bucket: the stamp of its group
  uint32_t stamp_ = 0;
  std::vector<Surface> out_;
};

}  // namespace

std::vector<Surface> mergeTriangles(const Scene& scene, const std::vector<SceneTriangle>& triangles, double tolerance,
                                    TriangleMergeCounts* counts) {
  TriangleMergeCounts local;
  TriangleMergeCounts& c = counts ? *counts : local;
  c = {};
  c.triangles = triangles.size();
  return Merger(scene, triangles, tolerance, c).run();
}

}  // namespace engine
