// Which triangles of a chunk a frame draws: each surface either whole (its elements) or as its
// outline (SurfaceDisplay::outline, the polygon alone) when its elements cannot show: the whole
// surface a few pixels across on the screen, or lit so evenly that its elements' Gouraud shading
// is its outline's within a contrast the eye does not see. A surface switches as a whole, so no
// two levels meet inside one (no cracks); the outline's edges are the polygon's, on which the
// elements' boundary points lie. Plain data, no GL: tests check it without a context.
#pragma once

#include "engine/document/display_mesh.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <climits>
#include <cstdint>
#include <span>
#include <vector>

namespace app {

struct DetailSettings {
  // A surface whose whole extent covers at most this many pixels is drawn as its outline.
  float outlinePixels = 3;
  // A surface becomes evenly lit when its vertices' luminance spans at most `evenContrast` of
  // their mean, and stops being so beyond `unevenContrast` (hysteresis: light that settles slowly
  // does not flip it back and forth).
  float evenContrast = 0.02f, unevenContrast = 0.03f;
};

// Chunks are judged by the depth of their nearest corner, in bands a factor of two apart: band b
// holds depths in [2^b, 2^(b+1)) scene units. kNearBand: the chunk reaches the eye (all detail).
constexpr int kNearBand = INT_MIN;
int depthBand(float nearestDepth);
// The view depth (clip w) of the nearest corner of the box [low, high] under `clipFromBox`.
float nearestDepth(const glm::mat4& clipFromBox, const glm::vec3& low, const glm::vec3& high);
// Pixels per scene unit at depth 1 for a frame `width` pixels wide drawn through `clipFromDisplay`
// (a perspective projection after a rigid view).
float pixelsPerUnit(const glm::mat4& clipFromDisplay, int width);

// Whether `radiance`'s luminance is even (DetailSettings), given whether it was.
bool evenlyLit(std::span<const glm::vec3> radiance, bool wasEven, const DetailSettings& settings);

// Whether `surface` is drawn as its outline in a chunk of `band`: never without an outline; when
// it is evenly lit, at any depth (the outline's shading is within the evenness contrast of its
// elements'); else when its extent is at most settings.outlinePixels at the band's nearest depth
// (never at kNearBand).
bool drawsOutline(const engine::SurfaceDisplay& surface, int band, float pixelsPerUnit, bool even,
                  const DetailSettings& settings);

// The triangles of `surfaces` (one chunk, its vertices one surface after another) at `band`:
// each surface's elements or its outline, indices moved past the vertices before it. `even` is
// per surface of the mesh.
void gatherTriangles(const engine::DisplayMesh& mesh, std::span<const uint32_t> surfaces, int band, float pixelsPerUnit,
                     std::span<const uint8_t> even, const DetailSettings& settings, std::vector<uint32_t>& out);

}  // namespace app
