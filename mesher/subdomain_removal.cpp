#include "mesher/subdomain_removal.h"

#include "mesher/triangulate.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

namespace mesher {

namespace {

void earClipAndMerge(const std::vector<Vec2>& ring, double rounding, std::vector<RingElement>& out) {
  const auto triangles = triangulate({ring, {}});
  std::vector<bool> used(triangles.size(), false);
  // Triangles sharing an edge (one runs it forward, the other backward).
  std::map<std::pair<uint32_t, uint32_t>, size_t> byEdge;
  for (size_t t = 0; t < triangles.size(); ++t)
    for (size_t k = 0; k < 3; ++k) byEdge[{triangles[t][k], triangles[t][(k + 1) % 3]}] = t;
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (used[t]) continue;
    bool merged = false;
    for (size_t k = 0; k < 3 && !merged; ++k) {
      const uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3], c = triangles[t][(k + 2) % 3];
      const auto other = byEdge.find({b, a});
      if (other == byEdge.end() || used[other->second] || other->second == t) continue;
      const auto& u = triangles[other->second];
      const uint32_t d = u[0] != a && u[0] != b ? u[0] : u[1] != a && u[1] != b ? u[1] : u[2];
      if (!strictlyConvexQuad(ring[a], ring[d], ring[b], ring[c], rounding)) continue;
      out.push_back({{a, d, b, c}, 4});
      used[t] = used[other->second] = true;
      merged = true;
    }
    if (!merged) {
      out.push_back({{triangles[t][0], triangles[t][1], triangles[t][2], 0}, 3});
      used[t] = true;
    }
  }
}

}  // namespace

bool RingBoundary::onBoundary(const std::vector<Vec2>& ring, size_t i) const {
  if (i + 1 < pathPoints) return true;
  const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
  return ((openSides & 1) && a.x == x0 && b.x == x0) || ((openSides & 2) && a.x == x0 + size && b.x == x0 + size) ||
         ((openSides & 4) && a.y == y0 && b.y == y0) || ((openSides & 8) && a.y == y0 + size && b.y == y0 + size);
}

template <class ConvexAt>
void SubdomainRemover::mergeRun(uint32_t hinge, size_t length, ConvexAt convexAt) {
  const uint32_t* run = run_.data();
  size_t i = 0;
  while (i + 1 < length) {
    const uint32_t a = run[i], b = run[i + 1];
    if (i + 2 < length && convexAt(i)) {
      trial_.push_back({{hinge, a, b, run[i + 2]}, 4});
      i += 2;
      continue;
    }
    trial_.push_back({{hinge, a, b, 0}, 3});
    i += 1;
  }
}

// The fans below write their runs into run_, sized beforehand, through a pointer: every ring
// searched tries them from each of its points.
bool SubdomainRemover::fanFromHinge(const std::vector<Vec2>& points, size_t ringSize, size_t hinge) {
  const size_t n = ringSize;
  const auto h = static_cast<uint32_t>(hinge);
  const Vec2* p = points.data();
  trial_.clear();
  run_.resize(n);
  uint32_t* run = run_.data();
  auto convexAt = [&](size_t i) { return strictlyConvexQuad(p[h], p[run[i]], p[run[i + 1]], p[run[i + 2]], rounding_); };
  size_t length = 0;
  for (size_t k = 1; k < n; ++k) {
    const auto i = static_cast<uint32_t>((hinge + k) % n);
    if (p[i] == p[h]) {  // the region is pinched here: a new run starts
      mergeRun(h, length, convexAt);
      length = 0;
      continue;
    }
    if (length > 0 && !turnsLeft(p[run[length - 1]], p[i], p[h], rounding_)) return false;
    run[length++] = i;
  }
  mergeRun(h, length, convexAt);
  return true;
}

