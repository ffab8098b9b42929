// The graphics processors' setup programs of the two projections, and the pixel planes each
// loads into the machine. Internal to pxpl5; hemisphere.cpp drives them.
#pragma once

#include "pxpl5/hemisphere.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace pxpl5 {

// Local frame of a viewpoint: origin at the point, z along the normal.
struct LocalFrame {
  glm::dvec3 origin{0.0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};

  glm::dvec3 localFromWorld(const glm::vec3& world) const {
    const glm::dvec3 d = glm::dvec3(world) - origin;
    return {glm::dot(d, x), glm::dot(d, y), glm::dot(d, z)};
  }
};
LocalFrame localFrame(const Viewpoint& view);

// One frame's polygons as the setup programs see them.
struct ProjectionInput {
  const PolygonSoup* soup = nullptr;
  LocalFrame frame;
  std::span<const uint32_t> skipIds;
  int resolution = 0;
};

// Keeps the part of the convex polygon `in[0, n)` where dot(k, v) >= 0 (a plane through the
// origin) in `out`, returns its vertex count. A crossing point is computed from the inside
// vertex towards the outside one, so two polygons sharing the edge get the same point.
int clipToHalfSpace(const glm::dvec3* in, int n, const glm::dvec3& k, glm::dvec3* out);

// A polygon's vertices in the local frame, or nothing (returns 0) for a polygon that is skipped
// or whose plane passes through the point. `normal` is its Newell normal, `offset` its plane's
// dot(normal, q) (positive when the winding is counter-clockwise seen from the point).
int localPolygon(const ProjectionInput& in, size_t index, glm::dvec3* v, glm::dvec3& normal, double& offset);

// The hemisphere's set-up: vectorised over polygons, and its plain reference, one polygon at a
// time; they emit the same primitives, bit for bit.
void setupHemisphere(const ProjectionInput& in, size_t begin, size_t end, Emitter& out);
void setupHemisphereReference(const ProjectionInput& in, size_t begin, size_t end, Emitter& out);
void setupHemicube(const ProjectionInput& in, size_t begin, size_t end, Emitter& out);

// Screen size of each projection, and its per-pixel planes: the stored term and clear depth in
// the machine, the weight of each pixel (summing to 1) in `weights` (machine stride).
void screenSize(Projection projection, int resolution, int& width, int& height);
void loadHemispherePlanes(Machine& machine, int resolution, std::vector<float>& weights);
void loadHemicubePlanes(Machine& machine, int resolution, std::vector<float>& weights);

}  // namespace pxpl5
