// A scene's surfaces meshed once by the modified quadtree, and what the display and the
// radiosity solver each take from those meshes: both see the same vertices in the same order,
// so the solver's vertex radiance goes straight onto the display's vertices.
#pragma once

#include "engine/scene.h"
#include "engine/surface_mesh.h"
#include "radiosity/radiosity.h"

#include <vector>

namespace engine {

struct MeshedScene {
  std::vector<SurfaceMesh> surfaces;  // per Scene::surfaces, in order
};

// Meshes every surface at its patch size.
MeshedScene meshScene(const Scene& scene);

// Shooting patches are squares of this many patch sizes (substructuring): elements stay at the
// patch size for display and receiving, while fewer patches shoot. Two patch sizes shot the
// light bounced off a floor onto the face of a box standing on it 15% too dark (a patch's near
// receivers take their visibility from its one shooting point); one and a half keep the Cornell
// box within 3% of a path tracer there too, at about 1.5 times the shots.
constexpr double kShootingPatchPatches = 1.5;

// The solver's input: per surface its world vertices and elements, normal, reflectance and
// emission, elements grouped into shooting patches of kShootingPatchPatches patch sizes.
std::vector<radiosity::Surface> radiosityInput(const Scene& scene, const MeshedScene& meshed);

}  // namespace engine
