// The lit-scene document: a scene, its meshes with their contact cut-outs (SceneEditor), the
// radiosity solution on them and, when asked for, adaptive refinement of the meshes as the light
// comes in (MeshAdaptation). The one way walkrad lights a scene: `render`, `export` and the
// window's lighting thread (lighting.h) all hold one.
#pragma once

#include "engine/document/mesh_adaptation.h"
#include "engine/document/scene_editor.h"
#include "radiosity/radiosity.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace engine {

// The display radiance of every surface, per display vertex (surface after surface, each in its
// mesh's vertex order, as DisplayMesh holds them): the solver's vertex radiance plus
// reflectance times its ambient term.
void displayRadiance(const radiosity::Solver& solver, std::vector<glm::vec3>& out);

enum class SolveStep { kShot, kAdapted, kDone };
// One step of solveTo: an adaptive pass when one is due, else a shot. kDone when there was
// nothing to do (converged, or nothing left to shoot).
SolveStep solveStep(radiosity::Solver& solver, double converge, MeshAdaptation* adaptation = nullptr);

// Shoots until the unshot fraction is at most `converge` or `maxShots` shots were taken, calling
// `progress` (when given) after every shot; returns the shots taken. With `adaptation` (whose
// input() the solver has), its passes run when due, and shooting goes on after each that
// changed a mesh until one at convergence changes none.
uint64_t solveTo(radiosity::Solver& solver, double converge, uint64_t maxShots,
                 const std::function<void(const radiosity::Solver&, uint64_t shots)>& progress = {},
                 MeshAdaptation* adaptation = nullptr);

// Takes a scene edit into a solution: the surfaces `edited` names (SceneEditor::takeEdited), as
// `meshed` has them now, replace the solver's, whose light is corrected rather than shot again
// (radiosity::Solver::edit); the other surfaces keep their elements and light. With
// `adaptation` (whose input the solver has), the adaptation takes the edit first and the solver
// its meshes of them (MeshAdaptation::edit). Returns what the solver took. How LitScene::setPose
// reaches the light.
std::vector<radiosity::SurfaceChange> applyEdit(radiosity::Solver& solver, const Scene& scene, const MeshedScene& meshed,
                                                std::span<const EditedSurface> edited,
                                                MeshAdaptation* adaptation = nullptr);

// A surface's mesh as the document had it at an update (LitScene::takeUpdates), placed where its object stood at `pose`.
struct SurfaceUpdate {
  uint32_t surface = 0;
  SurfaceMesh mesh;
  ObjectPose pose;
  // False when the surface only moved along with its object, its mesh the one it was loaded with:
  // where its object stood when loaded, nothing of it changed.
  bool meshChanged = true;
  // The mesh's outline for the display (surfaceOutline), made here rather than on the thread that
  // draws; empty when the mesh did not change.
  std::vector<uint32_t> outline;
};

struct LitSceneSettings {
  radiosity::SolverSettings solver{.overshoot = true};
  std::optional<AdaptiveSettings> adaptive;  // none: the meshes stay at their patch sizes
};

class LitScene {
 public:
  // Starts lighting `meshed` (the scene's meshes at their patch sizes). Throws what
  // radiosity::Solver throws for the surfaces.
  LitScene(Scene scene, MeshedScene meshed, const LitSceneSettings& settings);
  ~LitScene();
  LitScene(const LitScene&) = delete;
  LitScene& operator=(const LitScene&) = delete;

  const Scene& scene() const { return editor_.scene(); }
  const SceneEditor& editor() const { return editor_; }
  // The meshes the light is on: as adapted so far, else the editor's. The solver's vertex
  // radiance is per vertex of these (displayRadiance).
  const MeshedScene& meshed() const;
  const radiosity::Solver& solver() const { return *solver_; }
  // Adaptive passes that changed a mesh (0 without adaptive refinement).
  uint64_t adaptivePasses() const;

  // One step of solving to an unshot fraction of `converge` (solveStep).
  SolveStep step(double converge) { return solveStep(*solver_, converge, adaptation_.get()); }
  // Shoots to `converge` (solveTo); returns the shots.
  uint64_t solve(double converge, uint64_t maxShots,
                 const std::function<void(const radiosity::Solver&, uint64_t shots)>& progress = {});

  // Puts `object` at `pose` (SceneEditor::setPose: its surfaces, contact cut-outs, meshes), and
  // the light takes the edit: what was shot onto or from the changed surfaces is taken back and
  // sent again (radiosity::Solver::edit), the other surfaces keep their elements, light and
  // refinement. Returns whether anything moved. Throws as SceneEditor::setPose does, and the
  // scene, its meshes and light are then as they were.
  bool setPose(uint32_t object, const ObjectPose& pose);
  // Throws the solution away and starts again from the emitters, on the meshes as they are.
  void restart();

  // The meshes of the surfaces that changed since the last call (moved with an object, their
  // cut-outs changed or meshed anew around a footprint, refined or coarsened), each once, by
  // surface in ascending order.
  std::vector<SurfaceUpdate> takeUpdates();

 private:
  void markChanged(uint32_t surface, bool meshChanged);

  const LitSceneSettings settings_;
  SceneEditor editor_;
  std::unique_ptr<MeshAdaptation> adaptation_;
  std::unique_ptr<radiosity::Solver> solver_;
  std::vector<uint32_t> changed_;
  std::vector<uint8_t> isChanged_;  // per surface: 0 not in changed_, 1 moved along only, 2 mesh changed
};

}  // namespace engine
