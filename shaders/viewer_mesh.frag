#version 330 core
// Two-sided Lambert shading with ambient light. u_colour_by_scalar = 1 colours
// by a_scalar / u_scalar_max through a blue-cyan-green-yellow-red ramp (the
// displacement modulus); otherwise by the vertex colour.
uniform int u_colour_by_scalar;
uniform float u_scalar_max;
uniform vec3 u_light;  // unit direction towards the light, S
uniform int u_lit;
in vec3 v_normal;
in vec4 v_colour;
in float v_scalar;
out vec4 colour;

vec3 ramp(float s) {
  s = clamp(s, 0.0, 1.0);
  vec3 c = vec3(clamp(1.5 - abs(4.0 * s - 3.0), 0.0, 1.0),
                clamp(1.5 - abs(4.0 * s - 2.0), 0.0, 1.0),
                clamp(1.5 - abs(4.0 * s - 1.0), 0.0, 1.0));
  return c;
}

void main() {
  vec3 base = u_colour_by_scalar == 1 ? ramp(v_scalar / u_scalar_max) : v_colour.rgb;
  float diffuse = u_lit == 1 ? abs(dot(normalize(v_normal), u_light)) : 1.0;
  float light = u_lit == 1 ? 0.35 + 0.65 * diffuse : 1.0;
  colour = vec4(base * light, v_colour.a);
}
