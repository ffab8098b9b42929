// Draws a DisplayMesh with the shaders of shaders/: Gouraud-shaded radiance, optionally the
// mesh edges over it. One code path for the GLFW window and the OSMesa image. Needs a current
// GL 3.3 core context whose functions glad has loaded.
//
// The mesh lives on the GPU in chunks (display_chunks.h): surfaces of one object, each chunk with
// buffers and bounds of its own. A surface meshed again re-uploads its chunk only, an object
// moves by a transform of its own without any upload, and a chunk wholly outside the view is not
// drawn, nor is new radiance uploaded to it until it is. A chunk's triangles are gathered from
// the mesh when its level of detail changes (level_of_detail.h), its element edges when they are
// first drawn (the wireframe, or its object selected): a building's edges took 53 MB of the
// driver's memory, drawn by no frame without the wireframe.
#pragma once

#include "app/gl/display_chunks.h"
#include "app/gl/display_colours.h"
#include "app/gl/gl_program.h"
#include "app/gl/level_of_detail.h"
#include "app/image/image.h"
#include "engine/document/display_mesh.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace app {

struct FrameSettings {
  glm::mat4 clipFromDisplay{1.0f};  // clip coordinates from the display mesh's (clipFromDisplay)
  int width = 640, height = 480;
  float exposure = 1;
  bool wireframe = false;
  // The selected object: its element edges are drawn in the highlight colour whether or not the
  // wireframe is on.
  std::optional<uint32_t> highlight;
  // Surfaces too small on the screen or too evenly lit to show their elements drawn as their
  // outlines (level_of_detail.h): the window's frames. Off, every element is drawn (images).
  bool levelOfDetail = false;
  // The displayed colour computed per vertex and interpolated, as Gouraud shading hardware did
  // (Pixel-Planes 5 among it), instead of per pixel: a third less of llvmpipe's work on a kitchen
  // at 1280x720, for gradients a little darker between unlike vertices. The colours are made on
  // the CPU when radiance or exposure changes (display_colours.h). The window's frames; off,
  // images keep the exact per-pixel colour.
  bool toneMapVertices = false;
};

// What the last frame drew: chunks within the view, and chunks left out as wholly outside it;
// the triangles drawn.
struct FrameCounts {
  size_t chunksDrawn = 0, chunksCulled = 0;
  size_t triangles = 0;
};

class SceneRenderer {
 public:
  SceneRenderer();
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Replaces the mesh on the GPU, cut into chunks anew. Object transforms set stay.
  void upload(const engine::DisplayMesh& mesh);
  // Uploads again the chunks that hold `surfaces` of `mesh` (the mesh uploaded, with those
  // surfaces changed: moved, or meshed again with other vertices). The chunks stay as they were
  // cut.
  void updateSurfaces(const engine::DisplayMesh& mesh, std::span<const uint32_t> surfaces);
  // Takes the vertex radiance only (a new lighting snapshot) of the mesh uploaded: uploaded to each
  // chunk when it is next drawn. Throws std::invalid_argument, changing nothing, when a surface's
  // vertex count is not the one uploaded.
  void updateRadiance(const engine::DisplayMesh& mesh);
  // Draws `object`'s surfaces through `displayFromObjectDisplay` (display coordinates from its
  // vertices'): identity until set, kept across uploads.
  void setObjectTransform(uint32_t object, const glm::mat4& displayFromObjectDisplay);

  // Draws `mesh` (the one uploaded, as updated since) into the bound framebuffer: tone-mapped sRGB
  // colour, the wireframe when asked.
  void draw(const engine::DisplayMesh& mesh, const FrameSettings& frame);

  // Draws linear radiance (no wireframe, no tone mapping) into an offscreen float target and
  // reads it back; the bound framebuffer is left as it was.
  ImageRgbF drawLinear(const engine::DisplayMesh& mesh, const FrameSettings& frame);

  const FrameCounts& lastFrame() const { return lastFrame_; }
  size_t chunkCount() const { return chunks_.size(); }
  // Chunks' element edges uploaded since construction: each when first drawn after its chunk was
  // filled.
  size_t edgeUploads() const { return edgeUploads_; }

 private:
  struct Chunk {
    uint32_t object = 0;
    std::vector<uint32_t> surfaces;
    GLuint vao = 0, positions = 0, radiance = 0, triangles = 0, edges = 0;
    GLsizei triangleIndices = 0, edgeIndices = 0;
    size_t vertices = 0;
    glm::vec3 low{0}, high{0};  // the bounds of its positions (before its object's transform)
    // What its triangle buffer holds: the level of detail it was gathered at (kEveryElement
    // without one, kUngathered: to be gathered); whether radiance is waiting to be uploaded.
    int band = kUngathered;
    float pixelsPerUnit = 0;
    bool radianceStale = true;
    bool edgesStale = true;  // its edge buffer is not its surfaces' edges: gathered when drawn
    // What its radiance buffer holds (bytes of it): displayed colours at this exposure, or
    // linear radiance when empty.
    std::optional<float> colourExposure;
    size_t radianceBytes = 0;
  };
  static constexpr int kUngathered = INT_MAX, kEveryElement = INT_MAX - 1;

  void fill(const engine::DisplayMesh& mesh, Chunk& chunk);
  // Uploads the chunk's radiance, as displayed colours at `colourExposure` when there is one, and
  // judges its surfaces' evenness (even_) anew.
  void fillRadiance(const engine::DisplayMesh& mesh, Chunk& chunk, std::optional<float> colourExposure);
  // The chunk's triangles at the frame's level of detail, gathered again when it changed.
  void gatherDetail(const engine::DisplayMesh& mesh, const FrameSettings& frame, Chunk& chunk);
  void gatherEdges(const engine::DisplayMesh& mesh, Chunk& chunk);
  void release();
  glm::mat4 clipFromObject(const FrameSettings& frame, uint32_t object) const;
  // Which chunks the frame draws (visible_), counted in lastFrame_.
  void cull(const FrameSettings& frame);
  void drawTriangles(const engine::DisplayMesh& mesh, const FrameSettings& frame, bool linearOutput);

  // The shading's variants: tone mapping each pixel, and passing on what the vertices hold (linear
  // radiance or displayed colours).
  GlProgram toneMapping_{"gouraud.vert", "gouraud.frag"};
  GlProgram passThrough_{"gouraud.vert", "gouraud.frag", {"PASS_THROUGH"}};
  GlProgram wire_{"wire.vert", "wire.frag"};
  GLint wireClip_ = -1;
  std::vector<Chunk> chunks_;
  std::vector<uint32_t> chunkOf_;  // per surface
  std::vector<glm::mat4> displayFromObject_;
  std::vector<uint8_t> visible_;  // per chunk, in the frame being drawn
  const DetailSettings detail_;
  std::vector<uint8_t> even_;  // per surface: evenly lit (level_of_detail.h), as last uploaded
  FrameCounts lastFrame_;
  size_t edgeUploads_ = 0;
  // Scratch for assembling a chunk's buffers, kept from chunk to chunk.
  std::vector<glm::vec3> vectors_;
  std::vector<uint32_t> indices_;  // also the RGBA8 colours of fillRadiance
  std::optional<DisplayColours> colours_;  // at the exposure last asked for
};

// Reads the bound framebuffer's `buffer` (GL_BACK, GL_FRONT, GL_COLOR_ATTACHMENT0) as RGB8, top
// row first.
ImageRgb8 readFramebuffer(int width, int height, GLenum buffer);

}  // namespace app
