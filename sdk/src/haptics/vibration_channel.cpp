#include "haptics/vibration_channel.hpp"

#include <cmath>

#include "core/error.hpp"

namespace onetip::haptics {

void VibrationChannelOptions::validate() const {
  if (warmup_samples < 0 || warmup_samples > 100000)
    throw InputError("VibrationChannelOptions.warmup_samples: must be in 0..100000");
  if (fade_samples < 1 || fade_samples > 100000)
    throw InputError("VibrationChannelOptions.fade_samples: must be in 1..100000");
}

VibrationChannel::VibrationChannel(const TransferFunction& initial, const VibrationChannelOptions& options)
    : options_(options), current_(initial) {
  options_.validate();
  history_.assign(static_cast<size_t>(options_.warmup_samples), 0.0);
}

void VibrationChannel::select(const TransferFunction& tf) {
  if (fading()) {
    pending_ = tf;
    return;
  }
  const TransferFunction& now = current_.transferFunction();
  if (tf.a == now.a && tf.b == now.b) return;
  startFade(tf);
}

void VibrationChannel::startFade(const TransferFunction& tf) {
  previous_ = current_;
  current_ = IirFilter(tf);
  const size_t n = history_.size();
  for (size_t i = 0; i < history_count_; ++i) current_.process(history_[(history_next_ + n - history_count_ + i) % n]);
  fade_position_ = 0;
}

double VibrationChannel::process(double x) {
  if (!history_.empty()) {
    history_[history_next_] = x;
    history_next_ = (history_next_ + 1) % history_.size();
    history_count_ = std::min(history_count_ + 1, history_.size());
  }
  const double y_new = current_.process(x);
  if (!fading()) return y_new;
  const double y_old = previous_.process(x);
  ++fade_position_;
  const double w = 0.5 * (1.0 - std::cos(M_PI * fade_position_ / options_.fade_samples));
  const double y = (1.0 - w) * y_old + w * y_new;
  if (fade_position_ >= options_.fade_samples) {
    fade_position_ = -1;
    if (pending_) {
      const TransferFunction next = *pending_;
      pending_.reset();
      select(next);
    }
  }
  return y;
}

}  // namespace onetip::haptics
