// The best partition of a small ring into convex triangles and quadrilaterals with corners at
// its points, by dynamic programming over chords (Klincsek's scheme for optimal polygon
// triangulations, with four-cornered pieces too). Subdomain removal (5.4) fans every piece out
// from one point; a thin strip with a point near one end needs pieces around several.
#pragma once

#include "mesher/polygon.h"

#include <glm/geometric.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace mesher {

// Sine of a turn at or below which a corner is a sliver or straight.
inline constexpr double kMinTurnSine = 1e-9;

// Whether a turn (orient2 of a -> b -> c, with |ab|^2 and |bc|^2) is left by more than a sliver
// (no 180-degree corners), and by more than moving each point by `rounding` could undo
// (TreeFrame::rounding): points computed on one input edge lie that far off its line, and the
// turn three of them make may be the other way in the plane. Squared, so no square root: turn >
// kMinTurnSine |ab| |bc|, and turn > 2 sqrt(2) rounding sqrt(|ab|^2 + |bc|^2), which bounds how far
// the moves change it.
inline bool turnsPast(double turn, double ab2, double bc2, double rounding) {
  return turn > 0 && turn * turn > kMinTurnSine * kMinTurnSine * ab2 * bc2 && turn * turn > 8 * rounding * rounding * (ab2 + bc2);
}
// Inline: fans test every corner they make.
inline bool turnsLeft(Vec2 a, Vec2 b, Vec2 c, double rounding = 0) {
  const Vec2 ab = b - a, bc = c - b;
  return turnsPast(orient2(a, b, c), glm::dot(ab, ab), glm::dot(bc, bc), rounding);
}
inline bool strictlyConvexQuad(Vec2 a, Vec2 b, Vec2 c, Vec2 d, double rounding = 0) {
  return turnsLeft(a, b, c, rounding) && turnsLeft(b, c, d, rounding) && turnsLeft(c, d, a, rounding) && turnsLeft(d, a, b, rounding);
}

// Whether the chord between ring points i and j (not neighbours) runs inside the simple
// counter-clockwise ring, touching it nowhere else: a diagonal that cuts it in two.
bool isDiagonal(const std::vector<Vec2>& ring, size_t i, size_t j);

// Three or four indices into a ring, counter-clockwise.
struct RingElement {
  std::array<uint32_t, 4> v{};
  uint8_t count = 0;
};

class ConvexPartition {
 public:
  // Partitions the simple counter-clockwise ring `points` (shapes judged there: collinear grid
  // points are exact in tree coordinates) into strictly convex pieces. The score of a piece is
  // its worst corner angle, measured on `shaped` (the ring in true proportions), over what that
  // corner can reach (`reach`, degrees); a partition's is its worst piece's. The best partition
  // wins, and among those scoring 1 or more the one with fewest pieces. Appends it to `out` and
  // returns its score, or returns -1 when the ring has no such partition. Cost grows with the
  // fourth power of the ring's size: meant for the few rings fans leave short. Pieces' corners
  // turn by more than `rounding` can undo, as turnsLeft's.
  double partition(const std::vector<Vec2>& points, const std::vector<Vec2>& shaped, const std::vector<double>& reach,
                   std::vector<RingElement>& out, double rounding = 0);

 private:
  struct Best {
    double score = -1;  // -1: no partition
    uint32_t count = 0;
    // The piece on the sub-ring's closing chord: its corners between the chord's ends.
    uint32_t a = 0, b = 0;  // b == a: a triangle
  };
  void emit(size_t i, size_t j, std::vector<RingElement>& out) const;

  size_t n_ = 0;
  std::vector<uint8_t> chord_;  // n x n: ring edge or inner diagonal
  std::vector<Best> best_;      // n x n, for i < j: the sub-ring i, i + 1, ..., j
  std::vector<double> length2_;  // n x n: squared distances between ring points
};

}  // namespace mesher
