#include "engine/document/scene_editor.h"

#include "util/check.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace engine {

namespace {

// How a surface whose cut-outs the move concerns takes it. kHome: its cut-outs are those it was
// loaded with, and it is meshed as it was loaded (exactly: hole insertion and removal leave a
// mesh a little different from the mesher's around a footprint).
enum class Remesh { kMovedAlong, kHolesChanged, kHome, kAnew };

struct Recut {
  uint32_t surface = 0;
  Surface cut;  // with its cut-outs where the objects stand after the move
  Remesh how = Remesh::kAnew;
  SurfaceMesh mesh;  // kAnew: the new mesh
  // kHolesChanged: the footprint hole ids that go, the rings (plane coordinates) that come, and
  // the ids of the cut's footprints in order, -1 for those to come.
  std::vector<int> going;
  std::vector<mesher::Ring2> coming;
  std::vector<int> footprints;
};

// The footprints of `before` (with hole ids `ids`) that `after` no longer has, and those it has
// anew, in the plane coordinates of `frame`; false when the surfaces differ in more than their
// footprints. Footprints that stay keep their ids.
bool planFootprints(const Surface& before, const std::vector<int>& ids, const PlaneFrame& frame, Recut& recut) {
  const Surface& after = recut.cut;
  const size_t ownBefore = before.holes.size() - before.contactHoles, ownAfter = after.holes.size() - after.contactHoles;
  if (ownBefore != ownAfter || !std::equal(before.holes.begin(), before.holes.begin() + static_cast<ptrdiff_t>(ownBefore),
                                           after.holes.begin()))
    return false;
  std::vector<uint8_t> stays(before.contactHoles, 0);
  for (size_t j = ownAfter; j < after.holes.size(); ++j) {
    size_t i = 0;
    while (i < before.contactHoles && (stays[i] || before.holes[ownBefore + i] != after.holes[j])) ++i;
    if (i < before.contactHoles) {
      stays[i] = 1;
      recut.footprints.push_back(ids[i]);
      continue;
    }
    recut.footprints.push_back(-1);
    mesher::Ring2& ring = recut.coming.emplace_back();
    for (const Vec3& p : after.holes[j]) ring.push_back(frame.project(p));
  }
  for (size_t i = 0; i < before.contactHoles; ++i)
    if (!stays[i]) recut.going.push_back(ids[i]);
  return true;
}

}  // namespace

SceneEditor::SceneEditor(Scene scene, MeshedScene meshed)
    : scene_(std::move(scene)),
      meshed_(std::move(meshed)),
      poses_(scene_),
      adaptive_(scene_.surfaces.size()) {
  if (meshed_.surfaces.size() != scene_.surfaces.size())
    throw std::invalid_argument("a meshed scene of " + std::to_string(meshed_.surfaces.size()) + " surfaces for " +
                                std::to_string(scene_.surfaces.size()));
  // Only what can move needs its loaded positions kept: a building's fixed walls are most surfaces.
  for (uint32_t s = 0; s < meshed_.surfaces.size(); ++s)
    if (scene_.objects[scene_.surfaces[s].object].movable)
      home_.emplace(s, Home{meshed_.surfaces[s].positions, meshed_.surfaces[s].worldFromPlane});
  homeMesh_.assign(scene_.surfaces.size(), 1);
  loadedKeys_.assign(scene_.surfaces.size(), 1);
  for (uint32_t s = 0; s < scene_.surfaces.size(); ++s) {
    const Surface& surface = scene_.surfaces[s];
    if (surface.contactHoles > 0)
      loadedFootprints_.emplace(s, std::vector<Ring3>(surface.holes.end() - static_cast<ptrdiff_t>(surface.contactHoles),
                                                      surface.holes.end()));
  }
}

bool SceneEditor::atLoadedFootprints(uint32_t s, const Surface& cut) const {
  const uint32_t object = scene_.surfaces[s].object;
  if (poseOf(scene_.objects[object]) != poses_.loadedPose(object)) return false;
  const auto loaded = loadedFootprints_.find(s);
  if (loaded == loadedFootprints_.end()) return cut.contactHoles == 0;
  return cut.contactHoles == loaded->second.size() &&
         std::equal(loaded->second.begin(), loaded->second.end(), cut.holes.end() - static_cast<ptrdiff_t>(cut.contactHoles));
}

