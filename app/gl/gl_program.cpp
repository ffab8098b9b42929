#include "app/gl/gl_program.h"

#include "shaders/shader_sources.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace app {

namespace {

// Throws with the info log when a shader or program `id` failed its `status` check; `what` names
// it in the message. `getStatus`/`getLog`/`destroy` are the glGet*iv, glGet*InfoLog and glDelete*
// of its kind.
template <typename GetStatus, typename GetLog, typename Destroy>
void checkStatus(GLuint id, GLenum status, GetStatus getStatus, GetLog getLog, Destroy destroy,
                 const std::string& what) {
  GLint ok = 0;
  getStatus(id, status, &ok);
  if (ok) return;
  char log[2048] = {};
  getLog(id, sizeof log, nullptr, log);
  destroy(id);
  throw std::runtime_error(what + ": " + log);
}

std::string_view embedded(std::string_view file) {
  const std::string_view text = shaders::source(file);
  if (text.empty()) throw std::runtime_error("no embedded shader named " + std::string(file));
  return text;
}

// GLSL has no #include: each line `#include "NAME"` becomes the embedded file NAME, so that the
// stages share functions (tone.glsl). `defines` follow the first line (GLSL's #version must come
// first).
std::string preprocessed(std::string_view text, std::initializer_list<std::string_view> defines) {
  static constexpr std::string_view kInclude = "#include \"";
  std::string out;
  for (bool first = true; !text.empty(); first = false) {
    const size_t end = std::min(text.find('\n'), text.size() - 1) + 1;
    const std::string_view line = text.substr(0, end);
    const size_t close = line.find('"', kInclude.size());
    if (line.starts_with(kInclude) && close != std::string_view::npos)
      out += embedded(line.substr(kInclude.size(), close - kInclude.size()));
    else
      out += line;
    text.remove_prefix(end);
    if (first)
      for (const std::string_view name : defines) out.append("#define ").append(name) += '\n';
  }
  return out;
}

GLuint compile(GLenum stage, std::string_view file, std::initializer_list<std::string_view> defines) {
  const std::string text = preprocessed(embedded(file), defines);
  const GLuint shader = glCreateShader(stage);
  const char* data = text.data();
  const auto size = static_cast<GLint>(text.size());
  glShaderSource(shader, 1, &data, &size);
  glCompileShader(shader);
  checkStatus(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, glDeleteShader, std::string(file));
  return shader;
}

}  // namespace

GlProgram::GlProgram(std::string_view vertexFile, std::string_view fragmentFile,
                     std::initializer_list<std::string_view> defines) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertexFile, defines);
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragmentFile, defines);
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  checkStatus(id_, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, glDeleteProgram,
              std::string(vertexFile) + " + " + std::string(fragmentFile));
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

}  // namespace app
