#include "mesher/triangulate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace mesher {

namespace {

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// True when the direction from v toward `target` points into the polygon's interior at corner
// prev -> v -> next of a counter-clockwise boundary (interior on the left).
bool intoInterior(Vec2 prev, Vec2 v, Vec2 next, Vec2 target) {
  const Vec2 d = target - v, toPrev = prev - v, toNext = next - v;
  if (orient2(prev, v, next) > 0) return cross(toNext, d) > 0 && cross(d, toPrev) > 0;
  return !(cross(toPrev, d) >= 0 && cross(d, toNext) >= 0);
}

// A closed boundary as indices into the point array.
using Loop = std::vector<uint32_t>;

struct Bridger {
  const std::vector<Vec2>& points;
  double tolerance;  // a length: a bridge passing this close to an edge is taken to touch it

  // True when segment m-v stays clear of every edge of `loop` other than edges ending at m or v.
  bool clearOf(const Loop& loop, Vec2 m, Vec2 v) const {
    for (size_t e = 0; e < loop.size(); ++e) {
      const Vec2 a = points[loop[e]], b = points[loop[(e + 1) % loop.size()]];
      if (a == m || b == m || a == v || b == v) continue;
      if (segmentDistance(m, v, a, b) <= tolerance) return false;
    }
    return true;
  }

