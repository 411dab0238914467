#include "os_outputs/spnav_protocol.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace onetip::os_outputs::spnav {

namespace {
constexpr size_t kWordBytes = sizeof(std::int32_t);
constexpr size_t kChunkBytes = 24;           // string bytes per message (data0..5)
constexpr std::int32_t kContinuation = 0x10000;
constexpr size_t kMaxNameLength = 255;

template <typename T>
void appendBytes(std::vector<std::byte>& out, const T& value) {
  const auto* p = reinterpret_cast<const std::byte*>(&value);
  out.insert(out.end(), p, p + sizeof(T));
}

bool acceptableSensitivity(float s) { return std::isfinite(s) && std::abs(s) <= kMaxSensitivity; }
}  // namespace

Message motionMessage(const std::array<std::int32_t, 6>& axes, std::int32_t period_ms) noexcept {
  return {kEventMotion, axes[0], axes[1], axes[2], axes[3], axes[4], axes[5], period_ms};
}

Message buttonMessage(bool press, std::int32_t button) noexcept {
  return {press ? kEventPress : kEventRelease, button, press ? 1 : 0, 0, 0, 0, 0, 0};
}

Session::Result Session::feed(std::span<const std::byte> bytes) {
  Result r;
  pending_.insert(pending_.end(), bytes.begin(), bytes.end());
  size_t used = 0;
  for (;;) {
    const size_t need = version_ == 0 ? kWordBytes : kMessageBytes;
    if (pending_.size() - used < need) break;
    bool ok = false;
    if (version_ == 0) {
      std::int32_t word = 0;
      std::memcpy(&word, pending_.data() + used, kWordBytes);
      ok = onWordV0(word, r);
    } else {
      Message req{};
      std::memcpy(req.data(), pending_.data() + used, kMessageBytes);
      ok = onRequestV1(req, r);
    }
    used += need;
    if (!ok) {
      r.garbage = true;
      pending_.clear();
      return r;
    }
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(used));
  return r;
}

bool Session::onWordV0(std::int32_t word, Result& r) {
  greeted_ = true;
  if ((word & static_cast<std::int32_t>(0xffffff00)) == (kReqTag | kReqChangeProto)) {
    version_ = std::min(word & 0xff, kMaxProtocol);
    const std::int32_t granted = kReqTag | kReqChangeProto | version_;
    appendBytes(r.reply, granted);
    if (version_ > 0) event_mask_ = kEvMaskMotion | kEvMaskButton | kEvMaskDev;
    return true;
  }
  const float s = std::bit_cast<float>(word);
  if (!acceptableSensitivity(s)) {
    r.reason = "protocol v0 word is neither the version handshake nor a sensitivity";
    return false;
  }
  sensitivity_ = s;
  return true;
}

bool Session::onRequestV1(Message& req, Result& r) {
  const std::int32_t tag = req[0] & static_cast<std::int32_t>(0xffff0000);
  if (tag != kReqTag && tag != 0) {
    r.reason = "protocol v1 request without the request tag";
    return false;
  }
  auto respond = [&](std::int32_t status) {
    req[7] = status;
    appendBytes(r.reply, req);
  };
  switch (req[0] & 0xffff) {
    case kReqSetName:
      if (!receiveName(req)) {
        r.reason = "malformed client-name transfer";
        return false;
      }
      return true;  // spacenavd sends no reply to SET_NAME
    case kReqSetSens: {
      // libspnav 1.0 sends the low 32 bits of a double here, which are 0 for
      // 1.0, 2.0, 0.5, ...: keep the current sensitivity rather than mute the client.
      if (req[1] == 0) {
        respond(0);
        return true;
      }
      const float s = std::bit_cast<float>(req[1]);
      if (acceptableSensitivity(s)) sensitivity_ = s;
      respond(acceptableSensitivity(s) ? 0 : -1);
      return true;
    }
    case kReqGetSens:
      req[1] = std::bit_cast<std::int32_t>(sensitivity_);
      respond(0);
      return true;
    case kReqSetEvMask:
      event_mask_ = static_cast<std::uint32_t>(req[1]);
      respond(0);
      return true;
    case kReqGetEvMask:
      req[1] = static_cast<std::int32_t>(event_mask_);
      respond(0);
      return true;
    case kReqDevName:
      appendString(req[0], device_.name, r);
      return true;
    case kReqDevPath:
      appendString(req[0], device_.path, r);
      return true;
    case kReqDevAxes:
      req[1] = device_.axes;
      respond(0);
      return true;
    case kReqDevButtons:
      req[1] = device_.buttons;
      respond(0);
      return true;
    case kReqDevType:
      req[1] = 0;  // SPNAV_DEV_UNKNOWN: not one of the known 3Dconnexion models
      respond(0);
      return true;
    case kReqCfgGetSens:
      req[1] = std::bit_cast<std::int32_t>(1.0f);
      respond(0);
      return true;
    case kReqDevUsbId:  // not a USB device
    default:
      respond(-1);
      return true;
  }
}

bool Session::receiveName(const Message& req) {
  const std::int32_t field = req[7];
  if (field < 0 || field >= 2 * kContinuation) return false;
  const bool first = (field & kContinuation) == 0;
  const int remaining = field & 0xffff;
  if (first) {
    name_buffer_.clear();
  } else if (name_expect_ != remaining) {
    return false;
  }
  const size_t take = std::min<size_t>(static_cast<size_t>(remaining), kChunkBytes);
  const char* chunk = reinterpret_cast<const char*>(&req[1]);
  const size_t room = kMaxNameLength - std::min(kMaxNameLength, name_buffer_.size());
  name_buffer_.append(chunk, std::min(take, room));
  name_expect_ = remaining - static_cast<int>(take);
  if (name_expect_ == 0) {
    name_ = name_buffer_.substr(0, name_buffer_.find('\0'));
    name_expect_ = -1;
  }
  return true;
}

void Session::appendString(std::int32_t type, const std::string& text, Result& r) const {
  int remaining = static_cast<int>(std::min<size_t>(text.size(), 0xffff));
  size_t offset = 0;
  Message m{};
  m[0] = type;
  m[7] = remaining;
  do {
    std::fill(m.begin() + 1, m.begin() + 7, 0);
    const size_t take = std::min<size_t>(static_cast<size_t>(remaining), kChunkBytes);
    std::memcpy(&m[1], text.data() + offset, take);
    offset += take;
    remaining -= static_cast<int>(take);
    appendBytes(r.reply, m);
    m[7] = remaining | kContinuation;
  } while (remaining > 0);
}

}  // namespace onetip::os_outputs::spnav
