#include "dds/ros_clock.hpp"

namespace onetip::dds {

double systemSecondsAt(std::chrono::steady_clock::time_point t) {
  const auto steady_now = std::chrono::steady_clock::now();
  const auto system_now = std::chrono::system_clock::now();
  return std::chrono::duration<double>(system_now.time_since_epoch()).count() -
         std::chrono::duration<double>(steady_now - t).count();
}

double SourceToSystemClock::stamp(double source_t, double system_at_arrival) {
  if (!offset_) offset_ = system_at_arrival - source_t;
  return source_t + *offset_;
}

}  // namespace onetip::dds
