// The displayed colour of linear radiance made on the CPU, by the encoding of shaders/tone.glsl
// (times the exposure, clamped, sRGB), for colours tone mapped per vertex: uploaded as bytes they
// cost llvmpipe's single-threaded vertex stage nothing per frame, and a third of the memory.
#pragma once

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstdint>

namespace app {

class DisplayColours {
 public:
  explicit DisplayColours(float exposure);

  float exposure() const { return exposure_; }
  // RGBA8 (alpha 255), red in the lowest byte: GL_UNSIGNED_BYTE x 4 in memory order. Within one
  // level of the exact encoding. Inline: a new snapshot turns millions of vertices.
  uint32_t rgba(const glm::vec3& radiance) const {
    uint32_t out = 0xff000000u;
    for (int k = 0; k < 3; ++k) {
      // NaN (a solver fault) clamps to black, as the shader's clamp leaves it undefined.
      const float c = std::clamp(radiance[k] * exposure_, 0.0f, 1.0f);
      const auto step = c == c ? static_cast<size_t>(c * kSteps + 0.5f) : 0;
      out |= static_cast<uint32_t>(encoded_[step]) << (8 * k);
    }
    return out;
  }

 private:
  // The encoding of c in [0, 1] at kSteps + 1 evenly spaced points: steep enough steps that the
  // nearest point is within half a level of 8 bits plus the rounding.
  static constexpr int kSteps = 8192;
  float exposure_;
  std::array<uint8_t, kSteps + 1> encoded_;
};

}  // namespace app
