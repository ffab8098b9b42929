// Corrections after an edit that cost what changed (Chen 1990, "Incremental radiosity": shoot
// the difference). A patch that did not move sees the old and the new scene alike except in the
// directions of the elements that changed, so its take-back and resend differ only in a window
// of its hemisphere image: both frames are rendered in that window alone (pxpl5's scissor), and
// only the receivers whose pixels or item-buffer targets changed there are judged again.
// These are the geometric steps, on plain arrays; Solver::frameInWindow (solver.cpp) drives them.
// Internal to radiosity/.
//
// Windows are rectangles of pixels of the hemisphere image (pxpl5::HemisphereFrame), `resolution`
// across; a pixel (i, j) looks along local (x, y, z) with x = (i + 0.5) * 2 / resolution - 1.
#pragma once

#include "radiosity/item_buffer.h"

#include "pxpl5/pxpl5.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace radiosity {

// The pixels whose directions from `eye` can meet the sphere (centre, radius), a pixel wider
// each side for rounding; empty when the sphere is wholly below the horizon, the whole image
// when it holds the eye. Conservative: every polygon inside the sphere is drawn within it, and
// every point inside reads its item from within it.
pxpl5::PixelRect sphereWindow(const HemisphereAxes& axes, const glm::dvec3& eye, int resolution, const glm::dvec3& centre,
                              double radius);

// The smallest rectangle holding both; an empty one is left out.
pxpl5::PixelRect unite(const pxpl5::PixelRect& a, const pxpl5::PixelRect& b);
bool overlaps(const pxpl5::PixelRect& a, const pxpl5::PixelRect& b);
bool contains(const pxpl5::PixelRect& outer, const pxpl5::PixelRect& inner);
inline int64_t pixelsOf(const pxpl5::PixelRect& r) {
  return r.empty() ? 0 : int64_t{r.x1 - r.x0} * int64_t{r.y1 - r.y0};
}

struct Sphere {
  glm::dvec3 centre{0};
  double radius = 0;
};

// Spheres around groups of `elements` (spheres given by `centre` and `radius`, indexed by
// element), the group split at the median of its box's longest side until each holds at most
// `maxElements`. A flat region seen at a slant fills much less of a hemisphere than one sphere
// around it: the windows of the parts are tighter. Deterministic; the order of `elements` is
// changed.
std::vector<Sphere> sphereClusters(std::span<const glm::dvec3> centre, std::span<const double> radius,
                                   std::span<uint32_t> elements, size_t maxElements);

// The elements and their patches as spheres (the scene of one geometry); patch p's elements are
// patchElements[patchFirst[p], patchLast[p]), and its sphere holds them all.
struct SceneSpheres {
  std::span<const glm::dvec3> centre;
  std::span<const double> radius;
  std::span<const uint32_t> surface;
  std::span<const glm::dvec3> patchCentre;
  std::span<const double> patchRadius;
  std::span<const uint32_t> patchFirst, patchLast, patchElements;
};

// Which elements a window correction looks at, from the window `changed` around the elements
// that changed. cull: the elements whose pixels may lie in `changed` (`judged`: candidates to be
// judged again) and those that may be drawn there (`drawn`, ascending), `window` = `changed`.
// drawWithin: `window` and `drawn` for a larger window (grown over the receivers that are judged
// again, so that their pixel counts and item-buffer targets are whole). Elements of surface
// `skipSurface` (the shooter's plane: not drawn, not judged) are left out.
class WindowCull {
 public:
  void cull(const SceneSpheres& scene, const HemisphereAxes& axes, const glm::dvec3& eye, int resolution,
            uint32_t skipSurface, const pxpl5::PixelRect& changed);
  void drawWithin(const pxpl5::PixelRect& grown);
  // Element j's sphereWindow from the last cull's eye (computed once per cull).
  const pxpl5::PixelRect& rectOf(uint32_t j);

  std::vector<uint32_t> judged, drawn;
  pxpl5::PixelRect window;

 private:
  SceneSpheres scene_;
  HemisphereAxes axes_;
  glm::dvec3 eye_{0};
  int resolution_ = 0;
  uint32_t generation_ = 0, drawGeneration_ = 0;
  uint32_t skipSurface_ = 0;
  std::vector<pxpl5::PixelRect> rect_, patchRect_;
  std::vector<uint32_t> rectMade_, drawnMark_;  // per element, the cull that made its rect, the drawWithin that drew it
};

}  // namespace radiosity
