#include "engine/document/scene_view.h"

#include <utility>

namespace engine {

namespace {

void place(SurfaceMesh& mesh, const RigidMotion& motion) {
  for (Vec3& p : mesh.positions) p = motion.place(p);
  mesh.worldFromPlane = {motion.place(mesh.worldFromPlane.origin), motion.turn(mesh.worldFromPlane.u),
                         motion.turn(mesh.worldFromPlane.v)};
}

}  // namespace

SceneView::SceneView(Scene scene, const MeshedScene& meshed)
    : poses_(std::move(scene)), meshed_(meshed), display_(displayMesh(meshed_)) {}

void SceneView::placeObject(uint32_t object, const ObjectPose& from, const ObjectPose& to) {
  const RigidMotion motion(scene().objects[object], from, to);
  for (uint32_t s : poses_.surfacesOf(object)) place(meshed_.surfaces[s], motion);
}

bool SceneView::setPose(uint32_t object, const ObjectPose& pose) {
  const ObjectPose from = poses_.pose(object);
  if (!poses_.setPose(object, pose)) return false;
  placeObject(object, from, pose);
  updatePositions(meshed_, poses_.surfacesOf(object), display_);
  return true;
}

SceneView::Taken SceneView::take(const LightingUpdate& update) {
  Taken taken;
  for (const SurfaceUpdate& u : update.meshes) {
    SurfaceMesh& mesh = meshed_.surfaces[u.surface];
    mesh = u.mesh;
    const uint32_t object = scene().surfaces[u.surface].object;
    if (u.pose != poses_.pose(object)) place(mesh, RigidMotion(scene().objects[object], u.pose, poses_.pose(object)));
  }
  for (const PoseRefusal& r : update.refusals) {
    // Asked to move again since, the object waits for that pose's verdict.
    if (poses_.pose(r.object) != r.refused) continue;
    placeObject(r.object, r.refused, r.kept);
    poses_.setPose(r.object, r.kept);
    taken.movedBack.push_back(r.object);
  }
  if (!update.meshes.empty()) {
    DisplayMesh fresh = displayMesh(meshed_, display_.origin);
    carryRadiance(display_, fresh);
    display_ = std::move(fresh);
    taken.geometry = true;
  } else if (!taken.movedBack.empty()) {
    for (uint32_t object : taken.movedBack) updatePositions(meshed_, poses_.surfacesOf(object), display_);
    taken.geometry = true;
  }
  const bool fresh = update.snapshot != shown_ || taken.geometry;
  if (update.snapshot && fresh && update.snapshot->radiance.size() == display_.positions.size()) {
    display_.radiance = update.snapshot->radiance;
    taken.radiance = true;
  }
  shown_ = update.snapshot;
  return taken;
}

}  // namespace engine
