// Sections: table | the box tree | faces prepared (planes, triangles, bounds) | coplanar pairs |
// crossing pairs | a pair of faces | edges of objects | backs seen | checkModel.
#include "engine/geometry/model_check.h"

#include "mesher/triangulate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <span>
#include <tuple>
#include <unordered_map>

namespace engine {

// ---- table ----

namespace {

struct KindInfo {
  const char* id;
  Severity severity;
  const char* name;
  const char* action;
};

constexpr KindInfo kKinds[] = {
#define WALKRAD_FINDING_INFO(id, severity, name, action) {#id, Severity::severity, name, action},
    WALKRAD_MODEL_FINDINGS(WALKRAD_FINDING_INFO)
#undef WALKRAD_FINDING_INFO
};
static_assert(std::size(kKinds) == kFindingKinds);

}  // namespace

const char* idOf(FindingKind kind) { return kKinds[static_cast<size_t>(kind)].id; }
const char* nameOf(FindingKind kind) { return kKinds[static_cast<size_t>(kind)].name; }
const char* actionOf(FindingKind kind) { return kKinds[static_cast<size_t>(kind)].action; }
Severity severityOf(FindingKind kind) { return kKinds[static_cast<size_t>(kind)].severity; }

const char* nameOf(Severity severity) {
  switch (severity) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "?";
}

namespace {

// `value` to `digits` significant digits, as a stream prints it (%g): without a stream, whose
// set-up costs more than the printing when a model has thousands of findings, nor printf, whose
// exact digits of numbers far from 1 cost thousands of instructions (to_chars gives the same).
std::string number(double value, int digits = 4) {
  char text[32];
  const auto printed = std::to_chars(text, text + sizeof text, value, std::chars_format::general, digits);
  return std::string(text, printed.ptr);
}

}  // namespace

std::string describeLocation(const Scene& scene, const Finding& finding) {
  const Surface& s = scene.surfaces[finding.surface];
  return s.jsonPath + " (" + scene.objects[s.object].name + ", " + s.face + ") at (" + number(finding.point.x, 6) + ", " +
         number(finding.point.y, 6) + ", " + number(finding.point.z, 6) + ")";
}

namespace {

using Triangle = std::array<Vec3, 3>;

std::string faceName(const Scene& scene, uint32_t surface) {
  const Surface& s = scene.surfaces[surface];
  return "\"" + scene.objects[s.object].name + "\" " + s.face + " (" + s.jsonPath + ")";
}

// ---- the box tree ----

struct Box {
  Vec3 lo{INFINITY}, hi{-INFINITY};
  void add(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
};

// Closed boxes: touching counts.
bool overlaps(const Box& a, const Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

// Where the ray origin + t direction enters `box` for t in [from, to], or infinity for a miss.
// `inverse` is 1 / direction, per coordinate.
double rayEntry(const Box& box, const Vec3& origin, const Vec3& direction, const Vec3& inverse, double from, double to) {
  for (int k = 0; k < 3; ++k) {
    if (direction[k] == 0) {
      if (origin[k] < box.lo[k] || origin[k] > box.hi[k]) return INFINITY;
      continue;
    }
    double near = (box.lo[k] - origin[k]) * inverse[k], far = (box.hi[k] - origin[k]) * inverse[k];
    if (near > far) std::swap(near, far);
    from = std::max(from, near);
    to = std::min(to, far);
  }
  return from <= to ? from : INFINITY;
}

// A bounding volume hierarchy over boxes (faces for pairs, triangles for rays): each node halves
// its boxes at the median of their centres along their widest spread, down to kLeafSize a leaf,
// so it is balanced however the boxes lie. A query visits the nodes whose bounds it meets: its
// work follows the boxes near it, not how the rest of the scene is spread (a uniform grid over
// the scene crams a small dense part, a dome beside a distant box, into a few cells).
class BoxTree {
 public:
  // The tree over `items`, which index `boxes`.
  BoxTree(const std::vector<Box>& boxes, std::vector<uint32_t> items) : items_(std::move(items)) {
    if (items_.empty()) return;
    nodes_.reserve(2 * items_.size());
    nodes_.emplace_back();
    build(boxes, 0, 0, static_cast<uint32_t>(items_.size()));
    boxes_.reserve(items_.size());
    for (uint32_t item : items_) boxes_.push_back(boxes[item]);
  }

  // Calls visit(item) for each item whose box overlaps `box`; counts the boxes compared.
  template <class Visit>
  void overlapping(const Box& box, uint64_t& tests, Visit visit) const {
    std::array<uint32_t, kDeepest> stack;
    size_t top = 0;
    if (!nodes_.empty()) stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      ++tests;
      if (!overlaps(node.box, box)) continue;
      if (node.count == 0) {
        stack[top++] = node.first;
        stack[top++] = node.first + 1;
        continue;
      }
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        ++tests;
        if (overlaps(boxes_[i], box)) visit(items_[i]);
      }
    }
  }

