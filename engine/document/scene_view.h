// The scene as the thread that draws holds it: the objects' poses (to pick and drag them) and the
// display mesh, kept apart from the document (lit_scene.h) that cuts, meshes and lights on the
// lighting thread. The display holds each object's surfaces where the object stood when loaded,
// and the object's transform (objectTransform) shows it where it stands now: a move costs the
// moved object's surfaces (for picking) and no vertex. The document's meshes of the surfaces that
// changed, its radiance and its refusals come back later (LightingThread::take) and cost what
// changed.
#pragma once

#include "engine/document/display_mesh.h"
#include "engine/document/lighting.h"
#include "engine/document/scene_poses.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace engine {

class SceneView {
 public:
  // `meshed` is `scene`'s meshes at their patch sizes, as the document starts from.
  SceneView(Scene scene, const MeshedScene& meshed);

  const ScenePoses& poses() const { return poses_; }
  const Scene& scene() const { return poses_.scene(); }
  const DisplayMesh& display() const { return display_; }
  DisplayMesh& display() { return display_; }

  // Puts `object` at `pose` in the picture (ScenePoses::setPose; throws as it does). Returns
  // whether it moved; the document is to be asked for the same pose.
  bool setPose(uint32_t object, const ObjectPose& pose);
  // Display coordinates of `object` where it stands, from those of its display vertices (where it
  // stood when loaded): the identity for an object that has not moved.
  glm::dmat4 objectTransform(uint32_t object) const;

  // What the document sent (LightingUpdate): the surfaces' new meshes, each placed where its
  // object stands in the picture now, the poses it refused (the object goes back to where the
  // document keeps it, unless it has been moved again since), then the radiance when it is for
  // the display's vertices. Returns what changed.
  struct Taken {
    std::vector<uint32_t> surfaces;   // whose display was replaced (ascending): to upload again
    bool radiance = false;            // the display's radiance changed
    std::vector<uint32_t> movedBack;  // objects a refusal put back: their transforms changed
  };
  Taken take(const LightingUpdate& update);

 private:
  ScenePoses poses_;
  DisplayMesh display_;  // each object where it stood when loaded
  std::shared_ptr<const LightingSnapshot> shown_;  // the snapshot whose radiance the display has
};

}  // namespace engine
