// Sections: pieces, welding and plane groups | edges: pairing and T-junction splits | tracing
// rings | a group into surfaces | the inputs: mergeTriangles, mergeFaces.
#include "engine/geometry/coplanar_merge.h"

#include "engine/geometry/surface_mesh.h"

#include "mesher/polygon.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <compare>
#include <numbers>
#include <numeric>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>

namespace engine {

namespace {

using mesher::Vec2;
constexpr uint32_t kNone = 0xffffffffu;
constexpr size_t kMaxHoles = 256;  // as in scene files: the display's hole bridging is quadratic
constexpr int kSplitRounds = 8;    // times a group may shed the pieces at its touching corners
constexpr double kNormalGrid = 1e4;  // plane groups: unit normals rounded to 1e-4
constexpr double kOffsetCells = 4;   // plane groups: offsets rounded to this many tolerances

// ---- pieces, welding and plane groups ----

// Corners are welded when their coordinates are equal exactly: exporters repeat a corner once
// per normal and texture coordinate, and a scene file's flush faces repeat each other's corners.
// An open-addressing table of welded vertices, at most half full, allocates nothing per corner
// (a model has millions).
class Welder {
 public:
  // For at most `corners` corners.
  explicit Welder(size_t corners)
      : slots_(std::bit_ceil(2 * corners + 2), kNone), shift_(64 - std::countr_zero(slots_.size())) {}

  // The welded vertex at `p`, appended to `points` when new.
  uint32_t weld(const Vec3& p, std::vector<Vec3>& points) {
    for (size_t i = slotOf(p);; i = (i + 1) & (slots_.size() - 1)) {
      if (slots_[i] == kNone) {
        slots_[i] = static_cast<uint32_t>(points.size());
        points.push_back(p);
        return slots_[i];
      }
      if (points[slots_[i]] == p) return slots_[i];
    }
  }

 private:
  // Fibonacci hashing of the coordinates' bits: round numbers have no low bits to tell them
  // apart. (-0.0 + 0.0 is +0.0, so both zeros, which compare equal, hash alike.)
  size_t slotOf(const Vec3& p) const {
    uint64_t h = 1469598103934665603ull;
    for (int k = 0; k < 3; ++k) h = (h ^ std::bit_cast<uint64_t>(p[k] + 0.0)) * 1099511628211ull;
    return static_cast<size_t>((h * 0x9e3779b97f4a7c15ull) >> shift_);
  }

  std::vector<uint32_t> slots_;  // welded vertex or kNone
  int shift_;                    // 64 - log2 of the slot count
};

struct PlaneKey {
  int64_t owner;  // the object, or -1 for fixed objects, which may merge with each other
  uint32_t material;
  int64_t nx, ny, nz, offset;
  auto operator<=>(const PlaneKey&) const = default;
};

// A planar piece to merge: a triangle, or a face with holes.
struct Piece {
  uint32_t firstRing;  // into Merger::ringEnd_; its rings (outer, then holes) run to the next piece's
  Vec3 normal;
  double area;
  uint32_t material, object;
  uint32_t source;  // the caller's index
  PlaneKey key;
};

// One surface a merge makes; its material and object are its first piece's.
struct Polygon {
  Ring3 outer;  // empty: a piece on its own as it was given (most are: no copies of their rings)
  std::vector<Ring3> holes;
  Vec3 normal;
  double area = 0;
};

struct Merged {
  std::vector<Polygon> polygons;
  std::vector<uint32_t> sources;     // polygon after polygon, ascending: its pieces' sources
  std::vector<uint32_t> sourcesEnd;  // per polygon: one past its last in `sources`

