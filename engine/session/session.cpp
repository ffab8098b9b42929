#include "engine/session/session.h"

#include "engine/geometry/meshed_scene.h"
#include "engine/io/gltf_loader.h"
#include "engine/io/input_file.h"
#include "engine/io/load_limits.h"
#include "engine/io/scene_loader.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <utility>

namespace engine {

namespace {

PanelModel sceneModel(const Scene& scene) {
  PanelModel model;
  model.file = std::filesystem::path(scene.file).filename().string();
  model.units = scene.units;
  model.surfaces = scene.surfaces.size();
  for (const Object& o : scene.objects) model.objects.push_back({o.name, o.solids.size(), 0, o.movable});
  for (const Surface& s : scene.surfaces) ++model.objects[s.object].surfaces;
  for (const Camera& c : scene.cameras) model.cameras.push_back(c.name);
  return model;
}

// The view of `meshed`, shaded with the ambient term until the first light arrives.
SceneView shadedView(const Scene& scene, const MeshedScene& meshed) {
  SceneView view(scene, meshed);
  shadeWithAmbient(scene, view.display());
  return view;
}

void addMoved(std::vector<uint32_t>& moved, uint32_t object) {
  if (std::find(moved.begin(), moved.end(), object) == moved.end()) moved.push_back(object);
}

}  // namespace

OpenedScene openScene(const std::string& path, const LoadOptions& load, std::optional<double> patchSize) {
  OpenedScene opened;
  opened.path = path;
  if (isGltfPath(path)) {
    opened.scene = loadScene(path, load);
  } else {
    refuseGltfOptions(path, load);
    opened.text = readInputFile(path);
    opened.scene = parseScene(opened.text, path);
  }
  if (patchSize) overridePatchSize(opened.scene, *patchSize);
  return opened;
}

Session::Session(OpenedScene opened, const LightingSettings& lighting, const ViewCamera& camera)
    : Session(std::move(opened), meshScene(opened.scene), lighting, camera) {}

// The lighting thread's document and the view start from the same meshes.
Session::Session(OpenedScene&& opened, MeshedScene meshed, const LightingSettings& lighting, const ViewCamera& camera)
    : edits_(opened.path, std::move(opened.text), shadedView(opened.scene, meshed)),
      lighting_(std::move(opened.scene), std::move(meshed), lighting),
      shown_(lighting_.latest()),
      camera_(camera),
      panel_(sceneModel(scene())) {
  walk_.speed = defaultWalkSpeed(scene());
  updatePanel();
}

SessionFrame Session::frame(const SessionInput& input) {
  SessionFrame changes;
  // The walk; the wheel lifts what is dragged instead.
  WalkInput walk = input.walk;
  if (dragging()) walk.scroll = 0;
  applyWalk(walk, input.seconds, walk_, camera_);
  clock_ += input.seconds;
  if (input.jumpToCamera && *input.jumpToCamera < scene().cameras.size())
    camera_ = fromSceneCamera(scene().cameras[*input.jumpToCamera]);

  edit(input, changes);
  exchange(changes);
  if (changes.light) reportProgress(changes);
  if (input.save) {
    panel_.saveReport = edits_.save();
    changes.reports.push_back(panel_.saveReport);
  }

  if (input.pause) paused_ = *input.pause;
  if (paused_ != shown_->paused) lighting_.setPaused(paused_);
  if (input.restart) lighting_.restart();
  std::sort(changes.moved.begin(), changes.moved.end());
  updatePanel();
  return changes;
}

void Session::edit(const SessionInput& input, SessionFrame& changes) {
  ObjectDrag& drag = edits_.drag();
  const auto record = [&](const std::optional<PoseEdit>& edit) {
    if (edit) edits_.record(*edit);
  };
  if (input.press) drag.press(input.pointer);
  if (input.held && drag.dragging()) {
    drag.follow(input.pointer);
    if (input.walk.scroll != 0) drag.lift(input.walk.scroll * kLiftPerNotchMeters / scene().metersPerUnit);
  }
  if (!input.held) record(drag.release());
  if (input.turns != 0) record(drag.turn(input.turns * kTurnStepDeg));
  if (input.deselect) {
    record(drag.release());
    drag.deselect();
  }
  if (input.undo) edits_.undo();
  if (input.redo) edits_.redo();
  // An object moved in the view: the picture follows at once, the document is asked for the pose.
  for (const auto& [object, pose] : edits_.takePosesToSend()) {
    lighting_.requestPose(object, pose);
    addMoved(changes.moved, object);
  }
}

void Session::exchange(SessionFrame& changes) {
  const std::string refusedBefore = edits_.drag().refusal();
  // What the document did since the last frame: meshes, refusals, light.
  const LightingUpdate update = lighting_.take();
  const SceneView::Taken taken = edits_.take(update);
  changes.surfaces = taken.surfaces;
  changes.radiance = taken.radiance;
  for (uint32_t object : taken.movedBack) addMoved(changes.moved, object);
  changes.light = update.snapshot != shown_;
  shown_ = update.snapshot;
  const std::string& refused = edits_.drag().refusal();
  if (refused != refusedBefore && !refused.empty()) changes.reports.push_back("move refused: " + refused);
}

void Session::reportProgress(SessionFrame& changes) {
  const LightingSnapshot& s = *shown_;
  if (!s.error.empty() && s.error != errorReported_) changes.errors.push_back("the solver stopped: " + s.error);
  errorReported_ = s.error;
  std::ostringstream line;
  if (s.converged && !convergedReported_) {
    line << scene().file << ": converged after " << s.shots << " shots in " << s.solveSeconds << " s (unshot "
         << 100 * s.unshotFraction << "%)";
    convergedReported_ = true;
  } else if (!s.converged && s.shots > 0 && clock_ - lastProgress_ >= 2) {
    line << scene().file << ": " << s.shots << " shots, unshot " << 100 * s.unshotFraction << "%";
    lastProgress_ = clock_;
  }
  if (!s.converged) convergedReported_ = false;
  if (!line.str().empty()) changes.reports.push_back(line.str());
}

void Session::updatePanel() {
  const DisplayMesh& mesh = display();
  panel_.elements = mesh.elements;
  panel_.quads = mesh.quads;
  panel_.vertices = mesh.vertices;
  panel_.light = shown_;
  panel_.posesWaiting = static_cast<size_t>(edits_.posesSent() - std::min(shown_->edits, edits_.posesSent()));
  panel_.paused = paused_;
  panel_.walkSpeed = walk_.speed;
  panel_.selected.reset();
  if (const auto object = selected()) {
    const Object& o = scene().objects[*object];
    panel_.selected = PanelSelection{o.name, o.movable, o.position, o.rotateYDeg};
  }
  const EditHistory& history = edits_.history();
  panel_.canUndo = history.canUndo();
  panel_.canRedo = history.canRedo();
  panel_.unsaved = history.unsaved();
  panel_.editReport = edits_.drag().refusal();
}

}  // namespace engine
