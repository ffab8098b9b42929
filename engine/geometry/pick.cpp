#include "engine/geometry/pick.h"

#include "mesher/polygon.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace engine {

namespace {

// Drops the coordinate the normal leans along most: the ring keeps its shape up to a stretch,
// which is all an inside test needs.
mesher::Vec2 flatten(const Vec3& p, int dropped) {
  return dropped == 0 ? mesher::Vec2{p.y, p.z} : dropped == 1 ? mesher::Vec2{p.x, p.z} : mesher::Vec2{p.x, p.y};
}

bool contains(const Ring3& ring, const Vec3& p, int dropped) {
  mesher::Ring2 flat;
  flat.reserve(ring.size());
  for (const Vec3& q : ring) flat.push_back(flatten(q, dropped));
  return mesher::containsPoint(flat, flatten(p, dropped));
}

}  // namespace

std::optional<SurfaceHit> pickSurface(const Scene& scene, const Vec3& origin, const Vec3& direction) {
  std::optional<SurfaceHit> nearest;
  for (uint32_t i = 0; i < scene.surfaces.size(); ++i) {
    const Surface& s = scene.surfaces[i];
    const double along = glm::dot(s.normal, direction);
    if (along == 0 || s.outer.empty()) continue;
    const double t = (s.planeOffset() - glm::dot(s.normal, origin)) / along;
    if (!(t > 0) || (nearest && t >= nearest->distance)) continue;
    const Vec3 p = origin + t * direction;
    const Vec3 n = glm::abs(s.normal);
    const int dropped = n.x >= n.y && n.x >= n.z ? 0 : n.y >= n.z ? 1 : 2;
    if (!contains(s.outer, p, dropped)) continue;
    bool inHole = false;
    for (const Ring3& hole : s.holes) inHole = inHole || contains(hole, p, dropped);
    if (!inHole) nearest = SurfaceHit{i, t, p};
  }
  return nearest;
}

}  // namespace engine
