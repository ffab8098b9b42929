// The solver against closed forms and conservation laws: the furnace, two pairs of unit squares
// with known form factors, energy balance in a closed and an open box, reciprocity.
#include "radiosity/radiosity.h"

#include "radiosity/form_factors.h"
#include "radiosity/item_buffer.h"
#include "radiosity/near_field.h"
#include "tests/radiosity/scenes.h"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

namespace radiosity {
namespace {

using test::area;
using test::areaTimesRadiance;
using test::closedBox;
using test::rectangle;

// Whether the vector paths run here: elsewhere they fall back to the reference, and comparing
// the two would compare it with itself.
bool vectorPathsRun() {
#if defined(__x86_64__)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

// Uniform numbers in [0, 1) from a 64-bit LCG's top 53 bits: the same sequence on every machine.
struct Uniform {
  uint64_t state;
  double operator()() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1.0p-53;
  }
};

constexpr double kPi = std::numbers::pi;

void groupAll(std::vector<Surface>& surfaces, double patchEdge) {
  for (Surface& s : surfaces) s.patchOfElement = groupIntoPatches(s, patchEdge);
}

// A closed box of one material: the radiance is E / (1 - rho) everywhere, on every element and
// every vertex, and nothing escapes.
void expectFurnace(double patchEdge) {
  const glm::dvec3 rho{0.5, 0.25, 0.8}, emission{1, 2, 0.5};
  std::vector<Surface> box = closedBox(1, 0.25, rho, emission);
  if (patchEdge > 0) groupAll(box, patchEdge);
  Solver solver(box);
  solver.solve(1e-7);
  const glm::dvec3 exact = emission / (1.0 - rho);
  double worst = 0;
  for (uint32_t s = 0; s < box.size(); ++s) {
    for (const glm::dvec3& b : solver.elementRadiance(s))
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(b[c] / exact[c] - 1));
    for (const glm::dvec3& b : solver.vertexRadiance(s, solver.ambient()))
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(b[c] / exact[c] - 1));
  }
  std::printf("furnace (patches %g): %llu shots, worst relative error %.2e, escaped %.2e of emitted\n", patchEdge,
              static_cast<unsigned long long>(solver.stats().shots), worst,
              solver.stats().escapedPower.x / solver.stats().emittedPower.x);
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(solver.stats().escapedPower.x, 1e-9 * solver.stats().emittedPower.x);
}

TEST(RadiosityPhysics, FurnaceElementsShootAlone) { expectFurnace(0); }
TEST(RadiosityPhysics, FurnaceWithShootingPatches) { expectFurnace(0.5); }

// Before convergence the ambient term stands in for the light not yet shot; in a furnace it is
// exact once the unshot light is spread evenly, which it is before the first shot.
TEST(RadiosityPhysics, FurnaceAmbientBeforeAnyShot) {
  const glm::dvec3 rho{0.5}, emission{1};
  const std::vector<Surface> box = closedBox(1, 0.5, rho, emission);
  Solver solver(box);
  for (const glm::dvec3& b : solver.vertexRadiance(0, solver.ambient())) EXPECT_NEAR(b.x, 2.0, 1e-12);
}

// The form factor from an emitter to a receiver, through the whole pipeline: the emitter does not
// reflect, so the receiver's reflected power is rho x emission x A_e x F_er.
double factorThroughSolver(const Surface& emitter, const Surface& receiver, double patchEdge) {
  std::vector<Surface> scene{emitter, receiver};
  if (patchEdge > 0) groupAll(scene, patchEdge);
  Solver solver(scene);
  solver.solve(0);
  double emitterArea = 0;
  for (uint32_t e = 0; e < emitter.elements.size(); ++e) emitterArea += area(emitter, e);
  return areaTimesRadiance(solver, receiver, 1).x / (receiver.reflectance.x * emitter.emission.x * emitterArea);
}

struct SquaresCase {
  double elementSize;
  double patchEdge;  // 0: elements shoot alone
};

