// Edits (Solver::edit, Chen 1990): the light is corrected, not shot again, and comes out as a
// fresh solve of the edited scene would.
#include "radiosity/radiosity.h"
#include "tests/radiosity/scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace radiosity {
namespace {

using test::ledgerResidual;
using test::meanDifference;
using test::roomWithBoard;

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
  const double error = meanDifference(solver, fresh);
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
  EXPECT_GT(meanDifference(solver, unmoved), 0.02);
  solver.edit(roomWithBoard(0, 0.4));
  solver.solve(1e-3);
  EXPECT_LT(meanDifference(solver, unmoved), 0.005);
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
  EXPECT_LT(meanDifference(solver, fresh), 0.01);
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
