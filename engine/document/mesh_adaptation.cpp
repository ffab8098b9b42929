#include "engine/document/mesh_adaptation.h"

#include "engine/geometry/surface_mesh.h"

#include <unordered_map>

namespace engine {

namespace {

// An adaptive mesh of `surfaceMesh`'s polygon when it is that mesh, element for element under the
// same keys; else null: a triangle that is its own element (meshSurface), which the quadtree
// cuts up, or refuses where it is finer than the tree resolves.
std::unique_ptr<mesher::AdaptiveMesh> adaptiveMeshOf(const SurfaceMesh& surfaceMesh, double patchSize) {
  try {
    auto adaptive = std::make_unique<mesher::AdaptiveMesh>(surfaceMesh.polygon, mesher::MeshSettings{patchSize});
    const mesher::Mesh snapshot = adaptive->snapshot();
    if (snapshot.elements == surfaceMesh.mesh.elements && snapshot.vertices == surfaceMesh.mesh.vertices &&
        elementKeys(adaptive->elements()) == surfaceMesh.keys)
      return adaptive;
  } catch (const mesher::MeshRefused&) {
  }
  return nullptr;
}

}  // namespace

MeshAdaptation::MeshAdaptation(const Scene& scene, const MeshedScene& meshed, const AdaptiveSettings& settings)
    : scene_(scene),
      meshed_(meshed),
      settings_{.threshold = settings.threshold, .minElementSize = settings.minElementSize},
      input_(radiosityInput(scene, meshed)) {
  adaptive_.resize(scene.surfaces.size());
  unadaptable_.assign(scene.surfaces.size(), 0);
}

MeshAdaptation::~MeshAdaptation() = default;

mesher::AdaptiveMesh* MeshAdaptation::adaptiveMesh(size_t surface) {
  if (!adaptive_[surface] && !unadaptable_[surface]) {
    adaptive_[surface] = adaptiveMeshOf(meshed_.surfaces[surface], scene_.surfaces[surface].patchSize);
    unadaptable_[surface] = !adaptive_[surface];
  }
  return adaptive_[surface].get();
}

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
    if (verdicts.refineCount == 0 && (!adaptive_[s] || verdicts.coarsenCount == 0)) continue;

    mesher::AdaptiveMesh* const adaptive = adaptiveMesh(s);
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
    surfaceMesh.mesh = mesh.snapshot();
    surfaceMesh.keys = elementKeys(mesh.elements());
    addWorldPositions(scene_.surfaces[s], surfaceMesh);  // the vertices it had keep theirs
    input_[s] = radiosityInput(scene_, meshed_, s);
    changes.push_back({static_cast<uint32_t>(s), input_[s]});
    changed_.push_back(static_cast<uint32_t>(s));
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
    scene_.surfaces[e.surface] = scene.surfaces[e.surface];  // an edit costs what it changed
    adaptive_[e.surface].reset();
    unadaptable_[e.surface] = 0;
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
