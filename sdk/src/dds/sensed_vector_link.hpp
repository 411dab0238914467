// dds/sensed_vector_link.hpp — the haptic channel: the remote tactile
// sensor's sensed vector (N channels, any sensor) to the operator's renderer,
// on rt/<ns>/haptic/sensed as onetip_msgs/SensedVector (idl/onetip_msgs/msg/
// SensedVector.idl), with the high_rate QoS (best effort, keep last 1,
// deadline, liveliness: stream_qos.hpp).
//
// The publisher numbers its samples 1, 2, ... and announces its sensor's
// name in each; the subscriber follows one writer (writer_follower.hpp) and reports each
// received sample with the time it arrived (steady clock) and its one-way
// latency, the reader's wall clock at arrival minus the writer's source
// timestamp (meaningful where both clocks are one, e.g. on one machine).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dds/endpoint.hpp"
#include "dds/writer_follower.hpp"

namespace onetip::dds {

struct SensedSample {
  std::uint64_t sequence = 0;
  double stamp_s = 0;                               // header stamp (the sensor's time)
  std::string sensor;                               // as announced, made printable (shownSensorName)
  std::vector<double> values;
  std::string undecodable;                          // why it could not be decoded (endpoint.hpp; values empty); "" if it was
  std::chrono::steady_clock::time_point received{};
  double latency_ms = 0;                            // reception wall clock - source timestamp
};

class SensedVectorPublisher {
 public:
  SensedVectorPublisher(const Participant& participant, std::string sensor, const StreamQos& qos = {});
  // Publishes one vector (stamp: the sensor's time in seconds); returns its sequence number.
  std::uint64_t publish(double stamp_s, const std::vector<double>& values);
  int matchedReaders() const { return writer_.matchedReaders(); }

 private:
  std::string sensor_;
  Writer writer_;
  std::uint64_t sequence_ = 0;
};

class SensedVectorSubscriber {
 public:
  // sensor: the name of the writer to follow (writer_follower.hpp; empty: the
  // first writer a sample comes from). requested_deadline_s: the reader's
  // deadline request (>= the writer's offer).
  explicit SensedVectorSubscriber(const Participant& participant, const std::string& sensor = {},
                                  const StreamQos& qos = {},
                                  double requested_deadline_s = std::numeric_limits<double>::infinity());
  // Takes what arrived (non-blocking) and returns the newest sample of the
  // followed writer when one came since the last call (older ones taken with
  // it are counted in received(); other writers' in follower().ignored()).
  // A sample it could not decode (endpoint.hpp) is returned instead, with
  // `undecodable` set, whatever else came with it: the loop refuses it.
  bool takeNewest(SensedSample& out);
  bool waitForData(double timeout_s) { return reader_.waitForData(timeout_s); }
  std::uint64_t received() const noexcept { return received_; }
  int matchedWriters() const { return reader_.matchedWriters(); }
  int aliveWriters() const { return reader_.aliveWriters(); }
  WriterFollower& follower() noexcept { return follower_; }
  const WriterFollower& follower() const noexcept { return follower_; }

 private:
  WriterFollower follower_;  // before reader_: the reader's topic filter refers to it
  Reader reader_;
  std::uint64_t received_ = 0;
};

}  // namespace onetip::dds
