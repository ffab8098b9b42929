#include "engine/document/mesh_adaptation.h"

#include "engine/geometry/surface_mesh.h"

#include <unordered_map>

namespace engine {

MeshAdaptation::MeshAdaptation(const Scene& scene, const MeshedScene& meshed, const AdaptiveSettings& settings,
                               AdaptiveMeshes& meshes)
    : scene_(scene),
      meshed_(meshed),
      settings_{.threshold = settings.threshold, .minElementSize = settings.minElementSize},
      adaptive_(meshes),
      input_(radiosityInput(scene, meshed)) {}

MeshAdaptation::~MeshAdaptation() = default;

size_t MeshAdaptation::pass(radiosity::Solver& solver) {
  const glm::dvec3 ambient = solver.ambient();
  const double floor = radiosity::kLuminanceFloorShare * radiosity::meanLuminance(input_, solver, ambient);
  size_t changed = 0;
  std::vector<radiosity::SurfaceChange> changes;
  std::vector<glm::dvec3> lit;
  for (size_t s = 0; s < input_.size(); ++s) {
    // Judged as the display shows it: with the ambient term, so that early on a region not yet
    // reached by reflected light does not look like a shadow.
    const std::span<const glm::dvec3> radiance = solver.elementRadiance(static_cast<uint32_t>(s));
    lit.assign(radiance.begin(), radiance.end());
    for (glm::dvec3& l : lit) l += input_[s].reflectance * ambient;
    radiosity::RefinementSettings settings = settings_;
    if (settings.minElementSize <= 0) settings.minElementSize = scene_.surfaces[s].patchSize / 4;
    const radiosity::RefinementVerdicts verdicts = radiosity::judgeElements(input_[s], lit, floor, settings);
    // A surface still at its patch size has nothing to coarsen.
    const auto surface = static_cast<uint32_t>(s);
    if (verdicts.refineCount == 0 && (!adaptive_.find(surface) || verdicts.coarsenCount == 0)) continue;

    mesher::AdaptiveMesh* const adaptive = adaptive_.get(surface, scene_.surfaces[s], meshed_.surfaces[s]);
    if (!adaptive) continue;
    mesher::AdaptiveMesh& mesh = *adaptive;
    SurfaceMesh& surfaceMesh = meshed_.surfaces[s];
    // The verdicts by key: elements made by this pass's refinement reuse freed slots, with a
    // new generation, and take none.
    std::unordered_map<uint64_t, uint32_t> byKey;
    for (uint32_t i = 0; i < surfaceMesh.keys.size(); ++i) byKey.emplace(surfaceMesh.keys[i], i);
    const auto verdict = [&](const std::vector<uint8_t>& of) {
      return [&](mesher::ElementId e) {
        const auto found = byKey.find(elementKey(e));
        return found != byKey.end() && of[found->second] != 0;
      };
    };
    const mesher::MeshDelta delta = mesh.adapt(verdict(verdicts.refine), verdict(verdicts.coarsen));
    if (delta.empty()) continue;
    changed += delta.removed.size() + delta.added.size();
    takeAdaptiveMesh(scene_.surfaces[s], mesh, surfaceMesh);
    input_[s] = radiosityInput(scene_, meshed_, s);
    changes.push_back({surface, input_[s]});
    changed_.push_back(surface);
  }
  if (!changes.empty()) {
    solver.edit(changes);
    ++passes_;
  }
  return changed;
}

bool MeshAdaptation::adaptIfDue(radiosity::Solver& solver, double converge) {
  // Not while an edit's light is being taken back: some elements hold negative light then.
  if (solver.pendingCorrections() > 0) return false;
  const double fraction = solver.unshotFraction();
  const bool converged = fraction <= converge;
  if (nextPassAt_ < 0) {
    // The first call after an edit whose take-backs are done: passes from this light on.
    nextPassAt_ = kPassFall * fraction;
    return false;
  }
  if (converged ? convergedPasses_ >= kMaxConvergedPasses : fraction > nextPassAt_) return false;
  const bool changed = pass(solver) > 0;
  if (converged) convergedPasses_ = changed ? convergedPasses_ + 1 : kMaxConvergedPasses;
  // From the light before the pass: the light its take-backs move shows only once they are done.
  nextPassAt_ = kPassFall * fraction;
  return changed;
}

std::vector<radiosity::SurfaceChange> MeshAdaptation::edit(const Scene& scene, const MeshedScene& meshed,
                                                           std::span<const EditedSurface> edited) {
  std::vector<radiosity::SurfaceChange> changes;
  for (const EditedSurface& e : edited) {
    // An edit costs what it changed. The editor dropped the adaptive meshes of the surfaces it
    // meshed anew or moved along; those whose cut-outs it changed in place are the meshes taken.
    scene_.surfaces[e.surface] = scene.surfaces[e.surface];
    meshed_.surfaces[e.surface] = meshed.surfaces[e.surface];
    input_[e.surface] = radiosityInput(scene_, meshed_, e.surface);
    changes.push_back({e.surface, input_[e.surface], e.meshedAnew});
  }
  // Passes are due again as the light after the edit settles (see adaptIfDue).
  nextPassAt_ = -1;
  convergedPasses_ = 0;
  return changes;
}

}  // namespace engine
