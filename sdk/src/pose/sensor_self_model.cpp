#include "pose/sensor_self_model.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/median.hpp"

namespace onetip::pose {

namespace {

void pushBounded(std::deque<double>& q, double v, int window) {
  q.push_back(v);
  while (static_cast<int>(q.size()) > window) q.pop_front();
}

// Median of chi^2 with one degree of freedom.
constexpr double kChi2OneMedian = 0.4549364;

}  // namespace

void SensorSelfOptions::validate() const {
  if (!(prior_noise_mm > 0 && prior_noise_mm <= 1))
    throw InputError("sensor self-model options: prior_noise_mm must be in (0, 1] mm");
  if (!(prior_frame_s > 0 && prior_frame_s <= 1))
    throw InputError("sensor self-model options: prior_frame_s must be in (0, 1] s");
  if (window < 1 || window > 1000) throw InputError("sensor self-model options: window must be in [1, 1000]");
}

SensorSelfModel::SensorSelfModel(SensorSelfOptions options) : options_(options) {
  options_.validate();
  self_.noise_mm = self_.largest_axis_noise_mm = options_.prior_noise_mm;
  self_.frame_s = options_.prior_frame_s;
}

void SensorSelfModel::setRest(const MarkerField& rest) {
  if (rest.position == rest_.position && rest.valid == rest_.valid) return;
  rest_ = rest;
  std::vector<double> gaps;
  for (int r = 0; r < rest.rows; ++r)
    for (int c = 0; c < rest.cols; ++c) {
      const size_t i = static_cast<size_t>(r * rest.cols + c);
      if (!rest.valid[i]) continue;
      if (c + 1 < rest.cols && rest.valid[i + 1]) gaps.push_back((rest.position[i + 1] - rest.position[i]).norm());
      const size_t below = i + static_cast<size_t>(rest.cols);
      if (r + 1 < rest.rows && rest.valid[below]) gaps.push_back((rest.position[below] - rest.position[i]).norm());
    }
  if (!gaps.empty()) self_.pitch_mm = upperMedian(std::move(gaps));
}

void SensorSelfModel::observe(const MarkerField& now, double t, bool at_rest) {
  if (have_t_ && t > last_t_) {
    pushBounded(dt_samples_, t - last_t_, options_.window);
    self_.frame_s = upperMedian({dt_samples_.begin(), dt_samples_.end()});
  }
  last_t_ = t;
  have_t_ = true;
  if (!at_rest) {
    have_previous_ = false;
    return;
  }
  if (have_previous_ && previous_rest_frame_.size() == now.size()) {
    std::vector<double> squares, axis[3];
    for (size_t i = 0; i < now.position.size(); ++i) {
      if (!now.valid[i] || !previous_rest_frame_.valid[i]) continue;
      const Eigen::Vector3d d = now.position[i] - previous_rest_frame_.position[i];
      for (int k = 0; k < 3; ++k) {
        squares.push_back(d[k] * d[k]);
        axis[k].push_back(d[k] * d[k]);
      }
    }
    if (squares.size() >= 9) {
      const auto sigma = [](std::vector<double> v) {
        return std::sqrt(upperMedian(std::move(v)) / kChi2OneMedian / 2.0);
      };
      pushBounded(noise_samples_, sigma(std::move(squares)), options_.window);
      self_.noise_mm = upperMedian({noise_samples_.begin(), noise_samples_.end()});
      self_.largest_axis_noise_mm = 0;
      for (int k = 0; k < 3; ++k) {
        pushBounded(axis_samples_[k], sigma(std::move(axis[k])), options_.window);
        self_.largest_axis_noise_mm =
            std::max(self_.largest_axis_noise_mm, upperMedian({axis_samples_[k].begin(), axis_samples_[k].end()}));
      }
      self_.noise_measured = true;
    }
  }
  previous_rest_frame_ = now;
  have_previous_ = true;
}

}  // namespace onetip::pose
