// Picking: which surface a ray from the eye meets first (a click in the window).
#pragma once

#include "engine/scene.h"

#include <cstdint>
#include <optional>

namespace engine {

struct SurfaceHit {
  uint32_t surface = 0;  // index into Scene::surfaces
  double distance = 0;   // along the ray, in units of |direction|
  Vec3 point{0};
};

// The nearest surface the ray origin + t * direction (t > 0) meets, from either side, inside its
// outer ring and outside its holes; nothing when it meets none. Linear in the scene's points.
std::optional<SurfaceHit> pickSurface(const Scene& scene, const Vec3& origin, const Vec3& direction);

}  // namespace engine
