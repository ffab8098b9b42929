#include "app/gl/display_colours.h"

#include <cmath>

namespace app {

namespace {

double srgbEncoded(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }

}  // namespace

DisplayColours::DisplayColours(float exposure) : exposure_(exposure) {
  for (int i = 0; i <= kSteps; ++i)
    encoded_[static_cast<size_t>(i)] = static_cast<uint8_t>(std::lround(255 * srgbEncoded(static_cast<double>(i) / kSteps)));
}

}  // namespace app
