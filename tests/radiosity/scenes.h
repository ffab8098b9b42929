// Scenes for the radiosity tests: rectangles meshed by the quadtree mesher, single quads, a closed
// box, a lit room with a board; and the measures the tests compare solutions by.
#pragma once

#include "radiosity/radiosity.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace radiosity::test {

// The rectangle origin + s u + t v for s, t in [0, 1], meshed at `patchSize`; its front is the
// side u x v points to.
Surface rectangle(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, double patchSize, glm::dvec3 reflectance,
                  glm::dvec3 emission = glm::dvec3(0));

// One quad element, origin, origin + u, origin + u + v, origin + v, for scenes at scales the
// mesher has no business with; its front is the side u x v points to.
Surface quad(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, glm::dvec3 reflectance, glm::dvec3 emission = glm::dvec3(0));

// The six inner faces of the box [0, size]^3, one material.
std::vector<Surface> closedBox(double size, double patchSize, glm::dvec3 reflectance, glm::dvec3 emission);

// A closed unit room lit by a panel under its ceiling, with a horizontal board standing in the
// light at `height`, offset by `dx` along x.
std::vector<Surface> roomWithBoard(double dx, double height);

// roomWithBoard's board: its top and its underside.
inline constexpr uint32_t kBoard[] = {7, 8};

// An edit of `surfaces` (Solver::edit) of these of `now`, keeping their keys.
std::vector<SurfaceChange> changesOf(const std::vector<Surface>& now, std::span<const uint32_t> surfaces);

// Sum over a surface's elements of area x radiance: its reflected power over pi.
glm::dvec3 areaTimesRadiance(const Solver& solver, const Surface& surface, uint32_t index);

double area(const Surface& surface, uint32_t element);

double channelSum(const glm::dvec3& v);

// Mean absolute difference of element radiance over the mean, all surfaces (`b` the reference).
double meanDifference(const Solver& a, const Solver& b);

// The largest relative difference of element radiance, any channel, any element lit above a
// millionth of the mean (`b` the reference): below that lie faces that see nothing (a block's
// bottom on the floor), whose radiance is rounding left over from shots of both signs.
double worstDifference(const Solver& a, const Solver& b);

}  // namespace radiosity::test
