// haptics/servo_response.hpp — where the display's three RC servos actually
// are while the renderer's commands stream in, for replays over time (the
// objective evaluation drives the device "over time", journal paper Sec. 3.1).
//
// The paper's servos (Pololu sub-micro 3.7 g; Sec. 2.1): commanded at
// control_rate_hz = 50 Hz, positioning resolution 0.5 deg, top speed 60 deg in
// 0.07 s (857 deg/s). Model, per servo i, in 1 ms ticks:
//   at each control instant (every 1 / control_rate_hz s) the target becomes
//     the newest command, rounded to the resolution and clamped to [30, 195] deg;
//   theta_i moves toward the target by at most max_speed_deg_s * 1 ms per tick.
// Neglected: acceleration limits, overshoot, load-dependent speed. advance()
// takes the newest command and the time until the next reading and returns
// the angles at that reading. Degrees, seconds.
#pragma once

#include <array>

namespace onetip::haptics {

struct ServoResponseOptions {
  double control_rate_hz = 50.0;
  double resolution_deg = 0.5;
  double max_speed_deg_s = 60.0 / 0.07;
  void validate() const;  // throws InputError naming the bad field
};

class ServoResponse {
 public:
  // Starts at rest (every servo at 30 deg), a control instant due at once.
  explicit ServoResponse(const ServoResponseOptions& options = {});
  // The newest command (degrees) holds from now for dt_s seconds (> 0);
  // returns the servo angles at the end of that interval.
  const std::array<double, 3>& advance(const std::array<double, 3>& command, double dt_s);

 private:
  ServoResponseOptions options_;
  std::array<double, 3> angle_;
  std::array<double, 3> target_;
  double time_to_control_s_ = 0.0;
};

}  // namespace onetip::haptics
