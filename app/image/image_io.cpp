#include "app/image/image.h"
#include "engine/io/atomic_file.h"

#include <stb_image_write.h>

#include <cstring>
#include <sstream>
#include <stdexcept>

namespace app {

namespace {

void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

}  // namespace

void writePng(const std::string& path, const ImageRgb8& image) {
  std::string bytes;
  if (!stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 3, image.pixels.data(), image.width * 3))
    throw std::runtime_error(path + ": cannot encode PNG");
  engine::writeFileAtomically(path, bytes);
}

void writePfm(const std::string& path, const ImageRgbF& image) {
  std::string bytes = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  const size_t row = static_cast<size_t>(image.width) * 3;
  for (int y = image.height - 1; y >= 0; --y) {  // PFM stores the bottom row first
    const float* data = image.pixels.data() + static_cast<size_t>(y) * row;
    bytes.append(reinterpret_cast<const char*>(data), row * sizeof(float));  // x86-64 is little-endian
  }
  engine::writeFileAtomically(path, bytes);
}

}  // namespace app
