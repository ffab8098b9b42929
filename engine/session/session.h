// A walk through a scene with its edits, free of any window system (no GLFW, GL or ImGui), as
// Dear ImGui's null backend runs a UI: the window translates its keys, mouse and panel into a
// SessionInput each frame, and draws what the session gives back (the camera, the objects'
// transforms, the display mesh's changes and the panel's model). The session owns the scene as
// the thread that draws holds it (SceneView), the edits and their undo history and saving
// (SceneEdits), the drag, the walker's camera, and the lighting thread (LightingThread) that
// meshes, cuts and lights the document. Tests drive it frame by frame with no display.
#pragma once

#include "engine/document/lighting.h"
#include "engine/io/load_scene.h"
#include "engine/session/scene_edits.h"
#include "engine/session/view_camera.h"
#include "engine/session/walk_controls.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace engine {

// A scene opened for walking: its file's path and text (kept for saving poses into it; empty
// for a glTF model, which is never written) and the scene.
struct OpenedScene {
  std::string path, text;
  Scene scene;
};

// Opens a scene file or glTF model, its patch sizes overridden by `patchSize` when given.
// Throws SceneError for a file that is not a valid scene or model.
OpenedScene openScene(const std::string& path, const LoadOptions& load = {}, std::optional<double> patchSize = {});

// What the user asked for in one frame, as actions rather than keys and buttons.
struct SessionInput {
  double seconds = 0;  // since the last frame: how far the walk goes
  // Walking and looking; its wheel notches lift the object being dragged instead of changing
  // the walking speed.
  WalkInput walk;
  Ray pointer;        // the ray under the cursor
  bool press = false;  // the select button went down (off the panel): select what `pointer` hits, grab it if movable
  bool held = false;   // the select button is down: a grabbed object follows `pointer`; up, the drag ends
  int turns = 0;       // turn steps of the selected object (kTurnStepDeg each; negative: the other way)
  bool deselect = false;
  bool undo = false, redo = false, save = false;
  std::optional<bool> pause;  // the solver's pause asked for: true pauses, false resumes
  bool restart = false;       // the solver starts again from the emitters
  std::optional<size_t> jumpToCamera;  // index into the scene's cameras
};

// One object of the scene, as the panel lists it.
struct PanelObject {
  std::string name;
  size_t solids = 0, surfaces = 0;
  bool movable = true;
};

// The selected object, as the panel shows it.
struct PanelSelection {
  std::string name;
  bool movable = false;
  Vec3 position{0};
  double turnDeg = 0;  // rotate_y
};

// What the panel shows, in numbers and strings; the window draws it.
struct PanelModel {
  std::string file, units;  // the scene file's name (no folder), and the scene's length unit
  size_t surfaces = 0;
  size_t elements = 0, quads = 0, vertices = 0;  // of the display mesh
  std::vector<PanelObject> objects;
  std::vector<std::string> cameras;  // the scene's, by name, in order
  std::shared_ptr<const LightingSnapshot> light;  // the newest: shots, unshot energy, corrections, errors
  size_t posesWaiting = 0;  // poses sent to the lighting thread that it has not taken yet
  bool paused = false;  // the pause asked for (the light follows after the shot in flight)
  double walkSpeed = 1;  // scene units per second
  std::optional<PanelSelection> selected;
  bool canUndo = false, canRedo = false, unsaved = false;
  std::string saveReport;  // the last save's one-line report
  std::string editReport;  // why the document refused the last move; empty when it did not
};

// What changed in a frame, for the window to draw.
struct SessionFrame {
  std::vector<uint32_t> moved;     // objects whose transforms changed (Session::objectTransform), ascending
  std::vector<uint32_t> surfaces;  // whose display meshes were replaced: to upload again, ascending
  bool radiance = false;           // the display's radiance changed
  bool light = false;              // a new lighting snapshot (PanelModel::light)
  // One-line reports for the terminal: the light's progress (a line about every two seconds while
  // it shoots, one when it converges), saves, refused moves.
  std::vector<std::string> reports;
  std::vector<std::string> errors;  // one-line reports of failures: the solver stopped
};

class Session {
 public:
  static constexpr double kTurnStepDeg = 15;  // R and Shift+R
  static constexpr double kLiftPerNotchMeters = 0.05;  // the wheel during a drag

  // Meshes `opened` and starts lighting it on its own thread (`lighting`: its adaptive
  // refinement as the caller chose for the scene), the display shaded with the ambient term
  // until the first light arrives; the walk starts at `camera`. Throws what meshScene and
  // LightingThread throw.
  Session(OpenedScene opened, const LightingSettings& lighting, const ViewCamera& camera);
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // One frame: the walk, the drag and turns, undo, redo and saving, the poses sent to the
  // lighting thread and what it sent back. Never waits for a shot.
  SessionFrame frame(const SessionInput& input);

  const Scene& scene() const { return edits_.view().scene(); }  // where every object stands in the picture
  const ViewCamera& camera() const { return camera_; }
  // The display mesh, each object where it stood when loaded; objectTransform shows it where it stands.
  const DisplayMesh& display() const { return edits_.view().display(); }
  glm::dmat4 objectTransform(uint32_t object) const { return edits_.view().objectTransform(object); }
  std::optional<uint32_t> selected() const { return edits_.drag().selected(); }
  bool dragging() const { return edits_.drag().dragging(); }
  const PanelModel& panel() const { return panel_; }

 private:
  Session(OpenedScene&& opened, MeshedScene meshed, const LightingSettings& lighting, const ViewCamera& camera);
  // The mouse and keys' edits of the frame; the objects they moved go into `moved`.
  void edit(const SessionInput& input, SessionFrame& changes);
  // Sends the poses the edits gave to the lighting thread, and takes what it sent back.
  void exchange(SessionFrame& changes);
  // The progress lines for a new lighting snapshot.
  void reportProgress(SessionFrame& changes);
  void updatePanel();

  SceneEdits edits_;
  LightingThread lighting_;
  std::shared_ptr<const LightingSnapshot> shown_;  // the newest snapshot taken
  ViewCamera camera_;
  WalkSettings walk_;
  bool paused_ = false;  // asked for
  // What the progress lines said: the session's time (the frames' seconds summed) at the last, whether
  // the light's convergence was reported, the last error reported.
  double clock_ = 0, lastProgress_ = 0;
  bool convergedReported_ = false;
  std::string errorReported_;
  PanelModel panel_;
};

}  // namespace engine
