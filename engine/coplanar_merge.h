// Preprocessing of thesis 3.2: surfaces in one plane, facing the same way, of one material, that
// share boundary, are merged into one surface (with holes) before meshing, so their meshes
// cannot meet with T-vertices. Touching edges may split each other (T-junctions in the input).
#pragma once

#include "engine/scene.h"

#include <vector>

namespace engine {

// Merges surfaces of one object, or of different objects that are all fixed (movable: false),
// that are coplanar within `tolerance` (scene units), face the same way, share a material and
// touch along part of an edge. A group whose union is not one polygon with holes (touching only
// at a point, say) is left as it was. The merged surface keeps the first surface's object and
// json path, the smallest patch size, and lists the face names joined by " + ".
std::vector<Surface> mergeCoplanarSurfaces(const Scene& scene, std::vector<Surface> surfaces, double tolerance);

}  // namespace engine
