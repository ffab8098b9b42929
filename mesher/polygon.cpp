#include "mesher/polygon.h"

#include <glm/geometric.hpp>
#include <numbers>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mesher {

namespace {

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

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

}  // namespace

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
    if (lengths > 0 && orient2(a, b, c) * sign < -tolerance * lengths) return false;
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
  for (size_t i = 0; i < n; ++i)
    if (ring[i] == ring[(i + 1) % n]) return false;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        // Adjacent edges share one point; they must not fold back onto each other.
        const size_t shared = (j == i + 1) ? j : i;
        const Vec2 s = ring[shared];
        const Vec2 p = ring[(shared + n - 1) % n], q = ring[(shared + 1) % n];
        if (orient2(p, s, q) == 0 && glm::dot(p - s, q - s) > 0) return false;
        continue;
      }
      if (segmentsIntersect(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) return false;
    }
  }
  return n >= 3;
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
