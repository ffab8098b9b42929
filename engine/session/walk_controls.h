// Walking through the model: what a frame's keys, mouse and wheel do to the camera. Plain
// logic, free of GLFW, so it is tested without a window.
#pragma once

#include "engine/session/view_camera.h"

namespace engine {

struct WalkInput {
  bool forward = false, back = false, left = false, right = false;  // W S A D
  bool up = false, down = false;                                    // E/PageUp, Q/PageDown
  bool fast = false;                                                // Shift
  double lookDx = 0, lookDy = 0;  // mouse motion in pixels while the right button is held
  double scroll = 0;              // wheel notches, positive away from the user
};

struct WalkSettings {
  double speed = 1;                 // scene units per second
  double radiansPerPixel = 0.0035;  // mouse-look sensitivity
};

// The walking speed a scene starts with: 1.4 m/s in the scene's units.
double defaultWalkSpeed(const engine::Scene& scene);

// Moves and turns the camera for `seconds` of input. Movement stays horizontal (a walker's
// heading), up and down are along world +y; the wheel scales the speed by 1.2 per notch; pitch
// stays within +-89 degrees.
void applyWalk(const WalkInput& input, double seconds, WalkSettings& settings, ViewCamera& camera);

}  // namespace engine
