#include "sensor_notices.hpp"

#include <algorithm>
#include <cstdio>

namespace onetip::tools {

int SensorNotices::report(long long index, const std::vector<input::InputEvent>& events) {
  std::vector<std::string> now;
  int printed = 0;
  for (const input::InputEvent& e : events) {
    if (e.type != input::EventType::error) continue;
    if (std::find(last_.begin(), last_.end(), e.message) == last_.end()) {
      std::fprintf(stderr, "onetip %s: frame %lld: %s\n", command_.c_str(), index, e.message.c_str());
      ++printed;
    }
    now.push_back(e.message);
  }
  last_ = std::move(now);
  return printed;
}

}  // namespace onetip::tools