bool SubdomainRemover::insideSeesRing(const std::vector<Vec2>& points, size_t ringSize) {
  const size_t n = ringSize;
  const Vec2* p = points.data();
  insideQuad_.resize(n);
  insideScore_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    if (!turnsLeft(p[i], p[(i + 1) % n], p[n], rounding_)) return false;
    const auto h = static_cast<uint32_t>(n), a = static_cast<uint32_t>(i), b = static_cast<uint32_t>((i + 1) % n),
               c = static_cast<uint32_t>((i + 2) % n);
    insideQuad_[i] = strictlyConvexQuad(p[n], p[a], p[b], p[c], rounding_);
    insideScore_[i][0] = elementScore({{h, a, b, 0}, 3});
    insideScore_[i][1] = insideQuad_[i] ? elementScore({{h, a, b, c}, 4}) : 0;
  }
  return true;
}

void SubdomainRemover::fanFromInside(size_t ringSize, size_t start) {
  const size_t n = ringSize;
  trial_.clear();
  run_.resize(n + 1);
  uint32_t* run = run_.data();
  for (size_t k = 0; k <= n; ++k) run[k] = static_cast<uint32_t>((start + k) % n);
  mergeRun(static_cast<uint32_t>(n), n + 1, [&](size_t i) { return insideQuad_[run[i]] != 0; });
}

bool SubdomainRemover::trialReachesBound() const {
  for (const RingElement& e : trial_)
    for (uint8_t k = 0; k < e.count; ++k) {
      const uint32_t at = e.v[k];
      const Vec2 u = shaped_[e.v[(k + e.count - 1) % e.count]] - shaped_[at], v = shaped_[e.v[(k + 1) % e.count]] - shaped_[at];
      const double dot = glm::dot(u, v);
      if (dot > 0 && std::abs(u.x * v.y - u.y * v.x) < tanReach_[at] * dot * (1 - 1e-12)) return false;
    }
  return true;
}

double SubdomainRemover::elementScore(const RingElement& e) const {
  double worst = std::numeric_limits<double>::infinity();
  for (uint8_t k = 0; k < e.count; ++k) {
    const uint32_t at = e.v[k];
    if (reach_[at] <= 0) continue;
    const double angle = cornerAngleDeg(shaped_[e.v[(k + e.count - 1) % e.count]], shaped_[at], shaped_[e.v[(k + 1) % e.count]]);
    worst = std::min(worst, angle / reach_[at]);
  }
  return worst;
}

double SubdomainRemover::score(double cutoff) const {
  double worst = std::numeric_limits<double>::infinity();
  for (const RingElement& e : trial_) {
    worst = std::min(worst, elementScore(e));
    if (worst <= cutoff) return worst;
  }
  return worst;
}

double SubdomainRemover::insideFanScore() const {
  double worst = std::numeric_limits<double>::infinity();
  for (const RingElement& e : trial_) worst = std::min(worst, insideScore_[e.v[1]][e.count == 4 ? 1 : 0]);
  return worst;
}

void SubdomainRemover::shape(size_t n, Vec2 shapeScale) {
  // Angles are judged with the ring scaled to its true proportions.
  shaped_.resize(points_.size());
  for (size_t i = 0; i < points_.size(); ++i) shaped_[i] = points_[i] * shapeScale;
  // What each ring corner's elements can reach: the bound, or the ring's own angle where
  // sharper; as a tangent for the quick test, in degrees for scores. Written through pointers
  // with each corner's neighbours carried along: this runs for every ring searched.
  static const double kTanBound = std::tan(kAngleBoundDeg * std::numbers::pi / 180);
  reach_.resize(n + 1);
  tanReach_.resize(n + 1);
  const Vec2* shaped = shaped_.data();
  double* reach = reach_.data();
  double* tanReach = tanReach_.data();
  reach[n] = kAngleBoundDeg;
  tanReach[n] = kTanBound;
  Vec2 prev = shaped[n - 1], at = shaped[0];
  for (size_t i = 0; i < n; ++i) {
    const Vec2 next = shaped[i + 1 < n ? i + 1 : 0];
    const Vec2 u = prev - at, v = next - at;
    const double dot = glm::dot(u, v), turn = v.x * u.y - v.y * u.x;  // > 0: a convex corner
    const bool sharp = turn > 0 && dot > 0 && turn < kTanBound * dot;
    tanReach[i] = sharp ? turn / dot : kTanBound;
    reach[i] = sharp ? cornerAngleDeg(prev, at, next) : kAngleBoundDeg;
    prev = at;
    at = next;
  }
}