  std::span<const uint32_t> sourcesOf(size_t polygon) const {
    const uint32_t begin = polygon == 0 ? 0 : sourcesEnd[polygon - 1];
    return {sources.data() + begin, sourcesEnd[polygon] - begin};
  }
};

// Whether ring corners that are exactly collinear, and used by no other surface, may go.
enum class Corners { DropUnsharedCollinear, KeepAll };

// A plane group's 2-D frame, counter-clockwise about its normal; world axes when the normal is
// one, so coordinates stay exact (axisPlaneAxes, as surfaces are laid down for meshing).
struct Frame {
  Vec3 u, v;
  Vec2 project(const Vec3& p) const { return {glm::dot(p, u), glm::dot(p, v)}; }
};

Frame frameFor(const Vec3& n) {
  if (const auto axes = axisPlaneAxes(n)) return {axes->first, axes->second};
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  const Vec3 a = glm::abs(n);
  const Vec3 helper = a.x <= a.y && a.x <= a.z ? x : (a.y <= a.z ? y : z);
  const Vec3 u = glm::normalize(glm::cross(helper, n));
  return {u, glm::cross(n, u)};
}

// ---- edges: pairing and T-junction splits ----

struct HalfEdge {
  uint32_t a, b;   // local vertices, in the ring's order
  uint32_t piece;  // local piece
};

// For each half-edge its twin running the other way (a piece across it), or kNone. Several
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

// One plane group after splitting: local vertices, pieces, their rings and half-edges (only the
// pieces for a piece alone in its plane).
struct Bucket {
  Vec3 normal;
  std::vector<uint32_t> global;         // local vertex -> welded vertex
  std::vector<Vec2> p2;                 // local vertex in the group's frame
  std::vector<uint32_t> pieces;         // local piece -> index into the pieces
  std::vector<uint32_t> firstRing;      // per local piece, and one past the last: its local rings
  std::vector<HalfEdge> edges;          // after splitting; a ring's are contiguous, in order
  std::vector<uint32_t> ringFirstEdge;  // per local ring, and one past the last
  std::vector<uint32_t> twin;           // per half-edge

  uint32_t firstEdge(uint32_t piece) const { return ringFirstEdge[firstRing[piece]]; }
};

class Merger {
 public:
  // For pieces with at most `cornerCount` corners in all.
  Merger(const Scene& scene, double tolerance, Corners corners, TriangleMergeCounts& counts, size_t cornerCount)
      : scene_(scene), tolerance_(tolerance), cornerRule_(corners), counts_(counts), welder_(cornerCount) {
    ringCorners_.reserve(cornerCount);
  }

  // A piece is given ring by ring (its outer ring counter-clockwise seen from the front, then its
  // holes, clockwise), then closed by addPiece.
  void addRing(std::span<const Vec3> ring) {
    for (const Vec3& p : ring) ringCorners_.push_back(welder_.weld(p, points_));
    ringEnd_.push_back(static_cast<uint32_t>(ringCorners_.size()));
  }

  // Closes the piece whose rings were just added; `source` is the caller's index for it. Its
  // plane's offset is taken at the mean of its outer corners.
  void addPiece(const Vec3& normal, double area, uint32_t material, uint32_t object, uint32_t source) {
    Piece p{nextRing_, normal, area, material, object, source, {}};
    nextRing_ = static_cast<uint32_t>(ringEnd_.size());
    const uint32_t begin = ringBegin(p.firstRing), end = ringEnd_[p.firstRing];
    Vec3 sum{0};
    for (uint32_t k = begin; k < end; ++k) sum += points_[ringCorners_[k]];
    const double offset = glm::dot(normal, sum / static_cast<double>(end - begin));
    auto grid = [](double c) { return static_cast<int64_t>(std::llround(c * kNormalGrid)); };
    p.key = {scene_.objects[object].movable ? static_cast<int64_t>(object) : -1, material, grid(normal.x), grid(normal.y),
             grid(normal.z), static_cast<int64_t>(std::llround(offset / (kOffsetCells * tolerance_)))};
    pieces_.push_back(p);
  }

  Merged run() {
    std::vector<Bucket> buckets = groupByPlane();
    if (cornerRule_ == Corners::DropUnsharedCollinear) {
      uses_.assign(points_.size(), 0);
      for (const Bucket& b : buckets) {
        for (const HalfEdge& e : b.edges) ++uses_[b.global[e.a]];
        if (b.pieces.size() == 1)
          for (uint32_t k = ringBegin(pieces_[b.pieces[0]].firstRing); k < ringBegin(ringsEnd(b.pieces[0])); ++k)
            ++uses_[ringCorners_[k]];  // its corners, as its unsplit half-edges would count them
      }
    }
    out_.polygons.reserve(buckets.size());
    for (const Bucket& b : buckets) {
      if (b.pieces.size() == 1) emitGiven(b.pieces[0]);
      else emitBucket(b);
    }
    counts_.surfaces = out_.polygons.size();
    return std::move(out_);
  }

