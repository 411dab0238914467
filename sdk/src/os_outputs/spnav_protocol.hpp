// os_outputs/spnav_protocol.hpp — the spacenavd AF_UNIX wire protocol, server
// side, without any I/O (so every rule is testable on bytes).
//
// Everything on the wire is int32 in host byte order.
// Events (server -> client), 32 bytes = eight int32 (protocol v0 and v1):
//   motion:  [0, x, y, z, rx, ry, rz, period_ms]
//   press:   [1, button, 1, 0, 0, 0, 0, 0]      release: [2, button, 0, 0, ...]
// Version handshake (libspnav >= 1.0 sends it right after connecting):
//   client -> server one int32  REQ_TAG | REQ_CHANGE_PROTO | wanted (0x7faa55vv);
//   server -> client one int32  REQ_TAG | REQ_CHANGE_PROTO | granted, where
//   granted = min(wanted, 1); from then on the client speaks that version.
// Protocol v0, client -> server: int32 words; any word that is not the
// handshake is the client's sensitivity as a float.
// Protocol v1, client -> server: 32-byte requests [type, data0..data6];
// (type & 0xffff) selects the request, the upper 16 bits are REQ_TAG or 0
// (libspnav sends SET_NAME untagged). The reply echoes the type with data6 the
// status (0 ok, -1 failure). Strings travel in 24-byte chunks (data0..5),
// data6 = remaining length, with bit 16 set on continuation chunks.
//
// Garbage, after which the server drops the client: a v0 word that is neither
// the handshake nor a finite sensitivity with |s| <= 1000; a v1 request whose
// upper type bits are neither REQ_TAG nor 0; a malformed string transfer.
// Well-formed requests the server does not implement (the 0x3000
// configuration requests of spnavcfg) are answered with status -1.
// A v1 SET_SENS whose value bits are all zero is acknowledged but ignored:
// libspnav 1.0 (Debian 12) sends the low half of a double there, which is 0
// for every "round" value (1.0, 2.0, 0.5), and would otherwise mute itself.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace onetip::os_outputs::spnav {

using Message = std::array<std::int32_t, 8>;  // one 32-byte event or request
inline constexpr size_t kMessageBytes = sizeof(Message);
static_assert(kMessageBytes == 32);

inline constexpr std::int32_t kEventMotion = 0;
inline constexpr std::int32_t kEventPress = 1;
inline constexpr std::int32_t kEventRelease = 2;

inline constexpr std::int32_t kReqTag = 0x7faa0000;
inline constexpr std::int32_t kReqChangeProto = 0x5500;
inline constexpr int kMaxProtocol = 1;

// Requests (type & 0xffff) the server answers.
inline constexpr std::int32_t kReqSetName = 0x1000, kReqSetSens = 0x1001, kReqGetSens = 0x1002,
                              kReqSetEvMask = 0x1003, kReqGetEvMask = 0x1004;
inline constexpr std::int32_t kReqDevName = 0x2000, kReqDevPath = 0x2001, kReqDevAxes = 0x2002,
                              kReqDevButtons = 0x2003, kReqDevUsbId = 0x2004, kReqDevType = 0x2005;
inline constexpr std::int32_t kReqCfgGetSens = 0x3001;

inline constexpr std::uint32_t kEvMaskMotion = 0x01, kEvMaskButton = 0x02, kEvMaskDev = 0x04;

inline constexpr float kMaxSensitivity = 1000.0f;

Message motionMessage(const std::array<std::int32_t, 6>& axes, std::int32_t period_ms) noexcept;
Message buttonMessage(bool press, std::int32_t button) noexcept;

// What the server tells clients about its device (v1 device queries).
struct DeviceInfo {
  std::string name = "onetip tactile fingertip";
  std::string path;     // e.g. the input source; may be empty
  int axes = 6;
  int buttons = 1;
};

// One client's protocol state. Feed it every byte the client sends; it
// returns the bytes to send back (in order) and flags garbage.
class Session {
 public:
  explicit Session(DeviceInfo device) : device_(std::move(device)) {}

  struct Result {
    std::vector<std::byte> reply;  // handshake word and/or 32-byte responses
    bool garbage = false;
    std::string reason;            // why it is garbage
  };
  Result feed(std::span<const std::byte> bytes);

  // True once the client sent its first word (handshake or v0 sensitivity).
  bool greeted() const noexcept { return greeted_; }
  int version() const noexcept { return version_; }
  float sensitivity() const noexcept { return sensitivity_; }
  std::uint32_t eventMask() const noexcept { return event_mask_; }
  const std::string& name() const noexcept { return name_; }

 private:
  bool onWordV0(std::int32_t word, Result& r);
  bool onRequestV1(Message& req, Result& r);
  bool receiveName(const Message& req);
  void appendString(std::int32_t type, const std::string& text, Result& r) const;

  DeviceInfo device_;
  std::vector<std::byte> pending_;
  bool greeted_ = false;
  int version_ = 0;
  float sensitivity_ = 1.0f;
  std::uint32_t event_mask_ = kEvMaskMotion | kEvMaskButton;
  std::string name_;
  std::string name_buffer_;
  int name_expect_ = -1;  // bytes still expected of a name transfer, -1 = none
};

}  // namespace onetip::os_outputs::spnav
