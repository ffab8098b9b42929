#include "engine/document/scene_editor.h"

#include "engine/geometry/contact_cutouts.h"
#include "engine/geometry/solid_surfaces.h"
#include "engine/io/load_limits.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace engine {

ObjectPose poseOf(const Object& object) { return {object.position, object.rotateYDeg}; }

bool inSceneLimits(const ObjectPose& pose) {
  const auto within = [](double x) { return std::abs(x) <= kMaxLength; };  // false for NaN
  return within(pose.position.x) && within(pose.position.y) && within(pose.position.z) && within(pose.rotateYDeg);
}

Vec3 clampToSceneLimits(const Vec3& position) { return glm::clamp(position, Vec3(-kMaxLength), Vec3(kMaxLength)); }

SceneEditor::SceneEditor(Scene scene, MeshedScene meshed)
    : scene_(std::move(scene)), meshed_(std::move(meshed)), surfacesOf_(scene_.objects.size()) {
  if (meshed_.surfaces.size() != scene_.surfaces.size())
    throw std::invalid_argument("a meshed scene of " + std::to_string(meshed_.surfaces.size()) + " surfaces for " +
                                std::to_string(scene_.surfaces.size()));
  for (uint32_t s = 0; s < scene_.surfaces.size(); ++s) surfacesOf_[scene_.surfaces[s].object].push_back(s);
  homeSurfaces_ = scene_.surfaces;
  removeContacts(homeSurfaces_);
  uncut_ = homeSurfaces_;
  for (const SurfaceMesh& m : meshed_.surfaces) {
    homePositions_.push_back(m.positions);
    homeFrames_.push_back(m.worldFromPlane);
  }
  homeMesh_.assign(scene_.surfaces.size(), 1);
  for (const Object& o : scene_.objects) homePoses_.push_back(poseOf(o));
  contactTolerance_ = contactTolerance(scene_);
}

std::optional<uint32_t> SceneEditor::findObject(std::string_view name) const {
  for (uint32_t i = 0; i < scene_.objects.size(); ++i)
    if (scene_.objects[i].name == name) return i;
  return std::nullopt;
}

bool SceneEditor::setPose(uint32_t object, const ObjectPose& pose) {
  if (object >= scene_.objects.size()) throw std::invalid_argument("no object " + std::to_string(object));
  Object& o = scene_.objects[object];
  if (!o.movable) throw std::invalid_argument("object \"" + o.name + "\" is not movable");
  if (!inSceneLimits(pose)) throw std::invalid_argument("object \"" + o.name + "\" would stand beyond the scene limits");
  if (poseOf(o) == pose) return false;

  // From the loaded placement to the new one: world = now * home^-1 (a rotation about y and a
  // translation, so the inverse is the transpose).
  Object home = o, now = o;
  home.position = homePoses_[object].position;
  home.rotateYDeg = homePoses_[object].rotateYDeg;
  now.position = pose.position;
  now.rotateYDeg = pose.rotateYDeg;
  const Placement from = placementOf(home), to = placementOf(now);
  const glm::dmat3 turn = to.worldFromObject * glm::transpose(from.worldFromObject);
  const bool atHome = pose == homePoses_[object];
  auto place = [&](const Vec3& p) { return atHome ? p : turn * (p - from.translation) + to.translation; };
  auto turned = [&](const Vec3& d) { return atHome ? d : turn * d; };
  std::vector<Surface> cut = uncut_;
  std::vector<Surface> placed;  // the object's surfaces as uncut_ is to hold them
  for (uint32_t s : surfacesOf_[object]) {
    const Surface& before = homeSurfaces_[s];
    Surface& surface = cut[s];
    for (size_t i = 0; i < before.outer.size(); ++i) surface.outer[i] = place(before.outer[i]);
    for (size_t h = 0; h < before.holes.size(); ++h)
      for (size_t i = 0; i < before.holes[h].size(); ++i) surface.holes[h][i] = place(before.holes[h][i]);
    surface.normal = atHome ? before.normal : glm::normalize(turn * before.normal);
    placed.push_back(surface);
  }

  // Cut-outs anew; a surface whose footprints changed, or that has or had any while it moves,
  // is meshed again; the moved object's other surfaces move their meshes along. Everything is
  // meshed before anything changes: a mesh refused (a footprint leaving a sliver a hair wide)
  // leaves the scene and its meshes as they were.
  cutOutContacts(cut, contactTolerance_);
  std::vector<uint32_t> changed, remeshed;
  std::vector<SurfaceMesh> meshes;
  for (uint32_t s = 0; s < cut.size(); ++s) {
    const bool ofObject = scene_.surfaces[s].object == object;
    if (!ofObject && cut[s].holes == scene_.surfaces[s].holes) continue;
    changed.push_back(s);
    if (ofObject && homeMesh_[s] && cut[s].contactHoles == 0 && scene_.surfaces[s].contactHoles == 0) continue;  // rigid
    try {
      meshes.push_back(meshSurface(cut[s], mesher_));
    } catch (const mesher::MeshRefused& refused) {
      const Surface& refusedSurface = cut[s];
      throw meshRefusal(refused, scene_.file, refusedSurface.jsonPath,
                        "moving \"" + o.name + "\" there, the " + refusedSurface.face + " of \"" +
                            scene_.objects[refusedSurface.object].name + "\"");
    }
    remeshed.push_back(s);
  }

  o.position = pose.position;
  o.rotateYDeg = pose.rotateYDeg;
  for (size_t k = 0; k < placed.size(); ++k) uncut_[surfacesOf_[object][k]] = std::move(placed[k]);
  std::vector<EditedSurface> edited;
  for (size_t k = 0, m = 0; k < changed.size(); ++k) {
    const uint32_t s = changed[k];
    scene_.surfaces[s] = std::move(cut[s]);
    const bool anew = m < remeshed.size() && remeshed[m] == s;
    edited.push_back({s, anew});
    if (anew) {
      meshed_.surfaces[s] = std::move(meshes[m++]);
      homeMesh_[s] = 0;
    } else {
      // Moved along: the same plane coordinates, in a frame moved with the surface.
      SurfaceMesh& mesh = meshed_.surfaces[s];
      for (size_t i = 0; i < mesh.positions.size(); ++i) mesh.positions[i] = place(homePositions_[s][i]);
      const PlaneFrame& loaded = homeFrames_[s];
      mesh.worldFromPlane = {place(loaded.origin), turned(loaded.u), turned(loaded.v)};
    }
  }
  remeshed_ = std::move(remeshed);
  addEdits(edited_, edited);
  scene_.computeBounds();
  return true;
}

}  // namespace engine
