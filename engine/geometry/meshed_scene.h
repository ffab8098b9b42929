// A scene's surfaces meshed once by the modified quadtree, and what the display and the
// radiosity solver each take from those meshes: both see the same vertices in the same order,
// so the solver's vertex radiance goes straight onto the display's vertices.
#pragma once

#include "engine/geometry/surface_mesh.h"
#include "engine/scene.h"
#include "radiosity/radiosity.h"

#include <cstdint>
#include <span>
#include <vector>

namespace engine {

struct MeshedScene {
  std::vector<SurfaceMesh> surfaces;  // per Scene::surfaces, in order
};

// A surface an edit changed (SceneEditor::setPose): moved along with its object, its mesh and
// its elements' keys going on; or its cut-outs changed in its adaptive mesh, the elements near
// them removed and added, the others going on under their keys; or meshed anew.
struct EditedSurface {
  uint32_t surface = 0;
  bool meshedAnew = false;
  bool holesChanged = false;
  bool operator==(const EditedSurface&) const = default;
};

// Adds `more` to `edits` (by surface, each once): a surface meshed anew, or whose cut-outs
// changed, in either was so.
void addEdits(std::vector<EditedSurface>& edits, std::span<const EditedSurface> more);

// The most elements a scene's meshes may have in all: far above the large models' (a living room
// of 2.6 million), and about 2 GB of meshes, solver and display data.
constexpr size_t kMaxSceneElements = size_t{1} << 24;

// Meshes every surface at its patch size, through one mesher::Mesher (`repeats`, when given,
// counts the surfaces that were repeats: Mesher::repeats). Throws SceneError naming the scene's
// file and the surface's JSON path for a surface the mesher refuses (mesher.h's limits), or
// where the meshes pass kMaxSceneElements.
MeshedScene meshScene(const Scene& scene, size_t* repeats = nullptr);

// Shooting patches are squares of this many patch sizes (substructuring): elements stay at the
// patch size for display and receiving, while fewer patches shoot. A patch's near receivers take
// their visibility from its one shooting point, which with patches this size left the face of a
// box standing on a floor 15% too dark: a floor patch reaching around the box's corner shoots
// from a point that sees only the face's back. The solver now gives such a face the light of the
// patch's part in front of it (radiosity/solver.cpp), and every Cornell probe is within about 1%
// of the path tracer. Three patch sizes shoot 40% fewer times but leave that face 3-4% too dark.
constexpr double kShootingPatchPatches = 2;

// The solver's input: per surface its world vertices, elements and their keys, normal,
// reflectance and emission, elements grouped into shooting patches of kShootingPatchPatches
// patch sizes.
std::vector<radiosity::Surface> radiosityInput(const Scene& scene, const MeshedScene& meshed);
// The same for one surface (its index in both).
radiosity::Surface radiosityInput(const Scene& scene, const MeshedScene& meshed, size_t surface);
// The solver's edit (radiosity::Solver::edit) of the surfaces `edited` names: their input now.
std::vector<radiosity::SurfaceChange> radiosityChanges(const Scene& scene, const MeshedScene& meshed,
                                                       std::span<const EditedSurface> edited);

}  // namespace engine