class RadiositySquares : public ::testing::TestWithParam<SquaresCase> {
 protected:
  // The unit square at the origin in the x-y plane emits; a unit square at `corner` spanned by
  // `u` and `v` receives; the factor through the solver is within 1% of `exact`.
  void expectFactor(const char* what, glm::dvec3 corner, glm::dvec3 u, glm::dvec3 v, double exact) {
    const SquaresCase c = GetParam();
    const Surface emitter = rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, c.elementSize, glm::dvec3(0), glm::dvec3(1));
    const Surface receiver = rectangle(corner, u, v, c.elementSize, glm::dvec3(0.5));
    const double f = factorThroughSolver(emitter, receiver, c.patchEdge);
    std::printf("%s squares, elements %g, patches %g: F = %.5f (exact %.5f, %+.2f%%)\n", what, c.elementSize, c.patchEdge, f,
                exact, 100 * (f / exact - 1));
    EXPECT_NEAR(f, exact, 0.01 * exact);
  }
};

// Two unit squares facing each other a unit apart: F = 0.19982 (Siegel and Howell).
TEST_P(RadiositySquares, Opposed) { expectFactor("opposed", {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, 0.19982); }

// Two unit squares at a right angle sharing an edge: F = 0.20004.
TEST_P(RadiositySquares, Perpendicular) { expectFactor("perpendicular", {0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 0.20004); }

INSTANTIATE_TEST_SUITE_P(Meshes, RadiositySquares,
                         ::testing::Values(SquaresCase{1, 0}, SquaresCase{0.25, 0}, SquaresCase{0.25, 0.5},
                                           SquaresCase{0.125, 1}));

// The receiver's Gauss rule, the fast path for receivers far for their size, against Lambert's
// contour integral: quads of aspect 1 to 2 and triangles, every orientation, distance and
// direction above the horizon; within 1% each (its error falls as the fourth power of radius over
// distance) and exactly the contour integral where the rule does not apply.
TEST(RadiosityPhysics, ReceiverGaussRuleAgreesWithContourIntegral) {
  Uniform uniform{12345};
  const auto direction = [&] {
    glm::dvec3 d;
    do d = {2 * uniform() - 1, 2 * uniform() - 1, 2 * uniform() - 1};
    while (glm::length(d) > 1 || glm::length(d) < 0.1);
    return glm::normalize(d);
  };
  const glm::dvec3 point{0, 0, 0}, normal{0, 0, 1};
  double worst = 0;
  int fast = 0;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 n = direction();
    const glm::dvec3 t = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 b = glm::cross(n, t);
    const double aspect = 1 + uniform();
    const glm::dvec3 centre = (1 + 10 * uniform()) * direction();
    Polygon3 p;
    if (i % 4 == 0) p = {{centre - t - b, centre + t - b, centre + aspect * b, {}}, 3};
    else p = {{centre - aspect * t - b, centre + aspect * t - b, centre + aspect * t + b, centre - aspect * t + b}, 4};
    const double exact = pointToPolygon(point, normal, p);
    const Receiver r = makeReceiver(p, n);
    const bool gauss = glm::dot(r.centre - point, normal) >= r.radius &&
                       glm::length(r.centre - point) >= kGaussReceiverRatio * r.radius;
    fast += gauss;
    if (gauss) worst = std::max(worst, std::abs(pointToReceiver(point, normal, r) / exact - 1));
    else EXPECT_EQ(pointToReceiver(point, normal, r), exact);
  }
  std::printf("receiver Gauss rule: %d of 20000 receivers, worst relative error %.2e\n", fast, worst);
  EXPECT_GT(fast, 1000);
  EXPECT_LT(worst, 0.01);
}

// Lambert's sum with the edges in vector lanes against its scalar reference: the same bits, for
// random triangles and quads in every direction and for edges through the point, of zero length
// and facing away (angles over 90 degrees).
TEST(RadiosityPhysics, VectorContourSumMatchesScalarReference) {
  if (!vectorPathsRun()) GTEST_SKIP() << "no AVX2 here: the vector path is the reference";
  Uniform uniform{777};
  const auto around = [&] { return glm::dvec3(4 * uniform() - 2, 4 * uniform() - 2, 4 * uniform() - 0.5); };
  const glm::dvec3 normal = glm::normalize(glm::dvec3(0.1, -0.2, 1));
  int differ = 0;
  for (int i = 0; i < 20000; ++i) {
    const int m = 3 + i % 2;
    glm::dvec3 v[4];
    for (int k = 0; k < m; ++k) v[k] = around();
    if (i % 7 == 0) v[1] = v[0];                  // an edge of zero length
    if (i % 11 == 0) v[2] = -0.5 * v[1];          // an edge through the point
    if (i % 13 == 0) v[0] = glm::dvec3(0, 0, 0);  // a corner at the point
    const double vector = contourSum(v, m, normal), reference = contourSumReference(v, m, normal);
    differ += std::memcmp(&vector, &reference, sizeof(double)) != 0;
  }
  EXPECT_EQ(differ, 0);
}

// The receiver's Gauss rule with its points in vector lanes against its scalar reference: the
// same bits, for random triangles and quads seen from points all around them.
TEST(RadiosityPhysics, VectorGaussSumMatchesScalarReference) {
  if (!vectorPathsRun()) GTEST_SKIP() << "no AVX2 here: the vector path is the reference";
  Uniform uniform{4242};
  const auto around = [&] { return glm::dvec3(4 * uniform() - 2, 4 * uniform() - 2, 4 * uniform() - 2); };
  int differ = 0;
  for (int i = 0; i < 20000; ++i) {
    const int m = 3 + i % 2;
    const glm::dvec3 a = around(), u = 0.3 * around(), w = 0.3 * around();
    Polygon3 p{{a, a + u, a + u + w, a + w}, m};
    const Receiver r = makeReceiver(p, glm::normalize(glm::cross(u, w)));
    const glm::dvec3 point = around(), normal = glm::normalize(around());
    const double vector = gaussSum(point, normal, r), reference = gaussSumReference(point, normal, r);
    differ += std::memcmp(&vector, &reference, sizeof(double)) != 0;
  }
  EXPECT_EQ(differ, 0);
}

// A 6 x 6 patch of a floor and its tree, and receivers from touching it to beyond the near field,
// facing every way, and walls standing on its edges and across it.
struct FloorPatch {
  Surface floor = rectangle({0, 0, 0}, {1.5, 0, 0}, {0, 1.5, 0}, 0.25, glm::dvec3(0.5));
  std::vector<Receiver> elements;
  std::vector<uint32_t> order;  // the tree's
  PatchTree tree;
  std::vector<Receiver> pieces;  // the elements in the tree's order

  FloorPatch() {
    for (const auto& c : floor.elements) {
      Polygon3 p{{}, c[3] == kNone ? 3 : 4};
      for (int k = 0; k < p.n; ++k) p.v[k] = floor.vertices[c[k]];
      elements.push_back(makeReceiver(p, floor.normal));
    }
    order.resize(elements.size());
    for (uint32_t e = 0; e < order.size(); ++e) order[e] = e;
    const HemisphereAxes axes = hemisphereAxes(glm::vec3(floor.normal));
    std::vector<Polygon3> polygons;
    std::vector<glm::dvec3> centres;
    std::vector<double> areas;
    for (const Receiver& e : elements) polygons.push_back(e.polygon), centres.push_back(e.centre), areas.push_back(e.area);
    tree = buildPatchTree(order, {polygons, centres, areas}, axes.x, axes.y);
    for (uint32_t e : order) pieces.push_back(elements[e]);
  }

  // Per element in the tree's order, its share of the light: `light` at its centre times its
  // area, over the sum.
  template <typename Light>
  std::vector<glm::dvec3> shares(const Light& light) const {
    std::vector<glm::dvec3> out;
    glm::dvec3 total{0};
    for (uint32_t e : order) total += out.emplace_back(elements[e].area * light(elements[e].centre));
    for (glm::dvec3& w : out) w /= total;
    return out;
  }

  static std::vector<Receiver> receivers() {
    const auto square = [](const glm::dvec3& centre, const glm::dvec3& facing, const glm::dvec3& t) {
      const glm::dvec3 b = glm::cross(facing, t);
      return makeReceiver(
          {{centre - 0.1 * t - 0.1 * b, centre + 0.1 * t - 0.1 * b, centre + 0.1 * t + 0.1 * b, centre - 0.1 * t + 0.1 * b}, 4},
          facing);
    };
    std::vector<Receiver> out;
    for (double height : {0.1, 0.5, 1.5, 4.0, 12.0})
      for (const glm::dvec3 facing : {glm::dvec3(0, 0, -1), glm::dvec3(1, 0, 0), glm::dvec3(0.6, 0, -0.8)})
        out.push_back(square({0.4, 0.9, height}, facing, glm::normalize(glm::cross(facing, glm::dvec3(0, 1, 0)))));
    // Walls standing on the patch's edges (all of the patch in front of their plane) and across
    // it (the patch on both sides), from their foot up.
    for (double z : {0.1, 0.4})
      for (const auto& [x, facing] : {std::pair{0.0, 1.0}, std::pair{1.5, -1.0}, std::pair{0.75, 1.0}, std::pair{0.75, -1.0}})
        out.push_back(square({x, 0.9, z}, {facing, 0, 0}, {0, 1, 0}));
    return out;
  }

  // The reference: every element of the patch integrated on its own, weighted by its share.
  void elementByElement(std::span<const glm::dvec3> shares, const Receiver& r, glm::dvec3& front, glm::dvec3& back) const {
    for (size_t k = 0; k < order.size(); ++k) {
      double f = 0, g = 0;
      areaToPolygon(elements[order[k]], 1.0, floor.normal, r, 8, 3, 3, f, g);
      front += shares[k] * f;
      back += shares[k] * g;
    }
  }
};

// The largest relative difference of `front` + `back` from the reference's, and of the fronts.
double worstDifference(const glm::dvec3& front, const glm::dvec3& back, const glm::dvec3& referenceFront,
                       const glm::dvec3& referenceBack) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) {
    const double reference = referenceFront[c] + referenceBack[c];
    if (reference != 0) worst = std::max(worst, std::abs(front[c] + back[c] - reference) / std::abs(reference));
    if (referenceFront[c] != 0) worst = std::max(worst, std::abs(front[c] - referenceFront[c]) / std::abs(referenceFront[c]));
  }
  return worst;
}

