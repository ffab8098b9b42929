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

PatchTree buildPatchTree(std::span<uint32_t> elements, const ElementShapes& shapes, const glm::dvec3& x,
                         const glm::dvec3& y) {
  PatchTree tree;
  tree.x = x;
  tree.y = y;
  tree.z = glm::cross(x, y);
  const auto centroid = [&](uint32_t first, uint32_t last) {
    double a = 0;
    glm::dvec3 c{0};
    for (uint32_t k = first; k < last; ++k) {
      const uint32_t e = elements[k];
      a += shapes.area[e], c += shapes.area[e] * shapes.centre[e];
    }
    return c / a;
  };
  tree.origin = centroid(0, static_cast<uint32_t>(elements.size()));
  const auto planeOf = [&](uint32_t e) {
    const glm::dvec3 d = shapes.centre[e] - tree.origin;
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
      const Polygon3& p = shapes.polygon[elements[k]];
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

  // Each node's points: the Gauss points of its area's second moments about its centroid, and
  // the axes that measure the light's first moment along them. Its area's moments (about the
  // tree's origin) are its children's summed: bottom up, as breadth-first order puts children
  // after their parent. A leaf counts by its own integral and needs no points.
  for (uint32_t e : elements) tree.plane.push_back(planeOf(e));
  struct Moments {
    double area = 0;
    glm::dvec2 first{0};
    glm::dvec3 second{0};  // uu, uv, vv
  };
  std::vector<Moments> moments(tree.nodes.size());
  for (size_t n = tree.nodes.size(); n-- > 0;) {
    PatchTree::Node& node = tree.nodes[n];
    Moments& m = moments[n];
    if (node.children == 0) {
      const uint32_t e = elements[node.first];
      const double area = shapes.area[e];
      const glm::dvec2 p = tree.plane[node.first];
      m = {area, area * p,
           area * (glm::dvec3(p.x * p.x, p.x * p.y, p.y * p.y) + areaMoments(shapes.polygon[e], shapes.centre[e], x, y))};
      continue;
    }
    for (uint32_t c = node.child; c < node.child + node.children; ++c)
      m.area += moments[c].area, m.first += moments[c].first, m.second += moments[c].second;
    const glm::dvec2 mean = m.first / m.area;
    const glm::dvec3 c = m.second / m.area - glm::dvec3(mean.x * mean.x, mean.x * mean.y, mean.y * mean.y);
    // The covariance's principal axes: a rectangle gets its 2 x 2 Gauss points.
    const double half = 0.5 * (c.x + c.z), difference = 0.5 * (c.x - c.z);
    const double root = std::sqrt(difference * difference + c.y * c.y);
    glm::dvec2 axis{difference + root, c.y};
    const double length = glm::length(axis);
    axis = length > 0 ? axis / length : glm::dvec2(0, 1);
    const double major = std::sqrt(std::max(half + root, 0.0)), minor = std::sqrt(std::max(half - root, 0.0));
    const glm::dvec3 u = major * (axis.x * x + axis.y * y), v = minor * (axis.x * y - axis.y * x);
    const glm::dvec3 at = tree.origin + mean.x * x + mean.y * y;
    node.points = {at - u - v, at + u - v, at + u + v, at - u + v};
    node.mean = mean;
    node.axes[0] = major > 0 ? axis / major : glm::dvec2(0);
    node.axes[1] = minor > 0 ? glm::dvec2(-axis.y, axis.x) / minor : glm::dvec2(0);
  }
  return tree;
}

void lightPatchTree(const PatchTree& tree, std::span<const glm::dvec3> shares, std::vector<NodeLight>& out) {
  // Per node, its weight and its light's first moment about the tree's origin (per channel, along
  // u and v): its children's summed, bottom up.
  out.resize(tree.nodes.size());
  for (size_t n = tree.nodes.size(); n-- > 0;) {
    const PatchTree::Node& node = tree.nodes[n];
    NodeLight& light = out[n];
    if (node.children == 0) {
      const glm::dvec2 p = tree.plane[node.first];
      light.weight = shares[node.first];
      light.first = {shares[node.first] * p.x, shares[node.first] * p.y};
    } else {
      light.weight = glm::dvec3(0);
      light.first = {glm::dvec3(0), glm::dvec3(0)};
      for (uint32_t c = node.child; c < node.child + node.children; ++c) {
        light.weight += out[c].weight;
        light.first[0] += out[c].first[0];
        light.first[1] += out[c].first[1];
      }
    }
    // The light as a linear function over the node's area with its weight and first moment; the
    // Gauss points integrate that, each weighing what the function is there.
    const glm::dvec3 u = light.first[0] - light.weight * node.mean.x, v = light.first[1] - light.weight * node.mean.y;
    const glm::dvec3 major = u * node.axes[0].x + v * node.axes[0].y, minor = u * node.axes[1].x + v * node.axes[1].y;
    light.points = {0.25 * (light.weight - major - minor), 0.25 * (light.weight + major - minor),
                    0.25 * (light.weight + major + minor), 0.25 * (light.weight - major + minor)};
  }
}

void planPatchToReceiver(const PatchTree& tree, std::span<const Receiver> pieces, const glm::dvec3& normal,
                         const Receiver& r, double farRatio, double ratio, int splits, NearPlans& out) {
  const size_t steps = out.steps.size(), factors = out.factors.size();
  // Heights over r's plane in the tree's coordinates: at the origin, and per unit along each axis.
  const double originHeight = glm::dot(r.normal, tree.origin) - r.offset;
  const glm::dvec3 slope{glm::dot(r.normal, tree.x), glm::dot(r.normal, tree.y), glm::dot(r.normal, tree.z)};
  const auto visit = [&](const auto& self, uint32_t n) -> void {
    const PatchTree::Node& node = tree.nodes[n];
    if (node.children == 0) {
      double f = 0, b = 0;
      areaToPolygon(pieces[node.first], 1.0, normal, r, farRatio, ratio, splits, f, b);
      out.steps.push_back({n, NearStep::kElement});
      out.factors.emplace_back(f, b);
      return;
    }
    // A node that r's plane cuts sees r's front from one part and its back from the other: the
    // factor has a kink there that a few points would smooth over.
    const double distance = glm::length(node.centre - r.centre) - r.radius;
    // Corners on r's plane (to rounding) are on neither side.
    const glm::dvec3 middle = 0.5 * (node.low + node.high), half = 0.5 * (node.high - node.low);
    const double height = originHeight + glm::dot(slope, middle), spread = glm::dot(glm::abs(slope), half);
    const double touch = 1e-9 * node.radius;
    const bool cut = height - spread < -touch && height + spread > touch;
    if (cut || node.radius * ratio > distance) {
      for (uint32_t c = node.child; c < node.child + node.children; ++c) self(self, c);
      return;
    }
    out.steps.push_back({n, NearStep::kPoints});
  };
  visit(visit, 0);
  out.sizes.push_back({static_cast<uint32_t>(out.steps.size() - steps), static_cast<uint32_t>(out.factors.size() - factors)});
}

void applyPlan(const PatchTree& tree, std::span<const NodeLight> light, std::span<const NearStep> steps,
               std::span<const glm::dvec2> factors, const glm::dvec3& normal, const Receiver& r, glm::dvec3& front,
               glm::dvec3& back) {
  const glm::dvec2* factor = factors.data();
  for (const NearStep& step : steps) {
    const glm::dvec3& weight = light[step.node].weight;
    // A kElement step's factors are passed over also where there is nothing to shoot (under a
    // solid, say).
    if (step.kind == NearStep::kElement) {
      const glm::dvec2 f = *factor++;
      front += weight * f.x, back += weight * f.y;
      continue;
    }
    if (weight == glm::dvec3(0)) continue;
    const PatchTree::Node& node = tree.nodes[step.node];
    for (int k = 0; k < 4; ++k) addPoint(node.points[k], light[step.node].points[k], normal, r, front, back);
  }
}

void patchToReceiver(const PatchTree& tree, std::span<const NodeLight> light, std::span<const Receiver> pieces,
                     const glm::dvec3& normal, const Receiver& r, double farRatio, double ratio, int splits,
                     glm::dvec3& front, glm::dvec3& back) {
  NearPlans plan;
  planPatchToReceiver(tree, pieces, normal, r, farRatio, ratio, splits, plan);
  applyPlan(tree, light, plan.steps, plan.factors, normal, r, front, back);
}

}  // namespace radiosity
