// The solver's parts: shooter choice, the convergence measure, substructuring, vertex radiance,
// receivers of very different sizes, determinism.
#include "radiosity/radiosity.h"

#include "tests/radiosity/scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <malloc.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace radiosity {
namespace {

using test::area;
using test::closedBox;
using test::quad;
using test::rectangle;

constexpr double kPi = std::numbers::pi;

TEST(RadiositySolver, ShootsLargestUnshotPowerFirst) {
  // A small bright lamp (power pi x 10 x 0.01) and a large dim one (pi x 1 x 1) facing a floor.
  const std::vector<Surface> scene{
      quad({0, 0, 2}, {0.1, 0, 0}, {0, -0.1, 0}, glm::dvec3(0), glm::dvec3(10)),
      quad({2, 0, 2}, {1, 0, 0}, {0, -1, 0}, glm::dvec3(0), glm::dvec3(1)),
      quad({-2, -2, 0}, {6, 0, 0}, {0, 6, 0}, glm::dvec3(0.5)),
  };
  Solver solver(scene);
  ASSERT_TRUE(solver.nextShooter());
  EXPECT_EQ(solver.nextShooter()->surface, 1u);
  // It shoots all of its radiance, 1 in every channel, over its area of 1.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(solver.nextShooter()->unshotPower[c], kPi, 1e-12);
  ASSERT_TRUE(solver.step());
  EXPECT_EQ(solver.nextShooter()->surface, 2u);  // the floor now holds more than the small lamp
  ASSERT_TRUE(solver.step());
  EXPECT_EQ(solver.nextShooter()->surface, 0u);
  EXPECT_EQ(solver.stats().shots, 2u);
}

TEST(RadiositySolver, ConvergenceIsUnshotOverEmittedPower) {
  // A lamp facing a black-backed receiver of reflectance 0.5 and nothing else.
  const std::vector<Surface> scene{quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::dvec3(0), glm::dvec3(2)),
                                   quad({0, 0, 1}, {0, 1, 0}, {1, 0, 0}, glm::dvec3(0.5))};
  Solver solver(scene);
  EXPECT_DOUBLE_EQ(solver.unshotFraction(), 1.0);
  EXPECT_FALSE(solver.converged(0.5));
  ASSERT_TRUE(solver.step());
  // What is unshot now is what the receiver reflects: 0.5 x the factor 0.19982.
  EXPECT_NEAR(solver.unshotFraction(), 0.5 * 0.19982, 0.002);
  EXPECT_TRUE(solver.converged(0.2));
  ASSERT_TRUE(solver.step());
  EXPECT_EQ(solver.unshotFraction(), 0.0);  // the lamp reflects nothing
  EXPECT_FALSE(solver.step());
  EXPECT_FALSE(solver.nextShooter());
  EXPECT_EQ(Solver(std::vector<Surface>{scene[1]}).unshotFraction(), 0.0);  // nothing emits
}