// The near field through the patch's tree (clusters far for their size by four points) against
// its reference, every element of the patch integrated on its own: the patch lit unevenly (per
// element and channel), within 1% each, in sum and on the front.
TEST(RadiosityPhysics, PatchTreeAgreesWithElementByElement) {
  const FloorPatch patch;
  const std::vector<glm::dvec3> shares =
      patch.shares([](const glm::dvec3& c) { return glm::dvec3(1 + c.x, 1 + c.y * c.y, c.x < 0.5 ? 0.0 : 1.0); });
  std::vector<NodeLight> light;
  lightPatchTree(patch.tree, shares, light);
  double worst = 0;
  for (const Receiver& r : FloorPatch::receivers()) {
    glm::dvec3 front{0}, back{0}, referenceFront{0}, referenceBack{0};
    patchToReceiver(patch.tree, light, patch.pieces, patch.floor.normal, r, 8, 3, 3, front, back);
    patch.elementByElement(shares, r, referenceFront, referenceBack);
    for (int c = 0; c < 3; ++c) ASSERT_GT(referenceFront[c] + referenceBack[c], 0);
    worst = std::max(worst, worstDifference(front, back, referenceFront, referenceBack));
  }
  std::printf("patch tree: worst relative difference from element by element %.2e\n", worst);
  EXPECT_LT(worst, 0.01);
}

