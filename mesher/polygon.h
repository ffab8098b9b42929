// Plain 2-D polygon geometry shared by the scene loader's validation and the meshers.
// A Ring2 is a closed polygon: points in order, the edge from the last point back to the
// first is implied, no point repeated at the end.
#pragma once

#include "util/fast_atan2.h"

#include <glm/vec2.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace mesher {

using Vec2 = glm::dvec2;
using Ring2 = std::vector<Vec2>;

// Twice the signed area of triangle (a, b, c): positive when counter-clockwise.
inline double orient2(Vec2 a, Vec2 b, Vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The angle at `at` between the directions to `prev` and `next`, in degrees.
inline double cornerAngleDeg(Vec2 prev, Vec2 at, Vec2 next) {
  const Vec2 u = prev - at, v = next - at;
  return util::fastAtan2(std::abs(u.x * v.y - u.y * v.x), u.x * v.x + u.y * v.y) * (180 / std::numbers::pi);
}

// Signed area of a ring: positive when counter-clockwise.
double signedArea(const Ring2& ring);

// Area centroid of a ring with non-zero area.
Vec2 centroid(const Ring2& ring);

// Largest coordinate extent of the ring's bounding box; 0 for an empty ring.
double extent(const Ring2& ring);

// True when the ring turns one way only, once around: no reflex corner and no edge folding back
// along the one before. Collinear corners are allowed, and so are corners turning the wrong way
// by less than `tolerance` (the sine of the turn: rounding of collinear points). Needs at least 3
// points and non-zero area to be meaningful (checked separately).
bool isConvex(const Ring2& ring, double tolerance = 1e-6);

// True when no two non-adjacent edges of the ring touch and no edge has zero length.
bool isSimple(const Ring2& ring);

// True when p lies strictly inside the convex ring (either winding), at least `margin` away
// from every edge line.
bool strictlyInsideConvex(const Ring2& convex, Vec2 p, double margin);

// Even-odd point-in-polygon test for a simple ring; points on the boundary give either answer.
bool containsPoint(const Ring2& ring, Vec2 p);

// Whether segments [a, b] and [c, d] share a point: they cross, or one's end lies on the other
// (touching, or overlapping along one line), as the orientations of their ends say.
bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// Distance between segments [a, b] and [c, d]; 0 when they intersect.
double segmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// Smallest distance between the boundaries of two rings; 0 when they touch or cross.
double boundaryDistance(const Ring2& r, const Ring2& s);

}  // namespace mesher
