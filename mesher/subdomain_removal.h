// Meshing one leaf's region by subdomain removal (thesis 5.4): convex quadrilaterals and
// triangles that all share a hinge vertex, quadrilaterals preferred. Interior squares use the
// same procedure over every hinge, which yields the templates of 5.3. Beyond the thesis, a
// region no such fan meshes within the angle bound takes points on its boundary, another inner
// point, pieces around several points, or a cut in two with a point of its own in each side.
#pragma once

#include "mesher/convex_partition.h"
#include "mesher/mesher.h"
#include "mesher/polygon.h"

#include <array>
#include <cstdint>
#include <vector>

namespace mesher {

// Which edges of a leaf's ring (ring[i] -> ring[i + 1], the last back to the first) lie on the
// polygon's boundary, where points may be added without making a T-vertex: the path's (the
// ring's first pathPoints points run along input edges), and those along an open side of the
// leaf square, across which there is no inside (the root's border, or only leaves outside the
// polygon). Worked out edge by edge only for the few rings that need points added.
struct RingBoundary {
  size_t pathPoints = 0;
  int openSides = 0;  // bits: 1 west, 2 east, 4 south, 8 north
  double x0 = 0, y0 = 0, size = 0;  // the leaf square, tree coordinates
  bool any() const { return pathPoints >= 2 || openSides != 0; }
  bool onBoundary(const std::vector<Vec2>& ring, size_t i) const;
};

// Meshes leaf rings by subdomain removal. Among the fans from each hinge and, when `inner` is
// given (a point inside the ring, index ring.size() in the elements), the fans around it, it
// takes one whose angles all reach kAngleBoundDeg (or the ring's own corner there, when that is
// sharper) with the fewest elements; when none does, it goes on beyond the thesis (see mesh())
// and, failing everything, keeps the fan closest to the bound. `preferredHinge`, the rule of
// 5.4, wins ties. A ring that neither a fan, a partition nor a cut meshes (pinched at a point) is ear
// clipped, triangle pairs merged into convex quads. Shapes are judged on `ring` (tree
// coordinates, where collinear grid points are exact), angles on the ring scaled by
// `shapeScale` (plane units per tree unit on each axis); corners turn by more than `rounding`
// can undo (turnsLeft; TreeFrame::rounding). Scratch memory is kept from ring to ring.
class SubdomainRemover {
 public:
  // `boundary`, when given: which ring edges lie on the polygon's boundary (LeafRegion's). Where
  // no fan reaches the bound, points may then be added on them and the inner point may move;
  // and pieces may gather around several points (ConvexPartition). Elements index points(), and
  // ringIndexOf() tells which of them are ring points.
  void mesh(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
            std::vector<RingElement>& out, const RingBoundary* boundary = nullptr, double rounding = 0);
  // The points the last mesh() call's elements index (tree coordinates): the ring with any
  // added points in order, then the inner point; or, after a cut, the ring and then each side's
  // point of its own.
  const std::vector<Vec2>& points() const { return points_; }
  // Which ring point points()[i] is, or -1 for the inner point or an added one.
  int ringIndexOf(size_t i) const { return origin_[i]; }
  // Whether the last mesh() call's elements reach kAngleBoundDeg at every corner (or the ring's
  // own corner there, when that is sharper).
  bool reachedBound() const { return score_ >= 1; }
  // Whether mesh() would give elements that reach kAngleBoundDeg at every corner (or the ring's
  // own corner there, when that is sharper), short of its last step (cutAndFan); quicker than
  // mesh(), as it stops at the first set that does. `innerMayMove` false leaves out the next
  // dearest step, moving the inner point.
  bool reachesBound(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
                    const RingBoundary* boundary = nullptr, bool innerMayMove = true, double rounding = 0);

