#version 330 core
// Mesh edges over the shading, as in the thesis' colour plates.
layout(location = 0) in vec3 a_position;

uniform mat4 u_clipFromDisplay;

void main() {
  gl_Position = u_clipFromDisplay * vec4(a_position, 1.0);
}
