#include "engine/document/scene_poses.h"

#include "engine/geometry/contact_cutouts.h"
#include "engine/geometry/solid_surfaces.h"
#include "engine/io/load_limits.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace engine {

ObjectPose poseOf(const Object& object) { return {object.position, object.rotateYDeg}; }

bool inSceneLimits(const ObjectPose& pose) {
  const auto within = [](double x) { return std::abs(x) <= kMaxLength; };  // false for NaN
  return within(pose.position.x) && within(pose.position.y) && within(pose.position.z) && within(pose.rotateYDeg);
}

Vec3 clampToSceneLimits(const Vec3& position) { return glm::clamp(position, Vec3(-kMaxLength), Vec3(kMaxLength)); }

RigidMotion::RigidMotion(const Object& object, const ObjectPose& from, const ObjectPose& to) : identity_(from == to) {
  if (identity_) return;
  // world = to * from^-1: a turn about y and a translation, so the inverse is the transpose.
  Object before = object, after = object;
  before.position = from.position;
  before.rotateYDeg = from.rotateYDeg;
  after.position = to.position;
  after.rotateYDeg = to.rotateYDeg;
  const Placement a = placementOf(before), b = placementOf(after);
  turn_ = b.worldFromObject * glm::transpose(a.worldFromObject);
  from_ = a.translation;
  to_ = b.translation;
}

glm::dmat4 RigidMotion::matrix() const {
  glm::dmat4 m(turn_);
  m[3] = glm::dvec4(place(Vec3(0)), 1);
  return m;
}

ScenePoses::ScenePoses(Scene scene) : scene_(std::move(scene)), surfacesOf_(scene_.objects.size()) {
  removeContacts(scene_.surfaces);
  // Only what can move needs its loaded outline kept: a building's fixed walls are most surfaces.
  for (uint32_t s = 0; s < scene_.surfaces.size(); ++s)
    if (scene_.objects[scene_.surfaces[s].object].movable) loaded_.emplace(s, scene_.surfaces[s]);
  for (const Object& o : scene_.objects) loadedPoses_.push_back(poseOf(o));
  for (uint32_t s = 0; s < scene_.surfaces.size(); ++s) surfacesOf_[scene_.surfaces[s].object].push_back(s);
  for (uint32_t o = 0; o < scene_.objects.size(); ++o) objectBounds_.push_back(boundsOf(o));
}

std::optional<std::pair<Vec3, Vec3>> ScenePoses::boundsOf(uint32_t object) const {
  std::optional<std::pair<Vec3, Vec3>> bounds;
  for (uint32_t s : surfacesOf_[object])
    for (const Vec3& p : scene_.surfaces[s].outer)
      bounds = bounds ? std::pair{glm::min(bounds->first, p), glm::max(bounds->second, p)} : std::pair{p, p};
  return bounds;
}

std::optional<uint32_t> ScenePoses::findObject(std::string_view name) const {
  for (uint32_t i = 0; i < scene_.objects.size(); ++i)
    if (scene_.objects[i].name == name) return i;
  return std::nullopt;
}

RigidMotion ScenePoses::motionTo(uint32_t object, const ObjectPose& pose) const {
  return {scene_.objects[object], loadedPoses_[object], pose};
}

Surface ScenePoses::placed(uint32_t surface, const RigidMotion& motion) const {
  Surface s = loaded_.at(surface);
  for (Vec3& p : s.outer) p = motion.place(p);
  for (Ring3& hole : s.holes)
    for (Vec3& p : hole) p = motion.place(p);
  if (!motion.identity()) s.normal = glm::normalize(motion.turn(s.normal));
  return s;
}

void ScenePoses::checkPose(uint32_t object, const ObjectPose& pose) const {
  if (object >= scene_.objects.size()) throw std::invalid_argument("no object " + std::to_string(object));
  const Object& o = scene_.objects[object];
  if (!o.movable) throw std::invalid_argument("object \"" + o.name + "\" is not movable");
  if (!inSceneLimits(pose)) throw std::invalid_argument("object \"" + o.name + "\" would stand beyond the scene limits");
}

bool ScenePoses::setPose(uint32_t object, const ObjectPose& pose) {
  checkPose(object, pose);
  if (this->pose(object) == pose) return false;
  const RigidMotion motion = motionTo(object, pose);
  for (uint32_t s : surfacesOf_[object]) scene_.surfaces[s] = placed(s, motion);
  scene_.objects[object].position = pose.position;
  scene_.objects[object].rotateYDeg = pose.rotateYDeg;
  // The scene's bounds from the objects': as Scene::computeBounds makes them, at the cost of the
  // objects rather than of every surface.
  objectBounds_[object] = boundsOf(object);
  bool first = true;
  for (const auto& bounds : objectBounds_)
    if (bounds) {
      scene_.boundsMin = first ? bounds->first : glm::min(scene_.boundsMin, bounds->first);
      scene_.boundsMax = first ? bounds->second : glm::max(scene_.boundsMax, bounds->second);
      first = false;
    }
  return true;
}

}  // namespace engine
