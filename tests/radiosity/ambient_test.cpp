#include "radiosity/ambient.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace radiosity {
namespace {

// A closed box of one material: every surface sees the same light, so the exact radiance is
// E / (1 - rho) everywhere, and emission plus rho x ambient must give it.
TEST(RadiosityAmbient, FurnaceIsExact) {
  const glm::dvec3 rho{0.5, 0.25, 0.9}, emission{1, 2, 0.5};
  std::vector<SurfaceLight> box(6, SurfaceLight{2.0, rho, emission});
  const glm::dvec3 ambient = ambientRadiance(box);
  const glm::dvec3 displayed = emission + rho * ambient;
  const glm::dvec3 exact = emission / (1.0 - rho);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(displayed[c], exact[c], 1e-12 * exact[c]);
}

TEST(RadiosityAmbient, ScalesWithEmittedPowerNotEmitterCount) {
  // One emitter of area 1 or two of area 0.5 emit the same power into the same room.
  const SurfaceLight wall{10, glm::dvec3{0.5}, glm::dvec3{0}};
  const std::vector<SurfaceLight> one{wall, {1, glm::dvec3{0.5}, glm::dvec3{4}}};
  const std::vector<SurfaceLight> two{wall, {0.5, glm::dvec3{0.5}, glm::dvec3{4}}, {0.5, glm::dvec3{0.5}, glm::dvec3{4}}};
  EXPECT_NEAR(ambientRadiance(one).x, ambientRadiance(two).x, 1e-12);
  EXPECT_NEAR(ambientRadiance(one).x, 4.0 / 11.0 / 0.5, 1e-12);
}

TEST(RadiosityAmbient, DarkSceneAndEmptySceneGiveZero) {
  EXPECT_EQ(ambientRadiance(std::vector<SurfaceLight>{{1, glm::dvec3{0.5}, glm::dvec3{0}}}), glm::dvec3{0});
  EXPECT_EQ(ambientRadiance({}), glm::dvec3{0});
}

TEST(RadiosityAmbient, PerfectReflectorsStayFinite) {
  const glm::dvec3 a = ambientRadiance(std::vector<SurfaceLight>{{1, glm::dvec3{1}, glm::dvec3{1}}});
  EXPECT_TRUE(std::isfinite(a.x));
  EXPECT_NEAR(a.x, 1000, 1e-6);
}

}  // namespace
}  // namespace radiosity
