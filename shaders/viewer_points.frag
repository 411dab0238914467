#version 330 core
// u_points = 1: round points (gl_PointCoord), filled or as a ring, with a dark
// rim so they stand out on any background; u_points = 0: lines, plain colour.
uniform int u_points;
in vec4 v_colour;
flat in float v_ring;
out vec4 colour;

void main() {
  if (u_points == 0) {
    colour = v_colour;
    return;
  }
  float r = 2.0 * length(gl_PointCoord - vec2(0.5));
  if (r > 1.0) discard;
  if (v_ring > 0.5 && r < 0.6) discard;
  colour = r > 0.8 ? vec4(0.0, 0.0, 0.0, v_colour.a) : v_colour;
}
