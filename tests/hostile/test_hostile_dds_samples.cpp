// The findings of the DDS sample fuzzer (tests/fuzz/fuzz_dds_samples.cpp),
// replayed as a peer on the domain would send them: crafted payloads handed to
// Cyclone DDS's receive checks and then to onetip's own consumers
// (tests/dds/raw_sample_peer.hpp), in one process on the loopback.
//   - An XCDR2 sensed vector whose sequence claims twice the doubles that
//     follow passes Debian's Cyclone DDS 0.10.2 checks, and decoding it read
//     the heap past the payload into the sensed values (under ASan: a
//     heap-buffer-overflow in the subscriber's topic filter). onetip now
//     decodes XCDR1 alone and refuses the rest (dds/endpoint.hpp).
//   - The sensor name a sample announces went unfiltered into teleop's log
//     (escape sequences, newlines, any length); it is now shown printable and
//     short (dds/writer_follower.hpp, shownSensorName).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "dds/endpoint.hpp"
#include "dds/sensed_vector_link.hpp"
#include "onetip_msgs/msg/InputEvent.h"
#include "onetip_msgs/msg/SensedVector.h"
#include "raw_sample_peer.hpp"

namespace {

using namespace onetip;

// A little-endian CDR body; `max_align` 8 for XCDR1, 4 for XCDR2.
struct CdrBody {
  std::size_t max_align;
  std::vector<std::uint8_t> bytes;
  template <typename T>
  void put(T v) {
    while (bytes.size() % std::min(sizeof(T), max_align)) bytes.push_back(0);
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof v);
  }
  void string(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size() + 1));
    bytes.insert(bytes.end(), s.begin(), s.end());
    bytes.push_back(0);
  }
  // The encapsulation (plain CDR, little endian: 0x0001 XCDR1, 0x0007 XCDR2), then the body.
  std::vector<std::uint8_t> payload() const {
    std::vector<std::uint8_t> p(4 + bytes.size(), 0);
    p[1] = max_align == 8 ? 1 : 7;
    std::copy(bytes.begin(), bytes.end(), p.begin() + 4);
    return p;
  }
};

// A SensedVector whose sequence says `claimed` doubles and holds `values`, then `trailing` zero bytes.
std::vector<std::uint8_t> sensedPayload(bool xcdr2, const std::string& sensor, const std::vector<double>& values,
                                        std::uint32_t claimed, std::size_t trailing = 0) {
  CdrBody c{xcdr2 ? 4u : 8u, {}};
  c.put<std::int32_t>(1700000000);  // header.stamp
  c.put<std::uint32_t>(0);
  c.string("");                     // header.frame_id
  c.put<std::uint64_t>(1);          // serial
  c.string(sensor);
  c.put(claimed);
  for (double v : values) c.put(v);
  c.bytes.resize(c.bytes.size() + trailing, 0);
  return c.payload();
}

class HostileDdsSamples : public ::testing::Test {
 protected:
  dds::Participant participant_{dds_test::loopbackOnlyOptions()};
  dds_test::RawSamplePeer peer_{participant_, onetip_msgs_msg_dds__SensedVector__desc,
                                participant_.topic("haptic/sensed"), dds::StreamKind::high_rate};
  dds::SensedVectorSubscriber subscriber_{participant_};

  dds::SensedSample sendAndTake(const std::vector<std::uint8_t>& payload) {
    EXPECT_TRUE(peer_.send(payload, dds_time())) << "Cyclone DDS refused the payload";
    dds::SensedSample s;
    EXPECT_TRUE(subscriber_.takeNewest(s)) << "nothing reached the subscriber";
    return s;
  }
};

TEST_F(HostileDdsSamples, Xcdr2SequenceLongerThanItsPayloadIsRefusedNotReadPastTheEnd) {
  const dds::SensedSample valid = sendAndTake(sensedPayload(false, "biotac_like", {1100, 0, 0.002}, 3));
  EXPECT_TRUE(valid.undecodable.empty());
  EXPECT_EQ(valid.values, (std::vector<double>{1100, 0, 0.002}));
  // 12 doubles claimed, 48 bytes follow: Cyclone 0.10.2 checks 12 * 4 of the 12 * 8 bytes.
  const dds::SensedSample crafted = sendAndTake(sensedPayload(true, "biotac_like", {}, 12, 48));
  EXPECT_FALSE(crafted.undecodable.empty());
  EXPECT_TRUE(crafted.values.empty()) << crafted.values.size() << " values decoded from 48 bytes";
  // A well-formed XCDR2 sample is refused too: onetip decodes XCDR1 alone.
  const dds::SensedSample xcdr2 = sendAndTake(sensedPayload(true, "biotac_like", {1100, 0, 0.002}, 3));
  EXPECT_NE(xcdr2.undecodable.find("XCDR1"), std::string::npos);
  EXPECT_TRUE(xcdr2.values.empty());
  EXPECT_EQ(subscriber_.received(), 3u) << "both came from the followed writer";
}

TEST_F(HostileDdsSamples, Xcdr2EventIsNotDecoded) {
  dds_test::RawSamplePeer events_peer(participant_, onetip_msgs_msg_dds__InputEvent__desc, participant_.topic("events"),
                                      dds::StreamKind::events);
  dds::Reader events(participant_, onetip_msgs_msg_dds__InputEvent__desc, participant_.topic("events"),
                     dds::StreamKind::events);
  CdrBody c{4, {}};
  c.put<std::int32_t>(0);
  c.put<std::uint32_t>(0);
  c.string("onetip_sensor");
  c.put<std::uint8_t>(6);  // error
  c.put<std::uint8_t>(0);
  c.put<std::int64_t>(-1);
  for (int i = 0; i < 6; ++i) c.put(0.0);
  c.string("camera lost");
  ASSERT_TRUE(events_peer.send(c.payload(), dds_time()));
  int decoded = 0, refused = 0;
  events.take([&](const void* sample, const dds_sample_info_t&) { ++(sample ? decoded : refused); });
  EXPECT_EQ(decoded, 0);
  EXPECT_EQ(refused, 1);
  EXPECT_EQ(events.undecodable(), 1u);
}

TEST_F(HostileDdsSamples, AnnouncedSensorNameIsShownPrintableAndShort) {
  std::string followed_name;
  subscriber_.follower().locked = [&](const dds::FollowedWriter& w) { followed_name = w.sensor; };
  const dds::SensedSample escape = sendAndTake(sensedPayload(false, "tip\x1b[2J\nleft\\", {1100, 0, 0.002}, 3));
  EXPECT_EQ(escape.sensor, "tip\\x1b[2J\\x0aleft\\x5c");
  EXPECT_EQ(followed_name, escape.sensor) << "what teleop prints";
  const dds::SensedSample huge = sendAndTake(sensedPayload(false, std::string(10000, 'a'), {1100, 0, 0.002}, 3));
  EXPECT_EQ(huge.sensor, std::string(dds::kSensorNameMax, 'a') + "...");
  const dds::SensedSample plain = sendAndTake(sensedPayload(false, "tip_left-2.0", {1100, 0, 0.002}, 3));
  EXPECT_EQ(plain.sensor, "tip_left-2.0");
}

}  // namespace