double SubdomainRemover::search(size_t n, int preferredHinge, bool hasInner, Vec2 shapeScale, bool hinges) {
  shape(n, shapeScale);
  // Good sets beat the rest; among good ones the fewest elements win, among the rest a clearly
  // better score (or as good a one with fewer elements). The thesis' hinge goes first, so it
  // wins ties. No fan has fewer elements than the n - 2 triangles of a hinge merged in pairs:
  // a good set that small ends the search.
  best_.clear();
  double bestScore = -1;
  const size_t fewest = (n - 1) / 2;
  auto done = [&] { return bestScore >= 1 && (firstGood_ || best_.size() <= fewest); };
  auto consider = [&](bool fanned, bool aroundInner) {
    const size_t count = trial_.size();
    if (!fanned || (bestScore >= 1 && count > best_.size())) return;
    // Only asked whether some set is good: the first one ends the search, no score is needed.
    if (firstGood_) {
      if (trialReachesBound()) best_.swap(trial_), bestScore = 1;
      return;
    }
    // The first good set of the fewest elements ends the search: its score is not needed.
    if (best_.empty() && count <= fewest && trialReachesBound()) {
      best_.swap(trial_), bestScore = 1;
      return;
    }
    // A trial scoring at most `cutoff` loses to best_ (the rule below), so its scan of the
    // corners may stop there: the worst found so far already rules it out.
    double cutoff = -std::numeric_limits<double>::infinity();
    if (!best_.empty()) {
      const double belowGood = std::nextafter(1.0, 0.0);
      if (bestScore >= 1) cutoff = count < best_.size() ? belowGood : bestScore;
      else cutoff = std::min(belowGood, count < best_.size() ? bestScore - 0.05 : bestScore + 0.05);
    }
    const double s = aroundInner ? insideFanScore() : score(cutoff);
    bool better = best_.empty();
    if (!better) {
      const bool good = s >= 1, bestGood = bestScore >= 1;
      if (good != bestGood) better = good;
      else if (good) better = count < best_.size() || (count == best_.size() && s > bestScore);
      else better = s > bestScore + 0.05 || (s > bestScore - 0.05 && count < best_.size());
    }
    if (better) best_.swap(trial_), bestScore = s;
  };
  if (hinges && preferredHinge >= 0) consider(fanFromHinge(points_, n, static_cast<size_t>(preferredHinge)), false);
  for (size_t h = 0; hinges && h < n && !done(); ++h)
    if (static_cast<int>(h) != preferredHinge) consider(fanFromHinge(points_, n, h), false);
  if (hasInner && insideSeesRing(points_, n))
    for (size_t start = 0; start < n && !done(); ++start) fanFromInside(n, start), consider(true, true);
  return bestScore;
}

double SubdomainRemover::attempt(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
                                 const RingBoundary* boundary, bool innerMoved) {
  const size_t n = ring.size();
  points_.assign(ring.begin(), ring.end());
  if (inner) points_.push_back(*inner);
  origin_.resize(points_.size());
  for (size_t i = 0; i < points_.size(); ++i) origin_[i] = i < n ? static_cast<int>(i) : -1;
  const double plain = search(n, preferredHinge, inner != nullptr, shapeScale, !innerMoved);
  if (plain >= 1 || !boundary || !boundary->any()) return plain;

  // Falling short, the ring may gain points on its edges along the polygon's boundary (nothing
  // lies across them, so they make no T-vertex): the feet of the other points, so that a thin
  // strip along an edge splits into pieces across it instead of slivers along it. Every foot
  // first; failing that, each foot alone (another one can leave a sliver beside it).
  save(plain_, plain);
  double bestScore = plain;
  bool augmentedBetter = false;
  const size_t feet = augment(ring, *boundary, inner, shapeScale, -1);
  for (int only = -1; only < static_cast<int>(feet > 1 && !innerMoved ? feet : 0) && bestScore < 1; ++only) {
    if (only >= 0) augment(ring, *boundary, inner, shapeScale, only);
    const size_t m = points_.size() - (inner ? 1 : 0);
    int hinge = -1;
    for (size_t i = 0; i < m && preferredHinge >= 0; ++i)
      if (origin_[i] == preferredHinge) hinge = static_cast<int>(i);
    const double augmented = feet > 0 ? search(m, hinge, inner != nullptr, shapeScale, !innerMoved) : -1;
    if (augmented >= 1 || augmented > bestScore + 0.05) {
      bestScore = augmented;
      save(augmented_, augmented);
      augmentedBetter = true;
    }
  }
  return load(augmentedBetter ? augmented_ : plain_);
}

