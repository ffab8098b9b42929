#include "tests/app/image_read.h"

#include <stb_image.h>

#include <fstream>
#include <stdexcept>

namespace app::test {

ImageRgb8 readPng(const std::string& path) {
  int width = 0, height = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 3);
  if (!data) throw std::runtime_error(path + ": cannot read PNG: " + stbi_failure_reason());
  ImageRgb8 image{width, height, std::vector<uint8_t>(data, data + static_cast<size_t>(width) * static_cast<size_t>(height) * 3)};
  stbi_image_free(data);
  return image;
}

ImageRgbF readPfm(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::string magic;
  ImageRgbF image;
  double scale = 0;
  file >> magic >> image.width >> image.height >> scale;
  file.get();  // the single whitespace byte before the data
  if (!file || magic != "PF" || scale >= 0 || image.width <= 0 || image.height <= 0)
    throw std::runtime_error(path + ": not a little-endian RGB PFM");
  const size_t row = static_cast<size_t>(image.width) * 3;
  image.pixels.resize(row * static_cast<size_t>(image.height));
  for (int y = image.height - 1; y >= 0; --y)
    file.read(reinterpret_cast<char*>(image.pixels.data() + static_cast<size_t>(y) * row),
              static_cast<std::streamsize>(row * sizeof(float)));
  if (!file) throw std::runtime_error(path + ": PFM is truncated");
  return image;
}

}  // namespace app::test