 private:
  // Ring r's corners are ringCorners_[ringBegin(r), ringEnd_[r]); piece p's rings are
  // [pieces_[p].firstRing, ringsEnd(p)).
  uint32_t ringBegin(uint32_t ring) const { return ring == 0 ? 0 : ringEnd_[ring - 1]; }
  uint32_t ringsEnd(uint32_t piece) const {
    return piece + 1 < pieces_.size() ? pieces_[piece + 1].firstRing : static_cast<uint32_t>(ringEnd_.size());
  }

  std::vector<Bucket> groupByPlane() {
    std::vector<uint32_t> order(pieces_.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t i, uint32_t j) {
      return std::tie(pieces_[i].key, i) < std::tie(pieces_[j].key, j);
    });
    std::vector<Bucket> buckets;
    std::vector<uint32_t> localOf(points_.size(), kNone);
    for (size_t i = 0; i < order.size();) {
      size_t end = i;
      while (end < order.size() && pieces_[order[end]].key == pieces_[order[i]].key) ++end;
      Bucket& b = buckets.emplace_back();
      b.pieces.assign(order.begin() + i, order.begin() + end);
      // A piece alone in its plane has nothing to merge with or to split its edges at.
      if (end - i > 1) fillBucket(b, pieces_[order[i]].key, localOf);
      i = end;
    }
    return buckets;
  }

