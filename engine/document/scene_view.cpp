#include "engine/document/scene_view.h"

#include <utility>

namespace engine {

SceneView::SceneView(Scene scene, const MeshedScene& meshed)
    : poses_(std::move(scene)), display_(displayMesh(poses_.scene(), meshed)) {}

bool SceneView::setPose(uint32_t object, const ObjectPose& pose) { return poses_.setPose(object, pose); }

glm::dmat4 SceneView::objectTransform(uint32_t object) const {
  const RigidMotion motion = poses_.motionTo(object, poses_.pose(object));
  if (motion.identity()) return glm::dmat4{1.0};
  // In display coordinates (world less the origin) the turn stays and the translation is where
  // the motion takes the origin, less the origin: small numbers for float, however far the scene.
  glm::dmat4 transform = motion.matrix();
  transform[3] = glm::dvec4(motion.place(display_.origin) - display_.origin, 1);
  return transform;
}

SceneView::Taken SceneView::take(const LightingUpdate& update) {
  Taken taken;
  for (const SurfaceUpdate& u : update.meshes) {
    if (!u.meshChanged) continue;  // the display has it where its object stood when loaded
    // Back to where the object stood when loaded: the object's transform shows it where it is.
    const uint32_t object = scene().surfaces[u.surface].object;
    const RigidMotion toLoaded(scene().objects[object], u.pose, poses_.loadedPose(object));
    replaceSurface(display_, u.surface, surfaceDisplay(u.mesh, object, displayFromWorld(display_) * toLoaded.matrix(), u.outline));
    taken.surfaces.push_back(u.surface);
  }
  for (const PoseRefusal& r : update.refusals) {
    // Asked to move again since, the object waits for that pose's verdict.
    if (poses_.pose(r.object) != r.refused) continue;
    poses_.setPose(r.object, r.kept);
    taken.movedBack.push_back(r.object);
  }
  const bool fresh = update.snapshot != shown_ || !taken.surfaces.empty();
  if (update.snapshot && fresh) taken.radiance = setRadiance(display_, update.snapshot->radiance);
  shown_ = update.snapshot;
  return taken;
}

}  // namespace engine
