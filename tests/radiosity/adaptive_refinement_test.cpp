// The refinement verdicts (thesis 5.5) on radiance laid out by hand: refine across a jump, down to
// the minimum size; coarsen only where it is smooth; no gradients out of dark noise.
#include "radiosity/adaptive_refinement.h"
#include "tests/radiosity/scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace radiosity {
namespace {

glm::dvec3 centroid(const Surface& s, uint32_t e) {
  const auto& c = s.elements[e];
  const int n = c[3] == kNone ? 3 : 4;
  glm::dvec3 sum{0};
  for (int k = 0; k < n; ++k) sum += s.vertices[c[k]];
  return sum / double(n);
}

std::vector<glm::dvec3> radianceBy(const Surface& s, const std::function<double(glm::dvec3)>& at) {
  std::vector<glm::dvec3> out;
  for (uint32_t e = 0; e < s.elements.size(); ++e) out.push_back(glm::dvec3(at(centroid(s, e))));
  return out;
}

// A 4 x 2 wall of 0.5 elements, bright left of x = 2.1 and dark right of it.
TEST(AdaptiveRefinement, RefinesTheElementsAlongAJumpAndCoarsensTheRest) {
  const Surface wall = test::rectangle({0, 0, 0}, {4, 0, 0}, {0, 2, 0}, 0.5, glm::dvec3(0.5));
  const auto radiance = radianceBy(wall, [](glm::dvec3 p) { return p.x < 2.1 ? 1.0 : 0.2; });
  const RefinementVerdicts v = judgeElements(wall, radiance, 0.01, {.threshold = 0.25, .minElementSize = 0.1});
  EXPECT_GT(v.refineCount, 0u);
  for (uint32_t e = 0; e < wall.elements.size(); ++e) {
    const double x = centroid(wall, e).x;
    const bool besideJump = std::abs(x - 2.1) < 0.5;  // the elements on either side of x = 2.1
    EXPECT_EQ(v.refine[e] != 0, besideJump) << "element at x = " << x;
    EXPECT_EQ(v.coarsen[e] != 0, !besideJump) << "element at x = " << x;
  }
}

TEST(AdaptiveRefinement, StopsAtTheMinimumSize) {
  const Surface wall = test::rectangle({0, 0, 0}, {4, 0, 0}, {0, 2, 0}, 0.5, glm::dvec3(0.5));
  const auto radiance = radianceBy(wall, [](glm::dvec3 p) { return p.x < 2.1 ? 1.0 : 0.2; });
  // Children of 0.5 elements are 0.25 wide: allowed at 0.25, not above.
  EXPECT_GT(judgeElements(wall, radiance, 0.01, {.threshold = 0.25, .minElementSize = 0.25}).refineCount, 0u);
  EXPECT_EQ(judgeElements(wall, radiance, 0.01, {.threshold = 0.25, .minElementSize = 0.26}).refineCount, 0u);
}

TEST(AdaptiveRefinement, SmallDifferencesAreNotGradientsAndDarkNoiseIsNotEither) {
  const Surface wall = test::rectangle({0, 0, 0}, {4, 0, 0}, {0, 2, 0}, 0.5, glm::dvec3(0.5));
  // A gentle ramp: 10% from element to element, under a threshold of 25% and over its quarter:
  // neither refined nor coarsened.
  const auto ramp = radianceBy(wall, [](glm::dvec3 p) { return std::exp(0.2 * p.x); });
  const RefinementVerdicts gentle = judgeElements(wall, ramp, 0.01, {.threshold = 0.25});
  EXPECT_EQ(gentle.refineCount, 0u);
  EXPECT_EQ(gentle.coarsenCount, 0u);
  // Dark noise: 0.001 against 0.003 is a jump of 100% of its mean, but not of a floor of 0.1.
  const auto noise = radianceBy(wall, [](glm::dvec3 p) { return std::fmod(std::floor(2 * p.x), 2.0) == 0 ? 0.001 : 0.003; });
  EXPECT_GT(judgeElements(wall, noise, 0, {.threshold = 0.25}).refineCount, 0u);
  EXPECT_EQ(judgeElements(wall, noise, 0.1, {.threshold = 0.25}).refineCount, 0u);
}

TEST(AdaptiveRefinement, LuminanceWeighsGreenMost) {
  EXPECT_NEAR(luminance(glm::dvec3(1)), 1.0, 1e-12);
  EXPECT_GT(luminance({0, 1, 0}), luminance({1, 0, 0}));
  EXPECT_GT(luminance({1, 0, 0}), luminance({0, 0, 1}));
}

}  // namespace
}  // namespace radiosity
