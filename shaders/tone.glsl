// The displayed colour of linear radiance: times the exposure, clamped, encoded as sRGB.
vec3 displayColour(vec3 radiance, float exposure) {
  vec3 c = clamp(radiance * exposure, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
