// Checks the screenshot that the window test took under Xvfb: the Cornell box as the headless
// render shows it, and the ImGui panel drawn over it.
#include "app/image/image.h"
#include "tests/app/image_read.h"
#include "tests/app/pixel_probe.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>

namespace app {
namespace {

TEST(WindowScreenshot, ShowsTheCornellBoxAndThePanel) {
  const char* path = std::getenv("WALKRAD_WINDOW_PNG");
  ASSERT_NE(path, nullptr);
  const ImageRgb8 image = test::readPng(path);
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(image.height, 720);
  // 16:9 with a 39.3 degree vertical field: the side walls span 23-33% and 67-77% of the width;
  // the panel covers the left wall down to about 60% of the height.
  const glm::dvec3 left = test::meanColor(image, 0.235, 0.25, 0.80, 0.90);
  const glm::dvec3 right = test::meanColor(image, 0.68, 0.75, 0.45, 0.55);
  EXPECT_GT(left.r, 2 * left.g) << "left wall is not red";
  EXPECT_GT(right.g, 1.25 * right.r) << "right wall is not green";
  // The panel sits at the top left over the black background: its text makes bright pixels.
  size_t bright = 0, total = 0;
  for (int y = 15; y < 200; ++y)
    for (int x = 15; x < 360; ++x, ++total) {
      const uint8_t* p = &image.pixels[(static_cast<size_t>(y) * 1280 + static_cast<size_t>(x)) * 3];
      if (p[0] + p[1] + p[2] > 400) ++bright;
    }
  EXPECT_GT(bright, total / 100) << "no panel text";
}

// `view --stats` of the same run: its five frames, their times in order, the display and memory.
TEST(WindowScreenshot, StatsCountTheFramesAndTheMemory) {
  const char* path = std::getenv("WALKRAD_WINDOW_STATS");
  ASSERT_NE(path, nullptr);
  const nlohmann::json stats = nlohmann::json::parse(std::ifstream(path));
  EXPECT_EQ(stats.at("frames"), 5);
  const double median = stats.at("frame_ms_median"), p95 = stats.at("frame_ms_p95"), most = stats.at("frame_ms_max");
  EXPECT_GT(median, 0);
  EXPECT_LE(median, p95);
  EXPECT_LE(p95, most);
  EXPECT_GT(stats.at("elements").get<double>(), 100);  // the Cornell box meshed at its patch size
  EXPECT_GT(stats.at("vertices").get<double>(), stats.at("elements").get<double>());
  // The camera sees into the whole box: every chunk (one for each of its three objects) drawn.
  EXPECT_EQ(stats.at("chunks_drawn").get<int>(), 3);
  EXPECT_EQ(stats.at("chunks_culled").get<int>(), 0);
  EXPECT_GT(stats.at("peak_rss_mb").get<double>(), 10);
  EXPECT_LT(stats.at("peak_rss_mb").get<double>(), 4096);
}

}  // namespace
}  // namespace app
