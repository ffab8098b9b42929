// The scenes in assets/ load and hold what the project promises of them.
#include "engine/geometry/surface_mesh.h"
#include "engine/io/load_scene.h"
#include "mesher/mesh_check.h"
#include "tests/engine/test_scenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

namespace engine {
namespace {

Scene loadAsset(const char* name) { return loadScene(std::string(WALKRAD_ASSETS) + "/" + name); }

bool hasObject(const Scene& scene, const std::string& name) {
  for (const Object& o : scene.objects)
    if (o.name == name) return true;
  return false;
}

double emittedPower(const Scene& scene) {
  double power = 0;
  for (const Surface& s : scene.surfaces) {
    const Vec3 e = scene.materials[s.material].emission;
    power += (e.x + e.y + e.z) * s.area;
  }
  return power;
}

TEST(ShippedScenes, CornellBoxIsTheMeasuredBox) {
  const Scene scene = loadAsset("cornell.json");
  EXPECT_EQ(scene.units, "mm");
  EXPECT_EQ(scene.boundsMin, (Vec3{0, 0, 0}));
  EXPECT_EQ(scene.boundsMax, (Vec3{556, 548.8, 559.2}));
  // The front (z = 0) is open: no surface lies in that plane.
  for (const Surface& s : scene.surfaces)
    EXPECT_FALSE(s.normal.z != 0 && test::centroidOf(s).z == 0) << s.face;
  auto wallAt = [&](double x) -> const Surface* {
    for (const Surface& s : scene.surfaces)
      if (scene.objects[s.object].name == "room" && std::abs(s.normal.x) == 1 && test::centroidOf(s).x == x) return &s;
    return nullptr;
  };
  const Surface* red = wallAt(556);
  const Surface* green = wallAt(0);
  ASSERT_TRUE(red && green);
  EXPECT_EQ(scene.materials[red->material].name, "red");
  EXPECT_EQ(scene.materials[green->material].name, "green");
  EXPECT_EQ(red->normal, (Vec3{-1, 0, 0}));  // facing into the box
  const Surface& light = test::surfaceOf(scene, "room", "top hole 0 fill");
  EXPECT_DOUBLE_EQ(light.area, 130.0 * 105.0);
  EXPECT_EQ(light.normal, (Vec3{0, -1, 0}));
  for (const Vec3& p : light.outer) EXPECT_EQ(p.y, 548.8);  // flush with the ceiling
  EXPECT_TRUE(hasObject(scene, "short block"));
  EXPECT_TRUE(hasObject(scene, "tall block"));
  const Camera* camera = scene.findCamera("default");
  ASSERT_NE(camera, nullptr);
  EXPECT_EQ(camera->position, (Vec3{278, 273, -800}));
  EXPECT_EQ(glm::normalize(camera->lookAt - camera->position), (Vec3{0, 0, 1}));
  EXPECT_NEAR(camera->fovYDeg, 39.3, 0.01);
}

TEST(ShippedScenes, OfficeHasItsFurnitureLightAndSkyWindow) {
  const Scene scene = loadAsset("office.json");
  for (const char* name : {"desk", "cabinet", "pillar"}) EXPECT_TRUE(hasObject(scene, name)) << name;
  int filledHoles = 0;
  for (const Surface& s : scene.surfaces)
    if (s.face.find("fill") != std::string::npos && scene.materials[s.material].emission != Vec3{0}) ++filledHoles;
  EXPECT_GE(filledHoles, 2);  // the ceiling panel and the sky in the window
  EXPECT_GT(emittedPower(scene), 0);
  EXPECT_NE(scene.findCamera("default"), nullptr);
}

TEST(ShippedScenes, KitchenIsAtTheThesisScale) {
  const Scene scene = loadAsset("kitchen.json");
  EXPECT_EQ(scene.units, "in");
  EXPECT_GE(scene.surfaces.size(), 900u);
  for (const char* name : {"table", "chair 1"}) EXPECT_TRUE(hasObject(scene, name)) << name;
  int emitters = 0;
  for (const Surface& s : scene.surfaces)
    if (scene.materials[s.material].emission != Vec3{0}) ++emitters;
  EXPECT_GE(emitters, 3);
  EXPECT_NE(scene.findCamera("default"), nullptr);
}

TEST(ShippedScenes, FurnaceIsAClosedBoxOfOneEmittingMaterial) {
  const Scene scene = loadAsset("furnace.json");
  ASSERT_FALSE(scene.surfaces.empty());
  const uint32_t material = scene.surfaces.front().material;
  for (const Surface& s : scene.surfaces) EXPECT_EQ(s.material, material);
  EXPECT_NE(scene.materials[material].emission, Vec3{0});
  for (const Object& o : scene.objects) {
    const Vec3 net = test::netArea(scene, o.name);
    EXPECT_NEAR(glm::length(net), 0, 1e-9);
    EXPECT_LT(test::enclosedVolume(scene, o.name), 0);  // closed, seen from inside
  }
}

// Every surface of the shipped scenes meshes exactly, without T-vertices and with no element
// angle below the bound but at sharper corners of its own, at the scene's patch sizes and at
// patch sizes across the range a user may set (as `walkrad mesh --patch-size` sets them). The
// Cornell box at 30 mm and finer had two elements of 0.3 and 9 degrees, at a block's corner a hair
// from a grid line, before vertex leaves were split up to eight levels.
TEST(ShippedScenes, EverySurfaceMeetsTheAngleBoundAtManyPatchSizes) {
  const std::vector<std::pair<const char*, std::vector<double>>> cases{
      {"cornell.json", {0, 30, 24, 16}}, {"office.json", {0, 0.6, 0.15}}, {"kitchen.json", {0, 24, 8}}, {"box-on-floor.json", {0, 0.1}}};
  for (const auto& [name, patchSizes] : cases) {
    const Scene scene = loadAsset(name);
    for (double patchSize : patchSizes) {
      SCOPED_TRACE(std::string(name) + " at " + (patchSize > 0 ? std::to_string(patchSize) : "its own patch sizes"));
      mesher::Mesher mesher;
      size_t elements = 0;
      for (Surface surface : scene.surfaces) {
        if (patchSize > 0) surface.patchSize = patchSize;
        const SurfaceMesh meshed = meshSurface(surface, mesher);
        const mesher::MeshCheck check = mesher::checkMesh(meshed.polygon, meshed.mesh);
        EXPECT_EQ(check.belowAngleBound, 0u) << surface.face << ": smallest angle " << check.smallestAngleDeg;
        EXPECT_EQ(check.tVertices, 0u) << surface.face;
        EXPECT_EQ(check.movedInputVertices, 0u) << surface.face;
        EXPECT_EQ(check.notCounterClockwiseOrConvex, 0u) << surface.face;
        EXPECT_NEAR(check.elementArea, check.polygonArea, 1e-9 * check.polygonArea) << surface.face;
        elements += meshed.mesh.elements.size();
      }
      EXPECT_GT(elements, scene.surfaces.size());
    }
  }
}

TEST(ShippedScenes, EverySurfaceHasAreaAndAPatchSize) {
  for (const char* name : {"cornell.json", "office.json", "kitchen.json", "furnace.json"}) {
    const Scene scene = loadAsset(name);
    for (const Surface& s : scene.surfaces) {
      EXPECT_GT(s.area, 0) << name << " " << s.jsonPath << " " << s.face;
      EXPECT_GT(s.patchSize, 0) << name;
    }
  }
}

}  // namespace
}  // namespace engine
