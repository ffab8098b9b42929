#include "mesher/polygon.h"

#include <glm/geometric.hpp>
#include <numbers>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace mesher {

namespace {

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

// The ring's edges swept left to right (Shamos and Hoey 1976): edges crossing the sweep line are
// kept in order along it, and only edges next to each other in that order are tested, so a ring
// of n points costs n log n, not n^2. Whether two edges that are not neighbours in the ring meet
// (cross or touch): the first meeting, going left to right, is between edges that were next to
// each other before it. The ring's points must all lie apart.
class SegmentSweep {
 public:
  explicit SegmentSweep(const Ring2& ring) : ring_(ring), n_(ring.size()), status_(Below{this}) {}

  bool anyMeeting() {
    struct Event {
      Vec2 at;
      uint32_t edge;
      bool start;
    };
    std::vector<Event> events;
    events.reserve(2 * n_);
    for (uint32_t e = 0; e < n_; ++e) {
      events.push_back({left(e), e, true});
      events.push_back({right(e), e, false});
    }
    // Left to right, then up; at one point the edges ending there leave before others start.
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
      if (a.at.x != b.at.x) return a.at.x < b.at.x;
      if (a.at.y != b.at.y) return a.at.y < b.at.y;
      return !a.start && b.start;
    });
    std::vector<std::set<uint32_t, Below>::iterator> where(n_, status_.end());
    for (const Event& event : events) {
      if (!event.start) {
        const auto at = where[event.edge];
        const auto above = std::next(at);
        if (at != status_.begin() && above != status_.end() && meet(*std::prev(at), *above)) return true;
        status_.erase(at);
        continue;
      }
      const auto at = status_.insert(event.edge).first;
      where[event.edge] = at;
      if (met_) return true;
      if (at != status_.begin() && meet(*std::prev(at), event.edge)) return true;
      if (std::next(at) != status_.end() && meet(event.edge, *std::next(at))) return true;
    }
    return false;
  }

 private:
  // The order along the sweep line of two edges it crosses, judged at the left end of the one
  // that starts later: only an edge being inserted is compared, with edges already crossing.
  struct Below {
    SegmentSweep* sweep;
    bool operator()(uint32_t a, uint32_t b) const { return sweep->below(a, b); }
  };

  Vec2 from(uint32_t e) const { return ring_[e]; }
  Vec2 to(uint32_t e) const { return ring_[(e + 1) % n_]; }
  static bool leftOf(Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
  Vec2 left(uint32_t e) const { return leftOf(to(e), from(e)) ? to(e) : from(e); }
  Vec2 right(uint32_t e) const { return leftOf(to(e), from(e)) ? from(e) : to(e); }
  bool neighbours(uint32_t a, uint32_t b) const { return (a + 1) % n_ == b || (b + 1) % n_ == a; }
  // Whether edges a and b, not neighbours in the ring, meet.
  bool meet(uint32_t a, uint32_t b) const { return !neighbours(a, b) && segmentsIntersect(from(a), to(a), from(b), to(b)); }

  bool below(uint32_t a, uint32_t b) {
    if (a == b) return false;
    const bool aLater = leftOf(left(b), left(a));
    const uint32_t later = aLater ? a : b, earlier = aLater ? b : a;
    // A later edge starting on the earlier one's line meets it there, unless they are
    // neighbours (they start at one point): then their other ends decide.
    double side = orient2(left(earlier), right(earlier), left(later));
    if (side == 0) {
      met_ = met_ || meet(a, b);
      side = orient2(left(earlier), right(earlier), right(later));
      if (side == 0) return a < b;  // along one line: they meet, met_ says so
    }
    return (side > 0) != aLater;  // the later edge lies above the earlier one when side > 0
  }

  const Ring2& ring_;
  size_t n_;
  std::set<uint32_t, Below> status_;
  bool met_ = false;
};

}  // namespace

bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = orient2(c, d, a), d2 = orient2(c, d, b);
  const double d3 = orient2(a, b, c), d4 = orient2(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  // Touching or collinear overlap: some endpoint lies on the other segment.
  auto onSegment = [](Vec2 p, Vec2 q, Vec2 r, double o) {
    return o == 0 && std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
           std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
  };
  return onSegment(c, d, a, d1) || onSegment(c, d, b, d2) || onSegment(a, b, c, d3) ||
         onSegment(a, b, d, d4);
}

