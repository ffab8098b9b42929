#include "engine/document/mesh_adaptation.h"

#include "engine/geometry/surface_mesh.h"

#include <array>
#include <cmath>
#include <map>

namespace engine {

namespace {

bool sameGeometry(const Surface& a, const Surface& b) {
  return a.outer == b.outer && a.holes == b.holes && a.normal == b.normal && a.patchSize == b.patchSize;
}

// Per live element of `adaptive` (slot order): its index in `mesh`, or kNone. The same order
// when `mesh` is the adaptive mesh's snapshot (after its first pass); else matched by corners
// (a mesh from the plain mesher, which may order or start its elements otherwise).
std::vector<uint32_t> indicesIn(const mesher::AdaptiveMesh& adaptive, const mesher::Mesh& mesh, double patchSize) {
  const mesher::Mesh snapshot = adaptive.snapshot();
  std::vector<uint32_t> index(snapshot.elements.size(), radiosity::kNone);
  if (snapshot.elements == mesh.elements && snapshot.vertices == mesh.vertices) {
    for (uint32_t i = 0; i < index.size(); ++i) index[i] = i;
    return index;
  }
  // Corners on a grid far finer than any element: a mesh moved along with its surface has its
  // plane coordinates projected back, a few ulps off the quadtree's.
  const double grid = 1e-9 * patchSize;
  const auto key = [&](const mesher::Mesh& m, const std::array<uint32_t, 4>& corners) {
    std::array<long long, 8> k{};
    for (int c = 0; c < 4; ++c)
      if (corners[c] != mesher::Mesh::kNone)
        k[2 * c] = std::llround(m.vertices[corners[c]].x / grid), k[2 * c + 1] = std::llround(m.vertices[corners[c]].y / grid);
    return k;
  };
  std::map<std::array<long long, 8>, uint32_t> byCorners;
  for (uint32_t i = 0; i < mesh.elements.size(); ++i) byCorners[key(mesh, mesh.elements[i])] = i;
  for (uint32_t i = 0; i < index.size(); ++i)
    if (const auto found = byCorners.find(key(snapshot, snapshot.elements[i])); found != byCorners.end())
      index[i] = found->second;
  return index;
}

}  // namespace

MeshAdaptation::MeshAdaptation(const Scene& scene, const MeshedScene& meshed, const AdaptiveSettings& settings)
    : scene_(scene),
      meshed_(meshed),
      settings_{.threshold = settings.threshold, .minElementSize = settings.minElementSize},
      input_(radiosityInput(scene, meshed)) {
  adaptive_.resize(scene.surfaces.size());
}

MeshAdaptation::~MeshAdaptation() = default;

mesher::AdaptiveMesh* MeshAdaptation::adaptiveMesh(size_t surface) {
  if (!adaptive_[surface]) {
    try {
      adaptive_[surface] = std::make_unique<mesher::AdaptiveMesh>(meshed_.surfaces[surface].polygon,
                                                                  mesher::MeshSettings{scene_.surfaces[surface].patchSize});
    } catch (const mesher::MeshRefused&) {
      // A surface moved rigidly keeps the mesh made where it was loaded; where it stands now its
      // detail may be finer than the coordinates resolve. Its mesh stays as it is.
      return nullptr;
    }
  }
  return adaptive_[surface].get();
}

size_t MeshAdaptation::pass(radiosity::Solver& solver) {
  const glm::dvec3 ambient = solver.ambient();
  const double floor = radiosity::kLuminanceFloorShare * radiosity::meanLuminance(input_, solver, ambient);
  size_t changed = 0;
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
    // The verdicts by slot, with the generation they are for: elements made by this pass's
    // refinement reuse freed slots and must not take the verdicts of what was there.
    const std::vector<mesher::ElementId> ids = mesh.elements();
    const std::vector<uint32_t> index = indicesIn(mesh, meshed_.surfaces[s].mesh, scene_.surfaces[s].patchSize);
    std::vector<std::pair<uint32_t, uint32_t>> bySlot;  // (generation, index)
    for (size_t i = 0; i < ids.size(); ++i) {
      if (bySlot.size() <= ids[i].slot) bySlot.resize(ids[i].slot + 1, {0, radiosity::kNone});
      bySlot[ids[i].slot] = {ids[i].generation, index[i]};
    }
    const auto verdict = [&](const std::vector<uint8_t>& of) {
      return [&](mesher::ElementId e) {
        if (e.slot >= bySlot.size() || bySlot[e.slot].first != e.generation) return false;
        const uint32_t i = bySlot[e.slot].second;
        return i != radiosity::kNone && of[i] != 0;
      };
    };
    const mesher::MeshDelta delta = mesh.adapt(verdict(verdicts.refine), verdict(verdicts.coarsen));
    if (delta.empty()) continue;
    changed += delta.removed.size() + delta.added.size();
    SurfaceMesh& surfaceMesh = meshed_.surfaces[s];
    surfaceMesh.mesh = mesh.snapshot();
    surfaceMesh.positions = worldPositions(scene_.surfaces[s], surfaceMesh.mesh.vertices);
    input_[s] = radiosityInput(scene_, meshed_, s);
  }
  if (changed > 0) {
    solver.edit(input_);
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

void MeshAdaptation::edit(const Scene& scene, const MeshedScene& meshed) {
  for (size_t s = 0; s < scene.surfaces.size(); ++s) {
    if (sameGeometry(scene.surfaces[s], scene_.surfaces[s])) continue;
    adaptive_[s].reset();
    // A mesh the editor moved along with its surface keeps the plane coordinates of where it
    // was; refining goes on from where it is.
    SurfaceMesh& mesh = meshed_.surfaces[s] = meshed.surfaces[s];
    mesh.polygon = planePolygon(scene.surfaces[s], scene.surfaces[s]);
    mesh.mesh.vertices = planeVertices(scene.surfaces[s], mesh.positions);
    input_[s] = radiosityInput(scene, meshed_, s);
  }
  scene_ = scene;
  // Passes are due again as the light after the edit settles (see adaptIfDue).
  nextPassAt_ = -1;
  convergedPasses_ = 0;
}

}  // namespace engine
