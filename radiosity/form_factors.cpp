#include "radiosity/form_factors.h"

#include "util/fast_atan2.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

// AVX2 intrinsics where GCC or Clang builds for x86-64, used when the CPU has AVX2 (asked at run
// time: the build's baseline lacks it); the plain scalar loops elsewhere. Intrinsics rather than
// GCC's vector types (as pxpl5 uses): these paths must repeat the scalar reference's operations
// one for one, unfused, to give its bits.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define WALKRAD_FORM_FACTOR_AVX2 1
#include <immintrin.h>
#else
#define WALKRAD_FORM_FACTOR_AVX2 0
#endif

namespace radiosity {

namespace {

// Newell's normal: its length is twice the area, for either winding.
glm::dvec3 newell(const Polygon3& p) {
  glm::dvec3 n{0};
  for (int k = 0; k < p.n; ++k) {
    const glm::dvec3& a = p.v[k];
    const glm::dvec3& b = p.v[(k + 1) % p.n];
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

double pieceRadius(const Polygon3& p, const glm::dvec3& centre) {
  double r2 = 0;
  for (int k = 0; k < p.n; ++k) r2 = std::max(r2, glm::dot(p.v[k] - centre, p.v[k] - centre));
  return std::sqrt(r2);
}

// The four pieces of a polygon cut at its edge midpoints (and, for a quad, its bilinear centre).
int splitInFour(const Polygon3& p, Polygon3 out[4]) {
  if (p.n == 3) {
    const glm::dvec3 ab = (p.v[0] + p.v[1]) * 0.5, bc = (p.v[1] + p.v[2]) * 0.5, ca = (p.v[2] + p.v[0]) * 0.5;
    out[0] = {{p.v[0], ab, ca, {}}, 3};
    out[1] = {{ab, p.v[1], bc, {}}, 3};
    out[2] = {{ca, bc, p.v[2], {}}, 3};
    out[3] = {{ab, bc, ca, {}}, 3};
    return 4;
  }
  const glm::dvec3 ab = (p.v[0] + p.v[1]) * 0.5, bc = (p.v[1] + p.v[2]) * 0.5, cd = (p.v[2] + p.v[3]) * 0.5,
                   da = (p.v[3] + p.v[0]) * 0.5, m = (p.v[0] + p.v[1] + p.v[2] + p.v[3]) * 0.25;
  out[0] = {{p.v[0], ab, m, da}, 4};
  out[1] = {{ab, p.v[1], bc, m}, 4};
  out[2] = {{m, bc, p.v[2], cd}, 4};
  out[3] = {{da, m, cd, p.v[3]}, 4};
  return 4;
}

}  // namespace

double polygonArea(const Polygon3& p) { return 0.5 * glm::length(newell(p)); }

glm::dvec3 polygonCentroid(const Polygon3& p) {
  // Fan triangles from the first corner, weighted by their areas.
  glm::dvec3 sum{0};
  double total = 0;
  for (int k = 1; k + 1 < p.n; ++k) {
    const double a = 0.5 * glm::length(glm::cross(p.v[k] - p.v[0], p.v[k + 1] - p.v[0]));
    sum += a * (p.v[0] + p.v[k] + p.v[k + 1]) / 3.0;
    total += a;
  }
  if (total <= 0) {
    glm::dvec3 mean{0};
    for (int k = 0; k < p.n; ++k) mean += p.v[k];
    return mean / double(p.n);
  }
  return sum / total;
}

double pointToPolygon(const glm::dvec3& point, const glm::dvec3& normal, const Polygon3& p) {
  // Clip at the horizon first: Lambert's formula holds only for what the hemisphere sees. Most
  // polygons are wholly above it and are taken as they are.
  glm::dvec3 corner[4], clipped[8];
  double height[4];
  bool above = true;
  for (int k = 0; k < p.n; ++k) {
    corner[k] = p.v[k] - point;
    height[k] = glm::dot(corner[k], normal);
    above = above && height[k] >= 0;
  }
  const glm::dvec3* v = corner;
  int m = p.n;
  if (!above) {
    m = 0;
    for (int k = 0; k < p.n; ++k) {
      const int next = k + 1 < p.n ? k + 1 : 0;
      const glm::dvec3 &a = corner[k], &b = corner[next];
      const double da = height[k], db = height[next];
      if (da >= 0) clipped[m++] = a;
      if ((da >= 0) != (db >= 0)) clipped[m++] = a + (da / (da - db)) * (b - a);
    }
    v = clipped;
    if (m < 3) return 0;
  }
  const double sum = contourSum(v, m, normal);
  return std::abs(sum) / (2 * std::numbers::pi);
}

double contourSumReference(const glm::dvec3* v, int m, const glm::dvec3& normal) {
  double sum = 0;
  for (int k = 0; k < m; ++k) {
    // The edge's angle and its great circle's normal do not depend on the lengths of a and b:
    // no need to normalise them.
    const glm::dvec3& a = v[k];
    const glm::dvec3& b = v[k + 1 < m ? k + 1 : 0];
    const glm::dvec3 c = glm::cross(a, b);
    const double s = glm::length(c);
    if (s == 0) continue;
    // The polynomial atan2 (2e-8 radians): this sum runs for most receivers of every shot.
    sum += util::fastAtan2(s, glm::dot(a, b)) * glm::dot(normal, c) / s;
  }
  return sum;
}

namespace {

#if WALKRAD_FORM_FACTOR_AVX2
// Asked once: the contour sums and Gauss rules take their AVX2 paths only on CPUs that have it.
bool hasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}
#endif

// The edges of a triangle or quad in the four lanes of AVX2, every operation the reference's, in
// its order and unfused, so the sum has the same bits: the runs use either interchangeably.
#if WALKRAD_FORM_FACTOR_AVX2
[[gnu::target("avx2")]] double contourSumAvx2(const glm::dvec3* v, int m, const glm::dvec3& normal) {
  // Lane k holds edge k, from corner a = v[k] to b = v[k + 1]; a triangle's fourth lane is empty
  // (a = b = 0), whose s == 0 drops it as the reference does.
  const glm::dvec3 zero{0};
  const glm::dvec3& a3 = m == 4 ? v[3] : zero;
  const glm::dvec3& b2 = m == 4 ? v[3] : v[0];
  const glm::dvec3& b3 = m == 4 ? v[0] : zero;
  const __m256d ax = _mm256_set_pd(a3.x, v[2].x, v[1].x, v[0].x), bx = _mm256_set_pd(b3.x, b2.x, v[2].x, v[1].x);
  const __m256d ay = _mm256_set_pd(a3.y, v[2].y, v[1].y, v[0].y), by = _mm256_set_pd(b3.y, b2.y, v[2].y, v[1].y);
  const __m256d az = _mm256_set_pd(a3.z, v[2].z, v[1].z, v[0].z), bz = _mm256_set_pd(b3.z, b2.z, v[2].z, v[1].z);
  // c = cross(a, b), s = length(c), dot(a, b), dot(normal, c), as glm computes them.
  const __m256d cx = _mm256_sub_pd(_mm256_mul_pd(ay, bz), _mm256_mul_pd(by, az));
  const __m256d cy = _mm256_sub_pd(_mm256_mul_pd(az, bx), _mm256_mul_pd(bz, ax));
  const __m256d cz = _mm256_sub_pd(_mm256_mul_pd(ax, by), _mm256_mul_pd(bx, ay));
  const __m256d s = _mm256_sqrt_pd(
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(cx, cx), _mm256_mul_pd(cy, cy)), _mm256_mul_pd(cz, cz)));
  const __m256d x = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ax, bx), _mm256_mul_pd(ay, by)), _mm256_mul_pd(az, bz));
  const __m256d nc = _mm256_add_pd(
      _mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(normal.x), cx), _mm256_mul_pd(_mm256_set1_pd(normal.y), cy)),
      _mm256_mul_pd(_mm256_set1_pd(normal.z), cz));
  // util::fastAtan2(s, x) for s >= 0: z is the smaller of s and |x| over the larger.
  const __m256d zeroes = _mm256_setzero_pd();
  const __m256d absX = _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
  const __m256d steep = _mm256_cmp_pd(s, absX, _CMP_GT_OQ);
  const __m256d z = _mm256_div_pd(_mm256_blendv_pd(s, absX, steep), _mm256_blendv_pd(absX, s, steep));
  const __m256d z2 = _mm256_mul_pd(z, z);
  const double* c = util::kFastAtanCoefficients;
  __m256d inner = _mm256_mul_pd(z2, _mm256_set1_pd(c[7]));
  for (int k = 6; k >= 0; --k) inner = _mm256_mul_pd(z2, _mm256_add_pd(_mm256_set1_pd(c[k]), inner));
  const __m256d atanZ = _mm256_mul_pd(z, _mm256_add_pd(_mm256_set1_pd(1.0), inner));
  const __m256d angle = _mm256_blendv_pd(atanZ, _mm256_sub_pd(_mm256_set1_pd(std::numbers::pi / 2), atanZ), steep);
  const __m256d atan2 = _mm256_blendv_pd(angle, _mm256_sub_pd(_mm256_set1_pd(std::numbers::pi), angle),
                                         _mm256_cmp_pd(x, zeroes, _CMP_LT_OQ));
  // Empty edges (s == 0) add nothing, as the reference skips them.
  const __m256d terms = _mm256_blendv_pd(_mm256_div_pd(_mm256_mul_pd(atan2, nc), s), zeroes,
                                         _mm256_cmp_pd(s, zeroes, _CMP_EQ_OQ));
  alignas(32) double lane[4];
  _mm256_store_pd(lane, terms);
  double sum = 0;
  for (double t : lane) sum += t;
  return sum;
}
#endif

}  // namespace