  // Lays the group into its plane, splits its unmatched edges at the group's vertices lying on
  // them (T-junctions), and pairs the pieces.
  void fillBucket(Bucket& b, const PlaneKey& key, std::vector<uint32_t>& localOf) {
    const int64_t g = static_cast<int64_t>(kNormalGrid);
    const bool axis = std::abs(key.nx) + std::abs(key.ny) + std::abs(key.nz) == g &&
                      (std::abs(key.nx) == g || std::abs(key.ny) == g || std::abs(key.nz) == g);
    Vec3 sum{0};
    for (uint32_t p : b.pieces) sum += pieces_[p].normal * pieces_[p].area;
    b.normal = axis ? Vec3(key.nx / g, key.ny / g, key.nz / g) : glm::normalize(sum);
    const Frame frame = frameFor(b.normal);

    // Local vertices and whole edges, ring after ring.
    std::vector<HalfEdge> whole;
    std::vector<uint32_t> wholeRingStart;  // per local ring, and one past the last
    whole.reserve(3 * b.pieces.size());
    b.firstRing.reserve(b.pieces.size() + 1);
    for (uint32_t t = 0; t < b.pieces.size(); ++t) {
      const uint32_t piece = b.pieces[t];
      b.firstRing.push_back(static_cast<uint32_t>(wholeRingStart.size()));
      for (uint32_t r = pieces_[piece].firstRing; r < ringsEnd(piece); ++r) {
        wholeRingStart.push_back(static_cast<uint32_t>(whole.size()));
        const uint32_t begin = ringBegin(r), end = ringEnd_[r];
        for (uint32_t k = begin; k < end; ++k) {
          const uint32_t v = ringCorners_[k];
          if (localOf[v] == kNone) {
            localOf[v] = static_cast<uint32_t>(b.global.size());
            b.global.push_back(v);
            b.p2.push_back(frame.project(points_[v]));
          }
        }
        for (uint32_t k = begin; k < end; ++k)
          whole.push_back({localOf[ringCorners_[k]], localOf[ringCorners_[k + 1 < end ? k + 1 : begin]], t});
      }
    }
    b.firstRing.push_back(static_cast<uint32_t>(wholeRingStart.size()));
    wholeRingStart.push_back(static_cast<uint32_t>(whole.size()));
    for (uint32_t v : b.global) localOf[v] = kNone;
    const std::vector<uint32_t> wholeTwin = pairEdges(whole);

    // Only unmatched edges can hold a T-junction, and only at an end of another unmatched edge:
    // those ends, sorted along u and along v, are searched for each such edge along the axis it
    // spans least (walls and floors: only the ends in line with it).
    std::array<std::vector<uint32_t>, 2> ends;
    for (size_t e = 0; e < whole.size(); ++e)
      if (wholeTwin[e] == kNone) ends[0].push_back(whole[e].a), ends[0].push_back(whole[e].b);
    std::sort(ends[0].begin(), ends[0].end());
    ends[0].erase(std::unique(ends[0].begin(), ends[0].end()), ends[0].end());
    ends[1] = ends[0];
    for (int k = 0; k < 2; ++k)
      std::sort(ends[k].begin(), ends[k].end(), [&](uint32_t i, uint32_t j) { return std::tie(b.p2[i][k], i) < std::tie(b.p2[j][k], j); });
    std::vector<uint32_t> ownedBy(b.global.size(), kNone);  // per local vertex: the last piece using it
    std::vector<std::pair<double, uint32_t>> cuts;
    b.edges.reserve(whole.size());
    b.ringFirstEdge.reserve(wholeRingStart.size());
    for (uint32_t t = 0; t < b.pieces.size(); ++t) {
      const uint32_t first = wholeRingStart[b.firstRing[t]], last = wholeRingStart[b.firstRing[t + 1]];
      for (uint32_t e = first; e < last; ++e) ownedBy[whole[e].a] = t;
      for (uint32_t r = b.firstRing[t]; r < b.firstRing[t + 1]; ++r) {
        b.ringFirstEdge.push_back(static_cast<uint32_t>(b.edges.size()));
        for (uint32_t e = wholeRingStart[r]; e < wholeRingStart[r + 1]; ++e) {
          const HalfEdge& edge = whole[e];
          cuts.clear();
          if (wholeTwin[e] == kNone) {
            const Vec2 a = b.p2[edge.a], d = b.p2[edge.b] - a;
            const double length = glm::length(d);
            const int k = std::abs(d.x) <= std::abs(d.y) ? 0 : 1;
            const std::vector<uint32_t>& line = ends[k];
            const Vec2 lo = glm::min(a, a + d) - tolerance_, hi = glm::max(a, a + d) + tolerance_;
            auto from = std::lower_bound(line.begin(), line.end(), lo[k], [&](uint32_t i, double c) { return b.p2[i][k] < c; });
            for (auto it = from; it != line.end() && b.p2[*it][k] <= hi[k]; ++it) {
              const Vec2 q = b.p2[*it];
              // A sliver's own corner may lie within the tolerance of its edge: not a junction.
              if (q[1 - k] < lo[1 - k] || q[1 - k] > hi[1 - k] || ownedBy[*it] == t) continue;
              const Vec2 p = q - a;
              const double along = glm::dot(p, d) / length;
              if (along <= tolerance_ || along >= length - tolerance_) continue;
              if (std::abs(p.x * d.y - p.y * d.x) / length > tolerance_) continue;
              cuts.push_back({along, *it});
            }
            std::sort(cuts.begin(), cuts.end());
            counts_.tJunctions += cuts.size();
          }
          uint32_t at = edge.a;
          for (const auto& [along, v] : cuts) {
            b.edges.push_back({at, v, t});
            at = v;
          }
          b.edges.push_back({at, edge.b, t});
        }
      }
    }
    b.ringFirstEdge.push_back(static_cast<uint32_t>(b.edges.size()));
    b.twin = pairEdges(b.edges);
  }

  // ---- a group into surfaces ----

  void emitBucket(const Bucket& b) {
    // Pieces joined across paired half-edges (union-find by local piece).
    std::vector<uint32_t> root(b.pieces.size());
    std::iota(root.begin(), root.end(), 0u);
    unite(b, root, [](uint32_t) { return true; });
    std::vector<std::vector<uint32_t>> groups = groupsOf(root, [](uint32_t) { return true; });
    member_.assign(b.pieces.size(), kNone);
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
      if (t == kNone || !keep(b.edges[e].piece) || !keep(b.edges[t].piece)) continue;
      root[find(b.edges[e].piece)] = find(b.edges[t].piece);
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

    // Corners where the boundary touches itself: the pieces there go on their own, the rest is
    // tried again (it may fall apart into several groups).
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
      std::vector<uint8_t> single(b.pieces.size(), 0);
      for (uint32_t t : group)
        for (uint32_t e = b.firstEdge(t); e < b.firstEdge(t + 1); ++e)
          if (std::binary_search(touching.begin(), touching.end(), b.edges[e].a)) single[t] = 1;
      std::vector<uint32_t> root(b.pieces.size());
      std::iota(root.begin(), root.end(), 0u);
      auto rest = [&](uint32_t t) { return member_[t] == stamp && !single[t]; };
      unite(b, root, rest);
      std::vector<std::vector<uint32_t>> parts = groupsOf(root, rest);
      for (uint32_t t : group)
        if (single[t]) emitSingle(b, t);
      for (std::vector<uint32_t>& part : parts) emitGroup(b, std::move(part), round + 1);
      return;
    }