bool SubdomainRemover::partitionReaches(const std::vector<Vec2>& ring, const Vec2* inner, Vec2 shapeScale,
                                        const RingBoundary* boundary, bool noFan) {
  // The ring as it is, then with every foot on its boundary edges.
  const bool withFeet = boundary && boundary->any();
  for (int feet = 0; feet < (withFeet ? 2 : 1); ++feet) {
    if (feet == 0) {
      points_.assign(ring.begin(), ring.end());
      origin_.resize(ring.size());
      for (size_t i = 0; i < ring.size(); ++i) origin_[i] = static_cast<int>(i);
    } else if (augment(ring, *boundary, inner, shapeScale, -1) == 0) {
      break;
    }
    const size_t n = points_.size() - (feet == 1 && inner ? 1 : 0);
    shape(n, shapeScale);
    ringOnly_.assign(points_.begin(), points_.begin() + static_cast<std::ptrdiff_t>(n));
    trial_.clear();
    const double score = partition_.partition(ringOnly_, shaped_, reach_, trial_, rounding_);
    // A ring no point sees whole takes the best partition even when it falls short.
    if (score >= 1 || (noFan && feet == 0 && score >= 0)) {
      best_.swap(trial_);
      score_ = score;
      return true;
    }
  }
  return false;
}

void SubdomainRemover::mesh(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
                            std::vector<RingElement>& out, const RingBoundary* boundary, double rounding) {
  rounding_ = rounding;
  score_ = attempt(ring, preferredHinge, inner, shapeScale, boundary);
  // Still short, or no fan at all: pieces around several points (ConvexPartition). Asked only
  // whether some set reaches the bound, this goes first: it settles most rings at once.
  auto partition = [&] {
    if (score_ >= 1) return;
    save(stage_, score_);
    if (!partitionReaches(ring, inner, shapeScale, boundary, best_.empty())) score_ = load(stage_);
  };
  if (firstGood_) partition();
  // Still short, the inner point may sit elsewhere: in line with a ring point across or along
  // the region (a thin strip beside a point close to its corner is cut square there, and the
  // inner point's foot on the boundary splits the strip).
  if (score_ < 1 && inner && boundary && innerMayMove_) {
    candidates_.clear();
    for (const Vec2& p : ring)
      for (const Vec2& c : {Vec2{p.x, inner->y}, Vec2{inner->x, p.y}})
        if (c != *inner && std::find(candidates_.begin(), candidates_.end(), c) == candidates_.end() && containsPoint(ring, c))
          candidates_.push_back(c);
    for (size_t i = 0; i < candidates_.size() && score_ < 1; ++i) {
      save(stage_, score_);
      const double s = attempt(ring, preferredHinge, &candidates_[i], shapeScale, boundary, true);
      if (s >= 1) {
        score_ = s;
        continue;
      }
      score_ = load(stage_);
    }
  }
  if (!firstGood_) partition();
  // The dearest step, for the few rings all else leaves short. Not when only asked whether some
  // set reaches the bound: the quality refiner splits such leaves first, which costs fewer elements.
  if (!firstGood_ && score_ < 1) cutAndFan(ring, shapeScale);
  if (!best_.empty()) {
    out.insert(out.end(), best_.begin(), best_.end());
    return;
  }
  score_ = -1;
  if (firstGood_) return;  // reachesBound asks only whether some set reaches the bound: none did
  points_.assign(ring.begin(), ring.end());
  origin_.resize(ring.size());
  for (size_t i = 0; i < ring.size(); ++i) origin_[i] = static_cast<int>(i);
  earClipAndMerge(ring, rounding_, out);
}

