// What adaptive refinement (thesis 5.5) should do to a surface's mesh, judged from the light on
// it: elements across whose edges the radiance jumps are refined, smooth groups coarsened. The
// mesher refines and coarsens (mesher/adaptive_mesh.h); this only decides, per element, from
// the solver's radiance, so either side can be tested without the other.
#pragma once

#include "radiosity/radiosity.h"

#include <cstdint>
#include <span>
#include <vector>

namespace radiosity {

struct RefinementSettings {
  // An element is refined when the luminance of an edge neighbour differs from its own by more
  // than this fraction of their mean (or of the scene's floor, below). Elements whose every
  // neighbour is within a quarter of it may coarsen (hysteresis: refined groups do not merge
  // again at once).
  double threshold = 0.25;
  // Elements are refined only while their children (half as wide) are at least this wide (an
  // element's width is its longest edge, in scene units). 0: no limit but the mesher's depth.
  double minElementSize = 0;
};

// Differences below this share of the scene's mean luminance are noise, not gradients: in dark
// corners a few percent of nearly nothing would otherwise refine.
constexpr double kLuminanceFloorShare = 0.1;

// Rec. 709 luminance of a radiance.
double luminance(const glm::dvec3& radiance);

// The area-weighted mean luminance of every element of `surfaces` (the solver's input), with
// reflectance x `ambient` added to each, as the display shows it.
double meanLuminance(std::span<const Surface> surfaces, const Solver& solver, const glm::dvec3& ambient);

// Per element of `surface`: the largest difference of its luminance to an edge neighbour's (an
// element of this surface sharing an edge with it), over their mean luminance or `floor`,
// whichever is larger. `radiance` is per element (radiance plus any ambient). 0 for elements
// without neighbours.
std::vector<double> luminanceJumps(const Surface& surface, std::span<const glm::dvec3> radiance, double floor);

struct RefinementVerdicts {
  std::vector<uint8_t> refine;   // per element: split it
  std::vector<uint8_t> coarsen;  // per element: may merge with its siblings (all must agree)
  size_t refineCount = 0, coarsenCount = 0;
};

// The verdicts for `surface` from luminanceJumps(surface, radiance, floor) and the settings.
RefinementVerdicts judgeElements(const Surface& surface, std::span<const glm::dvec3> radiance, double floor,
                                 const RefinementSettings& settings);

}  // namespace radiosity
