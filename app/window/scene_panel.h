// The Dear ImGui panel of the walkthrough window: what the scene holds, how fast it draws,
// its viewpoints, and the display settings.
#pragma once

#include "engine/display_mesh.h"
#include "engine/lighting.h"
#include "engine/scene.h"

#include <string>

namespace app {

struct PanelState {
  float exposure = 1;
  bool wireframe = false;
  double walkSpeed = 1;         // scene units per second, shown
  int jumpToCamera = -1;        // set by the panel when a camera is clicked, index into cameras
  bool screenshotRequested = false;
  std::string lastScreenshot;   // path of the last screenshot, shown
  bool paused = false;          // the solver's pause toggle
  bool restartRequested = false;
  bool autoExposureRequested = false;
};

// Draws the panel for one frame; inputs that change the view or the solver are written into
// `state`. `lighting` is the newest solver snapshot.
void drawScenePanel(const engine::Scene& scene, const engine::DisplayMesh& mesh, const engine::LightingSnapshot& lighting,
                    PanelState& state);

}  // namespace app
