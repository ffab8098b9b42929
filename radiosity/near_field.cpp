#include "radiosity/near_field.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace radiosity {

namespace {

// Second moments of a convex polygon's area about `centre`, over its area, in the plane
// coordinates x, y: a fan of triangles, each contributing area / 12 (sum p p^T + s s^T) with
// s the sum of its corners p.
glm::dvec3 areaMoments(const Polygon3& p, const glm::dvec3& centre, const glm::dvec3& x, const glm::dvec3& y) {
  const auto at = [&](int k) { return glm::dvec2(glm::dot(p.v[k] - centre, x), glm::dot(p.v[k] - centre, y)); };
  glm::dvec3 sum{0};
  double total = 0;
  const glm::dvec2 a = at(0);
  for (int k = 1; k + 1 < p.n; ++k) {
    const glm::dvec2 b = at(k), c = at(k + 1), s = a + b + c;
    const double area = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    sum += area / 12 * glm::dvec3(a.x * a.x + b.x * b.x + c.x * c.x + s.x * s.x,
                                  a.x * a.y + b.x * b.y + c.x * c.y + s.x * s.y,
                                  a.y * a.y + b.y * b.y + c.y * c.y + s.y * s.y);
    total += area;
  }
  return total > 0 ? sum / total : glm::dvec3(0);
}

void addPoint(const glm::dvec3& point, const glm::dvec3& weight, const glm::dvec3& normal, const Receiver& r,
              glm::dvec3& front, glm::dvec3& back) {
  (glm::dot(r.normal, point) > r.offset ? front : back) += weight * pointToReceiver(point, normal, r);
}

}  // namespace

PatchTree buildPatchTree(std::span<uint32_t> elements, std::span<const Receiver> receivers, const glm::dvec3& x,
                         const glm::dvec3& y) {
  PatchTree tree;
  tree.x = x;
  tree.y = y;
  tree.z = glm::cross(x, y);
  const auto centroid = [&](uint32_t first, uint32_t last) {
    double a = 0;
    glm::dvec3 c{0};
    for (uint32_t k = first; k < last; ++k) {
      const Receiver& e = receivers[elements[k]];
      a += e.area, c += e.area * e.centre;
    }
    return c / a;
  };
  tree.origin = centroid(0, static_cast<uint32_t>(elements.size()));
  const auto planeOf = [&](uint32_t e) {
    const glm::dvec3 d = receivers[e].centre - tree.origin;
    return glm::dvec2(glm::dot(d, x), glm::dot(d, y));
  };
  const auto addNode = [&](uint32_t first, uint32_t last) {
    PatchTree::Node& n = tree.nodes.emplace_back();
    n.first = first;
    n.last = last;
    n.centre = centroid(first, last);
    n.low = glm::dvec3(INFINITY);
    n.high = glm::dvec3(-INFINITY);
    for (uint32_t k = first; k < last; ++k) {
      const Polygon3& p = receivers[elements[k]].polygon;
      for (int i = 0; i < p.n; ++i) {
        n.radius = std::max(n.radius, glm::length(p.v[i] - n.centre));
        const glm::dvec3 d = p.v[i] - tree.origin, local{glm::dot(d, x), glm::dot(d, y), glm::dot(d, tree.z)};
        n.low = glm::min(n.low, local);
        n.high = glm::max(n.high, local);
      }
    }
  };

  // Breadth first: a node's elements are reordered before any of its descendants exist.
  addNode(0, static_cast<uint32_t>(elements.size()));
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const uint32_t first = tree.nodes[i].first, last = tree.nodes[i].last;
    if (last - first < 2) continue;
    const glm::dvec3 d = tree.nodes[i].centre - tree.origin;
    const glm::dvec2 middle{glm::dot(d, x), glm::dot(d, y)};
    const auto quadrant = [&](uint32_t e) {
      const glm::dvec2 q = planeOf(e);
      return int(q.x >= middle.x) + 2 * int(q.y >= middle.y);
    };
    uint32_t* begin = elements.data() + first;
    uint32_t* end = elements.data() + last;
    std::stable_sort(begin, end, [&](uint32_t a, uint32_t b) { return quadrant(a) < quadrant(b); });
    std::vector<uint32_t> cuts{first};
    for (uint32_t k = first + 1; k < last; ++k)
      if (quadrant(elements[k]) != quadrant(elements[k - 1])) cuts.push_back(k);
    if (cuts.size() == 1) {
      std::stable_sort(begin, end, [&](uint32_t a, uint32_t b) { return planeOf(a).x < planeOf(b).x; });
      cuts.push_back(first + (last - first) / 2);
    }
    cuts.push_back(last);
    tree.nodes[i].child = static_cast<uint32_t>(tree.nodes.size());
    tree.nodes[i].children = static_cast<uint32_t>(cuts.size() - 1);
    for (size_t c = 0; c + 1 < cuts.size(); ++c) addNode(cuts[c], cuts[c + 1]);
  }

  for (uint32_t e : elements) {
    tree.plane.push_back(planeOf(e));
    tree.spread.push_back(areaMoments(receivers[e].polygon, receivers[e].centre, x, y));
  }
  return tree;
}

