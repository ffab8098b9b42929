// Undo and redo of object moves (Ctrl+Z, Ctrl+Y), and whether the scene differs from its file.
#pragma once

#include "engine/document/scene_poses.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace engine {

struct PoseEdit {
  uint32_t object = 0;
  ObjectPose before, after;
};

class EditHistory {
 public:
  // Records an edit that has been applied; edits undone before it can no longer be redone.
  // An edit that changes nothing is not recorded.
  void record(const PoseEdit& edit);
  // The edit to take back (apply its `before`), or nothing when there is none.
  std::optional<PoseEdit> undo();
  // The edit to apply again (its `after`), or nothing when there is none.
  std::optional<PoseEdit> redo();
  // The last edit done moved `object` to `refused`, which the document refused: it moved the
  // object to `kept` instead (an edit that then changes nothing goes). Other edits stay.
  void amendLast(uint32_t object, const ObjectPose& refused, const ObjectPose& kept);
  bool canUndo() const { return done_ > 0; }
  bool canRedo() const { return done_ < edits_.size(); }

  // The scene was saved (or loaded) as it stands now.
  void markSaved() { saved_ = done_; }
  // Whether the scene differs from what was last saved, by the edits' count (undoing back to the
  // saved state makes it clean again).
  bool unsaved() const { return saved_ != done_; }

 private:
  std::vector<PoseEdit> edits_;
  size_t done_ = 0;
  // How many edits were done at the last save; SIZE_MAX once that state can no longer be reached.
  size_t saved_ = 0;
};

}  // namespace engine
