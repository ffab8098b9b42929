#version 330 core
// Mesh edges over the shading, as in the thesis' colour plates.
layout(location = 0) in vec3 a_position;

// Clip coordinates from the vertices' (the display's, through their object's transform).
uniform mat4 u_clipFromObject;

void main() {
  gl_Position = u_clipFromObject * vec4(a_position, 1.0);
}
