#include "tests/mesher/random_polygons.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mesher::test {

namespace {

// `points` points counter-clockwise round `center`, at angles jittered by up to `jitter` of their
// spacing and at radii from `nearest` x radius to radius.
Ring2 ringAround(std::mt19937& random, Vec2 center, double radius, int points, double jitter, double nearest) {
  std::uniform_real_distribution<double> unit(0, 1);
  Ring2 ring;
  for (int i = 0; i < points; ++i) {
    const double a = 2 * std::numbers::pi * (i + jitter * unit(random)) / points;
    const double r = nearest < 1 ? radius * (nearest + (1 - nearest) * unit(random)) : radius;
    ring.push_back(center + r * Vec2{std::cos(a), std::sin(a)});
  }
  return ring;
}

// An outer ring of `points` about a random centre up to `offset` from the origin, of radius 1
// to 101 (ringAround's jitter and nearest).
struct Outline {
  Ring2 ring;
  Vec2 center;
  double radius;
};
Outline randomOutline(std::mt19937& random, double offset, int points, double jitter, double nearest) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double radius = 1 + 100 * unit(random);
  const Vec2 center{2 * offset * (unit(random) - 0.5), 2 * offset * (unit(random) - 0.5)};
  return {ringAround(random, center, radius, points, jitter, nearest), center, radius};
}

}  // namespace

PolygonWithHoles randomPolygonWithHoles(std::mt19937& random, int trial, double offset) {
  std::uniform_real_distribution<double> unit(0, 1);
  PolygonWithHoles p;
  const int sides = 3 + trial % 9;
  const auto [outer, center, radius] = randomOutline(random, offset, sides, 0.3, 1);
  p.outer = outer;
  // Holes in the cells of a square grid inside the largest circle about the centre.
  double clearance = radius;
  for (int i = 0; i < sides; ++i) {
    const Vec2 a = p.outer[static_cast<size_t>(i)], b = p.outer[static_cast<size_t>((i + 1) % sides)];
    clearance = std::min(clearance, orient2(a, b, center) / glm::length(b - a));
  }
  const double inner = 0.7 * clearance;
  const int cells = trial % 4;
  for (int cx = 0; cx < cells; ++cx)
    for (int cy = 0; cy < cells; ++cy) {
      if (unit(random) < 0.3) continue;
      const double cell = 2 * inner / cells;
      const Vec2 c = center + Vec2{-inner + (cx + 0.5) * cell, -inner + (cy + 0.5) * cell};
      Ring2 hole = ringAround(random, c, 0.4 * cell, 3 + static_cast<int>(unit(random) * 5), 0.5, 1);
      if (trial % 2) std::reverse(hole.begin(), hole.end());
      p.holes.push_back(hole);
    }
  return p;
}

PolygonWithHoles randomStarPolygon(std::mt19937& random, int trial, double offset) {
  std::uniform_real_distribution<double> unit(0, 1);
  PolygonWithHoles p;
  const int points = 6 + trial % 35;
  const auto [outer, center, radius] = randomOutline(random, offset, points, 0.8, 0.3);
  p.outer = outer;
  // Angle gaps stay under 108 degrees, so the disk of 0.3 x 0.58 x radius is inside.
  const double clear = 0.3 * 0.58 * radius;
  const int holes = trial % 4;
  for (int h = 0; h < holes; ++h) {
    const double a = 2 * std::numbers::pi * h / std::max(holes, 1);
    const Vec2 c = center + (holes > 1 ? 0.5 * clear : 0.0) * Vec2{std::cos(a), std::sin(a)};
    p.holes.push_back(ringAround(random, c, 0.2 * clear, 3 + static_cast<int>(unit(random) * 5), 0.5, 1));
  }
  return p;
}

RandomTestPolygon randomTestPolygon(std::mt19937& random, bool concave, int trial) {
  if (concave) return {randomStarPolygon(random, trial, trial % 2 ? 1e5 : 10), 2.0 + trial % 30};
  return {randomPolygonWithHoles(random, trial), 5.0 + trial % 40};
}

RandomTestPolygon randomTestPolygon(unsigned seed, bool concave, int trial) {
  std::mt19937 random(seed);
  RandomTestPolygon polygon;
  for (int made = 0; made <= trial; ++made) polygon = randomTestPolygon(random, concave, made);
  return polygon;
}

}  // namespace mesher::test
