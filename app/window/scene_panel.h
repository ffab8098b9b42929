// The Dear ImGui panel of the walkthrough window: it draws the session's panel model (what the
// scene holds, the light's progress, the selection and history) with the window's own display
// settings, and turns its buttons into the next frame's session input.
#pragma once

#include "engine/session/session.h"

#include <string>

namespace app {

// What the window keeps of its own: display settings, and what only it knows.
struct PanelState {
  float exposure = 1;
  bool wireframe = false;
  bool levelOfDetail = true;    // far or evenly lit surfaces drawn as their outlines (level_of_detail.h)
  size_t chunksDrawn = 0, chunksCulled = 0;  // the display's chunks in the last frame, shown
  size_t trianglesDrawn = 0;                  // and its triangles, shown
  bool screenshotRequested = false;
  std::string lastScreenshot;   // path of the last screenshot, shown
  bool autoExposureRequested = false;
  std::string openReport;       // why the last file dropped onto the window did not open
};

// Draws the panel for one frame. Display settings change `state`; what the session is to do
// (undo, redo, save, pause, restart, a camera to jump to) goes into `next`, the next frame's input.
void drawScenePanel(const engine::PanelModel& model, PanelState& state, engine::SessionInput& next);

}  // namespace app
