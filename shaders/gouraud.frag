#version 330 core
// Writes either linear radiance (for float targets and --linear) or the displayed colour: per
// pixel, or as the vertices' displayed colours interpolated (u_toneMapVertices).
in vec3 v_radiance;

uniform float u_exposure;
uniform bool u_linearOutput;
uniform bool u_toneMapVertices;

out vec4 o_color;

#include "tone.glsl"

void main() {
  if (u_linearOutput || u_toneMapVertices) {
    o_color = vec4(v_radiance, 1.0);
  } else {
    o_color = vec4(displayColour(v_radiance, u_exposure), 1.0);
  }
}
