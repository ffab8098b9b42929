// Moving objects of a loaded, meshed scene: the one edit path that the window's drags and
// `walkrad render --move` share. A moved object's surfaces keep their meshes and move rigidly
// with it; contact cut-outs (geometry/contact_cutouts.h) follow: a surface whose footprints
// changed (the floor under a moved box, the box's own top when something stood on it) is meshed
// again.
// Every pose is reached from the pose the scene was loaded with in one rigid motion, so moving
// an object back restores the loaded geometry and meshes exactly, however many moves came
// between.
#pragma once

#include "engine/geometry/meshed_scene.h"
#include "engine/scene.h"

#include <cstdint>
#include <optional>
#include <string_view>
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

class SceneEditor {
 public:
  SceneEditor(Scene scene, MeshedScene meshed);

  const Scene& scene() const { return scene_; }
  const MeshedScene& meshed() const { return meshed_; }
  // The surfaces an object is made of (indices into Scene::surfaces).
  const std::vector<uint32_t>& surfacesOf(uint32_t object) const { return surfacesOf_[object]; }
  std::optional<uint32_t> findObject(std::string_view name) const;

  // Puts `object` at `pose`, surfaces, meshes, cut-outs and scene bounds with it; returns
  // whether anything moved. Throws std::invalid_argument for an object that does not exist or is
  // not movable, or a pose beyond the scene limits (inSceneLimits). Throws SceneError
  // (MeshTooLarge, MeshTooFine at the surface's JSON path) when a surface to be meshed again is
  // refused by the mesher (a footprint leaving a sliver of floor a hair wide); the scene, its
  // meshes and remeshed() are then as they were before the call.
  bool setPose(uint32_t object, const ObjectPose& pose);
  // The surfaces the last setPose meshed again (their element counts may differ); the object's
  // other surfaces kept their meshes.
  const std::vector<uint32_t>& remeshed() const { return remeshed_; }
  // The surfaces that setPose changed since the last call, for the light to take
  // (engine::applyEdit): the moved objects' surfaces, and every surface meshed again (meshed
  // anew, though it was moved along in another call).
  std::vector<EditedSurface> takeEdited() { return std::exchange(edited_, {}); }

 private:
  Scene scene_;
  MeshedScene meshed_;
  std::vector<std::vector<uint32_t>> surfacesOf_;  // per object
  // The surfaces without cut-outs where the objects stand now, from which cut-outs are made.
  std::vector<Surface> uncut_;
  // As loaded: the surfaces without cut-outs, the mesh positions of those that had none, the
  // objects' poses.
  std::vector<Surface> homeSurfaces_;
  std::vector<std::vector<Vec3>> homePositions_;
  std::vector<PlaneFrame> homeFrames_;
  std::vector<uint8_t> homeMesh_;  // per surface: its mesh is still the loaded one (moved rigidly)
  std::vector<ObjectPose> homePoses_;
  double contactTolerance_ = 0;
  mesher::Mesher mesher_;
  std::vector<uint32_t> remeshed_;
  std::vector<EditedSurface> edited_;
};

}  // namespace engine