  // Calls visit(item) for each item whose box the ray origin + t direction meets for t in
  // [from, to], nearer nodes first. `visit` may lower `to` (it found a hit there), which leaves
  // out what lies beyond. Counts the boxes tested.
  template <class Visit>
  void alongRay(const Vec3& origin, const Vec3& direction, double from, double& to, uint64_t& tests, Visit visit) const {
    const Vec3 inverse = 1.0 / direction;
    std::array<std::pair<uint32_t, double>, kDeepest> stack;  // nodes and where the ray enters them
    size_t top = 0;
    if (!nodes_.empty()) {
      ++tests;
      const double entry = rayEntry(nodes_[0].box, origin, direction, inverse, from, to);
      if (entry != INFINITY) stack[top++] = {0, entry};
    }
    while (top > 0) {
      const auto [index, entry] = stack[--top];
      if (entry > to) continue;
      const Node& node = nodes_[index];
      if (node.count > 0) {
        for (uint32_t i = node.first; i < node.first + node.count; ++i) {
          ++tests;
          visit(items_[i]);
        }
        continue;
      }
      tests += 2;
      double entries[2];
      for (uint32_t c = 0; c < 2; ++c) entries[c] = rayEntry(nodes_[node.first + c].box, origin, direction, inverse, from, to);
      const uint32_t nearer = entries[1] < entries[0] ? 1 : 0;
      for (uint32_t c : {1 - nearer, nearer})  // the nearer on top
        if (entries[c] != INFINITY) stack[top++] = {node.first + c, entries[c]};
    }
  }

 private:
  static constexpr uint32_t kLeafSize = 4;
  // Median splits make the tree at most 32 levels deep for 2^32 items; a walk keeps at most one
  // node a level waiting, and two at the deepest.
  static constexpr size_t kDeepest = 66;

  struct Node {
    Box box;
    uint32_t first = 0;  // a leaf's first item, or an inner node's first child (the second follows)
    uint32_t count = 0;  // a leaf's items; 0 for an inner node
  };

  void build(const std::vector<Box>& boxes, uint32_t index, uint32_t first, uint32_t count) {
    Box bounds, centres;
    for (uint32_t i = first; i < first + count; ++i) {
      const Box& b = boxes[items_[i]];
      bounds.add(b);
      centres.add({b.lo + b.hi, b.lo + b.hi});
    }
    nodes_[index].box = bounds;
    if (count <= kLeafSize) {
      nodes_[index].first = first;
      nodes_[index].count = count;
      return;
    }
    const Vec3 spread = centres.hi - centres.lo;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
    const uint32_t half = count / 2;
    const auto begin = items_.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [&](uint32_t a, uint32_t b) {
      return boxes[a].lo[axis] + boxes[a].hi[axis] < boxes[b].lo[axis] + boxes[b].hi[axis];
    });
    const auto children = static_cast<uint32_t>(nodes_.size());
    nodes_[index].first = children;
    nodes_.emplace_back();
    nodes_.emplace_back();
    build(boxes, children, first, half);
    build(boxes, children + 1, first + half, count - half);
  }

