// Images in memory and on disk: 8-bit sRGB PNG and linear float PFM, rows top first.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace app {

struct ImageRgb8 {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // width * height * 3, top row first
};

struct ImageRgbF {
  int width = 0, height = 0;
  std::vector<float> pixels;  // width * height * 3, top row first
};

// Both writers write a temporary file beside `path` and rename it, so an existing file is
// replaced whole or not at all. They throw std::runtime_error naming the path on failure.
void writePng(const std::string& path, const ImageRgb8& image);
// Standard PFM: "PF", little-endian (negative scale), rows stored bottom row first.
void writePfm(const std::string& path, const ImageRgbF& image);

}  // namespace app
