// Sweeping a solid's profile into its faces, cutting holes and placing them in the world.
#pragma once

#include "engine/scene.h"

#include <glm/mat3x3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace engine {

// One face of a swept solid in the solid's own (object) coordinates, before holes.
struct SolidFace {
  std::string name;        // "bottom", "top", "side N" or, for radial tapers, "side N.K"
  Ring3 ring;              // counter-clockwise seen from the front
  Vec3 normal;             // unit, outward (or inward for `inward` solids)
  Vec3 origin, u, v;       // the face's 2-D frame for hole coordinates (spec: FACE)
  mesher::Ring2 ring2;     // `ring` in that frame
};

// The faces of a solid, named as the spec names them; faces shrunk to a point (tapered apexes)
// are left out. The solid must already be valid (convex profile, from < to).
std::vector<SolidFace> sweepSolid(const Solid& solid);

// Where an object puts its solids: rotate_y about the origin, then the translation.
struct Placement {
  glm::dmat3 worldFromObject{1.0};
  Vec3 translation{0};
  Vec3 point(const Vec3& p) const { return worldFromObject * p + translation; }
  Vec3 direction(const Vec3& d) const { return worldFromObject * d; }
};
Placement placementOf(const Object& object);

// Appends the surfaces of one solid (faces not open, with their holes, plus one surface per
// filled hole) to `out`. Throws SceneError for an override naming a missing face, or for holes
// outside their face or touching each other. A surface's patch size comes from its face, else
// its solid, else `objectPatchSize`; 0 when none of them sets one (the scene's size applies).
void appendSolidSurfaces(const Scene& scene, uint32_t objectIndex, const Solid& solid,
                         std::optional<double> objectPatchSize, std::vector<Surface>& out);

}  // namespace engine
