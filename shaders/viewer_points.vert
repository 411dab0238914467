#version 330 core
// Coloured points and lines: detected corners over the camera image, the
// contact map, the deformation arrows. Positions go through u_transform (an
// orthographic map of panel coordinates, or a panel's perspective camera).
// a_style.x: point diameter in pixels; a_style.y: 0 filled disc, 1 ring.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_colour;
layout(location = 2) in vec2 a_style;
uniform mat4 u_transform;
out vec4 v_colour;
flat out float v_ring;

void main() {
  v_colour = a_colour;
  v_ring = a_style.y;
  gl_PointSize = a_style.x;
  gl_Position = u_transform * vec4(a_position, 1.0);
}