  std::vector<uint32_t> items_;  // in the order of the leaves
  std::vector<Box> boxes_;       // by position in items_
  std::vector<Node> nodes_;      // the root first
};

// ---- faces prepared (planes, triangles, bounds) ----

// The index of the coordinate a plane with normal n is projected along (its largest).
int dominantAxis(const Vec3& n) {
  const Vec3 a = glm::abs(n);
  return a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
}

mesher::Vec2 drop(const Vec3& p, int axis) {
  return axis == 0 ? mesher::Vec2{p.y, p.z} : (axis == 1 ? mesher::Vec2{p.z, p.x} : mesher::Vec2{p.x, p.y});
}

struct Face {
  bool degenerate = false;
  Vec3 normal{0};
  double offset = 0;            // the plane is dot(normal, p) = offset
  double area = 0;
  Box bounds;                   // padded by the tolerance
  uint32_t firstTriangle = 0, triangleCount = 0;
  Vec3 inside{0};               // a point strictly inside the face (its largest triangle's centroid)
};

// Newell's vector of a ring: its direction is the ring's normal, its length twice its area.
// Taken about the first point, so rings far from the origin keep their digits.
Vec3 newell(const Ring3& ring) {
  Vec3 sum{0};
  for (size_t i = 1; i + 1 < ring.size(); ++i) sum += glm::cross(ring[i] - ring[0], ring[i + 1] - ring[0]);
  return sum;
}

void prepareFace(const Surface& s, double tolerance, Face& face, std::vector<Triangle>& triangles) {
  face.firstTriangle = static_cast<uint32_t>(triangles.size());
  double longest = 0;
  for (size_t i = 0; i < s.outer.size(); ++i)
    longest = std::max(longest, glm::length(s.outer[(i + 1) % s.outer.size()] - s.outer[i]));
  const Vec3 n = newell(s.outer);
  double area = 0.5 * glm::length(n);
  for (const Ring3& hole : s.holes) area -= 0.5 * glm::length(newell(hole));
  face.area = area;
  // No width anywhere above the tolerance: a point, a line, or a ring folded onto itself.
  face.degenerate = s.outer.size() < 3 || area <= tolerance * longest;
  if (face.degenerate) return;
  face.normal = glm::normalize(n);
  face.offset = glm::dot(face.normal, s.outer.front());
  for (const Vec3& p : s.outer) face.bounds.add({p - Vec3(tolerance), p + Vec3(tolerance)});

  // Tiled by ear clipping in the projection along the normal's largest coordinate.
  const int axis = dominantAxis(face.normal);
  mesher::PolygonWithHoles polygon;
  std::vector<Vec3> points(s.outer);
  for (const Vec3& p : s.outer) polygon.outer.push_back(drop(p, axis));
  for (const Ring3& hole : s.holes) {
    polygon.holes.emplace_back();
    for (const Vec3& p : hole) polygon.holes.back().push_back(drop(p, axis));
    points.insert(points.end(), hole.begin(), hole.end());
  }
  double largest = -1;
  for (const auto& t : s.outer.size() == 3 && s.holes.empty() ? std::vector<std::array<uint32_t, 3>>{{0, 1, 2}}
                                                              : mesher::triangulate(polygon)) {
    const Triangle triangle{points[t[0]], points[t[1]], points[t[2]]};
    const double a = glm::length(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
    if (a > largest) {
      largest = a;
      face.inside = (triangle[0] + triangle[1] + triangle[2]) / 3.0;
    }
    triangles.push_back(triangle);
  }
  face.triangleCount = static_cast<uint32_t>(triangles.size()) - face.firstTriangle;
  face.degenerate = face.triangleCount == 0;
}

// ---- coplanar pairs ----

double area2(const std::vector<mesher::Vec2>& polygon) {
  double sum = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const mesher::Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    sum += a.x * b.y - a.y * b.x;
  }
  return 0.5 * sum;
}

// Area of the intersection of two triangles in the plane (Sutherland-Hodgman: `b` clipped by
// each edge of `a`).
double overlapArea(std::array<mesher::Vec2, 3> a, const std::array<mesher::Vec2, 3>& b) {
  if (mesher::orient2(a[0], a[1], a[2]) < 0) std::swap(a[1], a[2]);
  std::vector<mesher::Vec2> polygon(b.begin(), b.end()), next;
  for (int e = 0; e < 3 && !polygon.empty(); ++e) {
    const mesher::Vec2 p = a[e], q = a[(e + 1) % 3];
    next.clear();
    for (size_t i = 0; i < polygon.size(); ++i) {
      const mesher::Vec2 c = polygon[i], d = polygon[(i + 1) % polygon.size()];
      const double sc = mesher::orient2(p, q, c), sd = mesher::orient2(p, q, d);
      if (sc >= 0) next.push_back(c);
      if ((sc >= 0) != (sd >= 0)) next.push_back(c + (d - c) * (sc / (sc - sd)));
    }
    polygon.swap(next);
  }
  return polygon.size() < 3 ? 0 : std::abs(area2(polygon));
}

// The overlap of two coplanar faces and their own areas, all projected along `axis`.
struct Overlap {
  double shared = 0, a = 0, b = 0;
};

Overlap coplanarOverlap(const Face& fa, const Face& fb, const std::vector<Triangle>& triangles, int axis) {
  const auto project = [&](const Face& f) {
    std::vector<std::array<mesher::Vec2, 3>> out;
    for (uint32_t t = f.firstTriangle; t < f.firstTriangle + f.triangleCount; ++t)
      out.push_back({drop(triangles[t][0], axis), drop(triangles[t][1], axis), drop(triangles[t][2], axis)});
    return out;
  };
  const auto ta = project(fa), tb = project(fb);
  Overlap overlap;
  for (const auto& t : ta) overlap.a += 0.5 * std::abs(mesher::orient2(t[0], t[1], t[2]));
  for (const auto& t : tb) overlap.b += 0.5 * std::abs(mesher::orient2(t[0], t[1], t[2]));
  for (const auto& s : ta) {
    const mesher::Vec2 sLo = glm::min(s[0], glm::min(s[1], s[2])), sHi = glm::max(s[0], glm::max(s[1], s[2]));
    for (const auto& t : tb) {
      const mesher::Vec2 tLo = glm::min(t[0], glm::min(t[1], t[2])), tHi = glm::max(t[0], glm::max(t[1], t[2]));
      if (sHi.x <= tLo.x || tHi.x <= sLo.x || sHi.y <= tLo.y || tHi.y <= sLo.y) continue;
      overlap.shared += overlapArea(s, t);
    }
  }
  return overlap;
}

// Every point of `s` within `tolerance` of face f's plane.
bool onPlane(const Surface& s, const Face& f, double tolerance) {
  for (const Vec3& p : s.outer)
    if (std::abs(glm::dot(f.normal, p) - f.offset) > tolerance) return false;
  return true;
}

// ---- crossing pairs ----

// Where the rings of `s` cross the plane n.p = offset, as intervals of the line along
// `direction` (unit) that lies in that plane: parameters dot(p, direction), paired in order.
// Points within `tolerance` of the plane count as in front, so a face that only touches the
// plane yields nothing. Empty unless `s` has points strictly on both sides.
std::vector<double> crossings(const Surface& s, const Vec3& n, double offset, const Vec3& direction, double tolerance) {
  bool front = false, back = false;
  const auto distance = [&](const Vec3& p) { return glm::dot(n, p) - offset; };
  for (const Vec3& p : s.outer) {
    front |= distance(p) > tolerance;
    back |= distance(p) < -tolerance;
  }
  if (!front || !back) return {};
  std::vector<double> out;
  const auto ring = [&](const Ring3& r) {
    for (size_t i = 0; i < r.size(); ++i) {
      const Vec3 &p = r[i], &q = r[(i + 1) % r.size()];
      const double dp = distance(p), dq = distance(q);
      if ((dp >= -tolerance) == (dq >= -tolerance)) continue;
      const double t = std::clamp(dp / (dp - dq), 0.0, 1.0);
      out.push_back(glm::dot(p + t * (q - p), direction));
    }
  };
  ring(s.outer);
  for (const Ring3& hole : s.holes) ring(hole);
  std::sort(out.begin(), out.end());
  return out;
}

// The longest stretch inside both interval lists ([x0, x1], [x2, x3], ...); its middle is
// returned in `middle`.
double sharedStretch(const std::vector<double>& a, const std::vector<double>& b, double& middle) {
  double best = 0;
  for (size_t i = 0; i + 1 < a.size(); i += 2)
    for (size_t j = 0; j + 1 < b.size(); j += 2) {
      const double lo = std::max(a[i], b[j]), hi = std::min(a[i + 1], b[j + 1]);
      if (hi - lo > best) {
        best = hi - lo;
        middle = 0.5 * (lo + hi);
      }
    }
  return best;
}

// ---- a pair of faces ----

// Faces a < b whose bounds overlap: coplanar ones overlapping (duplicates, coincident, back to
// back), or crossing ones (each has points strictly on both sides of the other's plane, and the
// chords the two planes cut from them share a stretch).
void checkPair(const Scene& scene, const std::vector<Face>& faces, const std::vector<Triangle>& triangles, uint32_t a,
               uint32_t b, double tolerance, std::vector<Finding>& out) {
  const Face &fa = faces[a], &fb = faces[b];
  const Surface &sa = scene.surfaces[a], &sb = scene.surfaces[b];

  const double facing = glm::dot(fa.normal, fb.normal);
  if (std::abs(facing) > 0.99 && onPlane(sb, fa, tolerance) && onPlane(sa, fb, tolerance)) {
    const Overlap overlap = coplanarOverlap(fa, fb, triangles, dominantAxis(fa.normal));
    if (overlap.shared <= 1e-6 * std::min(overlap.a, overlap.b) + tolerance * tolerance) return;
    const Vec3 point = fb.inside;
    const std::string share = number(100 * overlap.shared / overlap.b) + "% of it";
    if (facing > 0) {
      const bool same = overlap.shared >= (1 - 1e-6) * std::max(overlap.a, overlap.b);
      if (same)
        out.push_back({FindingKind::DuplicateFace, b, a, point, "the same polygon as " + faceName(scene, a)});
      else
        out.push_back({FindingKind::CoincidentFaces, b, a, point, share + " lies on " + faceName(scene, a) + ", facing the same way"});
    } else if (sa.object == sb.object) {
      // Between objects this is one resting on the other: contact cut-outs handle it.
      out.push_back({FindingKind::BackToBackFaces, b, a, point, share + " lies on " + faceName(scene, a) + ", back to back"});
    }
    return;
  }

  const Vec3 u = glm::cross(fa.normal, fb.normal);
  if (glm::length(u) < 1e-9) return;  // parallel planes apart
  const Vec3 along = glm::normalize(u);
  const std::vector<double> ca = crossings(sa, fb.normal, fb.offset, along, tolerance);
  if (ca.empty()) return;
  const std::vector<double> cb = crossings(sb, fa.normal, fa.offset, along, tolerance);
  if (cb.empty()) return;
  double middle = 0;
  const double stretch = sharedStretch(ca, cb, middle);
  if (stretch <= tolerance) return;
  // The point of the line of the two planes at parameter `middle`.
  const Vec3 onLine = (fa.offset * glm::cross(fb.normal, u) + fb.offset * glm::cross(u, fa.normal)) / glm::dot(u, u);
  out.push_back({FindingKind::Interpenetration, a, b, onLine + middle * along, "crosses " + faceName(scene, b) + " along " + number(stretch)});
}

// ---- edges of objects ----

struct EdgeUse {
  std::array<uint32_t, 2> uses{0, 0};  // [0] from the lower vertex id to the higher, [1] back
  std::array<std::array<uint32_t, 2>, 2> faces{};  // the first two faces using it each way
  double length = 0;
  Vec3 middle{0};
};

// Vertex ids shared by points closer than the tolerance (points snapped to a lattice of that
// spacing; points either side of a lattice boundary stay apart, which only makes an edge look
// open where a model has near-miss vertices).
class VertexIds {
 public:
  explicit VertexIds(double tolerance) : step_(tolerance) {}
  uint32_t operator()(const Vec3& p) {
    const Key key{std::llround(p.x / step_), std::llround(p.y / step_), std::llround(p.z / step_)};
    const auto [at, added] = ids_.try_emplace(key, static_cast<uint32_t>(ids_.size()));
    if (added) positions_.push_back(p);
    return at->second;
  }
  const Vec3& position(uint32_t id) const { return positions_[id]; }

