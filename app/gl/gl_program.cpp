#include "app/gl/gl_program.h"

#include "shaders/shader_sources.h"

#include <stdexcept>
#include <string>

namespace app {

namespace {

GLuint compile(GLenum stage, std::string_view file) {
  const std::string_view text = shaders::source(file);
  if (text.empty()) throw std::runtime_error("no embedded shader named " + std::string(file));
  const GLuint shader = glCreateShader(stage);
  const char* data = text.data();
  const auto size = static_cast<GLint>(text.size());
  glShaderSource(shader, 1, &data, &size);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string(file) + ": " + log);
  }
  return shader;
}

}  // namespace

GlProgram::GlProgram(std::string_view vertexFile, std::string_view fragmentFile) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertexFile);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragmentFile);
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(id_, sizeof log, nullptr, log);
    glDeleteProgram(id_);
    throw std::runtime_error(std::string(vertexFile) + " + " + std::string(fragmentFile) + ": " + log);
  }
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

}  // namespace app
