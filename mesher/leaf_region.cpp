#include "mesher/leaf_region.h"

#include "mesher/wedge_handover.h"

#include <algorithm>
#include <cmath>

namespace mesher {

namespace {

// The square's border as a line parameter running counter-clockwise from the lower-left corner.
struct Border {
  double x0, y0, s;
  double param(Vec2 p) const {
    if (p.y == y0 && p.x < x0 + s) return p.x - x0;
    if (p.x == x0 + s && p.y < y0 + s) return s + (p.y - y0);
    if (p.y == y0 + s && p.x > x0) return 2 * s + (x0 + s - p.x);
    return 3 * s + (y0 + s - p.y);  // the left side, lower-left corner excluded above
  }
};

// Where edge a->b meets the side line the Liang-Barsky clip stopped at, with the line's
// coordinate exact and the other one computed from the line alone.
struct Clip {
  double t0 = 0, t1 = 1;
  int entrySide = -1, exitSide = -1;  // 0 west (x = x0), 1 east, 2 south (y = y0), 3 north
};

Clip clipToSquare(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1) {
  Clip c;
  const Vec2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) continue;
    const double r = q[k] / p[k];
    if (p[k] < 0 && r > c.t0) c.t0 = r, c.entrySide = k;
    if (p[k] > 0 && r < c.t1) c.t1 = r, c.exitSide = k;
  }
  return c;
}

// The template key's bit for each side, in Side order (West, East, South, North).
constexpr int kTemplateBit[4] = {1, 2, 4, 8};

// The template key of an interior square's border points: the sides holding exactly their
// midpoint, or -1 when some side holds anything else (an unbalanced neighbour).
int midpointSides(const std::vector<RegionPoint>& points, double x0, double y0, double s) {
  if (points.size() > 8) return -1;
  int key = 0;
  for (const RegionPoint& p : points) {
    const double dx = p.at.x - x0, dy = p.at.y - y0;
    const bool corner = (dx == 0 || dx == s) && (dy == 0 || dy == s);
    if (corner) continue;
    if (dy == 0 && 2 * dx == s) key |= 4;
    else if (dy == s && 2 * dx == s) key |= 8;
    else if (dx == 0 && 2 * dy == s) key |= 1;
    else if (dx == s && 2 * dy == s) key |= 2;
    else return -1;
  }
  return key;
}

}  // namespace