 private:
  using Key = std::array<int64_t, 3>;
  struct Hash {
    size_t operator()(const Key& k) const {
      return std::hash<int64_t>()(k[0] * 73856093 ^ k[1] * 19349663 ^ k[2] * 83492791);
    }
  };
  double step_;
  std::unordered_map<Key, uint32_t, Hash> ids_;
  std::vector<Vec3> positions_;  // by id: the first point given it
};

using EdgeKey = std::pair<uint32_t, uint32_t>;  // vertex ids, lower first

// A stretch of an edge used by an odd number of faces, after T-junctions are resolved.
struct OddEdge {
  uint32_t uses = 0;
  const EdgeUse* from = nullptr;  // the edge of a face it is part of
  double length = 0;
  Vec3 middle{0};
};

// The stretches of an object's edges that an odd number of faces use: the edges used an odd
// number of times, split where a vertex of another such edge lies on them, so that an edge of
// one face running along the edges of two others (a T-junction) is not taken for open. Only
// odd edges are split: an edge used once each way is closed however its neighbours run.
std::map<EdgeKey, OddEdge> oddEdges(const std::map<EdgeKey, EdgeUse>& edges, const VertexIds& ids, double tolerance,
                                    ModelCheckWork& work) {
  std::vector<std::pair<EdgeKey, const EdgeUse*>> odd;
  std::vector<uint32_t> candidates;
  for (const auto& [key, use] : edges)
    if ((use.uses[0] + use.uses[1]) % 2 == 1) {
      odd.push_back({key, &use});
      candidates.push_back(key.first);
      candidates.push_back(key.second);
    }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

  std::map<EdgeKey, OddEdge> out;
  if (odd.empty()) return out;
  std::vector<Box> points(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i) points[i] = {ids.position(candidates[i]), ids.position(candidates[i])};
  std::vector<uint32_t> items(candidates.size());
  std::iota(items.begin(), items.end(), 0);
  const BoxTree tree(points, std::move(items));

  std::vector<std::pair<double, uint32_t>> cuts;
  for (const auto& [key, use] : odd) {
    const Vec3 a = ids.position(key.first), b = ids.position(key.second), d = b - a;
    cuts.clear();
    const Box reach{glm::min(a, b) - Vec3(tolerance), glm::max(a, b) + Vec3(tolerance)};
    tree.overlapping(reach, work.edgeBoundsTests, [&, ends = key](uint32_t i) {
      const uint32_t v = candidates[i];
      if (v == ends.first || v == ends.second) return;
      const Vec3 p = ids.position(v);
      const double t = glm::dot(p - a, d) / glm::dot(d, d);
      if (t > 0 && t < 1 && glm::length(a + t * d - p) <= tolerance) cuts.push_back({t, v});
    });
    std::sort(cuts.begin(), cuts.end());
    uint32_t from = key.first;
    cuts.push_back({1, key.second});
    for (const auto& [t, to] : cuts) {
      if (to == from) continue;
      OddEdge& piece = out[std::minmax(from, to)];
      piece.uses += use->uses[0] + use->uses[1];
      piece.from = use;
      piece.length = glm::length(ids.position(to) - ids.position(from));
      piece.middle = 0.5 * (ids.position(to) + ids.position(from));
      from = to;
    }
  }
  std::erase_if(out, [](const auto& piece) { return piece.second.uses % 2 == 0; });
  return out;
}

// Union-find over vertex ids, to gather open edges into openings.
uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// Finds inconsistent orientation and the openings of solids; returns per object whether it is
// sealed: every edge used as often one way as the other (closed, consistently oriented shells).
std::vector<bool> checkEdges(const Scene& scene, const std::vector<Face>& faces, double tolerance, double closedShare,
                             ModelCheckWork& work, std::vector<Finding>& out) {
  VertexIds ids(tolerance);
  // Per object, its edges by (lower id, higher id).
  std::vector<std::map<EdgeKey, EdgeUse>> edges(scene.objects.size());
  for (uint32_t f = 0; f < faces.size(); ++f) {
    if (faces[f].degenerate) continue;
    const Surface& s = scene.surfaces[f];
    const auto ring = [&](const Ring3& r) {
      for (size_t i = 0; i < r.size(); ++i) {
        const Vec3 &p = r[i], &q = r[(i + 1) % r.size()];
        const uint32_t a = ids(p), b = ids(q);
        if (a == b) continue;
        EdgeUse& use = edges[s.object][std::minmax(a, b)];
        const size_t way = a < b ? 0 : 1;
        if (use.uses[way] < 2) use.faces[way][use.uses[way]] = f;
        ++use.uses[way];
        use.length = glm::length(q - p);
        use.middle = 0.5 * (p + q);
      }
    };
    ring(s.outer);
    for (const Ring3& hole : s.holes) ring(hole);
  }

  std::vector<bool> sealed(scene.objects.size(), false);
  for (uint32_t o = 0; o < edges.size(); ++o) {
    sealed[o] = !edges[o].empty();
    double total = 0;
    std::set<std::pair<uint32_t, uint32_t>> flipped;  // face pairs already reported
    for (const auto& [key, use] : edges[o]) {
      total += use.length;
      sealed[o] = sealed[o] && use.uses[0] == use.uses[1];
      // Two faces run along an edge the same way: one of them is turned over. The later one is
      // reported.
      for (size_t way : {0, 1})
        if (use.uses[way] >= use.uses[1 - way] + 2) {
          const auto [first, later] = use.faces[way];
          if (flipped.insert({first, later}).second)
            out.push_back({FindingKind::InconsistentOrientation, later, first, use.middle,
                           "runs along an edge of " + faceName(scene, first) + " the same way: their normals disagree"});
        }
    }
    // A solid (most of its edges closed) with open edges: gather them into openings (connected
    // runs of open edges).
    const std::map<EdgeKey, OddEdge> open = oddEdges(edges[o], ids, tolerance, work);
    double openLength = 0;
    for (const auto& [key, piece] : open) openLength += piece.length;
    const double closed = total > 0 ? 1 - openLength / total : 0;
    if (open.empty() || closed < closedShare) continue;
    std::map<uint32_t, uint32_t> local;
    for (const auto& [key, piece] : open) {
      local.try_emplace(key.first, static_cast<uint32_t>(local.size()));
      local.try_emplace(key.second, static_cast<uint32_t>(local.size()));
    }
    std::vector<uint32_t> parent(local.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& [key, piece] : open) parent[findRoot(parent, local[key.first])] = findRoot(parent, local[key.second]);
    struct Opening {
      size_t edges = 0;
      double length = 0;
      const OddEdge* first = nullptr;
    };
    std::map<uint32_t, Opening> openings;
    for (const auto& [key, piece] : open) {
      Opening& opening = openings[findRoot(parent, local[key.first])];
      ++opening.edges;
      opening.length += piece.length;
      if (!opening.first) opening.first = &piece;
    }
    for (const auto& [root, opening] : openings) {
      const EdgeUse& use = *opening.first->from;
      const uint32_t face = use.uses[0] > 0 ? use.faces[0][0] : use.faces[1][0];
      out.push_back({FindingKind::OpenEdge, face, -1, opening.first->middle,
                     "an opening of " + std::to_string(opening.edges) + " edge" + (opening.edges == 1 ? "" : "s") +
                         " (" + number(opening.length) + " long) in object \"" + scene.objects[o].name + "\", " +
                         number(100 * closed) + "% of whose edges are closed"});
    }
  }
  return sealed;
}

// ---- backs seen ----

// Distance along the ray to triangle t (Moller-Trumbore), or a negative number for a miss.
double rayHit(const Vec3& origin, const Vec3& direction, const Triangle& t) {
  const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Vec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-300) return -1;
  const Vec3 s = origin - t[0];
  const double u = glm::dot(s, p) / det;
  if (u < 0 || u > 1) return -1;
  const Vec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) / det;
  if (v < 0 || u + v > 1) return -1;
  return glm::dot(e2, q) / det;
}

