// tests/dds/raw_sample_peer.hpp — a DDS peer that sends arbitrary bytes as a
// sample of one topic, to onetip's own consumers in the same process: the
// fuzz harness of the sample decoding paths (tests/fuzz/fuzz_dds_samples.cpp)
// and the hostile tests that replay its findings.
//
// What a peer controls on the wire is a DATA submessage's serialized payload
// (a 4-byte encapsulation header, then the CDR body) and, through INFO_TS, the
// sample's source timestamp. send() hands exactly those to Cyclone DDS as its
// receive path would: the payload goes through ddsi_serdata_from_ser_iov, which
// checks and normalises the CDR against the topic's type (a malformed payload
// is dropped there, as on reception), and the sample is then delivered to the
// local readers of the topic (their topic filters run, as for a remote writer)
// with the source timestamp as given. Delivery to readers in the same
// participant is synchronous: when send() returns, a reader can take it.
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <span>
#include <string>

#include "dds/participant.hpp"
#include "dds/stream_qos.hpp"

struct ddsi_sertype;

namespace onetip::dds_test {

// A participant on the loopback alone (no multicast, no peers: nothing leaves
// the machine) with a namespace of its own per process, so that its topics
// meet no other process's.
dds::DdsOptions loopbackOnlyOptions();

class RawSamplePeer {
 public:
  // A writer on `topic_name` of `type` with the QoS of `kind` (stream_qos.hpp).
  RawSamplePeer(const dds::Participant& participant, const dds_topic_descriptor_t& type, const std::string& topic_name,
                dds::StreamKind kind);
  ~RawSamplePeer();
  RawSamplePeer(const RawSamplePeer&) = delete;
  RawSamplePeer& operator=(const RawSamplePeer&) = delete;

  // Sends `payload` (encapsulation header + CDR) stamped `source_timestamp`
  // (ns since the epoch); false when Cyclone DDS refuses it as malformed.
  bool send(std::span<const std::uint8_t> payload, dds_time_t source_timestamp);

 private:
  dds_entity_t topic_ = 0, writer_ = 0;
  const ddsi_sertype* type_ = nullptr;  // the topic's serialisation type, referenced
};

}  // namespace onetip::dds_test
