// The spacenavd wire protocol on bytes (no sockets) and the spnav scaling.
// Expected values are worked out by hand from the formulas documented in
// axis_scaling.hpp and the protocol description in spnav_protocol.hpp.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "os_outputs/axis_scaling.hpp"
#include "os_outputs/spnav_protocol.hpp"

namespace onetip::os_outputs {
namespace {

using spnav::Message;
using spnav::Session;

std::vector<std::byte> bytesOf(const void* p, size_t n) {
  const auto* b = static_cast<const std::byte*>(p);
  return {b, b + n};
}
std::vector<std::byte> word(std::int32_t w) { return bytesOf(&w, sizeof(w)); }
std::vector<std::byte> message(const Message& m) { return bytesOf(m.data(), sizeof(m)); }

std::vector<Message> messagesIn(const std::vector<std::byte>& bytes) {
  EXPECT_EQ(bytes.size() % 32, 0u);
  std::vector<Message> out(bytes.size() / 32);
  std::memcpy(out.data(), bytes.data(), out.size() * 32);
  return out;
}

Session greetedV1() {
  Session s(spnav::DeviceInfo{});
  const auto r = s.feed(word(0x7faa5501));
  EXPECT_FALSE(r.garbage);
  EXPECT_EQ(s.version(), 1);
  return s;
}

TEST(SpnavScaling, WorkingRangeMapsToFullScale) {
  const WorkingRange range;  // dx,dy ±4 mm, dz 0..3 mm, pitch/roll ±40, yaw ±15 deg
  Input6 in;
  in.dx = 2;      // 2/4*350 = 175
  in.dy = -1.2;   // -1.2/4*350 = -105
  in.dz = 0.6;    // 0.6/3*350 = 70
  in.pitch = -8;  // -8/40*350 = -70
  in.roll = 16;   // 16/40*350 = 140
  in.yaw = -6;    // -6/15*350 = -140
  const auto a = spnavAxes(in, range, 350);
  EXPECT_EQ(a, (std::array<std::int32_t, 6>{175, -105, 70, -70, 140, -140}));
  // Beyond the working range: saturates at ±full_scale; NaN is the rest value.
  in = Input6{};
  in.dx = 10;
  in.yaw = -100;
  in.dz = std::nan("");
  EXPECT_EQ(spnavAxes(in, range, 350), (std::array<std::int32_t, 6>{350, 0, 0, 0, 0, -350}));
  EXPECT_EQ(spnavAxes(Input6{}, range, 350), (std::array<std::int32_t, 6>{}));
}

TEST(SpnavScaling, InvalidRangeNamesTheAxis) {
  WorkingRange r;
  r.axes[4] = {5, 1};
  try {
    r.validate();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("roll"), std::string::npos) << e.what();
  }
  r.axes[4] = {1, 5};  // does not contain the onset pose 0
  EXPECT_THROW(r.validate(), InputError);
}

TEST(SpnavProtocol, EventLayoutIsEightInt32) {
  EXPECT_EQ(spnav::motionMessage({1, 2, 3, 4, 5, 6}, 16), (Message{0, 1, 2, 3, 4, 5, 6, 16}));
  EXPECT_EQ(spnav::buttonMessage(true, 0), (Message{1, 0, 1, 0, 0, 0, 0, 0}));
  EXPECT_EQ(spnav::buttonMessage(false, 3), (Message{2, 3, 0, 0, 0, 0, 0, 0}));
}

TEST(SpnavProtocol, HandshakeGrantsAtMostVersionOne) {
  Session s(spnav::DeviceInfo{});
  EXPECT_FALSE(s.greeted());
  auto r = s.feed(word(0x7faa5507));  // a future client asking for v7
  EXPECT_FALSE(r.garbage);
  EXPECT_EQ(r.reply, word(0x7faa5501));
  EXPECT_TRUE(s.greeted());
  EXPECT_EQ(s.version(), 1);

  Session v0(spnav::DeviceInfo{});
  r = v0.feed(word(0x7faa5500));
  EXPECT_EQ(r.reply, word(0x7faa5500));
  EXPECT_EQ(v0.version(), 0);
}

TEST(SpnavProtocol, V0SensitivityWordAndGarbage) {
  Session s(spnav::DeviceInfo{});
  auto r = s.feed(word(std::bit_cast<std::int32_t>(2.5f)));
  EXPECT_FALSE(r.garbage);
  EXPECT_TRUE(r.reply.empty());
  EXPECT_FLOAT_EQ(s.sensitivity(), 2.5f);
  r = s.feed(word(std::bit_cast<std::int32_t>(std::nanf(""))));
  EXPECT_TRUE(r.garbage);
  Session big(spnav::DeviceInfo{});
  EXPECT_TRUE(big.feed(word(std::bit_cast<std::int32_t>(1e6f))).garbage);
}

TEST(SpnavProtocol, BytesMayArriveInPieces) {
  Session s(spnav::DeviceInfo{});
  const auto hello = word(0x7faa5501);
  auto r = s.feed(std::span(hello).first(3));
  EXPECT_TRUE(r.reply.empty());
  EXPECT_FALSE(s.greeted());
  r = s.feed(std::span(hello).subspan(3));
  EXPECT_EQ(r.reply, hello);
  const auto req = message({0x7faa0000 | spnav::kReqDevAxes, 0, 0, 0, 0, 0, 0, 0});
  r = s.feed(std::span(req).first(20));
  EXPECT_TRUE(r.reply.empty());
  r = s.feed(std::span(req).subspan(20));
  ASSERT_EQ(r.reply.size(), 32u);
  const auto m = messagesIn(r.reply)[0];
  EXPECT_EQ(m[1], 6);  // six axes
  EXPECT_EQ(m[7], 0);  // status ok
}

TEST(SpnavProtocol, DeviceNameIsSentInChunks) {
  spnav::DeviceInfo info;
  info.name = "a device name longer than twenty-four bytes";  // 43 bytes -> 2 chunks
  Session s(info);
  s.feed(word(0x7faa5501));
  const std::int32_t type = 0x7faa0000 | spnav::kReqDevName;
  const auto r = s.feed(message({type, 0, 0, 0, 0, 0, 0, 0}));
  const auto ms = messagesIn(r.reply);
  ASSERT_EQ(ms.size(), 2u);
  EXPECT_EQ(ms[0][0], type);
  EXPECT_EQ(ms[0][7], 43);                 // first chunk: the whole length
  EXPECT_EQ(ms[1][7], (43 - 24) | 0x10000);  // continuation: remaining | bit 16
  std::string got(reinterpret_cast<const char*>(&ms[0][1]), 24);
  got.append(reinterpret_cast<const char*>(&ms[1][1]), 43 - 24);
  EXPECT_EQ(got, info.name);
}

TEST(SpnavProtocol, RequestsAnsweredWithStatus) {
  Session s = greetedV1();
  const std::int32_t tag = 0x7faa0000;
  auto reply = [&](Message req) {
    const auto r = s.feed(message(req));
    EXPECT_FALSE(r.garbage);
    const auto ms = messagesIn(r.reply);
    return ms.empty() ? Message{} : ms[0];
  };
  EXPECT_EQ(reply({tag | spnav::kReqSetEvMask, 1, 0, 0, 0, 0, 0, 0})[7], 0);
  EXPECT_EQ(s.eventMask(), 1u);
  EXPECT_EQ(reply({tag | spnav::kReqGetEvMask, 0, 0, 0, 0, 0, 0, 0})[1], 1);
  EXPECT_EQ(reply({tag | spnav::kReqDevButtons, 0, 0, 0, 0, 0, 0, 0})[1], 1);
  EXPECT_EQ(reply({tag | spnav::kReqDevUsbId, 0, 0, 0, 0, 0, 0, 0})[7], -1);  // not USB
  EXPECT_EQ(reply({tag | 0x3000, 0, 0, 0, 0, 0, 0, 0})[7], -1);               // config: not served
  EXPECT_EQ(reply({tag | spnav::kReqSetSens, std::bit_cast<std::int32_t>(0.5f), 0, 0, 0, 0, 0, 0})[7], 0);
  EXPECT_FLOAT_EQ(s.sensitivity(), 0.5f);
  EXPECT_EQ(reply({tag | spnav::kReqSetSens, std::bit_cast<std::int32_t>(std::nanf("")), 0, 0, 0, 0, 0, 0})[7], -1);
  EXPECT_FLOAT_EQ(s.sensitivity(), 0.5f);
}

TEST(SpnavProtocol, ClientNameTransfer) {
  Session s = greetedV1();
  const std::string name = "blender 3.4 with a long client name";  // 35 bytes
  Message first{spnav::kReqSetName, 0, 0, 0, 0, 0, 0, 35};
  std::memcpy(&first[1], name.data(), 24);
  Message second{spnav::kReqSetName, 0, 0, 0, 0, 0, 0, (35 - 24) | 0x10000};
  std::memcpy(&second[1], name.data() + 24, 11);
  auto r = s.feed(message(first));
  EXPECT_TRUE(r.reply.empty());  // no reply to SET_NAME
  r = s.feed(message(second));
  EXPECT_FALSE(r.garbage);
  EXPECT_EQ(s.name(), name);
  // A continuation that does not match the announced length is malformed.
  Message wrong{spnav::kReqSetName, 0, 0, 0, 0, 0, 0, 7 | 0x10000};
  EXPECT_TRUE(s.feed(message(wrong)).garbage);
}

TEST(SpnavProtocol, UntaggedGarbageRequestIsRejected) {
  Session s = greetedV1();
  const auto r = s.feed(message({0x12345678, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_TRUE(r.garbage);
  EXPECT_FALSE(r.reason.empty());
}

}  // namespace
}  // namespace onetip::os_outputs
