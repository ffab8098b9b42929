#include "engine/session/scene_edits.h"

#include "engine/io/atomic_file.h"
#include "engine/io/gltf_loader.h"
#include "engine/io/scene_loader.h"
#include "engine/io/scene_saver.h"

#include <exception>
#include <utility>

namespace engine {

SceneEdits::SceneEdits(std::string path, std::string text, engine::SceneView view)
    : path_(std::move(path)), text_(std::move(text)), view_(std::move(view)) {}

// Undo and redo put an object back at a pose the scene stood in, every other object where it
// stood then: the document places surfaces from their loaded pose, so the polygons to mesh are
// bit for bit those it meshed then (SceneEditor tests), and the mesher cannot refuse them.
std::optional<uint32_t> SceneEdits::undo() {
  if (const auto dragged = drag_.release()) history_.record(*dragged);  // a drag in progress first
  const auto edit = history_.undo();
  if (!edit) return std::nullopt;
  view_.setPose(edit->object, edit->before);
  toSend_.emplace_back(edit->object, edit->before);
  return edit->object;
}

std::optional<uint32_t> SceneEdits::redo() {
  if (const auto dragged = drag_.release()) history_.record(*dragged);
  const auto edit = history_.redo();
  if (!edit) return std::nullopt;
  view_.setPose(edit->object, edit->after);
  toSend_.emplace_back(edit->object, edit->after);
  return edit->object;
}

std::vector<std::pair<uint32_t, engine::ObjectPose>> SceneEdits::takePosesToSend() {
  // A drag's pose was set before any undo in the same frame (undo releases the drag first).
  std::vector<std::pair<uint32_t, engine::ObjectPose>> poses;
  if (const auto dragged = drag_.takeNewPose()) poses.push_back(*dragged);
  for (auto& pose : toSend_) poses.push_back(pose);
  toSend_.clear();
  posesSent_ += poses.size();
  return poses;
}

engine::SceneView::Taken SceneEdits::take(const engine::LightingUpdate& update) {
  for (const engine::PoseRefusal& refusal : update.refusals) {
    drag_.refused(refusal);
    history_.amendLast(refusal.object, refusal.refused, refusal.kept);
    refusalShownUntil_ = posesSent_;
  }
  if (update.refusals.empty() && update.snapshot && update.snapshot->edits > refusalShownUntil_) drag_.accepted();
  return view_.take(update);
}

std::string SceneEdits::save() {
  // Rewriting a modeller's file would lose what walkrad does not read (textures, normals,
  // animation), so poses are written only into scene files.
  if (engine::isGltfPath(path_)) return "not saved: " + path_ + " is a glTF model; walkrad saves poses only into scene files (.json)";
  try {
    const std::string text = engine::sceneTextWithPoses(text_, view_.scene());
    // A file that would not load again is not written; the loader's error says why (an object
    // moved so far off that the scene's patch size is too small for its extent).
    engine::parseScene(text, path_);
    engine::writeFileAtomically(path_, text);
    text_ = text;
    history_.markSaved();
    return "saved " + path_;
  } catch (const std::exception& e) {
    return std::string("not saved: ") + e.what();
  }
}

}  // namespace engine