// A face a ray met: its distance along the ray and whether the ray sees its front.
struct RayHit {
  uint32_t face;
  double distance;
  bool front;
};

// The face the ray sees first, skipping `self` and fronts at the start (coincident faces,
// reported as such), and its distance; a negative face for none. Faces within the tolerance of
// the nearest are at one place (a solid resting on another): a back there covers, then the
// face first in the file is taken, so the answer does not depend on the order of the search.
std::pair<int64_t, double> castRay(const BoxTree& tree, const std::vector<Face>& faces, const std::vector<Triangle>& triangles,
                                   const std::vector<uint32_t>& faceOfTriangle, uint32_t self, const Vec3& origin,
                                   const Vec3& direction, double tolerance, std::vector<RayHit>& hits, ModelCheckWork& work) {
  hits.clear();
  double nearest = INFINITY, reach = INFINITY;  // the nearest hit and the tolerance beyond it
  tree.alongRay(origin, direction, -tolerance, reach, work.rayBoundsTests, [&](uint32_t t) {
    const uint32_t f = faceOfTriangle[t];
    if (f == self) return;
    const Face& face = faces[f];
    // The face's plane first: most faces met lie behind the start or beyond the nearest.
    const double facing = glm::dot(face.normal, direction);
    if (facing == 0) return;
    const double plane = (face.offset - glm::dot(face.normal, origin)) / facing;
    if (plane < -tolerance || plane > reach) return;
    const double hit = rayHit(origin, direction, triangles[t]);
    if (hit < -tolerance || hit > reach) return;
    const bool front = facing < 0;
    if (hit <= tolerance && front) return;
    hits.push_back({f, hit, front});
    if (hit < nearest) {
      nearest = hit;
      reach = hit + tolerance;
    }
  });
  const RayHit* seen = nullptr;
  for (const RayHit& hit : hits)
    if (hit.distance <= reach &&
        (!seen || std::tie(hit.front, hit.face, hit.distance) < std::tie(seen->front, seen->face, seen->distance)))
      seen = &hit;
  return seen ? std::pair<int64_t, double>{seen->face, seen->distance} : std::pair<int64_t, double>{-1, INFINITY};
}

}  // namespace

