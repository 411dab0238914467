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
// The choice is made when a sample is taken (its name is in the sample), and
// from then on kept in a topic filter on the writer alone (Cyclone DDS runs it
// on its receive threads before a sample enters the reader's history): the
// reader keeps a bounded history (dds/stream_qos.hpp), so a faster second
// writer would otherwise push the followed writer's samples out before the
// loop took them.
// The filter reads the sample info only: a filter that reads the sample makes
// Cyclone decode it first, on its receive thread, before onetip can refuse an
// encapsulation it does not decode (endpoint.hpp). Until the choice is made,
// every writer's samples enter the history, which holds a take period's worth
// of them, so the first writer to announce the name is the one seen first.
// This keeps one stream; it proves no identity: a writer started before the
// real sensor, or announcing its name first, is followed instead. Only DDS
// Security's authentication keeps a stranger out.
#pragma once

#include <dds/dds.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace onetip::dds {

constexpr std::size_t kSensorNameMax = 64;  // characters

// 1 .. kSensorNameMax characters of [A-Za-z0-9_.-]; InputError naming `what` otherwise.
void validateSensorName(const std::string& name, const std::string& what);
// The name a sample announces, as onetip shows it (teleop's log, FollowedWriter):
// any writer on the domain chooses it, so it is made printable and short. Its
// first kSensorNameMax bytes, each byte outside printable ASCII (control
// characters such as ESC or a newline, bytes >= 0x7f) and each backslash
// written as \xNN, then "..." when there were more: at most
// 4 * kSensorNameMax + 3 characters. A name onetip's publishers send (valid
// for validateSensorName) is shown unchanged; null is "".
std::string shownSensorName(const char* announced);

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

  // The topic filter that keeps the choice; `this` must outlive the reader made with it.
  dds_topic_filter topicFilter();
  // Whether a sample of `writer` is let into the history (any thread): every
  // one until a writer is followed, then the followed writer's alone.
  bool admit(dds_instance_handle_t writer);
  // On the reading thread, with each sample taken (sensor: the name it
  // announces, null when it could not be decoded): whether it is the followed
  // writer's. The first sample that qualifies chooses its writer; then
  // guid_of names it and `locked`, when set, is told.
  bool taken(dds_instance_handle_t writer, const char* sensor, const std::function<std::string()>& guid_of);

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
  FollowedWriter followed_;
};

}  // namespace onetip::dds