double contourSum(const glm::dvec3* v, int m, const glm::dvec3& normal) {
#if WALKRAD_FORM_FACTOR_AVX2
  if (hasAvx2() && (m == 3 || m == 4)) return contourSumAvx2(v, m, normal);
#endif
  return contourSumReference(v, m, normal);
}

namespace {

// The rule's Gauss points: a triangle's at its barycentric (2/3, 1/6, 1/6) and turns, a quad's
// on its bilinear map at u, v in {1/2 -+ 1/(2 sqrt 3)}, u the outer loop.
// 1/2 -+ 1/(2 sqrt 3) written out: std::sqrt is not constexpr in the standard (clang refuses it).
constexpr double kGaussQuad[2] = {0.21132486540518711775, 0.78867513459481288225};
constexpr double kGaussTriangle[3][3] = {{2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}, {1.0 / 6, 1.0 / 6, 2.0 / 3}};

glm::dvec3 gaussPoint(const Polygon3& p, int k) {
  if (p.n == 3) {
    const double* w = kGaussTriangle[k];
    return w[0] * p.v[0] + w[1] * p.v[1] + w[2] * p.v[2];
  }
  const double u = kGaussQuad[k / 2], v = kGaussQuad[k % 2];
  const glm::dvec3 &a = p.v[0], &b = p.v[1], &c = p.v[2], &d = p.v[3];
  return (1 - u) * (1 - v) * a + u * (1 - v) * b + u * v * c + (1 - u) * v * d;
}

}  // namespace

