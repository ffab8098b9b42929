// The window's editing state: the scene being edited, its undo history, the mouse drag, and
// saving back to the scene's file (Ctrl+S) atomically.
#pragma once

#include "app/window/object_drag.h"
#include "engine/document/edit_history.h"
#include "engine/document/scene_editor.h"

#include <optional>
#include <string>

namespace app {

class SceneEdits {
 public:
  // `text` is the file's text `scene` was parsed from (empty for a glTF model); the scene is
  // meshed here.
  SceneEdits(std::string path, std::string text, engine::Scene scene);

  engine::SceneEditor& editor() { return editor_; }
  const engine::SceneEditor& editor() const { return editor_; }
  ObjectDrag& drag() { return drag_; }
  const engine::EditHistory& history() const { return history_; }

  // Records an edit that has been applied (a drag released, a turn).
  void record(const engine::PoseEdit& edit) { history_.record(edit); }
  // Takes back / applies again the last edit; returns the object that moved.
  std::optional<uint32_t> undo();
  std::optional<uint32_t> redo();

  // Writes the poses into the scene's file (temporary file, then rename). Returns a one-line
  // report: where it was saved, or why not (the file is then as it was). A glTF model is never
  // written, nor a text the loader would refuse: the report says so.
  std::string save();

 private:
  std::string path_, text_;
  engine::SceneEditor editor_;
  engine::EditHistory history_;
  ObjectDrag drag_{editor_};
};

}  // namespace app