TEST(RadiositySolver, GroupsElementsIntoPatchesOfTheGivenSize) {
  const Surface wall = rectangle({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, 0.25, glm::dvec3(0.5));
  const std::vector<uint32_t> patches = groupIntoPatches(wall, 0.5);
  ASSERT_EQ(patches.size(), wall.elements.size());
  uint32_t count = 0;
  for (uint32_t p : patches) count = std::max(count, p + 1);
  EXPECT_EQ(count, 8u);  // 2 x 1 in squares of 0.5
  std::vector<double> patchArea(count, 0.0);
  for (uint32_t e = 0; e < patches.size(); ++e) patchArea[patches[e]] += area(wall, e);
  for (double a : patchArea) EXPECT_NEAR(a, 0.25, 1e-12);
  EXPECT_EQ(groupIntoPatches(wall, 0.5), patches);  // deterministic
}

// Substructuring: patches shoot fewer times than their elements would, and the elements still
// receive their own light.
TEST(RadiositySolver, SubstructuringShootsLessForTheSameLight) {
  std::vector<Surface> alone = closedBox(1, 0.125, glm::dvec3(0.5), glm::dvec3(0));
  alone[1].emission = glm::dvec3(1);  // the ceiling glows
  std::vector<Surface> grouped = alone;
  for (Surface& s : grouped) s.patchOfElement = groupIntoPatches(s, 0.5);
  Solver a(alone), b(grouped);
  EXPECT_EQ(b.patchCount(), 24u);
  EXPECT_EQ(a.patchCount(), a.elementCount());
  a.solve(1e-5);
  b.solve(1e-5);
  std::printf("substructuring: %llu shots alone, %llu with patches\n", static_cast<unsigned long long>(a.stats().shots),
              static_cast<unsigned long long>(b.stats().shots));
  EXPECT_LT(b.stats().shots * 3, a.stats().shots);
  // The floor's radiance varies over its elements (brighter in the middle), the same either way.
  const std::span<const glm::dvec3> fa = a.elementRadiance(0), fb = b.elementRadiance(0);
  double lo = 1e9, hi = 0;
  for (size_t e = 0; e < fa.size(); ++e) {
    EXPECT_NEAR(fb[e].x, fa[e].x, 0.01 * fa[e].x) << e;
    lo = std::min(lo, fa[e].x), hi = std::max(hi, fa[e].x);
  }
  EXPECT_GT(hi, 1.2 * lo);
}

TEST(RadiositySolver, VertexRadianceIsTheAreaWeightedMeanOfItsElements) {
  // A lamp lights a floor unevenly; each floor vertex gets the mean of its elements by area.
  const std::vector<Surface> scene{quad({0, 0, 1}, {0, 0.3, 0}, {0.3, 0, 0}, glm::dvec3(0), glm::dvec3(5)),
                                   rectangle({-1, -1, 0}, {2.5, 0, 0}, {0, 2, 0}, 0.4, glm::dvec3(0.6))};
  Solver solver(scene);
  solver.solve(0);
  const Surface& floor = scene[1];
  const std::span<const glm::dvec3> elements = solver.elementRadiance(1);
  std::vector<glm::dvec3> sum(floor.vertices.size(), glm::dvec3(0));
  std::vector<double> weight(floor.vertices.size(), 0);
  for (uint32_t e = 0; e < floor.elements.size(); ++e)
    for (int k = 0; k < (floor.elements[e][3] == kNone ? 3 : 4); ++k) {
      sum[floor.elements[e][k]] += area(floor, e) * elements[e];
      weight[floor.elements[e][k]] += area(floor, e);
    }
  const std::vector<glm::dvec3> vertices = solver.vertexRadiance(1, glm::dvec3(0));
  ASSERT_EQ(vertices.size(), floor.vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) EXPECT_NEAR(vertices[v].x, sum[v].x / weight[v], 1e-12 * sum[v].x / weight[v]);
  // A corner belongs to one element only.
  uint32_t owner = 0;
  for (uint32_t e = 0; e < floor.elements.size(); ++e)
    for (uint32_t c : floor.elements[e])
      if (c == 0) owner = e;
  EXPECT_EQ(vertices[0], elements[owner]);
  // The ambient term adds reflectance x ambient.
  const std::vector<glm::dvec3> shown = solver.vertexRadiance(1, solver.ambient());
  for (size_t v = 0; v < vertices.size(); ++v) EXPECT_NEAR(shown[v].x, vertices[v].x + 0.6 * solver.ambient().x, 1e-12);
}

// A tiny receiver near the shooter and a huge one far away subtend the same solid angle: they
// receive the same power per steradian, so their radiances differ by their area ratio (10^10).
// Their factors are a couple of hemisphere pixels, so pixel counts would be off by up to half.
TEST(RadiositySolver, TinyAndHugeReceiversAtEqualSolidAngle) {
  const glm::dvec3 towardTiny = glm::normalize(glm::dvec3(0.5, 0, 1)), towardHuge = glm::normalize(glm::dvec3(-0.5, 0.1, 1));
  const auto facing = [](glm::dvec3 centre, glm::dvec3 toward, double side) {
    const glm::dvec3 u = glm::normalize(glm::cross(toward, glm::dvec3(0, 1, 0))) * side;
    const glm::dvec3 v = glm::cross(u, toward);  // u x v points back along -toward
    return quad(centre - 0.5 * u - 0.5 * v, u, v, glm::dvec3(0.5));
  };
  const double tinySide = 1e-4, hugeSide = 1, tinyDistance = 0.009, hugeDistance = tinyDistance * hugeSide / tinySide;
  const std::vector<Surface> scene{quad({-5e-4, -5e-4, 0}, {1e-3, 0, 0}, {0, 1e-3, 0}, glm::dvec3(0), glm::dvec3(1)),
                                   facing(towardTiny * tinyDistance, towardTiny, tinySide),
                                   facing(towardHuge * hugeDistance, towardHuge, hugeSide)};
  Solver solver(scene);
  solver.step();
  // Expected: rho x E x F x A_s / A_r with F = A_r cos / (pi d^2) (the receivers face the shooter).
  const double tiny = solver.elementRadiance(1)[0].x, huge = solver.elementRadiance(2)[0].x;
  const double expectTiny = 0.5 * 1e-6 * towardTiny.z / (kPi * tinyDistance * tinyDistance);
  const double expectHuge = 0.5 * 1e-6 * towardHuge.z / (kPi * hugeDistance * hugeDistance);
  std::printf("tiny receiver %.6e (expected %.6e), huge %.6e (expected %.6e), %llu small receivers\n", tiny, expectTiny,
              huge, expectHuge, static_cast<unsigned long long>(solver.stats().smallReceivers));
  EXPECT_NEAR(tiny, expectTiny, 0.01 * expectTiny);
  EXPECT_NEAR(huge, expectHuge, 0.01 * expectHuge);
}

// A tiny receiver behind an occluder gets nothing, its unoccluded twin gets its share: the item
// buffer's visibility is read in the right pixel.
TEST(RadiositySolver, SmallReceiverBehindOccluderIsDark) {
  const std::vector<Surface> scene{
      quad({-0.05, -0.05, 0}, {0.1, 0, 0}, {0, 0.1, 0}, glm::dvec3(0), glm::dvec3(1)),
      quad({0.99, 0.3, 2.01}, {0, 0.02, 0}, {0.02, 0, 0}, glm::dvec3(0.5)),   // behind the occluder
      quad({-1.01, 0.3, 2.01}, {0, 0.02, 0}, {0.02, 0, 0}, glm::dvec3(0.5)),  // in the open
      quad({0.3, 0.05, 1.0}, {0, 0.3, 0}, {0.4, 0, 0}, glm::dvec3(0)),        // the occluder, facing down
  };
  Solver solver(scene);
  solver.step();
  EXPECT_GT(solver.stats().smallReceivers, 0u);
  EXPECT_EQ(solver.elementRadiance(1)[0].x, 0.0);
  EXPECT_GT(solver.elementRadiance(2)[0].x, 0.0);
}

TEST(RadiositySolver, DeterministicAndIndependentOfGraphicsProcessors) {
  std::vector<Surface> scene = closedBox(1, 0.25, glm::dvec3(0.6), glm::dvec3(0));
  scene.push_back(rectangle({0.3, 0.3, 0.999}, {0, 0.3, 0}, {0.3, 0, 0}, 0.1, glm::dvec3(0.5), glm::dvec3(4)));
  SolverSettings two;
  two.graphicsProcessors = 2;
  Solver a(scene), b(scene), c(scene, two);
  a.solve(0.01);
  b.solve(0.01);
  c.solve(0.01);
  for (uint32_t s = 0; s < scene.size(); ++s)
    for (size_t e = 0; e < scene[s].elements.size(); ++e) {
      EXPECT_EQ(a.elementRadiance(s)[e], b.elementRadiance(s)[e]);
      EXPECT_EQ(a.elementRadiance(s)[e], c.elementRadiance(s)[e]);
    }
}

// A patch's kept frame and judgement (SolverSettings::shotCacheBytes) stand for new ones bit for
// bit, with its light spread unevenly over its elements (overshoot) and a budget too small for all.
TEST(RadiositySolver, KeptShotsGiveTheSameLight) {
  std::vector<Surface> scene = closedBox(1, 0.25, glm::dvec3(0.6), glm::dvec3(0));
  scene.push_back(rectangle({0.3, 0.3, 0.999}, {0, 0.3, 0}, {0.3, 0, 0}, 0.1, glm::dvec3(0.5), glm::dvec3(4)));
  for (Surface& s : scene) s.patchOfElement = groupIntoPatches(s, 0.5);
  SolverSettings none, some, all;
  none.shotCacheBytes = 0;
  some.shotCacheBytes = 64 << 10;
  for (SolverSettings* s : {&none, &some, &all}) s->overshoot = true;
  Solver a(scene, none), b(scene, some), c(scene, all);
  a.solve(0.001);
  b.solve(0.001);
  c.solve(0.001);
  EXPECT_EQ(a.stats().reusedShots, 0u);
  EXPECT_GT(b.stats().reusedShots, 0u);
  EXPECT_GT(c.stats().reusedShots, b.stats().reusedShots);
  EXPECT_EQ(a.stats().shots, c.stats().shots);
  EXPECT_EQ(a.stats().smallReceivers, c.stats().smallReceivers);
  EXPECT_EQ(a.stats().nearReceivers, c.stats().nearReceivers);
  for (uint32_t s = 0; s < scene.size(); ++s)
    for (size_t e = 0; e < scene[s].elements.size(); ++e) {
      EXPECT_EQ(a.elementRadiance(s)[e], b.elementRadiance(s)[e]);
      EXPECT_EQ(a.elementRadiance(s)[e], c.elementRadiance(s)[e]);
    }
}

// A shot larger than SolverSettings::shotCacheRecordBytes is not kept, however much the budget
// has room for: a building's shots would fill it with a few patches'.
TEST(RadiositySolver, KeepsNoShotLargerThanItsRecordBound) {
  std::vector<Surface> scene = closedBox(1, 0.25, glm::dvec3(0.6), glm::dvec3(0));
  scene.push_back(rectangle({0.3, 0.3, 0.999}, {0, 0.3, 0}, {0.3, 0, 0}, 0.1, glm::dvec3(0.5), glm::dvec3(4)));
  for (Surface& s : scene) s.patchOfElement = groupIntoPatches(s, 0.5);
  SolverSettings small;
  small.shotCacheRecordBytes = 1024;
  Solver a(scene), b(scene, small);
  a.solve(0.01);
  b.solve(0.01);
  EXPECT_GT(a.stats().reusedShots, 0u);
  EXPECT_EQ(b.stats().reusedShots, 0u);
  EXPECT_EQ(a.stats().shots, b.stats().shots);
}

// A shot's receivers are judged in chunks whose storage is kept for the next shot; beyond
// SolverSettings::scratchBytes a shot gives back what it left more than half spare. A box's
// ceiling shot as one patch judges every element near; the small patches that shoot after it
// need a fraction of that. Unbounded, the chunks keep the ceiling's storage and gain more (on a
// building, 800 MB for shots that needed 40); bounded, they hold about what those shots need.
TEST(RadiositySolver, GivesBackScratchAShotLeftSpareBeyondItsBound) {
  std::vector<Surface> box = closedBox(1, 1.0 / 32, glm::dvec3(0.5), glm::dvec3(0));
  box[1].emission = glm::dvec3(1);  // the ceiling
  for (size_t s = 0; s < box.size(); ++s) box[s].patchOfElement = groupIntoPatches(box[s], s == 1 ? 2.0 : 4.0 / 32);
  SolverSettings bounded;
  bounded.scratchBytes = 0;
  Solver a(box), b(box, bounded);
  ASSERT_TRUE(a.step());
  ASSERT_TRUE(b.step());
  const uint64_t ceiling = a.stats().scratchBytes;
  for (int shot = 0; shot < 4; ++shot) {
    ASSERT_TRUE(a.step());
    ASSERT_TRUE(b.step());
  }
  EXPECT_GE(a.stats().scratchBytes, ceiling);
  EXPECT_LT(b.stats().scratchBytes, ceiling / 3);
  for (uint32_t s = 0; s < box.size(); ++s)
    for (size_t e = 0; e < box[s].elements.size(); ++e) EXPECT_EQ(a.elementRadiance(s)[e], b.elementRadiance(s)[e]);
}

// A shot that is not to be kept judges each chunk of receivers in its graphics processor's
// scratch and drops the judgement once the chunk is integrated; a shot that may be kept holds its
// chunks' judgements for keeping until they pass what a record may hold. A box's ceiling shot as
// one patch judges every element near: kept, its chunks hold it all; with no record allowed,
// little; with a record that its frame fits and its judgements do not, what came before they
// passed it. The light is the same bit for bit.
TEST(RadiositySolver, AShotNotKeptDropsItsJudgementsAsItGoes) {
  std::vector<Surface> box = closedBox(1, 1.0 / 32, glm::dvec3(0.5), glm::dvec3(0));
  box[1].emission = glm::dvec3(1);  // the ceiling
  for (size_t s = 0; s < box.size(); ++s) box[s].patchOfElement = groupIntoPatches(box[s], s == 1 ? 2.0 : 4.0 / 32);
  SolverSettings none, part;
  none.shotCacheRecordBytes = 0;
  part.shotCacheRecordBytes = 256 << 10;
  Solver kept(box), unkept(box, none), passed(box, part);
  for (Solver* solver : {&kept, &unkept, &passed}) ASSERT_TRUE(solver->step());
  const uint64_t all = kept.stats().scratchBytes;
  EXPECT_LT(unkept.stats().scratchBytes, all / 3);
  EXPECT_GT(passed.stats().scratchBytes, unkept.stats().scratchBytes);
  EXPECT_LT(passed.stats().scratchBytes, all / 2);
  for (Solver* solver : {&kept, &unkept, &passed}) solver->solve(0.01, 30);
  EXPECT_GT(kept.stats().reusedShots, 0u);
  EXPECT_EQ(passed.stats().reusedShots, 0u);
  for (uint32_t s = 0; s < box.size(); ++s)
    for (size_t e = 0; e < box[s].elements.size(); ++e) {
      EXPECT_EQ(kept.elementRadiance(s)[e], unkept.elementRadiance(s)[e]);
      EXPECT_EQ(kept.elementRadiance(s)[e], passed.elementRadiance(s)[e]);
    }
}

// The heap a solver holds per element (issue 20: the White Room's 2.6 million elements must fit
// in 2.5 GB with the scene, its meshes and the display): constructed, and after its first shot.
// Measured between a box of N elements and one of 4 N, which cancels what does not grow with the
// elements (the emulated Pixel-Planes 5's memories). Constructed, it held about 1.4 KB an
// element: a Receiver of 448 bytes, every patch's tree (about 540 bytes an element) whether it
// shoots or not, five item-buffer targets of 120 bytes, arrays grown by doubling. A shot adds its
// scratch: in this box every element is a small receiver, judged and kept with the shot.
TEST(RadiositySolver, HoldsUnderHalfAKilobyteAnElement) {
  struct Held {
    size_t elements = 0;
    double constructed = 0, shot = 0;
  };
  const auto heldBy = [](double patchSize) {
    std::vector<Surface> box = closedBox(1, patchSize, glm::dvec3(0.5), glm::dvec3(0));
    box[1].emission = glm::dvec3(1);  // the ceiling
    Held held;
    for (Surface& s : box) s.patchOfElement = groupIntoPatches(s, 4 * patchSize), held.elements += s.elements.size();
    const auto heap = [] {
      const struct mallinfo2 m = mallinfo2();
      return static_cast<double>(m.uordblks + m.hblkhd);
    };
    const double before = heap();
    Solver solver(box);
    held.constructed = heap() - before;
    EXPECT_TRUE(solver.step());
    held.shot = heap() - before;
    return held;
  };
  const Held small = heldBy(1.0 / 64), large = heldBy(1.0 / 128);
  // The sanitizers' allocators keep their own counts: mallinfo2 sees nothing.
  if (large.constructed <= 0) GTEST_SKIP() << "mallinfo2 counts no heap under this allocator";
  ASSERT_GT(large.elements, 3 * small.elements);
  const auto perElement = [&](double Held::*bytes) {
    return (large.*bytes - small.*bytes) / static_cast<double>(large.elements - small.elements);
  };
  std::printf("solver: %.0f bytes an element constructed, %.0f after a shot (%zu and %zu elements)\n",
              perElement(&Held::constructed), perElement(&Held::shot), small.elements, large.elements);
  EXPECT_LT(perElement(&Held::constructed), 512);
  EXPECT_LT(perElement(&Held::shot), 768);
}

TEST(RadiositySolver, RefusesBadInput) {
  Surface s = quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::dvec3(0.5));
  s.elements[0][2] = 7;
  EXPECT_THROW(Solver(std::vector<Surface>{s}), std::invalid_argument);
  s = quad({0, 0, 0}, {1, 0, 0}, {0, 0, 0}, glm::dvec3(0.5));
  EXPECT_THROW(Solver(std::vector<Surface>{s}), std::invalid_argument);
  s = quad({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, glm::dvec3(0.5));
  s.patchOfElement = {0, 1};
  EXPECT_THROW(Solver(std::vector<Surface>{s}), std::invalid_argument);
}

}  // namespace
}  // namespace radiosity
