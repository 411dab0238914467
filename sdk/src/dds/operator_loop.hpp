// dds/operator_loop.hpp — the operator side of teleoperation: a remote
// sensed vector arriving over DDS (sensed_vector_link.hpp) is rendered by the
// kNN renderer off the loop thread (haptics/render_worker.hpp) and drives a
// fingertip display from a fixed-rate loop (haptics/periodic_loop.hpp, 1 kHz).
//
// Per tick:
//   1. take the newest sensed sample of the one writer the subscriber
//      follows (dds/writer_follower.hpp; other writers' samples are ignored),
//      if any; a sample it could not decode (an encapsulation other than
//      XCDR1: dds/endpoint.hpp) or a vector the dataset cannot
//      answer (haptics/sensed_bounds.hpp: a size other than its channel
//      count, a NaN or infinite value, or one far outside the dataset's
//      range) is refused: the device is told an input error (it retracts at
//      once), nothing is commanded in that tick, and the loop resumes as after
//      a stall. A render that found no dataset row is refused the same way;
//   2. stale = no sample yet, or the newest arrived more than stale_s ago
//      (steady clock), or no writer of the stream is alive any more: DDS
//      liveliness, which drops at once when the publisher deletes its writer
//      and within the writer's lease (0.5 s, stream_qos.hpp) when the
//      publishing process dies without a word (SIGKILL, power, cable).
//      On becoming stale: device.reportInputError() (the driver retracts at
//      once and holds rest) and nothing more is commanded;
//   3. otherwise the newest rendered command becomes the target of a linear
//      ramp over ramp_ticks ticks (haptics/command_ramp.hpp), and the ramp's
//      value is commanded every tick. After a stall the loop waits for a
//      command rendered from a sample that arrived after it, and the ramp
//      starts there; the driver's output gate then moves from rest at the
//      device's speed limit (no jump).
// So the device retracts within min(stale_s, the time DDS takes to declare the
// writer gone) + one tick + the driver's own period after the last sample,
// whether the stream stops, stalls or the publisher dies. The stale timer alone
// covers a dead publisher too; liveliness matters when stale_s is set long
// (a slow sensor) and tells the two causes apart in stats and in the error.
#pragma once

#include <atomic>
#include <cstdint>

#include "dds/sensed_vector_link.hpp"
#include "devices/cutaneous_device.hpp"
#include "haptics/knn_renderer.hpp"
#include "haptics/periodic_loop.hpp"
#include "pipeline/timing_stats.hpp"

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
  std::uint64_t received = 0;        // sensed samples of the followed writer taken from DDS
  std::uint64_t ignored = 0;         // samples of any other writer (writer_follower.hpp: one writer followed)
  std::uint64_t refused = 0;         // refused samples (undecodable, size, non-finite, out of range) and empty renders
  std::uint64_t rendered = 0;
  std::uint64_t stalls = 0;          // times the stream went stale (either cause)
  std::uint64_t writers_lost = 0;    // of those, times because no writer was alive any more
  std::uint64_t commands = 0;        // goals given to the device
  // Response at the operator's device: from a sample's arrival (the tick that
  // took it from DDS) to the first goal given to the device that ramps towards
  // its rendered command (ms; the kNN query on the worker thread and the wait
  // for the next tick). Order statistics of the last 10,000 rendered samples.
  // The ramp then takes ramp_ticks ticks to reach it, and the device's driver
  // sends it within its own period (the servo platform: 20 ms).
  pipeline::StageSummary sample_to_command;
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
