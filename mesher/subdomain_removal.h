// Meshing one leaf's region by subdomain removal (thesis 5.4): convex quadrilaterals and
// triangles that all share a hinge vertex, quadrilaterals preferred. Interior squares use the
// same procedure over every hinge, which yields the templates of 5.3.
#pragma once

#include "mesher/mesher.h"
#include "mesher/polygon.h"

#include <array>
#include <cstdint>
#include <vector>

namespace mesher {

// Three or four indices into a ring, counter-clockwise.
struct RingElement {
  std::array<uint32_t, 4> v{};
  uint8_t count = 0;
};

// Meshes leaf rings by subdomain removal. Among the fans from each hinge and, when `inner` is
// given (a point inside the ring, index ring.size() in the elements), the fans around it, it
// takes one whose angles all reach kAngleBoundDeg (or the ring's own corner there, when that is
// sharper) with the fewest elements; when none does, the one closest to it. `preferredHinge`,
// the rule of 5.4, wins ties. A ring no point sees whole is ear clipped, triangle pairs merged
// into convex quads. Shapes are judged on `ring` (tree coordinates, where collinear grid points
// are exact), angles on the ring scaled by `shapeScale` (plane units per tree unit on each
// axis). Scratch memory is kept from ring to ring.
class SubdomainRemover {
 public:
  // `boundaryPoints`: the ring's first points run along the polygon's boundary (LeafRegion's
  // pathPoints). Where no fan reaches the bound, points may be added on that stretch: elements
  // then index points(), and ringIndexOf() tells which of them are ring points.
  void mesh(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
            std::vector<RingElement>& out, size_t boundaryPoints = 0);
  // The points the last mesh() call's elements index (tree coordinates): the ring with any
  // added points in order, then the inner point.
  const std::vector<Vec2>& points() const { return points_; }
  // Which ring point points()[i] is, or -1 for the inner point or an added one.
  int ringIndexOf(size_t i) const { return origin_[i]; }
  // Whether mesh() would give elements that reach kAngleBoundDeg at every corner (or the ring's
  // own corner there, when that is sharper); quicker than mesh(), as it stops at the first fan
  // that does.
  bool reachesBound(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
                    size_t boundaryPoints = 0);

 private:
  // Fans `points` (a ring, with the inner point appended when there is one) out from
  // points[hinge], merging neighbouring fan triangles into strictly convex quadrilaterals, first
  // come first served, into trial_. False when some fan triangle would have no area (a ring
  // point hidden from the hinge, or in line with it and a neighbour: a T-vertex). Points equal
  // to the hinge (a region pinched at its vertex) split the fan.
  bool fanFromHinge(const std::vector<Vec2>& points, size_t ringSize, size_t hinge);
  // Fans the ring around the inner point points[ringSize], starting at ring[start]; false when
  // the point does not see some ring edge.
  bool fanFromInside(const std::vector<Vec2>& points, size_t ringSize, size_t start);
  void mergeRun(const std::vector<Vec2>& points, uint32_t hinge);
  // The best fan of points_ (the first n a ring, then the inner point when `hasInner`) into
  // best_; returns its score.
  double search(size_t n, int preferredHinge, bool hasInner, Vec2 shapeScale);
  // Rebuilds points_ and origin_ as `ring` with the feet of its points on its boundary stretch
  // (all of them, or only the one numbered `only`); returns how many feet there are.
  size_t augment(const std::vector<Vec2>& ring, size_t boundaryPoints, const Vec2* inner, Vec2 shapeScale, int only);
  // How close trial_ comes to the bound: 1 or more when every angle reaches what it can.
  double score() const;
  // Whether trial_ reaches the bound at every corner (score() >= 1), without angles.
  bool trialReachesBound() const;

  std::vector<Vec2> points_, shaped_;
  std::vector<double> reach_, tanReach_;
  std::vector<uint32_t> run_;
  std::vector<int> origin_;
  std::vector<double> feet_;
  std::vector<RingElement> trial_, best_, kept_, unused_, augmentedBest_;
  std::vector<Vec2> augmentedPoints_;
  std::vector<int> augmentedOrigin_;
  double score_ = -1;       // the last mesh() call's: 1 or more when its elements reach the bound
  bool firstGood_ = false;  // the search stops at the first fan that reaches the bound
};

}  // namespace mesher