void SubdomainRemover::save(Solution& to, double score) const {
  to.elements.assign(best_.begin(), best_.end());
  to.points.assign(points_.begin(), points_.end());
  to.origin.assign(origin_.begin(), origin_.end());
  to.score = score;
}

double SubdomainRemover::load(Solution& from) {
  best_.swap(from.elements);
  points_.swap(from.points);
  origin_.swap(from.origin);
  return from.score;
}

double SubdomainRemover::fanSide(const std::vector<Vec2>& side, Vec2 shapeScale, Solution& into) {
  save(into, attempt(side, -1, nullptr, shapeScale, nullptr));
  if (into.score >= 1 && into.elements.size() <= (side.size() - 1) / 2) return into.score;  // none has fewer
  // Points of its own: a grid over the side, and the apexes of triangles on its edges, right-angled
  // and equilateral (a short edge far from the grid's points wants a point close to it).
  candidates_.clear();
  Vec2 low = side[0], high = side[0];
  for (const Vec2& p : side) low = glm::min(low, p), high = glm::max(high, p);
  constexpr int kGrid = 8;
  for (int gx = 0; gx < kGrid; ++gx)
    for (int gy = 0; gy < kGrid; ++gy) candidates_.push_back(low + (high - low) * Vec2{(gx + 0.5) / kGrid, (gy + 0.5) / kGrid});
  for (size_t i = 0; i < side.size(); ++i) {
    const Vec2 a = side[i] * shapeScale, d = side[(i + 1) % side.size()] * shapeScale - a;
    const Vec2 inward{-d.y, d.x};  // the ring is counter-clockwise
    for (double height : {0.5, std::numbers::sqrt3 / 2}) candidates_.push_back((a + 0.5 * d + height * inward) / shapeScale);
  }
  for (const Vec2& at : candidates_) {
    if (cutAttemptsLeft_ == 0) break;
    if (!containsPoint(side, at)) continue;
    --cutAttemptsLeft_;
    const double s = attempt(side, -1, &at, shapeScale, nullptr, true);
    const bool better = s >= 1 ? into.score < 1 || best_.size() < into.elements.size() : s > into.score;
    if (better) save(into, s);
  }
  return into.score;
}

void SubdomainRemover::cutAndFan(const std::vector<Vec2>& ring, Vec2 shapeScale) {
  const size_t n = ring.size();
  save(stage_, score_);
  cut_.score = -1;
  cutAttemptsLeft_ = kCutAndFanAttempts;
  // Fans the sides, the first from ring point i to j, the second (when `cut`) from j round to i,
  // and keeps them in cut_ when both reach the bound with fewer elements than any before.
  auto consider = [&](size_t i, size_t j, bool cut) {
    const size_t sizes[2] = {cut ? j - i + 1 : n, n - (j - i) + 1};
    size_t count = 0;
    for (int s = 0; s < (cut ? 2 : 1); ++s) {
      side_.clear();
      for (size_t k = 0; k < sizes[s]; ++k) side_.push_back(ring[((s == 0 ? i : j) + k) % n]);
      if (fanSide(side_, shapeScale, cutSides_[s]) < 1) return;
      count += cutSides_[s].elements.size();
    }
    if (cut_.score >= 1 && count >= cut_.elements.size()) return;
    cut_.elements.clear();
    cut_.points.assign(ring.begin(), ring.end());
    cut_.origin.resize(n);
    for (size_t k = 0; k < n; ++k) cut_.origin[k] = static_cast<int>(k);
    cut_.score = 1;
    for (int s = 0; s < (cut ? 2 : 1); ++s) {
      const Solution& side = cutSides_[s];
      // A side's point k is the ring's (first + k) or a point of its own, appended.
      cutIndex_.resize(side.points.size());
      for (size_t k = 0; k < side.points.size(); ++k) {
        if (side.origin[k] >= 0) {
          cutIndex_[k] = static_cast<uint32_t>(((s == 0 ? i : j) + static_cast<size_t>(side.origin[k])) % n);
          continue;
        }
        cutIndex_[k] = static_cast<uint32_t>(cut_.points.size());
        cut_.points.push_back(side.points[k]);
        cut_.origin.push_back(-1);
      }
      for (RingElement e : side.elements) {
        for (uint8_t k = 0; k < e.count; ++k) e.v[k] = cutIndex_[e.v[k]];
        cut_.elements.push_back(e);
      }
    }
  };
  consider(0, 0, false);  // no cut: the whole ring around a point of its own
  auto angle = [&](size_t prev, size_t at, size_t next) {
    return cornerAngleDeg(ring[prev] * shapeScale, ring[at] * shapeScale, ring[next] * shapeScale);
  };
  for (size_t i = 0; i < n && cutAttemptsLeft_ > 0; ++i)
    for (size_t j = i + 2; j < n && cutAttemptsLeft_ > 0; ++j) {
      if ((i == 0 && j == n - 1) || !isDiagonal(ring, i, j)) continue;
      // A cut must not make a corner sharper than the bound.
      if (std::min({angle(j, i, i + 1), angle(j - 1, j, i), angle(i, j, (j + 1) % n), angle((i + n - 1) % n, i, j)}) >=
          kAngleBoundDeg)
        consider(i, j, true);
    }
  score_ = load(cut_.score >= 1 ? cut_ : stage_);
}

