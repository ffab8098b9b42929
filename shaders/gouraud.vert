#version 330 core
// Gouraud shading: radiance is computed per vertex (by the solver) and interpolated, as linear
// radiance or, when the vertices are tone mapped, as the displayed colour.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_radiance;

// Clip coordinates from the vertices' (the display's, through their object's transform).
uniform mat4 u_clipFromObject;
uniform float u_exposure;
uniform bool u_toneMapVertices;

out vec3 v_radiance;

#include "tone.glsl"

void main() {
  gl_Position = u_clipFromObject * vec4(a_position, 1.0);
  v_radiance = u_toneMapVertices ? displayColour(a_radiance, u_exposure) : a_radiance;
}
