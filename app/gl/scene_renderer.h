// Draws a DisplayMesh with the shaders of shaders/: Gouraud-shaded radiance, optionally the
// mesh edges over it. One code path for the GLFW window and the OSMesa image. Needs a current
// GL 3.3 core context whose functions glad has loaded.
#pragma once

#include "app/gl/gl_program.h"
#include "app/image/image.h"
#include "engine/document/display_mesh.h"

#include <glm/mat4x4.hpp>

#include <utility>
#include <vector>

namespace app {

struct FrameSettings {
  glm::mat4 clipFromDisplay{1.0f};  // clip coordinates from the display mesh's (clipFromDisplay)
  int width = 640, height = 480;
  float exposure = 1;
  bool wireframe = false;
  // Index ranges [first, end) of the mesh's edge list drawn in the highlight colour whether or
  // not the wireframe is on: the selected object.
  std::vector<std::pair<uint32_t, uint32_t>> highlight;
};

class SceneRenderer {
 public:
  SceneRenderer();
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Replaces the mesh on the GPU.
  void upload(const engine::DisplayMesh& mesh);
  // Replaces the vertex radiance only (a new lighting snapshot); one value per uploaded vertex.
  void updateRadiance(const std::vector<glm::vec3>& radiance);
  // Replaces the vertex positions only (an object moved; same mesh).
  void updatePositions(const std::vector<glm::vec3>& positions);

  // Draws into the bound framebuffer: tone-mapped sRGB colour, the wireframe when asked.
  void draw(const FrameSettings& frame) const;

  // Draws linear radiance (no wireframe, no tone mapping) into an offscreen float target and
  // reads it back; the bound framebuffer is left as it was.
  ImageRgbF drawLinear(const FrameSettings& frame) const;

 private:
  void drawTriangles(const FrameSettings& frame, bool linearOutput) const;
  void replaceVertexData(GLuint buffer, const std::vector<glm::vec3>& values) const;

  GlProgram shading_{"gouraud.vert", "gouraud.frag"};
  GlProgram wire_{"wire.vert", "wire.frag"};
  GLuint vao_ = 0, positions_ = 0, radiance_ = 0, triangles_ = 0, edges_ = 0;
  GLsizei triangleIndices_ = 0, edgeIndices_ = 0;
  size_t vertices_ = 0;
};

// Reads the bound framebuffer's `buffer` (GL_BACK, GL_FRONT, GL_COLOR_ATTACHMENT0) as RGB8, top
// row first.
ImageRgb8 readFramebuffer(int width, int height, GLenum buffer);

}  // namespace app
