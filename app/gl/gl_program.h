// A linked GLSL program from two of the embedded shaders.
#pragma once

#include <glad/gl.h>

#include <initializer_list>
#include <string_view>

namespace app {

class GlProgram {
 public:
  // Compiles and links, with each of `defines` #defined in both stages (a variant of the
  // shaders); throws std::runtime_error with the GL info log on failure.
  GlProgram(std::string_view vertexFile, std::string_view fragmentFile,
            std::initializer_list<std::string_view> defines = {});
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  GLuint id() const { return id_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace app
