#include "mesher/convex_partition.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mesher {

namespace {

// Whether c lies on segment [a, b] or so close to its line, within its extent, that a chord
// along it would graze c: chords are refused rather than trusted to rounding.
bool touches(Vec2 a, Vec2 b, Vec2 c) {
  if (c.x < std::min(a.x, b.x) || c.x > std::max(a.x, b.x) || c.y < std::min(a.y, b.y) || c.y > std::max(a.y, b.y)) return false;
  return std::abs(orient2(a, b, c)) <= kMinTurnSine * glm::length(b - a) * glm::length(c - a);
}

bool segmentsMeet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  // Boxes apart, segments apart: most edges of a ring are far from a chord.
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
      std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
    return false;
  const double o1 = orient2(a, b, c), o2 = orient2(a, b, d), o3 = orient2(c, d, a), o4 = orient2(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return touches(a, b, c) || touches(a, b, d) || touches(c, d, a) || touches(c, d, b);
}

// Whether the direction from ring point `at` to `to` leaves it into the ring's inside, strictly
// between its edges to `prev` and `next` (counter-clockwise ring).
bool inCone(Vec2 prev, Vec2 at, Vec2 next, Vec2 to) {
  if (orient2(prev, at, next) > 0) return orient2(at, to, prev) > 0 && orient2(to, at, next) > 0;
  return !(orient2(at, to, next) >= 0 && orient2(to, at, prev) >= 0);
}

}  // namespace

bool isDiagonal(const std::vector<Vec2>& p, size_t i, size_t j) {
  const size_t n = p.size();
  if (!inCone(p[(i + n - 1) % n], p[i], p[(i + 1) % n], p[j]) || !inCone(p[(j + n - 1) % n], p[j], p[(j + 1) % n], p[i]))
    return false;
  for (size_t k = 0; k < n; ++k) {
    const size_t l = (k + 1) % n;
    if (k == i || k == j || l == i || l == j) {
      // Edges at the chord's ends meet it there; another point of theirs on it is a graze.
      const size_t other = k == i || k == j ? l : k;
      if (other != i && other != j && touches(p[i], p[j], p[other])) return false;
      continue;
    }
    if (segmentsMeet(p[i], p[j], p[k], p[l])) return false;
  }
  return true;
}

double ConvexPartition::partition(const std::vector<Vec2>& points, const std::vector<Vec2>& shaped,
                                  const std::vector<double>& reach, std::vector<RingElement>& out, double rounding) {
  const size_t n = points.size();
  if (n < 3) return -1;
  n_ = n;
  chord_.assign(n * n, 0);
  for (size_t i = 0; i < n; ++i) {
    chord_[i * n + (i + 1) % n] = chord_[((i + 1) % n) * n + i] = 1;
    for (size_t j = i + 2; j < n; ++j)
      if (!(i == 0 && j == n - 1) && isDiagonal(points, i, j)) chord_[i * n + j] = chord_[j * n + i] = 1;
  }
  auto corner = [&](size_t prev, size_t at, size_t next) {
    return cornerAngleDeg(shaped[prev], shaped[at], shaped[next]) / reach[at];
  };
  length2_.resize(n * n);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j) length2_[i * n + j] = glm::dot(points[j] - points[i], points[j] - points[i]);
  // turnsLeft by indices, with the squared lengths looked up (computed once per ring).
  auto turns = [&](size_t a, size_t b, size_t c) {
    return turnsPast(orient2(points[a], points[b], points[c]), length2_[a * n + b], length2_[b * n + c], rounding);
  };
  constexpr double kOpen = std::numeric_limits<double>::infinity();  // a ring edge: nothing to partition
  best_.assign(n * n, Best{});
  for (size_t i = 0; i + 1 < n; ++i) best_[i * n + i + 1] = {kOpen, 0, 0, 0};
  // Better: a higher score, with scores of 1 and more counting alike, then fewer pieces. Asked
  // first of the sub-partitions alone (a piece can only lower the score), it prunes.
  auto better = [](double score, uint32_t count, const Best& than) {
    const double s = std::min(score, 1.0), t = std::min(than.score, 1.0);
    return s > t || (s == t && count < than.count);
  };
  for (size_t span = 2; span < n; ++span)
    for (size_t i = 0; i + span < n; ++i) {
      const size_t j = i + span;
      if (!chord_[i * n + j]) continue;
      Best& here = best_[i * n + j];
      for (size_t a = i + 1; a < j; ++a) {
        if (!chord_[i * n + a] || !chord_[a * n + j]) continue;
        const Best &left = best_[i * n + a], &right = best_[a * n + j];
        if (left.score < 0) continue;
        if (right.score >= 0 && better(std::min(left.score, right.score), left.count + right.count + 1, here) &&
            turns(i, a, j) && turns(a, j, i) && turns(j, i, a)) {
          const double score =
              std::min({left.score, right.score, corner(j, i, a), corner(i, a, j), corner(a, j, i)});
          const uint32_t count = left.count + right.count + 1;
          if (better(score, count, here)) here = {score, count, static_cast<uint32_t>(a), static_cast<uint32_t>(a)};
        }
        for (size_t b = a + 1; b < j; ++b) {
          if (!chord_[a * n + b] || !chord_[b * n + j]) continue;
          const Best &middle = best_[a * n + b], &last = best_[b * n + j];
          if (middle.score < 0 || last.score < 0 ||
              !better(std::min({left.score, middle.score, last.score}), left.count + middle.count + last.count + 1, here) ||
              !turns(i, a, b) || !turns(a, b, j) || !turns(b, j, i) || !turns(j, i, a))
            continue;
          const double score = std::min({left.score, middle.score, last.score, corner(j, i, a), corner(i, a, b),
                                         corner(a, b, j), corner(b, j, i)});
          const uint32_t count = left.count + middle.count + last.count + 1;
          if (better(score, count, here))
            here = {score, count, static_cast<uint32_t>(a), static_cast<uint32_t>(b)};
        }
      }
    }
  const Best& whole = best_[n - 1];
  if (whole.score < 0) return -1;
  emit(0, n - 1, out);
  return whole.score;
}

void ConvexPartition::emit(size_t i, size_t j, std::vector<RingElement>& out) const {
  if (j == i + 1) return;
  const Best& piece = best_[i * n_ + j];
  const auto ii = static_cast<uint32_t>(i), jj = static_cast<uint32_t>(j);
  if (piece.a == piece.b) {
    out.push_back({{ii, piece.a, jj, 0}, 3});
    emit(i, piece.a, out);
  } else {
    out.push_back({{ii, piece.a, piece.b, jj}, 4});
    emit(i, piece.a, out);
    emit(piece.a, piece.b, out);
  }
  emit(piece.b, j, out);
}

}  // namespace mesher
