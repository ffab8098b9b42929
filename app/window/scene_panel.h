// The Dear ImGui panel of the walkthrough window: what the scene holds, how fast it draws,
// its viewpoints, and the display settings.
#pragma once

#include "engine/document/display_mesh.h"
#include "engine/document/lighting.h"
#include "engine/scene.h"

#include <glm/vec3.hpp>

#include <string>

namespace app {

struct PanelState {
  float exposure = 1;
  bool wireframe = false;
  bool levelOfDetail = true;    // far or evenly lit surfaces drawn as their outlines (level_of_detail.h)
  double walkSpeed = 1;         // scene units per second, shown
  size_t chunksDrawn = 0, chunksCulled = 0;  // the display's chunks in the last frame, shown
  size_t trianglesDrawn = 0;                  // and its triangles, shown
  int jumpToCamera = -1;        // set by the panel when a camera is clicked, index into cameras
  bool screenshotRequested = false;
  std::string lastScreenshot;   // path of the last screenshot, shown
  bool paused = false;          // the solver's pause toggle
  bool restartRequested = false;
  bool autoExposureRequested = false;
  // Editing: what the window shows of the selection and history, and what the panel asks for.
  std::string selected;            // the selected object's name; empty when none
  bool selectedMovable = false;
  glm::dvec3 selectedPosition{0};
  double selectedTurn = 0;         // rotate_y, degrees
  bool canUndo = false, canRedo = false, unsaved = false;
  std::string saveReport;          // the last save's one-line report
  std::string editReport;          // why the last move was refused; empty when it was not
  std::string openReport;          // why the last file dropped onto the window did not open
  bool undoRequested = false, redoRequested = false, saveRequested = false;
};

// Draws the panel for one frame; inputs that change the view or the solver are written into
// `state`. `lighting` is the newest solver snapshot.
void drawScenePanel(const engine::Scene& scene, const engine::DisplayMesh& mesh, const engine::LightingSnapshot& lighting,
                    PanelState& state);

}  // namespace app
