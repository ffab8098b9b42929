// The viewer's camera: a pinhole at a position with a heading (yaw) and pitch, as a walker
// holds it, and the matrices that take the world to the screen.
#pragma once

#include "engine/scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace engine {

struct ViewCamera {
  glm::dvec3 position{0};
  double yaw = 0;    // radians; 0 looks along +z, positive turns toward +x
  double pitch = 0;  // radians; positive looks up
  glm::dvec3 up{0, 1, 0};
  double fovYDeg = 60;

  glm::dvec3 forward() const;
  glm::dvec3 right() const;  // forward x up, the image's right (spec: CAMERA)
};

// The camera as a scene file describes it (spec: CAMERA).
ViewCamera fromSceneCamera(const engine::Camera& camera);

// The camera a scene without cameras opens with: outside its bounds, looking at their centre
// from the front-left and a little above.
ViewCamera overviewCamera(const engine::Scene& scene);

// The scene camera named `name`; with an empty name the one named "default", else the first
// one, else the overview. Returns false (and leaves `out` alone) when a named camera is missing.
bool chooseCamera(const engine::Scene& scene, const std::string& name, ViewCamera& out);

// Clip coordinates from a display mesh's (world less `origin`: engine::DisplayMesh) for an image
// of `aspect` = width / height, with near and far planes that enclose the scene's bounds. Made in
// double and only then rounded, so the world's far-off origin never meets float.
glm::mat4 clipFromDisplay(const ViewCamera& camera, double aspect, const engine::Scene& scene, const glm::dvec3& origin);

// The direction from the eye through the point `ndc` of the image (x right, y up, both -1..1)
// of an image of `aspect` = width / height: where a click points.
glm::dvec3 rayThrough(const ViewCamera& camera, double aspect, glm::dvec2 ndc);

}  // namespace engine
