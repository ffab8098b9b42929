// How the renderer cuts a display mesh into chunks, each drawn with buffers of its own, and when
// it leaves one out. Plain data, no GL: tests check it without a context.
#pragma once

#include "engine/document/display_mesh.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace app {

// Surfaces of one object drawn together: a surface meshed again re-uploads its chunk only, and
// an object moves by its transform alone (SceneRenderer::setObjectTransform).
struct ChunkPlan {
  uint32_t object = 0;
  std::vector<uint32_t> surfaces;  // indices into DisplayMesh::surfaces
};

// About the most vertices a chunk holds: few enough that culling a chunk saves drawing, many
// enough that a scene is hundreds of draws, not hundreds of thousands.
constexpr size_t kChunkVertices = size_t{1} << 16;

// Every surface in exactly one chunk, whole, with surfaces of its own object only; chunks in the
// order of their objects. An object of at most `maxVertices` vertices is one chunk, its surfaces
// in order. A larger one (a glTF building, one object of 266,000 surfaces) is cut into chunks of
// at most `maxVertices` (a larger surface alone) along the Morton order of its surfaces' centres,
// so each chunk is a compact region that culling can leave out.
std::vector<ChunkPlan> planChunks(const engine::DisplayMesh& mesh, size_t maxVertices = kChunkVertices);

// Whether the box [low, high] lies wholly outside the view volume of `clipFromBox` (clip
// coordinates from the box's): all its corners beyond one clip plane. Conservative: a box that
// only misses the volume near a corner of it is kept.
bool outsideView(const glm::mat4& clipFromBox, const glm::vec3& low, const glm::vec3& high);

}  // namespace app
