// A Mesher gives a repeat of a polygon met before (the same shape elsewhere in the plane, or
// turned) the mesh meshing it would give, without meshing it; anything else is meshed.
#include "mesher/mesher.h"

#include "tests/mesher/random_polygons.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace mesher {
namespace {

// An L-shaped room with a pillar, in inches: turned by quarter turns, or moved by whole inches
// nearby (where the rounding allowed for is the same), it comes into the tree bit for bit alike.
PolygonWithHoles room() {
  return {{{0, 0}, {240, 0}, {240, 96}, {132, 96}, {132, 180}, {0, 180}}, {{{40, 40}, {40, 52.5}, {52.5, 52.5}, {52.5, 40}}}};
}

PolygonWithHoles mapped(const PolygonWithHoles& polygon, const std::function<Vec2(Vec2)>& map) {
  PolygonWithHoles out;
  for (const Vec2& p : polygon.outer) out.outer.push_back(map(p));
  for (const Ring2& hole : polygon.holes) {
    out.holes.emplace_back();
    for (const Vec2& p : hole) out.holes.back().push_back(map(p));
  }
  return out;
}

void expectFreshMesh(const Mesh& mesh, const PolygonWithHoles& polygon, double patchSize) {
  const Mesh fresh = meshPolygon(polygon, {patchSize});
  EXPECT_EQ(mesh.vertices, fresh.vertices);
  EXPECT_EQ(mesh.elements, fresh.elements);
}

TEST(MeshMemo, RepeatsMovedOrTurnedGetTheMeshMeshingThemGives) {
  Mesher mesher;
  const Mesh first = mesher.mesh(room(), {12});
  EXPECT_EQ(mesher.repeats(), 0u);
  const std::function<Vec2(Vec2)> moves[] = {
      [](Vec2 p) { return p + Vec2{8, 16}; },              // moved
      [](Vec2 p) { return Vec2{-p.y, p.x}; },              // a quarter turn
      [](Vec2 p) { return Vec2{240 - p.x, 180 - p.y}; },  // a half turn, in the same place
  };
  size_t repeats = 0;
  for (const auto& move : moves) {
    const PolygonWithHoles repeat = mapped(room(), move);
    const Mesh mesh = mesher.mesh(repeat, {12});
    EXPECT_EQ(mesher.repeats(), ++repeats);
    expectFreshMesh(mesh, repeat, 12);
    // The same elements, and the same points moved along.
    EXPECT_EQ(mesh.elements, first.elements);
    ASSERT_EQ(mesh.vertices.size(), first.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) EXPECT_EQ(mesh.vertices[i], move(first.vertices[i])) << i;
  }
}

TEST(MeshMemo, OnlyTheSameTreeInputIsARepeat) {
  Mesher mesher;
  mesher.mesh(room(), {12});
  const PolygonWithHoles mirrored = mapped(room(), [](Vec2 p) { return Vec2{-p.x, p.y}; });
  const PolygonWithHoles farAway = mapped(room(), [](Vec2 p) { return p + Vec2{5000, 0}; });  // coarser rounding
  PolygonWithHoles nudged = room();
  nudged.holes[0][1].y = std::nextafter(52.5, 60.0);
  PolygonWithHoles startsElsewhere = room();  // the same ring from another vertex: other ids
  std::rotate(startsElsewhere.outer.begin(), startsElsewhere.outer.begin() + 1, startsElsewhere.outer.end());
  // Patch sizes 10 and 12 give the same tree depth here (equation 5.2), 6 another one.
  const std::pair<PolygonWithHoles, double> others[] = {{room(), 6}, {mirrored, 12}, {farAway, 12}, {nudged, 12}, {startsElsewhere, 12}};
  for (const auto& [polygon, patch] : others) {
    expectFreshMesh(mesher.mesh(polygon, {patch}), polygon, patch);
    EXPECT_EQ(mesher.repeats(), 0u);
  }
}

TEST(MeshMemo, WithoutMemoryNothingIsARepeat) {
  Mesher mesher(0);
  for (int i = 0; i < 3; ++i) expectFreshMesh(mesher.mesh(room(), {12}), room(), 12);
  EXPECT_EQ(mesher.repeats(), 0u);
}

// Random polygons and rooms of many sizes (each its own tree input, each mesh of about the same
// size), met forward and then backward, through a memory that fills and starts over again and
// again: every mesh is the one meshing gives.
TEST(MeshMemo, AFullMemoryStartsOverAndMeshesStayExact) {
  std::mt19937 random(17);
  std::vector<std::pair<PolygonWithHoles, double>> polygons;  // with the patch size
  for (int trial = 0; trial < 40; ++trial) {
    polygons.emplace_back(trial % 2 ? test::randomStarPolygon(random, trial) : test::randomPolygonWithHoles(random, trial),
                          4 + trial % 5);
    const double scale = 1 + trial / 64.0;
    polygons.emplace_back(mapped(room(), [&](Vec2 p) { return p * scale; }), 24 * scale);
  }
  const size_t roomElements = meshPolygon(polygons[1].first, {polygons[1].second}).elements.size();
  const size_t capacity = 16 * roomElements;  // keeps a room's mesh, sixteen in all
  Mesher mesher(capacity);
  size_t met = 0;
  for (int round = 0; round < 2; ++round)
    for (size_t k = 0; k < polygons.size(); ++k) {
      const size_t i = round == 0 ? k : polygons.size() - 1 - k;
      SCOPED_TRACE(testing::Message() << "round " << round << ", polygon " << i);
      const auto& [polygon, patch] = polygons[i];
      const Mesh mesh = mesher.mesh(polygon, {patch});
      expectFreshMesh(mesh, polygon, patch);
      met += round > 0 && mesh.elements.size() <= capacity / 16;
    }
  EXPECT_GT(mesher.repeats(), 0u);
  EXPECT_LT(mesher.repeats(), met);  // some were forgotten when the memory filled
}

}  // namespace
}  // namespace mesher
