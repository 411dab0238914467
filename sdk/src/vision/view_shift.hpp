// vision/view_shift.hpp — a mirror or the camera moved against the pad, told
// from the two views themselves and corrected before triangulation.
//
// A camera bumped on its mount, a crop that moves, a mirror that tilts:
// each translates a view's image (a shifted principal point; a small mirror
// tilt is the same to first order) while the pad stays. Every corner of that
// view moves by one vector. In 3-D this is not a rigid motion of the markers:
// a shift of one view changes the disparity, so the field appears to move
// into or out of the pad as under a flat plate pressed over the whole
// pattern, and the rest keeper (input/rest_keeper.hpp), which sees only S,
// must not take that for a move of the sensor. In the images the two differ.
//
// Per view v, with the corners' rest positions r_i (the reference frame, view
// px), the offset o_v corrected so far and this frame's n corners m_i valid in
// both (at least min_corners):
//   d_i = m_i - o_v - r_i,   t_v = median_i d_i (per component),
//   e_i = d_i - t_v,         sigma_v = max(1.4826 median |e_i|, min_sigma_px)
// (e_i's components pooled): sigma_v is the corner noise, measured on the
// frame itself, and s_v = 1.2533 sigma_v / sqrt(n) the sd of the median t_v.
// The view moved when every |e_i| <= k sigma_v (k = move_sigmas: the corners
// moved together, to within their noise) and |t_v| > k s_v (the common
// motion is beyond what the noise makes of a median). A finger moves the
// corners near it and not the others, so its dimple stays in the residuals
// and the median stays where most corners are. With each view's translation
// T_v in the delivered frame (x negated where the view is flipped):
//   - one view moved, the other did not: that view's mirror moved; o_v += t_v;
//   - both moved, |T_L - T_R| <= k sqrt(s_L^2 + s_R^2): the camera moved (the
//     whole frame); both offsets take their t_v;
//   - both moved by different vectors: a change of disparity, which the pad's
//     own motion into or out of itself makes (a flat plate, a thermal swell);
//     not a move of the sensor, left to the rest keeper.
// A slow ramp is followed frame by frame to within k s_v (hundredths of a
// pixel), so what is left of it at a touch does not bend the field.
// The caller decides only on frames whose predecessor was out of contact (a
// finger's pad moves under it) and corrects every view's corners by -o_v
// before triangulation from then on. A move is reported once its correction
// not yet reported reaches report_px.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "vision/view_markers.hpp"

namespace onetip::vision {

struct ViewShiftOptions {
  double move_sigmas = 8;      // [3, 1000] noise sigmas: how far a view must move, and how closely together
  double min_sigma_px = 0.01;  // [0.001, 1] px: the corner noise is taken as at least this (quantised corners)
  int min_corners = 12;        // [3, 10000]: fewer corners seen in a view at rest and now: no decision
  double report_px = 0.5;      // [0, 100] px: a correction is reported once it adds up to this much
  void validate() const;       // throws InputError naming the bad field
};

struct ViewShiftUpdate {
  bool corrected = false;  // an offset changed this frame
  std::string report;      // non-empty: what moved, for an event
};

class ViewShiftKeeper {
 public:
  // flip_left / flip_right: the views' flips in the delivered frame (core/calibration.hpp).
  ViewShiftKeeper(bool flip_left, bool flip_right, ViewShiftOptions options = {});

  // Decides on this frame's corners (m_i, view px) against the rest ones; call only on frames whose
  // predecessor was out of contact.
  ViewShiftUpdate update(const ViewMarkers& rest_left, const ViewMarkers& rest_right, const ViewMarkers& now_left,
                         const ViewMarkers& now_right);
  // The corners with the offset so far taken away (view px), for triangulation.
  // Takes each view's offset off its corners, in place (nothing to do while no view has moved).
  void correct(ViewMarkers& left, ViewMarkers& right) const;
  cv::Point2d offset(int view) const { return offset_[view]; }
  void reset();

 private:
  bool flip_[2];
  ViewShiftOptions options_;
  cv::Point2d offset_[2];
  cv::Point2d unreported_[2];
};

}  // namespace onetip::vision
