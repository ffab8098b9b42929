// Where a scene's objects stand, and their surfaces placed there rigidly, without contact
// cut-outs or meshes: what the thread that draws needs to pick and drag objects, while the
// document (lit_scene.h) cuts, meshes and lights on its own thread. Every pose is reached from the
// pose the scene was loaded with in one rigid motion, so moving an object back restores its
// surfaces bit for bit, however many moves came between.
#pragma once

#include "engine/scene.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <cstdint>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace engine {

// Where an object stands: the spec's `position` and `rotate_y`.
struct ObjectPose {
  Vec3 position{0};
  double rotateYDeg = 0;
  bool operator==(const ObjectPose&) const = default;
};
ObjectPose poseOf(const Object& object);

// Whether a scene file can hold `pose`: its `position` and `rotate_y` finite and within
// kMaxLength, as the loader checks them, so that a scene saved after moves loads again.
bool inSceneLimits(const ObjectPose& pose);
// The position nearest a finite `position` that is within those limits (each coordinate clamped).
Vec3 clampToSceneLimits(const Vec3& position);

// The rigid motion (a turn about the vertical and a translation) that takes an object's points
// from one pose to another. From a pose to itself it is exactly the identity.
class RigidMotion {
 public:
  RigidMotion(const Object& object, const ObjectPose& from, const ObjectPose& to);
  Vec3 place(const Vec3& point) const { return identity_ ? point : turn_ * (point - from_) + to_; }
  Vec3 turn(const Vec3& direction) const { return identity_ ? direction : turn_ * direction; }
  bool identity() const { return identity_; }
  glm::dmat4 matrix() const;

 private:
  bool identity_;
  glm::dmat3 turn_{1.0};
  Vec3 from_{0}, to_{0};
};

class ScenePoses {
 public:
  // Takes the loaded scene; its surfaces lose their contact cut-outs.
  explicit ScenePoses(Scene scene);

  // The scene with every object where it stands now, its surfaces without cut-outs, and its
  // bounds.
  const Scene& scene() const { return scene_; }
  // The surfaces an object is made of (indices into Scene::surfaces).
  const std::vector<uint32_t>& surfacesOf(uint32_t object) const { return surfacesOf_[object]; }
  std::optional<uint32_t> findObject(std::string_view name) const;
  ObjectPose pose(uint32_t object) const { return poseOf(scene_.objects[object]); }
  const ObjectPose& loadedPose(uint32_t object) const { return loadedPoses_[object]; }
  // From where the object stood when loaded to `pose`.
  RigidMotion motionTo(uint32_t object, const ObjectPose& pose) const;
  // The surface `surface` of a movable object as loaded (without cut-outs), placed by `motion`.
  // Throws std::out_of_range for a fixed object's.
  Surface placed(uint32_t surface, const RigidMotion& motion) const;

  // Throws std::invalid_argument for an object that does not exist or is not movable, or a pose
  // beyond the scene limits (inSceneLimits).
  void checkPose(uint32_t object, const ObjectPose& pose) const;
  // Puts `object` at `pose`, its surfaces and the scene's bounds with it (after checkPose); returns
  // whether it moved. Costs the object's surfaces and one look at every object, not the scene's
  // surfaces.
  bool setPose(uint32_t object, const ObjectPose& pose);

 private:
  Scene scene_;
  std::unordered_map<uint32_t, Surface> loaded_;  // movable objects' surfaces as loaded, without cut-outs
  std::vector<ObjectPose> loadedPoses_;
  std::vector<std::vector<uint32_t>> surfacesOf_;  // per object
  std::optional<std::pair<Vec3, Vec3>> boundsOf(uint32_t object) const;  // of its surfaces where they stand
  std::vector<std::optional<std::pair<Vec3, Vec3>>> objectBounds_;  // per object: none without surfaces
};

}  // namespace engine
