// haptics/latest_value.hpp — a lock-free, wait-free "latest value" slot
// between one producer thread and one consumer thread (a triple buffer).
//
// Three slots: the producer writes into its own back slot, then atomically
// swaps it with the shared middle slot, marking it fresh; the consumer, when
// the middle is fresh, swaps it with its own front slot. Neither side ever
// waits for the other or sees a half-written value; the consumer always reads
// the newest complete value published (older ones may be skipped). T must be
// copyable; publish() and fetch() copy one T.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

namespace onetip::haptics {

template <typename T>
class LatestValue {
 public:
  explicit LatestValue(const T& initial = T{}) { slots_.fill(initial); }

  // Producer side.
  void publish(const T& value) {
    slots_[back_] = value;
    const std::uint8_t old = middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel);
    back_ = old & kIndex;
  }

  // Consumer side: copies the newest value into `out`; true when it is newer
  // than the one the previous fetch returned.
  bool fetch(T& out) {
    bool fresh = false;
    if (middle_.load(std::memory_order_relaxed) & kFresh) {
      const std::uint8_t old = middle_.exchange(front_, std::memory_order_acq_rel);
      front_ = old & kIndex;
      fresh = true;
    }
    out = slots_[front_];
    return fresh;
  }

 private:
  static constexpr std::uint8_t kIndex = 3, kFresh = 4;
  std::array<T, 3> slots_;
  std::atomic<std::uint8_t> middle_{1};
  std::uint8_t back_ = 0;   // producer's
  std::uint8_t front_ = 2;  // consumer's
  static_assert(std::atomic<std::uint8_t>::is_always_lock_free);
};

}  // namespace onetip::haptics
