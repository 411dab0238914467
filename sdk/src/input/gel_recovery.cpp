#include "input/gel_recovery.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/option_checks.hpp"

namespace onetip::input {

void GelRecoveryOptions::validate() const {
  requireInRange("gel recovery: fit_sigmas", fit_sigmas, 3, 100);
  requireInRange("gel recovery: release_factor", release_factor, 1, 100);
  requireInRange("gel recovery: release_false_alarm", release_false_alarm, 1e-9, 0.1);
}

DecayPair decayPair(const std::vector<Eigen::Vector3d>& before, const std::vector<std::uint8_t>& before_valid,
                    const std::vector<Eigen::Vector3d>& now, const std::vector<std::uint8_t>& now_valid,
                    double noise_mm) {
  DecayPair out;
  if (before.size() != now.size() || before_valid.size() != before.size() || now_valid.size() != now.size() ||
      !(noise_mm > 0))
    return out;
  double uu = 0, uv = 0;
  int n = 0;
  for (size_t i = 0; i < before.size(); ++i) {
    if (!before_valid[i] || !now_valid[i]) continue;
    uu += before[i].squaredNorm();
    uv += before[i].dot(now[i]);
    ++n;
  }
  if (n < 3 || !(uu > 0)) return out;
  out.measured = true;
  out.markers = n;
  out.alpha = uv / uu;
  const double s = noise_mm * std::sqrt(1 + out.alpha * out.alpha);
  out.alpha_sd = s / std::sqrt(uu);
  for (size_t i = 0; i < before.size(); ++i) {
    if (!before_valid[i] || !now_valid[i]) continue;
    out.worst_sigmas = std::max(out.worst_sigmas, (now[i] - out.alpha * before[i]).norm() / s);
    out.worst_growth_sigmas = std::max(out.worst_growth_sigmas, (now[i].norm() - out.alpha * before[i].norm()) / s);
  }
  return out;
}

double noiseMaximum(int markers, double false_alarm) {
  // P(|r| > b) for r with three independent unit-normal components (chi with 3 degrees of freedom):
  // erfc(b / sqrt 2) + sqrt(2 / pi) b exp(-b^2 / 2).
  const auto tail = [](double b) {
    return std::erfc(b / std::numbers::sqrt2) + std::sqrt(2 / std::numbers::pi) * b * std::exp(-b * b / 2);
  };
  const double per_marker = false_alarm / std::max(markers, 1);
  double lo = 0, hi = 40;
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    (tail(mid) > per_marker ? lo : hi) = mid;
  }
  return hi;
}

GelRecovery::GelRecovery(GelRecoveryOptions options) : options_(options) { options_.validate(); }

const std::vector<Eigen::Vector3d>& GelRecovery::advance() {
  for (auto& v : remainder_) v *= remainder_alpha_;
  return remainder_;
}

MarkerField withoutRemainder(const MarkerField& now, const std::vector<Eigen::Vector3d>& remainder) {
  if (remainder.size() != now.position.size()) return now;
  MarkerField out = now;
  for (size_t i = 0; i < out.position.size(); ++i) out.position[i] -= remainder[i];
  return out;
}

void GelRecovery::reset() {
  remainder_.clear();
  remainder_began_ = false;
  previous_.clear();
  previous_valid_.clear();
  window_.armed = false;
  recovering_ = false;
}

