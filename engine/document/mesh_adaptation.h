// Adaptive refinement during solving (thesis 5.5): the scene's meshes follow the light. Every so
// often a pass judges each surface's elements by the luminance jumps across their edges
// (radiosity/adaptive_refinement.h), refines and coarsens those surfaces' quadtrees
// (mesher/adaptive_mesh.h: 2:1 balanced, no T-vertices, exact boundaries) and hands the new
// meshes to the solver as an edit (radiosity::Solver::edit). That edit is what gives new elements
// their light: every patch that has shot light which may reach them takes it back along the old
// mesh and sends it again along the new one, so new elements gather what was already shot (they
// are not interpolated) and the result is what a fresh solve on the adapted mesh would give,
// with the power ledgers exact.
#pragma once

#include "engine/document/adaptive_meshes.h"
#include "engine/geometry/meshed_scene.h"
#include "engine/scene.h"
#include "mesher/adaptive_mesh.h"
#include "radiosity/adaptive_refinement.h"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace engine {

class MeshAdaptation {
 public:
  // A pass is due when the unshot fraction has fallen to this share of what it was at the last
  // pass (the first when a quarter of the light is left) and no edit's light is still being
  // taken back: early passes are cheap (few
  // patches have shot, so little light is sent again) and catch direct shadows.
  static constexpr double kPassFall = 0.25;
  // Passes once converged, each followed by shooting to convergence again, at most this many:
  // the early passes have refined most of the way by then (each refines one level), a pass at
  // convergence costs about a solve (every patch has shot light that may reach what changed),
  // and refining and coarsening could otherwise take turns.
  static constexpr int kMaxConvergedPasses = 1;

  // Starts from `meshed` (the scene's meshes at their patch sizes), refining in `meshes`, the
  // document's adaptive meshes of them (SceneEditor::adaptiveMeshes, which outlive this).
  // settings.minElementSize 0 stands for a quarter of each surface's patch size.
  MeshAdaptation(const Scene& scene, const MeshedScene& meshed, const AdaptiveSettings& settings,
                 AdaptiveMeshes& meshes);
  ~MeshAdaptation();

  // The meshes as adapted so far, and the solver's input made from them.
  const MeshedScene& meshed() const { return meshed_; }
  const std::vector<radiosity::Surface>& input() const { return input_; }

  // One pass over every surface, judged on `solver`'s light, whose input must be input().
  // The surfaces whose meshes changed go to the solver (Solver::edit), their elements by their
  // keys: the adaptive mesh's element handles. Returns the elements removed plus added (0:
  // nothing changed).
  size_t pass(radiosity::Solver& solver);
  // A pass when one is due (see kPassFall, kMaxConvergedPasses; `converge` is the unshot
  // fraction the caller shoots to). Returns whether a mesh changed.
  bool adaptIfDue(radiosity::Solver& solver, double converge);

  // The scene was edited (objects moved): the surfaces `edited` names take `meshed`'s mesh, the
  // others keep theirs. A surface whose cut-outs changed in its adaptive mesh keeps its
  // refinement away from them; one meshed anew or moved along loses it. Returns the solver's part
  // of it: their input now (engine::applyEdit). A surface moved along keeps its mesh's plane
  // coordinates, so the mesh it takes is one its refinement came from: the keys of the elements
  // it still had go on. Passes are due again as the light after the edit settles.
  std::vector<radiosity::SurfaceChange> edit(const Scene& scene, const MeshedScene& meshed,
                                             std::span<const EditedSurface> edited);

  uint64_t passes() const { return passes_; }  // passes that changed a mesh
  // The surfaces whose meshes passes changed since the last call (a surface may come twice).
  std::vector<uint32_t> takeChangedSurfaces() { return std::exchange(changed_, {}); }

 private:
  Scene scene_;
  MeshedScene meshed_;
  radiosity::RefinementSettings settings_;
  // Made when a surface is first refined (AdaptiveMeshes::get); null where none is its mesh, and
  // the surface is then not refined until it is meshed anew.
  AdaptiveMeshes& adaptive_;
  std::vector<radiosity::Surface> input_;
  double nextPassAt_ = kPassFall;
  int convergedPasses_ = 0;
  uint64_t passes_ = 0;
  std::vector<uint32_t> changed_;
};

}  // namespace engine
