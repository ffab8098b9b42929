#include "app/gl/scene_renderer.h"

#include <glm/common.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace app {

namespace {

constexpr GLuint kPosition = 0, kRadiance = 1;

void uploadBuffer(GLuint buffer, GLenum target, const void* data, size_t bytes) {
  glBindBuffer(target, buffer);
  glBufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
}

template <typename T>
void uploadBuffer(GLuint buffer, GLenum target, const std::vector<T>& values) {
  uploadBuffer(buffer, target, values.data(), values.size() * sizeof(T));
}

// The surfaces' per-vertex `values`, one surface after the other.
void gatherVertices(const engine::DisplayMesh& mesh, std::span<const uint32_t> surfaces,
                    std::vector<glm::vec3> engine::SurfaceDisplay::*values, std::vector<glm::vec3>& out) {
  out.clear();
  for (uint32_t s : surfaces) out.insert(out.end(), (mesh.surfaces[s].*values).begin(), (mesh.surfaces[s].*values).end());
}

// The surfaces' `indices`, one surface after the other, each moved past the vertices before it.
void gatherIndices(const engine::DisplayMesh& mesh, std::span<const uint32_t> surfaces,
                   std::vector<uint32_t> engine::SurfaceDisplay::*indices, std::vector<uint32_t>& out) {
  out.clear();
  uint32_t first = 0;
  for (uint32_t s : surfaces) {
    const engine::SurfaceDisplay& surface = mesh.surfaces[s];
    for (uint32_t i : surface.*indices) out.push_back(first + i);
    first += static_cast<uint32_t>(surface.positions.size());
  }
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

SceneRenderer::SceneRenderer() : wireClip_(wire_.uniform("u_clipFromObject")) {}

SceneRenderer::~SceneRenderer() { release(); }

void SceneRenderer::release() {
  for (const Chunk& chunk : chunks_) {
    const GLuint buffers[4] = {chunk.positions, chunk.radiance, chunk.triangles, chunk.edges};
    glDeleteBuffers(4, buffers);
    glDeleteVertexArrays(1, &chunk.vao);
  }
  chunks_.clear();
}

void SceneRenderer::upload(const engine::DisplayMesh& mesh) {
  release();
  chunkOf_.assign(mesh.surfaces.size(), 0);
  even_.assign(mesh.surfaces.size(), 0);
  for (ChunkPlan& plan : planChunks(mesh)) {
    Chunk& chunk = chunks_.emplace_back();
    chunk.object = plan.object;
    chunk.surfaces = std::move(plan.surfaces);
    for (uint32_t s : chunk.surfaces) chunkOf_[s] = static_cast<uint32_t>(chunks_.size() - 1);
    if (chunk.object >= displayFromObject_.size()) displayFromObject_.resize(chunk.object + 1, glm::mat4{1.0f});

    glGenVertexArrays(1, &chunk.vao);
    GLuint buffers[4];
    glGenBuffers(4, buffers);
    chunk.positions = buffers[0], chunk.radiance = buffers[1], chunk.triangles = buffers[2], chunk.edges = buffers[3];
    glBindVertexArray(chunk.vao);
    glBindBuffer(GL_ARRAY_BUFFER, chunk.positions);
    glEnableVertexAttribArray(kPosition);
    glVertexAttribPointer(kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(kRadiance);  // its form and buffer: fillRadiance()
    glBindVertexArray(0);
    fill(mesh, chunk);
  }
}

void SceneRenderer::fill(const engine::DisplayMesh& mesh, Chunk& chunk) {
  gatherVertices(mesh, chunk.surfaces, &engine::SurfaceDisplay::positions, vectors_);
  chunk.vertices = vectors_.size();
  chunk.low = glm::vec3{INFINITY}, chunk.high = glm::vec3{-INFINITY};
  for (const glm::vec3& p : vectors_) chunk.low = glm::min(chunk.low, p), chunk.high = glm::max(chunk.high, p);
  uploadBuffer(chunk.positions, GL_ARRAY_BUFFER, vectors_);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  chunk.radianceStale = true;
  chunk.edgesStale = true;
  chunk.band = kUngathered;
}

void SceneRenderer::gatherEdges(const engine::DisplayMesh& mesh, Chunk& chunk) {
  gatherIndices(mesh, chunk.surfaces, &engine::SurfaceDisplay::edges, indices_);
  // Element buffers are the VAO's state.
  glBindVertexArray(chunk.vao);
  uploadBuffer(chunk.edges, GL_ELEMENT_ARRAY_BUFFER, indices_);
  chunk.edgeIndices = static_cast<GLsizei>(indices_.size());
  glBindVertexArray(0);
  chunk.edgesStale = false;
  ++edgeUploads_;
}

void SceneRenderer::fillRadiance(const engine::DisplayMesh& mesh, Chunk& chunk, std::optional<float> colourExposure) {
  const void* data = nullptr;
  size_t bytes = 0;
  if (colourExposure) {
    if (!colours_ || colours_->exposure() != *colourExposure) colours_.emplace(*colourExposure);
    indices_.clear();
    for (uint32_t s : chunk.surfaces)
      for (const glm::vec3& radiance : mesh.surfaces[s].radiance) indices_.push_back(colours_->rgba(radiance));
    data = indices_.data(), bytes = indices_.size() * sizeof(uint32_t);
  } else {
    gatherVertices(mesh, chunk.surfaces, &engine::SurfaceDisplay::radiance, vectors_);
    data = vectors_.data(), bytes = vectors_.size() * sizeof(glm::vec3);
  }
  glBindBuffer(GL_ARRAY_BUFFER, chunk.radiance);
  if (bytes == chunk.radianceBytes && colourExposure.has_value() == chunk.colourExposure.has_value()) {
    // Into the storage there is: a new store every snapshot would cost llvmpipe fresh pages.
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
  } else {
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_DRAW);
    glBindVertexArray(chunk.vao);  // the attribute's form is the VAO's state
    if (colourExposure)
      glVertexAttribPointer(kRadiance, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, nullptr);
    else
      glVertexAttribPointer(kRadiance, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
    chunk.radianceBytes = bytes;
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  chunk.colourExposure = colourExposure;
  chunk.radianceStale = false;
  bool changed = false;
  for (uint32_t s : chunk.surfaces) {
    const bool even = evenlyLit(mesh.surfaces[s].radiance, even_[s] != 0, detail_);
    changed = changed || even != (even_[s] != 0);
    even_[s] = even;
  }
  if (changed) chunk.band = kUngathered;
}

void SceneRenderer::gatherDetail(const engine::DisplayMesh& mesh, const FrameSettings& frame, Chunk& chunk) {
  const float perUnit = frame.levelOfDetail ? pixelsPerUnit(frame.clipFromDisplay, frame.width) : 0;
  const int band = frame.levelOfDetail ? depthBand(nearestDepth(clipFromObject(frame, chunk.object), chunk.low, chunk.high)) : kEveryElement;
  if (band == chunk.band && perUnit == chunk.pixelsPerUnit) return;
  chunk.band = band;
  chunk.pixelsPerUnit = perUnit;
  if (band == kEveryElement)
    gatherIndices(mesh, chunk.surfaces, &engine::SurfaceDisplay::triangles, indices_);
  else
    gatherTriangles(mesh, chunk.surfaces, band, perUnit, even_, detail_, indices_);
  glBindVertexArray(chunk.vao);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, chunk.triangles);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices_.size() * sizeof(uint32_t)), indices_.data(), GL_DYNAMIC_DRAW);
  glBindVertexArray(0);
  chunk.triangleIndices = static_cast<GLsizei>(indices_.size());
}

void SceneRenderer::updateSurfaces(const engine::DisplayMesh& mesh, std::span<const uint32_t> surfaces) {
  std::vector<uint32_t> changed;
  changed.reserve(surfaces.size());
  for (uint32_t s : surfaces) changed.push_back(chunkOf_.at(s));
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  for (uint32_t c : changed) fill(mesh, chunks_[c]);
}

void SceneRenderer::updateRadiance(const engine::DisplayMesh& mesh) {
  for (const Chunk& chunk : chunks_) {
    size_t vertices = 0;
    for (uint32_t s : chunk.surfaces) vertices += mesh.surfaces.at(s).radiance.size();
    if (vertices != chunk.vertices)
      throw std::invalid_argument("radiance for " + std::to_string(vertices) + " vertices of a chunk that has " +
                                  std::to_string(chunk.vertices));
  }
  for (Chunk& chunk : chunks_) chunk.radianceStale = true;
}

void SceneRenderer::setObjectTransform(uint32_t object, const glm::mat4& displayFromObjectDisplay) {
  if (object >= displayFromObject_.size()) displayFromObject_.resize(object + 1, glm::mat4{1.0f});
  displayFromObject_[object] = displayFromObjectDisplay;
}

glm::mat4 SceneRenderer::clipFromObject(const FrameSettings& frame, uint32_t object) const {
  return frame.clipFromDisplay * displayFromObject_[object];
}

void SceneRenderer::cull(const FrameSettings& frame) {
  visible_.assign(chunks_.size(), 0);
  lastFrame_ = {};
  for (size_t c = 0; c < chunks_.size(); ++c) {
    const Chunk& chunk = chunks_[c];
    if (chunk.vertices == 0) continue;
    visible_[c] = !outsideView(clipFromObject(frame, chunk.object), chunk.low, chunk.high);
    ++(visible_[c] ? lastFrame_.chunksDrawn : lastFrame_.chunksCulled);
  }
}

void SceneRenderer::drawTriangles(const engine::DisplayMesh& mesh, const FrameSettings& frame, bool linearOutput) {
  cull(frame);
  const std::optional<float> colourExposure =
      frame.toneMapVertices && !linearOutput ? std::optional(frame.exposure) : std::nullopt;
  for (size_t c = 0; c < chunks_.size(); ++c) {
    if (!visible_[c]) continue;
    Chunk& chunk = chunks_[c];
    if (chunk.radianceStale || chunk.colourExposure != colourExposure) fillRadiance(mesh, chunk, colourExposure);
    gatherDetail(mesh, frame, chunk);
    lastFrame_.triangles += static_cast<size_t>(chunk.triangleIndices) / 3;
  }
  glViewport(0, 0, frame.width, frame.height);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  const GlProgram& shading = colourExposure || linearOutput ? passThrough_ : toneMapping_;
  const GLint clip = shading.uniform("u_clipFromObject");
  glUseProgram(shading.id());
  glUniform1f(shading.uniform("u_exposure"), frame.exposure);

  // Faces are one-sided, and their backs are not drawn: a walker outside a room sees into it
  // (a doll's house view) instead of a black wall, and silhouettes get no black seams where a
  // back face would win a pixel on the shared edge.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1, 1);  // keeps the wireframe in front of its own triangles
  for (size_t c = 0; c < chunks_.size(); ++c) {
    if (!visible_[c]) continue;
    const Chunk& chunk = chunks_[c];
    glUniformMatrix4fv(clip, 1, GL_FALSE, glm::value_ptr(clipFromObject(frame, chunk.object)));
    glBindVertexArray(chunk.vao);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, chunk.triangles);
    glDrawElements(GL_TRIANGLES, chunk.triangleIndices, GL_UNSIGNED_INT, nullptr);
  }
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void SceneRenderer::draw(const engine::DisplayMesh& mesh, const FrameSettings& frame) {
  drawTriangles(mesh, frame, false);
  if (frame.wireframe || frame.highlight) {
    glUseProgram(wire_.id());
    glDepthFunc(GL_LEQUAL);
    // The highlight after the whole wireframe, so that no white edge covers it.
    const auto drawEdges = [&](bool selectedOnly, glm::vec3 colour) {
      glUniform4f(wire_.uniform("u_color"), colour.r, colour.g, colour.b, 1);
      for (size_t c = 0; c < chunks_.size(); ++c) {
        Chunk& chunk = chunks_[c];
        if (!visible_[c] || (selectedOnly && chunk.object != *frame.highlight)) continue;
        if (chunk.edgesStale) gatherEdges(mesh, chunk);
        glUniformMatrix4fv(wireClip_, 1, GL_FALSE, glm::value_ptr(clipFromObject(frame, chunk.object)));
        glBindVertexArray(chunk.vao);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, chunk.edges);
        glDrawElements(GL_LINES, chunk.edgeIndices, GL_UNSIGNED_INT, nullptr);
      }
    };
    if (frame.wireframe) drawEdges(false, glm::vec3{1});
    if (frame.highlight) drawEdges(true, glm::vec3{1, 0.8f, 0.1f});
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

ImageRgbF SceneRenderer::drawLinear(const engine::DisplayMesh& mesh, const FrameSettings& frame) {
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
    drawTriangles(mesh, frame, true);
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