bool GelRecovery::recovering(const contact::ContactField& field, bool was_in_contact, double noise_mm,
                             double contact_threshold_mm) {
  if (!options_.enabled) return false;
  const double k = options_.fit_sigmas;
  const DecayPair pair = decayPair(previous_, previous_valid_, field.displacement, field.valid, noise_mm);
  const bool shrinking = pair.measured && pair.alpha < 1 - k * pair.alpha_sd;
  remainder_began_ = false;
  decaying_frames_ = 0;
  if (!field.in_contact) {
    recovering_ = false;  // within the contact threshold (or no decision): the contact rule says it all
    remainder_.clear();
  } else if (recovering_) {
    // No marker moves away from the rest beyond the decay of the last frame, and the field does not grow;
    // else a finger touches again. (One still brushing the pad as it leaves only takes deformation away.)
    // And it keeps shrinking at the recovery's own rate (or faster, as a finger leaves): a shrink that slows
    // or stops is held by something, a finger.
    const double rate = rate_sum_ / rate_count_;
    recovering_ = pair.measured && pair.worst_growth_sigmas <= k &&
                  pair.alpha <= rate + k * pair.alpha_sd * std::sqrt(1 + 1.0 / rate_count_);
    if (recovering_) {
      rate_sum_ += pair.alpha;
      ++rate_count_;
    } else {
      // A finger touches the recovering gel: what is left of the recovery goes on at the measured rate.
      remainder_alpha_ = rate;
      remainder_.assign(previous_.size(), Eigen::Vector3d::Zero());
      for (size_t i = 0; i < previous_.size(); ++i)
        if (previous_valid_[i]) remainder_[i] = remainder_alpha_ * previous_[i];
      remainder_began_ = true;
    }
  } else if (was_in_contact && window_.armed) {
    // Since the last shrink that changed shape (frame j, n frames ago): every frame a scaled copy of u_j,
    // alpha_n = <u_j, u_k> / <u_j, u_j>, shrinking.
    ++window_.frames;
    const DecayPair since = decayPair(window_.base, window_.base_valid, field.displacement, field.valid, noise_mm);
    const double bound = noiseMaximum(since.markers, options_.release_false_alarm);
    if (since.measured && since.worst_sigmas <= bound && since.alpha > 0 && since.alpha < 1 - k * since.alpha_sd) {
      decaying_frames_ = window_.frames;
      // The first pair after the change releases by itself when it shrank more slowly than the change did,
      // and by enough that a finger still holding a field at the contact threshold, which leaves a part
      // that does not scale ((1 - alpha) times that field), would have shown.
      const double s = noise_mm * std::sqrt(1 + since.alpha * since.alpha);
      recovering_ = window_.frames == 1 &&
                    since.alpha - window_.alpha > k * std::hypot(since.alpha_sd, window_.alpha_sd) &&
                    (1 - since.alpha) * contact_threshold_mm > bound * s;
      rate_sum_ = recovering_ ? since.alpha : 0;
      rate_count_ = recovering_ ? 1 : 0;
    }
  }
  const bool copy = pair.measured && pair.worst_sigmas <= noiseMaximum(pair.markers, options_.release_false_alarm);
  if (recovering_ || !field.in_contact || (!shrinking && !copy)) {
    window_.armed = false;  // released, or something other than a gel moved the markers
  } else if (shrinking && !copy) {
    // The shape changed while the field shrank: what stays may be the gel alone, judged from here on. The
    // finger's own field going (a change beyond release_factor x fit_sigmas) arms the release; its rate is
    // what the gel's must be slower than.
    if (pair.worst_sigmas > options_.release_factor * k) window_.armed = true;
    window_.alpha = pair.alpha;
    window_.alpha_sd = pair.alpha_sd;
    window_.base = field.displacement;
    window_.base_valid = field.valid;
    window_.frames = 0;
  }
  previous_ = field.displacement;
  previous_valid_ = field.valid;
  if (recovering_ && !remainder_.empty()) {
    // Released again: the gel alone is left, the old remainder with the new one; follow it whole.
    for (size_t i = 0; i < previous_.size() && i < remainder_.size(); ++i) previous_[i] += remainder_[i];
    remainder_.clear();
  }
  return recovering_;
}

void clearContact(contact::ContactField& field) {
  field.in_contact = false;
  field.regions.clear();
  std::fill(field.region_of.begin(), field.region_of.end(), -1);
}

}  // namespace onetip::input
