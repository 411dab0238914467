// pose/sensor_self_model.hpp — what the sensor measures about itself, from
// which every threshold of the pose estimator follows (none is a constant in
// mm or frames tuned at one operating point).
//
//  noise_mm  per-axis standard deviation sigma of a marker position (S, mm),
//            measured on frames out of contact from the change of each valid
//            marker since the previous such frame, d_i = p_i(k) - p_i(k-1):
//            each component of d_i has variance 2 sigma^2, and a robust
//            estimate of it is median(d^2) / 0.4549 (the median of a chi^2
//            variable with one degree of freedom). The running value is the
//            median of the last `window` per-frame estimates; before the first
//            one, the prior. Markers lost in either frame are skipped.
//  largest_axis_noise_mm  the same estimate per axis of S, the largest of the
//            three. Through a stereo pair the depth is the noisiest axis (its
//            error is the disparity's, times depth over baseline): through the
//            simulator's images z 0.0013 mm against x and y 0.0002, so the
//            pooled sigma above (0.00026) is the lateral one. A bound on a
//            marker's whole 3-D noise (a field pressed into the pad) takes this.
//  pitch_mm  the pattern pitch: median distance between rest grid neighbours.
//  frame_s   the frame interval: median of the last `window` timestamp steps
//            (prior until two frames have been seen).
#pragma once

#include <deque>

#include "core/marker_field.hpp"

namespace onetip::pose {

struct SensorSelf {
  double noise_mm = 0.0006;
  double largest_axis_noise_mm = 0.0006;
  double pitch_mm = 1.2;
  double frame_s = 1.0 / 30;
  bool noise_measured = false;
};

struct SensorSelfOptions {
  double prior_noise_mm = 0.0006;   // (0, 1] mm: the vision front end's error at default image quality
  double prior_frame_s = 1.0 / 30;  // (0, 1] s
  int window = 15;                  // [1, 1000] estimates kept for the running medians
  void validate() const;            // throws InputError naming the bad field
};

class SensorSelfModel {
 public:
  explicit SensorSelfModel(SensorSelfOptions options = {});
  // The rest field (S): sets the pitch (recomputed only when the field changes).
  void setRest(const MarkerField& rest);
  // Every frame, in time order: `at_rest` when no contact is seen, so the
  // change since the previous at-rest frame is noise only.
  void observe(const MarkerField& now, double t, bool at_rest);
  const SensorSelf& current() const { return self_; }

 private:
  SensorSelfOptions options_;
  SensorSelf self_;
  MarkerField rest_, previous_rest_frame_;
  bool have_previous_ = false;
  double last_t_ = 0;
  bool have_t_ = false;
  std::deque<double> noise_samples_, dt_samples_;
  std::deque<double> axis_samples_[3];
};

}  // namespace onetip::pose
