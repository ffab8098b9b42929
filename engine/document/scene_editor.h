// Moving objects of a loaded, meshed scene: the one edit path that the window's drags and
// `walkrad render --move` share. A moved object's surfaces keep their meshes and move rigidly
// with it; contact cut-outs (geometry/contact_cutouts.h) follow: on a surface whose footprints
// changed (the floor under a moved box) the footprints that went are taken out of its persistent
// adaptive mesh and those that came cut in (hole removal and insertion, mesher/adaptive_mesh.h),
// so its elements away from them go on under their keys and their light with them. The moved
// object's own surfaces with cut-outs (its top when something stood on it), and a surface no
// adaptive mesh reproduces or whose mesh refuses a footprint, are meshed again.
// Every pose is reached from the pose the scene was loaded with in one rigid motion, so moving
// an object back restores the loaded geometry and meshes exactly, however many moves came
// between.
#pragma once

#include "engine/document/adaptive_meshes.h"
#include "engine/document/scene_poses.h"
#include "engine/geometry/contact_cutouts.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/scene.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <unordered_map>
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
  // meshes, their adaptive meshes and footprint ids, and remeshed() are then as they were.
  bool setPose(uint32_t object, const ObjectPose& pose);
  // The surfaces the last setPose cut anew, which is what it cost: the object's, and those its
  // faces rest on where it stood and where it went.
  const std::vector<uint32_t>& recut() const { return recut_; }
  // The surfaces whose meshes the last setPose changed, meshed anew or their cut-outs changed in
  // place (their element counts may differ); the object's other surfaces kept their meshes.
  const std::vector<uint32_t>& remeshed() const { return remeshed_; }
  // Of those, the ones whose cut-outs changed in their adaptive meshes, and how many elements
  // each lost and gained (the rest went on).
  struct HoleEdit {
    uint32_t surface = 0;
    size_t removed = 0, added = 0;
  };
  const std::vector<HoleEdit>& holeEdits() const { return holeEdits_; }
  // The document's adaptive meshes (adaptive_meshes.h): made here for the surfaces whose
  // cut-outs change, dropped for those meshed anew or moved along; adaptive refinement
  // (MeshAdaptation) refines in the same ones.
  AdaptiveMeshes& adaptiveMeshes() { return adaptive_; }
  const AdaptiveMeshes& adaptiveMeshes() const { return adaptive_; }
  // The surfaces that setPose changed since the last call, for the light to take
  // (engine::applyEdit): the moved objects' surfaces, and every surface meshed again (meshed
  // anew, though it was moved along in another call).
  std::vector<EditedSurface> takeEdited() { return std::exchange(edited_, {}); }

 private:
  Scene scene_;
  MeshedScene meshed_;
  // The surfaces without cut-outs where the objects stand now, from which cut-outs are made.
  ScenePoses poses_;
  // Of the surfaces without cut-outs; made at the first move: a scene that is only looked at and
  // lit needs none (on the White Room it took 61 MB).
  std::optional<ContactIndex> contacts_;
  // Movable objects' surfaces (only they move along) as loaded: the mesh positions and plane frame.
  struct Home {
    std::vector<Vec3> positions;
    PlaneFrame worldFromPlane;
  };
  std::unordered_map<uint32_t, Home> home_;
  std::vector<uint8_t> homeMesh_;  // per surface: its mesh is still the loaded one (moved rigidly)
  // Per surface: its element keys name elements of its loaded mesh or of adaptive meshes made
  // from it (not of a mesh made anew since).
  std::vector<uint8_t> loadedKeys_;
  // The footprints the surfaces that had any were loaded with (Surface::holes' last contactHoles).
  std::unordered_map<uint32_t, std::vector<Ring3>> loadedFootprints_;
  // Whether surface `s` stands where it was loaded and `cut`'s footprints are those it was
  // loaded with.
  bool atLoadedFootprints(uint32_t s, const Surface& cut) const;
  mesher::Mesher mesher_;
  AdaptiveMeshes adaptive_;
  std::vector<uint32_t> remeshed_, recut_;
  std::vector<HoleEdit> holeEdits_;
  std::vector<EditedSurface> edited_;
};

}  // namespace engine