bool SceneEditor::setPose(uint32_t object, const ObjectPose& pose) {
  poses_.checkPose(object, pose);
  const Object& o = scene_.objects[object];
  if (poseOf(o) == pose) return false;

  if (!contacts_) contacts_.emplace(poses_.scene().surfaces, contactTolerance(scene_));  // as loaded: nothing moved yet
  ContactIndex& contacts = *contacts_;
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
    contacts.supportsUnder(uncut[own[k]], concerned);
    contacts.supportsUnder(placed[k], concerned);
  }
  std::sort(concerned.begin(), concerned.end());
  concerned.erase(std::unique(concerned.begin(), concerned.end()), concerned.end());
  const auto fileObject = [&](bool there) {
    for (size_t k = 0; k < own.size(); ++k)
      there ? contacts.move(own[k], uncut[own[k]], placed[k]) : contacts.move(own[k], placed[k], uncut[own[k]]);
  };
  fileObject(true);

  // Cut-outs anew, and how each surface they changed takes them: the moved object's surfaces
  // move their meshes along unless they have or had cut-outs; another surface has its footprints
  // replaced in its adaptive mesh. The rest are meshed anew: those of the object, and any whose
  // mesh no adaptive mesh reproduces, or refuses a footprint (one touching its border or another
  // hole within the mesher's clearance, or needing more tree levels than it has), as surfaces
  // were meshed before adaptive meshes took cut-outs. Everything that may fail is tried before
  // anything changes: a refused mesh leaves the scene, its meshes and adaptive meshes as they were.
  std::vector<Recut> recuts;
  std::vector<uint32_t> madeHere;  // adaptive meshes made by this call, dropped should it fail
  const auto refuse = [&](const mesher::MeshRefused& refused, const Surface& surface) {
    fileObject(false);
    for (uint32_t s : madeHere) adaptive_.forget(s);
    return meshRefusal(refused, scene_.file, surface.jsonPath,
                       "moving \"" + o.name + "\" there, the " + surface.face + " of \"" +
                           scene_.objects[surface.object].name + "\"");
  };
  for (uint32_t s : concerned) {
    Recut recut;
    recut.surface = s;
    recut.cut = contacts.cut(s, uncutNow);
    const Surface& before = scene_.surfaces[s];
    const bool ofObject = before.object == object;
    if (!ofObject && recut.cut.holes == before.holes) continue;
    if (ofObject && homeMesh_[s] && recut.cut.contactHoles == 0 && before.contactHoles == 0) {
      recut.how = Remesh::kMovedAlong;
    } else if (!ofObject && homeMesh_[s] == 0 && atLoadedFootprints(s, recut.cut)) {
      recut.how = Remesh::kHome;
    } else if (!ofObject) {
      if (!adaptive_.known(s)) madeHere.push_back(s);
      mesher::AdaptiveMesh* const adaptive = adaptive_.get(s, before, meshed_.surfaces[s]);
      if (adaptive && planFootprints(before, adaptive_.footprints(s), meshed_.surfaces[s].worldFromPlane, recut) &&
          adaptive->holesFit(recut.going, recut.coming))
        recut.how = Remesh::kHolesChanged;
    }
    if (recut.how == Remesh::kAnew || recut.how == Remesh::kHome) {
      try {
        recut.mesh = meshSurface(recut.cut, mesher_);
      } catch (const mesher::MeshRefused& refused) {
        throw refuse(refused, recut.cut);
      }
    }
    recuts.push_back(std::move(recut));
  }

  poses_.setPose(object, pose);
  scene_.objects[object].position = pose.position;
  scene_.objects[object].rotateYDeg = pose.rotateYDeg;
  scene_.boundsMin = poses_.scene().boundsMin;  // cut-outs leave the outlines as they are
  scene_.boundsMax = poses_.scene().boundsMax;
  std::vector<EditedSurface> edited;
  std::vector<uint32_t> remeshed;
  holeEdits_.clear();
  for (Recut& recut : recuts) {
    const uint32_t s = recut.surface;
    SurfaceMesh& mesh = meshed_.surfaces[s];
    bool anew = false;
    if (recut.how == Remesh::kMovedAlong) {
      // The same plane coordinates, in a frame moved with the surface. The loaded mesh's adaptive
      // mesh (refined since, perhaps) is not this mesh.
      const Home& asLoaded = home_.at(s);
      for (size_t i = 0; i < mesh.positions.size(); ++i) mesh.positions[i] = motion.place(asLoaded.positions[i]);
      const PlaneFrame& loaded = asLoaded.worldFromPlane;
      mesh.worldFromPlane = {motion.place(loaded.origin), motion.turn(loaded.u), motion.turn(loaded.v)};
      adaptive_.forget(s);
    } else if (recut.how == Remesh::kHolesChanged) {
      mesher::AdaptiveMesh& adaptive = *adaptive_.find(s);
      std::optional<mesher::AdaptiveMesh::HoleChange> change = adaptive.replaceHoles(recut.going, recut.coming);
      CHECK(change.has_value());  // holesFit said it would
      auto inserted = change->inserted.begin();
      for (int& id : recut.footprints)
        if (id < 0) id = *inserted++;
      adaptive_.setFootprints(s, std::move(recut.footprints));
      takeAdaptiveMesh(recut.cut, adaptive, mesh);
      // Its polygon as the adaptive mesh has it: the outline and own holes it had, the footprints
      // in the plane coordinates they were cut in.
      const size_t ownHoles = recut.cut.holes.size() - recut.cut.contactHoles;
      mesh.polygon.holes.resize(ownHoles);
      const mesher::PolygonWithHoles now = planePolygon(recut.cut, mesh.worldFromPlane);
      mesh.polygon.holes.insert(mesh.polygon.holes.end(), now.holes.begin() + static_cast<ptrdiff_t>(ownHoles),
                                now.holes.end());
      holeEdits_.push_back({s, change->delta.removed.size(), change->delta.added.size()});
      homeMesh_[s] = 0;
      remeshed.push_back(s);
    } else {
      // Meshed anew. As loaded, its elements are numbered as they were then ({i, 0}), and an
      // element of its adaptive mesh whose slot kept generation 0 is still the loaded element
      // i: while its keys came down from the loaded mesh, they go on.
      const bool home = recut.how == Remesh::kHome;
      anew = !home || !loadedKeys_[s];
      loadedKeys_[s] = home;
      homeMesh_[s] = home;
      mesh = std::move(recut.mesh);
      adaptive_.forget(s);
      remeshed.push_back(s);
    }
    scene_.surfaces[s] = std::move(recut.cut);
    edited.push_back({s, anew, !anew && recut.how != Remesh::kMovedAlong});
  }
  remeshed_ = std::move(remeshed);
  recut_ = std::move(concerned);
  addEdits(edited_, edited);
  return true;
}

}  // namespace engine
