// The near field of a shooting patch: its elements grouped into a tree of ever smaller clusters,
// so a receiver near the patch integrates over it by clusters where it is far for their size and
// by elements only where it is close. Without the tree a patch of K elements costs every near
// receiver K integrals, and patches large enough to take few shots cost more than they save.
// Internal to radiosity/.
#pragma once

#include "radiosity/form_factors.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace radiosity {

// One patch's tree. Nodes are in breadth-first order, the root first. Node n holds the elements
// at positions [first, last) of the patch's element list; a node of one element is a leaf,
// others have 2 to 4 children, nodes [child, child + children).
struct PatchTree {
  struct Node {
    uint32_t first = 0, last = 0;
    uint32_t child = 0, children = 0;
    glm::dvec3 centre{0};  // area centroid
    double radius = 0;     // of the sphere about centre that holds every corner
    // The box that holds every corner, in the tree's coordinates (origin + u x + v y + w z, z the
    // patch's normal): the heights of the corners over a receiver's plane lie within its image.
    glm::dvec3 low{0}, high{0};
    // Four points with the first and second moments of its area (a rectangle's 2 x 2 Gauss
    // points), where it counts by points: its area's centroid plus and minus its principal axes
    // (major, minor) scaled by their deviations, in the order (-,-), (+,-), (+,+), (-,+).
    std::array<glm::dvec3, 4> points{};
    // Its centroid in plane coordinates, and per principal axis the direction over its deviation
    // (zero for a node without extent along it).
    glm::dvec2 mean{0};
    std::array<glm::dvec2, 2> axes{};
  };
  std::vector<Node> nodes;
  std::vector<glm::dvec2> plane;  // per element (in the patch's order): its centroid (origin + u x + v y)
  glm::dvec3 origin{0}, x{0}, y{0}, z{0};
};

// Per element: its polygon, its area's centroid (polygonCentroid) and its area.
struct ElementShapes {
  std::span<const Polygon3> polygon;
  std::span<const glm::dvec3> centre;
  std::span<const double> area;
};

// Builds the tree over a patch's elements (indices into `shapes`, all in one plane with unit
// axes x and y) and reorders `elements` so that each node's elements are contiguous. Clusters
// split at their centroid into quadrants (in half along the plane's u axis when the quadrants
// would not divide them).
PatchTree buildPatchTree(std::span<uint32_t> elements, const ElementShapes& shapes, const glm::dvec3& x,
                         const glm::dvec3& y);

// A node's share of one shot: per channel the sum of its elements' shares of the patch's unshot
// power, and the weights of its four points: the light taken as a linear function over the
// node's area with the elements' weight and first moment, at each point, a quarter of the area
// each (a patch brighter at one end weighs that end's points more). Points stay where the node's
// area puts them, so a shot's integrals are linear in its elements' light: the sum of two shots'
// factors is the factors of one shot of their summed light (what a correction after an edit takes
// back, Solver::edit).
struct NodeLight {
  glm::dvec3 weight{0};
  std::array<glm::dvec3, 2> first{};  // the light's first moment about the tree's origin, along u and v
  std::array<glm::dvec3, 4> points{};
};

// Per node of `tree`, its light for elements whose per-channel shares (in the patch's element
// order) are `shares`. `out` is resized to the tree's nodes.
void lightPatchTree(const PatchTree& tree, std::span<const glm::dvec3> shares, std::vector<NodeLight>& out);

// Adds to front/back (per channel) the form factor from the patch to `r`, unoccluded, weighted by
// the shares: from the root down, a node that r's plane does not cut and that is farther from
// r's bounding sphere than `ratio` times its radius counts by its four points, others by their
// children; a leaf's element by areaToPolygon with `farRatio`, `ratio` and `splits`. `pieces` are
// the patch's elements as receivers, in tree order; `normal` is the patch's. A node is cut by r's
// plane when its corners lie on both sides of it (by its box), not merely near it: a patch
// touching r's plane (a floor patch at the foot of a wall) sees r's front from all of it.
void patchToReceiver(const PatchTree& tree, std::span<const NodeLight> light, std::span<const Receiver> pieces,
                     const glm::dvec3& normal, const Receiver& r, double farRatio, double ratio, int splits,
                     glm::dvec3& front, glm::dvec3& back);

// patchToReceiver in two halves, for a patch that shoots at the same receivers again and again
// with its light spread differently each time. Which nodes count by their points and which
// elements by their own integral depends on the geometry alone, and so do those integrals (most
// of the work): they are the receiver's plan. The light only weighs the integrals and the points.
// planPatchToReceiver then applyPlan gives patchToReceiver's sums bit for bit, whatever the light.
struct NearStep {
  enum Kind : uint32_t { kElement, kPoints };
  uint32_t node = 0;
  Kind kind = kElement;
};
// The size of one receiver's plan: its steps in traversal order and, per kElement step in order,
// the leaf element's form factor to the receiver (unweighted): front and back.
struct NearPlanSize {
  uint32_t steps = 0, factors = 0;
};
// Plans of receivers one after another, and a run of them.
struct NearPlans {
  std::vector<NearStep> steps;
  std::vector<glm::dvec2> factors;
  std::vector<NearPlanSize> sizes;
};
struct NearPlansView {
  std::span<const NearStep> steps;
  std::span<const glm::dvec2> factors;
  std::span<const NearPlanSize> sizes;
};

// Appends r's plan to `out`, the arguments as patchToReceiver's.
void planPatchToReceiver(const PatchTree& tree, std::span<const Receiver> pieces, const glm::dvec3& normal,
                         const Receiver& r, double farRatio, double ratio, int splits, NearPlans& out);

// Adds to front/back (per channel) r's plan (`steps`, and `factors` of its kElement steps) made
// with planPatchToReceiver over `tree`, weighted by `light`; `normal` is the patch's.
void applyPlan(const PatchTree& tree, std::span<const NodeLight> light, std::span<const NearStep> steps,
               std::span<const glm::dvec2> factors, const glm::dvec3& normal, const Receiver& r, glm::dvec3& front,
               glm::dvec3& back);

}  // namespace radiosity