void lightPatchTree(const PatchTree& tree, std::span<const glm::dvec3> shares, std::vector<NodeLight>& out) {
  out.resize(tree.nodes.size());
  for (size_t n = 0; n < tree.nodes.size(); ++n) {
    const PatchTree::Node& node = tree.nodes[n];
    NodeLight& light = out[n];
    light.weight = glm::dvec3(0);
    light.sets = 1;
    for (int channel = 0; channel < 3; ++channel) {
      // Shares of both signs (unshot light left negative by overshooting or an edit) would put
      // the moments anywhere as they cancel: the points are where the light's magnitude is.
      double total = 0, magnitude = 0;
      glm::dvec2 first{0};
      glm::dvec3 second{0};
      for (uint32_t k = node.first; k < node.last; ++k) {
        const double w = shares[k][channel], m = std::abs(w);
        const glm::dvec2 p = tree.plane[k];
        total += w;
        magnitude += m;
        first += m * p;
        second += m * (glm::dvec3(p.x * p.x, p.x * p.y, p.y * p.y) + tree.spread[k]);
      }
      light.weight[channel] = total;
      if (!(magnitude > 0)) continue;
      const glm::dvec2 mean = first / magnitude;
      const glm::dvec3 c = second / magnitude - glm::dvec3(mean.x * mean.x, mean.x * mean.y, mean.y * mean.y);
      // The covariance's principal axes: a rectangle lit evenly gets its Gauss points.
      const double half = 0.5 * (c.x + c.z), difference = 0.5 * (c.x - c.z);
      const double root = std::sqrt(difference * difference + c.y * c.y);
      glm::dvec2 axis{difference + root, c.y};
      const double length = glm::length(axis);
      axis = length > 0 ? axis / length : glm::dvec2(0, 1);
      const double major = std::sqrt(std::max(half + root, 0.0)), minor = std::sqrt(std::max(half - root, 0.0));
      const glm::dvec3 u = major * (axis.x * tree.x + axis.y * tree.y), v = minor * (axis.x * tree.y - axis.y * tree.x);
      const glm::dvec3 m = tree.origin + mean.x * tree.x + mean.y * tree.y;
      light.mean[channel] = m;
      light.points[channel] = {m - u - v, m + u - v, m + u + v, m - u + v};
    }
    // The first lit channel's points serve all three when the others' lie within 2% of the node's
    // radius of them: the factor then moves by about that much over the distance, under 1% where
    // points are used. A colour that varies more across the node needs its own points.
    int lit = 0;
    while (lit < 2 && light.weight[lit] == 0.0) ++lit;
    light.mean[0] = light.mean[lit];
    light.points[0] = light.points[lit];
    const auto alike = [&](int channel) {
      if (light.weight[channel] == 0.0) return true;
      for (int k = 0; k < 4; ++k)
        if (glm::length(light.points[channel][k] - light.points[0][k]) > 0.02 * node.radius) return false;
      return glm::length(light.mean[channel] - light.mean[0]) <= 0.02 * node.radius;
    };
    light.sets = alike(1) && alike(2) ? 1 : 3;
  }
  // Top down: breadth-first order puts every node after its parent.
  if (!out.empty()) out[0].lit = out[0].weight != glm::dvec3(0);
  for (size_t n = 0; n < tree.nodes.size(); ++n)
    for (uint32_t c = tree.nodes[n].child; c < tree.nodes[n].child + tree.nodes[n].children; ++c)
      out[c].lit = out[n].lit && out[c].weight != glm::dvec3(0);
}