// ---- checkModel ----

std::vector<Finding> checkModel(const Scene& scene, const ModelCheckSettings& settings, ModelCheckWork* counted) {
  std::vector<Finding> out;
  ModelCheckWork work;
  const size_t n = scene.surfaces.size();
  if (n == 0) return out;

  // Faces prepared: planes, bounds, triangles.
  Vec3 lo = scene.surfaces.front().outer.empty() ? Vec3(0) : scene.surfaces.front().outer.front(), hi = lo;
  for (const Surface& s : scene.surfaces)
    for (const Vec3& p : s.outer) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double tolerance = settings.tolerance > 0 ? settings.tolerance : 1e-6 * extent;
  std::vector<Face> faces(n);
  std::vector<Triangle> triangles;
  std::vector<uint32_t> kept;  // the faces with area
  for (uint32_t f = 0; f < n; ++f) {
    prepareFace(scene.surfaces[f], tolerance, faces[f], triangles);
    if (!faces[f].degenerate) {
      kept.push_back(f);
      continue;
    }
    const Ring3& ring = scene.surfaces[f].outer;
    out.push_back({FindingKind::DegenerateFace, f, -1, ring.empty() ? Vec3(0) : ring.front(),
                   "area " + number(faces[f].area) + ": its points lie on a line or on one point"});
  }

  // Pairs of faces whose bounds overlap, each from its first face, in the file's order.
  std::vector<Box> bounds(n);
  for (uint32_t f : kept) bounds[f] = faces[f].bounds;
  const BoxTree faceTree(bounds, kept);
  std::vector<uint32_t> partners;
  for (uint32_t a : kept) {
    partners.clear();
    faceTree.overlapping(bounds[a], work.pairBoundsTests, [&](uint32_t b) {
      if (b > a) partners.push_back(b);
    });
    std::sort(partners.begin(), partners.end());
    work.pairsChecked += partners.size();
    for (uint32_t b : partners) checkPair(scene, faces, triangles, a, b, tolerance, out);
  }

  // Edges of objects: orientation and openings.
  const std::vector<bool> sealed = checkEdges(scene, faces, tolerance, settings.closedShare, work, out);

  // Backs seen: from a point inside each face, straight back and, but for sealed objects, 45
  // degrees off it four ways, the first face met shows its front. A sealed object's backs face
  // its inside, seen only from something in there, which the straight ray meets; the slanted
  // rays look out through openings (an open crate's sides are seen past its rim).
  std::vector<Box> triangleBounds(triangles.size());
  std::vector<uint32_t> faceOfTriangle(triangles.size());
  for (uint32_t f : kept)
    for (uint32_t t = faces[f].firstTriangle; t < faces[f].firstTriangle + faces[f].triangleCount; ++t) {
      faceOfTriangle[t] = f;
      for (const Vec3& p : triangles[t]) triangleBounds[t].add({p - Vec3(tolerance), p + Vec3(tolerance)});
    }
  std::vector<uint32_t> allTriangles(triangles.size());
  std::iota(allTriangles.begin(), allTriangles.end(), 0);
  const BoxTree triangleTree(triangleBounds, std::move(allTriangles));
  std::vector<RayHit> hits;
  for (uint32_t f : kept) {
    const Vec3 back = -faces[f].normal;
    const Vec3 t1 = glm::normalize(glm::cross(back, std::abs(back.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 t2 = glm::cross(back, t1);
    const size_t rays = sealed[scene.surfaces[f].object] ? 1 : 5;
    const Vec3 directions[] = {back, glm::normalize(back + t1), glm::normalize(back - t1), glm::normalize(back + t2),
                               glm::normalize(back - t2)};
    for (const Vec3& direction : std::span(directions, rays)) {
      ++work.rays;
      const auto [hit, distance] =
          castRay(triangleTree, faces, triangles, faceOfTriangle, f, faces[f].inside, direction, tolerance, hits, work);
      if (hit < 0 || glm::dot(faces[hit].normal, direction) >= 0) continue;  // none, or a back
      out.push_back({FindingKind::Facade, f, hit, faces[f].inside,
                     "its back is seen from the front of " + faceName(scene, static_cast<uint32_t>(hit)) + ", " +
                         number(distance) + " away"});
      break;
    }
  }

  std::stable_sort(out.begin(), out.end(), [](const Finding& x, const Finding& y) {
    const Severity sx = severityOf(x.kind), sy = severityOf(y.kind);
    return std::tie(sx, x.surface, x.kind, x.other) < std::tie(sy, y.surface, y.kind, y.other);
  });
  if (counted) *counted = work;
  return out;
}

}  // namespace engine
