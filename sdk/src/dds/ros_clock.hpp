// dds/ros_clock.hpp — header stamps on the clock a ROS 2 node uses: the
// system clock (CLOCK_REALTIME, seconds since 1970), which rviz2 and tf2
// compare with their own now().
//
// A frame's source time t (seconds; the scenario time of a sim: source, the
// capture time of a camera, on whatever clock the source keeps) is mapped to
//
//   stamp = t + offset,   offset = system time at the first frame's arrival
//                                  - that frame's t   (fixed from then on)
//
// so the first stamp is the system time at which that frame arrived from its
// source, and stamps keep the source's own spacing: a camera's capture times,
// one frame period apart for a sim: source (which then runs ahead of the wall
// clock unless it is paced with playback_rate: 1). The arrival is taken on the
// steady clock and carried to the system clock by the difference of the two
// clocks' now(). Not thread-safe: one publishing thread.
#pragma once

#include <chrono>
#include <optional>

namespace onetip::dds {

// The system time (s since the epoch) of a steady-clock instant in the recent past.
double systemSecondsAt(std::chrono::steady_clock::time_point t);

class SourceToSystemClock {
 public:
  // Stamp (system seconds) of source time t; the first call fixes the offset
  // from system_at_arrival (systemSecondsAt of that frame's arrival).
  double stamp(double source_t, double system_at_arrival);
  std::optional<double> offset() const noexcept { return offset_; }

 private:
  std::optional<double> offset_;
};

}  // namespace onetip::dds
