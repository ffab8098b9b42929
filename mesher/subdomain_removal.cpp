#include "mesher/subdomain_removal.h"

#include "mesher/triangulate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace mesher {

namespace {

// A corner counts as turning when its sine exceeds this: no slivers, no 180-degree corners.
constexpr double kMinSine = 1e-9;

bool turnsLeft(Vec2 a, Vec2 b, Vec2 c) {
  const double lengths = glm::length(b - a) * glm::length(c - b);
  return lengths > 0 && orient2(a, b, c) > kMinSine * lengths;
}

bool strictlyConvexQuad(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return turnsLeft(a, b, c) && turnsLeft(b, c, d) && turnsLeft(c, d, a) && turnsLeft(d, a, b);
}

// Greedy merge of consecutive triangles of one fan run.
void mergeRun(const std::vector<Vec2>& ring, uint32_t hinge, const std::vector<uint32_t>& run,
              std::vector<RingElement>& out) {
  size_t i = 0;
  while (i + 1 < run.size()) {
    const uint32_t a = run[i], b = run[i + 1];
    if (i + 2 < run.size()) {
      const uint32_t c = run[i + 2];
      if (strictlyConvexQuad(ring[hinge], ring[a], ring[b], ring[c])) {
        out.push_back({{hinge, a, b, c}, 4});
        i += 2;
        continue;
      }
    }
    out.push_back({{hinge, a, b, 0}, 3});
    i += 1;
  }
}

void earClipAndMerge(const std::vector<Vec2>& ring, std::vector<RingElement>& out) {
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
      if (!strictlyConvexQuad(ring[a], ring[d], ring[b], ring[c])) continue;
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

double angleDeg(Vec2 prev, Vec2 at, Vec2 next) {
  const Vec2 u = prev - at, v = next - at;
  return std::atan2(std::abs(u.x * v.y - u.y * v.x), glm::dot(u, v)) * 180 / std::numbers::pi;
}

}  // namespace

double smallestAngleDeg(const std::vector<Vec2>& points, const RingElement& element) {
  double smallest = 180;
  for (uint8_t k = 0; k < element.count; ++k)
    smallest = std::min(smallest, angleDeg(points[element.v[(k + element.count - 1) % element.count]],
                                           points[element.v[k]], points[element.v[(k + 1) % element.count]]));
  return smallest;
}

bool fanFromHinge(const std::vector<Vec2>& ring, size_t hinge, std::vector<RingElement>& out) {
  const size_t n = ring.size();
  const auto h = static_cast<uint32_t>(hinge);
  std::vector<RingElement> elements;
  std::vector<uint32_t> run;
  for (size_t k = 1; k < n; ++k) {
    const auto i = static_cast<uint32_t>((hinge + k) % n);
    if (ring[i] == ring[h]) {  // the region is pinched here: a new run starts
      mergeRun(ring, h, run, elements);
      run.clear();
      continue;
    }
    if (!run.empty() && !turnsLeft(ring[run.back()], ring[i], ring[h])) return false;
    run.push_back(i);
  }
  mergeRun(ring, h, run, elements);
  out.insert(out.end(), elements.begin(), elements.end());
  return true;
}

void removeSubdomains(const std::vector<Vec2>& ring, int preferredHinge, Vec2 shapeScale, std::vector<RingElement>& out) {
  // Angles are judged with the ring scaled to its true proportions.
  std::vector<Vec2> shaped(ring);
  for (Vec2& p : shaped) p *= shapeScale;
  auto smallestAngle = [&](const std::vector<RingElement>& elements) {
    double angle = 180;
    for (const RingElement& e : elements) angle = std::min(angle, smallestAngleDeg(shaped, e));
    return angle;
  };
  // A hinge beats the best so far with a clearly larger smallest angle, or as large an angle
  // and fewer elements. The thesis' hinge goes first, so it wins ties.
  std::vector<RingElement> best, trial;
  double bestAngle = -1;
  auto consider = [&](size_t h) {
    trial.clear();
    if (!fanFromHinge(ring, h, trial)) return;
    const double angle = smallestAngle(trial);
    const bool better = best.empty() || angle > bestAngle + 1 ||
                        (angle > bestAngle - 1 && trial.size() < best.size());
    if (better) best = trial, bestAngle = angle;
  };
  if (preferredHinge >= 0) consider(static_cast<size_t>(preferredHinge));
  for (size_t h = 0; h < ring.size(); ++h)
    if (static_cast<int>(h) != preferredHinge) consider(h);
  if (!best.empty()) {
    out.insert(out.end(), best.begin(), best.end());
    return;
  }
  earClipAndMerge(ring, out);
}

}  // namespace mesher