double signedArea(const Ring2& ring) {
  // Relative to the first point, so rings far from the origin keep their precision.
  double twice = 0;
  const size_t n = ring.size();
  if (n == 0) return 0;
  const Vec2 o = ring.front();
  for (size_t i = 1; i + 1 < n; ++i) {
    const Vec2 a = ring[i] - o, b = ring[i + 1] - o;
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

Vec2 centroid(const Ring2& ring) {
  // Relative to the first point, to keep precision for rings far from the origin.
  const Vec2 o = ring.front();
  Vec2 sum{0, 0};
  double twiceArea = 0;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i] - o, b = ring[(i + 1) % ring.size()] - o;
    const double cross = a.x * b.y - b.x * a.y;
    twiceArea += cross;
    sum += (a + b) * cross;
  }
  return o + sum / (3.0 * twiceArea);
}

double extent(const Ring2& ring) {
  if (ring.empty()) return 0;
  Vec2 lo = ring.front(), hi = ring.front();
  for (Vec2 p : ring) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return std::max(hi.x - lo.x, hi.y - lo.y);
}

bool isConvex(const Ring2& ring, double tolerance) {
  const size_t n = ring.size();
  if (n < 3) return false;
  const double sign = signedArea(ring) >= 0 ? 1.0 : -1.0;
  for (size_t i = 0; i < n; ++i) {
    // The sine of the turn at each corner, so a small notch is caught however large the ring.
    const Vec2 a = ring[i], b = ring[(i + 1) % n], c = ring[(i + 2) % n];
    const double lengths = glm::length(b - a) * glm::length(c - b);
    const double turn = orient2(a, b, c) * sign;
    if (lengths > 0 && turn < -tolerance * lengths) return false;
    // An edge running back along the one before turns half a circle, which the sum below counts
    // as +pi or -pi by the sign of a zero: a fold out and back again would cancel to nothing.
    if (turn <= 0 && glm::dot(b - a, c - b) < 0) return false;
  }
  // A ring that winds around twice turns one way everywhere but is not convex.
  double angle = 0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 e0 = ring[(i + 1) % n] - ring[i], e1 = ring[(i + 2) % n] - ring[(i + 1) % n];
    angle += std::atan2(e0.x * e1.y - e0.y * e1.x, glm::dot(e0, e1));
  }
  return std::abs(angle) < 2 * std::numbers::pi + 1e-6;
}

bool isSimple(const Ring2& ring) {
  const size_t n = ring.size();
  if (n < 3) return false;
  // Edges of no length, and adjacent edges folding back onto each other (they share one point).
  for (size_t i = 0; i < n; ++i) {
    const Vec2 p = ring[(i + n - 1) % n], s = ring[i], q = ring[(i + 1) % n];
    if (s == q || (orient2(p, s, q) == 0 && glm::dot(p - s, q - s) > 0)) return false;
  }
  // Points repeated further apart make edges that touch. With every point apart, at most the
  // two edges of one point meet there, and the sweep below finds any other meeting.
  std::vector<uint32_t> order(n);
  for (uint32_t i = 0; i < n; ++i) order[i] = i;
  const auto lexicographic = [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return lexicographic(ring[a], ring[b]); });
  for (size_t k = 1; k < n; ++k)
    if (ring[order[k]] == ring[order[k - 1]]) return false;
  return !SegmentSweep(ring).anyMeeting();
}

bool strictlyInsideConvex(const Ring2& convex, Vec2 p, double margin) {
  const size_t n = convex.size();
  const double sign = signedArea(convex) >= 0 ? 1.0 : -1.0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 a = convex[i], b = convex[(i + 1) % n];
    const double len = glm::length(b - a);
    if (len == 0) continue;
    if (orient2(a, b, p) * sign / len <= margin) return false;
  }
  return true;
}

bool containsPoint(const Ring2& ring, Vec2 p) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[i], b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

double segmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segmentsIntersect(a, b, c, d)) return 0;
  return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d),
                   pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)});
}

double boundaryDistance(const Ring2& r, const Ring2& s) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < r.size(); ++i)
    for (size_t j = 0; j < s.size(); ++j)
      best = std::min(best, segmentDistance(r[i], r[(i + 1) % r.size()], s[j], s[(j + 1) % s.size()]));
  return best;
}

}  // namespace mesher
