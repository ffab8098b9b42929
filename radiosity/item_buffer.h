// Visibility read back from a hemisphere frame's item buffer, for receivers too small to own
// pixels of their own. Internal to radiosity/.
#pragma once

#include "pxpl5/hemisphere.h"

#include <glm/vec3.hpp>

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

// Per element: its plane (dot(normal, q) == offset) and its surface.
struct ElementPlanes {
  std::span<const glm::dvec3> normal;
  std::span<const double> offset;
  std::span<const uint32_t> surface;
};

// The share of `targets` (points on element `element`) that the frame's viewpoint `eye` sees.
// A target is hidden when the polygon in its pixel is of another surface and that polygon's
// plane crosses the segment from eye to target before the target. The pixel's own element, an
// element of the same surface (a neighbour that won the pixel) or an empty pixel leave it
// visible. Targets below the horizon (outside the disk) are not counted; with none left the
// answer is 1: the buffer knows nothing against it. Hemisphere projection only.
double itemBufferVisibility(const pxpl5::HemisphereFrame& frame, const HemisphereAxes& axes, const glm::dvec3& eye,
                            std::span<const glm::dvec3> targets, uint32_t element, const ElementPlanes& planes);

}  // namespace radiosity
