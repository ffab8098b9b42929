// What the loader makes of every feature of spec/scene-format.md.
#include "engine/geometry/solid_surfaces.h"
#include "engine/io/load_scene.h"
#include "radiosity/adaptive_refinement.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <set>

namespace engine {
namespace {

using test::centroidOf;
using test::parse;
using test::sceneWithSolid;
using test::surfaceOf;

Json boxSolid(const char* axis = "y") {
  return {{"profile", {{0, 0}, {2, 0}, {2, 1}, {0, 1}}}, {"axis", axis}, {"from", 0}, {"to", 3}, {"material", "white"}};
}

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SceneLoader, BaseSceneHasRoomBoxAndLampSurfaces) {
  const Scene scene = parse(test::baseScene());
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_FALSE(scene.objects[0].movable);
  EXPECT_TRUE(scene.objects[1].movable);
  // room: 6 faces + the lamp filling the ceiling hole; box: 6 faces.
  EXPECT_EQ(scene.surfaces.size(), 13u);
  EXPECT_EQ(scene.materials.size(), 2u);
  EXPECT_DOUBLE_EQ(scene.patchSize, 0.5);
}

TEST(SceneLoader, UnitsGiveMetresPerUnit) {
  for (const auto& [units, meters] : {std::pair{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}, {"ft", 0.3048}}) {
    Json j = test::baseScene();
    j["units"] = units;
    EXPECT_DOUBLE_EQ(parse(j).metersPerUnit, meters) << units;
  }
  Json j = test::baseScene();
  j.erase("units");
  EXPECT_EQ(parse(j).units, "m");
}

TEST(SceneLoader, AdaptiveSettingsAreOffUnlessGivenAndTheirKeysDefault) {
  Json j = test::baseScene();
  EXPECT_FALSE(test::parse(j).adaptive);
  j["settings"]["adaptive"] = Json::object();
  const Scene defaults = test::parse(j);
  ASSERT_TRUE(defaults.adaptive);
  EXPECT_EQ(defaults.adaptive->threshold, radiosity::RefinementSettings{}.threshold);
  EXPECT_EQ(defaults.adaptive->minElementSize, 0);
  j["settings"]["adaptive"] = {{"threshold", 0.1}, {"min_element_size", 0.05}};
  const Scene given = test::parse(j);
  EXPECT_EQ(given.adaptive->threshold, 0.1);
  EXPECT_EQ(given.adaptive->minElementSize, 0.05);
}

TEST(SceneLoader, MaterialsKeepTheirValuesAndEmissionDefaultsToBlack) {
  const Scene scene = parse(test::baseScene());
  EXPECT_EQ(scene.materials[0].name, "white");
  EXPECT_EQ(scene.materials[0].emission, Vec3{0});
  EXPECT_EQ(scene.materials[1].emission, Vec3{4});
}

TEST(SceneLoader, ABoxSeenFromOutsideHasOutwardNormalsWhicheverWayItsProfileRuns) {
  for (bool reversed : {false, true}) {
    Json solid = boxSolid();
    if (reversed) std::reverse(solid["profile"].begin(), solid["profile"].end());
    const Scene scene = parse(sceneWithSolid(solid));
    ASSERT_EQ(scene.surfaces.size(), 6u);
    const Vec3 center{1, 1.5, 0.5};
    for (const Surface& s : scene.surfaces) {
      EXPECT_GT(glm::dot(s.normal, centroidOf(s) - center), 0) << s.face;
      EXPECT_NEAR(glm::length(s.normal), 1, 1e-12);
    }
    EXPECT_NEAR(test::enclosedVolume(scene, "thing"), 6, 1e-12);
    expectNear(test::netArea(scene, "thing"), Vec3{0});
  }
}

TEST(SceneLoader, ARoomSeenFromInsideHasInwardNormals) {
  Json solid = boxSolid();
  solid["inward"] = true;
  const Scene scene = parse(sceneWithSolid(solid));
  const Vec3 center{1, 1.5, 0.5};
  for (const Surface& s : scene.surfaces) EXPECT_LT(glm::dot(s.normal, centroidOf(s) - center), 0) << s.face;
  EXPECT_NEAR(test::enclosedVolume(scene, "thing"), -6, 1e-12);
}

TEST(SceneLoader, EveryPointOfASurfaceLiesInItsPlane) {
  Json j = test::baseScene();
  j["objects"][1]["rotate_y"] = 27;
  j["objects"][1]["solids"][0]["taper"] = {{"kind", "radial"}, {"slices", 3}};
  const Scene scene = parse(j);
  for (const Surface& s : scene.surfaces) {
    for (const Vec3& p : s.outer) EXPECT_NEAR(glm::dot(p, s.normal), s.planeOffset(), 1e-12) << s.face;
    for (const Ring3& h : s.holes)
      for (const Vec3& p : h) EXPECT_NEAR(glm::dot(p, s.normal), s.planeOffset(), 1e-12) << s.face;
  }
}

TEST(SceneLoader, OuterRingsRunCounterClockwiseAboutTheNormal) {
  const Scene scene = parse(test::baseScene());
  for (const Surface& s : scene.surfaces) {
    Vec3 newell{0};
    for (size_t i = 0; i < s.outer.size(); ++i)
      newell += glm::cross(s.outer[i], s.outer[(i + 1) % s.outer.size()]);
    EXPECT_GT(glm::dot(newell, s.normal), 0) << s.face;
    EXPECT_NEAR(0.5 * glm::length(newell), s.area + [&] {
      double holes = 0;
      for (const Ring3& h : s.holes) {
        Vec3 n{0};
        for (size_t i = 0; i < h.size(); ++i) n += glm::cross(h[i], h[(i + 1) % h.size()]);
        EXPECT_LT(glm::dot(n, s.normal), 0) << "hole of " << s.face << " is not clockwise";
        holes += 0.5 * glm::length(n);
      }
      return holes;
    }(), 1e-12);
  }
}

// The profile's coordinates are the two world axes other than `axis`, in order (spec: SOLID).
TEST(SceneLoader, SolidsAlongEachAxisMapProfileCoordinates) {
  struct Case {
    const char* axis;
    Vec3 min, max;
  };
  // profile spans [0,2] x [0,1], the sweep [0,3].
  for (const Case& c : {Case{"x", {0, 0, 0}, {3, 2, 1}}, Case{"y", {0, 0, 0}, {2, 3, 1}}, Case{"z", {0, 0, 0}, {2, 1, 3}}}) {
    const Scene scene = parse(sceneWithSolid(boxSolid(c.axis)));
    expectNear(scene.boundsMin, c.min);
    expectNear(scene.boundsMax, c.max);
    EXPECT_NEAR(test::enclosedVolume(scene, "thing"), 6, 1e-12) << c.axis;
  }
}

TEST(SceneLoader, FaceNamesFollowTheProfileEdges) {
  const Scene scene = parse(sceneWithSolid(boxSolid()));
  std::set<std::string> names;
  for (const Surface& s : scene.surfaces) names.insert(s.face);
  EXPECT_EQ(names, (std::set<std::string>{"bottom", "top", "side 0", "side 1", "side 2", "side 3"}));
  // side 1 joins (2,0) to (2,1): the plane x = 2, facing +x; bottom is at `from`, facing down.
  expectNear(surfaceOf(scene, "thing", "side 1").normal, {1, 0, 0});
  EXPECT_DOUBLE_EQ(centroidOf(surfaceOf(scene, "thing", "side 1")).x, 2);
  expectNear(surfaceOf(scene, "thing", "bottom").normal, {0, -1, 0});
  expectNear(surfaceOf(scene, "thing", "top").normal, {0, 1, 0});
  EXPECT_DOUBLE_EQ(surfaceOf(scene, "thing", "side 3").area, 3);  // edge (0,1)->(0,0), length 1
}

TEST(SceneLoader, PositionAndRotateYPlaceTheObjectExactly) {
  Json j = sceneWithSolid(boxSolid());
  j["objects"][0]["position"] = {10, 0, 0};
  j["objects"][0]["rotate_y"] = 90;  // +x turns toward -z
  const Scene scene = parse(j);
  // The box spans x in [0,2], z in [0,1]; turned, x in [0,1], z in [-2,0]; then moved by 10.
  EXPECT_EQ(scene.boundsMin, (Vec3{10, 0, -2}));
  EXPECT_EQ(scene.boundsMax, (Vec3{11, 3, 0}));
  expectNear(surfaceOf(scene, "thing", "side 1").normal, {0, 0, -1});
}

TEST(SceneLoader, ArbitraryRotationKeepsShapeAndOrientation) {
  Json j = sceneWithSolid(boxSolid());
  j["objects"][0]["rotate_y"] = 33.3;
  const Scene scene = parse(j);
  EXPECT_NEAR(test::enclosedVolume(scene, "thing"), 6, 1e-12);
  const double angle = glm::radians(33.3);
  expectNear(surfaceOf(scene, "thing", "side 1").normal, {std::cos(angle), 0, -std::sin(angle)});
}

TEST(SceneLoader, LinearTaperToAnApexMakesAPyramid) {
  Json solid = boxSolid();
  solid["taper"] = {{"kind", "linear"}, {"scale", 0}};
  const Scene scene = parse(sceneWithSolid(solid));
  EXPECT_EQ(scene.surfaces.size(), 5u);  // no top
  EXPECT_NEAR(test::enclosedVolume(scene, "thing"), 2.0 * 3 / 3, 1e-12);
  expectNear(test::netArea(scene, "thing"), Vec3{0}, 1e-12);
  for (const Surface& s : scene.surfaces)
    if (s.face != "bottom") {
      EXPECT_EQ(s.outer.size(), 3u) << s.face;
    }
  expectNear(scene.boundsMax, {2, 3, 1});
}

TEST(SceneLoader, LinearTaperMakesAFrustum) {
  Json solid = boxSolid();
  solid["taper"] = {{"kind", "linear"}, {"scale", 0.5}};
  const Scene scene = parse(sceneWithSolid(solid));
  EXPECT_EQ(scene.surfaces.size(), 6u);
  EXPECT_NEAR(surfaceOf(scene, "thing", "top").area, 0.25 * 2, 1e-12);
  EXPECT_NEAR(test::enclosedVolume(scene, "thing"), 2.0 * 3 * (1 + 0.5 + 0.25) / 3, 1e-12);
}

TEST(SceneLoader, RadialTaperMakesADomeOfNamedBands) {
  Json solid = boxSolid();
  solid["taper"] = {{"kind", "radial"}, {"slices", 4}};
  const Scene scene = parse(sceneWithSolid(solid));
  EXPECT_EQ(scene.surfaces.size(), 1u + 4 * 4);  // bottom and 4 bands of 4 sides, apex at the top
  EXPECT_EQ(surfaceOf(scene, "thing", "side 2.3").outer.size(), 3u);  // the last band closes at the apex
  EXPECT_EQ(surfaceOf(scene, "thing", "side 2.0").outer.size(), 4u);
  expectNear(test::netArea(scene, "thing"), Vec3{0}, 1e-12);
  EXPECT_GT(test::enclosedVolume(scene, "thing"), 0);
  // Scale at fraction t is sqrt(1 - t^2): the band boundary at t = 1/4 lies at sqrt(15)/4.
  const Surface& band = surfaceOf(scene, "thing", "side 1.0");  // edge (2,0)->(2,1), x = 2 at the base
  double topX = 0;
  for (const Vec3& p : band.outer)
    if (p.y > 0) topX = p.x;
  EXPECT_NEAR(topX, 1 + std::sqrt(15.0) / 4, 1e-12);
}

TEST(SceneLoader, RadialTaperWithBothEndsHasNoCaps) {
  Json solid = boxSolid();
  solid["taper"] = {{"kind", "radial"}, {"slices", 6}, {"both_ends", true}};
  const Scene scene = parse(sceneWithSolid(solid));
  EXPECT_EQ(scene.surfaces.size(), 4u * 6);
  expectNear(test::netArea(scene, "thing"), Vec3{0}, 1e-12);
  EXPECT_GT(test::enclosedVolume(scene, "thing"), 0);
}

TEST(SceneLoader, FaceOverridesSetMaterialAndOpenFaces) {
  Json solid = boxSolid();
  solid["faces"] = {{"side 0", {{"open", true}}}, {"top", {{"material", "lamp"}}}};
  const Scene scene = parse(sceneWithSolid(solid));
  EXPECT_EQ(scene.surfaces.size(), 5u);
  EXPECT_EQ(scene.materials[surfaceOf(scene, "thing", "top").material].name, "lamp");
  EXPECT_EQ(scene.materials[surfaceOf(scene, "thing", "bottom").material].name, "white");
}

TEST(SceneLoader, PatchSizeComesFromFaceThenSolidThenObjectThenSettings) {
  Json j = sceneWithSolid(boxSolid());
  j["objects"][0]["patch_size"] = 0.4;
  j["objects"][0]["solids"][0]["patch_size"] = 0.3;
  j["objects"][0]["solids"][0]["faces"] = {{"top", {{"patch_size", 0.2}}}};
  j["objects"].push_back({{"name", "plain"}, {"solids", {boxSolid()}}});
  j["objects"].push_back({{"name", "object"}, {"patch_size", 0.4}, {"solids", {boxSolid()}}});
  const Scene scene = parse(j);
  EXPECT_DOUBLE_EQ(surfaceOf(scene, "thing", "top").patchSize, 0.2);
  EXPECT_DOUBLE_EQ(surfaceOf(scene, "thing", "bottom").patchSize, 0.3);
  EXPECT_DOUBLE_EQ(surfaceOf(scene, "object", "bottom").patchSize, 0.4);
  EXPECT_DOUBLE_EQ(surfaceOf(scene, "plain", "bottom").patchSize, 0.5);
}

TEST(SceneLoader, WithoutPatchSizeAnEighthOfTheSceneIsUsed) {
  Json j = sceneWithSolid(boxSolid());
  j.erase("settings");
  const Scene scene = parse(j);
  EXPECT_DOUBLE_EQ(scene.patchSize, 3.0 / 8);
  for (const Surface& s : scene.surfaces) EXPECT_DOUBLE_EQ(s.patchSize, 3.0 / 8);
}

TEST(SceneLoader, OpenHoleCutsTheFace) {
  Json j = test::baseScene();
  j["objects"][0]["solids"][0]["faces"]["top"]["holes"][0].erase("fill");
  const Scene scene = parse(j);
  EXPECT_EQ(scene.surfaces.size(), 12u);
  const Surface& ceiling = surfaceOf(scene, "room", "top");
  ASSERT_EQ(ceiling.holes.size(), 1u);
  EXPECT_NEAR(ceiling.area, 12 - 1, 1e-12);
  for (const Vec3& p : ceiling.holes[0]) EXPECT_EQ(p.y, 2.5);
}

TEST(SceneLoader, FilledHoleSharesItsBoundaryExactly) {
  const Scene scene = parse(test::baseScene());
  const Surface& ceiling = surfaceOf(scene, "room", "top");
  const Surface& lamp = surfaceOf(scene, "room", "top hole 0 fill");
  EXPECT_EQ(scene.materials[lamp.material].name, "lamp");
  EXPECT_EQ(lamp.normal, ceiling.normal);
  expectNear(lamp.normal, {0, -1, 0});  // an inward ceiling faces down into the room
  EXPECT_NEAR(lamp.area, 1, 1e-12);
  ASSERT_EQ(ceiling.holes.size(), 1u);
  EXPECT_EQ(lamp.outer, Ring3(ceiling.holes[0].rbegin(), ceiling.holes[0].rend()));
  // Room and lamp together are closed, but for the box's footprint cut out of the floor (1 m2
  // of floor facing up).
  expectNear(test::netArea(scene, "room"), Vec3{0, -1, 0}, 1e-12);
}

// A box standing on the floor is cut out of it: the floor loses the footprint, as a hole equal
// to the box's bottom face, and nothing is left under the box to light.
TEST(SceneLoader, FurnitureIsCutOutOfTheFloorItStandsOn) {
  const Scene scene = parse(test::baseScene());
  const Surface& floor = surfaceOf(scene, "room", "bottom");
  const Surface& bottom = surfaceOf(scene, "box", "bottom");
  ASSERT_EQ(floor.holes.size(), 1u);
  EXPECT_EQ(floor.holes[0], bottom.outer);
  EXPECT_NEAR(floor.area, 4 * 3 - 1, 1e-12);
  // The room's floor alone takes the cut: the box, resting on nothing but the floor, keeps its
  // faces whole.
  for (const Surface& s : scene.surfaces) {
    if (scene.objects[s.object].name == "box") {
      EXPECT_TRUE(s.holes.empty()) << s.face;
    }
  }
}

// A footprint that reaches the floor's edge (a box against the wall), or hovers above it, is
// left uncut.
TEST(SceneLoader, FootprintsAtTheEdgeOrAboveTheFloorAreNotCut) {
  for (const char* profile : {"[[0, 1], [1, 1], [1, 2], [0, 2]]", "[[1, 1], [2, 1], [2, 2], [1, 2]]"}) {
    Json j = test::baseScene();
    j["objects"][1]["solids"][0]["profile"] = Json::parse(profile);
    if (std::string(profile).find("[0, 1]") == std::string::npos) j["objects"][1]["solids"][0]["from"] = 0.01;
    const Scene scene = parse(j);
    EXPECT_TRUE(surfaceOf(scene, "room", "bottom").holes.empty()) << profile;
  }
}

// Side hole coordinates: u along the edge at `from` from point N, v from that edge toward `to`.
TEST(SceneLoader, HolesInSideFacesUseEdgeCoordinates) {
  Json j = test::baseScene();
  j["objects"][0]["solids"][0]["faces"]["side 1"] = {
      {"holes", {{{"polygon", {{0.5, 1}, {1.5, 1}, {1.5, 2}, {0.5, 2}}}, {"fill", "lamp"}}}}};
  const Scene scene = parse(j);
  // side 1 runs from (4,0) to (4,3) in (x, z): the wall x = 4, u along +z, v up.
  const Surface& window = surfaceOf(scene, "room", "side 1 hole 0 fill");
  for (const Vec3& p : window.outer) {
    EXPECT_EQ(p.x, 4);
    EXPECT_TRUE(p.z == 0.5 || p.z == 1.5);
    EXPECT_TRUE(p.y == 1 || p.y == 2);
  }
  expectNear(window.normal, {-1, 0, 0});
}

TEST(SceneLoader, HolesInTaperedSideFacesAreMeasuredInTheFacePlane) {
  Json solid = boxSolid();
  solid["profile"] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  solid["taper"] = {{"kind", "linear"}, {"scale", 0.5}};
  solid["faces"] = {{"side 0", {{"holes", {{{"polygon", {{1.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}, {1.5, 1.5}}}}}}}}};
  const Scene scene = parse(sceneWithSolid(solid));
  const Surface& side = surfaceOf(scene, "thing", "side 0");
  ASSERT_EQ(side.holes.size(), 1u);
  // The face leans in by 1 over a height of 3; v = 0.5 is 0.5 along the slant from z = 0.
  const double slant = std::sqrt(1.0 + 9.0);
  for (const Vec3& p : side.holes[0]) {
    const double v = (p.y == 0 ? 0 : std::sqrt(p.y * p.y + p.z * p.z));
    EXPECT_TRUE(std::abs(v - 0.5) < 1e-12 || std::abs(v - 1.5) < 1e-12) << v;
    EXPECT_NEAR(p.z, p.y / 3, 1e-12);
  }
  EXPECT_NEAR(side.area, (4 + 2) / 2.0 * slant - 1, 1e-12);
}

TEST(SceneLoader, CamerasWithDefaults) {
  Json j = test::baseScene();
  j["cameras"]["top"] = {{"position", {2, 10, 1.5}}, {"look_at", {2, 0, 1.5}}, {"up", {0, 0, 1}}, {"fov_y", 30}};
  const Scene scene = parse(j);
  ASSERT_EQ(scene.cameras.size(), 2u);
  EXPECT_EQ(scene.cameras[0].name, "default");  // file order kept
  EXPECT_EQ(scene.cameras[0].up, (Vec3{0, 1, 0}));
  EXPECT_DOUBLE_EQ(scene.cameras[0].fovYDeg, 60);
  ASSERT_NE(scene.findCamera("top"), nullptr);
  EXPECT_DOUBLE_EQ(scene.findCamera("top")->fovYDeg, 30);
  EXPECT_EQ(scene.findCamera("nope"), nullptr);
}

TEST(SceneLoader, LoadsFromAFile) {
  const Scene scene = loadScene(std::string(WALKRAD_ASSETS) + "/cornell.json");
  EXPECT_EQ(scene.units, "mm");
  EXPECT_FALSE(scene.surfaces.empty());
}

}  // namespace
}  // namespace engine
