// tools/sensor_notices.hpp — what the sensor says about itself, on stderr, for
// the commands that print a frame stream (`onetip process`, `onetip demo`).
//
// The pose tracker reports its notices as error events with a message
// (input/pose_tracker.hpp): the camera or a mirror moved against the pad and
// the rest follows it, markers hidden for good (which ids), the solver failed,
// a step limited for safety, the working range left. A user running a real pad
// needs to see them where they happen, not only through the API or DDS. Each
// is printed as "onetip <command>: frame N: <message>" when it begins: a
// message the previous frame also carried is not repeated, so a condition that
// lasts (a limited step on every frame of a fast motion) prints once per
// episode, not once per frame.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "input/input_event.hpp"

namespace onetip::tools {

class SensorNotices {
 public:
  explicit SensorNotices(std::string command) : command_(std::move(command)) {}

  // Prints the error events of frame `index` that begin there; returns how many it printed.
  int report(long long index, const std::vector<input::InputEvent>& events);

 private:
  std::string command_;
  std::vector<std::string> last_;  // the messages of the previous frame
};

}  // namespace onetip::tools