bool SubdomainRemover::reachesBound(const std::vector<Vec2>& ring, int preferredHinge, const Vec2* inner, Vec2 shapeScale,
                                    const RingBoundary* boundary, bool innerMayMove, double rounding) {
  firstGood_ = true;
  innerMayMove_ = innerMayMove;
  unused_.clear();
  mesh(ring, preferredHinge, inner, shapeScale, unused_, boundary, rounding);
  firstGood_ = false;
  innerMayMove_ = true;
  return score_ >= 1;
}

size_t SubdomainRemover::augment(const std::vector<Vec2>& ring, const RingBoundary& boundary, const Vec2* inner,
                                 Vec2 shapeScale, int only) {
  const size_t n = ring.size();
  points_.clear();
  origin_.clear();
  size_t found = 0;
  std::vector<double>& feet = feet_;
  for (size_t i = 0; i < n; ++i) {
    points_.push_back(ring[i]);
    origin_.push_back(static_cast<int>(i));
    if (!boundary.onBoundary(ring, i)) continue;
    // Feet on the boundary edge ring[i] -> ring[next], judged in true proportions.
    const size_t next = (i + 1) % n;
    const Vec2 a = ring[i] * shapeScale, ab = ring[next] * shapeScale - a;
    const double length2 = glm::dot(ab, ab);
    feet.clear();
    for (size_t j = 0; j <= n; ++j) {
      if (j == i || j == next || length2 == 0 || (j == n && !inner)) continue;
      const Vec2 ap = (j < n ? ring[j] : *inner) * shapeScale - a;
      const double t = glm::dot(ap, ab) / length2;
      // A foot nearer an end of the edge than a third of the point's distance from it would
      // leave a sliver between them. Beyond that it may be as near the end as it comes (a
      // crossing a hair from a T-vertex wants a tiny triangle cut off), but not on it.
      const double fromEnd = std::min(t, 1 - t) * std::sqrt(length2), distance = std::abs(ap.x * ab.y - ap.y * ab.x) / std::sqrt(length2);
      if (fromEnd > 0.34 * distance && fromEnd > 1e-6 * std::sqrt(length2)) feet.push_back(t);
    }
    std::sort(feet.begin(), feet.end());
    feet.erase(std::unique(feet.begin(), feet.end(), [](double s, double t) { return t - s < 0.05; }), feet.end());
    for (double t : feet) {
      if (only < 0 || static_cast<size_t>(only) == found) {
        points_.push_back(ring[i] + t * (ring[next] - ring[i]));
        origin_.push_back(-1);
      }
      ++found;
    }
  }
  if (inner) points_.push_back(*inner), origin_.push_back(-1);
  return found;
}

}  // namespace mesher