const LeafRegion& LeafRegionBuilder::build(int32_t q, const std::array<int32_t, 4>* adjacent) {
  const Quadtree& tree = tree_;
  LeafRegion& region = region_;
  region.ring.clear();
  region.hinge = -1;
  region.templateKey = -1;
  region.handedOver = false;
  region.boundary = {};
  region.westLeaves.clear();
  region.southLeaves.clear();
  const Quadrant& leaf = tree[q];
  if (leaf.status == QuadStatus::Outside) return region;
  const double s = static_cast<double>(tree.edgeLength(leaf));
  const double x0 = static_cast<double>(leaf.x), y0 = static_cast<double>(leaf.y);
  const double x1 = x0 + s, y1 = y0 + s;
  const Border border{x0, y0, s};
  const QuadtreeInput& in = tree.input;

  // Every point of the border that is a mesh vertex: corners, finer neighbours' corners, the
  // leaf's vertex when it lies on the border. Points are written in place: built aside and
  // copied in, they stalled on every copy.
  std::vector<RegionPoint>& onBorder = onBorder_;
  onBorder.resize(4);
  const double corners[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (size_t k = 0; k < 4; ++k) {
    onBorder[k].at.x = corners[k][0];
    onBorder[k].at.y = corners[k][1];
    onBorder[k].inputVertex = -1;
  }
  // An interior square whose finer neighbours are all one level finer (the usual case once
  // balanced) has only side midpoints besides its corners: those sides are noted, as bits of the
  // template key, instead of sorting points.
  const bool square = leaf.edgeCount == 0 && leaf.vertex < 0 && leaf.status == QuadStatus::Inside;
  int midpoints = 0, openSides = 0;
  bool deeper = false;  // some finer neighbour is more than one level finer
  for (Side side : {Side::West, Side::East, Side::South, Side::North}) {
    // The west and south leaves are kept in the region (found there, not copied in).
    std::vector<int32_t>& across = side == Side::West ? region.westLeaves : side == Side::South ? region.southLeaves : across_;
    across.clear();
    // Quadtree::neighbors, with a leaf across (the usual case) taken without a call.
    const int32_t r = adjacent ? (*adjacent)[static_cast<size_t>(side)] : tree.adjacent(q, side);
    if (r >= 0 && tree[r].isLeaf()) across.push_back(r);
    else tree.leavesFacing(r, side, across);
    // Interior squares always mesh within the bound: their open sides are not worked out.
    bool open = !square;
    for (int32_t n : across) {
      const Quadrant& other = tree[n];
      open = open && other.status == QuadStatus::Outside;
      if (other.level <= leaf.level || other.status == QuadStatus::Outside) continue;
      if (square && other.level == leaf.level + 1) {
        midpoints |= kTemplateBit[static_cast<size_t>(side)];
        continue;
      }
      deeper = true;
      const double ns = static_cast<double>(tree.edgeLength(other));
      const bool vertical = side == Side::West || side == Side::East;
      const Vec2 a = vertical ? Vec2{side == Side::West ? x0 : x1, static_cast<double>(other.y)}
                              : Vec2{static_cast<double>(other.x), side == Side::South ? y0 : y1};
      const Vec2 b = vertical ? Vec2{a.x, a.y + ns} : Vec2{a.x + ns, a.y};
      for (const Vec2& p : {a, b}) {
        if (vertical ? (p.y > y0 && p.y < y1) : (p.x > x0 && p.x < x1)) onBorder.push_back({p});
      }
    }
    if (open) openSides |= kTemplateBit[static_cast<size_t>(side)];
  }
  if (square && !deeper) {
    // The ring sorting would give: corners counter-clockwise from the lower-left, each side's
    // midpoint after the corner it starts at.
    static constexpr int kSideAfterCorner[4] = {4, 2, 8, 1};  // south, east, north, west
    const double midpointAfter[4][2] = {{x0 + s / 2, y0}, {x1, y0 + s / 2}, {x0 + s / 2, y1}, {x0, y0 + s / 2}};
    region.ring.clear();
    for (size_t k = 0; k < 4; ++k) {
      region.ring.push_back(onBorder[k]);
      if (midpoints & kSideAfterCorner[k]) {
        RegionPoint& mid = region.ring.emplace_back();
        mid.at.x = midpointAfter[k][0];
        mid.at.y = midpointAfter[k][1];
      }
    }
    region.templateKey = midpoints;
    region.inner = {x0 + s / 2, y0 + s / 2};
    return region;
  }
  region.boundary = {0, openSides, x0, y0, s};
  // Otherwise the noted midpoints join the sort.
  for (size_t side = 0; side < 4; ++side) {
    if (!(midpoints & kTemplateBit[side])) continue;
    RegionPoint& mid = onBorder.emplace_back();
    mid.at = side == 0 ? Vec2{x0, y0 + s / 2} : side == 1 ? Vec2{x1, y0 + s / 2} : side == 2 ? Vec2{x0 + s / 2, y0} : Vec2{x0 + s / 2, y1};
  }
  const bool vertexOnBorder = leaf.vertex >= 0 && [&] {
    const Vec2 v = in.vertices[static_cast<size_t>(leaf.vertex)];
    return v.x == x0 || v.x == x1 || v.y == y0 || v.y == y1;
  }();
  if (vertexOnBorder) onBorder.push_back({in.vertices[static_cast<size_t>(leaf.vertex)], leaf.vertex});

  // The polygon's boundary through the leaf, from where it enters to where it leaves.
  std::vector<RegionPoint>& path = path_;
  path.clear();
  Vec2 hinge{0};
  std::array<PathCrossing, 2> crossings{};  // entry, exit
  if (leaf.edgeCount > 0) {
    auto crossing = [&](uint32_t e, bool entry) {
      const Vec2 a = in.vertices[in.edges[e][0]], b = in.vertices[in.edges[e][1]];
      const Clip c = clipToSquare(a, b, x0, y0, x1, y1);
      const int side = entry ? c.entrySide : c.exitSide;
      crossings[entry ? 0 : 1] = {e, side};
      const bool vertical = side < 2;
      const double line = side == 0 ? x0 : side == 1 ? x1 : side == 2 ? y0 : y1;
      return RegionPoint{crossingOnLine(a, b, vertical, line, vertical ? y0 : x0, vertical ? y1 : x1, tree.gridSnap)};
    };
    if (leaf.vertex >= 0) {
      const auto v = static_cast<uint32_t>(leaf.vertex);
      const uint32_t into = in.edgeInto[v], outOf = in.edgeOutOf[v];
      const bool storedInto = std::find(leaf.edges.begin(), leaf.edges.begin() + leaf.edgeCount, into) != leaf.edges.begin() + leaf.edgeCount;
      const bool storedOutOf = std::find(leaf.edges.begin(), leaf.edges.begin() + leaf.edgeCount, outOf) != leaf.edges.begin() + leaf.edgeCount;
      if (storedInto) path.push_back(crossing(into, true));
      path.push_back({in.vertices[v], leaf.vertex});
      if (storedOutOf) path.push_back(crossing(outOf, false));
      hinge = in.vertices[v];
    } else {
      path.push_back(crossing(leaf.edges[0], true));
      path.push_back(crossing(leaf.edges[0], false));
      hinge = path.back().at;  // the end of the line (5.4)
    }
  }

  // Order the border points counter-clockwise, one per position (an input vertex first).
  std::vector<std::pair<double, RegionPoint>>& keyed = keyed_;
  keyed.clear();
  for (const RegionPoint& p : onBorder) keyed.push_back({border.param(p.at), p});
  auto before = [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && a.second.inputVertex > b.second.inputVertex);
  };
  // Mostly a handful of points: sorted by insertion in place, the order std::sort gives up to 16
  // elements (its own insertion sort) without its set-up.
  if (keyed.size() <= 16) {
    for (size_t i = 1; i < keyed.size(); ++i)
      for (size_t j = i; j > 0 && before(keyed[j], keyed[j - 1]); --j) std::swap(keyed[j], keyed[j - 1]);
  } else {
    std::sort(keyed.begin(), keyed.end(), before);
  }
  keyed.erase(std::unique(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.second.at == b.second.at; }),
              keyed.end());

  // An edge that only grazes a corner (its crossings snapped onto one point) leaves the square
  // wholly on one side: which, its own direction says at the centre.
  const bool grazing = leaf.vertex < 0 && path.size() == 2 && path.front().at == path.back().at;
  if (path.empty() || grazing) {
    const bool inside = grazing ? tree.insideAt(q, {x0 + s / 2, y0 + s / 2}) : leaf.status == QuadStatus::Inside;
    if (!inside) return region;
    for (const auto& [param, p] : keyed) region.ring.push_back(p);
    // A whole square meshes as its template, also with the polygon's vertex at a corner (the
    // corner of a rectangle): its shape is the same.
    if (!grazing) region.templateKey = midpointSides(region.ring, x0, y0, s);
    region.inner = {x0 + s / 2, y0 + s / 2};
    return region;
  }

  // The inside runs along the border counter-clockwise from where the boundary leaves the
  // square to where it enters.
  const double from = border.param(path.back().at), to = border.param(path.front().at);
  const double span = to > from ? to - from : to + 4 * s - from;
  region.ring.assign(path.begin(), path.end());
  // The border points are in order of their parameter: those past `from` first, then the rest.
  const auto pastFrom = std::upper_bound(keyed.begin(), keyed.end(), from, [](double f, const auto& k) { return f < k.first; });
  for (auto k = pastFrom; k != keyed.end() && k->first - from < span; ++k) region.ring.push_back(k->second);
  for (auto k = keyed.begin(); k != pastFrom && k->first + 4 * s - from < span; ++k)
    if (k->first != from) region.ring.push_back(k->second);
  // Drop points repeated next to each other (a crossing on a corner, the vertex on the border).
  std::vector<RegionPoint>& ring = ring_;
  ring.clear();
  for (size_t i = 0; i < region.ring.size(); ++i) {
    const RegionPoint& p = region.ring[i];
    if (!ring.empty() && ring.back().at == p.at) {
      if (p.inputVertex >= 0) ring.back() = p;
      continue;
    }
    ring.push_back(p);
    if (i < path.size()) region.boundary.pathPoints = ring.size();
  }
  while (ring.size() > 1 && ring.front().at == ring.back().at) {
    if (ring.back().inputVertex >= 0) ring.front() = ring.back();
    ring.pop_back();
  }
  region.boundary.pathPoints = std::min(region.boundary.pathPoints, ring.size());
  region.ring.swap(ring);
  if (region.ring.size() < 3) {
    region.ring.clear();
    region.boundary.pathPoints = 0;
    return region;
  }
  handOverWedges(q, crossings, hinge);
  if (region.ring.empty()) return region;
  for (size_t i = 0; i < region.ring.size(); ++i)
    if (region.ring[i].at == hinge) region.hinge = static_cast<int>(i);
  at_.clear();
  for (const RegionPoint& p : region.ring) at_.push_back(p.at);
  region.inner = centroid(at_);
  return region;
}