    if (cornerRule_ == Corners::DropUnsharedCollinear) {
      std::unordered_map<uint32_t, uint32_t> groupUses;
      for (uint32_t t : group)
        for (uint32_t e = b.firstEdge(t); e < b.firstEdge(t + 1); ++e) ++groupUses[b.edges[e].a];
      for (auto& ring : rings) dropCollinear(b, ring, groupUses);
    }
    if (!emitPolygon(b, group, rings))
      for (uint32_t t : group) emitSingle(b, t);
  }

  // The group's boundary: half-edges without a twin in the group, traced into rings; where
  // several leave one vertex, the one turning most to the left (the first clockwise from the way
  // back) keeps each ring from crossing into another.
  std::vector<std::vector<uint32_t>> traceRings(const Bucket& b, const std::vector<uint32_t>& group, uint32_t stamp) const {
    std::vector<uint32_t> boundary;
    for (uint32_t t : group)
      for (uint32_t e = b.firstEdge(t); e < b.firstEdge(t + 1); ++e)
        if (b.twin[e] == kNone || member_[b.edges[b.twin[e]].piece] != stamp) boundary.push_back(e);
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

  // Drops ring corners that are exactly collinear with their neighbours and that no piece
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

    std::vector<uint32_t> pieces(group.size());
    for (size_t i = 0; i < group.size(); ++i) pieces[i] = b.pieces[group[i]];
    Polygon& s = addPolygon(pieces);
    s.normal = b.normal;
    for (uint32_t v : rings[outerIndex]) s.outer.push_back(points_[b.global[v]]);
    for (size_t h : holes) {
      Ring3& ring = s.holes.emplace_back();
      for (uint32_t v : rings[h]) ring.push_back(points_[b.global[v]]);
    }
    return true;
  }

  // A piece on its own, with the vertices splitting its edges, so neighbours meet it corner to
  // corner; its rings start where they started.
  void emitSingle(const Bucket& b, uint32_t t) {
    const uint32_t piece = b.pieces[t];
    const uint32_t firstRing = b.firstRing[t];
    // Near a needle-sharp corner one vertex may lie on two of its edges: the split ring would
    // touch itself, so such a piece keeps its own corners only.
    bool split = false, simple = true;
    for (uint32_t r = firstRing; r < b.firstRing[t + 1] && simple; ++r) {
      const uint32_t given = pieces_[piece].firstRing + (r - firstRing);
      if (b.ringFirstEdge[r + 1] - b.ringFirstEdge[r] == ringEnd_[given] - ringBegin(given)) continue;
      split = true;
      mesher::Ring2 ring;
      for (uint32_t e = b.ringFirstEdge[r]; e < b.ringFirstEdge[r + 1]; ++e) ring.push_back(b.p2[b.edges[e].a]);
      simple = mesher::isSimple(ring);
    }
    if (!split || !simple) return emitGiven(piece);
    Polygon& s = addPolygon({&piece, 1});
    s.normal = pieces_[piece].normal;
    for (uint32_t r = firstRing; r < b.firstRing[t + 1]; ++r) {
      Ring3& ring = r == firstRing ? s.outer : s.holes.emplace_back();
      for (uint32_t e = b.ringFirstEdge[r]; e < b.ringFirstEdge[r + 1]; ++e) ring.push_back(points_[b.global[b.edges[e].a]]);
    }
    ++counts_.singles;
  }

  // A piece on its own, as it was given: its rings are the caller's (left empty here).
  void emitGiven(uint32_t piece) {
    addPolygon({&piece, 1}).normal = pieces_[piece].normal;
    ++counts_.singles;
  }

  // A new polygon made of `pieces` (ascending), their sources recorded.
  Polygon& addPolygon(std::span<const uint32_t> pieces) {
    Polygon& s = out_.polygons.emplace_back();
    for (uint32_t p : pieces) {
      s.area += pieces_[p].area;
      out_.sources.push_back(pieces_[p].source);
    }
    out_.sourcesEnd.push_back(static_cast<uint32_t>(out_.sources.size()));
    return s;
  }

