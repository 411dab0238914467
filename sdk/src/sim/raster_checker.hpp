// sim/raster_checker.hpp — the anti-aliased checkerboard texture, evaluated
// analytically per pixel (no texture memory, no supersampling).
//
// Pattern coordinates (u, v) in mm as in checker_sheet.hpp. A pixel's
// footprint in (u, v) is approximated by an axis-aligned box of half-widths
// (wu, wv) = 0.5 * (|du/dx| + |du/dy|, |dv/dx| + |dv/dy|) from the triangle's
// affine Jacobian; the texture is box-filtered over it exactly:
//   - the checker is mid - amp * s(u) * s(v) with s the square wave of period
//     2 * square (+1 where floor(u / square) is even); the box filter of s is
//     (T(u + w) - T(u - w)) / (2 w), T its integral (a triangle wave);
//   - the board and the outer border are rectangles whose filtered indicator
//     is the product of the clipped-overlap fractions along u and along v;
//     at the board's edge the square wave is integrated over the part of the
//     window inside the board only;
//   - grey = background + (light - background) * border + (checker - light) * board,
//     all terms box-filtered (exact for an axis-aligned box footprint).
// A symmetric filter keeps every inner corner an exact saddle of the shading,
// so anti-aliasing does not move the corners. Grey levels are pre-exposure.
// classify() lets the rasteriser shade a whole triangle at once where its
// widened (u, v) box holds no texture edge (most of them), and skip the
// border terms inside the board.
#pragma once

#include <algorithm>
#include <cmath>

#include "sim/checker_sheet.hpp"

namespace onetip::sim {

// A pixel footprint: half-widths in u and v (mm) and their 1 / (2 w).
struct Footprint {
  double wu, wv, inv_width_u, inv_width_v;
  Footprint(double half_u, double half_v)
      : wu(half_u), wv(half_v), inv_width_u(0.5 / half_u), inv_width_v(0.5 / half_v) {}
};

class FilteredChecker {
 public:
  // How the filtered texture varies over a (u, v) box widened by the footprint.
  enum class Region { kUniform, kBoardInterior, kGeneral };

  explicit FilteredChecker(const CheckerTexture& t)
      : inv_square_(1.0 / t.square_mm),
        square_(t.square_mm),
        board_u_hi_(t.cols * t.square_mm),
        board_v_hi_(t.rows * t.square_mm),
        board_lo_(-t.square_mm),
        border_(t.border_mm),
        mid_(0.5 * (t.dark + t.light)),
        amp_(0.5 * (t.light - t.dark)),
        light_(t.light),
        background_(t.background) {}

  // Classifies [u_lo - wu, u_hi + wu] x [v_lo - wv, v_hi + wv]: kUniform (no
  // texture edge inside; `grey` is then its level), kBoardInterior (inside
  // the printed board: shadeBoard() is exact there) or kGeneral (shade()).
  Region classify(double u_lo, double u_hi, double v_lo, double v_hi, const Footprint& f, double& grey) const {
    u_lo -= f.wu, u_hi += f.wu, v_lo -= f.wv, v_hi += f.wv;
    const bool no_square_edge = fastFloor(u_lo * inv_square_) == fastFloor(u_hi * inv_square_) &&
                                fastFloor(v_lo * inv_square_) == fastFloor(v_hi * inv_square_);
    const bool in_board = u_lo > board_lo_ && u_hi < board_u_hi_ && v_lo > board_lo_ && v_hi < board_v_hi_;
    const auto crosses = [](double lo, double hi, double edge) { return lo <= edge && edge <= hi; };
    const bool crosses_outer = crosses(u_lo, u_hi, board_lo_ - border_) ||
                               crosses(u_lo, u_hi, board_u_hi_ + border_) ||
                               crosses(v_lo, v_hi, board_lo_ - border_) || crosses(v_lo, v_hi, board_v_hi_ + border_);
    if (no_square_edge && !crosses_outer) {
      grey = shade(0.5 * (u_lo + u_hi), 0.5 * (v_lo + v_hi), Footprint(0.5 * (u_hi - u_lo), 0.5 * (v_hi - v_lo)));
      return Region::kUniform;
    }
    return in_board ? Region::kBoardInterior : Region::kGeneral;
  }

  // Grey level of the pixel whose footprint is centred at (u, v), in mm.
  double shade(double u, double v, const Footprint& f) const {
    const double outer = overlap(u, f.wu, f.inv_width_u, board_lo_ - border_, board_u_hi_ + border_) *
                         overlap(v, f.wv, f.inv_width_v, board_lo_ - border_, board_v_hi_ + border_);
    const ClippedWave along_u = clippedSquareWave(u, f.wu, f.inv_width_u, board_u_hi_);
    const ClippedWave along_v = clippedSquareWave(v, f.wv, f.inv_width_v, board_v_hi_);
    const double board = along_u.inside * along_v.inside;
    return background_ + (light_ - background_) * outer + (mid_ - light_) * board - amp_ * along_u.mean * along_v.mean;
  }

  // shade() where the footprint lies inside the printed board.
  double shadeBoard(double u, double v, const Footprint& f) const { return checker(u, v, f); }

 private:
  double checker(double u, double v, const Footprint& f) const {
    return mid_ - amp_ * filteredSquareWave(u, f.wu, f.inv_width_u) * filteredSquareWave(v, f.wv, f.inv_width_v);
  }

  // Integral of the square wave divided by the square size: triangle wave
  // rising 0 -> 1 over [0, 1) and falling back over [1, 2) (argument in squares).
  static double triangleWave(double p) { return 1.0 - std::abs(p - 2.0 * fastFloor(0.5 * p) - 1.0); }

  // floor() without a libm call on baseline x86-64 (|p| well inside int64).
  static double fastFloor(double p) {
    const double t = static_cast<double>(static_cast<long long>(p));
    return t > p ? t - 1.0 : t;
  }

  double filteredSquareWave(double u, double w, double inv_width) const {
    return square_ * (triangleWave((u + w) * inv_square_) - triangleWave((u - w) * inv_square_)) * inv_width;
  }

  // Fraction of [u - w, u + w] inside [lo, hi].
  static double overlap(double u, double w, double inv_width, double lo, double hi) {
    return std::clamp((std::min(u + w, hi) - std::max(u - w, lo)) * inv_width, 0.0, 1.0);
  }

  // Over the window [u - w, u + w]: the fraction inside the board [board_lo_, hi]
  // and the integral of the square wave over that part, both divided by 2 w.
  struct ClippedWave {
    double inside, mean;
  };
  ClippedWave clippedSquareWave(double u, double w, double inv_width, double hi) const {
    const double lo_clip = std::max(u - w, board_lo_), hi_clip = std::min(u + w, hi);
    if (hi_clip <= lo_clip) return {0.0, 0.0};
    return {(hi_clip - lo_clip) * inv_width,
            square_ * (triangleWave(hi_clip * inv_square_) - triangleWave(lo_clip * inv_square_)) * inv_width};
  }

  double inv_square_, square_, board_u_hi_, board_v_hi_, board_lo_, border_;
  double mid_, amp_, light_, background_;
};

}  // namespace onetip::sim