void LeafRegionBuilder::handOverWedges(int32_t q, const std::array<PathCrossing, 2>& crossings, Vec2& hinge) {
  LeafRegion& region = region_;
  std::vector<RegionPoint>& ring = region.ring;
  const size_t n = ring.size(), path = region.boundary.pathPoints;
  const std::vector<uint8_t>& shallow = tree_.input.shallow;
  auto isShallow = [&](const PathCrossing& c) { return c.side >= 0 && c.edge < shallow.size() && shallow[c.edge]; };
  if (path < 2 || (!isShallow(crossings[0]) && !isShallow(crossings[1]))) return;
  // The entry crossing is ring[0], its neighbour along the border the last point; the exit
  // crossing is ring[path - 1], its neighbour the next one.
  std::array<std::optional<WedgeHandover>, 2> handovers;
  const std::array<size_t, 2> at{0, path - 1}, neighbour{n - 1, path};
  for (size_t k = 0; k < 2; ++k) {
    const PathCrossing& c = crossings[k];
    if (c.side < 0 || neighbour[k] < path || neighbour[k] >= n || ring[at[k]].inputVertex >= 0) continue;
    int32_t tooCoarse = -1;
    handovers[k] = wedgeHandover(tree_, frame_.planePerTree(), q, c.edge, c.side, ring[at[k]].at, ring[neighbour[k]].at, &tooCoarse);
    if (tooCoarse >= 0 && coarseTakers_) coarseTakers_->push_back(tooCoarse);
  }
  if (!handovers[0] && !handovers[1]) return;
  region.handedOver = true;
  std::vector<RegionPoint>& out = handed_;
  out.clear();
  closing_.clear();  // an entering taker's points after M, the ring's last point
  size_t pathKept = 0;
  for (size_t i = 0; i < n; ++i) {
    const size_t k = i == at[0] && handovers[0] ? 0 : i == at[1] && handovers[1] ? 1 : 2;
    if (k == 2) {
      out.push_back(ring[i]);
      pathKept += i < path;
      continue;
    }
    const WedgeHandover& h = *handovers[k];
    const RegionPoint end{h.mPrime, h.vertex};
    if (hinge == ring[i].at) hinge = h.mPrime;
    if (h.giver == q) {
      // The giver keeps what is left of its wedge: it runs V -> M (V is its next path point
      // already), or from M' on.
      if (h.vertex < 0) out.push_back(end), ++pathKept;
      continue;
    }
    // M -> M' (or V) joins the taker's ring where Q was: after M, or (entering) before it.
    out.push_back(end);
    ++pathKept;
    if (k == 0) {
      pointsBetween(tree_, h, closing_);
    } else {
      between_.clear();
      pointsBetween(tree_, h, between_);
      for (auto p = between_.rbegin(); p != between_.rend(); ++p) out.push_back({*p});
    }
  }
  for (const Vec2& p : closing_) out.push_back({p});
  // M' where the edge leaves the giver repeats that crossing.
  ring.clear();
  for (size_t i = 0; i < out.size(); ++i) {
    if (!ring.empty() && ring.back().at == out[i].at) {
      pathKept -= i < pathKept;
      continue;
    }
    ring.push_back(out[i]);
  }
  while (ring.size() > 1 && ring.front().at == ring.back().at) ring.pop_back();
  region.boundary.pathPoints = std::min(pathKept, ring.size());
  // A giver left with points on the line through M -> M' alone has nothing left.
  bool flat = false;
  for (const std::optional<WedgeHandover>& h : handovers)
    if (h && h->giver == q && h->vertex < 0) {
      const bool acrossX = h->m.x == h->mPrime.x;
      flat = flat || std::all_of(ring.begin(), ring.end(), [&](const RegionPoint& p) { return acrossX ? p.at.x == h->m.x : p.at.y == h->m.y; });
    }
  if (flat || ring.size() < 3) {
    ring.clear();
    region.boundary.pathPoints = 0;
  }
}

}  // namespace mesher
