// Fuzzes the samples a DDS peer can send onetip, through onetip's own
// consumers (tests/dds/raw_sample_peer.hpp: the bytes go where a DATA
// submessage's payload goes, into Cyclone DDS's CDR check, then to the
// readers). The first byte picks the topic and the source timestamp a peer's
// INFO_TS can give; the rest is the payload (4-byte encapsulation header, CDR).
//   sensed vector (rt/<ns>/haptic/sensed, SensedVector): teleop's subscriber
//     (its writer-following topic filter, takeNewest), then what the operator
//     loop does with a sample (dds/operator_loop.hpp): the dataset's bounds
//     (haptics/sensed_bounds.hpp) and, for a vector they pass, the kNN render.
//     A vector that passes must render, at a finite distance, to a command
//     inside the dataset's commands' range on every servo; the sensor name
//     kept for teleop's log must be printable and short. A sample Cyclone
//     accepts but onetip does not decode (not XCDR1: dds/endpoint.hpp) comes
//     back with no values, refused.
//   events (rt/<ns>/events, InputEvent): onetip only publishes them; a reader
//     takes what a peer sends (the decoding a subscriber of onetip's IDL does).
// The dataset is built in: 3 channels on a 5 x 5 x 5 grid, commands across
// the servo platform's range (degrees).
#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "dds/endpoint.hpp"
#include "dds/sensed_vector_link.hpp"
#include "haptics/knn_renderer.hpp"
#include "onetip_msgs/msg/InputEvent.h"
#include "onetip_msgs/msg/SensedVector.h"
#include "raw_sample_peer.hpp"

namespace {

using namespace onetip;

haptics::TactileDataset gridDataset() {
  haptics::TactileDataset d;
  d.channels = 3;
  for (int i = 0; i < 125; ++i) {
    const int a = i % 5, b = i / 5 % 5, c = i / 25;
    d.append({30.0 + 40.0 * a, 40.0 + 35.0 * b, 50.0 + 30.0 * c}, {1000.0 + 50.0 * a, -2.0 + b, 1e-3 * c});
  }
  return d;
}

struct Consumers {
  dds::Participant participant{dds_test::loopbackOnlyOptions()};
  dds_test::RawSamplePeer sensed_peer{participant, onetip_msgs_msg_dds__SensedVector__desc,
                                      participant.topic("haptic/sensed"), dds::StreamKind::high_rate};
  dds_test::RawSamplePeer events_peer{participant, onetip_msgs_msg_dds__InputEvent__desc, participant.topic("events"),
                                      dds::StreamKind::events};
  dds::SensedVectorSubscriber sensed{participant};
  dds::Reader events{participant, onetip_msgs_msg_dds__InputEvent__desc, participant.topic("events"),
                     dds::StreamKind::events};
  haptics::TactileDataset dataset = gridDataset();
  haptics::KnnRenderer renderer{dataset};
  std::array<float, 3> low{1e30f, 1e30f, 1e30f}, high{-1e30f, -1e30f, -1e30f};  // of its commands, per servo
  Consumers() {
    for (size_t i = 0; i < dataset.commands.size(); ++i) {
      low[i % 3] = std::min(low[i % 3], dataset.commands[i]);
      high[i % 3] = std::max(high[i % 3], dataset.commands[i]);
    }
  }
};

// What a peer's INFO_TS can make a sample's source timestamp: a time of its
// choice (here now), none (Cyclone DDS then gives 0), infinite, or the
// earliest its 32-bit seconds can say.
constexpr std::array<dds_time_t, 4> kStampKinds{-1, 0, DDS_NEVER, static_cast<dds_time_t>(INT32_MIN) * DDS_NSECS_IN_SEC};

bool printable(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](char ch) { return ch >= 0x20 && ch < 0x7f; });
}

void checkSensed(Consumers& c) {
  dds::SensedSample s;
  if (!c.sensed.takeNewest(s)) return;
  if (!printable(s.sensor) || s.sensor.size() > 4 * dds::kSensorNameMax + 3) __builtin_trap();
  if (!s.undecodable.empty() && !s.values.empty()) __builtin_trap();
  if (!c.renderer.bounds().refusal(s.values).empty()) return;
  const haptics::RenderResult r = c.renderer.render(s.values.data(), 4);
  // Inside the bounds, standardised distances cannot overflow: a row is found.
  if (!r.found() || !std::isfinite(r.nearest_distance)) __builtin_trap();
  for (size_t axis = 0; axis < 3; ++axis)
    if (!(r.command[axis] >= c.low[axis] - 1e-3 && r.command[axis] <= c.high[axis] + 1e-3)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Consumers c;
  if (size == 0) return 0;
  const dds_time_t kind = kStampKinds[(data[0] >> 1) & 3];
  const dds_time_t stamp = kind == -1 ? dds_time() : kind;
  const std::span<const std::uint8_t> payload(data + 1, size - 1);
  if (data[0] & 1) {
    if (c.events_peer.send(payload, stamp)) c.events.take([](const void*, const dds_sample_info_t&) {});
  } else if (c.sensed_peer.send(payload, stamp)) {
    checkSensed(c);
  }
  return 0;
}
