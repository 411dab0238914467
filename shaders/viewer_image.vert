#version 330 core
// A textured rectangle without vertex buffers: vertex i of a 4-vertex triangle
// strip is the corner (i & 1, i >> 1) of u_rect = (x0, y0, x1, y1) in normalised
// device coordinates; v = 0 at the image's first row (top).
uniform vec4 u_rect;
out vec2 v_uv;

void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
  v_uv = vec2(corner.x, 1.0 - corner.y);
  gl_Position = vec4(mix(u_rect.xy, u_rect.zw, corner), 0.0, 1.0);
}
