#include "mesher/tree_frame.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <initializer_list>
#include <cmath>

namespace mesher {

namespace {

// The unit direction of the longest outer edge, exact for axis-aligned edges.
Vec2 longestEdgeDirection(const Ring2& outer) {
  Vec2 best{1, 0};
  double bestLength = -1;
  for (size_t i = 0; i < outer.size(); ++i) {
    const Vec2 d = outer[(i + 1) % outer.size()] - outer[i];
    const double length = glm::length(d);
    if (length > bestLength) bestLength = length, best = d;
  }
  if (best.y == 0) return {best.x > 0 ? 1.0 : -1.0, 0};
  if (best.x == 0) return {0, best.y > 0 ? 1.0 : -1.0};
  return best / bestLength;
}

double nextPowerOfTwo(double x) { return std::exp2(std::ceil(std::log2(x))); }

}  // namespace

Vec2 TreeFrame::toTree(Vec2 plane) const {
  const Vec2 d = plane - origin;
  Vec2 t{glm::dot(d, xAxis), glm::dot(d, yAxis())};
  t *= scale;
  t[shortAxis] *= stretch;
  return t;
}

Vec2 TreeFrame::toPlane(Vec2 tree) const {
  tree[shortAxis] /= stretch;
  tree /= scale;
  return origin + xAxis * tree.x + yAxis() * tree.y;
}

int TreeFrame::finestLevel() const {
  if (!std::isfinite(scale * stretch) || !std::isfinite(rounding)) return -1;
  const double coarser = std::ceil(std::log2(kFinestLeafOverRounding * rounding));
  return maxDepth - static_cast<int>(std::clamp(coarser, 0.0, maxDepth + 1.0));
}

Vec2 TreeFrame::planePerTree() const {
  Vec2 perUnit{1 / scale, 1 / scale};
  perUnit[shortAxis] /= stretch;
  return perUnit;
}

TreeFrame setupTreeFrame(const PolygonWithHoles& polygon, int maxDepth) {
  TreeFrame frame;
  frame.maxDepth = maxDepth;
  frame.xAxis = longestEdgeDirection(polygon.outer);

  // Extents along the turned axes (holes lie inside the outer ring).
  Vec2 lo{INFINITY}, hi{-INFINITY};
  for (const Vec2& p : polygon.outer) {
    const Vec2 turned{glm::dot(p, frame.xAxis), glm::dot(p, frame.yAxis())};
    lo = glm::min(lo, turned);
    hi = glm::max(hi, turned);
  }
  frame.origin = frame.xAxis * lo.x + frame.yAxis() * lo.y;
  const Vec2 extent = hi - lo;
  const int longAxis = extent.x >= extent.y ? 0 : 1;
  frame.shortAxis = 1 - longAxis;

  const double root = std::exp2(maxDepth);
  frame.scale = root / extent[longAxis];
  const double shortScaled = extent[frame.shortAxis] * frame.scale;
  frame.stretch = std::max(1.0, nextPowerOfTwo(shortScaled)) / shortScaled;

  // Rounding in tree coordinates: of the root square's size, and of the plane coordinates (their
  // magnitude, carried through the turn and the scale: a few roundings of each), with a margin.
  // Taken down to a power of two, so that a polygon repeated nearby (at a magnitude a little
  // different) has the same frame bit for bit and is found a repeat (MeshMemo); up, it kept a
  // deeper tree from a few polygons that needed one.
  double magnitude = 0;
  for (const Vec2& p : polygon.outer) magnitude = std::max({magnitude, std::abs(p.x), std::abs(p.y)});
  constexpr double kEpsilon = 0x1p-52;
  const double rounding = std::max(16 * root * kEpsilon, 16 * magnitude * kEpsilon * frame.scale * frame.stretch);
  int exponent = 0;
  std::frexp(rounding, &exponent);  // rounding = m * 2^exponent, m in [0.5, 1)
  frame.rounding = std::ldexp(1.0, exponent - 1);
  frame.gridSnap = std::max(1e-6, frame.rounding);
  return frame;
}

int initialDepth(double longerExtent, double patchSize, int maxDepth) {
  const double depth = std::ceil(std::log2(longerExtent / patchSize));
  // NaN, from a frame without extent (a ring of no area), is no depth: the frame is refused.
  if (std::isnan(depth)) return 0;
  return static_cast<int>(std::clamp(depth, 0.0, static_cast<double>(maxDepth)));
}

}  // namespace mesher
