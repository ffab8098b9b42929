// The ambient term of progressive refinement (Cohen, Chen, Wallace, Greenberg 1988): an estimate
// of the light not yet shot, spread uniformly over the scene, so a picture is plausible before
// the solution converges. Before any shot it is the whole display lighting.
#pragma once

#include <glm/vec3.hpp>

#include <span>

namespace radiosity {

struct SurfaceLight {
  double area = 0;                    // in squared scene units, > 0
  glm::dvec3 reflectance{0};          // diffuse albedo per channel, 0..1
  glm::dvec3 unshotRadiance{0};       // radiance not yet shot; before any shot: the emission
};

// Returns the ambient radiance La = (sum of unshot radiance x area / total area) / (1 - mean
// reflectance): light bouncing forever in a closed room of the scene's mean reflectance. A
// surface is then displayed with its own radiance plus reflectance x La. Exact for a furnace (a
// closed box of one material). Mean reflectance is capped at 0.999; an empty span gives 0.
glm::dvec3 ambientRadiance(std::span<const SurfaceLight> surfaces);

}  // namespace radiosity
