// The scene's surface meshes that change locally (mesher/adaptive_mesh.h): one persistent
// AdaptiveMesh per surface that needs one, shared by the document's editor (contact cut-outs by
// hole insertion and removal, scene_editor.h) and adaptive refinement (mesh_adaptation.h), so
// that an element key (SurfaceMesh::keys, the element's ElementId) names one element whichever of
// them changed the mesh last. A surface's adaptive mesh is made when it is first needed, from the
// mesh the surface has then, never for every surface up front (the White Room has 266k surfaces).
#pragma once

#include "engine/geometry/surface_mesh.h"
#include "engine/scene.h"
#include "mesher/adaptive_mesh.h"

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace engine {

class AdaptiveMeshes {
 public:
  explicit AdaptiveMeshes(size_t surfaces);
  ~AdaptiveMeshes();
  AdaptiveMeshes(const AdaptiveMeshes&) = delete;
  AdaptiveMeshes& operator=(const AdaptiveMeshes&) = delete;

  // Surface `s`'s adaptive mesh; when it has none yet, made from `mesh` (its polygon, whose last
  // `surface.contactHoles` holes are its footprints: they take hole ids and can go again). Null
  // where no adaptive mesh is `mesh` element for element under the same keys: a triangle that is
  // its own element (meshSurface), which the quadtree cuts up, a repeat the mesher placed from
  // another surface's mesh, or a polygon finer than the tree resolves. A null answer is kept
  // until the surface is meshed anew (forget).
  mesher::AdaptiveMesh* get(uint32_t s, const Surface& surface, const SurfaceMesh& mesh);
  // The adaptive mesh surface `s` has, or null; makes none.
  mesher::AdaptiveMesh* find(uint32_t s) const;
  // Whether get() has looked at surface `s` since it was last meshed anew (it has an adaptive
  // mesh, or none reproduces its mesh).
  bool known(uint32_t s) const { return unadaptable_[s] || find(s); }
  // The hole ids of surface `s`'s footprints in its adaptive mesh, in the order of its contact
  // holes (Surface::holes' last contactHoles). The surface must have an adaptive mesh.
  const std::vector<int>& footprints(uint32_t s) const { return entries_.at(s).footprints; }
  void setFootprints(uint32_t s, std::vector<int> ids) { entries_.at(s).footprints = std::move(ids); }
  // Surface `s` was meshed anew (or moved along with its object from the mesh it was loaded
  // with): its adaptive mesh, if any, no longer is its mesh and goes; get() makes one again.
  void forget(uint32_t s);

  size_t size() const { return entries_.size(); }  // surfaces that have one

 private:
  struct Entry {
    std::unique_ptr<mesher::AdaptiveMesh> mesh;
    std::vector<int> footprints;
  };
  std::unordered_map<uint32_t, Entry> entries_;
  std::vector<uint8_t> unadaptable_;  // per surface: no adaptive mesh is its mesh
};

// `mesh` (surface `surface`'s) takes `adaptive`'s elements after a change: their corners and
// keys, and world positions for the vertices it has none for yet (those it has keep theirs).
void takeAdaptiveMesh(const Surface& surface, const mesher::AdaptiveMesh& adaptive, SurfaceMesh& mesh);

}  // namespace engine