std::array<double, 4> gaussWeights(const Polygon3& p) {
  if (p.n == 3) return {1.0 / 3, 1.0 / 3, 1.0 / 3, 0};
  std::array<double, 4> weight{};
  const glm::dvec3 &a = p.v[0], &b = p.v[1], &c = p.v[2], &d = p.v[3];
  double total = 0;
  for (int k = 0; k < 4; ++k) {
    const double u = kGaussQuad[k / 2], v = kGaussQuad[k % 2];
    const glm::dvec3 du = (1 - v) * (b - a) + v * (c - d), dv = (1 - u) * (d - a) + u * (c - b);
    total += weight[k] = glm::length(glm::cross(du, dv));  // the map's area scale there
  }
  for (double& w : weight) w /= total;
  return weight;
}

Quadrature gaussRule(const Polygon3& p) {
  Quadrature rule;
  const std::array<double, 4> weight = gaussWeights(p);
  for (rule.n = 0; rule.n < (p.n == 3 ? 3 : 4); ++rule.n) {
    rule.point[rule.n] = gaussPoint(p, rule.n);
    rule.weight[rule.n] = weight[rule.n];
  }
  return rule;
}

Receiver makeReceiver(const Polygon3& p, const glm::dvec3& normal) {
  Receiver r;
  r.polygon = p;
  r.centre = polygonCentroid(p);
  r.radius = pieceRadius(p, r.centre);
  r.normal = normal;
  r.offset = glm::dot(r.normal, r.centre);
  r.area = polygonArea(p);
  r.lanes = gaussLanes(p, gaussWeights(p));
  return r;
}

