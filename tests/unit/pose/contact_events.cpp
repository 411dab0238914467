#include "contact_events.hpp"

#include <algorithm>

namespace onetip::poseval {

int ContactEvents::lateEnds() const {
  return static_cast<int>(std::count_if(end_lag.begin(), end_lag.end(), [](int lag) { return lag > kLateEndFrames; }));
}

int ContactEvents::worstEndLag() const {
  return end_lag.empty() ? 0 : *std::max_element(end_lag.begin(), end_lag.end());
}

ContactEvents contactEvents(const std::vector<ReplayFrame>& frames) {
  ContactEvents e;
  for (size_t k = 1; k < frames.size(); ++k) {
    const int at = static_cast<int>(k);
    if (!frames[k - 1].gt_contact && frames[k].gt_contact) e.truth_onset.push_back(at);
    if (frames[k - 1].gt_contact && !frames[k].gt_contact) e.truth_end.push_back(at);
    if (frames[k - 1].contact && !frames[k].contact) e.estimate_end.push_back(at);
    if (!frames[k - 1].contact && frames[k].contact) {
      e.estimate_onset.push_back(at);
      const bool touched = std::any_of(frames[k].gt_contact_markers.begin(), frames[k].gt_contact_markers.end(),
                                       [](std::uint8_t m) { return m != 0; });
      e.onsets_untouched += touched ? 0 : 1;
    }
  }
  for (int end : e.truth_end) {
    int onset = 0;
    for (int o : e.truth_onset)
      if (o < end) onset = o;
    const auto it = std::find_if(e.estimate_end.begin(), e.estimate_end.end(), [&](int x) { return x >= onset; });
    e.end_lag.push_back((it == e.estimate_end.end() ? static_cast<int>(frames.size()) : *it) - end);
  }
  return e;
}

}  // namespace onetip::poseval
