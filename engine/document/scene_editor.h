// Moving objects of a loaded, meshed scene: the one edit path that the window's drags and
// `walkrad render --move` share. A moved object's surfaces keep their meshes and move rigidly
// with it; contact cut-outs (geometry/contact_cutouts.h) follow: a surface whose footprints
// changed (the floor under a moved box, the box's own top when something stood on it) is meshed
// again.
// Every pose is reached from the pose the scene was loaded with in one rigid motion, so moving
// an object back restores the loaded geometry and meshes exactly, however many moves came
// between.
#pragma once

#include "engine/document/scene_poses.h"
#include "engine/geometry/contact_cutouts.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/scene.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace engine {

class SceneEditor {
 public:
  SceneEditor(Scene scene, MeshedScene meshed);

  const Scene& scene() const { return scene_; }
  const MeshedScene& meshed() const { return meshed_; }
  // The surfaces an object is made of (indices into Scene::surfaces).
  const std::vector<uint32_t>& surfacesOf(uint32_t object) const { return poses_.surfacesOf(object); }
  std::optional<uint32_t> findObject(std::string_view name) const { return poses_.findObject(name); }

  // Puts `object` at `pose`, surfaces, meshes, cut-outs and scene bounds with it; returns
  // whether anything moved. Costs the object's surfaces and those it rests on (where it stood and
  // where it goes), whatever the scene's size. Throws std::invalid_argument for an object that does not exist or is
  // not movable, or a pose beyond the scene limits (inSceneLimits). Throws SceneError
  // (MeshTooLarge, MeshTooFine at the surface's JSON path) when a surface to be meshed again is
  // refused by the mesher (a footprint leaving a sliver of floor a hair wide); the scene, its
  // meshes and remeshed() are then as they were before the call.
  bool setPose(uint32_t object, const ObjectPose& pose);
  // The surfaces the last setPose cut anew, which is what it cost: the object's, and those its
  // faces rest on where it stood and where it went.
  const std::vector<uint32_t>& recut() const { return recut_; }
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
  // The surfaces without cut-outs where the objects stand now, from which cut-outs are made.
  ScenePoses poses_;
  ContactIndex contacts_;  // of the surfaces without cut-outs
  // As loaded: the mesh positions and plane frames.
  std::vector<std::vector<Vec3>> homePositions_;
  std::vector<PlaneFrame> homeFrames_;
  std::vector<uint8_t> homeMesh_;  // per surface: its mesh is still the loaded one (moved rigidly)
  mesher::Mesher mesher_;
  std::vector<uint32_t> remeshed_, recut_;
  std::vector<EditedSurface> edited_;
};

}  // namespace engine
