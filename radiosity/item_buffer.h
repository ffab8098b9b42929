// Visibility read back from a hemisphere frame's item buffer, for receivers too small to own
// pixels of their own. Internal to radiosity/.
#pragma once

#include "pxpl5/hemisphere.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

#include <cstdint>
#include <span>

namespace radiosity {

// The hemisphere's local axes for a viewpoint normal. pxpl5 does not publish them: this repeats
// pxpl5::localFrame (Duff et al. 2017, from the float normal the renderer is given). The tests
// of small occluded receivers fail if the two ever differ.
struct HemisphereAxes {
  glm::dvec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
};
HemisphereAxes hemisphereAxes(const glm::vec3& normal);

// Per element: its plane (dot(normal, q) == offset) and its surface; the normal is its
// surface's (surfaceNormal, per surface), held once.
struct ElementPlanes {
  std::span<const glm::dvec3> surfaceNormal;
  std::span<const double> offset;
  std::span<const uint32_t> surface;
  const glm::dvec3& normal(uint32_t element) const { return surfaceNormal[surface[element]]; }
};

// The pixel of a hemisphere image `resolution` across whose item is read for `target` seen
// from `eye`, or false when the target is on or below the horizon or off the image. Pixel
// (i, j) looks along x = (i + 0.5) * 2 / resolution - 1: the nearest centre to x is
// floor((x + 1) * resolution / 2), and x + 1 >= 0, so the conversion truncates it the same.
inline bool targetPixel(const HemisphereAxes& axes, const glm::dvec3& eye, int resolution, const glm::dvec3& target,
                        int& i, int& j) {
  const glm::dvec3 d = target - eye;
  if (glm::dot(d, axes.z) <= 0) return false;
  const double scale = 0.5 * resolution / std::sqrt(glm::dot(d, d));
  i = static_cast<int>(glm::dot(d, axes.x) * scale + 0.5 * resolution);
  j = static_cast<int>(glm::dot(d, axes.y) * scale + 0.5 * resolution);
  return i >= 0 && j >= 0 && i < resolution && j < resolution;
}

// The share of `targets` (points on element `element`) that the frame's viewpoint `eye` sees.
// A target is hidden when the polygon in its pixel is of another surface and that polygon's
// plane crosses the segment from eye to target before the target. The pixel's own element, an
// element of the same surface (a neighbour that won the pixel) or an empty pixel leave it
// visible. Targets below the horizon (outside the disk) are not counted; with none left the
// answer is 1: the buffer knows nothing against it. Hemisphere projection only.
double itemBufferVisibility(const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes, const glm::dvec3& eye,
                            std::span<const glm::dvec3> targets, uint32_t element, const ElementPlanes& planes);

}  // namespace radiosity
