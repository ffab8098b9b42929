// Edits (Solver::edit, Chen 1990): the light is corrected, not shot again, and comes out as a
// fresh solve of the edited scene would.
#include "radiosity/radiosity.h"
#include "tests/radiosity/scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace radiosity {
namespace {

// A closed unit room lit by a panel under its ceiling, with a horizontal board standing in the
// light at `height`, offset by `dx` along x.
std::vector<Surface> roomWithBoard(double dx, double height) {
  std::vector<Surface> room = test::closedBox(1, 0.125, glm::dvec3(0.6), glm::dvec3(0));
  room.push_back(test::rectangle({0.4, 0.4, 0.999}, {0, 0.2, 0}, {0.2, 0, 0}, 0.1, glm::dvec3(0.5), {10, 10, 10}));
  // The board faces up (its top is lit) and down (its underside casts the shadow).
  room.push_back(test::rectangle({0.3 + dx, 0.3, height}, {0.4, 0, 0}, {0, 0.4, 0}, 0.1, glm::dvec3(0.6)));
  room.push_back(test::rectangle({0.3 + dx, 0.3, height}, {0, 0.4, 0}, {0.4, 0, 0}, 0.1, glm::dvec3(0.6)));
  return room;
}

// Mean absolute difference of element radiance over the mean, all surfaces.
double difference(const Solver& a, const Solver& b) {
  double diff = 0, level = 0;
  for (uint32_t s = 0; s < a.surfaceCount(); ++s) {
    const auto ra = a.elementRadiance(s), rb = b.elementRadiance(s);
    for (size_t e = 0; e < ra.size(); ++e)
      for (int c = 0; c < 3; ++c) diff += std::abs(ra[e][c] - rb[e][c]), level += std::abs(rb[e][c]);
  }
  return diff / level;
}

double ledgerResidual(const Solver& solver) {
  const Stats& s = solver.stats();
  const auto sum = [](const glm::dvec3& v) { return v.x + v.y + v.z; };
  const double emitted = sum(s.emittedPower);
  return std::abs(emitted - sum(s.absorbedPower) - sum(s.backPower) - sum(s.escapedPower) - sum(s.removedPower) -
                  sum(solver.unshotPower())) / emitted;
}

TEST(RadiosityEdit, AMovedBoardGivesWhatAFreshSolveGives) {
  Solver solver(roomWithBoard(0, 0.4));
  solver.solve(1e-3);
  const double before = solver.unshotFraction();
  solver.edit(roomWithBoard(0.25, 0.4));
  EXPECT_GT(solver.pendingCorrections(), 0u);
  EXPECT_GT(solver.unshotFraction(), before);  // the light still to correct counts as unshot
  const uint64_t shotsBefore = solver.stats().shots;
  solver.solve(1e-3);
  EXPECT_EQ(solver.pendingCorrections(), 0u);
  EXPECT_LT(ledgerResidual(solver), 1e-12);

  Solver fresh(roomWithBoard(0.25, 0.4));
  fresh.solve(1e-3);
  const double error = difference(solver, fresh);
  std::printf("moved board: %llu corrections and %llu shots after the edit (a fresh solve: %llu shots); "
              "difference %.3f%%\n",
              static_cast<unsigned long long>(solver.stats().corrections),
              static_cast<unsigned long long>(solver.stats().shots - shotsBefore),
              static_cast<unsigned long long>(fresh.stats().shots), 100 * error);
  EXPECT_LT(error, 0.01);
  EXPECT_LT(solver.stats().shots - shotsBefore, fresh.stats().shots);
}

TEST(RadiosityEdit, MovingAndMovingBackRestoresTheSolution) {
  Solver solver(roomWithBoard(0, 0.4));
  solver.solve(1e-3);
  Solver unmoved(roomWithBoard(0, 0.4));
  unmoved.solve(1e-3);
  solver.edit(roomWithBoard(0.3, 0.2));
  solver.solve(1e-3);
  EXPECT_GT(difference(solver, unmoved), 0.02);
  solver.edit(roomWithBoard(0, 0.4));
  solver.solve(1e-3);
  EXPECT_LT(difference(solver, unmoved), 0.005);
  EXPECT_LT(ledgerResidual(solver), 1e-12);
}

// A surface meshed again keeps the light of the elements it keeps; the new ones gather theirs.
TEST(RadiosityEdit, ARemeshedSurfaceGathersItsLight) {
  std::vector<Surface> scene = roomWithBoard(0, 0.4);
  Solver solver(scene);
  solver.solve(1e-3);
  std::vector<Surface> finer = scene;
  finer[0] = test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.0625, glm::dvec3(0.6));  // the floor, finer
  const Surface& floor = scene[0];
  ASSERT_EQ(finer[0].normal, floor.normal);
  solver.edit(finer);
  solver.solve(1e-3);
  Solver fresh(finer);
  fresh.solve(1e-3);
  EXPECT_LT(difference(solver, fresh), 0.01);
  EXPECT_LT(ledgerResidual(solver), 1e-12);
}

TEST(RadiosityEdit, NoChangeNoCorrectionsAndAWrongSceneIsRefused) {
  Solver solver(roomWithBoard(0, 0.4));
  solver.solve(1e-2);
  solver.edit(roomWithBoard(0, 0.4));
  EXPECT_EQ(solver.pendingCorrections(), 0u);
  std::vector<Surface> fewer = roomWithBoard(0, 0.4);
  fewer.pop_back();
  EXPECT_THROW(solver.edit(fewer), std::invalid_argument);
}

}  // namespace
}  // namespace radiosity
