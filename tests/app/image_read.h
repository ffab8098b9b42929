// Reading back the images walkrad writes (app/image/image.h), for the tests: the program itself
// only writes them.
#pragma once

#include "app/image/image.h"

#include <string>

namespace app::test {

// Reads a PNG as RGB8; throws std::runtime_error naming the path when it cannot.
ImageRgb8 readPng(const std::string& path);
// Reads a PFM written by writePfm (or any little-endian RGB PFM); throws std::runtime_error
// naming the path when it cannot.
ImageRgbF readPfm(const std::string& path);

}  // namespace app::test
