// The CPU's displayed colours against the sRGB encoding's closed form (IEC 61966-2-1).
#include "app/gl/display_colours.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace app {
namespace {

int level(uint32_t rgba, int channel) { return static_cast<int>((rgba >> (8 * channel)) & 0xffu); }

double exactLevel(double linear) {
  const double c = std::fmin(std::fmax(linear, 0.0), 1.0);
  return 255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055);
}

TEST(DisplayColours, AreWithinOneLevelOfTheExactEncodingAcrossTheRange) {
  const DisplayColours colours(1.0f);
  double worst = 0;
  for (int i = 0; i <= 100000; ++i) {
    const float c = static_cast<float>(i) / 100000;
    const uint32_t rgba = colours.rgba(glm::vec3{c, c * 0.5f, c * c});
    worst = std::fmax(worst, std::fabs(level(rgba, 0) - exactLevel(c)));
    worst = std::fmax(worst, std::fabs(level(rgba, 1) - exactLevel(c * 0.5)));
    worst = std::fmax(worst, std::fabs(level(rgba, 2) - exactLevel(static_cast<double>(c) * c)));
    ASSERT_EQ(level(rgba, 3), 255);
  }
  EXPECT_LE(worst, 1.0);
}

TEST(DisplayColours, ScaleByTheExposureAndClampOutOfRangeValues) {
  const DisplayColours colours(4.0f);
  EXPECT_EQ(colours.rgba(glm::vec3{0.125f, 0.25f, 1.0f}), colours.rgba(glm::vec3{0.125f, 0.25f, 7.0f}));
  EXPECT_NEAR(level(colours.rgba(glm::vec3{0.125f}), 0), exactLevel(0.5), 1.0);
  EXPECT_EQ(level(colours.rgba(glm::vec3{0.25f}), 0), 255);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(colours.rgba(glm::vec3{-1.0f, nan, 0.0f}), 0xff000000u);
}

}  // namespace
}  // namespace app
