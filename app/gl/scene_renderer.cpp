#include "app/gl/scene_renderer.h"

#include <glm/gtc/type_ptr.hpp>

#include <stdexcept>
#include <string>

namespace app {

namespace {

constexpr GLuint kPosition = 0, kRadiance = 1;

void uploadBuffer(GLuint buffer, GLenum target, const void* data, size_t bytes) {
  glBindBuffer(target, buffer);
  glBufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
}

// GL rows run bottom-up; images run top-down.
template <typename T>
void flipRows(std::vector<T>& pixels, size_t rowLength, int height) {
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(pixels.begin() + static_cast<ptrdiff_t>(y * rowLength),
                     pixels.begin() + static_cast<ptrdiff_t>((y + 1) * rowLength),
                     pixels.begin() + static_cast<ptrdiff_t>((height - 1 - y) * rowLength));
}

}  // namespace

SceneRenderer::SceneRenderer() {
  glGenVertexArrays(1, &vao_);
  GLuint buffers[4];
  glGenBuffers(4, buffers);
  positions_ = buffers[0], radiance_ = buffers[1], triangles_ = buffers[2], edges_ = buffers[3];
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, positions_);
  glEnableVertexAttribArray(kPosition);
  glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, radiance_);
  glEnableVertexAttribArray(kRadiance);
  glVertexAttribPointer(kRadiance, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindVertexArray(0);
}

SceneRenderer::~SceneRenderer() {
  const GLuint buffers[4] = {positions_, radiance_, triangles_, edges_};
  glDeleteBuffers(4, buffers);
  glDeleteVertexArrays(1, &vao_);
}

void SceneRenderer::upload(const engine::DisplayMesh& mesh) {
  glBindVertexArray(vao_);
  uploadBuffer(positions_, GL_ARRAY_BUFFER, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  uploadBuffer(radiance_, GL_ARRAY_BUFFER, mesh.radiance.data(), mesh.radiance.size() * sizeof(glm::vec3));
  glBindVertexArray(0);
  uploadBuffer(triangles_, GL_ELEMENT_ARRAY_BUFFER, mesh.triangles.data(), mesh.triangles.size() * sizeof(uint32_t));
  uploadBuffer(edges_, GL_ELEMENT_ARRAY_BUFFER, mesh.edges.data(), mesh.edges.size() * sizeof(uint32_t));
  triangleIndices_ = static_cast<GLsizei>(mesh.triangles.size());
  edgeIndices_ = static_cast<GLsizei>(mesh.edges.size());
  vertices_ = mesh.positions.size();
}

void SceneRenderer::replaceVertexData(GLuint buffer, const std::vector<glm::vec3>& values) const {
  if (values.size() != vertices_) throw std::invalid_argument("vertex data for " + std::to_string(values.size()) +
                                                              " vertices, the mesh has " + std::to_string(vertices_));
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(values.size() * sizeof(glm::vec3)), values.data());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void SceneRenderer::updateRadiance(const std::vector<glm::vec3>& radiance) { replaceVertexData(radiance_, radiance); }

void SceneRenderer::updatePositions(const std::vector<glm::vec3>& positions) { replaceVertexData(positions_, positions); }

void SceneRenderer::drawTriangles(const FrameSettings& frame, bool linearOutput) const {
  glViewport(0, 0, frame.width, frame.height);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(shading_.id());
  glUniformMatrix4fv(shading_.uniform("u_clipFromDisplay"), 1, GL_FALSE, glm::value_ptr(frame.clipFromDisplay));
  glUniform1f(shading_.uniform("u_exposure"), frame.exposure);
  glUniform1i(shading_.uniform("u_linearOutput"), linearOutput ? 1 : 0);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, triangles_);

  // Faces are one-sided, and their backs are not drawn: a walker outside a room sees into it
  // (a doll's house view) instead of a black wall, and silhouettes get no black seams where a
  // back face would win a pixel on the shared edge.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1, 1);  // keeps the wireframe in front of its own triangles
  glDrawElements(GL_TRIANGLES, triangleIndices_, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void SceneRenderer::draw(const FrameSettings& frame) const {
  drawTriangles(frame, false);
  if ((frame.wireframe || !frame.highlight.empty()) && edgeIndices_ > 0) {
    glUseProgram(wire_.id());
    glUniformMatrix4fv(wire_.uniform("u_clipFromDisplay"), 1, GL_FALSE, glm::value_ptr(frame.clipFromDisplay));
    glDepthFunc(GL_LEQUAL);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, edges_);
    if (frame.wireframe) {
      glUniform4f(wire_.uniform("u_color"), 1, 1, 1, 1);
      glDrawElements(GL_LINES, edgeIndices_, GL_UNSIGNED_INT, nullptr);
    }
    glUniform4f(wire_.uniform("u_color"), 1, 0.8f, 0.1f, 1);
    for (const auto& [first, end] : frame.highlight)
      glDrawElements(GL_LINES, static_cast<GLsizei>(end - first), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(static_cast<uintptr_t>(first) * sizeof(uint32_t)));
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

ImageRgbF SceneRenderer::drawLinear(const FrameSettings& frame) const {
  GLint previous = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  GLuint target = 0, color = 0, depth = 0;
  glGenFramebuffers(1, &target);
  glGenRenderbuffers(1, &color);
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, frame.width, frame.height);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, frame.width, frame.height);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;

  ImageRgbF image{frame.width, frame.height, {}};
  if (complete) {
    drawTriangles(frame, true);
    glBindVertexArray(0);
    glUseProgram(0);
    image.pixels.resize(static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height) * 3);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, frame.width, frame.height, GL_RGB, GL_FLOAT, image.pixels.data());
    flipRows(image.pixels, static_cast<size_t>(frame.width) * 3, frame.height);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  glDeleteRenderbuffers(1, &color);
  glDeleteRenderbuffers(1, &depth);
  glDeleteFramebuffers(1, &target);
  if (!complete) throw std::runtime_error("the GL driver has no float render target");
  return image;
}

ImageRgb8 readFramebuffer(int width, int height, GLenum buffer) {
  ImageRgb8 image{width, height, std::vector<uint8_t>(static_cast<size_t>(width) * static_cast<size_t>(height) * 3)};
  glReadBuffer(buffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.pixels.data());
  flipRows(image.pixels, static_cast<size_t>(width) * 3, height);
  return image;
}

}  // namespace app
