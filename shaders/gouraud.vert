#version 330 core
// Gouraud shading: what each vertex holds (linear radiance from the solver, or its displayed
// colour) is interpolated across the triangles.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_radiance;

// Clip coordinates from the vertices' (the display's, through their object's transform).
uniform mat4 u_clipFromObject;

out vec3 v_radiance;

void main() {
  gl_Position = u_clipFromObject * vec4(a_position, 1.0);
  v_radiance = a_radiance;
}
