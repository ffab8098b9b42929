// One image of a scene through OSMesa: the same renderer as the window, no display needed.
#pragma once

#include "app/gl/scene_renderer.h"
#include "app/image/image.h"
#include "engine/document/display_mesh.h"
#include "engine/scene.h"
#include "engine/session/view_camera.h"

namespace app {

struct HeadlessImages {
  ImageRgb8 color;   // tone-mapped sRGB, with the wireframe when asked
  ImageRgbF linear;  // radiance; empty unless asked for
};

// Creates an offscreen GL 3.3 core context for the call. Throws std::runtime_error when OSMesa
// or the GL driver fails.
HeadlessImages renderHeadless(const engine::Scene& scene, const engine::DisplayMesh& mesh,
                              const engine::ViewCamera& camera, int width, int height, float exposure,
                              bool wireframe, bool wantLinear);

}  // namespace app
