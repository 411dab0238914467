// dds/operator_loop.hpp — the operator side of teleoperation: a remote
// sensed vector arriving over DDS (sensed_vector_link.hpp) is rendered by the
// kNN renderer off the loop thread (haptics/render_worker.hpp) and drives a
// fingertip display from a fixed-rate loop (haptics/periodic_loop.hpp, 1 kHz).
//
// Per tick:
//   1. take the newest sensed sample, if any; a vector whose size is not the
//      renderer's channel count is refused (input error: the device retracts);
//   2. stale = no sample yet, or the newest arrived more than stale_s ago
//      (steady clock). On becoming stale: device.reportInputError() (the
//      driver retracts at once and holds rest) and nothing more is commanded;
//   3. otherwise the newest rendered command becomes the target of a linear
//      ramp over ramp_ticks ticks (haptics/command_ramp.hpp), and the ramp's
//      value is commanded every tick. After a stall the loop waits for a
//      command rendered from a sample that arrived after it, and the ramp
//      starts there; the driver's output gate then moves from rest at the
//      device's speed limit (no jump).
// So the device retracts within stale_s + one tick + the driver's own period
// after the last sample, whether the stream stops, stalls or the publisher dies.
#pragma once

#include <atomic>
#include <cstdint>

#include "dds/sensed_vector_link.hpp"
#include "devices/cutaneous_device.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/periodic_loop.hpp"

namespace onetip::dds {

struct OperatorLoopOptions {
  int neighbors = 4;                 // kNN neighbours
  double stale_s = 0.1;              // the stream is stale after this long without a sample
  double rate_hz = 1000.0;           // loop rate
  int ramp_ticks = 10;               // ramp length between rendered commands (a 100 Hz sensor at 1 kHz)
  haptics::LoopPriority priority = haptics::LoopPriority::best_available;
  void validate() const;             // throws InputError naming the bad field
};

struct OperatorLoopStats {
  std::uint64_t received = 0;        // sensed samples taken from DDS
  std::uint64_t refused = 0;         // of the wrong size
  std::uint64_t rendered = 0;
  std::uint64_t stalls = 0;          // times the stream went stale
  std::uint64_t commands = 0;        // goals given to the device
  haptics::PeriodicLoopResult loop;
};

class OperatorLoop {
 public:
  // All must outlive the loop; the device must be open and take 3 servo angles (deg).
  OperatorLoop(SensedVectorSubscriber& input, const haptics::KnnRenderer& renderer, devices::CutaneousDevice& device,
               const OperatorLoopOptions& options = {});
  // Runs on the calling thread for duration_s (<= 0: until stop()).
  OperatorLoopStats run(double duration_s);
  void stop() noexcept { loop_.stop(); }

 private:
  SensedVectorSubscriber& input_;
  const haptics::KnnRenderer& renderer_;
  devices::CutaneousDevice& device_;
  OperatorLoopOptions options_;
  haptics::PeriodicLoop loop_;
};

}  // namespace onetip::dds
