#include "dds/writer_follower.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace onetip::dds {
namespace {

bool admitWriter(const dds_sample_info_t* info, void* arg) {
  return static_cast<WriterFollower*>(arg)->admit(info->publication_handle);
}

}  // namespace

void validateSensorName(const std::string& name, const std::string& what) {
  const bool ok = !name.empty() && name.size() <= kSensorNameMax && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
           c == '-';
  });
  if (!ok) throw InputError(what + " '" + name + "': a sensor name is 1 .. 64 characters of [A-Za-z0-9_.-]");
}

std::string shownSensorName(const char* announced) {
  if (!announced) return {};
  std::string shown;
  std::size_t n = 0;
  for (; announced[n] && n < kSensorNameMax; ++n) {
    const auto c = static_cast<unsigned char>(announced[n]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      shown += static_cast<char>(c);
    } else {
      static const char kHex[] = "0123456789abcdef";
      shown += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
    }
  }
  if (announced[n]) shown += "...";
  return shown;
}

WriterFollower::WriterFollower(std::string sensor) : wanted_(std::move(sensor)) {
  if (!wanted_.empty()) validateSensorName(wanted_, "sensor");
}

dds_topic_filter WriterFollower::topicFilter() {
  dds_topic_filter f{};
  f.mode = DDS_TOPIC_FILTER_SAMPLEINFO_ARG;
  f.f.sampleinfo_arg = admitWriter;
  f.arg = this;
  return f;
}

bool WriterFollower::admit(dds_instance_handle_t writer) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!following_ || writer == writer_) return true;
  ++ignored_;
  return false;
}

bool WriterFollower::taken(dds_instance_handle_t writer, const char* sensor,
                           const std::function<std::string()>& guid_of) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (following_) {
    if (writer == writer_) return true;
    ++ignored_;  // let in before the choice
    return false;
  }
  if (!wanted_.empty() && !(sensor && wanted_ == sensor)) {
    ++ignored_;
    return false;
  }
  following_ = true;
  writer_ = writer;
  lock.unlock();
  const FollowedWriter w{guid_of(), shownSensorName(sensor)};
  lock.lock();
  followed_ = w;
  lock.unlock();
  if (locked) locked(w);
  return true;
}

bool WriterFollower::following() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return following_;
}

FollowedWriter WriterFollower::followed() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return followed_;
}

std::uint64_t WriterFollower::ignored() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return ignored_;
}

}  // namespace onetip::dds
