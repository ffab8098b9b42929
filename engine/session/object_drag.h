// Selecting and moving objects with the mouse and keys, as a pure controller over the scene as the
// thread that draws holds it (engine::SceneView): the window feeds it rays and key presses, asks
// the document for the poses it gives (newPose) and takes back the edits to record. A drag slides the object along the horizontal plane through the point grabbed (its
// resting plane: furniture stays on the floor); the wheel during a drag lifts it; turns are about
// the vertical through the object's origin.
#pragma once

#include "engine/document/edit_history.h"
#include "engine/document/scene_view.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace engine {

struct Ray {
  glm::dvec3 origin{0}, direction{0, 0, 1};
};

class ObjectDrag {
 public:
  explicit ObjectDrag(engine::SceneView& view) : view_(view) {}

  std::optional<uint32_t> selected() const { return selected_; }
  void deselect();
  bool dragging() const { return dragging_; }

  // A press of the left button: selects the object under the ray (or nothing) and, when it is
  // movable, grabs it. Returns whether a drag started.
  bool press(const Ray& ray);
  // The mouse moved with the button held: the grabbed object follows the ray's crossing with
  // its resting plane (not when the ray runs above the horizon), up to the scene limits
  // (engine::inSceneLimits). Returns whether it moved.
  bool follow(const Ray& ray);
  // Raises the grabbed object by `dy` (scene units; negative lowers it), up to the scene limits.
  // Returns whether it moved.
  bool lift(double dy);
  // The button came up: the drag's edit, when the object moved.
  std::optional<engine::PoseEdit> release();

  // Turns the selected object (dragged or not) by `degrees` about the vertical. The edit, when
  // an object is selected, is movable and not being dragged (a drag records its turns with it).
  std::optional<engine::PoseEdit> turn(double degrees);

  // The pose the last move or turn put an object at, for the document to take; once taken.
  std::optional<std::pair<uint32_t, engine::ObjectPose>> takeNewPose() { return std::exchange(newPose_, std::nullopt); }
  // The document refused a pose (the mesher refused a surface it would have cut); the view has
  // put the object back where the document keeps it. A drag goes on from there; its edit, and a
  // turn's recorded already, are what the history is to hold.
  void refused(const engine::PoseRefusal& refusal);
  // Why the document last refused a pose (one line), until `accepted` says a later one was taken.
  const std::string& refusal() const { return refusal_; }
  void accepted() { refusal_.clear(), refusedPose_.reset(); }

 private:
  // Puts the selected object at `pose`, unless the view or the document refused it (the pointer
  // held on a refused spot does not ask the document again every frame); returns whether it moved.
  bool place(const engine::ObjectPose& pose);
  // Puts the grabbed object where the drag's slide and lift take it, within the scene limits.
  bool moveGrabbed();

  engine::SceneView& view_;
  std::optional<uint32_t> selected_;
  bool dragging_ = false;
  engine::ObjectPose start_;   // the pose when the drag began
  glm::dvec3 grab_{0};         // the point grabbed, at the drag's start
  double lifted_ = 0;          // height added by the wheel during this drag
  glm::dvec3 slid_{0};         // horizontal offset from the drag's start
  std::string refusal_;
  std::optional<std::pair<uint32_t, engine::ObjectPose>> refusedPose_;  // the last the document refused
  std::optional<std::pair<uint32_t, engine::ObjectPose>> newPose_;
};

}  // namespace engine
