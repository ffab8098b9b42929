#include "app/gl/display_colours.h"

#include <algorithm>
#include <cmath>

namespace app {

namespace {

double srgbEncoded(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }

}  // namespace

DisplayColours::DisplayColours(float exposure) : exposure_(exposure) {
  for (int i = 0; i <= kSteps; ++i)
    encoded_[static_cast<size_t>(i)] = static_cast<uint8_t>(std::lround(255 * srgbEncoded(static_cast<double>(i) / kSteps)));
}

uint32_t DisplayColours::rgba(const glm::vec3& radiance) const {
  uint32_t out = 0xff000000u;
  for (int k = 0; k < 3; ++k) {
    // NaN (a solver fault) clamps to black, as the shader's clamp leaves it undefined.
    const float c = std::clamp(radiance[k] * exposure_, 0.0f, 1.0f);
    const auto step = c == c ? static_cast<size_t>(c * kSteps + 0.5f) : 0;
    out |= static_cast<uint32_t>(encoded_[step]) << (8 * k);
  }
  return out;
}

}  // namespace app
