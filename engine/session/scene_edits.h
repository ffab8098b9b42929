// A session's editing state (session.h): the scene as the thread that draws holds it, its undo
// history, the mouse drag, the exchange with the document on the lighting thread (poses asked
// for, what it sends back), and saving back to the scene's file (Ctrl+S) atomically.
#pragma once

#include "engine/document/edit_history.h"
#include "engine/document/scene_view.h"
#include "engine/session/object_drag.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace engine {

class SceneEdits {
 public:
  // `text` is the file's text the view's scene was parsed from (empty for a glTF model).
  SceneEdits(std::string path, std::string text, engine::SceneView view);
  SceneEdits(const SceneEdits&) = delete;  // the drag holds on to the view
  SceneEdits& operator=(const SceneEdits&) = delete;

  engine::SceneView& view() { return view_; }
  const engine::SceneView& view() const { return view_; }
  ObjectDrag& drag() { return drag_; }
  const ObjectDrag& drag() const { return drag_; }
  const engine::EditHistory& history() const { return history_; }

  // Records an edit that has been made (a drag released, a turn).
  void record(const engine::PoseEdit& edit) { history_.record(edit); }
  // Takes back / applies again the last edit; returns the object that moved.
  std::optional<uint32_t> undo();
  std::optional<uint32_t> redo();

  // The poses to ask the document for (engine::LightingThread::requestPose), in order: what
  // drags, turns, undo and redo did since the last call.
  std::vector<std::pair<uint32_t, engine::ObjectPose>> takePosesToSend();
  // How many poses takePosesToSend has given, in all (LightingSnapshot::edits counts those taken).
  uint64_t posesSent() const { return posesSent_; }
  // What the document sent back (LightingThread::take) goes into the view. A refused pose puts
  // the object back where the document keeps it; the drag shows why until a pose asked for after
  // the refusal has been taken, and an edit recorded with that pose keeps the pose the object
  // stayed at instead.
  engine::SceneView::Taken take(const engine::LightingUpdate& update);

  // Writes the poses into the scene's file (temporary file, then rename). Returns a one-line
  // report: where it was saved, or why not (the file is then as it was). A glTF model is never
  // written, nor a text the loader would refuse: the report says so.
  std::string save();

 private:
  std::string path_, text_;
  engine::SceneView view_;
  engine::EditHistory history_;
  ObjectDrag drag_{view_};
  std::vector<std::pair<uint32_t, engine::ObjectPose>> toSend_;  // from undo and redo
  uint64_t posesSent_ = 0;
  uint64_t refusalShownUntil_ = 0;  // the poses sent when the last refusal came
};

}  // namespace engine
