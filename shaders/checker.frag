#version 330 core
// Fragment stage: the box-filtered checkerboard of sim/raster_checker.hpp
// (same maths as the CPU FilteredChecker): the pixel footprint's half-widths
// in (u, v) come from the screen derivatives of the affine (u, v), the
// square wave is filtered through its triangle-wave integral, clipped to the
// board at its edge, and the board and border rectangles are box-filtered.
in vec2 v_uv;
uniform float square_mm;
uniform vec2 board_hi;      // (cols, rows) * square_mm; the board starts at -square_mm
uniform float border_mm;
uniform float mid_grey, amplitude, light_grey, background_grey;
layout(location = 0) out vec4 grey;

float triangleWave(float p) { return 1.0 - abs(p - 2.0 * floor(0.5 * p) - 1.0); }

float overlap(float u, float w, float lo, float hi) {
  return clamp((min(u + w, hi) - max(u - w, lo)) / (2.0 * w), 0.0, 1.0);
}

// (fraction of the window inside the board, integral of the square wave there) / (2 w)
vec2 clippedSquareWave(float u, float w, float hi) {
  float lo_clip = max(u - w, -square_mm), hi_clip = min(u + w, hi);
  if (hi_clip <= lo_clip) return vec2(0.0);
  return vec2(hi_clip - lo_clip,
              square_mm * (triangleWave(hi_clip / square_mm) - triangleWave(lo_clip / square_mm))) / (2.0 * w);
}

void main() {
  vec2 w = max(0.5 * (abs(dFdx(v_uv)) + abs(dFdy(v_uv))), vec2(1e-4 * square_mm));
  float lo = -square_mm - border_mm;
  float outer = overlap(v_uv.x, w.x, lo, board_hi.x + border_mm) * overlap(v_uv.y, w.y, lo, board_hi.y + border_mm);
  vec2 along_u = clippedSquareWave(v_uv.x, w.x, board_hi.x);
  vec2 along_v = clippedSquareWave(v_uv.y, w.y, board_hi.y);
  float board = along_u.x * along_v.x;
  grey = vec4(background_grey + (light_grey - background_grey) * outer + (mid_grey - light_grey) * board -
                  amplitude * along_u.y * along_v.y, 0.0, 0.0, 1.0);
}
