// dds/writer_follower.hpp — which writer of the haptic channel a subscriber
// follows. Without DDS Security anyone on the domain can write the topic
// (docs/dds/README.md, "Security"); a second writer, by mistake or on purpose,
// must not take the platform over from the first. So the subscriber follows
// one writer for its whole life: the first writer a sample arrives from, or,
// when a sensor name is given, the first writer whose sample announces that
// name (SensedVector's `sensor` field). Samples of every other writer are
// ignored and counted, whatever name they announce, so a later writer cannot
// take over by copying the name. If the followed writer goes away the stream
// goes stale (the operator loop retracts) and stays so until the subscriber is
// made again (restart `onetip teleop`). The loop's liveliness check counts
// every writer of the topic, so while an ignored writer lives, the loss of the
// followed one is noticed by the stale timer alone.
//
// The choice is made in a topic filter (Cyclone DDS runs it on its receive
// threads before a sample enters the reader's history), not when samples are
// taken: the stream keeps one sample (KEEP_LAST 1), so a faster second writer
// would otherwise push the followed writer's samples out before the loop took
// them. This keeps one stream; it proves no identity: a writer started before
// the real sensor, or announcing its name first, is followed instead. Only DDS
// Security's authentication keeps a stranger out.
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace onetip::dds {

// 1 .. 64 characters of [A-Za-z0-9_.-]; InputError naming `what` otherwise.
void validateSensorName(const std::string& name, const std::string& what);

struct FollowedWriter {
  std::string guid;    // the writer's DDS GUID, as Cyclone DDS logs it (4 hex words: participant prefix, entity)
  std::string sensor;  // the name its samples announce
};

class WriterFollower {
 public:
  // sensor: follow the first writer announcing this name; empty: the first writer at all.
  explicit WriterFollower(std::string sensor = {});
  WriterFollower(const WriterFollower&) = delete;
  WriterFollower& operator=(const WriterFollower&) = delete;

  // The topic filter that applies it; `this` must outlive the reader made with it.
  dds_topic_filter topicFilter();
  // Whether a sample of `writer` announcing `sensor` is let in (any thread).
  // The first one that qualifies is followed from then on.
  bool admit(dds_instance_handle_t writer, const char* sensor);
  // On the reading thread, with each sample taken: the first time, names the
  // followed writer (guid_of) and tells `locked`, when set.
  void taken(const std::string& sensor, const std::function<std::string()>& guid_of);

  bool following() const;
  FollowedWriter followed() const;
  std::uint64_t ignored() const;                           // samples of other writers (or other names before)
  std::function<void(const FollowedWriter&)> locked;       // optional: told once when it starts following

 private:
  const std::string wanted_;
  mutable std::mutex mutex_;  // admit() runs on Cyclone's receive threads
  bool following_ = false;
  dds_instance_handle_t writer_ = 0;
  std::uint64_t ignored_ = 0;
  FollowedWriter followed_;   // filled on the reading thread
  bool announced_ = false;    // the reading thread's only
};

}  // namespace onetip::dds
