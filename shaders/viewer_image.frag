#version 330 core
// u_grey = 1: a one-channel camera image shown as grey, opaque.
// u_grey = 0: a colour overlay with straight alpha (text, gauges).
uniform sampler2D u_image;
uniform int u_grey;
in vec2 v_uv;
out vec4 colour;

void main() {
  vec4 texel = texture(u_image, v_uv);
  colour = u_grey == 1 ? vec4(texel.rrr, 1.0) : texel;
}
