// dds/endpoint.hpp — a typed DDS writer or reader on one topic of a
// Participant, with the QoS of its stream kind (stream_qos.hpp).
//
// Samples are the C structs idlc generates from idl/ (e.g.
// sensor_msgs_msg_dds__Joy_), passed as void* with the topic descriptor that
// goes with them. Reader::take hands each valid sample and its DDS sample
// info (source_timestamp: the writer's wall clock, ns since the epoch) to a
// callback, then frees it.
//
// Reader::take decodes only plain XCDR1 (the encapsulation onetip's writers
// and ROS 2's use for these final types). Debian's Cyclone DDS 0.10.2 checks
// an XCDR2 sample's 8-byte sequences and arrays against half their size
// (fixed upstream in 0.11, commit 9dd9e7527), so decoding one a peer crafted
// reads up to the payload's length past its end (found by
// tests/fuzz/fuzz_dds_samples.cpp). So take() gets the samples serialized,
// decodes the XCDR1 ones itself and hands any other to the callback as a
// null sample (counted in undecodable()): the consumer refuses it. A topic
// filter that looks at samples would decode them first, on Cyclone's receive
// thread: only sample-info filters are safe (writer_follower.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "dds/participant.hpp"
#include "dds/stream_qos.hpp"

namespace onetip::dds {

class Writer {
 public:
  Writer(const Participant& participant, const dds_topic_descriptor_t& type, const std::string& topic_name,
         StreamKind kind, const StreamQos& qos = {});
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  void write(const void* sample);  // std::runtime_error when DDS refuses
  int matchedReaders() const;
  const std::string& topicName() const noexcept { return name_; }

 private:
  std::string name_;
  dds_entity_t topic_ = 0, writer_ = 0;
};

class Reader {
 public:
  using Visit = std::function<void(const void* sample, const dds_sample_info_t& info)>;
  // filter: optional, set on the reader's own topic before the reader is made
  // (Cyclone DDS then drops what it refuses before the reader's history).
  Reader(const Participant& participant, const dds_topic_descriptor_t& type, const std::string& topic_name,
         StreamKind kind, const StreamQos& qos = {},
         double requested_deadline_s = std::numeric_limits<double>::infinity(),
         std::optional<dds_topic_filter> filter = std::nullopt);
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  // Takes every available sample (up to `max`), visiting the valid ones (a
  // sample not in XCDR1 as null); returns how many were visited.
  int take(const Visit& visit, int max = 64);
  std::uint64_t undecodable() const noexcept { return undecodable_; }
  // Blocks until data is available or timeout_s passes; true when data is there.
  bool waitForData(double timeout_s);
  int matchedWriters() const;
  // Writers whose liveliness is asserted now (0 after the publisher's lease expired).
  int aliveWriters() const;
  // The GUID of a matched writer (a sample's publication_handle) as Cyclone DDS logs it,
  // four hex words "prefix:prefix:prefix:entity"; "unknown" when it is no longer matched.
  std::string writerGuid(dds_instance_handle_t writer) const;
  const std::string& topicName() const noexcept { return name_; }

 private:
  std::string name_;
  const dds_topic_descriptor_t& type_;
  dds_entity_t topic_ = 0, reader_ = 0, waitset_ = 0, condition_ = 0;
  std::uint64_t undecodable_ = 0;
};

}  // namespace onetip::dds
