#include "engine/document/scene_editor.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace engine {

SceneEditor::SceneEditor(Scene scene, MeshedScene meshed)
    : scene_(std::move(scene)),
      meshed_(std::move(meshed)),
      poses_(scene_),
      contacts_(poses_.scene().surfaces, contactTolerance(scene_)) {
  if (meshed_.surfaces.size() != scene_.surfaces.size())
    throw std::invalid_argument("a meshed scene of " + std::to_string(meshed_.surfaces.size()) + " surfaces for " +
                                std::to_string(scene_.surfaces.size()));
  // Only what can move needs its loaded positions kept.
  for (size_t s = 0; s < meshed_.surfaces.size(); ++s) {
    const bool movable = scene_.objects[scene_.surfaces[s].object].movable;
    homePositions_.push_back(movable ? meshed_.surfaces[s].positions : std::vector<Vec3>{});
    homeFrames_.push_back(meshed_.surfaces[s].worldFromPlane);
  }
  homeMesh_.assign(scene_.surfaces.size(), 1);
}

bool SceneEditor::setPose(uint32_t object, const ObjectPose& pose) {
  poses_.checkPose(object, pose);
  const Object& o = scene_.objects[object];
  if (poseOf(o) == pose) return false;

  const RigidMotion motion = poses_.motionTo(object, pose);
  const std::vector<uint32_t>& own = surfacesOf(object);  // ascending
  const std::vector<Surface>& uncut = poses_.scene().surfaces;
  std::vector<Surface> placed;
  for (uint32_t s : own) placed.push_back(poses_.placed(s, motion));
  const auto uncutNow = [&](uint32_t s) -> const Surface& {
    const auto at = std::lower_bound(own.begin(), own.end(), s);
    return at != own.end() && *at == s ? placed[static_cast<size_t>(at - own.begin())] : uncut[s];
  };

  // The surfaces whose cut-outs may change: those the object's faces rest on where it stood and
  // where it goes, and its own; the others' stay as they are.
  std::vector<uint32_t> concerned = own;
  for (size_t k = 0; k < own.size(); ++k) {
    contacts_.supportsUnder(uncut[own[k]], concerned);
    contacts_.supportsUnder(placed[k], concerned);
  }
  std::sort(concerned.begin(), concerned.end());
  concerned.erase(std::unique(concerned.begin(), concerned.end()), concerned.end());
  const auto fileObject = [&](bool there) {
    for (size_t k = 0; k < own.size(); ++k)
      there ? contacts_.move(own[k], uncut[own[k]], placed[k]) : contacts_.move(own[k], placed[k], uncut[own[k]]);
  };
  fileObject(true);

  // Cut-outs anew; a surface whose footprints changed, or that has or had any while it moves,
  // is meshed again; the moved object's other surfaces move their meshes along. Everything is
  // meshed before anything changes: a mesh refused (a footprint leaving a sliver a hair wide)
  // leaves the scene and its meshes as they were.
  std::vector<uint32_t> changed, remeshed;
  std::vector<Surface> cut;
  std::vector<SurfaceMesh> meshes;
  for (uint32_t s : concerned) {
    Surface surface = contacts_.cut(s, uncutNow);
    const bool ofObject = scene_.surfaces[s].object == object;
    if (!ofObject && surface.holes == scene_.surfaces[s].holes) continue;
    changed.push_back(s);
    const bool rigid = ofObject && homeMesh_[s] && surface.contactHoles == 0 && scene_.surfaces[s].contactHoles == 0;
    if (!rigid) {
      try {
        meshes.push_back(meshSurface(surface, mesher_));
      } catch (const mesher::MeshRefused& refused) {
        fileObject(false);
        throw meshRefusal(refused, scene_.file, surface.jsonPath,
                          "moving \"" + o.name + "\" there, the " + surface.face + " of \"" +
                              scene_.objects[surface.object].name + "\"");
      }
      remeshed.push_back(s);
    }
    cut.push_back(std::move(surface));
  }

  poses_.setPose(object, pose);
  scene_.objects[object].position = pose.position;
  scene_.objects[object].rotateYDeg = pose.rotateYDeg;
  scene_.boundsMin = poses_.scene().boundsMin;  // cut-outs leave the outlines as they are
  scene_.boundsMax = poses_.scene().boundsMax;
  std::vector<EditedSurface> edited;
  for (size_t k = 0, m = 0; k < changed.size(); ++k) {
    const uint32_t s = changed[k];
    scene_.surfaces[s] = std::move(cut[k]);
    const bool anew = m < remeshed.size() && remeshed[m] == s;
    edited.push_back({s, anew});
    if (anew) {
      meshed_.surfaces[s] = std::move(meshes[m++]);
      homeMesh_[s] = 0;
    } else {
      // Moved along: the same plane coordinates, in a frame moved with the surface.
      SurfaceMesh& mesh = meshed_.surfaces[s];
      for (size_t i = 0; i < mesh.positions.size(); ++i) mesh.positions[i] = motion.place(homePositions_[s][i]);
      const PlaneFrame& loaded = homeFrames_[s];
      mesh.worldFromPlane = {motion.place(loaded.origin), motion.turn(loaded.u), motion.turn(loaded.v)};
    }
  }
  remeshed_ = std::move(remeshed);
  recut_ = std::move(concerned);
  addEdits(edited_, edited);
  return true;
}

}  // namespace engine
