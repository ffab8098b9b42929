#version 330 core
// Writes the displayed colour per pixel; or, with PASS_THROUGH defined, what the vertices hold:
// linear radiance (float targets, --linear) or their displayed colours (app/gl/display_colours.h).
// The variants are programs of their own (app/gl/scene_renderer.h), not a branch on a uniform:
// llvmpipe paid for the branch in every pixel, a third of the window's frame on the kitchen.
in vec3 v_radiance;

uniform float u_exposure;

out vec4 o_color;

#include "tone.glsl"

void main() {
#ifdef PASS_THROUGH
  o_color = vec4(v_radiance, 1.0);
#else
  o_color = vec4(displayColour(v_radiance, u_exposure), 1.0);
#endif
}
