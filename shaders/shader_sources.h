// The GLSL sources of shaders/, embedded in the program at build time.
#pragma once

#include <string_view>

namespace shaders {

// The text of a shader file by its file name ("gouraud.vert"), or empty when there is none.
std::string_view source(std::string_view name);

}  // namespace shaders