 private:
  // Fans `points` (a ring, with the inner point appended when there is one) out from
  // points[hinge], merging neighbouring fan triangles into strictly convex quadrilaterals, first
  // come first served, into trial_. False when some fan triangle would have no area (a ring
  // point hidden from the hinge, or in line with it and a neighbour: a T-vertex). Points equal
  // to the hinge (a region pinched at its vertex) split the fan.
  bool fanFromHinge(const std::vector<Vec2>& points, size_t ringSize, size_t hinge);
  // Whether the inner point points[ringSize] sees every ring edge, which a fan around it needs
  // from whichever point it starts; if so, works out insideQuad_ and insideScore_ (shape() first).
  bool insideSeesRing(const std::vector<Vec2>& points, size_t ringSize);
  // Fans the ring around the inner point (insideSeesRing true), starting at ring[start], merged
  // as above, into trial_.
  void fanFromInside(size_t ringSize, size_t start);
  // The fan of run_'s first `length` points around point `hinge`, neighbouring triangles merged
  // where convexAt(i) says run_[i], run_[i + 1] and run_[i + 2] make a strictly convex
  // quadrilateral with it, into trial_.
  template <class ConvexAt>
  void mergeRun(uint32_t hinge, size_t length, ConvexAt convexAt);
  // The best fan of points_ (the first n a ring, then the inner point when `hasInner`) into
  // best_, from ring points too unless `hinges` is false; returns its score.
  double search(size_t n, int preferredHinge, bool hasInner, Vec2 shapeScale, bool hinges = true);
  // The best fan of `ring` around `inner` (see mesh()), with points added on the boundary
  // stretch when that does better: into best_, points_ and origin_; returns its score.
  // `innerMoved`: only the inner point differs from an attempt before, so the plain ring's
  // fans from its own points are not tried again.
  double attempt(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
                 const RingBoundary* boundary, bool innerMoved = false);
  // Partitions the ring, then the ring with the feet on its boundary edges, into convex pieces
  // (ConvexPartition); the first partition reaching the bound becomes best_ (with points_,
  // origin_ and score_ to match). When `noFan`, the plain ring's best partition does even if
  // it falls short. False when none did (points_ and origin_ are then overwritten).
  bool partitionReaches(const std::vector<Vec2>& ring, const Vec2* inner, Vec2 shapeScale,
                        const RingBoundary* boundary, bool noFan);
  // A set of elements with the points they index and its score, set aside while another is
  // tried: save() copies best_, points_ and origin_ into `to`; load() brings `from` back and
  // returns its score.
  struct Solution {
    std::vector<RingElement> elements;
    std::vector<Vec2> points;
    std::vector<int> origin;
    double score = -1;
  };
  void save(Solution& to, double score) const;
  double load(Solution& from);
  // Cuts the ring along one diagonal, or not at all, and meshes each side by a fan from one of
  // its points or around a point of its own inside it (see fanSide). For rings whose reflex
  // corner lies so near a leaf side, where no point may be added, that no fan or partition of
  // the ring's points reaches the bound. Takes the fewest elements that reach it (into best_,
  // points_, origin_ and score_); leaves all as it was when none does. Tries at most
  // kCutAndFanAttempts fans, taking the best of those.
  void cutAndFan(const std::vector<Vec2>& ring, Vec2 shapeScale);
  // Every diagonal of a ring of n points, each side fanned from up to 64 + 2n points, makes
  // about 130 n^3 fans: 30,000 for a fuzzed ring of 42 points (4 s under the sanitizers), where
  // the rings of the shipped scenes and the large models (up to 28 points) need at most 1,916.
  static constexpr size_t kCutAndFanAttempts = 4096;
  // The best fan of `side` (a ring) from its points or around a point inside it (a grid's, or an
  // apex of a triangle on one of its edges), into `into`; returns its score.
  double fanSide(const std::vector<Vec2>& side, Vec2 shapeScale, Solution& into);
  // Scales points_' first n (a ring) to true proportions into shaped_, and works out what
  // each corner can reach (reach_, tanReach_).
  void shape(size_t n, Vec2 shapeScale);
  // Rebuilds points_ and origin_ as `ring` with the feet of its points and `inner` on its
  // boundary edges (all of them, or only the one numbered `only`); returns how many feet there
  // are.
  size_t augment(const std::vector<Vec2>& ring, const RingBoundary& boundary, const Vec2* inner, Vec2 shapeScale,
                 int only);
  // How close trial_ comes to the bound: 1 or more when every angle reaches what it can. Stops
  // at the first corner that brings it to `cutoff` or below, returning that (not the score).
  double score(double cutoff) const;
  // The same for one element of trial_'s kind: its worst corner.
  double elementScore(const RingElement& e) const;
  // score() of a fan around the inner point, from insideScore_.
  double insideFanScore() const;
  // Whether trial_ reaches the bound at every corner (score() >= 1), without angles.
  bool trialReachesBound() const;

  std::vector<Vec2> points_, shaped_;
  std::vector<double> reach_, tanReach_;
  std::vector<uint32_t> run_;
  // Per ring point i, for fans around the inner point: whether it, ring[i], ring[i + 1] and
  // ring[i + 2] make a strictly convex quad; the scores of its triangle and quad from ring[i].
  std::vector<uint8_t> insideQuad_;
  std::vector<std::array<double, 2>> insideScore_;
  std::vector<int> origin_;
  std::vector<double> feet_;
  std::vector<RingElement> trial_, best_, unused_;
  std::vector<Vec2> candidates_;
  Solution plain_, augmented_, stage_;  // set aside: the plain ring's, the best with feet, a stage's
  Solution cutSides_[2], cut_;  // cutAndFan's: the two sides of a cut, the best cut's elements
  size_t cutAttemptsLeft_ = 0;  // cutAndFan's fans still allowed
  std::vector<Vec2> side_;
  std::vector<uint32_t> cutIndex_;
  std::vector<Vec2> ringOnly_;
  ConvexPartition partition_;
  double score_ = -1;       // the last mesh() call's: 1 or more when its elements reach the bound
  double rounding_ = 0;     // the mesh() call's
  bool innerMayMove_ = true;  // false only within a reachesBound call that says so
  bool firstGood_ = false;  // the search stops at the first set that reaches the bound
};

}  // namespace mesher
