#include "dds/writer_follower.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "onetip_msgs/msg/SensedVector.h"

namespace onetip::dds {
namespace {

bool admitSensed(const void* sample, const dds_sample_info_t* info, void* arg) {
  const auto& s = *static_cast<const onetip_msgs_msg_dds__SensedVector_*>(sample);
  return static_cast<WriterFollower*>(arg)->admit(info->publication_handle, s.sensor);
}

}  // namespace

void validateSensorName(const std::string& name, const std::string& what) {
  const bool ok = !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
           c == '-';
  });
  if (!ok) throw InputError(what + " '" + name + "': a sensor name is 1 .. 64 characters of [A-Za-z0-9_.-]");
}

WriterFollower::WriterFollower(std::string sensor) : wanted_(std::move(sensor)) {
  if (!wanted_.empty()) validateSensorName(wanted_, "sensor");
}

dds_topic_filter WriterFollower::topicFilter() {
  dds_topic_filter f{};
  f.mode = DDS_TOPIC_FILTER_SAMPLE_SAMPLEINFO_ARG;
  f.f.sample_sampleinfo_arg = admitSensed;
  f.arg = this;
  return f;
}

bool WriterFollower::admit(dds_instance_handle_t writer, const char* sensor) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!following_ && (wanted_.empty() || (sensor && wanted_ == sensor))) {
    following_ = true;
    writer_ = writer;
  }
  if (following_ && writer == writer_) return true;
  ++ignored_;
  return false;
}

void WriterFollower::taken(const std::string& sensor, const std::function<std::string()>& guid_of) {
  if (announced_) return;
  announced_ = true;
  FollowedWriter w{guid_of(), sensor};
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    followed_ = w;
  }
  if (locked) locked(w);
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
