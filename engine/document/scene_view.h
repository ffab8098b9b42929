// The scene as the thread that draws holds it: the objects' poses (to pick and drag them) and the
// display mesh, kept apart from the document (lit_scene.h) that cuts, meshes and lights on the
// lighting thread. A move shows at once at the cost of the moved object alone; the document's
// meshes of the surfaces that changed, its radiance and its refusals come back later
// (LightingThread::take) and cost what changed.
#pragma once

#include "engine/document/display_mesh.h"
#include "engine/document/lighting.h"
#include "engine/document/scene_poses.h"

#include <glm/vec3.hpp>

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

  // What the document sent (LightingUpdate): the surfaces' new meshes, each placed where its
  // object stands in the picture now, the poses it refused (the object goes back to where the
  // document keeps it, unless it has been moved again since), then the radiance when it is for
  // the display's vertices. Returns what changed.
  struct Taken {
    bool geometry = false;  // vertices or elements: the display is to be uploaded again
    bool radiance = false;
    std::vector<uint32_t> movedBack;  // objects a refusal put back
  };
  Taken take(const LightingUpdate& update);

 private:
  void placeObject(uint32_t object, const ObjectPose& from, const ObjectPose& to);

  ScenePoses poses_;
  // The meshes the display is made from, each where its object stands in the picture.
  MeshedScene meshed_;
  DisplayMesh display_;
  std::shared_ptr<const LightingSnapshot> shown_;  // the snapshot whose radiance the display has
};

}  // namespace engine
