// Moving objects of a loaded, meshed scene: the one edit path that the window's drags and
// `walkrad render --move` share. A moved object's surfaces keep their meshes and move rigidly
// with it. Every pose is reached from the pose the scene was loaded with in one rigid motion, so
// moving an object back restores its loaded geometry exactly, however many moves came between.
#pragma once

#include "engine/meshed_scene.h"
#include "engine/scene.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace engine {

// Where an object stands: the spec's `position` and `rotate_y`.
struct ObjectPose {
  Vec3 position{0};
  double rotateYDeg = 0;
  bool operator==(const ObjectPose&) const = default;
};
ObjectPose poseOf(const Object& object);

class SceneEditor {
 public:
  SceneEditor(Scene scene, MeshedScene meshed);

  const Scene& scene() const { return scene_; }
  const MeshedScene& meshed() const { return meshed_; }
  // The surfaces an object is made of (indices into Scene::surfaces).
  const std::vector<uint32_t>& surfacesOf(uint32_t object) const { return surfacesOf_[object]; }
  std::optional<uint32_t> findObject(std::string_view name) const;

  // Puts `object` at `pose`, surfaces, meshes and scene bounds with it; returns whether anything
  // moved. Throws std::invalid_argument for an object that does not exist or is not movable.
  bool setPose(uint32_t object, const ObjectPose& pose);

 private:
  Scene scene_;
  MeshedScene meshed_;
  std::vector<std::vector<uint32_t>> surfacesOf_;  // per object
  // As loaded: the surfaces, their mesh positions and the objects' poses.
  std::vector<Surface> homeSurfaces_;
  std::vector<std::vector<Vec3>> homePositions_;
  std::vector<ObjectPose> homePoses_;
};

}  // namespace engine
