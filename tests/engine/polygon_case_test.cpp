#include "engine/io/polygon_case.h"

#include <gtest/gtest.h>

namespace engine {
namespace {

PolygonCase parse(const char* text) {
  const JsonReader in("case.json");
  return parsePolygonCase(in.parse(text), in);
}

void expectRefused(const char* text, Diag diag, const char* place) {
  try {
    parse(text);
    ADD_FAILURE() << "accepted " << text;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), diag) << e.what();
    EXPECT_EQ(e.place(), place) << e.what();
  }
}

TEST(PolygonCase, ReadsTheSpecExample) {
  const PolygonCase c = parse(R"({ "name": "wall-with-window", "patch_size": 12,
    "outer": [[0, 0], [240, 0], [240, 96], [0, 96]], "holes": [ [[30, 40], [30, 80], [66, 80], [66, 40]] ] })");
  EXPECT_EQ(c.name, "wall-with-window");
  EXPECT_EQ(c.patchSize, 12);
  EXPECT_EQ(c.polygon.outer.size(), 4u);
  ASSERT_EQ(c.polygon.holes.size(), 1u);
  EXPECT_EQ(c.polygon.holes[0][1], (mesher::Vec2{30, 80}));
}

TEST(PolygonCase, ConcaveOuterRingsAreFine) {
  EXPECT_NO_THROW(parse(R"({"outer": [[0, 0], [10, 0], [10, 6], [6, 6], [6, 10], [0, 10]], "holes": [[[1, 1], [1, 3], [3, 3], [3, 1]]]})"));
}

TEST(PolygonCase, BrokenCasesAreRefusedWithTheirPath) {
  expectRefused(R"({"outer": [[0, 0], [10, 10], [10, 0], [0, 10]]})", Diag::SelfIntersecting, "outer");
  expectRefused(R"({"outer": [[0, 0], [10, 0], [10, 0], [0, 10]]})", Diag::Degenerate, "outer");
  expectRefused(R"({"outer": [[0, 0], [10, 0], [20, 0]]})", Diag::SelfIntersecting, "outer");  // folds back on itself
  expectRefused(R"({"outer": [[0, 0], [10, 0]]})", Diag::TooFewPoints, "outer");
  expectRefused(R"({"outer": [[0, 0], [10, 0], [10, 10]], "patch_size": 0})", Diag::OutOfRange, "patch_size");
  expectRefused(R"({"outer": [[0, 0], [10, 0], [10, 10], [0, 10]], "holes": [[[8, 8], [12, 8], [12, 9]]]})", Diag::HoleOutsideFace, "holes[0]");
  // A hole inside the concave outer ring's notch is outside the polygon.
  expectRefused(R"({"outer": [[0, 0], [10, 0], [10, 6], [6, 6], [6, 10], [0, 10]], "holes": [[[7, 7], [9, 7], [9, 9], [7, 9]]]})",
                Diag::HoleOutsideFace, "holes[0]");
  expectRefused(R"({"outer": [[0, 0], [10, 0], [10, 10], [0, 10]], "holes": [[[1, 1], [3, 1], [3, 3], [1, 3]], [[3, 2], [5, 2], [5, 4]]]})",
                Diag::HolesTouch, "holes[1]");
  expectRefused(R"({"outer": [[0, 0], [10, 0], [10, 10], [0, 10]], "shape": 1})", Diag::UnknownKey, "shape");
}

// The scene files' limit, 100,000 patches along the extent, holds for a case's own patch size and
// for --patch-size alike.
TEST(PolygonCase, PatchSizesTooSmallForThePolygonAreRefused) {
  expectRefused(R"({"outer": [[0, 0], [10, 0], [10, 10]], "patch_size": 1e-5})", Diag::PatchTooSmall, "patch_size");
  const JsonReader in("case.json");
  const PolygonCase fine = parse(R"({"outer": [[0, 0], [10, 0], [10, 10]], "patch_size": 1e-4})");
  EXPECT_EQ(casePatchSize(fine, std::nullopt, in), 1e-4);
  EXPECT_EQ(casePatchSize(fine, 2.0, in), 2.0);
  try {
    casePatchSize(fine, 1e-12, in);
    ADD_FAILURE() << "a patch size of 1e-12 accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), Diag::PatchTooSmall);
    EXPECT_EQ(e.place(), "--patch-size");
  }
  const PolygonCase without = parse(R"({"outer": [[0, 0], [10, 0], [10, 10]]})");
  EXPECT_THROW(casePatchSize(without, std::nullopt, in), SceneError);
}

// A coordinate too large for a double is placed by line and column.
TEST(PolygonCase, NumbersBeyondDoubleAreRefusedWhereTheyAre) {
  try {
    parse("{\"patch_size\": 1,\n \"outer\": [[0, 0], [-1e999, 0], [1, 1]]}");
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.diag(), Diag::NotFinite) << e.what();
    EXPECT_STREQ(e.what(), "case.json:2:21: not a finite number: -1e999 is too large for a double");
  }
}

TEST(PolygonCase, TellsCasesFromScenes) {
  const JsonReader in("x.json");
  EXPECT_TRUE(isPolygonCase(in.parse(R"({"outer": []})")));
  EXPECT_FALSE(isPolygonCase(in.parse(R"({"format": "walkrad-scene/1", "outer": []})")));
  EXPECT_FALSE(isPolygonCase(in.parse(R"([1, 2])")));
}

}  // namespace
}  // namespace engine
