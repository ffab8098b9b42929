// Scenes for the radiosity tests: rectangles meshed by the quadtree mesher, a closed box, and the
// shipped Cornell box meshed by the engine.
#pragma once

#include "radiosity/radiosity.h"

#include <glm/vec3.hpp>

#include <vector>

namespace radiosity::test {

// The rectangle origin + s u + t v for s, t in [0, 1], meshed at `patchSize`; its front is the
// side u x v points to.
Surface rectangle(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, double patchSize, glm::dvec3 reflectance,
                  glm::dvec3 emission = glm::dvec3(0));

// The six inner faces of the box [0, size]^3, one material.
std::vector<Surface> closedBox(double size, double patchSize, glm::dvec3 reflectance, glm::dvec3 emission);

// Sum over a surface's elements of area x radiance: its reflected power over pi.
glm::dvec3 areaTimesRadiance(const Solver& solver, const Surface& surface, uint32_t index);

// Every surface of the shipped Cornell box meshed at its patch size, as the solver takes it.
std::vector<Surface> cornellBox();

double area(const Surface& surface, uint32_t element);

}  // namespace radiosity::test
