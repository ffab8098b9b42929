// Overshooting (Feda and Purgathofer 1992; Gortler, Cohen and Slusallek 1994, "Radiosity and
// relaxation methods"): a patch about to shoot also sends, ahead of time, the light it will
// reflect of what the patches it sees still hold unshot. When they shoot, that light comes back
// and cancels the negative unshot light the patch is left with, instead of making the patch
// shoot again. Energy stays exact (the overshoot is shot light like any other, and the patch's
// unshot light goes negative by as much); only the order in which light moves changes.
// Internal to radiosity/.
#pragma once

#include "radiosity/item_buffer.h"

#include "pxpl5/hemisphere.h"

#include <glm/vec3.hpp>

#include <span>

namespace radiosity {

// The radiance a point at `eye` gathers directly from the elements' unshot radiance `unshot`
// (per element, signed), per channel: the sum over the frame's factors F_j of F_j x unshot_j, for
// the elements whose front faces `eye` (a back sends nothing). By reciprocity that is what those
// elements will send the patch shooting from `eye` per unit of its area when they shoot.
glm::dvec3 gatherUnshot(std::span<const pxpl5::IdFactor> factors, const glm::dvec3& eye, const ElementPlanes& planes,
                        std::span<const glm::dvec3> unshot);

}  // namespace radiosity
