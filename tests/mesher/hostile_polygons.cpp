#include "tests/mesher/hostile_polygons.h"

#include "mesher/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace mesher::test {

namespace {

double unit(std::mt19937& random) { return std::uniform_real_distribution<double>(0, 1)(random); }

// 10^x for x uniform in [lo, hi].
double logUniform(std::mt19937& random, double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * unit(random)); }

int between(std::mt19937& random, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(random); }

// A long thin triangle of length 1: its apex `width` off the base, somewhere along it or past an
// end (the needle has it a hair from one end).
Ring2 needle(std::mt19937& random) {
  const double width = logUniform(random, -9, -1);
  const double along = unit(random) < 0.3 ? logUniform(random, -12, -4) : unit(random);
  return {{0, 0}, {1, 0}, {along, width}};
}

// A thin quadrilateral or pentagon along the x axis, a few heights tiny against its length.
Ring2 sliver(std::mt19937& random) {
  const double h = logUniform(random, -9, -2);
  if (unit(random) < 0.5) return {{0, 0}, {1, 0}, {1, h * unit(random) + h}, {0, h}};
  return {{0, 0}, {0.5, 0}, {1, h}, {0.5, 2 * h}, {0, h}};
}

// A regular polygon with one of its vertices doubled a hair away, along the next side or off it.
Ring2 hairApart(std::mt19937& random) {
  Ring2 ring = regularPolygon({0, 0}, 1, between(random, 3, 63), 360 * unit(random));
  const size_t at = static_cast<size_t>(between(random, 0, static_cast<int>(ring.size()) - 1));
  const Vec2 p = ring[at], next = ring[(at + 1) % ring.size()];
  const double d = logUniform(random, -13, -2);
  const Vec2 along = (next - p) / std::hypot(next.x - p.x, next.y - p.y);
  const Vec2 inward = -p / std::hypot(p.x, p.y);
  const double mix = unit(random);
  ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(at) + 1, p + d * (mix * along + (1 - mix) * inward));
  return ring;
}

// A comb of up to 15 teeth: thin teeth, teeth a hair apart, slanted teeth.
Ring2 randomComb(std::mt19937& random) {
  const int teeth = between(random, 1, 15);
  const double width = unit(random) < 0.3 ? logUniform(random, -9, -1) : unit(random) < 0.5 ? 1 - logUniform(random, -12, -1) : unit(random);
  const double height = logUniform(random, -2, 3);
  const double slant = unit(random) < 0.5 ? 0 : (unit(random) - 0.5) * height * 2;
  return comb(teeth, 1, std::max(width, 1e-12), height, slant);
}

// A star of 3 to 64 points at radii down to a millionth of the largest.
Ring2 star(std::mt19937& random) {
  const int points = between(random, 3, 64);
  const double nearest = logUniform(random, -6, 0);
  Ring2 ring;
  for (int i = 0; i < points; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.9 * unit(random)) / points;
    const double r = nearest + (1 - nearest) * unit(random);
    ring.push_back(r * Vec2{std::cos(a), std::sin(a)});
  }
  return ring;
}

// A square with square holes, some a hair from the outer ring or from each other.
PolygonWithHoles holesAHairApart(std::mt19937& random) {
  PolygonWithHoles p{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  const double gap = logUniform(random, -11, -2);
  const int holes = between(random, 1, 6);
  const double size = (1 - (holes + 1) * gap) / holes;
  const double low = unit(random) < 0.5 ? gap : 0.5 - size / 2;
  for (int h = 0; h < holes; ++h) {
    const double x = gap + h * (size + gap);
    p.holes.push_back({{x, low}, {x, low + size * 0.9}, {x + size, low + size * 0.9}, {x + size, low}});
  }
  return p;
}

// Scaled, turned (often by quarter turns, which keep axis-aligned edges exact) and moved.
PolygonWithHoles placed(std::mt19937& random, const PolygonWithHoles& polygon) {
  const double scale = logUniform(random, -6, 6);
  const double turn = unit(random) < 0.4 ? std::numbers::pi / 2 * between(random, 0, 3) : 2 * std::numbers::pi * unit(random);
  const double far = unit(random) < 0.3 ? 0 : logUniform(random, 0, 8.5);
  const Vec2 offset{far * (2 * unit(random) - 1), far * (2 * unit(random) - 1)};
  const Vec2 x{std::cos(turn), std::sin(turn)}, y{-x.y, x.x};
  auto map = [&](const Ring2& ring) {
    Ring2 out;
    for (const Vec2& q : ring) out.push_back(offset + scale * (q.x * x + q.y * y));
    return out;
  };
  PolygonWithHoles out{map(polygon.outer), {}};
  for (const Ring2& hole : polygon.holes) out.holes.push_back(map(hole));
  return out;
}

}  // namespace

