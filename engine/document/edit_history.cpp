#include "engine/document/edit_history.h"

namespace engine {

void EditHistory::record(const PoseEdit& edit) {
  if (edit.before == edit.after) return;
  edits_.resize(done_);
  // The saved state lay among the edits just dropped: no undo or redo leads back to it.
  if (saved_ > done_) saved_ = static_cast<size_t>(-1);
  edits_.push_back(edit);
  ++done_;
}

std::optional<PoseEdit> EditHistory::undo() {
  if (!canUndo()) return std::nullopt;
  return edits_[--done_];
}

std::optional<PoseEdit> EditHistory::redo() {
  if (!canRedo()) return std::nullopt;
  return edits_[done_++];
}

void EditHistory::amendLast(uint32_t object, const ObjectPose& refused, const ObjectPose& kept) {
  if (done_ == 0) return;
  PoseEdit& last = edits_[done_ - 1];
  if (last.object != object || last.after != refused) return;
  last.after = kept;
  if (last.before != last.after) return;
  edits_.erase(edits_.begin() + static_cast<ptrdiff_t>(--done_));
  if (saved_ > done_) saved_ = static_cast<size_t>(-1);  // the state saved was the refused pose's
}

}  // namespace engine