// The receivers' plans, made once, serve the patch lit any way (as a patch's kept shot serves its
// later shots): for each light, a plan gives what integrating afresh in that light gives, bit for
// bit, and that agrees with element by element within 1% where the light has one sign. The
// lights: even, uneven per channel, one end dark, and part of the light negative (an overshooting
// patch's, say), whose cancelling sums are matched within 2%.
TEST(RadiosityPhysics, NearFieldPlansServeAnyLight) {
  const FloorPatch patch;
  const std::vector<Receiver> receivers = FloorPatch::receivers();
  NearPlans plans;
  for (const Receiver& r : receivers)
    planPatchToReceiver(patch.tree, patch.pieces, patch.floor.normal, r, 8, 3, 3, plans);
  ASSERT_EQ(plans.sizes.size(), receivers.size());

  const std::vector<std::vector<glm::dvec3>> lights = {
      patch.shares([](const glm::dvec3&) { return glm::dvec3(1); }),
      patch.shares([](const glm::dvec3& c) { return glm::dvec3(1 + c.x, 1 + c.y * c.y, c.x < 0.5 ? 0.0 : 1.0); }),
      patch.shares([](const glm::dvec3& c) { return glm::dvec3(c.y < 0.75 ? 0.0 : 1.0); }),
      patch.shares([](const glm::dvec3& c) { return glm::dvec3(c.x < 0.5 ? -0.5 : 1.0, 1.0, c.y < 1.0 ? -0.2 : 1.0); }),
  };
  double worst = 0, worstCancelling = 0;
  std::vector<NodeLight> light;
  for (const std::vector<glm::dvec3>& shares : lights) {
    const bool oneSign = std::all_of(shares.begin(), shares.end(), [](const glm::dvec3& w) { return glm::all(glm::greaterThanEqual(w, glm::dvec3(0))); });
    lightPatchTree(patch.tree, shares, light);
    size_t step = 0, factor = 0;
    for (size_t k = 0; k < receivers.size(); ++k) {
      const NearPlanSize size = plans.sizes[k];
      glm::dvec3 front{0}, back{0}, freshFront{0}, freshBack{0}, referenceFront{0}, referenceBack{0};
      applyPlan(patch.tree, light, std::span(plans.steps).subspan(step, size.steps), std::span(plans.factors).subspan(factor, size.factors),
                patch.floor.normal, receivers[k], front, back);
      step += size.steps;
      factor += size.factors;
      patchToReceiver(patch.tree, light, patch.pieces, patch.floor.normal, receivers[k], 8, 3, 3, freshFront,
                      freshBack);
      EXPECT_EQ(front, freshFront);
      EXPECT_EQ(back, freshBack);
      patch.elementByElement(shares, receivers[k], referenceFront, referenceBack);
      double& into = oneSign ? worst : worstCancelling;
      into = std::max(into, worstDifference(front, back, referenceFront, referenceBack));
    }
  }
  std::printf("near-field plans: worst relative difference from element by element %.2e (light of both signs %.2e)\n",
              worst, worstCancelling);
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(worstCancelling, 0.02);
}

