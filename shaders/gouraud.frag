#version 330 core
// Writes either linear radiance (for float targets and --linear) or the displayed colour:
// radiance times exposure, clamped, encoded as sRGB.
in vec3 v_radiance;

uniform float u_exposure;
uniform bool u_linearOutput;

out vec4 o_color;

vec3 srgbFromLinear(vec3 c) {
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
  if (u_linearOutput) {
    o_color = vec4(v_radiance, 1.0);
  } else {
    o_color = vec4(srgbFromLinear(clamp(v_radiance * u_exposure, 0.0, 1.0)), 1.0);
  }
}
