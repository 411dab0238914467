#version 330 core
// Vertex stage of the simulator's GLSL renderer (sim/glsl_renderer.hpp).
// pixel: distorted pixel coordinates of the pinhole view, centres at integers
// (projected on the CPU with VirtualCamera::project); depth: camera-frame z, mm;
// uv: pattern coordinates, mm. The view fills the current viewport.
layout(location = 0) in vec2 pixel;
layout(location = 1) in float depth;
layout(location = 2) in vec2 uv;
uniform vec2 view_size;  // pixels
uniform float far_mm;    // depth range [0, far_mm] maps to the depth buffer
out vec2 v_uv;
void main() {
  gl_Position = vec4((pixel + 0.5) / view_size * 2.0 - 1.0, depth / far_mm * 2.0 - 1.0, 1.0);
  v_uv = uv;
}