// The tree's integral is linear in the light: two shots' factors add up to the factors of one
// shot of their summed light, to rounding. A correction after an edit takes back a patch's shots
// by one integral of all the light they sent (Solver::edit), so this is what lets it take back
// exactly what they gave.
TEST(RadiosityPhysics, NearFieldIsLinearInTheLight) {
  const FloorPatch patch;
  const std::vector<glm::dvec3> a = patch.shares([](const glm::dvec3& c) { return glm::dvec3(c.y < 0.75 ? 0.0 : 1.0); });
  const std::vector<glm::dvec3> b =
      patch.shares([](const glm::dvec3& c) { return glm::dvec3(1 + c.x, 1 + c.y * c.y, c.x < 0.5 ? -0.5 : 1.0); });
  std::vector<glm::dvec3> sum(a.size());
  for (size_t k = 0; k < a.size(); ++k) sum[k] = a[k] + b[k];
  std::vector<NodeLight> lightA, lightB, lightSum;
  lightPatchTree(patch.tree, a, lightA);
  lightPatchTree(patch.tree, b, lightB);
  lightPatchTree(patch.tree, sum, lightSum);
  double worst = 0;
  for (const Receiver& r : FloorPatch::receivers()) {
    glm::dvec3 front{0}, back{0}, sumFront{0}, sumBack{0};
    patchToReceiver(patch.tree, lightA, patch.pieces, patch.floor.normal, r, 8, 3, 3, front, back);
    patchToReceiver(patch.tree, lightB, patch.pieces, patch.floor.normal, r, 8, 3, 3, front, back);
    patchToReceiver(patch.tree, lightSum, patch.pieces, patch.floor.normal, r, 8, 3, 3, sumFront, sumBack);
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(front[c] + back[c] - sumFront[c] - sumBack[c]) / (std::abs(sumFront[c]) + std::abs(sumBack[c])));
  }
  std::printf("near-field: two lights' factors against their sum's, worst relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

// Every watt emitted is absorbed by the front of an element, arrives at the back of one, escapes
// or is still unshot. The absorbed power is computed here from the element radiances alone:
// an element of reflectance rho that reflects radiance B - E absorbed pi (B - E) A (1 - rho) / rho.
struct Balance {
  double emitted, absorbed, back, escaped, unshot;

  // What is not accounted for, over the emitted power; printed for the record.
  double residual(const char* what) const {
    const double r = (emitted - absorbed - back - escaped - unshot) / emitted;
    std::printf("%s: emitted %.6f absorbed %.6f back %.2e escaped %.6f unshot %.2e residual %.2e\n", what, emitted, absorbed,
                back, escaped, unshot, r);
    return r;
  }
};

Balance balanceOf(const std::vector<Surface>& scene, double convergence) {
  Solver solver(scene);
  solver.solve(convergence);
  Balance b{};
  const Stats& s = solver.stats();
  const auto sum = [](glm::dvec3 v) { return v.x + v.y + v.z; };
  b.emitted = sum(s.emittedPower);
  b.back = sum(s.backPower);
  b.escaped = sum(s.escapedPower);
  b.unshot = solver.unshotFraction() * b.emitted;
  for (uint32_t i = 0; i < scene.size(); ++i) {
    const std::span<const glm::dvec3> radiance = solver.elementRadiance(i);
    for (uint32_t e = 0; e < scene[i].elements.size(); ++e)
      b.absorbed += sum(kPi * (radiance[e] - scene[i].emission) * area(scene[i], e) * (1.0 - scene[i].reflectance) /
                        scene[i].reflectance);
  }
  return b;
}

std::vector<Surface> litBox(bool open, double blackReflectance) {
  std::vector<Surface> box = closedBox(1, 0.2, glm::dvec3(0.6, 0.5, 0.4), glm::dvec3(0));
  box[2].reflectance = {0.3, 0.7, 0.2};
  box[4].reflectance = {0.8, 0.2, 0.2};
  // A lamp under the ceiling, facing down.
  box.push_back(rectangle({0.4, 0.4, 0.999}, {0, 0.2, 0}, {0.2, 0, 0}, 0.1, glm::dvec3(0.5), {10, 8, 6}));
  if (open) box.erase(box.begin() + 5);
  else box[5].reflectance = glm::dvec3(blackReflectance);
  return box;
}

TEST(RadiosityPhysics, EnergyBalanceClosedBox) {
  const Balance b = balanceOf(litBox(false, 0.6), 1e-4);
  EXPECT_LT(std::abs(b.residual("closed box")), 1e-9);
  EXPECT_LT(b.escaped, 1e-9 * b.emitted);
}

// With one side open some light escapes, and it is what a nearly black wall put there absorbs.
TEST(RadiosityPhysics, EnergyBalanceOpenBox) {
  const Balance open = balanceOf(litBox(true, 0), 1e-4);
  EXPECT_LT(std::abs(open.residual("open box")), 1e-9);

  const std::vector<Surface> closed = litBox(false, 1e-3);
  Solver solver(closed);
  solver.solve(1e-4);
  const glm::dvec3 reflected = kPi * areaTimesRadiance(solver, closed[5], 5);
  const double sink = (reflected.x + reflected.y + reflected.z) * (1 - 1e-3) / 1e-3;
  std::printf("open box: escaped %.6f, absorbed by a black wall in the opening %.6f (%+.2f%%)\n", open.escaped, sink,
              100 * (open.escaped / sink - 1));
  EXPECT_GT(open.escaped, 0.05 * open.emitted);
  EXPECT_NEAR(open.escaped, sink, 0.01 * sink);
}

// A_i F_ij = A_j F_ji for two unequal, tilted rectangles: i lit by j and j lit by i.
TEST(RadiosityPhysics, Reciprocity) {
  const auto make = [](bool iEmits) {
    Surface i = rectangle({0, 0, 0}, {1, 0, 0}, {0, 2, 0}, 0.25, glm::dvec3(iEmits ? 0 : 0.5), glm::dvec3(iEmits ? 1 : 0));
    Surface j = rectangle({1.0, 0.3, 1.0}, {0, 0.8, 0}, {0.6, 0, -0.25}, 0.2, glm::dvec3(iEmits ? 0.5 : 0),
                          glm::dvec3(iEmits ? 0 : 1));
    return std::vector<Surface>{i, j};
  };
  const std::vector<Surface> a = make(true), b = make(false);
  Solver fromI(a), fromJ(b);
  fromI.solve(0);
  fromJ.solve(0);
  double areaI = 0, areaJ = 0;
  for (uint32_t e = 0; e < a[0].elements.size(); ++e) areaI += area(a[0], e);
  for (uint32_t e = 0; e < a[1].elements.size(); ++e) areaJ += area(a[1], e);
  const double fij = areaTimesRadiance(fromI, a[1], 1).x / (0.5 * areaI);
  const double fji = areaTimesRadiance(fromJ, b[0], 0).x / (0.5 * areaJ);
  std::printf("reciprocity: A_i F_ij = %.6f, A_j F_ji = %.6f (%+.3f%%)\n", areaI * fij, areaJ * fji,
              100 * (areaI * fij / (areaJ * fji) - 1));
  EXPECT_GT(fij, 0.01);
  EXPECT_NEAR(areaI * fij, areaJ * fji, 0.01 * areaJ * fji);
}

}  // namespace
}  // namespace radiosity
