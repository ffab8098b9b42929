// Mean colours of image regions and differences of images, for tests that check pictures on pixels.
#pragma once

#include "app/image/image.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cstdlib>

namespace app::test {

// Mean RGB (0..255) over the rectangle of fractions [x0, x1) x [y0, y1) of the image, y down.
inline glm::dvec3 meanColor(const ImageRgb8& image, double x0, double x1, double y0, double y1) {
  glm::dvec3 sum{0};
  int count = 0;
  for (int y = static_cast<int>(y0 * image.height); y < static_cast<int>(y1 * image.height); ++y)
    for (int x = static_cast<int>(x0 * image.width); x < static_cast<int>(x1 * image.width); ++x) {
      const uint8_t* p = &image.pixels[(static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x)) * 3];
      sum += glm::dvec3{p[0], p[1], p[2]};
      ++count;
    }
  return count ? sum / static_cast<double>(count) : sum;
}

// How two images of one size differ: the mean difference over all channels in 8-bit levels, and
// the share of pixels with a channel more than `levels` apart. `amplified`, when given, receives
// the difference eight times over, for whoever looks.
struct ImageDifference {
  double meanLevels = 0, shareBeyond = 0;
};
inline ImageDifference difference(const ImageRgb8& a, const ImageRgb8& b, double levels, ImageRgb8* amplified = nullptr) {
  if (amplified) *amplified = ImageRgb8{a.width, a.height, std::vector<uint8_t>(a.pixels.size())};
  double sum = 0;
  size_t beyond = 0;
  for (size_t p = 0; p < a.pixels.size(); p += 3) {
    int worst = 0;
    for (size_t k = 0; k < 3; ++k) {
      const int d = std::abs(int{a.pixels[p + k]} - int{b.pixels[p + k]});
      sum += d;
      worst = std::max(worst, d);
      if (amplified) amplified->pixels[p + k] = static_cast<uint8_t>(std::min(255, 8 * d));
    }
    beyond += worst > levels;
  }
  const double pixels = static_cast<double>(a.pixels.size() / 3);
  return {sum / static_cast<double>(a.pixels.size()), static_cast<double>(beyond) / pixels};
}

}  // namespace app::test