Receiver::RuleLanes gaussLanes(const Polygon3& p, const std::array<double, 4>& weights) {
  Receiver::RuleLanes lanes{};
  for (int k = 0; k < (p.n == 3 ? 3 : 4); ++k) {
    const glm::dvec3 point = gaussPoint(p, k);
    lanes.x[k] = point.x;
    lanes.y[k] = point.y;
    lanes.z[k] = point.z;
    lanes.weight[k] = weights[k];
  }
  return lanes;
}

double pointToReceiver(const glm::dvec3& point, const glm::dvec3& normal, const Receiver& r) {
  const glm::dvec3 toward = r.centre - point;
  const double above = glm::dot(toward, normal);
  if (above < r.radius || glm::dot(toward, toward) < kGaussReceiverRatio * kGaussReceiverRatio * r.radius * r.radius)
    return pointToPolygon(point, normal, r.polygon);
  return gaussSum(point, normal, r) * r.area / std::numbers::pi;
}

double gaussSumReference(const glm::dvec3& point, const glm::dvec3& normal, const Receiver& r) {
  // cos at the point x cos at the receiver / (pi d^2), each cosine a dot over d.
  double sum = 0;
  for (int k = 0; k < r.polygon.n; ++k) {
    const glm::dvec3 d = glm::dvec3(r.lanes.x[k], r.lanes.y[k], r.lanes.z[k]) - point;
    const double d2 = glm::dot(d, d);
    sum += r.lanes.weight[k] * glm::dot(d, normal) * std::abs(glm::dot(d, r.normal)) / (d2 * d2);
  }
  return sum;
}

namespace {

#if WALKRAD_FORM_FACTOR_AVX2
// The reference's operations in its order, unfused, a Gauss point per lane; a triangle's empty
// fourth lane is dropped as the reference never visits it.
[[gnu::target("avx2")]] double gaussSumAvx2(const glm::dvec3& point, const glm::dvec3& normal, const Receiver& r) {
  const __m256d dx = _mm256_sub_pd(_mm256_load_pd(r.lanes.x), _mm256_set1_pd(point.x));
  const __m256d dy = _mm256_sub_pd(_mm256_load_pd(r.lanes.y), _mm256_set1_pd(point.y));
  const __m256d dz = _mm256_sub_pd(_mm256_load_pd(r.lanes.z), _mm256_set1_pd(point.z));
  const __m256d d2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
  const __m256d up = _mm256_add_pd(
      _mm256_add_pd(_mm256_mul_pd(dx, _mm256_set1_pd(normal.x)), _mm256_mul_pd(dy, _mm256_set1_pd(normal.y))),
      _mm256_mul_pd(dz, _mm256_set1_pd(normal.z)));
  const __m256d facing = _mm256_andnot_pd(
      _mm256_set1_pd(-0.0),
      _mm256_add_pd(
          _mm256_add_pd(_mm256_mul_pd(dx, _mm256_set1_pd(r.normal.x)), _mm256_mul_pd(dy, _mm256_set1_pd(r.normal.y))),
          _mm256_mul_pd(dz, _mm256_set1_pd(r.normal.z))));
  const __m256d terms = _mm256_div_pd(_mm256_mul_pd(_mm256_mul_pd(_mm256_load_pd(r.lanes.weight), up), facing),
                                      _mm256_mul_pd(d2, d2));
  alignas(32) double lane[4];
  _mm256_store_pd(lane, terms);
  double sum = 0;
  for (int k = 0; k < r.polygon.n; ++k) sum += lane[k];
  return sum;
}
#endif

}  // namespace