void planPatchToReceiver(const PatchTree& tree, std::span<const uint32_t> elements, std::span<const Receiver> receivers,
                         const glm::dvec3& normal, const Receiver& r, double farRatio, double ratio, int splits,
                         NearPlans& out) {
  const size_t steps = out.steps.size(), factors = out.factors.size();
  // Heights over r's plane in the tree's coordinates: at the origin, and per unit along each axis.
  const double originHeight = glm::dot(r.normal, tree.origin) - r.offset;
  const glm::dvec3 slope{glm::dot(r.normal, tree.x), glm::dot(r.normal, tree.y), glm::dot(r.normal, tree.z)};
  const auto visit = [&](const auto& self, uint32_t n) -> void {
    const PatchTree::Node& node = tree.nodes[n];
    if (node.children == 0) {
      double f = 0, b = 0;
      areaToPolygon(receivers[elements[node.first]], 1.0, normal, r, farRatio, ratio, splits, f, b);
      out.steps.push_back({n, NearStep::kElement});
      out.factors.emplace_back(f, b);
      return;
    }
    // A node that r's plane cuts sees r's front from one part and its back from the other: the
    // factor has a kink there that a few points would smooth over.
    const double distance = glm::length(node.centre - r.centre) - r.radius;
    const bool far = node.radius * farRatio <= distance;
    // Corners on r's plane (to rounding) are on neither side.
    const glm::dvec3 middle = 0.5 * (node.low + node.high), half = 0.5 * (node.high - node.low);
    const double height = originHeight + glm::dot(slope, middle), spread = glm::dot(glm::abs(slope), half);
    const double touch = 1e-9 * node.radius;
    const bool cut = height - spread < -touch && height + spread > touch;
    if (cut || (!far && node.radius * ratio > distance)) {
      for (uint32_t c = node.child; c < node.child + node.children; ++c) self(self, c);
      return;
    }
    out.steps.push_back({n, far ? NearStep::kMean : NearStep::kPoints});
  };
  visit(visit, 0);
  out.sizes.push_back({static_cast<uint32_t>(out.steps.size() - steps), static_cast<uint32_t>(out.factors.size() - factors)});
}

void applyPlan(std::span<const NodeLight> light, std::span<const NearStep> steps,
               std::span<const glm::dvec2> factors, const glm::dvec3& normal, const Receiver& r, glm::dvec3& front,
               glm::dvec3& back) {
  const glm::dvec2* factor = factors.data();
  for (const NearStep& step : steps) {
    const NodeLight& l = light[step.node];
    // A kElement step's factors are passed over also where there is nothing to shoot (under a
    // solid, say).
    if (step.kind == NearStep::kElement) {
      const glm::dvec2 f = *factor++;
      if (l.lit) front += l.weight * f.x, back += l.weight * f.y;
      continue;
    }
    if (!l.lit) continue;
    for (int set = 0; set < l.sets; ++set) {
      glm::dvec3 weight = l.weight;
      if (l.sets > 1) weight = glm::dvec3(0), weight[set] = l.weight[set];
      if (weight == glm::dvec3(0)) continue;
      if (step.kind == NearStep::kMean) addPoint(l.mean[set], weight, normal, r, front, back);
      else
        for (const glm::dvec3& p : l.points[set]) addPoint(p, 0.25 * weight, normal, r, front, back);
    }
  }
}

void patchToReceiver(const PatchTree& tree, std::span<const NodeLight> light, std::span<const uint32_t> elements,
                     std::span<const Receiver> receivers, const glm::dvec3& normal, const Receiver& r,
                     double farRatio, double ratio, int splits, glm::dvec3& front, glm::dvec3& back) {
  NearPlans plan;
  planPatchToReceiver(tree, elements, receivers, normal, r, farRatio, ratio, splits, plan);
  applyPlan(light, plan.steps, plan.factors, normal, r, front, back);
}

}  // namespace radiosity
