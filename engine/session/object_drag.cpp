#include "engine/session/object_drag.h"

#include "engine/geometry/pick.h"

#include <cmath>

namespace engine {

void ObjectDrag::deselect() {
  if (dragging_) release();
  selected_.reset();
}

bool ObjectDrag::press(const Ray& ray) {
  const engine::Scene& scene = view_.scene();
  const auto hit = engine::pickSurface(scene, ray.origin, ray.direction);
  if (!hit) {
    selected_.reset();
    return false;
  }
  selected_ = scene.surfaces[hit->surface].object;
  if (!scene.objects[*selected_].movable) return false;
  dragging_ = true;
  start_ = engine::poseOf(scene.objects[*selected_]);
  grab_ = hit->point;
  lifted_ = 0;
  slid_ = glm::dvec3{0};
  return true;
}

bool ObjectDrag::follow(const Ray& ray) {
  if (!dragging_ || ray.direction.y == 0) return false;
  // The resting plane is the horizontal through the grab point, lifted with the object.
  const double t = (grab_.y + lifted_ - ray.origin.y) / ray.direction.y;
  if (!(t > 0)) return false;
  const glm::dvec3 on = ray.origin + t * ray.direction;
  if (!std::isfinite(on.x) || !std::isfinite(on.z)) return false;  // a ray a hair from the horizon
  slid_ = {on.x - grab_.x, 0, on.z - grab_.z};
  return moveGrabbed();
}

bool ObjectDrag::lift(double dy) {
  if (!dragging_ || !std::isfinite(dy)) return false;
  lifted_ += dy;
  return moveGrabbed();
}

bool ObjectDrag::moveGrabbed() {
  const glm::dvec3 wanted = start_.position + slid_ + glm::dvec3{0, lifted_, 0};
  const glm::dvec3 position = engine::clampToSceneLimits(wanted);
  // Held at the scene limits, the slide and lift keep only what was reached, so the way back
  // starts with the first step.
  if (position != wanted) {
    slid_ = {position.x - start_.position.x, 0, position.z - start_.position.z};
    lifted_ = position.y - start_.position.y;
  }
  engine::ObjectPose pose = engine::poseOf(view_.scene().objects[*selected_]);
  pose.position = position;
  return place(pose);
}

std::optional<engine::PoseEdit> ObjectDrag::release() {
  if (!dragging_) return std::nullopt;
  dragging_ = false;
  const engine::ObjectPose now = engine::poseOf(view_.scene().objects[*selected_]);
  if (now == start_) return std::nullopt;
  return engine::PoseEdit{*selected_, start_, now};
}

std::optional<engine::PoseEdit> ObjectDrag::turn(double degrees) {
  if (!selected_ || !view_.scene().objects[*selected_].movable) return std::nullopt;
  const engine::ObjectPose before = engine::poseOf(view_.scene().objects[*selected_]);
  engine::ObjectPose after = before;
  after.rotateYDeg = std::remainder(before.rotateYDeg + degrees, 360.0);
  if (!place(after) || dragging_) return std::nullopt;
  return engine::PoseEdit{*selected_, before, after};
}

bool ObjectDrag::place(const engine::ObjectPose& pose) {
  if (refusedPose_ && *refusedPose_ == std::pair{*selected_, pose}) return false;
  if (!view_.setPose(*selected_, pose)) return false;
  newPose_ = {*selected_, pose};
  return true;
}

void ObjectDrag::refused(const engine::PoseRefusal& refusal) {
  refusal_ = refusal.why;
  refusedPose_ = {refusal.object, refusal.refused};
}

}  // namespace engine