double gaussSum(const glm::dvec3& point, const glm::dvec3& normal, const Receiver& r) {
#if WALKRAD_FORM_FACTOR_AVX2
  if (hasAvx2()) return gaussSumAvx2(point, normal, r);
#endif
  return gaussSumReference(point, normal, r);
}

double distanceToReceiver(const glm::dvec3& point, const Receiver& r, double enough) {
  const double sphere = glm::length(point - r.centre) - r.radius;
  if (sphere >= enough) return sphere;
  // The point's foot on the plane, if inside the polygon, else the nearest point of an edge.
  const double height = glm::dot(r.normal, point) - r.offset;
  const glm::dvec3 foot = point - height * r.normal;
  const Polygon3& p = r.polygon;
  double edge2 = INFINITY;
  bool left = true, right = true;  // of every edge: inside, for either winding
  for (int k = 0; k < p.n; ++k) {
    const glm::dvec3 a = p.v[k], ab = p.v[(k + 1) % p.n] - a;
    const double side = glm::dot(glm::cross(ab, foot - a), r.normal);
    left = left && side >= 0;
    right = right && side <= 0;
    const double t = std::clamp(glm::dot(point - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    const glm::dvec3 d = point - (a + t * ab);
    edge2 = std::min(edge2, glm::dot(d, d));
  }
  return left || right ? std::abs(height) : std::sqrt(edge2);
}

namespace {

// areaToPolygon for a piece whose centroid and radius are known, and its Gauss rule when `rule`
// is not null.
void integrate(const Polygon3& piece, const glm::dvec3& centre, double size, const Quadrature* rule, double weight,
               const glm::dvec3& normal, const Receiver& r, double farRatio, double ratio, int splits, double& front,
               double& back) {
  const double distance = distanceToReceiver(centre, r, size * farRatio);
  if (size * farRatio <= distance) {
    // Far for its size: its centre stands for it, as a whole shooter's does for far receivers.
    const double f = weight * pointToReceiver(centre, normal, r);
    (glm::dot(r.normal, centre) > r.offset ? front : back) += f;
    return;
  }
  if (splits <= 0 || size * ratio <= distance) {
    // A piece small for its distance: its Gauss rule, whose error falls as the fourth power of
    // the piece's size where the midpoint rule's falls as the square.
    const Quadrature own = rule ? *rule : gaussRule(piece);
    for (int k = 0; k < own.n; ++k) {
      const double f = weight * own.weight[k] * pointToReceiver(own.point[k], normal, r);
      (glm::dot(r.normal, own.point[k]) > r.offset ? front : back) += f;
    }
    return;
  }
  Polygon3 parts[4];
  const int count = splitInFour(piece, parts);
  const double area = polygonArea(piece);
  for (int k = 0; k < count; ++k)
    areaToPolygon(parts[k], weight * polygonArea(parts[k]) / area, normal, r, farRatio, ratio, splits - 1, front, back);
}

}  // namespace

void areaToPolygon(const Polygon3& piece, double weight, const glm::dvec3& normal, const Receiver& r,
                   double farRatio, double ratio, int splits, double& front, double& back) {
  const glm::dvec3 centre = polygonCentroid(piece);
  integrate(piece, centre, pieceRadius(piece, centre), nullptr, weight, normal, r, farRatio, ratio, splits, front,
            back);
}

void areaToPolygon(const Receiver& piece, double weight, const glm::dvec3& normal, const Receiver& r, double farRatio,
                   double ratio, int splits, double& front, double& back) {
  Quadrature rule;
  for (rule.n = 0; rule.n < piece.polygon.n; ++rule.n) {
    rule.point[rule.n] = {piece.lanes.x[rule.n], piece.lanes.y[rule.n], piece.lanes.z[rule.n]};
    rule.weight[rule.n] = piece.lanes.weight[rule.n];
  }
  integrate(piece.polygon, piece.centre, piece.radius, &rule, weight, normal, r, farRatio, ratio, splits, front,
            back);
}

}  // namespace radiosity
