// Headless renders through OSMesa, checked on pixels.
#include "app/gl/headless_render.h"

#include "engine/document/display_mesh.h"
#include "engine/io/load_scene.h"
#include "tests/app/pixel_probe.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>

namespace app {
namespace {

engine::Scene loadAsset(const char* name) { return engine::loadScene(std::string(WALKRAD_ASSETS) + "/" + name); }

HeadlessImages render(const engine::Scene& scene, int width, int height, bool wireframe = false, bool linear = false) {
  engine::DisplayMesh mesh = engine::displayMesh(scene, engine::meshScene(scene));
  engine::shadeWithAmbient(scene, mesh);
  engine::ViewCamera camera;
  EXPECT_TRUE(engine::chooseCamera(scene, "", camera));
  return renderHeadless(scene, mesh, camera, width, height, static_cast<float>(engine::autoExposure(mesh)), wireframe, linear);
}

// The classic view: the red wall (x = 556) on the left, the green (x = 0) on the right.
TEST(HeadlessRender, CornellBoxRedLeftGreenRight) {
  const HeadlessImages images = render(loadAsset("cornell.json"), 320, 240);
  ASSERT_EQ(images.color.width, 320);
  ASSERT_EQ(images.color.height, 240);
  writePng(std::string(WALKRAD_TEST_OUTPUT) + "/cornell-headless.png", images.color);
  // The box fills the middle of a 4:3 image; its side walls lie 14-28% in from each edge.
  const glm::dvec3 left = test::meanColor(images.color, 0.16, 0.26, 0.4, 0.6);
  const glm::dvec3 right = test::meanColor(images.color, 0.74, 0.84, 0.4, 0.6);
  const glm::dvec3 back = test::meanColor(images.color, 0.45, 0.55, 0.4, 0.6);
  EXPECT_GT(left.r, 2 * left.g) << "left wall is not red";
  EXPECT_GT(left.r, 2 * left.b);
  // Olive rather than pure green: the ambient light is as warm as the lamp.
  EXPECT_GT(right.g, 1.25 * right.r) << "right wall is not green";
  EXPECT_GT(right.g, 2 * right.b);
  EXPECT_GT(back.r + back.g + back.b, 150) << "back wall is dark";
  // Outside the box, through the open front's margin, is the black background.
  const glm::dvec3 corner = test::meanColor(images.color, 0.0, 0.05, 0.0, 0.05);
  EXPECT_LT(corner.r + corner.g + corner.b, 1);
  // The light in the ceiling is the brightest thing: white.
  const glm::dvec3 light = test::meanColor(images.color, 0.48, 0.52, 0.13, 0.15);
  EXPECT_GT(std::min({light.r, light.g, light.b}), 250);
}

// Linear output is radiance: in the furnace the placeholder is exact, E / (1 - rho) = 2.
TEST(HeadlessRender, LinearFurnaceImageIsTheExactRadiance) {
  const engine::Scene scene = loadAsset("furnace.json");
  const engine::Material& m = scene.materials[scene.surfaces.front().material];
  const double expected = m.emission.x / (1 - m.reflectance.x);
  const HeadlessImages images = render(scene, 64, 48, false, true);
  ASSERT_EQ(images.linear.pixels.size(), 64u * 48 * 3);
  for (float v : images.linear.pixels) ASSERT_NEAR(v, expected, 1e-5 * expected);
}

TEST(HeadlessRender, WireframeDrawsWhiteEdges) {
  const engine::Scene scene = loadAsset("cornell.json");
  const HeadlessImages plain = render(scene, 320, 240);
  const HeadlessImages wired = render(scene, 320, 240, true);
  size_t changed = 0, white = 0;
  for (size_t i = 0; i < plain.color.pixels.size(); i += 3) {
    if (plain.color.pixels[i] != wired.color.pixels[i] || plain.color.pixels[i + 1] != wired.color.pixels[i + 1]) {
      ++changed;
      if (wired.color.pixels[i] == 255 && wired.color.pixels[i + 1] == 255 && wired.color.pixels[i + 2] == 255) ++white;
    }
  }
  EXPECT_GT(changed, 300u);
  EXPECT_EQ(white, changed);
}

TEST(HeadlessRender, SameSceneSamePixels) {
  const engine::Scene scene = loadAsset("office.json");
  EXPECT_EQ(render(scene, 160, 120).color.pixels, render(scene, 160, 120).color.pixels);
}

// tests/cli/far_room_box.json is a room 900 km from the world's origin (within the format's 1e6
// limit), where float world coordinates are 6 cm apart. It draws as its copy moved to the origin
// does (the display's float coordinates are about the mesh's middle): on 160 x 120 pixels, a
// mean difference under one level and under 1% of pixels more than 8 levels apart (edges that
// fall on the other side of a pixel centre). Drawn in float world coordinates the walls cracked
// open and the box lost its shape.
TEST(HeadlessRender, ARoomFarFromTheOriginDrawsAsItsCopyAtTheOrigin) {
  const std::string farPath = std::string(WALKRAD_SOURCE) + "/tests/cli/far_room_box.json";
  nlohmann::json json = nlohmann::json::parse(std::ifstream(farPath));
  const auto shift = [](nlohmann::json& pair) {
    for (int k : {0, 1}) pair[k] = pair[k].get<double>() - 900000;
  };
  nlohmann::json& room = json["objects"][0]["solids"][0];
  for (nlohmann::json& p : room["profile"]) shift(p);
  for (nlohmann::json& p : room["faces"]["top"]["holes"][0]["polygon"]) shift(p);
  for (const char* key : {"position", "look_at"}) json["cameras"]["default"][key][0] = json["cameras"]["default"][key][0].get<double>() - 900000;
  for (const char* key : {"position", "look_at"}) json["cameras"]["default"][key][2] = json["cameras"]["default"][key][2].get<double>() - 900000;
  nlohmann::json& box = json["objects"][1]["position"];
  box[0] = box[0].get<double>() - 900000;
  box[2] = box[2].get<double>() - 900000;
  const std::string nearPath = std::string(WALKRAD_TEST_OUTPUT) + "/near_room_box.json";
  std::ofstream(nearPath) << json.dump();

  const ImageRgb8 far = render(engine::loadScene(farPath), 160, 120).color;
  const ImageRgb8 near = render(engine::loadScene(nearPath), 160, 120).color;
  ASSERT_EQ(far.pixels.size(), near.pixels.size());
  const test::ImageDifference d = test::difference(far, near, 8);
  EXPECT_LT(d.meanLevels, 1.0);
  EXPECT_LT(d.shareBeyond, 0.01);
}

}  // namespace
}  // namespace app