Ring2 comb(int teeth, double pitch, double width, double height, double slant) {
  const double length = teeth * pitch;
  Ring2 ring{{0, 0}, {length, 0}, {length, 1}};
  for (int t = teeth - 1; t >= 0; --t) {
    const double right = t * pitch + (pitch + width) / 2, left = right - width;
    ring.push_back({right, 1});
    ring.push_back({right + slant, 1 + height});
    ring.push_back({left + slant, 1 + height});
    ring.push_back({left, 1});
  }
  ring.push_back({0, 1});
  return ring;
}

Ring2 regularPolygon(Vec2 center, double radius, int sides, double turnDeg) {
  Ring2 ring;
  for (int i = 0; i < sides; ++i) {
    const double a = (turnDeg + 360.0 * i / sides) * std::numbers::pi / 180;
    ring.push_back(center + radius * Vec2{std::cos(a), std::sin(a)});
  }
  return ring;
}

bool validPolygon(const PolygonWithHoles& polygon) {
  auto validRing = [](const Ring2& ring) {
    if (ring.size() < 3) return false;
    for (const Vec2& p : ring)
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    const double size = extent(ring);
    return isSimple(ring) && std::abs(signedArea(ring)) > 1e-12 * size * size;
  };
  if (!validRing(polygon.outer)) return false;
  const double margin = 1e-9 * extent(polygon.outer);
  for (size_t h = 0; h < polygon.holes.size(); ++h) {
    const Ring2& hole = polygon.holes[h];
    if (!validRing(hole) || !containsPoint(polygon.outer, hole.front()) || boundaryDistance(polygon.outer, hole) <= margin) return false;
    for (size_t g = 0; g < h; ++g)
      if (boundaryDistance(hole, polygon.holes[g]) <= margin || containsPoint(hole, polygon.holes[g].front()) ||
          containsPoint(polygon.holes[g], hole.front()))
        return false;
  }
  return true;
}

HostilePolygon randomHostilePolygon(std::mt19937& random) {
  static const char* const kKinds[] = {"needle", "sliver", "hair apart", "comb", "star", "holes a hair apart"};
  for (;;) {
    const int kind = between(random, 0, 5);
    PolygonWithHoles shape;
    switch (kind) {
      case 0: shape.outer = needle(random); break;
      case 1: shape.outer = sliver(random); break;
      case 2: shape.outer = hairApart(random); break;
      case 3: shape.outer = randomComb(random); break;
      case 4: shape.outer = star(random); break;
      default: shape = holesAHairApart(random); break;
    }
    HostilePolygon out{placed(random, shape), 0, kKinds[kind]};
    out.patchSize = extent(out.polygon.outer) / logUniform(random, -1, 5);
    if (validPolygon(out.polygon)) return out;
  }
}

std::string polygonCaseJson(const HostilePolygon& polygon) {
  std::string out;
  char number[64];
  auto ring = [&](const Ring2& r) {
    out += '[';
    for (size_t i = 0; i < r.size(); ++i) {
      std::snprintf(number, sizeof number, "%s[%.17g, %.17g]", i ? ", " : "", r[i].x, r[i].y);
      out += number;
    }
    out += ']';
  };
  std::snprintf(number, sizeof number, "{\"patch_size\": %.17g, \"outer\": ", polygon.patchSize);
  out += number;
  ring(polygon.polygon.outer);
  if (!polygon.polygon.holes.empty()) {
    out += ", \"holes\": [";
    for (size_t h = 0; h < polygon.polygon.holes.size(); ++h) {
      if (h) out += ", ";
      ring(polygon.polygon.holes[h]);
    }
    out += ']';
  }
  return out + "}";
}

}  // namespace mesher::test
