// Golden images of solved scenes (tests/golden/cases.json): the whole pipeline, from the scene
// file through the mesher and the radiosity solver to the OSMesa picture, against a reviewed PNG
// with the case's tolerances. WALKRAD_UPDATE_GOLDENS=1 writes the goldens instead.
#include "app/gl/headless_render.h"
#include "engine/document/display_mesh.h"
#include "engine/document/lighting.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/io/load_scene.h"
#include "tests/app/image_read.h"
#include "tests/app/pixel_probe.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

namespace app {
namespace {

struct GoldenCase {
  std::string name, scene, camera;
  int width = 0, height = 0;
  double converge = 0.01, meanLevels = 0, pixelLevels = 0, pixelShare = 0;
};

std::vector<GoldenCase> loadCases() {
  std::ifstream file(std::string(WALKRAD_GOLDEN) + "/cases.json");
  const nlohmann::json json = nlohmann::json::parse(file);
  std::vector<GoldenCase> cases;
  for (const nlohmann::json& c : json.at("cases"))
    cases.push_back({c.at("name"), c.at("scene"), c.at("camera"), c.at("width"), c.at("height"), c.at("converge"),
                     c.at("mean_levels"), c.at("pixel_levels"), c.at("pixel_share")});
  return cases;
}

ImageRgb8 renderSolved(const GoldenCase& c) {
  const engine::Scene scene = engine::loadScene(std::string(WALKRAD_ASSETS) + "/" + c.scene);
  const engine::MeshedScene meshed = engine::meshScene(scene);
  engine::DisplayMesh mesh = engine::displayMesh(scene, meshed);
  radiosity::SolverSettings settings;
  settings.graphicsProcessors = 2;  // the machine's two cores; the pictures do not depend on it
  settings.overshoot = true;       // as the application solves
  radiosity::Solver solver(engine::radiosityInput(scene, meshed), settings);
  engine::solveTo(solver, c.converge, UINT64_MAX);
  EXPECT_LE(solver.unshotFraction(), c.converge);
  engine::setRadiance(mesh, solver);
  engine::ViewCamera camera;
  EXPECT_TRUE(engine::chooseCamera(scene, c.camera, camera));
  return renderHeadless(scene, mesh, camera, c.width, c.height, static_cast<float>(engine::autoExposure(mesh)), false, false).color;
}

class Golden : public testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, SolvedImageMatchesTheGolden) {
  const GoldenCase& c = GetParam();
  const ImageRgb8 image = renderSolved(c);
  const std::string golden = std::string(WALKRAD_GOLDEN) + "/" + c.name + ".png";
  if (const char* update = std::getenv("WALKRAD_UPDATE_GOLDENS"); update && std::string(update) == "1") {
    writePng(golden, image);
    GTEST_SKIP() << "wrote " << golden;
  }
  writePng(std::string(WALKRAD_TEST_OUTPUT) + "/golden-" + c.name + "-actual.png", image);
  const ImageRgb8 expected = test::readPng(golden);
  ASSERT_EQ(image.width, expected.width);
  ASSERT_EQ(image.height, expected.height);

  // The difference, amplified eight times, beside the actual image for whoever looks.
  ImageRgb8 amplified;
  const test::ImageDifference d = test::difference(image, expected, c.pixelLevels, &amplified);
  writePng(std::string(WALKRAD_TEST_OUTPUT) + "/golden-" + c.name + "-difference.png", amplified);
  EXPECT_LE(d.meanLevels, c.meanLevels) << "mean difference in 8-bit levels";
  EXPECT_LE(d.shareBeyond, c.pixelShare) << "share of pixels more than " << c.pixelLevels << " levels off";
}

INSTANTIATE_TEST_SUITE_P(Scenes, Golden, testing::ValuesIn(loadCases()),
                         [](const testing::TestParamInfo<GoldenCase>& param) { return param.param.name; });

}  // namespace
}  // namespace app
