// `walkrad mesh --dump` keeps the contract of spec/cli.md.
#include "app/cli/mesh_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace app {
namespace {

nlohmann::json readJson(const std::string& path) {
  std::ifstream file(path);
  return nlohmann::json::parse(file);
}

TEST(MeshCommand, PolygonDumpKeepsInputVerticesAndTilesThePolygon) {
  const std::string dir = WALKRAD_TEST_OUTPUT;
  {
    std::ofstream c(dir + "/case.json");
    c << R"({"patch_size": 7, "outer": [[0, 0], [40, 0], [40, 30], [0, 30]], "holes": [[[10.5, 10.25], [10.5, 20], [20, 20], [20, 10.25]]]})";
  }
  MeshOptions options;
  options.input = dir + "/case.json";
  options.dump = dir + "/case-dump.json";
  options.stats = dir + "/case-stats.json";
  ASSERT_EQ(runMesh(options), 0);
  const nlohmann::json dump = readJson(options.dump), stats = readJson(options.stats);
  const std::vector<std::vector<double>> input{{0, 0}, {40, 0}, {40, 30}, {0, 30}, {10.5, 10.25}, {10.5, 20}, {20, 20}, {20, 10.25}};
  std::vector<std::vector<double>> vertices = dump["vertices"];
  for (size_t i = 0; i < input.size(); ++i) EXPECT_EQ(vertices[i], input[i]);
  double area = 0;
  for (const auto& element : dump["elements"]) {
    ASSERT_TRUE(element.size() == 3 || element.size() == 4);
    double twice = 0;
    for (size_t k = 0; k < element.size(); ++k) {
      const auto& a = vertices[element[k].get<size_t>()];
      const auto& b = vertices[element[(k + 1) % element.size()].get<size_t>()];
      twice += a[0] * b[1] - b[0] * a[1];
    }
    EXPECT_GT(twice, 0);  // counter-clockwise
    area += twice / 2;
  }
  EXPECT_NEAR(area, 40 * 30 - 9.5 * 9.75, 1e-9);
  EXPECT_EQ(stats["elements"], dump["elements"].size());
  EXPECT_EQ(stats["vertices"], vertices.size());
  EXPECT_EQ(stats["t_vertices"], 0);
  EXPECT_EQ(stats["quads"].get<size_t>() + stats["triangles"].get<size_t>(), stats["elements"].get<size_t>());
}

TEST(MeshCommand, SceneDumpNamesTheSurfaceOfEachElement) {
  MeshOptions options;
  options.input = std::string(WALKRAD_ASSETS) + "/furnace.json";
  options.dump = std::string(WALKRAD_TEST_OUTPUT) + "/furnace-dump.json";
  options.stats = std::string(WALKRAD_TEST_OUTPUT) + "/furnace-stats.json";
  ASSERT_EQ(runMesh(options), 0);
  const nlohmann::json dump = readJson(options.dump);
  // The cube's faces are alike: the first is meshed, the other five are its repeats.
  EXPECT_EQ(readJson(options.stats)["repeats"], 5);
  EXPECT_EQ(dump["surface"].size(), dump["elements"].size());
  EXPECT_EQ(dump["vertices"][0].size(), 3u);
  // Six 1 m faces at 0.25 m patches: 16 quads each.
  EXPECT_EQ(dump["elements"].size(), 6u * 16);
  EXPECT_EQ(dump["surface"].back(), 5);
}

}  // namespace
}  // namespace app
