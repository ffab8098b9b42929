#include "engine/document/lit_scene.h"

#include "engine/document/display_mesh.h"

#include <glm/common.hpp>

#include <algorithm>

namespace engine {

void displayRadiance(const radiosity::Solver& solver, std::vector<glm::vec3>& out) {
  out.clear();
  // Sized once: grown by doubling, a building's 52 MB were copied on the way and held twice.
  out.reserve(solver.vertexCount());
  const glm::dvec3 ambient = solver.ambient();
  // Light shot back by corrections (and overshooting) can leave residue a hair below zero,
  // within the unshot tolerance: shown, there is no light there.
  for (uint32_t s = 0; s < solver.surfaceCount(); ++s)
    for (const glm::dvec3& radiance : solver.vertexRadiance(s, ambient)) out.emplace_back(glm::max(radiance, glm::dvec3(0)));
}

SolveStep solveStep(radiosity::Solver& solver, double converge, MeshAdaptation* adaptation) {
  if (adaptation && adaptation->adaptIfDue(solver, converge)) return SolveStep::kAdapted;
  if (solver.converged(converge) || !solver.step()) return SolveStep::kDone;
  return SolveStep::kShot;
}

uint64_t solveTo(radiosity::Solver& solver, double converge, uint64_t maxShots,
                 const std::function<void(const radiosity::Solver&, uint64_t shots)>& progress,
                 MeshAdaptation* adaptation) {
  uint64_t shots = 0;
  while (shots < maxShots) {
    const SolveStep step = solveStep(solver, converge, adaptation);
    if (step == SolveStep::kDone) break;
    if (step == SolveStep::kAdapted) continue;
    ++shots;
    if (progress) progress(solver, shots);
  }
  return shots;
}

std::vector<radiosity::SurfaceChange> applyEdit(radiosity::Solver& solver, const Scene& scene, const MeshedScene& meshed,
                                                std::span<const EditedSurface> edited, MeshAdaptation* adaptation) {
  std::vector<radiosity::SurfaceChange> changes =
      adaptation ? adaptation->edit(scene, meshed, edited) : radiosityChanges(scene, meshed, edited);
  solver.edit(changes);
  return changes;
}

LitScene::LitScene(Scene scene, MeshedScene meshed, const LitSceneSettings& settings)
    : settings_(settings), editor_(std::move(scene), std::move(meshed)), isChanged_(editor_.scene().surfaces.size(), 0) {
  if (settings.adaptive)
    adaptation_ = std::make_unique<MeshAdaptation>(editor_.scene(), editor_.meshed(), *settings.adaptive,
                                                   editor_.adaptiveMeshes());
  restart();
}

LitScene::~LitScene() = default;

const MeshedScene& LitScene::meshed() const { return adaptation_ ? adaptation_->meshed() : editor_.meshed(); }

uint64_t LitScene::adaptivePasses() const { return adaptation_ ? adaptation_->passes() : 0; }

uint64_t LitScene::solve(double converge, uint64_t maxShots,
                         const std::function<void(const radiosity::Solver&, uint64_t shots)>& progress) {
  return solveTo(*solver_, converge, maxShots, progress, adaptation_.get());
}

bool LitScene::setPose(uint32_t object, const ObjectPose& pose) {
  if (!editor_.setPose(object, pose)) return false;
  const std::vector<EditedSurface> edited = editor_.takeEdited();
  applyEdit(*solver_, editor_.scene(), editor_.meshed(), edited, adaptation_.get());
  // Adapting, a surface moved along loses its refinement: its mesh changes too.
  for (const EditedSurface& e : edited) markChanged(e.surface, e.meshedAnew || e.holesChanged || adaptation_);
  return true;
}

void LitScene::restart() {
  solver_ = std::make_unique<radiosity::Solver>(
      adaptation_ ? adaptation_->input() : radiosityInput(editor_.scene(), editor_.meshed()), settings_.solver);
}

std::vector<SurfaceUpdate> LitScene::takeUpdates() {
  if (adaptation_)
    for (uint32_t s : adaptation_->takeChangedSurfaces()) markChanged(s, true);
  std::sort(changed_.begin(), changed_.end());
  std::vector<SurfaceUpdate> updates;
  updates.reserve(changed_.size());
  const Scene& scene = editor_.scene();
  for (uint32_t s : changed_) {
    const bool meshChanged = isChanged_[s] == 2;
    const SurfaceMesh& mesh = meshed().surfaces[s];
    updates.push_back({s, mesh, poseOf(scene.objects[scene.surfaces[s].object]), meshChanged,
                       meshChanged ? surfaceOutline(mesh) : std::vector<uint32_t>{}});
    isChanged_[s] = 0;
  }
  changed_.clear();
  return updates;
}

void LitScene::markChanged(uint32_t surface, bool meshChanged) {
  if (!isChanged_[surface]) changed_.push_back(surface);
  isChanged_[surface] = std::max<uint8_t>(isChanged_[surface], meshChanged ? 2 : 1);
}

}  // namespace engine
