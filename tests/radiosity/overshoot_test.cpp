// Overshooting (SolverSettings::overshoot, radiosity/overshoot.h): ledgers exact with the negative
// unshot light it leaves, a furnace's exact light, and edits still corrected. The same light in
// fewer shots on the shipped Cornell box: tests/engine/cornell_light_test.cpp.
#include "radiosity/radiosity.h"

#include "tests/radiosity/scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace radiosity {
namespace {

SolverSettings overshooting() {
  SolverSettings settings;
  settings.overshoot = true;
  return settings;
}

using test::channelSum;
using test::meanDifference;
using test::quad;
using test::roomWithBoard;
using test::worstDifference;

// A closed room of three materials lit by a panel: some patches are left with negative unshot
// light, and the ledgers still close with the signed unshot term, at every step.
TEST(RadiosityOvershoot, LedgersStayExactWithNegativeUnshotLight) {
  std::vector<Surface> room = test::closedBox(1, 0.2, glm::dvec3(0.6, 0.5, 0.4), glm::dvec3(0));
  room[2].reflectance = {0.3, 0.7, 0.2};
  room[4].reflectance = {0.8, 0.2, 0.2};
  room.push_back(test::rectangle({0.4, 0.4, 0.999}, {0, 0.2, 0}, {0.2, 0, 0}, 0.1, glm::dvec3(0.5), {10, 8, 6}));
  Solver solver(room, overshooting());
  bool negative = false;
  double worst = 0;
  while (!solver.converged(1e-4) && solver.step()) {
    worst = std::max(worst, solver.ledgerResidual());
    // Magnitudes summed exceed the signed sum only where some unshot light is negative.
    negative = negative || solver.unshotFraction() * channelSum(solver.stats().emittedPower) >
                               channelSum(solver.unshotPower()) * (1 + 1e-9);
  }
  EXPECT_TRUE(negative);
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(solver.stats().escapedPower.x, 1e-9 * solver.stats().emittedPower.x);
}

// A big floor right under a tiny lamp: from the floor's centre the lamp looks 45 times larger
// than it is from the floor's average point, so the floor's overshoot is more than the lamp will
// ever send it and leaves the floor the largest (negative) unshot power. The floor must then
// shoot that back rather than the same overshoot again and again (the kitchen stalled at 15%).
TEST(RadiosityOvershoot, AnOvershootThatDoesNotComeBackIsShotBack) {
  const std::vector<Surface> scene{
      quad({-3, -3, 0}, {6, 0, 0}, {0, 6, 0}, glm::dvec3(0.9)),
      quad({-0.05, -0.05, 0.5}, {0, 0.1, 0}, {0.1, 0, 0}, glm::dvec3(0.9), glm::dvec3(1)),
      quad({2, -3, 3}, {0, 6, 0}, {1, 0, 0}, glm::dvec3(0), glm::dvec3(10)),
  };
  Solver solver(scene, overshooting());
  const uint64_t shots = solver.solve(1e-6, 1000);
  EXPECT_TRUE(solver.converged(1e-6)) << shots << " shots";
  EXPECT_LT(shots, 100u);
  EXPECT_LT(solver.ledgerResidual(), 1e-12);
}

// A furnace: exact E / (1 - rho) everywhere within 0.1%, as without overshooting.
TEST(RadiosityOvershoot, FurnaceWithShootingPatches) {
  const glm::dvec3 rho{0.5, 0.25, 0.8}, emission{1, 2, 0.5};
  std::vector<Surface> box = test::closedBox(1, 0.25, rho, emission);
  for (Surface& s : box) s.patchOfElement = groupIntoPatches(s, 0.5);
  Solver solver(box, overshooting());
  solver.solve(1e-7);
  const glm::dvec3 exact = emission / (1.0 - rho);
  double worst = 0;
  for (uint32_t s = 0; s < box.size(); ++s)
    for (const glm::dvec3& b : solver.elementRadiance(s))
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(b[c] / exact[c] - 1));
  EXPECT_LT(worst, 1e-3);
}

// A board moved in a lit room: the corrected light is what a fresh solve gives, both overshooting.
TEST(RadiosityOvershoot, AnEditIsCorrectedAsAFreshSolve) {
  Solver solver(roomWithBoard(0, 0.4), overshooting());
  solver.solve(1e-4);
  solver.edit(test::changesOf(roomWithBoard(0.25, 0.4), test::kBoard));
  solver.solve(1e-4);
  EXPECT_LT(solver.ledgerResidual(), 1e-12);
  Solver fresh(roomWithBoard(0.25, 0.4), overshooting());
  fresh.solve(1e-4);
  const double worst = worstDifference(solver, fresh);
  std::printf("overshooting, moved board: worst element difference from a fresh solve %.3f%%\n", 100 * worst);
  EXPECT_LT(worst, 0.01);
}

}  // namespace
}  // namespace radiosity
