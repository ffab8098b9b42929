// Mean colours of image regions, for tests that check pictures on pixels.
#pragma once

#include "app/image/image.h"

#include <glm/vec3.hpp>

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

}  // namespace app::test
