// Analytic form factors, used where the hemisphere's item buffer is not good enough: from a
// point to a polygon (Lambert's contour integral, clipped at the point's horizon, unoccluded),
// and from an area to a polygon by splitting the area until each piece is small compared with
// its distance to the polygon. Internal to radiosity/.
#pragma once

#include <glm/vec3.hpp>

#include <array>

namespace radiosity {

// A convex planar polygon of 3 or 4 world-space corners.
struct Polygon3 {
  std::array<glm::dvec3, 4> v{};
  int n = 0;
};

double polygonArea(const Polygon3& p);
glm::dvec3 polygonCentroid(const Polygon3& p);  // area-weighted

// The form factor from a differential area at `point` with unit `normal` to polygon `p`,
// ignoring occlusion: the part of p below the point's horizon is clipped away, then Lambert's
// formula sums each edge's angle times the cosine between its great circle and the normal.
// 0 when p lies on or below the horizon. Either winding.
double pointToPolygon(const glm::dvec3& point, const glm::dvec3& normal, const Polygon3& p);

// Lambert's sum over the edges of the polygon v[0, m) (corners relative to the point, on or
// above its horizon): each edge's angle times the cosine between `normal` and the normal of the
// edge's great circle; +-2 pi times the form factor, by the winding. contourSum takes a
// triangle's or quad's edges four at a time where the CPU can (AVX2), with the same bits as the
// plain loop of contourSumReference.
double contourSum(const glm::dvec3* v, int m, const glm::dvec3& normal);
double contourSumReference(const glm::dvec3* v, int m, const glm::dvec3& normal);

// A rule exact for quadratics over a polygon: 2 x 2 Gauss points on a quad's bilinear map, the
// 3-point rule on a triangle. Weights are shares of the area and sum to 1.
struct Quadrature {
  std::array<glm::dvec3, 4> point{};
  std::array<double, 4> weight{};
  int n = 0;
};
Quadrature gaussRule(const Polygon3& p);
// Its weights alone (a triangle's fourth is 0): the costly part of the rule (a root and a
// division per point), which gaussLanes makes the whole rule from again.
std::array<double, 4> gaussWeights(const Polygon3& p);

// A receiving element: its polygon and bounding sphere, its plane (dot(normal, q) == offset),
// whose front alone reflects, and its area and Gauss rule. makeReceiver takes the front's unit
// normal.
struct Receiver {
  Polygon3 polygon;
  glm::dvec3 centre{0};
  double radius = 0;
  glm::dvec3 normal{0};
  double offset = 0;
  double area = 0;
  // The Gauss rule (gaussRule: polygon.n points) by coordinate, for the vector lanes (a
  // triangle's fourth weight is 0).
  struct RuleLanes {
    alignas(32) double x[4], y[4], z[4], weight[4];
  } lanes{};
};
Receiver makeReceiver(const Polygon3& p, const glm::dvec3& normal);
// gaussRule(p) as Receiver::lanes, from its `weights` (gaussWeights(p)): what makeReceiver
// gives, for a caller that holds the rest.
Receiver::RuleLanes gaussLanes(const Polygon3& p, const std::array<double, 4>& weights);

// A point at least this many receiver radii from the receiver's centre, with the receiver wholly
// above its horizon, takes the factor from the receiver's Gauss rule: Lambert's differential
// formula at each Gauss point, error falling as the fourth power of radius over distance (under
// 0.7% at 4 radii for any orientation, 0.06% on average), at an eighth of the contour
// integral's cost.
constexpr double kGaussReceiverRatio = 4;

// The form factor from a differential area at `point` with unit `normal` to `r`, unoccluded:
// by r's Gauss rule where kGaussReceiverRatio allows, else pointToPolygon.
double pointToReceiver(const glm::dvec3& point, const glm::dvec3& normal, const Receiver& r);

// The sum over r's Gauss points of weight x cos at the point x |cos at r| / d^2 (the factor from
// `point` by r's rule, over area / pi): gaussSum four points in AVX2 lanes where the CPU can,
// with the same bits as the plain loop of gaussSumReference.
double gaussSum(const glm::dvec3& point, const glm::dvec3& normal, const Receiver& r);
double gaussSumReference(const glm::dvec3& point, const glm::dvec3& normal, const Receiver& r);

// The distance from `point` to r's polygon, or at least `enough` when it is that far: the
// distance to r's bounding sphere answers when that is at least `enough`.
double distanceToReceiver(const glm::dvec3& point, const Receiver& r, double enough);

// Adds to front/back weight x the form factor from `piece` (a part of the shooter, whose
// normal is `normal`) to `r`, averaged over the piece. A piece whose centre is farther from r's
// polygon than `farRatio` times its radius counts by its centre alone. Otherwise `piece` is split
// into four (edge midpoints) while its radius exceeds that distance over `ratio` and `splits`
// allows, then each piece is integrated by its Gauss rule (the factor from a point varies on
// the scale of its distance to the polygon, not to the polygon's centre). A point behind r's
// plane sees r's back: its share goes to `back`. `weight` is the piece's share of the shooter's
// area.
void areaToPolygon(const Polygon3& piece, double weight, const glm::dvec3& normal, const Receiver& r,
                   double farRatio, double ratio, int splits, double& front, double& back);
// The same for a whole element, whose centroid, radius and Gauss rule are at hand.
void areaToPolygon(const Receiver& piece, double weight, const glm::dvec3& normal, const Receiver& r, double farRatio,
                   double ratio, int splits, double& front, double& back);

}  // namespace radiosity