  const Scene& scene_;
  double tolerance_;
  Corners cornerRule_;
  TriangleMergeCounts& counts_;
  Welder welder_;
  std::vector<Vec3> points_;            // welded
  std::vector<uint32_t> ringCorners_;   // welded vertices, ring after ring, piece after piece
  std::vector<uint32_t> ringEnd_;       // per ring: one past its last in ringCorners_
  uint32_t nextRing_ = 0;               // the first ring of the piece being given
  std::vector<Piece> pieces_;
  std::vector<uint32_t> uses_;    // per welded vertex: half-edges starting there, all groups
  std::vector<uint32_t> member_;  // per local piece of the bucket: the stamp of its group
  uint32_t stamp_ = 0;
  Merged out_;
};

}  // namespace

std::vector<Surface> mergeTriangles(const Scene& scene, const std::vector<SceneTriangle>& triangles, double tolerance,
                                    TriangleMergeCounts* counts) {
  TriangleMergeCounts local;
  TriangleMergeCounts& c = counts ? *counts : local;
  c = {};
  c.triangles = triangles.size();
  Merger merger(scene, tolerance, Corners::DropUnsharedCollinear, c, 3 * triangles.size());
  for (uint32_t i = 0; i < triangles.size(); ++i) {
    const SceneTriangle& in = triangles[i];
    const auto& p = in.corners;
    const Vec3 cross = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double twiceArea = glm::length(cross);
    const double longest = std::max({glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
    // No area: a repeated corner, or its height above the longest edge is within the tolerance.
    if (p[0] == p[1] || p[1] == p[2] || p[2] == p[0] || !(twiceArea > tolerance * longest)) {
      ++c.degenerate;
      continue;
    }
    merger.addRing(p);
    merger.addPiece(cross / twiceArea, twiceArea / 2, in.material, in.object, i);
  }
  Merged merged = merger.run();
  std::vector<Surface> out(merged.polygons.size());
  for (size_t k = 0; k < out.size(); ++k) {
    Polygon& made = merged.polygons[k];
    const std::span<const uint32_t> sources = merged.sourcesOf(k);
    const SceneTriangle& first = triangles[sources.front()];
    Surface& s = out[k];
    if (made.outer.empty()) s.outer.assign(first.corners.begin(), first.corners.end());
    else s.outer = std::move(made.outer);
    s.holes = std::move(made.holes);
    s.normal = made.normal;
    s.area = made.area;
    s.material = first.material;
    s.object = first.object;
    s.face = std::to_string(sources.size()) + (sources.size() == 1 ? " triangle" : " triangles");
  }
  return out;
}

std::vector<Surface> mergeFaces(const Scene& scene, std::vector<Surface> faces, double tolerance) {
  TriangleMergeCounts counts;
  size_t corners = 0;
  for (const Surface& f : faces) {
    corners += f.outer.size();
    for (const Ring3& hole : f.holes) corners += hole.size();
  }
  Merger merger(scene, tolerance, Corners::KeepAll, counts, corners);
  for (uint32_t i = 0; i < faces.size(); ++i) {
    const Surface& f = faces[i];
    merger.addRing(f.outer);
    for (const Ring3& hole : f.holes) merger.addRing(hole);
    merger.addPiece(f.normal, f.area, f.material, f.object, i);
  }
  Merged merged = merger.run();

  // Back in the faces' order, each merged surface where its first face was.
  std::vector<uint32_t> order(merged.polygons.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t i, uint32_t j) { return merged.sourcesOf(i).front() < merged.sourcesOf(j).front(); });
  std::vector<Surface> out;
  out.reserve(merged.polygons.size());
  for (uint32_t k : order) {
    const std::span<const uint32_t> sources = merged.sourcesOf(k);
    Polygon& made = merged.polygons[k];
    Surface& s = out.emplace_back(std::move(faces[sources.front()]));
    if (made.outer.empty()) continue;  // a face on its own, exactly as given
    s.outer = std::move(made.outer);
    s.holes = std::move(made.holes);
    s.area = made.area;
    for (uint32_t m : sources.subspan(1)) {
      s.face += " + " + faces[m].face;
      s.patchSize = std::min(s.patchSize, faces[m].patchSize);
    }
  }
  return out;
}

}  // namespace engine
