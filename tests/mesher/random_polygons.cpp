#include "tests/mesher/random_polygons.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mesher::test {

PolygonWithHoles randomPolygonWithHoles(std::mt19937& random, int trial, double offset) {
  std::uniform_real_distribution<double> unit(0, 1);
  PolygonWithHoles p;
  const int sides = 3 + trial % 9;
  const double radius = 1 + 100 * unit(random);
  const Vec2 center{2 * offset * (unit(random) - 0.5), 2 * offset * (unit(random) - 0.5)};
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.3 * unit(random)) / sides;
    p.outer.push_back(center + radius * Vec2{std::cos(a), std::sin(a)});
  }
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
      Ring2 hole;
      const int holeSides = 3 + static_cast<int>(unit(random) * 5);
      for (int i = 0; i < holeSides; ++i) {
        const double a = 2 * std::numbers::pi * (i + 0.5 * unit(random)) / holeSides;
        hole.push_back(c + 0.4 * cell * Vec2{std::cos(a), std::sin(a)});
      }
      if (trial % 2) std::reverse(hole.begin(), hole.end());
      p.holes.push_back(hole);
    }
  return p;
}

}  // namespace mesher::test