  // Splices `hole` (clockwise) into `boundary` (counter-clockwise) through the nearest boundary
  // point that sees the hole's rightmost point.
  void join(Loop& boundary, const Loop& hole, const std::vector<Loop>& otherHoles) const {
    size_t mAt = 0;
    for (size_t i = 1; i < hole.size(); ++i)
      if (points[hole[i]].x > points[hole[mAt]].x) mAt = i;
    const Vec2 m = points[hole[mAt]];
    const Vec2 mPrev = points[hole[(mAt + hole.size() - 1) % hole.size()]];
    const Vec2 mNext = points[hole[(mAt + 1) % hole.size()]];

    size_t best = boundary.size(), nearest = 0;
    double bestDist = std::numeric_limits<double>::infinity(), nearestDist = bestDist;
    for (size_t k = 0; k < boundary.size(); ++k) {
      const Vec2 v = points[boundary[k]];
      const double dist = glm::length(v - m);
      if (dist < nearestDist) nearestDist = dist, nearest = k;
      if (dist >= bestDist || v == m) continue;
      const Vec2 prev = points[boundary[(k + boundary.size() - 1) % boundary.size()]];
      const Vec2 next = points[boundary[(k + 1) % boundary.size()]];
      if (!intoInterior(prev, v, next, m) || !intoInterior(mPrev, m, mNext, v)) continue;
      if (!clearOf(boundary, m, v) || !clearOf(hole, m, v)) continue;
      if (!std::all_of(otherHoles.begin(), otherHoles.end(),
                       [&](const Loop& h) { return clearOf(h, m, v); }))
        continue;
      best = k, bestDist = dist;
    }
    if (best == boundary.size()) best = nearest;  // only reached for invalid input

    Loop spliced(boundary.begin(), boundary.begin() + static_cast<ptrdiff_t>(best) + 1);
    for (size_t i = 0; i <= hole.size(); ++i) spliced.push_back(hole[(mAt + i) % hole.size()]);
    spliced.insert(spliced.end(), boundary.begin() + static_cast<ptrdiff_t>(best), boundary.end());
    boundary = std::move(spliced);
  }
};

// `slack` is an area: points this close to a candidate ear count as inside it, so that a point
// a rounding error outside an ear's edge (as on rotated input) does not let the ear through.
void clipEars(const std::vector<Vec2>& points, const Loop& loop, double slack,
              std::vector<std::array<uint32_t, 3>>& triangles) {
  const size_t n = loop.size();
  std::vector<size_t> prev(n), next(n);
  for (size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  auto at = [&](size_t i) { return points[loop[i]]; };

  auto isEar = [&](size_t i) {
    const Vec2 a = at(prev[i]), b = at(i), c = at(next[i]);
    if (orient2(a, b, c) <= slack) return false;
    for (size_t j = next[next[i]]; j != prev[i]; j = next[j]) {
      const Vec2 p = at(j);
      if (p == a || p == b || p == c) continue;  // bridge copies of the corners
      if (orient2(a, b, p) >= -slack && orient2(b, c, p) >= -slack && orient2(c, a, p) >= -slack) return false;
    }
    return true;
  };
  auto emitAndRemove = [&](size_t i) {
    if (orient2(at(prev[i]), at(i), at(next[i])) > 0)
      triangles.push_back({loop[prev[i]], loop[i], loop[next[i]]});
    next[prev[i]] = next[i];
    prev[next[i]] = prev[i];
  };

  size_t remaining = n, i = 0, sinceLastEar = 0;
  while (remaining > 3) {
    if (isEar(i)) {
      const size_t after = next[i];
      emitAndRemove(i);
      --remaining, sinceLastEar = 0;
      i = after;
      continue;
    }
    i = next[i];
    if (++sinceLastEar > remaining) {
      // No ear in a full turn: only degenerate input gets here. Drop the flattest corner so the
      // loop always ends.
      size_t flattest = i;
      double smallest = std::numeric_limits<double>::infinity();
      size_t j = i;
      do {
        const double turn = std::abs(orient2(at(prev[j]), at(j), at(next[j])));
        if (turn < smallest) smallest = turn, flattest = j;
        j = next[j];
      } while (j != i);
      i = next[flattest];
      emitAndRemove(flattest);
      --remaining, sinceLastEar = 0;
    }
  }
  if (remaining == 3) emitAndRemove(i);
}

}  // namespace

std::vector<std::array<uint32_t, 3>> triangulate(const PolygonWithHoles& polygon) {
  std::vector<std::array<uint32_t, 3>> triangles;
  if (polygon.outer.size() < 3) return triangles;

  // Number the points: outer first, then each hole.
  std::vector<Vec2> points(polygon.outer);
  for (const Ring2& hole : polygon.holes) points.insert(points.end(), hole.begin(), hole.end());

  // Orient the loops: boundary counter-clockwise, holes clockwise.
  auto makeLoop = [](uint32_t first, size_t count, bool reverse) {
    Loop loop(count);
    for (size_t i = 0; i < count; ++i) loop[i] = first + static_cast<uint32_t>(i);
    if (reverse) std::reverse(loop.begin(), loop.end());
    return loop;
  };
  Loop boundary = makeLoop(0, polygon.outer.size(), signedArea(polygon.outer) < 0);
  std::vector<Loop> holes;
  uint32_t first = static_cast<uint32_t>(polygon.outer.size());
  for (const Ring2& hole : polygon.holes) {
    if (hole.size() >= 3) holes.push_back(makeLoop(first, hole.size(), signedArea(hole) > 0));
    first += static_cast<uint32_t>(hole.size());
  }

  // Join holes rightmost first, so each bridge runs toward boundary already joined.
  std::sort(holes.begin(), holes.end(), [&](const Loop& a, const Loop& b) {
    auto maxX = [&](const Loop& l) {
      double x = -std::numeric_limits<double>::infinity();
      for (uint32_t i : l) x = std::max(x, points[i].x);
      return x;
    };
    return maxX(a) > maxX(b);
  });
  // Tolerances relative to the polygon's size, a few hundred rounding errors wide.
  const double size = extent(polygon.outer);
  const double tolerance = 1e-13 * size;
  const Bridger bridger{points, tolerance};
  for (size_t h = 0; h < holes.size(); ++h) {
    const std::vector<Loop> later(holes.begin() + static_cast<ptrdiff_t>(h) + 1, holes.end());
    bridger.join(boundary, holes[h], later);
  }

  triangles.reserve(boundary.size());
  clipEars(points, boundary, tolerance * size, triangles);
  return triangles;
}

}  // namespace mesher
